/* hbao_cpu.c - CPU kernel of the `hbao` node (method and geometry in README.md): the march
 * and its entry point; the image checks, pattern and column tables and the padded depth it
 * reads are prepared in hbao_pattern.c (the job they share: hbao_cpu.h).
 *
 * Layout for speed, as in ssao_cpu.c. A row is cut into chunks of CHUNK pixels whose
 * surface pixels are packed into the first lanes (background costs nothing); per chunk,
 * what depends on the pixel only (V, the azimuth basis, the march length) is set up once
 * in structure-of-arrays scratch, then per pair of opposite directions D, -D what
 * depends on the azimuth (screen step, slice coefficients, tangents; -D reuses D's
 * work), then per step two straight loops over the chunk: one places the samples and
 * computes their pixel indices, one reads the depth there (the only gather) and updates
 * the horizon. Both vectorise (SSE4, AVX2 or AVX-512 through run-time selected clones).
 *
 * Cost per sample is kept to a few multiplies and compares:
 * - Points come from the depth: Q = dq (a_u, a_v, -1), a_u = (u + 0.5 - cx) / f,
 *   a_v = -(v + 0.5 - cy) / f. With V = -(a_u, a_v, -1) / L (L = |(a_u, a_v, -1)|) and D
 *   perpendicular to V, a sample at pixel offset (ou, ov) from P gives
 *     H.V = dq (ou Vx - ov Vy) / f - L (dq - dp),   H.D = dq (ou Dx - ov Dy) / f,
 *   since P.V = -L dp and P.D = 0; exactly 0 on P's own pixel. Both are affine in dq,
 *   and so is the projection of place_step: per sample H'.V = dq a + L dp, H'.D = dq b.
 * - With falloff none, sines are compared as hv |hv| bq > bv |bv| q (no root, no
 *   division) and the horizon's sine is taken once per direction; the linear falloff
 *   weighs each raising sample by its own distance, which costs a root and a division.
 * - The depth is copied once into a plane padded by one pixel, where background, garbage
 *   and the border hold +inf: samples off screen are clamped into the border, and an
 *   infinite depth makes q inf or NaN, which fails q <= R^2: no other test is needed.
 * - The march is not normalised per direction (setup_direction).
 * Per-pixel counts of directions (the `count` input, README.md): a chunk marches only the
 * directions some lane needs; a lane's direction past its count starts with its horizon
 * at +inf, so no sample raises it (no term in the linear falloff), and finish_direction
 * adds 0 for it. Adding 0 leaves a sum's bits unchanged, and the division is by n_i,
 * so count = directions gives the bits of the path without the input, which stays as it
 * was (`counted` is a constant at each call site).
 * Bands of 32 rows go to ssg_parallel_rows, chunk columns outside and rows inside, so the
 * depth window around a chunk (the march reaches ~150-300 px at 1080p, more than L2
 * holds) slides down one row at a time: taller bands refill it from L3 less often. Each
 * pixel depends only on the inputs and every per-pixel sum runs in a fixed order, so
 * the output does not depend on the thread count (no reassociation); the FMA clones round
 * a little differently from the baseline's (vector_loops.h). */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/sampling.h"
#include "hbao_cpu.h"

enum { CHUNK = 128, ROWS_PER_BAND = 32 };

/* A slice whose plane lies within asin(0.1) ~ 5.7 degrees of the tangent plane
   (|N projected on it|^2 = (V.N)^2 + (D.N)^2 < SLICE_MIN) has no well-conditioned tangent
   line: the correction of place_step would divide float noise by ~0, and the band
   between tangent and horizon is a sliver. Such slices add nothing. They exist only
   where V.N < 0.1, i.e. on surfaces seen within 6 degrees of grazing. */
#define SLICE_MIN 0.01f

/* Per-lane values of one chunk, structure of arrays; a lane is a surface pixel (xs).
   Directions come in opposite pairs D, -D (k and k + directions / 2); the arrays
   [2][CHUNK] hold one row per member. */
