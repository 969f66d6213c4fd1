/* halton.h - the parameters and constants of the `halton` node, shared by halton.c
 * (descriptor, check, prepare), halton_pattern.c (the rotation tiles), halton_cpu.c and
 * halton_gl.c (the copies into the outputs) and test_halton*.c here; the radical inverse
 * it is built on is core/scene/radical_inverse.h, which the environment's lights and a
 * graph's `jitter` line share.
 *
 * Method (the Halton sequence, eq. 5-7, and its period property, eq. 8): README.md in
 * this folder. Everything here is pure and thread-safe. */
#ifndef SSG_HALTON_H
#define SSG_HALTON_H

#include <stdint.h>

#include "scene/radical_inverse.h"
#include "graph/node.h"

/* Ports, one row each (node.h): enumerator, name, types, doc. */
#define SSG_HALTON_OUT(X)                                                                  \
    X(SSG_HALTON_OUT_SAMPLES, "samples", SSG_T_KERNEL,                                     \
      "count x 1 tangent-space offsets in the unit hemisphere around +z")                  \
    X(SSG_HALTON_OUT_ROTATION, "rotation", SSG_T_PATTERN,                                  \
      "n x n tile of (cos, sin) of a rotation about the normal; lengths=shifted adds the "  \
      "pixel's length offset (fraction of the radius) and its sample index shift")
SSG_PORT_ENUM(ssg_halton_output, SSG_HALTON_OUT, SSG_HALTON_OUTPUTS);

#define SSG_HALTON_MAX_COUNT 1024  /* most kernel samples */
#define SSG_HALTON_MAX_PATTERN 64  /* largest rotation tile side */

enum ssg_halton_mapping {
    SSG_HALTON_COSINE,  /* cosine-weighted hemisphere (Malley's method) */
    SSG_HALTON_UNIFORM, /* uniform over the hemisphere's solid angle */
};

/* Whether every pixel uses the kernel's lengths or its own (README.md, "Lengths"). */
enum ssg_halton_lengths {
    SSG_HALTON_SHARED,  /* every pixel the kernel's lengths (the papers' kernel) */
    SSG_HALTON_SHIFTED, /* per pixel a Cranley-Patterson shift of the lengths (planes 3, 4) */
};

/* How the rotation tile is laid out (halton_pattern.c). */
enum ssg_halton_rotations {
    SSG_HALTON_TILE,        /* n*n van der Corput angles, seeded permutation (white) */
    SSG_HALTON_INTERLEAVED, /* n angles on a Latin square: rows and columns hold each once */
    SSG_HALTON_BLUE_NOISE,  /* n*n angles on a void-and-cluster rank map (Ulichney 1993) */
};

/* The parameters, one row each (lang/params.h): kind, field, doc, then default, range,
   unit and choices. No shader reads them: prepare() makes the kernel and the tile. */
#define SSG_HALTON_PARAMS(P)                                                               \
    P(INT, count, "kernel samples", .def = 16, .min = 1, .max = SSG_HALTON_MAX_COUNT,      \
      .soft_min = 1, .soft_max = 256,                                                      \
      .unit = "samples")                                                                   \
    P(INTS, bases, "distinct primes: elevation, azimuth, optional length (eq. 7)",         \
      .def_ints = {2, 3}, .def_ints_count = 2, .min_count = 2, .max_count = 3, .min = 2,   \
      .max = 997)                                                                          \
    P(INT, offset, "first sequence index (0 is the point 0,0,0)", .def = 1, .min = 0,      \
      .max = 1000000000, .soft_min = 0, .soft_max = 1024)                                  \
    P(INT, period,                                                                         \
      "eq. 8 period N_g: blocks of N_g samples alike, prefixes quasi-uniform; 0 = off",    \
      .def = 0, .min = 0, .max = SSG_HALTON_MAX_COUNT, .soft_min = 0, .soft_max = 64,      \
      .unit = "samples")                                                                   \
    P(ENUM, mapping, "direction density over the hemisphere", .def = SSG_HALTON_COSINE,    \
      .choices = ssg_halton_mapping_choices)                                               \
    P(FLOAT, falloff,                                                                      \
      "length = lerp(min_scale, 1, t^falloff): > 1 packs samples near the centre",         \
      .def = 2, .min = 0.01, .max = 16, .soft_min = 0.25, .soft_max = 4)                   \
    P(FLOAT, min_scale, "shortest sample length as a fraction of the radius", .def = 0.1,  \
      .min = 0, .max = 1, .soft_min = 0, .soft_max = 1)                                    \
    P(INT, pattern, "side of the tiled rotation pattern", .def = 4, .min = 1,              \
      .max = SSG_HALTON_MAX_PATTERN, .soft_min = 1, .soft_max = 16, .unit = "px")          \
    P(ENUM, rotations,                                                                     \
      "tile layout: tile = n*n angles, white; interleaved = n angles, every row and "      \
      "column holds each once; blue_noise = n*n angles, void-and-cluster (n = 64)",        \
      .def = SSG_HALTON_TILE, .choices = ssg_halton_rotations_choices)                   \
    P(ENUM, lengths,                                                                       \
      "shared = every pixel the kernel's sample lengths; shifted = per pixel a "           \
      "Cranley-Patterson shift of the length coordinate (needs falloff=1, 2 bases)",       \
      .def = SSG_HALTON_SHARED, .choices = ssg_halton_lengths_choices)
