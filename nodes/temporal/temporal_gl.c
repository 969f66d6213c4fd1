/* temporal_gl.c - the GL side of the `temporal` node (method in README.md, shader
 * temporal.glsl): one pass, one invocation per pixel. The ports are bound by hand: input
 * `in` is a GLSL keyword (bound as src), and in2, history2, normal and prev_normal only
 * where the variant (IN2_CH, NORMALS) reads them, since a bound uniform the shader lacks
 * is an error. gamma and depth_tolerance come from the table (#pragma ssg_params),
 * prepare()'s constants likewise (#pragma ssg_consts). */
#include <stdio.h>

#include "gl/gl.h"
#include "temporal.h"

enum ssg_err ssg_temporal_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io)
{
    const struct ssg_temporal_consts *c = consts;
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
    ssg_gl_input(&p, "src", in);
    ssg_gl_input(&p, "history", io->in[SSG_TEMPORAL_IN_HISTORY]);
    if (in2) {
        ssg_gl_input(&p, "src2", in2);
        ssg_gl_input(&p, "history2", io->in[SSG_TEMPORAL_IN_HISTORY2]);
    }
    ssg_gl_input(&p, "length_in", io->in[SSG_TEMPORAL_IN_LENGTH_IN]);
    ssg_gl_input(&p, "motion", io->in[SSG_TEMPORAL_IN_MOTION]);
    ssg_gl_input(&p, "depth", io->in[SSG_TEMPORAL_IN_DEPTH]);
    ssg_gl_input(&p, "prev_depth", io->in[SSG_TEMPORAL_IN_PREV_DEPTH]);
    if (nrm) {
        ssg_gl_input(&p, "normal", nrm);
        ssg_gl_input(&p, "prev_normal", io->in[SSG_TEMPORAL_IN_PREV_NORMAL]);
        ssg_gl_float(&p, "normal_tolerance", c->p.normal_tolerance);
    }
    ssg_gl_output(&p, "dst_out", io->out[SSG_TEMPORAL_OUT_OUT]);
    ssg_gl_output(&p, "dst_out2", io->out[SSG_TEMPORAL_OUT_OUT2]);
    ssg_gl_output(&p, "dst_length", io->out[SSG_TEMPORAL_OUT_LENGTH]);
    ssg_gl_int(&p, "reset", ctx->history_reset != 0);
    ssg_gl_dispatch(&p, in->width, in->height);
    return ssg_gl_pass_end(&p);
}
