/* gtao_cpu.c - CPU kernel of the `gtao` node (method and geometry in README.md).
 *
 * Layout for speed, as in hbao_cpu.c: a row is cut into chunks of CHUNK pixels held in
 * structure-of-arrays scratch; per chunk, what depends on the pixel only (V, the basis,
 * the march length, the jitter) is set up once, then per slice what depends on its
 * direction (D, M, the screen step, the coefficients of the sample formulas), then per
 * step two straight loops over the chunk: one places the samples of both sides and
 * computes their pixel indices, one reads the depth there (the only gather) and updates
 * both horizons (with the back input also each side's bottom, horizon_back, from a second
 * padded plane at the same index). A last loop per slice turns them into its terms. Every
 * loop vectorises (SSE4, AVX2 or AVX-512 through run-time selected clones): selects, no
 * branches, and no libm call but sqrtf (-fno-math-errno) and floorf / nearbyintf.
 *
 * Per sample, as in hbao_cpu.c, everything but the depth dq is folded into per-step
 * coefficients: with Q = dq (a_u', a_v', -1) the sample's point and P = dp (a_u, a_v, -1),
 * H = Q - P has, for the offset (ou, ov) (px; -D's sample is at (-ou, -ov)),
 *   H.V = dq (ou Vx - ov Vy) / f - L (dq - dp),  H.D = dq (ou Dx - ov Dy) / f,
 *   H.M = dq (ou Mx - ov My) / f          (L = |P| / dp, V.D = V.M = 0),
 * all affine in dq; so are the components of H' (the sample brought back onto the slice
 * along the tangent plane, README.md): H'.V = dq a + L dp, sg H'.D = dq b. |H|^2 =
 * (H.V)^2 + dq^2 ((H.D)^2 + (H.M)^2) / dq^2 (V, D, M orthonormal). The sample counts when
 * sg H'.D > |H.M|, i.e. b > |c| (dq > 0). The horizon cosine is H'.V / |H'|.
 * The slice's terms use no trigonometry but one acos per slice (its normal angle n =
 * pi/2 - acos(sin n)) and one per side with a horizon (ssg_acos, a polynomial that
 * gtao.glsl evaluates by the same operations): sin h = sg sqrt((1 - cos h)(1 + cos h)),
 * and the cosines and sines of 2h - n, h -/+ n, 3h - n by the angle-sum formulas.
 *
 * Determinism: each pixel depends only on the inputs and every per-pixel sum runs in a
 * fixed order (slices in order, the -D side's terms before +D's), whatever the chunk, the
 * band (ssg_parallel_rows' fixed bands); the FMA clones round a little differently from
 * the baseline's (vector_loops.h). gtao.glsl performs the same operations in the same
 * order (`precise`); sqrt, division, pow (power != 1) and fused multiply-adds may round
 * differently on GL. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "common/sampling.h"
#include "gtao.h"

enum { CHUNK = SSG_SAMPLING_CHUNK, ROWS_PER_BAND = 32 };

/* |proj N|^2 below this: the slice lies within asin(0.1) of the tangent plane (README.md). */
#define SLICE_MIN 0.01f
#define HALF_PI 1.57079632679489661923f
/* A side's horizon cosine within this of its lowest counts as no horizon: samples of P's
   own plane land on the tangent only up to float rounding (README.md). */
#define OPEN_EPS 1e-5f

struct job {
    const struct ssg_gtao_consts *c;
    struct ssg_gtao_frame fr;     /* this frame's slices and noise offset */
    const float *pos[3], *nrm[3]; /* planes of the G-buffer */
    const float *depth;           /* plane the depth is read from */
    float depth_sign;             /* depth = depth_sign * plane: 1 for depth, -1 for z */
    const float *rot;             /* the tile, cos plane then sin plane; NULL = none */
    int n;                        /* tile side */
    float *padded;                /* the depth padded by +inf (ssg_sampling_pad_depth) */
    const float *back;            /* the back input's plane; NULL = unconnected */
    float *padded_back;           /* back padded likewise (README.md); NULL = unconnected */
    int pw;                       /* w + 2 */
    float *out, *bent;            /* outputs; bent: three planes */
    int w, h;
};

