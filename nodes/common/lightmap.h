/* lightmap.h - the maps of a scene's own lights (point, spot, directional), shared by
 * the node that renders them (`lightmaps`) and the nodes that read them (shadowed direct
 * light, the reflective-shadow-map gather): every node builds the same faces from the scene
 * alone, so no matrix travels along an edge (as nodes/common/shadowmap.h does for the
 * probe's lights).
 *
 * Faces. Light i of the scene (scene order) owns consecutive faces: one for a directional
 * light, an orthographic map over the scene's bounding sphere in the frame of
 * ssg_shadow_frame_make (l = -direction, towards the light), or T x T of them, its tiles
 * (`tiles` T > 1: the map cut into a T x T grid, tile (tx, ty) at face first + ty T + tx,
 * each a face of its own with R x R texels; see ssg_lightmap_tile_texel), six for a point light, a
 * cube map around its position, face k a 90 degree perspective view along CUBE axis k
 * (+x, -x, +y, -y, +z, -z), and for a spot light one perspective face along its axis
 * whose half-width is tan(outer angle) when the outer angle is at most
 * 60 degrees (SSG_LIGHTMAP_SPOT_FACE_COS), else a point light's six. A scene without such lights has
 * one empty face (light -1), so that an image always has channels.
 *
 * Texel (x, y) of a face (row 0 at -v) has a = 2 (x + 0.5) / R - 1, b = 2 (y + 0.5) / R - 1
 * in [-1, 1]; its ray runs
 *   orthographic: from origin + half (a u + b v) along axis (= -l),
 *   perspective:  from the light's position (origin) along axis + half (a u + b v)
 *                 (a cube face has half 1),
 * and a world point p lies at depth z = dot(p - origin, axis) on every face kind:
 * orthographic a = dot(p - origin, u) / half, perspective a = dot(p - origin, u) / (z half)
 * (same for b with v). That depth z is what the maps store and what a shadow test
 * compares.
 *
 * Images (SSG_T_LIGHTMAPS, R x R, planar channels, F faces):
 *   depth   F channels: z of the nearest surface on texel (x, y) of face f (both faces of
 *           every triangle count), SSG_SHADOW_EMPTY where the ray meets nothing (within
 *           2 radius for an orthographic face, within the scene for a cube face);
 *   normal  3F channels (face f at channels 3f .. 3f + 2): that surface's unit world shading
 *           normal, turned to face the light; 0 where empty;
 *   flux    3F channels: the RGB radiant flux that surface patch reflects (diffuse albedo
 *           times the flux arriving through the texel, W): orthographic
 *           albedo x E x (2 half / R)^2 with E the light's colour x intensity (irradiance on
 *           a surface facing it), perspective albedo x I x cone x
 *           ssg_lightmap_texel_solid_angle with I the colour x intensity (radiant intensity)
 *           and cone the spot's falloff along the texel's ray (1 for a point light); 0
 *           where empty. A patch of reflected flux
 *           Phi at y with normal n_y gives a point x with normal n_x the irradiance
 *           Phi / pi x max(0, n_y . w) max(0, -n_x . w) / d^2, w = (y - x) / d reversed
 *           (Dachsbacher and Stamminger, "Reflective Shadow Maps", I3D 2005, eq. 1, with the
 *           1/pi of a Lambertian sender that the paper folds into its flux). */
#ifndef SSG_LIGHTMAP_H
#define SSG_LIGHTMAP_H

#include <math.h>
#include <stddef.h>

#include "ssgraph.h" /* enum ssg_err */
#include "common/shadowmap.h"

struct ssg_scene;
struct ssg_light;
struct ssg_camera;
struct ssg_frame;

enum { SSG_LIGHTMAP_CUBE_FACES = 6 };
/* Most faces one set of maps may have: the normal and flux images hold 3 channels a face
   and an image at most SSG_IMAGE_MAX_CHANNELS (2048) channels. */
enum { SSG_LIGHTMAP_FACES_MAX = 682 };

struct ssg_lightmap_face {
    int light;        /* index into scene->lights; -1 for the empty face of a scene without;
                         SSG_LIGHTMAP_ENV_LIGHT(k) for environment light k */
    int ortho;        /* 1: a directional light's orthographic map; 0: perspective (a
                         cube face or a spot light's face) */
    float origin[3];  /* orthographic: the centre of the map's plane; perspective: the
                         light */
    float u[3], v[3]; /* the face's image axes (a along u, b along v) */
    float axis[3];    /* the direction depth is measured along (perspective: u x v = axis;
                         orthographic: u, v of ssg_shadow_frame_make, u x v = -axis) */
    float half;       /* orthographic: half the map's side, world units; perspective: the
                         tangent of half its field of view (a cube face: 1) */
};

