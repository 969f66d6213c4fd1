/* bilateral_cpu.c - CPU kernel of the `bilateral` node (method in README.md).
 *
 * The loops run over output pixels innermost: a row is cut into chunks, and for each tap
 * (dy, dx) of the window one loop walks the chunk, reading the neighbours at a fixed
 * offset (contiguous loads) and adding into per-pixel sums. Each pixel's sums are thus
 * independent lanes, which the compiler vectorises without reassociating anything, and
 * the sum order per pixel is fixed whatever the threads. The three weights multiply by
 * adding their logarithms (spatial from prepare, depth, p * ln(n.n')) and taking one
 * exp(); exp and ln are small polynomial versions that vectorise (libm's do not without
 * -ffast-math), accurate to a few 1e-7 relative (bilateral_math.h).
 * The separable form runs the same loops twice with a one-row, then a one-column window
 * (run_passes): 2 size taps per pixel instead of size^2; the `atrous` node runs them as
 * dilated 5 x 5 passes. The optional in2 is carried as
 * further channels after in's (1 + 1, 1 + 3, 3 + 1, 3 + 3): each tap's weight is computed
 * once for all of them, and per channel the sums are those of a filter of that image
 * alone, so out2 is bit for bit a second node's output. */
#define SSG_VECTOR_FMA /* a filter: fused multiply-adds allowed (vector_loops.h) */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "bilateral.h"

#include "common/bilateral_math.h"

enum { CHUNK = 256, ROWS_PER_BAND = 4, MAX_CH = 6 };

struct job {
    const struct ssg_bilateral_consts *c;
    const float *in[MAX_CH]; /* channel planes: in's, then in2's */
    int channels;            /* in's and in2's together: 1, 2, 3, 4 or 6 */
    const float *depth;
    const float *nrm[3];     /* NULL when there is no normal term */
    float *out[MAX_CH];      /* out's planes, then out2's */
    int w, h;
    int rx, ry;            /* half-widths of the window walked: radius, or 0 on the axis a
                              separable pass does not cover */
    int step;              /* px between taps: 1, or an a-trous pass's dilation */
};

/* Per-pixel values of one chunk, structure of arrays. */
struct chunk {
    float dc[CHUNK];                    /* centre depth */
    float kd[CHUNK];                    /* depth_scale / centre depth */
    float nx[CHUNK], ny[CHUNK], nz[CHUNK]; /* unit centre normal */
    float acc[MAX_CH][CHUNK];           /* weighted sums per channel */
    float wsum[CHUNK];                  /* sum of weights */
};

/* Two straight loops (the normal one only with a normal input) rather than one with a
   test inside: both vectorise. */
static void setup_chunk(const struct job *j, struct chunk *k, int y, int x0, int len)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x0;
    const float *restrict depth = j->depth + o;
    const float scale = j->c->u.depth_scale;
    for (int i = 0; i < len; i++) {
        float d = depth[i];
        k->dc[i] = d;
        k->kd[i] = d > 0.0f ? scale / d : 0.0f;
        k->wsum[i] = 0.0f;
        for (int ch = 0; ch < MAX_CH; ch++)
            k->acc[ch][i] = 0.0f;
        k->nx[i] = k->ny[i] = k->nz[i] = 0.0f;
    }
    if (!j->nrm[0])
        return;
    const float *restrict n0 = j->nrm[0] + o, *restrict n1 = j->nrm[1] + o;
    const float *restrict n2 = j->nrm[2] + o;
    for (int i = 0; i < len; i++) {
        float nx = n0[i], ny = n1[i], nz = n2[i], nn = nx * nx + ny * ny + nz * nz;
        float inv = nn > 0.0f ? 1.0f / sqrtf(nn) : 0.0f;
        k->nx[i] = nx * inv, k->ny[i] = ny * inv, k->nz[i] = nz * inv;
    }
}

/* Adds tap (dx, dy) with spatial log-weight es to pixels [i0, i1) of the chunk; q points
   at the tap's pixel for chunk index 0 (offset into each plane). `channels` and `mode`
   are constants at each call site, so each variant is its own straight loop. Normal
   cosines below normal_min (whose weight c^p is below 1e-30) count as 0: then every
   power of c computed is a normal float, and weights below 1e-30 are dropped too, so no
   denormal ever slows the loop. */
