/* combine_gl.c - GL side of the `combine` node (method in README.md, shader combine.glsl):
 * one pass, one invocation per pixel and all three channels. Parameters and ports are bound
 * by the descriptor's tables: unconnected optional inputs are zero images with their
 * `_bound` flag off, and the shader then uses the CPU's stand-ins (ao and modulation 1,
 * environment and indirect 0). The ambient factor k and the modulation's last plane are
 * prepare()'s, the CPU's very bits. */
#include "combine.h"
#include "gl/gl.h"

enum ssg_err ssg_combine_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    struct ssg_image *out = io->out[SSG_COMBINE_OUT_OUT];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "combine.glsl", NULL);
    ssg_gl_ports(&p, io);
    ssg_gl_dispatch(&p, out->width, out->height);
    return ssg_gl_pass_end(&p);
}