SSG_PARAMS_STRUCT(ssg_halton_params, SSG_HALTON_PARAMS);

/* What prepare() computes and both backends read: images in the planar layout of
 * ssgraph.h, ready to be copied into the outputs: frame 0's. A later frame of a sequence
 * is made from them and p by ssg_halton_frame. */
struct ssg_halton_consts {
    struct ssg_halton_params p; /* the parameters as given */
    int count;  /* kernel samples (kernel image width) */
    int n;      /* rotation tile side (pattern image width and height) */
    int planes; /* pattern planes: 2 (cos, sin), 4 with lengths=shifted (offset, shift) */
    float kernel[3 * SSG_HALTON_MAX_COUNT];                       /* x plane, y, z */
    float pattern[4 * SSG_HALTON_MAX_PATTERN * SSG_HALTON_MAX_PATTERN]; /* cos, sin, dl, k */
    /* lengths=shifted: each cell's place in its samples' strata in frame 0, (j + 1/2) / n
       for the cell's Latin-square level j; in [0, 1) */
    double place[SSG_HALTON_MAX_PATTERN * SSG_HALTON_MAX_PATTERN];
};

/* The unit-cube point behind kernel sample `sample` (0-based): u[0], u[1] drive the
 * direction (eq. 7 with the first two bases at index offset + sample), u[2] the length
 * (third base, else the stratified value described in README.md). */
void ssg_halton_point(const struct ssg_halton_params *p, int sample, double u[3]);
/* The same in frame `frame` of a sequence (README.md, "Frames"): Halton index offset +
 * frame * count + sample, so N frames of count samples use N * count distinct points; a
 * stratified length moves within its stratum by the golden-ratio sequence. Frame 0 is
 * ssg_halton_point. */
void ssg_halton_point_at(const struct ssg_halton_params *p, int frame, int sample,
                         double u[3]);

/* Kernel (3 * count floats, planar) and rotation tile (planes * n * n floats) of frame
 * `frame` from prepare()'s constants: the kernel of ssg_halton_point_at, the tile turned
 * about the normal by 2 pi ssg_sampling_frame_turn(frame), the length offsets of
 * ssg_halton_length_offset. Frame 0 copies the constants' bytes. Both backends run this,
 * so they copy the same floats. */
void ssg_halton_frame(const struct ssg_halton_consts *c, int frame, float *kernel,
                      float *pattern);

/* lengths=shifted: the offset (fraction of the radius) that moves every sample length
 * of a pixel whose cell has place `place` (consts.place) in frame `frame`: from its
 * place in its stratum of the length coordinate t (the stratified value of
 * ssg_halton_point_at: the stratum's middle in frame 0, then the golden-ratio sequence)
 * to frac(place + ssg_sampling_frame_turn(frame)); the length is linear in t (falloff 1),
 * so the offset is (1 - min_scale) (that - mid) / count, the same for every sample. */
double ssg_halton_length_offset(const struct ssg_halton_params *p, int frame, double place);

/* The cells of lengths=shifted (halton_pattern.c; a stream of its own: the rotation
 * tiles keep theirs), from three Latin squares Q, A, B = (s(x) + t(y)) mod n, each with
 * its own seeded permutations s and t, so that every row and every column holds each of
 * their n values once: place[y * n + x] = (Q + 1/2) / n, and the index shift k of
 * README.md, "Lengths", shift[i] = floor(count (n A + B) / n^2): every row and every
 * column holds each of the n blocks floor(k n / count) of sample indices once. */
void ssg_halton_make_places(int n, int count, uint64_t seed, double *place, float *shift);

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
enum ssg_err ssg_halton_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);
/* The GL backend (halton_gl.c, ssg_gl_fill): the same copy on the GPU. */
enum ssg_err ssg_halton_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
