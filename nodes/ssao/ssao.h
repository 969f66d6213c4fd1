/* ssao.h - parameters and prepared constants of the `ssao` node, shared by ssao.c
 * (descriptor, check, prepare), ssao_cpu.c (the CPU kernel) and ssao_gl.c (the GL side).
 * Method and conventions are described in ssao.c. */
#ifndef SSG_SSAO_H
#define SSG_SSAO_H

#include "graph/node.h"

enum ssg_ssao_range {
    SSG_SSAO_RANGE_NONE,   /* every occluder counts fully */
    SSG_SSAO_RANGE_HARD,   /* occluders farther than radius in depth do not count */
    SSG_SSAO_RANGE_SMOOTH, /* weight smoothstep(0, 1, radius / |depth difference|) */
};

enum ssg_ssao_mode {
    SSG_SSAO_MODE_HEMISPHERE, /* samples in the hemisphere about the normal */
    SSG_SSAO_MODE_SPHERE,     /* normal-free: samples in the sphere about the point */
    SSG_SSAO_MODE_DISC,       /* normal-free: depth samples in a screen-space disc */
};

/* Input ports, in order. */
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_ssao_input {
    SSG_SSAO_IN_POSITION,
    SSG_SSAO_IN_NORMAL,
    SSG_SSAO_IN_KERNEL,
    SSG_SSAO_IN_ROTATION,
    SSG_SSAO_IN_DEPTH,
    SSG_SSAO_IN_COUNT,
    SSG_SSAO_INPUTS
};
enum ssg_ssao_output {
    SSG_SSAO_OUT_OUT,
    SSG_SSAO_OUTPUTS
};

struct ssg_ssao_params {
    float radius;            /* hemisphere radius, scene units, > 0; default 0.5 */
    float bias;              /* depth margin before a sample counts as occluded, scene
                                units; default 0 */
    float power;             /* ao = visibility^power; default 2 */
    int range_check;         /* enum ssg_ssao_range; default hard */
    float max_screen_radius; /* px; caps the projected radius (0 = no cap); default 0 */
    int mode;                /* enum ssg_ssao_mode; default hemisphere */
};

struct ssg_ssao_consts {
    struct ssg_ssao_params p; /* the parameters as given */
    struct ssg_projection proj; /* the frame's camera as seen by the G-buffer's
                                   resolution (ssg_projection_scaled: a subsampled
                                   G-buffer sees the same camera) */
};

enum ssg_err ssg_ssao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);
/* The GL side (ssao_gl.c, shader ssao.glsl). */
enum ssg_err ssg_ssao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);

#endif
