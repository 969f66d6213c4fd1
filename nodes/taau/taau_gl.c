/* taau_gl.c - the GL side of the `taau` node (method in README.md, shader taau.glsl): one
 * pass, one invocation per output pixel. Ports, parameters and prepare()'s constants are
 * bound by the tables (the frame's jitter among prepare()'s constants); ctx->history_reset,
 * which no table holds, by hand. */
#include <stdio.h>

#include "gl/gl.h"
#include "taau.h"

enum ssg_err ssg_taau_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    const struct ssg_taau_consts *c = consts;
    const struct ssg_image *in = io->in[SSG_TAAU_IN_IN];
    char defines[40];
    snprintf(defines, sizeof defines, "#define CHANNELS %d\n", in->channels);
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "taau.glsl", defines);
    ssg_gl_ports(&p, io);
    ssg_gl_int(&p, "reset", ctx->history_reset != 0);
    ssg_gl_dispatch(&p, in->width * c->p.factor, in->height * c->p.factor);
    return ssg_gl_pass_end(&p);
}
