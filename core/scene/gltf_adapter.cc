/* gltf_adapter.cc - the C++ side of gltf.h: reads a glTF 2.0 file with the Debian build of
 * tinygltf (libtinygltf.so, images decoded by its built-in stb loader) and flattens the
 * default scene into world-space triangle meshes, materials, textures and a camera.
 *
 * Everything is gathered in std::vector first and copied into malloc'd C arrays only once
 * the whole file has been read, so a failure half-way frees itself. Problems are thrown as
 * Failure (gltf_adapter.h) and caught in ssg_gltf_load: no exception leaves it. Reading
 * the buffers behind accessors, with their bounds checks, is gltf_accessor_adapter.cc. */
#include "scene/gltf_adapter.h"

extern "C" {
#include "lang/files.h"
}

#include <algorithm>
#include <array>
#include <cerrno>
#include <sys/stat.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace {

using gltf_adapter::Failure;
using gltf_adapter::fail;
using gltf_adapter::read_floats;
using gltf_adapter::read_indices;
using gltf_adapter::shown;

using Mat4 = std::array<double, 16>; /* column-major, as glTF stores it */

Mat4 identity()
{
    return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

Mat4 multiply(const Mat4 &a, const Mat4 &b)
{
    Mat4 r{};
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++)
            for (int k = 0; k < 4; k++)
                r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
    return r;
}

/* T * R * S, the order glTF defines for a node's TRS properties. */
Mat4 trs_matrix(const tinygltf::Node &node)
{
    double t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1};
    if (node.translation.size() == 3)
        for (int i = 0; i < 3; i++) t[i] = node.translation[i];
    if (node.rotation.size() == 4)
        for (int i = 0; i < 4; i++) q[i] = node.rotation[i];
    if (node.scale.size() == 3)
        for (int i = 0; i < 3; i++) s[i] = node.scale[i];
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w),
                         2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w),
                         2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)};
    Mat4 m = identity();
    for (int c = 0; c < 3; c++)
        for (int row = 0; row < 3; row++) m[c * 4 + row] = r[c * 3 + row] * s[c];
    for (int i = 0; i < 3; i++) m[12 + i] = t[i];
    return m;
}

Mat4 local_matrix(const tinygltf::Node &node)
{
    if (node.matrix.size() == 16) {
        Mat4 m;
        for (int i = 0; i < 16; i++) m[i] = node.matrix[i];
        return m;
    }
    return trs_matrix(node);
}

/* Cofactor matrix of the upper 3x3: proportional to the inverse transpose, which is what
 * carries normals through a non-uniform scale. */
std::array<double, 9> normal_matrix(const Mat4 &m, double *det)
{
    auto e = [&](int row, int col) { return m[col * 4 + row]; };
    std::array<double, 9> c;
    for (int row = 0; row < 3; row++)
        for (int col = 0; col < 3; col++) {
            int r1 = (row + 1) % 3, r2 = (row + 2) % 3, c1 = (col + 1) % 3, c2 = (col + 2) % 3;
            c[col * 3 + row] = e(r1, c1) * e(r2, c2) - e(r1, c2) * e(r2, c1);
        }
    *det = e(0, 0) * c[0] + e(0, 1) * c[3] + e(0, 2) * c[6];
    return c;
}

/* Turns strips and fans into a triangle list; lines and points are not surfaces. */
std::vector<uint32_t> triangle_list(const std::vector<uint32_t> &idx, int mode,
                                    const std::string &where)
{
    std::vector<uint32_t> tris;
    size_t n = idx.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        if (n % 3)
            fail(where + ": index count " + std::to_string(n) + " is not a multiple of 3");
        return idx;
    }
    if (mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
        fail(where + ": mode " + std::to_string(mode) +
             " is not a triangle mode (expected 4 TRIANGLES, 5 STRIP or 6 FAN)");
    for (size_t i = 0; i + 2 < n; i++) {
        uint32_t a = idx[i], b = idx[i + 1], c = idx[i + 2];
        if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
            a = idx[0];
        else if (i % 2)
            std::swap(a, b); /* keep the winding of odd strip triangles */
        tris.insert(tris.end(), {a, b, c});
    }
    return tris;
}