/* Per-lane values of one chunk, structure of arrays; side m = 0 is +D, m = 1 is -D. */
struct chunk {
    /* per pixel; CHUNK floats are whole cache lines, so every array starts on one */
    _Alignas(64) float dp[CHUNK];          /* depth of P */
    float nx[CHUNK], ny[CHUNK], nz[CHUNK]; /* unit normal */
    float px[CHUNK], py[CHUNK], pz[CHUNK]; /* P (loaded by ssg_sampling_load; unused) */
    int32_t fg[CHUNK];                     /* 1 = surface, 0 = background */
    float co[CHUNK], si[CHUNK];            /* rotation of the tile */
    float xf[CHUNK];                       /* pixel column */
    float u[CHUNK];                        /* step jitter in (0, 1] */
    float lp[CHUNK], ldp[CHUNK];           /* L = |P| / dp, L dp */
    float v[3][CHUNK];                     /* V */
    float vxf[CHUNK], vyf[CHUNK];          /* Vx / f, -Vy / f */
    float e1x[CHUNK], e1z[CHUNK];          /* e1 = (e1x, 0, e1z) */
    float e2[3][CHUNK];                    /* e2 = V x e1 */
    float e1n[CHUNK], e2n[CHUNK];          /* e1.N, e2.N */
    float au[CHUNK], av[CHUNK];            /* a_u, a_v of P's pixel */
    float vn[CHUNK];                       /* V.N, floored at 1e-6 */
    float step[CHUNK];                     /* march length / steps, px */
    float vis[CHUNK], open[CHUNK];         /* sums over slices of |proj N| a, open a */
    float bsum[3][CHUNK];                  /* sum over slices of the bent-normal terms */
    /* per slice */
    float d[3][CHUNK];                     /* D */
    float du[CHUNK], dv[CHUNK];            /* screen step of D, px per step */
    float dxf[CHUNK], dyf[CHUNK];          /* Dx / f, -Dy / f */
    float mxf[CHUNK], myf[CHUNK];          /* Mx / f, -My / f */
    float ax[CHUNK], ay[CHUNK];            /* a = ou ax + ov ay -/+ L */
    float bx[CHUNK], by[CHUNK];            /* b = ou bx + ov by */
    float cn[CHUNK], sn[CHUNK], pl[CHUNK]; /* cos n, sin n, |proj N| */
    float hc[2][CHUNK], low[2][CHUNK];     /* horizon cosine so far, its lowest; the
                                              fast path: H'.V of the highest sample */
    float hq[2][CHUNK];                    /* the fast path: |H'|^2 of the highest
                                              sample (1 at first, with hc = low) */
    float bot[2][CHUNK];                   /* with back: the lowest bottom cosine of the
                                              samples that occlude (2 = none) */
    float pdep[2][CHUNK], pcos[2][CHUNK];  /* with back: depth and faded cosine of the
                                              side's last valid sample (P at first) */
    /* per step */
    float a[2][CHUNK], r[2][CHUNK];        /* H'.V = dq a + L dp, H.V = dq r + L dp */
    float b[CHUNK];                        /* sg H'.D = dq b (both sides) */
    float e[CHUNK];                        /* |H|^2 = (H.V)^2 + dq^2 e */
    int32_t ok[CHUNK];                     /* b > |c|: the sample is along the slice */
    int32_t idx[2][CHUNK];                 /* index in the padded plane */
};

/* 1 - interleaved gradient noise (Jimenez 2014) at the pixel: in (0, 1]. */
static inline __attribute__((always_inline)) float step_jitter(float x, float y)
{
    return 1.0f - ssg_ign(x, y);
}

