/* gtao.h - parameters and prepared constants of the `gtao` node, shared by gtao.c
 * (descriptor, check, prepare), gtao_cpu.c (the CPU kernel) and gtao_gl.c (the GL side).
 * Method and conventions are described in gtao.c. Read-only after prepare(); the kernel
 * is thread-safe. */
#ifndef SSG_GTAO_H
#define SSG_GTAO_H

#include "graph/image.h"
#include "graph/node.h"

#define SSG_GTAO_MAX_SLICES 32
#define SSG_GTAO_MAX_STEPS 64
/* With back: the side's previous sample links to a sample lying at most this times R
   behind its back (gtao.c). Measured with graphs/ao_error.graph at 640x480, gtao's rmse
   against reference_ao: 0, 0.05, 0.1, 0.2, 0.4 gave 0.0516, 0.0504, 0.0493, 0.0469,
   0.0451 on the thin panel and 0.0319, 0.0317, 0.0317, 0.0320, 0.0338 on the table
   (0.0496 and 0.0698 without back); 0.3 (0.0456, 0.0326) keeps most of both gains. */
#define SSG_GTAO_BACK_LINK 0.3f

/* Ports: the descriptor's arrays are indexed by these. */
enum ssg_gtao_input {
    SSG_GTAO_IN_POSITION,
    SSG_GTAO_IN_NORMAL,
    SSG_GTAO_IN_ROTATION,
    SSG_GTAO_IN_DEPTH,
    SSG_GTAO_IN_BACK,
    SSG_GTAO_INPUTS
};
enum ssg_gtao_output {
    SSG_GTAO_OUT_OUT,
    SSG_GTAO_OUT_BENT_NORMAL,
    SSG_GTAO_OUTPUTS
};

struct ssg_gtao_params {
    int slices;              /* slice directions per pixel, 1..32; default 8 */
    int steps;               /* samples per side of a slice, 1..64; default 12 */
    float radius;            /* R, scene units, > 0; default 0.5 */
    float falloff;           /* fraction of R over which a sample's weight fades to 0 at R,
                                0..1; 0 = hard cutoff at R; default 0 */
    float thickness;         /* paper sec. 4.3 thin-occluder heuristic: how far a lower
                                sample pulls the horizon back down, 0..0.99; 0 = every
                                depth sample is an infinitely thick height field; default 0 */
    float power;             /* out = visibility^power, 0.1..8; default 1 */
    float max_screen_radius; /* px; caps the march length (0 = no cap); default 0 */
};

struct ssg_gtao_consts {
    struct ssg_gtao_params p;   /* the parameters as given */
    struct ssg_projection proj; /* the frame's camera at the G-buffer's resolution */
    float fall_mul, fall_add;   /* falloff weight w = clamp(r fall_mul + fall_add, 0, 1)
                                   (falloff > 0; falloff 0 is the test r <= R) */
    float link;                 /* with back: a sample's arc reaches down to the side's
                                   previous sample when that lies at most this far behind
                                   the sample's back, scene units (gtao.c) */
    float slice_cos[SSG_GTAO_MAX_SLICES]; /* cos(pi k / slices) */
    float slice_sin[SSG_GTAO_MAX_SLICES]; /* sin(pi k / slices) */
    /* Per column x of the G-buffer (width w): e1 = (1, 0, a_u) / sqrt(1 + a_u^2), e1x at
       [x] and e1z at [w + x] (ssg_sampling_column_basis); read by both backends. */
    float e1[2 * SSG_IMAGE_MAX_SIDE];
};

/* The descriptor (gtao.c); the GL side binds its parameter table. */
extern const struct ssg_node_desc ssg_node_gtao;

enum ssg_err ssg_gtao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);
/* The GL side (gtao_gl.c, shader gtao.glsl). */
enum ssg_err ssg_gtao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);

#endif
