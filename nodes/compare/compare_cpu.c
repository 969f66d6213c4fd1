/* compare_cpu.c - CPU kernel of the `compare` node (method in README.md).
 *
 * Work is split over fixed bands of rows; each band writes its own partial sums (in double)
 * and the run adds them up in band order afterwards, so the metrics are the same bits
 * whatever the thread count.
 *
 * SSIM's local statistics are Gaussian sums of six pointwise moments of the counted pixels,
 * m, m a, m b, m a^2, m b^2, m a b (m = 1 for a counted pixel, else 0), each divided by the
 * Gaussian sum of m: that is the window renormalised over the counted pixels inside the
 * image (README.md). The 2D Gaussian is separable, so each sum is a horizontal pass over
 * zero-padded rows, then a vertical pass (symmetric taps paired: 6 products a pass instead of
 * 121 for the 2D window). A band keeps the horizontal sums of the 11 rows around its current
 * row in a ring, filling it with its own rows plus 5 rows on either side; a row's sums depend
 * on that row only, so a pixel's value does not depend on its band. The moments are doubles:
 * E[a^2] - E[a]^2 cancels, and float would leave noise of 1e-7 in variances that
 * C2 = 9e-4 does not hide. About 90 cycles a pixel and channel on one core.
 *
 * FLIP is flip.c's and the structure measure structure.c's; this file hands them the
 * counted pixels and reports what they find. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "compare.h"
#include "structure.h"

enum {
    R = SSG_COMPARE_RADIUS,
    TAPS = SSG_COMPARE_TAPS,
    ROWS_PER_BAND = 64,
    /* The pointwise moments, in this order in every buffer. */
    M_ONE = 0, M_A, M_B, M_AA, M_BB, M_AB, MOMENTS
};

/* What one band adds up; combined in band order by the caller. */
struct partial {
    double sq;                              /* sum of (a - b)^2 over counted values */
    double abs;                             /* sum of |a - b| */
    double diff;                            /* sum of a - b (the signed bias) */
    double sum_a, sum_b;                    /* sums of a and of b (the means) */
    double ssim[SSG_COMPARE_MAX_CHANNELS];  /* sum of per-pixel SSIM, per channel */
    long long count;                        /* counted pixels */
    double *col_sum;        /* banding: channels x w sums of a - b down this band's part of
                               each column, NULL when banding is off */
    long long *col_count;   /* banding: w counted pixels of each column in this band */
    int failed;                             /* 1 = the band's buffers were not allocated */
};

struct job {
    const struct ssg_compare_consts *c;
    const float *a[SSG_COMPARE_MAX_CHANNELS]; /* channel planes of a */
    const float *b[SSG_COMPARE_MAX_CHANNELS]; /* channel planes of b */
    const float *mask;       /* NULL = every pixel counts */
    float *diff[3];          /* R, G, B planes of the diff image */
    double *row_sum;         /* banding: channels x h sums of a - b along each row (each row
                                written by its one band), NULL when banding is off */
    long long *row_count;    /* banding: h counted pixels of each row */
    int w, h, channels;      /* shape of a and b, px */
    struct partial *parts;   /* one per band */
    unsigned char *on;       /* FLIP and structure: w * h, 1 = counted(); NULL outside
                                report_maps */
};

/* 1 when pixel (x, y) counts: inside the frame's region (compare.c; the frame itself
   without a region), within `edge` of its border
   when edge > 0, and under the mask. */
static int counted(const struct job *j, int x, int y)
{
    const struct ssg_compare_consts *c = j->c;
    if (x < c->rx0 || x >= c->rx1 || y < c->ry0 || y >= c->ry1)
        return 0;
    if (c->edge > 0 && x >= c->x0 + c->edge && x < c->x1 - c->edge && y >= c->y0 + c->edge &&
        y < c->y1 - c->edge)
        return 0;
    return !j->mask || j->mask[(size_t)y * (size_t)j->w + (size_t)x] > 0.5f;
}

