/* scene_build.h - private to the scene loader: what scene.c makes of a scene file (one
 * validated entity per statement, with its arguments bound through the entity kind's
 * parameter table) and what scene_build.c turns into a struct ssg_scene.
 *
 * The loader and everything it points at live in its arena; the scene it fills owns its
 * own malloc'd arrays. One loader per call of ssg_scene_load; not shared. */
#ifndef SSG_SCENE_BUILD_H
#define SSG_SCENE_BUILD_H

#include "lang/arena.h"
#include "lang/params.h"
#include "lang/parse.h"
#include "scene/scene.h"

enum scene_kind {
    SK_CAMERA,
    SK_CAMERA_KEY,
    SK_ORBIT,
    SK_FRAME_RATE,
    SK_MATERIAL,
    SK_POINT_LIGHT,
    SK_DIRECTIONAL_LIGHT,
    SK_SPOT_LIGHT,
    SK_ENVIRONMENT,
    SK_PLANE,
    SK_BOX,
    SK_SPHERE,
    SK_MESH,
    SK_COUNT
};

/* The arguments of each kind, as its parameter table (scene_tables.c) fills them. */
struct camera_args {
    float position[3], target[3], up[3]; /* world, scene units */
    float fov;                           /* vertical, degrees */
    float near_z, far_z;                 /* scene units */
};
struct camera_key_args {
    float time;                          /* seconds from the start of the sequence */
    float position[3], target[3], up[3]; /* world, scene units */
    float fov;                           /* vertical, degrees */
    int cut;                             /* 1 = the path jumps to this key */
};
struct orbit_args {
    float target[3], up[3]; /* world */
    float radius, height;   /* scene units: horizontal distance, height above target */
    float period, start;    /* seconds a turn; degrees at time 0 */
    float fov;              /* vertical, degrees */
};
struct frame_rate_args {
    float fps; /* frames per second */
};
struct material_args {
    float albedo[3], specular[3]; /* linear reflectances */
    float shininess;              /* Blinn-Phong exponent */
    char texture[SSG_STR_MAX];    /* albedo texture path, "" = none */
    int alpha_mode;               /* enum ssg_alpha_mode */
    float alpha_cutoff, opacity;  /* coverage.h */
    float emission[3];            /* emitted radiance, linear RGB */
    char normal_map[SSG_STR_MAX]; /* tangent-space normal map path, "" = none */
    float normal_scale;           /* multiplies the map's x and y */
};
struct light_args {
    float position[3];  /* point and spot light, world */
    float direction[3]; /* directional light: the way the light travels; spot: its axis */
    float color[3];
    float intensity;
    float inner_angle, outer_angle; /* spot: the cone's half-angles, degrees */
};

/* The kinds that are one of the scene's own lights (a light line). */
static inline int scene_kind_is_own_light(enum scene_kind k)
{
    return k == SK_POINT_LIGHT || k == SK_DIRECTIONAL_LIGHT || k == SK_SPOT_LIGHT;
}
struct environment_args {
    float color[3];
    float intensity;
    char image[SSG_STR_MAX]; /* lat-long HDR path, "" = none */
};
struct shape_args {
    char material[SSG_NAME_MAX]; /* "" = the default material */
    float center[3], size[3], normal[3], rotate[3];
    float radius;
    int subdivisions;
};
struct mesh_args {
    char file[SSG_STR_MAX];
    char material[SSG_NAME_MAX]; /* "" = the model file's own materials */
    float translate[3], rotate[3], scale[3];
    int lights;                  /* 1 = the file's own lights join the scene's */
};

#define SCENE_MAX_ARGS 16 /* the most parameters a kind has (test_scene checks every table) */

/* An entity kind: its name in scene files, its parameter table, the size of its *_args
   struct, and what it is (docs/scenes.md). */
struct scene_kind_desc {
    const char *name;
    struct ssg_param_table table;
    size_t size;
    const char *doc;
};
extern const struct scene_kind_desc ssg_scene_kinds[SK_COUNT];

/* One statement of the scene file. */
struct scene_entity {
    enum scene_kind kind;
    const struct ssg_stmt *stmt;
    void *args;                       /* one of the *_args structs above */
    struct ssg_loc at[SCENE_MAX_ARGS]; /* where argument i was written; src NULL = default */
    int material;                     /* shapes, meshes: entity index of the named material,
                                         -1 = none named */
    int depth;                        /* 0: the scene file's own; n: from an include n deep */
};

struct scene_loader {
    struct ssg_arena arena;
    struct ssg_diags *diags;
    enum ssg_err first;             /* first error reported, SSG_OK while none */
    struct scene_entity *ents;      /* in the loader's arena; grown by doubling */
    int count, ent_cap;
    struct ssg_scene *scene;        /* being filled by scene_build.c */
    int mesh_cap, material_cap, texture_cap, model_cap, light_cap;
    int default_material;           /* index in scene->materials, -1 until first needed */
    int *material_of;               /* entity index -> scene material index */
    long long triangles;            /* in the scene so far, against SSG_SCENE_MAX_TRIANGLES */
    int depth;                      /* the include depth of the file being read */
};

