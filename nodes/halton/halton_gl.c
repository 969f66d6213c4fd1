/* halton_gl.c - GL side of the `halton` node (method in README.md): prepare() already made
 * the kernel and the rotation tile on the CPU, as for the CPU backend, so running is
 * copying those bytes into the two outputs (ssg_gl_fill). No Halton maths runs in GLSL:
 * both backends hold the very same floats. */
#include "gl/gl.h"
#include "halton.h"

enum ssg_err ssg_halton_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    const struct ssg_halton_consts *c = consts;
    const float *planes[2] = {c->kernel, c->pattern};
    return ssg_gl_fill(ctx, planes, io->out, 2);
}
