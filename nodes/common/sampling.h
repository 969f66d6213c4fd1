/* sampling.h - what the screen-space sampling nodes (ssao, hbao, ssdo, bounce, complexity)
 * share on the C side: the checks of their optional G-buffer inputs, the camera as the
 * G-buffer's resolution sees it (made once in prepare() for both backends), and the chunk
 * loaders of the CPU kernels (a chunk is up to 128 pixels of one row in structure-of-arrays
 * scratch, so that the per-sample loops vectorise; see ssao_cpu.c). Its GLSL twin is
 * sampling.glsl (the shaders #include it). */
#ifndef SSG_SAMPLING_H
#define SSG_SAMPLING_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "graph/node.h"

/* Pixels of one row a CPU kernel processes at a time (its structure-of-arrays scratch). */
enum { SSG_SAMPLING_CHUNK = 128 };

/* check() of a sampling node: its inputs besides position and normal, against position:
 * the kernel (count x 1, 3 channels; NULL: the node has no kernel input), the optional
 * rotation tile (n x n, 2 channels, or 4 with the length shift), the optional depth and per-pixel count (1 channel,
 * the size of position; count NULL: no such input); channels 0 = unconnected. Returns
 * SSG_OK, or the error code with the reason in why. */
enum ssg_err ssg_sampling_check_inputs(const struct ssg_shape *position,
                                       const struct ssg_shape *kernel,
                                       const struct ssg_shape *rotation,
                                       const struct ssg_shape *depth,
                                       const struct ssg_shape *count, char *why,
                                       size_t why_len);

/* check() of the ambient-occlusion nodes (ssao, hbao, gtao), one copy for the three:
 * position and normal must be 3-channel images of one size (normal channels 0 =
 * unconnected, an optional port), the other inputs as ssg_sampling_check_inputs checks
 * them (kernel and count NULL: the node has no such port); out[0] becomes one channel at
 * position's size (the nodes run at the G-buffer's resolution, which may be a subsampled
 * frame). Returns SSG_OK, or the error code with the reason in why. */
enum ssg_err ssg_sampling_check_ao(const struct ssg_shape *position,
                                   const struct ssg_shape *normal,
                                   const struct ssg_shape *kernel,
                                   const struct ssg_shape *rotation,
                                   const struct ssg_shape *depth,
                                   const struct ssg_shape *count, struct ssg_shape *out,
                                   char *why, size_t why_len);

/* prepare() of a sampling node: the frame's camera as an image of `gbuffer`'s size sees it
 * (ssg_projection_scaled: a subsampled G-buffer sees the same camera). Reports "needs a
 * frame with size and field of view" through ctx and returns SSG_E_VALUE when the frame
 * has neither. */
enum ssg_err ssg_sampling_projection(const struct ssg_node_ctx *ctx,
                                     const struct ssg_shape *gbuffer,
                                     struct ssg_projection *out);

/* Per-frame samples (docs/time.md): what turns a sampling node's directions in frame
 * `frame` of a sequence, so that averaging frames adds samples rather than repeating
 * them. ssg_sampling_frame_turn is frac(frame / phi), the golden-ratio (Kronecker)
 * sequence: any N consecutive frames split [0, 1) into gaps of at most three lengths
 * (the three-distance theorem), the most even 1D sequence that can be extended frame by
 * frame. ssg_sampling_frame_shift is the pixel offset of interleaved gradient noise in
 * that frame, 5.588238 (frame mod 64) (Jimenez 2014, "Next Generation Post Processing in
 * Call of Duty: Advanced Warfare", the temporal variant of ssg_ign). Both are exactly 0
 * in frame 0, where every node gives its single-frame bytes. */
double ssg_sampling_frame_turn(int frame);
float ssg_sampling_frame_shift(int frame);

/* The scalar pass of a chunk holding a normal that is not unit: every normal of the chunk
 * divided by its length (a unit one keeps its bits to within the rounding of 1 / 1). */
static inline void ssg_sampling_normalize(int len, float *restrict nx, float *restrict ny,
                                          float *restrict nz)
{
    for (int i = 0; i < len; i++) {
        float nn = nx[i] * nx[i] + ny[i] * ny[i] + nz[i] * nz[i];
        float inv = 1.0f / sqrtf(nn);
        nx[i] *= inv, ny[i] *= inv, nz[i] *= inv;
    }
}