/* What depends on the pixel only: V, e2 = V x e1, V.N, the march length (README.md). */
static inline __attribute__((always_inline)) void
setup_chunk(const struct job *j, struct chunk *restrict k, int y, int x0, int len)
{
    const struct ssg_gtao_consts *c = j->c;
    const float invf = c->invf, radius = c->p.radius, f = c->proj.f;
    const float cap = c->p.max_screen_radius, fs = (float)c->p.steps, yf = (float)y;
    const float av = -(yf + 0.5f - c->proj.cy) * invf;
    for (int i = 0; i < len; i++) {
        float xf = (float)(x0 + i);
        float au = (xf + 0.5f - c->proj.cx) * invf;
        float l = sqrtf(au * au + av * av + 1.0f), il = 1.0f / l;
        float vx = -au * il, vy = -av * il, vz = il;
        float e1x = c->e1[x0 + i], e1z = c->e1[j->w + x0 + i];
        float e2x = vy * e1z, e2y = vz * e1x - vx * e1z, e2z = -vy * e1x;
        float nx = k->nx[i], ny = k->ny[i], nz = k->nz[i], dp = k->dp[i];
        float vn = vx * nx + vy * ny + vz * nz;
        k->xf[i] = xf;
        k->au[i] = au;
        k->av[i] = av;
        k->lp[i] = l;
        k->ldp[i] = l * dp;
        k->v[0][i] = vx, k->v[1][i] = vy, k->v[2][i] = vz;
        k->vxf[i] = vx * invf;
        k->vyf[i] = -vy * invf;
        k->e1x[i] = e1x, k->e1z[i] = e1z;
        k->e2[0][i] = e2x, k->e2[1][i] = e2y, k->e2[2][i] = e2z;
        k->e1n[i] = e1x * nx + e1z * nz;
        k->e2n[i] = e2x * nx + e2y * ny + e2z * nz;
        k->vn[i] = vn > 1e-6f ? vn : 1e-6f;
        /* f R / den reaches every point of the slice within R (README.md). */
        float near = dp - radius, half = 0.5f * dp;
        float rp = f * radius / (near > half ? near : half);
        rp = cap > 0.0f && rp > cap ? cap : rp;
        k->step[i] = rp / fs;
        k->u[i] = step_jitter(xf + j->fr.shift, yf + j->fr.shift);
        k->vis[i] = k->open[i] = 0.0f;
        k->bsum[0][i] = k->bsum[1][i] = k->bsum[2][i] = 0.0f;
    }
}

/* Slice direction phi = pi kd / slices + psi: D, M = V x D (= c e2 - s e1), the normal
   projected on the slice (cos n, sin n, |proj N|), the screen step and the coefficients
   of the sample formulas, with the tangent-plane correction al, be of hbao_cpu.c's
   place_step folded in; horizons start at their lowest, cos(n -/+ pi/2). */
static inline __attribute__((always_inline)) void
setup_slice(const struct job *j, struct chunk *restrict k, int len, float dc, float ds)
{
    const float invf = j->c->invf;
    for (int i = 0; i < len; i++) {
        float cs = dc * k->co[i] - ds * k->si[i], s = ds * k->co[i] + dc * k->si[i];
        float dx = cs * k->e1x[i] + s * k->e2[0][i], dy = s * k->e2[1][i];
        float dz = cs * k->e1z[i] + s * k->e2[2][i];
        float mx = cs * k->e2[0][i] - s * k->e1x[i], my = cs * k->e2[1][i];
        float dn = cs * k->e1n[i] + s * k->e2n[i], mn = cs * k->e2n[i] - s * k->e1n[i];
        float vn = k->vn[i], sl = vn * vn + dn * dn;
        float pl = sqrtf(sl), cn = vn / pl, sn = dn / pl;
        float isl = mn / sl, al = isl * vn, be = isl * dn;
        k->d[0][i] = dx, k->d[1][i] = dy, k->d[2][i] = dz;
        k->du[i] = (dx + k->au[i] * dz) * k->step[i];
        k->dv[i] = -(dy + k->av[i] * dz) * k->step[i];
        float dxf = dx * invf, dyf = -dy * invf, mxf = mx * invf, myf = -my * invf;
        k->dxf[i] = dxf, k->dyf[i] = dyf, k->mxf[i] = mxf, k->myf[i] = myf;
        k->ax[i] = k->vxf[i] + mxf * al;
        k->ay[i] = k->vyf[i] + myf * al;
        k->bx[i] = dxf + mxf * be;
        k->by[i] = dyf + myf * be;
        /* A slice within asin(0.1) of the tangent plane adds nothing (finish_slice). */
        k->pl[i] = sl >= SLICE_MIN ? pl : 0.0f;
        k->cn[i] = cn, k->sn[i] = sn;
        k->hc[0][i] = k->low[0][i] = -sn;
        k->hc[1][i] = k->low[1][i] = sn;
        k->hq[0][i] = k->hq[1][i] = 1.0f;
        k->bot[0][i] = k->bot[1][i] = 2.0f;
        k->pdep[0][i] = k->pdep[1][i] = k->dp[i];
        k->pcos[0][i] = k->low[0][i], k->pcos[1][i] = k->low[1][i];
    }
}

