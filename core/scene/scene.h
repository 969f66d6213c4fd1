/* scene.h - the loaded scene: camera, lights, environment, materials and triangle meshes
 * in world space, plus the Embree scene every CPU ray query goes through.
 *
 * Scene files (examples/NAME.scene) use the statement syntax of parse.h, one entity a line:
 *   camera(position=[0,1,3.4], target=[0,1,0], up=[0,1,0], fov=40, near=0.05, far=50)
 *   white = material(albedo=[0.73,0.73,0.73], specular=[0,0,0], shininess=32, texture="t.png")
 *   point_light(position=[0,1.9,0], color=[1,1,1], intensity=4)
 *   directional_light(direction=[-1,-2,-1], color=[1,1,1], intensity=1)
 *   environment(color=[1,1,1], intensity=0.3, image="probe.hdr")
 *   plane(material=white, center=[0,0,0], size=[2,0,2], normal=[0,1,0]) ... box, sphere
 *   mesh("bunny.gltf", material=white, translate=[..], rotate=[..], scale=1)
 *     (glTF 2.0, or OBJ, PLY, FBX, 3DS, STL, DAE, glTF 1.0... through Assimp: model.h)
 * Each entity's arguments are a parameter table (params.h). Relative paths resolve against
 * the scene file. The scene owns all its memory; ssg_scene_destroy frees it. A loaded scene
 * is read-only and may be shared by threads. */
#ifndef SSG_SCENE_H
#define SSG_SCENE_H

#include <stdint.h>

#include "ssgraph.h"

