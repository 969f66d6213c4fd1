/* upsample.h - parameters and prepared constants of the `upsample` node, shared by
 * upsample.c (descriptor, check, prepare), upsample_cpu.c (the CPU kernel) and
 * upsample_gl.c (the GL side). Method in upsample.c. */
#ifndef SSG_UPSAMPLE_H
#define SSG_UPSAMPLE_H

#include "graph/node.h"

#define SSG_UPSAMPLE_MAX_SIZE 9
#define SSG_UPSAMPLE_MAX_FACTOR 16

/* Input ports, in order. */
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_upsample_input {
    SSG_UPSAMPLE_IN_IN,
    SSG_UPSAMPLE_IN_DEPTH,
    SSG_UPSAMPLE_IN_NORMAL,
    SSG_UPSAMPLE_IN_LOW_DEPTH,
    SSG_UPSAMPLE_IN_LOW_NORMAL,
    SSG_UPSAMPLE_IN_IN2,
    SSG_UPSAMPLE_INPUTS
};
enum ssg_upsample_output {
    SSG_UPSAMPLE_OUT_OUT,
    SSG_UPSAMPLE_OUT_OUT2,
    SSG_UPSAMPLE_OUTPUTS
};

struct ssg_upsample_params {
    int size;            /* low-res taps per side, odd, 1..9; default 3 */
    float sigma_spatial; /* low-res px; 0 = size / 3; default 0 */
    float sigma_depth;   /* depth difference as a fraction of the full-res depth; 0.05 */
    int normal_power;    /* p of max(0, n.n')^p, 0..127, 0 = no normal term; default 16 */
};

struct ssg_upsample_consts {
    int radius;          /* (size - 1) / 2, low-res px */
    float spatial_k;     /* -0.5 / sigma_spatial^2: ln of the spatial weight per px^2 */
    float depth_scale;   /* 1 / sigma_depth */
    float normal_power;  /* as in the parameters */
    float normal_min;    /* cosines below this weigh c^p < 1e-30 and count as 0 */
    int factor;          /* k: in is depth subsampled by k (ssg_upsample_factor) */
};

/* The integer factor k with ceil(width / k) = low_width and ceil(height / k) = low_height
 * (the sizes `downsample` makes), or 0 when there is none. */
int ssg_upsample_factor(int width, int height, int low_width, int low_height);

enum ssg_err ssg_upsample_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io);
/* The GL side (upsample_gl.c, shader upsample*.glsl). */
enum ssg_err ssg_upsample_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io);

#endif
