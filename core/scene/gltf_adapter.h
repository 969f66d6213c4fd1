/* gltf_adapter.h - private to the tinygltf adapter: what the scene flattening in
 * gltf_adapter.cc and the accessor reading in gltf_accessor_adapter.cc share. Problems are
 * thrown as Failure (model_adapter.h, the type the Assimp adapter throws too) and caught
 * in ssg_gltf_load. C++ only. */
#ifndef SSG_GLTF_ADAPTER_H
#define SSG_GLTF_ADAPTER_H

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

} // namespace gltf_adapter

#endif
