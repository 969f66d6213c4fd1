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
#include <float.h>
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
    float *wt[3]; /* wt[d][x]: the sample at near + d - 1 */
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
            a->wt[d][x] = i >= 0 && i < size ? expf(c->u.neg_inv_2s2 * (dist * dist)) : 0.0f;
        }
    }
}

/* ---- the window's moments, once per pixel of in ---- */

/* A window's mean and gamma times its deviation from its sums of v and v^2 over count
   taps. */
static inline void window_stats(float m1, float m2, float count, float gamma,
                                float *restrict mean, float *restrict sd)
{
    float mu = m1 / count;
    float var = m2 / count - mu * mu;
    *mean = mu;
    *sd = gamma * sqrtf(var > 0.0f ? var : 0.0f);
}

/* Row y of in: per pixel and channel the mean of its 3 x 3 window (taps outside in left
   out) and gamma times the deviation. Per column the three rows' sums (c1, c2: a row of
   in's width each), then the three columns', as the shader adds them; a tap outside in
   counts 0 times, one inside 1 time (a product by 1 is exact, so the interior leaves the
   products out). */
SSG_VECTOR_CLONES static void moments_row(const struct job *j, int y, float *restrict c1,
                                          float *restrict c2)
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
        const float count = 3.0f * ny;
        for (int x = 1; x < w - 1; x++) { /* the interior: one straight loop */
            window_stats(c1[x - 1] + c1[x] + c1[x + 1], c2[x - 1] + c2[x] + c2[x + 1], count,
                         gamma, &mean[x], &sd[x]);
        }
        for (int x = 0; x < w; x += w > 1 ? w - 1 : 1) { /* the edges: the column past
                                                             one counts 0 times */
            float il = x > 0 ? 1.0f : 0.0f, ir = x < w - 1 ? 1.0f : 0.0f;
            int l = x > 0 ? x - 1 : 0, r = x < w - 1 ? x + 1 : w - 1;
            window_stats(il * c1[l] + c1[x] + ir * c1[r], il * c2[l] + c2[x] + ir * c2[r],
                         ((il + 1.0f) + ir) * ny, gamma, &mean[x], &sd[x]);
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

/* ---- the output, a chunk of a row at a time ---- */

enum { CHUNK = 64 };

/* Per-pixel values of one chunk of a row, structure of arrays: each step below is one
   straight loop over the chunk's pixels (vector lanes; the loads at in's columns and at
   the history's texel are gathers on AVX2). */
struct chunk {
    int l[CHUNK], r[CHUNK];           /* in's columns left and right of the nearest */
    int q[CHUNK];                     /* in's nearest sample */
    int texel[CHUNK];                 /* the history's texel of the point (its weight) */
    int tx0[CHUNK], ty[4][CHUNK];     /* the history's leftmost column, its rows' offsets */
    float cx[4][CHUNK], cy[4][CHUNK]; /* Catmull-Rom weights */
    float wsum[CHUNK], hw[CHUNK], inv_wsum[CHUNK], inv_total[CHUNK];
    int valid[CHUNK];
    float cur[CHUNK], hist[CHUNK];
};

/* Catmull-Rom weights of the four texels around fraction f (Karis 2014). */
static inline void catmull_rom(float f, float *w0, float *w1, float *w2, float *w3)
{
    *w0 = f * (-0.5f + f * (1.0f - 0.5f * f));
    *w1 = 1.0f + f * f * (-2.5f + 1.5f * f);
    *w2 = f * (0.5f + f * (2.0f - 1.5f * f));
    *w3 = f * f * (-0.5f + 0.5f * f);
}

/* Per pixel of the chunk: in's columns, the samples' weight, where the point was in the
   previous output (motion of in's nearest sample, in output pixels), whether that lies
   inside it, the history's weight there (its texel, capped) and the Catmull-Rom taps. */
SSG_VECTOR_CLONES static void
locate(const struct job *j, struct chunk *restrict k, int y, int x0, int len)
{
    const float fac = j->c->u.fac, cap = j->c->p.max_weight;
    const float bw = (float)j->bw, bh = (float)j->bh, py = (float)y + 0.5f;
    const float sy = (j->ay.wt[0][y] + j->ay.wt[1][y]) + j->ay.wt[2][y];
    const int rb = j->ay.near[y] * j->w, last = j->w - 1, ly = j->bh - 1;
    const int bwi = j->bw, live = !j->reset;
    const int *restrict near = j->ax.near + x0;
    const float *restrict w0 = j->ax.wt[0] + x0, *restrict w1 = j->ax.wt[1] + x0;
    const float *restrict w2 = j->ax.wt[2] + x0;
    const float *restrict mx = j->motion[0], *restrict my = j->motion[1];
    const float *restrict wi = j->weight_in;
    for (int i = 0; i < len; i++) {
        int n = near[i];
        k->l[i] = n > 0 ? n - 1 : 0;
        k->r[i] = n < last ? n + 1 : last;
        float wsum = ((w0[i] + w1[i]) + w2[i]) * sy;
        int q = rb + n;
        k->q[i] = q;
        float hx = ((float)(x0 + i) + 0.5f) + mx[q] * fac;
        float hy = py + my[q] * fac;
        int valid = live & (hx >= 0.0f) & (hx < bw) & (hy >= 0.0f) & (hy < bh);
        hx = valid ? hx : 0.5f; /* a safe place for the loads below */
        hy = valid ? hy : 0.5f;
        k->texel[i] = (int)hy * bwi + (int)hx;
        float sx = hx - 0.5f, sy2 = hy - 0.5f;
        float fx0 = floorf(sx), fy0 = floorf(sy2);
        catmull_rom(sx - fx0, &k->cx[0][i], &k->cx[1][i], &k->cx[2][i], &k->cx[3][i]);
        catmull_rom(sy2 - fy0, &k->cy[0][i], &k->cy[1][i], &k->cy[2][i], &k->cy[3][i]);
        k->tx0[i] = (int)fx0 - 1;
        int ty0 = (int)fy0 - 1;
#pragma GCC unroll 4 /* so that the loop over pixels is the one vectorised */
        for (int b = 0; b < 4; b++) {
            int ty = ty0 + b;
            k->ty[b][i] = (ty < 0 ? 0 : ty > ly ? ly : ty) * bwi;
        }
        k->inv_wsum[i] = 1.0f / wsum; /* one division a pixel, not a channel (as the
                                         shader) */
        k->wsum[i] = wsum;
        k->valid[i] = valid;
    }
    /* the history's weight at its texel: a loop of its own, so that both vectorise */
    for (int i = 0; i < len; i++) {
        float hw = wi[k->texel[i]];
        hw = hw < cap ? hw : cap;
        hw = k->valid[i] ? hw : 0.0f;
        k->hw[i] = hw;
        k->inv_total[i] = 1.0f / (hw + k->wsum[i]);
    }
}

/* One channel of this frame's estimate: the Gaussian's horizontal step over the row's
   vertical sums v (the window's mean where no sample weighs anything). */
SSG_VECTOR_CLONES static void
estimate(const struct job *j, struct chunk *restrict k, const float *restrict v,
         const float *restrict mean, int x0, int len)
{
    const float *restrict w0 = j->ax.wt[0] + x0, *restrict w1 = j->ax.wt[1] + x0;
    const float *restrict w2 = j->ax.wt[2] + x0;
    const int *restrict near = j->ax.near + x0;
    for (int i = 0; i < len; i++) {
        float sum = w0[i] * v[k->l[i]] + w1[i] * v[near[i]] + w2[i] * v[k->r[i]];
        float mu = mean[k->q[i]]; /* loaded either way: a select, not a branch */
        /* (a subnormal W would make 1 / W infinite: a GPU flushes it to 0, so both count
           it as no weight) */
        k->cur[i] = k->wsum[i] >= FLT_MIN ? sum * k->inv_wsum[i] : mu;
    }
}

/* One channel of the history at pixel i's taps: per column the four rows' weighted sum,
   then the four columns', ((a + b) + c) + d both times. Columns past an edge are clamped
   to it; inside, each row's four texels are one vector load. */
static float history_at(const struct job *j, const struct chunk *k, const float *h, int i)
{
    const int tx0 = k->tx0[i];
#if defined(__SSE__)
    if (tx0 >= 0 && tx0 + 3 < j->bw) {
        const float *p = h + tx0;
        __m128 c0 = _mm_mul_ps(_mm_set1_ps(k->cy[0][i]), _mm_loadu_ps(p + k->ty[0][i]));
        __m128 c1 = _mm_mul_ps(_mm_set1_ps(k->cy[1][i]), _mm_loadu_ps(p + k->ty[1][i]));
        __m128 col = _mm_add_ps(c0, c1);
        col = _mm_add_ps(col, _mm_mul_ps(_mm_set1_ps(k->cy[2][i]), _mm_loadu_ps(p + k->ty[2][i])));
        col = _mm_add_ps(col, _mm_mul_ps(_mm_set1_ps(k->cy[3][i]), _mm_loadu_ps(p + k->ty[3][i])));
        __m128 m = _mm_mul_ps(col, _mm_setr_ps(k->cx[0][i], k->cx[1][i], k->cx[2][i], k->cx[3][i]));
        __m128 s = _mm_add_ss(m, _mm_shuffle_ps(m, m, _MM_SHUFFLE(1, 1, 1, 1)));
        s = _mm_add_ss(s, _mm_shuffle_ps(m, m, _MM_SHUFFLE(2, 2, 2, 2)));
        s = _mm_add_ss(s, _mm_shuffle_ps(m, m, _MM_SHUFFLE(3, 3, 3, 3)));
        return _mm_cvtss_f32(s);
    }
#endif
    float col[4];
    for (int a = 0; a < 4; a++) {
        int x = tx0 + a;
        x = x < 0 ? 0 : x > j->bw - 1 ? j->bw - 1 : x;
        col[a] = k->cy[0][i] * h[k->ty[0][i] + x] + k->cy[1][i] * h[k->ty[1][i] + x];
        col[a] = col[a] + k->cy[2][i] * h[k->ty[2][i] + x];
        col[a] = col[a] + k->cy[3][i] * h[k->ty[3][i] + x];
    }
    float s = k->cx[0][i] * col[0] + k->cx[1][i] * col[1];
    s = s + k->cx[2][i] * col[2];
    return s + k->cx[3][i] * col[3];
}

static void history(const struct job *j, struct chunk *k, const float *h, int len)
{
    for (int i = 0; i < len; i++)
        k->hist[i] = k->valid[i] ? history_at(j, k, h, i) : 0.0f;
}

/* One channel's blend: the history clamped to mean +/- gamma sd (gamma 0: not clamped),
   weighted by its capped weight against this frame's samples. */
SSG_VECTOR_CLONES static void
blend(const struct chunk *restrict k, const float *restrict mean, const float *restrict sd,
      int clamp, float *restrict out, int len)
{
    for (int i = 0; i < len; i++) {
        float mu = mean[k->q[i]], s = sd[k->q[i]], c = k->cur[i], hv = k->hist[i];
        /* a history that is not finite (a bad frame upstream) is this frame's estimate,
           so that it washes out rather than spreading through the taps and the weight */
        hv = fabsf(hv) <= FLT_MAX ? hv : c;
        float lo = mu - s, hi = mu + s;
        float hc = hv < lo ? lo : hv;
        hc = hc > hi ? hi : hc;
        hv = clamp ? hc : hv;
        float blended = (k->hw[i] * hv + k->wsum[i] * c) * k->inv_total[i];
        out[i] = k->hw[i] + k->wsum[i] >= FLT_MIN ? blended : c;
    }
}

SSG_VECTOR_CLONES static void
weights(const struct chunk *restrict k, float cap, float *restrict out, int len)
{
    for (int i = 0; i < len; i++) {
        float total = k->hw[i] + k->wsum[i];
        out[i] = total < cap ? total : cap;
    }
}

/* The Gaussian's vertical step for output row y: in's three rows around the nearest,
   weighted by the row's factors, in the order ((a + b) + e). */
SSG_VECTOR_CLONES static void
row_sums(const float *restrict a, const float *restrict b, const float *restrict e, float w0,
         float w1, float w2, float *restrict v, int w)
{
    for (int i = 0; i < w; i++)
        v[i] = w0 * a[i] + w1 * b[i] + w2 * e[i];
}

/* Output row y (README.md, steps 1-4); v holds a row of in's width per channel. */
static void row(const struct job *j, float *const *v, struct chunk *k, int y)
{
    const int j0 = j->ay.near[y], lasty = j->h - 1;
    const size_t ra = (size_t)(j0 > 0 ? j0 - 1 : 0) * (size_t)j->w;
    const size_t rb = (size_t)j0 * (size_t)j->w;
    const size_t rc = (size_t)(j0 < lasty ? j0 + 1 : lasty) * (size_t)j->w;
    for (int ch = 0; ch < j->channels; ch++)
        row_sums(j->in[ch] + ra, j->in[ch] + rb, j->in[ch] + rc, j->ay.wt[0][y],
                 j->ay.wt[1][y], j->ay.wt[2][y], v[ch], j->w);
    const int clamp = j->c->p.gamma > 0.0f;
    const size_t o = (size_t)y * (size_t)j->bw;
    for (int x0 = 0; x0 < j->bw; x0 += CHUNK) {
        int len = j->bw - x0 < CHUNK ? j->bw - x0 : CHUNK;
        locate(j, k, y, x0, len);
        for (int ch = 0; ch < j->channels; ch++) {
            estimate(j, k, v[ch], j->mean[ch], x0, len);
            history(j, k, j->hist[ch], len);
            blend(k, j->mean[ch], j->sd[ch], clamp, j->out[ch] + o + (size_t)x0, len);
        }
        weights(k, j->c->p.max_weight, j->weight_out + o + (size_t)x0, len);
    }
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    float *buf = malloc(sizeof(float) * MAX_CH * (size_t)j->w);
    struct chunk *k = malloc(sizeof *k);
    if (buf && k) {
        float *v[MAX_CH];
        for (int ch = 0; ch < MAX_CH; ch++)
            v[ch] = buf + (size_t)ch * (size_t)j->w;
        for (int y = y0; y < y1; y++)
            row(j, v, k, y);
    } else { /* the caller reports it */
        __atomic_store_n(j->failed, 1, __ATOMIC_RELAXED);
    }
    free(buf);
    free(k);
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
    size_t tables = n * (sizeof(int) + 3 * sizeof(float));
    char *block = malloc(tables + sizeof(float) * 2 * (size_t)j.channels * plane);
    if (!block)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "no memory for %dx%d tables", j.w, j.h);
    float *wt = (float *)block; /* three rows of n: each axis' factors d = 0, 1, 2 */
    int *near = (int *)(wt + 3 * n);
    float *stats = (float *)(block + tables);
    for (int ch = 0; ch < j.channels; ch++) {
        j.mean[ch] = stats + (size_t)(2 * ch) * plane;
        j.sd[ch] = j.mean[ch] + plane;
    }
    j.ax = (struct axis){near, {wt, wt + n, wt + 2 * n}};
    j.ay = (struct axis){near + j.bw, {wt + j.bw, wt + n + j.bw, wt + 2 * n + j.bw}};
    make_axis(c, &j.ax, j.bw, j.w, c->u.jitter_x);
    make_axis(c, &j.ay, j.bh, j.h, c->u.jitter_y);
    int failed = 0;
    j.failed = &failed;
    ssg_parallel_rows(j.h, ROWS_PER_BAND, moments_band, &j);
    if (!failed) /* the output reads every moment */
        ssg_parallel_rows(j.bh, ROWS_PER_BAND, band, &j);
    free(block);
    if (failed)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "no memory for a band's rows of %d pixels",
                             j.w);
    return SSG_OK;
}