/* Area-weighted smooth normals for primitives that come without any. */
std::vector<float> compute_normals(const std::vector<float> &p, const std::vector<uint32_t> &idx)
{
    std::vector<float> n(p.size(), 0.0f);
    for (size_t t = 0; t + 2 < idx.size(); t += 3) {
        const float *a = &p[3 * idx[t]], *b = &p[3 * idx[t + 1]], *c = &p[3 * idx[t + 2]];
        float e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        float e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        float f[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                      e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++) n[3 * idx[t + (size_t)k] + (size_t)j] += f[j];
    }
    return n;
}

using model_adapter::Prim;
using model_adapter::printable;
using model_adapter::Tex;

class Flattener {
  public:
    explicit Flattener(const tinygltf::Model &model) : m(model), mats(model) {}
    void run();
    ssg_gltf *to_c() const;

  private:
    const tinygltf::Model &m;
    std::vector<Prim> prims;
    gltf_adapter::Materials mats; /* its materials, textures and what is not read */
    std::vector<ssg_light> lights; /* KHR_lights_punctual's, world space */
    bool has_camera = false;
    ssg_camera camera{};
    size_t visits = 0; /* node instances seen, against shared subtrees blowing up */

    void visit(int node, const Mat4 &parent, int depth);
    void add_primitive(const tinygltf::Primitive &p, const Mat4 &world, const std::string &where);
    void add_camera(int index, const Mat4 &world);
    void add_light(const tinygltf::Node &node, const Mat4 &world);
    void read_tangents(const tinygltf::Primitive &p, Prim &out, const Mat4 &world,
                       bool mirrored, const std::string &where);
};

void Flattener::run()
{
    mats.convert();
    for (const std::string &x : m.extensionsUsed) {
        /* the material extensions' rows name the materials; quantized attributes are read
           as any accessor (gltf_accessor_adapter.cc) */
        if (x == "KHR_texture_transform" || x == "KHR_mesh_quantization" ||
            x == "KHR_materials_emissive_strength")
            continue;
        if (x != "KHR_lights_punctual") /* read; its spot lights are listed one by one */
            mats.ignored.add("extension " + printable(x), "");
    }
    std::vector<int> roots;
    if (!m.scenes.empty()) {
        size_t s = m.defaultScene >= 0 ? (size_t)m.defaultScene : 0;
        if (s >= m.scenes.size())
            fail("default scene " + std::to_string(s) + " does not exist");
        roots = m.scenes[s].nodes;
    } else { /* no scene at all: every node that is nobody's child is a root */
        std::vector<bool> child(m.nodes.size(), false);
        for (const tinygltf::Node &n : m.nodes)
            for (int c : n.children)
                if (c >= 0 && (size_t)c < child.size()) child[(size_t)c] = true;
        for (size_t i = 0; i < m.nodes.size(); i++)
            if (!child[i]) roots.push_back((int)i);
    }
    for (int r : roots) visit(r, identity(), 0);
}

void Flattener::visit(int index, const Mat4 &parent, int depth)
{
    if (index < 0 || (size_t)index >= m.nodes.size())
        fail("node " + std::to_string(index) + " does not exist");
    if (depth > 64 || ++visits > (1u << 20))
        fail("node hierarchy deeper than 64 levels or over 2^20 node instances (a cycle?)");
    const tinygltf::Node &node = m.nodes[(size_t)index];
    Mat4 world = multiply(parent, local_matrix(node));
    if (node.mesh >= 0) {
        if ((size_t)node.mesh >= m.meshes.size())
            fail("node " + std::to_string(index) + " names missing mesh " +
                 std::to_string(node.mesh));
        const tinygltf::Mesh &mesh = m.meshes[(size_t)node.mesh];
        for (size_t p = 0; p < mesh.primitives.size(); p++)
            add_primitive(mesh.primitives[p], world,
                          "mesh " + std::to_string(node.mesh) + " primitive " + std::to_string(p));
    }
    add_light(node, world);
    if (node.camera >= 0 && (size_t)node.camera < m.cameras.size() && !has_camera &&
        m.cameras[(size_t)node.camera].type == "perspective")
        add_camera(node.camera, world);
    for (int c : node.children) visit(c, world, depth + 1);
}

