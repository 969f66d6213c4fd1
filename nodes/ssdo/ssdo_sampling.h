/* ssdo_sampling.h - the per-sample maths of screen-space directional occlusion that the
 * `ssdo` node and the `bounce` node (both in nodes/ssdo) share, so that bounce's
 * output is exactly ssdo's bounce output for the same inputs: the same loops, the same
 * operations in the same order.
 *
 * The method (sampling, the visibility test with its hard range check, the bounce's patch
 * form factors and their normalisation): README.md in this folder, "Sampling, visibility
 * and the bounce".
 *
 * Layout (as ssao_cpu.c): chunks of CHUNK pixels of one row in structure-of-arrays
 * scratch; per kernel sample, straight loops over the chunk that GCC vectorises (the
 * lookups at computed indices become gathers). Every per-pixel sum runs in kernel order,
 * so results depend neither on the threads nor on the instruction set.
 * Everything here is static inline: both nodes compile the same code. Thread-safe: a job is
 * read-only, a chunk belongs to one thread. */
#ifndef SSG_SSDO_SAMPLING_H
#define SSG_SSDO_SAMPLING_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "common/sampling.h"
#include "graph/node.h"

/* Input ports of both nodes, one row each (graph/node.h), in order: bounce has the first
   seven (albedo and light required there, with its own docs: bounce.h), ssdo all eight.
   Both descriptors' arrays are indexed by these enumerators (SSG_<NODE>_IN_<PORT>; the
   ports are ssdo's, so is the prefix). */
#define SSG_SSDO_GEOM_IN(X)                                                                \
    X(SSG_SSDO_IN_POSITION, "position", SSG_T_VECTOR, "view-space position")               \
    X(SSG_SSDO_IN_NORMAL, "normal", SSG_T_VECTOR, "unit view-space normal")                \
    X(SSG_SSDO_IN_KERNEL, "kernel", SSG_T_KERNEL,                                          \
      "hemisphere samples, uniform in solid angle (halton mapping=uniform)")               \
    X(SSG_SSDO_IN_ROTATION, "rotation", SSG_T_PATTERN,                                     \
      "per-pixel rotation tile (halton.rotation; a third plane moves the sample "          \
      "lengths); none = no rotation", .optional = 1)                                       \
    X(SSG_SSDO_IN_DEPTH, "depth", SSG_T_SCALAR,                                            \
      "linear depth for the occluder lookup; none = -position.z", .optional = 1)
#define SSG_SSDO_IN(X)                                                                     \
    SSG_SSDO_GEOM_IN(X)                                                                    \
    X(SSG_SSDO_IN_ALBEDO, "albedo", SSG_T_COLOR,                                           \
      "diffuse albedo (mode radiance and bounce)", .optional = 1)                          \
    X(SSG_SSDO_IN_LIGHT, "light", SSG_T_COLOR,                                             \
      "outgoing radiance of each pixel, the bounce's senders (bounce)", .optional = 1)     \
    X(SSG_SSDO_IN_COUNT, "count", SSG_T_SCALAR,                                            \
      "per-pixel sample count (complexity.count): the first n of the kernel; none = all",  \
      .optional = 1) /* ssdo only */
SSG_PORT_ENUM(ssg_ssdo_input, SSG_SSDO_IN, SSG_SSDO_INPUTS);
enum { SSG_BOUNCE_INPUTS = SSG_SSDO_IN_COUNT };

enum { SSG_SSDO_CHUNK = SSG_SAMPLING_CHUNK, SSG_SSDO_ROWS_PER_BAND = 16 };

/* The parameters of the sampling and the bounce, one row each (lang/params.h), the first
   rows of both nodes' tables. max_screen_radius is read through prepare()'s cap. */
#define SSG_SSDO_GEOM_PARAMS(P)                                                            \
    P(FLOAT, radius, "r_max: hemisphere radius around the pixel", .def = 0.5, .min = 1e-6, \
      .max = 1e6, .soft_min = 0.05, .soft_max = 5, .unit = "scene units")                  \
    P(FLOAT, bias, "a sample is occluded only when the surface is this much in front of it", \
      .def = 0.02, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 0.2,                   \
      .unit = "scene units")                                                               \
    P(FLOAT, strength, "multiplies the sender patch area A_s = pi radius^2 / K", .def = 1,  \
      .min = 0, .max = 64, .soft_min = 0, .soft_max = 8)                                   \
    P(FLOAT, min_distance,                                                                 \
      "sender distance clamp against 1/d^2; 0 = sqrt(A_s/pi), where one patch's form "     \
      "factor reaches 1",                                                                  \
      .def = 0, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 1, .unit = "scene units") \
    P(FLOAT, max_screen_radius, "caps the projected radius; 0 = no cap", .def = 0,         \
      .min = 0, .max = 16384, .soft_min = 0, .soft_max = 512, .unit = "px",                \
      .host_only = 1) /* prepare(): cap, capped */

