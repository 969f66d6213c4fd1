/* bilateral.c - the `bilateral` node: a geometry-aware bilateral filter (full 2D window)
 * that smooths the noise of screen-space passes without bleeding across edges.
 *
 * Method: Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", section 4.1:
 * a plain Gaussian blur bleeds over edges and between pixels close in 2D but distant in
 * 3D, so the filter is "a modified bilateral filtering on the base of normals and depth
 * value". Belonogov, "Global Illumination methods in simulated VR environments", section
 * 4.3.2, eq. 4.5 (Tomasi and Manduchi's bilateral filter with the range term taken on depth
 * instead of intensity). Both papers then split it into a horizontal and a vertical pass
 * (Szentandrasi after Reinbothe et al., Hybrid Ambient Occlusion; Belonogov eq. 4.6, 4.7);
 * the default is the exact, non-separable 2D form (Belonogov notes the separation is only
 * an approximation): out(p) = sum_q w(p,q) in(q) / sum_q w(p,q) over a size x size window,
 *   w = exp(-|p-q|^2 / (2 sigma_s^2)) * exp(-(d_q - d_p)^2 / (2 (sigma_d d_p)^2))
 *       * max(0, n_p . n_q)^normal_power.
 * The depth term is relative to the centre depth d_p, so a given sigma_depth means the same
 * at every distance (a depth step of 5% at 1 unit and at 50 units alike). The normal term
 * stops the blur at creases where depth is continuous. Background pixels (depth 0) neither
 * contribute nor are filtered: they pass through unchanged.
 * sigma_spatial defaults to size / 3: the window is meant to average away the tiled
 * rotation noise of `ssao`, so the weights stay broad across it (about 0.41 at the window's
 * edge) rather than a narrow Gaussian that would waste most of the window.
 * separable = 1 runs that formula over a 1 x size row, then over a size x 1 column of the
 * row pass's result, each pass weighing against its own centre pixel's depth and normal:
 * O(size) instead of O(size^2) per pixel. The spatial Gaussian factors exactly; where the
 * depth varies along one axis only (and normals are constant) so does everything else and
 * the two forms agree; elsewhere the row normalisation and the cross term of the depth
 * Gaussian make the difference, small on smooth surfaces (tests/test_bilateral.c).
 * A second image `in2` (SSDO's bounce beside its modulation) may ride along: its channels
 * are filtered with exactly the weights of `in`, computed once, into `out2`, bit for bit
 * what a second bilateral node on in2 gives at a fraction of the cost (the weights are most
 * of the work); out2 is all 0, shaped like out, when in2 is unconnected. */
#include <math.h>
#include <stdio.h>

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

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_bilateral_params *p = params;
    struct ssg_bilateral_consts *c = consts;
    struct ssg_joint_weights w;
    if (!ssg_joint_weights_make(p->size, SSG_BILATERAL_MAX_SIZE, p->sigma_spatial,
                                p->sigma_depth, p->normal_power, &w))
        return ssg_node_fail(ctx, SSG_E_VALUE, "invalid parameters");
    c->radius = w.radius;
    c->size = p->size;
    c->depth_scale = w.depth_scale;
    c->normal_power = p->normal_power;
    c->normal_min = w.normal_min;
    c->separable = p->separable;
    const float k = w.spatial_k;
    for (int dy = -c->radius; dy <= c->radius; dy++)
        for (int dx = -c->radius; dx <= c->radius; dx++)
            c->spatial[(dy + c->radius) * c->size + dx + c->radius] =
                k * (float)(dx * dx + dy * dy);
    return SSG_OK;
}

int ssg_bilateral_passes(const struct ssg_bilateral_consts *c,
                         struct ssg_bilateral_pass pass[SSG_BILATERAL_MAX_PASSES])
{
    if (c->atrous > 0) {
        for (int i = 0; i < c->atrous; i++)
            pass[i] = (struct ssg_bilateral_pass){c->radius, c->radius, 1 << i};
        return c->atrous;
    }
    if (c->separable) {
        pass[0] = (struct ssg_bilateral_pass){c->radius, 0, 1};
        pass[1] = (struct ssg_bilateral_pass){0, c->radius, 1};
        return 2;
    }
    pass[0] = (struct ssg_bilateral_pass){c->radius, c->radius, 1};
    return 1;
}

