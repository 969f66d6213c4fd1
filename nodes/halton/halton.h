/* halton.h - the parameters and constants of the `halton` node, and the radical inverse
 * it is built on, shared by halton.c (descriptor, check, prepare), halton_cpu.c and
 * halton_gl.c (the copies into the outputs) and tests/test_halton.c.
 *
 * Method: Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", section 4.2:
 * the Halton sequence (eq. 5-7) and its period property (eq. 8). Everything here is pure
 * and thread-safe. */
#ifndef SSG_HALTON_H
#define SSG_HALTON_H

#include <stdint.h>

#include "lang/params.h"

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_halton_output {
    SSG_HALTON_OUT_SAMPLES,
    SSG_HALTON_OUT_ROTATION,
    SSG_HALTON_OUTPUTS
};

#define SSG_HALTON_MAX_COUNT 1024  /* most kernel samples */
#define SSG_HALTON_MAX_PATTERN 64  /* largest rotation tile side */

enum ssg_halton_mapping {
    SSG_HALTON_COSINE,  /* cosine-weighted hemisphere (Malley's method) */
    SSG_HALTON_UNIFORM, /* uniform over the hemisphere's solid angle */
};

/* How the rotation tile is laid out (halton_pattern.c). */
enum ssg_halton_rotations {
    SSG_HALTON_TILE,        /* n*n van der Corput angles, seeded permutation (white) */
    SSG_HALTON_INTERLEAVED, /* n angles on a Latin square: rows and columns hold each once */
    SSG_HALTON_BLUE_NOISE,  /* n*n angles on a void-and-cluster rank map (Ulichney 1993) */
};

/* Parameters as the graph file sets them (see the table in halton.c). */
struct ssg_halton_params {
    int count;             /* kernel samples, 1..1024; default 16 */
    struct ssg_ints bases; /* 2 or 3 distinct primes: direction bases, then an optional
                              radius base; default [2, 3] */
    int offset;            /* first sequence index, >= 0; default 1 (index 0 is the point
                              (0, 0, 0) in every base) */
    int period;            /* eq. 8 period N_g in samples, 0 = off; default 0 */
    int mapping;           /* enum ssg_halton_mapping; default cosine */
    float falloff;         /* exponent of the length curve, > 0; default 2 */
    float min_scale;       /* shortest sample length, fraction of the radius; default 0.1 */
    int pattern;           /* rotation tile side n in pixels, 1..64; default 4 */
    int rotations;         /* enum ssg_halton_rotations: the tile's layout; default tile */
};

/* What prepare() computes and both backends read: images in the planar layout of
 * ssgraph.h, ready to be copied into the outputs. */
struct ssg_halton_consts {
    int count;  /* kernel samples (kernel image width) */
    int n;      /* rotation tile side (pattern image width and height) */
    float kernel[3 * SSG_HALTON_MAX_COUNT];                       /* x plane, y, z */
    float pattern[2 * SSG_HALTON_MAX_PATTERN * SSG_HALTON_MAX_PATTERN]; /* cos plane, sin */
};

/* Radical inverse Phi_b(i) of eq. 6: the base-b digits of i (eq. 5) mirrored about the
 * radix point. Exact (correctly rounded) for i < 2^32 and b <= 1000. */
double ssg_halton_radical_inverse(uint64_t i, int base);

/* The unit-cube point behind kernel sample `sample` (0-based): u[0], u[1] drive the
 * direction (eq. 7 with the first two bases at index offset + sample), u[2] the length
 * (third base, else the stratified value described in halton.c). */
void ssg_halton_point(const struct ssg_halton_params *p, int sample, double u[3]);

/* Largest k with base^k dividing period (0 when period <= 0): the number of leading
 * digits that eq. 8 guarantees samples sample and sample + m*period share. */
int ssg_halton_period_digits(int period, int base);

/* The rotation tile of layout `kind` (enum ssg_halton_rotations), side n (1..64), as
 * (cos, sin) planes of n*n floats each, from the frame seed (halton_pattern.c). Returns 0
 * when out of memory (blue_noise's work buffers), else 1. Pure, thread-safe. */
int ssg_halton_make_pattern(int kind, int n, uint64_t seed, float *pattern);

/* The void-and-cluster rank map (Ulichney 1993) of the n x n torus behind blue_noise:
 * rank[y * n + x] in 0..n*n-1, each once, from the seed. Returns 0 when out of memory. */
int ssg_halton_blue_noise_ranks(int n, uint64_t seed, int *rank);

/* The CPU backend (halton_cpu.c): copies the prepared kernel and tile into the outputs. */
struct ssg_node_ctx;
struct ssg_io;
enum ssg_err ssg_halton_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);
/* The GL backend (halton_gl.c, ssg_gl_fill): the same copy on the GPU. */
enum ssg_err ssg_halton_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
