/* lightprobe_gl.c - GL side of the `lightprobe` node (README.md): the light list made in
 * prepare() copied into the output texture (ssg_gl_fill), the CPU's very bytes. */
#include "gl/gl.h"
#include "lightprobe.h"

enum ssg_err ssg_lightprobe_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io)
{
    const struct ssg_lightprobe_consts *c = consts;
    const float *planes[1] = {c->lights};
    return ssg_gl_fill(ctx, planes, io->out, 1);
}
