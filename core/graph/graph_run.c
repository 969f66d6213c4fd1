/* graph_run.c - the executor (ssg_graph_run, ssgraph.h): every live node of a loaded graph
 * in run order, each prepared once and run every frame (sinks in the last frame only),
 * images from a pool, each given back after its last reader, each node timed; the
 * statistics (timings, profile, metrics) handed to the caller after the last frame. It
 * prints nothing: the files it writes are told through the run's log callback. */
#include <limits.h>
#include <omp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graph/behind.h"
#include "graph/gl_backend.h"
#include "graph/graph.h"
#include "graph/graph_history.h"
#include "graph/graph_skip.h"
#include "graph/image.h"
#include "graph/metrics.h"
#include "graph/profile.h"
#include "scene/camera_path.h"

/* Frames whose files may wait to be written while the next frame runs: one written, one
   waiting (two copies of a frame's layers), so a slow disk holds the frames back rather
   than fill the memory. */
enum { BEHIND_DEPTH = 2 };

struct run {
    struct ssg_graph *g;
    struct ssg_pool *pool;
    const struct ssg_run_options *opt;
    struct ssg_diags *diags;
    struct ssg_node_timing *t; /* per run position, of the last frame */
    struct ssg_live *state;    /* per run position: consts, scratch, prepared, kept, why:
                                  the graph's (live) or `own` (graph.h) */
    struct ssg_live own;       /* a run that is not kept: its state for its frames */
    unsigned char *hold;       /* per node index: 1 = its outputs stand through the run's
                                  frames (no frame can change them), so they are kept */
    int (*why)[SSG_WHY_COUNT]; /* per run position: how often each reason held */
    int *producer;             /* per run position: the producer named by SSG_WHY_INPUT */
    struct ssg_profile prof;   /* per run position */
    struct ssg_metrics metrics;
    int uses_gl;               /* a node runs on GL: the backend is open */
    struct ssg_live *live;     /* the graph's kept state (graph.h), NULL = a fresh run */
    unsigned char *ran;        /* per node index: ran in this frame */
    int first_frame;           /* the frame index of the run's frame 0 (graph_time.c) */
    int frames;                /* frames in this run */
    struct ssg_time_step step; /* the frame being run: time, prev_camera, history_reset */
    struct ssg_skip *skip;     /* what a frame may skip (graph_skip.h); NULL in a live
                                  graph, whose every output may be looked at after a run */
    struct ssg_behind *behind; /* a sequence's files, written behind its frames (behind.h);
                                  NULL = in the frame (one frame, or none could be made) */
    int behind_tried;
    struct { int p, frame; } unlogged[BEHIND_DEPTH + 1]; /* jobs handed over, not yet told */
    long logged;               /* jobs told as written ("wrote PATH") */
};

static void release_output(struct run *r, struct gnode *n, int port)
{
    if (n->out_img[port]) {
        ssg_pool_release(r->pool, n->out_img[port]);
        n->out_img[port] = NULL;
    }
}

/* Takes output images for the outputs in `want` (bit k = output k) from the pool, giving
   back the frame before's. */
static enum ssg_err allocate_outputs(struct run *r, struct gnode *n, unsigned want)
{
    for (int k = 0; k < n->desc->output_count; k++) {
        const struct ssg_shape *s = &n->out_shape[k];
        /* a requested output (ssg_overrides.outputs) is kept to the end of the run, so the
           last frame's can be handed out: the frame before's goes back to the pool here */
        if (!ssg_history_keep(r->g, r->pool, n, k)) /* read through prev(): kept */
            release_output(r, n, k);
        if ((n->desc->outputs[k].on_demand && n->last_reader[k] < 0) || !(want >> k & 1u))
            continue; /* nothing reads it: the node skips its work (node.h) */
        n->out_img[k] = ssg_pool_acquire(r->pool, s->width, s->height, s->channels);
        if (!n->out_img[k]) {
            ssg_diag_at(r->diags, SSG_E_NOMEM, n->loc, "out of memory for output '%s' of "
                        "node '%s' (%dx%dx%d)", n->desc->outputs[k].name, n->name, s->width,
                        s->height, s->channels);
            return SSG_E_NOMEM;
        }
    }
    return SSG_OK;
}

