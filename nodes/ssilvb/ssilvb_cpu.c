/* ssilvb_cpu.c - CPU kernel of the `ssilvb` node (method in README.md, the slice march in
 * nodes/gtao/README.md and gtao_cpu.c, whose layout this follows).
 *
 * Layout: a row is cut into chunks of CHUNK pixels held in structure-of-arrays scratch;
 * per chunk what depends on the pixel only (V, the basis, the march length, the noise) is
 * set up once, per slice what depends on its direction (D, M, the screen step, the
 * coefficients of the sample formulas, the slice's measure), then per step one straight
 * loop over the chunk handles the +D and the -D sample: place them, read the depth, the
 * back depth, the sender's normal and light (gathers), mark the sectors and add the
 * bounce. A last loop per slice adds the slice's visibility. Every loop is selects and
 * arithmetic (no libm call but sqrtf and floorf / nearbyintf), so it vectorises in the
 * SSG_VECTOR_CLONES clones.
 *
 * Per sample, as in gtao_cpu.c, everything but the sample's depth d is folded into
 * per-step coefficients (V, D, M orthonormal, L = |P| / dp): the point on the ray at depth
 * d, brought back onto the slice along the tangent plane, has H'.V = d a + L dp and
 * sg H'.D = d b; the true offset has H.V = d r + L dp and |H|^2 = (H.V)^2 + d^2 e. The
 * front point is d = dq, the back point d = db; the sample counts when b > |c| (it lies
 * more along the slice than off it), dq is finite and |H| <= R.
 *
 * Determinism: each pixel depends only on the inputs and the seed, and every per-pixel
 * sum runs in a fixed order (slices in order, per step +D before -D), whatever the chunk
 * or the band. ssilvb.glsl performs the same operations in the same order (`precise`);
 * sqrt and division may round differently on GL, which can move a sector boundary. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "common/sampling.h"
#include "ssilvb.h"

enum { CHUNK = SSG_SAMPLING_CHUNK, ROWS_PER_BAND = 32 };

/* |proj N|^2 below this: the slice lies within asin(0.1) of the tangent plane (gtao/README.md). */
#define SLICE_MIN 0.01f
#define HALF_PI 1.57079632679489661923f
/* The farthest back point used: its direction is then the sample's ray to float precision,
   and the products below stay finite. */
#define BACK_MAX 1.0e6f

struct job {
    const struct ssg_ssilvb_consts *c;
    struct ssg_ssilvb_frame fr;   /* this frame's slices and noise offsets */
    const float *pos[3], *nrm[3]; /* planes of the G-buffer */
    const float *depth;           /* plane the depth is read from */
    float depth_sign;             /* depth = depth_sign * plane: 1 for depth, -1 for z */
    const float *light[3], *albedo[3];
    const float *back;            /* back depth plane (unconnected: any plane, times 0) */
    float back_mul;               /* 1 with back, 0 without: a load under a condition
                                     would stop the step loop vectorising */
    float *padded;                /* the depth padded by +inf (ssg_sampling_pad_depth) */
    int pw;                       /* w + 2 */
    float *ao, *bounce;           /* outputs; bounce: three planes */
    int w, h;
};

