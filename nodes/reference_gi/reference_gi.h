/* reference_gi.h - parameters and prepared constants of the `reference_gi` node, shared by
 * reference_gi.c (descriptor, check, prepare) and reference_gi_cpu.c (the CPU kernel).
 * Method, estimators and sampling are described in reference_gi.c. */
#ifndef SSG_REFERENCE_GI_H
#define SSG_REFERENCE_GI_H

#include <stdint.h>

#include "graph/node.h"

/* Ports, in order. */
/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_reference_gi_input {
    SSG_REFERENCE_GI_IN_POSITION,
    SSG_REFERENCE_GI_IN_NORMAL,
    SSG_REFERENCE_GI_IN_ALBEDO,
    SSG_REFERENCE_GI_INPUTS
};
enum ssg_reference_gi_output {
    SSG_REFERENCE_GI_OUT_DIRECT,
    SSG_REFERENCE_GI_OUT_BOUNCE,
    SSG_REFERENCE_GI_OUT_OUT,
    SSG_REFERENCE_GI_OUTPUTS
};

/* Largest `samples`: the sample tables of the constants hold this many points. */
#define SSG_REFERENCE_GI_MAX_SAMPLES 65536

struct ssg_reference_gi_params {
    int samples;     /* environment samples and bounce paths per pixel, 1..65536; default 64 */
    int bounce;      /* 1 = trace the one diffuse bounce; 0 = bounce output 0, no bounce
                        rays; default 1 */
    float offset;    /* ray origins move this far along the normal and this far back
                        along the arriving ray, against self-intersection, scene units,
                        >= 0; default 1e-3 (raised to 1024 float ulps of the point's
                        magnitude, as in reference_ao) */
    int environment; /* 1 = include the scene's environment light; default 1 */
};

/* The 4D Hammersley set (i / n, phi2(i), phi3(i), phi5(i)), i < n = samples, in the forms
   the kernel reads (reference_gi.c): the first two coordinates serve the environment
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
