/* upsample_gl.c - GL side of the `upsample` node (method in README.md, shader
 * upsample.glsl): one pass over the full-res frame, in and the optional in2 upsampled
 * with the same weights, out2 written 0 when in2 is unconnected (into a scratch image when
 * nobody reads out2); every constant is
 * prepare()'s, as on the CPU. Ports and constants are bound by the tables (upsample.h
 * marks what only the NORMALS and IN2_CH variants read). */
#include <stdio.h>

#include "gl/gl.h"
#include "upsample.h"

enum ssg_err ssg_upsample_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io)
{
    const struct ssg_upsample_consts *c = consts;
    const struct ssg_image *in2 = io->in[SSG_UPSAMPLE_IN_IN2];
    const struct ssg_image *lnrm = io->in[SSG_UPSAMPLE_IN_LOW_NORMAL];
    char defines[80];
    snprintf(defines, sizeof defines,
             "#define IN_CH %d\n#define IN2_CH %d\n#define NORMALS %d\n",
             io->in[SSG_UPSAMPLE_IN_IN]->channels, in2 && io->out[1] ? in2->channels : 0,
             lnrm && c->normal_power > 0.0f);
    /* the shader stores out2 always: where nobody reads it (on_demand, no image) in2 is
       not upsampled (IN2_CH 0, as on the CPU) and a scratch image takes the stores
       (ssg_gl_unread_outputs) */
    struct ssg_gl_unread o;
    enum ssg_err e = ssg_gl_unread_outputs(ctx, io, &o);
    if (e)
        return e;
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "upsample.glsl", defines);
    ssg_gl_ports(&p, &o.io);
    ssg_gl_dispatch(&p, o.out[0]->width, o.out[0]->height);
    e = ssg_gl_pass_end(&p);
    ssg_gl_unread_release(&o);
    return e;
}