static inline __attribute__((always_inline)) void
add_tap(const struct job *j, struct chunk *restrict k, size_t q, int i0, int i1, float es,
        int channels, int mode)
{
    const float *restrict dq = j->depth + q;
    const float p = (float)j->c->u.normal_power, cmin = j->c->u.normal_min;
    for (int i = i0; i < i1; i++) {
        float delta = (dq[i] - k->dc[i]) * k->kd[i];
        float e = es - 0.5f * delta * delta;
        float wn = 1.0f, c0 = 1.0f;
        if (mode != SSG_NORMAL_OFF) {
            c0 = k->nx[i] * j->nrm[0][q + (size_t)i] + k->ny[i] * j->nrm[1][q + (size_t)i] +
                 k->nz[i] * j->nrm[2][q + (size_t)i];
            wn = ssg_normal_factor(c0 >= cmin ? c0 : 1.0f, p, mode, &e);
        }
        /* One float-compare select at a time: GCC does not vectorise a select on a
           mask combined from several comparisons here. */
        float w = exp_neg(e) * wn;
        w = w >= 1e-30f ? w : 0.0f;
        w = dq[i] > 0.0f ? w : 0.0f; /* background lends nothing */
        if (mode != SSG_NORMAL_OFF)
            w = c0 >= cmin ? w : 0.0f;
        k->wsum[i] += w;
        for (int ch = 0; ch < channels; ch++)
            k->acc[ch][i] += w * j->in[ch][q + (size_t)i];
    }
}

/* All taps of the window for one chunk row, in a fixed order: dy in [-ry, ry], dx in
   [-rx, rx], step px apart. The full filter has rx = ry = radius; the separable passes
   one of them 0; an a-trous pass spreads its 5 x 5 taps `step` px apart. */
static inline __attribute__((always_inline)) void
taps(const struct job *j, struct chunk *k, int y, int x0, int len, int channels, int mode)
{
    const int r = j->c->u.radius, size = j->c->u.size, rx = j->rx, ry = j->ry, step = j->step;
    for (int dy = -ry; dy <= ry; dy++) {
        int qy = y + dy * step;
        if (qy < 0 || qy >= j->h)
            continue;
        for (int dx = -rx; dx <= rx; dx++) {
            /* Chunk pixels whose neighbour x0 + i + ox lies inside the row. */
            int ox = dx * step;
            int i0 = -ox - x0 > 0 ? -ox - x0 : 0;
            int i1 = j->w - ox - x0 < len ? j->w - ox - x0 : len;
            if (i0 >= i1)
                continue;
            size_t q = (size_t)qy * (size_t)j->w + (size_t)(x0 + ox);
            add_tap(j, k, q, i0, i1, j->c->spatial[(dy + r) * size + dx + r], channels, mode);
        }
    }
}

/* taps() for one channel count, one straight loop a normal mode. */
static inline __attribute__((always_inline)) void
taps_of(const struct job *j, struct chunk *k, int y, int x0, int len, int channels)
{
    int mode = ssg_normal_mode(j->nrm[0] != NULL && j->c->u.normal_power > 0,
                               j->c->u.squarings);
#define TAPS(m) taps(j, k, y, x0, len, channels, m)
    SSG_NORMAL_MODE_SWITCH(mode, TAPS)
#undef TAPS
}

/* The hot loop, compiled per instruction set (SSG_VECTOR_CLONES, vector_loops.h). */
SSG_VECTOR_CLONES
static void bilateral_add_taps(const struct job *j, struct chunk *k, int y, int x0, int len)
{
    switch (j->channels) {
    case 1: taps_of(j, k, y, x0, len, 1); break;
    case 2: taps_of(j, k, y, x0, len, 2); break;
    case 3: taps_of(j, k, y, x0, len, 3); break;
    case 4: taps_of(j, k, y, x0, len, 4); break;
    default: taps_of(j, k, y, x0, len, 6); break;
    }
}

