/* gtao_gl.c - GL side of the `gtao` node (method in README.md, shader gtao.glsl): one pass,
 * one invocation per pixel, writing both outputs. Parameters and ports are bound by the
 * descriptor's tables; the projection, 1 / f, the columns' basis vectors and the
 * falloff factors are prepare()'s, the frame's slice table and noise offset
 * ssg_gtao_frame_of's, so both backends start from the same bits. */
#include "common/horizon_gl.h"
#include "gtao.h"

enum ssg_err ssg_gtao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    const struct ssg_gtao_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_GTAO_IN_POSITION];
    struct ssg_gl_pass p;
    ssg_horizon_gl_begin(&p, ctx, "gtao.glsl", io, c->e1, &c->proj, c->invf);
    struct ssg_gtao_frame fr;
    ssg_gtao_frame_of(c, ctx->frame_index, &fr);
    ssg_gl_floats(&p, "slice_cos", c->p.slices, fr.slice_cos);
    ssg_gl_floats(&p, "slice_sin", c->p.slices, fr.slice_sin);
    ssg_gl_float(&p, "noise_shift", fr.shift);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