/* Step s of both sides for the whole chunk: the sample lies at (s + u) step along the
   screen direction, rounded to the nearest pixel (ties to even); -D's is the point
   reflection (rint is odd), whose coefficients are D's with the signs the header gives. */
static inline __attribute__((always_inline)) void
place_step(const struct job *j, struct chunk *restrict k, int len, float y, float sf)
{
    const float fw = (float)j->w, fh = (float)j->h;
    const int pw = j->pw;
    for (int i = 0; i < len; i++) {
        float t = sf + k->u[i];
        float ou = nearbyintf(k->du[i] * t), ov = nearbyintf(k->dv[i] * t);
        float pr = ou * k->vxf[i] + ov * k->vyf[i];
        float c = ou * k->mxf[i] + ov * k->myf[i];
        float bd = ou * k->dxf[i] + ov * k->dyf[i];
        float pa = ou * k->ax[i] + ov * k->ay[i];
        float b = ou * k->bx[i] + ov * k->by[i];
        float l = k->lp[i];
        k->ok[i] = b > fabsf(c);
        k->b[i] = b;
        k->e[i] = bd * bd + c * c;
        k->a[0][i] = pa - l;
        k->a[1][i] = -(pa + l);
        k->r[0][i] = pr - l;
        k->r[1][i] = -(pr + l);
        k->idx[0][i] = ssg_sampling_padded_index(k->xf[i], y, ou, ov, fw, fh, pw);
        k->idx[1][i] = ssg_sampling_padded_index(k->xf[i], y, -ou, -ov, fw, fh, pw);
    }
}

/* One sample of one side: its horizon cosine, faded towards the lowest by its weight,
   raises the horizon, or with thickness t > 0 a lower one within reach pulls it down.
   Samples off screen, on background (+inf) or off the slice (!ok) change nothing. */
static inline __attribute__((always_inline)) float
horizon_one(float hc, float low, float dq, float a, float r, float b, float e, float ldp,
            int ok, const struct ssg_gtao_consts *c, float r2max, int linear)
{
    float hv = dq * r + ldp, pv = dq * a + ldp, pd = dq * b;
    float q = hv * hv + dq * dq * e;
    float w;
    if (linear) {
        w = sqrtf(q) * c->u.fall_mul + c->u.fall_add;
        w = w < 0.0f ? 0.0f : w;
        w = w < 1.0f ? w : 1.0f;
    } else {
        w = q <= r2max ? 1.0f : 0.0f;
    }
    float shc = pv / sqrtf(pv * pv + pd * pd);
    shc = low + w * (shc - low);
    int valid = ok & (dq < INFINITY);
    int up = valid & (shc > hc);
    int thin = valid & !(shc > hc) & (w > 0.0f) & (c->p.thickness > 0.0f);
    float pulled = hc + c->p.thickness * (shc - hc);
    return up ? shc : thin ? pulled : hc;
}

/* One sample of one side with the back input (README.md): it occludes the arc between its
   front point and its back point, the latter no farther than where the pixel's ray leaves
   the sphere of radius R about P (the larger root d of (d r + L dp)^2 + d^2 e = R^2), both
   faded towards the lowest by its weight; nothing behind (+inf) is solid down to the
   lowest. When the side's previous sample (P itself at first) lies no farther than this
   one's back, the front surface runs on from it, and the arc reaches down to it too. A
   sample whose front point rises above the tangent plane raises the side's top hc and
   lowers its bottom *bot; one on P's own plane or below changes neither. */
