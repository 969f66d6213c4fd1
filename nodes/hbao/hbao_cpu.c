/* hbao_cpu.c - CPU kernel of the `hbao` node (method and geometry in README.md): its
 * integrator on the horizon march of nodes/common/horizon.h, which loads and packs the
 * chunk's surface pixels, sets up what depends on the pixel and on the slice, places the
 * samples and drives the rows; the pattern and the job are in hbao_pattern.c and
 * hbao_cpu.h.
 *
 * Layout for speed (horizon.h): per chunk the pixels' lanes, then per pair of opposite
 * directions D, -D what depends on the azimuth (-D reuses D's work), then per step two
 * straight loops over the chunk: one places the samples and computes their pixel indices,
 * one reads the depth there (the only gather) and updates the horizon. Both vectorise
 * (SSE4, AVX2 or AVX-512 through run-time selected clones).
 *
 * Cost per sample is kept to a few multiplies and compares:
 * - Points come from the depth: with V = -(a_u, a_v, -1) / L and D perpendicular to V, a
 *   sample at pixel offset (ou, ov) from P gives
 *     H.V = dq (ou Vx - ov Vy) / f - L (dq - dp),   H.D = dq (ou Dx - ov Dy) / f,
 *   since P.V = -L dp and P.D = 0; exactly 0 on P's own pixel. Both are affine in dq,
 *   and so is the projection of place_step: per sample H'.V = dq a + L dp, H'.D = dq b.
 * - With falloff none, sines are compared as hv |hv| bq > bv |bv| q (no root, no
 *   division) and the horizon's sine is taken once per direction; the linear falloff
 *   weighs each raising sample by its own distance, which costs a root and a division.
 * - The depth is read from horizon.h's padded plane, where background, garbage and the
 *   border hold +inf: samples off screen are clamped into the border, and an infinite
 *   depth makes q inf or NaN, which fails q <= R^2: no other test is needed.
 * - The march is not normalised per direction (ssg_horizon_slice), and V and its length
 *   come from one division (ssg_horizon_setup's one_division).
 * Per-pixel counts of directions (the `count` input, README.md): a chunk marches only the
 * directions some lane needs; a lane's direction past its count starts with its horizon
 * at +inf, so no sample raises it (no term in the linear falloff), and finish_direction
 * adds 0 for it. Adding 0 leaves a sum's bits unchanged, and the division is by n_i,
 * so count = directions gives the bits of the path without the input, which stays as it
 * was (`counted` is a constant at each call site).
 * Each pixel depends only on the inputs and every per-pixel sum runs in a fixed order, so
 * the output does not depend on the thread count (no reassociation); the FMA clones round
 * a little differently from the baseline's (vector_loops.h). */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "common/horizon.h"
#include "hbao_cpu.h"

enum { CHUNK = SSG_HORIZON_CHUNK };

/* hbao's lanes of one chunk on horizon.h's, structure of arrays. Directions come in
   opposite pairs D, -D (k and k + directions / 2); the arrays [2][CHUNK] hold one row per
   member. */
struct chunk {
    struct ssg_horizon_lanes h;            /* the pixels and the slice (horizon.h) */
    float occ[CHUNK];                      /* sum of horizon terms over directions */
    int32_t cnt[CHUNK];                    /* count input: directions n_i of the lane */
    /* per direction (pair) */
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
    int32_t idx[2][CHUNK];                 /* index in the padded plane */
};
_Static_assert(sizeof(struct chunk) <= SSG_HORIZON_CHUNK_BYTES, "hbao's chunk");

/* The chunk's surface pixels (ssg_horizon_load) with their tile rotation and step jitter
   from the unrolled pattern rows (hbao_pattern.c). Returns the number of lanes. */
static inline __attribute__((always_inline)) int load_chunk(const struct job *j,
                                                            struct chunk *restrict k,
                                                            int y, int x0, int len)
{
    const int m = ssg_horizon_load(&j->r, &k->h, y, x0, len);
    size_t po = (size_t)(y % j->n) * (size_t)j->r.w + (size_t)x0;
    const float *restrict rc = j->rot_c + po, *restrict rs = j->rot_s + po;
    const float *restrict ju = j->jitter + po;
    for (int i = 0; i < len; i++) {
        k->h.co[i] = rc[i];
        k->h.si[i] = rs[i];
        k->h.u[i] = ju[i];
        k->occ[i] = 0.0f;
    }
    ssg_horizon_pack(&k->h, m, len, k->h.co);
    ssg_horizon_pack(&k->h, m, len, k->h.si);
    ssg_horizon_pack(&k->h, m, len, k->h.u);
    return m;
}

/* Azimuth theta = 2 pi kd / directions + psi (ssg_horizon_slice) and the starting
   horizons sin(t + bias) of D and of -D (1 when t + bias passes the zenith; for -D, sin t
   changes sign and cos t does not). */
