/* downsample_cpu.c - CPU kernel of the `downsample` node (method in README.md).
 *
 * Each band of output rows first picks the representative pixel of each block of its rows
 * (factor 2: a few minima and maxima a block, pick_row_2; else a tiny sort of at most 16
 * depths), then copies every connected plane from those pixels
 * (unconnected ones get zeros: pool images arrive with old contents); an output nothing
 * reads has no image and is not made.
 * A block depends only on its own input pixels, so the result is the same whatever the
 * threads. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "downsample.h"

enum {
    ROWS_PER_BAND = 8,
    CHUNK = 256,
    MAX_BLOCK = SSG_DOWNSAMPLE_MAX_FACTOR * SSG_DOWNSAMPLE_MAX_FACTOR
};

struct job {
    const struct ssg_image *in[SSG_DOWNSAMPLE_INPUTS]; /* NULL = unconnected */
    struct ssg_image *out[SSG_DOWNSAMPLE_INPUTS];
    int factor;
    int w, h;   /* input size */
    int ow, oh; /* output size */
};

/* The median of n > 0 values (sorted in place): the middle one, or for an even count the
   lower (nearer) of the two middle ones, a depth the block has: the mean of the two would
   lie exactly between them, and a block split two and two by an edge would then choose its
   side by a rounding in the last bit, differently on each backend. The body is the GL
   shader's too (nodes/common/median.glsl). */
static float median(float *v, int n)
{
#include "common/median.glsl"
}

/* Input pixel index of block (bx, by)'s representative. */
static size_t representative(const struct job *j, int bx, int by)
{
    const float *depth = j->in[SSG_DOWNSAMPLE_IN_DEPTH]->data;
    int x0 = bx * j->factor, y0 = by * j->factor;
    int x1 = x0 + j->factor < j->w ? x0 + j->factor : j->w;
    int y1 = y0 + j->factor < j->h ? y0 + j->factor : j->h;
    float v[MAX_BLOCK];
    int n = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            float d = depth[(size_t)y * (size_t)j->w + (size_t)x];
            if (d > 0.0f)
                v[n++] = d;
        }
    size_t best = (size_t)y0 * (size_t)j->w + (size_t)x0;
    if (n == 0)
        return best; /* all background: its first pixel */
    float m = median(v, n), best_err = INFINITY;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            size_t o = (size_t)y * (size_t)j->w + (size_t)x;
            float err = fabsf(depth[o] - m);
            if (depth[o] > 0.0f && err < best_err) { /* strict: ties keep the first */
                best_err = err;
                best = o;
            }
        }
    return best;
}

/* representative() of blocks bx0 .. bx0 + len - 1 of block row by, factor 2, every block
   inside the image, into pick: the same choice without a sort, a straight loop over the
   blocks (the frame's most common downsample, gi_temporal_half's 16 planes). With the
   block's surface depths sorted s0 <= s1 <= ..., the median of n is s1 for n = 3 or 4 and
   s0 for n = 1 or 2 (the lower middle one); the chosen pixel is the first in row-major
   order with exactly that depth (its |depth - median| is 0, which nothing undercuts). A
   block whose median is not finite is marked (SIZE_MAX) for representative(). */
SSG_VECTOR_CLONES
static void pick_row_2(const struct job *j, int bx0, int by, int len, size_t *restrict pick)
{
    const float *restrict r0 = j->in[SSG_DOWNSAMPLE_IN_DEPTH]->data +
                               (size_t)(2 * by) * (size_t)j->w + (size_t)(2 * bx0);
    const float *restrict r1 = r0 + j->w;
    const size_t first = (size_t)(2 * by) * (size_t)j->w + (size_t)(2 * bx0), w = (size_t)j->w;
    for (int i = 0; i < len; i++) {
        float a = r0[2 * i], b = r0[2 * i + 1], c = r1[2 * i], d = r1[2 * i + 1];
        int n = (a > 0.0f) + (b > 0.0f) + (c > 0.0f) + (d > 0.0f);
        float A = a > 0.0f ? a : INFINITY, B = b > 0.0f ? b : INFINITY;
        float C = c > 0.0f ? c : INFINITY, D = d > 0.0f ? d : INFINITY;
        float lo1 = A < B ? A : B, hi1 = A < B ? B : A, lo2 = C < D ? C : D;
        float hi2 = C < D ? D : C;
        float s0 = lo1 < lo2 ? lo1 : lo2, up = lo1 < lo2 ? lo2 : lo1;
        float s1 = up < (hi1 < hi2 ? hi1 : hi2) ? up : (hi1 < hi2 ? hi1 : hi2);
        float m = n >= 3 ? s1 : s0;
        size_t at = first + 2 * (size_t)i;
        size_t q = a == m ? at : b == m ? at + 1 : c == m ? at + w : at + w + 1;
        pick[i] = n == 0 ? at : m < INFINITY ? q : SIZE_MAX;
    }
}