struct chunk {
    /* per lane; every array starts on a cache line (CHUNK floats are whole lines), so
       vector loads never straddle two */
    _Alignas(64) float dp[CHUNK];          /* depth of P */
    float nx[CHUNK], ny[CHUNK], nz[CHUNK]; /* unit normal */
    float co[CHUNK], si[CHUNK];            /* rotation of the tile */
    float u[CHUNK];                        /* step jitter in (0, 1] */
    float lp[CHUNK];                       /* L = |P| / depth */
    float ldp[CHUNK];                      /* L dp = |P| */
    float vxf[CHUNK], vyf[CHUNK];          /* Vx / f, -Vy / f */
    float e1x[CHUNK], e1z[CHUNK];          /* e1 = (e1x, 0, e1z) */
    float e2[3][CHUNK];                    /* e2 = V x e1 */
    float e1n[CHUNK], e2n[CHUNK];          /* e1.N, e2.N */
    float au[CHUNK], av[CHUNK];            /* a_u, a_v of P's pixel */
    float vn[CHUNK];                       /* V.N, floored at 1e-6 */
    float step[CHUNK];                     /* march length / steps, px */
    float xf[CHUNK];                       /* pixel column */
    int32_t fg[CHUNK];                     /* by column: 1 = surface, 0 = background */
    int32_t xs[CHUNK];                     /* column within the chunk of each lane */
    float occ[CHUNK];                      /* sum of horizon terms over directions */
    int32_t cnt[CHUNK];                    /* count input: directions n_i of the lane */
    /* per direction (pair) */
    float du[CHUNK], dv[CHUNK];            /* screen step of D, px per step */
    float mxf[CHUNK], myf[CHUNK];          /* Mx / f, -My / f, M = V x D: H.M = dq c,
                                              c = ou mxf + ov myf */
    float ax[CHUNK], ay[CHUNK];            /* a = ou ax + ov ay - L (place_step) */
    float bx[CHUNK], by[CHUNK];            /* b = ou bx + ov by (place_step) */
    float sin_tb[2][CHUNK];                /* falloff none: sin(t + bias), 1 past the
                                              zenith */
    float bv[2][CHUNK], bq[2][CHUNK];      /* horizon so far: falloff none: H'.V and
                                              |H'|^2 of the highest sample, (sin_tb, 1)
                                              at first; linear: bv = its sine */
    /* per sample */
    float a[2][CHUNK];                     /* H'.V = dq a + L dp; NaN for a sample
                                              rejected by place_step */
    float b[CHUNK];                        /* H'.D_m = dq b, D_m the member's
                                              direction (D or -D): one b for both */
    int32_t idx[2][CHUNK];                 /* sv pw + su for the sample's pixel (su, sv),
                                              each in [-1, size]: relative to the
                                              padded plane's pixel (0, 0) */
};

/* Loads the chunk's pixels (ssg_sampling_load: fg, the unit normal and the depth) and
   keeps only the surface ones, packed into the first lanes (xs: their columns within the
   chunk): background pixels (depth 0 or no normal) are 1 and cost nothing more, which
   matters where the scene leaves much of the frame empty. Packing moves a lane only to
   a lower one, so it runs in place. Returns the number of surface pixels. */
