/* noderun.c - one node alone on in-memory images (ssg_node_run in ssgraph.h): how users
 * and our own tests call a node without a graph file. Inputs are matched to ports by name
 * and typed by their channel count; every problem is reported by port name. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graph/exec.h"
#include "graph/gl_backend.h"
#include "graph/image.h"
#include "graph/metrics.h"
#include "lang/parse.h"
#include "scene/scene.h"

struct single {
    const struct ssg_node_desc *d;
    const struct ssg_image *in[SSG_MAX_PORTS];
    struct ssg_shape in_shape[SSG_MAX_PORTS];
    const char *extra_names[SSG_MAX_EXTRA];
    const struct ssg_image *extra[SSG_MAX_EXTRA];
    unsigned extra_types[SSG_MAX_EXTRA];
    int extra_count;
    int frame_index; /* "frame=N" among the sets: the run is frame N of a sequence */
};

static enum ssg_err bind_one(struct single *s, const struct ssg_binding *b,
                             struct ssg_diags *diags)
{
    const struct ssg_node_desc *d = s->d;
    int port = ssg_port_find(d->inputs, d->input_count, b->port, strlen(b->port));
    unsigned accepted = port >= 0 ? d->inputs[port].types : SSG_T_IMAGE;
    if (port < 0 && (!d->extra_inputs || s->extra_count == SSG_MAX_EXTRA)) {
        ssg_diag_file(diags, SSG_E_UNKNOWN_PORT, NULL, "node '%s' has no input '%s'", d->name,
                      b->port);
        return SSG_E_UNKNOWN_PORT;
    }
    unsigned type = b->image ? ssg_type_of_image(accepted, b->image) : 0;
    if (!type) {
        char want[64];
        ssg_type_names(accepted, want, sizeof want);
        ssg_diag_file(diags, SSG_E_CHANNELS, NULL, "input '%s' of node '%s' expects %s "
                      "(scalar: 1 channel, vector/color: 3, kernel: Nx1 with 3, pattern: 2), "
                      "got %d channels", b->port, d->name, want,
                      b->image ? b->image->channels : 0);
        return SSG_E_CHANNELS;
    }
    if (port < 0) {
        s->extra_names[s->extra_count] = b->port;
        s->extra_types[s->extra_count] = type;
        s->extra[s->extra_count++] = b->image;
        return SSG_OK;
    }
    s->in[port] = b->image;
    s->in_shape[port] = (struct ssg_shape){b->image->width, b->image->height,
                                           b->image->channels, type};
    return SSG_OK;
}

static enum ssg_err bind_inputs(struct single *s, const struct ssg_binding *inputs, int count,
                                struct ssg_diags *diags)
{
    enum ssg_err first = SSG_OK;
    for (int i = 0; i < count; i++) {
        enum ssg_err e = SSG_E_USAGE;
        if (!inputs[i].port || !inputs[i].image)
            ssg_diag_file(diags, SSG_E_USAGE, NULL, "ssg_node_run: inputs[%d].%s is NULL "
                          "(expected a port name and an image)", i,
                          inputs[i].port ? "image" : "port");
        else
            e = bind_one(s, &inputs[i], diags);
        if (e && !first)
            first = e;
    }
    for (int i = 0; i < s->d->input_count; i++) {
        if (!s->in[i] && !s->d->inputs[i].optional) {
            ssg_diag_file(diags, SSG_E_MISSING_INPUT, NULL, "node '%s' needs input '%s'",
                          s->d->name, s->d->inputs[i].name);
            if (!first)
                first = SSG_E_MISSING_INPUT;
        }
    }
    return first;
}

/* The frame: the caller's, with size defaulting to the first frame-sized input's. */
static struct ssg_frame make_frame(const struct single *s, const struct ssg_frame *given)
{
    const struct ssg_frame def = SSG_FRAME_DEFAULTS;
    struct ssg_frame f = given ? *given : def;
    if (f.fov_y <= 0)
        f.fov_y = def.fov_y;
    if (f.near_z <= 0)
        f.near_z = def.near_z;
    if (f.far_z <= 0)
        f.far_z = def.far_z;
    for (int i = 0; i < s->d->input_count && f.width <= 0; i++) {
        if (s->in[i] && (s->in_shape[i].type & SSG_T_IMAGE)) {
            f.width = s->in[i]->width;
            f.height = s->in[i]->height;
        }
    }
    return f;
}

/* A caller's frame whose projection the nodes cannot use (fov 1e-30 gives an infinite focal
   length) is refused, with the bounds a scene's camera has (ssg_camera_fault). */
