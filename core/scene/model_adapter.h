/* model_adapter.h - private to the two model readers, the tinygltf adapter
 * (gltf_adapter.cc) and the Assimp adapter (assimp_adapter.cc): what both gather while
 * reading a file, the one copy into the C struct ssg_gltf (gltf.h) once the whole file has
 * been read, and the one boundary where their exceptions become an error code and a
 * message. C++ only; no shared state. */
#ifndef SSG_MODEL_ADAPTER_H
#define SSG_MODEL_ADAPTER_H

#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scene/gltf.h"

namespace model_adapter {

/* A problem with the file, thrown while reading it and caught by guarded(). */
struct Failure {
    ssg_err code;
    std::string message;
};

[[noreturn]] inline void fail(const std::string &message)
{
    throw Failure{SSG_E_GLTF, message};
}

/* An sRGB-encoded value in [0, 1] as linear light (IEC 61966-2-1). */
inline float srgb_to_linear(float c)
{
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

/* A triangle mesh gathered in C++ containers until the whole file has loaded. */
struct Prim {
    std::vector<float> positions, normals, uvs; /* world xyz, unit xyz, uv (or empty) */
    std::vector<float> tangents;                /* world xyzw (glTF TANGENT), or empty */
    std::vector<float> colors;                  /* rgb per vertex (glTF COLOR_0), or empty */
    std::vector<uint32_t> indices;              /* 3 per triangle */
    int material;                               /* index into the materials, -1 = none */
};

/* A decoded texture: linear RGB, row 0 at the top, and its alpha (empty = opaque). */
struct Tex {
    int width, height;
    std::vector<float> rgb, alpha;
};

/* What a file uses that ssgraph does not read, gathered while reading it: per feature
   ("normal maps (normalTexture)"), the materials (or meshes, extensions) that use it. */
class Ignored {
  public:
    void add(const std::string &feature, const std::string &where);
    /* One line a feature, in the order first seen, cut to fit struct ssg_gltf's ignored. */
    std::string text() const;

  private:
    std::vector<std::pair<std::string, std::vector<std::string>>> features;
};

/* The gathered model as malloc'd C arrays (camera NULL = none); throws std::bad_alloc
   having freed what it made. */
ssg_gltf *to_c(const std::vector<Prim> &prims, const std::vector<ssg_gltf_material> &materials,
               const std::vector<Tex> &textures, const ssg_camera *camera,
               const Ignored &ignored, const std::vector<ssg_light> &lights = {});

/* Frees a struct ssg_gltf and every array it holds (ssg_gltf_destroy's body). */
void free_model(ssg_gltf *g);

/* One printable line: a library's messages may quote raw bytes of the file. */
std::string printable(std::string text);

/* Runs load(path) into *out; every exception becomes an error code and "path: message" in
   why (`library` names the reader for an unknown exception). Never throws. */
ssg_err guarded(const char *path, ssg_gltf **out, char *why, size_t why_len,
                ssg_gltf *(*load)(const char *path), const char *library);
/* The same for a load that needs more than the path (what it returns may be NULL). */
ssg_err guarded(const char *path, ssg_gltf **out, char *why, size_t why_len,
                const std::function<ssg_gltf *()> &load, const char *library);

} // namespace model_adapter

#endif