static inline __attribute__((always_inline)) int load_chunk(const struct job *j,
                                                            struct chunk *restrict k,
                                                            int y, int x0, int len)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x0;
    size_t po = (size_t)(y % j->n) * (size_t)j->w + (size_t)x0;
    const float *restrict rc = j->rot_c + po, *restrict rs = j->rot_s + po;
    const float *restrict ju = j->jitter + po;
    ssg_sampling_load(NULL, j->nrm, j->depth, j->depth_sign, o, len, k->fg, k->nx, k->ny,
                      k->nz, NULL, NULL, NULL, k->dp);
    int all = 1;
    for (int i = 0; i < len; i++)
        all &= k->fg[i];
    if (all) {
        /* The common case, a chunk all surface: straight vector copies. */
        for (int i = 0; i < len; i++) {
            k->xs[i] = i;
            k->xf[i] = (float)(x0 + i);
            k->co[i] = rc[i];
            k->si[i] = rs[i];
            k->u[i] = ju[i];
            k->occ[i] = 0.0f;
        }
        return len;
    }
    int m = 0;
    for (int i = 0; i < len; i++) {
        if (!k->fg[i])
            continue;
        k->xs[m] = i;
        k->nx[m] = k->nx[i];
        k->ny[m] = k->ny[i];
        k->nz[m] = k->nz[i];
        k->dp[m] = k->dp[i];
        k->xf[m] = (float)(x0 + i);
        k->co[m] = rc[i];
        k->si[m] = rs[i];
        k->u[m] = ju[i];
        k->occ[m] = 0.0f;
        m++;
    }
    return m;
}

/* What depends on the pixel only: V, the basis e1 = normalize(y x V), e2 = V x e1, the
   tangent term V.N and the march length (README.md). */
static inline __attribute__((always_inline)) void setup_chunk(const struct job *j,
                                                              struct chunk *restrict k,
                                                              int y, int x0, int len)
{
    const float invf = j->c->invf, radius = j->c->p.radius;
    const float rf = j->c->u.rf, cap = j->c->p.max_screen_radius;
    const float inv_steps = j->c->u.inv_steps;
    const float av = -((float)y + 0.5f - j->cy) * invf;
    for (int i = 0; i < len; i++) {
        float au = (k->xf[i] + 0.5f - j->cx) * invf;
        float l = sqrtf(au * au + av * av + 1.0f);
        /* One division for 1 / l and 1 / den (den: the march's nearest depth). */
        float d = k->dp[i], near = d - radius, half = 0.5f * d;
        float den = near > half ? near : half;
        float inv = 1.0f / (l * den);
        float il = den * inv;
        float vx = -au * il, vy = -av * il, vz = il;
        float e1x = j->e1x[x0 + k->xs[i]], e1z = j->e1z[x0 + k->xs[i]];
        k->e1x[i] = e1x;
        k->e1z[i] = e1z;
        k->e2[0][i] = vy * e1z;
        k->e2[1][i] = vz * e1x - vx * e1z;
        k->e2[2][i] = -vy * e1x;
        k->au[i] = au;
        k->av[i] = av;
        k->lp[i] = l;
        k->ldp[i] = l * k->dp[i];
        k->vxf[i] = vx * invf;
        k->vyf[i] = -vy * invf;
        float vn = vx * k->nx[i] + vy * k->ny[i] + vz * k->nz[i];
        k->vn[i] = vn > 1e-6f ? vn : 1e-6f;
        k->e1n[i] = e1x * k->nx[i] + e1z * k->nz[i];
        k->e2n[i] = k->e2[0][i] * k->nx[i] + k->e2[1][i] * k->ny[i] + k->e2[2][i] * k->nz[i];
        /* f R / den: the march along D reaches f R |J D| / den (setup_direction). */
        float rp = rf * l * inv;
        rp = cap > 0.0f && rp > cap ? cap : rp;
        k->step[i] = rp * inv_steps;
    }
}

/* Azimuth theta = 2 pi kd / directions + psi: the slice direction D, its screen step,
   and the starting horizons sin(t + bias) of D and of -D (1 when t + bias passes the
   zenith; for -D, sin t changes sign and cos t does not). The screen direction
   (su, sv) = (Dx + a_u Dz, -(Dy + a_v Dz)) is J D up to the factor f / depth and is not
   normalised: `steps` steps of step (su, sv), step = f R / (den steps), reach
   f R |(su, sv)| / den, which is exactly the bound of README.md for this slice. */
