/* ssao_cpu.c - CPU kernel of the `ssao` node (method in README.md).
 *
 * Layout for speed. A row is cut into chunks of CHUNK pixels; per chunk, each pixel's
 * rotated, radius-scaled tangent frame is folded once into projective coefficients
 * (struct chunk) in structure-of-arrays scratch on the stack. Then, per kernel sample, one
 * loop over the chunk places and projects the sample and a second one reads the scene
 * depth there (one float plane: the depth image, or position's z plane) and adds the
 * occlusion; both are straight-line code the compiler vectorises (SSE4, AVX2 or AVX-512
 * through run-time selected clones). Cache: the samples of a chunk read a window of about
 * (CHUNK + 2 Rp) x 2 Rp depths, Rp the projected radius in pixels; 128 keeps that in a
 * 512 KiB L2 for Rp up to about 130 (radius 0.5 at depth 5 in 1080p), and walking a band's
 * rows inside each chunk column (not columns inside rows) slides that window one row at
 * a time. max_screen_radius bounds Rp where near geometry would blow it up.
 * Per-pixel counts (the `count` input, README.md): a chunk runs the samples up to the largest
 * count among its surface pixels, and a lane adds a sample's occlusion only while
 * s < n_i (a select, so the loops still vectorise); the division is by n_i. Adding a
 * masked 0 leaves a sum's bits unchanged, so count = K everywhere gives the bits of the
 * path without the input, which itself stays as it was (the flag is a constant at each
 * call site).
 * Bands of rows go to ssg_parallel_rows; each pixel depends only on the inputs and every
 * per-pixel sum runs in kernel order, so the output does not depend on the thread count
 * (the FMA clones round a little differently from the baseline's: vector_loops.h). */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/sampling.h"
#include "ssao.h"

enum { CHUNK = SSG_SAMPLING_CHUNK, ROWS_PER_BAND = 16 };

struct job {
    const struct ssg_ssao_consts *c;
    const float *pos[3], *nrm[3]; /* planes of position and normal (NULL: normal-free) */
    const float *depth;           /* plane the scene depth is read from */
    float depth_sign;             /* depth = depth_sign * plane: 1 for depth, -1 for z */
    const float *kernel;          /* planar count x 1 x 3 */
    int count;
    const float *rot;             /* planar n x n x 2 (cos, sin), NULL = none */
    const float *off;             /* the tile's length shift (planes 3, 4), NULL = none */
    const float *lens;            /* |s| of each kernel sample */
    int n;
    const float *cnt;             /* per-pixel sample counts, NULL = the whole kernel */
    float *out;
    int w, h;
    float f, cx, cy;              /* projection of this resolution */
};

/* Per-pixel values of one chunk, structure of arrays. A sample s of pixel P lands at
   S = P + r (T s.x + B s.y + N s.z); its projection u = cx + f S.x / -S.z is
   (f S.x + cx Z) / Z with Z = -S.z, and numerator and Z are affine in s. So each pixel
   keeps three 4-vectors of coefficients and a sample costs three dot products and one
   division. */
struct chunk {
    float nx[CHUNK], ny[CHUNK], nz[CHUNK]; /* unit normal (scratch of the setup) */
    float co[CHUNK], si[CHUNK];            /* rotation of the tile (scratch) */
    float dl[CHUNK];                       /* the tile's length offset, 0 without */
    float dk[CHUNK];                       /* the tile's sample index shift, 0 without */
    float gs[CHUNK];                       /* per sample: its length shift's factor */
    float px[CHUNK], py[CHUNK], pz[CHUNK]; /* P (scratch) */
    float cu[4][CHUNK];                    /* u * Z = cu0 + cu1 s.x + cu2 s.y + cu3 s.z */
    float cv[4][CHUNK];                    /* v * Z, likewise */
    float cz[4][CHUNK];                    /* Z - bias, likewise (see sample_chunk) */
    float dp[CHUNK];                       /* depth of P */
    float rr[CHUNK];                       /* r, scene units (range check) */
    float zb[CHUNK];                       /* per sample: -S.z - bias, -1 off screen */
    int32_t idx[CHUNK];                    /* per sample: pixel S lands on */
    float d[CHUNK];                        /* per sample: scene depth there */
    int32_t far[CHUNK];                    /* per sample: occluded from beyond r */
    float occ[CHUNK];                      /* weighted occluded samples */
    int32_t fg[CHUNK];                     /* 1 = surface, 0 = background */
    float rp[CHUNK];                       /* disc: f r / depth, px per kernel unit */
    float xf[CHUNK];                       /* disc: pixel column */
    int32_t cnt[CHUNK];                    /* count input: samples n_i of the pixel */
    float icnt[CHUNK];                     /* count input: 1 / n_i */
};

