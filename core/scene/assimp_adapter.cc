/* assimp_adapter.cc - the C++ side of ssg_assimp_load (model.h): reads OBJ, PLY, FBX, 3DS,
 * STL, DAE, glTF 1.0 and the other formats of Debian's Assimp into the struct ssg_gltf the
 * tinygltf path fills, so the scene loader places both the same way. It runs in this
 * process: model.c calls it in a child process (model_sandbox.c), the fuzz target here.
 *
 * Assimp triangulates, drops points and lines, makes smooth normals where the file has
 * none and flips v to the top-left texture origin glTF uses; the node hierarchy is walked
 * here so every mesh instance gets its world transform (normals by the cofactor matrix,
 * the winding flipped under a mirroring transform). No axis or unit conversion is added
 * here, so a Z-up or millimetre model is turned and scaled by the mesh line's rotate and
 * scale, like a glTF; but some of Assimp's own readers convert: the 3DS reader turns 3ds
 * Max's Z-up into Y-up, and the Collada reader the file's <up_axis>. find_up says which
 * way is up after the import, and on what that rests (for `ssgraph check`), from those
 * readers and from the UpAxis metadata others (FBX) leave. A diffuse colour becomes base_color,
 * a diffuse texture texture_file (decoded by the caller, scene_build.c). Assimp's own
 * DefaultMaterial, the 3DS reader's grey %%%DEFAULT, the unnamed white one of PLY (files
 * without materials), and a
 * material with neither a diffuse colour nor a texture, map to "none": the scene's
 * default white applies, as for a glTF primitive without material.
 *
 * Every file Assimp opens, the model and what it names (.mtl, .bin), is read through
 * ssg_input_read, the same rules as every input (lang/files.h). Nothing is logged;
 * Assimp's error string becomes the message, and no exception leaves this file. */
#include "scene/model.h"
#include "scene/model_adapter.h"

extern "C" {
#include "lang/files.h"
}

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <sys/stat.h>
#include <vector>

#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

namespace {

using model_adapter::Failure;
using model_adapter::Prim;
using model_adapter::fail;
using model_adapter::printable;

/* Assimp's file access, through ssg_input_read: a regular file of at most
   SSG_MAX_MODEL_BYTES, read whole into memory. Read-only. Remembers the first file it
   could not open: Assimp goes on without a missing .mtl or buffer, the loader does not. */
class InputIO : public Assimp::IOSystem {
  public:
    std::string failed; /* "'gone.mtl' (No such file or directory)", "" = none */

    bool Exists(const char *path) const override
    {
        struct stat st;
        return stat(path, &st) == 0;
    }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream *Open(const char *path, const char *mode) override
    {
        if (!mode || std::strchr(mode, 'w') || std::strchr(mode, 'a'))
            return nullptr;
        char *data = nullptr, why[256];
        size_t len = 0;
        if (ssg_input_read(path, SSG_MAX_MODEL_BYTES, &data, &len, why, sizeof why)) {
            if (failed.empty())
                failed = std::string("'") + path + "' (" + why + ")";
            return nullptr;
        }
        uint8_t *copy = new (std::nothrow) uint8_t[len ? len : 1];
        if (copy && len)
            std::memcpy(copy, data, len);
        std::free(data);
        return copy ? new (std::nothrow) Assimp::MemoryIOStream(copy, len, true) : nullptr;
    }
    void Close(Assimp::IOStream *stream) override { delete stream; }
};

/* Cofactor matrix of the upper 3x3 (row-major like aiMatrix4x4): proportional to the
   inverse transpose, which carries normals through a non-uniform scale. */
void cofactor(const aiMatrix4x4 &m, double c[9], double *det)
{
    const double e[3][3] = {{m.a1, m.a2, m.a3}, {m.b1, m.b2, m.b3}, {m.c1, m.c2, m.c3}};
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            c[3 * r + k] = e[r1][k1] * e[r2][k2] - e[r1][k2] * e[r2][k1];
        }
    *det = e[0][0] * c[0] + e[0][1] * c[1] + e[0][2] * c[2];
}

