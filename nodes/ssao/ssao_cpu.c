/* ssao_cpu.c - CPU kernel of the `ssao` node (method in ssao.c).
 *
 * Layout for speed: a row is cut into chunks of CHUNK pixels; per chunk the pixel's
 * position, its radius-scaled rotated tangent frame and its depth are computed once into
 * structure-of-arrays scratch on the stack. Then, per kernel sample, one loop over the
 * chunk places and projects the sample (straight-line arithmetic the compiler vectorises)
 * and a second loop fetches the scene depth at the projected pixels (one float plane:
 * the depth image, or position's z plane) and accumulates the weighted occlusion.
 * Samples stay within `radius` of their pixel, so consecutive pixels fetch nearby depths
 * and the fetches hit cache. Bands of rows go to ssg_parallel_rows; each pixel depends
 * only on the inputs, so the output does not depend on the thread count. */
#include <math.h>
#include <stdint.h>

#include "ssao.h"

enum { CHUNK = 256, ROWS_PER_BAND = 8 };

struct job {
    const struct ssg_ssao_consts *c;
    const float *pos[3], *nrm[3]; /* planes of position and normal */
    const float *depth;           /* plane the scene depth is read from */
    float depth_sign;             /* depth = depth_sign * plane: 1 for depth, -1 for z */
    const float *kernel;          /* planar count x 1 x 3 */
    int count;
    const float *rot;             /* planar n x n x 2 (cos, sin), NULL = none */
    int n;
    float *out;
    int w, h;
    float f, cx, cy;              /* projection of this resolution */
};

/* Per-pixel values of one chunk, structure of arrays. */
struct chunk {
    float px[CHUNK], py[CHUNK], pz[CHUNK];          /* P, view space */
    float tx[CHUNK], ty[CHUNK], tz[CHUNK];          /* r * T (rotated tangent) */
    float bx[CHUNK], by[CHUNK], bz[CHUNK];          /* r * B */
    float nx[CHUNK], ny[CHUNK], nz[CHUNK];          /* r * N */
    float dp[CHUNK];                                /* depth of P */
    float rr[CHUNK];                                /* r for the range check */
    float occ[CHUNK];                               /* weighted occluded samples */
    float lim[CHUNK];                               /* -S.z - bias, or -1 when off screen */
    int32_t idx[CHUNK];                             /* pixel S lands on */
    unsigned char fg[CHUNK];                        /* 1 = surface, 0 = background */
};

/* Orthonormal T, B with T x B = N, branch-free apart from the sign (Duff et al., "Building
   an Orthonormal Basis, Revisited", JCGT 2017): continuous except at n.z = 0 crossings,
   which a rotated kernel does not care about. */
static void tangent_frame(const float n[3], float t[3], float b[3])
{
    float sign = copysignf(1.0f, n[2]);
    float a = -1.0f / (sign + n[2]);
    float bb = n[0] * n[1] * a;
    t[0] = 1.0f + sign * n[0] * n[0] * a;
    t[1] = sign * bb;
    t[2] = -sign * n[0];
    b[0] = bb;
    b[1] = sign + n[1] * n[1] * a;
    b[2] = -n[1];
}

static void setup_background(struct chunk *k, int i)
{
    /* Harmless values: the sample lands at the screen centre; the result is replaced. */
    k->fg[i] = 0;
    k->px[i] = k->py[i] = 0.0f;
    k->pz[i] = -1.0f;
    k->tx[i] = k->ty[i] = k->tz[i] = k->bx[i] = k->by[i] = k->bz[i] = 0.0f;
    k->nx[i] = k->ny[i] = k->nz[i] = 0.0f;
    k->dp[i] = k->rr[i] = 1.0f;
    k->occ[i] = 0.0f;
}

