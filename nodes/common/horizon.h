/* horizon.h - the horizon march the slice nodes (hbao, gtao, ssilvb) share on the CPU; its
 * GLSL twin is horizon.glsl. A horizon node marches, for every surface pixel P, slices of
 * directions about the view vector V on screen, `steps` depth samples on either side, and
 * turns the samples of each side into its integrand: hbao the highest sine (Bavoil et al.),
 * gtao the cosine-weighted arc between the horizons (Jimenez et al.), ssilvb the sectors of
 * a bitmask (Therrien et al.). What is alike lives here, once: the camera and the column
 * basis prepare() makes, the depth padded by one pixel of +inf, the row driver, the chunk
 * of lanes with its per-pixel and per-slice setup, and where each step's samples land
 * together with the folded coefficients of their geometry (nodes/gtao/README.md, "Slices",
 * and the header of gtao_cpu.c). A node writes its integrator alone: its per-slice
 * quantities, what one sample does to them, and how a slice ends.
 *
 * Geometry (per lane): a_u = (x + 0.5 - cx) / f, a_v = -(y + 0.5 - cy) / f, L = |(a_u, a_v,
 * -1)|, V = -(a_u, a_v, -1) / L, the basis e1 = normalize(y x V) (a column's, made once in
 * prepare()), e2 = V x e1, and a slice's D = c e1 + s e2, M = V x D = c e2 - s e1 for its
 * angle turned by the lane's (co, si). A sample at pixel offset (ou, ov) of depth d lies at
 * H'.V = d a + L dp, sg H'.D = d b after the tangent-plane correction (hbao_cpu.c's
 * place_step), H.V = d r + L dp and |H|^2 = (H.V)^2 + d^2 e without it, and counts along
 * the slice when b > |c| (ok). -D's sample is the point reflection (rint is odd).
 *
 * Use (nodes/hbao/hbao_cpu.c is the shortest user): a node's job begins with a struct
 * ssg_horizon_run, which its run_cpu fills (ssg_horizon_gbuffer, then the march's
 * constants and its row function) and hands to ssg_horizon_execute; that function pads the
 * depth and calls the row function for every chunk of every row in fixed bands. The row
 * function, the node's hot code under SSG_VECTOR_CLONES, calls ssg_horizon_load,
 * ssg_horizon_setup, and per slice ssg_horizon_slice and ssg_horizon_fold, per step
 * ssg_horizon_place, all static inline, so that they compile into its vector loops. The
 * run is read-only while the bands run; they share nothing else, so the output does not
 * depend on the thread count. */
#ifndef SSG_HORIZON_H
#define SSG_HORIZON_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "common/sampling.h"
#include "graph/node.h"

/* |proj N|^2 = (V.N)^2 + (D.N)^2 below this: the slice lies within asin(0.1) ~ 5.7 degrees
   of the tangent plane, has no well-conditioned tangent line and adds nothing (gtao's
   README.md); such slices exist only where V.N < 0.1. */
#define SSG_HORIZON_SLICE_MIN 0.01f
#define SSG_HORIZON_HALF_PI 1.57079632679489661923f

enum {
    SSG_HORIZON_CHUNK = SSG_SAMPLING_CHUNK, /* lanes of one chunk */
    SSG_HORIZON_ROWS_PER_BAND = 32,         /* rows of one band (ssg_parallel_rows) */
    SSG_HORIZON_CHUNK_BYTES = 48 * 1024,    /* the most a node's chunk may hold */
};

/* The input port rows hbao and gtao share, one copy of their docs (node.h's one-line
 * rows), given the node's four enumerators in this order and what the directions are
 * called (the rotation's "none = fixed <what>"). */
#define SSG_HORIZON_IN(X, position, normal, rotation, depth, what)                         \
    X(position, "position", SSG_T_VECTOR,                                                  \
      "view-space position (its -z is the depth unless depth is given)")                   \
    X(normal, "normal", SSG_T_VECTOR, "unit view-space normal")                            \
    X(rotation, "rotation", SSG_T_PATTERN,                                                 \
      "per-pixel rotation tile (halton.rotation); none = fixed " what, .optional = 1)      \
    X(depth, "depth", SSG_T_SCALAR,                                                        \
      "linear depth the points are reconstructed from; none = -position.z", .optional = 1)

