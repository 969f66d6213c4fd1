/* gtao.h - parameters and prepared constants of the `gtao` node, shared by gtao.c
 * (descriptor, check, prepare), gtao_cpu.c (the CPU kernel) and gtao_gl.c (the GL side).
 * Method and conventions: README.md. Read-only after prepare(); the kernel
 * is thread-safe. */
#ifndef SSG_GTAO_H
#define SSG_GTAO_H

#include "common/horizon.h"
#include "graph/node.h"

#define SSG_GTAO_MAX_SLICES 32
#define SSG_GTAO_MAX_STEPS 64
/* With back: the side's previous sample links to a sample lying at most this times R
   behind its back (README.md). Measured with graphs/ao_error.graph at 640x480, gtao's rmse
   against reference_ao: 0, 0.05, 0.1, 0.2, 0.4 gave 0.0516, 0.0504, 0.0493, 0.0469,
   0.0451 on the thin panel and 0.0319, 0.0317, 0.0317, 0.0320, 0.0338 on the table
   (0.0496 and 0.0698 without back); 0.3 (0.0456, 0.0326) keeps most of both gains. */
#define SSG_GTAO_BACK_LINK 0.3f

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields; the
   G-buffer's four as the horizon nodes share them (common/horizon.h). */
#define SSG_GTAO_IN(X)                                                                     \
    SSG_HORIZON_IN(X, SSG_GTAO_IN_POSITION, SSG_GTAO_IN_NORMAL,                   \
                            SSG_GTAO_IN_ROTATION, SSG_GTAO_IN_DEPTH, "slices")             \
    X(SSG_GTAO_IN_BACK, "back", SSG_T_SCALAR,                                              \
      "depth of the next surface behind each pixel's (gbuffer.back, +inf = none): a "      \
      "sample occludes only between its depth and this; none = infinitely thick",          \
      .optional = 1)
#define SSG_GTAO_OUT(X)                                                                    \
    X(SSG_GTAO_OUT_OUT, "out", SSG_T_SCALAR,                                               \
      "cosine-weighted visibility within radius, 1 = unoccluded")                          \
    X(SSG_GTAO_OUT_BENT_NORMAL, "bent_normal", SSG_T_VECTOR,                               \
      "unit view-space mean unoccluded direction; background 0")
SSG_PORT_ENUM(ssg_gtao_input, SSG_GTAO_IN, SSG_GTAO_INPUTS);
SSG_PORT_ENUM(ssg_gtao_output, SSG_GTAO_OUT, SSG_GTAO_OUTPUTS);

/* The parameters, one row each (lang/params.h); the GL shader reads them as p_<field>
   (#pragma ssg_params). */
#define SSG_GTAO_PARAMS(P)                                                                 \
    P(INT, slices,                                                                         \
      "slice directions per pixel over the half circle about the view vector, each "       \
      "marched both ways (turned by the rotation pattern)",                                \
      .def = 8, .min = 1, .max = SSG_GTAO_MAX_SLICES, .soft_min = 1,                       \
      .soft_max = SSG_GTAO_MAX_SLICES)                                                     \
    P(INT, steps, "depth samples on each side of a slice", .def = 12, .min = 1,            \
      .max = SSG_GTAO_MAX_STEPS, .soft_min = 1, .soft_max = 32)                            \
    P(FLOAT, radius, "R: samples farther than this from the pixel are ignored",            \
      .def = 0.5, .min = 1e-6, .max = 1e6, .soft_min = 0.05, .soft_max = 5,                \
      .unit = "scene units")                                                               \
    P(FLOAT, falloff,                                                                      \
      "fraction of R over which a sample's weight fades to 0 at R; 0 = hard cutoff "       \
      "(reference_ao's distance limit)",                                                   \
      .def = 0, .min = 0, .max = 1, .soft_min = 0, .soft_max = 1)                          \
    P(FLOAT, thickness,                                                                    \
      "thin-occluder heuristic: how far a sample below the horizon pulls it down; 0 = "    \
      "depth samples are an infinitely thick height field",                                \
      .def = 0, .min = 0, .max = 0.99, .soft_min = 0, .soft_max = 0.99)                    \
    P(FLOAT, power, "out = visibility^power", .def = 1, .min = 0.1, .max = 8,              \
      .soft_min = 0.1, .soft_max = 8)                                                      \
    P(FLOAT, max_screen_radius,                                                            \
      "caps the projected radius f R / (depth - R) of the march; 0 = no cap", .def = 0,    \
      .min = 0, .max = 16384, .soft_min = 0, .soft_max = 512, .unit = "px")
SSG_PARAMS_STRUCT(ssg_gtao_params, SSG_GTAO_PARAMS);

/* What prepare() makes once for both backends; sized to the G-buffer's width
   (consts_size_of: the column table e1 is a flexible array). */
/* The constants prepare() makes for both backends, one row each (lang/params.h); the
   shader reads them under these names (#pragma ssg_consts). Falloff weight w = clamp(r
   fall_mul + fall_add, 0, 1) (falloff > 0; falloff 0 is the test r <= R); with back, a
   sample's arc reaches down to the side's previous sample when that lies at most `link`
   behind the sample's back, scene units (README.md). */
#define SSG_GTAO_UNIFORMS(U)                                                               \
    U(FLOAT, fall_mul, "falloff slope") U(FLOAT, fall_add, "falloff offset")               \
    U(FLOAT, link, "with back: the arcs' link distance")
SSG_UNIFORMS_STRUCT(ssg_gtao_uniforms, SSG_GTAO_UNIFORMS);

struct ssg_gtao_consts {
    struct ssg_gtao_params p;   /* the parameters as given */
    struct ssg_projection proj; /* the frame's camera at the G-buffer's resolution */
    float invf;                 /* 1 / f */
    struct ssg_gtao_uniforms u; /* prepare()'s constants both backends read by name */
    /* Per column x of the G-buffer (width w): e1 = (1, 0, a_u) / sqrt(1 + a_u^2), e1x at
       [x] and e1z at [w + x] (ssg_horizon_frame); read by both backends. */
    float e1[];
};

/* What changes from one frame of a sequence to the next (README.md, "Frames"), made by
   ssg_gtao_frame_of for both backends: the slice table turned by a golden-ratio fraction
   of one slice, and the offset of the step jitter's noise. */
struct ssg_gtao_frame {
    float slice_cos[SSG_GTAO_MAX_SLICES]; /* cos(pi (k + ssg_sampling_frame_turn) / slices) */
    float slice_sin[SSG_GTAO_MAX_SLICES]; /* sin of the same */
    float shift; /* pixels added to both coordinates of the jitter noise; 0 in frame 0 */
};
void ssg_gtao_frame_of(const struct ssg_gtao_consts *c, int frame, struct ssg_gtao_frame *f);

enum ssg_err ssg_gtao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);
/* The GL side (gtao_gl.c, shader gtao.glsl). */
enum ssg_err ssg_gtao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);

#endif