class Flattener {
  public:
    explicit Flattener(const aiScene &scene) : s(scene) {}
    void run();
    ssg_gltf *to_c() const;

  private:
    const aiScene &s;
    std::vector<Prim> prims;
    std::vector<ssg_gltf_material> materials;
    std::vector<int> slot; /* Assimp material -> materials index, -1 = its default */
    size_t visits = 0;
    model_adapter::Ignored ignored; /* what the file uses and no path reads */

    void convert_materials();
    void note_ignored(const aiMaterial &src, const ssg_gltf_material &mat);
    void visit(const aiNode *node, const aiMatrix4x4 &parent, int depth);
    void add_mesh(const aiMesh &mesh, const aiMatrix4x4 &world);
};

/* An emission map (map_Ke) multiplies Ke; with Ke black or absent it is the emission
   itself (Ke taken as 1: a file that names an emission map means it to glow). */
static void read_emission_map(const aiMaterial &src, ssg_gltf_material &mat)
{
    aiString map;
    if (src.GetTexture(aiTextureType_EMISSIVE, 0, &map) != AI_SUCCESS || !map.length)
        return;
    if (map.length >= sizeof mat.emission_file)
        fail(std::string("material '") + mat.name + "' names an emission map path of " +
             std::to_string(map.length) + " characters (at most " +
             std::to_string(sizeof mat.emission_file - 1) + ")");
    std::snprintf(mat.emission_file, sizeof mat.emission_file, "%s", map.C_Str());
    if (mat.emission[0] <= 0.0f && mat.emission[1] <= 0.0f && mat.emission[2] <= 0.0f)
        mat.emission[0] = mat.emission[1] = mat.emission[2] = 1.0f;
}

/* The parts of a material no path reads yet (docs/scenes.md's feature table). */
void Flattener::note_ignored(const aiMaterial &src, const ssg_gltf_material &mat)
{
    std::string who = std::string("'") + model_adapter::printable(mat.name) + "'";
    float opacity = 1.0f;
    if (src.GetTextureCount(aiTextureType_HEIGHT) > 0)
        ignored.add("bump maps (map_bump, heights; a tangent-space normal map is read "
                    "from norm)", who);
    if (src.Get(AI_MATKEY_OPACITY, opacity) == AI_SUCCESS && opacity < 1.0f)
        ignored.add("opacity below 1 (d, Tr: drawn opaque)", who);
}