/* The loads of the hemisphere mode and the tile's rotation (nodes/common/sampling.h). */
static void load_chunk(const struct job *j, struct chunk *restrict k, int y, int x0, int len)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x0;
    ssg_sampling_load(j->pos, j->nrm, j->depth, j->depth_sign, o, len, k->fg, k->nx, k->ny,
                      k->nz, k->px, k->py, k->pz, k->dp);
    ssg_sampling_rotation(j->rot, j->n, y, x0, len, k->co, k->si);
    ssg_sampling_offsets(j->off, j->n, y, x0, len, k->dl, k->dk);
}

/* The loads of the normal-free modes: every pixel with a depth is a surface, and the
   sample frame is the view axis (N = +z, so setup_chunk's T, B are x, y turned by the
   tile). */
static void load_chunk_free(const struct job *j, struct chunk *restrict k, int y, int x0,
                            int len)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x0;
    const float *restrict dpl = j->depth + o;
    const float *restrict px0 = j->pos[0] + o, *restrict py0 = j->pos[1] + o;
    const float *restrict pz0 = j->pos[2] + o;
    const float sign = j->depth_sign;
    for (int i = 0; i < len; i++) {
        float d = sign * dpl[i];
        int fg = (d > 0.0f) & (d <= 3.0e38f);
        k->fg[i] = fg;
        k->nx[i] = 0.0f;
        k->ny[i] = 0.0f;
        k->nz[i] = 1.0f;
        k->dp[i] = fg ? d : 1.0f;
        k->px[i] = px0[i];
        k->py[i] = py0[i];
        k->pz[i] = pz0[i];
        k->xf[i] = (float)(x0 + i);
    }
    ssg_sampling_rotation(j->rot, j->n, y, x0, len, k->co, k->si);
    ssg_sampling_offsets(j->off, j->n, y, x0, len, k->dl, k->dk);
}

/* Vectorised part of the setup: tangent frame (Duff et al., "Building an Orthonormal
   Basis, Revisited", JCGT 2017: T x B = N, branch-free), turned about N by the tile's
   angle (which turns the whole kernel), scaled by r and folded into the projective
   coefficients. */
static void setup_chunk(const struct job *j, struct chunk *restrict k, int len)
{
    const float f = j->f, cx = j->cx, cy = j->cy, radius = j->c->p.radius;
    const float bias = j->c->p.bias;
    const float cap = j->c->u.cap; /* r <= cap * depth */
    const int capped = j->c->u.capped;
    for (int i = 0; i < len; i++) {
        float nx = k->nx[i], ny = k->ny[i], nz = k->nz[i];
        float t[3], b[3];
        ssg_sampling_basis(nx, ny, nz, t, b);
        float t0 = t[0], t1 = t[1], t2 = t[2], b0 = b[0], b1 = b[1], b2 = b[2];
        float rcap = cap * k->dp[i];
        float r = capped & (rcap < radius) ? rcap : radius;
        float co = r * k->co[i], si = r * k->si[i];
        float tx = co * t0 + si * b0, ty = co * t1 + si * b1, tz = co * t2 + si * b2;
        float bx = co * b0 - si * t0, by = co * b1 - si * t1, bz = co * b2 - si * t2;
        float nxr = r * nx, nyr = r * ny, nzr = r * nz;
        float qx = k->px[i], qy = k->py[i], qz = -k->pz[i];
        k->cz[0][i] = qz - bias;
        k->cz[1][i] = -tz;
        k->cz[2][i] = -bz;
        k->cz[3][i] = -nzr;
        k->cu[0][i] = f * qx + cx * qz;
        k->cu[1][i] = f * tx - cx * tz;
        k->cu[2][i] = f * bx - cx * bz;
        k->cu[3][i] = f * nxr - cx * nzr;
        k->cv[0][i] = cy * qz - f * qy;
        k->cv[1][i] = -cy * tz - f * ty;
        k->cv[2][i] = -cy * bz - f * by;
        k->cv[3][i] = -cy * nzr - f * nyr;
        k->rr[i] = r;
        k->occ[i] = 0.0f;
    }
}

