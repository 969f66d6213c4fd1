/* upsample_cpu.c - CPU kernel of the `upsample` node (method in README.md).
 *
 * As in bilateral_cpu.c the loops run over output pixels innermost: a full-res row is cut
 * into chunks, whose pixels are sorted by phase (x mod k, see struct chunk); for each
 * low-res tap row the part the chunk reaches is copied once into small arrays padded
 * with background (with where in its block each sample was taken, found once a run for
 * every low-res pixel: offset_band), then for each tap column and phase one straight loop
 * over contiguous data adds the weighted values into per-pixel sums; each pixel's depth
 * slopes are found when its chunk is set up. The spatial and depth weights multiply
 * by adding their logarithms and taking one polynomial exp() (bilateral_math.h), the normal
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
    /* the tap row, low-res columns x0 / k - radius on, background outside the image */
    float rd[ROW_MAX], rv[MAX_CH][ROW_MAX], rn[3][ROW_MAX];
    float rox[ROW_MAX], roy[ROW_MAX]; /* where in its block each was taken (sample_offset) */
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

static void setup_pixel(const struct job *j, struct chunk *k, int i, int x, int y, size_t lo)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x;
    float d = j->depth[o];
    k->dp[i] = d;
    k->kd[i] = d > 0.0f ? j->c->depth_scale / d : 0.0f;
    k->wsum[i] = 0.0f;
    for (int ch = 0; ch < j->channels; ch++) {
        k->acc[ch][i] = 0.0f;
        k->ref[ch][i] = j->in[ch][lo];
    }
    k->nx[i] = k->ny[i] = k->nz[i] = 0.0f;
    if (j->nrm[0]) {
        float nx = j->nrm[0][o], ny = j->nrm[1][o], nz = j->nrm[2][o];
        float nn = nx * nx + ny * ny + nz * nz, inv = nn > 0.0f ? 1.0f / sqrtf(nn) : 0.0f;
        k->nx[i] = nx * inv, k->ny[i] = ny * inv, k->nz[i] = nz * inv;
    }
}

static void setup_chunk(const struct job *j, struct chunk *k, int y, int x0, int len, int cw)
{
    size_t lrow = (size_t)(y / j->k) * (size_t)j->lw;
    k->per_phase = cw / j->k;
    row_slopes(j, y, x0, len, k->sx, k->sy);
    for (int m = 0; m < j->k; m++) {
        k->count[m] = m < len ? (len - m + j->k - 1) / j->k : 0;
        for (int t = 0; t < k->count[m]; t++) {
            int i = m * k->per_phase + t, c = m + j->k * t;
            setup_pixel(j, k, i, x0 + c, y, lrow + (size_t)(x0 / j->k + t));
            k->gx[i] = k->sx[c];
            k->gy[i] = k->sy[c];
        }
    }
}

/* Copies low-res row qy, columns x0 / k - radius .. + n - 1, into the chunk's row arrays;
   columns outside the image get depth 0 (background: no weight) and value 0. */
static void fill_row(const struct job *j, struct chunk *k, int qy, int x0, int n)
{
    size_t row = (size_t)qy * (size_t)j->lw;
    int base = x0 / j->k - j->c->radius;
    for (int t = 0; t < n; t++) {
        int qx = base + t;
        int inside = qx >= 0 && qx < j->lw;
        size_t q = row + (size_t)(inside ? qx : 0);
        k->rd[t] = inside ? j->ldepth[q] : 0.0f;
        for (int ch = 0; ch < j->channels; ch++)
            k->rv[ch][t] = inside ? j->in[ch][q] : 0.0f;
        for (int ch = 0; j->lnrm[0] && ch < 3; ch++)
            k->rn[ch][t] = inside ? j->lnrm[ch][q] : 0.0f;
        float centre = 0.5f * (float)(j->k - 1);
        k->rox[t] = inside ? j->ox[q] : centre;
        k->roy[t] = inside ? j->oy[q] : centre;
    }
}

/* Adds one tap to the n pixels of one phase (slots i0 ..): row column q0 + t for slot
   i0 + t. bx = x - k qx and by = y - k qy, the pixels' offset from the tap's block corner
   (the same for the whole phase), less where the sample sits in its block, give the
   full-res offset (rx, ry) from the sample to the pixel: the spatial weight's distance,
   and the depth the pixel's own plane has at the sample, d - (gx rx + gy ry), which the
   depth term compares with the tap's. `channels` and `mode` are constants at each call
   site, so each variant is its own straight loop. */
