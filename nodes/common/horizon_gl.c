/* horizon_gl.c - the GL pass setup of the horizon nodes (horizon_gl.h). */
#include "common/horizon_gl.h"

void ssg_horizon_gl_begin(struct ssg_gl_pass *p, const struct ssg_node_ctx *ctx,
                          const char *shader, const struct ssg_io *io, const float *e1,
                          const struct ssg_projection *proj, float invf)
{
    ssg_gl_pass_begin(p, ctx, shader, NULL);
    ssg_gl_buffer(p, 0, e1, 2 * (size_t)io->in[0]->width * sizeof *e1);
    ssg_gl_ports(p, io);
    ssg_gl_float(p, "invf", invf);
    ssg_gl_projection(p, "proj", proj);
}
