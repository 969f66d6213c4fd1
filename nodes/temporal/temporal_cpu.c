/* temporal_cpu.c - the CPU kernel of the `temporal` node (method in README.md): the
 * reference the GL side (temporal.glsl) is tested against.
 *
 * Fixed bands of rows (ssg_parallel_rows); every pixel is computed from the inputs alone,
 * so the result does not depend on the thread count. A row is cut into chunks and each
 * step is one straight loop over the chunk's pixels with per-pixel lanes (structure of
 * arrays): the 3 x 3 moments of in (neighbours at fixed offsets: contiguous loads,
 * vectorised), the four bilinear history taps with their tests (index and weight per tap;
 * weight 0 for a rejected tap; gathers on AVX2), then the clamp and blend
 * (vectorised; the history's taps are gathers on AVX2 and up). No fused multiply-adds
 * (SSG_VECTOR_FMA is not defined): every multiply and add rounds as the shader's
 * `precise` ones do. in2 rides along as further
 * channels after in's, with in's taps, weights and blend factor and its own moments. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <string.h>

#include "temporal.h"

enum { CHUNK = 128, ROWS_PER_BAND = 8, MAX_CH = 6, TAPS = 4 };

struct job {
    const struct ssg_temporal_consts *c;
    int channels;                       /* in's and in2's together: 1, 3, 4 or 6 */
    const float *in[MAX_CH];            /* planes: in's, then in2's */
    const float *hist[MAX_CH];          /* history's, then history2's */
    float *out[MAX_CH];                 /* out's, then out2's */
    const float *len_in, *depth, *prev_depth;
    const float *motion[3];             /* x, y (px), z (previous view depth) */
    const float *nrm[3], *prev_nrm[3];  /* NULL without normals */
    float *len_out;
    int w, h;
};

/* Per-pixel values of one chunk, structure of arrays. */
struct chunk {
    float m1[MAX_CH][CHUNK], m2[MAX_CH][CHUNK]; /* sums of v and v^2 over the 3 x 3 window */
    float count[CHUNK];                         /* window taps inside the image */
    int idx[TAPS][CHUNK];                       /* history tap's pixel (a safe one if out) */
    float wt[TAPS][CHUNK];                      /* its bilinear weight, 0 when rejected */
    float wsum[CHUNK];                          /* sum of the accepted weights */
};

/* Sums of in (and in2) and their squares over the 3 x 3 window, taps outside the image
   left out, in a fixed order (dy, then dx: the shader's). */
SSG_VECTOR_CLONES static void
moments(const struct job *j, struct chunk *restrict k, int y, int x0, int len)
{
    for (int i = 0; i < len; i++) {
        k->count[i] = 0.0f;
        for (int ch = 0; ch < MAX_CH; ch++)
            k->m1[ch][i] = k->m2[ch][i] = 0.0f;
    }
    for (int qy = y - 1; qy <= y + 1; qy++) {
        if (qy < 0 || qy >= j->h)
            continue;
        for (int dx = -1; dx <= 1; dx++) {
            int i0 = -dx - x0 > 0 ? -dx - x0 : 0;
            int i1 = j->w - dx - x0 < len ? j->w - dx - x0 : len;
            size_t q = (size_t)qy * (size_t)j->w + (size_t)(x0 + dx);
            for (int i = i0; i < i1; i++)
                k->count[i] += 1.0f;
            for (int ch = 0; ch < j->channels; ch++) {
                const float *restrict v = j->in[ch] + q;
                for (int i = i0; i < i1; i++) {
                    float a = v[i];
                    k->m1[ch][i] += a;
                    k->m2[ch][i] += a * a;
                }
            }
        }
    }
}

/* The four bilinear taps of the previous frame around pixel centre + motion, each with
   its weight if it passes the tests (inside the image, previous surface present, relative
   depth difference within depth_tolerance, normals within normal_tolerance), else 0.
   Pixel (x, y)'s centre is x + 0.5, so the taps' top-left is floor(x + motion.x). The
   depth test is |z - d'| <= tol z (the ratio of DESIGN without a division). The loop over
   pixels vectorises (the taps' loads are gathers on AVX2), as do the blend and moments. */
