/* upsample.c - the `upsample` node: joint bilateral upsampling of a low-resolution
 * screen-space result (AO, SSDO light) to the full frame, guided by the full-resolution
 * depth and normals so that nothing bleeds across an edge.
 *
 * Method: Kopf, Cohen, Lischinski and Uyttendaele, "Joint Bilateral Upsampling" (SIGGRAPH
 * 2007), as Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", section 4.1
 * uses it: "joint bilateral upsampling can be used with the same modifications as for
 * smoothing to honor geometry properties" (figure 3 and 6, table 1: 2x subsampling, 3x3
 * upsampling filter); Belonogov, "Global Illumination methods in simulated VR
 * environments", section 4.7.1 ("the calculated values require the correct upsampling").
 * Kopf's form is out(p) = sum_q in_low(q) f(|p/k - q|) g(guide) / sum of the weights, the
 * spatial term on the low-res grid and the range term on the full-resolution guide; the
 * "same modifications" make the range term the relative depth and normal weights of
 * `bilateral`: for the full-res pixel p at low-res coordinate u = (p + 0.5) / k - 0.5 and
 * the low-res taps q in the size x size block around the one that contains p,
 *   w = exp(-|u - q|^2 / (2 sigma_s^2)) * exp(-(D_q - d_p)^2 / (2 (sigma_d d_p)^2))
 *       * max(0, n_p . N_q)^normal_power,
 * d_p, n_p the full-res depth and normal, D_q, N_q the low-res ones (the depth and normal
 * the low-res image was computed on, e.g. `downsample`'s). k is the integer factor with
 * ceil(full / k) = low. Low-res background (D_q = 0) lends nothing. When every weight is
 * below 1e-30 (p lies on a surface none of the taps sampled, e.g. a thin object lost by
 * the subsampling) the tap of closest depth is taken as it is (ties: the first in
 * row-major tap order), and the centre tap when all taps are background. Full-res
 * background pixels (d_p = 0) are 0. The sum is formed relative to the centre tap's value,
 * so that a constant image stays exactly constant.
 * A second low-res image `in2` (e.g. SSDO's bounce next to its modulation) may ride along:
 * it is upsampled with the very same weights and fallback taps into `out2`, so one node
 * does the work of two with the weights computed once; `out2` is all 0 (shaped like
 * `out`) when in2 is unconnected. */
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
    if (!ssg_joint_weights_make(p->size, SSG_UPSAMPLE_MAX_SIZE, p->sigma_spatial,
                                p->sigma_depth, p->normal_power, &w))
        return ssg_node_fail(ctx, SSG_E_VALUE, "invalid parameters");
    const struct ssg_shape *dep = &ctx->in_shape[SSG_UPSAMPLE_IN_DEPTH];
    const struct ssg_shape *low = &ctx->in_shape[SSG_UPSAMPLE_IN_IN];
    c->factor = ssg_upsample_factor(dep->width, dep->height, low->width, low->height);
    c->radius = w.radius;
    c->spatial_k = w.spatial_k;
    c->depth_scale = w.depth_scale;
    c->normal_power = (float)p->normal_power;
    c->normal_min = w.normal_min;
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "size", SSG_FIELD_INT(struct ssg_upsample_params, size), .def = 3, .min = 1,
     .max = SSG_UPSAMPLE_MAX_SIZE, .unit = "low-res px",
     .help = "taps per side around the low-res pixel, odd"},
    {.name = "sigma_spatial", SSG_FIELD_FLOAT(struct ssg_upsample_params, sigma_spatial),
     .def = 0, .min = 0, .max = 1000, .unit = "low-res px",
     .help = "spatial Gaussian sigma; 0 = size / 3"},
    {.name = "sigma_depth", SSG_FIELD_FLOAT(struct ssg_upsample_params, sigma_depth),
     .def = 0.05, .min = 1e-6, .max = 1000,
     .help = "depth sigma as a fraction of the full-res pixel's depth"},
    {.name = "normal_power", SSG_FIELD_INT(struct ssg_upsample_params, normal_power), .def = 16,
     .min = 0, .max = 127, .help = "normal weight max(0, n.N)^p; 0 = off"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_UPSAMPLE_IN_IN] = {.name = "in", .types = SSG_T_SCALAR | SSG_T_COLOR,
     .doc = "low-resolution image"},
    [SSG_UPSAMPLE_IN_DEPTH] = {.name = "depth", .types = SSG_T_SCALAR,
     .doc = "full-resolution depth; 0 = background"},
    [SSG_UPSAMPLE_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR, .optional = 1,
     .doc = "full-resolution unit normal; with low_normal, or neither"},
    [SSG_UPSAMPLE_IN_LOW_DEPTH] = {.name = "low_depth", .types = SSG_T_SCALAR,
     .doc = "the depth `in` was computed on (its size)"},
    [SSG_UPSAMPLE_IN_LOW_NORMAL] = {.name = "low_normal", .types = SSG_T_VECTOR, .optional = 1,
     .doc = "the normal `in` was computed on; none = no normal term"},
    [SSG_UPSAMPLE_IN_IN2] = {.name = "in2", .types = SSG_T_SCALAR | SSG_T_COLOR, .optional = 1,
     .doc = "second low-res image (size of in), upsampled with the same weights"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_UPSAMPLE_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_UPSAMPLE_OUT_OUT] = {.name = "out", .types = SSG_T_SCALAR, .same_as = "in",
     .doc = "full-resolution image (size of depth); background 0"},
    [SSG_UPSAMPLE_OUT_OUT2] = {.name = "out2", .types = SSG_T_SCALAR, .same_as = "in2",
     .doc = "in2 upsampled with out's weights (type of in2); all 0, shaped like out, when "
            "in2 is unconnected"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_UPSAMPLE_OUTPUTS, "one entry a port enumerator");

