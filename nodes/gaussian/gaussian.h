/* gaussian.h - ports, parameters and prepared constants of the `gaussian` node, shared by
 * gaussian.c (descriptor, check, prepare), gaussian_cpu.c (the CPU kernel) and
 * gaussian_gl.c (the GL side). Method in README.md. Read-only after prepare(); the kernel
 * is thread-safe. */
#ifndef SSG_GAUSSIAN_H
#define SSG_GAUSSIAN_H

#include "graph/node.h"

#define SSG_GAUSSIAN_MAX_SIZE 1023 /* widest window, px */
#define SSG_GAUSSIAN_MAX_SIGMA 170 /* px: its window 2 ceil(3 sigma) + 1 = 1021 fits */
_Static_assert(2 * 3 * SSG_GAUSSIAN_MAX_SIGMA + 1 <= SSG_GAUSSIAN_MAX_SIZE,
               "the widest sigma's window fits the weight table");

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_GAUSSIAN_IN(X)                                                                 \
    X(SSG_GAUSSIAN_IN_IN, "in", SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR, "image to blur")
#define SSG_GAUSSIAN_OUT(X)                                                                \
    X(SSG_GAUSSIAN_OUT_OUT, "out", SSG_T_SCALAR, "blurred image", .same_as = "in")
SSG_PORT_ENUM(ssg_gaussian_input, SSG_GAUSSIAN_IN, SSG_GAUSSIAN_INPUTS);
SSG_PORT_ENUM(ssg_gaussian_output, SSG_GAUSSIAN_OUT, SSG_GAUSSIAN_OUTPUTS);

/* The parameters, one row each (lang/params.h). Both only make the weights in prepare():
   the shader reads the constants, no parameter. */
#define SSG_GAUSSIAN_PARAMS(P)                                                             \
    P(FLOAT, sigma, "standard deviation", .def = 2, .min = 0.01,                           \
      .max = SSG_GAUSSIAN_MAX_SIGMA, .soft_min = 0.25, .soft_max = 32, .unit = "px",       \
      .host_only = 1)                                                                      \
    P(INT, size, "window diameter, odd; 0 = 2 ceil(3 sigma) + 1", .def = 0, .min = 0,      \
      .max = SSG_GAUSSIAN_MAX_SIZE, .soft_min = 0, .soft_max = 63, .unit = "px",           \
      .host_only = 1)
SSG_PARAMS_STRUCT(ssg_gaussian_params, SSG_GAUSSIAN_PARAMS);

/* What the shader reads by name (#pragma ssg_consts). */
#define SSG_GAUSSIAN_UNIFORMS(U) U(INT, radius, "(size - 1) / 2, px")
SSG_UNIFORMS_STRUCT(ssg_gaussian_uniforms, SSG_GAUSSIAN_UNIFORMS);

struct ssg_gaussian_consts {
    struct ssg_gaussian_uniforms u;         /* the radius */
    float weight[SSG_GAUSSIAN_MAX_SIZE];    /* normalised weights of offsets -radius..radius
                                               (index offset + radius); they sum to 1 */
};

enum ssg_err ssg_gaussian_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io);
enum ssg_err ssg_gaussian_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);

#endif
