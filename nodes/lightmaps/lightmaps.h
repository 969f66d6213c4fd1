/* lightmaps.h - the `lightmaps` node (README.md): depth, normal and reflected flux of the
 * nearest surface on every face of the scene's own lights' maps (nodes/common/lightmap.h),
 * shared by both backends. */
#ifndef SSG_LIGHTMAPS_H
#define SSG_LIGHTMAPS_H

#include "graph/node.h"
#include "common/lightmap.h"

/* Ports, one row each (graph/node.h): enumerator, name, types, doc. */
#define SSG_LIGHTMAPS_OUT(X)                                                               \
    X(SSG_LIGHTMAPS_OUT_DEPTH, "depth", SSG_T_LIGHTMAPS,                                   \
      "R x R, channel f the depth of the nearest surface on face f (lightmap.h), "         \
      "SSG_SHADOW_EMPTY where none")                                                       \
    X(SSG_LIGHTMAPS_OUT_NORMAL, "normal", SSG_T_LIGHTMAPS,                                 \
      "R x R, channels 3f..3f+2 that surface's unit world normal, facing the light",      \
      .on_demand = 1)                                                                      \
    X(SSG_LIGHTMAPS_OUT_FLUX, "flux", SSG_T_LIGHTMAPS,                                     \
      "R x R, channels 3f..3f+2 the RGB flux that surface reflects (albedo x flux "        \
      "through the texel, W)",                                                             \
      .on_demand = 1)
SSG_PORT_ENUM(ssg_lightmaps_output, SSG_LIGHTMAPS_OUT, SSG_LIGHTMAPS_OUTPUTS);

/* Bounds of the resolution parameter (texels a side). */
enum { SSG_LIGHTMAPS_RES_MIN = 16, SSG_LIGHTMAPS_RES_MAX = 8192 };

/* The parameters, one row each (lang/params.h). The struct below and the table in
   lightmaps.c are made from these rows; the shader reads them as p_<field> (#pragma
   ssg_params). */
#define SSG_LIGHTMAPS_PARAMS(P)                                                            \
    P(INT, resolution,                                                                     \
      "side of every face (a point light has six, a directional light one); memory 7 x "   \
      "faces x resolution^2 floats",                                                       \
      .def = 512, .min = SSG_LIGHTMAPS_RES_MIN, .max = SSG_LIGHTMAPS_RES_MAX,              \
      .soft_min = 16, .soft_max = 2048,                                                    \
      .unit = "texels")                                                                    \
    P(BOOL, own, "the scene's own point, spot and directional lights (their faces first)",        \
      .def = 1, .host_only = 1)                                                            \
    P(INT, environment,                                                                    \
      "the scene's environment as this many directional lights too (a probe's drawn "     \
      "through its brightness, a quarter uniform, as lightprobe sampling=importance "      \
      "uniform_share=0.25; a constant sky's uniform; each its share of the probe; 0 = "    \
      "none), so that rsm bounces the sky or probe; an rsm reading these maps needs the "  \
      "same own and environment",                                                          \
      .def = 0, .min = 0, .max = SSG_LIGHTMAP_ENV_MAX, .soft_min = 0, .soft_max = 128,     \
      .unit = "lights", .host_only = 1)                                                    \
    P(ENUM, fit,                                                                           \
      "a directional light's map over the scene's bounding sphere, or over what the "     \
      "camera sees (view: finer shadows, made again when the camera moves; a "            \
      "direct_light reading it needs the same fit; an rsm needs scene, its senders off "  \
      "screen)",                                                                           \
      .def = SSG_LIGHTMAP_FIT_SCENE, .choices = ssg_lightmap_fit_choices, .host_only = 1) \
    P(INT, tiles,                                                                          \
      "a directional light's map as tiles x tiles faces of resolution each, one map of "  \
      "side tiles x resolution (finer sun shadows without finer point-light cubes; a "    \
      "direct_light reading it needs the same tiles, an rsm 1)",                          \
      .def = 1, .min = 1, .max = SSG_LIGHTMAP_TILES_MAX, .soft_min = 1,                    \
      .soft_max = SSG_LIGHTMAP_TILES_MAX, .unit = "tiles a side",                          \
      .host_only = 1)                                                                      \
    P(BOOL, proxy,                                                                         \
      "draw each dense mesh (4096 triangles or more, not alpha-masked) as its simplified "  \
      "proxy, within about a sixteenth of the finest texel that meets it (core/scene/"     \
      "proxy.h): the maps then cost what a texel can show, not the triangle count; false " \
      "draws every triangle",                                                              \
      .def = 1, .host_only = 1)
SSG_PARAMS_STRUCT(ssg_lightmaps_params, SSG_LIGHTMAPS_PARAMS);

/* Floats a face takes in the GL shader's storage buffer (lightmaps.glsl's FACE). */
enum { SSG_LIGHTMAPS_FACE_FLOATS = 24 };

/* A cube face's near plane, as a fraction of the scene's bounding radius: nearer surfaces
   are cut (GL's clip and the CPU's polygon clip at the same plane). */
#define SSG_LIGHTMAPS_NEAR 1.0e-3f

/* The depth range the shader reads by name (#pragma ssg_consts). */
#define SSG_LIGHTMAPS_UNIFORMS(U)                                                          \
    U(FLOAT, near_z, "cube faces' near plane, scene units")                               \
    U(FLOAT, far_z, "cube faces' far plane (GL depth range)")
SSG_UNIFORMS_STRUCT(ssg_lightmaps_uniforms, SSG_LIGHTMAPS_UNIFORMS);

/* The constants both backends read: the faces of the scene's lights. */
struct ssg_lightmaps_consts {
    int res, count;                    /* R and the face count F */
    struct ssg_lightmaps_uniforms u;   /* the depth range */
    float flux[SSG_LIGHTMAP_FACES_MAX][3]; /* per face: E x texel area (orthographic) or I
                                              (perspective, times the texel's solid angle
                                              and the spot's falloff) */
    struct ssg_lightmap_face faces[SSG_LIGHTMAP_FACES_MAX];
    float texel; /* a quarter of the finest texel of a drawn face at the scene's dense
                    meshes: both backends draw ssg_raster_scene's view for it
                    (common/raster.h); INFINITY with proxy=false */
    /* the same faces as lightmaps.glsl reads them, SSG_LIGHTMAPS_FACE_FLOATS each: origin,
       u, v, axis, half, ortho, flux rgb, has a light (1 or 0), the depth range's half
       (the scene's radius: an orthographic face spans depths 0 .. 2 radius, also when
       fitted to the view, whose plane is the scene fit's), the light's cone scale and
       offset (ssg_cone_falloff; 0 and 1 but for a spot light) and its axis */
    float face_floats[SSG_LIGHTMAPS_FACE_FLOATS * SSG_LIGHTMAP_FACES_MAX];
};

enum ssg_err ssg_lightmaps_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io);
enum ssg_err ssg_lightmaps_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_lightmaps;

#endif
