/* compare.c - the `compare` node: how far image `a` (the method under test) is from image `b`
 * (the reference), as metrics and as a false-colour difference image.
 *
 * Metrics, over the counted pixels (mask > 0.5, or all pixels without a mask), all channels:
 *   rmse   sqrt(MSE), MSE = sum (a - b)^2 / (pixels * channels)
 *   mae    sum |a - b| / (pixels * channels)
 *   psnr   10 log10(peak^2 / MSE) in dB; +inf when the images are identical (JSON: null)
 *   ssim   mean SSIM, Wang, Bovik, Sheikh and Simoncelli, "Image Quality Assessment: From
 *          Error Visibility to Structural Similarity", IEEE TIP 13(4), 2004: eq. 13 with
 *          the Gaussian-weighted local statistics of eqs. 14-16 (11 x 11 window, sigma 1.5,
 *          K1 = 0.01, K2 = 0.03, L = peak), averaged as in eq. 17 over the counted pixels,
 *          then over channels
 *   pixels the number of pixels counted
 *   mean, reference_mean  sum a and sum b / (pixels * channels): a term's energy against
 *          the reference's is their ratio
 * With no pixel counted, every metric but `pixels` is NaN (null in JSON).
 *
 * Banding (banding = r > 0; not measured by default): structured error along image rows or
 * columns, the streaks and bands a tiled sampling pattern leaves after a filter, which
 * rmse mixes with white noise. Per channel, with e = a - b over the counted pixels:
 *   m_y  the mean of e over the counted pixels of row y, for every row with at least half
 *        as many counted pixels as the fullest row (the others are left out: a line that
 *        clips the mask's corner is too short a mean); likewise m_x per column
 *   h_i  m_i minus its moving average over the kept lines j with |j - i| <= r: the value at
 *        i of the least-squares line through those (j, m_j). Where the window is whole
 *        (r kept lines on either side) that is exactly the centred moving average
 *        (1 / (2r + 1)) sum m_j; at the region's ends and next to left-out lines the
 *        line fit keeps a linear gradient at exactly 0, as it is in the interior
 *   banding_rows = sqrt(mean over kept rows of h_y^2)     (horizontal bands)
 *   banding_cols = sqrt(mean over kept columns of h_x^2)  (vertical streaks)
 *   banding      = sqrt(banding_rows^2 + banding_cols^2)
 * each mean square averaged over channels before the root. Known values: stripes
 * e = A (-1)^x give banding = A (1 - 1/(2r + 1)) away from the ends (A 16/17 for r = 8); a
 * smooth gradient gives ~0 (a linear one exactly 0); white noise of deviation s over an
 * H x W region gives about s sqrt(1/H + 1/W), the floor below which streaks are not seen.
 * `region` = [x0, y0, x1, y1] (frame pixels, x1 and y1 excluded) restricts every metric to
 * that rectangle, so that banding can be read on one wall; it is cut to the frame, so a
 * graph keeps running at another --size (a region wholly outside counts no pixel).
 * Only the frame counts: images with a guard band around it (ssg_frame.guard,
 * docs/guard_band.md) are compared without the band, so that a graph with a band and one
 * without score the same pixels. `edge` > 0 further restricts the count to the pixels
 * within `edge` of the frame's border, the region a guard band is meant to fix.
 *
 * Departure from the paper, at borders and mask edges: the paper averages only windows that
 * lie wholly inside the image. Here every counted pixel has an SSIM value, and its window
 * uses only the pixels that are inside the image and counted, with the Gaussian weights
 * renormalised over them. So a mask excludes pixels from the statistics of their
 * neighbours too (background never leaks into the foreground's score), and small images
 * have a score. Away from borders and mask edges this is the paper's SSIM exactly.
 *
 * The `diff` image (colour) shows the signed difference d = a - b on a blue-white-red map:
 * t = clamp(d / scale, -1, 1); white at t = 0, pure red (1, 0, 0) at t = +1 (a above b,
 * for AO: the method too bright, missing occlusion), pure blue (0, 0, 1) at t = -1 (a below
 * b: too dark), linear in between. For 3-channel images d is the channel difference of
 * largest magnitude. Pixels not counted are black. */
#include <math.h>
#include <stdio.h>

