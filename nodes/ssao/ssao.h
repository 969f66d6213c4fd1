/* ssao.h - parameters and prepared constants of the `ssao` node, shared by ssao.c
 * (descriptor, check, prepare), ssao_cpu.c (the CPU kernel) and ssao_gl.c (the GL side).
 * Method and conventions: README.md. */
#ifndef SSG_SSAO_H
#define SSG_SSAO_H

#include "graph/node.h"

enum ssg_ssao_range {
    SSG_SSAO_RANGE_NONE,   /* every occluder counts fully */
    SSG_SSAO_RANGE_HARD,   /* occluders farther than radius in depth do not count */
    SSG_SSAO_RANGE_SMOOTH, /* weight smoothstep(0, 1, radius / |depth difference|) */
};

enum ssg_ssao_mode {
    SSG_SSAO_MODE_HEMISPHERE, /* samples in the hemisphere about the normal */
    SSG_SSAO_MODE_SPHERE,     /* normal-free: samples in the sphere about the point */
    SSG_SSAO_MODE_DISC,       /* normal-free: depth samples in a screen-space disc */
};

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_SSAO_IN(X)                                                                     \
    X(SSG_SSAO_IN_POSITION, "position", SSG_T_VECTOR, "view-space position")               \
    X(SSG_SSAO_IN_NORMAL, "normal", SSG_T_VECTOR,                                          \
      "unit view-space normal (mode hemisphere only; required there)", .optional = 1)      \
    X(SSG_SSAO_IN_KERNEL, "kernel", SSG_T_KERNEL, "hemisphere samples (halton.samples)")    \
    X(SSG_SSAO_IN_ROTATION, "rotation", SSG_T_PATTERN,                                     \
      "per-pixel rotation tile (halton.rotation; a third plane moves the sample "          \
      "lengths); none = no rotation", .optional = 1)                                       \
    X(SSG_SSAO_IN_DEPTH, "depth", SSG_T_SCALAR,                                            \
      "linear depth for the occluder lookup; none = -position.z", .optional = 1)           \
    X(SSG_SSAO_IN_COUNT, "count", SSG_T_SCALAR,                                            \
      "per-pixel sample count (complexity.count): the first n of the kernel; none = all",  \
      .optional = 1)
#define SSG_SSAO_OUT(X) X(SSG_SSAO_OUT_OUT, "out", SSG_T_SCALAR, "visibility, 1 = unoccluded")
SSG_PORT_ENUM(ssg_ssao_input, SSG_SSAO_IN, SSG_SSAO_INPUTS);
SSG_PORT_ENUM(ssg_ssao_output, SSG_SSAO_OUT, SSG_SSAO_OUTPUTS);

/* The parameters, one row each (lang/params.h): kind, field, doc, then default, range,
   unit and choices. The struct below and the table in ssao.c are made from these rows;
   the GL shader reads them as p_<field> (#pragma ssg_params). */
#define SSG_SSAO_PARAMS(P)                                                                 \
    P(FLOAT, radius, "hemisphere radius around the pixel", .def = 0.5, .min = 1e-6,        \
      .max = 1e6, .soft_min = 0.05, .soft_max = 5, .unit = "scene units")                  \
    P(FLOAT, bias,                                                                         \
      "a sample is occluded only when the surface is this much in front of it (default "   \
      "0: chosen by ssgraph tune over the example scenes, docs/accuracy.md)",              \
      .def = 0, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 0.2,                      \
      .unit = "scene units")                                                               \
    P(FLOAT, power,                                                                        \
      "intensity: out = visibility^power (default 2: with 16 samples the lowest mean "     \
      "error against reference_ao, docs/accuracy.md)",                                     \
      .def = 2, .min = 0, .max = 64, .soft_min = 0, .soft_max = 8)                         \
    P(ENUM, range_check, "how occluders far in depth from the pixel are discounted",       \
      .def = SSG_SSAO_RANGE_HARD, .choices = ssg_ssao_range_choices)                       \
    P(FLOAT, max_screen_radius, "caps the projected radius; 0 = no cap", .def = 0,         \
      .min = 0, .max = 16384, .soft_min = 0, .soft_max = 512, .unit = "px",                \
      .host_only = 1) /* prepare(): cap, capped */                                         \
    P(ENUM, mode,                                                                          \
      "hemisphere about the normal; sphere (normal-free, Knuth and Kohlhammer); disc "     \
      "(screen-space depth samples, Crytek 2007)",                                         \
      .def = SSG_SSAO_MODE_HEMISPHERE, .choices = ssg_ssao_mode_choices)
SSG_PARAMS_STRUCT(ssg_ssao_params, SSG_SSAO_PARAMS);

/* The constants prepare() makes for both backends, one row each (lang/params.h); the
   shader reads them under these names (#pragma ssg_consts). */
#define SSG_SSAO_UNIFORMS(U)                                                               \
    U(FLOAT, cap, "max_screen_radius / f: r <= cap depth(P) when capped")                  \
    U(BOOL, capped, "max_screen_radius > 0")                                               \
    U(FLOAT, inv_samples, "1 / kernel width")                                              \
    U(PROJECTION, proj,                                                                    \
      "the frame's camera as seen by the G-buffer's resolution (ssg_projection_scaled: a " \
      "subsampled G-buffer sees the same camera)")
SSG_UNIFORMS_STRUCT(ssg_ssao_uniforms, SSG_SSAO_UNIFORMS);

struct ssg_ssao_consts {
    struct ssg_ssao_params p; /* the parameters as given */
    struct ssg_ssao_uniforms u; /* prepare()'s constants both backends read by name */
};

enum ssg_err ssg_ssao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);
/* The GL side (ssao_gl.c, shader ssao.glsl). */
enum ssg_err ssg_ssao_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);

#endif
