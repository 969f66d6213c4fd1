/* rsm_maps.h - what the `rsm` tests (test_rsm.c, test_gl_rsm.c) share: light maps made by
 * hand in the format of nodes/common/lightmap.h (no lightmaps node needed), receivers
 * placed in world space and written into a small view-space G-buffer, and one run of the
 * node. Header-only, single-threaded. */
#ifndef SSG_TEST_RSM_MAPS_H
#define SSG_TEST_RSM_MAPS_H

#include "common/trace.h"
#include "rsm/rsm.h"
#include "scene_node.h"

struct maps {
    struct ssg_lightmap_face face[SSG_LIGHTMAP_FACES_MAX];
    int faces, res;
    struct ssg_image *depth, *normal, *flux; /* R x R, F / 3F / 3F channels, all empty */
};

static inline struct maps maps_make(const struct ssg_scene *s, int res)
{
    struct maps m = {.res = res};
    m.faces = ssg_lightmap_faces(s, SSG_LIGHTMAP_OWN_ONLY, m.face, SSG_LIGHTMAP_FACES_MAX);
    m.depth = ssg_image_create(res, res, m.faces);
    m.normal = ssg_image_create(res, res, 3 * m.faces);
    m.flux = ssg_image_create(res, res, 3 * m.faces);
    for (size_t i = 0; i < (size_t)res * res * m.faces; i++)
        m.depth->data[i] = SSG_SHADOW_EMPTY;
    return m;
}

static inline void maps_free(struct maps *m)
{
    ssg_image_destroy(&m->depth);
    ssg_image_destroy(&m->normal);
    ssg_image_destroy(&m->flux);
}

/* Texel (x, y) of face f: depth z, normal n, flux phi; its world point into p. */
static inline void maps_set(struct maps *m, int f, int x, int y, float z, const float n[3],
                            const float phi[3], float p[3])
{
    size_t plane = (size_t)m->res * m->res, at = (size_t)y * m->res + x;
    m->depth->data[f * plane + at] = z;
    for (int k = 0; k < 3; k++) {
        m->normal->data[(3 * f + k) * plane + at] = n[k];
        m->flux->data[(3 * f + k) * plane + at] = phi[k];
    }
    if (p)
        ssg_lightmap_texel_point(&m->face[f], m->res, x, y, z, p);
}

/* A view-space G-buffer of w x h receivers (world points and normals set by gbuf_set;
   background until then) and an albedo of (0.5, 0.25, 1). */
struct gbuf {
    int w, h;
    float rot[9], eye[3];
    struct ssg_image *position, *normal, *albedo;
};

static inline struct gbuf gbuf_make(const struct ssg_scene *s, int w, int h)
{
    struct gbuf g = {.w = w, .h = h};
    ssg_camera_frame(&s->camera, g.rot, g.eye);
    g.position = ssg_image_create(w, h, 3);
    g.normal = ssg_image_create(w, h, 3);
    g.albedo = ssg_image_create(w, h, 3);
    for (int i = 0; i < w * h; i++) {
        g.albedo->data[i] = 0.5f;
        g.albedo->data[w * h + i] = 0.25f;
        g.albedo->data[2 * w * h + i] = 1.0f;
    }
    return g;
}

static inline void gbuf_free(struct gbuf *g)
{
    ssg_image_destroy(&g->position);
    ssg_image_destroy(&g->normal);
    ssg_image_destroy(&g->albedo);
}

/* Pixel i receives at world point x with normal n (made unit): view = rot (world - eye). */
static inline void gbuf_set(struct gbuf *g, int i, const float x[3], const float n[3])
{
    size_t plane = (size_t)g->w * g->h;
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int r = 0; r < 3; r++) {
        float p = 0, q = 0;
        for (int k = 0; k < 3; k++) {
            p += g->rot[3 * r + k] * (x[k] - g->eye[k]);
            q += g->rot[3 * r + k] * n[k] / len;
        }
        g->position->data[r * plane + i] = p;
        g->normal->data[r * plane + i] = q;
    }
}

/* Runs rsm on the maps and receivers in frame `frame_index`; returns out (w x h x 3). */
static inline struct ssg_image *rsm_run_at(const struct ssg_scene *s, const struct maps *m,
                                           const struct gbuf *g, int albedo, uint64_t seed,
                                           int frame_index, const char *const *sets,
                                           int set_count, enum ssg_backend backend)
{
    struct ssg_frame frame = {g->w, g->h, 45, 0.05f, 100, seed, 0, 0, 0};
    struct ssg_image *out[1] = {ssg_image_create(g->w, g->h, 3)};
    const struct ssg_image *in[SSG_RSM_INPUTS] = {g->position, g->normal, m->depth, m->normal,
                                                  m->flux, albedo ? g->albedo : NULL};
    void *params = node_params(&ssg_node_rsm, sets, set_count);
    CHECK_EQ(node_run_scene_at(&ssg_node_rsm, s, NULL, &frame, frame_index, params, in, out,
                               backend),
             SSG_OK);
    free(params);
    return out[0];
}

/* rsm_run_at in frame 0. */
static inline struct ssg_image *rsm_run(const struct ssg_scene *s, const struct maps *m,
                                        const struct gbuf *g, int albedo, uint64_t seed,
                                        const char *const *sets, int set_count,
                                        enum ssg_backend backend)
{
    return rsm_run_at(s, m, g, albedo, seed, 0, sets, set_count, backend);
}

static inline float px(const struct ssg_image *im, int c, int i)
{
    return im->data[(size_t)c * im->width * im->height + i];
}

#endif