static const struct ssg_param_desc params[] = {
    {.name = "size", SSG_FIELD_INT(struct ssg_bilateral_params, size), .def = 9, .min = 1,
     .max = SSG_BILATERAL_MAX_SIZE, .unit = "px", .help = "window diameter, odd"},
    {.name = "sigma_spatial", SSG_FIELD_FLOAT(struct ssg_bilateral_params, sigma_spatial),
     .def = 0, .min = 0, .max = 1000, .unit = "px",
     .help = "spatial Gaussian sigma; 0 = size / 3"},
    SSG_BILATERAL_EDGE_PARAMS(struct ssg_bilateral_params),
    {.name = "separable", SSG_FIELD_BOOL(struct ssg_bilateral_params, separable), .def = 0,
     .help = "horizontal then vertical pass: O(size) per pixel, an approximation"},
};

const struct ssg_port_desc ssg_bilateral_inputs[SSG_BILATERAL_INPUTS] = {
    [SSG_BILATERAL_IN_IN] = {.name = "in", .types = SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR,
     .doc = "image to smooth"},
    [SSG_BILATERAL_IN_DEPTH] = {.name = "depth", .types = SSG_T_SCALAR,
     .doc = "linear depth; 0 = background"},
    [SSG_BILATERAL_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR, .optional = 1,
     .doc = "unit view-space normal; none = no normal term"},
    [SSG_BILATERAL_IN_IN2] = {.name = "in2", .types = SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR,
     .optional = 1, .doc = "a second image the size of in, filtered with in's weights"},
};


const struct ssg_port_desc ssg_bilateral_outputs[SSG_BILATERAL_OUTPUTS] = {
    [SSG_BILATERAL_OUT_OUT] = {.name = "out", .types = SSG_T_SCALAR, .same_as = "in",
     .doc = "smoothed image"},
    [SSG_BILATERAL_OUT_OUT2] = {.name = "out2", .types = SSG_T_SCALAR, .same_as = "in2",
     .doc = "in2 smoothed with out's weights (type of in2); all 0, shaped like out, when "
            "in2 is unconnected"},
};


double ssg_bilateral_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_bilateral_consts *c = consts;
    int ch = in[SSG_BILATERAL_IN_IN].channels + in[SSG_BILATERAL_IN_IN2].channels;
    double weight = ssg_joint_tap_flops(in[SSG_BILATERAL_IN_NORMAL].channels > 0,
                                        c->normal_power);
    struct ssg_bilateral_pass pass[SSG_BILATERAL_MAX_PASSES];
    int passes = ssg_bilateral_passes(c, pass);
    double taps = 0.0;
    for (int i = 0; i < passes; i++)
        taps += (2.0 * pass[i].rx + 1.0) * (2.0 * pass[i].ry + 1.0);
    return passes * (10.0 + ch) + taps * (weight + 2.0 * ch);
}

const struct ssg_node_desc ssg_node_bilateral = {
    .name = "bilateral",
    .summary = "geometry-aware bilateral filter (depth and normal weights, full 2D window "
               "or separable)",
    .method = "Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 4.1 "
              "(geometry-aware bilateral filtering, separated as in Reinbothe et al.); "
              "Belonogov, Global Illumination methods in simulated VR environments, sec. "
              "4.3.2, eq. 4.5 with a depth range term, separable form eq. 4.6 and 4.7",
    .doc =
        "Weighted mean over a size x size window: spatial Gaussian (sigma_spatial px), "
        "relative depth Gaussian exp(-0.5 (dd / (sigma_depth d))^2) and normal weight "
        "max(0, n.n')^normal_power, normalised. By default the exact 2D filter; separable=true "
        "runs the same weights over a row, then over a column of the row pass's result "
        "(the documents' approximation, O(size) per pixel). Background pixels (depth 0) "
        "pass through and are never used. An optional second image in2 is filtered with "
        "the same weights into out2 in the same pass (one node for SSDO's modulation and "
        "bounce); out2 is all 0 when in2 is unconnected.",
    SSG_BILATERAL_FAMILY,
    SSG_NODE_PARAMS(params, struct ssg_bilateral_params),
    .check = check,
    .prepare = prepare,
};
