/* direct.h - the irradiance a surface point receives from one of the scene's own lights,
 * unshadowed: the formulas of the G-buffer's `direct` output (gbuffer_cpu.c), shared with
 * direct_light (which adds the shadow), so that the two agree bit for bit where nothing
 * blocks the light. Inline, branch-free, for vectorised loops over pixels. */
#ifndef SSG_DIRECT_H
#define SSG_DIRECT_H

#include <math.h>

/* Below float precision for any unit-scale vector; keeps 1/sqrt finite for a zero one. */
#define SSG_DIRECT_TINY 1e-30f

/* A point light of radiant intensity `intensity` at lp, seen from point p with unit normal
   n: E = intensity max(0, N.L) / d^2; the unit direction L to it into l. */
static inline float ssg_point_irradiance(const float lp[3], float intensity, float px,
                                         float py, float pz, float nx, float ny, float nz,
                                         float l[3])
{
    float lx = lp[0] - px, ly = lp[1] - py, lz = lp[2] - pz;
    float inv = 1.0f / sqrtf(lx * lx + ly * ly + lz * lz + SSG_DIRECT_TINY);
    lx *= inv, ly *= inv, lz *= inv;
    float ndl = nx * lx + ny * ly + nz * lz;
    l[0] = lx, l[1] = ly, l[2] = lz;
    return intensity * (ndl > 0.0f ? ndl : 0.0f) * inv * inv;
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