/* The sampling's constants, made once in prepare() from those rows (ssg_ssdo_geom_make)
   and read by both backends. */
struct ssg_ssdo_geom {
    float radius;       /* r_max, scene units, > 0; default 0.5 */
    float bias;         /* depth margin before a sample counts as occluded, scene units;
                           default 0.02 */
    float strength;     /* multiplies the patch area A_s; default 1 */
    float min_distance; /* clamp of the sender distance, scene units; 0 = the radius of a
                           disc of area A_s; default 0 */
    float cap;          /* max_screen_radius / f: r <= cap depth(P) when capped */
    int capped;         /* max_screen_radius > 0 (px; 0 = no cap, the default) */
};

/* What ssdo.glsl's sampling reads of prepare()'s constants (#pragma ssg_consts), rows over
   the fields both nodes' consts keep (g, proj; lang/params.h's SSG_UNIFORMS_AT_TABLE):
   kind, GLSL name, field, doc. */
#define SSG_SSDO_GEOM_UNIFORMS(U)                                                          \
    U(FLOAT, cap, g.cap, "max_screen_radius / f: r <= cap depth(P) when capped")           \
    U(BOOL, capped, g.capped, "max_screen_radius > 0")                                     \
    U(PROJECTION, proj, proj, "(f, cx, cy) of this resolution")

/* The geometry of a node's parameters `p` (a struct holding SSG_SSDO_GEOM_PARAMS' rows)
   at focal length f (px). */
#define ssg_ssdo_geom_of(p, f)                                                             \
    ssg_ssdo_geom_make((p)->radius, (p)->bias, (p)->strength, (p)->min_distance,           \
                       (p)->max_screen_radius, (f))
static inline struct ssg_ssdo_geom ssg_ssdo_geom_make(float radius, float bias,
                                                      float strength, float min_distance,
                                                      float max_screen_radius, float f)
{
    return (struct ssg_ssdo_geom){.radius = radius, .bias = bias, .strength = strength,
                                  .min_distance = min_distance,
                                  .cap = max_screen_radius / f,
                                  .capped = max_screen_radius > 0.0f};
}

/* What one run reads: image planes, the kernel, the projection of this resolution. */
struct ssg_ssdo_job {
    struct ssg_ssdo_geom g;
    const float *pos[3], *nrm[3];   /* planes of position and normal */
    const float *alb[3], *light[3]; /* planes of albedo and light (NULL when unbound) */
    const float *depth;             /* depth plane, or position's z plane */
    float depth_sign;               /* depth = depth_sign * plane */
    int own_depth;                  /* 1 = a depth input is bound */
    const float *kernel;            /* planar count x 1 x 3 */
    int count;                      /* K */
    const float *rot;               /* planar n x n x 2 (cos, sin), NULL = none */
    const float *off;               /* the tile's length shift (planes 3, 4), NULL = none */
    const float *lens;              /* |s| per kernel sample, twice over (the caller's) */
    int n;
    int w, h;                       /* px */
    float f, cx, cy;                /* projection of this resolution */
    int bounce;                     /* 1 = gather the bounce */
};

/* Per-pixel values of one chunk, structure of arrays. The projection of a sample is
   affine in s over Z (see ssao_cpu.c), so each pixel keeps three 4-vectors. */