#include "compare.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_shape *a = &in[SSG_COMPARE_IN_A], *b = &in[SSG_COMPARE_IN_B];
    const struct ssg_shape *m = &in[SSG_COMPARE_IN_MASK];
    if (a->channels != b->channels || a->type != b->type) {
        char ta[32], tb[32];
        ssg_type_names(a->type, ta, sizeof ta);
        ssg_type_names(b->type, tb, sizeof tb);
        snprintf(why, why_len, "a and b must have the same type: a is %s (%d channel%s), b is "
                 "%s (%d channel%s)", ta, a->channels, a->channels == 1 ? "" : "s", tb,
                 b->channels, b->channels == 1 ? "" : "s");
        return SSG_E_TYPE;
    }
    if (a->channels > SSG_COMPARE_MAX_CHANNELS) {
        snprintf(why, why_len, "a and b have %d channels, at most %d are compared",
                 a->channels, SSG_COMPARE_MAX_CHANNELS);
        return SSG_E_CHANNELS;
    }
    if (a->width != b->width || a->height != b->height) {
        snprintf(why, why_len, "a and b must have the same size: a is %dx%d, b is %dx%d",
                 a->width, a->height, b->width, b->height);
        return SSG_E_SIZE;
    }
    if (m->channels != 0 && (m->width != a->width || m->height != a->height)) {
        snprintf(why, why_len, "mask must have the size of a and b (%dx%d), got %dx%d",
                 a->width, a->height, m->width, m->height);
        return SSG_E_SIZE;
    }
    const struct ssg_compare_params *p = params;
    const struct ssg_ints *r = &p->region;
    int whole = r->v[0] == 0 && r->v[1] == 0 && r->v[2] == 0 && r->v[3] == 0;
    if (!whole && (r->v[2] <= r->v[0] || r->v[3] <= r->v[1])) {
        snprintf(why, why_len, "region [%d, %d, %d, %d] must be [x0, y0, x1, y1] with x0 < x1 "
                 "and y0 < y1 (frame pixels), or [0, 0, 0, 0] for the whole frame", r->v[0],
                 r->v[1], r->v[2], r->v[3]);
        return SSG_E_VALUE;
    }
    /* The diff has the compared images' size, which need not be the frame's. */
    out[0].width = a->width;
    out[0].height = a->height;
    out[0].channels = 3;
    out[0].type = SSG_T_COLOR;
    return SSG_OK;
}

/* The region in image pixels: the frame's pixels [x0, x1) x [y0, y1) narrowed to the
   parameter, which is in frame pixels and cut to the frame (a graph made for 1280 x 720
   still runs at --size 96x64: a region wholly outside counts no pixel, metrics NaN). */
