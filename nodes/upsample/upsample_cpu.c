/* upsample_cpu.c - CPU kernel of the `upsample` node (method in README.md).
 *
 * As in bilateral_cpu.c the loops run over output pixels innermost: a full-res row is cut
 * into chunks, whose pixels are sorted by phase (x mod k, see struct chunk); for each
 * low-res tap row the part the chunk reaches is copied once into small arrays padded
 * with background (with where in its block each sample was taken, found once a run for
 * every low-res pixel: offset_band), then for each tap column and phase one straight loop
 * over contiguous data adds the weighted values into per-pixel sums; each pixel's depth
 * slopes are found when its chunk is set up. For size 3 (radius 1, what the graphs use)
 * away from the image's top and bottom rows a faster path copies the three tap rows at
 * once and gives each phase's pixels all nine taps in one loop, their sums in registers
 * (upsample_fast_taps: 2.3x less time than a pass a tap, the same operations in the same
 * order). The per-pixel set-up and the results' interleaving into the row run a phase at
 * a time, the factor a constant for 2 and 4, so they vectorise too. The spatial and depth
 * weights multiply by adding their logarithms and taking one polynomial exp()
 * (bilateral_math.h), the normal
 * weight c^p by squarings when p is a power of two (the default 16: 4 squarings instead of
 * a log and a multiply in the exponent; as bilateral does); each pixel's sums are
 * independent lanes in a fixed order, so the result does not depend on the threads or the
 * vector width. The optional second image `in2` is carried as further channels (after
 * those of `in`) through the same loops: each weight is computed once and applied to all
 * channels, and since every channel's sum is its own chain of the same operations, `out`
 * and `out2` are bit for bit what upsampling each image alone gives. */
#define SSG_VECTOR_FMA /* a filter: fused multiply-adds allowed (vector_loops.h) */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "upsample.h"

#include "common/bilateral_math.h"

enum { CHUNK = 256, ROWS_PER_BAND = 4 };

/* Channels carried at most: in (1 or 3) and in2 (0, 1 or 3). */
enum { MAX_CH = 6 };

struct job {
    const struct ssg_upsample_consts *c;
    const float *in[MAX_CH]; /* low-res channel planes: in's, then in2's */
    int channels;            /* in's and in2's together: 1, 2, 3, 4 or 6 */
    const float *depth;      /* full res */
    const float *nrm[3];     /* full res; NULL = no normal term */
    const float *ldepth;     /* low res */
    const float *lnrm[3];    /* low res */
    float *out[MAX_CH];      /* full res: out's planes, then out2's */
    int w, h;                /* full-res size */
    int lw, lh;              /* low-res size */
    int k;                   /* factor */
    float *ox, *oy;          /* low res: where in its block each sample was taken
                                (sample_offset), in the node's scratch */
};

/* Low-res columns one chunk can reach: its own (at most CHUNK) plus radius each side. */
enum { ROW_MAX = CHUNK + 2 * ((SSG_UPSAMPLE_MAX_SIZE - 1) / 2) + 1 };

/* The fast path's radius (size 3, what the graphs use): see upsample_fast_taps. */
enum { FAST_R = 1, FAST_ROWS = 2 * FAST_R + 1 };

/* One low-res row of taps as a chunk reaches it, background (depth 0, value 0, normal 0,
   the block's centre as sample offset) outside the image. */
struct tap_row {
    float d[ROW_MAX], v[MAX_CH][ROW_MAX], n[3][ROW_MAX];
    float ox[ROW_MAX], oy[ROW_MAX]; /* where in its block each was taken (sample_offset) */
};

/* One chunk: full-res pixels x0 .. x0 + len - 1 of a row, x0 a multiple of the factor k,
   stored by phase: pixel x0 + m + k t sits in slot m * per_phase + t. All pixels of a
   phase have the same offset from their low-res column (x0 / k + t), so a tap reads the
   low-res row contiguously (column index t + radius + dx in the row arrays) and its
   spatial weight is one number per phase: no gathers, no bounds tests. */