struct ssg_ssdo_chunk {
    int32_t fg[SSG_SSDO_CHUNK];                 /* 1 = surface, 0 = background */
    float nx[SSG_SSDO_CHUNK], ny[SSG_SSDO_CHUNK], nz[SSG_SSDO_CHUNK]; /* unit N */
    float tx[SSG_SSDO_CHUNK], ty[SSG_SSDO_CHUNK], tz[SSG_SSDO_CHUNK]; /* unit T, turned */
    float bx[SSG_SSDO_CHUNK], by[SSG_SSDO_CHUNK], bz[SSG_SSDO_CHUNK]; /* unit B, turned */
    float co[SSG_SSDO_CHUNK], si[SSG_SSDO_CHUNK]; /* rotation of the tile (scratch) */
    float dl[SSG_SSDO_CHUNK];                   /* the tile's length offset (with off) */
    float dk[SSG_SSDO_CHUNK];                   /* the tile's index shift (with off) */
    float gs[SSG_SSDO_CHUNK];                   /* per sample: its length shift's factor */
    float px[SSG_SSDO_CHUNK], py[SSG_SSDO_CHUNK], pz[SSG_SSDO_CHUNK]; /* P */
    float dp[SSG_SSDO_CHUNK];                   /* depth of P */
    float rr[SSG_SSDO_CHUNK];                   /* r, scene units */
    float r2[SSG_SSDO_CHUNK];                   /* r^2 (range check) */
    float cu[4][SSG_SSDO_CHUNK];                /* u Z = cu0 + cu1 s.x + cu2 s.y + cu3 s.z */
    float cv[4][SSG_SSDO_CHUNK];                /* v Z, likewise */
    float cz[4][SSG_SSDO_CHUNK];                /* Z - bias, likewise */
    int32_t idx[SSG_SSDO_CHUNK];                /* per sample: pixel S lands on */
    float zb[SSG_SSDO_CHUNK];                   /* per sample: depth(S) - bias, -1 = none */
    float vis[SSG_SSDO_CHUNK];                  /* per sample: V, 1 or 0 */
    int32_t cand[SSG_SSDO_CHUNK];               /* per sample: 1 = behind the depth there */
    /* Per sample, compacted over the candidates (lanes whose depth test failed): */
    int32_t list[SSG_SSDO_CHUNK];               /* their lanes */
    int32_t cocc[SSG_SSDO_CHUNK];               /* 1 = occluded (range check too) */
    float cf[SSG_SSDO_CHUNK];                   /* F_i, 0 unless occluded */
    float cl[3][SSG_SSDO_CHUNK];                /* F_i L_i */
    float ff[SSG_SSDO_CHUNK];                   /* A_s / pi = strength r^2 / K */
    float md2[SSG_SSDO_CHUNK];                  /* min_distance^2 */
    float fsum[SSG_SSDO_CHUNK];                 /* sum of F_i */
    float br[SSG_SSDO_CHUNK], bg[SSG_SSDO_CHUNK], bb[SSG_SSDO_CHUNK]; /* sum F_i L_i */
    int32_t cnt[SSG_SSDO_CHUNK];                /* ssdo's count input: samples n_i of the
                                                   pixel (read only when counted) */
};

/* The job of a run: planes, kernel, tile and the projection of the inputs' resolution
   (prepare()'s, ssg_sampling_projection). The executor has verified the images' shapes. */
static inline void ssg_ssdo_job_init(struct ssg_ssdo_job *j, const struct ssg_io *io,
                                     const struct ssg_ssdo_geom *g,
                                     const struct ssg_projection *proj, int bounce)
{
    const struct ssg_image *pos = io->in[SSG_SSDO_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_SSDO_IN_NORMAL];
    const struct ssg_image *ker = io->in[SSG_SSDO_IN_KERNEL];
    const struct ssg_image *rot = io->in[SSG_SSDO_IN_ROTATION];
    const struct ssg_image *dep = io->in[SSG_SSDO_IN_DEPTH];
    const struct ssg_image *alb = io->in[SSG_SSDO_IN_ALBEDO];
    const struct ssg_image *lig = io->in[SSG_SSDO_IN_LIGHT];
    *j = (struct ssg_ssdo_job){.g = *g, .kernel = ker->data, .count = ker->width,
                               .w = pos->width, .h = pos->height, .bounce = bounce};
    for (int c = 0; c < 3; c++) {
        j->pos[c] = ssg_image_plane(pos, c);
        j->nrm[c] = ssg_image_plane(nrm, c);
        j->alb[c] = alb ? ssg_image_plane(alb, c) : NULL;
        j->light[c] = lig ? ssg_image_plane(lig, c) : NULL;
    }
    j->own_depth = dep != NULL;
    j->depth = dep ? dep->data : j->pos[2];
    j->depth_sign = dep ? 1.0f : -1.0f;
    j->rot = rot ? rot->data : NULL;
    j->off = ssg_sampling_offset_plane(rot);
    j->n = rot ? rot->width : 1;
    j->f = proj->f;
    j->cx = proj->cx;
    j->cy = proj->cy;
}

