/* bounce_gl.c - GL side of the `bounce` node (method in bounce.md): ssdo's shader
 * (ssdo/ssdo.glsl) with SSDO_BOUNCE_NODE defined, which runs only the sampling and the
 * bounce, as bounce_cpu.c runs only ssdo_sampling.h's part of ssdo. Ports, parameters and
 * prepare()'s cap and projection are bound by bounce's tables (the constants' rows are
 * ssdo_sampling.h's SSG_SSDO_GEOM_UNIFORMS, ssdo's first). */
#include "bounce.h"
#include "gl/gl.h"
#include "ssdo.h"

enum ssg_err ssg_bounce_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    (void)consts;
    const struct ssg_image *pos = io->in[SSG_SSDO_IN_POSITION];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "ssdo.glsl", "#define SSDO_BOUNCE_NODE 1\n");
    ssg_gl_ports(&p, io);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
