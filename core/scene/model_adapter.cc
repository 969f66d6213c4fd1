/* model_adapter.cc - what the tinygltf and Assimp adapters share (model_adapter.h): the
 * copy into malloc'd C arrays, its release, and the exception boundary. */
#include "scene/model_adapter.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>

namespace model_adapter {

namespace {

template <typename T> T *c_array(const std::vector<T> &v)
{
    if (v.empty())
        return nullptr;
    T *p = static_cast<T *>(std::malloc(v.size() * sizeof(T)));
    if (!p)
        throw std::bad_alloc();
    std::memcpy(p, v.data(), v.size() * sizeof(T));
    return p;
}

void report(char *why, size_t why_len, const char *path, const std::string &message)
{
    if (why && why_len)
        std::snprintf(why, why_len, "%s: %s", path, message.c_str());
}

} // namespace

void Ignored::add(const std::string &feature, const std::string &where)
{
    for (auto &f : features)
        if (f.first == feature) {
            for (const std::string &w : f.second)
                if (w == where)
                    return;
            f.second.push_back(where);
            return;
        }
    features.push_back({feature, {where}});
}

std::string Ignored::text() const
{
    std::string all;
    for (const auto &f : features) {
        std::string line = f.first;
        if (!f.second.empty() && !f.second[0].empty()) {
            line += ": " + std::to_string(f.second.size()) + " use" +
                    (f.second.size() == 1 ? "" : "s") + ": ";
            for (size_t i = 0; i < f.second.size() && i < 4; i++)
                line += (i ? ", " : "") + f.second[i];
            if (f.second.size() > 4)
                line += " and " + std::to_string(f.second.size() - 4) + " more";
        }
        if (all.size() + line.size() + 1 >= SSG_MODEL_IGNORED_MAX)
            break;
        all += line + "\n";
    }
    return all;
}

ssg_gltf *to_c(const std::vector<Prim> &prims, const std::vector<ssg_gltf_material> &materials,
               const std::vector<Tex> &textures, const ssg_camera *camera,
               const Ignored &ignored, const std::vector<ssg_light> &lights)
{
    ssg_gltf *g = static_cast<ssg_gltf *>(std::calloc(1, sizeof *g));
    if (!g)
        throw std::bad_alloc();
    try {
        g->meshes = static_cast<ssg_mesh *>(std::calloc(prims.size() + 1, sizeof(ssg_mesh)));
        g->materials = c_array(materials);
        g->lights = c_array(lights);
        g->light_count = (int)lights.size();
        if (!lights.empty() && !g->lights)
            throw std::bad_alloc();
        g->textures =
            static_cast<ssg_texture *>(std::calloc(textures.size() + 1, sizeof(ssg_texture)));
        if (!g->meshes || !g->textures || (!materials.empty() && !g->materials))
            throw std::bad_alloc();
        g->material_count = (int)materials.size();
        for (const Prim &p : prims) {
            ssg_mesh &o = g->meshes[g->mesh_count++];
            o.vertex_count = (int)(p.positions.size() / 3);
            o.triangle_count = (int)(p.indices.size() / 3);
            o.material = p.material;
            o.positions = c_array(p.positions);
            o.normals = c_array(p.normals);
            o.uvs = c_array(p.uvs);
            o.tangents = c_array(p.tangents);
            o.colors = c_array(p.colors);
            o.indices = c_array(p.indices);
        }
        for (const Tex &t : textures) {
            ssg_texture &o = g->textures[g->texture_count++];
            o.width = t.width;
            o.height = t.height;
            o.rgb = c_array(t.rgb);
            o.alpha = c_array(t.alpha);
        }
    } catch (...) {
        free_model(g);
        throw;
    }
    std::snprintf(g->ignored, sizeof g->ignored, "%s", ignored.text().c_str());
    g->has_camera = camera != nullptr;
    if (camera)
        g->camera = *camera;
    return g;
}

void free_model(ssg_gltf *g)
{
    for (int i = 0; g->meshes && i < g->mesh_count; i++) {
        std::free(g->meshes[i].positions);
        std::free(g->meshes[i].normals);
        std::free(g->meshes[i].uvs);
        std::free(g->meshes[i].tangents);
        std::free(g->meshes[i].colors);
        std::free(g->meshes[i].indices);
    }
    for (int i = 0; g->textures && i < g->texture_count; i++) {
        std::free(g->textures[i].rgb);
        std::free(g->textures[i].alpha);
    }
    std::free(g->meshes);
    std::free(g->materials);
    std::free(g->lights);
    std::free(g->textures);
    std::free(g);
}

std::string printable(std::string text)
{
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    for (char &c : text)
        if (c == '\n')
            c = ';';
        else if ((unsigned char)c < 32 || (unsigned char)c > 126)
            c = '?';
    return text;
}

ssg_err guarded(const char *path, ssg_gltf **out, char *why, size_t why_len,
                ssg_gltf *(*load)(const char *path), const char *library)
{
    return guarded(path, out, why, why_len, [&] { return load(path); }, library);
}

ssg_err guarded(const char *path, ssg_gltf **out, char *why, size_t why_len,
                const std::function<ssg_gltf *()> &load, const char *library)
{
    *out = nullptr;
    try {
        *out = load();
        return SSG_OK;
    } catch (const Failure &f) {
        report(why, why_len, path, f.message);
        return f.code;
    } catch (const std::bad_alloc &) {
        report(why, why_len, path, "out of memory");
        return SSG_E_NOMEM;
    } catch (const std::exception &e) {
        report(why, why_len, path, printable(e.what()));
    } catch (...) {
        report(why, why_len, path, std::string("unexpected failure inside ") + library);
    }
    return SSG_E_GLTF;
}

} // namespace model_adapter