int attribute(const tinygltf::Primitive &p, const std::string &name)
{
    auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}

void transform_points(std::vector<float> &v, const Mat4 &m)
{
    for (size_t i = 0; i + 2 < v.size(); i += 3) {
        double x = v[i], y = v[i + 1], z = v[i + 2];
        for (int r = 0; r < 3; r++)
            v[i + (size_t)r] = (float)(m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r]);
    }
}

/* A material's KHR_texture_transform baked into its mesh's uvs. */
void transform_uvs(std::vector<float> &uv, const gltf_adapter::UvTransform &t)
{
    if (t == gltf_adapter::UV_IDENTITY)
        return;
    for (size_t i = 0; i + 1 < uv.size(); i += 2) {
        double u = uv[i], v = uv[i + 1];
        uv[i] = (float)(t[0] * u + t[1] * v + t[2]);
        uv[i + 1] = (float)(t[3] * u + t[4] * v + t[5]);
    }
}

void transform_normals(std::vector<float> &v, const Mat4 &m)
{
    double det;
    std::array<double, 9> c = normal_matrix(m, &det);
    double sign = det < 0 ? -1.0 : 1.0;
    for (size_t i = 0; i + 2 < v.size(); i += 3) {
        double n[3];
        for (int r = 0; r < 3; r++)
            n[r] = c[(size_t)r] * v[i] + c[3 + (size_t)r] * v[i + 1] + c[6 + (size_t)r] * v[i + 2];
        double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double s = len > 0 ? sign / len : 0.0;
        if (len <= 0) /* a degenerate normal still has to be a unit vector */
            n[1] = 1.0, s = 1.0;
        for (int r = 0; r < 3; r++) v[i + (size_t)r] = (float)(n[r] * s);
    }
}

void Flattener::add_primitive(const tinygltf::Primitive &p, const Mat4 &world,
                              const std::string &where)
{
    int pos = attribute(p, "POSITION");
    if (pos < 0)
        fail(where + " has no POSITION attribute");
    Prim out;
    out.positions = read_floats(m, pos, 3);
    size_t nv = out.positions.size() / 3;
    std::vector<uint32_t> idx;
    if (p.indices >= 0)
        idx = read_indices(m, p.indices);
    else
        for (size_t i = 0; i < nv; i++) idx.push_back((uint32_t)i);
    out.indices = triangle_list(idx, p.mode < 0 ? TINYGLTF_MODE_TRIANGLES : p.mode, where);
    for (uint32_t i : out.indices)
        if (i >= nv)
            fail(where + ": index " + std::to_string(i) + " out of range (" +
                 std::to_string(nv) + " vertices)");
    if (out.indices.empty())
        return;
    int col = attribute(p, "COLOR_0");
    if (col >= 0) { /* VEC3 or VEC4 (its alpha not read), float or normalised integers */
        int n = m.accessors[(size_t)col].type == TINYGLTF_TYPE_VEC4 ? 4 : 3;
        std::vector<float> c = read_floats(m, col, n);
        for (size_t i = 0; i + (size_t)n <= c.size(); i += (size_t)n)
            for (int k = 0; k < 3; k++)
                out.colors.push_back(c[i + (size_t)k]);
    }
    if (!out.colors.empty() && out.colors.size() / 3 != nv)
        fail(where + ": COLOR_0 count differs from POSITION count");
    int nrm = attribute(p, "NORMAL");
    out.normals = nrm >= 0 ? read_floats(m, nrm, 3) : compute_normals(out.positions, out.indices);
    if (out.normals.size() != out.positions.size())
        fail(where + ": NORMAL count differs from POSITION count");
    out.material = p.material >= 0 && (size_t)p.material < mats.materials.size() ? p.material : -1;
    int set = out.material >= 0 ? mats.materials[(size_t)out.material].texcoord : 0;
    int uv = attribute(p, "TEXCOORD_" + std::to_string(set));
    if (uv >= 0) {
        out.uvs = read_floats(m, uv, 2);
        if (out.uvs.size() / 2 != nv)
            fail(where + ": TEXCOORD count differs from POSITION count");
        if (out.material >= 0)
            transform_uvs(out.uvs, mats.uv_transforms[(size_t)out.material]);
    }
    transform_points(out.positions, world);
    transform_normals(out.normals, world);
    double det;
    normal_matrix(world, &det);
    read_tangents(p, out, world, det < 0, where);
    if (det < 0) /* a mirroring transform flips the winding; flip it back */
        for (size_t t = 0; t < out.indices.size(); t += 3)
            std::swap(out.indices[t + 1], out.indices[t + 2]);
    prims.push_back(std::move(out));
}