/* Places sample (sx, sy, sz) around every pixel of the chunk and projects it; then looks
   up the scene depth there and adds its weighted occlusion. Separate loops, because GCC
   vectorises a lookup at a computed index (an emulated gather) only when the indices
   come from memory. `range` is a constant at each call site, so each variant is its own
   straight code; selects of computed values, no conditional arithmetic. */
static inline __attribute__((always_inline)) void
place_chunk(const struct job *j, struct chunk *restrict k, int len, float sx, float sy,
            float sz, int s)
{
    if (j->off)
        ssg_sampling_place_shifted(k->cz, k->cu, k->cv, len, sx, sy, sz, s, j->lens, k->dl,
                                   k->dk, k->gs, j->c->p.bias, j->w, j->h, k->idx, k->zb);
    else
        ssg_sampling_place(k->cz, k->cu, k->cv, len, sx, sy, sz, j->c->p.bias, j->w, j->h,
                           k->idx, k->zb);
}

/* Looks up the scene depth at each sample placed in k->idx (threshold k->zb) and adds
   its weighted occlusion. */
static inline __attribute__((always_inline)) void
lookup_chunk(const struct job *j, struct chunk *restrict k, int len, int range, int counted,
             int s)
{
    const float sign = j->depth_sign;
    /* Occluders within r in depth weigh 1 in every mode (smoothstep of r / |dp - d|
       >= 1 is exactly 1), so this loop adds those; the smooth mode's division is needed
       only for the rare occluders farther away, done below when a chunk has any. */
    const float *restrict plane = j->depth;
    int far_any = 0;
    for (int i = 0; i < len; i++) {
        float d = sign * plane[k->idx[i]];
        /* d = 0 is background: infinitely far, never in front of the sample. */
        /* With counts, a lane past its n_i samples adds nothing (counted is a constant
           at each call site: without counts this is the plain test). */
        int active = counted ? s < k->cnt[i] : 1;
        int occluded = (d > 0.0f) & (d < k->zb[i]) & active;
        int near = fabsf(k->dp[i] - d) <= k->rr[i];
        int counts = range == SSG_SSAO_RANGE_NONE ? occluded : occluded & near;
        k->occ[i] += counts ? 1.0f : 0.0f;
        if (range == SSG_SSAO_RANGE_SMOOTH) {
            k->d[i] = d;
            k->far[i] = occluded & !near;
            far_any |= occluded & !near;
        }
    }
    if (range != SSG_SSAO_RANGE_SMOOTH || !far_any)
        return;
    for (int i = 0; i < len; i++) {
        /* smoothstep(0, 1, r / |dp - d|), |dp - d| > r here; the max keeps the other
           lanes' division harmless. */
        float den = fabsf(k->dp[i] - k->d[i]);
        den = den > k->rr[i] ? den : k->rr[i];
        float t = k->rr[i] / den;
        float wgt = t * t * (3.0f - 2.0f * t);
        k->occ[i] += k->far[i] ? wgt : 0.0f;
    }
}

static inline __attribute__((always_inline)) void
sample_chunk(const struct job *j, struct chunk *restrict k, int len, float sx, float sy,
             float sz, int range, int counted, int s)
{
    place_chunk(j, k, len, sx, sy, sz, s);
    lookup_chunk(j, k, len, range, counted, s);
}

/* The hot loop, compiled per instruction set (SSG_VECTOR_CLONES, vector_loops.h). */
static inline __attribute__((always_inline)) void
sample_loop(const struct job *j, struct chunk *k, int len, int used, int counted)
{
    const int count = j->count, sphere = j->c->p.mode == SSG_SSAO_MODE_SPHERE;
    const float *kx = j->kernel, *ky = kx + count, *kz = ky + count;
    for (int s = 0; s < used; s++) {
        /* The sphere mode adds each sample's point reflection (README.md), in this order. */
        for (int m = 0; m <= sphere; m++) {
            float sx = m ? -kx[s] : kx[s], sy = m ? -ky[s] : ky[s], sz = m ? -kz[s] : kz[s];
            switch (j->c->p.range_check) {
            case SSG_SSAO_RANGE_NONE:
                sample_chunk(j, k, len, sx, sy, sz, SSG_SSAO_RANGE_NONE, counted, s);
                break;
            case SSG_SSAO_RANGE_HARD:
                sample_chunk(j, k, len, sx, sy, sz, SSG_SSAO_RANGE_HARD, counted, s);
                break;
            default:
                sample_chunk(j, k, len, sx, sy, sz, SSG_SSAO_RANGE_SMOOTH, counted, s);
                break;
            }
        }
    }
}