SSG_VECTOR_CLONES static void
reproject(const struct job *j, int y, int x0, int len, const float *restrict mx,
          const float *restrict my, const float *restrict mz, const float *restrict depth,
          const float *restrict n0, const float *restrict n1, const float *restrict n2,
          const float *restrict prev_depth, const float *restrict pn0,
          const float *restrict pn1, const float *restrict pn2, int (*restrict idx)[CHUNK],
          float (*restrict wt)[CHUNK], float *restrict wsums)
{
    /* Every plane is a restrict parameter: so the compiler knows that the gathers and the
       stores into the chunk do not overlap, and vectorises the loop over pixels. Without
       normals the caller passes other planes and ntol -inf (the test always passes), so
       that no load depends on a condition. */
    const int iw = j->w, ih = j->h;
    const float tol = j->c->p.depth_tolerance;
    const float ntol = j->nrm[0] ? j->c->p.normal_tolerance : -INFINITY;
    const float xmax = (float)j->w + 1.0f, ymax = (float)j->h + 1.0f;
    const int row = y * iw + x0; /* int indices: 8 of them a gather on AVX2 */
    for (int i = 0; i < len; i++) {
        int o = row + i;
        /* clamped so that a wild vector cannot overflow the int below */
        float px = (float)(x0 + i) + mx[o], py = (float)y + my[o];
        px = px > -2.0f ? px : -2.0f; /* selects: fminf and fmaxf are libm calls here */
        px = px < xmax ? px : xmax;
        py = py > -2.0f ? py : -2.0f;
        py = py < ymax ? py : ymax;
        float fx0 = floorf(px), fy0 = floorf(py);
        float fx = px - fx0, fy = py - fy0;
        int ix = (int)fx0, iy = (int)fy0;
        float z = mz[o];
        int here = (depth[o] > 0.0f) & (z > 0.0f); /* &, not &&: no branches */
        float wsum = 0.0f;
#pragma GCC unroll 4 /* so that the loop over pixels is the one vectorised */
        for (int t = 0; t < TAPS; t++) {
            int tx = ix + (t & 1), ty = iy + (t >> 1);
            int inside = (tx >= 0) & (tx < iw) & (ty >= 0) & (ty < ih);
            /* the tap's pixel, or this pixel outside the image; masked, not selected: GCC 12
               vectorises no gather through a selected index */
            int q = o + ((ty * iw + tx - o) & -inside);
            float wx = (t & 1) ? fx : 1.0f - fx, wy = (t >> 1) ? fy : 1.0f - fy;
            float pd = prev_depth[q];
            int ok = here & inside & (pd > 0.0f) & (fabsf(z - pd) <= tol * z);
            float c = n0[o] * pn0[q] + n1[o] * pn1[q] + n2[o] * pn2[q];
            ok = ok & (c >= ntol);
            float w = ok ? wx * wy : 0.0f;
            idx[t][i] = q;
            wt[t][i] = w;
            wsum += w;
        }
        wsums[i] = wsum;
    }
}

/* The tap-weighted mean of one plane of the previous frame at pixel i of the chunk. Every
   tap's index is a pixel of the image, so the loads need no condition (the loop stays
   straight); a pixel without history divides by 1 and its value is not used. */
static inline float fetch(const struct chunk *restrict k, const float *restrict plane, int i)
{
    float s = k->wt[0][i] * plane[k->idx[0][i]] + k->wt[1][i] * plane[k->idx[1][i]];
    s = s + k->wt[2][i] * plane[k->idx[2][i]];
    s = s + k->wt[3][i] * plane[k->idx[3][i]];
    float wsum = k->wsum[i];
    return s / (wsum >= SSG_TEMPORAL_MIN_WEIGHT ? wsum : 1.0f);
}

/* The previous length n, the blend factor alpha = max(1 / (n + 1), 1 / max_length) and
   the new length. A pixel without enough valid history (wsum below
   SSG_TEMPORAL_MIN_WEIGHT) restarts: n = 0, length 1. The selects compute both sides, so
   the loop stays straight; restrict parameters tell the compiler the gathers do not
   alias the stores. */
SSG_VECTOR_CLONES static void
blend_length(const struct ssg_temporal_consts *c, const struct chunk *restrict k,
             const float *restrict len_in, float *restrict len_out, float *restrict alpha,
             int len)
{
    const float lmax = c->u.length_cap, amin = c->u.inv_max_length;
    for (int i = 0; i < len; i++) {
        int valid = k->wsum[i] >= SSG_TEMPORAL_MIN_WEIGHT;
        float n = fetch(k, len_in, i);
        n = valid ? n : 0.0f;
        float a = 1.0f / (n + 1.0f);
        alpha[i] = a > amin ? a : amin;
        float l = n + 1.0f;
        len_out[i] = valid ? (l < lmax ? l : lmax) : 1.0f;
    }
}

/* One channel: the history clamped to mean +/- gamma sigma of the window (gamma 0: not
   clamped, and the window's moments are neither made nor read: temporal_chunk), then
   out = h + alpha (in - h); a restarting pixel gets in. */
SSG_VECTOR_CLONES static void
blend_channel(const struct chunk *restrict k, int ch, const float *restrict hist,
              const float *restrict in, const float *restrict alpha, float *restrict out,
              float gamma, int len)
{
    if (!(gamma > 0.0f)) {
        for (int i = 0; i < len; i++) {
            int valid = k->wsum[i] >= SSG_TEMPORAL_MIN_WEIGHT;
            float hv = fetch(k, hist, i), v = in[i];
            out[i] = valid ? hv + alpha[i] * (v - hv) : v;
        }
        return;
    }
    for (int i = 0; i < len; i++) {
        int valid = k->wsum[i] >= SSG_TEMPORAL_MIN_WEIGHT;
        float hv = fetch(k, hist, i);
        float mean = k->m1[ch][i] / k->count[i];
        float var = k->m2[ch][i] / k->count[i] - mean * mean;
        float sd = sqrtf(var > 0.0f ? var : 0.0f);
        float lo = mean - gamma * sd, hi = mean + gamma * sd;
        float hc = hv < lo ? lo : hv;
        hv = hc > hi ? hi : hc;
        float v = in[i];
        out[i] = valid ? hv + alpha[i] * (v - hv) : v;
    }
}

