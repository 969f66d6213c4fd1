/* lightprobe.h - the `lightprobe` node's parameters and constants (lightprobe.c), shared by
 * its backends and tests: the scene's environment turned into a light list (SSG_T_LIGHTS,
 * nodes/common/shadowmap.h) once, in prepare().
 *
 * Method: Knuth and Kohlhammer, "A Hybrid Ambient Occlusion Technique for Dynamic Scenes",
 * sec. 3 and 4 ("Global part": the light probe is converted into directional lights by
 * sampling it uniformly); importance sampling after Knuth and Fuhrmann 2005. */
#ifndef SSG_LIGHTPROBE_H
#define SSG_LIGHTPROBE_H

#include "scene/env.h"
#include "graph/node.h"
#include "common/shadowmap.h"

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_lightprobe_output {
    SSG_LIGHTPROBE_OUT_LIGHTS,
    SSG_LIGHTPROBE_OUTPUTS
};

enum ssg_lightprobe_sampling {
    SSG_LIGHTPROBE_UNIFORM,    /* a spherical Fibonacci set: near-equal areas 4 pi / N */
    SSG_LIGHTPROBE_IMPORTANCE, /* Hammersley points through the probe's luminance CDF */
};

struct ssg_lightprobe_params {
    int count;    /* lights N, SSG_LIGHTS_MIN..SSG_LIGHTS_MAX; default 128 */
    int sampling; /* enum ssg_lightprobe_sampling; default uniform */
    int missing;  /* without environment light: 0 an error, 1 dark lights; default error */
};

/* What prepare() makes: the light list exactly as the output image holds it (planar; row 0
 * the directions, row 1 the irradiances). */
struct ssg_lightprobe_consts {
    int count;
    float lights[3 * 2 * SSG_LIGHTS_MAX]; /* channel c, row r, light i at
                                             (c * 2 + r) * count + i */
};

/* Unit world directions of the N lights of a sampling (dirs: 3 N floats, xyz per light).
 * Importance sampling reads env; uniform does not. */
void ssg_lightprobe_directions(const struct ssg_env *env, int sampling, int count,
                               float *dirs);

/* E_i of every light: the probe's radiance times solid angle summed over the texels whose
 * nearest light is i (its Voronoi region on the sphere at texel resolution), so the E_i
 * add up to the probe's whole integral. A constant environment is integrated on a fixed
 * internal lat-long grid. irradiance: 3 N doubles, rgb per light. */
enum ssg_err ssg_lightprobe_regions(const struct ssg_env *env, const float *dirs, int count,
                                    double *irradiance);

enum ssg_err ssg_lightprobe_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);
enum ssg_err ssg_lightprobe_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_lightprobe;

#endif
