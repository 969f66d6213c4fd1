/* downsample.h - parameters and ports of the `downsample` node, shared by downsample.c
 * (descriptor, check), downsample_cpu.c (the CPU kernel) and downsample_gl.c (the GL
 * side). Method in downsample.c. */
#ifndef SSG_DOWNSAMPLE_H
#define SSG_DOWNSAMPLE_H

#include "graph/node.h"

/* Ports, in order; output k copies input k. */
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_downsample_input {
    SSG_DOWNSAMPLE_IN_DEPTH,
    SSG_DOWNSAMPLE_IN_POSITION,
    SSG_DOWNSAMPLE_IN_NORMAL,
    SSG_DOWNSAMPLE_IN_ALBEDO,
    SSG_DOWNSAMPLE_IN_DIRECT,
    SSG_DOWNSAMPLE_IN_ENVIRONMENT,
    SSG_DOWNSAMPLE_INPUTS
};
enum ssg_downsample_output {
    SSG_DOWNSAMPLE_OUT_DEPTH,
    SSG_DOWNSAMPLE_OUT_POSITION,
    SSG_DOWNSAMPLE_OUT_NORMAL,
    SSG_DOWNSAMPLE_OUT_ALBEDO,
    SSG_DOWNSAMPLE_OUT_DIRECT,
    SSG_DOWNSAMPLE_OUT_ENVIRONMENT,
    SSG_DOWNSAMPLE_OUTPUTS
};
_Static_assert((int)SSG_DOWNSAMPLE_INPUTS == (int)SSG_DOWNSAMPLE_OUTPUTS,
               "downsample: output k is input k subsampled");

#define SSG_DOWNSAMPLE_MAX_FACTOR 4

struct ssg_downsample_params {
    int factor; /* block side, px: 2 or 4; default 2 */
};
enum ssg_err ssg_downsample_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);
/* The GL side (downsample_gl.c, shader downsample*.glsl). */
enum ssg_err ssg_downsample_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);

#endif