/* Loads P, N, depth, the tile's rotation and its length offsets (nodes/common/sampling.h). */
static inline __attribute__((always_inline)) void
ssg_ssdo_load(const struct ssg_ssdo_job *j, struct ssg_ssdo_chunk *restrict k, int y, int x0,
              int len)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x0;
    ssg_sampling_load(j->pos, j->nrm, j->depth, j->depth_sign, o, len, k->fg, k->nx, k->ny,
                      k->nz, k->px, k->py, k->pz, k->dp);
    ssg_sampling_rotation(j->rot, j->n, y, x0, len, k->co, k->si);
    if (j->off)
        ssg_sampling_offsets(j->off, j->n, y, x0, len, k->dl, k->dk);
}

/* Tangent frame (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017,
   branch-free, T x B = N) turned about N by the tile's angle, the radius (capped like
   ssao), the projective coefficients of S, and the bounce's per-pixel constants. */
static inline __attribute__((always_inline)) void
ssg_ssdo_setup(const struct ssg_ssdo_job *j, struct ssg_ssdo_chunk *restrict k, int len)
{
    const float f = j->f, cx = j->cx, cy = j->cy, radius = j->g.radius, bias = j->g.bias;
    const float cap = j->g.cap; /* r <= cap * depth */
    const int capped = j->g.capped;
    const float per_k = j->g.strength / (float)j->count;
    const float md = j->g.min_distance;
    const int auto_md = !(md > 0.0f);
    for (int i = 0; i < len; i++) {
        float nx = k->nx[i], ny = k->ny[i], nz = k->nz[i];
        float t[3], b[3];
        ssg_sampling_basis(nx, ny, nz, t, b);
        float t0 = t[0], t1 = t[1], t2 = t[2], b0 = b[0], b1 = b[1], b2 = b[2];
        float co = k->co[i], si = k->si[i];
        float tx = co * t0 + si * b0, ty = co * t1 + si * b1, tz = co * t2 + si * b2;
        float bx = co * b0 - si * t0, by = co * b1 - si * t1, bz = co * b2 - si * t2;
        k->tx[i] = tx, k->ty[i] = ty, k->tz[i] = tz;
        k->bx[i] = bx, k->by[i] = by, k->bz[i] = bz;
        float rcap = cap * k->dp[i];
        float r = (capped & (rcap < radius)) ? rcap : radius;
        float qx = k->px[i], qy = k->py[i], qz = -k->pz[i];
        float rtz = r * tz, rbz = r * bz, rnz = r * nz;
        k->cz[0][i] = qz - bias;
        k->cz[1][i] = -rtz;
        k->cz[2][i] = -rbz;
        k->cz[3][i] = -rnz;
        k->cu[0][i] = f * qx + cx * qz;
        k->cu[1][i] = f * (r * tx) - cx * rtz;
        k->cu[2][i] = f * (r * bx) - cx * rbz;
        k->cu[3][i] = f * (r * nx) - cx * rnz;
        k->cv[0][i] = cy * qz - f * qy;
        k->cv[1][i] = -cy * rtz - f * (r * ty);
        k->cv[2][i] = -cy * rbz - f * (r * by);
        k->cv[3][i] = -cy * rnz - f * (r * ny);
        k->rr[i] = r;
        k->r2[i] = r * r;
        k->ff[i] = per_k * (r * r);
        k->md2[i] = auto_md ? per_k * (r * r) : md * md;
        k->fsum[i] = 0.0f;
        k->br[i] = k->bg[i] = k->bb[i] = 0.0f;
    }
}

/* Places sample (sx, sy, sz) around every pixel of the chunk and projects it: the pixel
   index it lands on, and depth(S) - bias there (-1 when off screen or behind the camera,
   which no depth > 0 undercuts: visible). With the tile's length shift, sample number s
   of each pixel keeps its direction and takes its shifted length; the light and
   environment weights see the direction alone, so only this placement changes. */
static inline __attribute__((always_inline)) void
ssg_ssdo_place(const struct ssg_ssdo_job *j, struct ssg_ssdo_chunk *restrict k, int len,
               float sx, float sy, float sz, int s)
{
    if (j->off)
        ssg_sampling_place_shifted(k->cz, k->cu, k->cv, len, sx, sy, sz, s, j->lens, k->dl,
                                   k->dk, k->gs, j->g.bias, j->w, j->h, k->idx, k->zb);
    else
        ssg_sampling_place(k->cz, k->cu, k->cv, len, sx, sy, sz, j->g.bias, j->w, j->h,
                           k->idx, k->zb);
}

