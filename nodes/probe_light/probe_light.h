/* probe_light.h - the `probe_light` node (probe_light.c; method: README.md): the hybrid AO's
 * global pass, a G-buffer lit by a light list through its shadow maps. Shared by both
 * backends: the constants prepare() makes, and the per-light maps both compute the same
 * way. */
#ifndef SSG_PROBE_LIGHT_H
#define SSG_PROBE_LIGHT_H

#include "graph/node.h"
#include "common/shadowmap.h"

enum { SSG_PROBE_LIGHT_MAX_TILE = 16, SSG_PROBE_LIGHT_MAX_TAPS = 16 };
enum { SSG_PROBE_LIGHT_MAX_INTERLEAVE = 4 };
/* The largest tan(angle of N to l) the slope offset grows to (84 degrees). */
#define SSG_PROBE_LIGHT_MAX_SLOPE 10.0f

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_PROBE_LIGHT_IN(X)                                                              \
    X(SSG_PROBE_LIGHT_IN_POSITION, "position", SSG_T_VECTOR,                               \
      "view-space position (gbuffer)")                                                     \
    X(SSG_PROBE_LIGHT_IN_NORMAL, "normal", SSG_T_VECTOR,                                   \
      "unit view-space normal, 0 = background (gbuffer)")                                  \
    X(SSG_PROBE_LIGHT_IN_ALBEDO, "albedo", SSG_T_COLOR,                                    \
      "diffuse albedo, linear RGB (gbuffer); unconnected: out is the light a white "       \
      "receiver reflects, E / pi (for a low-resolution pass whose combine multiplies "     \
      "the full-resolution albedo, combine environment_albedo)", .optional = 1)            \
    X(SSG_PROBE_LIGHT_IN_LIGHTS, "lights", SSG_T_LIGHTS, "light list (lightprobe)")        \
    X(SSG_PROBE_LIGHT_IN_SHADOWMAPS, "shadowmaps", SSG_T_SHADOWMAPS,                       \
      "one map per light (shadowmaps); unconnected: no shadows", .optional = 1)
#define SSG_PROBE_LIGHT_OUT(X)                                                             \
    X(SSG_PROBE_LIGHT_OUT_OUT, "out", SSG_T_COLOR,                                         \
      "albedo / pi * sum of shadowed Lambert light (1 / pi without albedo), linear RGB "   \
      "(like "                                                                             \
      "gbuffer.environment, with self-shadowing)")                                         \
    X(SSG_PROBE_LIGHT_OUT_VISIBILITY, "visibility", SSG_T_SCALAR,                          \
      "the lit fraction of the pixel's light (luminance-weighted), comparable with AO")
SSG_PORT_ENUM(ssg_probe_light_input, SSG_PROBE_LIGHT_IN, SSG_PROBE_LIGHT_INPUTS);
SSG_PORT_ENUM(ssg_probe_light_output, SSG_PROBE_LIGHT_OUT, SSG_PROBE_LIGHT_OUTPUTS);

/* The parameters, one row each (lang/params.h); probe_light.glsl reads the jitter's and
   the soft lookups' taps and search radius as p_<field> (#pragma ssg_params). The
   offsets reach both backends in scene units, made in prepare() (offset_world, ...):
   their rows are host_only. */
