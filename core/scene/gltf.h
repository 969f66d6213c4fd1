/* gltf.h - loads a glTF 2.0 file (.gltf with its buffers, or .glb) into plain C structs:
 * the triangles of every node of the default scene with the node's world transform
 * applied, the base colours and decoded base-colour textures of its materials, and its
 * first perspective camera. The C++ adapter over tinygltf (gltf_adapter.cc, with its
 * accessor reading in gltf_accessor_adapter.cc) lives behind this header and never lets
 * an exception cross it.
 *
 * Ownership: ssg_gltf_load returns a struct the caller frees with ssg_gltf_destroy. Every
 * array in it comes from malloc, so the caller may take an array over (set the pointer in
 * the struct to NULL) and free it later itself. Thread-safe: no shared state. */
#ifndef SSG_GLTF_H
#define SSG_GLTF_H

#include <stddef.h>

#include "scene/scene.h"
#include "ssgraph.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A glTF material, reduced to what the renderer honours. */
struct ssg_gltf_material {
    char name[64];       /* glTF name, "" when it has none */
    float base_color[4]; /* baseColorFactor, linear RGBA; default 1,1,1,1 */
    int texture;         /* baseColorTexture: index into textures, -1 = none */
    int texcoord;        /* TEXCOORD_n set the texture reads; default 0 */
    char texture_file[256]; /* an undecoded diffuse texture (Assimp formats), relative to
                               the model file; "" = none; "*N" = embedded in the file */
    int alpha_mode;      /* enum ssg_alpha_mode: glTF alphaMode; an OBJ's map_d naming the
                            diffuse texture: mask */
    float alpha_cutoff;  /* glTF alphaCutoff, default 0.5; base_color[3] is the opacity */
    int normal_texture;  /* normalTexture: index into textures (stored values, not sRGB), -1 */
    float normal_scale;  /* normalTexture.scale, default 1 */
    float emission[3];   /* emissiveFactor x KHR_materials_emissive_strength (Assimp: Ke) */
    int emission_texture; /* emissiveTexture: index into textures (sRGB decoded), -1 */
    char normal_file[256]; /* an undecoded tangent-space normal map (Assimp formats: an
                              OBJ's norm), relative to the model file; "" = none */
    char emission_file[256]; /* an undecoded emission texture (Assimp formats: an OBJ's
                                map_Ke, sRGB), relative to the model file; "" = none */
    char opacity_file[256]; /* an undecoded coverage map other than the diffuse texture
                               (Assimp formats: an OBJ's map_d naming another file: its
                               alpha channel, else its first), relative to the model; "" */
};

struct ssg_gltf {
    /* One mesh per triangle primitive instance, in the file's world space. `material`
       indexes materials (-1 = the primitive names none); `uvs` holds the set the
       material's texture reads (TEXCOORD_0 without a texture), or NULL. */
    int mesh_count;
    struct ssg_mesh *meshes;
    int material_count;
    struct ssg_gltf_material *materials;
    /* Base-colour textures, decoded and converted from sRGB to linear RGB; a masked
       material's texture keeps its alpha channel as its coverage plane. */
    int texture_count;
    struct ssg_texture *textures;
    /* KHR_lights_punctual's point, spot and directional lights on the default scene's nodes,
       in world space, in the order the nodes are visited (glTF's candela and lux taken as
       ssgraph's W/sr and W/m^2, one to one). */
    int light_count;
    struct ssg_light *lights;
    int has_camera; /* 1 = a node of the default scene carries a perspective camera */
    struct ssg_camera camera;  /* that node's camera in world space (yfov in degrees) */
    /* What the file uses that no path of ssgraph reads (docs/scenes.md's feature table),
       one line a feature with the materials using it ("normal maps (normalTexture): 3
       materials: 'bark', 'leaf', 'stone'"); "" = nothing. The scene loader warns with it
       and `ssgraph check` lists it. */
    char ignored[SSG_MODEL_IGNORED_MAX];
};

/* Loads path. On failure returns SSG_E_IO (cannot read the file), SSG_E_GLTF (malformed or
 * unsupported content) or SSG_E_NOMEM, writes a message that names the file into why, and
 * sets *out to NULL. */
enum ssg_err ssg_gltf_load(const char *path, struct ssg_gltf **out, char *why, size_t why_len);
void ssg_gltf_destroy(struct ssg_gltf **gltf);

/* What a glTF file's bytes declare, read from its JSON (a .glb's first chunk) without
 * loading it: *major is asset.version's major number (0 = none, or not glTF JSON), *draco
 * 1 when it uses KHR_draco_mesh_compression (which the tinygltf build cannot decode). */
void ssg_gltf_sniff(const char *data, size_t len, int *major, int *draco);

#ifdef __cplusplus
}
#endif
#endif
