/* temporal.h - the ports, parameters and prepared constants of the `temporal` node
 * (temporal accumulation with reprojection, disocclusion tests and variance clipping),
 * shared by temporal.c (descriptor, check, prepare), temporal_cpu.c (the CPU kernel) and
 * temporal_gl.c (the GL side). The method: README.md in this folder. Nothing here changes
 * after the graph is loaded; the kernels only read it, from any thread. */
#ifndef SSG_TEMPORAL_H
#define SSG_TEMPORAL_H

#include "graph/node.h"

/* Ports, one row each (graph/node.h). history, history2, length_in, prev_depth and
   prev_normal are ordinary images: a graph wires them with prev(node.port) (the previous
   frame's image of that port, all 0 with ctx->history_reset 1 in the first frame). The
   shader reads `in` as src (a GLSL keyword), in2 and history2 only with IN2_CH and the
   normals only with NORMALS (its defines, temporal_gl.c). */
#define SSG_TEMPORAL_VALUE_TYPES (SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR)
#define SSG_TEMPORAL_IN(X)                                                                 \
    X(SSG_TEMPORAL_IN_IN, "in", SSG_TEMPORAL_VALUE_TYPES,                                  \
      "this frame's noisy value (1 or 3 channels)", .gl_name = "src")                     \
    X(SSG_TEMPORAL_IN_IN2, "in2", SSG_T_COLOR | SSG_T_VECTOR,                              \
      "a second value accumulated with in's weights (the bounce beside a modulation)",    \
      .optional = 1, .gl_if = "IN2_CH")                                                    \
    X(SSG_TEMPORAL_IN_HISTORY, "history", SSG_TEMPORAL_VALUE_TYPES,                        \
      "the previous frame's out: prev(t.out)")                                             \
    X(SSG_TEMPORAL_IN_HISTORY2, "history2", SSG_T_COLOR | SSG_T_VECTOR,                    \
      "the previous frame's out2: prev(t.out2); needed with in2", .optional = 1,           \
      .gl_if = "IN2_CH")                                                                   \
    X(SSG_TEMPORAL_IN_LENGTH_IN, "length_in", SSG_T_SCALAR,                                \
      "the previous frame's length: prev(t.length)")                                       \
    X(SSG_TEMPORAL_IN_MOTION, "motion", SSG_T_VECTOR,                                      \
      "g.motion: previous pixel minus this pixel (x, y, px), previous view depth (z)")     \
    X(SSG_TEMPORAL_IN_DEPTH, "depth", SSG_T_SCALAR, "linear depth; 0 = background")        \
    X(SSG_TEMPORAL_IN_NORMAL, "normal", SSG_T_VECTOR,                                      \
      "unit view-space normal; none = no normal test", .optional = 1, .gl_if = "NORMALS")  \
    X(SSG_TEMPORAL_IN_PREV_DEPTH, "prev_depth", SSG_T_SCALAR,                              \
      "the previous frame's depth: prev(g.depth)")                                         \
    X(SSG_TEMPORAL_IN_PREV_NORMAL, "prev_normal", SSG_T_VECTOR,                            \
      "the previous frame's normal: prev(g.normal); needed with normal", .optional = 1,    \
      .gl_if = "NORMALS")
#define SSG_TEMPORAL_OUT(X)                                                                \
    X(SSG_TEMPORAL_OUT_OUT, "out", SSG_T_SCALAR, "the accumulated value", .same_as = "in") \
    X(SSG_TEMPORAL_OUT_OUT2, "out2", SSG_T_SCALAR,                                         \
      "in2 accumulated with out's weights; all 0, shaped like out, without in2",           \
      .same_as = "in2")                                                                    \
    X(SSG_TEMPORAL_OUT_LENGTH, "length", SSG_T_SCALAR,                                     \
      "frames accumulated per pixel, 1 after a restart, at most max_length")
SSG_PORT_ENUM(ssg_temporal_input, SSG_TEMPORAL_IN, SSG_TEMPORAL_INPUTS);
SSG_PORT_ENUM(ssg_temporal_output, SSG_TEMPORAL_OUT, SSG_TEMPORAL_OUTPUTS);

/* Parameters, one row each (lang/params.h). The shader reads gamma, depth_tolerance and
   (the variant with normals only) normal_tolerance as p_<field>; max_length reaches it as
   prepare()'s inv_max_length. */
#define SSG_TEMPORAL_PARAMS(P)                                                             \
    P(INT, max_length, "most frames averaged: past it, an exponential blend of weight "   \
      "1 / max_length", .def = 32, .min = 1, .max = 4096, .soft_min = 1, .soft_max = 256,  \
      .unit = "frames",                                                                    \
      .host_only = 1)                                                                      \
    P(FLOAT, gamma, "history clamped to mean +/- gamma stddev of in's 3 x 3 "              \
      "neighbourhood; 0 = no clamp", .def = 1, .min = 0, .max = 1000, .soft_min = 0,       \
      .soft_max = 4)                                                                       \
    P(FLOAT, depth_tolerance, "a history tap is rejected when |motion.z - prev_depth| / "  \
      "motion.z exceeds this", .def = 0.05, .min = 0, .max = 1000, .soft_min = 0,          \
      .soft_max = 0.5)                                                                     \
    P(FLOAT, normal_tolerance, "a history tap is rejected when dot(normal, prev_normal) "  \
      "is below this", .def = 0.9, .min = -1, .max = 1, .soft_min = -1, .soft_max = 1,     \
      .gl_if = "NORMALS")
SSG_PARAMS_STRUCT(ssg_temporal_params, SSG_TEMPORAL_PARAMS);

/* What prepare() makes once for both backends (the shader reads it by name,
   #pragma ssg_consts). */
#define SSG_TEMPORAL_UNIFORMS(U)                                                           \
    U(FLOAT, inv_max_length, "1 / max_length: the smallest blend weight")                \
    U(FLOAT, length_cap, "max_length as a float: the largest length")
SSG_UNIFORMS_STRUCT(ssg_temporal_uniforms, SSG_TEMPORAL_UNIFORMS);

struct ssg_temporal_consts {
    struct ssg_temporal_params p;   /* the parameters as given */
    struct ssg_temporal_uniforms u; /* the constants both backends read */
};

/* The smallest sum of bilinear weights of valid history taps that still counts as a
   history (below it the pixel restarts), as in SVGF's reprojection (Schied et al. 2017). */
#define SSG_TEMPORAL_MIN_WEIGHT 0.01f

/* The descriptor (temporal.c); nodes/nodes.def lists it as X(temporal). */
extern const struct ssg_node_desc ssg_node_temporal;

/* The backends (consts: struct ssg_temporal_consts). */
enum ssg_err ssg_temporal_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io);
enum ssg_err ssg_temporal_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);

#endif