/* The camera a scene starts from is refused, never dropped, when glTF forbids its values
   (yfov and znear > 0, zfar > znear) or its node gives it no direction: a camera that
   silently vanished left the user framing the bounds without knowing why. A field of
   view past 1 to 179 degrees is refused too (the scene format's range). */

/* A spot light's cone (radians in glTF: 0 <= inner < outer <= pi / 2) into l, in the
   scene format's range (outer at most 89 degrees, inner at most outer); a point or
   directional light gets no cone. */
static void set_cone(const tinygltf::Light &src, const std::string &who, ssg_light *l)
{
    double inner = src.spot.innerConeAngle * 180.0 / M_PI;
    double outer = src.spot.outerConeAngle * 180.0 / M_PI;
    if (l->kind == SSG_LIGHT_SPOT && !(inner >= 0 && outer > 0 && inner <= outer &&
                                       outer <= 90.0 + 1e-6))
        fail("spot light " + who + ": innerConeAngle " +
                            std::to_string(src.spot.innerConeAngle) + " and outerConeAngle " +
                            std::to_string(src.spot.outerConeAngle) +
                            " (expected 0 <= inner <= outer <= pi/2, radians)");
    outer = std::min(outer, 89.0);
    ssg_light_set_cone(l, (float)std::min(inner, outer), (float)outer);
}

/* A node's KHR_lights_punctual light (its extension's "light" index): a point or spot
   light at the node's origin, a directional or spot one along its -Z axis; colour
   (default white) and intensity as given, glTF's candela or lux read as ssgraph's W/sr or
   W/m^2, a spot's cone as spot_light's. A light's range is not read: it is listed as
   ignored. */
void Flattener::add_light(const tinygltf::Node &node, const Mat4 &w)
{
    auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end() || !ext->second.Has("light"))
        return;
    int index = ext->second.Get("light").GetNumberAsInt();
    if (index < 0 || (size_t)index >= m.lights.size())
        fail("a node names KHR_lights_punctual light " + std::to_string(index) +
             ", which does not exist");
    const tinygltf::Light &src = m.lights[(size_t)index];
    std::string who = src.name.empty() ? "light " + std::to_string(index)
                                       : "'" + model_adapter::printable(src.name) + "'";
    if (src.type != "point" && src.type != "directional" && src.type != "spot")
        fail("KHR_lights_punctual light " + who + " has type '" +
             model_adapter::printable(src.type) + "' (expected point, spot or directional)");
    if (src.range > 0)
        mats.ignored.add("light ranges (KHR_lights_punctual range: a light falls off as "
                         "1/d^2 without a cut-off)", who);
    ssg_light l{};
    l.kind = src.type == "point" ? SSG_LIGHT_POINT
             : src.type == "spot" ? SSG_LIGHT_SPOT : SSG_LIGHT_DIRECTIONAL;
    double axis[3] = {-w[8], -w[9], -w[10]}; /* the node's -z: where glTF lights point */
    double len = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    if (l.kind != SSG_LIGHT_POINT && !(len > 0 && std::isfinite(len)))
        fail(src.type + " light " + who + ": its node's transform leaves it no direction");
    set_cone(src, who, &l);
    for (int i = 0; i < 3; i++) {
        l.position[i] = (float)w[12 + i];
        l.direction[i] = l.kind != SSG_LIGHT_POINT ? (float)(axis[i] / len) : 0.0f;
        l.color[i] = src.color.size() == 3 ? (float)src.color[(size_t)i] : 1.0f;
    }
    l.intensity = (float)src.intensity;
    if (!(l.intensity >= 0) || !std::isfinite(l.intensity) ||
        !(l.color[0] >= 0 && l.color[1] >= 0 && l.color[2] >= 0) ||
        !std::isfinite(l.color[0] + l.color[1] + l.color[2]))
        fail("light " + who + ": colour and intensity must be finite and >= 0");
    lights.push_back(l);
}

