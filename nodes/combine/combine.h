/* combine.h - ports, parameters and prepared constants of the `combine` node (final
 * shading), shared by combine.c (descriptor, check, prepare), combine_cpu.c (the kernel),
 * combine_gl.c (the GL side) and test_combine.c. Method in README.md. */
#ifndef SSG_COMBINE_H
#define SSG_COMBINE_H

#include "graph/node.h"

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_COMBINE_IN(X)                                                                  \
    X(SSG_COMBINE_IN_DIRECT, "direct", SSG_T_COLOR,                                        \
      "direct light (diffuse + specular) of the visible surface, linear RGB")              \
    X(SSG_COMBINE_IN_ALBEDO, "albedo", SSG_T_COLOR, "diffuse reflectance, linear RGB")     \
    X(SSG_COMBINE_IN_AMBIENT_OCCLUSION, "ambient_occlusion", SSG_T_SCALAR,                 \
      "ambient occlusion, 1 = unoccluded; unconnected = 1 everywhere", .optional = 1)      \
    X(SSG_COMBINE_IN_INDIRECT, "indirect", SSG_T_COLOR,                                    \
      "indirect light (a bounce), linear RGB; unconnected = 0", .optional = 1)             \
    X(SSG_COMBINE_IN_MODULATION, "modulation", SSG_T_SCALAR | SSG_T_COLOR,                 \
      "SSDO modulation factor (1 or 3 channels) darkening direct, environment, ambient "   \
      "and (darken_indirect) indirect light; unconnected = 1", .optional = 1)              \
    X(SSG_COMBINE_IN_ENVIRONMENT, "environment", SSG_T_COLOR,                              \
      "unoccluded environment light (gbuffer.environment), darkened like the ambient "     \
      "term; unconnected = 0", .optional = 1)                                              \
    X(SSG_COMBINE_IN_FAR_VISIBILITY, "far_visibility", SSG_T_SCALAR,                       \
      "visibility V already in environment (probe_light.visibility): the modulation "      \
      "then darkens it by min(1, M / V), not M, and far_bounce fills max(0, M - V); "      \
      "unconnected = no far field", .optional = 1)                                         \
    X(SSG_COMBINE_IN_IRRADIANCE, "irradiance", SSG_T_COLOR,                                \
      "indirect light as E / pi (a white diffuse surface's radiance, e.g. rsm.out "        \
      "upsampled): adds M ao albedo irradiance; unconnected = 0", .optional = 1)          \
    X(SSG_COMBINE_IN_EMISSION, "emission", SSG_T_COLOR,                                    \
      "light the surface emits (gbuffer.emission), added as it is: no factor darkens "    \
      "it; unconnected = 0", .optional = 1)
#define SSG_COMBINE_OUT(X)                                                                 \
    X(SSG_COMBINE_OUT_OUT, "out", SSG_T_COLOR,                                             \
      "shaded frame, linear RGB (unbounded; write tone-maps its PNG)", .same_as = "direct")
SSG_PORT_ENUM(ssg_combine_input, SSG_COMBINE_IN, SSG_COMBINE_INPUTS);
SSG_PORT_ENUM(ssg_combine_output, SSG_COMBINE_OUT, SSG_COMBINE_OUTPUTS);

/* The parameters, one row each (lang/params.h). The ambient light becomes one factor k in
   prepare(); the shader reads the three switches as p_<field> (#pragma ssg_params). */
#define SSG_COMBINE_PARAMS(P)                                                              \
    P(FLOAT, ambient,                                                                      \
      "strength of the uniform ambient light that AO darkens (linear, like direct)",       \
      .def = 0.3, .min = 0, .max = 10, .soft_min = 0, .soft_max = 2,                       \
      .host_only = 1) /* prepare(): k */                                                   \
    P(VEC3, ambient_color, "tint of the ambient light", .min = 0, .max = 100,              \
      .def3 = {1, 1, 1}, .unit = "linear RGB", .host_only = 1) /* prepare(): k */          \
    P(BOOL, darken_indirect,                                                               \
      "the modulation factor darkens the indirect light too (the one-step SSDO rule "      \
      "against over-bright corners)",                                                      \
      .def = 1)                                                                            \
    P(BOOL, far_bounce,                                                                    \
      "with far_visibility: directions blocked beyond the modulation's reach bounce "      \
      "albedo x the pixel's own radiance (its environment part alone when irradiance is "  \
      "connected)",                                                                        \
      .def = 1)                                                                            \
    P(BOOL, environment_albedo,                                                            \
      "environment is E / pi of a white receiver (probe_light without albedo, computed "  \
      "at low resolution and upsampled): it is multiplied by the albedo here",             \
      .def = 0)                                                                            \
    P(BOOL, darken_direct,                                                                 \
      "the modulation factor darkens direct light (false for direct light that is "        \
      "already shadowed, direct_light.out)",                                               \
      .def = 1)
SSG_PARAMS_STRUCT(ssg_combine_params, SSG_COMBINE_PARAMS);

/* What prepare() makes for both backends (the shader reads it by name, #pragma
   ssg_consts). */
#define SSG_COMBINE_UNIFORMS(U)                                                            \
    U(VEC3, k, "ambient * ambient_color, per channel")                                    \
    U(INT, modulation_last, "last plane of the modulation: 0 (one factor, or none) or 2 " \
      "(RGB); channel c reads plane min(c, this)")
SSG_UNIFORMS_STRUCT(ssg_combine_uniforms, SSG_COMBINE_UNIFORMS);

struct ssg_combine_consts {
    struct ssg_combine_params p;   /* the parameters as given */
    struct ssg_combine_uniforms u; /* the constants both backends read */
};

/* The CPU backend (combine_cpu.c). */
enum ssg_err ssg_combine_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);
/* The GL side (combine_gl.c, shader combine.glsl). */
enum ssg_err ssg_combine_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);

#endif