static inline __attribute__((always_inline)) void
blend(const struct job *j, const struct chunk *k, int y, int x0, int len)
{
    const size_t row = (size_t)y * (size_t)j->w + (size_t)x0;
    float alpha[CHUNK];
    blend_length(j->c, k, j->len_in, j->len_out + row, alpha, len);
    for (int ch = 0; ch < j->channels; ch++)
        blend_channel(k, ch, j->hist[ch], j->in[ch] + row, alpha, j->out[ch] + row,
                      j->c->p.gamma, len);
}

/* One chunk of a row. Each step above is compiled per instruction set
   (SSG_VECTOR_CLONES, vector_loops.h): a clone cannot be inlined into a function of
   another target, so the clones are the steps themselves. */
static void temporal_chunk(const struct job *j, struct chunk *k, int y, int x0, int len)
{
    if (j->c->p.gamma > 0.0f) /* gamma 0 clamps nothing: blend_channel reads no moments */
        moments(j, k, y, x0, len);
    const float *const *n = j->nrm[0] ? j->nrm : j->motion; /* any planes: see reproject */
    const float *const *pn = j->nrm[0] ? j->prev_nrm : j->motion;
    reproject(j, y, x0, len, j->motion[0], j->motion[1], j->motion[2], j->depth, n[0], n[1],
              n[2], j->prev_depth, pn[0], pn[1], pn[2], k->idx, k->wt, k->wsum);
    blend(j, k, y, x0, len);
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    for (int y = y0; y < y1; y++)
        for (int x0 = 0; x0 < j->w; x0 += CHUNK)
            temporal_chunk(j, &k, y, x0, j->w - x0 < CHUNK ? j->w - x0 : CHUNK);
}

static void fill(const struct ssg_image *im, float v)
{
    size_t n = (size_t)im->width * (size_t)im->height * (size_t)im->channels;
    for (size_t i = 0; i < n; i++)
        im->data[i] = v;
}

/* ctx->history_reset: no earlier frame may be reused, whatever the history images hold
   (prev() gives zeros then): out = in, out2 = in2, length 1. */
static void restart(const struct job *j)
{
    size_t plane = (size_t)j->w * (size_t)j->h;
    for (int ch = 0; ch < j->channels; ch++)
        memcpy(j->out[ch], j->in[ch], sizeof(float) * plane);
    for (size_t i = 0; i < plane; i++)
        j->len_out[i] = 1.0f;
}

enum ssg_err ssg_temporal_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io)
{
    const struct ssg_image *in = io->in[SSG_TEMPORAL_IN_IN];
    const struct ssg_image *in2 = io->in[SSG_TEMPORAL_IN_IN2];
    const struct ssg_image *nrm = io->in[SSG_TEMPORAL_IN_NORMAL];
    const int n1 = in->channels, n2 = in2 ? in2->channels : 0;
    struct job j = {.c = consts, .channels = n1 + n2, .w = in->width, .h = in->height,
                    .len_in = io->in[SSG_TEMPORAL_IN_LENGTH_IN]->data,
                    .depth = io->in[SSG_TEMPORAL_IN_DEPTH]->data,
                    .prev_depth = io->in[SSG_TEMPORAL_IN_PREV_DEPTH]->data,
                    .len_out = io->out[SSG_TEMPORAL_OUT_LENGTH]->data};
    for (int ch = 0; ch < n1 + n2; ch++) {
        int second = ch >= n1, c = second ? ch - n1 : ch;
        j.in[ch] = ssg_image_plane(second ? in2 : in, c);
        j.hist[ch] = ssg_image_plane(io->in[second ? SSG_TEMPORAL_IN_HISTORY2
                                                   : SSG_TEMPORAL_IN_HISTORY], c);
        j.out[ch] = ssg_image_plane(io->out[second ? SSG_TEMPORAL_OUT_OUT2
                                                   : SSG_TEMPORAL_OUT_OUT], c);
    }
    for (int c = 0; c < 3; c++) {
        j.motion[c] = ssg_image_plane(io->in[SSG_TEMPORAL_IN_MOTION], c);
        j.nrm[c] = nrm ? ssg_image_plane(nrm, c) : NULL;
        j.prev_nrm[c] = nrm ? ssg_image_plane(io->in[SSG_TEMPORAL_IN_PREV_NORMAL], c) : NULL;
    }
    if (!in2) /* out2 is documented as all 0 without in2 */
        fill(io->out[SSG_TEMPORAL_OUT_OUT2], 0.0f);
    if (ctx->history_reset)
        restart(&j);
    else
        ssg_parallel_rows(j.h, ROWS_PER_BAND, band, &j);
    return SSG_OK;
}
