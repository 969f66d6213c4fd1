/* ssdo.h - parameters and prepared constants of the `ssdo` node, shared by ssdo.c
 * (descriptor, check, prepare), ssdo_cpu.c (the CPU kernel) and ssdo_gl.c (the GL side).
 * Method and conventions are described in ssdo.c; the per-sample maths it shares with
 * `bounce` in ssdo_sampling.h (on GL, ssdo.glsl serves both nodes).
 * Read-only after prepare(); the kernel is thread-safe. */
#ifndef SSG_SSDO_H
#define SSG_SSDO_H

#include "scene/env.h"
#include "graph/image.h"
#include "graph/node.h"
#include "ssdo_sampling.h"

#define SSG_SSDO_MAX_LIGHTS 8

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_ssdo_output {
    SSG_SSDO_OUT_OUT,
    SSG_SSDO_OUT_BOUNCE,
    SSG_SSDO_OUTPUTS
};

enum ssg_ssdo_mode {
    SSG_SSDO_MODE_MODULATION, /* one-step method (Szentandrasi sec. 4.1): lit / unoccluded */
    SSG_SSDO_MODE_RADIANCE,   /* two-step first pass: albedo / pi * directional light (eq. 2) */
};

struct ssg_ssdo_params {
    struct ssg_ssdo_geom g; /* radius, bias, max_screen_radius, strength, min_distance */
    int mode;               /* enum ssg_ssdo_mode; default modulation */
    int channels;           /* modulation output channels, 1 or 3; default 1 */
    int bounce;             /* 1 = compute the indirect bounce output; default 0 */
    int lobe;               /* cosine power spreading a delta light over a cone, 1..64;
                               default 4 */
    float power;            /* modulation mode: out = M^power (per channel), 0..8;
                               default 1 */
};

/* A scene light in view space. */
struct ssg_ssdo_light {
    int directional;  /* 0 = point light at `v`, 1 = directional light from unit `v` */
    float v[3];       /* point: view-space position; directional: unit direction to it */
    float rgb[3];     /* colour * intensity */
};

enum ssg_ssdo_env { SSG_SSDO_ENV_CONSTANT, SSG_SSDO_ENV_CUBE };

struct ssg_ssdo_consts {
    struct ssg_ssdo_params p;   /* the parameters as given */
    struct ssg_projection proj; /* the frame's camera as the G-buffer's resolution sees
                                   it (ssg_sampling_projection) */
    int out_channels;           /* of output `out`: 1, or 3 (radiance, channels=3) */
    int light_count;            /* 0..SSG_SSDO_MAX_LIGHTS */
    struct ssg_ssdo_light lights[SSG_SSDO_MAX_LIGHTS];
    int env;                    /* enum ssg_ssdo_env */
    float env_rgb[3];           /* constant environment radiance (1 without a scene) */
    struct ssg_env_cube cube;   /* the probe in view space (env = cube) */
};

enum ssg_err ssg_ssdo_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io);
/* The GL side (ssdo_gl.c, shader ssdo.glsl). */
enum ssg_err ssg_ssdo_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);
/* Binds what ssdo.glsl's sampling reads (the inputs of ssdo_sampling.h's ports, the
   geometry and the projection of position's size), for ssdo and bounce on GL. */
struct ssg_gl_pass;
void ssg_ssdo_gl_bind_geometry(struct ssg_gl_pass *p, const struct ssg_io *io,
                               const struct ssg_ssdo_geom *g,
                               const struct ssg_projection *proj);

#endif