/* Per-lane values of one chunk, structure of arrays. */
struct chunk {
    _Alignas(64) float dp[CHUNK];          /* depth of P */
    float nx[CHUNK], ny[CHUNK], nz[CHUNK]; /* unit normal */
    float px[CHUNK], py[CHUNK], pz[CHUNK]; /* P (loaded by ssg_sampling_load; unused) */
    int32_t fg[CHUNK];                     /* 1 = surface, 0 = background */
    float co[CHUNK], si[CHUNK];            /* the pixel's slice rotation */
    float xf[CHUNK];                       /* pixel column */
    float u[CHUNK];                        /* step jitter in (0, 1] */
    float lp[CHUNK], ldp[CHUNK];           /* L = |P| / dp, L dp */
    float vxf[CHUNK], vyf[CHUNK];          /* Vx / f, -Vy / f */
    float e1x[CHUNK], e1z[CHUNK];          /* e1 = (e1x, 0, e1z) */
    float e2[3][CHUNK];                    /* e2 = V x e1 */
    float e1n[CHUNK], e2n[CHUNK];          /* e1.N, e2.N */
    float au[CHUNK], av[CHUNK];            /* a_u, a_v of P's pixel */
    float vn[CHUNK];                       /* V.N, floored at 1e-6 */
    float step[CHUNK];                     /* march length / steps, px */
    float vis[CHUNK], wsum[CHUNK];         /* sums over slices of w visible, of w */
    float bsum[3][CHUNK];                  /* the bounce's sum */
    /* per slice */
    float du[CHUNK], dv[CHUNK];            /* screen step of D, px per step */
    float dxf[CHUNK], dyf[CHUNK];          /* Dx / f, -Dy / f */
    float mxf[CHUNK], myf[CHUNK];          /* Mx / f, -My / f */
    float ax[CHUNK], ay[CHUNK];            /* a = ou ax + ov ay -/+ L */
    float bx[CHUNK], by[CHUNK];            /* b = ou bx + ov by */
    float cn[CHUNK], sn[CHUNK];            /* cos n, sin n */
    float lim[2][CHUNK];                   /* acos of the hemisphere's edge: +D, -D */
    float g1[CHUNK], ia[CHUNK];            /* -C(n - pi/2), 1 / A */
    float w[CHUNK], w32[CHUNK];            /* |proj N| A (0: slice skipped), w / 32 */
    uint32_t mask[CHUNK];                  /* the slice's sectors */
};

/* Population count of 32 bits by shifts, masks and adds. It vectorises where a popcnt
   would not; GCC recognises the usual form with a final multiply as popcount and then
   leaves the loop scalar, so this one adds the halves instead. */
static inline __attribute__((always_inline)) uint32_t bit_count(uint32_t x)
{
    x = (x & 0x55555555u) + ((x >> 1) & 0x55555555u);
    x = (x & 0x33333333u) + ((x >> 2) & 0x33333333u);
    x = (x & 0x0F0F0F0Fu) + ((x >> 4) & 0x0F0F0F0Fu);
    x = (x & 0x00FF00FFu) + ((x >> 8) & 0x00FF00FFu);
    return (x & 0x0000FFFFu) + (x >> 16);
}

/* The sectors whose centres lie in [min(u0, u1), max(u0, u1)] (u in [0, 1]). */
static inline __attribute__((always_inline)) uint32_t sector_bits(float u0, float u1)
{
    float lo = u0 < u1 ? u0 : u1, hi = u0 < u1 ? u1 : u0;
    int32_t l = (int32_t)(lo * 32.0f + 0.5f), h = (int32_t)(hi * 32.0f + 0.5f);
    uint32_t ml = l >= 32 ? 0xFFFFFFFFu : (1u << (l & 31)) - 1u;
    uint32_t mh = h >= 32 ? 0xFFFFFFFFu : (1u << (h & 31)) - 1u;
    return mh & ~ml;
}

/* The direction (hv, hd) = (H'.V, sg H'.D) of the slice (hd > 0) as the cumulative
   cosine-weighted measure u in [0, 1] (README.md): C(theta) with theta = sg acos(c), then
   (C + g1) / A; past the hemisphere's edge (acos above lim) 1 on the +D side, 0 on -D. */
static inline __attribute__((always_inline)) float
sector_u(float hv, float hd, float sg, float cn, float sn, float g1, float ia, float lim)
{
    float c = hv / sqrtf(hv * hv + hd * hd);
    c = c < 1.0f ? c : 1.0f;
    c = c > -1.0f ? c : -1.0f;
    float s2 = (1.0f - c) * (1.0f + c), s = sqrtf(s2);
    float a = ssg_acos(c);
    float cm = 0.5f * (sg * cn * s2 + sn * (a - s * c));
    float u = (cm + g1) * ia;
    u = u > 0.0f ? u : 0.0f;
    u = u < 1.0f ? u : 1.0f;
    float edge = sg > 0.0f ? 1.0f : 0.0f;
    return a > lim ? edge : u;
}