/* Banding's line sums of row y: the row's own, and its share of every column's. */
static void banding_row(const struct job *j, struct partial *p, int y)
{
    size_t o = (size_t)y * (size_t)j->w;
    long long n = 0;
    for (int x = 0; x < j->w; x++) {
        int on = counted(j, x, y);
        n += on;
        p->col_count[x] += on;
    }
    j->row_count[y] = n;
    for (int ch = 0; ch < j->channels; ch++) {
        const float *a = j->a[ch] + o, *b = j->b[ch] + o;
        double *col = p->col_sum + (size_t)ch * (size_t)j->w, row = 0;
        for (int x = 0; x < j->w; x++) {
            if (!counted(j, x, y))
                continue;
            double d = (double)a[x] - (double)b[x];
            row += d;
            col[x] += d;
        }
        j->row_sum[(size_t)ch * (size_t)j->h + (size_t)y] = row;
    }
}

static void errors_row(const struct job *j, struct partial *p, int y)
{
    size_t o = (size_t)y * (size_t)j->w;
    for (int x = 0; x < j->w; x++)
        p->count += counted(j, x, y);
    if (p->col_sum)
        banding_row(j, p, y);
    for (int ch = 0; ch < j->channels; ch++) {
        const float *a = j->a[ch] + o, *b = j->b[ch] + o;
        double sq = 0, ab = 0, df = 0, sa = 0, sb = 0;
        for (int x = 0; x < j->w; x++) {
            if (!counted(j, x, y))
                continue;
            double d = (double)a[x] - (double)b[x];
            sq += d * d;
            ab += fabs(d);
            df += d;
            sa += a[x];
            sb += b[x];
        }
        p->sq += sq;
        p->abs += ab;
        p->diff += df;
        p->sum_a += sa;
        p->sum_b += sb;
    }
}

/* Blue-white-red of d = a - b (README.md); the channel difference of largest magnitude. */
static void diff_row(const struct job *j, int y)
{
    size_t o = (size_t)y * (size_t)j->w;
    for (int x = 0; x < j->w; x++) {
        size_t i = o + (size_t)x;
        float d = 0.0f;
        for (int ch = 0; ch < j->channels; ch++) {
            float dc = j->a[ch][i] - j->b[ch][i];
            d = fabsf(dc) > fabsf(d) ? dc : d;
        }
        float t = d * j->c->inv_scale;
        t = t < -1.0f ? -1.0f : t > 1.0f ? 1.0f : t;
        float rgb[3] = {t < 0 ? 1.0f + t : 1.0f, 1.0f - fabsf(t), t > 0 ? 1.0f - t : 1.0f};
        int on = counted(j, x, y);
        for (int ch = 0; ch < 3; ch++)
            j->diff[ch][i] = on ? rgb[ch] : 0.0f;
    }
}

/* A band's SSIM buffers. The horizontal sums of the 11 rows around the current output
   row live in a ring: image row ry in slot ry % TAPS. */
struct window {
    size_t padded;   /* w + 2R: a moment row with R zeros on either side */
    double *row;     /* MOMENTS padded rows: the moments of one image row */
    double *ring;    /* MOMENTS x TAPS rows of w: horizontal sums */
    double *zero;    /* w zeros: the rows above and below the image */
    double *acc;     /* MOMENTS rows of w: the full 2D sums of one output row */
    double *ssim;    /* w: SSIM of each pixel of the output row (0 where not counted) */
};

static int window_alloc(struct window *win, const struct job *j)
{
    size_t w = (size_t)j->w;
    win->padded = w + 2 * R;
    /* calloc: the padding of `row` and the zero row stay zero for good. */
    win->row = calloc(MOMENTS * win->padded, sizeof(double));
    win->ring = malloc(MOMENTS * TAPS * w * sizeof(double));
    win->zero = calloc(w, sizeof(double));
    win->acc = malloc(MOMENTS * w * sizeof(double));
    win->ssim = malloc(w * sizeof(double));
    return win->row && win->ring && win->zero && win->acc && win->ssim;
}

static void window_free(struct window *win)
{
    free(win->row);
    free(win->ring);
    free(win->zero);
    free(win->acc);
    free(win->ssim);
}

static double *ring_row(const struct job *j, const struct window *win, int k, int ry)
{
    return win->ring + ((size_t)k * TAPS + (size_t)(ry % TAPS)) * (size_t)j->w;
}

/* Moments of image row y of channel ch into the padded rows. A value not counted is 0
   whatever the pixel holds (a NaN outside the mask must not leak in). */