void Flattener::convert_materials()
{
    for (unsigned i = 0; i < s.mNumMaterials; i++) {
        const aiMaterial *src = s.mMaterials[i];
        aiString name, tex;
        src->Get(AI_MATKEY_NAME, name);
        aiColor4D diffuse(1.0f, 1.0f, 1.0f, 1.0f);
        bool coloured = src->Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) == AI_SUCCESS;
        bool textured = src->GetTextureCount(aiTextureType_DIFFUSE) > 0;
        bool white = diffuse.r == 1.0f && diffuse.g == 1.0f && diffuse.b == 1.0f;
        bool placeholder = name.length == 0 && white && !textured; /* PLY's, STL's */
        /* "%%%DEFAULT": the grey (0.3) the 3DS reader gives faces without a material */
        placeholder |= std::strcmp(name.C_Str(), "%%%DEFAULT") == 0;
        if (std::strcmp(name.C_Str(), AI_DEFAULT_MATERIAL_NAME) == 0 || placeholder ||
            (!coloured && !textured)) {
            slot.push_back(-1);
            continue;
        }
        ssg_gltf_material mat{};
        std::snprintf(mat.name, sizeof mat.name, "%s", name.C_Str());
        const float rgba[4] = {diffuse.r, diffuse.g, diffuse.b, diffuse.a};
        for (int k = 0; k < 4; k++)
            mat.base_color[k] = std::isfinite(rgba[k]) ? std::fmin(std::fmax(rgba[k], 0.0f), 1.0f)
                                                       : 1.0f;
        mat.texture = -1;
        mat.normal_texture = -1; /* a normal map comes as normal_file, decoded by the caller */
        mat.normal_scale = 1.0f;
        mat.emission_texture = -1; /* an emission map comes as emission_file */
        aiColor3D ke(0, 0, 0);
        if (src->Get(AI_MATKEY_COLOR_EMISSIVE, ke) == AI_SUCCESS) {
            const float e[3] = {ke.r, ke.g, ke.b};
            for (int k = 0; k < 3; k++)
                mat.emission[k] = std::isfinite(e[k]) && e[k] > 0.0f ? e[k] : 0.0f;
        }
        read_emission_map(*src, mat);
        if (src->GetTexture(aiTextureType_DIFFUSE, 0, &tex) == AI_SUCCESS && tex.length) {
            if (tex.length >= sizeof mat.texture_file)
                fail(std::string("material '") + name.C_Str() + "' names a texture path of " +
                     std::to_string(tex.length) + " characters (at most " +
                     std::to_string(sizeof mat.texture_file - 1) + ")");
            std::snprintf(mat.texture_file, sizeof mat.texture_file, "%s", tex.C_Str());
        }
        aiString normals;
        if (src->GetTexture(aiTextureType_NORMALS, 0, &normals) == AI_SUCCESS &&
            normals.length) {
            if (normals.length >= sizeof mat.normal_file)
                fail(std::string("material '") + name.C_Str() + "' names a normal map path "
                     "of " + std::to_string(normals.length) + " characters (at most " +
                     std::to_string(sizeof mat.normal_file - 1) + ")");
            std::snprintf(mat.normal_file, sizeof mat.normal_file, "%s", normals.C_Str());
        }
        /* an OBJ's map_d (opacity texture) masks the surface as glTF's MASK at 0.5: the
           diffuse texture's own alpha when it names that file, else its own file's
           coverage (opacity_file, decoded by the caller) */
        aiString opacity;
        mat.alpha_cutoff = 0.5f;
        if (src->GetTexture(aiTextureType_OPACITY, 0, &opacity) == AI_SUCCESS &&
            opacity.length) {
            mat.alpha_mode = SSG_ALPHA_MASK;
            if (opacity.length >= sizeof mat.opacity_file)
                fail(std::string("material '") + name.C_Str() + "' names an opacity map "
                     "path of " + std::to_string(opacity.length) + " characters (at most " +
                     std::to_string(sizeof mat.opacity_file - 1) + ")");
            if (std::strcmp(opacity.C_Str(), mat.texture_file) != 0)
                std::snprintf(mat.opacity_file, sizeof mat.opacity_file, "%s", opacity.C_Str());
        }
        note_ignored(*src, mat);
        slot.push_back((int)materials.size());
        materials.push_back(mat);
    }
}

void Flattener::run()
{
    convert_materials();
    if (!s.mRootNode)
        fail("the file has no node hierarchy");
    visit(s.mRootNode, aiMatrix4x4(), 0);
    if (prims.empty())
        fail("no triangles in it (points, lines or an empty file?)");
}

void Flattener::visit(const aiNode *node, const aiMatrix4x4 &parent, int depth)
{
    if (depth > 64 || ++visits > (1u << 20))
        fail("node hierarchy deeper than 64 levels or over 2^20 node instances");
    aiMatrix4x4 world = parent * node->mTransformation;
    for (unsigned i = 0; i < node->mNumMeshes; i++) {
        unsigned index = node->mMeshes[i];
        if (index >= s.mNumMeshes)
            fail("a node names missing mesh " + std::to_string(index));
        add_mesh(*s.mMeshes[index], world);
    }
    for (unsigned i = 0; i < node->mNumChildren; i++)
        visit(node->mChildren[i], world, depth + 1);
}

