/* scene_node.h - running one node that reads the scene (ctx->scene), which ssg_node_run
 * (no scene) cannot: a scene from a few lines of text, a node's parameters from "name=value"
 * strings, a run on either backend with every output back on the CPU (through the
 * executor, exec.h, as a graph run does), light lists, and whole graphs read back from
 * their EXR layers. Scenes from text come from scenes.h. */
#ifndef SSG_TEST_SCENE_NODE_H
#define SSG_TEST_SCENE_NODE_H

#include <stdlib.h>
#include <sys/stat.h>

#include "check.h"
#include "graph/exec.h"
#include "graph/gl_backend.h"
#include "graph/node.h"
#include "scene/scene.h"
#include "scenes.h"

/* A path in the test's temporary folder (SSG_TMP, else /tmp, as scenes.h's). */
static inline const char *scene_node_path(const char *name)
{
    static char path[1024];
    const char *dir = getenv("SSG_TMP");
    dir = dir && dir[0] ? dir : "/tmp";
    mkdir(dir, 0755);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return path;
}

/* A light list of n directions (normalised here) with irradiance (1, 2, 3). */
static inline struct ssg_image *light_list(const float (*dirs)[3], int n)
{
    struct ssg_image *l = ssg_image_create(n, 2, 3);
    for (int i = 0; i < n; i++) {
        const float *d = dirs[i];
        float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (int c = 0; c < 3; c++) {
            l->data[(c * 2) * n + i] = d[c] / len;
            l->data[(c * 2 + 1) * n + i] = (float)(c + 1);
        }
    }
    return l;
}

/* Loads and runs a graph file with the overrides ov into out_dir, printing its messages. */
static inline enum ssg_err graph_run_with(const char *graph, const struct ssg_overrides *ov,
                                          const char *out_dir)
{
    struct ssg_run_options opt = {.out_dir = out_dir};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load(graph, ov, &g, &d);
    if (!e)
        e = ssg_graph_run(g, &opt, &d);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
    return e;
}

/* Loads and runs a graph file at w x h (scene: NULL = the graph's own) into out_dir. */
static inline enum ssg_err graph_run_sets(const char *graph, const char *scene, int w, int h,
                                          const char *out_dir, const char *const *sets,
                                          int set_count)
{
    struct ssg_overrides ov = {.scene = scene, .width = w, .height = h, .seed = -1,
                               .sets = sets, .set_count = set_count};
    return graph_run_with(graph, &ov, out_dir);
}

/* A graph file at its own size on `backend` ("cpu" or "gl"; scene NULL = its own). */
static inline enum ssg_err graph_run_on(const char *graph, const char *scene,
                                        const char *backend, const char *out_dir)
{
    struct ssg_overrides ov = {.scene = scene, .seed = -1, .backend = backend};
    return graph_run_with(graph, &ov, out_dir);
}

static inline enum ssg_err graph_run(const char *graph, const char *scene, int w, int h,
                                     const char *out_dir)
{
    return graph_run_sets(graph, scene, w, h, out_dir, NULL, 0);
}

/* Layer `name` (NULL = the main image) of dir/file; NULL and a failed check when absent. */
static inline struct ssg_image *exr_layer(const char *dir, const char *file, const char *name)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    struct ssg_image *im = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_image_read(path, name, &im, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return im;
}

/* The world point of view-space point v under the camera's view matrix m
   (ssg_camera_view_matrix: view = R world + t, column-major): world = R^T (v - t). */
static inline void view_to_world(const float m[16], const float v[3], float w[3])
{
    float d[3] = {v[0] - m[12], v[1] - m[13], v[2] - m[14]};
    for (int r = 0; r < 3; r++)
        w[r] = m[4 * r] * d[0] + m[4 * r + 1] * d[1] + m[4 * r + 2] * d[2];
}

/* The world point of pixel i of a G-buffer's view-space `position` image (camera view
   matrix m) into w; 0 on the background (no surface: view z 0). */
static inline int pixel_world(const struct ssg_image *position, const float m[16], size_t i,
                              float w[3])
{
    size_t plane = (size_t)position->width * position->height;
    float v[3] = {position->data[i], position->data[plane + i], position->data[2 * plane + i]};
    view_to_world(m, v, w);
    return v[2] != 0.0f;
}