/* prepare() of a horizon node: the camera as `gbuffer`'s size sees it (ssg_sampling_projection,
 * whose error it returns before anything else), *invf = 1 / f for both backends, and the
 * column basis e1 for its width: e1 = normalize(y x V) = (1, 0, a_u) / sqrt(1 + a_u^2)
 * depends on the column x only; e1x for the w columns goes to e1[0..w), e1z to e1[w..2w). */
enum ssg_err ssg_horizon_frame(const struct ssg_node_ctx *ctx, const struct ssg_shape *gbuffer,
                               struct ssg_projection *proj, float *invf, float *e1);

/* consts_size_of of a horizon node: its consts struct of `head` bytes ending in the column
 * table e1 (2 floats a column of `position`). */
static inline size_t ssg_horizon_consts_size(size_t head, const struct ssg_shape *position)
{
    return head + 2 * (size_t)position->width * sizeof(float);
}

/* The azimuth tables: co[k], si[k] = cos, sin of turn (k + shift) / n for k < n, in double
 * rounded to float (turn 2 pi: hbao's directions round the circle; pi: the slices over the
 * half circle; shift 0 for a fixed table, ssg_sampling_frame_turn for a frame's). */
void ssg_horizon_angles(int n, double turn, double shift, float *co, float *si);

struct ssg_horizon_run;
/* A node's row function: row y's chunk of columns [x0, x0 + len) (len <= SSG_HORIZON_CHUNK),
 * with `chunk` its scratch (SSG_HORIZON_CHUNK_BYTES, 64-byte aligned, kept from one call
 * to the next in a band). r is the first member of the node's job. */
typedef void (*ssg_horizon_row_fn)(const struct ssg_horizon_run *r, void *chunk, int y, int x0,
                                   int len);

/* One run of a horizon node's CPU kernel: the first member of its job. */
struct ssg_horizon_run {
    /* The G-buffer (ssg_horizon_gbuffer) */
    int w, h;              /* its size */
    const float *nrm[3];   /* planes of the unit normal */
    const float *depth;    /* plane the depth is read from */
    float depth_sign;      /* depth = depth_sign * plane: 1 for depth, -1 for z */
    /* The march, from the node's consts */
    struct ssg_projection proj; /* the camera at the G-buffer's resolution */
    float invf;            /* 1 / f */
    const float *e1;       /* the column basis (ssg_horizon_frame) */
    float radius;          /* R, scene units */
    float cap;             /* cap of the projected radius f R / den, px; 0 = none */
    int steps;             /* samples on each side of a slice */
    const float *back;     /* a second depth plane, padded alike (gtao's back); NULL = none */
    ssg_horizon_row_fn row;
    /* Set by ssg_horizon_execute */
    int pw;                /* w + 2, the padded planes' row length */
    float *padded;         /* the depth, (w + 2) x (h + 2), with background (0), garbage
                              (negative, NaN, inf) and a one-pixel border set to +inf */
    float *padded_back;    /* back padded likewise; NULL without back */
};

/* The G-buffer's part of r: its size, the normal's planes, and the depth (the depth input,
 * or -position.z without it). */
void ssg_horizon_gbuffer(struct ssg_horizon_run *r, const struct ssg_image *position,
                         const struct ssg_image *normal, const struct ssg_image *depth);

/* Pads the depth (and back) into the node's scratch, then calls r->row for every chunk of
 * every row: bands of SSG_HORIZON_ROWS_PER_BAND rows in parallel, chunk columns outside and
 * rows inside, so the depth window around a chunk (the march reaches 150-300 px at 1080p,
 * more than L2 holds) slides down one row at a time. Returns SSG_OK, or fails ctx with
 * SSG_E_NOMEM. */
enum ssg_err ssg_horizon_execute(const struct ssg_node_ctx *ctx, struct ssg_horizon_run *r);

/* Rows [y0, y1) of the w-wide `depth` (times sign) into rows y0 + 1 .. of `padded` (w + 2
 * wide), background (0), garbage (negative, NaN, inf) and the border column +inf. */
