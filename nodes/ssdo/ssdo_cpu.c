/* ssdo_cpu.c - CPU kernel of the `ssdo` node (method in README.md; the sampling, visibility
 * and bounce shared with `bounce` in ssdo_sampling.h).
 *
 * Layout for speed, as ssao_cpu.c: a row is cut into chunks of SSG_SSDO_CHUNK pixels whose
 * per-pixel constants live in structure-of-arrays scratch; per kernel sample, straight
 * loops over the chunk place and project the sample and read the depth there (a gather);
 * only the samples behind that depth go on, compacted, to the range check and the bounce
 * (ssdo_sampling.h); then the environment and light weights are added. Chunk
 * columns outside, a band's rows inside, so the depth window a chunk's samples read stays
 * in cache from one row to the next. The environment's dot product N.w = s.z / |s| does
 * not depend on the pixel, so a constant environment costs one add per sample; a light
 * probe is looked up in the view-space cube per sample (a scalar loop). Each pixel depends
 * only on the inputs and every per-pixel sum runs in kernel order: the output does not
 * depend on the thread count; the FMA clones round a little differently from the
 * baseline's (vector_loops.h).
 * Per-pixel counts (the `count` input, README.md): a chunk runs the samples up to the largest
 * count among its surface pixels; a lane past its own count is no candidate of the depth
 * test (ssdo_sampling.h) and adds 0 to the light and environment sums (selects, so the
 * loops still vectorise), and its dw and patch area use its count. Adding a masked 0
 * leaves a sum's bits unchanged, so count = K everywhere gives the bits of the path
 * without the input, which stays as it was (`counted` is a constant at each call). */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "ssdo.h"
#include "scene/scene.h" /* ssg_cone_falloff */

enum { CHUNK = SSG_SSDO_CHUNK, MAXL = SSG_SSDO_MAX_LIGHTS };

struct job {
    struct ssg_ssdo_job s;         /* what the shared sampling reads */
    const struct ssg_ssdo_consts *c;
    float *out[3];                 /* planes of out (1 or 3) */
    float *bounce[3];              /* planes of the bounce output */
    int out_channels;
    float dw;                      /* pi / (sum of nw over the kernel): dw_of[K] */
    float *nw;                     /* per sample: N.w = s.z / |s| (>= 0) */
    float *inv_len;                /* per sample: 1 / |s| (0 for s = 0) */
    float full_w;                  /* sum of nw in kernel order */
    const float *cnt;              /* per-pixel sample counts, NULL = the whole kernel */
    float *dw_of;                  /* dw_of[n] = pi / (sum of nw over the first n samples),
                                      0 where that sum is 0; n = 0..K (count input) */
};

/* The lighting part of a chunk: per light the tangent-space direction to it and its
   unshadowed irradiance factor, the lobe weight sums, and the environment sums. */
struct light_chunk {
    float lt[MAXL][3][CHUNK];   /* (T.L, B.L, N.L) */
    float e[MAXL][CHUNK];       /* max(0, N.L) / d^2 (point) or max(0, N.L) */
    float ws[MAXL][CHUNK];      /* sum of w_il */
    float wv[MAXL][CHUNK];      /* sum of w_il V_i */
    float c[CHUNK], p[CHUNK];   /* scratch of the lobe power (generic lobe) */
    float litw[CHUNK];          /* constant environment: sum of nw V */
    float lit[3][CHUNK];        /* cube: sum of L_env nw V */
    float full[3][CHUNK];       /* cube: sum of L_env nw */
    int32_t texel[CHUNK];       /* cube: per sample, the float offset of its texel */
    float num[3][CHUNK], den[3][CHUNK]; /* finish: lit and unoccluded light per channel */
    float vis[CHUNK];           /* finish: vis_l of one light */
    float dwl[CHUNK];           /* count input: dw_of[n_i] */
    float fullw[CHUNK];         /* count input, constant environment: sum of nw over the
                                   pixel's n_i samples */
};

