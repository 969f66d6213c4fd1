/* downsample_gl.c - GL side of the `downsample` node (method in README.md, shader
 * downsample.glsl): one pass over the output, every port copied from the representative
 * pixel its invocation picks, the ports and the factor bound by the descriptor's tables
 * (an output nothing reads takes its stores in a scratch image: ssg_gl_ports). It only
 * selects pixels, so the result equals the CPU's. */
#include "downsample.h"
#include "gl/gl.h"

enum ssg_err ssg_downsample_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io)
{
    (void)consts;
    const struct ssg_shape *low = &ctx->out_shape[SSG_DOWNSAMPLE_OUT_DEPTH];
    struct ssg_gl_pass pass;
    ssg_gl_pass_begin(&pass, ctx, "downsample.glsl", NULL);
    ssg_gl_ports(&pass, io);
    ssg_gl_dispatch(&pass, low->width, low->height);
    return ssg_gl_pass_end(&pass);
}