void ssg_horizon_pad_depth(const float *depth, float sign, int w, int y0, int y1,
                           float *padded);

/* The index in a padded plane (row length pw, based one row and one column in) of the
 * sample at (x + ou, y + ov). A sample off screen is clamped into the border, whose infinite
 * depth makes it no occluder: the clamp replaces a test (ou, ov are finite: rounded
 * products of finite values). */
static inline __attribute__((always_inline)) int32_t
ssg_horizon_padded_index(float x, float y, float ou, float ov, float fw, float fh, int pw)
{
    float su = x + ou, sv = y + ov;
    su = su < -1.0f ? -1.0f : su;
    su = su < fw ? su : fw;
    sv = sv < -1.0f ? -1.0f : sv;
    sv = sv < fh ? sv : fh;
    return (int)sv * pw + (int)su;
}

/* The lanes of one chunk, structure of arrays; a lane is a surface pixel, packed into the
   first lanes (xs: its column within the chunk). Every array starts on a cache line
   (CHUNK floats are whole lines), so vector loads never straddle two. */
struct ssg_horizon_lanes {
    /* per pixel */
    _Alignas(64) float dp[SSG_HORIZON_CHUNK];   /* depth of P */
    float nx[SSG_HORIZON_CHUNK], ny[SSG_HORIZON_CHUNK], nz[SSG_HORIZON_CHUNK]; /* unit N */
    int32_t fg[SSG_HORIZON_CHUNK];   /* by column: 1 = surface, 0 = background */
    int32_t xs[SSG_HORIZON_CHUNK];   /* column within the chunk of each lane */
    float xf[SSG_HORIZON_CHUNK];     /* pixel column */
    float co[SSG_HORIZON_CHUNK], si[SSG_HORIZON_CHUNK]; /* the lane's turn of the slices
                                                          (the node's) */
    float u[SSG_HORIZON_CHUNK];      /* step jitter in (0, 1] (the node's) */
    float lp[SSG_HORIZON_CHUNK], ldp[SSG_HORIZON_CHUNK]; /* L = |P| / dp, L dp */
    float v[3][SSG_HORIZON_CHUNK];   /* V */
    float vxf[SSG_HORIZON_CHUNK], vyf[SSG_HORIZON_CHUNK]; /* Vx / f, -Vy / f */
    float e1x[SSG_HORIZON_CHUNK], e1z[SSG_HORIZON_CHUNK]; /* e1 = (e1x, 0, e1z) */
    float e2[3][SSG_HORIZON_CHUNK];  /* e2 = V x e1 */
    float e1n[SSG_HORIZON_CHUNK], e2n[SSG_HORIZON_CHUNK]; /* e1.N, e2.N */
    float au[SSG_HORIZON_CHUNK], av[SSG_HORIZON_CHUNK];   /* a_u, a_v of P's pixel */
    float vn[SSG_HORIZON_CHUNK];     /* V.N, floored at 1e-6 */
    float step[SSG_HORIZON_CHUNK];   /* march length / steps, px */
    /* per slice (ssg_horizon_slice, ssg_horizon_fold) */
    float du[SSG_HORIZON_CHUNK], dv[SSG_HORIZON_CHUNK];   /* screen step of D, px */
    float dxf[SSG_HORIZON_CHUNK], dyf[SSG_HORIZON_CHUNK]; /* Dx / f, -Dy / f */
    float mxf[SSG_HORIZON_CHUNK], myf[SSG_HORIZON_CHUNK]; /* Mx / f, -My / f */
    float ax[SSG_HORIZON_CHUNK], ay[SSG_HORIZON_CHUNK];   /* a = ou ax + ov ay -/+ L */
    float bx[SSG_HORIZON_CHUNK], by[SSG_HORIZON_CHUNK];   /* b = ou bx + ov by */
};

/* Loads row y's pixels [x0, x0 + len) (ssg_sampling_load: fg, the unit normal, the depth)
   and keeps the surface ones, packed into the first lanes with their columns xs and xf:
   background (depth 0 or no normal) costs nothing more, which matters where the scene
   leaves much of the frame empty. Packing moves a lane only to a lower one, so it runs in
   place. Returns the number of lanes; the node then sets their co, si and u
   (ssg_horizon_pack). */