/* The view matrix of scene file `path`'s camera into m (its meshes are not loaded). */
static inline void scene_view_matrix(const char *path, float m[16])
{
    struct ssg_scene *s = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_scene_load(path, 0, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (s)
        ssg_camera_view_matrix(&s->camera, m);
    ssg_scene_destroy(&s);
}

/* The node's defaults with `sets` applied; free() it. */
static inline void *node_params(const struct ssg_node_desc *desc, const char *const *sets,
                                int set_count)
{
    void *params = calloc(1, desc->params_size ? desc->params_size : 1);
    ssg_params_defaults(desc->params, params);
    struct ssg_diags d = {0};
    for (int i = 0; i < set_count; i++)
        CHECK_EQ(ssg_param_set_text(desc->params, params, sets[i], "<test>", desc->name, &d),
                 SSG_OK);
    ssg_diags_print(&d, stderr);
    return params;
}

/* Runs prepare() and the node's kernel on `backend` with the caller's ctx (its frame,
   history_reset, ...); on GL the outputs come back to the CPU and every GL copy of
   io's images is freed. Returns the node's error (its message in ctx->diags). */
static inline enum ssg_err node_execute_on(const struct ssg_node_desc *desc,
                                           const struct ssg_node_ctx *ctx, const void *params,
                                           const struct ssg_io *io, enum ssg_backend backend)
{
    struct ssg_node_timing t;
    enum ssg_err e = backend == SSG_BACKEND_GL ? ssg_gl_open(ctx->diags) : SSG_OK;
    if (!e)
        e = ssg_node_execute(desc, ctx, params, io, backend, &t);
    if (backend == SSG_BACKEND_GL) {
        double ms = 0;
        for (int i = 0; i < desc->output_count; i++) {
            if (!io->out[i])
                continue; /* an on-demand output left unbound */
            if (!e)
                e = ssg_gl_to_cpu(io->out[i], &ms, ctx->diags);
            ssg_gl_image_free(io->out[i]);
        }
        for (int i = 0; i < desc->input_count; i++)
            if (io->in[i])
                ssg_gl_image_free((struct ssg_image *)io->in[i]);
        ssg_gl_close();
    }
    return e;
}

/* Runs the node on `backend` with the scene; `in` in port order (NULL = unconnected),
   `out` allocated by the caller to the node's output shapes. On GL the outputs come back
   to the CPU and every GL copy is freed. Returns the node's error (printed). prev is the
   previous frame's camera (ctx->prev_camera; NULL = the scene's, a first frame), frame_index
   ctx->frame_index. */
static inline enum ssg_err node_run_scene_at(const struct ssg_node_desc *desc,
                                             const struct ssg_scene *scene,
                                             const struct ssg_camera *prev,
                                             const struct ssg_frame *frame, int frame_index,
                                             const void *params,
                                             const struct ssg_image *const *in,
                                             struct ssg_image *const *out,
                                             enum ssg_backend backend)
{
    struct ssg_diags d = {0};
    struct ssg_node_ctx ctx = {.desc = desc, .instance = desc->name, .frame = frame,
                               .scene = scene, .out_dir = ".", .diags = &d,
                               .prev_camera = prev ? prev : scene ? &scene->camera : NULL,
                               .frame_index = frame_index};
    struct ssg_io io = {.in = in, .out = out};
    struct ssg_io_shapes shapes;
    ssg_io_shapes_of(desc, &io, &shapes);
    ssg_node_ctx_set_shapes(&ctx, &shapes);
    enum ssg_err e = node_execute_on(desc, &ctx, params, &io, backend);
    ssg_diags_print(&d, stderr);
    return e;
}

static inline enum ssg_err node_run_scene_prev(const struct ssg_node_desc *desc,
                                               const struct ssg_scene *scene,
                                               const struct ssg_camera *prev,
                                               const struct ssg_frame *frame,
                                               const void *params,
                                               const struct ssg_image *const *in,
                                               struct ssg_image *const *out,
                                               enum ssg_backend backend)
{
    return node_run_scene_at(desc, scene, prev, frame, 0, params, in, out, backend);
}

/* node_run_scene_at in frame 0 with the scene's camera as the previous one. */

static inline enum ssg_err node_run_scene(const struct ssg_node_desc *desc,
                                          const struct ssg_scene *scene,
                                          const struct ssg_frame *frame, const void *params,
                                          const struct ssg_image *const *in,
                                          struct ssg_image *const *out,
                                          enum ssg_backend backend)
{
    return node_run_scene_prev(desc, scene, NULL, frame, params, in, out, backend);
}

#endif
