/* combine.h - the parameters and port order of the `combine` node (final shading), shared
 * by combine.c (descriptor), combine_cpu.c (the kernel), combine_gl.c (the GL side) and
 * tests/test_combine.c.
 *
 * Method in combine.c: AO darkens the ambient light (Szentandrasi sec. 3.1), SSDO's
 * modulation factor darkens the light it was computed for and the bounce (sec. 4.1). */
#ifndef SSG_COMBINE_H
#define SSG_COMBINE_H

#include "graph/node.h"

/* Input ports, in the order of the descriptor's table. */
enum ssg_combine_input {
    SSG_COMBINE_DIRECT,   /* color, required: direct diffuse + specular light */
    SSG_COMBINE_ALBEDO,   /* color, required: diffuse reflectance */
    SSG_COMBINE_AO,       /* scalar, optional: ambient occlusion, 1 = open; missing = 1 */
    SSG_COMBINE_INDIRECT, /* color, optional: indirect light; missing = 0 */
    SSG_COMBINE_MODULATION, /* scalar or color, optional: SSDO modulation factor; missing = 1 */
    SSG_COMBINE_ENVIRONMENT, /* color, optional: unoccluded environment light; missing = 0 */
    SSG_COMBINE_INPUTS
};

/* Parameters as the graph file sets them (see the table in combine.c). */
struct ssg_combine_params {
    float ambient;          /* strength of the ambient light, 0..10; default 0.3 */
    float ambient_color[3]; /* linear RGB tint of the ambient light, 0..100; default [1,1,1] */
    int darken_indirect;    /* 1 = the modulation factor also darkens indirect; default 1 */
};

/* The CPU backend (combine_cpu.c); `consts` is a struct ssg_combine_params. */
enum ssg_err ssg_combine_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);
/* The GL side (combine_gl.c, shader combine.glsl); `consts` as for the CPU. */
enum ssg_err ssg_combine_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);

#endif
