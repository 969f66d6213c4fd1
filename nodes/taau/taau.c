/* taau.c - the `taau` node's descriptor, shape check and prepare: temporal upsampling of
 * a jittered frame into an image `factor` times its size, from this frame's samples and
 * the reprojected output of the frame before. The method, its sources and conventions:
 * README.md in this folder. */
#include <stdio.h>

#include "taau.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_taau_params *p = params;
    const struct ssg_shape *im = &in[SSG_TAAU_IN_IN];
    /* The shapes first: the graph's quiet first pass (graph_check.c) keeps them while the
       history, made by this node, is not known yet. */
    struct ssg_shape big = *im;
    big.width = im->width * p->factor;
    big.height = im->height * p->factor;
    out[SSG_TAAU_OUT_OUT] = big;
    out[SSG_TAAU_OUT_WEIGHT].width = big.width;
    out[SSG_TAAU_OUT_WEIGHT].height = big.height;
    const struct ssg_shape *hist = &in[SSG_TAAU_IN_HISTORY], *hw = &in[SSG_TAAU_IN_WEIGHT_IN];
    const struct ssg_shape *m = &in[SSG_TAAU_IN_MOTION];
    const char *e = NULL;
    if (hist->channels != im->channels || !ssg_shape_same_size(hist, &big))
        e = "history must have in's channels and factor x in's size (prev of this node's out)";
    else if (hw->channels != 1 || !ssg_shape_same_size(hw, &big))
        e = "weight_in must be 1 channel of factor x in's size (prev of this node's weight)";
    else if (m->channels != 3 || !ssg_shape_same_size(m, im))
        e = "motion must be a 3-channel image the size of in";
    else if (frame && frame->guard > 0) /* write crops a band only from frame-sized images */
        e = "a frame with a guard band (a `guard` line or --guard) is not upsampled: the "
            "band would stay in out; leave the guard band out";
    if (e) {
        snprintf(why, why_len, "%s", e);
        return SSG_E_SIZE;
    }
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_taau_consts *c = consts;
    c->p = *(const struct ssg_taau_params *)params;
    c->u.inv_factor = 1.0f / (float)c->p.factor;
    c->u.fac = (float)c->p.factor;
    c->u.neg_inv_2s2 = -1.0f / (2.0f * c->p.sigma * c->p.sigma);
    c->u.jitter_x = ctx->frame->jitter_x;
    c->u.jitter_y = ctx->frame->jitter_y;
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_taau_params, SSG_TAAU_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_taau_uniforms, SSG_TAAU_UNIFORMS);
SSG_PORT_TABLE(inputs, SSG_TAAU_IN);
SSG_PORT_TABLE(outputs, SSG_TAAU_OUT);

/* Flops per output pixel, by reading taau_cpu.c: the 3 x 3 samples' weights, sums and
   moments (9 x (1 + 5 a channel)), the mean, deviation and clamp (10 a channel), the
   Catmull-Rom weights (20) and its 16 taps (32 a channel), the blend (6 a channel). */
static double flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts;
    return 29.0 + 93.0 * in[SSG_TAAU_IN_IN].channels;
}

const struct ssg_node_desc ssg_node_taau = {
    .name = "taau",
    .summary = "temporal upsampling: a jittered frame's samples and the reprojected history "
               "gathered into an image factor x its size, the history clamped to the "
               "samples' neighbourhood",
    .method = "Karis, High Quality Temporal Supersampling, SIGGRAPH 2014 (jittered samples "
              "gathered over frames, reprojection by motion, neighbourhood clamp, "
              "Catmull-Rom history); Salvi, An Excursion in Temporal Supersampling, GDC "
              "2016 (variance clipping); the samples weighted by their distance to the "
              "output pixel and the history by its accumulated weight, as in temporal "
              "upsampling (Unreal Engine 4.19 TAAU; AMD FSR 2)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_taau_params),
    .consts_size = sizeof(struct ssg_taau_consts),
    SSG_NODE_UNIFORMS(uniforms, struct ssg_taau_consts, u),
    /* the frame's jitter (ctx->frame) is the camera's */
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = flops,
    .run_cpu = ssg_taau_run_cpu,
    .run_gl = ssg_taau_run_gl,
    /* GLSL's exp and the CPU's expf differ in the last bits of the sample weights */
    .parity = {.max = 2e-6, .mean = 2e-7},
};
