/* input_gl.c - the `input` node on GL: the supplied image's planes filled into the output
 * texture (ssg_gl_fill), the same bytes as the CPU copy. */
#include "gl/gl.h"
#include "input.h"

const struct ssg_image *ssg_input_image(const struct ssg_node_ctx *ctx);

enum ssg_err ssg_input_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_image *src = ssg_input_image(ctx);
    if (!src)
        return SSG_E_MISSING_INPUT;
    const float *planes[1] = {src->data};
    return ssg_gl_fill(ctx, planes, &io->out[SSG_INPUT_OUT_OUT], 1);
}