static inline __attribute__((always_inline)) float
horizon_back(float hc, float *bot, float *pdep, float *pcos, float low, float dq, float db,
             float a, float r, float b, float e, float ldp, int ok,
             const struct ssg_gtao_consts *c, float r2max, int linear)
{
    float hv = dq * r + ldp, pv = dq * a + ldp, pd = dq * b;
    float q = hv * hv + dq * dq * e;
    float w;
    if (linear) {
        w = sqrtf(q) * c->u.fall_mul + c->u.fall_add;
        w = w < 0.0f ? 0.0f : w;
        w = w < 1.0f ? w : 1.0f;
    } else {
        w = q <= r2max ? 1.0f : 0.0f;
    }
    float qa = r * r + e, qb = r * ldp, qc = ldp * ldp - r2max;
    float disc = qb * qb - qa * qc;
    float exit = (sqrtf(disc > 0.0f ? disc : 0.0f) - qb) / qa;
    float d = db < exit ? db : exit; /* db = +inf: the exit */
    d = d > dq ? d : dq;             /* NaN (qa = 0) too: the front point */
    float bv = d * a + ldp, bd = d * b;
    float top = pv / sqrtf(pv * pv + pd * pd), under = bv / sqrtf(bv * bv + bd * bd);
    top = low + w * (top - low);
    under = db < INFINITY ? low + w * (under - low) : low; /* none behind: solid */
    int valid = ok & (dq < INFINITY);
    under = (*pdep <= db + c->u.link) & (*pcos < under) ? *pcos : under;
    *pdep = valid ? dq : *pdep;
    *pcos = valid ? top : *pcos;
    int counts = valid & (w > 0.0f) & (top > low + OPEN_EPS);
    *bot = counts & (under < *bot) ? under : *bot;
    return counts & (top > hc) ? top : hc;
}

/* The fast path (hard cutoff, no thickness: the defaults): a side's horizon is the highest
   sample within R, and cosines are compared without a root or a division, as hbao_cpu.c
   does: pv / sqrt(q) > hv / sqrt(hq) exactly when pv |pv| hq > hv |hv| q (q, hq > 0); the
   root is taken once per slice (fast_horizons), which gives the highest sample's
   pv / sqrt(pv^2 + pd^2), the cosine the general path would keep. */
static inline __attribute__((always_inline)) void
horizon_fast(float *restrict hv, float *restrict hq, float dq, float a, float r, float b,
             float e, float ldp, int ok, float r2max)
{
    float rv = dq * r + ldp, pv = dq * a + ldp, pd = dq * b;
    float d2 = rv * rv + dq * dq * e;
    float q = pv * pv + pd * pd;
    float v = *hv, vq = *hq;
    /* +inf depth (off screen, background) makes d2 inf or NaN: not within R. */
    int up = ok & (d2 <= r2max) & (pv * fabsf(pv) * vq > v * fabsf(v) * q);
    *hv = up ? pv : v;
    *hq = up ? q : vq;
}

static inline __attribute__((always_inline)) void
horizon_step(const struct job *j, struct chunk *restrict k, int len, int linear, int fast,
             int back)
{
    /* Index (v, u) of the padded plane is pixel (v - 1, u - 1). */
    const float *restrict plane = j->padded + j->pw + 1;
    const float *restrict bplane = back ? j->padded_back + j->pw + 1 : plane;
    const float r2max = j->c->p.radius * j->c->p.radius;
    for (int i = 0; i < len; i++) {
        float d0 = plane[k->idx[0][i]], d1 = plane[k->idx[1][i]];
        if (back) {
            float b0 = bplane[k->idx[0][i]], b1 = bplane[k->idx[1][i]];
            for (int m = 0; m < 2; m++)
                k->hc[m][i] = horizon_back(k->hc[m][i], &k->bot[m][i], &k->pdep[m][i],
                                           &k->pcos[m][i], k->low[m][i], m ? d1 : d0,
                                           m ? b1 : b0, k->a[m][i], k->r[m][i], k->b[i],
                                           k->e[i], k->ldp[i], k->ok[i], j->c, r2max, linear);
            continue;
        }
        if (fast) {
            horizon_fast(&k->hc[0][i], &k->hq[0][i], d0, k->a[0][i], k->r[0][i], k->b[i],
                         k->e[i], k->ldp[i], k->ok[i], r2max);
            horizon_fast(&k->hc[1][i], &k->hq[1][i], d1, k->a[1][i], k->r[1][i], k->b[i],
                         k->e[i], k->ldp[i], k->ok[i], r2max);
            continue;
        }
        k->hc[0][i] = horizon_one(k->hc[0][i], k->low[0][i], d0, k->a[0][i], k->r[0][i],
                                  k->b[i], k->e[i], k->ldp[i], k->ok[i], j->c, r2max, linear);
        k->hc[1][i] = horizon_one(k->hc[1][i], k->low[1][i], d1, k->a[1][i], k->r[1][i],
                                  k->b[i], k->e[i], k->ldp[i], k->ok[i], j->c, r2max, linear);
    }
}

