/* halton_gl.c - GL side of the `halton` node (method in README.md): the running frame's
 * kernel and rotation tile are made on the CPU by ssg_halton_frame, as for the CPU
 * backend, and copied into the two outputs (ssg_gl_fill). No Halton maths runs in GLSL:
 * both backends hold the very same floats. */
#include <stdlib.h>

#include "gl/gl.h"
#include "halton.h"

enum ssg_err ssg_halton_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    const struct ssg_halton_consts *c = consts;
    /* The largest kernel and tile: 76 KiB, too much for a stack frame we do not own. */
    size_t cells = (size_t)c->n * (size_t)c->n;
    float *kernel = malloc(sizeof(float) * (3 * (size_t)c->count + (size_t)c->planes * cells));
    if (!kernel)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the frame's kernel");
    float *pattern = kernel + 3 * (size_t)c->count;
    ssg_halton_frame(c, ctx->frame_index, kernel, pattern);
    const float *planes[2] = {kernel, pattern};
    enum ssg_err e = ssg_gl_fill(ctx, planes, io->out, 2);
    free(kernel);
    return e;
}