/* The cosine of the widest spot light's outer half-angle (60 degrees) that one
   perspective face maps; a wider one takes six cube faces, as a point light: a face much
   wider than 120 degrees spends its texels at the rim. */
#define SSG_LIGHTMAP_SPOT_FACE_COS 0.5f

/* Which lights a set of maps holds: the scene's own (point, spot, directional) lights, and
   the environment as this many directional lights (0: none). At least one of the two. */
struct ssg_lightmap_sources {
    int own;
    int environment;
    int tiles; /* an own directional light's map as tiles x tiles faces (0 or 1: one) */
};
#define SSG_LIGHTMAP_OWN_ONLY ((struct ssg_lightmap_sources){1, 0, 1})
/* Most tiles a side a directional light's map may be cut into (64 faces). */
enum { SSG_LIGHTMAP_TILES_MAX = 8 };
/* Most environment lights a set of maps may hold. */
enum { SSG_LIGHTMAP_ENV_MAX = 512 };

#define SSG_LIGHTMAP_ENV_LIGHT(k) (-2 - (k))
/* The environment light a face maps (0 .. N - 1), or -1 for an own light's or empty face. */
static inline int ssg_lightmap_face_env(const struct ssg_lightmap_face *f)
{
    return f->light <= -2 ? -2 - f->light : -1;
}

/* Faces one own light takes: tiles^2 (directional; tiles 0 counts as 1), 1 (a spot up to
   60 degrees) or SSG_LIGHTMAP_CUBE_FACES (point, a wider spot): then the face a direction
   from the light falls on is ssg_lightmap_cube_face's. */
int ssg_lightmap_light_faces(const struct ssg_light *light, int tiles);

/* A tiled directional map read as one map of side T R: texel (x, y) of that map, 0 <= x,
   y < T R, lies in tile (x / R, y / R) at (x % R, y % R). Projecting a point on the first
   tile's face (ssg_lightmap_project with resolution R) gives its coordinates on that whole
   map, since the tiles share the plane, the axis and the depth. Returns the face offset
   from the light's first face; *tx, *ty become the texel within it. */
static inline int ssg_lightmap_tile_texel(int tiles, int res, int *x, int *y)
{
    int cx = *x / res, cy = *y / res;
    *x -= cx * res, *y -= cy * res;
    return cy * tiles + cx;
}

/* Faces the sources need: ssg_lightmap_light_faces per own light, 1 an environment light;
   with own lights, at least 1 (the empty face of a scene without). */
int ssg_lightmap_face_count(const struct ssg_scene *scene, struct ssg_lightmap_sources src);

/* The faces of every light, own lights first in scene order, then the environment's, into
   faces[0 .. count - 1]; returns the count (as ssg_lightmap_face_count), or -1 when it is
   over max (nothing meaningful written). */
int ssg_lightmap_faces(const struct ssg_scene *scene, struct ssg_lightmap_sources src,
                       struct ssg_lightmap_face *faces, int max);

/* Where a directional light's map lies (the `fit` parameter of lightmaps and direct_light,
   which must agree: both build the faces). SCENE: over the scene's bounding sphere, the
   same for every camera (what a reflective shadow map needs, its senders off screen too).
   VIEW: a square in the light's plane around what the camera can see (its frustum, near to
   far, clipped to the scene's box), turned in the plane to the smallest such square, padded
   by SSG_LIGHTMAP_FIT_PAD texels; the depth axis and the plane stay the scene fit's, so
   every occluder between the light and what is seen is still in the map. Never larger than
   the scene fit; nothing visible keeps the scene fit. Environment lights always SCENE. */
enum ssg_lightmap_fit { SSG_LIGHTMAP_FIT_SCENE, SSG_LIGHTMAP_FIT_VIEW };
/* Their names as parameters take them ("scene", "view"), NULL-terminated. */
extern const char *const ssg_lightmap_fit_choices[];
/* Texels of margin a view-fitted map keeps on every side: a pixel at the view's edge still
   finds its PCF disc (1.5 texels) and normal offset (2 texels) in the map. */
enum { SSG_LIGHTMAP_FIT_PAD = 8 };

/* What a view fit reads: the frame (size with guard band, fov_y, near_z, far_z), the
   camera's pose and the maps' side R (the padding is in texels). */
struct ssg_lightmap_view {
    const struct ssg_frame *frame;
    const struct ssg_camera *camera;
    int res;
};

/* ssg_lightmap_faces with the own directional lights' maps fitted by `fit`; view is read
   only for SSG_LIGHTMAP_FIT_VIEW (may be NULL otherwise). */
int ssg_lightmap_faces_fit(const struct ssg_scene *scene, struct ssg_lightmap_sources src,
                           enum ssg_lightmap_fit fit, const struct ssg_lightmap_view *view,
                           struct ssg_lightmap_face *faces, int max);