/* At most this many scene files nested by `include` (a deeper chain is surely a cycle). */
#define SSG_SCENE_MAX_INCLUDE 16

/* `include "file"` (scene_include.c): the file's path, resolved against the including
   file's folder, into path; 0 with the error reported (not one quoted name, too deep). */
int ssg_scene_include_path(struct scene_loader *l, const struct ssg_stmt *st, char *path,
                           size_t len);
/* After a file's statements, its entities from `first` on (those at depth l->depth its
   own): drops what its includes gave of each kind the file has itself (a camera, a camera
   path, an environment, a frame rate). */
void ssg_scene_replace_included(struct scene_loader *l, int first);

/* At most this many triangles in one scene (about 150 bytes each with the ray-tracing
 * structure: 2.4 GB), checked before a shape is tessellated and as each glTF is added. */
#define SSG_SCENE_MAX_TRIANGLES (16LL << 20)

/* Records e as the loader's result if it is the first error. */
void ssg_scene_fail(struct scene_loader *l, enum ssg_err e);
/* Resolves a path written in an entity's arguments against the directory of the file the
   entity was written in (the scene file, or the lights file that replaced its lights). */
void ssg_scene_path(const struct scene_entity *e, const char *rel, char *out, size_t len);
/* Loads textures, tessellates shapes, reads glTF files, picks the camera and builds the
 * Embree scene, for entities scene.c has validated. Problems go to l->diags. */
void ssg_scene_build(struct scene_loader *l);

/* Grows array (count used, *cap allocated) by doubling when full; NULL with the scene
   failed when out of memory (scene_build.c). */
void *ssg_scene_reserve(struct scene_loader *l, void *array, int count, int *cap, size_t size);

struct ssg_gltf_material;

/* The scene's textures (scene_textures.c); each returns the texture's index in
   scene->textures, or -1 with a message naming the file and the scene failed. */
/* Adds a texture, taking over rgb and alpha (NULL = opaque). */
int ssg_scene_add_texture(struct scene_loader *l, int width, int height, float *rgb,
                          float *alpha);
/* An image file as interleaved linear RGB (gray fills all three); finite_only: a NaN or
   infinite pixel is refused; keep_alpha: its alpha channel becomes the coverage plane. */
int ssg_scene_load_texture_file(struct scene_loader *l, const char *path, int finite_only,
                                int keep_alpha);
/* The same for a path written in entity `from`, relative to its file. */
int ssg_scene_load_texture(struct scene_loader *l, const struct scene_entity *from,
                           const char *rel, int finite_only, int keep_alpha);
/* A normal map written in a material line: the values as stored, not sRGB-decoded. */
int ssg_scene_load_normal_map(struct scene_loader *l, const struct scene_entity *from,
                              const char *rel);
/* The diffuse texture an Assimp material names, relative to the model file. */
int ssg_scene_model_texture(struct scene_loader *l, const struct scene_entity *e,
                            const char *model, const struct ssg_gltf_material *gm);
/* The emission map (OBJ map_Ke) an Assimp material names, relative to the model file,
   sRGB-decoded as a colour texture. */
int ssg_scene_model_emission(struct scene_loader *l, const struct scene_entity *e,
                             const char *model, const struct ssg_gltf_material *gm);
/* An Assimp material's separate coverage map (opacity_file) as the alpha plane of its
   texture `texture` (resampled onto its texels), or of a new white texture of the map's
   size when texture < 0; returns the texture's index, -1 with a message when it cannot be
   read. */
int ssg_scene_model_opacity(struct scene_loader *l, const struct scene_entity *e,
                            const char *model, const struct ssg_gltf_material *gm, int texture);
/* The normal map (OBJ norm) an Assimp material names, relative to the model file, as
   data. */
int ssg_scene_model_normal_map(struct scene_loader *l, const struct scene_entity *e,
                               const char *model, const struct ssg_gltf_material *gm);

/* The camera path (scene_path.c): checks the camera_key, orbit and frame_rate lines
 * together (two keys at one time, a lone key, keys beside an orbit...), reporting at the
 * line; then fills scene->camera_path from them, the `camera` line's arguments giving what a key
 * or the orbit leaves out (up, fov, near, far), and, when there is a path, its camera at
 * time 0 as the scene's camera. */
void ssg_scene_path_check(struct scene_loader *l);
void ssg_scene_path_fill(struct scene_loader *l, const struct camera_args *camera);

/* The camera a camera line's arguments describe (checked by ssg_camera_fault). */
struct ssg_camera ssg_scene_camera_of(const struct camera_args *args);

#endif