static void moments_row(const struct job *j, struct window *win, int ch, int y)
{
    size_t o = (size_t)y * (size_t)j->w;
    double *m[MOMENTS];
    for (int k = 0; k < MOMENTS; k++)
        m[k] = win->row + (size_t)k * win->padded + R;
    for (int x = 0; x < j->w; x++) {
        int on = counted(j, x, y);
        double a = on ? (double)j->a[ch][o + (size_t)x] : 0.0;
        double b = on ? (double)j->b[ch][o + (size_t)x] : 0.0;
        m[M_ONE][x] = on ? 1.0 : 0.0;
        m[M_A][x] = a;
        m[M_B][x] = b;
        m[M_AA][x] = a * a;
        m[M_BB][x] = b * b;
        m[M_AB][x] = a * b;
    }
}

/* out[x] = sum_t g[t] in[x + t]; the Gaussian is symmetric, so taps pair up around the
   centre R: g[R] in[x + R] + sum_k g[R - k] (in[x + R - k] + in[x + R + k]). */
static void gauss_row(const double *g, const double *restrict in, double *restrict out,
                      int w)
{
    for (int x = 0; x < w; x++) {
        const double *p = in + x + R;
        double s = g[R] * p[0];
        for (int k = 1; k <= R; k++)
            s += g[R - k] * (p[-k] + p[k]);
        out[x] = s;
    }
}

/* The same down a column of rows: rows[t] is row t of the window (or the zero row). */
static void gauss_column(const double *g, const double *const *rows, double *restrict out,
                         int w)
{
    for (int x = 0; x < w; x++) {
        double s = g[R] * rows[R][x];
        for (int k = 1; k <= R; k++)
            s += g[R - k] * (rows[R - k][x] + rows[R + k][x]);
        out[x] = s;
    }
}

/* Image row ry's moments, summed horizontally, into its ring slot. */
static void fill_row(const struct job *j, struct window *win, int ch, int ry)
{
    moments_row(j, win, ch, ry);
    for (int k = 0; k < MOMENTS; k++)
        gauss_row(j->c->gauss, win->row + (size_t)k * win->padded, ring_row(j, win, k, ry),
                  j->w);
}

/* SSIM of every pixel of row y from the 2D sums in acc, eq. 13 with eqs. 14-16 as
   E[.] - E[.]E[.], 0 where not counted. For a == b the numerator and denominator are the
   same bits (doubling is exact), so identical images score exactly 1. */
static void ssim_pixels(const struct job *j, const struct window *win, int y)
{
    size_t w = (size_t)j->w;
    const double *s[MOMENTS];
    for (int k = 0; k < MOMENTS; k++)
        s[k] = win->acc + (size_t)k * w;
    const double c1 = j->c->c1, c2 = j->c->c2;
    double *restrict out = win->ssim;
    for (size_t x = 0; x < w; x++) {
        double inv = 1.0 / s[M_ONE][x];
        double mu_a = s[M_A][x] * inv, mu_b = s[M_B][x] * inv;
        double var_a = s[M_AA][x] * inv - mu_a * mu_a;
        double var_b = s[M_BB][x] * inv - mu_b * mu_b;
        double cov = s[M_AB][x] * inv - mu_a * mu_b;
        out[x] = ((2.0 * mu_a * mu_b + c1) * (2.0 * cov + c2)) /
                 ((mu_a * mu_a + mu_b * mu_b + c1) * (var_a + var_b + c2));
    }
    /* A pixel not counted may have no counted neighbour (0 / 0): computed, then dropped. */
    for (size_t x = 0; x < w; x++)
        out[x] = counted(j, (int)x, y) ? out[x] : 0.0;
}

