/* ssao_gl.c - GL side of the `ssao` node (method in ssao.c, shader ssao.glsl): one pass,
 * one invocation per pixel, every mode, range check and optional input. The projection
 * of this resolution comes from prepare(); what the CPU kernel works out once per run
 * (the cap's factor, 1 / K) is worked out here the same way and passed as uniforms, so
 * both backends start from the same bits. */
#include "gl/gl.h"
#include "ssao.h"

enum ssg_err ssg_ssao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    const struct ssg_ssao_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_SSAO_IN_POSITION];
    const struct ssg_image *ker = io->in[SSG_SSAO_IN_KERNEL];
    struct ssg_image *out = io->out[0];
    const struct ssg_projection sp = c->proj;
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "ssao.glsl", NULL);
    ssg_gl_input(&p, "position", pos);
    ssg_gl_input(&p, "normal", io->in[SSG_SSAO_IN_NORMAL]);
    ssg_gl_input(&p, "kernel", ker);
    ssg_gl_input(&p, "rotation", io->in[SSG_SSAO_IN_ROTATION]);
    ssg_gl_input(&p, "depth", io->in[SSG_SSAO_IN_DEPTH]);
    ssg_gl_input(&p, "count", io->in[SSG_SSAO_IN_COUNT]);
    ssg_gl_output(&p, "dst", out);
    ssg_gl_int(&p, "mode", c->p.mode);
    ssg_gl_int(&p, "range_check", c->p.range_check);
    ssg_gl_float(&p, "radius", c->p.radius);
    ssg_gl_float(&p, "bias", c->p.bias);
    ssg_gl_float(&p, "power", c->p.power);
    ssg_gl_float(&p, "cap", c->p.max_screen_radius / sp.f);
    ssg_gl_int(&p, "capped", c->p.max_screen_radius > 0.0f);
    ssg_gl_float(&p, "inv_samples", 1.0f / (float)ker->width);
    ssg_gl_projection(&p, "proj", &sp);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
