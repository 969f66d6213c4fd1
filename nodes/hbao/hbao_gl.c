/* hbao_gl.c - GL side of the `hbao` node (method in README.md, shader hbao.glsl): one pass,
 * one invocation per pixel, both falloffs and every optional input. Parameters and ports
 * are bound by the descriptor's tables; the projection, the columns' basis vectors e1,
 * the direction tables and the derived values (1 / f, f R, 1 / steps, ...) are
 * prepare()'s, so both backends start from the same bits. */
#include "common/horizon_gl.h"
#include "hbao.h"

enum ssg_err ssg_hbao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    const struct ssg_hbao_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_HBAO_IN_POSITION];
    const int nd = c->p.directions;
    struct ssg_gl_pass p;
    ssg_horizon_gl_begin(&p, ctx, "hbao.glsl", io, c->e1, &c->proj, c->invf);
    ssg_gl_floats(&p, "dir_cos", nd, c->dir_cos);
    ssg_gl_floats(&p, "dir_sin", nd, c->dir_sin);
    ssg_gl_ints(&p, "dir_rank", nd, c->dir_rank);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
