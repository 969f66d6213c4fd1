/* halton_gl.c - GL side of the `halton` node (method in halton.c): prepare() already made
 * the kernel and the rotation tile on the CPU, as for the CPU backend, so running is
 * copying those bytes into the two outputs through a storage buffer (halton_copy.glsl).
 * No Halton maths runs in GLSL: both backends hold the very same floats. */
#include "gl.h"
#include "halton.h"

/* One prepared image (planar floats) into `dst`, every channel in one dispatch. */
static void copy_planes(struct ssg_gl_pass *p, const float *planes, struct ssg_image *dst)
{
    size_t texels = (size_t)dst->width * (size_t)dst->height * (size_t)dst->channels;
    ssg_gl_buffer(p, 0, planes, texels * sizeof(float));
    ssg_gl_output(p, "dst", dst);
    ssg_gl_int(p, "channels", dst->channels);
    ssg_gl_dispatch(p, dst->width, dst->height);
}

enum ssg_err ssg_halton_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    const struct ssg_halton_consts *c = consts;
    struct ssg_image *kernel = io->out[0], *rotation = io->out[1];
    if (!ssg_image_is(kernel, c->count, 1, 3) || !ssg_image_is(rotation, c->n, c->n, 2))
        return ssg_node_fail(ctx, SSG_E_SIZE, "halton",
                             "outputs must be count x 1 x 3 and n x n x 2");
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "halton_copy.glsl", NULL);
    copy_planes(&p, c->kernel, kernel);
    copy_planes(&p, c->pattern, rotation);
    return ssg_gl_pass_end(&p);
}