/* What depends on the pixel only: V, e2 = V x e1, V.N, the march length, the noise. */
static inline __attribute__((always_inline)) void
setup_chunk(const struct job *j, struct chunk *restrict k, int y, int x0, int len)
{
    const struct ssg_ssilvb_consts *c = j->c;
    const float invf = c->invf, radius = c->p.radius, f = c->proj.f;
    const float cap = c->p.max_screen_radius, fs = (float)c->p.steps, yf = (float)y;
    const float av = -(yf + 0.5f - c->proj.cy) * invf;
    const float *no = j->fr.noise_off;
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
        k->vxf[i] = vx * invf;
        k->vyf[i] = -vy * invf;
        k->e1x[i] = e1x, k->e1z[i] = e1z;
        k->e2[0][i] = e2x, k->e2[1][i] = e2y, k->e2[2][i] = e2z;
        k->e1n[i] = e1x * nx + e1z * nz;
        k->e2n[i] = e2x * nx + e2y * ny + e2z * nz;
        k->vn[i] = vn > 1e-6f ? vn : 1e-6f;
        float near = dp - radius, half = 0.5f * dp;
        float rp = f * radius / (near > half ? near : half);
        rp = cap > 0.0f && rp > cap ? cap : rp;
        k->step[i] = rp / fs;
        float turn = ssg_ign(xf + no[0], yf + no[1]) * (float)SSG_SSILVB_TURNS;
        int32_t t = (int32_t)turn;
        t = t < SSG_SSILVB_TURNS - 1 ? t : SSG_SSILVB_TURNS - 1;
        k->co[i] = c->turn_cos[t];
        k->si[i] = c->turn_sin[t];
        k->u[i] = 1.0f - ssg_ign(yf + no[2], xf + no[3]);
        k->vis[i] = k->wsum[i] = 0.0f;
        k->bsum[0][i] = k->bsum[1][i] = k->bsum[2][i] = 0.0f;
    }
}

/* Slice direction phi = pi kd / slices + the pixel's turn: D, M = V x D, the normal's
   angle n in the slice, the measures (README.md), the screen step and the sample
   coefficients with gtao_cpu.c's tangent-plane correction folded in. */
static inline __attribute__((always_inline)) void
setup_slice(const struct job *j, struct chunk *restrict k, int len, float dc, float ds)
{
    const float invf = 1.0f / j->c->proj.f;
    for (int i = 0; i < len; i++) {
        float cs = dc * k->co[i] - ds * k->si[i], s = ds * k->co[i] + dc * k->si[i];
        float dx = cs * k->e1x[i] + s * k->e2[0][i], dy = s * k->e2[1][i];
        float dz = cs * k->e1z[i] + s * k->e2[2][i];
        float mx = cs * k->e2[0][i] - s * k->e1x[i], my = cs * k->e2[1][i];
        float dn = cs * k->e1n[i] + s * k->e2n[i], mn = cs * k->e2n[i] - s * k->e1n[i];
        float vn = k->vn[i], sl = vn * vn + dn * dn;
        float pl = sqrtf(sl), cn = vn / pl, sn = dn / pl;
        float isl = mn / sl, al = isl * vn, be = isl * dn;
        k->du[i] = (dx + k->au[i] * dz) * k->step[i];
        k->dv[i] = -(dy + k->av[i] * dz) * k->step[i];
        float dxf = dx * invf, dyf = -dy * invf, mxf = mx * invf, myf = -my * invf;
        k->dxf[i] = dxf, k->dyf[i] = dyf, k->mxf[i] = mxf, k->myf[i] = myf;
        k->ax[i] = k->vxf[i] + mxf * al;
        k->ay[i] = k->vyf[i] + myf * al;
        k->bx[i] = dxf + mxf * be;
        k->by[i] = dyf + myf * be;
        float n = HALF_PI - ssg_acos(sn);
        float area = cn + n * sn;
        k->cn[i] = cn, k->sn[i] = sn;
        k->lim[0][i] = HALF_PI + n;
        k->lim[1][i] = HALF_PI - n;
        k->g1[i] = 0.5f * (cn + (n - HALF_PI) * sn);
        k->ia[i] = 1.0f / area;
        /* A slice within asin(0.1) of the tangent plane adds nothing (gtao/README.md). */
        float w = sl >= SLICE_MIN ? pl * area : 0.0f;
        k->w[i] = w;
        k->w32[i] = w * (1.0f / 32.0f);
        k->mask[i] = 0u;
    }
}

