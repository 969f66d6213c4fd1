/* upsample_gl.c - GL side of the `upsample` node (method in README.md, shader
 * upsample.glsl): one pass over the full-res frame, in and the optional in2 upsampled
 * with the same weights, out2 written 0 when in2 is unconnected or out2 unread; every
 * constant is prepare()'s, as on the CPU. Ports and constants are bound by the tables (upsample.h
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
    /* out2 nobody reads (on_demand): in2 is not upsampled (IN2_CH 0, as on the CPU), and
       ssg_gl_ports gives the shader's zero stores a scratch image */
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "upsample.glsl", defines);
    ssg_gl_ports(&p, io);
    ssg_gl_dispatch(&p, io->out[0]->width, io->out[0]->height);
    return ssg_gl_pass_end(&p);
}