void Flattener::add_camera(int index, const Mat4 &w)
{
    const tinygltf::Camera &cam = m.cameras[(size_t)index];
    const tinygltf::PerspectiveCamera &p = cam.perspective;
    std::string name = "camera " + std::to_string(index) +
                       (cam.name.empty() ? "" : " ('" + printable(cam.name) + "')");
    double degrees = p.yfov * 180.0 / 3.14159265358979323846;
    if (!(degrees >= 1.0 && degrees <= 179.0))
        fail(name + ": yfov " + shown(p.yfov) + " rad (" + shown(degrees) +
             " degrees) is outside 1 to 179 degrees (0.0175 to 3.124 rad; glTF's yfov is in "
             "radians and must be above 0)");
    if (!(p.znear > 0.0) || !std::isfinite(p.znear))
        fail(name + ": znear " + shown(p.znear) + " is not a finite distance above "
             "0 (glTF requires znear > 0)");
    if (!(p.zfar >= 0.0) || !std::isfinite(p.zfar) || (p.zfar > 0.0 && p.zfar <= p.znear))
        fail(name + ": zfar " + shown(p.zfar) + " is not beyond znear " +
             shown(p.znear) + " (glTF requires zfar > znear, or no zfar)");
    double fwd[3] = {-w[8], -w[9], -w[10]}, up[3] = {w[4], w[5], w[6]};
    double fl = std::sqrt(fwd[0] * fwd[0] + fwd[1] * fwd[1] + fwd[2] * fwd[2]);
    double ul = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    if (!(fl > 0) || !(ul > 0) || !std::isfinite(fl) || !std::isfinite(ul))
        fail(name + ": its node's transform leaves it no direction to look in (a zero or "
             "non-finite scale)");
    for (int i = 0; i < 3; i++) {
        camera.position[i] = (float)w[12 + i];
        camera.target[i] = (float)(w[12 + i] + fwd[i] / fl);
        camera.up[i] = (float)(up[i] / ul);
    }
    camera.fov_y = (float)degrees;
    camera.near_z = (float)p.znear;
    /* zfar absent means an infinite projection; use a far plane well past the near one */
    camera.far_z = (float)(p.zfar > p.znear ? p.zfar : std::fmax(100.0, p.znear * 1e4));
    has_camera = true;
}

/* A normal-mapped primitive's TANGENT (xyzw, glTF 2.0 3.7.2.1) into world space: xyz as a
   direction of the node's transform, normalised; w flips with a mirroring transform, as the
   bitangent does. A mesh without them gets them made from its uvs (scene_shapes.h). */
void Flattener::read_tangents(const tinygltf::Primitive &p, Prim &out, const Mat4 &world,
                              bool mirrored, const std::string &where)
{
    int tan = attribute(p, "TANGENT");
    if (tan < 0 || out.material < 0 || mats.materials[(size_t)out.material].normal_texture < 0)
        return;
    out.tangents = read_floats(m, tan, 4);
    if (out.tangents.size() != out.positions.size() / 3 * 4)
        fail(where + ": TANGENT count differs from POSITION count");
    for (size_t i = 0; i + 3 < out.tangents.size(); i += 4) {
        double x = out.tangents[i], y = out.tangents[i + 1], z = out.tangents[i + 2], d[3];
        for (int r = 0; r < 3; r++)
            d[r] = world[r] * x + world[4 + r] * y + world[8 + r] * z;
        double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int r = 0; r < 3; r++)
            out.tangents[i + (size_t)r] = (float)(len > 0 ? d[r] / len : 0.0);
        out.tangents[i + 3] = (out.tangents[i + 3] < 0) != mirrored ? -1.0f : 1.0f;
    }
}