static inline __attribute__((always_inline)) void
setup_direction(const struct job *j, struct chunk *restrict k, int len, float dc, float ds,
                int linear)
{
    const float invf = j->c->invf, cb = j->c->u.cos_bias, sb = j->c->u.sin_bias;
    for (int i = 0; i < len; i++) {
        float c = dc * k->co[i] - ds * k->si[i], s = ds * k->co[i] + dc * k->si[i];
        float dx = c * k->e1x[i] + s * k->e2[0][i];
        float dy = s * k->e2[1][i];
        float dz = c * k->e1z[i] + s * k->e2[2][i];
        k->du[i] = (dx + k->au[i] * dz) * k->step[i];
        k->dv[i] = -(dy + k->av[i] * dz) * k->step[i];
        /* M = V x D = c e2 - s e1 (V x e1 = e2, V x e2 = -e1); N's components on the
           rotated basis come from those on e1, e2. */
        float mx = c * k->e2[0][i] - s * k->e1x[i], my = c * k->e2[1][i];
        float dn = c * k->e1n[i] + s * k->e2n[i], mn = c * k->e2n[i] - s * k->e1n[i];
        float vn = k->vn[i];
        float sl = vn * vn + dn * dn; /* = 1 - mn^2, |N projected on the slice|^2 > 0 */
        float ir = 1.0f / sqrtf(sl);
        /* mn / sl; huge only in the slices disabled below, whose samples it then
           rejects (q > R^2, or NaN). */
        float isl = mn * ir * ir;
        /* The projection along the tangent plane (place_step), folded in. */
        float mxf = mx * invf, myf = -my * invf, al = isl * vn, be = isl * dn;
        k->mxf[i] = mxf;
        k->myf[i] = myf;
        k->ax[i] = k->vxf[i] + mxf * al;
        k->ay[i] = k->vyf[i] + myf * al;
        k->bx[i] = dx * invf + mxf * be;
        k->by[i] = -dy * invf + myf * be;
        float st = -dn * ir, ct = vn * ir;
        float stb = st * cb + ct * sb, ctb = ct * cb - st * sb;
        float stb2 = ct * sb - st * cb, ctb2 = ct * cb + st * sb;
        /* Past the zenith, or a slice too close to the tangent plane (below): no term. */
        stb = (ctb < 0.0f) | (sl < SLICE_MIN) ? 1.0f : stb;
        stb2 = (ctb2 < 0.0f) | (sl < SLICE_MIN) ? 1.0f : stb2;
        k->bv[0][i] = stb;
        k->bv[1][i] = stb2;
        if (!linear) {
            k->sin_tb[0][i] = stb;
            k->sin_tb[1][i] = stb2;
            k->bq[0][i] = 1.0f;
            k->bq[1][i] = 1.0f;
        }
    }
}

/* Places step jf of D, and of -D when `pair`, for the whole chunk: the sample lies at
   (jf + u) step along the screen direction, rounded to the nearest pixel (ties to even),
   and what does not depend on its depth is folded into a and b.
   The rounding moves a sample off the slice by hm = H.M (at most half a pixel); it is
   brought back onto the slice along the tangent plane, not orthogonally:
   H' = H - hm M' / (M'.M) with M' = M - (M.N) N, so H'.V = H.V + hm al and
   H'.D = H.D + hm be, al = mn vn / (1 - mn^2), be = mn dn / (1 - mn^2) (mn = M.N,
   1 - mn^2 = vn^2 + dn^2). A sample of the tangent plane thus lands on the slice's
   tangent line, and a flat surface stays exactly unoccluded whatever the rounding.
   hm = dq (ou Mx - ov My) / f is linear in dq like H.D, so the correction folds into
   the per-direction coefficients ax, ay, bx, by (setup_direction).
   A sample that the rounding put more off the slice than forward along it
   (|H.M| >= H'.D) says nothing about this half of the slice, and its H' would be noise:
   since H'.D = dq b and H.M = dq c share the factor dq > 0 the test is b > |c|, and a
   NaN in a rejects the sample. That happens within a pixel or two of P, mostly on
   surfaces seen at a grazing angle, and for an occluder so nearly straight above P that
   its forward offset is below the rounding's.
   -D's sample is the point reflection: rint is odd (ties to even), so its offset is
   (-ou, -ov), its a is -(p + L) where D's is p - L, and its b and c, both odd in the
   offset and in the direction, equal D's: one b serves both. */
