/* complexity.h - parameters and prepared constants of the `complexity` node, shared by
 * complexity.c (descriptor, check, prepare), complexity_cpu.c (the CPU pass) and
 * complexity_gl.c (the GL side). Method and the gradient-to-count mapping: README.md in
 * this folder. Read-only after prepare(); the pass is thread-safe. */
#ifndef SSG_COMPLEXITY_H
#define SSG_COMPLEXITY_H

#include "graph/node.h"

#define SSG_COMPLEXITY_MAX_SCALE 8       /* largest base cell side, px */
#define SSG_COMPLEXITY_MAX_RESOLUTIONS 4 /* scales combined: scale, 2 scale, 4, 8 scale */

/* Ports, one row each (node.h): enumerator, name, types, doc; on GL (.gl_in) the inputs
   are read by the means and the count pass, the output written by the count pass. */
#define SSG_COMPLEXITY_IN(X)                                                               \
    X(SSG_COMPLEXITY_IN_DEPTH, "depth", SSG_T_SCALAR, "linear depth (0 = background)",     \
      .gl_in = SSG_COMPLEXITY_GL_PIXELS)                                                   \
    X(SSG_COMPLEXITY_IN_NORMAL, "normal", SSG_T_VECTOR, "unit view-space normal",          \
      .gl_in = SSG_COMPLEXITY_GL_PIXELS)
#define SSG_COMPLEXITY_OUT(X)                                                              \
    X(SSG_COMPLEXITY_OUT_COUNT, "count", SSG_T_SCALAR,                                     \
      "per-pixel sample count, one of levels (for ssao/hbao/ssdo.count)",                  \
      .gl_in = SSG_COMPLEXITY_GL_COUNT)
#define SSG_COMPLEXITY_GL_PIXELS "complexity_means.glsl complexity_count.glsl"
#define SSG_COMPLEXITY_GL_COUNT "complexity_count.glsl"
#define SSG_COMPLEXITY_GL_WEIGHT "complexity_weight.glsl"
SSG_PORT_ENUM(ssg_complexity_input, SSG_COMPLEXITY_IN, SSG_COMPLEXITY_INPUTS);
SSG_PORT_ENUM(ssg_complexity_output, SSG_COMPLEXITY_OUT, SSG_COMPLEXITY_OUTPUTS);

/* The parameters, one row each (lang/params.h): kind, field, doc, then default, range and
   unit. On GL (#pragma ssg_params, p_<field>) complexity_weight.glsl reads the thresholds
   and gains, complexity_count.glsl the levels and the grids (grid r: cells of
   p_scale << r px, as prepare() lays them out). */
#define SSG_COMPLEXITY_PARAMS(P)                                                           \
    P(INTS, levels,                                                                        \
      "sample counts, ascending, each a multiple of period (Szentandrasi table 1)",        \
      .def_ints = {20, 30, 40, 50}, .def_ints_count = 4, .min_count = 1,                   \
      .max_count = SSG_INTS_MAX, .min = 1, .max = 1024, .unit = "samples",                 \
      .gl_in = SSG_COMPLEXITY_GL_COUNT)                                                    \
    P(INT, period, "Halton period N_g of the kernel (eq. 8): counts are whole periods",    \
      .def = 10, .min = 1, .max = 1024, .soft_min = 1, .soft_max = 64, .unit = "samples",  \
      .host_only = 1) /* check() */                                                        \
    P(INT, scale, "cell side of the grid the gradients are taken on: 1, 2, 4 or 8",        \
      .def = 4, .min = 1, .max = SSG_COMPLEXITY_MAX_SCALE, .soft_min = 1,                  \
      .soft_max = SSG_COMPLEXITY_MAX_SCALE, .unit = "px",                                  \
      .gl_in = SSG_COMPLEXITY_GL_COUNT)                                                    \
    P(INT, resolutions, "grids combined by max: cells of scale, 2 scale, ... px",          \
      .def = 1, .min = 1, .max = SSG_COMPLEXITY_MAX_RESOLUTIONS, .soft_min = 1,            \
      .soft_max = SSG_COMPLEXITY_MAX_RESOLUTIONS,                                          \
      .gl_in = SSG_COMPLEXITY_GL_COUNT)                                                    \
    P(FLOAT, normal_threshold,                                                             \
      "sum over neighbour cells of |n - n_nb| below which a cell is flat", .def = 0.1,     \
      .min = 0, .max = 8, .soft_min = 0, .soft_max = 1, .gl_in = SSG_COMPLEXITY_GL_WEIGHT) \
    P(FLOAT, normal_gain, "weight = (gradient - threshold) gain, clamped to [0, 1]",       \
      .def = 2, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 20,                       \
      .gl_in = SSG_COMPLEXITY_GL_WEIGHT)                                                   \
    P(FLOAT, depth_threshold,                                                              \
      "sum of |n . (P_nb - P)| / depth (depth change off the tangent plane, relative) "    \
      "below which a cell is flat",                                                        \
      .def = 0.02, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 0.2,                   \
      .gl_in = SSG_COMPLEXITY_GL_WEIGHT)                                                   \
    P(FLOAT, depth_gain, "weight = (gradient - threshold) gain, clamped to [0, 1]",        \
      .def = 10, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 100,                     \
      .gl_in = SSG_COMPLEXITY_GL_WEIGHT)
SSG_PARAMS_STRUCT(ssg_complexity_params, SSG_COMPLEXITY_PARAMS);

/* One grid of cells, as prepare() lays it out for the inputs' size. */
struct ssg_complexity_grid {
    int side;   /* cell side, px: scale << r for grid r */
    int gw, gh; /* cells across and down: ceil(width / side), ceil(height / side) */
};

struct ssg_complexity_consts {
    struct ssg_complexity_params p; /* the parameters as given */
    struct ssg_projection proj;     /* the frame's camera as the G-buffer's resolution
                                       sees it (ssg_sampling_projection) */
    int grids;                      /* resolutions: grids combined */
    struct ssg_complexity_grid grid[SSG_COMPLEXITY_MAX_RESOLUTIONS]; /* the first grids */
};

/* The constant the means pass reads (#pragma ssg_consts), a row over the consts' field. */
#define SSG_COMPLEXITY_UNIFORMS(U)                                                         \
    U(PROJECTION, proj, proj, "(f, cx, cy) of the inputs' size",                           \
      .gl_in = "complexity_means.glsl")

enum ssg_err ssg_complexity_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);
/* The GL side (complexity_gl.c, shaders complexity_*.glsl). */
enum ssg_err ssg_complexity_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io);

#endif
