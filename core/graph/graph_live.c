/* graph_live.c - live graphs (ssgraph.h): the run state kept from one ssg_graph_run to the
 * next, parameters changed on a loaded graph, and the kept images handed out.
 *
 * Correctness rule: a node's outputs are reused only while nothing they depend on has
 * changed. Every change here names what it changed to graph_redo.c (ssg_redo,
 * ssg_redo_reading), the one rule for what runs again: a set, the node whose parameter it
 * is (only a run when its check_params says the run alone reads it) and every node whose
 * shapes moved; a new view, the camera's readers; new lights, theirs; a supplied image,
 * its node. A run re-runs every node whose outputs are not kept or one of whose producers
 * ran, so any sequence of changes and runs gives the bytes of a fresh load with the final
 * settings. */
#include <stdlib.h>
#include <string.h>

#include "graph/gl_backend.h"
#include "graph/graph.h"
#include "graph/graph_history.h"
#include "graph/image.h"

int ssg_live_init(struct ssg_live *l, int count)
{
    size_t n = (size_t)(count ? count : 1);
    *l = (struct ssg_live){.count = count, .pool = ssg_pool_create(),
                           .consts = calloc(n, sizeof *l->consts),
                           .scratch = calloc(n, sizeof *l->scratch),
                           .prepared = calloc(n, 1), .kept = calloc(n, 1),
                           .why = calloc(n, 1), .reported = calloc(n, sizeof *l->reported),
                           .reported_count = calloc(n, sizeof *l->reported_count),
                           .made = calloc(n, sizeof *l->made)};
    return l->pool && l->consts && l->scratch && l->prepared && l->kept && l->why &&
           l->reported && l->reported_count && l->made;
}

int ssg_graph_output_kept(const struct ssg_graph *g, int node, int k)
{
    int p = 0;
    while (p < g->order_count && g->order[p] != node)
        p++;
    return g->live && p < g->order_count && g->live->kept[p] && g->nodes[node].out_img[k];
}

enum ssg_err ssg_graph_keep(struct ssg_graph *g, size_t max_bytes, struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_keep", "graph", 1, g))
        return SSG_E_USAGE;
    if (g->live) {
        g->live->max_bytes = max_bytes;
        return SSG_OK;
    }
    struct ssg_live *l = calloc(1, sizeof *l);
    g->live = l;
    if (!l || !ssg_live_init(l, g->order_count)) {
        ssg_live_free(g);
        ssg_diag_file(diags, SSG_E_NOMEM, g->path, "out of memory keeping the run state");
        return SSG_E_NOMEM;
    }
    l->max_bytes = max_bytes;
    return SSG_OK;
}

/* The bytes of the images node p's outputs hold now. */
static size_t kept_bytes(const struct ssg_graph *g, int p)
{
    const struct gnode *n = &g->nodes[g->order[p]];
    size_t bytes = 0;
    for (int k = 0; k < n->desc->output_count; k++)
        if (n->out_img[k])
            bytes += (size_t)n->out_img[k]->width * (size_t)n->out_img[k]->height *
                     (size_t)n->out_img[k]->channels * sizeof(float);
    return bytes;
}

/* Gives back node p's output images. */
static void release_outputs(struct ssg_graph *g, struct ssg_live *l, int p)
{
    struct gnode *n = &g->nodes[g->order[p]];
    for (int k = 0; k < SSG_MAX_PORTS; k++) {
        ssg_pool_release(l->pool, n->out_img[k]);
        n->out_img[k] = NULL;
    }
}

void ssg_live_after_run(struct ssg_graph *g, int used_gl)
{
    struct ssg_live *l = g->live;
    l->used_gl |= used_gl;
    size_t total = 0;
    for (int p = 0; p < g->order_count; p++)
        total += kept_bytes(g, p);
    while (l->max_bytes && total > l->max_bytes) { /* the eviction rule: largest first */
        int worst = -1;
        size_t most = 0;
        for (int p = 0; p < g->order_count; p++)
            if (kept_bytes(g, p) > most)
                most = kept_bytes(g, p), worst = p;
        if (worst < 0)
            break;
        release_outputs(g, l, worst);
        ssg_redo(g, l, worst, SSG_RECOMPUTE_RUN, SSG_WHY_EVICTED);
        total -= most;
    }
}

