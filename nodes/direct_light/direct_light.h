/* direct_light.h - the `direct_light` node (README.md): a G-buffer lit by the scene's
 * own point and directional lights through their maps (lightmaps), with filtered shadows.
 * Shared by both backends: the constants prepare() makes. */
#ifndef SSG_DIRECT_LIGHT_H
#define SSG_DIRECT_LIGHT_H

#include "graph/node.h"
#include "common/lightmap.h"

enum { SSG_DIRECT_LIGHT_MAX_SAMPLES = 64, SSG_DIRECT_LIGHT_MAX_LIGHTS = SSG_LIGHTMAP_FACES_MAX };
/* Steps of the contact march (`contact`), and the cosine between a G-buffer pixel's
   surface and the view ray below which the march takes no plane from it. */
enum { SSG_DIRECT_LIGHT_CONTACT_STEPS = 8 };
#define SSG_DIRECT_LIGHT_CONTACT_GRAZING 0.2f
/* The widest PCF disc a pixel may get (soft shadows), texels. */
#define SSG_DIRECT_LIGHT_MAX_RADIUS 24.0f
/* The steepest receiver plane a tap follows, depth texels per texel (84 degrees). */
#define SSG_DIRECT_LIGHT_MAX_SLOPE 10.0f

/* Ports, one row each (graph/node.h): enumerator, name, types, doc, further fields. */
#define SSG_DIRECT_LIGHT_IN(X)                                                             \
    X(SSG_DIRECT_LIGHT_IN_POSITION, "position", SSG_T_VECTOR,                              \
      "view-space position (gbuffer)")                                                     \
    X(SSG_DIRECT_LIGHT_IN_NORMAL, "normal", SSG_T_VECTOR,                                  \
      "unit view-space normal, 0 = background (gbuffer)")                                  \
    X(SSG_DIRECT_LIGHT_IN_ALBEDO, "albedo", SSG_T_COLOR,                                   \
      "diffuse albedo, linear RGB (gbuffer)")                                              \
    X(SSG_DIRECT_LIGHT_IN_MAPS, "maps", SSG_T_LIGHTMAPS,                                   \
      "the depth of the scene's lights' maps (lightmaps)")
#define SSG_DIRECT_LIGHT_OUT(X)                                                            \
    X(SSG_DIRECT_LIGHT_OUT_OUT, "out", SSG_T_COLOR,                                        \
      "albedo / pi x the shadowed irradiance of the scene's lights (gbuffer.direct with "  \
      "shadows, diffuse part)",                                                            \
      .lit = 1)                                                                            \
    X(SSG_DIRECT_LIGHT_OUT_VISIBILITY, "visibility", SSG_T_SCALAR,                         \
      "the luminance-weighted share of the unshadowed direct light that arrives, 1 where " \
      "none would", .on_demand = 1)
SSG_PORT_ENUM(ssg_direct_light_input, SSG_DIRECT_LIGHT_IN, SSG_DIRECT_LIGHT_INPUTS);
SSG_PORT_ENUM(ssg_direct_light_output, SSG_DIRECT_LIGHT_OUT, SSG_DIRECT_LIGHT_OUTPUTS);

/* The parameters, one row each (lang/params.h). The struct below and the table in
   direct_light.c are made from these rows; the shader reads those not host_only as
   p_<field> (#pragma ssg_params). */