/* Per light, L in the tangent frame and E / colour; the sums start at 0. */
static inline __attribute__((always_inline)) void
setup_lights(const struct job *j, const struct ssg_ssdo_chunk *restrict k,
             struct light_chunk *restrict lc, int len)
{
    for (int l = 0; l < j->c->light_count; l++) {
        const struct ssg_ssdo_light *li = &j->c->lights[l];
        const float vx = li->v[0], vy = li->v[1], vz = li->v[2];
        const float point = li->directional ? 0.0f : 1.0f;
        const float ax = li->axis[0], ay = li->axis[1], az = li->axis[2];
        for (int i = 0; i < len; i++) {
            /* point: v - P; directional: v (P weighted by 0) */
            float lx = vx - point * k->px[i], ly = vy - point * k->py[i];
            float lz = vz - point * k->pz[i];
            float d2 = lx * lx + ly * ly + lz * lz;
            float inv = 1.0f / sqrtf(d2 > 1e-30f ? d2 : 1e-30f);
            lx *= inv, ly *= inv, lz *= inv;
            float ndl = k->nx[i] * lx + k->ny[i] * ly + k->nz[i] * lz;
            float fall = li->directional ? 1.0f : inv * inv;
            float cone = ssg_cone_falloff(-(ax * lx + ay * ly + az * lz), li->cone_scale,
                                          li->cone_offset); /* 1 but for a spot */
            lc->e[l][i] = (ndl > 0.0f ? ndl : 0.0f) * fall * cone;
            lc->lt[l][0][i] = k->tx[i] * lx + k->ty[i] * ly + k->tz[i] * lz;
            lc->lt[l][1][i] = k->bx[i] * lx + k->by[i] * ly + k->bz[i] * lz;
            lc->lt[l][2][i] = ndl;
            lc->ws[l][i] = 0.0f;
            lc->wv[l][i] = 0.0f;
        }
    }
    for (int i = 0; i < len; i++) {
        lc->litw[i] = 0.0f;
        for (int ch = 0; ch < 3; ch++)
            lc->lit[ch][i] = lc->full[ch][i] = 0.0f;
    }
}

/* max(0, cl)^lobe nw by squaring for lobe < 16: p = nw, then per bit b of lobe from the
   lowest p *= c (bit set) and c *= c (higher bits left). With `lobe` a constant the
   fixed-count loop unrolls into straight code that vectorises (a loop on lobe >>= 1 would
   not: its trip count is not affine); the generic passes of add_lights do the same
   operations in the same order, so every lobe gives the same bits either way. */
static inline __attribute__((always_inline)) float lobe_pow(float cl, float nw, int lobe)
{
    float c = cl > 0.0f ? cl : 0.0f, p = nw;
    for (int b = 0; b < 4; b++) {
        if ((lobe >> b) & 1)
            p *= c;
        if ((lobe >> b) > 1)
            c *= c;
    }
    return p;
}

/* One light's lobe weights in one fused pass, lobe and counted constants at each call
   site (counted: lanes past their count weigh 0). */
static inline __attribute__((always_inline)) void
add_light_lobe(struct light_chunk *restrict lc, const struct ssg_ssdo_chunk *restrict k,
               int l, int len, float sx, float sy, float sz, float il, float nw, int lobe,
               int counted, int s)
{
    for (int i = 0; i < len; i++) {
        float cl = (sx * lc->lt[l][0][i] + sy * lc->lt[l][1][i] + sz * lc->lt[l][2][i]) * il;
        float p = lobe_pow(cl, nw, lobe);
        if (counted)
            p = s < k->cnt[i] ? p : 0.0f;
        lc->ws[l][i] += p;
        lc->wv[l][i] += p * k->vis[i];
    }
}

/* One sample's lobe weights max(0, w.L)^lobe (N.w) for every light (the power by
   squaring: one fused pass for lobes 1..8, else one vector pass per bit of lobe). wv
   gets w V: with V = 1 exactly w, so an open plane's vis is exactly 1. */
static inline __attribute__((always_inline)) void
add_lights(const struct job *j, const struct ssg_ssdo_chunk *restrict k,
           struct light_chunk *restrict lc, int len, float sx, float sy, float sz, int s,
           int counted)
{
    const float il = j->inv_len[s], nw = j->nw[s];
    const int lobe = j->c->p.lobe;
    for (int l = 0; l < j->c->light_count; l++) {
        switch (lobe) {
#define SSDO_LOBE_CASE(n)                                                                   \
    case n:                                                                                 \
        add_light_lobe(lc, k, l, len, sx, sy, sz, il, nw, n, counted, s);                   \
        continue;
            SSDO_LOBE_CASE(1) SSDO_LOBE_CASE(2) SSDO_LOBE_CASE(3) SSDO_LOBE_CASE(4)
            SSDO_LOBE_CASE(5) SSDO_LOBE_CASE(6) SSDO_LOBE_CASE(7) SSDO_LOBE_CASE(8)
#undef SSDO_LOBE_CASE
        default:
            break;
        }
        for (int i = 0; i < len; i++) {
            float cl =
                (sx * lc->lt[l][0][i] + sy * lc->lt[l][1][i] + sz * lc->lt[l][2][i]) * il;
            lc->c[i] = cl > 0.0f ? cl : 0.0f;
            lc->p[i] = nw;
        }
        for (int e = lobe; e; e >>= 1) {
            if (e & 1)
                for (int i = 0; i < len; i++)
                    lc->p[i] *= lc->c[i];
            if (e > 1)
                for (int i = 0; i < len; i++)
                    lc->c[i] *= lc->c[i];
        }
        for (int i = 0; counted && i < len; i++)
            lc->p[i] = s < k->cnt[i] ? lc->p[i] : 0.0f;
        for (int i = 0; i < len; i++) {
            lc->ws[l][i] += lc->p[i];
            lc->wv[l][i] += lc->p[i] * k->vis[i];
        }
    }
}

