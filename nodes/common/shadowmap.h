/* shadowmap.h - the orthographic shadow maps of the hybrid AO's global part (Knuth and
 * Kohlhammer, "A Hybrid Ambient Occlusion Technique for Dynamic Scenes", sec. 3 and 4):
 * one map per directional light of a light list, every map fitted to the scene's bounding
 * sphere, so that the `shadowmaps` node that renders them and the `probe_light` node that
 * reads them agree on every map's frame without passing matrices along an edge, and every
 * map has the same texel size (2 radius / R), so one depth offset suits them all.
 *
 * Light list (SSG_T_LIGHTS, count x 2, 3 channels, planar): pixel (i, 0) the unit world
 * direction l_i towards light i, pixel (i, 1) its RGB irradiance E_i on a surface facing it.
 *
 * Map of light i (channel i of an R x R SSG_T_SHADOWMAPS image): the plane through
 * origin = centre + radius l_i, perpendicular to l_i, spanned by (u_i, v_i) of
 * ssg_shadow_frame_make; texel (x, y) has its centre at
 *   origin + radius ((2 (x + 0.5) / R - 1) u_i + (2 (y + 0.5) / R - 1) v_i)
 * (row 0 at -v) and holds the depth t >= 0 along -l_i from there to the nearest surface,
 * or SSG_SHADOW_EMPTY when the ray meets nothing within 2 radius. A world point P lies at
 * depth dot(origin - P, l_i) and in texel floor of ssg_shadow_texel(P); it is lit by light
 * i when its depth <= the texel's depth + offset (the paper's shift of the shadow behind
 * the occluder, figure 1). */
#ifndef SSG_SHADOWMAP_H
#define SSG_SHADOWMAP_H

#include <math.h>

struct ssg_scene;

/* The depth of a texel whose ray meets no surface: larger than any real depth plus any
 * offset, and finite so that sums and comparisons stay ordinary. */
#define SSG_SHADOW_EMPTY 1.0e30f

/* Bounds of the light count and map resolution the nodes accept. */
enum { SSG_LIGHTS_MIN = 1, SSG_LIGHTS_MAX = 2048, SSG_SHADOW_RES_MIN = 16,
       SSG_SHADOW_RES_MAX = 4096 };

struct ssg_bounding_sphere {
    float centre[3];
    float radius;
};

struct ssg_shadow_frame {
    float u[3], v[3], l[3]; /* orthonormal, right-handed (u x v = l); l towards the light */
    float origin[3];        /* centre + radius l: the centre of the map's plane */
    float radius;           /* half the map's side in world units */
};

/* The sphere around the axis-aligned bounds of every mesh of the scene (centre of the box,
 * radius half its diagonal, grown by 0.1 % so surfaces on the box never graze the map's
 * plane). A scene without triangles gets the unit sphere at the origin. */
struct ssg_bounding_sphere ssg_scene_bounding_sphere(const struct ssg_scene *scene);

/* The frame of the map of a light in unit world direction l (towards the light). u, v come
 * from l alone (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017), so
 * every backend builds the same one. */
struct ssg_shadow_frame ssg_shadow_frame_make(const struct ssg_bounding_sphere *sphere,
                                              const float l[3]);

/* Where world point p falls on a map of resolution res: (x, y) in texels (not floored;
 * inside the map for 0 <= x, y < res) and its depth below the map's plane. */
static inline void ssg_shadow_project(const struct ssg_shadow_frame *f, int res,
                                      const float p[3], float *x, float *y, float *depth)
{
    float d[3] = {p[0] - f->origin[0], p[1] - f->origin[1], p[2] - f->origin[2]};
    float scale = 0.5f * (float)res / f->radius;
    *x = (d[0] * f->u[0] + d[1] * f->u[1] + d[2] * f->u[2]) * scale + 0.5f * (float)res;
    *y = (d[0] * f->v[0] + d[1] * f->v[1] + d[2] * f->v[2]) * scale + 0.5f * (float)res;
    *depth = -(d[0] * f->l[0] + d[1] * f->l[1] + d[2] * f->l[2]);
}

/* The world point at the centre of texel (x, y) on the map's plane (the start of its ray,
 * which runs along -l). */
static inline void ssg_shadow_texel_origin(const struct ssg_shadow_frame *f, int res, int x,
                                           int y, float p[3])
{
    float a = f->radius * (2.0f * ((float)x + 0.5f) / (float)res - 1.0f);
    float b = f->radius * (2.0f * ((float)y + 0.5f) / (float)res - 1.0f);
    for (int k = 0; k < 3; k++)
        p[k] = f->origin[k] + a * f->u[k] + b * f->v[k];
}

#endif