/* Loads one chunk of row pixels [o, o + len) of the G-buffer planes: P (px, py, pz),
 * the unit normal (nx, ny, nz), the depth dp = sign * depth plane, and fg = 1 on a
 * surface. Background (depth 0, normal 0) or garbage gets fg = 0 and harmless values (N =
 * +z, dp = 1) whose result the caller replaces. Normals are unit by the frame conventions
 * (node.h); the rare chunk holding one that is not gets a scalar pass, so the common case
 * stays a vector loop (sqrtf does not vectorise while it may set errno). Positions load
 * unconditionally (a load under a condition would stop vectorising), in a loop of their
 * own that pos NULL leaves out: a kernel that rebuilds its points from the depth (hbao)
 * passes NULL for pos and px, py, pz. */
static inline __attribute__((always_inline)) void
ssg_sampling_load(const float *const pos[3], const float *const nrm[3], const float *depth,
                  float sign, size_t o, int len, int32_t *restrict fg, float *restrict nx,
                  float *restrict ny, float *restrict nz, float *restrict px,
                  float *restrict py, float *restrict pz, float *restrict dp)
{
    const float *restrict dpl = depth + o;
    const float *restrict nx0 = nrm[0] + o, *restrict ny0 = nrm[1] + o;
    const float *restrict nz0 = nrm[2] + o;
    int not_unit = 0;
    for (int i = 0; i < len; i++) {
        float x = nx0[i], y = ny0[i], z = nz0[i];
        float nn = x * x + y * y + z * z;
        float d = sign * dpl[i];
        int f = (d > 0.0f) & (d <= 3.0e38f) & (nn > 1e-12f);
        not_unit |= f & (fabsf(nn - 1.0f) > 1e-5f);
        fg[i] = f;
        nx[i] = f ? x : 0.0f;
        ny[i] = f ? y : 0.0f;
        nz[i] = f ? z : 1.0f;
        dp[i] = f ? d : 1.0f;
    }
    if (pos) {
        const float *restrict px0 = pos[0] + o, *restrict py0 = pos[1] + o;
        const float *restrict pz0 = pos[2] + o;
        for (int i = 0; i < len; i++) {
            px[i] = px0[i];
            py[i] = py0[i];
            pz[i] = pz0[i];
        }
    }
    if (not_unit)
        ssg_sampling_normalize(len, nx, ny, nz);
}

/* Two consecutive planes of an n x n tile (planar, `tile` the first) for pixels
 * [x0, x0 + len) of row y, into a and b; without a tile (NULL) the constants a0 and b0. */
static inline __attribute__((always_inline)) void
ssg_sampling_tile_pair(const float *tile, int n, int y, int x0, int len, float a0, float b0,
                       float *restrict a, float *restrict b)
{
    if (tile) {
        const float *ra = tile + (size_t)(y % n) * (size_t)n, *rb = ra + (size_t)n * n;
        for (int i = 0, xm = x0 % n; i < len; i++, xm = xm + 1 == n ? 0 : xm + 1) {
            a[i] = ra[xm];
            b[i] = rb[xm];
        }
    } else {
        for (int i = 0; i < len; i++) {
            a[i] = a0;
            b[i] = b0;
        }
    }
}

/* The rotation (cos, sin) of the n x n tile `rot` (planar, cos plane then sin plane) for
 * pixels [x0, x0 + len) of row y; without a tile (rot NULL) no rotation. */
static inline __attribute__((always_inline)) void
ssg_sampling_rotation(const float *rot, int n, int y, int x0, int len, float *restrict co,
                      float *restrict si)
{
    ssg_sampling_tile_pair(rot, n, y, x0, len, 1.0f, 0.0f, co, si);
}

/* The length shift of the tile (halton lengths=shifted, nodes/halton/README.md,
 * "Lengths"): planes 3 and 4 of an n x n rotation tile, `off` the third, for pixels
 * [x0, x0 + len) of row y: dl, the offset of every sample length of the pixel (units of
 * the radius), and k, its sample index shift (a whole number as a float): sample i of the
 * pixel gets the length of kernel sample (i + k) mod K, plus dl. Without them (off NULL)
 * 0 and 0: no change. */
static inline __attribute__((always_inline)) void
ssg_sampling_offsets(const float *off, int n, int y, int x0, int len, float *restrict dl,
                     float *restrict k)
{
    ssg_sampling_tile_pair(off, n, y, x0, len, 0.0f, 0.0f, dl, k);
}

/* The third plane of a rotation tile (the length offsets, the index shifts after them),
 * or NULL when it has two. */