/* Flops per pixel (node.h), by reading upsample_cpu.c: per tap the weight
   (ssg_joint_tap_flops) and 3 a channel (sums relative to the centre tap); size^2
   low-resolution taps a full-resolution pixel. */
static double upsample_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_upsample_consts *c = consts;
    int ch = in[SSG_UPSAMPLE_IN_IN].channels + in[SSG_UPSAMPLE_IN_IN2].channels;
    double weight = ssg_joint_tap_flops(in[SSG_UPSAMPLE_IN_LOW_NORMAL].channels > 0,
                                        (int)c->normal_power);
    double size = 2.0 * c->radius + 1.0;
    return 10.0 + 2.0 * ch + size * size * (weight + 3.0 * ch);
}

const struct ssg_node_desc ssg_node_upsample = {
    .name = "upsample",
    .summary = "joint bilateral upsampling guided by full-resolution depth and normals",
    .method = "Kopf et al., Joint Bilateral Upsampling (SIGGRAPH 2007), with the geometry "
              "weights of Szentandrasi, Modern Methods of Realistic Lighting in Real Time, "
              "sec. 4.1 (fig. 6 / table 1: 3x3 upsampling); Belonogov, Global Illumination "
              "methods in simulated VR environments, sec. 4.7.1",
    .doc = "Each full-resolution pixel is the normalised weighted mean of the size x size "
           "low-res taps around the one containing it: spatial Gaussian on the low-res grid "
           "(sigma_spatial low-res px) times the relative depth Gaussian "
           "exp(-0.5 ((D - d) / (sigma_depth d))^2) of the tap's low-res depth D against the "
           "pixel's own depth d, times max(0, n.N)^normal_power. When no tap has weight, the "
           "tap of closest depth is copied. Background pixels are 0; low-res background "
           "lends nothing. The factor is found from the sizes (ceil(full / factor) = low). An "
           "optional second image in2 (the size of in) is upsampled with exactly the same "
           "weights and fallbacks into out2, computing the weights once for both; out2 is "
           "all 0 (the shape of out) when in2 is unconnected.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_upsample_params),
    .consts_size = sizeof(struct ssg_upsample_consts),
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = upsample_flops,
    .run_cpu = ssg_upsample_run_cpu,
    .run_gl = ssg_upsample_run_gl,
};
