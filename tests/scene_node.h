/* scene_node.h - running one node that reads the scene (ctx->scene), which ssg_node_run
 * (no scene) cannot: a scene from a few lines of text, a node's parameters from "name=value"
 * strings, and a run on either backend with every output back on the CPU. The hybrid AO's
 * tests use it; it goes through the executor (exec.h) as a graph run does. */
#ifndef SSG_TEST_SCENE_NODE_H
#define SSG_TEST_SCENE_NODE_H

#include <stdlib.h>
#include <sys/stat.h>

#include "check.h"
#include "exec.h"
#include "gl_backend.h"
#include "node.h"
#include "scene.h"

/* A path in the test's temporary folder (SSG_TMP, made on first use). */
static inline const char *scene_node_path(const char *name)
{
    static char path[1024];
    const char *dir = getenv("SSG_TMP") ? getenv("SSG_TMP") : "/tmp/ssg_scene_node";
    mkdir(dir, 0755);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    return path;
}

/* Writes `text` to <tmp>/<name> and loads it with its assets; NULL (and a failed check)
   when it does not load. */
static inline struct ssg_scene *scene_from_text(const char *name, const char *text)
{
    const char *path = scene_node_path(name);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (!f)
        return NULL;
    fputs(text, f);
    fclose(f);
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(path, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return s;
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

/* Runs the node on `backend` with the scene; `in` in port order (NULL = unconnected),
   `out` allocated by the caller to the node's output shapes. On GL the outputs come back
   to the CPU and every GL copy is freed. Returns the node's error (printed). */
static inline enum ssg_err node_run_scene(const struct ssg_node_desc *desc,
                                          const struct ssg_scene *scene,
                                          const struct ssg_frame *frame, const void *params,
                                          const struct ssg_image *const *in,
                                          struct ssg_image *const *out,
                                          enum ssg_backend backend)
{
    struct ssg_diags d = {0};
    struct ssg_node_ctx ctx = {desc->name, frame, scene, ".", &d, NULL};
    struct ssg_io io = {.in = in, .out = out};
    struct ssg_node_timing t;
    enum ssg_err e = backend == SSG_BACKEND_GL ? ssg_gl_open(&d) : SSG_OK;
    if (!e)
        e = ssg_node_execute(desc, &ctx, params, &io, backend, &t);
    if (backend == SSG_BACKEND_GL) {
        double ms = 0;
        for (int i = 0; i < desc->output_count; i++) {
            if (!e)
                e = ssg_gl_to_cpu(out[i], &ms, &d);
            ssg_gl_image_free(out[i]);
        }
        for (int i = 0; i < desc->input_count; i++)
            if (in[i])
                ssg_gl_image_free((struct ssg_image *)in[i]);
        ssg_gl_close();
    }
    ssg_diags_print(&d, stderr);
    return e;
}

#endif
