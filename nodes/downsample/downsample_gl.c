/* downsample_gl.c - GL side of the `downsample` node (method in README.md, shader
 * downsample.glsl): one pass over the output, every port copied from the representative
 * pixel its invocation picks, the ports and the factor bound by the descriptor's tables.
 * It only selects pixels, so the result equals the CPU's. */
#include <string.h>

#include "downsample.h"
#include "gl/gl.h"

/* The shader stores every port: an output nothing reads (on_demand, bound to no image)
   gets a scratch image, so that its stores never land in another output's image unit. */
enum ssg_err ssg_downsample_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io)
{
    (void)consts;
    struct ssg_image *out[SSG_DOWNSAMPLE_OUTPUTS], *scratch[SSG_DOWNSAMPLE_OUTPUTS] = {0};
    memcpy(out, io->out, sizeof out);
    const struct ssg_shape *low = &ctx->out_shape[SSG_DOWNSAMPLE_OUT_DEPTH];
    enum ssg_err e = SSG_OK;
    for (int k = 0; k < SSG_DOWNSAMPLE_OUTPUTS && !e; k++)
        if (!out[k]) {
            out[k] = scratch[k] = ssg_gl_scratch(ctx, low->width, low->height,
                                                 ctx->out_shape[k].channels);
            e = scratch[k] ? SSG_OK : ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
        }
    struct ssg_io bound = *io;
    bound.out = out;
    if (!e) {
        struct ssg_gl_pass pass;
        ssg_gl_pass_begin(&pass, ctx, "downsample.glsl", NULL);
        ssg_gl_ports(&pass, &bound);
        ssg_gl_dispatch(&pass, low->width, low->height);
        e = ssg_gl_pass_end(&pass);
    }
    for (int k = 0; k < SSG_DOWNSAMPLE_OUTPUTS; k++)
        ssg_gl_scratch_release(&scratch[k]);
    return e;
}
