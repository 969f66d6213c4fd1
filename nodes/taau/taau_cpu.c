/* taau_cpu.c - the CPU kernel of the `taau` node (method in README.md): the reference the
 * GL side (taau.glsl) is tested against.
 *
 * Fixed bands of output rows (ssg_parallel_rows); every pixel is computed from the inputs
 * alone, so the result does not depend on the thread count. What does not depend on the
 * output pixel itself is made once: a sample's Gaussian weight is a column's factor times
 * a row's, which depend only on the output column or row and the frame's jitter (axis
 * tables); the 3 x 3 window's mean and deviation depend only on in's nearest sample (a
 * pass over in's pixels); the Gaussian's vertical step only on the output row (a row of
 * in's width). A pixel then combines three columns and reads 16 history texels, four
 * rows of four adjacent ones (one vector load a row). No fused multiply-adds: every
 * operation rounds as the shader's `precise` ones do, in the same order. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#if defined(__SSE__)
#include <immintrin.h>
#endif

#include "taau.h"

enum { ROWS_PER_BAND = 8, MAX_CH = 3 };

/* One axis of the output: per output coordinate, in's nearest sample index (clamped into
   in) and the Gaussian factor of the samples at index - 1, index, index + 1 (0 for one
   outside in). */
struct axis {
    int *near;
    float (*wt)[3];
};

struct job {
    const struct ssg_taau_consts *c;
    int channels, w, h, bw, bh; /* in's size, the output's */
    const float *in[MAX_CH], *hist[MAX_CH], *motion[2], *weight_in;
    float *out[MAX_CH], *weight_out;
    float *mean[MAX_CH], *sd[MAX_CH]; /* per pixel of in: its window's mean, gamma x sd */
    struct axis ax, ay;
    int reset;
    int *failed; /* set by a band without memory */
};

/* The axis table for `n` output coordinates over `size` samples jittered by `jitter`:
   output coordinate X's centre is (X + 0.5) / factor in in's pixels, sample i's is
   i + 0.5 + jitter, so the nearest is floor(centre - jitter) and a sample's distance is
   counted in output pixels. */
static void make_axis(const struct ssg_taau_consts *c, struct axis *a, int n, int size,
                      float jitter)
{
    for (int x = 0; x < n; x++) {
        float centre = ((float)x + 0.5f) * c->u.inv_factor;
        int i0 = (int)floorf(centre - jitter);
        i0 = i0 < 0 ? 0 : i0 > size - 1 ? size - 1 : i0;
        a->near[x] = i0;
        for (int d = 0; d < 3; d++) {
            int i = i0 + d - 1;
            float dist = ((float)i + 0.5f + jitter - centre) * c->u.fac;
            a->wt[x][d] = i >= 0 && i < size ? expf(c->u.neg_inv_2s2 * (dist * dist)) : 0.0f;
        }
    }
}

/* ---- the window's moments, once per pixel of in ---- */

/* Row y of in: per pixel and channel the mean of its 3 x 3 window (taps outside in left
   out) and gamma times the deviation. Per column the three rows' sums (c1, c2: a row of
   in's width each), then the three columns', as the shader adds them; a tap outside in
   counts 0 times, one inside 1 time (a product by 1 is exact, so the interior leaves the
   products out). */
