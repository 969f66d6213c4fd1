/* upsample_gl.c - GL side of the `upsample` node (method in README.md, shader
 * upsample.glsl): one pass over the full-res frame, in and the optional in2 upsampled
 * with the same weights, out2 written 0 when in2 is unconnected; every constant is
 * prepare()'s, as on the CPU. */
#include <stdio.h>

#include "gl/gl.h"
#include "upsample.h"

enum ssg_err ssg_upsample_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io)
{
    const struct ssg_upsample_consts *c = consts;
    const int k = c->factor;
    const struct ssg_image *in2 = io->in[SSG_UPSAMPLE_IN_IN2];
    const struct ssg_image *lnrm = io->in[SSG_UPSAMPLE_IN_LOW_NORMAL];
    char defines[80];
    snprintf(defines, sizeof defines,
             "#define IN_CH %d\n#define IN2_CH %d\n#define NORMALS %d\n",
             io->in[SSG_UPSAMPLE_IN_IN]->channels, in2 ? in2->channels : 0,
             lnrm && c->normal_power > 0.0f);
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "upsample.glsl", defines);
    ssg_gl_input(&p, "src", io->in[SSG_UPSAMPLE_IN_IN]);
    if (in2) /* read only when compiled with IN2_CH > 0 */
        ssg_gl_input(&p, "src2", in2);
    ssg_gl_input(&p, "depth", io->in[SSG_UPSAMPLE_IN_DEPTH]);
    const int normals = lnrm && c->normal_power > 0.0f; /* NORMALS: reads both normals */
    if (normals)
        ssg_gl_input(&p, "normal", io->in[SSG_UPSAMPLE_IN_NORMAL]);
    ssg_gl_input(&p, "low_depth", io->in[SSG_UPSAMPLE_IN_LOW_DEPTH]);
    if (normals) {
        ssg_gl_input(&p, "low_normal", lnrm);
        ssg_gl_float(&p, "normal_power", c->normal_power);
        ssg_gl_float(&p, "normal_min", c->normal_min);
        ssg_gl_int(&p, "squarings", c->squarings);
    }
    ssg_gl_output(&p, "dst", io->out[0]);
    ssg_gl_output(&p, "dst2", io->out[1]);
    ssg_gl_int(&p, "factor", k);
    ssg_gl_int(&p, "radius", c->radius);
    ssg_gl_float(&p, "spatial_k", c->spatial_k);
    ssg_gl_float(&p, "depth_scale", c->depth_scale);
    ssg_gl_dispatch(&p, io->out[0]->width, io->out[0]->height);
    return ssg_gl_pass_end(&p);
}