/* The environment of one sample: constant (one weight sum) or the cube: one vector loop
   finds every pixel's texel (branch-free face selection), a second gathers and adds. */
static inline __attribute__((always_inline)) void
add_environment(const struct job *j, const struct ssg_ssdo_chunk *restrict k,
                struct light_chunk *restrict lc, int len, float sx, float sy, float sz, int s,
                int counted)
{
    const float nw = j->nw[s];
    if (j->c->env == SSG_SSDO_ENV_CONSTANT && !counted) {
        for (int i = 0; i < len; i++)
            lc->litw[i] += nw * k->vis[i];
        return;
    }
    if (j->c->env == SSG_SSDO_ENV_CONSTANT) {
        /* fullw: the pixel's own sum of nw (the whole-kernel path's full_w). */
        for (int i = 0; i < len; i++) {
            float w = s < k->cnt[i] ? nw : 0.0f;
            lc->litw[i] += w * k->vis[i];
            lc->fullw[i] += w;
        }
        return;
    }
    for (int i = 0; i < len; i++) {
        float dx = k->tx[i] * sx + k->bx[i] * sy + k->nx[i] * sz;
        float dy = k->ty[i] * sx + k->by[i] * sy + k->ny[i] * sz;
        float dz = k->tz[i] * sx + k->bz[i] * sy + k->nz[i] * sz;
        lc->texel[i] = 3 * ssg_env_cube_index(dx, dy, dz);
    }
    const float *rgb = j->c->cube.rgb;
    for (int ch = 0; ch < 3; ch++)
        for (int i = 0; i < len; i++) {
            float v = rgb[lc->texel[i] + ch] * nw;
            if (counted)
                v = s < k->cnt[i] ? v : 0.0f;
            lc->full[ch][i] += v;
            lc->lit[ch][i] += v * k->vis[i];
        }
}

/* The hot loop, per kernel sample in order, samples 0..used-1 (used: K, or the chunk's
   largest count). */
static inline __attribute__((always_inline)) void
sample_all(const struct job *j, struct ssg_ssdo_chunk *k, struct light_chunk *lc, int len,
           int used, int counted)
{
    const int count = j->s.count, bounce = j->s.bounce, own = j->s.own_depth;
    const float *kx = j->s.kernel, *ky = kx + count, *kz = ky + count;
    for (int s = 0; s < used; s++) {
        float sx = kx[s], sy = ky[s], sz = kz[s];
        /* constant flags at each call, so each variant is straight code */
        if (own && bounce)
            ssg_ssdo_sample_counted(&j->s, k, len, s, 1, 1, counted);
        else if (own)
            ssg_ssdo_sample_counted(&j->s, k, len, s, 1, 0, counted);
        else if (bounce)
            ssg_ssdo_sample_counted(&j->s, k, len, s, 0, 1, counted);
        else
            ssg_ssdo_sample_counted(&j->s, k, len, s, 0, 0, counted);
        add_environment(j, k, lc, len, sx, sy, sz, s, counted);
        add_lights(j, k, lc, len, sx, sy, sz, s, counted);
    }
}

/* The count input for the chunk's pixels: n_i = round(count) (half up) clamped to
   [1, K], NaN = K (selects only), then what depends on it: dw = dw_of[n_i] and the patch
   area A_s / pi = strength r^2 / n_i (and min_distance^2 when automatic), the same
   operations as ssg_ssdo_setup with n_i for K. Returns the largest n_i among the surface
   pixels (at least 1). */
static inline __attribute__((always_inline)) int
load_counts(const struct job *j, struct ssg_ssdo_chunk *restrict k,
            struct light_chunk *restrict lc, int len, size_t o)
{
    const float *restrict c = j->cnt + o;
    const int kw = j->s.count;
    const float strength = j->s.g.strength;
    const int auto_md = !(j->s.g.min_distance > 0.0f);
    int most = 1;
    for (int i = 0; i < len; i++) {
        int n = ssg_sampling_count(c[i], kw);
        k->cnt[i] = n;
        lc->fullw[i] = 0.0f;
        lc->dwl[i] = j->dw_of[n];
        float per_n = strength / (float)n, rr = k->rr[i];
        k->ff[i] = per_n * (rr * rr);
        k->md2[i] = auto_md ? per_n * (rr * rr) : k->md2[i];
        most = k->fg[i] && n > most ? n : most;
    }
    return most;
}

