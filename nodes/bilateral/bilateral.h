/* bilateral.h - parameters and prepared constants of the `bilateral` node, shared by
 * bilateral.c (descriptor, check, prepare), bilateral_cpu.c (the CPU kernel) and
 * bilateral_gl.c (the GL side), and by the `atrous` node. Method: README.md here. */
#ifndef SSG_BILATERAL_H
#define SSG_BILATERAL_H

#include "graph/node.h"

#define SSG_BILATERAL_MAX_SIZE 63

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. The
   `atrous` node has the same ports (its descriptor names these tables). */
#define SSG_BILATERAL_IMAGE_TYPES (SSG_T_SCALAR | SSG_T_COLOR | SSG_T_VECTOR)
#define SSG_BILATERAL_IN(X)                                                                \
    X(SSG_BILATERAL_IN_IN, "in", SSG_BILATERAL_IMAGE_TYPES, "image to smooth")             \
    X(SSG_BILATERAL_IN_DEPTH, "depth", SSG_T_SCALAR, "linear depth; 0 = background")       \
    X(SSG_BILATERAL_IN_NORMAL, "normal", SSG_T_VECTOR,                                     \
      "unit view-space normal; none = no normal term", .optional = 1)                      \
    X(SSG_BILATERAL_IN_IN2, "in2", SSG_BILATERAL_IMAGE_TYPES,                              \
      "a second image the size of in, filtered with in's weights", .optional = 1)
#define SSG_BILATERAL_OUT(X)                                                               \
    X(SSG_BILATERAL_OUT_OUT, "out", SSG_T_SCALAR, "smoothed image", .same_as = "in")       \
    X(SSG_BILATERAL_OUT_OUT2, "out2", SSG_T_SCALAR,                                        \
      "in2 smoothed with out's weights (type of in2); all 0, shaped like out, when in2 "   \
      "is unconnected", .same_as = "in2")
SSG_PORT_ENUM(ssg_bilateral_input, SSG_BILATERAL_IN, SSG_BILATERAL_INPUTS);
SSG_PORT_ENUM(ssg_bilateral_output, SSG_BILATERAL_OUT, SSG_BILATERAL_OUTPUTS);

/* The edge-stopping parameters both joint filters of this folder declare (bilateral and
   atrous), as parameter rows (lang/params.h). No shader reads a parameter: the GL side
   binds prepare()'s constants. */
#define SSG_BILATERAL_EDGE_PARAMS(P)                                                       \
    P(FLOAT, sigma_depth, "depth sigma as a fraction of the centre pixel's depth",         \
      .def = 0.05, .min = 1e-6, .max = 1000, .soft_min = 0.005, .soft_max = 0.5)           \
    P(INT, normal_power, "normal weight max(0, n.n')^p; 0 = off", .def = 16, .min = 0,     \
      .max = 127, .soft_min = 0, .soft_max = 64)

/* The spatial weight's shape (README.md, "Window"). */
enum ssg_bilateral_window {
    SSG_BILATERAL_GAUSSIAN, /* exp(-0.5 d^2 / sigma_spatial^2) */
    SSG_BILATERAL_TENT,     /* (1 - |dx| / (radius + 1)) (1 - |dy| / (radius + 1)) */
};

/* The parameters, one row each (lang/params.h): kind, field, doc, then default, range and
   unit. */
#define SSG_BILATERAL_PARAMS(P)                                                            \
    P(INT, size, "window diameter, odd", .def = 9, .min = 1,                               \
      .max = SSG_BILATERAL_MAX_SIZE, .soft_min = 1, .soft_max = 31, .unit = "px")          \
    P(FLOAT, sigma_spatial, "spatial Gaussian sigma; 0 = size / 3", .def = 0, .min = 0,    \
      .max = 1000, .soft_min = 0, .soft_max = 16, .unit = "px")                            \
    P(ENUM, window,                                                                        \
      "spatial weight: gaussian (sigma_spatial) or tent (1 - |d| / (radius + 1) a side; "  \
      "size 2 P - 1 removes any pattern of period P, such as an interleaved tile's)",      \
      .def = SSG_BILATERAL_GAUSSIAN, .choices = ssg_bilateral_window_choices)              \
    SSG_BILATERAL_EDGE_PARAMS(P)                                                           \
    P(BOOL, separable,                                                                     \
      "horizontal then vertical pass: O(size) per pixel, an approximation", .def = 0)
