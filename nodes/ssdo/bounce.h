/* bounce.h - parameters and prepared constants of the `bounce` node, shared by bounce.c
 * (descriptor, check, prepare), bounce_cpu.c (the CPU kernel) and bounce_gl.c (the GL
 * side). Method in bounce.md; the per-sample maths is ssdo's (ssdo_sampling.h, and
 * ssdo.glsl on GL): one folder, two descriptors. Read-only after prepare(). */
#ifndef SSG_BOUNCE_H
#define SSG_BOUNCE_H

#include "graph/node.h"
#include "ssdo_sampling.h"

/* Ports, one row each (graph/node.h): ssdo's first five inputs (ssdo_sampling.h, the same
   enumerators), then albedo and light, required here. */
#define SSG_BOUNCE_IN(X)                                                                   \
    SSG_SSDO_GEOM_IN(X)                                                                    \
    X(SSG_SSDO_IN_ALBEDO, "albedo", SSG_T_COLOR, "diffuse albedo of the receiver")         \
    X(SSG_SSDO_IN_LIGHT, "light", SSG_T_COLOR,                                             \
      "the senders' radiance: the first pass's direct light (ssdo mode=radiance)")
#define SSG_BOUNCE_OUT(X)                                                                  \
    X(SSG_BOUNCE_OUT_OUT, "out", SSG_T_COLOR, "one indirect bounce, albedo * sum F_i L_i")
SSG_PORT_ENUM(ssg_bounce_output, SSG_BOUNCE_OUT, SSG_BOUNCE_OUTPUTS);

/* The parameters: ssdo's sampling rows (ssdo_sampling.h), their meanings and defaults. */
SSG_PARAMS_STRUCT(ssg_bounce_params, SSG_SSDO_GEOM_PARAMS);

struct ssg_bounce_consts {
    struct ssg_bounce_params p; /* the parameters as given */
    struct ssg_projection proj; /* the frame's camera as the G-buffer's resolution sees
                                   it (ssg_sampling_projection) */
    struct ssg_ssdo_geom g;     /* the sampling's constants (ssg_ssdo_geom_of) */
};

enum ssg_err ssg_bounce_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);
/* The GL side (bounce_gl.c, ssdo's shader ssdo/ssdo.glsl). */
enum ssg_err ssg_bounce_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