static inline const float *ssg_sampling_offset_plane(const struct ssg_image *rot)
{
    return rot && rot->channels == 4 ? ssg_image_plane(rot, 2) : NULL;
}

/* |s| of a kernel sample: sqrt of the squares summed in x, y, z order (sampling.glsl's
 * ssg_shifted_sample does the same operations). */
static inline float ssg_sampling_len(float sx, float sy, float sz)
{
    return sqrtf(sx * sx + sy * sy + sz * sz);
}

/* 1 / |s| of a kernel sample, 0 for s = 0 (ssdo's per-sample constants). */
static inline float ssg_sampling_inv_len(float sx, float sy, float sz)
{
    float l = ssg_sampling_len(sx, sy, sz);
    return l > 0.0f ? 1.0f / l : 0.0f;
}

/* lens[i] = |s_(i mod K)| for i < 2 K, of the K samples of a planar kernel (x plane, y,
 * z), for the length shift's look-ups: twice over, so that lens[s + k] needs no wrap. */
static inline void ssg_sampling_lengths(const float *kernel, int count, float *lens)
{
    for (int i = 0; i < count; i++) {
        lens[i] = ssg_sampling_len(kernel[i], kernel[count + i], kernel[2 * count + i]);
        lens[count + i] = lens[i];
    }
}

/* Duff et al.'s branch-free orthonormal basis about unit N ("Building an Orthonormal
 * Basis, Revisited", JCGT 2017; -0 counts as negative): T = t, B = b, T x B = N, before
 * the tile's turn. Scalar, inlined into the vector loops of the setups. */
static inline __attribute__((always_inline)) void ssg_sampling_basis(float nx, float ny,
                                                                     float nz, float t[3],
                                                                     float b[3])
{
    float sign = copysignf(1.0f, nz);
    float a = -1.0f / (sign + nz);
    float c = nx * ny * a;
    t[0] = 1.0f + sign * nx * nx * a;
    t[1] = sign * c;
    t[2] = -sign * nx;
    b[0] = c;
    b[1] = sign + ny * ny * a;
    b[2] = -ny;
}

/* Places kernel sample s = (sx, sy, sz) around each of len pixels through their
 * projective coefficients (Z - bias = cz . (1, s), u Z = cu . (1, s), v Z = cv . (1, s),
 * each a plane of 4 x CHUNK floats) and projects it on a w x h image: idx = the pixel it
 * lands on, zb = Z - bias (the depth an occluder must be nearer than), or -1 behind the
 * camera or off screen (no depth > 0 undercuts it: unoccluded, visible). Comparisons are
 * false for NaN, so a degenerate Z lands there too. */
static inline __attribute__((always_inline)) void
ssg_sampling_place_lane(const float (*restrict cz)[SSG_SAMPLING_CHUNK],
                        const float (*restrict cu)[SSG_SAMPLING_CHUNK],
                        const float (*restrict cv)[SSG_SAMPLING_CHUNK], int i, float sx,
                        float sy, float sz, float bias, int w, float fw, float fh,
                        int32_t *restrict idx, float *restrict zbs)
{
    float zb = cz[0][i] + cz[1][i] * sx + cz[2][i] * sy + cz[3][i] * sz;
    float z = zb + bias;
    float nu = cu[0][i] + cu[1][i] * sx + cu[2][i] * sy + cu[3][i] * sz;
    float nv = cv[0][i] + cv[1][i] * sx + cv[2][i] * sy + cv[3][i] * sz;
    float inv = 1.0f / z;
    float u = nu * inv, v = nv * inv;
    int ok = (z > 0.0f) & (u >= 0.0f) & (u < fw) & (v >= 0.0f) & (v < fh);
    /* Select in float, then convert: converting an out-of-range float is undefined. */
    float us = ok ? u : 0.0f, vs = ok ? v : 0.0f;
    idx[i] = (int)vs * w + (int)us;
    zbs[i] = ok ? zb : -1.0f;
}

static inline __attribute__((always_inline)) void
ssg_sampling_place(const float (*restrict cz)[SSG_SAMPLING_CHUNK],
                   const float (*restrict cu)[SSG_SAMPLING_CHUNK],
                   const float (*restrict cv)[SSG_SAMPLING_CHUNK], int len, float sx, float sy,
                   float sz, float bias, int w, int h, int32_t *restrict idx,
                   float *restrict zbs)
{
    const float fw = (float)w, fh = (float)h;
    for (int i = 0; i < len; i++)
        ssg_sampling_place_lane(cz, cu, cv, i, sx, sy, sz, bias, w, fw, fh, idx, zbs);
}