static inline __attribute__((always_inline)) void
place_step(const struct job *j, struct chunk *restrict k, int len, int pair, float y,
           float jf)
{
    const float fw = (float)j->w, fh = (float)j->h;
    const int pw = j->pw;
    int32_t *restrict i0 = k->idx[0], *restrict i1 = k->idx[1];
    float *restrict a0 = k->a[0], *restrict a1 = k->a[1], *restrict kb = k->b;
    for (int i = 0; i < len; i++) {
        float t = jf + k->u[i];
        float ou = nearbyintf(k->du[i] * t), ov = nearbyintf(k->dv[i] * t);
        float pa = ou * k->ax[i] + ov * k->ay[i];
        float b = ou * k->bx[i] + ov * k->by[i];
        float c = ou * k->mxf[i] + ov * k->myf[i];
        int ok = b > fabsf(c);
        kb[i] = b;
        i0[i] = ssg_sampling_padded_index(k->xf[i], y, ou, ov, fw, fh, pw);
        a0[i] = ok ? pa - k->lp[i] : __builtin_nanf("");
        if (pair) {
            i1[i] = ssg_sampling_padded_index(k->xf[i], y, -ou, -ov, fw, fh, pw);
            a1[i] = ok ? -(pa + k->lp[i]) : __builtin_nanf("");
        }
    }
}

/* Reads the depth at a sample and raises the horizon (bv, bq) when the sample is within
   R and higher. With falloff none only the final horizon matters (the terms telescope,
   finish_direction adds it), and sines are compared without a root or a division:
   hv / sqrt(q) > bv / sqrt(bq) exactly when hv |hv| bq > bv |bv| q (q, bq > 0). With the
   linear falloff each raising sample adds (sin h_j - sin h_{j-1}) (1 - r_j / R) at once
   (bv then holds sin h directly and bq is unused): a root and a division per sample. */
static inline __attribute__((always_inline)) void
horizon_one(float dq, float a, float b, float ldp, float r2, float inv_radius, int linear,
            float *bvp, float *bqp, float *occ)
{
    float hv = dq * a + ldp;
    float hd = dq * b;
    float q = hv * hv + hd * hd;
    float bv = *bvp;
    /* Background, garbage and off-screen samples read +inf, which makes q inf or NaN,
       and samples rejected by place_step carry a NaN: no occluder. P's own pixel gives
       q = 0 (and sh NaN): never higher. */
    int in = q <= r2;
    if (linear) {
        float r = sqrtf(q);
        float sh = hv / r;
        int take = in & (sh > bv);
        float gain = (sh - bv) * (1.0f - r * inv_radius);
        gain = take ? gain : 0.0f;
        *occ += gain;
        *bvp = take ? sh : bv;
    } else {
        float bq = *bqp;
        int take = in & (hv * fabsf(hv) * bq > bv * fabsf(bv) * q);
        *bvp = take ? hv : bv;
        *bqp = take ? q : bq;
    }
}

static inline __attribute__((always_inline)) void
horizon_step(const struct job *j, struct chunk *restrict k, int len, int pair, int linear)
{
    /* Index (v, u) of the padded plane is pixel (v - 1, u - 1): base it one row and one
       column in, so sample (su, sv) reads at sv * pw + su. */
    const float *restrict plane = j->padded + j->pw + 1;
    const float r2 = j->c->u.r2, inv_radius = j->c->u.inv_radius;
    const int32_t *restrict i0 = k->idx[0], *restrict i1 = k->idx[1];
    float *restrict v0 = k->bv[0], *restrict v1 = k->bv[1];
    float *restrict q0 = k->bq[0], *restrict q1 = k->bq[1];
    float *restrict occ = k->occ;
    for (int i = 0; i < len; i++) {
        horizon_one(plane[i0[i]], k->a[0][i], k->b[i], k->ldp[i], r2, inv_radius, linear,
                    &v0[i], &q0[i], &occ[i]);
        if (pair)
            horizon_one(plane[i1[i]], k->a[1][i], k->b[i], k->ldp[i], r2, inv_radius,
                        linear, &v1[i], &q1[i], &occ[i]);
    }
}