void ssg_live_release(struct ssg_graph *g, struct ssg_live *l)
{
    ssg_gl_shared_clear(&l->gl);
    for (int p = 0; p < l->count && l->pool; p++)
        release_outputs(g, l, p);
    ssg_history_free(g, l->pool);
    ssg_pool_destroy(&l->pool);
    for (int p = 0; l->consts && p < l->count; p++)
        free(l->consts[p]);
    for (int p = 0; l->scratch && p < l->count; p++)
        ssg_scratch_free(&l->scratch[p]);
    free(l->consts);
    free(l->scratch);
    free(l->prepared);
    free(l->kept);
    free(l->why);
    for (int p = 0; l->reported && p < l->count; p++)
        free(l->reported[p]);
    free(l->reported);
    free(l->reported_count);
    free(l->made);
    *l = (struct ssg_live){0};
}

void ssg_live_free(struct ssg_graph *g)
{
    struct ssg_live *l = g->live;
    if (!l)
        return;
    struct ssg_diags quiet = {0};
    int gl = l->used_gl && ssg_gl_open(&quiet) == SSG_OK; /* textures die with GL current */
    ssg_live_release(g, l);
    if (gl)
        ssg_gl_close();
    free(l);
    g->live = NULL;
}

/* Every node's shapes, to tell after a change which moved. */
struct ssg_shapes_saved {
    int count;
    struct ssg_shape shape[][2][SSG_MAX_PORTS];
};

struct ssg_shapes_saved *ssg_shapes_save(const struct ssg_graph *g)
{
    struct ssg_shapes_saved *s = calloc(1, sizeof *s + (size_t)(g->count + 1) *
                                                          sizeof s->shape[0]);
    for (int k = 0; s && k < g->count; k++) {
        memcpy(s->shape[k][0], g->nodes[k].in_shape, sizeof s->shape[k][0]);
        memcpy(s->shape[k][1], g->nodes[k].out_shape, sizeof s->shape[k][1]);
    }
    if (s)
        s->count = g->count;
    return s;
}

void ssg_redo_moved(struct ssg_graph *g, const struct ssg_shapes_saved *saved)
{
    for (int p = 0; g->live && p < g->order_count; p++) {
        const struct gnode *m = &g->nodes[g->order[p]];
        if (memcmp(saved->shape[g->order[p]][0], m->in_shape, sizeof saved->shape[0][0]) ||
            memcmp(saved->shape[g->order[p]][1], m->out_shape, sizeof saved->shape[0][1]))
            ssg_redo(g, g->live, p, SSG_RECOMPUTE_HISTORY, SSG_WHY_SHAPE);
    }
}

/* The node a key "node.param" names when the node has that parameter, else -1 with
   *e set and reported as ssg_graph_param reports it. */
static int find_param(struct ssg_graph *g, const char *key, enum ssg_err *e,
                      struct ssg_diags *diags)
{
    double unused;
    const char *dot = strchr(key, '.');
    int i = dot ? ssg_graph_find(g, key, (size_t)(dot - key)) : -1;
    if (i < 0 || ssg_param_find(g->nodes[i].desc->params, dot + 1, strlen(dot + 1)) < 0) {
        *e = ssg_graph_param(g, key, &unused, NULL, diags); /* its message, same fault */
        return -1;
    }
    return i;
}

/* 1 when the set line `line` ("node.param=value", spaces allowed) sets `key`. */
static int sets_key(const char *line, const char *key)
{
    while (*line == ' ' || *line == '\t')
        line++;
    size_t n = strlen(key);
    if (strncmp(line, key, n))
        return 0;
    line += n;
    while (*line == ' ' || *line == '\t')
        line++;
    return *line == '=';
}

/* Records a set that took as the graph's set lines, which the run's files record (write's
   EXR metadata): it replaces the line of the same key where there is one, else it comes
   last, as --set would have listed it. In the graph's arena, freed with it. */
static enum ssg_err record_set(struct ssg_graph *g, const char *key, const char *text)
{
    char *line = ssg_arena_strndup(&g->arena, text, strlen(text));
    if (!line)
        return SSG_E_NOMEM;
    for (int k = g->set_count - 1; k >= 0; k--)
        if (sets_key(g->sets[k], key)) {
            g->sets[k] = line;
            return SSG_OK;
        }
    const char **sets = ssg_arena_alloc(&g->arena, (size_t)(g->set_count + 1) * sizeof *sets);
    if (!sets)
        return SSG_E_NOMEM;
    for (int k = 0; k < g->set_count; k++)
        sets[k] = g->sets[k];
    sets[g->set_count] = line;
    g->sets = sets;
    g->set_count++;
    return SSG_OK;
}

/* The errors of a refused set from index `first` on point at the node's definition, the
   place to change it for good, and quote the set ("do.radius=-3: parameter ..."). */