static void region_pixels(struct ssg_compare_consts *c, const struct ssg_ints *r)
{
    c->rx0 = c->x0, c->ry0 = c->y0, c->rx1 = c->x1, c->ry1 = c->y1;
    if (r->count != 4 || (r->v[0] == 0 && r->v[1] == 0 && r->v[2] == 0 && r->v[3] == 0))
        return;
    c->rx0 = c->x0 + r->v[0] < c->x1 ? c->x0 + r->v[0] : c->x1;
    c->ry0 = c->y0 + r->v[1] < c->y1 ? c->y0 + r->v[1] : c->y1;
    c->rx1 = c->x0 + r->v[2] < c->x1 ? c->x0 + r->v[2] : c->x1;
    c->ry1 = c->y0 + r->v[3] < c->y1 ? c->y0 + r->v[3] : c->y1;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_compare_params *p = params;
    struct ssg_compare_consts *c = consts;
    if (!(p->scale > 0) || !(p->peak > 0)) {
        return ssg_node_fail(ctx, SSG_E_VALUE, "scale and peak must be positive");
    }
    /* Section III-C: "an 11 x 11 circular-symmetric Gaussian weighting function ... with
       standard deviation of 1.5 samples, normalized to unit sum". */
    double sum = 0;
    for (int i = 0; i < SSG_COMPARE_TAPS; i++) {
        double d = i - SSG_COMPARE_RADIUS;
        c->gauss[i] = exp(-d * d / (2.0 * 1.5 * 1.5));
        sum += c->gauss[i];
    }
    for (int i = 0; i < SSG_COMPARE_TAPS; i++)
        c->gauss[i] /= sum;
    c->c1 = (0.01 * p->peak) * (0.01 * p->peak);
    c->c2 = (0.03 * p->peak) * (0.03 * p->peak);
    c->peak = p->peak;
    c->inv_scale = 1.0f / p->scale;
    c->edge = p->edge;
    c->banding = p->banding;
    ssg_frame_region(ctx->frame, &ctx->in_shape[SSG_COMPARE_IN_A], &c->x0, &c->y0, &c->x1,
                     &c->y1);
    region_pixels(c, &p->region);
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "scale", SSG_FIELD_FLOAT(struct ssg_compare_params, scale),
     .def = 0.25, .min = 1e-6, .max = 1e6,
     .help = "diff image: |a - b| at which the colour is pure red or blue"},
    {.name = "peak", SSG_FIELD_FLOAT(struct ssg_compare_params, peak),
     .def = 1, .min = 1e-6, .max = 1e6,
     .help = "signal peak: PSNR's maximum and SSIM's dynamic range L (1 for AO, [0,1] data)"},
    {.name = "edge", SSG_FIELD_INT(struct ssg_compare_params, edge), .def = 0, .min = 0,
     .max = 16384, .unit = "px",
     .help = "> 0: compare only the pixels within this distance of the frame's border "
             "(where screen-space methods lack occluders); 0 = the whole frame"},
    {.name = "region", SSG_FIELD_INTS(struct ssg_compare_params, region),
     .def_ints = {0, 0, 0, 0}, .def_ints_count = 4, .min_count = 4, .max_count = 4,
     .min = 0, .max = 65536, .unit = "px",
     .help = "[x0, y0, x1, y1]: compare only frame pixels x0 <= x < x1, y0 <= y < y1 (e.g. "
             "one wall; cut to the frame); [0, 0, 0, 0] = the whole frame"},
    {.name = "banding", SSG_FIELD_INT(struct ssg_compare_params, banding), .def = 0,
     .min = 0, .max = 4096, .unit = "px",
     .help = "> 0: also report banding, banding_rows, banding_cols: RMS of the row and column "
             "means of a - b minus their moving average over lines i +- banding; 0 = off"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_COMPARE_IN_A] = {.name = "a", .types = SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR,
     .doc = "image under test"},
    [SSG_COMPARE_IN_B] = {.name = "b", .types = SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR,
     .doc = "reference image, same type and size as a"},
    [SSG_COMPARE_IN_MASK] = {.name = "mask", .types = SSG_T_SCALAR, .optional = 1,
     .doc = "pixels with mask > 0.5 are compared; none = every pixel"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_COMPARE_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_COMPARE_OUT_DIFF] = {.name = "diff", .types = SSG_T_COLOR,
     .doc = "a - b on blue (a < b), white (equal), red (a > b); black = not compared"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_COMPARE_OUTPUTS, "one entry a port enumerator");

const struct ssg_node_desc ssg_node_compare = {
    .name = "compare",
    .summary = "error of image a against reference b: RMSE, MAE, PSNR, SSIM and a diff image",
    .method = "RMSE, MAE, PSNR = 10 log10(peak^2 / MSE); SSIM: Wang, Bovik, Sheikh, "
              "Simoncelli, IEEE TIP 13(4) 2004, eqs. 13-17 (Gaussian window 11x11, sigma 1.5, "
              "K1 0.01, K2 0.03)",
    .doc = "Reports rmse, mae, bias (the mean of a - b: > 0 where a is brighter than b), psnr "
           "(dB, inf when identical), ssim and pixels over the pixels "
           "with mask > 0.5 (all without a mask) within the frame (a guard band is left "
           "out; edge > 0: only the frame's border of that width; region: only that "
           "rectangle of the frame), averaged over channels; `ssgraph run` prints "
           "them and writes them to <out>/metrics.json. SSIM windows use only counted pixels "
           "inside the image, weights renormalised. `diff` maps t = clamp((a - b) / scale, "
           "-1, 1) to blue (-1), white (0), red (+1); for 3 channels the channel difference "
           "of largest magnitude; pixels not compared are black. With banding = r > 0 also "
           "banding_rows (horizontal bands) and banding_cols (vertical streaks): per channel "
           "the mean of e = a - b over each row (column) with at least half the counted "
           "pixels of the fullest one, minus its moving average over the lines within r "
           "(a least-squares line where the window is cut, so a linear gradient scores 0), "
           "RMS over those lines, mean square over channels; banding = sqrt(rows^2 + "
           "cols^2). Stripes A (-1)^x score A (1 - 1/(2r+1)); white noise of deviation s "
           "over H x W pixels about s sqrt(1/H + 1/W).",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_compare_params),
    .consts_size = sizeof(struct ssg_compare_consts),
    .is_sink = 1,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_compare_run_cpu,
};