/* Samples 0..used-1 (used: the kernel width, or the chunk's largest count). */
SSG_VECTOR_CLONES
static void sample_all(const struct job *j, struct chunk *k, int len, int used)
{
    if (j->cnt)
        sample_loop(j, k, len, used, 1);
    else
        sample_loop(j, k, len, used, 0);
}

/* Disc mode: per pixel the radius r (capped as in setup_chunk) and f r / depth, the
   screen radius of the disc. */
static void setup_disc(const struct job *j, struct chunk *restrict k, int len)
{
    const float radius = j->c->p.radius;
    const float cap = j->c->u.cap; /* r <= cap * depth */
    const int capped = j->c->u.capped;
    for (int i = 0; i < len; i++) {
        float rcap = cap * k->dp[i];
        float r = capped & (rcap < radius) ? rcap : radius;
        k->rr[i] = r;
        k->rp[i] = j->f * r / k->dp[i];
        k->occ[i] = 0.0f;
    }
}

/* Disc mode: places the depth sample at screen offset +-rp R (sx, sy) g (R the tile's
   rotation, +y up the screen, g the pixel's length shift of sample s, exactly 1 without
   one: ssg_sampling_shift_factor), rounded to whole pixels (ties to even, so the two signs stay exact
   opposites); it occludes when its depth is below depth(P) - bias. */
static inline __attribute__((always_inline)) void
place_disc(const struct job *j, struct chunk *restrict k, int len, float y, float sx,
           float sy, int s, float sign)
{
    const float bias = j->c->p.bias;
    const float fw = (float)j->w, fh = (float)j->h;
    const int w = j->w;
    ssg_sampling_shift_factors(len, s, j->lens, k->dl, k->dk, k->gs);
    for (int i = 0; i < len; i++) {
        float g = k->gs[i];
        float gx = sx * g, gy = sy * g;
        float ou = nearbyintf(k->rp[i] * (k->co[i] * gx - k->si[i] * gy));
        float ov = nearbyintf(k->rp[i] * (k->si[i] * gx + k->co[i] * gy));
        float u = k->xf[i] + sign * ou, v = y - sign * ov;
        int ok = (u >= 0.0f) & (u < fw) & (v >= 0.0f) & (v < fh);
        float us = ok ? u : 0.0f, vs = ok ? v : 0.0f;
        k->idx[i] = (int)vs * w + (int)us;
        k->zb[i] = ok ? k->dp[i] - bias : -1.0f;
    }
}

/* Disc mode: every kernel sample's offset and its opposite. */
static inline __attribute__((always_inline)) void
disc_loop(const struct job *j, struct chunk *k, int len, int y, int used, int counted)
{
    const int count = j->count;
    const float *kx = j->kernel, *ky = kx + count;
    for (int s = 0; s < used; s++)
        for (int m = 0; m < 2; m++) {
            place_disc(j, k, len, (float)y, kx[s], ky[s], s, m ? -1.0f : 1.0f);
            switch (j->c->p.range_check) {
            case SSG_SSAO_RANGE_NONE:
                lookup_chunk(j, k, len, SSG_SSAO_RANGE_NONE, counted, s);
                break;
            case SSG_SSAO_RANGE_HARD:
                lookup_chunk(j, k, len, SSG_SSAO_RANGE_HARD, counted, s);
                break;
            default:
                lookup_chunk(j, k, len, SSG_SSAO_RANGE_SMOOTH, counted, s);
                break;
            }
        }
}

SSG_VECTOR_CLONES
static void sample_disc(const struct job *j, struct chunk *k, int len, int y, int used)
{
    if (j->cnt)
        disc_loop(j, k, len, y, used, 1);
    else
        disc_loop(j, k, len, y, used, 0);
}

/* The count input for the chunk's pixels: n_i = round(count) (half up) clamped to
   [1, K], NaN = K (selects only, so the loop vectorises), and 1 / n_i. Returns the
   largest n_i among the surface pixels (at least 1): the samples the chunk must run. */
static int load_counts(const struct job *j, struct chunk *restrict k, int y, int x0,
                       int len)
{
    const float *restrict c = j->cnt + (size_t)y * (size_t)j->w + (size_t)x0;
    int most = 1;
    for (int i = 0; i < len; i++) {
        int n = ssg_sampling_count(c[i], j->count);
        k->cnt[i] = n;
        k->icnt[i] = 1.0f / (float)n;
        most = k->fg[i] && n > most ? n : most;
    }
    return most;
}

