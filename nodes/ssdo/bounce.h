/* bounce.h - parameters and prepared constants of the `bounce` node, shared by bounce.c
 * (descriptor, check, prepare), bounce_cpu.c (the CPU kernel) and bounce_gl.c (the GL
 * side). Method in bounce.c; the per-sample maths is ssdo's (ssdo_sampling.h, and
 * ssdo.glsl on GL): one folder, two descriptors. Read-only after prepare(). */
#ifndef SSG_BOUNCE_H
#define SSG_BOUNCE_H

#include "graph/node.h"
#include "ssdo_sampling.h"

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_bounce_output {
    SSG_BOUNCE_OUT_OUT,
    SSG_BOUNCE_OUTPUTS
};

struct ssg_bounce_params {
    struct ssg_ssdo_geom g; /* radius, bias, max_screen_radius, strength, min_distance:
                               the meanings and defaults of ssdo's */
};

struct ssg_bounce_consts {
    struct ssg_bounce_params p; /* the parameters as given */
    struct ssg_projection proj; /* the frame's camera as the G-buffer's resolution sees
                                   it (ssg_sampling_projection) */
};

enum ssg_err ssg_bounce_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);
/* The GL side (bounce_gl.c, ssdo's shader ssdo/ssdo.glsl). */
enum ssg_err ssg_bounce_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
