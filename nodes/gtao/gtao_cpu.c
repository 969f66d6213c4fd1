/* gtao_cpu.c - CPU kernel of the `gtao` node (method and geometry in README.md): its
 * integrator on the horizon march of nodes/common/horizon.h, which loads and packs the
 * chunk's surface pixels, sets up what depends on the pixel and on the slice, places the
 * samples and drives the rows.
 *
 * Layout for speed (horizon.h): per slice, per step two straight loops over the chunk:
 * one places the samples of both sides and computes their pixel indices, one reads the
 * depth there (the only gather) and updates both horizons (with the back input also each
 * side's bottom, horizon_back, from a second padded plane at the same index). A last loop
 * per slice turns them into its terms. Every loop vectorises (SSE4, AVX2 or AVX-512
 * through run-time selected clones): selects, no branches, and no libm call but sqrtf
 * (-fno-math-errno) and floorf / nearbyintf.
 *
 * Per sample everything but the depth dq is folded into per-step coefficients
 * (ssg_horizon_place): H'.V = dq a + L dp, sg H'.D = dq b (the sample brought back onto
 * the slice along the tangent plane, README.md), H.V = dq r + L dp and |H|^2 = (H.V)^2 +
 * dq^2 e; the sample counts when b > |c|. The horizon cosine is H'.V / |H'|.
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

#include "common/horizon.h"
#include "gtao.h"

enum { CHUNK = SSG_HORIZON_CHUNK };

#define HALF_PI SSG_HORIZON_HALF_PI
/* A side's horizon cosine within this of its lowest counts as no horizon: samples of P's
   own plane land on the tangent only up to float rounding (README.md). */
#define OPEN_EPS 1e-5f

struct job {
    struct ssg_horizon_run r;     /* the G-buffer and the march (horizon.h); first */
    const struct ssg_gtao_consts *c;
    struct ssg_gtao_frame fr;     /* this frame's slices and noise offset */
    const float *rot;             /* the tile, cos plane then sin plane (n x n); NULL = none */
    int n;                        /* tile side */
    float *out, *bent;            /* outputs; bent: three planes */
};

/* gtao's lanes of one chunk on horizon.h's, structure of arrays; side m = 0 is +D, m = 1
   is -D. */