/* Numerator and denominator of every channel: per pixel and channel the environment
   term, then each light's e vis and e in light order. Vector loops over the chunk (lights
   and channels outside); the same operations in the same order as a per-pixel loop. */
static inline __attribute__((always_inline)) void
light_sums(const struct job *j, struct light_chunk *restrict lc, int len, int counted)
{
    for (int ch = 0; ch < 3; ch++) {
        float *restrict n = lc->num[ch], *restrict d = lc->den[ch];
        if (counted && j->c->env == SSG_SSDO_ENV_CONSTANT) {
            /* per pixel what the whole-kernel branch computes once */
            for (int i = 0; i < len; i++) {
                float scale = j->c->env_rgb[ch] * lc->dwl[i];
                n[i] = scale * lc->litw[i];
                d[i] = scale * lc->fullw[i];
            }
        } else if (counted) {
            for (int i = 0; i < len; i++) {
                n[i] = lc->lit[ch][i] * lc->dwl[i];
                d[i] = lc->full[ch][i] * lc->dwl[i];
            }
        } else if (j->c->env == SSG_SSDO_ENV_CONSTANT) {
            const float scale = j->c->env_rgb[ch] * j->dw, dfull = scale * j->full_w;
            for (int i = 0; i < len; i++) {
                n[i] = scale * lc->litw[i];
                d[i] = dfull;
            }
        } else {
            for (int i = 0; i < len; i++) {
                n[i] = lc->lit[ch][i] * j->dw;
                d[i] = lc->full[ch][i] * j->dw;
            }
        }
    }
    for (int l = 0; l < j->c->light_count; l++) {
        for (int i = 0; i < len; i++) { /* no trapping maths: 0/0 lanes are selected away */
            float ws = lc->ws[l][i], q = lc->wv[l][i] / ws;
            lc->vis[i] = ws > 0.0f ? q : 1.0f;
        }
        for (int ch = 0; ch < 3; ch++) {
            const float rgb = j->c->lights[l].rgb[ch];
            float *restrict n = lc->num[ch], *restrict d = lc->den[ch];
            for (int i = 0; i < len; i++) {
                float e = rgb * lc->e[l][i];
                n[i] += e * lc->vis[i];
                d[i] += e;
            }
        }
    }
}

/* out = M^power over the chunk's modulation planes (powf(x, 0) = 1, even at 0). */
static void raise_to_power(const struct job *j, int len, size_t o)
{
    const float power = j->c->p.power;
    for (int ch = 0; ch < j->out_channels; ch++) {
        float *restrict out = j->out[ch] + o;
        for (int i = 0; i < len; i++)
            out[i] = powf(out[i], power);
    }
}

/* Modulation (per channel or of luminances) or radiance into the out planes; inputs are
   read unconditionally so the loops vectorise. */
static inline __attribute__((always_inline)) void
finish_chunk(const struct job *j, const struct ssg_ssdo_chunk *restrict k,
             struct light_chunk *restrict lc, int len, size_t o, int counted)
{
    static const float luma[3] = {0.2126f, 0.7152f, 0.0722f};
    const float inv_pi = (float)(1.0 / M_PI);
    light_sums(j, lc, len, counted);
    if (j->c->p.mode == SSG_SSDO_MODE_RADIANCE) {
        for (int ch = 0; ch < 3; ch++) {
            const float *restrict a = j->s.alb[ch] + o;
            float *restrict out = j->out[ch] + o;
            for (int i = 0; i < len; i++) {
                float v = a[i] * inv_pi * lc->num[ch][i];
                out[i] = k->fg[i] != 0 ? v : 0.0f;
            }
        }
    } else if (j->out_channels == 3) {
        for (int ch = 0; ch < 3; ch++) {
            float *restrict out = j->out[ch] + o;
            for (int i = 0; i < len; i++) {
                float n = lc->num[ch][i], d = lc->den[ch][i], q = n / d;
                out[i] = (k->fg[i] != 0) & (d > 1e-30f) ? q : 1.0f;
            }
        }
    } else {
        float *restrict out = j->out[0] + o;
        for (int i = 0; i < len; i++) {
            float yn = luma[0] * lc->num[0][i] + luma[1] * lc->num[1][i] +
                       luma[2] * lc->num[2][i];
            float yd = luma[0] * lc->den[0][i] + luma[1] * lc->den[1][i] +
                       luma[2] * lc->den[2][i];
            float q = yn / yd;
            out[i] = (k->fg[i] != 0) & (yd > 1e-30f) ? q : 1.0f;
        }
    }
    if (j->c->p.mode == SSG_SSDO_MODE_MODULATION && j->c->p.power != 1.0f)
        raise_to_power(j, len, o);
}