SSG_PARAMS_STRUCT(ssg_bilateral_params, SSG_BILATERAL_PARAMS);

/* The constants the shader reads by name (#pragma ssg_consts); the normal term's only in
   the variant with normals (NORMALS, bilateral_gl.c). */
#define SSG_BILATERAL_UNIFORMS(U)                                                          \
    U(INT, radius, "(size - 1) / 2, px")                                                   \
    U(INT, size, "2 * radius + 1, px")                                                     \
    U(FLOAT, depth_scale, "1 / sigma_depth: exponent -0.5 (dd * depth_scale / d)^2")      \
    U(INT, normal_power, "as in the parameters", .gl_if = "NORMALS")                      \
    U(FLOAT, normal_min, "normal cosines below this weigh c^p < 1e-30 and count as 0",    \
      .gl_if = "NORMALS")                                                                  \
    U(INT, squarings, "c^p by that many squarings of c; -1 = p ln(c) in the exponent "    \
      "(ssg_joint_squarings)", .gl_if = "NORMALS")
SSG_UNIFORMS_STRUCT(ssg_bilateral_uniforms, SSG_BILATERAL_UNIFORMS);

struct ssg_bilateral_consts {
    struct ssg_bilateral_uniforms u; /* what the shader reads */
    int separable;       /* as in the parameters */
    int atrous;          /* > 0: that many 5 x 5 passes, 1, 2, 4, ... px apart (the
                            `atrous` node's consts); 0 = bilateral */
    /* ln of the spatial weight (the Gaussian's -0.5 (dx^2 + dy^2) / sigma_spatial^2, or
       the tent's), for dy, dx in [-radius, radius]: row (dy + radius) * size + dx +
       radius; a sum of an x and a y part, so a separable run's passes take its row and
       column. Logarithms, so that the three weights multiply by adding exponents and one
       exp() does it all. */
    float spatial[SSG_BILATERAL_MAX_SIZE * SSG_BILATERAL_MAX_SIZE];
};

/* One pass of a run: the window's half-widths walked and the px between taps. */
struct ssg_bilateral_pass {
    int rx, ry, step;
};
enum { SSG_BILATERAL_MAX_PASSES = 8 };

/* The passes of a run of these consts, into pass; returns how many: the full window
   (one), separable (a row, then a column), or a-trous (`atrous` dilated windows). Both
   backends run this list. */
int ssg_bilateral_passes(const struct ssg_bilateral_consts *c,
                         struct ssg_bilateral_pass pass[SSG_BILATERAL_MAX_PASSES]);

/* What the `atrous` node (atrous.c in this folder) shares: its ports are bilateral's (the
   port tables, their shape check), its consts a struct ssg_bilateral_consts, and so the
   flops (node.h; by reading bilateral_cpu.c: per tap the weight, ssg_joint_tap_flops, and
   2 a channel, per pass about 10 and 1 a channel to set up and finish) and both run
   functions are bilateral's. */
extern const struct ssg_port_desc ssg_bilateral_inputs[SSG_BILATERAL_INPUTS];
extern const struct ssg_port_desc ssg_bilateral_outputs[SSG_BILATERAL_OUTPUTS];
enum ssg_err ssg_bilateral_check_shapes(const struct ssg_shape *in, struct ssg_shape *out,
                                        char *why, size_t why_len);
double ssg_bilateral_flops(const void *consts, const struct ssg_shape *in);
/* The descriptor fields both nodes share: ports, consts, flops and run functions, and the
   constants' rows (each file makes its table `uniforms` from SSG_BILATERAL_UNIFORMS). */
#define SSG_BILATERAL_FAMILY                                                             \
    SSG_NODE_PORTS(ssg_bilateral_inputs, ssg_bilateral_outputs),                          \
    .consts_size = sizeof(struct ssg_bilateral_consts),                                  \
    SSG_NODE_UNIFORMS(uniforms, struct ssg_bilateral_consts, u),                         \
    .flops_per_pixel = ssg_bilateral_flops, .run_cpu = ssg_bilateral_run_cpu,            \
    .run_gl = ssg_bilateral_run_gl
enum ssg_err ssg_bilateral_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io);
/* The GL side (bilateral_gl.c, shader bilateral*.glsl). */
enum ssg_err ssg_bilateral_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io);

#endif