/* Where the sample of side sg (1: +D at (ou, ov), -1: -D at (-ou, -ov)) lies: its index
   in the padded depth plane and, clamped to the image, in the other planes (off screen
   the padded plane gives +inf, so what the clamped pixel holds is never used). */
static inline __attribute__((always_inline)) void
side_index(const struct job *j, const struct chunk *restrict k, int i, float su, float sv,
           float y, int32_t *pidx, int32_t *q)
{
    const float fw = (float)j->w, fh = (float)j->h;
    *pidx = ssg_sampling_padded_index(k->xf[i], y, su, sv, fw, fh, j->pw);
    float qx = k->xf[i] + su, qy = y + sv;
    qx = qx > 0.0f ? qx : 0.0f;
    qx = qx < fw - 1.0f ? qx : fw - 1.0f;
    qy = qy > 0.0f ? qy : 0.0f;
    qy = qy < fh - 1.0f ? qy : fh - 1.0f;
    *q = (int32_t)qy * j->w + (int32_t)qx;
}

/* Loop invariants in locals: read through the job inside the loop they could alias its
   stores as far as the compiler knows, which keeps it scalar. */
struct consts_v {
    float invf, r2max, thickness;
};

/* The sample of side sg at depth dq (back depth bk, normal nq there): the sectors it
   newly marks in *mask, and the weight t = w (new bits) / 32 its light gets when its
   surface faces P (0 otherwise). Values in, values out: the gathers and the stores stay
   in the caller's loop, where restrict lets it vectorise. */
static inline __attribute__((always_inline)) float
side_bits(const struct consts_v *cv, const struct chunk *restrict k, int i, float su,
          float sv, float sg, float ok, float bb, float e, float dq, float bk, float qnx,
          float qny, float qnz, uint32_t *mask)
{
    const float invf = cv->invf, r2max = cv->r2max;
    float pr = su * k->vxf[i] + sv * k->vyf[i], pa = su * k->ax[i] + sv * k->ay[i];
    float l = k->lp[i], ldp = k->ldp[i];
    float a = pa - l, r = pr - l;
    float hv = dq * r + ldp;
    float d2 = hv * hv + dq * dq * e;
    int valid = (ok > 0.0f) & (dq < INFINITY) & (d2 <= r2max);
    float db = bk > dq ? bk : dq + cv->thickness; /* bk 0 or NaN: the constant */
    db = db < BACK_MAX ? db : BACK_MAX;
    float dqs = valid ? dq : 1.0f, dbs = valid ? db : 1.0f;
    float cn = k->cn[i], sn = k->sn[i], g1 = k->g1[i], ia = k->ia[i];
    float lim = sg > 0.0f ? k->lim[0][i] : k->lim[1][i];
    float uf = sector_u(dqs * a + ldp, dqs * bb, sg, cn, sn, g1, ia, lim);
    float ub = sector_u(dbs * a + ldp, dbs * bb, sg, cn, sn, g1, ia, lim);
    uint32_t sb = sector_bits(uf, ub);
    uint32_t bits = valid ? sb : 0u;
    uint32_t fresh = bits & ~*mask;
    *mask |= bits;
    /* The sender faces P when N_q . (Q - P) < 0, Q = dq (a_u', a_v', -1). */
    float aq = k->au[i] + su * invf, vq = k->av[i] - sv * invf;
    float facing = dqs * (qnx * aq + qny * vq - qnz) -
                   k->dp[i] * (qnx * k->au[i] + qny * k->av[i] - qnz);
    return facing < 0.0f ? (float)(int32_t)bit_count(fresh) * k->w32[i] : 0.0f;
}

/* Step st of both sides: the samples lie at (st + u) step along the screen direction,
   rounded to the nearest pixel (ties to even), -D's at the point reflection; +D first. */