/* One chunk of one row, start to end, compiled per instruction set (SSG_VECTOR_CLONES):
   the per-pixel passes (loads, frame, lights, finish) are vector loops too, worth the
   wider vectors. */
static inline __attribute__((always_inline)) void
chunk_body(const struct job *j, struct ssg_ssdo_chunk *k, struct light_chunk *lc, int y,
           int x0, int len, int counted)
{
    size_t o = (size_t)y * (size_t)j->s.w + (size_t)x0;
    ssg_ssdo_load(&j->s, k, y, x0, len);
    ssg_ssdo_setup(&j->s, k, len);
    setup_lights(j, k, lc, len);
    int used = counted ? load_counts(j, k, lc, len, o) : j->s.count;
    sample_all(j, k, lc, len, used, counted);
    finish_chunk(j, k, lc, len, o, counted);
    if (j->s.bounce)
        ssg_ssdo_finish_bounce(&j->s, k, len, o, j->bounce);
}

SSG_VECTOR_CLONES
static void
ssdo_chunk_row(const struct job *j, struct ssg_ssdo_chunk *k, struct light_chunk *lc, int y,
               int x0, int len)
{
    if (j->cnt)
        chunk_body(j, k, lc, y, x0, len, 1);
    else
        chunk_body(j, k, lc, y, x0, len, 0);
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct ssg_ssdo_chunk k;
    struct light_chunk lc;
    for (int x0 = 0; x0 < j->s.w; x0 += CHUNK) {
        int len = j->s.w - x0 < CHUNK ? j->s.w - x0 : CHUNK;
        for (int y = y0; y < y1; y++)
            ssdo_chunk_row(j, &k, &lc, y, x0, len);
    }
}

/* Per-sample constants of the kernel: 1 / |s| and N.w = s.z / |s|, and sum of N.w. */
static void kernel_constants(struct job *j)
{
    const int count = j->s.count;
    const float *kx = j->s.kernel, *ky = kx + count, *kz = ky + count;
    j->full_w = 0.0f;
    j->dw_of[0] = 0.0f;
    for (int s = 0; s < count; s++) {
        j->inv_len[s] = ssg_sampling_inv_len(kx[s], ky[s], kz[s]);
        float nw = kz[s] * j->inv_len[s];
        j->nw[s] = nw > 0.0f ? nw : 0.0f;
        j->full_w += j->nw[s];
        j->dw_of[s + 1] = j->full_w > 0.0f ? (float)M_PI / j->full_w : 0.0f;
    }
    j->dw = j->dw_of[count];
}

enum ssg_err ssg_ssdo_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_ssdo_consts *c = consts;
    const int out_channels = c->out_channels;
    const struct ssg_image *pos = io->in[SSG_SSDO_IN_POSITION];
    const struct ssg_image *cnt = io->in[SSG_SSDO_IN_COUNT];
    struct job j = {.c = c, .out_channels = out_channels, .cnt = cnt ? cnt->data : NULL};
    ssg_ssdo_job_init(&j.s, io, &c->g, &c->proj, c->p.bounce);
    for (int ch = 0; ch < 3; ch++) {
        j.out[ch] = ch < out_channels ? ssg_image_plane(io->out[0], ch) : NULL;
        j.bounce[ch] = ssg_image_plane(io->out[1], ch);
    }
    float *per_sample = malloc(sizeof(float) * (5 * (size_t)j.s.count + 1));
    if (!per_sample)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    j.nw = per_sample;
    j.inv_len = per_sample + j.s.count;
    j.dw_of = per_sample + 2 * j.s.count;
    float *lens = per_sample + 3 * j.s.count + 1;
    ssg_sampling_lengths(j.s.kernel, j.s.count, lens);
    j.s.lens = lens;
    kernel_constants(&j);
    if (!c->p.bounce)
        memset(io->out[1]->data, 0, sizeof(float) * 3 * (size_t)pos->width * pos->height);
    ssg_parallel_rows(j.s.h, SSG_SSDO_ROWS_PER_BAND, band, &j);
    free(per_sample);
    return SSG_OK;
}
