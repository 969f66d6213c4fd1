/* ssilvb_cpu.c - CPU kernel of the `ssilvb` node (method in README.md, the slice march in
 * nodes/gtao/README.md): its integrator on the horizon march of nodes/common/horizon.h,
 * which loads and packs the chunk's surface pixels, sets up what depends on the pixel and
 * on the slice, places the samples and drives the rows.
 *
 * Layout: per slice, per step one straight loop over the chunk handles the +D and the -D
 * sample: read the depth, the back depth, the sender's normal and light (gathers), mark
 * the sectors and add the bounce. A last loop per slice adds the slice's visibility.
 * Every loop is selects and arithmetic (no libm call but sqrtf and floorf / nearbyintf),
 * so it vectorises in the SSG_VECTOR_CLONES clones.
 *
 * Per sample everything but the sample's depth d is folded into per-step coefficients
 * (ssg_horizon_place): the point on the ray at depth d, brought back onto the slice along
 * the tangent plane, has H'.V = d a + L dp and sg H'.D = d b; the true offset has H.V =
 * d r + L dp and |H|^2 = (H.V)^2 + d^2 e. The front point is d = dq, the back point
 * d = db; the sample counts when b > |c| (it lies more along the slice than off it), dq
 * is finite and |H| <= R.
 *
 * Determinism: each pixel depends only on the inputs and the seed, and every per-pixel
 * sum runs in a fixed order (slices in order, per step +D before -D), whatever the chunk
 * or the band. ssilvb.glsl performs the same operations in the same order (`precise`);
 * sqrt and division may round differently on GL, which can move a sector boundary. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "common/horizon.h"
#include "ssilvb.h"

enum { CHUNK = SSG_HORIZON_CHUNK };

#define HALF_PI SSG_HORIZON_HALF_PI
/* The farthest back point used: its direction is then the sample's ray to float precision,
   and the products below stay finite. */
#define BACK_MAX 1.0e6f

struct job {
    struct ssg_horizon_run r;     /* the G-buffer and the march (horizon.h); first */
    const struct ssg_ssilvb_consts *c;
    struct ssg_ssilvb_frame fr;   /* this frame's slices and noise offsets */
    const float *light[3], *albedo[3];
    const float *back;            /* back depth plane (unconnected: any plane, times 0) */
    float back_mul;               /* 1 with back, 0 without: a load under a condition
                                     would stop the step loop vectorising */
    float *ao, *bounce;           /* outputs; bounce: three planes */
};

/* ssilvb's lanes of one chunk on horizon.h's, structure of arrays. */
struct chunk {
    struct ssg_horizon_lanes h;            /* the pixels and the slice (horizon.h) */
    float vis[CHUNK], wsum[CHUNK];         /* sums over slices of w visible, of w */
    float bsum[3][CHUNK];                  /* the bounce's sum */
    /* per slice */
    float cn[CHUNK], sn[CHUNK];            /* cos n, sin n */
    float lim[2][CHUNK];                   /* acos of the hemisphere's edge: +D, -D */
    float g1[CHUNK], ia[CHUNK];            /* -C(n - pi/2), 1 / A */
    float w[CHUNK], w32[CHUNK];            /* |proj N| A (0: slice skipped), w / 32 */
    uint32_t mask[CHUNK];                  /* the slice's sectors */
};
_Static_assert(sizeof(struct chunk) <= SSG_HORIZON_CHUNK_BYTES, "ssilvb's chunk");

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

/* The chunk's surface pixels (ssg_horizon_load) with their slice turn, one of the turn
   table's picked by noise, and their step jitter; the sums start at 0. Returns the number
   of lanes. */
static inline __attribute__((always_inline)) int
load_chunk(const struct job *j, struct chunk *restrict k, int y, int x0, int len)
{
    const struct ssg_ssilvb_consts *c = j->c;
    const int m = ssg_horizon_load(&j->r, &k->h, y, x0, len);
    const float *no = j->fr.noise_off, yf = (float)y;
    for (int i = 0; i < len; i++) {
        float xf = (float)(x0 + i);
        float turn = ssg_ign(xf + no[0], yf + no[1]) * (float)SSG_SSILVB_TURNS;
        int32_t t = (int32_t)turn;
        t = t < SSG_SSILVB_TURNS - 1 ? t : SSG_SSILVB_TURNS - 1;
        k->h.co[i] = c->turn_cos[t];
        k->h.si[i] = c->turn_sin[t];
        k->h.u[i] = 1.0f - ssg_ign(yf + no[2], xf + no[3]);
        k->vis[i] = k->wsum[i] = 0.0f;
        k->bsum[0][i] = k->bsum[1][i] = k->bsum[2][i] = 0.0f;
    }
    ssg_horizon_pack(&k->h, m, len, k->h.co);
    ssg_horizon_pack(&k->h, m, len, k->h.si);
    ssg_horizon_pack(&k->h, m, len, k->h.u);
    return m;
}