static void at_node(const struct gnode *n, const char *text, struct ssg_diags *diags,
                    int first)
{
    int line, column;
    ssg_loc_linecol(n->loc, &line, &column);
    for (int i = first; diags && n->loc.src && i < diags->count; i++) {
        struct ssg_diag *d = &diags->items[i];
        char message[sizeof d->message];
        snprintf(message, sizeof message, "%s: %s (node '%s' is defined here)", text,
                 d->message, n->name);
        snprintf(d->message, sizeof d->message, "%s", message);
        snprintf(d->file, sizeof d->file, "%s", n->loc.src->path);
        d->line = line;
        d->column = column;
    }
}

enum ssg_err ssg_graph_set(struct ssg_graph *g, const char *key, const char *value,
                           struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_set", "graph, key, value", 3, g, key, value))
        return SSG_E_USAGE;
    size_t text_len = strlen(key) + strlen(value) + 2;
    char *text = malloc(text_len);
    if (!text)
        return SSG_E_NOMEM;
    snprintf(text, text_len, "%s=%s", key, value);
    /* one line, checked before the key is looked up and named in a message */
    struct ssg_source line = {"<ssg_graph_set>", text, text_len - 1};
    enum ssg_err e = ssg_line_check(&line, diags);
    int i = e ? -1 : find_param(g, key, &e, diags);
    if (i < 0) {
        free(text);
        return e;
    }
    struct gnode *n = &g->nodes[i];
    size_t size = n->desc->params_size;
    struct ssg_shapes_saved *shapes = ssg_shapes_save(g);
    void *old = malloc(size ? size : 1);
    if (!shapes || !old) {
        free(shapes), free(old), free(text);
        return SSG_E_NOMEM;
    }
    memcpy(old, n->params, size);
    int first = diags ? diags->count : 0;
    e = ssg_graph_apply_set(g, text, diags);
    if (e)
        at_node(n, text, diags, first);
    if (!e)
        e = ssg_graph_reinfer(g, diags);
    if (!e)
        e = record_set(g, key, text);
    if (e) { /* the graph stays as it was: the old value, the old shapes */
        struct ssg_diags quiet = {0};
        memcpy(n->params, old, size);
        ssg_graph_reinfer(g, &quiet);
    }
    for (int p = 0; !e && g->live && p < g->order_count; p++)
        if (g->order[p] == i) /* prepare again unless its check_params says the run alone
                                 reads what changed (node.h) */
            ssg_redo(g, g->live, p, n->desc->check_params ? n->desc->check_params(old,
                     n->params) : SSG_RECOMPUTE_PREPARE, SSG_WHY_PARAM);
    if (!e)
        ssg_redo_moved(g, shapes);
    free(shapes), free(old), free(text);
    return e;
}

enum ssg_err ssg_graph_output(struct ssg_graph *g, const char *port, struct ssg_image **out,
                              struct ssg_diags *diags)
{
    if (out)
        *out = NULL;
    if (ssg_api_null(diags, "ssg_graph_output", "graph, port, out", 3, g, port, out))
        return SSG_E_USAGE;
    const char *dot = strchr(port, '.');
    int i = dot ? ssg_graph_find(g, port, (size_t)(dot - port)) : -1;
    const struct gnode *n = i >= 0 ? &g->nodes[i] : NULL;
    int k = n ? ssg_port_find(n->desc->outputs, n->desc->output_count, dot + 1,
                              strlen(dot + 1))
              : -1;
    if (k < 0) {
        ssg_diag_file(diags, SSG_E_UNKNOWN_NAME, g->path, "no output '%s' in the graph "
                      "(expected node.port of a node's output)", port);
        return SSG_E_UNKNOWN_NAME;
    }
    if (!ssg_graph_output_kept(g, i, k)) {
        ssg_diag_file(diags, SSG_E_USAGE, g->path, "'%s' has no current image: keep the "
                      "run state (ssg_graph_keep) and run the graph first (the node must "
                      "be live, and its output read or kept)", port);
        return SSG_E_USAGE;
    }
    const struct ssg_image *im = n->out_img[k];
    double ms = 0;
    enum ssg_err e = SSG_OK;
    if (im->gpu && !(e = ssg_gl_open(diags))) {
        e = ssg_gl_to_cpu(im, &ms, diags);
        ssg_gl_close();
    }
    if (!e && !(*out = ssg_image_create(im->width, im->height, im->channels)))
        e = SSG_E_NOMEM;
    if (!e)
        memcpy((*out)->data, im->data, (size_t)im->width * (size_t)im->height *
                                           (size_t)im->channels * sizeof *im->data);
    return e;
}