struct chunk {
    int per_phase;                         /* slots per phase: chunk width / k */
    int count[SSG_UPSAMPLE_MAX_FACTOR];    /* pixels of each phase in this chunk */
    float dp[CHUNK], kd[CHUNK];            /* depth, depth_scale / depth */
    float gx[CHUNK], gy[CHUNK];            /* depth slope per full-res px (plane_slope) */
    float sx[CHUNK], sy[CHUNK];            /* the same in pixel order (row_slopes) */
    float nx[CHUNK], ny[CHUNK], nz[CHUNK]; /* unit normal */
    float ref[MAX_CH][CHUNK];              /* centre tap's value: sums are relative to it */
    float acc[MAX_CH][CHUNK], wsum[CHUNK];
    /* tap rows (the general path uses the first), low-res columns x0 / k - radius on */
    struct tap_row row[FAST_ROWS];
};

/* The depth slope along one axis at a pixel of depth d whose neighbours there have depths
   lo and hi (0: background or outside): the one-sided difference of smaller magnitude
   (ties: hi - d), so that a pixel beside a depth edge takes its own surface's slope; 0
   when neither neighbour is a surface or the slope is steeper than max_slope d (then it
   crosses an edge: SSG_UPSAMPLE_MAX_SLOPE). The GL twin is upsample.glsl's plane_slope. */
static float plane_slope(float d, float lo, float hi, float max_slope)
{
    float f = hi > 0.0f ? hi - d : INFINITY, b = lo > 0.0f ? d - lo : INFINITY;
    float s = fabsf(f) <= fabsf(b) ? f : b;
    return fabsf(s) <= max_slope * d ? s : 0.0f;
}

/* Where low-res pixel (qx, qy), of depth dq, was taken in its k x k block: the first
   full-res pixel in row-major order whose depth is dq exactly (`downsample` copies one
   pixel a block), else the block's centre (k - 1) / 2 (a low-res image made otherwise,
   or background). The GL twin is upsample.glsl's sample_offset. */
static void sample_offset(const struct job *j, int qx, int qy, float dq, float *ox, float *oy)
{
    *ox = *oy = 0.5f * (float)(j->k - 1);
    if (!(dq > 0.0f))
        return;
    int x0 = qx * j->k, y0 = qy * j->k;
    int x1 = x0 + j->k < j->w ? x0 + j->k : j->w, y1 = y0 + j->k < j->h ? y0 + j->k : j->h;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++)
            if (j->depth[(size_t)y * (size_t)j->w + (size_t)x] == dq) {
                *ox = (float)(x - x0);
                *oy = (float)(y - y0);
                return;
            }
}

/* plane_slope along x at pixel x of a row, 0 for a neighbour outside the image. */
static float slope_x(const struct job *j, const float *row, int x)
{
    return plane_slope(row[x], x > 0 ? row[x - 1] : 0.0f, x + 1 < j->w ? row[x + 1] : 0.0f,
                       j->c->max_slope);
}

/* The slopes of full-res pixels x0 .. x0 + len - 1 of row y, in pixel order into sx, sy:
   straight loops over the row (along x over its interior, both neighbours inside the
   image; the image's first and last pixel apart), where one call a pixel would not
   vectorise. */
static void row_slopes(const struct job *j, int y, int x0, int len, float *sx, float *sy)
{
    const float *row = j->depth + (size_t)y * (size_t)j->w, ms = j->c->max_slope;
    const int has_up = y > 0, has_down = y + 1 < j->h;
    const float *up = has_up ? row - j->w : row, *down = has_down ? row + j->w : row;
    for (int t = 0; t < len; t++) {
        int x = x0 + t;
        sy[t] = plane_slope(row[x], has_up ? up[x] : 0.0f, has_down ? down[x] : 0.0f, ms);
    }
    int a = x0 == 0 ? 1 : 0, b = x0 + len == j->w ? len - 1 : len;
    for (int t = a; t < b; t++)
        sx[t] = plane_slope(row[x0 + t], row[x0 + t - 1], row[x0 + t + 1], ms);
    if (a == 1)
        sx[0] = slope_x(j, row, x0);
    if (b == len - 1 && len - 1 >= a)
        sx[len - 1] = slope_x(j, row, x0 + len - 1);
}

