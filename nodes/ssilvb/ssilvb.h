/* ssilvb.h - parameters and prepared constants of the `ssilvb` node, shared by ssilvb.c
 * (descriptor, check, prepare), ssilvb_cpu.c (the CPU kernel) and ssilvb_gl.c (the GL
 * side). Method and conventions are described in ssilvb.c. Read-only after prepare(); the
 * kernel is thread-safe. */
#ifndef SSG_SSILVB_H
#define SSG_SSILVB_H

#include "graph/image.h"
#include "graph/node.h"

#define SSG_SSILVB_MAX_SLICES 32
#define SSG_SSILVB_MAX_STEPS 64
/* Sectors of a slice's bitmask: one 32-bit word (paper sec. 3.2). */
#define SSG_SSILVB_SECTORS 32
/* Levels of the per-pixel slice rotation: the noise picks one of these turns. */
#define SSG_SSILVB_TURNS 64

/* Ports: the descriptor's arrays are indexed by these. */
enum ssg_ssilvb_input {
    SSG_SSILVB_IN_POSITION,
    SSG_SSILVB_IN_NORMAL,
    SSG_SSILVB_IN_DEPTH,
    SSG_SSILVB_IN_LIGHT,
    SSG_SSILVB_IN_ALBEDO,
    SSG_SSILVB_IN_BACK,
    SSG_SSILVB_INPUTS
};
enum ssg_ssilvb_output {
    SSG_SSILVB_OUT_AO,
    SSG_SSILVB_OUT_BOUNCE,
    SSG_SSILVB_OUTPUTS
};

struct ssg_ssilvb_params {
    int slices;              /* slice directions per pixel, 1..32; default 4 */
    int steps;               /* samples per side of a slice, 1..64; default 12 */
    float radius;            /* R, scene units, > 0; default 2 */
    float thickness;         /* t, scene units: a sample occludes from its depth to its
                                depth + t along its ray (`back` unconnected, or where back
                                is not behind the sample); default 0.5 */
    float power;             /* ao = visibility^power, 0.1..8; default 2.5 */
    float strength;          /* bounce scale, 0..16; default 1.2 */
    float max_screen_radius; /* px; caps the march length (0 = no cap); default 0 */
};

struct ssg_ssilvb_consts {
    struct ssg_ssilvb_params p;   /* the parameters as given */
    struct ssg_projection proj;   /* the frame's camera at the G-buffer's resolution */
    float noise_off[4];           /* seed-derived pixel offsets of the two noise patterns
                                     (rotation x, y; jitter x, y), whole numbers */
    float slice_cos[SSG_SSILVB_MAX_SLICES]; /* cos(pi k / slices) */
    float slice_sin[SSG_SSILVB_MAX_SLICES]; /* sin(pi k / slices) */
    float turn_cos[SSG_SSILVB_TURNS];       /* cos(pi (j + 0.5) / (TURNS slices)) */
    float turn_sin[SSG_SSILVB_TURNS];       /* sin of the same */
    /* Per column x of the G-buffer (width w): e1 = (1, 0, a_u) / sqrt(1 + a_u^2), e1x at
       [x] and e1z at [w + x] (ssg_sampling_column_basis); read by both backends. */
    float e1[2 * SSG_IMAGE_MAX_SIDE];
};

/* The descriptor (ssilvb.c); the GL side binds its parameter table. */
extern const struct ssg_node_desc ssg_node_ssilvb;

enum ssg_err ssg_ssilvb_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);
/* The GL side (ssilvb_gl.c, shader ssilvb.glsl). */
enum ssg_err ssg_ssilvb_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);

#endif