static void setup_pixel(const struct job *j, struct chunk *k, int i, int x, int y)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x;
    float d = j->depth_sign * j->depth[o];
    float n[3] = {j->nrm[0][o], j->nrm[1][o], j->nrm[2][o]};
    float nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (!(d > 0.0f) || !(nn > 0.0f) || !isfinite(d)) {
        setup_background(k, i);
        return;
    }
    float inv = 1.0f / sqrtf(nn);
    n[0] *= inv, n[1] *= inv, n[2] *= inv;
    float t[3], b[3], co = 1.0f, si = 0.0f;
    tangent_frame(n, t, b);
    if (j->rot) {
        size_t r = (size_t)(y % j->n) * (size_t)j->n + (size_t)(x % j->n);
        co = j->rot[r];
        si = j->rot[(size_t)j->n * (size_t)j->n + r];
    }
    float r = j->c->p.radius;
    if (j->c->p.max_screen_radius > 0.0f)
        r = fminf(r, j->c->p.max_screen_radius * d / j->f);
    k->fg[i] = 1;
    k->px[i] = j->pos[0][o];
    k->py[i] = j->pos[1][o];
    k->pz[i] = j->pos[2][o];
    /* Turning the frame about N by the tile's angle turns the whole kernel. */
    k->tx[i] = r * (co * t[0] + si * b[0]);
    k->ty[i] = r * (co * t[1] + si * b[1]);
    k->tz[i] = r * (co * t[2] + si * b[2]);
    k->bx[i] = r * (co * b[0] - si * t[0]);
    k->by[i] = r * (co * b[1] - si * t[1]);
    k->bz[i] = r * (co * b[2] - si * t[2]);
    k->nx[i] = r * n[0];
    k->ny[i] = r * n[1];
    k->nz[i] = r * n[2];
    k->dp[i] = d;
    k->rr[i] = r;
    k->occ[i] = 0.0f;
}

/* Places sample (sx, sy, sz) around every pixel of the chunk and projects it. */
static void place_samples(const struct job *j, struct chunk *restrict k, int len, float sx,
                          float sy, float sz)
{
    const float f = j->f, cx = j->cx, cy = j->cy, bias = j->c->p.bias;
    const float fw = (float)j->w, fh = (float)j->h;
    const int w = j->w;
    for (int i = 0; i < len; i++) {
        float x = k->px[i] + k->tx[i] * sx + k->bx[i] * sy + k->nx[i] * sz;
        float y = k->py[i] + k->ty[i] * sx + k->by[i] * sy + k->ny[i] * sz;
        float zq = -(k->pz[i] + k->tz[i] * sx + k->bz[i] * sy + k->nz[i] * sz);
        float inv = 1.0f / zq;
        float u = cx + f * x * inv;
        float v = cy - f * y * inv;
        /* Behind the camera or off screen: no depth there, so unoccluded. Comparisons
           are false for NaN, so a degenerate zq also lands here. */
        int ok = (zq > 0.0f) & (u >= 0.0f) & (u < fw) & (v >= 0.0f) & (v < fh);
        /* Select in float, then convert unconditionally: a conversion under a condition
           would keep a branch (an out-of-range one is undefined) and stop vectorising. */
        float us = ok ? u : 0.0f, vs = ok ? v : 0.0f;
        k->idx[i] = (int)vs * w + (int)us;
        k->lim[i] = ok ? zq - bias : -1.0f;
    }
}

/* Looks up the scene depth under each placed sample and adds its weighted occlusion.
   `range` is a constant at each call site, so the switch folds away. */
static inline __attribute__((always_inline)) void
accumulate(const struct job *j, struct chunk *restrict k, int len, int range)
{
    const float *restrict plane = j->depth;
    const float sign = j->depth_sign;
    for (int i = 0; i < len; i++) {
        float d = sign * plane[k->idx[i]];
        float wgt = 1.0f;
        if (range == SSG_SSAO_RANGE_HARD) {
            wgt = fabsf(d - k->dp[i]) <= k->rr[i] ? 1.0f : 0.0f;
        } else if (range == SSG_SSAO_RANGE_SMOOTH) {
            float t = k->rr[i] / fabsf(k->dp[i] - d); /* inf at 0 -> clamped to 1 */
            t = t < 1.0f ? t : 1.0f;
            wgt = t * t * (3.0f - 2.0f * t);
        }
        /* d = 0 is background: infinitely far, never in front of the sample. */
        int occluded = (d > 0.0f) & (d < k->lim[i]);
        k->occ[i] += occluded ? wgt : 0.0f;
    }
}

static void sample_all(const struct job *j, struct chunk *k, int len)
{
    const int count = j->count;
    const float *kx = j->kernel, *ky = kx + count, *kz = ky + count;
    for (int s = 0; s < count; s++) {
        place_samples(j, k, len, kx[s], ky[s], kz[s]);
        switch (j->c->p.range_check) {
        case SSG_SSAO_RANGE_NONE: accumulate(j, k, len, SSG_SSAO_RANGE_NONE); break;
        case SSG_SSAO_RANGE_HARD: accumulate(j, k, len, SSG_SSAO_RANGE_HARD); break;
        default: accumulate(j, k, len, SSG_SSAO_RANGE_SMOOTH); break;
        }
    }
}