/* The chunk's per-pixel constants, phase by phase: straight loops over each phase's pixels
   (every k-th of the row), which vectorise where one call a pixel did not. */
static inline __attribute__((always_inline)) void
setup_phases(const struct job *j, struct chunk *restrict k, int y, int x0, int len, int cw,
             int f)
{
    const size_t row = (size_t)y * (size_t)j->w;
    const size_t lrow = (size_t)(y / j->k) * (size_t)j->lw + (size_t)(x0 / j->k);
    const float scale = j->c->depth_scale;
    k->per_phase = cw / f;
    row_slopes(j, y, x0, len, k->sx, k->sy);
    for (int m = 0; m < f; m++) {
        const int n = m < len ? (len - m + f - 1) / f : 0, i0 = m * k->per_phase;
        const float *restrict dep = j->depth + row + (size_t)(x0 + m);
        k->count[m] = n;
        for (int t = 0; t < n; t++) {
            float d = dep[(size_t)f * (size_t)t];
            k->dp[i0 + t] = d;
            k->kd[i0 + t] = d > 0.0f ? scale / d : 0.0f;
            k->wsum[i0 + t] = 0.0f;
            k->gx[i0 + t] = k->sx[m + f * t];
            k->gy[i0 + t] = k->sy[m + f * t];
        }
        for (int ch = 0; ch < j->channels; ch++)
            for (int t = 0; t < n; t++) {
                k->acc[ch][i0 + t] = 0.0f;
                k->ref[ch][i0 + t] = j->in[ch][lrow + (size_t)t];
            }
        if (!j->nrm[0]) {
            for (int t = 0; t < n; t++)
                k->nx[i0 + t] = k->ny[i0 + t] = k->nz[i0 + t] = 0.0f;
            continue;
        }
        const float *restrict n0 = j->nrm[0] + row + (size_t)(x0 + m);
        const float *restrict n1 = j->nrm[1] + row + (size_t)(x0 + m);
        const float *restrict n2 = j->nrm[2] + row + (size_t)(x0 + m);
        for (int t = 0; t < n; t++) {
            size_t o = (size_t)f * (size_t)t;
            float nx = n0[o], ny = n1[o], nz = n2[o];
            float nn = nx * nx + ny * ny + nz * nz, inv = nn > 0.0f ? 1.0f / sqrtf(nn) : 0.0f;
            k->nx[i0 + t] = nx * inv, k->ny[i0 + t] = ny * inv, k->nz[i0 + t] = nz * inv;
        }
    }
}

/* setup_phases with the factor a constant for the common ones, so the strided loads
   vectorise as shuffles. */
static void setup_chunk(const struct job *j, struct chunk *k, int y, int x0, int len, int cw)
{
    switch (j->k) {
    case 2: setup_phases(j, k, y, x0, len, cw, 2); break;
    case 4: setup_phases(j, k, y, x0, len, cw, 4); break;
    default: setup_phases(j, k, y, x0, len, cw, j->k); break;
    }
}

/* dst[t] = plane[base + t] for the t in [lo, hi) (inside the image), `outside` for the
   other t < n. */
static void copy_padded(float *restrict dst, const float *restrict plane, int base, int lo,
                        int hi, int n, float outside)
{
    for (int t = 0; t < lo; t++)
        dst[t] = outside;
    memcpy(dst + lo, plane + base + lo, sizeof(float) * (size_t)(hi - lo));
    for (int t = hi; t < n; t++)
        dst[t] = outside;
}

/* Copies low-res row qy, columns x0 / k - radius .. + n - 1, into a tap row; columns
   outside the image get depth 0 (background: no weight) and value 0. */