static inline __attribute__((always_inline)) void
step_both(const struct job *j, struct chunk *restrict k, int len, float y, float sf,
          int has_back)
{
    const float *restrict depth = j->padded + j->pw + 1, *restrict back = j->back;
    const float *restrict n0 = j->nrm[0], *restrict n1 = j->nrm[1], *restrict n2 = j->nrm[2];
    const float *restrict l0 = j->light[0], *restrict l1 = j->light[1];
    const float *restrict l2 = j->light[2];
    const float bmul = j->back_mul;
    const struct consts_v cv = {j->c->invf, j->c->p.radius * j->c->p.radius,
                                j->c->p.thickness};
    for (int i = 0; i < len; i++) {
        float t = sf + k->u[i];
        float ou = nearbyintf(k->du[i] * t), ov = nearbyintf(k->dv[i] * t);
        float c = ou * k->mxf[i] + ov * k->myf[i];
        float bd = ou * k->dxf[i] + ov * k->dyf[i];
        float bb = ou * k->bx[i] + ov * k->by[i];
        float ok = bb > fabsf(c) ? 1.0f : 0.0f;
        float e = bd * bd + c * c;
        uint32_t mask = k->mask[i];
        int32_t p0, q0, p1, q1;
        side_index(j, k, i, ou, ov, y, &p0, &q0);
        side_index(j, k, i, -ou, -ov, y, &p1, &q1);
        float b0 = has_back ? back[q0] * bmul : 0.0f, b1 = has_back ? back[q1] * bmul : 0.0f;
        float w0 = side_bits(&cv, k, i, ou, ov, 1.0f, ok, bb, e, depth[p0], b0, n0[q0],
                             n1[q0], n2[q0], &mask);
        float w1 = side_bits(&cv, k, i, -ou, -ov, -1.0f, ok, bb, e, depth[p1], b1, n0[q1],
                             n1[q1], n2[q1], &mask);
        /* Written out for both sides (a loop over them is not unrolled before the
           vectoriser sees it); +D's light first. Loads before the selects: a load under
           a condition would not vectorise. */
        float a0 = l0[q0], a1 = l1[q0], a2 = l2[q0], c0 = l0[q1], c1 = l1[q1], c2 = l2[q1];
        float s0 = k->bsum[0][i], s1 = k->bsum[1][i], s2 = k->bsum[2][i];
        s0 += w0 > 0.0f ? w0 * a0 : 0.0f;
        s1 += w0 > 0.0f ? w0 * a1 : 0.0f;
        s2 += w0 > 0.0f ? w0 * a2 : 0.0f;
        s0 += w1 > 0.0f ? w1 * c0 : 0.0f;
        s1 += w1 > 0.0f ? w1 * c1 : 0.0f;
        s2 += w1 > 0.0f ? w1 * c2 : 0.0f;
        k->bsum[0][i] = s0, k->bsum[1][i] = s1, k->bsum[2][i] = s2;
        k->mask[i] = mask;
    }
}

/* Adds the slice's w (32 - set bits) / 32 to vis and w to wsum. */
static inline __attribute__((always_inline)) void finish_slice(struct chunk *restrict k,
                                                               int len)
{
    for (int i = 0; i < len; i++) {
        float open = (float)(32u - bit_count(k->mask[i]));
        k->vis[i] += k->w32[i] * open;
        k->wsum[i] += k->w[i];
    }
}

/* ao = (vis / wsum)^power, bounce = strength albedo bsum / wsum; background 1 and 0. */
static inline __attribute__((always_inline)) void
finish_chunk(const struct job *j, struct chunk *restrict k, size_t o, int len)
{
    const size_t plane = (size_t)j->w * (size_t)j->h;
    const float power = j->c->p.power, strength = j->c->p.strength;
    float *restrict ao = j->ao + o;
    for (int i = 0; i < len; i++) {
        float ws = k->wsum[i];
        float v = ws > 0.0f ? k->vis[i] / ws : 1.0f;
        v = v > 0.0f ? v : 0.0f;
        ao[i] = v < 1.0f ? v : 1.0f;
    }
    for (int i = 0; power != 1.0f && i < len; i++)
        ao[i] = powf(ao[i], power);
    for (int i = 0; i < len; i++)
        ao[i] = k->fg[i] ? ao[i] : 1.0f;
    for (int ch = 0; ch < 3; ch++) {
        float *restrict b = j->bounce + (size_t)ch * plane + o;
        const float *restrict alb = j->albedo[ch] + o;
        for (int i = 0; i < len; i++) {
            float ws = k->wsum[i];
            float s = ws > 0.0f ? strength * k->bsum[ch][i] / ws : 0.0f;
            b[i] = k->fg[i] ? alb[i] * s : 0.0f;
        }
    }
}