static void moments_row(const struct job *j, int y, float *c1, float *c2)
{
    const int w = j->w, h = j->h;
    const float gamma = j->c->p.gamma;
    float iy[3];
    int ry[3];
    for (int d = 0; d < 3; d++) {
        int r = y + d - 1;
        iy[d] = r >= 0 && r < h ? 1.0f : 0.0f;
        ry[d] = r < 0 ? 0 : r > h - 1 ? h - 1 : r;
    }
    const float ny = (iy[0] + iy[1]) + iy[2];
    for (int ch = 0; ch < j->channels; ch++) {
        const float *restrict a = j->in[ch] + (size_t)ry[0] * w;
        const float *restrict b = j->in[ch] + (size_t)ry[1] * w;
        const float *restrict e = j->in[ch] + (size_t)ry[2] * w;
        for (int i = 0; i < w; i++) {
            float va = a[i], vb = b[i], ve = e[i];
            c1[i] = iy[0] * va + iy[1] * vb + iy[2] * ve;
            c2[i] = iy[0] * (va * va) + iy[1] * (vb * vb) + iy[2] * (ve * ve);
        }
        float *restrict mean = j->mean[ch] + (size_t)y * w;
        float *restrict sd = j->sd[ch] + (size_t)y * w;
        for (int x = 0; x < w; x++) {
            float m1, m2, count;
            if (x > 0 && x < w - 1) {
                m1 = c1[x - 1] + c1[x] + c1[x + 1];
                m2 = c2[x - 1] + c2[x] + c2[x + 1];
                count = 3.0f * ny;
            } else { /* an edge: the column past it counts 0 times */
                float il = x > 0 ? 1.0f : 0.0f, ir = x < w - 1 ? 1.0f : 0.0f;
                int l = x > 0 ? x - 1 : 0, r = x < w - 1 ? x + 1 : w - 1;
                m1 = il * c1[l] + c1[x] + ir * c1[r];
                m2 = il * c2[l] + c2[x] + ir * c2[r];
                count = ((il + 1.0f) + ir) * ny;
            }
            float mu = m1 / count;
            float var = m2 / count - mu * mu;
            mean[x] = mu;
            sd[x] = gamma * sqrtf(var > 0.0f ? var : 0.0f);
        }
    }
}

static void moments_band(void *user, int y0, int y1)
{
    const struct job *j = user;
    float *c = malloc(sizeof(float) * 2 * (size_t)j->w);
    if (!c) { /* the caller reports it */
        __atomic_store_n(j->failed, 1, __ATOMIC_RELAXED);
        return;
    }
    for (int y = y0; y < y1; y++)
        moments_row(j, y, c, c + j->w);
    free(c);
}

/* ---- the output ---- */

/* The Gaussian's vertical step for output row y: in's three rows around the nearest,
   weighted by the row's factors, in the order ((a + b) + e). */
SSG_VECTOR_CLONES static void
row_sums(const float *restrict a, const float *restrict b, const float *restrict e,
         const float *restrict wy, float *restrict v, int w)
{
    const float w0 = wy[0], w1 = wy[1], w2 = wy[2];
    for (int i = 0; i < w; i++)
        v[i] = w0 * a[i] + w1 * b[i] + w2 * e[i];
}

/* Catmull-Rom weights of the four texels around fraction f (Karis 2014). */
static inline void catmull_rom(float f, float w[4])
{
    w[0] = f * (-0.5f + f * (1.0f - 0.5f * f));
    w[1] = 1.0f + f * f * (-2.5f + 1.5f * f);
    w[2] = f * (0.5f + f * (2.0f - 1.5f * f));
    w[3] = f * f * (-0.5f + 0.5f * f);
}

/* Where the history is read for one pixel: four row pointers, the first of four columns,
   and the weights. */
struct taps {
    int tx0;          /* leftmost column; the four may reach past an edge (clamped) */
    size_t row[4];    /* offsets of the four rows, clamped */
    float cx[4], cy[4];
};

static void taps_at(const struct job *j, float px, float py, struct taps *t)
{
    float sx = px - 0.5f, sy = py - 0.5f;
    float fx0 = floorf(sx), fy0 = floorf(sy);
    catmull_rom(sx - fx0, t->cx);
    catmull_rom(sy - fy0, t->cy);
    t->tx0 = (int)fx0 - 1;
    for (int b = 0; b < 4; b++) {
        int y = (int)fy0 - 1 + b;
        y = y < 0 ? 0 : y > j->bh - 1 ? j->bh - 1 : y;
        t->row[b] = (size_t)y * (size_t)j->bw;
    }
}

/* One channel of the history at the taps: per column the four rows' weighted sum, then
   the four columns', ((a + b) + c) + d both times. The columns past an edge are clamped
   to it; inside, each row's four texels are one vector load. */
