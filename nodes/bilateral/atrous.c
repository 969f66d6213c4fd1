/* atrous.c - the `atrous` node's descriptor, check and prepare: the edge-avoiding a-trous
 * wavelet filter, run by bilateral's passes. Method: atrous.md in this folder. */
#include <math.h>
#include <stdio.h>

#include "atrous.h"
#include "common/joint_weights.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    (void)params;
    (void)frame;
    return ssg_bilateral_check_shapes(in, out, why, why_len);
}

/* The B3 spline's 5 taps (1, 4, 6, 4, 1) / 16. */
static const float B3[5] = {1.0f / 16.0f, 4.0f / 16.0f, 6.0f / 16.0f, 4.0f / 16.0f,
                            1.0f / 16.0f};

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_atrous_params *p = params;
    struct ssg_bilateral_consts *c = consts;
    struct ssg_joint_weights w;
    (void)ctx;
    ssg_joint_weights_make(5, 0.0f, p->sigma_depth, p->normal_power, &w);
    *c = (struct ssg_bilateral_consts){.u = {.radius = 2, .size = 5,
                                             .depth_scale = w.depth_scale,
                                             .normal_power = p->normal_power,
                                             .normal_min = w.normal_min,
                                             .squarings = w.squarings},
                                       .atrous = p->iterations};
    /* the spatial term as a log-weight, as bilateral's Gaussian is */
    for (int dy = 0; dy < 5; dy++)
        for (int dx = 0; dx < 5; dx++)
            c->spatial[dy * 5 + dx] = logf(B3[dy] * B3[dx]);
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_atrous_params, SSG_ATROUS_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_bilateral_uniforms, SSG_BILATERAL_UNIFORMS);

const struct ssg_node_desc ssg_node_atrous = {
    .name = "atrous",
    .summary = "edge-avoiding a-trous wavelet filter: dilated 5 x 5 passes with depth and "
               "normal weights",
    .method = "Dammertz et al., Edge-Avoiding A-Trous Wavelet Transform for fast Global "
              "Illumination Filtering (HPG 2010): B3-spline taps 2^i px apart per pass; "
              "edge-stopping by the bilateral node's depth and normal weights (ours: no "
              "colour term)",
    SSG_BILATERAL_FAMILY,
    SSG_NODE_PARAMS(params, struct ssg_atrous_params),
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .parity = {.max = 1.4e-6, .mean = 1.8e-7}, /* test_gl_filters.c: 3.6e-7, 4.5e-8: 4x */
};
