/* ssao_gl.c - GL side of the `ssao` node (method in README.md, shader ssao.glsl): one pass,
 * one invocation per pixel, every mode, range check and optional input. Parameters and
 * ports are bound by the descriptor's tables, and so are the constants prepare() makes
 * (the projection of position's size too), so both backends start from the same bits. */
#include "gl/gl.h"
#include "ssao.h"

enum ssg_err ssg_ssao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    (void)consts; /* bound from the tables by the pass */
    const struct ssg_image *pos = io->in[SSG_SSAO_IN_POSITION];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "ssao.glsl", NULL);
    ssg_gl_ports(&p, io);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