/* Every block's representative in a run of len blocks. */
static void pick_blocks(const struct job *j, int bx0, int by, int len, size_t *pick)
{
    int inside = j->factor == 2 && 2 * (by + 1) <= j->h ? (j->w / 2 - bx0) : 0;
    inside = inside < len ? (inside > 0 ? inside : 0) : len;
    if (inside > 0)
        pick_row_2(j, bx0, by, inside, pick);
    for (int i = 0; i < len; i++)
        if (i >= inside || pick[i] == SIZE_MAX)
            pick[i] = representative(j, bx0 + i, by);
}

/* The copied motion's x and y in output pixels, measured from the output pixel's centre:
   the chosen pixel q moved by m (input pixels) lies at (q + 0.5 + m) / f in the previous
   frame's output grid, so from the centre b + 0.5 that is m / f + ((q + 0.5) / f - (b +
   0.5)). f is 2 or 4, so / f is an exact product by 1 / f, the same on GL
   (downsample.glsl). */
static void rescale_motion(const struct job *j, const size_t *pick, int bx0, int by, int len,
                           size_t dst)
{
    size_t out_plane = (size_t)j->ow * (size_t)j->oh;
    float *mx = j->out[SSG_DOWNSAMPLE_OUT_MOTION]->data + dst, *my = mx + out_plane;
    float inv_f = 1.0f / (float)j->factor;
    for (int i = 0; i < len; i++) {
        float qx = (float)(pick[i] % (size_t)j->w), qy = (float)(pick[i] / (size_t)j->w);
        mx[i] = mx[i] * inv_f + ((qx + 0.5f) * inv_f - ((float)(bx0 + i) + 0.5f));
        my[i] = my[i] * inv_f + ((qy + 0.5f) * inv_f - ((float)by + 0.5f));
    }
}

/* Representatives are picked for a run of CHUNK blocks, then each plane copies that run:
   one read and one write stream at a time, where copying all planes pixel by pixel would
   keep 32 streams open. */
static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    size_t in_plane = (size_t)j->w * (size_t)j->h, out_plane = (size_t)j->ow * (size_t)j->oh;
    size_t pick[CHUNK];
    for (int by = y0; by < y1; by++)
        for (int bx0 = 0; bx0 < j->ow; bx0 += CHUNK) {
            int len = j->ow - bx0 < CHUNK ? j->ow - bx0 : CHUNK;
            pick_blocks(j, bx0, by, len, pick);
            size_t dst = (size_t)by * (size_t)j->ow + (size_t)bx0;
            for (int k = 0; k < SSG_DOWNSAMPLE_INPUTS; k++)
                for (int ch = 0; j->out[k] && ch < j->out[k]->channels; ch++) {
                    float *out = j->out[k]->data + (size_t)ch * out_plane + dst;
                    if (!j->in[k]) {
                        memset(out, 0, sizeof(float) * (size_t)len);
                        continue;
                    }
                    const float *in = j->in[k]->data + (size_t)ch * in_plane;
                    for (int i = 0; i < len; i++)
                        out[i] = in[pick[i]];
                }
            if (j->in[SSG_DOWNSAMPLE_IN_MOTION] && j->out[SSG_DOWNSAMPLE_OUT_MOTION])
                rescale_motion(j, pick, bx0, by, len, dst);
        }
}

enum ssg_err ssg_downsample_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io)
{
    const struct ssg_downsample_params *p = consts;
    const struct ssg_image *dep = io->in[SSG_DOWNSAMPLE_IN_DEPTH];
    const struct ssg_shape *out = &ctx->out_shape[SSG_DOWNSAMPLE_OUT_DEPTH];
    struct job j = {.factor = p->factor, .w = dep->width, .h = dep->height,
                    .ow = out->width, .oh = out->height};
    for (int k = 0; k < SSG_DOWNSAMPLE_INPUTS; k++) {
        j.in[k] = io->in[k];
        j.out[k] = io->out[k];
    }
    ssg_parallel_rows(j.oh, ROWS_PER_BAND, band, &j);
    return SSG_OK;
}
