/* hbao_gl.c - GL side of the `hbao` node (method in hbao.c, shader hbao.glsl): one pass,
 * one invocation per pixel, both falloffs and every optional input. The projection of
 * this resolution, the columns' basis vectors e1 and the direction tables come from
 * prepare(); the per-run values the CPU kernel derives in C (1 / f, f R, 1 / steps,
 * strength / directions) are derived here by the same C expressions and passed as
 * uniforms, so that both backends start from the same bits. */
#include <math.h>
#include <stdlib.h>

#include "gl/gl.h"
#include "hbao_cpu.h"

static void set_uniforms(struct ssg_gl_pass *p, const struct ssg_hbao_consts *c,
                         const struct ssg_projection *sp)
{
    const struct ssg_hbao_params *q = &c->p;
    ssg_gl_int(p, "directions", q->directions);
    ssg_gl_int(p, "steps", q->steps);
    ssg_gl_int(p, "linear", q->falloff == SSG_HBAO_FALLOFF_LINEAR);
    ssg_gl_float(p, "radius", q->radius);
    ssg_gl_float(p, "r2", q->radius * q->radius);
    ssg_gl_float(p, "inv_radius", 1.0f / q->radius);
    ssg_gl_float(p, "cap", q->max_screen_radius);
    ssg_gl_float(p, "rf", sp->f * q->radius);
    ssg_gl_float(p, "invf", 1.0f / sp->f);
    ssg_gl_float(p, "inv_steps", 1.0f / (float)q->steps);
    ssg_gl_float(p, "cos_bias", c->cos_bias);
    ssg_gl_float(p, "sin_bias", c->sin_bias);
    ssg_gl_float(p, "strength", q->strength);
    ssg_gl_float(p, "scale", q->strength / (float)q->directions);
    ssg_gl_projection(p, "proj", sp);
    ssg_gl_floats(p, "dir_cos", q->directions, c->dir_cos);
    ssg_gl_floats(p, "dir_sin", q->directions, c->dir_sin);
    ssg_gl_ints(p, "dir_rank", q->directions, c->dir_rank);
}

enum ssg_err ssg_hbao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    const struct ssg_hbao_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_HBAO_IN_POSITION];
    struct ssg_image *out = io->out[0];
    const struct ssg_projection sp = c->proj;
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "hbao.glsl", NULL);
    ssg_gl_buffer(&p, 0, c->e1, 2 * (size_t)pos->width * sizeof *c->e1);
    ssg_gl_input(&p, "position", pos);
    ssg_gl_input(&p, "normal", io->in[SSG_HBAO_IN_NORMAL]);
    ssg_gl_input(&p, "rotation", io->in[SSG_HBAO_IN_ROTATION]);
    ssg_gl_input(&p, "depth", io->in[SSG_HBAO_IN_DEPTH]);
    ssg_gl_input(&p, "count", io->in[SSG_HBAO_IN_COUNT]);
    ssg_gl_output(&p, "dst", out);
    set_uniforms(&p, c, &sp);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