/* Sum of SSIM over the counted pixels of rows [y0, y1) of channel ch. */
static double ssim_band(const struct job *j, struct window *win, int ch, int y0, int y1)
{
    int first = y0 - R > 0 ? y0 - R : 0;
    for (int ry = first; ry < y0 + R && ry < j->h; ry++)
        fill_row(j, win, ch, ry);
    double sum = 0;
    for (int y = y0; y < y1; y++) {
        if (y + R < j->h)
            fill_row(j, win, ch, y + R);
        for (int k = 0; k < MOMENTS; k++) {
            const double *rows[TAPS];
            for (int t = 0; t < TAPS; t++) {
                int ry = y + t - R;
                rows[t] = ry >= 0 && ry < j->h ? ring_row(j, win, k, ry) : win->zero;
            }
            gauss_column(j->c->gauss, rows, win->acc + (size_t)k * (size_t)j->w, j->w);
        }
        ssim_pixels(j, win, y);
        for (int x = 0; x < j->w; x++)
            sum += win->ssim[x];
    }
    return sum;
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct partial *p = &j->parts[y0 / ROWS_PER_BAND];
    for (int y = y0; y < y1; y++) {
        errors_row(j, p, y);
        diff_row(j, y);
    }
    struct window win;
    if (!window_alloc(&win, j)) {
        p->failed = 1;
    } else {
        for (int ch = 0; ch < j->channels; ch++)
            p->ssim[ch] = ssim_band(j, &win, ch, y0, y1);
    }
    window_free(&win);
}

/* Mean over the kept lines of h_i^2 (README.md: the line means minus their moving average
   over i +- r, a least-squares line where the window is cut); NaN when no line has a
   counted pixel. m: scratch of `lines` doubles. */
static double highpass_ms(const double *sum, const long long *count, int lines, int r,
                          double *m)
{
    long long most = 0;
    for (int i = 0; i < lines; i++)
        most = count[i] > most ? count[i] : most;
    if (most == 0)
        return NAN;
    for (int i = 0; i < lines; i++)
        m[i] = 2 * count[i] >= most ? sum[i] / (double)count[i] : NAN;
    double ms = 0;
    int kept = 0;
    for (int i = 0; i < lines; i++) {
        if (isnan(m[i]))
            continue;
        double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0;
        for (int k = -r; k <= r; k++) {
            if (i + k < 0 || i + k >= lines || isnan(m[i + k]))
                continue;
            s0 += 1, s1 += k, s2 += (double)k * k;
            t0 += m[i + k], t1 += k * m[i + k];
        }
        /* The line through the window's (k, m) at k = 0; s1 = 0 (whole window): the mean. */
        double det = s0 * s2 - s1 * s1;
        double fit = s1 == 0 ? t0 / s0 : (s2 * t0 - s1 * t1) / det;
        double h = m[i] - fit;
        ms += h * h;
        kept++;
    }
    return ms / kept;
}

/* banding_rows, banding_cols and banding (README.md) from the line sums: the bands' column
   sums are added in band order first, so the result does not depend on the threads. */
static enum ssg_err report_banding(const struct ssg_node_ctx *ctx, const struct job *j,
                                   int bands)
{
    size_t w = (size_t)j->w, h = (size_t)j->h, n = w > h ? w : h;
    double *col = calloc((size_t)j->channels * w, sizeof(double));
    long long *count = calloc(w, sizeof(long long));
    double *m = malloc(n * sizeof(double));
    if (!col || !count || !m) {
        free(col), free(count), free(m);
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the banding lines");
    }
    for (int i = 0; i < bands; i++)
        for (size_t k = 0; k < (size_t)j->channels * w; k++)
            col[k] += j->parts[i].col_sum[k];
    for (int i = 0; i < bands; i++)
        for (size_t x = 0; x < w; x++)
            count[x] += j->parts[i].col_count[x];
    double rows = 0, cols = 0;
    for (int ch = 0; ch < j->channels; ch++) {
        rows += highpass_ms(j->row_sum + ch * h, j->row_count, j->h, j->c->banding, m);
        cols += highpass_ms(col + ch * w, count, j->w, j->c->banding, m);
    }
    rows /= j->channels, cols /= j->channels;
    ssg_metric_report(ctx, "banding", sqrt(rows + cols));
    ssg_metric_report(ctx, "banding_rows", sqrt(rows));
    ssg_metric_report(ctx, "banding_cols", sqrt(cols));
    free(col), free(count), free(m);
    return SSG_OK;
}

