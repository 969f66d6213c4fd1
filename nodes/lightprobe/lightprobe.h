/* lightprobe.h - the `lightprobe` node's parameters and constants (lightprobe.c), shared by
 * its backends and tests: the scene's environment turned into a light list (SSG_T_LIGHTS,
 * nodes/common/shadowmap.h) once, in prepare(). Method: README.md in this folder. */
#ifndef SSG_LIGHTPROBE_H
#define SSG_LIGHTPROBE_H

#include "scene/env.h"
#include "graph/node.h"
#include "common/env_lights.h"
#include "common/shadowmap.h"

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_LIGHTPROBE_OUT(X)                                                              \
    X(SSG_LIGHTPROBE_OUT_LIGHTS, "lights", SSG_T_LIGHTS,                                   \
      "N x 2: row 0 the unit world direction towards each light, row 1 its RGB "          \
      "irradiance; the irradiances add up to the probe's integral")
SSG_PORT_ENUM(ssg_lightprobe_output, SSG_LIGHTPROBE_OUT, SSG_LIGHTPROBE_OUTPUTS);

enum ssg_lightprobe_sampling {
    SSG_LIGHTPROBE_UNIFORM,    /* a spherical Fibonacci set: near-equal areas 4 pi / N */
    SSG_LIGHTPROBE_IMPORTANCE, /* the Fibonacci lattice through the probe's luminance CDF */
};

enum ssg_lightprobe_missing {
    SSG_LIGHTPROBE_MISSING_ERROR, /* a scene without environment light is an error */
    SSG_LIGHTPROBE_MISSING_DARK,  /* ... gets N lights of irradiance 0 */
};

/* The parameters, one row each (lang/params.h). The light list is made in prepare() and
   copied out on both backends, so every row is host_only. */
#define SSG_LIGHTPROBE_PARAMS(P)                                                           \
    P(INT, count, "directional lights N (the paper: 128 and 512, 2048 for its reference)",  \
      .def = 128, .min = SSG_LIGHTS_MIN, .max = SSG_LIGHTS_MAX,                            \
      .soft_min = SSG_LIGHTS_MIN, .soft_max = SSG_LIGHTS_MAX, .unit = "lights",            \
      .host_only = 1)                                                                      \
    P(ENUM, sampling,                                                                      \
      "uniform: equal-area Fibonacci set (the paper); importance: denser where the "      \
      "probe is bright",                                                                   \
      .def = SSG_LIGHTPROBE_UNIFORM, .choices = ssg_lightprobe_sampling_choices,           \
      .host_only = 1)                                                                      \
    P(FLOAT, uniform_share,                                                                \
      "importance: this share of the N lights is the uniform set, so the probe's dim "    \
      "parts keep lights of their own (0 = every light drawn through the probe)",          \
      .def = 0, .min = 0, .max = 1, .soft_min = 0, .soft_max = 1, .unit = "x N",           \
      .host_only = 1)                                                                      \
    P(ENUM, missing,                                                                       \
      "a scene without environment light: error, or dark (N lights of irradiance 0, "     \
      "so one graph serves scenes with and without a probe)",                              \
      .def = SSG_LIGHTPROBE_MISSING_ERROR, .choices = ssg_lightprobe_missing_choices,      \
      .host_only = 1)
SSG_PARAMS_STRUCT(ssg_lightprobe_params, SSG_LIGHTPROBE_PARAMS);

/* What prepare() makes: the light list exactly as the output image holds it (planar; row 0
 * the directions, row 1 the irradiances), sized to `count` (consts_size_of). */
struct ssg_lightprobe_consts {
    int count;
    float lights[]; /* 6 count floats: channel c, row r, light i at (c * 2 + r) * count + i */
};

enum ssg_err ssg_lightprobe_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);
enum ssg_err ssg_lightprobe_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_lightprobe;

#endif