static float history(const struct job *j, const float *h, const struct taps *t)
{
#if defined(__SSE__)
    if (t->tx0 >= 0 && t->tx0 + 3 < j->bw) {
        const float *p = h + t->tx0;
        __m128 col = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(t->cy[0]), _mm_loadu_ps(p + t->row[0])),
                                _mm_mul_ps(_mm_set1_ps(t->cy[1]), _mm_loadu_ps(p + t->row[1])));
        col = _mm_add_ps(col, _mm_mul_ps(_mm_set1_ps(t->cy[2]), _mm_loadu_ps(p + t->row[2])));
        col = _mm_add_ps(col, _mm_mul_ps(_mm_set1_ps(t->cy[3]), _mm_loadu_ps(p + t->row[3])));
        __m128 m = _mm_mul_ps(col, _mm_loadu_ps(t->cx));
        __m128 s = _mm_add_ss(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 1, 1, 1)));
        s = _mm_add_ss(s, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 2, 2, 2)));
        s = _mm_add_ss(s, _mm_shuffle_ps(m, m, _MM_SHUFFLE(3, 3, 3, 3)));
        return _mm_cvtss_f32(s);
    }
#endif
    float col[4];
    for (int a = 0; a < 4; a++) {
        int x = t->tx0 + a;
        x = x < 0 ? 0 : x > j->bw - 1 ? j->bw - 1 : x;
        col[a] = t->cy[0] * h[t->row[0] + x] + t->cy[1] * h[t->row[1] + x];
        col[a] = col[a] + t->cy[2] * h[t->row[2] + x];
        col[a] = col[a] + t->cy[3] * h[t->row[3] + x];
    }
    float s = t->cx[0] * col[0] + t->cx[1] * col[1];
    s = s + t->cx[2] * col[2];
    return s + t->cx[3] * col[3];
}

/* Output row y (README.md, steps 1-4); v holds a row of in's width per channel. */
SSG_VECTOR_CLONES static void row(const struct job *j, float *const *v, int y)
{
    const struct ssg_taau_consts *c = j->c;
    const int j0 = j->ay.near[y], last = j->w - 1, lasty = j->h - 1;
    const float *wy = j->ay.wt[y];
    const float sy = (wy[0] + wy[1]) + wy[2];
    const size_t ra = (size_t)(j0 > 0 ? j0 - 1 : 0) * (size_t)j->w;
    const size_t rb = (size_t)j0 * (size_t)j->w;
    const size_t rc = (size_t)(j0 < lasty ? j0 + 1 : lasty) * (size_t)j->w;
    for (int ch = 0; ch < j->channels; ch++)
        row_sums(j->in[ch] + ra, j->in[ch] + rb, j->in[ch] + rc, wy, v[ch], j->w);
    const float fac = c->u.fac, cap = c->p.max_weight;
    const float bw = (float)j->bw, bh = (float)j->bh, py = ((float)y + 0.5f);
    const int clamp = c->p.gamma > 0.0f;
    const size_t o = (size_t)y * (size_t)j->bw;
    for (int x = 0; x < j->bw; x++) {
        const int n = j->ax.near[x], l = n > 0 ? n - 1 : 0, r = n < last ? n + 1 : last;
        const float *wx = j->ax.wt[x];
        const float wsum = ((wx[0] + wx[1]) + wx[2]) * sy;
        const size_t q = rb + (size_t)n;
        /* the previous frame's position of this pixel's point, output pixels */
        float hx = ((float)x + 0.5f) + j->motion[0][q] * fac;
        float hy = py + j->motion[1][q] * fac;
        int valid = !j->reset && hx >= 0.0f && hx < bw && hy >= 0.0f && hy < bh;
        float hw = 0.0f;
        struct taps t = {0};
        if (valid) {
            hw = j->weight_in[(size_t)(int)hy * (size_t)j->bw + (size_t)(int)hx];
            hw = hw < cap ? hw : cap;
            taps_at(j, hx, hy, &t);
        }
        const float total = hw + wsum;
        /* one division each a pixel, not a channel (the shader does the same) */
        const float inv_wsum = 1.0f / wsum, inv_total = 1.0f / total;
        for (int ch = 0; ch < j->channels; ch++) {
            const float *vc = v[ch];
            float sum = wx[0] * vc[l] + wx[1] * vc[n] + wx[2] * vc[r];
            float mean = j->mean[ch][q], sd = j->sd[ch][q];
            /* no weight at all (a tiny sigma): the window's mean stands in */
            float cur = wsum > 0.0f ? sum * inv_wsum : mean;
            float hv = valid ? history(j, j->hist[ch], &t) : 0.0f;
            float lo = mean - sd, hi = mean + sd;
            float hc = hv < lo ? lo : hv;
            hc = hc > hi ? hi : hc;
            hv = clamp ? hc : hv;
            float blended = (hw * hv + wsum * cur) * inv_total;
            j->out[ch][o + (size_t)x] = total > 0.0f ? blended : cur;
        }
        j->weight_out[o + (size_t)x] = total < cap ? total : cap;
    }
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    float *buf = malloc(sizeof(float) * MAX_CH * (size_t)j->w);
    if (!buf) { /* the caller reports it */
        __atomic_store_n(j->failed, 1, __ATOMIC_RELAXED);
        return;
    }
    float *v[MAX_CH];
    for (int ch = 0; ch < MAX_CH; ch++)
        v[ch] = buf + (size_t)ch * (size_t)j->w;
    for (int y = y0; y < y1; y++)
        row(j, v, y);
    free(buf);
}

