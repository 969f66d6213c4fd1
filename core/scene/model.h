/* model.h - mesh files of any supported format, behind one call. glTF 2.0 (.gltf, .glb)
 * goes through tinygltf (gltf.h); OBJ, PLY, FBX, 3DS, STL, DAE, glTF 1.0 and whatever
 * else the installed Assimp reads go through the Assimp adapter (assimp_adapter.cc). Both
 * fill the same struct ssg_gltf: world-space triangle meshes, materials (a diffuse colour
 * becomes base_color, as glTF's baseColorFactor does), textures and an optional camera.
 *
 * Ownership as in gltf.h: the caller frees the result with ssg_gltf_destroy. Every message
 * names the file; the scene loader puts it at the mesh line. Thread-safe: no shared state
 * (each call makes its own Assimp importer). */
#ifndef SSG_MODEL_H
#define SSG_MODEL_H

#include <stddef.h>

#include "scene/gltf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The formats a message lists when a file's extension is not one of them. */
#define SSG_MODEL_FORMATS                                                                  \
    ".gltf/.glb (glTF 2.0 through tinygltf; glTF 1.0 through Assimp), and through Assimp "  \
    ".obj, .ply, .fbx, .3ds, .stl, .dae (and the other formats of the installed Assimp)"

/* 1 when path's extension names a format ssg_model_load reads; otherwise 0 with the
 * reason (the extension, or that there is none) in why. */
int ssg_model_supported(const char *path, char *why, size_t why_len);

/* Loads path by its extension (and, for glTF, by the version it declares). Returns
 * SSG_E_IO (unreadable), SSG_E_GLTF (malformed, unsupported content or format) or
 * SSG_E_NOMEM with a message naming the file in why, and *out NULL. */
enum ssg_err ssg_model_load(const char *path, struct ssg_gltf **out, char *why,
                            size_t why_len);

/* The Assimp side: 1 when the installed Assimp reads files ending in ext (".obj"). */
int ssg_assimp_supports(const char *ext);
/* Reads path through Assimp, triangulated, its node transforms applied; materials carry a
 * diffuse texture as texture_file (relative to the model file), decoded by the caller. */
enum ssg_err ssg_assimp_load(const char *path, struct ssg_gltf **out, char *why,
                             size_t why_len);

#ifdef __cplusplus
}
#endif
#endif