/* Gives back every image whose last reader ran at position p, and unread outputs of the
 * node at p itself. An image's last reader is one of the nodes reading it, so looking at
 * p's own inputs is enough: constant work per position, linear in the graph. */
static void release_after(struct run *r, int p)
{
    if (r->live)
        return; /* a live graph keeps every output for the next run (graph.h) */
    struct ssg_graph *g = r->g;
    struct gnode *n = &g->nodes[g->order[p]];
    for (int k = 0; k < n->desc->output_count; k++)
        if (n->last_reader[k] < 0)
            release_output(r, n, k);
    for (int k = 0; k < ssg_gnode_conn_count(n); k++) {
        const struct gconn *c = ssg_gnode_conn(n, k);
        if (c->node >= 0 && g->nodes[c->node].last_reader[c->port] == p && !r->hold[c->node])
            release_output(r, &g->nodes[c->node], c->port);
    }
}

static const char *out_dir(const struct run *r)
{
    return r->opt->out_dir ? r->opt->out_dir : "out";
}

/* One line to the run's log callback, if it has one. */
static void say(const struct run *r, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));
static void say(const struct run *r, const char *fmt, ...)
{
    if (!r->opt->log)
        return;
    char line[1400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    r->opt->log(r->opt->user, line);
}

/* The files a sink that just ran in `frame` has written, as its descriptor names them. */
static void log_files(const struct run *r, const struct gnode *n, int frame)
{
    char files[4][SSG_FILE_NAME_MAX];
    int count = n->desc->output_files ? n->desc->output_files(n->params, frame, files, 4) : 0;
    for (int i = 0; i < count; i++)
        say(r, "wrote %s/%s", out_dir(r), files[i]);
}

/* The queue a sink that writes files in every frame of a sequence may hand them to, made
   when the first such sink runs; NULL for any other node, in a one-frame run, or when
   the queue cannot be made (the files are then written in the frame, as before). */
static struct ssg_behind *behind_for(struct run *r, const struct gnode *n)
{
    const struct ssg_node_desc *d = n->desc;
    if (!d->output_files || !d->every_frame || !d->every_frame(n->params) || r->frames < 2)
        return NULL;
    if (!r->behind_tried) {
        r->behind_tried = 1;
        r->behind = ssg_behind_create(BEHIND_DEPTH, omp_get_max_threads());
    }
    return r->behind;
}

/* Tells the files of the jobs written since the last call, in the order handed over. */
static void log_written(struct run *r)
{
    long done = r->behind ? ssg_behind_done(r->behind) : 0;
    for (; r->logged < done; r->logged++) {
        int at = (int)(r->logged % (BEHIND_DEPTH + 1));
        log_files(r, &r->g->nodes[r->g->order[r->unlogged[at].p]], r->unlogged[at].frame);
    }
}

/* A job node p handed over for frame `frame`: told once written. */
static void remember_job(struct run *r, int p, int frame)
{
    long index = ssg_behind_submitted(r->behind) - 1;
    int at = (int)(index % (BEHIND_DEPTH + 1));
    r->unlogged[at].p = p, r->unlogged[at].frame = frame;
    log_written(r);
}

/* The profile row's bytes and flops of the node at p (exec.h, ssg_node_cost). */
static void set_cost(struct run *r, int p, const struct ssg_node_ctx *ctx)
{
    const struct gnode *n = &r->g->nodes[r->g->order[p]];
    struct ssg_node_cost cost;
    ssg_node_cost_of(n->desc, ctx, r->state->consts[p] ? r->state->consts[p] : n->params,
                     n->extra_count,
                     &cost);
    for (int k = 0; k < n->desc->output_count; k++) /* unread on_demand: unwritten */
        if (!n->out_img[k])
            cost.bytes -= (double)n->out_shape[k].width * n->out_shape[k].height *
                          n->out_shape[k].channels * sizeof(float);
    r->prof.rows[p].bytes = cost.bytes;
    r->prof.rows[p].flops = cost.flops;
}

/* Runs the node at position p; in the first frame it prepares it first (the timing of a
   one-frame run includes prepare, as ssg_node_execute's). A sink first runs in the last
   frame and is prepared there. */
static enum ssg_err run_node(struct run *r, int p, int frame)
{
    struct ssg_graph *g = r->g;
    struct gnode *n = &g->nodes[g->order[p]];
    const struct ssg_image *in[SSG_MAX_PORTS] = {0}, *extra[SSG_MAX_EXTRA] = {0};
    unsigned long long made[SSG_MAX_PORTS] = {0};
    for (int k = 0; k < n->desc->input_count; k++)
        if (n->in[k].node >= 0) {
            in[k] = g->nodes[n->in[k].node].out_img[n->in[k].port];
            made[k] = ssg_redo_made(g, r->state, &n->in[k]);
        }
    struct ssg_shape extra_shape[SSG_MAX_EXTRA];
    for (int k = 0; k < n->extra_count; k++) {
        const struct gnode *src = &g->nodes[n->extra[k].node];
        extra[k] = src->out_img[n->extra[k].port];
        extra_shape[k] = src->out_shape[n->extra[k].port];
    }
    int history_reset; /* prev() inputs: the frame before's images (graph_history.h) */
    enum ssg_err e = ssg_history_bind(g, r->pool, n, in, extra, &history_reset);
    if (!e)
        e = allocate_outputs(r, n, ~0u);
    if (e)
        return e;
    struct ssg_io io = {.in = in, .out = n->out_img, .extra_count = n->extra_count,
                        .extra_names = n->extra_names, .extra_in = extra,
                        .extra_types = n->extra_types};
    struct ssg_node_ctx ctx = {.desc = n->desc, .instance = n->name, .frame = &g->frame,
                               .scene = g->scene, .out_dir = out_dir(r), .diags = r->diags,
                               .metrics = &r->metrics, .in_shape = n->in_shape,
                               .out_shape = n->out_shape, .extra_shape = extra_shape,
                               .run = r->opt, .scratch = &r->state->scratch[p],
                               .graph_path = g->path, .sets = (const char *const *)g->sets,
                               .set_count = g->set_count, .supplied = n->supplied,
                               .frame_index = r->first_frame + frame,
                               .time_s = r->step.time_s,
                               .prev_camera = g->scene ? &r->step.prev : NULL,
                               .history_reset = r->step.reset,
                               .gl_shared = &r->state->gl, .in_made = made};
    if (history_reset >= 0) /* reads prev(): its history may be gone for its own reasons */
        ctx.history_reset = history_reset || r->step.reset;
    double prepare_ms = 0;
    if (!r->state->prepared[p]) {
        double t0 = ssg_now_ms();
        e = ssg_node_prepare(n->desc, &ctx, n->params, &r->state->consts[p]);
        prepare_ms = r->prof.rows[p].prepare_ms = ssg_now_ms() - t0;
        r->state->prepared[p] = 1;
    }
    if (!e) /* every run: a kept graph's node may run on constants of an earlier one */
        set_cost(r, p, &ctx);
    ctx.behind = behind_for(r, n);
    long submitted = r->behind ? ssg_behind_submitted(r->behind) : 0;
    if (!e)
        e = ssg_node_run_prepared(n->desc, &ctx, n->params, r->state->consts[p], &io,
                                  n->runs_on,
                                  &r->t[p]);
    if (!e && !ssg_profile_add(&r->prof, p, &r->t[p]))
        e = SSG_E_NOMEM;
    if (!e && r->behind && ssg_behind_submitted(r->behind) > submitted)
        remember_job(r, p, r->first_frame + frame);
    else if (!e)
        log_files(r, n, r->first_frame + frame);
    r->t[p].ms += prepare_ms;
    if (e && r->diags->count == 0)
        ssg_diag_at(r->diags, e, n->loc, "node '%s' (%s) failed: %s", n->name, n->desc->name,
                    ssg_err_text(e));
    return e;
}

/* A node whose outputs are all 0 or unused (graph_skip.h): the outputs in `fill` (read
   by what runs) are taken from the pool and set to +0, as its run would have made them;
   the others get no image. */
static enum ssg_err skip_node(struct run *r, int p, unsigned fill)
{
    struct gnode *n = &r->g->nodes[r->g->order[p]];
    double t0 = ssg_now_ms();
    enum ssg_err e = allocate_outputs(r, n, fill);
    for (int k = 0; !e && k < n->desc->output_count; k++) {
        struct ssg_image *im = n->out_img[k];
        if (!im)
            continue;
        memset(im->data, 0, sizeof(float) * (size_t)im->width * (size_t)im->height *
                                (size_t)im->channels);
        if (im->gpu)
            ssg_gl_mark_written(im, 0);
    }
    r->t[p] = (struct ssg_node_timing){.ms = ssg_now_ms() - t0};
    return e;
}

static int graph_uses_gl(const struct ssg_graph *g)
{
    for (int p = 0; p < g->order_count; p++)
        if (g->nodes[g->order[p]].runs_on == SSG_BACKEND_GL)
            return 1;
    return 0;
}

/* Which nodes' outputs stand through all of a run's frames (r->hold): in a sequence,
   those that read nothing a frame changes (the frame index; the camera, where a camera
   path moves it), read no prev(), and whose producers stand too. They run in the first
   frame only and keep their images to the end of the run; a one-frame run holds none.
   A `jitter` line moves every camera reader's pixels each frame, as a path does. */
static void mark_held(struct run *r, int frames)
{
    const struct ssg_graph *g = r->g;
    int path = g->scene && ssg_camera_path_active(&g->scene->camera_path);
    unsigned changing = SSG_READS_FRAME | (path || g->jitter > 1 ? SSG_READS_CAMERA : 0);
    for (int p = 0; p < g->order_count; p++) {
        const struct gnode *n = &g->nodes[g->order[p]];
        int hold = frames > 1 && !n->desc->is_sink && !ssg_history_reads_prev(n) &&
                   !(ssg_gnode_reads(g, n) & changing);
        for (int k = 0; hold && k < ssg_gnode_conn_count(n); k++)
            hold = ssg_gnode_conn(n, k)->node < 0 || r->hold[ssg_gnode_conn(n, k)->node];
        r->hold[g->order[p]] = (unsigned char)hold;
    }
}

/* The profile's rows and the per-position arrays of a run; 0 on out of memory. */
static int run_init(struct run *r, int frames)
{
    const struct ssg_graph *g = r->g;
    int count = g->order_count ? g->order_count : 1;
    r->t = calloc((size_t)count, sizeof *r->t);
    r->ran = calloc((size_t)(g->count ? g->count : 1), 1);
    r->hold = calloc((size_t)(g->count ? g->count : 1), 1);
    r->why = calloc((size_t)count, sizeof *r->why);
    r->producer = calloc((size_t)count, sizeof *r->producer);
    r->state = r->live ? r->live : &r->own;
    if ((!r->live && !ssg_live_init(&r->own, g->order_count)) || !r->t || !r->ran ||
        !r->hold || !r->why || !r->producer || !ssg_profile_init(&r->prof, g->order_count))
        return 0;
    if (!r->live && !(r->skip = ssg_skip_create(g)))
        return 0;
    r->pool = r->state->pool;
    mark_held(r, frames);
    for (int p = 0; p < g->order_count; p++) {
        const struct gnode *n = &g->nodes[g->order[p]];
        r->prof.rows[p] = (struct ssg_profile_row){.name = n->name, .type = n->desc->name,
                                                   .backend = ssg_backend_name(n->runs_on),
                                                   .min = r->prof.rows[p].min};
    }
    r->prof.width = g->width, r->prof.height = g->height;
    r->prof.threads = omp_get_max_threads();
    return ssg_history_begin(r->g, r->pool) == SSG_OK;
}

static void run_free(struct run *r)
{
    ssg_behind_destroy(&r->behind); /* its jobs were finished by ssg_graph_run */
    ssg_skip_free(&r->skip);
    free(r->t);
    free(r->ran);
    free(r->hold);
    free(r->why);
    free(r->producer);
    ssg_profile_free(&r->prof);
    if (!r->live) /* a live graph keeps its state (ssg_live_free); GL is still open */
        ssg_live_release(r->g, &r->own);
}

/* Node n runs in this frame: every node but a sink, which runs in the last frame only
   unless it asks for every frame (write sequence=true). */
static int runs_in(const struct gnode *n, int frame, int frames)
{
    const struct ssg_node_desc *desc = n->desc;
    return !desc->is_sink || frame == frames - 1 ||
           (desc->every_frame && desc->every_frame(n->params));
}

/* Before frame `frame` of the run: its time, camera and history state (graph_time.c),
   and what they change (graph_redo.c): a moved camera its readers, another frame index
   the frame's readers, and every prev() reader, whose input is a new frame. */
static void begin_frame(struct run *r, int frame, int frames)
{
    struct ssg_graph *g = r->g;
    int index = r->first_frame + frame;
    if (ssg_time_begin(g, index, frame == 0, frames, r->live != NULL, &r->step))
        ssg_redo_reading(g, r->state, SSG_READS_CAMERA, SSG_RECOMPUTE_PREPARE,
                         SSG_WHY_CAMERA);
    if (g->time.kept_frame != index)
        ssg_redo_reading(g, r->state, SSG_READS_FRAME, SSG_RECOMPUTE_RUN, SSG_WHY_FRAME);
    for (int p = 0; p < g->order_count; p++)
        if (ssg_history_reads_prev(&g->nodes[g->order[p]]))
            ssg_redo(g, r->state, p, SSG_RECOMPUTE_RUN, SSG_WHY_HISTORY);
    memset(r->ran, 0, (size_t)g->count);
}

/* A kept sink's metrics: those run position p added to the run's from index `from` on;
   0 on out of memory (the sink then runs every time, as before). */
static int remember_metrics(struct run *r, int p, int from)
{
    struct ssg_live *l = r->state;
    int n = r->metrics.count - from; /* never below 0: a node only adds */
    struct ssg_metric *copy = NULL;
    if (n > 0) {
        if (!(copy = malloc(sizeof *copy * (size_t)n)))
            return 0;
        memcpy(copy, r->metrics.items + from, sizeof *copy * (size_t)n);
    }
    free(l->reported[p]);
    l->reported[p] = copy;
    l->reported_count[p] = n;
    return 1;
}

/* A kept sink's metrics as this run's, in the place its run would have put them. */
static void report_again(struct run *r, int p)
{
    const struct ssg_live *l = r->state;
    for (int i = 0; i < l->reported_count[p]; i++)
        ssg_metrics_add(&r->metrics, l->reported[p][i].node, l->reported[p][i].name,
                        l->reported[p][i].value);
}

/* One frame: every node in order, images given back after their last reader. Sinks
   (write, compare) run in the last frame only: a real-time frame shows its image rather
   than writing files, and the frame time is that of the passes. */
static enum ssg_err run_frame(struct run *r, int frame, int frames)
{
    enum ssg_err e = SSG_OK;
    double sum = 0;
    ssg_history_frame(r->g, r->pool);
    for (int p = 0; p < r->g->order_count && !e; p++) {
        const struct gnode *n = &r->g->nodes[r->g->order[p]];
        int sink = n->desc->is_sink, fresh = !r->state->prepared[p], producer;
        if (r->opt->no_files && n->desc->output_files) {
            r->why[p][SSG_WHY_NO_FILES] += frame == frames - 1; /* told once, as a sink */
            continue;
        }
        enum ssg_why why = ssg_redo_decide(r->g, r->state, p, r->ran, &producer);
        unsigned fill;
        if (why != SSG_WHY_KEPT && runs_in(n, frame, frames) && r->skip &&
            ssg_skip_decide(r->skip, r->g, p, &fill)) {
            e = skip_node(r, p, fill);
            /* kept as a run's outputs are: what it skips for (zero lights, an unused
               output) cannot change while its outputs stand, and a live graph skips
               nothing */
            ssg_redo_after(r->state, p, !n->desc->is_sink && r->hold[r->g->order[p]], e);
            r->ran[r->g->order[p]] = 1;
            why = SSG_WHY_SKIPPED;
        } else if (why != SSG_WHY_KEPT && runs_in(n, frame, frames)) {
            int reported = r->metrics.count;
            e = run_node(r, p, frame);
            /* a metrics-only sink of a live graph's one-frame run is kept like any node
               (graph_redo.c), with what it reported */
            int keep_sink = sink && !n->desc->output_files && r->live && frames == 1 &&
                            !e && remember_metrics(r, p, reported);
            ssg_redo_after(r->state, p,
                           keep_sink || (!sink && (r->live || r->hold[r->g->order[p]])), e);
            r->ran[r->g->order[p]] = 1;
        } else if (why == SSG_WHY_KEPT && sink) {
            report_again(r, p);
        }
        if (why == SSG_WHY_KEPT || runs_in(n, frame, frames))
            r->why[p][why]++;
        if (producer >= 0)
            r->producer[p] = producer;
        release_after(r, p);
        if (why == SSG_WHY_KEPT)
            continue;
        if (!sink) /* the frame time leaves out a prepare made in this frame */
            sum += r->t[p].ms - (fresh ? r->prof.rows[p].prepare_ms : 0) +
                   r->t[p].transfer_ms;
    }
    if (!e && !ssg_profile_frame(&r->prof, sum))
        e = SSG_E_NOMEM;
    return e;
}

/* Copies the metrics and the GL context into the stats; 0 on out of memory. */
static int fill_reports(const struct run *r, struct ssg_run_stats *s)
{
    s->metrics = calloc((size_t)(r->metrics.count ? r->metrics.count : 1), sizeof *s->metrics);
    if (!s->metrics)
        return 0;
    for (int i = 0; i < r->metrics.count; i++, s->metric_count++) {
        struct ssg_run_metric *m = &s->metrics[i];
        snprintf(m->node, sizeof m->node, "%s", r->metrics.items[i].node);
        snprintf(m->name, sizeof m->name, "%s", r->metrics.items[i].name);
        m->value = r->metrics.items[i].value;
    }
    if (r->uses_gl && !(s->gl = strdup(ssg_gl_describe())))
        return 0;
    return 1;
}

/* Why each node ran or was kept, over the run's frames; 0 on out of memory. */
static int fill_why(const struct run *r, struct ssg_run_stats *s)
{
    for (int p = 0; p < s->node_count; p++) {
        char line[256];
        int from = r->producer[p];
        ssg_why_summary(r->why[p], from >= 0 ? r->g->nodes[from].name : NULL, line,
                        sizeof line);
        s->nodes[p].kept = r->why[p][SSG_WHY_KEPT];
        if (!(s->nodes[p].why = strdup(line)))
            return 0;
    }
    return 1;
}

/* What the frames measured, into the caller's stats (the pool still open: its peak). */
static enum ssg_err fill_stats(const struct run *r, double total, struct ssg_run_stats *s)
{
    *s = (struct ssg_run_stats){0};
    if (!ssg_profile_stats(&r->prof, r->t, s) || !fill_why(r, s) || !fill_reports(r, s)) {
        ssg_run_stats_free(s);
        return SSG_E_NOMEM;
    }
    s->total_ms = total;
    s->peak_pool_bytes = ssg_pool_peak_bytes(r->pool);
    return SSG_OK;
}

/* After the last frame: the statistics, then metrics.json. */
static enum ssg_err report(struct run *r, double total)
{
    enum ssg_err e = r->opt->stats ? fill_stats(r, total, r->opt->stats) : SSG_OK;
    if (!e && r->metrics.count) {
        char path[1100];
        snprintf(path, sizeof path, "%s/metrics.json", out_dir(r));
        e = ssg_make_dirs(out_dir(r), r->diags);
        if (!e)
            e = ssg_metrics_write_json(&r->metrics, path, r->diags);
        if (!e)
            say(r, "wrote %s", path);
    }
    return e;
}

/* Copies of the requested outputs (ssg_overrides.outputs) for the caller, downloaded
   first where GL made them; on failure none. */
static enum ssg_err hand_out(struct run *r)
{
    struct ssg_image **out = r->opt->outputs;
    const struct ssg_graph *g = r->g;
    enum ssg_err e = SSG_OK;
    for (int k = 0; out && k < g->wanted_count && !e; k++) {
        const struct ssg_image *im = g->nodes[g->wanted[k].node].out_img[g->wanted[k].port];
        double ms = 0;
        if (im->gpu)
            e = ssg_gl_to_cpu(im, &ms, r->diags);
        if (!e && !(out[k] = ssg_image_create(im->width, im->height, im->channels)))
            e = SSG_E_NOMEM;
        if (!e)
            memcpy(out[k]->data, im->data,
                   (size_t)im->width * (size_t)im->height * (size_t)im->channels *
                       sizeof *im->data);
    }
    for (int k = 0; e && k < g->wanted_count; k++)
        ssg_image_destroy(&out[k]);
    return e;
}

enum ssg_err ssg_graph_run(struct ssg_graph *g, const struct ssg_run_options *options,
                           struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_graph_run", "graph", 1, g))
        return SSG_E_USAGE;
    for (int k = 0; options && options->outputs && k < g->wanted_count; k++)
        options->outputs[k] = NULL;
    struct ssg_run_options defaults = {0};
    if (options && options->stats)
        *options->stats = (struct ssg_run_stats){0};
    int frames = options && options->frames > 1 ? options->frames : 1;
    if (frames - 1 > INT_MAX - g->time.next) { /* frame indices are ints (node.h) */
        ssg_diag_file(diags, SSG_E_VALUE, g->path, "%d frames from frame %d run past frame "
                      "%d, the last a sequence may have", frames, g->time.next, INT_MAX);
        return SSG_E_VALUE;
    }
    struct run r = {.g = g, .opt = options ? options : &defaults, .diags = diags,
                    .uses_gl = graph_uses_gl(g), .live = g->live, .frames = frames};
    if (r.opt->threads > 0)
        omp_set_num_threads(r.opt->threads);
    if (!run_init(&r, frames)) {
        run_free(&r);
        return SSG_E_NOMEM;
    }
    if (r.uses_gl && ssg_gl_open(diags)) {
        run_free(&r);
        return SSG_E_BACKEND;
    }
    enum ssg_err e = SSG_OK;
    double t0 = ssg_now_ms();
    r.first_frame = g->time.next;
    for (int f = 0; f < frames && !e; f++) {
        begin_frame(&r, f, frames);
        e = run_frame(&r, f, frames);
        if (!e)
            ssg_time_end(g, r.first_frame + f);
    }
    if (r.behind) { /* the files still being written belong to this run */
        enum ssg_err written = ssg_behind_finish(r.behind, diags);
        e = e ? e : written;
        log_written(&r);
    }
    if (!e)
        e = report(&r, ssg_now_ms() - t0);
    if (!e)
        e = hand_out(&r);
    if (r.live)
        ssg_live_after_run(g, r.uses_gl);
    run_free(&r);
    if (r.uses_gl)
        ssg_gl_close();
    return e;
}
