/* ssdo.h - parameters and prepared constants of the `ssdo` node, shared by ssdo.c
 * (descriptor, check, prepare), ssdo_cpu.c (the CPU kernel) and ssdo_gl.c (the GL side).
 * Method and conventions: README.md in this folder; the per-sample maths it shares with
 * `bounce` in ssdo_sampling.h (on GL, ssdo.glsl serves both nodes).
 * Read-only after prepare(); the kernel is thread-safe. */
#ifndef SSG_SSDO_H
#define SSG_SSDO_H

#include "scene/env.h"
#include "graph/image.h"
#include "graph/node.h"
#include "ssdo_sampling.h"

#define SSG_SSDO_MAX_LIGHTS 8

/* Output ports, one row each (graph/node.h); the inputs are ssdo_sampling.h's. */
#define SSG_SSDO_OUT(X)                                                                    \
    X(SSG_SSDO_OUT_OUT, "out", SSG_T_SCALAR | SSG_T_COLOR,                                 \
      "modulation factor (scalar, or color with channels=3; 1 = unoccluded) or, mode "     \
      "radiance, the directional light (color)")                                           \
    X(SSG_SSDO_OUT_BOUNCE, "bounce", SSG_T_COLOR,                                          \
      "one indirect bounce, albedo * sum F_i L_i; 0 when bounce=false")
SSG_PORT_ENUM(ssg_ssdo_output, SSG_SSDO_OUT, SSG_SSDO_OUTPUTS);

enum ssg_ssdo_mode {
    SSG_SSDO_MODE_MODULATION, /* one-step method (Szentandrasi sec. 4.1): lit / unoccluded */
    SSG_SSDO_MODE_RADIANCE,   /* two-step first pass: albedo / pi * directional light (eq. 2) */
};

/* The parameters, one row each (lang/params.h): the sampling's (ssdo_sampling.h), then
   ssdo's own. The struct below and the table in ssdo.c are made from these rows; the
   shader reads those not host_only as p_<field> (#pragma ssg_params). */
#define SSG_SSDO_PARAMS(P)                                                                 \
    SSG_SSDO_GEOM_PARAMS(P)                                                                \
    P(ENUM, mode,                                                                          \
      "modulation: lit / unoccluded light (one-step, sec. 4.1); radiance: albedo/pi * "    \
      "directional light (eq. 2)",                                                         \
      .def = SSG_SSDO_MODE_MODULATION, .choices = ssg_ssdo_mode_choices)                   \
    P(INT, channels, "modulation: 1 = one factor of the luminances, 3 = one per colour "   \
      "channel", .def = 1, .min = 1, .max = 3, .soft_min = 1, .soft_max = 3,               \
      .host_only = 1) /* check(), prepare(): out_channels */                               \
    P(BOOL, bounce, "compute the indirect bounce output (needs albedo and light)",         \
      .def = 0)                                                                            \
    P(INT, lobe,                                                                           \
      "cosine power of the cone over which a point or directional light is sampled",       \
      .def = 4, .min = 1, .max = 64, .soft_min = 1, .soft_max = 64)                        \
    P(FLOAT, power,                                                                        \
      "modulation: out = M^power, the darkening ssao's power gives its AO (ssdo.graph "    \
      "uses 2, measured: docs/accuracy.md)",                                               \
      .def = 1, .min = 0, .max = 8, .soft_min = 0, .soft_max = 8)
SSG_PARAMS_STRUCT(ssg_ssdo_params, SSG_SSDO_PARAMS);

/* A scene light in view space. On GL the array is a storage buffer of these structs as
   they are (ssdo.glsl's struct ssdo_light: std430 lays out an int, three float[3] and two
   floats as C does, 48 bytes). */
struct ssg_ssdo_light {
    int directional;  /* 0 = point or spot light at `v`, 1 = directional light from unit `v` */
    float v[3];       /* point: view-space position; directional: unit direction to it */
    float rgb[3];     /* colour * intensity */
    float axis[3];    /* spot: the cone's view-space unit axis */
    float cone_scale, cone_offset; /* the cone (ssg_cone_falloff; point: 0, 1) */
};
_Static_assert(sizeof(struct ssg_ssdo_light) == 12 * sizeof(float),
               "ssdo.glsl reads the lights as std430 structs of 12 scalars");

enum ssg_ssdo_env { SSG_SSDO_ENV_CONSTANT, SSG_SSDO_ENV_CUBE };

struct ssg_ssdo_consts {
    struct ssg_ssdo_params p;   /* the parameters as given */
    struct ssg_projection proj; /* the frame's camera as the G-buffer's resolution sees
                                   it (ssg_sampling_projection) */
    struct ssg_ssdo_geom g;     /* the sampling's constants (ssg_ssdo_geom_of) */
    int out_channels;           /* of output `out`: 1, or 3 (radiance, channels=3) */
    int light_count;            /* 0..SSG_SSDO_MAX_LIGHTS */
    struct ssg_ssdo_light lights[SSG_SSDO_MAX_LIGHTS];
    int env;                    /* enum ssg_ssdo_env */
    float env_rgb[3];           /* constant environment radiance (1 without a scene) */
    struct ssg_env_cube cube;   /* the probe in view space (env = cube) */
};

/* The constants ssdo.glsl reads (#pragma ssg_consts): the sampling's, then the lights'
   and the environment's (the lights themselves and the cube: storage buffers). */
#define SSG_SSDO_UNIFORMS(U)                                                               \
    SSG_SSDO_GEOM_UNIFORMS(U)                                                              \
    U(INT, out_channels, out_channels, "of output out: 1, or 3 (radiance, channels=3)")    \
    U(INT, light_count, light_count, "lights in the storage buffer, 0..8")                 \
    U(INT, env, env, "enum ssg_ssdo_env")                                                  \
    U(VEC3, env_rgb, env_rgb, "constant environment radiance")

enum ssg_err ssg_ssdo_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);
/* The GL side (ssdo_gl.c, shader ssdo.glsl). */
enum ssg_err ssg_ssdo_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);

#endif
