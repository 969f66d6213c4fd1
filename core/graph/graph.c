/* graph.c - the public graph API's loading half (ssgraph.h): load = build (graph_build.c)
 * + scene + validate (graph_check.c); check = the same without the scene's assets. Running
 * a loaded graph is graph_run.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graph/graph.h"
#include "graph/image.h"
#include "lang/files.h"
#include "lang/params.h"
#include "scene/camera_path.h"

static int needs_scene(const struct ssg_graph *g, struct ssg_loc *where)
{
    for (int i = 0; i < g->count; i++) {
        if (g->nodes[i].desc->reads & SSG_READS_SCENE) { /* declared: undeclared needs none */
            *where = g->nodes[i].loc;
            return 1;
        }
    }
    return 0;
}

/* Loads the scene (assets too when load_assets) and derives the frame from its camera. */
static enum ssg_err setup_frame(struct ssg_graph *g, int load_assets, float eye_offset,
                                struct ssg_diags *diags)
{
    struct ssg_loc where = {0};
    g->frame = SSG_FRAME_DEFAULTS;
    g->frame.width = g->width;
    g->frame.height = g->height;
    g->frame.guard = g->guard;
    g->frame.seed = (uint64_t)g->seed;
    if (!ssg_image_size_ok(g->width, g->height, 1)) {
        ssg_diag_at(diags, SSG_E_SIZE, g->size_loc, "frame size %dx%d is out of range "
                    "(expected 1 to %d per side, at most %d pixels)", g->width, g->height,
                    SSG_IMAGE_MAX_SIDE, SSG_IMAGE_MAX_PIXELS);
        return SSG_E_SIZE;
    }
    if (!ssg_image_size_ok(ssg_frame_full_width(&g->frame), ssg_frame_full_height(&g->frame),
                           1)) {
        ssg_diag_at(diags, SSG_E_SIZE, g->guard_loc, "frame size %dx%d with a guard band of "
                    "%d pixels is out of range (expected at most %d per side, %d pixels in "
                    "all)", g->width, g->height, g->guard, SSG_IMAGE_MAX_SIDE,
                    SSG_IMAGE_MAX_PIXELS);
        return SSG_E_SIZE;
    }
    if (!g->scene_path[0]) {
        if (!needs_scene(g, &where))
            return SSG_OK;
        ssg_diag_at(diags, SSG_E_SCENE, where, "this node needs a scene (expected a line "
                    "scene \"file.scene\" in the graph, or --scene FILE)");
        return SSG_E_SCENE;
    }
    /* A graph's `scene` line that names a file that is not there: say which line. */
    char why[256];
    if (g->scene_loc.src && ssg_input_check(g->scene_path, 1LL << 40, why, sizeof why)) {
        ssg_diag_at(diags, SSG_E_IO, g->scene_loc, "cannot read the scene file '%s': %s "
                    "(expected a path relative to this graph file, or --scene FILE)",
                    g->scene_path, why);
        return SSG_E_IO;
    }
    enum ssg_err e = ssg_scene_load_lit(g->scene_path, g->lights_path[0] ? g->lights_path : NULL,
                                        load_assets, &g->scene, diags);
    if (e)
        return e;
    g->eye_offset = eye_offset; /* each frame's camera of a path moves too (graph_time.c) */
    if (eye_offset != 0.0f)
        ssg_camera_shift(&g->scene->camera, eye_offset);
    g->frame.fov_y = g->scene->camera.fov_y;
    g->frame.near_z = g->scene->camera.near_z;
    g->frame.far_z = g->scene->camera.far_z;
    return SSG_OK;
}

/* Keeps the command line's --set strings with the graph (its arena): write records them. */
static enum ssg_err keep_sets(struct ssg_graph *g, const struct ssg_overrides *ov)
{
    int n = ov ? ov->set_count : 0;
    if (n <= 0)
        return SSG_OK;
    if (!(g->sets = ssg_arena_alloc(&g->arena, (size_t)n * sizeof *g->sets)))
        return SSG_E_NOMEM;
    for (int i = 0; i < n; i++)
        if (!(g->sets[i] = ssg_arena_strndup(&g->arena, ov->sets[i], strlen(ov->sets[i]))))
            return SSG_E_NOMEM;
    g->set_count = n;
    return SSG_OK;
}

/* 1 when the scene gives no light at all: no light line, a black environment and no
   material that emits. */
static int scene_is_dark(const struct ssg_scene *s)
{
    return s->light_lines == 0 && s->light_count == 0 && !ssg_scene_environment_lit(s) &&
           !ssg_scene_has_emission(s);
}