/* The depth test of each sample: a candidate when 0 < z_i < depth(S) - bias, z_i read at
   its pixel. Returns how many, their lanes compacted into k->list (in lane order); V
   starts at 1. `own_depth` is a constant at each call site: without a depth input z_i
   is -P_i.z. Only the candidates go on to the range check and the bounce, which need six
   to nine more scattered reads: most samples of a frame are not behind anything (about
   6 % in the closed Cornell box), and they cluster in corners, so the compaction (a
   serial dependency on n) skips blocks of 8 lanes without one. With `counted` (a constant
   at each call site) a lane past its count (s >= k->cnt) is no candidate: V = 1 and no
   bounce; ssdo masks its own sums of such lanes. */
static inline __attribute__((always_inline)) int
ssg_ssdo_depth_test(const struct ssg_ssdo_job *j, struct ssg_ssdo_chunk *restrict k, int len,
                    int own_depth, int counted, int s)
{
    const int32_t *restrict idx = k->idx;
    const float *restrict zbs = k->zb;
    const float *restrict dpl = j->depth, *restrict p2 = j->pos[2];
    int32_t any = 0;
    for (int i = 0; i < len; i++) {
        int id = idx[i];
        float d = own_depth ? dpl[id] : -p2[id];
        int32_t active = counted ? s < k->cnt[i] : 1;
        int32_t c = (d > 0.0f) & (d < zbs[i]) & active;
        k->cand[i] = c;
        k->vis[i] = 1.0f;
        any |= c;
    }
    if (!any)
        return 0;
    int n = 0;
    for (int i0 = 0; i0 < len; i0 += 8) {
        int end = len - i0 < 8 ? len : i0 + 8;
        int32_t blk = 0;
        for (int i = i0; i < end; i++)
            blk |= k->cand[i];
        if (!blk)
            continue;
        for (int i = i0; i < end; i++) {
            k->list[n] = i;
            n += k->cand[i];
        }
    }
    return n;
}

/* The range check |P_i - P| <= r of the n candidates (occluded: V = 0) and, with
   `bounce` (a constant at each call site), the form factor of each occluded sample's
   patch and F_i L_i (eq. 3/4, patch form, file header). A back-facing sender
   (N_i.w >= 0) or one behind the receiver's tangent plane gives 0; |v| = 0 gives w = 0
   and so 0. The sums per pixel run in kernel order (a lane appears once per sample). */
static inline __attribute__((always_inline)) void
ssg_ssdo_range_bounce(const struct ssg_ssdo_job *j, struct ssg_ssdo_chunk *restrict k, int n,
                      int bounce)
{
    const int32_t *restrict idx = k->idx;
    const float *restrict p0 = j->pos[0], *restrict p1 = j->pos[1], *restrict p2 = j->pos[2];
    const float *restrict n0 = j->nrm[0], *restrict n1 = j->nrm[1], *restrict n2 = j->nrm[2];
    const float *restrict l0 = j->light[0], *restrict l1 = j->light[1];
    const float *restrict l2 = j->light[2];
    for (int m = 0; m < n; m++) {
        int lane = k->list[m], id = idx[lane];
        float vx = p0[id] - k->px[lane], vy = p1[id] - k->py[lane], vz = p2[id] - k->pz[lane];
        float dd = vx * vx + vy * vy + vz * vz;
        int occ = dd <= k->r2[lane];
        k->cocc[m] = occ;
        if (!bounce)
            continue;
        float mx = n0[id], my = n1[id], mz = n2[id];
        float inv = 1.0f / sqrtf(dd > 1e-30f ? dd : 1e-30f);
        float wx = vx * inv, wy = vy * inv, wz = vz * inv;
        float cr = k->nx[lane] * wx + k->ny[lane] * wy + k->nz[lane] * wz;
        float cs = -(mx * wx + my * wy + mz * wz);
        cr = cr > 0.0f ? cr : 0.0f;
        cs = cs > 0.0f ? cs : 0.0f;
        float d2 = dd > k->md2[lane] ? dd : k->md2[lane];
        float fi = k->ff[lane] * cr * cs / d2;
        fi = occ ? fi : 0.0f;
        k->cf[m] = fi;
        k->cl[0][m] = fi * l0[id];
        k->cl[1][m] = fi * l1[id];
        k->cl[2][m] = fi * l2[id];
    }
    for (int m = 0; m < n; m++) { /* back to the lanes: scattered, scalar */
        int lane = k->list[m];
        k->vis[lane] = k->cocc[m] ? 0.0f : 1.0f;
        if (bounce) {
            k->fsum[lane] += k->cf[m];
            k->br[lane] += k->cl[0][m];
            k->bg[lane] += k->cl[1][m];
            k->bb[lane] += k->cl[2][m];
        }
    }
}

