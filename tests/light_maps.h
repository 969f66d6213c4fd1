/* light_maps.h - for the tests of `lightmaps` and `direct_light`: a G-buffer of a scene, the
 * maps of its own lights and the shadowed direct light, each on either backend through
 * scene_node.h's node_run_scene. Images are the caller's (ssg_image_destroy). */
#ifndef SSG_TEST_LIGHT_MAPS_H
#define SSG_TEST_LIGHT_MAPS_H

#include "scene_node.h"
#include "common/lightmap.h"
#include "direct_light/direct_light.h"
#include "gbuffer/gbuffer.h"
#include "lightmaps/lightmaps.h"

extern const struct ssg_node_desc ssg_node_gbuffer;

/* The pixel (x, y) of channel c. */
static inline float px_at(const struct ssg_image *im, int c, int x, int y)
{
    return ssg_image_plane(im, c)[(size_t)y * im->width + x];
}

/* gbuffer's six outputs of scene s at the frame's size, on the CPU. */
static inline void gbuffer_of(const struct ssg_scene *s, const struct ssg_frame *frame,
                              struct ssg_image *out[SSG_GBUFFER_OUTPUTS])
{
    for (int i = 0; i < SSG_GBUFFER_OUTPUTS; i++) /* back, motion: on demand, not read */
        out[i] = i == SSG_GBUFFER_OUT_BACK || i == SSG_GBUFFER_OUT_MOTION
                     ? NULL
                     : ssg_image_create(frame->width, frame->height,
                                        i == SSG_GBUFFER_OUT_DEPTH ? 1 : 3);
    void *params = node_params(&ssg_node_gbuffer, NULL, 0);
    CHECK_EQ(node_run_scene(&ssg_node_gbuffer, s, frame, params, NULL, out, SSG_BACKEND_CPU),
             SSG_OK);
    free(params);
}

/* The lightmaps node's depth, normal and flux of scene s at resolution res, for the lights
   src names (a directional light's map in src.tiles tiles a side), a directional light's
   map fitted by `fit` ("scene" or "view"). */
static inline enum ssg_err maps_fit(const struct ssg_scene *s, const struct ssg_frame *frame,
                                    int res, struct ssg_lightmap_sources src, const char *fit,
                                    enum ssg_backend backend, struct ssg_image *out[3])
{
    char set[5][40];
    snprintf(set[0], sizeof set[0], "resolution=%d", res);
    snprintf(set[1], sizeof set[1], "own=%s", src.own ? "true" : "false");
    snprintf(set[2], sizeof set[2], "environment=%d", src.environment);
    snprintf(set[3], sizeof set[3], "fit=%s", fit);
    snprintf(set[4], sizeof set[4], "tiles=%d", src.tiles > 1 ? src.tiles : 1);
    const char *sets[] = {set[0], set[1], set[2], set[3], set[4]};
    void *params = node_params(&ssg_node_lightmaps, sets, 5);
    int f = ssg_lightmap_face_count(s, src);
    out[0] = ssg_image_create(res, res, f);
    out[1] = ssg_image_create(res, res, 3 * f);
    out[2] = ssg_image_create(res, res, 3 * f);
    enum ssg_err e = node_run_scene(&ssg_node_lightmaps, s, frame, params, NULL, out, backend);
    free(params);
    return e;
}

/* The maps of the lights src names over the scene's bounding sphere (fit=scene). */
static inline enum ssg_err maps_with(const struct ssg_scene *s, const struct ssg_frame *frame,
                                     int res, struct ssg_lightmap_sources src,
                                     enum ssg_backend backend, struct ssg_image *out[3])
{
    return maps_fit(s, frame, res, src, "scene", backend, out);
}

/* The maps of the scene's own lights alone. */
static inline enum ssg_err maps_of(const struct ssg_scene *s, const struct ssg_frame *frame,
                                   int res, enum ssg_backend backend, struct ssg_image *out[3])
{
    return maps_with(s, frame, res, SSG_LIGHTMAP_OWN_ONLY, backend, out);
}

static inline void images_free(struct ssg_image **im, int n)
{
    for (int i = 0; i < n; i++)
        ssg_image_destroy(&im[i]);
}

/* direct_light's out and visibility on G-buffer g and maps depth, with `sets`. */
static inline enum ssg_err direct_of(const struct ssg_scene *s, const struct ssg_frame *frame,
                                     struct ssg_image *const g[6],
                                     const struct ssg_image *depth, const char *const *sets,
                                     int set_count, enum ssg_backend backend,
                                     struct ssg_image *out[2])
{
    void *params = node_params(&ssg_node_direct_light, sets, set_count);
    out[0] = ssg_image_create(frame->width, frame->height, 3);
    out[1] = ssg_image_create(frame->width, frame->height, 1);
    const struct ssg_image *in[4] = {g[SSG_GBUFFER_OUT_POSITION], g[SSG_GBUFFER_OUT_NORMAL],
                                     g[SSG_GBUFFER_OUT_ALBEDO], depth};
    enum ssg_err e = node_run_scene(&ssg_node_direct_light, s, frame, params, in, out, backend);
    free(params);
    return e;
}

#endif