/* Slice direction phi = pi kd / slices + the pixel's turn (ssg_horizon_slice): the
   normal's angle n in the slice, the measures (README.md), and the tangent-plane
   correction (ssg_horizon_fold). */
static inline __attribute__((always_inline)) void
setup_slice(const struct job *j, struct chunk *restrict k, int len, float dc, float ds)
{
    for (int i = 0; i < len; i++) {
        struct ssg_horizon_arc a = ssg_horizon_slice_arc(&k->h, i, dc, ds, j->r.invf);
        float cn = a.cn, sn = a.sn;
        float n = HALF_PI - ssg_acos(sn);
        float area = cn + n * sn;
        k->cn[i] = cn, k->sn[i] = sn;
        k->lim[0][i] = HALF_PI + n;
        k->lim[1][i] = HALF_PI - n;
        k->g1[i] = 0.5f * (cn + (n - HALF_PI) * sn);
        k->ia[i] = 1.0f / area;
        /* A slice within asin(0.1) of the tangent plane adds nothing (gtao/README.md). */
        float w = a.d.sl >= SSG_HORIZON_SLICE_MIN ? a.pl * area : 0.0f;
        k->w[i] = w;
        k->w32[i] = w * (1.0f / 32.0f);
        k->mask[i] = 0u;
    }
}

/* Where the sample at (su, sv) from lane i's pixel lies in the image planes (normal,
   light, back), clamped to the image: off screen the padded depth gives +inf, so what the
   clamped pixel holds is never used. */
static inline __attribute__((always_inline)) int32_t
image_index(const struct job *j, const struct chunk *restrict k, int i, float su, float sv,
            float y)
{
    const float fw = (float)j->r.w, fh = (float)j->r.h;
    float qx = k->h.xf[i] + su, qy = y + sv;
    qx = qx > 0.0f ? qx : 0.0f;
    qx = qx < fw - 1.0f ? qx : fw - 1.0f;
    qy = qy > 0.0f ? qy : 0.0f;
    qy = qy < fh - 1.0f ? qy : fh - 1.0f;
    return (int32_t)qy * j->r.w + (int32_t)qx;
}

/* Loop invariants in locals: read through the job inside the loop they could alias its
   stores as far as the compiler knows, which keeps it scalar. */
struct consts_v {
    float invf, r2max, thickness;
};

/* The sample of side sg at depth dq (back depth bk, normal nq there; a, r its
   coefficients, ssg_horizon_place): the sectors it newly marks in *mask, and the weight
   t = w (new bits) / 32 its light gets when its surface faces P (0 otherwise). Values
   in, values out: the gathers and the stores stay in the caller's loop, where restrict
   lets it vectorise. */
static inline __attribute__((always_inline)) float
side_bits(const struct consts_v *cv, const struct chunk *restrict k, int i, float su,
          float sv, float sg, float ok, float bb, float e, float a, float r, float dq,
          float bk, float qnx, float qny, float qnz, uint32_t *mask)
{
    const float invf = cv->invf, r2max = cv->r2max;
    const float ldp = k->h.ldp[i];
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
    float aq = k->h.au[i] + su * invf, vq = k->h.av[i] - sv * invf;
    float facing = dqs * (qnx * aq + qny * vq - qnz) -
                   k->h.dp[i] * (qnx * k->h.au[i] + qny * k->h.av[i] - qnz);
    return facing < 0.0f ? (float)(int32_t)bit_count(fresh) * k->w32[i] : 0.0f;
}

