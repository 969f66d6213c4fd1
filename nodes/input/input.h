/* input.h - the `input` node: an image the caller supplies (ssgraph.h, ssg_graph_supply),
 * so that an engine's own G-buffer or any image can run through a pipeline. Its port and
 * parameter rows, shared by input.c, input_cpu.c and input_gl.c; method: README.md. */
#ifndef SSG_INPUT_H
#define SSG_INPUT_H

#include "graph/node.h"

enum ssg_input_type { SSG_INPUT_SCALAR, SSG_INPUT_VECTOR, SSG_INPUT_COLOR };

/* One output; its type and shape come from the parameters (check() in input.c). */
#define SSG_INPUT_OUT(X)                                                                   \
    X(SSG_INPUT_OUT_OUT, "out", SSG_T_SCALAR,                                              \
      "the supplied image, of the type `type` says (scalar, vector or color)")
SSG_PORT_ENUM(ssg_input_output, SSG_INPUT_OUT, SSG_INPUT_OUTPUTS);

#define SSG_INPUT_PARAMS(P)                                                                \
    P(ENUM, type, "what the image holds: scalar (1 channel), vector or color (3)",        \
      .def = SSG_INPUT_SCALAR, .choices = ssg_input_type_choices, .host_only = 1)          \
    P(INT, width, "width in pixels; 0 = the frame's (with its guard band)", .def = 0,     \
      .min = 0, .max = 16384, .soft_min = 0, .soft_max = 4096, .unit = "px",               \
      .host_only = 1)                                                                      \
    P(INT, height, "height in pixels; 0 = the frame's (with its guard band)", .def = 0,   \
      .min = 0, .max = 16384, .soft_min = 0, .soft_max = 4096, .unit = "px",               \
      .host_only = 1)
SSG_PARAMS_STRUCT(ssg_input_params, SSG_INPUT_PARAMS);

extern const struct ssg_node_desc ssg_node_input;

enum ssg_err ssg_input_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io);
enum ssg_err ssg_input_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);

#endif