static enum ssg_err check_frame(const struct ssg_frame *f, struct ssg_diags *diags)
{
    if (f->fov_y >= SSG_CAMERA_FOV_MIN && f->fov_y <= 180 - SSG_CAMERA_FOV_MIN &&
        f->far_z > f->near_z && isfinite(f->far_z))
        return SSG_OK;
    ssg_diag_file(diags, SSG_E_VALUE, NULL, "the frame's fov %g must lie in [%g, %g] degrees "
                  "and its planes be finite with 0 < near (%g) < far (%g)", (double)f->fov_y,
                  SSG_CAMERA_FOV_MIN, 180 - SSG_CAMERA_FOV_MIN, (double)f->near_z,
                  (double)f->far_z);
    return SSG_E_VALUE;
}

/* "backend=cpu|gl" among the sets (as in a graph file); 1 when sets[i] was one. */
static int backend_set(const struct ssg_node_desc *d, const char *set, enum ssg_backend *b,
                       enum ssg_err *e, struct ssg_diags *diags)
{
    if (strncmp(set, "backend=", 8) != 0 || ssg_param_find(d->params, "backend", 7) >= 0)
        return 0;
    *e = SSG_OK;
    if (!ssg_backend_parse(set + 8, strlen(set + 8), b)) {
        ssg_diag_file(diags, SSG_E_VALUE, "<--set>", "backend must be cpu or gl, got '%s'",
                      set + 8);
        *e = SSG_E_VALUE;
    } else if (*b == SSG_BACKEND_GL && !d->run_gl) {
        ssg_diag_file(diags, SSG_E_BACKEND, "<--set>", "node '%s' has no GL implementation "
                      "(expected backend=cpu)", d->name);
        *e = SSG_E_BACKEND;
    }
    return 1;
}

/* "frame=N" among the sets (N >= 0): the node runs as frame N of a sequence (node.h's
   frame_index), where per-frame samples move (docs/time.md); 1 when set was one. */
static int frame_set(const struct ssg_node_desc *d, const char *set, int *frame,
                     enum ssg_err *e, struct ssg_diags *diags)
{
    if (strncmp(set, "frame=", 6) != 0 || ssg_param_find(d->params, "frame", 5) >= 0)
        return 0;
    char *end;
    long v = strtol(set + 6, &end, 10);
    *e = SSG_OK;
    if (end == set + 6 || *end || v < 0 || v > 1000000000) {
        ssg_diag_file(diags, SSG_E_VALUE, "<--set>", "frame must be an integer from 0 to "
                      "1000000000, got '%s'", set + 6);
        *e = SSG_E_VALUE;
    } else {
        *frame = (int)v;
    }
    return 1;
}

static enum ssg_err apply_sets(struct single *s, void *params, const char *const *sets,
                               int count, enum ssg_backend *backend, struct ssg_diags *diags)
{
    const struct ssg_node_desc *d = s->d;
    enum ssg_err first = SSG_OK;
    for (int i = 0; i < count; i++) {
        enum ssg_err e;
        if (!sets[i]) {
            ssg_diag_file(diags, SSG_E_USAGE, NULL, "ssg_node_run: sets[%d] is NULL (expected "
                          "\"param=value\")", i);
            e = SSG_E_USAGE;
        } else if (!backend_set(d, sets[i], backend, &e, diags) &&
                   !frame_set(d, sets[i], &s->frame_index, &e, diags))
            e = ssg_param_set_text(d->params, params, sets[i], "<--set>", d->name, diags);
        if (e && !first)
            first = e;
    }
    return first;
}

/* GL outputs come back to the CPU: the caller reads their pixels. */
static enum ssg_err outputs_to_cpu(struct ssg_outputs *outputs, struct ssg_diags *diags)
{
    double ms = 0;
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < outputs->count && !e; i++)
        e = ssg_gl_to_cpu(outputs->images[i], &ms, diags);
    for (int i = 0; i < outputs->count; i++)
        ssg_gl_image_free(outputs->images[i]);
    return e;
}

