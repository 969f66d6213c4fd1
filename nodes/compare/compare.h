/* compare.h - parameters and prepared constants of the `compare` node, shared by compare.c
 * (descriptor, check, prepare) and compare_cpu.c (the CPU kernel). Method in compare.c. */
#ifndef SSG_COMPARE_H
#define SSG_COMPARE_H

#include "graph/node.h"

/* SSIM window: 11 x 11 taps (Wang et al. 2004, section III-C). */
#define SSG_COMPARE_RADIUS 5
#define SSG_COMPARE_TAPS (2 * SSG_COMPARE_RADIUS + 1)
/* Most channels an input may have (scalar 1, vector/color 3). */
#define SSG_COMPARE_MAX_CHANNELS 4

/* Input ports, in order. */
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_compare_input {
    SSG_COMPARE_IN_A,
    SSG_COMPARE_IN_B,
    SSG_COMPARE_IN_MASK,
    SSG_COMPARE_INPUTS
};
enum ssg_compare_output {
    SSG_COMPARE_OUT_DIFF,
    SSG_COMPARE_OUTPUTS
};

struct ssg_compare_params {
    float scale; /* |a - b| shown in full colour in `diff`, image units; default 0.25 */
    float peak;  /* signal peak: PSNR's MAX and SSIM's dynamic range L; default 1 */
    int edge;    /* > 0: only pixels within this many of the frame's border count, px;
                    default 0 = every pixel of the frame */
    struct ssg_ints region; /* [x0, y0, x1, y1]: only pixels x0 <= x < x1, y0 <= y < y1 of
                               the frame count, px; default [0, 0, 0, 0] = the whole frame */
    int banding; /* > 0: report banding with a moving window of lines i +- banding, px;
                    default 0 = not measured */
};

struct ssg_compare_consts {
    double gauss[SSG_COMPARE_TAPS]; /* 1D Gaussian, sigma 1.5 px, sums to 1; the window is
                                       the outer product of it with itself */
    double c1;                      /* SSIM (K1 L)^2, K1 = 0.01 */
    double c2;                      /* SSIM (K2 L)^2, K2 = 0.03 */
    double peak;                    /* as in the parameters */
    float inv_scale;                /* 1 / scale */
    int x0, y0, x1, y1;             /* the frame within the images: [x0, x1) x [y0, y1),
                                       the guard band (ssg_frame.guard) left out */
    int rx0, ry0, rx1, ry1;         /* the region parameter in image pixels, inside the
                                       frame; the frame without one */
    int edge;                       /* as in the parameters */
    int banding;                    /* as in the parameters: the window's half-width */
};


enum ssg_err ssg_compare_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);

#endif
