/* upsample.h - parameters and prepared constants of the `upsample` node, shared by
 * upsample.c (descriptor, check, prepare), upsample_cpu.c (the CPU kernel) and
 * upsample_gl.c (the GL side). Method: README.md in this folder. */
#ifndef SSG_UPSAMPLE_H
#define SSG_UPSAMPLE_H

#include "graph/node.h"

#define SSG_UPSAMPLE_MAX_SIZE 9
#define SSG_UPSAMPLE_MAX_FACTOR 16
/* The steepest depth slope a pixel's plane may have, as a fraction of its depth per
   full-res px: on the example scenes a surface's own slope stays below 0.04 at 320 x 180
   (0.13 at 96 x 64), while a difference across a depth edge, the only one a pixel at the
   image border or on a one-pixel sliver has, is larger; such a pixel counts as flat. */
#define SSG_UPSAMPLE_MAX_SLOPE 0.25f

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. The shader
   reads `in` as src (a GLSL keyword), the normals only with NORMALS and in2 only with
   IN2_CH (its defines, upsample_gl.c). */
#define SSG_UPSAMPLE_IN(X)                                                                 \
    X(SSG_UPSAMPLE_IN_IN, "in", SSG_T_SCALAR | SSG_T_COLOR, "low-resolution image",        \
      .gl_name = "src")                                                                    \
    X(SSG_UPSAMPLE_IN_DEPTH, "depth", SSG_T_SCALAR,                                        \
      "full-resolution depth; 0 = background")                                             \
    X(SSG_UPSAMPLE_IN_NORMAL, "normal", SSG_T_VECTOR,                                      \
      "full-resolution unit normal; with low_normal, or neither", .optional = 1,           \
      .gl_if = "NORMALS")                                                                  \
    X(SSG_UPSAMPLE_IN_LOW_DEPTH, "low_depth", SSG_T_SCALAR,                                \
      "the depth `in` was computed on (its size)")                                         \
    X(SSG_UPSAMPLE_IN_LOW_NORMAL, "low_normal", SSG_T_VECTOR,                              \
      "the normal `in` was computed on; none = no normal term", .optional = 1,             \
      .gl_if = "NORMALS")                                                                  \
    X(SSG_UPSAMPLE_IN_IN2, "in2", SSG_T_SCALAR | SSG_T_COLOR,                              \
      "second low-res image (size of in), upsampled with the same weights", .optional = 1, \
      .gl_if = "IN2_CH")
#define SSG_UPSAMPLE_OUT(X)                                                                \
    X(SSG_UPSAMPLE_OUT_OUT, "out", SSG_T_SCALAR,                                           \
      "full-resolution image (size of depth); background 0", .same_as = "in")              \
    X(SSG_UPSAMPLE_OUT_OUT2, "out2", SSG_T_SCALAR,                                         \
      "in2 upsampled with out's weights (type of in2); all 0, shaped like out, when in2 "  \
      "is unconnected", .same_as = "in2", .on_demand = 1)
SSG_PORT_ENUM(ssg_upsample_input, SSG_UPSAMPLE_IN, SSG_UPSAMPLE_INPUTS);
SSG_PORT_ENUM(ssg_upsample_output, SSG_UPSAMPLE_OUT, SSG_UPSAMPLE_OUTPUTS);

/* The parameters, one row each (lang/params.h): kind, field, doc, then default, range and
   unit. No shader reads a parameter: the GL side binds prepare()'s constants. */
#define SSG_UPSAMPLE_PARAMS(P)                                                             \
    P(INT, size, "taps per side around the low-res pixel, odd", .def = 3, .min = 1,        \
      .max = SSG_UPSAMPLE_MAX_SIZE, .soft_min = 1, .soft_max = SSG_UPSAMPLE_MAX_SIZE,      \
      .unit = "low-res px")                                                                \
    P(FLOAT, sigma_spatial, "spatial Gaussian sigma; 0 = size / 3", .def = 0, .min = 0,    \
      .max = 1000, .soft_min = 0, .soft_max = 4, .unit = "low-res px")                     \
    P(FLOAT, sigma_depth, "depth sigma as a fraction of the full-res pixel's depth",       \
      .def = 0.05, .min = 1e-6, .max = 1000, .soft_min = 0.005, .soft_max = 0.5)           \
    P(INT, normal_power, "normal weight max(0, n.N)^p; 0 = off", .def = 16, .min = 0,      \
      .max = 127, .soft_min = 0, .soft_max = 64)
SSG_PARAMS_STRUCT(ssg_upsample_params, SSG_UPSAMPLE_PARAMS);

/* The constants prepare() makes, every one read by the shader by name (#pragma
   ssg_consts): the consts are this struct. The normal term's only with NORMALS. */
#define SSG_UPSAMPLE_UNIFORMS(U)                                                           \
    U(INT, radius, "(size - 1) / 2, low-res px")                                          \
    U(FLOAT, spatial_k, "-0.5 / (sigma_spatial k)^2: ln of the spatial weight per "      \
      "full-res px^2 (taps sit where their samples were taken)")                          \
    U(FLOAT, depth_scale, "1 / sigma_depth")                                              \
    U(FLOAT, normal_power, "as in the parameters", .gl_if = "NORMALS")                    \
    U(FLOAT, normal_min, "cosines below this weigh c^p < 1e-30 and count as 0",           \
      .gl_if = "NORMALS")                                                                  \
    U(INT, squarings, "c^p by that many squarings of c; -1 = p ln(c) in the exponent "    \
      "(ssg_joint_squarings)", .gl_if = "NORMALS")                                        \
    U(INT, factor, "k: in is depth subsampled by k (ssg_upsample_factor)")                \
    U(FLOAT, max_slope, "SSG_UPSAMPLE_MAX_SLOPE: steeper planes count as flat")
SSG_UNIFORMS_STRUCT(ssg_upsample_consts, SSG_UPSAMPLE_UNIFORMS);

/* The integer factor k with ceil(width / k) = low_width and ceil(height / k) = low_height
 * (the sizes `downsample` makes), or 0 when there is none. */
int ssg_upsample_factor(int width, int height, int low_width, int low_height);

enum ssg_err ssg_upsample_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io);
/* The GL side (upsample_gl.c, shader upsample*.glsl). */
enum ssg_err ssg_upsample_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io);

#endif
