/* reference_gi.h - parameters and prepared constants of the `reference_gi` node, shared by
 * reference_gi.c (descriptor, check, prepare) and reference_gi_cpu.c (the CPU kernel).
 * Method, estimators and sampling: README.md in this folder. */
#ifndef SSG_REFERENCE_GI_H
#define SSG_REFERENCE_GI_H

#include <stdint.h>

#include "graph/node.h"

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_REFERENCE_GI_IN(X)                                                             \
    X(SSG_REFERENCE_GI_IN_POSITION, "position", SSG_T_VECTOR,                              \
      "view-space position (gbuffer)")                                                     \
    X(SSG_REFERENCE_GI_IN_NORMAL, "normal", SSG_T_VECTOR,                                  \
      "unit view-space normal facing the camera, 0 = background (gbuffer)")                \
    X(SSG_REFERENCE_GI_IN_ALBEDO, "albedo", SSG_T_COLOR,                                   \
      "diffuse albedo, linear RGB (gbuffer)")
#define SSG_REFERENCE_GI_OUT(X)                                                            \
    X(SSG_REFERENCE_GI_OUT_DIRECT, "direct", SSG_T_COLOR,                                  \
      "diffuse light of the lights and the environment with true shadows, linear RGB")     \
    X(SSG_REFERENCE_GI_OUT_BOUNCE, "bounce", SSG_T_COLOR,                                  \
      "one diffuse bounce of that light off the scene's surfaces, linear RGB")             \
    X(SSG_REFERENCE_GI_OUT_OUT, "out", SSG_T_COLOR, "direct + bounce")
SSG_PORT_ENUM(ssg_reference_gi_input, SSG_REFERENCE_GI_IN, SSG_REFERENCE_GI_INPUTS);
SSG_PORT_ENUM(ssg_reference_gi_output, SSG_REFERENCE_GI_OUT, SSG_REFERENCE_GI_OUTPUTS);

/* Largest `samples`: the sample tables of the constants hold this many points. */
#define SSG_REFERENCE_GI_MAX_SAMPLES 65536

/* The parameters, one row each (lang/params.h). A CPU-only node: every row is host_only. */
#define SSG_REFERENCE_GI_PARAMS(P)                                                         \
    P(INT, samples,                                                                        \
      "environment samples (direct term) and bounce paths per pixel; the noise falls "     \
      "as 1 / sqrt(samples) or faster (stratified)",                                       \
      .def = 64, .min = 1, .max = SSG_REFERENCE_GI_MAX_SAMPLES, .soft_min = 1,             \
      .soft_max = 4096, .host_only = 1)                                                    \
    P(BOOL, bounce,                                                                        \
      "trace one diffuse bounce; false: the bounce output is 0 and no bounce rays "        \
      "are cast",                                                                          \
      .def = 1, .host_only = 1)                                                            \
    P(FLOAT, offset,                                                                       \
      "ray origins move this far along the normal and this far back along the "            \
      "arriving ray, against self-intersection (at least 1024 float ulps of the "          \
      "point's coordinates)",                                                              \
      .def = 1e-3, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 0.01,                  \
      .unit = "scene units", .host_only = 1)                                               \
    P(BOOL, environment,                                                                   \
      "include the scene's environment light (directly and at the bounce's end)",          \
      .def = 1, .host_only = 1)
SSG_PARAMS_STRUCT(ssg_reference_gi_params, SSG_REFERENCE_GI_PARAMS);

/* The 4D Hammersley set (i / n, phi2(i), phi3(i), phi5(i)), i < n = samples, in the forms
   the kernel reads (README.md, sampling): the first two coordinates serve the environment
   samples of the direct term and, mapped to the disk (Malley), the bounce directions; the
   last two the one environment sample at each bounce path's end. */
struct ssg_reference_gi_table {
    float u[SSG_REFERENCE_GI_MAX_SAMPLES];  /* i / n */
    float v[SSG_REFERENCE_GI_MAX_SAMPLES];  /* phi2(i), radical inverse base 2 */
    float c[SSG_REFERENCE_GI_MAX_SAMPLES];  /* cos(2 pi phi2(i)) */
    float s[SSG_REFERENCE_GI_MAX_SAMPLES];  /* sin(2 pi phi2(i)) */
    float e1[SSG_REFERENCE_GI_MAX_SAMPLES]; /* phi3(i), radical inverse base 3 */
    float e2[SSG_REFERENCE_GI_MAX_SAMPLES]; /* phi5(i), radical inverse base 5 */
};

struct ssg_reference_gi_consts {
    struct ssg_reference_gi_params p; /* the parameters as given */
    float rot[9];  /* world -> view rotation, row-major: view = rot * (world - eye) */
    float eye[3];  /* camera position, world */
    uint64_t seed; /* the frame's seed: decides every pixel's rotations */
    int use_env;   /* environment on and the scene's environment emits light */
    struct ssg_reference_gi_table t;
};

enum ssg_err ssg_reference_gi_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io);

#endif
