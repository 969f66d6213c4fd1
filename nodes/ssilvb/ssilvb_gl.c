/* ssilvb_gl.c - GL side of the `ssilvb` node (method in ssilvb.c, shader ssilvb.glsl): one
 * pass, one invocation per pixel, writing both outputs. The projection, the columns' basis
 * vectors, the slice and turn tables and the seed's noise offsets come from prepare(); 1 / f
 * is derived here by the CPU kernel's C expression, so that both backends start from the
 * same bits. */
#include "gl/gl.h"
#include "ssilvb.h"

enum ssg_err ssg_ssilvb_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    const struct ssg_ssilvb_consts *c = consts;
    const struct ssg_ssilvb_params *q = &c->p;
    const struct ssg_image *pos = io->in[SSG_SSILVB_IN_POSITION];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "ssilvb.glsl", NULL);
    ssg_gl_buffer(&p, 0, c->e1, 2 * (size_t)pos->width * sizeof *c->e1);
    ssg_gl_input(&p, "position", pos);
    ssg_gl_input(&p, "normal", io->in[SSG_SSILVB_IN_NORMAL]);
    ssg_gl_input(&p, "depth", io->in[SSG_SSILVB_IN_DEPTH]);
    ssg_gl_input(&p, "light", io->in[SSG_SSILVB_IN_LIGHT]);
    ssg_gl_input(&p, "albedo", io->in[SSG_SSILVB_IN_ALBEDO]);
    ssg_gl_input(&p, "back", io->in[SSG_SSILVB_IN_BACK]);
    ssg_gl_output(&p, "dst", io->out[SSG_SSILVB_OUT_AO]);
    ssg_gl_output(&p, "bounce", io->out[SSG_SSILVB_OUT_BOUNCE]);
    ssg_gl_params(&p, ssg_node_ssilvb.params, q);
    ssg_gl_float(&p, "invf", 1.0f / c->proj.f);
    ssg_gl_projection(&p, "proj", &c->proj);
    ssg_gl_vec4(&p, "noise_off", c->noise_off);
    ssg_gl_floats(&p, "slice_cos", q->slices, c->slice_cos);
    ssg_gl_floats(&p, "slice_sin", q->slices, c->slice_sin);
    ssg_gl_floats(&p, "turn_cos", SSG_SSILVB_TURNS, c->turn_cos);
    ssg_gl_floats(&p, "turn_sin", SSG_SSILVB_TURNS, c->turn_sin);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