/* The fast path's horizon cosines, H'.V / |H'| of the highest samples (low / 1 = low
   where none rose). */
static inline __attribute__((always_inline)) void fast_horizons(struct chunk *restrict k,
                                                                int len)
{
    for (int i = 0; i < len; i++) {
        k->hc[0][i] = k->hc[0][i] / sqrtf(k->hq[0][i]);
        k->hc[1][i] = k->hc[1][i] / sqrtf(k->hq[1][i]);
    }
}

/* One side of a slice (sg = 1: +D, h2; sg = -1: -D, h1): its horizon angle h from V, half
   the inner integral 1/4 (cos n + 2 h sin n - cos(2 h - n)), and its share of the bent
   normal's t0 and t1 (README.md). A side without a horizon lies at the hemisphere's limit
   h = n + sg pi/2, where every term is algebraic in cos n, sin n (cos(2 h - n) = -cos n,
   sin(h - n) = sg, sin(3 h - n) = -sg cos 2n, sin(h + n) = sg cos 2n, cos(3 h - n) =
   sg sin 2n, cos(h + n) = -sg sin 2n): exactly the open value. Otherwise h = sg acos hc,
   clamped to the normal's hemisphere (sec. 4.1), and the terms come from cos h, sin h by
   the angle-sum formulas. */
struct arc {
    float a, t0, t1;
};

static inline __attribute__((always_inline)) struct arc
side_arc(float hc, float low, float sg, float n, float cn, float sn)
{
    float lim = n + sg * HALF_PI;
    float c2 = cn * cn - sn * sn, s2 = 2.0f * sn * cn;
    struct arc o = {0.25f * (cn + 2.0f * lim * sn + cn), sg * (6.0f - 2.0f * c2),
                    2.0f * sg * s2};
    float h = sg * ssg_acos(hc);
    int clamp = sg > 0.0f ? !(h < lim) : !(h > lim); /* NaN (|hc| > 1) too */
    h = clamp ? lim : h;
    float ch = clamp ? -sg * sn : hc;
    float sh = clamp ? sg * cn : sg * sqrtf((1.0f - hc) * (1.0f + hc));
    float c2h = ch * ch - sh * sh, s2h = 2.0f * sh * ch;
    float c3h = ch * c2h - sh * s2h, s3h = sh * c2h + ch * s2h;
    float sin_hmn = sh * cn - ch * sn, sin_hpn = sh * cn + ch * sn;
    float sin_3hmn = s3h * cn - c3h * sn, cos_3hmn = c3h * cn + s3h * sn;
    float cos_hpn = ch * cn - sh * sn, cos_2hmn = c2h * cn + s2h * sn;
    struct arc g = {0.25f * (cn + 2.0f * h * sn - cos_2hmn),
                    6.0f * sin_hmn - sin_3hmn - 3.0f * sin_hpn, -cos_3hmn - 3.0f * cos_hpn};
    int open = !(hc > low + OPEN_EPS);
    return (struct arc){open ? o.a : g.a, open ? o.t0 : g.t0, open ? o.t1 : g.t1};
}

/* With back, a side's occluded arc runs from its top hc down to its bottom bot (README.md):
   what is visible is the side up to hc plus the arc from bot to the hemisphere's limit,
   side(hc) + open - side(bot), each term the side's integral from 0 plus one constant.
   A bottom at (or below) the tangent plane gives open - open = 0: the plain horizon. */