#define SSG_PROBE_LIGHT_PARAMS(P)                                                          \
    P(FLOAT, offset,                                                                       \
      "a point is lit when its depth <= the map's + offset (fig. 1): larger hides "        \
      "self-shadowing, lets light through thin occluders",                                 \
      .def = 0.5, .min = 0, .max = 1000, .soft_min = 0, .soft_max = 8, .unit = "texels",   \
      .host_only = 1)                                                                      \
    P(FLOAT, slope_offset,                                                                 \
      "more depth offset where the light grazes the surface: + slope_offset x "            \
      "tan(N, l) texels (tan up to 10); leaks through thin walls, normal_offset is "       \
      "the default remedy",                                                                \
      .def = 0, .min = 0, .max = 1000, .soft_min = 0, .soft_max = 8, .unit = "texels",     \
      .host_only = 1)                                                                      \
    P(FLOAT, normal_offset,                                                                \
      "the lookup point moves along the normal by normal_offset x sin(N, l) texels: "      \
      "no self-shadowing where the light grazes, no leak at a wall's foot (>= 0.7 + "      \
      "noise_radius)",                                                                     \
      .def = 2, .min = 0, .max = 1000, .soft_min = 0, .soft_max = 8, .unit = "texels",     \
      .host_only = 1)                                                                      \
    P(FLOAT, noise_radius,                                                                 \
      "hard lookups (softness=0): jitter of the map lookup (fig. 8), needs a larger "      \
      "offset; 0 = none",                                                                  \
      .def = 1, .min = 0, .max = 64, .soft_min = 0, .soft_max = 8, .unit = "texels")       \
    P(INT, noise_tile, "side of the tiled jitter pattern", .def = 4, .min = 1,             \
      .max = SSG_PROBE_LIGHT_MAX_TILE, .soft_min = 1,                                      \
      .soft_max = SSG_PROBE_LIGHT_MAX_TILE, .unit = "px")                                  \
    P(FLOAT, softness,                                                                     \
      "soft lookups (README.md): each light a cone of softness x its share of the "        \
      "sphere's angular radius acos(1 - 2/N) (at most 45 degrees), its shadow a "          \
      "penumbra as wide as that cone from the blocker (PCSS); 0 = one hard lookup, "       \
      "jittered by noise_radius",                                                          \
      .def = 1, .min = 0, .max = 4, .soft_min = 0, .soft_max = 4, .unit = "x",             \
      .host_only = 1)                                                                      \
    P(INT, taps, "soft lookups: map reads of the filter over the penumbra, per light",    \
      .def = 4, .min = 1, .max = SSG_PROBE_LIGHT_MAX_TAPS, .soft_min = 1,                  \
      .soft_max = SSG_PROBE_LIGHT_MAX_TAPS, .unit = "taps")                                \
    P(INT, search_taps, "soft lookups: map reads of the blocker search, per light (the "   \
      "first at the pixel)", .def = 4, .min = 1, .max = SSG_PROBE_LIGHT_MAX_TAPS,          \
      .soft_min = 1, .soft_max = SSG_PROBE_LIGHT_MAX_TAPS,                                 \
      .unit = "taps")                                                                      \
    P(FLOAT, search_radius, "soft lookups: the blocker search's radius, the widest "       \
      "penumbra", .def = 8, .min = 1, .max = 256, .soft_min = 1, .soft_max = 64,           \
      .unit = "texels")                                                                    \
    P(INT, interleave,                                                                     \
      "n: each pixel of an n x n tile takes every n^2-th light (those i with i mod n^2 = "  \
      "its cell), weighted n^2: the lights of n^2 pixels for the lookups of one; a "       \
      "filter of the tile's period (bilateral window=tent size=2n-1) joins them",          \
      .def = 1, .min = 1, .max = SSG_PROBE_LIGHT_MAX_INTERLEAVE, .soft_min = 1,            \
      .soft_max = SSG_PROBE_LIGHT_MAX_INTERLEAVE, .unit = "px")
SSG_PARAMS_STRUCT(ssg_probe_light_params, SSG_PROBE_LIGHT_PARAMS);

/* What prepare() makes of the inputs' shapes that probe_light.glsl reads by name (#pragma
   ssg_consts). */
#define SSG_PROBE_LIGHT_UNIFORMS(U)                                                        \
    U(INT, count, "lights N (the light list's width)")                                    \
    U(INT, res, "the maps' side R; 0 = no shadow maps")                                   \
    U(FLOAT, offset_world, "offset in scene units (texels of 2 radius / R)")              \
    U(FLOAT, slope_world, "slope_offset in scene units")                                  \
    U(FLOAT, normal_world, "normal_offset in scene units")                                \
    U(FLOAT, texel, "the maps' texel 2 radius / R, scene units (0: no maps)")             \
    U(FLOAT, cone_tan, "soft lookups: tan of the light's cone half-angle over texel "     \
      "(penumbra texels per scene unit of blocker height); 0 = hard lookups")
SSG_UNIFORMS_STRUCT(ssg_probe_light_uniforms, SSG_PROBE_LIGHT_UNIFORMS);

struct ssg_probe_light_consts {
    struct ssg_probe_light_params p;
    float rot[9], eye[3];               /* view -> world: world = eye + rot^T view */
    struct ssg_bounding_sphere sphere;  /* the maps' fit (nodes/common/shadowmap.h) */
    /* the jitter tile: offsets in the unit disc, x plane then y plane, tile^2 each */
    float noise[2 * SSG_PROBE_LIGHT_MAX_TILE * SSG_PROBE_LIGHT_MAX_TILE];
    /* Of the inputs' shapes, for both backends: */
    struct ssg_probe_light_uniforms u;  /* what probe_light.glsl reads by name */
    int frame_res;                      /* R the light frames are made for: res, or 1
                                           without maps (then unused, but finite) */
    /* soft lookups: the filter's taps' offsets in the unit disc (Vogel's spiral), x then
       y, taps each; then the blocker search's, search_taps each */
    float tap[4 * SSG_PROBE_LIGHT_MAX_TAPS];
    float cos_sin[];                    /* ssg_probe_light_rotations of the N lights, 2 N
                                           floats (consts_size_of) */
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
