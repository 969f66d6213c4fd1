/* downsample.h - parameters and ports of the `downsample` node, shared by downsample.c
 * (descriptor, check), downsample_cpu.c (the CPU kernel) and downsample_gl.c (the GL
 * side). Method: README.md in this folder. */
#ifndef SSG_DOWNSAMPLE_H
#define SSG_DOWNSAMPLE_H

#include "graph/node.h"

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. Output k
   copies input k (motion's x and y rescaled to the output's pixels), made only where read
   (on_demand: a graph run binds no image to an output nothing reads); inputs and outputs share their names (the shader's `<port>` and
   `dst_<port>`, ssg_gl_ports). */
#define SSG_DOWNSAMPLE_IN(X)                                                               \
    X(SSG_DOWNSAMPLE_IN_DEPTH, "depth", SSG_T_SCALAR, "linear depth; 0 = background")      \
    X(SSG_DOWNSAMPLE_IN_POSITION, "position", SSG_T_VECTOR, "view-space position",         \
      .optional = 1)                                                                       \
    X(SSG_DOWNSAMPLE_IN_NORMAL, "normal", SSG_T_VECTOR, "unit view-space normal",          \
      .optional = 1)                                                                       \
    X(SSG_DOWNSAMPLE_IN_ALBEDO, "albedo", SSG_T_COLOR, "albedo", .optional = 1)            \
    X(SSG_DOWNSAMPLE_IN_DIRECT, "direct", SSG_T_COLOR, "direct light", .optional = 1)      \
    X(SSG_DOWNSAMPLE_IN_ENVIRONMENT, "environment", SSG_T_COLOR, "environment light",      \
      .optional = 1)                                                                       \
    X(SSG_DOWNSAMPLE_IN_MOTION, "motion", SSG_T_VECTOR,                                    \
      "gbuffer.motion: previous pixel minus this pixel (x, y), previous view depth (z)",   \
      .optional = 1)
#define SSG_DOWNSAMPLE_OUT(X)                                                              \
    X(SSG_DOWNSAMPLE_OUT_DEPTH, "depth", SSG_T_SCALAR, "depth of each block's chosen pixel") \
    X(SSG_DOWNSAMPLE_OUT_POSITION, "position", SSG_T_VECTOR,                               \
      "position of the chosen pixel; 0 when unconnected", .on_demand = 1)                                  \
    X(SSG_DOWNSAMPLE_OUT_NORMAL, "normal", SSG_T_VECTOR,                                   \
      "normal of the chosen pixel; 0 when unconnected", .on_demand = 1)                                    \
    X(SSG_DOWNSAMPLE_OUT_ALBEDO, "albedo", SSG_T_COLOR,                                    \
      "albedo of the chosen pixel; 0 when unconnected", .on_demand = 1)                                    \
    X(SSG_DOWNSAMPLE_OUT_DIRECT, "direct", SSG_T_COLOR,                                    \
      "direct light of the chosen pixel; 0 when unconnected", .on_demand = 1)                              \
    X(SSG_DOWNSAMPLE_OUT_ENVIRONMENT, "environment", SSG_T_COLOR,                          \
      "environment light of the chosen pixel; 0 when unconnected", .on_demand = 1)                         \
    X(SSG_DOWNSAMPLE_OUT_MOTION, "motion", SSG_T_VECTOR,                                   \
      "the chosen pixel's motion in output pixels, from the output pixel's centre (x, y), " \
      "its previous view depth (z), for a temporal node at this resolution; 0 when "      \
      "unconnected",                                                                       \
      .on_demand = 1)
SSG_PORT_ENUM(ssg_downsample_input, SSG_DOWNSAMPLE_IN, SSG_DOWNSAMPLE_INPUTS);
SSG_PORT_ENUM(ssg_downsample_output, SSG_DOWNSAMPLE_OUT, SSG_DOWNSAMPLE_OUTPUTS);
_Static_assert((int)SSG_DOWNSAMPLE_INPUTS == (int)SSG_DOWNSAMPLE_OUTPUTS,
               "downsample: output k is input k subsampled");

#define SSG_DOWNSAMPLE_MAX_FACTOR 4

/* The parameter, one row (lang/params.h); the shader reads it as p_factor. */
#define SSG_DOWNSAMPLE_PARAMS(P)                                                           \
    P(INT, factor, "block side: 2 (half resolution) or 4", .def = 2, .min = 2,             \
      .max = SSG_DOWNSAMPLE_MAX_FACTOR, .soft_min = 2,                                     \
      .soft_max = SSG_DOWNSAMPLE_MAX_FACTOR, .unit = "px")
SSG_PARAMS_STRUCT(ssg_downsample_params, SSG_DOWNSAMPLE_PARAMS);

enum ssg_err ssg_downsample_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);
/* The GL side (downsample_gl.c, shader downsample*.glsl). */
enum ssg_err ssg_downsample_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);

#endif
