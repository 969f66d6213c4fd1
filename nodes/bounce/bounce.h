/* bounce.h - parameters and prepared constants of the `bounce` node, shared by bounce.c
 * (descriptor, check, prepare), bounce_cpu.c (the CPU kernel) and bounce_gl.c (the GL
 * side). Method in bounce.c; the per-sample maths is ssdo's (ssdo/ssdo_sampling.h, and
 * ssdo/ssdo.glsl on GL). Read-only after prepare(). */
#ifndef SSG_BOUNCE_H
#define SSG_BOUNCE_H

#include "graph/node.h"
#include "ssdo/ssdo_sampling.h"

struct ssg_bounce_params {
    struct ssg_ssdo_geom g; /* radius, bias, max_screen_radius, strength, min_distance:
                               the meanings and defaults of ssdo's */
};

struct ssg_bounce_consts {
    struct ssg_bounce_params p; /* the parameters as given */
    struct ssg_projection proj; /* ssg_frame_projection of the frame */
    int frame_width;            /* px, the frame proj belongs to */
    int frame_height;           /* px */
};

/* Both backends' run-time checks of the images (what check() promised). */
enum ssg_err ssg_bounce_check_run(const struct ssg_node_ctx *ctx, const struct ssg_io *io);
enum ssg_err ssg_bounce_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);
/* The GL side (bounce_gl.c, ssdo's shader ssdo/ssdo.glsl). */
enum ssg_err ssg_bounce_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
