/* bilateral.c - the `bilateral` node's descriptor, check and prepare: a geometry-aware
 * bilateral filter (depth and normal weights). Method: README.md in this folder. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bilateral.h"
#include "common/joint_weights.h"

enum ssg_err ssg_bilateral_check_shapes(const struct ssg_shape *in, struct ssg_shape *out,
                                        char *why, size_t why_len)
{
    const struct ssg_shape *im = &in[SSG_BILATERAL_IN_IN], *dep = &in[SSG_BILATERAL_IN_DEPTH];
    const struct ssg_shape *nrm = &in[SSG_BILATERAL_IN_NORMAL];
    if (dep->channels != 1 || dep->width != im->width || dep->height != im->height) {
        snprintf(why, why_len, "depth must be a 1-channel image the size of in");
        return SSG_E_SIZE;
    }
    if (nrm->channels != 0 && (nrm->channels != 3 || nrm->width != im->width ||
                               nrm->height != im->height)) {
        snprintf(why, why_len, "normal must be a 3-channel image the size of in");
        return SSG_E_SIZE;
    }
    const struct ssg_shape *im2 = &in[SSG_BILATERAL_IN_IN2];
    if (im2->channels != 0 && !ssg_shape_same_size(im2, im)) {
        snprintf(why, why_len, "in2 must be the size of in");
        return SSG_E_SIZE;
    }
    out[SSG_BILATERAL_OUT_OUT] = *im;
    /* out2: in2 filtered, or (unconnected) zeros shaped like out */
    out[SSG_BILATERAL_OUT_OUT2] = im2->channels != 0 ? *im2 : *im;
    return SSG_OK;
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_bilateral_params *p = params;
    (void)frame;
    if (p->size % 2 == 0) {
        snprintf(why, why_len, "size must be odd (a window centred on the pixel), got %d",
                 p->size);
        return SSG_E_VALUE;
    }
    return ssg_bilateral_check_shapes(in, out, why, why_len);
}

/* ln of the tent's weight d px off the centre: 1 - |d| / (r + 1), never 0 inside the
   window. The tent of size 2 P - 1 is a box of P convolved with itself, so its response
   is 0 at every multiple of the frequency 1 / P: a pattern repeating every P px (the
   interleaved tile of rsm or ssdo) leaves no trace on a flat surface. */
static float tent_log_weight(int d, int r)
{
    return logf(1.0f - (float)abs(d) / (float)(r + 1));
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_bilateral_params *p = params;
    struct ssg_bilateral_consts *c = consts;
    struct ssg_joint_weights w;
    (void)ctx;
    ssg_joint_weights_make(p->size, p->sigma_spatial, p->sigma_depth, p->normal_power, &w);
    c->u.radius = w.radius;
    c->u.size = p->size;
    c->u.depth_scale = w.depth_scale;
    c->u.normal_power = p->normal_power;
    c->u.normal_min = w.normal_min;
    c->u.squarings = w.squarings;
    c->separable = p->separable;
    const int r = c->u.radius;
    for (int dy = -r; dy <= r; dy++)
        for (int dx = -r; dx <= r; dx++)
            c->spatial[(dy + r) * c->u.size + dx + r] =
                p->window == SSG_BILATERAL_TENT
                    ? tent_log_weight(dx, r) + tent_log_weight(dy, r)
                    : w.spatial_k * (float)(dx * dx + dy * dy);
    return SSG_OK;
}

int ssg_bilateral_passes(const struct ssg_bilateral_consts *c,
                         struct ssg_bilateral_pass pass[SSG_BILATERAL_MAX_PASSES])
{
    if (c->atrous > 0) {
        for (int i = 0; i < c->atrous; i++)
            pass[i] = (struct ssg_bilateral_pass){c->u.radius, c->u.radius, 1 << i};
        return c->atrous;
    }
    if (c->separable) {
        pass[0] = (struct ssg_bilateral_pass){c->u.radius, 0, 1};
        pass[1] = (struct ssg_bilateral_pass){0, c->u.radius, 1};
        return 2;
    }
    pass[0] = (struct ssg_bilateral_pass){c->u.radius, c->u.radius, 1};
    return 1;
}

static const char *const ssg_bilateral_window_choices[] = {"gaussian", "tent", NULL};
SSG_PARAMS_TABLE(params, ssg_bilateral_params, SSG_BILATERAL_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_bilateral_uniforms, SSG_BILATERAL_UNIFORMS);

/* The port tables, shared with the `atrous` node (bilateral.h). */
const struct ssg_port_desc ssg_bilateral_inputs[SSG_BILATERAL_INPUTS] = {
    SSG_BILATERAL_IN(SSG_PORT_AS_ROW)};
const struct ssg_port_desc ssg_bilateral_outputs[SSG_BILATERAL_OUTPUTS] = {
    SSG_BILATERAL_OUT(SSG_PORT_AS_ROW)};

double ssg_bilateral_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_bilateral_consts *c = consts;
    int ch = in[SSG_BILATERAL_IN_IN].channels + in[SSG_BILATERAL_IN_IN2].channels;
    double weight = ssg_joint_tap_flops(in[SSG_BILATERAL_IN_NORMAL].channels > 0,
                                        c->u.normal_power);
    struct ssg_bilateral_pass pass[SSG_BILATERAL_MAX_PASSES];
    int passes = ssg_bilateral_passes(c, pass);
    double taps = 0.0;
    for (int i = 0; i < passes; i++)
        taps += (2.0 * pass[i].rx + 1.0) * (2.0 * pass[i].ry + 1.0);
    return passes * (10.0 + ch) + taps * (weight + 2.0 * ch);
}

/* A weighted mean of +0 is +0 (a pixel without weight passes its +0 through); out2 is 0
   without in2 (README.md). */
static const signed char zero_with[SSG_BILATERAL_OUTPUTS] = {
    [SSG_BILATERAL_OUT_OUT] = SSG_BILATERAL_IN_IN, [SSG_BILATERAL_OUT_OUT2] = SSG_BILATERAL_IN_IN2};

const struct ssg_node_desc ssg_node_bilateral = {
    .name = "bilateral",
    .summary = "geometry-aware bilateral filter (depth and normal weights, full 2D window "
               "or separable)",
    .method = "Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 4.1 "
              "(geometry-aware bilateral filtering, separated as in Reinbothe et al.); "
              "Belonogov, Global Illumination methods in simulated VR environments, sec. "
              "4.3.2, eq. 4.5 with a depth range term, separable form eq. 4.6 and 4.7",
    SSG_BILATERAL_FAMILY,
    SSG_NODE_PARAMS(params, struct ssg_bilateral_params),
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .zero_with = zero_with,
    .check = check,
    .prepare = prepare,
    .parity = {.max = 3e-6, .mean = 3.7e-7}, /* test_gl_filters.c: 7.8e-7, 9.3e-8: 4x */
};