/* The first live input reading a `lit` port (gbuffer's direct or environment light):
   its node in *reader and connection in *conn; 0 when none. */
static int reads_lit_port(const struct ssg_graph *g, int *reader, const struct gconn **conn)
{
    for (int i = 0; i < g->count; i++) {
        const struct gnode *n = &g->nodes[i];
        for (int p = 0; n->live && p < n->desc->input_count; p++) {
            const struct gconn *c = &n->in[p];
            if (c->node >= 0 && g->nodes[c->node].desc->outputs[c->port].lit) {
                *reader = i;
                *conn = c;
                return 1;
            }
        }
    }
    return 0;
}

/* A scene without any light renders black where the graph shows its light: an error when
   the graph reads the scene's light through a `lit` port, else a warning (AO alone, or a
   reference, still means something). */
static enum ssg_err check_scene_light(const struct ssg_graph *g, struct ssg_diags *diags)
{
    if (!g->scene || !scene_is_dark(g->scene))
        return SSG_OK;
    struct ssg_loc at = g->scene_loc;
    int reader;
    const struct gconn *c;
    if (!reads_lit_port(g, &reader, &c)) {
        ssg_diag_warn(diags, SSG_E_SCENE, at, "scene '%s' has no light and no environment: "
                      "whatever the graph shows of its light is black (expected a "
                      "point_light, directional_light or environment line, or --lights "
                      "examples/lights/sky.scene)", g->scene->path);
        return SSG_OK;
    }
    ssg_diag_at(diags, SSG_E_SCENE, c->value.loc, "'%s' (read by node '%s') is black: scene "
                "'%s' has no light and no environment (expected a point_light, "
                "directional_light or environment line in the scene, or --lights "
                "examples/lights/sky.scene)", c->ref, g->nodes[reader].name, g->scene->path);
    return SSG_E_SCENE;
}

enum ssg_err ssg_graph_set_lights(struct ssg_graph *g, const char *lights,
                                  struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_set_lights", "graph", 1, g))
        return SSG_E_USAGE;
    if (!g->scene) {
        ssg_diag_file(diags, SSG_E_SCENE, g->path, "cannot set the lights: the graph has no "
                      "scene (expected a line scene \"file.scene\" or --scene FILE)");
        return SSG_E_SCENE;
    }
    struct ssg_scene *lit = NULL; /* the scene anew under these lights: they move over */
    enum ssg_err e = ssg_scene_load_lit(g->scene_path, lights, 1, &lit, diags);
    struct ssg_shapes_saved *shapes = e ? NULL : ssg_shapes_save(g);
    if (!e && !shapes)
        e = SSG_E_NOMEM;
    if (!e) {
        ssg_scene_swap_lights(g->scene, lit);
        e = check_scene_light(g, diags);
        if (!e)
            e = ssg_graph_reinfer(g, diags);
        if (e) { /* the graph stays as it was */
            struct ssg_diags quiet = {0};
            ssg_scene_swap_lights(g->scene, lit);
            ssg_graph_reinfer(g, &quiet);
        }
    }
    if (!e) {
        snprintf(g->lights_path, sizeof g->lights_path, "%s", lights ? lights : "");
        if (g->live)
            ssg_redo_reading(g, g->live, SSG_READS_LIGHTS, SSG_RECOMPUTE_PREPARE,
                             SSG_WHY_LIGHTS);
        ssg_redo_moved(g, shapes);
    }
    free(shapes);
    ssg_scene_destroy(&lit); /* with the lights it gave up */
    return e;
}

enum ssg_err ssg_graph_read(struct ssg_graph *g, const char *path, struct ssg_loc from, int top,
                            struct ssg_file *file, struct ssg_diags *diags)
{
    if (top && g->text) /* ssg_graph_load_text: the caller's text stands for the file */
        return ssg_parse_text(&g->arena, path, g->text, file, diags);
    return ssg_parse_file(&g->arena, path, from, file, diags);
}

static enum ssg_err load(const char *path, const char *text, const struct ssg_overrides *ov,
                         int load_assets, struct ssg_graph **out, struct ssg_diags *diags)
{
    struct ssg_graph *g = calloc(1, sizeof *g);
    *out = NULL;
    if (!g)
        return SSG_E_NOMEM;
    g->text = text;
    enum ssg_err e = ssg_graph_build(g, path, ov, diags);
    g->text = NULL; /* the caller's */
    /* The scene is checked even when the graph has errors, so one run reports both. */
    enum ssg_err scene = setup_frame(g, load_assets, ov ? ov->eye_offset : 0.0f, diags);
    if (!e)
        e = scene;
    if (!e)
        e = keep_sets(g, ov);
    if (!e)
        e = ssg_graph_validate(g, diags);
    if (!e)
        e = check_scene_light(g, diags);
    if (e) {
        ssg_graph_destroy(&g);
        return e;
    }
    *out = g;
    return SSG_OK;
}