#ifdef __cplusplus
extern "C" { /* the C++ model adapters read lights */
#endif

struct ssg_camera {
    float position[3]; /* world, scene units */
    float target[3];   /* world point looked at */
    float up[3];       /* world up hint */
    float fov_y;       /* vertical field of view, degrees */
    float near_z;      /* scene units */
    float far_z;       /* scene units */
};

/* A camera path (docs/time.md): camera_key lines (two or more) or an orbit, and the frame
 * rate that turns frame numbers into times. Static geometry and lights only. Evaluated by
 * camera_path.h. */
struct ssg_camera_key {
    double time;                         /* seconds from the start of the sequence */
    float position[3], target[3], up[3]; /* world */
    float fov_y;                         /* degrees */
    int cut;                             /* 1 = the path jumps here from the key before */
};
struct ssg_orbit {
    float target[3], up[3]; /* world; up is unit length */
    float radius, height;   /* horizontal distance from target, height above it */
    float period, start;    /* seconds a turn; degrees around up at time 0 */
    float fov_y;            /* degrees */
};
struct ssg_camera_path {
    double fps;                  /* frames per second (frame_rate, default 30) */
    int key_count;               /* 0 = no keys, else >= 2 */
    struct ssg_camera_key *keys; /* sorted by time; the scene owns them */
    int has_orbit;               /* 1 = orbit (never together with keys) */
    struct ssg_orbit orbit;
    float near_z, far_z;         /* of the camera line, or its defaults */
};

enum ssg_light_kind { SSG_LIGHT_POINT, SSG_LIGHT_DIRECTIONAL, SSG_LIGHT_SPOT };

struct ssg_light {
    enum ssg_light_kind kind;
    float position[3];  /* point and spot: world position */
    float direction[3]; /* directional: unit direction the light travels; spot: the unit
                           axis of its cone (where it points); point: unused */
    float color[3];     /* linear RGB */
    float intensity;    /* point and spot: radiant intensity on the axis (falls off with
                           1/d^2); directional: irradiance */
    float cos_inner, cos_outer; /* spot: cosines of the cone's half-angles, inner >= outer */
    /* The cone as ssg_light_cone reads it, set by ssg_light_set_cone: a point light is a
       spot whose cone passes everything (scale 0, offset 1). */
    float cone_scale, cone_offset;
};

/* Sets a spot light's cone from its half-angles in degrees (0 < inner <= outer < 90, as
   the scene's checks and the glTF reader leave them), or a point light's (no cone). */
void ssg_light_set_cone(struct ssg_light *l, float inner_deg, float outer_deg);

/* The fraction of a point or spot light's axial intensity it sends along unit direction w
   (away from the light): 1 for a point light; for a spot light, with c = direction . w,
   t = clamp((c - cos_outer) / (cos_inner - cos_outer), 0, 1) and the fraction t^2 (the
   falloff KHR_lights_punctual recommends): 1 inside the inner cone, 0 outside the outer. */
static inline float ssg_cone_falloff(float cosine, float cone_scale, float cone_offset)
{
    float t = cosine * cone_scale + cone_offset;
    t = t < 0.0f ? 0.0f : t > 1.0f ? 1.0f : t;
    return t * t;
}
static inline float ssg_light_cone(const struct ssg_light *l, const float w[3])
{
    float c = l->direction[0] * w[0] + l->direction[1] * w[1] + l->direction[2] * w[2];
    return ssg_cone_falloff(c, l->cone_scale, l->cone_offset);
}

/* A decoded texture: linear RGB floats, interleaved, row 0 at the top, and its coverage
 * (alpha) plane when a masked material reads it. */
struct ssg_texture {
    int width, height;
    float *rgb;
    float *alpha; /* width x height coverages in [0, 1], or NULL: opaque everywhere */
};

/* How a material's alpha is honoured (glTF 2.0's alphaMode; docs/scenes.md). */
enum ssg_alpha_mode {
    SSG_ALPHA_OPAQUE, /* alpha ignored: a surface everywhere */
    SSG_ALPHA_MASK,   /* a surface where alpha >= alpha_cutoff, nothing elsewhere */
    SSG_ALPHA_BLEND,  /* read as MASK at cutoff 0.5 (no pass of ssgraph blends), warned */
};

struct ssg_material {
    char name[64];
    float albedo[3];    /* diffuse reflectance, linear; multiplies the texture */
    float specular[3];  /* Blinn-Phong specular colour, default 0 */
    float shininess;    /* Blinn-Phong exponent, default 32 */
    int texture;        /* index into scene->textures, -1 = none; its alpha plane (if any)
                           is the coverage a masked material reads */
    enum ssg_alpha_mode alpha_mode; /* default opaque */
    float alpha_cutoff; /* a masked surface exists where opacity x alpha >= this */
    float opacity;      /* alpha factor (glTF baseColorFactor's alpha, OBJ d), default 1 */
    int normal_texture; /* tangent-space normal map in scene->textures (its rgb holds the
                           stored values in [0, 1], not linearised), -1 = none */
    float normal_scale; /* glTF normalTexture.scale: multiplies the map's x and y */
    float emission[3];  /* emitted radiance, linear RGB, from both faces; 0 = none */
    int emission_texture; /* sRGB texture (linear once loaded) multiplying emission, on the
                             mesh's uvs; -1 = none */
};

/* A triangle mesh in world space. Every primitive and glTF primitive becomes one. */
struct ssg_mesh {
    int vertex_count, triangle_count;
    float *positions;  /* xyz per vertex, world */
    float *normals;    /* unit xyz per vertex, world */
    float *uvs;        /* uv per vertex, or NULL */
    uint32_t *indices; /* 3 per triangle */
    int material;      /* index into scene->materials */
    float *colors;     /* rgb per vertex multiplying the albedo (glTF COLOR_0), or NULL */
    float *tangents;   /* xyzw per vertex, world: the unit tangent along +u and the sign w
                          of the bitangent (cross(n, t) w points along +v), made by
                          ssg_mesh_tangents for a normal-mapped material; or NULL */
};

struct ssg_environment {
    float color[3];   /* constant radiance, linear RGB */
    float intensity;  /* multiplies color and image */
    int image;        /* lat-long HDR in scene->textures, -1 = none */
};

/* Room for what a model file uses that ssgraph does not read (one line a feature). */
#define SSG_MODEL_IGNORED_MAX 2048

/* One mesh(...) line of the scene file as loaded (what `ssgraph check` reports). */
struct ssg_scene_model {
    char file[512];             /* the path as the scene file writes it */
    char path[1024];            /* resolved against the folder of the file that has the line
                                   (a scene's, or one it includes) */
    int line, column;           /* of the file argument on the mesh line */
    char scene_file[1024];      /* the scene file that has the line (one an include names) */
    int first_mesh, mesh_count; /* its meshes: scene->meshes[first_mesh ...] */
    long long triangles;        /* in all of them */
    char ignored[SSG_MODEL_IGNORED_MAX]; /* what the file uses that ssgraph does not read, one line a
                                   feature (struct ssg_gltf's); "" = nothing */
};

struct ssg_rt;  /* Embree device + scene, see rt.h */
struct ssg_scene_proxies; /* proxy.h */
struct ssg_env; /* the environment's lookup and sampling tables, see env.h */

struct ssg_scene {
    char path[512];
    char lights_path[512]; /* the lights file that replaced the scene's lights, "" = none */
    int has_camera;  /* 0 = neither the scene nor a glTF gave one; a default is used */
    struct ssg_camera camera; /* with a path: the camera of the frame being run (time 0
                                 after loading) */
    struct ssg_camera_path camera_path; /* key_count 0 and has_orbit 0 = a static camera */
    struct ssg_environment environment;
    int light_count, material_count, mesh_count, texture_count;
    int light_lines; /* point_light, directional_light and spot_light lines (after a lights file), known
                        without loading: light_count is 0 until the scene is built */
    struct ssg_light *lights;
    struct ssg_material *materials;
    struct ssg_mesh *meshes;
    struct ssg_texture *textures;
    int model_count;
    struct ssg_scene_model *models; /* the mesh lines, in file order (load_assets 1) */
    struct ssg_rt *rt;   /* built by ssg_scene_load when load_assets is 1 */
    struct ssg_env *env; /* built by ssg_scene_load when load_assets is 1 (never NULL
                            then: a scene without environment gets a black one) */
    struct ssg_distance *distance; /* the triangles' coarse distance field (distance.h),
                                      built with rt; NULL without triangles */
    struct ssg_scene_proxies *proxies; /* simplified meshes for the map rasterisers
                                          (proxy.h), made on demand; NULL in a view */
    const struct ssg_scene *proxy_of;  /* a view's scene (proxy.h); NULL in a scene */
    float proxy_error;                 /* a view's distance bound from proxy_of's meshes */
};

/* Loads a scene file. With load_assets = 0 it only parses and validates the file (used by
 * `ssgraph check`): no meshes, images or Embree. All problems go into diags with location. */
enum ssg_err ssg_scene_load(const char *path, int load_assets, struct ssg_scene **out,
                            struct ssg_diags *diags);
/* Swaps the lights and environment of two loaded scenes (lights, light_count, light_lines,
 * environment, env, lights_path): a scene takes another's lighting without reloading its
 * geometry (ssg_graph_set_lights). */
void ssg_scene_swap_lights(struct ssg_scene *a, struct ssg_scene *b);

/* Same, with the scene's lights and environment replaced by those of the scene file
 * `lights` (which may hold only own light lines and environment; its image
 * paths are relative to itself): one geometry under a sun, a sky or a probe. lights NULL
 * = the scene's own. */
enum ssg_err ssg_scene_load_lit(const char *path, const char *lights, int load_assets,
                                struct ssg_scene **out, struct ssg_diags *diags);
void ssg_scene_destroy(struct ssg_scene **scene);

/* 1 when the material emits light (its emission is not black). */
int ssg_material_emits(const struct ssg_material *m);
/* 1 when any material of the scene emits: emissive surfaces light it. */
int ssg_scene_has_emission(const struct ssg_scene *scene);
/* 1 when the scene's environment gives light: its intensity and colour not 0 (an image is
   times the colour). Read from the scene file alone: also without the assets loaded. */
int ssg_scene_environment_lit(const struct ssg_scene *scene);

/* The axis-aligned box of every mesh vertex; lo > hi (+inf, -inf) when there is none. */
void ssg_scene_bounds(const struct ssg_scene *scene, float lo[3], float hi[3]);
/* When the bounding-box diagonal of the scene's models (its mesh lines; shapes do not
 * count) is under 1/20 or over 200 times `radius` (an AO radius in scene units), the
 * power-of-ten scale that brings it nearest to 8 radii (a model in millimetres gets 0.001
 * or 0.01); 0 when it fits or there is no model. */
float ssg_scene_scale_hint(const struct ssg_scene *scene, float radius, float *diagonal);

/* The camera's view matrix (world -> view, column-major 4x4) for the frame conventions of
 * node.h. */
void ssg_camera_view_matrix(const struct ssg_camera *camera, float m[16]);

/* A camera looking at the middle of the box lo..hi from `dir` (the unit vector from the
 * middle towards the eye), far enough for the box's bounding sphere to fit a vertical view of
 * SSG_DEFAULT_FOV_Y with a 10 % margin, up +Y, near and far hugging the sphere. Returns 0
 * and leaves *camera alone when the box is empty. (The scene's camera when none is given,
 * and the one `check MODEL` suggests.) */
int ssg_camera_frame_box(const float lo[3], const float hi[3], const float dir[3],
                         struct ssg_camera *camera);

/* The part of a camera at fault, so a scene file's message points at its argument. */
enum ssg_camera_part {
    SSG_CAMERA_FINE,
    SSG_CAMERA_POSITION, /* position (or target) not finite, or past +-SSG_PARAM_ABS_MAX */
    SSG_CAMERA_TARGET,   /* target - position is zero in float: nowhere to look */
    SSG_CAMERA_UP,       /* up not finite, zero or parallel to the view direction */
    SSG_CAMERA_FOV,      /* fov_y outside [SSG_CAMERA_FOV_MIN, 180 - SSG_CAMERA_FOV_MIN] */
    SSG_CAMERA_PLANES,   /* near and far not 0 < near < far, finite */
};
#define SSG_CAMERA_FOV_MIN 1e-3 /* degrees: 1 / tan(fov / 2) stays a modest float */

/* Why `camera` cannot be rendered, or NULL when it can, with *part the argument at fault.
 * Every place a camera enters (a scene file's camera and camera_key lines, a glTF camera,
 * ssg_graph_set_view) asks this one check: it judges what the renderer derives (the
 * direction target - position in float, its length, its cross product with up, the
 * projection's 1 / tan(fov / 2)), not only each input, since finite inputs near the float
 * limit (2e38 and -2e38) give an infinite direction that aborted inside Embree. The
 * check itself computes in double, so it cannot overflow. */
const char *ssg_camera_fault(const struct ssg_camera *camera, enum ssg_camera_part *part);
/* The scene file argument a part is written as: "position", "target", "up", "fov", "far". */
const char *ssg_camera_part_arg(enum ssg_camera_part part);

#ifdef __cplusplus
}
#endif

#endif
