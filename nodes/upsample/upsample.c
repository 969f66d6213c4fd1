/* upsample.c - the `upsample` node's descriptor, check and prepare: joint bilateral
 * upsampling guided by full-resolution depth and normals. Method: README.md here. */
#include <math.h>
#include <stdio.h>

#include "common/joint_weights.h"
#include "upsample.h"

int ssg_upsample_factor(int width, int height, int low_width, int low_height)
{
    for (int k = 1; k <= SSG_UPSAMPLE_MAX_FACTOR; k++)
        if ((width + k - 1) / k == low_width && (height + k - 1) / k == low_height)
            return k;
    return 0;
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_upsample_params *p = params;
    const struct ssg_shape *im = &in[SSG_UPSAMPLE_IN_IN], *dep = &in[SSG_UPSAMPLE_IN_DEPTH];
    const struct ssg_shape *nrm = &in[SSG_UPSAMPLE_IN_NORMAL];
    const struct ssg_shape *ldep = &in[SSG_UPSAMPLE_IN_LOW_DEPTH];
    const struct ssg_shape *lnrm = &in[SSG_UPSAMPLE_IN_LOW_NORMAL];
    if (p->size % 2 == 0) {
        snprintf(why, why_len, "size must be odd (taps centred on a low-res pixel), got %d",
                 p->size);
        return SSG_E_VALUE;
    }
    if (ldep->channels != 1 || !ssg_shape_same_size(ldep, im)) {
        snprintf(why, why_len, "low_depth must be a 1-channel image the size of in");
        return SSG_E_SIZE;
    }
    if ((nrm->channels != 0) != (lnrm->channels != 0)) {
        snprintf(why, why_len, "normal and low_normal go together (connect both or neither)");
        return SSG_E_MISSING_INPUT;
    }
    if (nrm->channels != 0 && (!ssg_shape_same_size(nrm, dep) ||
                               !ssg_shape_same_size(lnrm, im))) {
        snprintf(why, why_len, "normal must be the size of depth, low_normal the size of in");
        return SSG_E_SIZE;
    }
    if (!ssg_upsample_factor(dep->width, dep->height, im->width, im->height)) {
        snprintf(why, why_len, "in (%dx%d) is not depth (%dx%d) subsampled by an integer "
                 "factor up to %d (ceil(size / factor))", im->width, im->height, dep->width,
                 dep->height, SSG_UPSAMPLE_MAX_FACTOR);
        return SSG_E_SIZE;
    }
    const struct ssg_shape *im2 = &in[SSG_UPSAMPLE_IN_IN2];
    if (im2->channels != 0 && !ssg_shape_same_size(im2, im)) {
        snprintf(why, why_len, "in2 must be the size of in");
        return SSG_E_SIZE;
    }
    out[0] = (struct ssg_shape){dep->width, dep->height, im->channels, im->type};
    /* out2: in2 upsampled, or (unconnected) zeros shaped like out */
    out[1] = im2->channels != 0
                 ? (struct ssg_shape){dep->width, dep->height, im2->channels, im2->type}
                 : out[0];
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_upsample_params *p = params;
    struct ssg_upsample_consts *c = consts;
    struct ssg_joint_weights w;
    ssg_joint_weights_make(p->size, p->sigma_spatial, p->sigma_depth, p->normal_power, &w);
    const struct ssg_shape *dep = &ctx->in_shape[SSG_UPSAMPLE_IN_DEPTH];
    const struct ssg_shape *low = &ctx->in_shape[SSG_UPSAMPLE_IN_IN];
    c->factor = ssg_upsample_factor(dep->width, dep->height, low->width, low->height);
    c->radius = w.radius;
    /* distances are measured in full-res px (sample_offset): sigma_spatial k of them */
    c->spatial_k = w.spatial_k / (float)(c->factor * c->factor);
    c->depth_scale = w.depth_scale;
    c->normal_power = (float)p->normal_power;
    c->normal_min = w.normal_min;
    c->squarings = w.squarings;
    c->max_slope = SSG_UPSAMPLE_MAX_SLOPE;
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_upsample_params, SSG_UPSAMPLE_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_upsample_consts, SSG_UPSAMPLE_UNIFORMS);

SSG_PORT_TABLE(inputs, SSG_UPSAMPLE_IN);
SSG_PORT_TABLE(outputs, SSG_UPSAMPLE_OUT);

/* Flops per pixel (node.h), by reading upsample_cpu.c: the two slopes (about 10), per tap
   the weight (ssg_joint_tap_flops), 8 for the offset from the sample and the plane's depth
   there, and 3 a channel (sums relative to the centre tap); size^2 low-resolution taps a
   full-resolution pixel. */
static double upsample_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_upsample_consts *c = consts;
    int ch = in[SSG_UPSAMPLE_IN_IN].channels + in[SSG_UPSAMPLE_IN_IN2].channels;
    double weight = ssg_joint_tap_flops(in[SSG_UPSAMPLE_IN_LOW_NORMAL].channels > 0,
                                        (int)c->normal_power);
    double size = 2.0 * c->radius + 1.0;
    return 20.0 + 2.0 * ch + size * size * (weight + 8.0 + 3.0 * ch);
}

/* The weighted mean of +0 differences from a +0 reference is +0, and so is the fallback's
   pick and the background; out2 is 0 without in2 (README.md). */
static const signed char zero_with[SSG_UPSAMPLE_OUTPUTS] = {
    [SSG_UPSAMPLE_OUT_OUT] = SSG_UPSAMPLE_IN_IN, [SSG_UPSAMPLE_OUT_OUT2] = SSG_UPSAMPLE_IN_IN2};

const struct ssg_node_desc ssg_node_upsample = {
    .name = "upsample",
    .summary = "joint bilateral upsampling guided by full-resolution depth and normals",
    .method = "Kopf et al., Joint Bilateral Upsampling (SIGGRAPH 2007), with the geometry "
              "weights of Szentandrasi, Modern Methods of Realistic Lighting in Real Time, "
              "sec. 4.1 (fig. 6 / table 1: 3x3 upsampling); Belonogov, Global Illumination "
              "methods in simulated VR environments, sec. 4.7.1",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_upsample_params),
    .consts_size = sizeof(struct ssg_upsample_consts),
    .uniforms = SSG_TABLE(uniforms), /* the whole consts: uniforms_offset 0 */
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .zero_with = zero_with,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = upsample_flops,
    .run_cpu = ssg_upsample_run_cpu,
    .run_gl = ssg_upsample_run_gl,
    .parity = {.max = 1.2e-6, .mean = 1.4e-7}, /* test_gl_filters.c: 3.0e-7, 3.5e-8: 4x */
};