static inline __attribute__((always_inline)) int
ssg_horizon_load(const struct ssg_horizon_run *r, struct ssg_horizon_lanes *restrict k, int y,
                 int x0, int len)
{
    size_t o = (size_t)y * (size_t)r->w + (size_t)x0;
    ssg_sampling_load(NULL, r->nrm, r->depth, r->depth_sign, o, len, k->fg, k->nx, k->ny,
                      k->nz, NULL, NULL, NULL, k->dp);
    int all = 1;
    for (int i = 0; i < len; i++)
        all &= k->fg[i];
    if (all) { /* the common case, a chunk all surface: straight vector stores */
        for (int i = 0; i < len; i++) {
            k->xs[i] = i;
            k->xf[i] = (float)(x0 + i);
        }
        return len;
    }
    int m = 0;
    for (int i = 0; i < len; i++) {
        if (!k->fg[i])
            continue;
        k->xs[m] = i;
        k->xf[m] = (float)(x0 + i);
        k->nx[m] = k->nx[i];
        k->ny[m] = k->ny[i];
        k->nz[m] = k->nz[i];
        k->dp[m] = k->dp[i];
        m++;
    }
    return m;
}

/* Per-column values of the chunk (v[x] for its len columns) kept for its m lanes: v[i] =
   v[xs[i]], in place (xs[i] >= i, and rises); nothing to move when every column is a
   lane. A node fills its per-column turn and jitter this way, in straight loops over the
   columns. */
static inline __attribute__((always_inline)) void
ssg_horizon_pack(const struct ssg_horizon_lanes *restrict k, int m, int len, float *v)
{
    for (int i = 0; m < len && i < m; i++)
        v[i] = v[k->xs[i]];
}

/* The m lanes' values v written to the chunk's len columns of out, `background` where a
   column is no lane: a straight copy when every column is a lane, so the common case
   stays a vector loop (a scatter does not vectorise). */
static inline __attribute__((always_inline)) void
ssg_horizon_unpack(const struct ssg_horizon_lanes *restrict k, int m, int len,
                   const float *restrict v, float *restrict out, float background)
{
    if (m == len) {
        for (int i = 0; i < len; i++)
            out[i] = v[i];
        return;
    }
    for (int i = 0; i < len; i++)
        out[i] = background;
    for (int i = 0; i < m; i++)
        out[k->xs[i]] = v[i];
}

/* What depends on the pixel only, for lanes [0, m) of row y: V, e2 = V x e1, the tangent
   term V.N and the march length f R / den (den = max(dp - R, dp / 2), the nearest depth of
   the march), capped, per step. one_division (a constant at each call site) takes 1 / L
   and 1 / den from one division, 1 / (L den): hbao's rounding; else 1 / L and f R / den
   (gtao, ssilvb). Both are kept for the bits each node's outputs have. */
static inline __attribute__((always_inline)) void
ssg_horizon_setup(const struct ssg_horizon_run *r, struct ssg_horizon_lanes *restrict k,
                  int y, int x0, int m, int one_division)
{
    const float invf = r->invf, radius = r->radius, cap = r->cap;
    const float rf = r->proj.f * radius, fs = (float)r->steps, inv_steps = 1.0f / fs;
    const float cx = r->proj.cx, av = -((float)y + 0.5f - r->proj.cy) * invf;
    const float *e1x = r->e1 + x0, *e1z = r->e1 + r->w + x0;
    for (int i = 0; i < m; i++) {
        float au = (k->xf[i] + 0.5f - cx) * invf;
        float l = sqrtf(au * au + av * av + 1.0f);
        float dp = k->dp[i], near = dp - radius, half = 0.5f * dp;
        float den = near > half ? near : half;
        float inv = one_division ? 1.0f / (l * den) : 0.0f;
        float il = one_division ? den * inv : 1.0f / l;
        float rp = one_division ? rf * l * inv : rf / den;
        float vx = -au * il, vy = -av * il, vz = il;
        float ex = e1x[k->xs[i]], ez = e1z[k->xs[i]];
        float e2x = vy * ez, e2y = vz * ex - vx * ez, e2z = -vy * ex;
        float nx = k->nx[i], ny = k->ny[i], nz = k->nz[i];
        float vn = vx * nx + vy * ny + vz * nz;
        k->au[i] = au, k->av[i] = av, k->lp[i] = l, k->ldp[i] = l * dp;
        k->v[0][i] = vx, k->v[1][i] = vy, k->v[2][i] = vz;
        k->vxf[i] = vx * invf, k->vyf[i] = -vy * invf;
        k->e1x[i] = ex, k->e1z[i] = ez;
        k->e2[0][i] = e2x, k->e2[1][i] = e2y, k->e2[2][i] = e2z;
        k->e1n[i] = ex * nx + ez * nz;
        k->e2n[i] = e2x * nx + e2y * ny + e2z * nz;
        k->vn[i] = vn > 1e-6f ? vn : 1e-6f;
        rp = cap > 0.0f && rp > cap ? cap : rp;
        k->step[i] = one_division ? rp * inv_steps : rp / fs;
    }
}