/* Step st of both sides (ssg_horizon_place); +D first. */
static inline __attribute__((always_inline)) void
step_both(const struct job *j, struct chunk *restrict k, int len, float y, float sf,
          int has_back)
{
    const float *restrict depth = ssg_horizon_plane(&j->r, j->r.padded);
    const float *restrict back = j->back;
    const float *restrict n0 = j->r.nrm[0], *restrict n1 = j->r.nrm[1];
    const float *restrict n2 = j->r.nrm[2];
    const float *restrict l0 = j->light[0], *restrict l1 = j->light[1];
    const float *restrict l2 = j->light[2];
    const float bmul = j->back_mul;
    const struct consts_v cv = {j->r.invf, j->c->p.radius * j->c->p.radius,
                                j->c->p.thickness};
    const struct ssg_horizon_bounds bo = ssg_horizon_bounds(&j->r);
    for (int i = 0; i < len; i++) {
        struct ssg_horizon_step s = ssg_horizon_place(bo, &k->h, i, y, sf);
        float ok = s.ok ? 1.0f : 0.0f;
        uint32_t mask = k->mask[i];
        int32_t q0 = image_index(j, k, i, s.ou, s.ov, y);
        int32_t q1 = image_index(j, k, i, -s.ou, -s.ov, y);
        float b0 = has_back ? back[q0] * bmul : 0.0f, b1 = has_back ? back[q1] * bmul : 0.0f;
        float w0 = side_bits(&cv, k, i, s.ou, s.ov, 1.0f, ok, s.b, s.e, s.a[0], s.r[0],
                             depth[s.idx[0]], b0, n0[q0], n1[q0], n2[q0], &mask);
        float w1 = side_bits(&cv, k, i, -s.ou, -s.ov, -1.0f, ok, s.b, s.e, s.a[1], s.r[1],
                             depth[s.idx[1]], b1, n0[q1], n1[q1], n2[q1], &mask);
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

/* ao = (vis / wsum)^power, bounce = strength albedo bsum / wsum of the m lanes, computed
   in the slice's arrays (free by now); background 1 and 0. */
static inline __attribute__((always_inline)) void
finish_chunk(const struct job *j, struct chunk *restrict k, size_t o, int len, int m)
{
    const size_t plane = (size_t)j->r.w * (size_t)j->r.h;
    const float power = j->c->p.power, strength = j->c->p.strength;
    float *restrict v = k->cn, *restrict sc = k->sn;
    for (int i = 0; i < m; i++) {
        float ws = k->wsum[i];
        float a = ws > 0.0f ? k->vis[i] / ws : 1.0f;
        a = a > 0.0f ? a : 0.0f;
        v[i] = a < 1.0f ? a : 1.0f;
    }
    for (int i = 0; power != 1.0f && i < m; i++)
        v[i] = powf(v[i], power);
    ssg_horizon_unpack(&k->h, m, len, v, j->ao + o, 1.0f);
    for (int ch = 0; ch < 3; ch++) {
        float *restrict b = j->bounce + (size_t)ch * plane + o;
        const float *restrict alb = j->albedo[ch] + o;
        for (int i = 0; i < m; i++) {
            float ws = k->wsum[i];
            sc[i] = ws > 0.0f ? strength * k->bsum[ch][i] / ws : 0.0f;
        }
        ssg_horizon_unpack(&k->h, m, len, sc, b, 0.0f);
        for (int i = 0; i < len; i++)
            b[i] = k->h.fg[i] ? alb[i] * b[i] : 0.0f;
    }
}

/* has_back is a constant in each copy (ssilvb_chunk_row): without the back input the
   loop reads no back plane at all. */
static inline __attribute__((always_inline)) void
chunk_body(const struct job *j, struct chunk *restrict k, int y, int x0, int len,
           int has_back)
{
    const struct ssg_ssilvb_consts *c = j->c;
    const int m = load_chunk(j, k, y, x0, len);
    ssg_horizon_setup(&j->r, &k->h, y, x0, m, 0);
    for (int s = 0; s < c->p.slices; s++) {
        setup_slice(j, k, m, j->fr.slice_cos[s], j->fr.slice_sin[s]);
        for (int st = 0; st < c->p.steps; st++)
            step_both(j, k, m, (float)y, (float)st, has_back);
        finish_slice(k, m);
    }
    finish_chunk(j, k, (size_t)y * (size_t)j->r.w + (size_t)x0, len, m);
}

SSG_VECTOR_CLONES
static void ssilvb_chunk_row(const struct ssg_horizon_run *r, void *chunk, int y, int x0,
                             int len)
{
    const struct job *j = (const struct job *)r; /* r is the job's first member */
    if (j->back_mul > 0.0f)
        chunk_body(j, chunk, y, x0, len, 1);
    else
        chunk_body(j, chunk, y, x0, len, 0);
}

enum ssg_err ssg_ssilvb_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    const struct ssg_ssilvb_consts *c = consts;
    const struct ssg_image *back = io->in[SSG_SSILVB_IN_BACK];
    struct job j = {.r = {.proj = c->proj, .invf = c->invf, .e1 = c->e1, .radius = c->p.radius,
                          .cap = c->p.max_screen_radius, .steps = c->p.steps,
                          .row = ssilvb_chunk_row},
                    .c = c, .back_mul = back ? 1.0f : 0.0f,
                    .ao = io->out[SSG_SSILVB_OUT_AO]->data,
                    .bounce = io->out[SSG_SSILVB_OUT_BOUNCE]->data};
    ssg_ssilvb_frame_of(c, ctx->frame_index, &j.fr);
    ssg_horizon_gbuffer(&j.r, io->in[SSG_SSILVB_IN_POSITION], io->in[SSG_SSILVB_IN_NORMAL],
                        io->in[SSG_SSILVB_IN_DEPTH]);
    for (int ch = 0; ch < 3; ch++) {
        j.light[ch] = ssg_image_plane(io->in[SSG_SSILVB_IN_LIGHT], ch);
        j.albedo[ch] = ssg_image_plane(io->in[SSG_SSILVB_IN_ALBEDO], ch);
    }
    j.back = back ? back->data : j.r.depth;
    return ssg_horizon_execute(ctx, &j.r);
}
