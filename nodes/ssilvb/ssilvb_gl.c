/* ssilvb_gl.c - GL side of the `ssilvb` node (method in README.md, shader ssilvb.glsl): one
 * pass, one invocation per pixel, writing both outputs. Parameters and ports are bound by the
 * descriptor's tables; the projection, 1 / f, the columns' basis vectors, the turn table
 * and the seed's noise offsets are prepare()'s, the frame's slice table and offsets
 * ssg_ssilvb_frame_of's, so both backends start from the same bits. */
#include "common/horizon_gl.h"
#include "ssilvb.h"

enum ssg_err ssg_ssilvb_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    const struct ssg_ssilvb_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_SSILVB_IN_POSITION];
    struct ssg_gl_pass p;
    ssg_horizon_gl_begin(&p, ctx, "ssilvb.glsl", io, c->e1, &c->proj, c->invf);
    struct ssg_ssilvb_frame fr;
    ssg_ssilvb_frame_of(c, ctx->frame_index, &fr);
    ssg_gl_vec4(&p, "noise_off", fr.noise_off);
    ssg_gl_floats(&p, "slice_cos", c->p.slices, fr.slice_cos);
    ssg_gl_floats(&p, "slice_sin", c->p.slices, fr.slice_sin);
    ssg_gl_floats(&p, "turn_cos", SSG_SSILVB_TURNS, c->turn_cos);
    ssg_gl_floats(&p, "turn_sin", SSG_SSILVB_TURNS, c->turn_sin);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