#define SSG_DIRECT_LIGHT_PARAMS(P)                                                         \
    P(INT, samples,                                                                        \
      "percentage-closer taps a light (a Vogel disc turned per pixel), each a bilinear "   \
      "blend of four tests",                                                               \
      .def = 12, .min = 1, .max = SSG_DIRECT_LIGHT_MAX_SAMPLES, .soft_min = 1,             \
      .soft_max = SSG_DIRECT_LIGHT_MAX_SAMPLES, .unit = "taps")                            \
    P(FLOAT, filter,                                                                       \
      "radius of the PCF disc: wider softens the map's stair steps; 0 = one bilinear test", \
      .def = 1.5, .min = 0, .max = SSG_DIRECT_LIGHT_MAX_RADIUS, .soft_min = 0,             \
      .soft_max = 8, .unit = "texels")                                                     \
    P(FLOAT, offset,                                                                       \
      "constant depth offset of the test (map rounding); larger leaks light under thin "   \
      "occluders",                                                                         \
      .def = 0.5, .min = 0, .max = 1000, .soft_min = 0, .soft_max = 8, .unit = "texels")   \
    P(FLOAT, tap_slope,                                                                    \
      "more depth offset for a PCF tap, per texel of its distance from the disc's centre: " \
      "no false shadow in concave corners (a stair's step); larger leaks at a wall's foot " \
      "(0.5: none; 1: 1.7 texels)",                                                        \
      .def = 0.5, .min = 0, .max = 100, .soft_min = 0, .soft_max = 2,                      \
      .unit = "texels per texel")                                                          \
    P(FLOAT, normal_offset,                                                                \
      "the lookup point moves along the normal by normal_offset x sin(N, L) texels: no "   \
      "self-shadowing where the light grazes, no leak at a wall's foot",                   \
      .def = 2, .min = 0, .max = 1000, .soft_min = 0, .soft_max = 8, .unit = "texels")     \
    P(FLOAT, light_size,                                                                   \
      "point lights' diameter: > 0 gives contact-hardening soft shadows (PCSS); 0 = hard", \
      .def = 0, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 1, .unit = "scene units", \
      .host_only = 1) /* prepare(): the lights' spread */                                  \
    P(FLOAT, sun_angle,                                                                    \
      "directional lights' angular diameter (the sun: 0.53): > 0 gives PCSS soft "         \
      "shadows; 0 = hard",                                                                 \
      .def = 0, .min = 0, .max = 45, .soft_min = 0, .soft_max = 5, .unit = "degrees",      \
      .host_only = 1) /* prepare(): the lights' spread */                                  \
    P(FLOAT, contact,                                                                      \
      "screen-space contact shadows: each pixel also marches this many of its map's "      \
      "texels towards the light over the G-buffer, and a visible surface whose plane the " \
      "march passes behind shadows it (the occluders nearer than the map test's offsets: " \
      "a wall just under a ceiling, a box's foot); 0 = off",                               \
      .def = 0, .min = 0, .max = 64, .soft_min = 0, .soft_max = 32, .unit = "texels")      \
    P(ENUM, fit,                                                                           \
      "where the maps' directional lights lie: the fit of the lightmaps node that made "  \
      "them (scene or view; the two must agree)",                                          \
      .def = SSG_LIGHTMAP_FIT_SCENE, .choices = ssg_lightmap_fit_choices, .host_only = 1) \
    P(INT, tiles,                                                                          \
      "the tiles of the lightmaps node that made the maps (a directional light's map as " \
      "tiles x tiles faces; the two must agree)",                                          \
      .def = 1, .min = 1, .max = SSG_LIGHTMAP_TILES_MAX, .soft_min = 1,                    \
      .soft_max = SSG_LIGHTMAP_TILES_MAX, .unit = "tiles a side",                          \
      .host_only = 1)
SSG_PARAMS_STRUCT(ssg_direct_light_params, SSG_DIRECT_LIGHT_PARAMS);

/* One light as both backends read it. */
struct ssg_direct_light_light {
    float pos[3];   /* point and spot: position; directional: unused */
    float dir[3];   /* directional: direction the light travels; spot: its axis */
    float color[3]; /* linear RGB */
    float intensity; /* point and spot: radiant intensity; directional: irradiance */
    int point;      /* 1 = point or spot light (perspective faces), 0 = directional (one
                       orthographic face) */
    int face;       /* its first face in the maps */
    float texel;    /* directional: the map's texel, scene units; point: 2 half / R (a
                       texel at distance d is d x this) */
    float spread;   /* soft shadows: point light_size; directional tan(sun_angle) */
    int cube;       /* 1 = six cube faces (a point light, a wide spot), 0 = one face */
    int tiles;      /* directional: its map's tiles a side (ssg_lightmap_tile_texel); 1
                       otherwise */
    float cone_scale, cone_offset; /* the spot's cone (ssg_cone_falloff; point: 0, 1) */
};

/* What the shader reads by name (#pragma ssg_consts). */
#define SSG_DIRECT_LIGHT_UNIFORMS(U)                                                       \
    U(MAT3, rot, "view -> world: world = eye + rot^T view")                               \
    U(VEC3, eye, "the camera's position, world")                                          \
    U(INT, res, "the maps' side R")                                                        \
    U(INT, lights, "point, spot and directional lights of the scene")                           \
    U(PROJECTION, proj, "the frame's camera as seen by the G-buffer's resolution")
SSG_UNIFORMS_STRUCT(ssg_direct_light_uniforms, SSG_DIRECT_LIGHT_UNIFORMS);

struct ssg_direct_light_consts {
    struct ssg_direct_light_params p;
    struct ssg_direct_light_uniforms u; /* camera, maps' side and light count */
    int face_count;        /* faces of the maps (the scene's; 1, empty, without lights) */
    float taps[2 * SSG_DIRECT_LIGHT_MAX_SAMPLES]; /* Vogel disc in the unit disc, x y x y */
    struct ssg_direct_light_light light[SSG_DIRECT_LIGHT_MAX_LIGHTS];
    struct ssg_lightmap_face faces[SSG_LIGHTMAP_FACES_MAX];
};

/* The per-pixel rotation of the tap disc, in turns [0, 1): interleaved gradient noise
   (Jimenez, "Next Generation Post Processing in Call of Duty: Advanced Warfare", SIGGRAPH
   2014 course), which has no structure a filter or the eye picks up at any scale. */
static inline float ssg_direct_light_turn(int x, int y)
{
    float f = 0.06711056f * (float)x + 0.00583715f * (float)y;
    f = 52.9829189f * (f - floorf(f));
    return f - floorf(f);
}

enum ssg_err ssg_direct_light_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io);
enum ssg_err ssg_direct_light_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                     const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_direct_light;

#endif
