/* atrous.c - the `atrous` node: the edge-avoiding a-trous wavelet filter, several
 * dilated 5 x 5 passes that together reach far at a fixed cost per pass.
 *
 * Method: Dammertz, Sewtz, Hanika and Lensch, "Edge-Avoiding A-Trous Wavelet Transform for
 * fast Global Illumination Filtering" (HPG 2010): pass i (i = 0 .. iterations - 1) takes
 * the 5 x 5 taps of the B3-spline kernel h = (1, 4, 6, 4, 1) / 16, 2^i px apart, each
 * weighted by h(dx) h(dy) and edge-stopping functions, normalised; pass i + 1 filters pass
 * i's result. Three passes reach 14 px each side with 75 taps a pixel (a 29 x 29 bilateral
 * window would take 841). The edge-stopping functions are the bilateral node's, so the two
 * filters can be compared on one footing: the relative depth Gaussian
 * exp(-0.5 ((d_q - d_p) / (sigma_depth d_p))^2) and max(0, n_p . n_q)^normal_power (the
 * paper weighs position and normal differences with Gaussians and the colour too; a colour
 * term would stop the filter at the very noise it is meant to remove in a screen-space pass
 * of 16 samples, so there is none). Background pixels pass through and lend nothing; taps
 * outside the image are skipped. The passes are bilateral's (nodes/bilateral): the same
 * vectorised CPU loops and the same shader with a tap step, and in2 rides along with the
 * same weights. */
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
    if (p->iterations < 1 || p->iterations > SSG_ATROUS_MAX_ITERATIONS ||
        !ssg_joint_weights_make(5, 5, 0.0f, p->sigma_depth, p->normal_power, &w))
        return ssg_node_fail(ctx, SSG_E_VALUE, "invalid parameters");
    *c = (struct ssg_bilateral_consts){.radius = 2, .size = 5, .depth_scale = w.depth_scale,
                                       .normal_power = p->normal_power,
                                       .normal_min = w.normal_min, .atrous = p->iterations};
    /* the spatial term as a log-weight, as bilateral's Gaussian is */
    for (int dy = 0; dy < 5; dy++)
        for (int dx = 0; dx < 5; dx++)
            c->spatial[dy * 5 + dx] = logf(B3[dy] * B3[dx]);
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "iterations", SSG_FIELD_INT(struct ssg_atrous_params, iterations), .def = 3,
     .min = 1, .max = SSG_ATROUS_MAX_ITERATIONS, .unit = "passes",
     .help = "passes; pass i spaces its 5 x 5 taps 2^i px apart (3: 14 px each side)"},
    SSG_BILATERAL_EDGE_PARAMS(struct ssg_atrous_params),
};

const struct ssg_node_desc ssg_node_atrous = {
    .name = "atrous",
    .summary = "edge-avoiding a-trous wavelet filter: dilated 5 x 5 passes with depth and "
               "normal weights",
    .method = "Dammertz et al., Edge-Avoiding A-Trous Wavelet Transform for fast Global "
              "Illumination Filtering (HPG 2010): B3-spline taps 2^i px apart per pass; "
              "edge-stopping by the bilateral node's depth and normal weights (ours: no "
              "colour term)",
    .doc = "Filters `iterations` times with the 5 x 5 B3-spline kernel (1, 4, 6, 4, 1) / 16, "
           "its taps 1, 2, 4, ... px apart in pass 1, 2, 3, ..., each tap weighted as "
           "bilateral's: the relative depth Gaussian exp(-0.5 (dd / (sigma_depth d))^2) and "
           "max(0, n.n')^normal_power, normalised; each pass filters the last one's result. "
           "25 taps a pixel a pass, however far the passes reach. Background pixels (depth "
           "0) pass through and are never used. An optional second image in2 is filtered "
           "with the same weights into out2 in the same passes; out2 is all 0 when in2 is "
           "unconnected.",
    SSG_BILATERAL_FAMILY,
    SSG_NODE_PARAMS(params, struct ssg_atrous_params),
    .check = check,
    .prepare = prepare,
};