/* Kernel sample s's visibility (and bounce) for the chunk: place, depth test, range
   check. Both nodes call this for s = 0, 1, ... in kernel order; `own_depth` and `bounce`
   are constants at each call site. (Software prefetching of the next sample's depths and
   of the candidates' lines was tried: no measurable gain on the Cornell box.) */
static inline __attribute__((always_inline)) void
ssg_ssdo_sample_counted(const struct ssg_ssdo_job *j, struct ssg_ssdo_chunk *restrict k,
                        int len, int s, int own_depth, int bounce, int counted)
{
    const int count = j->count;
    const float *kx = j->kernel, *ky = kx + count, *kz = ky + count;
    ssg_ssdo_place(j, k, len, kx[s], ky[s], kz[s], s);
    int n = ssg_ssdo_depth_test(j, k, len, own_depth, counted, s);
    if (n)
        ssg_ssdo_range_bounce(j, k, n, bounce);
}

/* The same for every lane (no per-pixel counts): what `bounce` runs. */
static inline __attribute__((always_inline)) void
ssg_ssdo_sample(const struct ssg_ssdo_job *j, struct ssg_ssdo_chunk *restrict k, int len, int s,
                int own_depth, int bounce)
{
    ssg_ssdo_sample_counted(j, k, len, s, own_depth, bounce, 0);
}

/* bounce = albedo(P) sum F_i L_i, the F_i scaled by 1 / sum when the sum exceeds 1;
   0 for the background. out: three planes at the chunk's first pixel. The albedo is
   read unconditionally (harmless: the plane has every pixel). */
static inline __attribute__((always_inline)) void
ssg_ssdo_finish_bounce(const struct ssg_ssdo_job *j, const struct ssg_ssdo_chunk *restrict k,
                       int len, size_t o, float *const out[3])
{
    const float *restrict a0 = j->alb[0] + o, *restrict a1 = j->alb[1] + o;
    const float *restrict a2 = j->alb[2] + o;
    float *restrict o0 = out[0] + o, *restrict o1 = out[1] + o, *restrict o2 = out[2] + o;
    for (int i = 0; i < len; i++) {
        float fs = k->fsum[i];
        float s = fs > 1.0f ? 1.0f / fs : 1.0f;
        float x0 = a0[i] * (k->br[i] * s), x1 = a1[i] * (k->bg[i] * s);
        float x2 = a2[i] * (k->bb[i] * s);
        int fg = k->fg[i] != 0;
        o0[i] = fg ? x0 : 0.0f;
        o1[i] = fg ? x1 : 0.0f;
        o2[i] = fg ? x2 : 0.0f;
    }
}

/* check() of both nodes on the input shapes (channels 0 = unbound); count: ssdo's
   per-pixel count port, NULL for bounce, which has none. */
static inline enum ssg_err ssg_ssdo_check_shapes(const struct ssg_shape *in,
                                                 const struct ssg_shape *count, char *why,
                                                 size_t why_len)
{
    const struct ssg_shape *pos = &in[SSG_SSDO_IN_POSITION], *nrm = &in[SSG_SSDO_IN_NORMAL];
    const struct ssg_shape *ker = &in[SSG_SSDO_IN_KERNEL];
    if (pos->channels != 3 || nrm->channels != 3 || !ssg_shape_same_size(pos, nrm)) {
        snprintf(why, why_len, "position and normal must be 3-channel images of one size");
        return SSG_E_SIZE;
    }
    enum ssg_err e = ssg_sampling_check_inputs(pos, ker, &in[SSG_SSDO_IN_ROTATION],
                                               &in[SSG_SSDO_IN_DEPTH], count, why, why_len);
    if (e)
        return e;
    for (int p = SSG_SSDO_IN_ALBEDO; p <= SSG_SSDO_IN_LIGHT; p++)
        if (in[p].channels != 0 && (in[p].channels != 3 || !ssg_shape_same_size(pos, &in[p]))) {
            snprintf(why, why_len, "%s must be a 3-channel image the size of position",
                     p == SSG_SSDO_IN_ALBEDO ? "albedo" : "light");
            return SSG_E_SIZE;
        }
    return SSG_OK;
}

#endif
