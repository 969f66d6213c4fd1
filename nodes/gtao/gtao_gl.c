/* gtao_gl.c - GL side of the `gtao` node (method in gtao.c, shader gtao.glsl): one pass,
 * one invocation per pixel, writing both outputs. The projection, the columns' basis
 * vectors, the slice table and the falloff factors come from prepare(); 1 / f is derived
 * here by the CPU kernel's C expression and passed as a uniform, so that both backends
 * start from the same bits. */
#include "gl/gl.h"
#include "gtao.h"

enum ssg_err ssg_gtao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    const struct ssg_gtao_consts *c = consts;
    const struct ssg_gtao_params *q = &c->p;
    const struct ssg_image *pos = io->in[SSG_GTAO_IN_POSITION];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "gtao.glsl", NULL);
    ssg_gl_buffer(&p, 0, c->e1, 2 * (size_t)pos->width * sizeof *c->e1);
    ssg_gl_input(&p, "position", pos);
    ssg_gl_input(&p, "normal", io->in[SSG_GTAO_IN_NORMAL]);
    ssg_gl_input(&p, "rotation", io->in[SSG_GTAO_IN_ROTATION]);
    ssg_gl_input(&p, "depth", io->in[SSG_GTAO_IN_DEPTH]);
    ssg_gl_input(&p, "back", io->in[SSG_GTAO_IN_BACK]);
    ssg_gl_output(&p, "dst", io->out[SSG_GTAO_OUT_OUT]);
    ssg_gl_output(&p, "bent", io->out[SSG_GTAO_OUT_BENT_NORMAL]);
    ssg_gl_params(&p, ssg_node_gtao.params, q);
    ssg_gl_float(&p, "fall_mul", c->fall_mul);
    ssg_gl_float(&p, "fall_add", c->fall_add);
    ssg_gl_float(&p, "link", c->link);
    ssg_gl_float(&p, "invf", 1.0f / c->proj.f);
    ssg_gl_projection(&p, "proj", &c->proj);
    ssg_gl_floats(&p, "slice_cos", q->slices, c->slice_cos);
    ssg_gl_floats(&p, "slice_sin", q->slices, c->slice_sin);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
