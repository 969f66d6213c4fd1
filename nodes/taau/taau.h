/* taau.h - the ports, parameters and prepared constants of the `taau` node (temporal
 * upsampling: the jittered samples of the frames gathered into an image `factor` times
 * the frame's size), shared by taau.c (descriptor, check, prepare), taau_cpu.c (the CPU
 * kernel) and taau_gl.c (the GL side). The method: README.md in this folder. Nothing here
 * changes after the graph is loaded; the kernels only read it, from any thread. */
#ifndef SSG_TAAU_H
#define SSG_TAAU_H

#include "graph/node.h"

/* Ports, one row each (graph/node.h). history and weight_in are ordinary images: a graph
   wires them with prev(node.out) and prev(node.weight) (all 0 with ctx->history_reset in
   the first frame). The shader reads `in` as src (a GLSL keyword). */
#define SSG_TAAU_VALUE_TYPES (SSG_T_SCALAR | SSG_T_COLOR)
#define SSG_TAAU_IN(X)                                                                     \
    X(SSG_TAAU_IN_IN, "in", SSG_TAAU_VALUE_TYPES,                                          \
      "this frame's image at the frame's size, rendered under the graph's `jitter` "       \
      "(1 or 3 channels)", .gl_name = "src")                                               \
    X(SSG_TAAU_IN_MOTION, "motion", SSG_T_VECTOR,                                          \
      "g.motion at in's size: previous pixel minus this pixel (x, y, px of in)")           \
    X(SSG_TAAU_IN_HISTORY, "history", SSG_TAAU_VALUE_TYPES,                                \
      "the previous frame's out: prev(u.out)")                                             \
    X(SSG_TAAU_IN_WEIGHT_IN, "weight_in", SSG_T_SCALAR,                                    \
      "the previous frame's weight: prev(u.weight)")
#define SSG_TAAU_OUT(X)                                                                    \
    X(SSG_TAAU_OUT_OUT, "out", SSG_TAAU_VALUE_TYPES,                                       \
      "the upsampled image, factor x in's size, in's channels")                            \
    X(SSG_TAAU_OUT_WEIGHT, "weight", SSG_T_SCALAR,                                         \
      "the samples' weight gathered per output pixel, at most max_weight")
SSG_PORT_ENUM(ssg_taau_input, SSG_TAAU_IN, SSG_TAAU_INPUTS);
SSG_PORT_ENUM(ssg_taau_output, SSG_TAAU_OUT, SSG_TAAU_OUTPUTS);

/* Parameters, one row each (lang/params.h); the shader reads those not host_only as
   p_<field>. */
#define SSG_TAAU_PARAMS(P)                                                                 \
    P(INT, factor, "out is factor x in's size on both axes", .def = 2, .min = 1, .max = 4,  \
      .soft_min = 1, .soft_max = 4, .unit = "times", .host_only = 1)                        \
    P(FLOAT, sigma, "standard deviation of the Gaussian that weights a sample by its "     \
      "distance to the output pixel's centre", .def = 0.5, .min = 0.05, .max = 4,         \
      .soft_min = 0.2, .soft_max = 1.5, .unit = "output pixels", .host_only = 1)          \
    P(FLOAT, max_weight, "the history's weight is capped here: the larger, the longer "   \
      "the samples of earlier frames count (about max_weight / 0.4 frames at factor 2)",  \
      .def = 1, .min = 0, .max = 1000, .soft_min = 0, .soft_max = 32,                      \
      .unit = "samples on the centre")                                                     \
    P(FLOAT, gamma, "history clamped to mean +/- gamma stddev of in's 3 x 3 samples "      \
      "around the output pixel; 0 = no clamp", .def = 1.5, .min = 0, .max = 1000,           \
      .soft_min = 0, .soft_max = 4, .unit = "standard deviations")
SSG_PARAMS_STRUCT(ssg_taau_params, SSG_TAAU_PARAMS);

/* What prepare() makes once for both backends (the shader reads it by name,
   #pragma ssg_consts). */
#define SSG_TAAU_UNIFORMS(U)                                                               \
    U(FLOAT, inv_factor, "1 / factor: an output coordinate in in's pixels")               \
    U(FLOAT, fac, "factor as a float: in's distances in output pixels")                   \
    U(FLOAT, neg_inv_2s2, "-1 / (2 sigma^2): the Gaussian's exponent per squared pixel") \
    U(FLOAT, jitter_x, "the frame's jitter (ctx->frame): in's samples' offset, in's pixels; " \
      "prepare() runs again when it changes, as for a camera move")                         \
    U(FLOAT, jitter_y, "likewise, down")
SSG_UNIFORMS_STRUCT(ssg_taau_uniforms, SSG_TAAU_UNIFORMS);

struct ssg_taau_consts {
    struct ssg_taau_params p;   /* the parameters as given */
    struct ssg_taau_uniforms u; /* the constants both backends read */
};

/* The descriptor (taau.c); nodes/nodes.def lists it as X(taau). */
extern const struct ssg_node_desc ssg_node_taau;

/* The backends (consts: struct ssg_taau_consts). */
enum ssg_err ssg_taau_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);
enum ssg_err ssg_taau_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);

#endif
