/* direct.h - the irradiance a surface point receives from one of the scene's own lights,
 * unshadowed: the formulas of the G-buffer's `direct` output (gbuffer_cpu.c), shared with
 * direct_light (which adds the shadow), so that the two agree bit for bit where nothing
 * blocks the light. Inline, branch-free, for vectorised loops over pixels. */
#ifndef SSG_DIRECT_H
#define SSG_DIRECT_H

#include <math.h>

#include "scene/scene.h" /* ssg_cone_falloff */

/* Below float precision for any unit-scale vector; keeps 1/sqrt finite for a zero one. */
#define SSG_DIRECT_TINY 1e-30f

/* A point or spot light's position and cone (struct ssg_light's; a point light's cone,
   scale 0 and offset 1, passes everything). */
struct ssg_direct_cone {
    float axis[3];
    float scale, offset;
};

/* A point or spot light of axial radiant intensity `intensity` at lp, seen from point p
   with unit normal n: E = intensity cone(-L) max(0, N.L) / d^2 (ssg_cone_falloff); the
   unit direction L to it into l. */
static inline float ssg_point_irradiance(const float lp[3], const struct ssg_direct_cone *cone,
                                         float intensity, float px, float py, float pz,
                                         float nx, float ny, float nz, float l[3])
{
    float lx = lp[0] - px, ly = lp[1] - py, lz = lp[2] - pz;
    float inv = 1.0f / sqrtf(lx * lx + ly * ly + lz * lz + SSG_DIRECT_TINY);
    lx *= inv, ly *= inv, lz *= inv;
    float ndl = nx * lx + ny * ly + nz * lz;
    l[0] = lx, l[1] = ly, l[2] = lz;
    float c = -(cone->axis[0] * lx + cone->axis[1] * ly + cone->axis[2] * lz);
    return intensity * ssg_cone_falloff(c, cone->scale, cone->offset) *
           (ndl > 0.0f ? ndl : 0.0f) * inv * inv;
}

/* The cone of scene light l for ssg_point_irradiance. */
static inline struct ssg_direct_cone ssg_direct_cone_of(const struct ssg_light *l)
{
    return (struct ssg_direct_cone){{l->direction[0], l->direction[1], l->direction[2]},
                                    l->cone_scale, l->cone_offset};
}

/* A directional light travelling along `direction` with irradiance `intensity`: E =
   intensity max(0, N.L), L = -direction into l. */
static inline float ssg_directional_irradiance(const float direction[3], float intensity,
                                               float nx, float ny, float nz, float l[3])
{
    l[0] = -direction[0], l[1] = -direction[1], l[2] = -direction[2];
    float ndl = nx * l[0] + ny * l[1] + nz * l[2];
    return intensity * (ndl > 0.0f ? ndl : 0.0f);
}

#endif
