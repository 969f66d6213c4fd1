/* @name@_gl.c - the GL side of the `@name@` node (method in README.md, shader @name@.glsl):
 * one pass, one invocation per pixel. Ports are bound by their names and parameters by
 * the table (#pragma ssg_params), so nothing here names a uniform by hand. */
#include "@name@.h"
#include "gl/gl.h"

enum ssg_err ssg_@name@_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    (void)consts;
    const struct ssg_image *src = io->in[SSG_@NAME@_IN_SRC];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "@name@.glsl", NULL);
    ssg_gl_ports(&p, io);
    ssg_gl_dispatch(&p, src->width, src->height);
    return ssg_gl_pass_end(&p);
}