static inline __attribute__((always_inline)) void
add_tap(const struct job *j, struct chunk *restrict k, int i0, int n, int q0, float bx,
        float by, int channels, int mode)
{
    const float p = j->c->normal_power, cmin = j->c->normal_min, ks = j->c->spatial_k;
    const float *restrict rd = k->rd + q0;
    for (int t = 0; t < n; t++) {
        int i = i0 + t;
        float rx = bx - k->rox[q0 + t], ry = by - k->roy[q0 + t];
        float plane = k->dp[i] - (k->gx[i] * rx + k->gy[i] * ry);
        float delta = (rd[t] - plane) * k->kd[i];
        float e = ks * (rx * rx + ry * ry) - 0.5f * delta * delta;
        float c0 = 1.0f, wn = 1.0f;
        if (mode != SSG_NORMAL_OFF) {
            c0 = k->nx[i] * k->rn[0][q0 + t] + k->ny[i] * k->rn[1][q0 + t] +
                 k->nz[i] * k->rn[2][q0 + t];
            wn = ssg_normal_factor(c0 >= cmin ? c0 : 1.0f, p, mode, &e);
        }
        float w = exp_neg(e) * wn;
        w = w >= 1e-30f ? w : 0.0f;
        w = rd[t] > 0.0f ? w : 0.0f; /* background lends nothing */
        if (mode != SSG_NORMAL_OFF)
            w = c0 >= cmin ? w : 0.0f;
        k->wsum[i] += w;
        for (int ch = 0; ch < channels; ch++)
            k->acc[ch][i] += w * (k->rv[ch][q0 + t] - k->ref[ch][i]);
    }
}

/* add_tap for one channel count (in's plus in2's), one straight loop a normal mode. */
static inline __attribute__((always_inline)) void
taps_of(const struct job *j, struct chunk *k, int i0, int n, int q0, float bx, float by,
        int channels, int mode)
{
#define TAP(m) add_tap(j, k, i0, n, q0, bx, by, channels, m)
    SSG_NORMAL_MODE_SWITCH(mode, TAP)
#undef TAP
}

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
        fill_row(j, k, qy, x0, k->count[0] + 2 * r);
        float by = (float)(y - j->k * qy);
        for (int dx = -r; dx <= r; dx++)
            for (int m = 0; m < j->k; m++) {
                /* phase m's pixels lie m - k dx full-res px right of their tap's block */
                float bx = (float)(m - j->k * dx);
                int i0 = m * k->per_phase, n = k->count[m], q0 = r + dx;
                switch (j->channels) {
                case 1: taps_of(j, k, i0, n, q0, bx, by, 1, mode); break;
                case 2: taps_of(j, k, i0, n, q0, bx, by, 2, mode); break;
                case 3: taps_of(j, k, i0, n, q0, bx, by, 3, mode); break;
                case 4: taps_of(j, k, i0, n, q0, bx, by, 4, mode); break;
                default: taps_of(j, k, i0, n, q0, bx, by, 6, mode); break;
                }
            }
    }
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

static void finish_chunk(const struct job *j, const struct chunk *k, int y, int x0)
{
    size_t row = (size_t)y * (size_t)j->w;
    for (int m = 0; m < j->k; m++)
        for (int t = 0; t < k->count[m]; t++) {
            int i = m * k->per_phase + t, x = x0 + m + j->k * t;
            size_t o = row + (size_t)x;
            float val[MAX_CH] = {0.0f};
            if (k->dp[i] > 0.0f && k->wsum[i] > 0.0f) {
                for (int ch = 0; ch < j->channels; ch++)
                    val[ch] = k->ref[ch][i] + k->acc[ch][i] / k->wsum[i];
            } else if (k->dp[i] > 0.0f) {
                fallback(j, x, y, k->dp[i], val);
            }
            for (int ch = 0; ch < j->channels; ch++)
                j->out[ch][o] = val[ch];
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
    for (int y = y0; y < y1; y++)
        for (int x0 = 0; x0 < j->w; x0 += cw) {
            int len = j->w - x0 < cw ? j->w - x0 : cw;
            setup_chunk(j, &k, y, x0, len, cw);
            upsample_add_taps(j, &k, y, x0);
            finish_chunk(j, &k, y, x0);
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
    int n2 = in2 ? in2->channels : 0;
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
    if (!in2) /* out2 is documented as all 0 when in2 is unconnected */
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
