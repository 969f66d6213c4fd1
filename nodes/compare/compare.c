/* compare.c - the `compare` node's descriptor, check and prepare: image a against the
 * reference b as metrics and a diff image. Method: README.md in this folder. */
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
    const struct ssg_shape *z = &in[SSG_COMPARE_IN_DEPTH];
    if (z->channels != 0 && (z->width != a->width || z->height != a->height)) {
        snprintf(why, why_len, "depth must have the size of a and b (%dx%d), got %dx%d",
                 a->width, a->height, z->width, z->height);
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
    out[1] = out[0];
    out[1].channels = 1;
    out[1].type = SSG_T_SCALAR;
    out[2] = out[1];
    return SSG_OK;
}

/* The region in image pixels: the frame's pixels [x0, x1) x [y0, y1) narrowed to the
   parameter, which is in frame pixels and cut to the frame (a graph made for 1280 x 720
   still runs at --size 96x64: a region wholly outside counts no pixel, metrics NaN). */
static void region_pixels(struct ssg_compare_consts *c, const struct ssg_ints *r)
{
    c->rx0 = c->x0, c->ry0 = c->y0, c->rx1 = c->x1, c->ry1 = c->y1;
    if (r->v[0] == 0 && r->v[1] == 0 && r->v[2] == 0 && r->v[3] == 0)
        return;
    c->rx0 = c->x0 + r->v[0] < c->x1 ? c->x0 + r->v[0] : c->x1;
    c->ry0 = c->y0 + r->v[1] < c->y1 ? c->y0 + r->v[1] : c->y1;
    c->rx1 = c->x0 + r->v[2] < c->x1 ? c->x0 + r->v[2] : c->x1;
    c->ry1 = c->y0 + r->v[3] < c->y1 ? c->y0 + r->v[3] : c->y1;
}

const char *const ssg_compare_flip_choices[] = {"auto", "ldr", "hdr", "off", NULL};

/* auto: LDR-FLIP for one channel (AO in [0, 1], the value as grey), HDR-FLIP for three
   (our colour images are linear HDR radiance). By channels, not type: images read from
   files (`ssgraph compare`, bench's cached references) arrive typed vector. */
static int flip_mode(int mode, int channels)
{
    if (mode != SSG_COMPARE_FLIP_AUTO)
        return mode;
    return channels == 1 ? SSG_COMPARE_FLIP_LDR : SSG_COMPARE_FLIP_HDR;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_compare_params *p = params;
    struct ssg_compare_consts *c = consts;
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
    c->flip = flip_mode(p->flip, ctx->in_shape[SSG_COMPARE_IN_A].channels);
    c->ppd = p->ppd;
    ssg_frame_region(ctx->frame, &ctx->in_shape[SSG_COMPARE_IN_A], &c->x0, &c->y0, &c->x1,
                     &c->y1);
    region_pixels(c, &p->region);
    c->structure = p->structure;
    c->structure_sigma = p->structure_sigma * (c->x1 - c->x0);
    c->structure_smooth = p->structure_smooth;
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_compare_params, SSG_COMPARE_PARAMS);
SSG_PORT_TABLE(inputs, SSG_COMPARE_IN);
SSG_PORT_TABLE(outputs, SSG_COMPARE_OUT);

/* Every name compare_cpu.c reports (tests/test_node_metrics.c holds them equal). */
static const char *const metrics[] = {"rmse", "mae", "bias", "psnr", "ssim", "pixels", "mean",
                                      "reference_mean", "banding", "banding_rows",
                                      "banding_cols", "structure_pp",
                                      "structure_rms", "structure_pixels",
                                      "flip", NULL};

const struct ssg_node_desc ssg_node_compare = {
    .name = "compare",
    .summary = "error of image a against reference b: RMSE, MAE, PSNR, SSIM, FLIP, structure "
               "and a diff image",
    .method = "RMSE, MAE, PSNR = 10 log10(peak^2 / MSE); SSIM: Wang, Bovik, Sheikh, "
              "Simoncelli, IEEE TIP 13(4) 2004, eqs. 13-17 (Gaussian window 11x11, sigma 1.5, "
              "K1 0.01, K2 0.03); FLIP: Andersson, Nilsson, Akenine-Moller, Oskarsson, "
              "Astrom, Fairchild, HPG 2020 (CSF filters in YyCxCz, Hunt-adjusted L*a*b*, "
              "HyAB, edge and point features; qc 0.7, pc 0.4, pt 0.95, qf 0.5); "
              "HDR-FLIP: Andersson, Nilsson, Shirley, Akenine-Moller, EG 2021 (ACES, "
              "exposures from the reference); structure: G(a - b) / G(b), G a Gaussian of "
              "deviation structure_sigma x width, where b is smooth and far from edges",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_compare_params),
    .consts_size = sizeof(struct ssg_compare_consts),
    .metrics = metrics,
    .is_sink = 1,
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_compare_run_cpu,
};
