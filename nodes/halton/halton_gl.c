/* halton_gl.c - GL side of the `halton` node (method in halton.c): prepare() already made
 * the kernel and the rotation tile on the CPU, as for the CPU backend, so running is
 * copying those bytes into the two outputs (ssg_gl_fill). No Halton maths runs in GLSL:
 * both backends hold the very same floats. */
#include "gl/gl.h"
#include "halton.h"

enum ssg_err ssg_halton_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    const struct ssg_halton_consts *c = consts;
    struct ssg_image *kernel = io->out[0], *rotation = io->out[1];
    if (!ssg_image_is(kernel, c->count, 1, 3) || !ssg_image_is(rotation, c->n, c->n, 2))
        return ssg_node_fail(ctx, SSG_E_SIZE, "halton",
                             "outputs must be count x 1 x 3 and n x n x 2");
    const float *planes[2] = {c->kernel, c->pattern};
    return ssg_gl_fill(ctx, planes, io->out, 2);
}
