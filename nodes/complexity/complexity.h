/* complexity.h - parameters and prepared constants of the `complexity` node, shared by
 * complexity.c (descriptor, check, prepare), complexity_cpu.c (the CPU pass) and
 * complexity_gl.c (the GL side). Method and the gradient-to-count mapping are described
 * in complexity.c. Read-only after
 * prepare(); the pass is thread-safe. */
#ifndef SSG_COMPLEXITY_H
#define SSG_COMPLEXITY_H

#include "graph/node.h"

#define SSG_COMPLEXITY_MAX_SCALE 8       /* largest base cell side, px */
#define SSG_COMPLEXITY_MAX_RESOLUTIONS 4 /* scales combined: scale, 2 scale, 4, 8 scale */

/* Input ports, in order. */
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_complexity_input {
    SSG_COMPLEXITY_IN_DEPTH,
    SSG_COMPLEXITY_IN_NORMAL,
    SSG_COMPLEXITY_INPUTS
};
enum ssg_complexity_output {
    SSG_COMPLEXITY_OUT_COUNT,
    SSG_COMPLEXITY_OUTPUTS
};

struct ssg_complexity_params {
    struct ssg_ints levels;  /* sample counts, ascending, multiples of period; default
                                [20, 30, 40, 50] */
    int period;              /* Halton block size N_g (eq. 8), samples; default 10 */
    int scale;               /* cell side of the finest grid, px: 1, 2, 4 or 8; default 4 */
    int resolutions;         /* grids combined (scale, 2 scale, ...), 1..4; default 1 */
    float normal_threshold;  /* normal gradient below which a cell is flat; default 0.1 */
    float normal_gain;       /* t_n = clamp((g_n - threshold) gain, 0, 1); default 2 */
    float depth_threshold;   /* relative depth gradient below which a cell is flat;
                                default 0.02 */
    float depth_gain;        /* t_d = clamp((g_d - threshold) gain, 0, 1); default 10 */
};

struct ssg_complexity_consts {
    struct ssg_complexity_params p; /* the parameters as given */
    struct ssg_projection proj;     /* the frame's camera as the G-buffer's resolution
                                       sees it (ssg_sampling_projection) */
};

enum ssg_err ssg_complexity_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);
/* The GL side (complexity_gl.c, shaders complexity_*.glsl). */
enum ssg_err ssg_complexity_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io);

#endif