ssg_gltf *Flattener::to_c() const
{
    return model_adapter::to_c(prims, mats.materials, mats.textures,
                               has_camera ? &camera : nullptr, mats.ignored, lights);
}

/* tinygltf reads the buffers and images a glTF names through this: the same rules as
   every input (files.h): a regular file, at most SSG_MAX_MODEL_BYTES. A buffer URI naming
   /dev/zero or a FIFO is refused instead of read without end. */
bool read_whole_file(std::vector<unsigned char> *out, std::string *err,
                     const std::string &path, void *)
{
    char *data = nullptr, why[256];
    size_t len = 0;
    if (ssg_input_read(path.c_str(), SSG_MAX_MODEL_BYTES, &data, &len, why, sizeof why)) {
        if (err)
            *err += path + ": " + why + "\n";
        return false;
    }
    out->assign(data, data + len);
    std::free(data);
    return true;
}

/* Anything that exists "exists": read_whole_file then refuses what is not a plain file
   with its reason, rather than tinygltf falling back to a file of that name elsewhere. */
bool file_exists(const std::string &path, void *)
{
    struct stat st;
    return stat(path.c_str(), &st) == 0;
}

std::string expand_nothing(const std::string &path, void *)
{
    return path;
}

bool write_nothing(std::string *err, const std::string &, const std::vector<unsigned char> &,
                   void *)
{
    if (err)
        *err += "ssgraph does not write glTF files";
    return false;
}

std::string base_dir(const char *path)
{
    const char *slash = std::strrchr(path, '/');
    if (slash == path)
        return "/";
    return slash ? std::string(path, (size_t)(slash - path)) : std::string(".");
}

ssg_gltf *load(const char *path)
{
    char *data = nullptr, why[256];
    size_t len = 0;
    enum ssg_err e = ssg_input_read(path, SSG_MAX_MODEL_BYTES, &data, &len, why, sizeof why);
    if (e)
        throw Failure{e, why};
    std::unique_ptr<char, decltype(&std::free)> owned(data, &std::free);
    int major, draco;
    ssg_gltf_sniff(data, len, &major, &draco);
    if (major == 1)
        fail("glTF 1.0 file (tinygltf reads glTF 2.0; model.h sends 1.0 to Assimp)");
    if (draco)
        fail("Draco-compressed meshes (KHR_draco_mesh_compression) are not supported: "
             "export the model without mesh compression");
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({file_exists, expand_nothing, read_whole_file, write_nothing, nullptr});
    std::string err, warn, dir = base_dir(path);
    const unsigned char *bytes = reinterpret_cast<const unsigned char *>(data);
    bool binary = len >= 4 && std::memcmp(data, "glTF", 4) == 0;
    if (len > 0xffffffffu)
        fail("file too large for tinygltf (4 GiB)");
    bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes,
                                                   (unsigned)len, dir)
                     : loader.LoadASCIIFromString(&model, &err, &warn, data, (unsigned)len, dir);
    if (!ok) { /* JSON errors quote raw bytes of the file */
        err = model_adapter::printable(err);
        fail(err.empty() ? "tinygltf could not parse it" : err);
    }
    Flattener flat(model);
    flat.run();
    return flat.to_c();
}

} // namespace

namespace gltf_adapter {

std::string shown(double x)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

} // namespace gltf_adapter

extern "C" enum ssg_err ssg_gltf_load(const char *path, struct ssg_gltf **out, char *why,
                                      size_t why_len)
{
    return model_adapter::guarded(path, out, why, why_len, load, "tinygltf");
}

extern "C" void ssg_gltf_destroy(struct ssg_gltf **gltf)
{
    if (!gltf || !*gltf)
        return;
    model_adapter::free_model(*gltf);
    *gltf = nullptr;
}
