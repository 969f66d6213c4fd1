/* compare_cpu.c - CPU kernel of the `compare` node (method in compare.c).
 *
 * Work is split over fixed bands of rows; each band writes its own partial sums (in double)
 * and the run adds them up in band order afterwards, so the metrics are the same bits
 * whatever the thread count.
 *
 * SSIM's local statistics are Gaussian sums of six pointwise moments of the counted pixels,
 * m, m a, m b, m a^2, m b^2, m a b (m = 1 for a counted pixel, else 0), each divided by the
 * Gaussian sum of m: that is the window renormalised over the counted pixels inside the
 * image (compare.c). The 2D Gaussian is separable, so each sum is a horizontal pass over
 * zero-padded rows, then a vertical pass (symmetric taps paired: 6 products a pass instead of
 * 121 for the 2D window). A band keeps the horizontal sums of the 11 rows around its current
 * row in a ring, filling it with its own rows plus 5 rows on either side; a row's sums depend
 * on that row only, so a pixel's value does not depend on its band. The moments are doubles:
 * E[a^2] - E[a]^2 cancels, and float would leave noise of 1e-7 in variances that
 * C2 = 9e-4 does not hide. About 90 cycles a pixel and channel on one core. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "compare.h"

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
    double ssim[SSG_COMPARE_MAX_CHANNELS];  /* sum of per-pixel SSIM, per channel */
    long long count;                        /* counted pixels */
    int failed;                             /* 1 = the band's buffers were not allocated */
};

struct job {
    const struct ssg_compare_consts *c;
    const float *a[SSG_COMPARE_MAX_CHANNELS]; /* channel planes of a */
    const float *b[SSG_COMPARE_MAX_CHANNELS]; /* channel planes of b */
    const float *mask;       /* NULL = every pixel counts */
    float *diff[3];          /* R, G, B planes of the diff image */
    int w, h, channels;      /* shape of a and b, px */
    struct partial *parts;   /* one per band */
};

/* 1 when pixel (x, y) counts: inside the frame (compare.c), within `edge` of its border
   when edge > 0, and under the mask. */
static int counted(const struct job *j, int x, int y)
{
    const struct ssg_compare_consts *c = j->c;
    if (x < c->x0 || x >= c->x1 || y < c->y0 || y >= c->y1)
        return 0;
    if (c->edge > 0 && x >= c->x0 + c->edge && x < c->x1 - c->edge && y >= c->y0 + c->edge &&
        y < c->y1 - c->edge)
        return 0;
    return !j->mask || j->mask[(size_t)y * (size_t)j->w + (size_t)x] > 0.5f;
}

static void errors_row(const struct job *j, struct partial *p, int y)
{
    size_t o = (size_t)y * (size_t)j->w;
    for (int x = 0; x < j->w; x++)
        p->count += counted(j, x, y);
    for (int ch = 0; ch < j->channels; ch++) {
        const float *a = j->a[ch] + o, *b = j->b[ch] + o;
        double sq = 0, ab = 0, df = 0;
        for (int x = 0; x < j->w; x++) {
            if (!counted(j, x, y))
                continue;
            double d = (double)a[x] - (double)b[x];
            sq += d * d;
            ab += fabs(d);
            df += d;
        }
        p->sq += sq;
        p->abs += ab;
        p->diff += df;
    }
}

/* Blue-white-red of d = a - b (compare.c); the channel difference of largest magnitude. */
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
    return SSG_OK;
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
    ssg_parallel_rows(a->height, ROWS_PER_BAND, band, &j);
    enum ssg_err e = report(ctx, &j, bands);
    free(j.parts);
    return e;
}
