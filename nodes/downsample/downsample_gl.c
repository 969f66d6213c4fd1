/* downsample_gl.c - GL side of the `downsample` node (method in downsample.c, shader
 * downsample.glsl): one pass over the output, every port copied from the representative
 * pixel its invocation picks. It only selects pixels, so the result equals the CPU's. */
#include "downsample.h"
#include "gl/gl.h"

/* Sampler and image names of port k in downsample.glsl. */
static const char *const in_names[SSG_DOWNSAMPLE_INPUTS] = {
    "in_depth", "in_position", "in_normal", "in_albedo", "in_direct", "in_environment"};
static const char *const out_names[SSG_DOWNSAMPLE_INPUTS] = {
    "out_depth", "out_position", "out_normal", "out_albedo", "out_direct", "out_environment"};

enum ssg_err ssg_downsample_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io)
{
    const struct ssg_downsample_params *p = consts;
    const int ow = ctx->out_shape[SSG_DOWNSAMPLE_OUT_DEPTH].width;
    const int oh = ctx->out_shape[SSG_DOWNSAMPLE_OUT_DEPTH].height;
    struct ssg_gl_pass pass;
    ssg_gl_pass_begin(&pass, ctx, "downsample.glsl", NULL);
    for (int k = 0; k < SSG_DOWNSAMPLE_INPUTS; k++) {
        ssg_gl_input(&pass, in_names[k], io->in[k]);
        ssg_gl_output(&pass, out_names[k], io->out[k]);
    }
    ssg_gl_int(&pass, "factor", p->factor);
    ssg_gl_dispatch(&pass, ow, oh);
    return ssg_gl_pass_end(&pass);
}