/* out = (1 - occluded / count)^power, or for the normal-free modes, whose 2 count
   samples leave half of them occluded on an open plane, clamp(2 (1 - occluded /
   (2 count)), 0, 1)^power = clamp(2 - occluded / count, 0, 1)^power (README.md). */
static void finish_chunk(const struct job *j, struct chunk *k, int len, float *out)
{
    const float inv_count = j->c->u.inv_samples, power = j->c->p.power;
    /* Without counts every lane divides by K: the same bits as before counts existed. */
    for (int i = 0; !j->cnt && i < len; i++)
        k->icnt[i] = inv_count;
    if (j->c->p.mode == SSG_SSAO_MODE_HEMISPHERE) {
        for (int i = 0; i < len; i++) {
            float v = 1.0f - k->occ[i] * k->icnt[i];
            v = v > 0.0f ? v : 0.0f;
            out[i] = k->fg[i] ? v : 1.0f;
        }
    } else {
        for (int i = 0; i < len; i++) {
            float v = 2.0f - k->occ[i] * k->icnt[i];
            v = v > 0.0f ? v : 0.0f;
            v = v < 1.0f ? v : 1.0f;
            out[i] = k->fg[i] ? v : 1.0f;
        }
    }
    if (power != 1.0f)
        for (int i = 0; i < len; i++)
            out[i] = powf(out[i], power);
}

/* Chunk columns outside, rows inside: the rows of one band sample nearly the same part
   of the depth plane (a disc of the projected radius around the chunk), which then stays
   in cache from one row to the next. */
static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    for (int x0 = 0; x0 < j->w; x0 += CHUNK) {
        int len = j->w - x0 < CHUNK ? j->w - x0 : CHUNK;
        for (int y = y0; y < y1; y++) {
            if (j->c->p.mode == SSG_SSAO_MODE_DISC) {
                load_chunk_free(j, &k, y, x0, len);
                setup_disc(j, &k, len);
                int used = j->cnt ? load_counts(j, &k, y, x0, len) : j->count;
                sample_disc(j, &k, len, y, used);
            } else {
                if (j->c->p.mode == SSG_SSAO_MODE_SPHERE)
                    load_chunk_free(j, &k, y, x0, len);
                else
                    load_chunk(j, &k, y, x0, len);
                setup_chunk(j, &k, len);
                int used = j->cnt ? load_counts(j, &k, y, x0, len) : j->count;
                sample_all(j, &k, len, used);
            }
            finish_chunk(j, &k, len, j->out + (size_t)y * (size_t)j->w + (size_t)x0);
        }
    }
}

enum ssg_err ssg_ssao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_ssao_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_SSAO_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_SSAO_IN_NORMAL];
    const struct ssg_image *ker = io->in[SSG_SSAO_IN_KERNEL];
    const struct ssg_image *rot = io->in[SSG_SSAO_IN_ROTATION];
    const struct ssg_image *dep = io->in[SSG_SSAO_IN_DEPTH];
    struct job j = {.c = c, .kernel = ker->data, .count = ker->width, .out = io->out[0]->data,
                    .w = pos->width, .h = pos->height};
    for (int ch = 0; ch < 3; ch++) {
        j.pos[ch] = ssg_image_plane(pos, ch);
        j.nrm[ch] = nrm ? ssg_image_plane(nrm, ch) : NULL;
    }
    j.depth = dep ? dep->data : j.pos[2];
    j.depth_sign = dep ? 1.0f : -1.0f;
    j.rot = rot ? rot->data : NULL;
    j.off = ssg_sampling_offset_plane(rot);
    j.n = rot ? rot->width : 1;
    j.cnt = io->in[SSG_SSAO_IN_COUNT] ? io->in[SSG_SSAO_IN_COUNT]->data : NULL;
    j.f = c->u.proj.f;
    j.cx = c->u.proj.cx;
    j.cy = c->u.proj.cy;
    float *lens = malloc(sizeof(float) * 2 * (size_t)j.count);
    if (!lens)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the kernel's lengths");
    ssg_sampling_lengths(j.kernel, j.count, lens);
    j.lens = lens;
    ssg_parallel_rows(j.h, ROWS_PER_BAND, band, &j);
    free(lens);
    return SSG_OK;
}