/* The band partials, added in band order, into the reported metrics. */
static enum ssg_err report(const struct ssg_node_ctx *ctx, const struct job *j, int bands)
{
    struct partial t = {0};
    for (int i = 0; i < bands; i++) {
        const struct partial *p = &j->parts[i];
        if (p->failed)
            return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the SSIM window buffers");
        t.sq += p->sq;
        t.abs += p->abs;
        t.diff += p->diff;
        t.sum_a += p->sum_a;
        t.sum_b += p->sum_b;
        t.count += p->count;
        for (int ch = 0; ch < j->channels; ch++)
            t.ssim[ch] += p->ssim[ch];
    }
    double values = (double)t.count * j->channels;
    double mse = t.count ? t.sq / values : NAN;
    double ssim = 0;
    for (int ch = 0; ch < j->channels; ch++)
        ssim += t.ssim[ch] / (double)t.count;
    ssg_metric_report(ctx, "rmse", sqrt(mse));
    ssg_metric_report(ctx, "mae", t.count ? t.abs / values : NAN);
    /* mean(a - b): > 0 where a is brighter than the reference b (an AO method that misses
       occlusion), < 0 where darker; rmse alone cannot tell the two apart. */
    ssg_metric_report(ctx, "bias", t.count ? t.diff / values : NAN);
    ssg_metric_report(ctx, "psnr", mse > 0 ? 10.0 * log10(j->c->peak * j->c->peak / mse)
                                           : mse == 0 ? INFINITY : NAN);
    ssg_metric_report(ctx, "ssim", t.count ? ssim / j->channels : NAN);
    ssg_metric_report(ctx, "pixels", (double)t.count);
    /* The two means: their ratio is a term's energy against the reference's (bench.py's
       bounce column), which rmse and bias do not give. */
    ssg_metric_report(ctx, "mean", t.count ? t.sum_a / values : NAN);
    ssg_metric_report(ctx, "reference_mean", t.count ? t.sum_b / values : NAN);
    return j->row_sum ? report_banding(ctx, j, bands) : SSG_OK;
}

/* The compared pixels as bytes for flip.c (counted() is this file's). */
static void counted_rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    for (int y = y0; y < y1; y++)
        for (int x = 0; x < j->w; x++)
            j->on[(size_t)y * (size_t)j->w + (size_t)x] = (unsigned char)counted(j, x, y);
}

/* FLIP (flip.c, README.md) of a against the reference b; its mean over the counted pixels
   is the metric `flip`, reported after every other one so that those keep their order.
   The map goes to the `flip` output when something reads it (0 where not counted), else
   to a buffer of its own. The sum runs over the pixels in row order in one thread: the
   same bits whatever the thread count. */
static enum ssg_err report_flip(const struct ssg_node_ctx *ctx, struct job *j,
                                struct ssg_image *out)
{
    size_t n = (size_t)j->w * (size_t)j->h;
    float *map = out ? ssg_image_plane(out, 0) : NULL;
    if (j->c->flip == SSG_COMPARE_FLIP_OFF) {
        if (map)
            memset(map, 0, n * sizeof(float));
        return SSG_OK;
    }
    float *own = out ? NULL : malloc((n + 1) * sizeof(float));
    struct ssg_flip_input in = {.w = j->w, .h = j->h, .on = j->on, .ppd = j->c->ppd,
                                .hdr = j->c->flip == SSG_COMPARE_FLIP_HDR};
    for (int ch = 0; ch < 3; ch++) {
        in.test[ch] = j->a[ch < j->channels ? ch : 0]; /* a grey image: its plane thrice */
        in.ref[ch] = j->b[ch < j->channels ? ch : 0];
    }
    map = out ? map : own;
    if (!map || ssg_flip_map(&in, map, NULL)) {
        free(own);
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for FLIP's planes");
    }
    double sum = 0;
    long long count = 0;
    for (size_t i = 0; i < n; i++) {
        sum += j->on[i] ? (double)map[i] : 0.0;
        count += j->on[i];
        map[i] = j->on[i] ? map[i] : 0.0f;
    }
    ssg_metric_report(ctx, "flip", count ? sum / (double)count : NAN);
    free(own);
    return SSG_OK;
}

/* The structure measure (structure.c, README.md) of the channels' mean, when asked for;
   its map goes to the `structure` output when something reads it (all 0 when off). */
