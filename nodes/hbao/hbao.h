/* hbao.h - parameters and prepared constants of the `hbao` node, shared by hbao.c
 * (descriptor, check, prepare), hbao_cpu.c (the CPU kernel) and hbao_gl.c (the GL side).
 * Method and conventions are described in hbao.c. Read-only after prepare(); the kernel
 * is thread-safe. */
#ifndef SSG_HBAO_H
#define SSG_HBAO_H

#include "graph/image.h"
#include "graph/node.h"

#define SSG_HBAO_MAX_DIRECTIONS 64
#define SSG_HBAO_MAX_STEPS 64

/* Input ports, in order. */
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_hbao_input {
    SSG_HBAO_IN_POSITION,
    SSG_HBAO_IN_NORMAL,
    SSG_HBAO_IN_ROTATION,
    SSG_HBAO_IN_DEPTH,
    SSG_HBAO_IN_COUNT,
    SSG_HBAO_INPUTS
};
enum ssg_hbao_output {
    SSG_HBAO_OUT_OUT,
    SSG_HBAO_OUTPUTS
};

enum ssg_hbao_falloff {
    SSG_HBAO_FALLOFF_LINEAR, /* W = max(0, 1 - r / R) (Belonogov eq. 3.2) */
    SSG_HBAO_FALLOFF_NONE,   /* W = 1 for r <= R: a hard distance limit, for comparisons
                                with distance-limited references */
};

struct ssg_hbao_params {
    int directions;          /* azimuths per pixel, 1..64; default 8 */
    int steps;               /* samples along each direction, 1..64; default 6 */
    float radius;            /* R, scene units, > 0; default 0.5 */
    float bias;              /* tangent-angle bias, radians, 0..1.5; default 0.25 (about
                                14 degrees) */
    float strength;          /* out = 1 - strength * occlusion, 0..16; default 1.25 */
    int falloff;             /* enum ssg_hbao_falloff; default none */
    float max_screen_radius; /* px; caps the march length (0 = no cap); default 0 */
};

struct ssg_hbao_consts {
    struct ssg_hbao_params p;    /* the parameters as given */
    struct ssg_projection proj;  /* the frame's camera as the G-buffer's resolution sees
                                    it (ssg_sampling_projection) */
    float cos_bias, sin_bias;    /* of p.bias */
    float dir_cos[SSG_HBAO_MAX_DIRECTIONS]; /* cos(2 pi k / directions) */
    float dir_sin[SSG_HBAO_MAX_DIRECTIONS]; /* sin(2 pi k / directions) */
    int dir_rank[SSG_HBAO_MAX_DIRECTIONS];  /* place of direction k in the order the count
                                               input takes directions in (hbao.c) */
    /* Per column x of the G-buffer (width w): e1 = (1, 0, a_u) / sqrt(1 + a_u^2), e1x at
       [x] and e1z at [w + x]; read by both backends. */
    float e1[2 * SSG_IMAGE_MAX_SIDE];
};

enum ssg_err ssg_hbao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);
/* The GL side (hbao_gl.c, shader hbao.glsl). */
enum ssg_err ssg_hbao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);

#endif