/* Falloff none: eq. 3.2 for one azimuth, sin h - sin(t + bias) for the final horizon;
   exactly 0 when no sample rose above the tangent (then bv = sin(t + bias) and
   r = sqrt(1) = 1). */
static inline __attribute__((always_inline)) void
finish_direction(struct chunk *restrict k, int len, int m, int counted, int rank)
{
    for (int i = 0; i < len; i++) {
        float g = k->bv[m][i] / sqrtf(k->bq[m][i]) - k->sin_tb[m][i];
        int add = g > 0.0f;
        if (counted)
            add &= rank < k->cnt[i]; /* a direction past the count: its bv is +inf */
        k->occ[i] += add ? g : 0.0f;
    }
}

/* Count input: member m's direction (place `rank` in the order of README.md) is beyond the
   lanes' counts where rank >= n_i; there its horizon starts at +inf, which no sample
   rises above (the comparisons of horizon_one are false for it, and its gain is selected
   away). */
static inline __attribute__((always_inline)) void
mask_direction(struct chunk *restrict k, int len, int m, int rank)
{
    for (int i = 0; i < len; i++)
        k->bv[m][i] = rank < k->cnt[i] ? k->bv[m][i] : INFINITY;
}

/* The count input for the chunk's m surface lanes (columns xs): n_i = round(count) (half
   up) clamped to [1, directions], NaN = all. Returns the largest (at least 1). */
static int load_counts(const struct job *j, struct chunk *restrict k, int y, int x0, int m)
{
    const float *c = j->cnt + (size_t)y * (size_t)j->w + (size_t)x0;
    const int nd = j->c->p.directions;
    int most = 1;
    for (int i = 0; i < m; i++) {
        int n = ssg_sampling_count(c[k->xs[i]], nd);
        k->cnt[i] = n;
        most = n > most ? n : most;
    }
    return most;
}

/* One slice direction, or an opposite pair of them. `pair` and `linear` are constants
   at each call site, so each variant is its own straight code. */
static inline __attribute__((always_inline)) void
march(const struct job *j, struct chunk *restrict k, int len, float y, int d, int pair,
      int linear, int counted)
{
    const struct ssg_hbao_consts *c = j->c;
    const int r0 = c->dir_rank[d], r1 = pair ? c->dir_rank[d + c->p.directions / 2] : 0;
    setup_direction(j, k, len, c->dir_cos[d], c->dir_sin[d], linear);
    if (counted)
        mask_direction(k, len, 0, r0);
    if (counted && pair)
        mask_direction(k, len, 1, r1);
    for (int s = 0; s < c->p.steps; s++) {
        place_step(j, k, len, pair, y, (float)s);
        horizon_step(j, k, len, pair, linear);
    }
    if (!linear)
        finish_direction(k, len, 0, counted, r0);
    if (!linear && pair)
        finish_direction(k, len, 1, counted, r1);
}

static inline __attribute__((always_inline)) void
finish_chunk(const struct job *j, const struct chunk *restrict k, int len, int m, float *out,
             int counted)
{
    const float strength = j->c->p.strength;
    const float scale = j->c->u.scale;
    for (int i = 0; i < len; i++)
        out[i] = 1.0f;
    for (int i = 0; i < m; i++) {
        float sc = counted ? strength / (float)k->cnt[i] : scale;
        float v = 1.0f - k->occ[i] * sc;
        v = v > 0.0f ? v : 0.0f;
        out[k->xs[i]] = v < 1.0f ? v : 1.0f;
    }
}

/* One row of one chunk: the hot code, compiled per instruction set (SSG_VECTOR_CLONES).
   With an even number of directions, k and k + directions / 2 are opposite (theta + pi)
   and go as pairs; their terms are added in the order k, k + directions / 2. */
