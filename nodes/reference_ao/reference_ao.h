/* reference_ao.h - ports, parameters and prepared constants of the `reference_ao` node,
 * shared by reference_ao.c (descriptor, check, prepare) and reference_ao_cpu.c (the CPU
 * kernel). Method, conventions and the sampling: README.md. */
#ifndef SSG_REFERENCE_AO_H
#define SSG_REFERENCE_AO_H

#include <stdint.h>

#include "graph/node.h"

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_REFERENCE_AO_IN(X)                                                             \
    X(SSG_REFERENCE_AO_IN_POSITION, "position", SSG_T_VECTOR,                              \
      "view-space position (gbuffer)")                                                     \
    X(SSG_REFERENCE_AO_IN_NORMAL, "normal", SSG_T_VECTOR,                                  \
      "unit view-space normal facing the camera, 0 = background (gbuffer)")
#define SSG_REFERENCE_AO_OUT(X)                                                            \
    X(SSG_REFERENCE_AO_OUT_OUT, "out", SSG_T_SCALAR,                                       \
      "visibility, 1 = unoccluded (cosine-weighted, distance-limited)")
SSG_PORT_ENUM(ssg_reference_ao_input, SSG_REFERENCE_AO_IN, SSG_REFERENCE_AO_INPUTS);
SSG_PORT_ENUM(ssg_reference_ao_output, SSG_REFERENCE_AO_OUT, SSG_REFERENCE_AO_OUTPUTS);

/* Largest `rays`: the sample table of the constants holds this many directions. */
#define SSG_REFERENCE_AO_MAX_RAYS 65536

/* The parameters, one row each (lang/params.h); the struct below and the table in
   reference_ao.c are made from these rows. offset is raised to 1024 float ulps of the
   point's magnitude (README.md, Geometry). */
#define SSG_REFERENCE_AO_PARAMS(P)                                                         \
    P(INT, rays,                                                                           \
      "cosine-weighted rays per pixel; the standard error is sqrt(V (1 - V) / rays) or "   \
      "less (stratified)",                                                                 \
      .def = 256, .min = 1, .max = SSG_REFERENCE_AO_MAX_RAYS, .soft_min = 1,               \
      .soft_max = 4096)                                                                    \
    P(FLOAT, max_distance,                                                                 \
      "occluders farther along a ray do not count (the meaning of ssao's radius)",         \
      .def = 0.5, .min = 1e-6, .max = 1e30, .soft_min = 0.05, .soft_max = 10,              \
      .unit = "scene units")                                                               \
    P(FLOAT, offset,                                                                       \
      "ray origins move this far along the normal and this far towards the camera, "       \
      "against self-intersection (at least 1024 float ulps of the point's coordinates)",   \
      .def = 1e-3, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 0.01,                  \
      .unit = "scene units")
SSG_PARAMS_STRUCT(ssg_reference_ao_params, SSG_REFERENCE_AO_PARAMS);

struct ssg_reference_ao_consts {
    struct ssg_reference_ao_params p; /* the parameters as given */
    float rot[9];    /* world -> view rotation, row-major: view = rot * (world - eye) */
    float eye[3];    /* camera position, world */
    uint64_t seed;   /* the frame's seed: decides every pixel's rotation */
    /* The 2D Hammersley point set of `rays` points, mapped to the unit disk (Malley), in
       sample order: u = r^2 (so cos^2 theta = 1 - u) and the unit vector (c, s) at the
       point's angle. Pixels shift u and turn the angle (README.md). */
    float u[SSG_REFERENCE_AO_MAX_RAYS];
    float c[SSG_REFERENCE_AO_MAX_RAYS];
    float s[SSG_REFERENCE_AO_MAX_RAYS];
};

enum ssg_err ssg_reference_ao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io);

#endif
