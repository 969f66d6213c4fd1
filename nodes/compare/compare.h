/* compare.h - ports, parameters and prepared constants of the `compare` node, shared by
 * compare.c (descriptor, check, prepare) and compare_cpu.c (the CPU kernel). Method in
 * README.md. */
#ifndef SSG_COMPARE_H
#define SSG_COMPARE_H

#include "flip.h"
#include "graph/node.h"

/* SSIM window: 11 x 11 taps (Wang et al. 2004, section III-C). */
#define SSG_COMPARE_RADIUS 5
#define SSG_COMPARE_TAPS (2 * SSG_COMPARE_RADIUS + 1)
/* Most channels an input may have (scalar 1, vector/color 3). */
#define SSG_COMPARE_MAX_CHANNELS 4

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_COMPARE_IN(X)                                                                  \
    X(SSG_COMPARE_IN_A, "a", SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR, "image under test") \
    X(SSG_COMPARE_IN_B, "b", SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR,                    \
      "reference image, same type and size as a")                                          \
    X(SSG_COMPARE_IN_MASK, "mask", SSG_T_SCALAR,                                           \
      "pixels with mask > 0.5 are compared; none = every pixel", .optional = 1)         \
    X(SSG_COMPARE_IN_DEPTH, "depth", SSG_T_SCALAR,                                         \
      "view depth of b, for the structure measure: no pixel near a depth jump is "        \
      "measured; none = no depth edges", .optional = 1)
#define SSG_COMPARE_OUT(X)                                                                 \
    X(SSG_COMPARE_OUT_DIFF, "diff", SSG_T_COLOR,                                           \
      "a - b on blue (a < b), white (equal), red (a > b); black = not compared")          \
    X(SSG_COMPARE_OUT_FLIP, "flip", SSG_T_SCALAR,                                          \
      "FLIP error map in [0, 1] (0 = not compared, or flip = off)", .on_demand = 1)      \
    X(SSG_COMPARE_OUT_STRUCTURE, "structure", SSG_T_SCALAR,                                \
      "the structure measure's d = G(a - b) / G(b) on the measured pixels, 0 elsewhere "  \
      "(and with structure = false)", .on_demand = 1)
SSG_PORT_ENUM(ssg_compare_input, SSG_COMPARE_IN, SSG_COMPARE_INPUTS);
SSG_PORT_ENUM(ssg_compare_output, SSG_COMPARE_OUT, SSG_COMPARE_OUTPUTS);

/* The `flip` parameter's choices, in the order of ssg_compare_flip_choices (compare.c). */
enum ssg_compare_flip_mode {
    SSG_COMPARE_FLIP_AUTO,
    SSG_COMPARE_FLIP_LDR,
    SSG_COMPARE_FLIP_HDR,
    SSG_COMPARE_FLIP_OFF
};
extern const char *const ssg_compare_flip_choices[];

/* The parameters, one row each (lang/params.h); the struct below and the table in
   compare.c are made from these rows. region is [x0, y0, x1, y1] in frame pixels. */
#define SSG_COMPARE_PARAMS(P)                                                              \
    P(FLOAT, scale, "diff image: |a - b| at which the colour is pure red or blue",         \
      .def = 0.25, .min = 1e-6, .max = 1e6, .soft_min = 0.01, .soft_max = 1)               \
    P(FLOAT, peak,                                                                         \
      "signal peak: PSNR's maximum and SSIM's dynamic range L (1 for AO, [0,1] data)",     \
      .def = 1, .min = 1e-6, .max = 1e6, .soft_min = 0.1, .soft_max = 10)                  \
    P(INT, edge,                                                                           \
      "> 0: compare only the pixels within this distance of the frame's border (where "    \
      "screen-space methods lack occluders); 0 = the whole frame",                         \
      .def = 0, .min = 0, .max = 16384, .soft_min = 0, .soft_max = 128, .unit = "px")      \
    P(INTS, region,                                                                        \
      "[x0, y0, x1, y1]: compare only frame pixels x0 <= x < x1, y0 <= y < y1 (e.g. one "  \
      "wall; cut to the frame); [0, 0, 0, 0] = the whole frame",                           \
      .def_ints = {0, 0, 0, 0}, .def_ints_count = 4, .min_count = 4, .max_count = 4,       \
      .min = 0, .max = 65536, .unit = "px")                                                \
    P(INT, banding,                                                                        \
      "> 0: also report banding, banding_rows, banding_cols: RMS of the row and column "   \
      "means of a - b minus their moving average over lines i +- banding; 0 = off",        \
      .def = 0, .min = 0, .max = 4096, .soft_min = 0, .soft_max = 64, .unit = "px")        \
    P(ENUM, flip,                                                                          \
      "FLIP metric (Andersson et al. 2020/2021): auto = LDR-FLIP for 1 channel (the "      \
      "value as grey), HDR-FLIP for 3 (linear radiance); ldr; hdr; off = not reported",    \
      .def = SSG_COMPARE_FLIP_AUTO, .choices = ssg_compare_flip_choices)                   \
    P(FLOAT, ppd,                                                                          \
      "FLIP's observer: pixels per degree of visual angle (default: a 0.7 m wide "         \
      "3840-pixel monitor at 0.7 m)",                                                      \
      .def = SSG_FLIP_DEFAULT_PPD, .min = 1, .max = SSG_FLIP_MAX_PPD, .soft_min = 10,      \
      .soft_max = 200, .unit = "px/deg")                                                   \
    P(BOOL, structure,                                                                     \
      "also report structure_pp, structure_rms, structure_pixels: the low-frequency "     \
      "relative error G(a - b) / G(b) where b is smooth (README.md)",                     \
      .def = 0)                                                                            \
    P(FLOAT, structure_sigma,                                                              \
      "the structure measure's Gaussian deviation, as a fraction of the frame's width",   \
      .def = 0.01, .min = 1e-4, .max = 1, .soft_min = 0.001, .soft_max = 0.1)              \
    P(FLOAT, structure_smooth,                                                             \
      "the structure measure's smoothness test: b counts as smooth where its blurs of "   \
      "deviation sigma and 2 sigma differ by at most this fraction",                      \
      .def = 0.05, .min = 1e-6, .max = 1e6, .soft_min = 0.005, .soft_max = 0.5)
SSG_PARAMS_STRUCT(ssg_compare_params, SSG_COMPARE_PARAMS);

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
    int flip;                       /* FLIP resolved for the input type: LDR, HDR or OFF
                                       (never AUTO) */
    double ppd;                     /* as in the parameters */
    int structure;                  /* 1 = report the structure measure */
    double structure_sigma;         /* its deviation, px: structure_sigma x frame width */
    double structure_smooth;        /* as in the parameters */
};

enum ssg_err ssg_compare_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);

#endif
