/* hbao.h - parameters and prepared constants of the `hbao` node, shared by hbao.c
 * (descriptor, check, prepare), hbao_cpu.c (the CPU kernel) and hbao_gl.c (the GL side).
 * Method and conventions: README.md. Read-only after prepare(); the kernel
 * is thread-safe. */
#ifndef SSG_HBAO_H
#define SSG_HBAO_H

#include "common/horizon.h"
#include "graph/node.h"

#define SSG_HBAO_MAX_DIRECTIONS 64
#define SSG_HBAO_MAX_STEPS 64

enum ssg_hbao_falloff {
    SSG_HBAO_FALLOFF_LINEAR, /* W = max(0, 1 - r / R) (Belonogov eq. 3.2) */
    SSG_HBAO_FALLOFF_NONE,   /* W = 1 for r <= R: a hard distance limit, for comparisons
                                with distance-limited references */
};

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields; the
   G-buffer's four as the horizon nodes share them (common/horizon.h). */
#define SSG_HBAO_IN(X)                                                                     \
    SSG_HORIZON_IN(X, SSG_HBAO_IN_POSITION, SSG_HBAO_IN_NORMAL,                   \
                            SSG_HBAO_IN_ROTATION, SSG_HBAO_IN_DEPTH, "directions")         \
    X(SSG_HBAO_IN_COUNT, "count", SSG_T_SCALAR,                                            \
      "per-pixel number of directions (complexity.count), taken in a spread order; "       \
      "none = all", .optional = 1)
#define SSG_HBAO_OUT(X) X(SSG_HBAO_OUT_OUT, "out", SSG_T_SCALAR, "visibility, 1 = unoccluded")
SSG_PORT_ENUM(ssg_hbao_input, SSG_HBAO_IN, SSG_HBAO_INPUTS);
SSG_PORT_ENUM(ssg_hbao_output, SSG_HBAO_OUT, SSG_HBAO_OUTPUTS);

/* The parameters, one row each (lang/params.h); the GL shader reads them as p_<field>
   (#pragma ssg_params), bias only through prepare()'s cos_bias and sin_bias. */
#define SSG_HBAO_PARAMS(P)                                                                 \
    P(INT, directions,                                                                     \
      "azimuths per pixel (uniform about the view vector, turned by the rotation pattern)", \
      .def = 8, .min = 1, .max = SSG_HBAO_MAX_DIRECTIONS, .soft_min = 1, .soft_max = 32)   \
    P(INT, steps, "depth samples marched along each direction", .def = 6, .min = 1,        \
      .max = SSG_HBAO_MAX_STEPS, .soft_min = 1, .soft_max = 32)                            \
    P(FLOAT, radius, "R: occluders farther than this from the pixel are ignored",          \
      .def = 0.5, .min = 1e-6, .max = 1e6, .soft_min = 0.05, .soft_max = 5,                \
      .unit = "scene units")                                                               \
    P(FLOAT, bias,                                                                         \
      "tangent-angle bias against self occlusion (0.25 rad ~ 14 degrees; Bavoil's 0.1 "    \
      "lets tessellation and pixel steps read as occlusion)",                              \
      .def = 0.25, .min = 0, .max = 1.5, .soft_min = 0, .soft_max = 1, .unit = "radians",  \
      .host_only = 1)                                                                      \
    P(FLOAT, strength,                                                                     \
      "out = 1 - strength * occlusion, clamped to [0, 1] (default 1.25 with bias 0.25: "   \
      "the lowest mean error against reference_ao)",                                       \
      .def = 1.25, .min = 0, .max = 16, .soft_min = 0, .soft_max = 4)                      \
    P(ENUM, falloff,                                                                       \
      "attenuation W at the horizon: linear = max(0, 1 - r/R) (eq. 3.2), none = 1",        \
      .def = SSG_HBAO_FALLOFF_NONE, .choices = ssg_hbao_falloff_choices)                   \
    P(FLOAT, max_screen_radius,                                                            \
      "caps the projected radius f R / (depth - R) of the march; 0 = no cap", .def = 0,    \
      .min = 0, .max = 16384, .soft_min = 0, .soft_max = 512, .unit = "px")
SSG_PARAMS_STRUCT(ssg_hbao_params, SSG_HBAO_PARAMS);

/* What prepare() makes once for both backends; sized to the G-buffer's width
   (consts_size_of: the column table e1 is a flexible array). */
/* The constants prepare() makes for both backends, one row each (lang/params.h); the
   shader reads them under these names (#pragma ssg_consts). */
#define SSG_HBAO_UNIFORMS(U)                                                               \
    U(FLOAT, r2, "R^2") U(FLOAT, inv_radius, "1 / R")                                      \
    U(FLOAT, inv_steps, "1 / steps") U(FLOAT, scale, "strength / directions")              \
    U(FLOAT, cos_bias, "cos(bias)") U(FLOAT, sin_bias, "sin(bias)")
SSG_UNIFORMS_STRUCT(ssg_hbao_uniforms, SSG_HBAO_UNIFORMS);

struct ssg_hbao_consts {
    struct ssg_hbao_params p;    /* the parameters as given */
    struct ssg_projection proj;  /* the frame's camera as the G-buffer's resolution sees
                                    it (ssg_sampling_projection) */
    float invf;                  /* 1 / f */
    struct ssg_hbao_uniforms u;  /* prepare()'s constants both backends read by name */
    float dir_cos[SSG_HBAO_MAX_DIRECTIONS]; /* cos(2 pi k / directions) */
    float dir_sin[SSG_HBAO_MAX_DIRECTIONS]; /* sin(2 pi k / directions) */
    int dir_rank[SSG_HBAO_MAX_DIRECTIONS];  /* place of direction k in the order the count
                                               input takes directions in (README.md) */
    /* Per column x of the G-buffer (width w): e1 = (1, 0, a_u) / sqrt(1 + a_u^2), e1x at
       [x] and e1z at [w + x]; read by both backends. */
    float e1[];
};

enum ssg_err ssg_hbao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);
/* The GL side (hbao_gl.c, shader hbao.glsl). */
enum ssg_err ssg_hbao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);

#endif