enum ssg_err ssg_taau_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_taau_consts *c = consts;
    const struct ssg_image *in = io->in[SSG_TAAU_IN_IN];
    struct job j = {.c = c, .channels = in->channels, .w = in->width, .h = in->height,
                    .bw = in->width * c->p.factor, .bh = in->height * c->p.factor,
                    .weight_in = io->in[SSG_TAAU_IN_WEIGHT_IN]->data,
                    .weight_out = io->out[SSG_TAAU_OUT_WEIGHT]->data,
                    .reset = ctx->history_reset != 0};
    for (int ch = 0; ch < j.channels; ch++) {
        j.in[ch] = ssg_image_plane(in, ch);
        j.hist[ch] = ssg_image_plane(io->in[SSG_TAAU_IN_HISTORY], ch);
        j.out[ch] = ssg_image_plane(io->out[SSG_TAAU_OUT_OUT], ch);
    }
    for (int k = 0; k < 2; k++)
        j.motion[k] = ssg_image_plane(io->in[SSG_TAAU_IN_MOTION], k);
    /* one block: both axes' tables, then the window's mean and deviation planes */
    size_t n = (size_t)j.bw + (size_t)j.bh, plane = (size_t)j.w * (size_t)j.h;
    size_t tables = n * (sizeof(int) + sizeof(float[3]));
    char *block = malloc(tables + sizeof(float) * 2 * (size_t)j.channels * plane);
    if (!block)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "no memory for %dx%d tables", j.w, j.h);
    float(*wt)[3] = (float(*)[3])block;
    int *near = (int *)(wt + n);
    float *stats = (float *)(block + tables);
    for (int ch = 0; ch < j.channels; ch++) {
        j.mean[ch] = stats + (size_t)(2 * ch) * plane;
        j.sd[ch] = j.mean[ch] + plane;
    }
    j.ax = (struct axis){near, wt};
    j.ay = (struct axis){near + j.bw, wt + j.bw};
    make_axis(c, &j.ax, j.bw, j.w, ctx->frame->jitter_x);
    make_axis(c, &j.ay, j.bh, j.h, ctx->frame->jitter_y);
    int failed = 0;
    j.failed = &failed;
    ssg_parallel_rows(j.h, ROWS_PER_BAND, moments_band, &j);
    ssg_parallel_rows(j.bh, ROWS_PER_BAND, band, &j);
    free(block);
    if (failed)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "no memory for a band's rows of %d pixels",
                             j.w);
    return SSG_OK;
}
