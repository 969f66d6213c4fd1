/* gaussian_gl.c - GL side of the `gaussian` node (method in README.md): the horizontal
 * pass into a scratch image, then the vertical one, one dispatch per channel, the weights
 * from prepare() in a storage buffer, the radius by the table (#pragma ssg_consts). What
 * is bound by hand is each dispatch's own: the scratch image between the passes, the
 * axis and the channel. */
#include "gaussian.h"
#include "gl/gl.h"

static void one_axis(struct ssg_gl_pass *p, const struct ssg_image *src, struct ssg_image *dst,
                     int ax, int ay)
{
    ssg_gl_input(p, "src", src);
    ssg_gl_output(p, "dst", dst);
    ssg_gl_ivec2(p, "axis", ax, ay);
    for (int ch = 0; ch < src->channels; ch++) {
        ssg_gl_int(p, "layer", ch);
        ssg_gl_dispatch(p, src->width, src->height);
    }
}

enum ssg_err ssg_gaussian_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io)
{
    const struct ssg_gaussian_consts *c = consts;
    const struct ssg_image *in = io->in[SSG_GAUSSIAN_IN_IN];
    struct ssg_image *out = io->out[SSG_GAUSSIAN_OUT_OUT];
    struct ssg_image *tmp = ssg_gl_scratch(ctx, in->width, in->height, in->channels);
    if (!tmp)
        return SSG_E_NOMEM;
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "gaussian.glsl", NULL);
    ssg_gl_buffer(&p, 0, c->weight, (size_t)(2 * c->u.radius + 1) * sizeof(float));
    one_axis(&p, in, tmp, 1, 0);
    one_axis(&p, tmp, out, 0, 1);
    ssg_gl_scratch_release(&tmp);
    return ssg_gl_pass_end(&p);
}