/* A vertex colour of an Assimp format as linear RGB: PLY's and OBJ's colours are display
   colours (sRGB), unlike glTF's COLOR_0 (linear by the specification); alpha not read. */
static void add_colour(const aiColor4D &c, std::vector<float> &out)
{
    for (float x : {c.r, c.g, c.b}) {
        x = std::isfinite(x) ? std::min(std::max(x, 0.0f), 1.0f) : 0.0f;
        out.push_back(model_adapter::srgb_to_linear(x));
    }
}

void Flattener::add_mesh(const aiMesh &mesh, const aiMatrix4x4 &world)
{
    Prim out;
    for (unsigned f = 0; f < mesh.mNumFaces; f++) {
        const aiFace &face = mesh.mFaces[f];
        if (face.mNumIndices != 3)
            continue; /* a point or line Assimp kept: not a surface */
        for (unsigned k = 0; k < 3; k++) {
            if (face.mIndices[k] >= mesh.mNumVertices)
                fail("face index " + std::to_string(face.mIndices[k]) + " out of range");
            out.indices.push_back(face.mIndices[k]);
        }
    }
    if (out.indices.empty())
        return;
    double c[9], det;
    cofactor(world, c, &det);
    const double sign = det < 0 ? -1.0 : 1.0;
    for (unsigned v = 0; v < mesh.mNumVertices; v++) {
        aiVector3D p = world * mesh.mVertices[v];
        out.positions.insert(out.positions.end(), {p.x, p.y, p.z});
        double n[3] = {0, 1, 0}, len = 0;
        if (mesh.mNormals) {
            const aiVector3D &m = mesh.mNormals[v];
            for (int r = 0; r < 3; r++)
                n[r] = c[3 * r] * m.x + c[3 * r + 1] * m.y + c[3 * r + 2] * m.z;
            len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        }
        if (!(len > 0) || !std::isfinite(len)) /* degenerate triangles get NaN normals */
            n[0] = 0, n[1] = 1, n[2] = 0, len = sign;
        for (int r = 0; r < 3; r++)
            out.normals.push_back((float)(n[r] * sign / len));
        if (mesh.mTextureCoords[0]) {
            const aiVector3D &t = mesh.mTextureCoords[0][v];
            out.uvs.push_back(std::isfinite(t.x) ? t.x : 0.0f);
            out.uvs.push_back(std::isfinite(t.y) ? t.y : 0.0f);
        }
        if (mesh.HasVertexColors(0))
            add_colour(mesh.mColors[0][v], out.colors);
    }
    if (det < 0) /* a mirroring transform flips the winding; flip it back */
        for (size_t t = 0; t < out.indices.size(); t += 3)
            std::swap(out.indices[t + 1], out.indices[t + 2]);
    out.material = mesh.mMaterialIndex < slot.size() ? slot[mesh.mMaterialIndex] : -1;
    prims.push_back(std::move(out));
}

ssg_gltf *Flattener::to_c() const
{
    return model_adapter::to_c(prims, materials, {}, nullptr, ignored);
}

/* A face with no index (a PLY list of length 0) is typed a polygon by Assimp's scene
   preprocessor, and its triangulation then fails an assertion that aborts the process
   (Debian builds Assimp with ai_assert; TriangulateProcess.cpp: numOut != mNumFaces).
   Such faces are dropped, and the mesh's primitive types recomputed from what is left. */
void drop_empty_faces(const aiScene &scene)
{
    for (unsigned m = 0; m < scene.mNumMeshes; m++) {
        aiMesh &mesh = *scene.mMeshes[m]; /* the importer's own scene, mended in place */
        unsigned kept = 0, types = 0;
        for (unsigned f = 0; f < mesh.mNumFaces; f++) {
            aiFace &face = mesh.mFaces[f];
            if (!face.mNumIndices || !face.mIndices)
                continue;
            std::swap(mesh.mFaces[kept].mNumIndices, face.mNumIndices);
            std::swap(mesh.mFaces[kept].mIndices, face.mIndices); /* freed with the array */
            unsigned n = mesh.mFaces[kept++].mNumIndices;
            types |= n == 1 ? aiPrimitiveType_POINT : n == 2 ? aiPrimitiveType_LINE
                     : n == 3 ? aiPrimitiveType_TRIANGLE : aiPrimitiveType_POLYGON;
        }
        if (kept < mesh.mNumFaces)
            mesh.mNumFaces = kept, mesh.mPrimitiveTypes = types;
    }
}