static inline __attribute__((always_inline)) void
chunk_body(const struct job *j, struct chunk *k, int y, int x0, int len, int counted)
{
    const int nd = j->c->p.directions;
    const int linear = j->c->p.falloff == SSG_HBAO_FALLOFF_LINEAR;
    const int *rank = j->c->dir_rank;
    const int m = load_chunk(j, k, y, x0, len);
    /* With counts, directions (pairs: both members) beyond every lane's count are
       skipped; a skipped one adds nothing to any lane anyway. */
    const int most = counted ? load_counts(j, k, y, x0, m) : nd;
    setup_chunk(j, k, y, x0, m);
    for (int d = 0; nd % 2 == 0 && d < nd / 2; d++) {
        if (counted && rank[d] >= most && rank[d + nd / 2] >= most)
            continue;
        if (linear)
            march(j, k, m, (float)y, d, 1, 1, counted);
        else
            march(j, k, m, (float)y, d, 1, 0, counted);
    }
    for (int d = 0; nd % 2 == 1 && d < nd; d++) {
        if (counted && rank[d] >= most)
            continue;
        if (linear)
            march(j, k, m, (float)y, d, 0, 1, counted);
        else
            march(j, k, m, (float)y, d, 0, 0, counted);
    }
    finish_chunk(j, k, len, m, j->out + (size_t)y * (size_t)j->w + (size_t)x0, counted);
}

SSG_VECTOR_CLONES
static void hbao_chunk_row(const struct job *j, struct chunk *k, int y, int x0, int len)
{
    if (j->cnt)
        chunk_body(j, k, y, x0, len, 1);
    else
        chunk_body(j, k, y, x0, len, 0);
}

/* Chunk columns outside, rows inside: the rows of one band sample nearly the same part
   of the depth plane, which then stays in cache from one row to the next. */
static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    for (int x0 = 0; x0 < j->w; x0 += CHUNK) {
        int len = j->w - x0 < CHUNK ? j->w - x0 : CHUNK;
        for (int y = y0; y < y1; y++)
            hbao_chunk_row(j, &k, y, x0, len);
    }
}


enum ssg_err ssg_hbao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_hbao_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_HBAO_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_HBAO_IN_NORMAL];
    const struct ssg_image *rot = io->in[SSG_HBAO_IN_ROTATION];
    const struct ssg_image *dep = io->in[SSG_HBAO_IN_DEPTH];
    struct job j = {.c = c, .out = io->out[0]->data, .w = pos->width, .h = pos->height};
    j.cnt = io->in[SSG_HBAO_IN_COUNT] ? io->in[SSG_HBAO_IN_COUNT]->data : NULL;
    for (int ch = 0; ch < 3; ch++)
        j.nrm[ch] = ssg_image_plane(nrm, ch);
    j.depth = dep ? dep->data : ssg_image_plane(pos, 2);
    j.depth_sign = dep ? 1.0f : -1.0f;
    j.f = c->proj.f;
    j.cx = c->proj.cx;
    j.cy = c->proj.cy;
    j.e1x = c->e1;
    j.e1z = c->e1 + j.w;
    float *tables = ssg_hbao_pattern_unroll(rot, j.w, &j);
    if (!tables)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the pattern tables");
    j.pw = j.w + 2;
    /* the node's scratch (node.h): kept between frames, no fresh pages each run */
    j.padded = ssg_node_scratch(ctx, (size_t)j.pw * (size_t)(j.h + 2) * sizeof *j.padded);
    if (!j.padded) {
        free(tables);
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the padded depth");
    }
    float *last = j.padded + (size_t)(j.h + 1) * (size_t)j.pw;
    for (int x = 0; x < j.pw; x++)
        j.padded[x] = last[x] = INFINITY;
    ssg_parallel_rows(j.h, ROWS_PER_BAND, ssg_hbao_rows_pad, &j);
    ssg_parallel_rows(j.h, ROWS_PER_BAND, band, &j);
    free(tables);
    return SSG_OK;
}
