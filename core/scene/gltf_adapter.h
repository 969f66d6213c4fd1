/* gltf_adapter.h - private to the tinygltf adapter: what the scene flattening in
 * gltf_adapter.cc and the accessor reading in gltf_accessor_adapter.cc share. Problems are
 * thrown as Failure (model_adapter.h, the type the Assimp adapter throws too) and caught
 * in ssg_gltf_load. C++ only. */
#ifndef SSG_GLTF_ADAPTER_H
#define SSG_GLTF_ADAPTER_H

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "scene/gltf.h"
#include "scene/model_adapter.h"

namespace gltf_adapter {

using model_adapter::Failure;
using model_adapter::fail;

/* Accessor `index`'s elements as `components` floats each (VEC2 texcoords, VEC3
   positions), every one finite. Fails on a missing, sparse, mistyped or out-of-bounds
   accessor, however its count and offsets were forged. */
std::vector<float> read_floats(const tinygltf::Model &model, int index, int components);

/* Accessor `index` as unsigned indices (any of the three index component types). */
std::vector<uint32_t> read_indices(const tinygltf::Model &model, int index);

/* A glTF file's materials and the textures they read, converted once (gltf_material_adapter.cc):
   base colour (sRGB, with its alpha for a masked material), alphaMode, the normal map (as
   data), emission; and what of them no path reads, into `ignored`. */
/* A texture reference's KHR_texture_transform as the 2 x 3 matrix uv' = M (u, v, 1), row
   by row: translation x rotation x scale, the extension's order (identity without). */
using UvTransform = std::array<double, 6>;
constexpr UvTransform UV_IDENTITY = {1, 0, 0, 0, 1, 0};

class Materials {
  public:
    explicit Materials(const tinygltf::Model &model) : m(model) {}
    void convert();
    std::vector<ssg_gltf_material> materials;
    /* per material: the transform its textures' uvs take (baked into the mesh's uvs: one
       set a mesh, so a material whose textures disagree keeps the base colour's) */
    std::vector<UvTransform> uv_transforms;
    std::vector<model_adapter::Tex> textures;
    model_adapter::Ignored ignored; /* what the file uses and no path reads */

  private:
    const tinygltf::Model &m;
    std::vector<int> texture_slot; /* glTF texture index -> textures index, -1 = not yet */
    std::vector<int> data_slot;    /* the same for textures read as data (normal maps) */

    void note_ignored(const tinygltf::Material &src, const std::string &who);
    void read_emission(const tinygltf::Material &src, ssg_gltf_material &mat);
    UvTransform read_uv_transform(const tinygltf::Material &src, const std::string &who);
    int texture(int gltf_index, bool keep_alpha, bool srgb = true);
    void add_alpha(model_adapter::Tex &tex, const tinygltf::Image &img) const;
};

/* A number as a message writes it: "0.8", not std::to_string's "0.800000". */
std::string shown(double x);

} // namespace gltf_adapter

#endif