static enum ssg_err run_single(struct single *s, const void *params, const struct ssg_frame *f,
                               enum ssg_backend backend, struct ssg_outputs *outputs,
                               struct ssg_diags *diags)
{
    struct ssg_shape out_shape[SSG_MAX_PORTS];
    char why[400];
    enum ssg_err e = ssg_shapes_infer(s->d, params, f, s->in_shape, out_shape, why, sizeof why);
    if (e) {
        ssg_diag_file(diags, e, NULL, "node '%s': %s", s->d->name, why);
        return e;
    }
    outputs->count = s->d->output_count;
    for (int i = 0; i < s->d->output_count; i++) {
        outputs->names[i] = s->d->outputs[i].name;
        outputs->images[i] = ssg_image_create(out_shape[i].width, out_shape[i].height,
                                              out_shape[i].channels);
        if (!outputs->images[i])
            return SSG_E_NOMEM;
    }
    struct ssg_io io = {.in = s->in, .out = outputs->images, .extra_count = s->extra_count,
                        .extra_names = s->extra_names, .extra_in = s->extra,
                        .extra_types = s->extra_types};
    struct ssg_shape extra_shape[SSG_MAX_EXTRA];
    for (int i = 0; i < s->extra_count; i++)
        extra_shape[i] = ssg_shape_of_image(s->extra[i], s->extra_types[i]);
    struct ssg_metrics metrics = {0};
    struct ssg_node_ctx ctx = {.desc = s->d, .instance = s->d->name, .frame = f,
                               .out_dir = "out", .diags = diags, .metrics = &metrics,
                               .in_shape = s->in_shape, .out_shape = out_shape,
                               .extra_shape = extra_shape, .frame_index = s->frame_index,
                               .history_reset = 1};
    struct ssg_node_timing timing;
    if (backend == SSG_BACKEND_GL && (e = ssg_gl_open(diags)))
        return e;
    e = ssg_node_execute(s->d, &ctx, params, &io, backend, &timing);
    if (backend == SSG_BACKEND_GL) {
        enum ssg_err back = outputs_to_cpu(outputs, diags);
        for (int i = 0; i < s->d->input_count; i++)
            if (s->in[i])
                ssg_gl_image_free((struct ssg_image *)s->in[i]); /* the caller's image */
        for (int i = 0; i < s->extra_count; i++)
            ssg_gl_image_free((struct ssg_image *)s->extra[i]);
        ssg_gl_close();
        if (!e)
            e = back;
    }
    for (int i = 0; i < metrics.count && i < 16; i++) {
        snprintf(outputs->metric_names[i], sizeof outputs->metric_names[i], "%s",
                 metrics.items[i].name);
        outputs->metric_values[i] = metrics.items[i].value;
        outputs->metric_count = i + 1;
    }
    return e;
}

enum ssg_err ssg_node_run(const char *node, const struct ssg_binding *inputs, int input_count,
                          const char *const *sets, int set_count, const struct ssg_frame *frame,
                          struct ssg_outputs *outputs, struct ssg_diags *diags)
{
    if (outputs)
        memset(outputs, 0, sizeof *outputs);
    if (ssg_api_null(diags, "ssg_node_run", "node, outputs", 2, node, outputs))
        return SSG_E_USAGE;
    if ((input_count > 0 && !inputs) || (set_count > 0 && !sets) || input_count < 0 ||
        set_count < 0) {
        ssg_diag_file(diags, SSG_E_USAGE, NULL, "ssg_node_run: %s (expected an array of that "
                      "many entries)", input_count < 0 || (input_count > 0 && !inputs)
                          ? "input_count does not match inputs" : "set_count does not match sets");
        return SSG_E_USAGE;
    }
    const struct ssg_node_desc *d = ssg_node_find(node, strlen(node));
    if (!d) {
        ssg_diag_file(diags, SSG_E_UNKNOWN_NODE, NULL, "unknown node '%s' (see ssgraph nodes)",
                      node);
        return SSG_E_UNKNOWN_NODE;
    }
    return ssg_node_run_desc(d, inputs, input_count, sets, set_count, frame, outputs, diags);
}

enum ssg_err ssg_node_run_desc(const struct ssg_node_desc *d, const struct ssg_binding *inputs,
                               int input_count, const char *const *sets, int set_count,
                               const struct ssg_frame *frame, struct ssg_outputs *outputs,
                               struct ssg_diags *diags)
{
    memset(outputs, 0, sizeof *outputs);
    struct single s = {.d = d};
    const char *node = d->name;
    if (s.d->reads & SSG_READS_SCENE) {
        ssg_diag_file(diags, SSG_E_SCENE, NULL, "node '%s' renders a scene; run it in a graph "
                      "with a scene instead", node);
        return SSG_E_SCENE;
    }
    void *params = calloc(1, s.d->params_size ? s.d->params_size : 1);
    if (!params)
        return SSG_E_NOMEM;
    ssg_params_defaults(s.d->params, params);
    enum ssg_backend backend = SSG_BACKEND_CPU;
    enum ssg_err e = apply_sets(&s, params, sets, set_count, &backend, diags);
    enum ssg_err b = bind_inputs(&s, inputs, input_count, diags);
    if (!e)
        e = b;
    /* No size check here: a node with no frame-sized output (halton) needs no frame;
       the shape check rejects a frame-sized output of a frame without a size. */
    struct ssg_frame f = make_frame(&s, frame);
    if (!e)
        e = check_frame(&f, diags);
    if (!e)
        e = run_single(&s, params, &f, backend, outputs, diags);
    free(params);
    if (e)
        ssg_outputs_release(outputs);
    return e;
}

void ssg_outputs_release(struct ssg_outputs *outputs)
{
    if (!outputs)
        return;
    for (int i = 0; i < outputs->count; i++)
        ssg_image_destroy(&outputs->images[i]);
    outputs->count = 0;
}