static inline __attribute__((always_inline)) void
setup_direction(const struct job *j, struct chunk *restrict k, int len, float dc, float ds,
                int linear)
{
    const float invf = j->r.invf, cb = j->c->u.cos_bias, sb = j->c->u.sin_bias;
    for (int i = 0; i < len; i++) {
        struct ssg_horizon_dir d = ssg_horizon_slice(&k->h, i, dc, ds, invf);
        float vn = k->h.vn[i];
        float ir = 1.0f / sqrtf(d.sl); /* sl = 1 - mn^2, |N projected on the slice|^2 > 0 */
        /* isl = mn / sl; huge only in the slices disabled below, whose samples it then
           rejects (q > R^2, or NaN). */
        ssg_horizon_fold(&k->h, i, d.dn, d.mn * ir * ir);
        float st = -d.dn * ir, ct = vn * ir;
        float stb = st * cb + ct * sb, ctb = ct * cb - st * sb;
        float stb2 = ct * sb - st * cb, ctb2 = ct * cb + st * sb;
        /* Past the zenith, or a slice too close to the tangent plane: no term. */
        stb = (ctb < 0.0f) | (d.sl < SSG_HORIZON_SLICE_MIN) ? 1.0f : stb;
        stb2 = (ctb2 < 0.0f) | (d.sl < SSG_HORIZON_SLICE_MIN) ? 1.0f : stb2;
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

/* Places step jf of D, and of -D when `pair`, for the whole chunk (ssg_horizon_place).
   A sample that the rounding put more off the slice than forward along it
   (|H.M| >= H'.D) says nothing about this half of the slice, and its H' would be noise:
   since H'.D = dq b and H.M = dq c share the factor dq > 0 the test is b > |c|, and a
   NaN in a rejects the sample. That happens within a pixel or two of P, mostly on
   surfaces seen at a grazing angle, and for an occluder so nearly straight above P that
   its forward offset is below the rounding's. The NaN is added rather than selected: a
   select lets the compiler load a's inputs under the condition (masked loads, slower);
   adding 0 keeps every other a but turns -0 into +0, which dq a + L dp (L dp > 0) does
   not tell apart. -D's b equals D's (both odd in the offset and in the direction): one b
   serves both. */
static inline __attribute__((always_inline)) void
place_step(const struct job *j, struct chunk *restrict k, int len, int pair, float y,
           float jf)
{
    const struct ssg_horizon_bounds bo = ssg_horizon_bounds(&j->r);
    int32_t *restrict i0 = k->idx[0], *restrict i1 = k->idx[1];
    float *restrict a0 = k->a[0], *restrict a1 = k->a[1], *restrict kb = k->b;
    for (int i = 0; i < len; i++) {
        struct ssg_horizon_step s = ssg_horizon_place(bo, &k->h, i, y, jf);
        float reject = s.ok ? 0.0f : __builtin_nanf("");
        kb[i] = s.b;
        i0[i] = s.idx[0];
        a0[i] = s.a[0] + reject;
        if (pair) {
            i1[i] = s.idx[1];
            a1[i] = s.a[1] + reject;
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
    const float *restrict plane = ssg_horizon_plane(&j->r, j->r.padded);
    const float r2 = j->c->u.r2, inv_radius = j->c->u.inv_radius;
    const int32_t *restrict i0 = k->idx[0], *restrict i1 = k->idx[1];
    float *restrict v0 = k->bv[0], *restrict v1 = k->bv[1];
    float *restrict q0 = k->bq[0], *restrict q1 = k->bq[1];
    float *restrict occ = k->occ;
    for (int i = 0; i < len; i++) {
        horizon_one(plane[i0[i]], k->a[0][i], k->b[i], k->h.ldp[i], r2, inv_radius, linear,
                    &v0[i], &q0[i], &occ[i]);
        if (pair)
            horizon_one(plane[i1[i]], k->a[1][i], k->b[i], k->h.ldp[i], r2, inv_radius,
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
    const float *c = j->cnt + (size_t)y * (size_t)j->r.w + (size_t)x0;
    const int nd = j->c->p.directions;
    int most = 1;
    for (int i = 0; i < m; i++) {
        int n = ssg_sampling_count(c[k->h.xs[i]], nd);
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

/* out = 1 - occ scale, clamped, of the m lanes (in a[0], free by now); background 1. */
static inline __attribute__((always_inline)) void
finish_chunk(const struct job *j, struct chunk *restrict k, int len, int m, float *out,
             int counted)
{
    const float strength = j->c->p.strength;
    const float scale = j->c->u.scale;
    float *restrict v = k->a[0];
    for (int i = 0; i < m; i++) {
        float sc = counted ? strength / (float)k->cnt[i] : scale;
        float a = 1.0f - k->occ[i] * sc;
        a = a > 0.0f ? a : 0.0f;
        v[i] = a < 1.0f ? a : 1.0f;
    }
    ssg_horizon_unpack(&k->h, m, len, v, out, 1.0f);
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
    ssg_horizon_setup(&j->r, &k->h, y, x0, m, 1);
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
    finish_chunk(j, k, len, m, j->out + (size_t)y * (size_t)j->r.w + (size_t)x0, counted);
}

SSG_VECTOR_CLONES
static void hbao_chunk_row(const struct ssg_horizon_run *r, void *chunk, int y, int x0, int len)
{
    const struct job *j = (const struct job *)r; /* r is the job's first member */
    if (j->cnt)
        chunk_body(j, chunk, y, x0, len, 1);
    else
        chunk_body(j, chunk, y, x0, len, 0);
}

enum ssg_err ssg_hbao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_hbao_consts *c = consts;
    const struct ssg_image *cnt = io->in[SSG_HBAO_IN_COUNT];
    struct job j = {.r = {.proj = c->proj, .invf = c->invf, .e1 = c->e1, .radius = c->p.radius,
                          .cap = c->p.max_screen_radius, .steps = c->p.steps,
                          .row = hbao_chunk_row},
                    .c = c, .out = io->out[0]->data, .cnt = cnt ? cnt->data : NULL};
    ssg_horizon_gbuffer(&j.r, io->in[SSG_HBAO_IN_POSITION], io->in[SSG_HBAO_IN_NORMAL],
                        io->in[SSG_HBAO_IN_DEPTH]);
    float *tables = ssg_hbao_pattern_unroll(io->in[SSG_HBAO_IN_ROTATION], j.r.w, &j);
    if (!tables)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the pattern tables");
    enum ssg_err e = ssg_horizon_execute(ctx, &j.r);
    free(tables);
    return e;
}
