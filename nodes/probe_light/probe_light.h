/* probe_light.h - the `probe_light` node (probe_light.c): the hybrid AO's global pass, a
 * G-buffer lit by a light list through its shadow maps. Shared by both backends: the
 * constants prepare() makes, and the per-light maps both compute the same way. */
#ifndef SSG_PROBE_LIGHT_H
#define SSG_PROBE_LIGHT_H

#include "graph/node.h"
#include "common/shadowmap.h"

enum { SSG_PROBE_LIGHT_MAX_TILE = 16 };
/* The largest tan(angle of N to l) the slope offset grows to (84 degrees). */
#define SSG_PROBE_LIGHT_MAX_SLOPE 10.0f

/* Ports: the descriptor's arrays are indexed by these (one naming rule:
   SSG_<NODE>_IN_<PORT>, SSG_<NODE>_OUT_<PORT>; _INPUTS and _OUTPUTS count them). */
enum ssg_probe_light_input {
    SSG_PROBE_LIGHT_IN_POSITION,
    SSG_PROBE_LIGHT_IN_NORMAL,
    SSG_PROBE_LIGHT_IN_ALBEDO,
    SSG_PROBE_LIGHT_IN_LIGHTS,
    SSG_PROBE_LIGHT_IN_SHADOWMAPS,
    SSG_PROBE_LIGHT_INPUTS
};
enum ssg_probe_light_output {
    SSG_PROBE_LIGHT_OUT_OUT,
    SSG_PROBE_LIGHT_OUT_VISIBILITY,
    SSG_PROBE_LIGHT_OUTPUTS
};

struct ssg_probe_light_params {
    float offset;       /* depth offset in map texels; default 0.5 */
    float slope_offset; /* further offset in texels per unit tan(angle of N to l); default 0 */
    float normal_offset; /* lookup moved along N by normal_offset x sin(N, l) texels;
                            default 2 */
    float noise_radius; /* lookup jitter radius in map texels; default 1 */
    int noise_tile;     /* side of the tiled jitter pattern, px; default 4 */
};

struct ssg_probe_light_consts {
    struct ssg_probe_light_params p;
    float rot[9], eye[3];               /* view -> world: world = eye + rot^T view */
    struct ssg_bounding_sphere sphere;  /* the maps' fit (nodes/common/shadowmap.h) */
    /* the jitter tile: offsets in the unit disc, x plane then y plane, tile^2 each */
    float noise[2 * SSG_PROBE_LIGHT_MAX_TILE * SSG_PROBE_LIGHT_MAX_TILE];
    /* Of the inputs' shapes, for both backends: */
    int count;                          /* lights N (the light list's width) */
    int res;                            /* the maps' side R; 0 = no shadow maps */
    float offset_world, slope_world;    /* offset and slope_offset in scene units (texels
                                           of 2 radius / R) */
    float normal_world;                 /* normal_offset in scene units */
    float cos_sin[2 * SSG_LIGHTS_MAX];  /* ssg_probe_light_rotations of the N lights */
};

/* What one light is to a view-space point p (floats, in this order):
 *   [0..3]  texel x = dot(p, a) + a0      [4..7]  texel y = dot(p, b) + b0
 *   [8..11] depth below the map plane = dot(p, c) + c0
 *   [12..14] the direction towards the light in view space (N.l), [15] unused.
 * The GL side computes the same floats the same way (probe_light_frames.glsl). */
enum { SSG_PROBE_LIGHT_FRAME = 16 };
void ssg_probe_light_frame(const struct ssg_probe_light_consts *c, const float l[3], int res,
                           float frame[SSG_PROBE_LIGHT_FRAME]);

/* cos and sin of light i's jitter rotation (i times the golden angle), 2 N floats. */
void ssg_probe_light_rotations(int count, float *cos_sin);

enum ssg_err ssg_probe_light_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                     const struct ssg_io *io);
enum ssg_err ssg_probe_light_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_probe_light;

#endif