struct chunk {
    struct ssg_horizon_lanes h;            /* the pixels and the slice (horizon.h) */
    float vis[CHUNK], open[CHUNK];         /* sums over slices of |proj N| a, open a */
    float bsum[3][CHUNK];                  /* sum over slices of the bent-normal terms */
    /* per slice */
    float d[3][CHUNK];                     /* D */
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
_Static_assert(sizeof(struct chunk) <= SSG_HORIZON_CHUNK_BYTES, "gtao's chunk");

/* The chunk's surface pixels (ssg_horizon_load) with the tile's rotation and the step
   jitter, 1 - interleaved gradient noise (Jimenez 2014) at the pixel, in (0, 1]; the sums
   start at 0. Returns the number of lanes. */
static inline __attribute__((always_inline)) int
load_chunk(const struct job *j, struct chunk *restrict k, int y, int x0, int len)
{
    const int m = ssg_horizon_load(&j->r, &k->h, y, x0, len);
    const float shift = j->fr.shift, yf = (float)y;
    ssg_sampling_rotation(j->rot, j->n, y, x0, len, k->h.co, k->h.si);
    for (int i = 0; i < len; i++) {
        k->h.u[i] = 1.0f - ssg_ign((float)(x0 + i) + shift, yf + shift);
        k->vis[i] = k->open[i] = 0.0f;
        k->bsum[0][i] = k->bsum[1][i] = k->bsum[2][i] = 0.0f;
    }
    ssg_horizon_pack(&k->h, m, len, k->h.co);
    ssg_horizon_pack(&k->h, m, len, k->h.si);
    ssg_horizon_pack(&k->h, m, len, k->h.u);
    return m;
}

/* Slice direction phi = pi kd / slices + psi (ssg_horizon_slice): the normal projected on
   the slice (cos n, sin n, |proj N|) and the tangent-plane correction (ssg_horizon_fold);
   horizons start at their lowest, cos(n -/+ pi/2). */
static inline __attribute__((always_inline)) void
setup_slice(const struct job *j, struct chunk *restrict k, int len, float dc, float ds)
{
    for (int i = 0; i < len; i++) {
        struct ssg_horizon_arc n = ssg_horizon_slice_arc(&k->h, i, dc, ds, j->r.invf);
        float cn = n.cn, sn = n.sn;
        k->d[0][i] = n.d.dx, k->d[1][i] = n.d.dy, k->d[2][i] = n.d.dz;
        /* A slice within asin(0.1) of the tangent plane adds nothing (finish_slice). */
        k->pl[i] = n.d.sl >= SSG_HORIZON_SLICE_MIN ? n.pl : 0.0f;
        k->cn[i] = cn, k->sn[i] = sn;
        k->hc[0][i] = k->low[0][i] = -sn;
        k->hc[1][i] = k->low[1][i] = sn;
        k->hq[0][i] = k->hq[1][i] = 1.0f;
        k->bot[0][i] = k->bot[1][i] = 2.0f;
        k->pdep[0][i] = k->pdep[1][i] = k->h.dp[i];
        k->pcos[0][i] = k->low[0][i], k->pcos[1][i] = k->low[1][i];
    }
}

/* Step s of both sides for the whole chunk (ssg_horizon_place). */
static inline __attribute__((always_inline)) void
place_step(const struct job *j, struct chunk *restrict k, int len, float y, float sf)
{
    const struct ssg_horizon_bounds bo = ssg_horizon_bounds(&j->r);
    for (int i = 0; i < len; i++) {
        struct ssg_horizon_step s = ssg_horizon_place(bo, &k->h, i, y, sf);
        k->ok[i] = s.ok;
        k->b[i] = s.b;
        k->e[i] = s.e;
        k->a[0][i] = s.a[0], k->a[1][i] = s.a[1];
        k->r[0][i] = s.r[0], k->r[1][i] = s.r[1];
        k->idx[0][i] = s.idx[0], k->idx[1][i] = s.idx[1];
    }
}

/* A sample's weight at squared distance q from P: the linear fade of XeGTAO over the last
   `falloff` of R (w = clamp(r fall_mul + fall_add, 0, 1)), or the hard cutoff r <= R. */
static inline __attribute__((always_inline)) float
weight(float q, const struct ssg_gtao_consts *c, float r2max, int linear)
{
    if (!linear)
        return q <= r2max ? 1.0f : 0.0f;
    float w = sqrtf(q) * c->u.fall_mul + c->u.fall_add;
    w = w < 0.0f ? 0.0f : w;
    return w < 1.0f ? w : 1.0f;
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
    float w = weight(q, c, r2max, linear);
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
    float w = weight(q, c, r2max, linear);
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
    const float *restrict plane = ssg_horizon_plane(&j->r, j->r.padded);
    const float *restrict bplane = back ? ssg_horizon_plane(&j->r, j->r.padded_back) : plane;
    const float r2max = j->c->p.radius * j->c->p.radius;
    for (int i = 0; i < len; i++) {
        float d0 = plane[k->idx[0][i]], d1 = plane[k->idx[1][i]];
        if (back) {
            float b0 = bplane[k->idx[0][i]], b1 = bplane[k->idx[1][i]];
            for (int m = 0; m < 2; m++)
                k->hc[m][i] = horizon_back(k->hc[m][i], &k->bot[m][i], &k->pdep[m][i],
                                           &k->pcos[m][i], k->low[m][i], m ? d1 : d0,
                                           m ? b1 : b0, k->a[m][i], k->r[m][i], k->b[i],
                                           k->e[i], k->h.ldp[i], k->ok[i], j->c, r2max, linear);
            continue;
        }
        if (fast) {
            horizon_fast(&k->hc[0][i], &k->hq[0][i], d0, k->a[0][i], k->r[0][i], k->b[i],
                         k->e[i], k->h.ldp[i], k->ok[i], r2max);
            horizon_fast(&k->hc[1][i], &k->hq[1][i], d1, k->a[1][i], k->r[1][i], k->b[i],
                         k->e[i], k->h.ldp[i], k->ok[i], r2max);
            continue;
        }
        k->hc[0][i] = horizon_one(k->hc[0][i], k->low[0][i], d0, k->a[0][i], k->r[0][i],
                                  k->b[i], k->e[i], k->h.ldp[i], k->ok[i], j->c, r2max, linear);
        k->hc[1][i] = horizon_one(k->hc[1][i], k->low[1][i], d1, k->a[1][i], k->r[1][i],
                                  k->b[i], k->e[i], k->h.ldp[i], k->ok[i], j->c, r2max, linear);
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
            float bt = pl * (t0 * k->d[m][i] + t1 * k->h.v[m][i]);
            k->bsum[m][i] += live ? bt : 0.0f;
        }
    }
}

/* out = clamp(vis / open, 0, 1)^power and the normalised bent normal (no slice, all
   grazing: the normal itself) of the m lanes, computed in the slice's arrays (free by
   now); background 1 and 0. */