static inline __attribute__((always_inline)) struct arc
side_arc_back(float hc, float bot, float low, float sg, float n, float cn, float sn)
{
    struct arc t = side_arc(hc, low, sg, n, cn, sn);
    struct arc u = side_arc(bot > 1.5f ? low : bot, low, sg, n, cn, sn);
    struct arc o = side_arc(low, low, sg, n, cn, sn);
    return (struct arc){t.a + (o.a - u.a), t.t0 + (o.t0 - u.t0), t.t1 + (o.t1 - u.t1)};
}

/* Adds the slice's |proj N| a(h1, h2, n) to vis, its open value to open and its bent
   normal term to bsum; a disabled slice (pl 0) adds 0, which leaves the sums' bits. */
static inline __attribute__((always_inline)) void finish_slice(struct chunk *restrict k,
                                                               int len, int back)
{
    for (int i = 0; i < len; i++) {
        float cn = k->cn[i], sn = k->sn[i], pl = k->pl[i];
        float n = HALF_PI - ssg_acos(sn);
        struct arc a1, a2;
        if (back) {
            a1 = side_arc_back(k->hc[1][i], k->bot[1][i], k->low[1][i], -1.0f, n, cn, sn);
            a2 = side_arc_back(k->hc[0][i], k->bot[0][i], k->low[0][i], 1.0f, n, cn, sn);
        } else {
            a1 = side_arc(k->hc[1][i], k->low[1][i], -1.0f, n, cn, sn);
            a2 = side_arc(k->hc[0][i], k->low[0][i], 1.0f, n, cn, sn);
        }
        float lim1 = n - HALF_PI, lim2 = n + HALF_PI;
        int live = pl > 0.0f;
        float vis = pl * (a1.a + a2.a);
        float open = pl * (0.25f * (cn + 2.0f * lim1 * sn + cn) +
                           0.25f * (cn + 2.0f * lim2 * sn + cn));
        k->vis[i] += live ? vis : 0.0f;
        k->open[i] += live ? open : 0.0f;
        /* Bent normal: the slice's mean direction t0 D + t1 V (XeGTAO's closed form). */
        float t0 = (a1.t0 + a2.t0 + 16.0f * sn) / 12.0f;
        float t1 = (a1.t1 + a2.t1 + 8.0f * cn) / 12.0f;
        for (int m = 0; m < 3; m++) {
            float bt = pl * (t0 * k->d[m][i] + t1 * k->v[m][i]);
            k->bsum[m][i] += live ? bt : 0.0f;
        }
    }
}

/* out = clamp(vis / open, 0, 1)^power and the normalised bent normal (no slice, all
   grazing: the normal itself); background 1 and 0. */
static inline __attribute__((always_inline)) void
finish_chunk(const struct job *j, struct chunk *restrict k, size_t o, int len)
{
    const size_t plane = (size_t)j->w * (size_t)j->h;
    const float power = j->c->p.power;
    float *restrict out = j->out + o, *restrict b0 = j->bent + o;
    float *restrict b1 = b0 + plane, *restrict b2 = b1 + plane;
    for (int i = 0; i < len; i++) {
        float v = k->open[i] > 0.0f ? k->vis[i] / k->open[i] : 1.0f;
        v = v > 0.0f ? v : 0.0f;
        out[i] = v < 1.0f ? v : 1.0f;
    }
    for (int i = 0; power != 1.0f && i < len; i++)
        out[i] = powf(out[i], power);
    for (int i = 0; i < len; i++) {
        float bx = k->bsum[0][i], by = k->bsum[1][i], bz = k->bsum[2][i];
        float bl = sqrtf(bx * bx + by * by + bz * bz);
        float ib = bl > 0.0f ? 1.0f / bl : 0.0f;
        int fg = k->fg[i], some = bl > 0.0f;
        out[i] = fg ? out[i] : 1.0f;
        b0[i] = fg ? (some ? bx * ib : k->nx[i]) : 0.0f;
        b1[i] = fg ? (some ? by * ib : k->ny[i]) : 0.0f;
        b2[i] = fg ? (some ? bz * ib : k->nz[i]) : 0.0f;
    }
}

/* One row of one chunk: the hot code, compiled per instruction set (SSG_VECTOR_CLONES).
   Background lanes are
   marched like the others with harmless values (ssg_sampling_load) and replaced at the
   end. */