/* has_back is a constant in each copy (ssilvb_chunk_row): without the back input the
   loop reads no back plane at all. */
static inline __attribute__((always_inline)) void
chunk_body(const struct job *j, struct chunk *restrict k, int y, int x0, int len,
           int has_back)
{
    const struct ssg_ssilvb_consts *c = j->c;
    size_t o = (size_t)y * (size_t)j->w + (size_t)x0;
    ssg_sampling_load(j->pos, j->nrm, j->depth, j->depth_sign, o, len, k->fg, k->nx, k->ny,
                      k->nz, k->px, k->py, k->pz, k->dp);
    setup_chunk(j, k, y, x0, len);
    for (int s = 0; s < c->p.slices; s++) {
        setup_slice(j, k, len, j->fr.slice_cos[s], j->fr.slice_sin[s]);
        for (int st = 0; st < c->p.steps; st++)
            step_both(j, k, len, (float)y, (float)st, has_back);
        finish_slice(k, len);
    }
    finish_chunk(j, k, o, len);
}

SSG_VECTOR_CLONES
static void ssilvb_chunk_row(const struct job *j, struct chunk *restrict k, int y, int x0,
                             int len)
{
    if (j->back_mul > 0.0f)
        chunk_body(j, k, y, x0, len, 1);
    else
        chunk_body(j, k, y, x0, len, 0);
}

/* Chunk columns outside, rows inside: the rows of one band sample nearly the same part of
   the planes, which then stay in cache from one row to the next. */
static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    for (int x0 = 0; x0 < j->w; x0 += CHUNK) {
        int len = j->w - x0 < CHUNK ? j->w - x0 : CHUNK;
        for (int y = y0; y < y1; y++)
            ssilvb_chunk_row(j, &k, y, x0, len);
    }
}

static void rows_pad(void *user, int y0, int y1)
{
    const struct job *j = user;
    ssg_sampling_pad_depth(j->depth, j->depth_sign, j->w, y0, y1, j->padded);
}

enum ssg_err ssg_ssilvb_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    const struct ssg_ssilvb_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_SSILVB_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_SSILVB_IN_NORMAL];
    const struct ssg_image *dep = io->in[SSG_SSILVB_IN_DEPTH];
    const struct ssg_image *back = io->in[SSG_SSILVB_IN_BACK];
    struct job j = {.c = c, .w = pos->width, .h = pos->height};
    ssg_ssilvb_frame_of(c, ctx->frame_index, &j.fr);
    j.ao = io->out[SSG_SSILVB_OUT_AO]->data;
    j.bounce = io->out[SSG_SSILVB_OUT_BOUNCE]->data;
    for (int ch = 0; ch < 3; ch++) {
        j.pos[ch] = ssg_image_plane(pos, ch);
        j.nrm[ch] = ssg_image_plane(nrm, ch);
        j.light[ch] = ssg_image_plane(io->in[SSG_SSILVB_IN_LIGHT], ch);
        j.albedo[ch] = ssg_image_plane(io->in[SSG_SSILVB_IN_ALBEDO], ch);
    }
    j.depth = dep ? dep->data : ssg_image_plane(pos, 2);
    j.depth_sign = dep ? 1.0f : -1.0f;
    j.back = back ? back->data : j.depth;
    j.back_mul = back ? 1.0f : 0.0f;
    j.pw = j.w + 2;
    j.padded = ssg_node_scratch(ctx, (size_t)j.pw * (size_t)(j.h + 2) * sizeof *j.padded);
    if (!j.padded)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the padded depth");
    float *last = j.padded + (size_t)(j.h + 1) * (size_t)j.pw;
    for (int x = 0; x < j.pw; x++)
        j.padded[x] = last[x] = INFINITY;
    ssg_parallel_rows(j.h, ROWS_PER_BAND, rows_pad, &j);
    ssg_parallel_rows(j.h, ROWS_PER_BAND, band, &j);
    return SSG_OK;
}
