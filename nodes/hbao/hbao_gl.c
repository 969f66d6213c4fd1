/* hbao_gl.c - GL side of the `hbao` node (method in hbao.c, shader hbao.glsl): one pass,
 * one invocation per pixel, both falloffs and every optional input. The per-run values
 * the CPU kernel derives in C (the projection of this resolution, 1 / f, f R, 1 / steps,
 * strength / directions, and each column's basis vector e1) are derived here by the same
 * C expressions and passed as uniforms and a storage buffer, so that both backends start
 * from the same bits; the direction tables come from prepare(). */
#include <math.h>
#include <stdlib.h>

#include "gl/gl.h"
#include "hbao_cpu.h"

/* e1 = (1, 0, a_u) / sqrt(1 + a_u^2) per column, as hbao_pattern.c computes it: e1x for
   the w columns, then e1z. NULL when out of memory. */
static float *column_basis(int w, const struct ssg_projection *sp)
{
    float *e1 = malloc(2 * (size_t)w * sizeof *e1);
    for (int x = 0; e1 && x < w; x++) {
        float au = ((float)x + 0.5f - sp->cx) / sp->f;
        float h = 1.0f / sqrtf(1.0f + au * au);
        e1[x] = h;
        e1[w + x] = au * h;
    }
    return e1;
}

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
    /* The CPU kernel's checks of the shapes (hbao_pattern.c): no pixel is read there. */
    enum ssg_err e = ssg_hbao_images_check(ctx, io);
    if (e != SSG_OK)
        return e;
    const struct ssg_image *pos = io->in[SSG_HBAO_IN_POSITION];
    struct ssg_image *out = io->out[0];
    /* A G-buffer of another size than the frame (subsampled) sees the same camera. */
    struct ssg_projection sp = ssg_projection_scaled(&c->proj, c->frame_width,
                                                     c->frame_height, pos->width,
                                                     pos->height);
    float *e1 = column_basis(pos->width, &sp);
    if (!e1)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "hbao", "out of memory for the column table");
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "hbao.glsl", NULL);
    ssg_gl_buffer(&p, 0, e1, 2 * (size_t)pos->width * sizeof *e1);
    free(e1);
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
