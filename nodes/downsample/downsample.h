/* downsample.h - parameters and ports of the `downsample` node, shared by downsample.c
 * (descriptor, check), downsample_cpu.c (the CPU kernel) and downsample_gl.c (the GL
 * side). Method in downsample.c. */
#ifndef SSG_DOWNSAMPLE_H
#define SSG_DOWNSAMPLE_H

#include "graph/node.h"

/* Ports, in order; output k copies input k. */
enum {
    SSG_DOWNSAMPLE_DEPTH,
    SSG_DOWNSAMPLE_POSITION,
    SSG_DOWNSAMPLE_NORMAL,
    SSG_DOWNSAMPLE_ALBEDO,
    SSG_DOWNSAMPLE_DIRECT,
    SSG_DOWNSAMPLE_ENVIRONMENT,
    SSG_DOWNSAMPLE_PORTS
};

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