/* A slice of lane i: D, M and N's components dn = D.N, mn = M.N, and |proj N|^2 = sl. */
struct ssg_horizon_dir {
    float dx, dy, dz, dn, mn, sl;
};

/* Slice angle (dc, ds) turned by lane i's (co, si): sets its screen step (du, dv) (J D up
   to the factor f / depth, not normalised: `steps` steps of it reach f R |J D| / den,
   exactly the bound of gtao's README.md for this slice) and D / f, M / f; returns D and
   N's components, from which the node takes its isl (ssg_horizon_fold). */
static inline __attribute__((always_inline)) struct ssg_horizon_dir
ssg_horizon_slice(struct ssg_horizon_lanes *restrict k, int i, float dc, float ds, float invf)
{
    float c = dc * k->co[i] - ds * k->si[i], s = ds * k->co[i] + dc * k->si[i];
    float dx = c * k->e1x[i] + s * k->e2[0][i], dy = s * k->e2[1][i];
    float dz = c * k->e1z[i] + s * k->e2[2][i];
    /* M = V x D = c e2 - s e1 (V x e1 = e2, V x e2 = -e1); N's components on the turned
       basis come from those on e1, e2. */
    float mx = c * k->e2[0][i] - s * k->e1x[i], my = c * k->e2[1][i];
    float dn = c * k->e1n[i] + s * k->e2n[i], mn = c * k->e2n[i] - s * k->e1n[i];
    float vn = k->vn[i];
    k->du[i] = (dx + k->au[i] * dz) * k->step[i];
    k->dv[i] = -(dy + k->av[i] * dz) * k->step[i];
    k->dxf[i] = dx * invf, k->dyf[i] = -dy * invf;
    k->mxf[i] = mx * invf, k->myf[i] = -my * invf;
    return (struct ssg_horizon_dir){dx, dy, dz, dn, mn, vn * vn + dn * dn};
}

/* The tangent-plane correction folded into lane i's coefficients, isl = mn / sl (each
   node rounds it its own way). The rounding to pixels moves a sample off the slice by
   hm = H.M; it is brought back along the tangent plane, H' = H - hm M' / (M'.M) with
   M' = M - (M.N) N, so H'.V = H.V + hm al and H'.D = H.D + hm be (al = isl V.N,
   be = isl D.N): a sample of the tangent plane lands on the slice's tangent line, and a
   flat surface stays exactly unoccluded whatever the rounding (hbao_cpu.c). */
static inline __attribute__((always_inline)) void
ssg_horizon_fold(struct ssg_horizon_lanes *restrict k, int i, float dn, float isl)
{
    float al = isl * k->vn[i], be = isl * dn;
    k->ax[i] = k->vxf[i] + k->mxf[i] * al;
    k->ay[i] = k->vyf[i] + k->myf[i] * al;
    k->bx[i] = k->dxf[i] + k->mxf[i] * be;
    k->by[i] = k->dyf[i] + k->myf[i] * be;
}

/* The slice of lane i (ssg_horizon_slice) with the normal projected on it: its length
   pl = |proj N| and its angle n from V as cos n, sin n (the frame of the cosine-weighted
   methods, gtao and ssilvb). */
