/* temporal.c - the `temporal` node's descriptor, shape check and prepare: temporal
 * accumulation of a noisy per-frame value through motion-vector reprojection, with depth
 * and normal disocclusion tests and variance clipping of the history. The method, its
 * sources and conventions: README.md in this folder. */
#include <stdio.h>

#include "temporal.h"

/* An optional input that is connected must have in's size and the given channels. */
static int bad_input(const struct ssg_shape *in, int port, int channels)
{
    const struct ssg_shape *s = &in[port], *im = &in[SSG_TEMPORAL_IN_IN];
    return s->channels != 0 && (s->channels != channels || !ssg_shape_same_size(s, im));
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    (void)params, (void)frame;
    const struct ssg_shape *im = &in[SSG_TEMPORAL_IN_IN], *im2 = &in[SSG_TEMPORAL_IN_IN2];
    const struct ssg_shape *hist = &in[SSG_TEMPORAL_IN_HISTORY];
    const struct ssg_shape *hist2 = &in[SSG_TEMPORAL_IN_HISTORY2];
    /* The shapes first: the graph's quiet first pass (graph_check.c) keeps them when the
       history is not known yet, and prev(length) must then have in's size too. */
    out[SSG_TEMPORAL_OUT_OUT] = *im;
    out[SSG_TEMPORAL_OUT_OUT2] = im2->channels != 0 ? *im2 : *im;
    out[SSG_TEMPORAL_OUT_LENGTH].width = im->width; /* in's size: a low-res accumulation */
    out[SSG_TEMPORAL_OUT_LENGTH].height = im->height;
    const char *e = NULL;
    if (hist->channels != im->channels || !ssg_shape_same_size(hist, im))
        e = "history must have in's size and channels (prev of this node's out)";
    else if ((im2->channels != 0) != (hist2->channels != 0))
        e = "in2 and history2 go together (history2 = prev of this node's out2)";
    else if (bad_input(in, SSG_TEMPORAL_IN_IN2, 3) || bad_input(in, SSG_TEMPORAL_IN_HISTORY2, 3))
        e = "in2 and history2 must be 3-channel images the size of in";
    else if (bad_input(in, SSG_TEMPORAL_IN_LENGTH_IN, 1) ||
             bad_input(in, SSG_TEMPORAL_IN_DEPTH, 1) ||
             bad_input(in, SSG_TEMPORAL_IN_PREV_DEPTH, 1))
        e = "length_in, depth and prev_depth must be 1-channel images the size of in";
    else if (bad_input(in, SSG_TEMPORAL_IN_MOTION, 3))
        e = "motion must be a 3-channel image the size of in";
    else if ((in[SSG_TEMPORAL_IN_NORMAL].channels != 0) !=
             (in[SSG_TEMPORAL_IN_PREV_NORMAL].channels != 0))
        e = "normal and prev_normal go together (prev_normal = prev of the same normal)";
    else if (bad_input(in, SSG_TEMPORAL_IN_NORMAL, 3) ||
             bad_input(in, SSG_TEMPORAL_IN_PREV_NORMAL, 3))
        e = "normal and prev_normal must be 3-channel images the size of in";
    if (e) {
        snprintf(why, why_len, "%s", e);
        return SSG_E_SIZE;
    }
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_temporal_consts *c = consts;
    (void)ctx;
    c->p = *(const struct ssg_temporal_params *)params;
    c->u.inv_max_length = 1.0f / (float)c->p.max_length;
    c->u.length_cap = (float)c->p.max_length;
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_temporal_params, SSG_TEMPORAL_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_temporal_uniforms, SSG_TEMPORAL_UNIFORMS);
SSG_PORT_TABLE(inputs, SSG_TEMPORAL_IN);
SSG_PORT_TABLE(outputs, SSG_TEMPORAL_OUT);

/* Flops per pixel, by reading temporal_cpu.c: per channel of in and in2 the 3 x 3 moments
   (9 taps x 3: add, multiply, add), mean, variance and stddev (about 6), the clamp (4),
   four bilinear taps of history (8) and the blend (3): 48; per pixel the bilinear weights
   and the four taps' tests (about 40, 52 with normals) and the length (about 12). */
static double flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts;
    int ch = in[SSG_TEMPORAL_IN_IN].channels + in[SSG_TEMPORAL_IN_IN2].channels;
    return 52.0 + 48.0 * ch + (in[SSG_TEMPORAL_IN_NORMAL].channels ? 12.0 : 0.0);
}

const struct ssg_node_desc ssg_node_temporal = {
    .name = "temporal",
    .summary = "temporal accumulation: reprojected history with depth/normal disocclusion "
               "tests, variance clipping and a capped history length",
    .method = "Schied et al., Spatiotemporal Variance-Guided Filtering, HPG 2017, sec. 4.1 "
              "(bilinear reprojection with per-tap consistency tests, history length, "
              "alpha = max(1 / n, alpha_min)); Salvi, An Excursion in Temporal "
              "Supersampling, GDC 2016 (variance clipping: mean +/- gamma sigma of the "
              "3 x 3 neighbourhood); Karis, High Quality Temporal Supersampling, "
              "SIGGRAPH 2014 (neighbourhood clamp)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_temporal_params),
    .consts_size = sizeof(struct ssg_temporal_consts),
    SSG_NODE_UNIFORMS(uniforms, struct ssg_temporal_consts, u),
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = flops,
    .run_cpu = ssg_temporal_run_cpu,
    .run_gl = ssg_temporal_run_gl,
    .parity = {.max = 0, .mean = 0}, /* bit-exact on llvmpipe (test_temporal_parity.c) */
};