/* Fits orthographic face f (a scene-fit face: its plane, axis and frame) to the part of
   the box [lo, hi] the view sees (lightmap_fit.c); returns 1 when it did, 0 when it left f
   as it was (nothing of the box visible, or no smaller than f). */
int ssg_lightmap_fit_view(const struct ssg_lightmap_view *view, const float lo[3],
                          const float hi[3], struct ssg_lightmap_face *f);

/* SSG_E_VALUE with the reason in why when src names no light at all (own false, no
   environment lights): the check of every node that takes these two parameters. */
enum ssg_err ssg_lightmap_sources_check(struct ssg_lightmap_sources src, char *why,
                                        size_t why_len);

/* The unit directions towards the scene's N environment lights (3 N floats): under a probe
   (an image), drawn through its brightness with the last quarter the uniform set
   (ssg_env_lights_importance, as lightprobe sampling=importance uniform_share=0.25);
   under a constant sky or none, the spherical Fibonacci set. Why drawn: 48 uniform
   lights split the courtyard probe's low bright patch among a few hard-edged ones, and
   the bounce came out 10-25 % bright along the bunny's wall corner (lightmaps README).
   Fixed, not a parameter: rsm builds the same faces from the scene alone, and a mismatch
   could not be told from the maps. */
#define SSG_LIGHTMAP_ENV_UNIFORM_SHARE 0.25f
void ssg_lightmap_env_directions(const struct ssg_scene *scene, int count, float *dirs);

/* Where world point p falls on face f of resolution res: texel coordinates (x, y), not
   floored, inside the map for 0 <= x, y < res, and its depth z. Returns 0 when p is not
   in front of a cube face (z <= 0), 1 otherwise (the caller checks x, y against res). */
static inline int ssg_lightmap_project(const struct ssg_lightmap_face *f, int res,
                                       const float p[3], float *x, float *y, float *z)
{
    float d[3] = {p[0] - f->origin[0], p[1] - f->origin[1], p[2] - f->origin[2]};
    float depth = d[0] * f->axis[0] + d[1] * f->axis[1] + d[2] * f->axis[2];
    float du = d[0] * f->u[0] + d[1] * f->u[1] + d[2] * f->u[2];
    float dv = d[0] * f->v[0] + d[1] * f->v[1] + d[2] * f->v[2];
    *z = depth;
    if (!f->ortho && depth <= 0.0f)
        return 0;
    float scale = 1.0f / (f->ortho ? f->half : depth * f->half);
    *x = (du * scale + 1.0f) * 0.5f * (float)res;
    *y = (dv * scale + 1.0f) * 0.5f * (float)res;
    return 1;
}

/* The cube face (0..5, CUBE axis order) a direction d from a point light falls on: its
   largest component, ties to the lower face index. Selects, not branches: direct_light
   runs it in vector lanes. */
static inline int ssg_lightmap_cube_face(const float d[3])
{
    float ax = fabsf(d[0]), ay = fabsf(d[1]), az = fabsf(d[2]);
    int on_x = (ax >= ay) & (ax >= az), on_y = !on_x & (ay >= az);
    float s = on_x ? d[0] : on_y ? d[1] : d[2];
    return (on_x ? 0 : on_y ? 2 : 4) + !(s >= 0.0f);
}

/* The world point at depth z on the ray of texel (x, y) of face f (resolution res). */
static inline void ssg_lightmap_texel_point(const struct ssg_lightmap_face *f, int res,
                                           int x, int y, float z, float p[3])
{
    float a = 2.0f * ((float)x + 0.5f) / (float)res - 1.0f;
    float b = 2.0f * ((float)y + 0.5f) / (float)res - 1.0f;
    for (int k = 0; k < 3; k++) {
        if (f->ortho)
            p[k] = f->origin[k] + f->half * (a * f->u[k] + b * f->v[k]) + z * f->axis[k];
        else
            p[k] = f->origin[k] + z * (f->axis[k] + f->half * a * f->u[k] +
                                       f->half * b * f->v[k]);
    }
}

/* The solid angle of texel (x, y) of a perspective face of half-width `half` (a cube
   face: 1) and resolution res, seen from the light: (2 half / R)^2 / (1 + half^2 (a^2 +
   b^2))^(3/2) at its centre. */
static inline float ssg_lightmap_texel_solid_angle(float half, int res, int x, int y)
{
    float a = 2.0f * ((float)x + 0.5f) / (float)res - 1.0f;
    float b = 2.0f * ((float)y + 0.5f) / (float)res - 1.0f;
    float q = 1.0f + half * half * (a * a + b * b), s = 2.0f * half / (float)res;
    return s * s / (q * sqrtf(q));
}

#endif