static inline __attribute__((always_inline)) void
finish_chunk(const struct job *j, struct chunk *restrict k, size_t o, int len, int m)
{
    const size_t plane = (size_t)j->r.w * (size_t)j->r.h;
    const float power = j->c->p.power;
    float *restrict v = k->pl, *restrict n0 = k->d[0], *restrict n1 = k->d[1];
    float *restrict n2 = k->d[2];
    for (int i = 0; i < m; i++) {
        float a = k->open[i] > 0.0f ? k->vis[i] / k->open[i] : 1.0f;
        a = a > 0.0f ? a : 0.0f;
        v[i] = a < 1.0f ? a : 1.0f;
    }
    for (int i = 0; power != 1.0f && i < m; i++)
        v[i] = powf(v[i], power);
    for (int i = 0; i < m; i++) {
        float bx = k->bsum[0][i], by = k->bsum[1][i], bz = k->bsum[2][i];
        float bl = sqrtf(bx * bx + by * by + bz * bz);
        float ib = bl > 0.0f ? 1.0f / bl : 0.0f;
        int some = bl > 0.0f;
        n0[i] = some ? bx * ib : k->h.nx[i];
        n1[i] = some ? by * ib : k->h.ny[i];
        n2[i] = some ? bz * ib : k->h.nz[i];
    }
    ssg_horizon_unpack(&k->h, m, len, v, j->out + o, 1.0f);
    ssg_horizon_unpack(&k->h, m, len, n0, j->bent + o, 0.0f);
    ssg_horizon_unpack(&k->h, m, len, n1, j->bent + plane + o, 0.0f);
    ssg_horizon_unpack(&k->h, m, len, n2, j->bent + 2 * plane + o, 0.0f);
}

/* One row of one chunk: the hot code, compiled per instruction set (SSG_VECTOR_CLONES). */
static inline __attribute__((always_inline)) void
chunk_body(const struct job *j, struct chunk *restrict k, int y, int x0, int len,
           int linear, int fast, int back)
{
    const struct ssg_gtao_consts *c = j->c;
    const int m = load_chunk(j, k, y, x0, len);
    ssg_horizon_setup(&j->r, &k->h, y, x0, m, 0);
    for (int s = 0; s < c->p.slices; s++) {
        setup_slice(j, k, m, j->fr.slice_cos[s], j->fr.slice_sin[s]);
        for (int st = 0; st < c->p.steps; st++) {
            place_step(j, k, m, (float)y, (float)st);
            horizon_step(j, k, m, linear, fast, back);
        }
        if (fast)
            fast_horizons(k, m);
        finish_slice(k, m, back);
    }
    finish_chunk(j, k, (size_t)y * (size_t)j->r.w + (size_t)x0, len, m);
}

SSG_VECTOR_CLONES
static void gtao_chunk_row(const struct ssg_horizon_run *r, void *chunk, int y, int x0, int len)
{
    const struct job *j = (const struct job *)r; /* r is the job's first member */
    int linear = j->c->p.falloff > 0.0f;
    if (r->padded_back)
        chunk_body(j, chunk, y, x0, len, linear, 0, 1);
    else if (linear)
        chunk_body(j, chunk, y, x0, len, 1, 0, 0);
    else if (j->c->p.thickness > 0.0f)
        chunk_body(j, chunk, y, x0, len, 0, 0, 0);
    else
        chunk_body(j, chunk, y, x0, len, 0, 1, 0);
}

enum ssg_err ssg_gtao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_gtao_consts *c = consts;
    const struct ssg_image *rot = io->in[SSG_GTAO_IN_ROTATION];
    const struct ssg_image *back = io->in[SSG_GTAO_IN_BACK];
    struct job j = {.r = {.proj = c->proj, .invf = c->invf, .e1 = c->e1, .radius = c->p.radius,
                          .cap = c->p.max_screen_radius, .steps = c->p.steps,
                          .back = back ? back->data : NULL, .row = gtao_chunk_row},
                    .c = c, .rot = rot ? rot->data : NULL, .n = rot ? rot->width : 1,
                    .out = io->out[SSG_GTAO_OUT_OUT]->data,
                    .bent = io->out[SSG_GTAO_OUT_BENT_NORMAL]->data};
    ssg_gtao_frame_of(c, ctx->frame_index, &j.fr);
    ssg_horizon_gbuffer(&j.r, io->in[SSG_GTAO_IN_POSITION], io->in[SSG_GTAO_IN_NORMAL],
                        io->in[SSG_GTAO_IN_DEPTH]);
    return ssg_horizon_execute(ctx, &j.r);
}