static enum ssg_err report_structure(const struct ssg_node_ctx *ctx, const struct job *j,
                                     const struct ssg_image *depth, struct ssg_image *out)
{
    float *map = out ? ssg_image_plane(out, 0) : NULL;
    if (!j->c->structure) {
        if (map)
            memset(map, 0, (size_t)j->w * (size_t)j->h * sizeof(float));
        return SSG_OK;
    }
    struct ssg_structure_input in = {.w = j->w, .h = j->h, .channels = j->channels,
                                     .on = j->on, .depth = depth ? depth->data : NULL,
                                     .sigma = j->c->structure_sigma,
                                     .smooth = j->c->structure_smooth};
    for (int ch = 0; ch < j->channels; ch++)
        in.test[ch] = j->a[ch], in.ref[ch] = j->b[ch];
    struct ssg_structure_result r;
    if (ssg_structure_measure(&in, map, &r))
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the structure planes");
    ssg_metric_report(ctx, "structure_pp", r.pp);
    ssg_metric_report(ctx, "structure_rms", r.rms);
    ssg_metric_report(ctx, "structure_pixels", (double)r.pixels);
    return SSG_OK;
}

/* The structure measure, then FLIP: both on the compared pixels as bytes (j->on). */
static enum ssg_err report_maps(const struct ssg_node_ctx *ctx, struct job *j,
                                const struct ssg_io *io)
{
    if (!j->c->structure && j->c->flip == SSG_COMPARE_FLIP_OFF)
        return report_flip(ctx, j, io->out[SSG_COMPARE_OUT_FLIP]);
    j->on = malloc((size_t)j->w * (size_t)j->h + 1);
    if (!j->on)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the compared pixels");
    ssg_parallel_rows(j->h, ROWS_PER_BAND, counted_rows, j);
    enum ssg_err e = report_structure(ctx, j, io->in[SSG_COMPARE_IN_DEPTH],
                                      io->out[SSG_COMPARE_OUT_STRUCTURE]);
    if (!e)
        e = report_flip(ctx, j, io->out[SSG_COMPARE_OUT_FLIP]);
    free(j->on);
    j->on = NULL;
    return e;
}

/* Banding's line buffers (off: all NULL): the rows', shared (one band writes each row),
   and each band's own column sums, zeroed. 0 when out of memory. */
static int banding_alloc(struct job *j, int bands, double **cols, long long **counts)
{
    size_t w = (size_t)j->w, ch = (size_t)j->channels;
    *cols = NULL, *counts = NULL;
    if (j->c->banding <= 0)
        return 1;
    j->row_sum = calloc(ch * (size_t)j->h + 1, sizeof(double));
    j->row_count = calloc((size_t)j->h + 1, sizeof(long long));
    *cols = calloc((size_t)bands * ch * w + 1, sizeof(double));
    *counts = calloc((size_t)bands * w + 1, sizeof(long long));
    if (!j->row_sum || !j->row_count || !*cols || !*counts)
        return 0;
    for (int i = 0; i < bands; i++) {
        j->parts[i].col_sum = *cols + (size_t)i * ch * w;
        j->parts[i].col_count = *counts + (size_t)i * w;
    }
    return 1;
}

enum ssg_err ssg_compare_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io)
{
    const struct ssg_image *a = io->in[SSG_COMPARE_IN_A], *b = io->in[SSG_COMPARE_IN_B];
    const struct ssg_image *mask = io->in[SSG_COMPARE_IN_MASK];
    int bands = (a->height + ROWS_PER_BAND - 1) / ROWS_PER_BAND;
    struct job j = {.c = consts, .mask = mask ? mask->data : NULL, .w = a->width,
                    .h = a->height, .channels = a->channels,
                    .parts = calloc(bands > 0 ? (size_t)bands : 1, sizeof(struct partial))};
    if (!j.parts)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the partial sums");
    for (int ch = 0; ch < a->channels; ch++) {
        j.a[ch] = ssg_image_plane(a, ch);
        j.b[ch] = ssg_image_plane(b, ch);
    }
    for (int ch = 0; ch < 3; ch++)
        j.diff[ch] = ssg_image_plane(io->out[0], ch);
    double *cols;
    long long *counts;
    enum ssg_err e = SSG_E_NOMEM;
    if (banding_alloc(&j, bands, &cols, &counts)) {
        ssg_parallel_rows(a->height, ROWS_PER_BAND, band, &j);
        e = report(ctx, &j, bands);
        if (e == SSG_OK)
            e = report_maps(ctx, &j, io);
    } else {
        ssg_node_fail(ctx, e, "out of memory for the banding lines");
    }
    free(j.row_sum), free(j.row_count), free(cols), free(counts);
    free(j.parts);
    return e;
}
