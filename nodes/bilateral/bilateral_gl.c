/* bilateral_gl.c - GL side of the `bilateral` node (method in README.md, shader
 * bilateral.glsl): the full 2D window in one pass, or separable=true as a row pass into a
 * scratch image and a column pass over it, or the `atrous` node's dilated passes through
 * two scratch images in turn, as bilateral_cpu.c does. The spatial
 * log-weights from prepare() go to a storage buffer; the normal term's variant (by
 * squarings or through ln) is prepare()'s, as on the CPU. prepare()'s constants are bound
 * by the table (bilateral.h); by hand only what each pass has of its own (its source and
 * destination, the inputs or scratch images, its reach and step) and the inputs every
 * pass shares (ssg_gl_ports would bind in and out, which the passes replace). */
#include <stdio.h>

#include "bilateral.h"
#include "gl/gl.h"

static void one_pass(struct ssg_gl_pass *p, const struct ssg_image *src,
                     const struct ssg_image *src2, struct ssg_image *dst,
                     struct ssg_image *dst2, const struct ssg_bilateral_pass *pass)
{
    ssg_gl_input(p, "src", src);
    if (src2) /* the shader reads src2 only when compiled with IN2_CH > 0 */
        ssg_gl_input(p, "src2", src2);
    ssg_gl_output(p, "dst", dst);
    ssg_gl_output(p, "dst2", dst2);
    ssg_gl_ivec2(p, "reach", pass->rx, pass->ry);
    ssg_gl_int(p, "step", pass->step);
    ssg_gl_dispatch(p, src->width, src->height);
}

/* Binds what the passes share and runs them (ssg_bilateral_passes): pass 0 from the
   inputs, the last into the outputs, the others through tmp[i % 2] (tmp2 for in2). Without
   in2 a pass's dst2 (zeros) goes to out2, written again by the last. */
static enum ssg_err run(const struct ssg_node_ctx *ctx, const struct ssg_bilateral_consts *c,
                        const struct ssg_io *io, int passes,
                        const struct ssg_bilateral_pass *pass, struct ssg_image *tmp[2],
                        struct ssg_image *tmp2[2])
{
    const struct ssg_image *nrm = io->in[SSG_BILATERAL_IN_NORMAL];
    const struct ssg_image *in2 = io->in[SSG_BILATERAL_IN_IN2];
    struct ssg_image *out = io->out[SSG_BILATERAL_OUT_OUT];
    struct ssg_image *out2 = io->out[SSG_BILATERAL_OUT_OUT2];
    char defines[96];
    snprintf(defines, sizeof defines,
             "#define CHANNELS %d\n#define IN2_CH %d\n#define NORMALS %d\n",
             io->in[SSG_BILATERAL_IN_IN]->channels, in2 ? in2->channels : 0,
             nrm && c->u.normal_power > 0);
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "bilateral.glsl", defines);
    ssg_gl_buffer(&p, 0, c->spatial, sizeof(float) * (size_t)c->u.size * (size_t)c->u.size);
    ssg_gl_input(&p, "depth", io->in[SSG_BILATERAL_IN_DEPTH]);
    if (nrm && c->u.normal_power > 0) /* NORMALS 1: the only variant that reads it */
        ssg_gl_input(&p, "normal", nrm);
    for (int i = 0; i < passes; i++) {
        const struct ssg_image *src = i ? tmp[(i - 1) % 2] : io->in[SSG_BILATERAL_IN_IN];
        const struct ssg_image *src2 = i ? tmp2[(i - 1) % 2] : in2;
        int last = i == passes - 1;
        struct ssg_image *dst = last ? out : tmp[i % 2];
        struct ssg_image *dst2 = last || !in2 ? out2 : tmp2[i % 2];
        one_pass(&p, src, src2, dst, dst2, &pass[i]);
    }
    return ssg_gl_pass_end(&p);
}

enum ssg_err ssg_bilateral_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io)
{
    const struct ssg_bilateral_consts *c = consts;
    const struct ssg_image *in = io->in[SSG_BILATERAL_IN_IN];
    const struct ssg_image *in2 = io->in[SSG_BILATERAL_IN_IN2];
    struct ssg_bilateral_pass pass[SSG_BILATERAL_MAX_PASSES];
    int passes = ssg_bilateral_passes(c, pass), buffers = passes > 2 ? 2 : passes - 1;
    struct ssg_image *tmp[2] = {NULL, NULL}, *tmp2[2] = {NULL, NULL};
    int ok = 1;
    for (int b = 0; b < buffers; b++) {
        tmp[b] = ssg_gl_scratch(ctx, in->width, in->height, in->channels);
        if (in2)
            tmp2[b] = ssg_gl_scratch(ctx, in2->width, in2->height, in2->channels);
        ok = ok && tmp[b] && (tmp2[b] || !in2);
    }
    enum ssg_err e = ok ? run(ctx, c, io, passes, pass, tmp, tmp2) : SSG_E_NOMEM;
    for (int b = 0; b < 2; b++) {
        ssg_gl_scratch_release(&tmp[b]);
        ssg_gl_scratch_release(&tmp2[b]);
    }
    return e;
}