/* The factor g that gives kernel sample s (length ls = lens[s], il = 1 / ls or 0 for
 * ls = 0) of a pixel with length shift (dl, k) its shifted length with its direction: s g
 * has length lens[s + k] + dl (lens twice over: ssg_sampling_lengths). Written
 * 1 + (lens[s + k] - ls + dl) il, so that k = 0 and dl = 0 give exactly 1. */
static inline __attribute__((always_inline)) float
ssg_sampling_shift_factor(const float *restrict lens, int32_t j, float ls, float il, float dl)
{
    return 1.0f + (lens[j] - ls + dl) * il;
}

/* 1 / lens[s], or 0 for a sample of length 0 (which has no direction to keep). */
static inline float ssg_sampling_inv(float ls)
{
    return ls > 0.0f ? 1.0f / ls : 0.0f;
}

/* gs[i] = the factor g of kernel sample s for each of len lanes (dl, k their shifts), in
 * a loop of its own: its look-up at a computed index does not vectorise, and kept out of
 * the placement's loop it leaves that one vectorised. */
static inline __attribute__((always_inline)) void
ssg_sampling_shift_factors(int len, int s, const float *restrict lens,
                           const float *restrict dl, const float *restrict k,
                           float *restrict gs)
{
    const float ls = lens[s], il = ssg_sampling_inv(ls);
    for (int i = 0; i < len; i++)
        gs[i] = ssg_sampling_shift_factor(lens, s + (int32_t)k[i], ls, il, dl[i]);
}

/* The same for kernel sample number s with each pixel's length shift (dl[i], k[i],
 * ssg_sampling_offsets; lens the kernel's lengths twice over, gs scratch for the lanes'
 * factors): the sample s g (ssg_sampling_shift_factor) keeps its direction and takes its
 * shifted length. No shift gives the bits of ssg_sampling_place (g = 1), at the
 * cost of a look-up and a few flops a lane, so callers without a shift call that. */
static inline __attribute__((always_inline)) void
ssg_sampling_place_shifted(const float (*restrict cz)[SSG_SAMPLING_CHUNK],
                           const float (*restrict cu)[SSG_SAMPLING_CHUNK],
                           const float (*restrict cv)[SSG_SAMPLING_CHUNK], int len, float sx,
                           float sy, float sz, int s, const float *restrict lens,
                           const float *restrict dl, const float *restrict k,
                           float *restrict gs, float bias, int w, int h,
                           int32_t *restrict idx, float *restrict zbs)
{
    const float fw = (float)w, fh = (float)h;
    ssg_sampling_shift_factors(len, s, lens, dl, k, gs);
    for (int i = 0; i < len; i++) {
        float g = gs[i];
        ssg_sampling_place_lane(cz, cu, cv, i, sx * g, sy * g, sz * g, bias, w, fw, fh, idx,
                                zbs);
    }
}

/* The samples n a pixel uses of a kernel of k, from its `count` input value v: round(v)
 * (half up), clamped to [1, k]; NaN = k. Selects only, so a loop of it vectorises. */
static inline __attribute__((always_inline)) int ssg_sampling_count(float v, int k)
{
    const float kmax = (float)k;
    v = v < 1.0f ? 1.0f : v;
    v = v <= kmax ? v : kmax; /* NaN fails both compares above: k */
    int n = (int)(v + 0.5f);
    return n < k ? n : k;
}

/* acos by Abramowitz and Stegun 4.4.46 (|error| <= 2e-8 before float rounding), odd
   symmetry about 1/2 pi for x < 0; NaN for |x| > 1: the horizon angles of gtao and ssilvb.
   sampling.glsl's ssg_acos is the same operations. */
static inline __attribute__((always_inline)) float ssg_acos(float x)
{
    float ax = fabsf(x);
    float p = -0.0012624911f;
    p = p * ax + 0.0066700901f;
    p = p * ax - 0.0170881256f;
    p = p * ax + 0.0308918810f;
    p = p * ax - 0.0501743046f;
    p = p * ax + 0.0889789874f;
    p = p * ax - 0.2145988016f;
    p = p * ax + 1.5707963050f;
    float r = sqrtf(1.0f - ax) * p;
    return x < 0.0f ? 3.14159265358979323846f - r : r;
}

#endif