/* Mesh m's vertex v, as a message names it: "mesh 0 ('Cube') vertex 3". */
std::string vertex_name(const aiMesh &mesh, unsigned m, unsigned v)
{
    std::string name = printable(std::string(mesh.mName.C_Str()));
    return "mesh " + std::to_string(m) + (name.empty() ? "" : " ('" + name + "')") +
           " vertex " + std::to_string(v);
}

std::string show(const aiVector3D &p, int n)
{
    std::string text = "(";
    for (int k = 0; k < n; k++) {
        char one[32];
        std::snprintf(one, sizeof one, "%s%g", k ? ", " : "", (double)p[(unsigned)k]);
        text += one;
    }
    return text + ")";
}

bool finite(const aiVector3D &p, int n)
{
    for (int k = 0; k < n; k++)
        if (!std::isfinite(p[(unsigned)k]))
            return false;
    return true;
}

/* NaN or infinity in what the file holds for a vertex, as read (before the post-processing
   steps): a position would poison the bounds, the scene `check` suggests and the ray
   tracer; a normal or texture coordinate means a broken file too, and is refused as the
   glTF reader refuses it. The 3DS reader makes its normals itself (from smoothing groups,
   NaN on a degenerate face), so its normals are left to add_mesh's replacement. */
void check_finite(const aiScene &scene, const std::string &format)
{
    for (unsigned m = 0; m < scene.mNumMeshes; m++) {
        if (!scene.mMeshes[m] || !scene.mMeshes[m]->mVertices)
            continue; /* the validation step (after this) refuses it */
        const aiMesh &mesh = *scene.mMeshes[m];
        const aiVector3D *normals = format == "3DS" ? nullptr : mesh.mNormals;
        for (unsigned v = 0; v < mesh.mNumVertices; v++) {
            const char *what = !finite(mesh.mVertices[v], 3) ? "position"
                               : normals && !finite(normals[v], 3) ? "normal"
                               : mesh.mTextureCoords[0] && !finite(mesh.mTextureCoords[0][v], 2)
                                   ? "texture coordinate"
                                   : nullptr;
            if (!what)
                continue;
            const aiVector3D &p = what[0] == 'p' ? mesh.mVertices[v]
                                  : what[0] == 'n' ? normals[v] : mesh.mTextureCoords[0][v];
            fail(vertex_name(mesh, m, v) + ": its " + what + " is " +
                 show(p, what[0] == 't' ? 2 : 3) + " (expected finite values)");
        }
    }
}

/* "OBJ" for "cup.obj": the format as a message names it. */
std::string format_name(const char *path)
{
    const char *slash = std::strrchr(path, '/');
    const char *dot = std::strrchr(slash ? slash + 1 : path, '.');
    std::string name = dot ? dot + 1 : "";
    for (char &ch : name)
        ch = (char)std::toupper((unsigned char)ch);
    return name == "GLTF" || name == "GLB" ? "glTF 1.0" : name.empty() ? "a model" : name;
}

/* The up axis after the import, from what the reader did or left in the metadata. Only
   readers checked by tests/test_models.sh are named: 3DS and Collada convert, FBX keeps
   the file's axes and says which is up, OBJ, PLY and STL carry none. */
