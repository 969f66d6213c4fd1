/* env_lights.h - the scene's environment light as N directional lights: their directions
 * and the irradiance each carries (env_lights.c). The `lightprobe` node's whole method
 * (nodes/lightprobe/README.md) and the environment faces of the `lightmaps` node
 * (lightmap.h) share it. Pure and thread-safe; ssg_env_lights_regions runs on the pool. */
#ifndef SSG_ENV_LIGHTS_H
#define SSG_ENV_LIGHTS_H

#include "graph/node.h"
#include "scene/env.h"

/* Unit world directions of N lights (dirs: 3 N floats, xyz per light), a spherical
 * Fibonacci set about +y, the first near the zenith: near-equal areas 4 pi / N, and
 * independent of the environment. */
void ssg_env_lights_fibonacci(int count, float *dirs);

/* The same lattice warped through env's luminance CDF, so bright regions get more, smaller
 * lights; the last round(uniform_share N) of them are the uniform set of that many (the
 * dim parts keep lights). A constant environment gets the uniform set itself. */
void ssg_env_lights_importance(const struct ssg_env *env, int count, float uniform_share,
                               float *dirs);

/* E_i of every light: the probe's radiance times solid angle summed over the texels whose
 * nearest light is i (its Voronoi region on the sphere at texel resolution), so the E_i
 * add up to the probe's whole integral. A constant environment is integrated on a fixed
 * internal lat-long grid. irradiance: 3 N doubles, rgb per light. */
enum ssg_err ssg_env_lights_regions(const struct ssg_env *env, const float *dirs, int count,
                                    double *irradiance);

#endif
