/* gtao.c - the `gtao` node's descriptor, check and prepare: ground-truth ambient
 * occlusion. Method, geometry and sources: README.md in this folder. */
#include <math.h>
#include <stdio.h>

#include "common/horizon.h"
#include "gtao.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_shape *pos = &in[SSG_GTAO_IN_POSITION], *back = &in[SSG_GTAO_IN_BACK];
    enum ssg_err e = ssg_sampling_check_ao(pos, &in[SSG_GTAO_IN_NORMAL], NULL,
                                           &in[SSG_GTAO_IN_ROTATION], &in[SSG_GTAO_IN_DEPTH],
                                           NULL, out, why, why_len);
    if (e)
        return e;
    if (back->channels != 0 && (back->channels != 1 || !ssg_shape_same_size(back, pos))) {
        snprintf(why, why_len, "back must be a 1-channel image the size of position");
        return SSG_E_SIZE;
    }
    if (back->channels != 0 && ((const struct ssg_gtao_params *)params)->thickness > 0) {
        snprintf(why, why_len, "thickness (a guess at how thick occluders are) and back "
                 "(how thick they are) answer one question: give one");
        return SSG_E_VALUE;
    }
    out[SSG_GTAO_OUT_BENT_NORMAL] =
        (struct ssg_shape){pos->width, pos->height, 3, SSG_T_VECTOR};
    return SSG_OK;
}

/* The consts with e1 for the G-buffer's columns. */
static size_t consts_size_of(const void *params, const struct ssg_shape *in)
{
    return ssg_horizon_consts_size(sizeof(struct ssg_gtao_consts), &in[SSG_GTAO_IN_POSITION]);
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_gtao_consts *c = consts;
    const struct ssg_gtao_params *q = &c->p;
    c->p = *(const struct ssg_gtao_params *)params;
    enum ssg_err e = ssg_horizon_frame(ctx, &ctx->in_shape[SSG_GTAO_IN_POSITION],
                                       &c->proj, &c->invf, c->e1);
    /* XeGTAO's fade: w = 1 up to (1 - falloff) R, 0 at R: w = r mul + add. */
    float range = q->falloff * q->radius;
    c->u.fall_mul = q->falloff > 0 ? -1.0f / range : 0.0f;
    c->u.fall_add = q->falloff > 0 ? q->radius / range : 1.0f;
    c->u.link = SSG_GTAO_BACK_LINK * q->radius;
    return e;
}

void ssg_gtao_frame_of(const struct ssg_gtao_consts *c, int frame, struct ssg_gtao_frame *f)
{
    /* Frame 0: turn 0 and shift 0, the single-frame slices pi k / slices and noise. */
    ssg_horizon_angles(c->p.slices, M_PI, ssg_sampling_frame_turn(frame), f->slice_cos,
                           f->slice_sin);
    f->shift = ssg_sampling_frame_shift(frame);
}

SSG_PARAMS_TABLE(params, ssg_gtao_params, SSG_GTAO_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_gtao_uniforms, SSG_GTAO_UNIFORMS);

SSG_PORT_TABLE(inputs, SSG_GTAO_IN);
SSG_PORT_TABLE(outputs, SSG_GTAO_OUT);

/* Flops per pixel (node.h), by reading gtao_cpu.c: per slice about 70 (its frame and the
   arc integral's polynomials), per step of each side about 22, about 40 per pixel. */
static double gtao_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_gtao_consts *c = consts;
    return 40.0 + c->p.slices * (70.0 + 2.0 * 22.0 * c->p.steps);
}

const struct ssg_node_desc ssg_node_gtao = {
    .name = "gtao",
    .summary = "ground-truth (horizon-based, cosine-weighted) ambient occlusion",
    .method = "Jimenez, Wu, Pesce and Jarabo, Practical Realtime Strategies for Accurate "
              "Indirect Occlusion (SIGGRAPH 2016), sec. 4: slices about the view vector, "
              "two horizons per slice clamped to the normal's hemisphere, the analytic "
              "cosine-weighted inner integral weighted by the projected normal's length; "
              "sec. 4.3 distance falloff and thickness heuristic",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_gtao_params),
    .consts_size_of = consts_size_of,
    /* its slices turn every frame (docs/time.md) */
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA | SSG_READS_FRAME,
    SSG_NODE_UNIFORMS(uniforms, struct ssg_gtao_consts, u),
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = gtao_flops,
    .run_cpu = ssg_gtao_run_cpu,
    .run_gl = ssg_gtao_run_gl,
    .parity = {.max = 1.2e-6, .mean = 1.4e-7}, /* test_gl_gtao.c: 3.0e-7, 3.3e-8: 4x */
};
