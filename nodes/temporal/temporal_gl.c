/* temporal_gl.c - the GL side of the `temporal` node (method in README.md, shader
 * temporal.glsl): one pass, one invocation per pixel. Ports, parameters and prepare()'s
 * constants are bound by the tables (temporal.h names `in`'s GLSL name and marks what only
 * the IN2_CH and NORMALS variants read); `reset` is this run's ctx->history_reset, which
 * no table holds. */
#include <stdio.h>

#include "gl/gl.h"
#include "temporal.h"

enum ssg_err ssg_temporal_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io)
{
    const struct ssg_image *in = io->in[SSG_TEMPORAL_IN_IN];
    const struct ssg_image *in2 = io->in[SSG_TEMPORAL_IN_IN2];
    const struct ssg_image *nrm = io->in[SSG_TEMPORAL_IN_NORMAL];
    char defines[160];
    snprintf(defines, sizeof defines,
             "#define CHANNELS %d\n#define IN2_CH %d\n#define NORMALS %d\n"
             "#define SSG_TEMPORAL_MIN_WEIGHT %.9g\n",
             in->channels, in2 ? in2->channels : 0, nrm != NULL,
             (double)SSG_TEMPORAL_MIN_WEIGHT);
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "temporal.glsl", defines);
    ssg_gl_ports(&p, io);
    ssg_gl_int(&p, "reset", ctx->history_reset != 0);
    ssg_gl_dispatch(&p, in->width, in->height);
    return ssg_gl_pass_end(&p);
}