enum ssg_err ssg_graph_view(const struct ssg_graph *g, struct ssg_view *out,
                            struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_view", "graph, out", 2, g, out))
        return SSG_E_USAGE;
    if (!g->scene) {
        ssg_diag_file(diags, SSG_E_SCENE, g->path, "the graph has no scene, so no camera");
        return SSG_E_SCENE;
    }
    const struct ssg_camera *c = &g->scene->camera;
    memcpy(out->position, c->position, sizeof out->position);
    memcpy(out->target, c->target, sizeof out->target);
    memcpy(out->up, c->up, sizeof out->up);
    out->fov_y = c->fov_y;
    return SSG_OK;
}

enum ssg_err ssg_graph_set_view(struct ssg_graph *g, const struct ssg_view *v,
                                struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_set_view", "graph, view", 2, g, v))
        return SSG_E_USAGE;
    struct ssg_camera camera = g->scene ? g->scene->camera : (struct ssg_camera){0};
    memcpy(camera.position, v->position, sizeof camera.position);
    memcpy(camera.target, v->target, sizeof camera.target);
    memcpy(camera.up, v->up, sizeof camera.up);
    camera.fov_y = v->fov_y;
    enum ssg_camera_part part;
    const char *why = g->scene ? ssg_camera_fault(&camera, &part) : "the graph has no scene";
    if (why) {
        ssg_diag_file(diags, g->scene ? SSG_E_VALUE : SSG_E_SCENE, g->path, "cannot set "
                      "the camera: %s", why);
        return g->scene ? SSG_E_VALUE : SSG_E_SCENE;
    }
    g->scene->camera = camera;
    g->frame.fov_y = v->fov_y;
    g->time.has_last = 0; /* a cut (graph_time.c); one-frame runs keep this view */
    g->time.view_set = 1;
    struct ssg_diags quiet = {0};
    ssg_graph_reinfer(g, &quiet); /* shapes do not depend on the camera; checks may read it */
    /* The camera's readers (the G-buffer, the projection in prepare(), the ray tracers'
       frames) prepare and run again; the readers of a node that runs follow it. */
    if (g->live)
        ssg_redo_reading(g, g->live, SSG_READS_CAMERA, SSG_RECOMPUTE_HISTORY,
                         SSG_WHY_CAMERA);
    ssg_history_cut(g); /* a new camera is a cut: prev() inputs start afresh */
    return SSG_OK;
}

enum ssg_err ssg_graph_supply(struct ssg_graph *g, const char *node,
                              const struct ssg_image *image, struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_supply", "graph, node, image", 3, g, node, image))
        return SSG_E_USAGE;
    int i = ssg_graph_find(g, node, strlen(node));
    struct gnode *n = i >= 0 ? &g->nodes[i] : NULL;
    if (!n || !n->desc->supplied) {
        ssg_diag_file(diags, n ? SSG_E_TYPE : SSG_E_UNKNOWN_NAME, g->path, "%s '%s' %s "
                      "(expected a node of type input)", n ? "node" : "no node named", node,
                      n ? "takes no supplied image" : "in the graph");
        return n ? SSG_E_TYPE : SSG_E_UNKNOWN_NAME;
    }
    const struct ssg_shape *s = &n->out_shape[0];
    if (image->width != s->width || image->height != s->height ||
        image->channels != s->channels) {
        ssg_diag_at(diags, SSG_E_SIZE, n->loc, "node '%s' (%s) was supplied a %dx%d image "
                    "of %d channels (expected %dx%d with %d: its type and size, the frame's "
                    "with its guard band unless width and height say otherwise)", n->name,
                    n->desc->name, image->width, image->height, image->channels,
                    s->width, s->height, s->channels);
        return SSG_E_SIZE;
    }
    struct ssg_image *copy = ssg_image_create(image->width, image->height, image->channels);
    if (!copy)
        return SSG_E_NOMEM;
    memcpy(copy->data, image->data, (size_t)image->width * (size_t)image->height *
                                        (size_t)image->channels * sizeof *image->data);
    ssg_image_destroy(&n->supplied);
    n->supplied = copy;
    for (int p = 0; g->live && p < g->order_count; p++)
        if (g->order[p] == i)
            ssg_redo(g, g->live, p, SSG_RECOMPUTE_PREPARE, SSG_WHY_SUPPLIED);
    return SSG_OK;
}