static void fill_row(const struct job *j, struct tap_row *restrict r, int qy, int x0, int n)
{
    const size_t row = (size_t)qy * (size_t)j->lw;
    const int base = x0 / j->k - j->c->radius;
    const int lo = base < 0 ? -base : 0, hi = j->lw - base < n ? j->lw - base : n;
    const float centre = 0.5f * (float)(j->k - 1);
    copy_padded(r->d, j->ldepth + row, base, lo, hi, n, 0.0f);
    for (int ch = 0; ch < j->channels; ch++)
        copy_padded(r->v[ch], j->in[ch] + row, base, lo, hi, n, 0.0f);
    for (int ch = 0; j->lnrm[0] && ch < 3; ch++)
        copy_padded(r->n[ch], j->lnrm[ch] + row, base, lo, hi, n, 0.0f);
    copy_padded(r->ox, j->ox + row, base, lo, hi, n, centre);
    copy_padded(r->oy, j->oy + row, base, lo, hi, n, centre);
}

/* The weight of one tap for a pixel: bx = x - k qx and by = y - k qy, the pixel's offset
   from the tap's block corner, less where the sample sits in its block (ox, oy), give the
   full-res offset (rx, ry) from the sample to the pixel: the spatial weight's distance,
   and the depth the pixel's own plane (depth dp, slopes gx, gy) has at the sample,
   dp - (gx rx + gy ry), which the depth term compares with the tap's depth rd. c0 is the
   cosine between the pixel's normal and the tap's (mode a constant at each call site). */
static inline __attribute__((always_inline)) float
tap_weight(const struct ssg_upsample_consts *c, float bx, float by, float ox, float oy,
           float rd, float dp, float gx, float gy, float kd, float c0, int mode)
{
    float rx = bx - ox, ry = by - oy;
    float plane = dp - (gx * rx + gy * ry);
    float delta = (rd - plane) * kd;
    float e = c->spatial_k * (rx * rx + ry * ry) - 0.5f * delta * delta;
    float wn = 1.0f;
    if (mode != SSG_NORMAL_OFF)
        wn = ssg_normal_factor(c0 >= c->normal_min ? c0 : 1.0f, c->normal_power, mode, &e);
    float w = exp_neg(e) * wn;
    w = w >= 1e-30f ? w : 0.0f;
    w = rd > 0.0f ? w : 0.0f; /* background lends nothing */
    if (mode != SSG_NORMAL_OFF)
        w = c0 >= c->normal_min ? w : 0.0f;
    return w;
}

/* Adds one tap to the n pixels of one phase (slots i0 ..): row column q0 + t for slot
   i0 + t, at offset (bx, by) (tap_weight; the same for the whole phase). `channels` and
   `mode` are constants at each call site, so each variant is its own straight loop. */
static inline __attribute__((always_inline)) void
add_tap(const struct job *j, struct chunk *restrict k, int i0, int n, int q0, float bx,
        float by, int channels, int mode)
{
    const struct tap_row *r = &k->row[0];
    for (int t = 0; t < n; t++) {
        int i = i0 + t;
        float c0 = 1.0f;
        if (mode != SSG_NORMAL_OFF)
            c0 = k->nx[i] * r->n[0][q0 + t] + k->ny[i] * r->n[1][q0 + t] +
                 k->nz[i] * r->n[2][q0 + t];
        float w = tap_weight(j->c, bx, by, r->ox[q0 + t], r->oy[q0 + t], r->d[q0 + t],
                             k->dp[i], k->gx[i], k->gy[i], k->kd[i], c0, mode);
        k->wsum[i] += w;
        for (int ch = 0; ch < channels; ch++)
            k->acc[ch][i] += w * (r->v[ch][q0 + t] - k->ref[ch][i]);
    }
}

/* CALL(channels, mode) with both constants: one straight loop a channel count (in's plus
   in2's) and normal mode. */
