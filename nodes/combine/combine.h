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
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_combine_input {
    SSG_COMBINE_IN_DIRECT,
    SSG_COMBINE_IN_ALBEDO,
    SSG_COMBINE_IN_AMBIENT_OCCLUSION,
    SSG_COMBINE_IN_INDIRECT,
    SSG_COMBINE_IN_MODULATION,
    SSG_COMBINE_IN_ENVIRONMENT,
    SSG_COMBINE_IN_FAR_VISIBILITY,
    SSG_COMBINE_INPUTS
};
enum ssg_combine_output {
    SSG_COMBINE_OUT_OUT,
    SSG_COMBINE_OUTPUTS
};

/* Parameters as the graph file sets them (see the table in combine.c). */
struct ssg_combine_params {
    float ambient;          /* strength of the ambient light, 0..10; default 0.3 */
    float ambient_color[3]; /* linear RGB tint of the ambient light, 0..100; default [1,1,1] */
    int darken_indirect;    /* 1 = the modulation factor also darkens indirect; default 1 */
    int far_bounce;         /* with far_visibility: add the far bounce; default 1 */
    int indirect_albedo;    /* 1 = indirect is multiplied by albedo (an irradiance / pi made
                               at low resolution, rsm without albedo); default 0 */
};

/* The CPU backend (combine_cpu.c); `consts` is a struct ssg_combine_params. */
enum ssg_err ssg_combine_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);
/* The GL side (combine_gl.c, shader combine.glsl); `consts` as for the CPU. */
enum ssg_err ssg_combine_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);

#endif