static void finish_chunk(const struct job *j, const struct chunk *k, int y, int x0, int len)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x0;
    for (int ch = 0; ch < j->channels; ch++) {
        const float *restrict in = j->in[ch] + o;
        float *restrict out = j->out[ch] + o;
        for (int i = 0; i < len; i++) {
            /* Background, or nothing with weight (zero normal): pass through. Both
               values computed, then chosen: a load under a condition stops vectorising. */
            float v = in[i], f = k->acc[ch][i] / k->wsum[i];
            int keep = !(k->dc[i] > 0.0f) | !(k->wsum[i] > 0.0f);
            out[i] = keep ? v : f;
        }
    }
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    for (int y = y0; y < y1; y++)
        for (int x0 = 0; x0 < j->w; x0 += CHUNK) {
            int len = j->w - x0 < CHUNK ? j->w - x0 : CHUNK;
            setup_chunk(j, &k, y, x0, len);
            bilateral_add_taps(j, &k, y, x0, len);
            finish_chunk(j, &k, y, x0, len);
        }
}

/* The passes of a run (ssg_bilateral_passes), one after another: pass 0 reads the
   inputs, the last writes the outputs, the others go through the node's scratch
   (ssg_node_scratch, kept from frame to frame): one image of every channel, two in turn
   for three passes or more. Each pass is the full kernel with its own window and step, so
   all share the vectorised loops, and a pass starts only when the one before has finished
   every band. The separable approximation (Belonogov eq. 4.6 and 4.7) is a one-row pass
   and a one-column pass, each with the weights of the full filter restricted to its axis
   (the spatial Gaussian factors exactly; the depth and normal terms are taken against each
   pass's own centre pixel); a-trous is `atrous` passes of the 5 x 5 window, 1, 2, 4, ... px
   apart (atrous.c in this folder). */
static enum ssg_err run_passes(const struct ssg_node_ctx *ctx, struct job *j, int passes,
                               const struct ssg_bilateral_pass *pass)
{
    size_t plane = (size_t)j->w * (size_t)j->h, image = plane * (size_t)j->channels;
    int buffers = passes > 2 ? 2 : passes - 1;
    float *tmp = buffers ? ssg_node_scratch(ctx, sizeof(float) * image * (size_t)buffers)
                         : NULL;
    if (buffers && !tmp)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the filter's passes");
    for (int i = 0; i < passes; i++) {
        struct job p = *j;
        p.rx = pass[i].rx, p.ry = pass[i].ry, p.step = pass[i].step;
        for (int ch = 0; ch < j->channels; ch++) {
            if (i > 0)
                p.in[ch] = tmp + (size_t)((i - 1) % 2) * image + (size_t)ch * plane;
            if (i < passes - 1)
                p.out[ch] = tmp + (size_t)(i % 2) * image + (size_t)ch * plane;
        }
        ssg_parallel_rows(j->h, ROWS_PER_BAND, band, &p);
    }
    return SSG_OK;
}

enum ssg_err ssg_bilateral_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io)
{
    const struct ssg_image *in = io->in[SSG_BILATERAL_IN_IN];
    const struct ssg_image *dep = io->in[SSG_BILATERAL_IN_DEPTH];
    const struct ssg_image *nrm = io->in[SSG_BILATERAL_IN_NORMAL];
    const struct ssg_image *in2 = io->in[SSG_BILATERAL_IN_IN2];
    const struct ssg_bilateral_consts *c = consts;
    const int n2 = in2 ? in2->channels : 0;
    struct job j = {.c = c, .channels = in->channels + n2, .depth = dep->data,
                    .w = in->width, .h = in->height};
    for (int ch = 0; ch < in->channels; ch++) {
        j.in[ch] = ssg_image_plane(in, ch);
        j.out[ch] = ssg_image_plane(io->out[SSG_BILATERAL_OUT_OUT], ch);
    }
    for (int ch = 0; ch < n2; ch++) {
        j.in[in->channels + ch] = ssg_image_plane(in2, ch);
        j.out[in->channels + ch] = ssg_image_plane(io->out[SSG_BILATERAL_OUT_OUT2], ch);
    }
    if (!in2) { /* out2 is documented as all 0 when in2 is unconnected */
        const struct ssg_image *o2 = io->out[SSG_BILATERAL_OUT_OUT2];
        memset(o2->data, 0, sizeof(float) * (size_t)o2->width * (size_t)o2->height *
                                (size_t)o2->channels);
    }
    for (int ch = 0; nrm && ch < 3; ch++)
        j.nrm[ch] = ssg_image_plane(nrm, ch);
    struct ssg_bilateral_pass pass[SSG_BILATERAL_MAX_PASSES];
    return run_passes(ctx, &j, ssg_bilateral_passes(c, pass), pass);
}
