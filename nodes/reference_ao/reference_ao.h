/* reference_ao.h - parameters and prepared constants of the `reference_ao` node, shared by
 * reference_ao.c (descriptor, check, prepare) and reference_ao_cpu.c (the CPU kernel).
 * Method, conventions and the sampling are described in reference_ao.c. */
#ifndef SSG_REFERENCE_AO_H
#define SSG_REFERENCE_AO_H

#include <stdint.h>

#include "graph/node.h"

/* Input ports, in order. */
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_reference_ao_input {
    SSG_REFERENCE_AO_IN_POSITION,
    SSG_REFERENCE_AO_IN_NORMAL,
    SSG_REFERENCE_AO_INPUTS
};
enum ssg_reference_ao_output {
    SSG_REFERENCE_AO_OUT_OUT,
    SSG_REFERENCE_AO_OUTPUTS
};

/* Largest `rays`: the sample table of the constants holds this many directions. */
#define SSG_REFERENCE_AO_MAX_RAYS 65536

struct ssg_reference_ao_params {
    int rays;           /* rays per pixel, 1..65536; default 256 */
    float max_distance; /* occluders farther along the ray do not count, scene units, > 0;
                           default 0.5 (the meaning of ssao's radius) */
    float offset;       /* ray origins move this far along the normal and this far
                           towards the camera, against self-intersection, scene units,
                           >= 0; default 1e-3 (raised to 1024 float ulps of the point's
                           magnitude, see reference_ao.c) */
};

struct ssg_reference_ao_consts {
    struct ssg_reference_ao_params p; /* the parameters as given */
    float rot[9];    /* world -> view rotation, row-major: view = rot * (world - eye) */
    float eye[3];    /* camera position, world */
    uint64_t seed;   /* the frame's seed: decides every pixel's rotation */
    /* The 2D Hammersley point set of `rays` points, mapped to the unit disk (Malley), in
       sample order: u = r^2 (so cos^2 theta = 1 - u) and the unit vector (c, s) at the
       point's angle. Pixels shift u and turn the angle (reference_ao.c). */
    float u[SSG_REFERENCE_AO_MAX_RAYS];
    float c[SSG_REFERENCE_AO_MAX_RAYS];
    float s[SSG_REFERENCE_AO_MAX_RAYS];
};

enum ssg_err ssg_reference_ao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io);

#endif