void find_up(const aiScene &scene, const std::string &format, ssg_model_up *up)
{
    int32_t axis = -1, sign = 1;
    const aiMetadata *meta = scene.mMetaData;
    if (meta && meta->Get("UpAxis", axis) && axis >= 0 && axis <= 2) {
        meta->Get("UpAxisSign", sign);
        *up = ssg_model_up{(int)axis, sign < 0 ? -1 : 1, "", 0, 0};
        std::snprintf(up->basis, sizeof up->basis, "the file's UpAxis metadata (%c%c), kept "
                      "as written by Assimp's %s reader", sign < 0 ? '-' : '+', "XYZ"[axis],
                      format.c_str());
    } else if (format == "3DS") {
        /* the reader turns every file as if made Z-up; one made Y-up elsewhere (Debian's
           glmark2 cat.3ds) comes out lying on its side, -Z up, and the file cannot say */
        *up = ssg_model_up{1, 1, "Assimp's 3DS reader, which turns 3ds Max's Z-up into +Y",
                           2, -1};
    } else if (format == "DAE") {
        *up = ssg_model_up{1, 1, "Assimp's Collada reader, which turns the file's <up_axis> "
                                 "into +Y", 0, 0};
    } else if (format == "glTF 1.0") {
        *up = ssg_model_up{1, 1, "the glTF 1.0 specification (+Y up)", 0, 0};
    } else {
        *up = ssg_model_up{-1, 1, "", 0, 0};
        std::snprintf(up->basis, sizeof up->basis, "nothing: %s files do not say which way "
                      "is up", format.c_str());
    }
}

/* Reads path; with up, finds its up axis; with flatten, returns the meshes. */
ssg_gltf *load(const char *path, ssg_model_up *up, bool flatten)
{
    char why[256];
    enum ssg_err e = ssg_input_check(path, SSG_MAX_MODEL_BYTES, why, sizeof why);
    if (e) /* an unreadable file is reported the way every input is */
        throw Failure{e, why};
    Assimp::Importer importer;
    InputIO *io = new InputIO;
    importer.SetIOHandler(io); /* the importer owns it */
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    /* Normals made for a file without any keep edges sharper than 80 degrees (a box's) */
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 80.0f);
    const unsigned steps = aiProcess_Triangulate | aiProcess_SortByPType |
                           aiProcess_GenSmoothNormals | aiProcess_JoinIdenticalVertices |
                           aiProcess_FlipUVs | aiProcess_ValidateDataStructure;
    /* read first, then mend, then post-process: a face without indices kills the process
       in Assimp's triangulation (below); the up axis alone needs none of the steps */
    const aiScene *scene = importer.ReadFile(path, 0u);
    std::string format = format_name(path);
    if (scene && flatten) {
        check_finite(*scene, format);
        drop_empty_faces(*importer.GetScene());
        scene = importer.ApplyPostProcessing(steps);
    }
    if (!io->failed.empty())
        fail("a file it names cannot be read: " + printable(io->failed));
    if (!scene) {
        std::string error = printable(importer.GetErrorString());
        if (error.find("mNumMeshes is 0") != std::string::npos)
            error = "no meshes in it (an empty or broken file?)";
        if (error.find("bad_alloc") != std::string::npos) /* Assimp caught it: we report it */
            throw std::bad_alloc();
        fail("Assimp could not read it as " + format + ": " + error);
    }
    if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
        fail("Assimp read it as " + format + " only in part (no meshes: a broken file?)");
    if (up)
        find_up(*scene, format, up);
    if (!flatten)
        return nullptr;
    Flattener flat(*scene);
    flat.run();
    return flat.to_c();
}

} // namespace

extern "C" int ssg_assimp_supports(const char *ext)
{
    try {
        Assimp::Importer importer;
        return importer.IsExtensionSupported(ext) ? 1 : 0;
    } catch (...) {
        return 0;
    }
}

extern "C" enum ssg_err ssg_assimp_load(const char *path, struct ssg_gltf **out,
                                        struct ssg_model_up *up, char *why, size_t why_len)
{
    ssg_gltf *none = nullptr;
    return model_adapter::guarded(path, out ? out : &none, why, why_len,
                                  [&] { return load(path, up, out != nullptr); }, "Assimp");
}