static void finish_chunk(const struct job *j, const struct chunk *k, int len, float *out)
{
    const float inv_count = 1.0f / (float)j->count, power = j->c->p.power;
    for (int i = 0; i < len; i++) {
        float v = 1.0f - k->occ[i] * inv_count;
        v = v > 0.0f ? v : 0.0f;
        if (power != 1.0f)
            v = powf(v, power);
        out[i] = k->fg[i] ? v : 1.0f;
    }
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    for (int y = y0; y < y1; y++) {
        for (int x0 = 0; x0 < j->w; x0 += CHUNK) {
            int len = j->w - x0 < CHUNK ? j->w - x0 : CHUNK;
            for (int i = 0; i < len; i++)
                setup_pixel(j, &k, i, x0 + i, y);
            sample_all(j, &k, len);
            finish_chunk(j, &k, len, j->out + (size_t)y * (size_t)j->w + (size_t)x0);
        }
    }
}

static enum ssg_err fail(const struct ssg_node_ctx *ctx, enum ssg_err code, const char *what)
{
    ssg_diag_at(ctx->diags, code, (struct ssg_loc){0}, "ssao '%s': %s",
                ctx->instance ? ctx->instance : "", what);
    return code;
}

static int size_is(const struct ssg_image *im, int w, int h, int ch)
{
    return im && im->width == w && im->height == h && im->channels == ch;
}

/* Checks what check() checked on shapes, now on the images, so a hand-built run cannot
   read out of bounds. */
static enum ssg_err check_images(const struct ssg_node_ctx *ctx, const struct ssg_io *io)
{
    const struct ssg_image *pos = io->in[SSG_SSAO_IN_POSITION];
    const struct ssg_image *ker = io->in[SSG_SSAO_IN_KERNEL];
    const struct ssg_image *rot = io->in[SSG_SSAO_IN_ROTATION];
    const struct ssg_image *dep = io->in[SSG_SSAO_IN_DEPTH];
    if (!pos || pos->channels != 3 || !size_is(io->in[SSG_SSAO_IN_NORMAL], pos->width,
                                                pos->height, 3))
        return fail(ctx, SSG_E_SIZE, "position and normal must be 3-channel, one size");
    if (!ker || ker->channels != 3 || ker->height != 1 || ker->width < 1)
        return fail(ctx, SSG_E_CHANNELS, "kernel must be count x 1 x 3");
    if (rot && (rot->channels != 2 || rot->width != rot->height || rot->width < 1))
        return fail(ctx, SSG_E_CHANNELS, "rotation must be n x n x 2");
    if (dep && !size_is(dep, pos->width, pos->height, 1))
        return fail(ctx, SSG_E_SIZE, "depth must be 1-channel, the size of position");
    if (!size_is(io->out[0], pos->width, pos->height, 1))
        return fail(ctx, SSG_E_SIZE, "output must be 1-channel, the size of position");
    return SSG_OK;
}

enum ssg_err ssg_ssao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_ssao_consts *c = consts;
    enum ssg_err e = check_images(ctx, io);
    if (e != SSG_OK)
        return e;
    const struct ssg_image *pos = io->in[SSG_SSAO_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_SSAO_IN_NORMAL];
    const struct ssg_image *ker = io->in[SSG_SSAO_IN_KERNEL];
    const struct ssg_image *rot = io->in[SSG_SSAO_IN_ROTATION];
    const struct ssg_image *dep = io->in[SSG_SSAO_IN_DEPTH];
    struct job j = {.c = c, .kernel = ker->data, .count = ker->width, .out = io->out[0]->data,
                    .w = pos->width, .h = pos->height};
    for (int ch = 0; ch < 3; ch++) {
        j.pos[ch] = ssg_image_plane(pos, ch);
        j.nrm[ch] = ssg_image_plane(nrm, ch);
    }
    j.depth = dep ? dep->data : j.pos[2];
    j.depth_sign = dep ? 1.0f : -1.0f;
    j.rot = rot ? rot->data : NULL;
    j.n = rot ? rot->width : 1;
    /* A G-buffer of another size than the frame (subsampled) sees the same camera. */
    j.f = c->proj.f * (float)j.h / (float)c->frame_height;
    j.cx = c->proj.cx * (float)j.w / (float)c->frame_width;
    j.cy = c->proj.cy * (float)j.h / (float)c->frame_height;
    ssg_parallel_rows(j.h, ROWS_PER_BAND, band, &j);
    return SSG_OK;
}