static inline __attribute__((always_inline)) void
chunk_body(const struct job *j, struct chunk *restrict k, int y, int x0, int len,
           int linear, int fast, int back)
{
    const struct ssg_gtao_consts *c = j->c;
    size_t o = (size_t)y * (size_t)j->w + (size_t)x0;
    ssg_sampling_load(j->pos, j->nrm, j->depth, j->depth_sign, o, len, k->fg, k->nx, k->ny,
                      k->nz, k->px, k->py, k->pz, k->dp);
    ssg_sampling_rotation(j->rot, j->n, y, x0, len, k->co, k->si);
    setup_chunk(j, k, y, x0, len);
    for (int s = 0; s < c->p.slices; s++) {
        setup_slice(j, k, len, j->fr.slice_cos[s], j->fr.slice_sin[s]);
        for (int st = 0; st < c->p.steps; st++) {
            place_step(j, k, len, (float)y, (float)st);
            horizon_step(j, k, len, linear, fast, back);
        }
        if (fast)
            fast_horizons(k, len);
        finish_slice(k, len, back);
    }
    finish_chunk(j, k, o, len);
}

SSG_VECTOR_CLONES
static void gtao_chunk_row(const struct job *j, struct chunk *k, int y, int x0, int len)
{
    int linear = j->c->p.falloff > 0.0f;
    if (j->padded_back)
        chunk_body(j, k, y, x0, len, linear, 0, 1);
    else if (linear)
        chunk_body(j, k, y, x0, len, 1, 0, 0);
    else if (j->c->p.thickness > 0.0f)
        chunk_body(j, k, y, x0, len, 0, 0, 0);
    else
        chunk_body(j, k, y, x0, len, 0, 1, 0);
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
            gtao_chunk_row(j, &k, y, x0, len);
    }
}

static void rows_pad(void *user, int y0, int y1)
{
    const struct job *j = user;
    ssg_sampling_pad_depth(j->depth, j->depth_sign, j->w, y0, y1, j->padded);
    if (j->padded_back) /* +inf (none behind) stays +inf; background is never read */
        ssg_sampling_pad_depth(j->back, 1.0f, j->w, y0, y1, j->padded_back);
}

enum ssg_err ssg_gtao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_gtao_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_GTAO_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_GTAO_IN_NORMAL];
    const struct ssg_image *rot = io->in[SSG_GTAO_IN_ROTATION];
    const struct ssg_image *dep = io->in[SSG_GTAO_IN_DEPTH];
    struct job j = {.c = c, .w = pos->width, .h = pos->height};
    ssg_gtao_frame_of(c, ctx->frame_index, &j.fr);
    j.out = io->out[SSG_GTAO_OUT_OUT]->data;
    j.bent = io->out[SSG_GTAO_OUT_BENT_NORMAL]->data;
    for (int ch = 0; ch < 3; ch++) {
        j.pos[ch] = ssg_image_plane(pos, ch);
        j.nrm[ch] = ssg_image_plane(nrm, ch);
    }
    j.depth = dep ? dep->data : ssg_image_plane(pos, 2);
    j.depth_sign = dep ? 1.0f : -1.0f;
    j.rot = rot ? rot->data : NULL;
    j.n = rot ? rot->width : 1;
    j.pw = j.w + 2;
    const struct ssg_image *back = io->in[SSG_GTAO_IN_BACK];
    /* the node's scratch (node.h): kept between frames, no fresh pages each run; the
       padded back plane follows the padded depth */
    size_t plane = (size_t)j.pw * (size_t)(j.h + 2);
    j.padded = ssg_node_scratch(ctx, (back ? 2 : 1) * plane * sizeof *j.padded);
    if (!j.padded)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the padded depth");
    j.back = back ? back->data : NULL;
    j.padded_back = back ? j.padded + plane : NULL;
    for (int p = 0; p < (back ? 2 : 1); p++) {
        float *first = j.padded + p * plane, *last = first + (size_t)(j.h + 1) * (size_t)j.pw;
        for (int x = 0; x < j.pw; x++)
            first[x] = last[x] = INFINITY;
    }
    ssg_parallel_rows(j.h, ROWS_PER_BAND, rows_pad, &j);
    ssg_parallel_rows(j.h, ROWS_PER_BAND, band, &j);
    return SSG_OK;
}