struct ssg_horizon_arc {
    struct ssg_horizon_dir d;
    float pl, cn, sn;
};

/* ssg_horizon_slice and ssg_horizon_fold with isl = mn / sl, for the slice's normal frame. */
static inline __attribute__((always_inline)) struct ssg_horizon_arc
ssg_horizon_slice_arc(struct ssg_horizon_lanes *restrict k, int i, float dc, float ds,
                      float invf)
{
    struct ssg_horizon_dir d = ssg_horizon_slice(k, i, dc, ds, invf);
    float pl = sqrtf(d.sl);
    ssg_horizon_fold(k, i, d.dn, d.mn / d.sl);
    return (struct ssg_horizon_arc){d, pl, k->vn[i] / pl, d.dn / pl};
}

/* One step of lane i on both sides (side 0: +D at (ou, ov), side 1: -D at (-ou, -ov)):
   with the sample's depth d, H'.V = d a[m] + L dp, sg H'.D = d b, H.V = d r[m] + L dp,
   |H|^2 = (H.V)^2 + d^2 e; ok when the sample lies more along the slice than off it
   (b > |c|, c = H.M / d); idx[m] its index in the padded planes. A node keeps what its
   integrator reads; the compiler drops the rest. */
struct ssg_horizon_step {
    float ou, ov;       /* +D's offset, px */
    float a[2], r[2];   /* per side */
    float b, c, e;
    int32_t ok;
    int32_t idx[2];     /* per side */
};

/* The image's bounds as ssg_horizon_place reads them: taken once before a loop, in locals
   (read through the run inside it, they could alias the loop's stores as far as the
   compiler knows, which keeps the loop scalar). */
struct ssg_horizon_bounds {
    float fw, fh; /* width and height */
    int pw;       /* the padded planes' row length */
};

static inline struct ssg_horizon_bounds ssg_horizon_bounds(const struct ssg_horizon_run *r)
{
    return (struct ssg_horizon_bounds){(float)r->w, (float)r->h, r->pw};
}

/* Step sf of lane i of row y: the sample lies at (sf + u) step along the screen
   direction, rounded to the nearest pixel (ties to even). */
static inline __attribute__((always_inline)) struct ssg_horizon_step
ssg_horizon_place(struct ssg_horizon_bounds bo, const struct ssg_horizon_lanes *restrict k,
                  int i, float y, float sf)
{
    struct ssg_horizon_step s;
    float t = sf + k->u[i];
    float ou = nearbyintf(k->du[i] * t), ov = nearbyintf(k->dv[i] * t);
    float pa = ou * k->ax[i] + ov * k->ay[i];
    float b = ou * k->bx[i] + ov * k->by[i];
    float c = ou * k->mxf[i] + ov * k->myf[i];
    float pr = ou * k->vxf[i] + ov * k->vyf[i], bd = ou * k->dxf[i] + ov * k->dyf[i];
    float l = k->lp[i];
    s.ou = ou, s.ov = ov, s.b = b, s.c = c;
    s.ok = b > fabsf(c);
    s.e = bd * bd + c * c;
    s.a[0] = pa - l, s.a[1] = -(pa + l);
    s.r[0] = pr - l, s.r[1] = -(pr + l);
    s.idx[0] = ssg_horizon_padded_index(k->xf[i], y, ou, ov, bo.fw, bo.fh, bo.pw);
    s.idx[1] = ssg_horizon_padded_index(k->xf[i], y, -ou, -ov, bo.fw, bo.fh, bo.pw);
    return s;
}

/* The padded depth plane based one row and one column in: sample index idx reads it. */
static inline const float *ssg_horizon_plane(const struct ssg_horizon_run *r, const float *p)
{
    return p + r->pw + 1;
}

/* Interleaved gradient noise (Jimenez 2014) at (x, y): in [0, 1) (horizon.glsl's ssg_ign):
   gtao's step jitter, ssilvb's turn and jitter. */
static inline __attribute__((always_inline)) float ssg_ign(float x, float y)
{
    float a = 0.06711056f * x + 0.00583715f * y;
    float b = 52.9829189f * (a - floorf(a));
    return b - floorf(b);
}

#endif