#define CHANNELS_MODES(channels, mode, CALL)                                               \
    do {                                                                                   \
        switch (channels) {                                                                \
        case 1: SSG_NORMAL_MODE_SWITCH(mode, CALL##_1) break;                              \
        case 2: SSG_NORMAL_MODE_SWITCH(mode, CALL##_2) break;                              \
        case 3: SSG_NORMAL_MODE_SWITCH(mode, CALL##_3) break;                              \
        case 4: SSG_NORMAL_MODE_SWITCH(mode, CALL##_4) break;                              \
        default: SSG_NORMAL_MODE_SWITCH(mode, CALL##_6) break;                             \
        }                                                                                  \
    } while (0)

/* The general path, any radius and the image's top and bottom rows: tap row by tap row,
   each copied into the chunk (fill_row), one pass over a phase's pixels a tap. */
SSG_VECTOR_CLONES
static void upsample_add_taps(const struct job *j, struct chunk *k, int y, int x0)
{
    const int r = j->c->radius, ly = y / j->k;
    const int mode = ssg_normal_mode(j->lnrm[0] != NULL && j->c->normal_power > 0.0f,
                                     j->c->squarings);
    for (int dy = -r; dy <= r; dy++) {
        int qy = ly + dy;
        if (qy < 0 || qy >= j->lh)
            continue;
        fill_row(j, &k->row[0], qy, x0, k->count[0] + 2 * r);
        float by = (float)(y - j->k * qy);
        for (int dx = -r; dx <= r; dx++)
            for (int m = 0; m < j->k; m++) {
                /* phase m's pixels lie m - k dx full-res px right of their tap's block */
                float bx = (float)(m - j->k * dx);
                int i0 = m * k->per_phase, n = k->count[m], q0 = r + dx;
#define TAP(ch, md) add_tap(j, k, i0, n, q0, bx, by, ch, md)
#define TAP_1(md) TAP(1, md)
#define TAP_2(md) TAP(2, md)
#define TAP_3(md) TAP(3, md)
#define TAP_4(md) TAP(4, md)
#define TAP_6(md) TAP(6, md)
                CHANNELS_MODES(j->channels, mode, TAP);
            }
    }
#undef TAP_1
#undef TAP_2
#undef TAP_3
#undef TAP_4
#undef TAP_6
#undef TAP
}

/* The fast path: radius FAST_R, every tap row inside the image. Each phase's pixels take
   all their taps in one pass, their sums in registers, so no per-pixel value is reloaded
   and no sum stored a tap; the taps come in the general path's order (dy, then dx), so the
   sums are the same operations in the same order. All FAST_ROWS^2 taps of the n pixels of
   phase slots i0 ..: row column t + dx for slot i0 + t and tap column dx, at offset
   bx[dx], by[dy] (tap_weight). */
static inline __attribute__((always_inline)) void
fast_phase(const struct job *j, struct chunk *restrict k, int i0, int n, const float *bxs,
           const float *bys, int channels, int mode)
{
    float bx[FAST_ROWS], by[FAST_ROWS];
    for (int r = 0; r < FAST_ROWS; r++)
        bx[r] = bxs[r], by[r] = bys[r];
    for (int t = 0; t < n; t++) {
        const int i = i0 + t;
        const float dp = k->dp[i], gx = k->gx[i], gy = k->gy[i], kd = k->kd[i];
        const float nx = k->nx[i], ny = k->ny[i], nz = k->nz[i];
        float ref[MAX_CH], acc[MAX_CH], wsum = 0.0f;
        for (int ch = 0; ch < channels; ch++)
            ref[ch] = k->ref[ch][i], acc[ch] = 0.0f;
#pragma GCC unroll 3
        for (int dy = 0; dy < FAST_ROWS; dy++)
#pragma GCC unroll 3
            for (int dx = 0; dx < FAST_ROWS; dx++) {
                const struct tap_row *r = &k->row[dy];
                const int q = t + dx;
                float c0 = 1.0f;
                if (mode != SSG_NORMAL_OFF)
                    c0 = nx * r->n[0][q] + ny * r->n[1][q] + nz * r->n[2][q];
                float w = tap_weight(j->c, bx[dx], by[dy], r->ox[q], r->oy[q], r->d[q], dp,
                                     gx, gy, kd, c0, mode);
                wsum += w;
                for (int ch = 0; ch < channels; ch++)
                    acc[ch] += w * (r->v[ch][q] - ref[ch]);
            }
        k->wsum[i] = wsum;
        for (int ch = 0; ch < channels; ch++)
            k->acc[ch][i] = acc[ch];
    }
}

SSG_VECTOR_CLONES
static void upsample_fast_taps(const struct job *j, struct chunk *restrict k, int y)
{
    const int mode = ssg_normal_mode(j->lnrm[0] != NULL && j->c->normal_power > 0.0f,
                                     j->c->squarings);
    float bys[FAST_ROWS];
    for (int dy = 0; dy < FAST_ROWS; dy++)
        bys[dy] = (float)(y - j->k * (y / j->k - FAST_R + dy));
    for (int m = 0; m < j->k; m++) {
        /* phase m's pixels lie m - k dx full-res px right of their tap's block */
        float bxs[FAST_ROWS];
        for (int dx = 0; dx < FAST_ROWS; dx++)
            bxs[dx] = (float)(m - j->k * (dx - FAST_R));
        int i0 = m * k->per_phase, n = k->count[m];
#define FAST(ch, md) fast_phase(j, k, i0, n, bxs, bys, ch, md)
#define FAST_1(md) FAST(1, md)
#define FAST_2(md) FAST(2, md)
#define FAST_3(md) FAST(3, md)
#define FAST_4(md) FAST(4, md)
#define FAST_6(md) FAST(6, md)
        CHANNELS_MODES(j->channels, mode, FAST);
    }
#undef FAST_1
#undef FAST_2
#undef FAST_3
#undef FAST_4
#undef FAST_6
#undef FAST
}

/* No tap had weight: the low-res pixel of closest depth among the taps (first in tap
   order on ties), or the centre tap when all are background. */
static void fallback(const struct job *j, int x, int y, float dp, float *val)
{
    const int r = j->c->radius, lx = x / j->k, ly = y / j->k;
    size_t best = (size_t)ly * (size_t)j->lw + (size_t)lx;
    float best_err = INFINITY;
    for (int qy = ly - r; qy <= ly + r; qy++)
        for (int qx = lx - r; qx <= lx + r; qx++) {
            if (qy < 0 || qy >= j->lh || qx < 0 || qx >= j->lw)
                continue;
            size_t q = (size_t)qy * (size_t)j->lw + (size_t)qx;
            float err = fabsf(j->ldepth[q] - dp);
            if (j->ldepth[q] > 0.0f && err < best_err) {
                best_err = err;
                best = q;
            }
        }
    for (int ch = 0; ch < j->channels; ch++)
        val[ch] = j->in[ch][best];
}

/* The chunk's results in pixel order: ref + acc / wsum where a pixel is a surface with
   weight, else 0, one vector loop a channel and phase (into acc, in place), then
   interleaved into the output row (f a constant for the common factors: the stores
   vectorise as shuffles); then the fallback for the surface pixels no tap weighed. */
static inline __attribute__((always_inline)) void
finish_phases(const struct job *j, struct chunk *restrict k, int y, int x0, int len, int f)
{
    const size_t row = (size_t)y * (size_t)j->w;
    for (int ch = 0; ch < j->channels; ch++) {
        for (int m = 0; m < f; m++) {
            const int i0 = m * k->per_phase, n = k->count[m];
            for (int t = 0; t < n; t++) {
                int i = i0 + t;
                float v = k->ref[ch][i] + k->acc[ch][i] / k->wsum[i];
                int weighed = (k->dp[i] > 0.0f) & (k->wsum[i] > 0.0f);
                k->acc[ch][i] = weighed ? v : 0.0f;
            }
        }
        float *restrict out = j->out[ch] + row + (size_t)x0;
        const float *restrict res = k->acc[ch];
        const int whole = len / f, pp = k->per_phase;
        for (int t = 0; t < whole; t++)
            for (int m = 0; m < f; m++)
                out[f * t + m] = res[m * pp + t];
        for (int c = whole * f; c < len; c++)
            out[c] = res[(c % f) * pp + c / f];
    }
    for (int m = 0; m < f; m++)
        for (int t = 0; t < k->count[m]; t++) {
            int i = m * k->per_phase + t, x = x0 + m + f * t;
            if (!(k->dp[i] > 0.0f) || k->wsum[i] > 0.0f)
                continue;
            float val[MAX_CH];
            fallback(j, x, y, k->dp[i], val);
            for (int ch = 0; ch < j->channels; ch++)
                j->out[ch][row + (size_t)x] = val[ch];
        }
}

static void finish_chunk(const struct job *j, struct chunk *k, int y, int x0, int len)
{
    switch (j->k) {
    case 2: finish_phases(j, k, y, x0, len, 2); break;
    case 4: finish_phases(j, k, y, x0, len, 4); break;
    default: finish_phases(j, k, y, x0, len, j->k); break;
    }
}

/* sample_offset of every low-res pixel of rows y0 .. y1 - 1, found once for all the
   full-res pixels whose taps they are. */
static void offset_band(void *user, int y0, int y1)
{
    const struct job *j = user;
    for (int qy = y0; qy < y1; qy++)
        for (int qx = 0; qx < j->lw; qx++) {
            size_t q = (size_t)qy * (size_t)j->lw + (size_t)qx;
            sample_offset(j, qx, qy, j->ldepth[q], &j->ox[q], &j->oy[q]);
        }
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    const int cw = CHUNK / j->k * j->k; /* chunk width, a multiple of k */
    struct chunk k;
    for (int y = y0; y < y1; y++) {
        const int ly = y / j->k;
        const int fast = j->c->radius == FAST_R && ly >= FAST_R && ly + FAST_R < j->lh;
        for (int x0 = 0; x0 < j->w; x0 += cw) {
            int len = j->w - x0 < cw ? j->w - x0 : cw;
            setup_chunk(j, &k, y, x0, len, cw);
            if (fast) {
                for (int dy = 0; dy < FAST_ROWS; dy++)
                    fill_row(j, &k.row[dy], ly - FAST_R + dy, x0, k.count[0] + 2 * FAST_R);
                upsample_fast_taps(j, &k, y);
            } else {
                upsample_add_taps(j, &k, y, x0);
            }
            finish_chunk(j, &k, y, x0, len);
        }
    }
}

enum ssg_err ssg_upsample_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io)
{
    const struct ssg_image *in = io->in[SSG_UPSAMPLE_IN_IN],
                           *dep = io->in[SSG_UPSAMPLE_IN_DEPTH];
    const struct ssg_image *nrm = io->in[SSG_UPSAMPLE_IN_NORMAL];
    const struct ssg_image *ldep = io->in[SSG_UPSAMPLE_IN_LOW_DEPTH];
    const struct ssg_image *lnrm = io->in[SSG_UPSAMPLE_IN_LOW_NORMAL];
    const struct ssg_image *in2 = io->in[SSG_UPSAMPLE_IN_IN2];
    const int k = ((const struct ssg_upsample_consts *)consts)->factor;
    /* out2 nobody reads (on_demand: no image) is neither upsampled nor cleared */
    int n2 = in2 && io->out[1] ? in2->channels : 0;
    struct job j = {.c = consts, .channels = in->channels + n2, .depth = dep->data,
                    .ldepth = ldep->data, .w = dep->width, .h = dep->height,
                    .lw = in->width, .lh = in->height, .k = k};
    for (int ch = 0; ch < in->channels; ch++) {
        j.in[ch] = ssg_image_plane(in, ch);
        j.out[ch] = ssg_image_plane(io->out[0], ch);
    }
    for (int ch = 0; ch < n2; ch++) {
        j.in[in->channels + ch] = ssg_image_plane(in2, ch);
        j.out[in->channels + ch] = ssg_image_plane(io->out[1], ch);
    }
    if (!in2 && io->out[1]) /* out2 is documented as all 0 when in2 is unconnected */
        memset(io->out[1]->data, 0, sizeof(float) * (size_t)io->out[1]->width *
                                        (size_t)io->out[1]->height *
                                        (size_t)io->out[1]->channels);
    for (int ch = 0; nrm && ch < 3; ch++) {
        j.nrm[ch] = ssg_image_plane(nrm, ch);
        j.lnrm[ch] = ssg_image_plane(lnrm, ch);
    }
    size_t low = (size_t)j.lw * (size_t)j.lh;
    j.ox = ssg_node_scratch(ctx, 2 * low * sizeof(float));
    if (!j.ox)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the sample offsets");
    j.oy = j.ox + low;
    ssg_parallel_rows(j.lh, ROWS_PER_BAND, offset_band, &j);
    ssg_parallel_rows(j.h, ROWS_PER_BAND, band, &j);
    return SSG_OK;
}