enum ssg_err ssg_graph_load(const char *path, const struct ssg_overrides *ov,
                            struct ssg_graph **out, struct ssg_diags *diags)
{
    if (out)
        *out = NULL;
    if (ssg_api_null(diags, "ssg_graph_load", "path, out", 2, path, out))
        return SSG_E_USAGE;
    return load(path, NULL, ov, 1, out, diags);
}

enum ssg_err ssg_graph_load_text(const char *path, const char *text,
                                 const struct ssg_overrides *ov, struct ssg_graph **out,
                                 struct ssg_diags *diags)
{
    if (out)
        *out = NULL;
    if (ssg_api_null(diags, "ssg_graph_load_text", "path, text, out", 3, path, text, out))
        return SSG_E_USAGE;
    return load(path, text, ov, 1, out, diags);
}

enum ssg_err ssg_graph_check(const char *path, const struct ssg_overrides *ov,
                             struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_check", "path", 1, path))
        return SSG_E_USAGE;
    struct ssg_graph *g = NULL;
    enum ssg_err e = load(path, NULL, ov, 0, &g, diags);
    ssg_graph_destroy(&g);
    return e;
}

enum ssg_err ssg_scene_check(const char *path, struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_scene_check", "path", 1, path))
        return SSG_E_USAGE;
    struct ssg_scene *scene = NULL;
    enum ssg_err e = ssg_scene_load(path, 1, &scene, diags);
    ssg_scene_destroy(&scene);
    return e;
}

void ssg_graph_destroy(struct ssg_graph **graph)
{
    if (!graph || !*graph)
        return;
    ssg_live_free(*graph);
    for (int i = 0; i < (*graph)->count; i++)
        ssg_image_destroy(&(*graph)->nodes[i].supplied);
    ssg_scene_destroy(&(*graph)->scene);
    ssg_arena_free(&(*graph)->arena);
    free(*graph);
    *graph = NULL;
}

/* "g, k, ao, ...": the graph's node names for a message. */
static void instance_names(const struct ssg_graph *g, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = 0;
    for (int i = 0; i < g->count && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", i ? ", " : "",
                                 g->nodes[i].name);
}

enum ssg_err ssg_graph_param(const struct ssg_graph *g, const char *key, double *value,
                             int *integer, struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_param", "graph, key, value", 3, g, key, value))
        return SSG_E_USAGE;
    const char *dot = strchr(key, '.');
    if (!dot) {
        ssg_diag_file(diags, SSG_E_USAGE, g->path, "expected a parameter node.param, got "
                      "'%s'", key);
        return SSG_E_USAGE;
    }
    int i = ssg_graph_find(g, key, (size_t)(dot - key));
    char names[512];
    if (i < 0) {
        instance_names(g, names, sizeof names);
        ssg_diag_file(diags, SSG_E_UNKNOWN_NAME, g->path, "no node named '%.*s' (in '%s'; "
                      "expected one of: %s)", (int)(dot - key), key, key, names);
        return SSG_E_UNKNOWN_NAME;
    }
    const struct gnode *n = &g->nodes[i];
    int p = ssg_param_find(n->desc->params, dot + 1, strlen(dot + 1));
    if (p < 0) {
        ssg_param_names(n->desc->params, names, sizeof names);
        ssg_diag_at(diags, SSG_E_UNKNOWN_PARAM, n->loc, "node '%s' (%s) has no parameter "
                    "'%s' (expected one of: %s)", n->name, n->desc->name, dot + 1, names);
        return SSG_E_UNKNOWN_PARAM;
    }
    const struct ssg_param_desc *d = &n->desc->params.params[p];
    if (d->type != SSG_P_FLOAT && d->type != SSG_P_INT) {
        ssg_diag_at(diags, SSG_E_TYPE, n->loc, "parameter '%s' of node '%s' (%s) is not a "
                    "number (expected a decimal or integer parameter)", d->name, n->name,
                    n->desc->name);
        return SSG_E_TYPE;
    }
    const char *field = (const char *)n->params + d->offset;
    *value = d->type == SSG_P_FLOAT ? *(const float *)field : *(const int *)field;
    if (integer)
        *integer = d->type == SSG_P_INT;
    return SSG_OK;
}
