/* graph_run.c - the executor (ssg_graph_run, ssgraph.h): every live node of a loaded graph
 * in run order, each prepared once and run every frame (sinks in the last frame only),
 * images from a pool, each given back after its last reader, each node timed; metrics and
 * the profile reported after the last frame. */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gl/gl_backend.h"
#include "graph/graph.h"
#include "graph/image.h"
#include "graph/metrics.h"
#include "graph/profile.h"

struct run {
    struct ssg_graph *g;
    struct ssg_pool *pool;
    const struct ssg_run_options *opt;
    struct ssg_diags *diags;
    struct ssg_node_timing *t; /* per run position, of the last frame */
    void **consts;             /* per run position: what its prepare() made, once */
    unsigned char *prepared;   /* per run position: 1 once prepare() ran (a sink runs in
                                  the last frame only, so not always in frame 0) */
    struct ssg_profile prof;   /* per run position */
    struct ssg_metrics metrics;
    int uses_gl;               /* a node runs on GL: the backend is open */
};

static enum ssg_err allocate_outputs(struct run *r, struct gnode *n)
{
    for (int k = 0; k < n->desc->output_count; k++) {
        const struct ssg_shape *s = &n->out_shape[k];
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

static void release_output(struct run *r, struct gnode *n, int port)
{
    if (n->out_img[port]) {
        ssg_pool_release(r->pool, n->out_img[port]);
        n->out_img[port] = NULL;
    }
}

/* Gives back every image whose last reader ran at position p, and unread outputs of the
 * node at p itself. An image's last reader is one of the nodes reading it, so looking at
 * p's own inputs is enough: constant work per position, linear in the graph. */
static void release_after(struct run *r, int p)
{
    struct ssg_graph *g = r->g;
    struct gnode *n = &g->nodes[g->order[p]];
    for (int k = 0; k < n->desc->output_count; k++)
        if (n->last_reader[k] < 0)
            release_output(r, n, k);
    for (int k = 0; k < SSG_MAX_PORTS + n->extra_count; k++) {
        const struct gconn *c = k < SSG_MAX_PORTS ? &n->in[k] : &n->extra[k - SSG_MAX_PORTS];
        if (c->node >= 0 && g->nodes[c->node].last_reader[c->port] == p)
            release_output(r, &g->nodes[c->node], c->port);
    }
}

static void release_all(struct run *r)
{
    for (int q = 0; q < r->g->order_count; q++) {
        struct gnode *n = &r->g->nodes[r->g->order[q]];
        for (int k = 0; k < SSG_MAX_PORTS; k++) {
            ssg_pool_release(r->pool, n->out_img[k]);
            n->out_img[k] = NULL;
        }
    }
}

static const char *out_dir(const struct run *r)
{
    return r->opt->out_dir ? r->opt->out_dir : "out";
}

/* Runs the node at position p; in the first frame it prepares it first (the timing of a
   one-frame run includes prepare, as ssg_node_execute's). A sink first runs in the last
   frame and is prepared there. */
static enum ssg_err run_node(struct run *r, int p, int frame)
{
    struct ssg_graph *g = r->g;
    struct gnode *n = &g->nodes[g->order[p]];
    const struct ssg_image *in[SSG_MAX_PORTS] = {0}, *extra[SSG_MAX_EXTRA] = {0};
    for (int k = 0; k < n->desc->input_count; k++)
        if (n->in[k].node >= 0)
            in[k] = g->nodes[n->in[k].node].out_img[n->in[k].port];
    struct ssg_shape extra_shape[SSG_MAX_EXTRA];
    for (int k = 0; k < n->extra_count; k++) {
        const struct gnode *src = &g->nodes[n->extra[k].node];
        extra[k] = src->out_img[n->extra[k].port];
        extra_shape[k] = src->out_shape[n->extra[k].port];
    }
    enum ssg_err e = allocate_outputs(r, n);
    if (e)
        return e;
    struct ssg_io io = {.in = in, .out = n->out_img, .extra_count = n->extra_count,
                        .extra_names = n->extra_names, .extra_in = extra,
                        .extra_types = n->extra_types};
    struct ssg_node_ctx ctx = {.desc = n->desc, .instance = n->name, .frame = &g->frame,
                               .scene = g->scene, .out_dir = out_dir(r), .diags = r->diags,
                               .metrics = &r->metrics, .in_shape = n->in_shape,
                               .out_shape = n->out_shape, .extra_shape = extra_shape};
    double prepare_ms = 0;
    if (!r->prepared[p]) {
        double t0 = ssg_now_ms();
        e = ssg_node_prepare(n->desc, &ctx, n->params, &r->consts[p]);
        prepare_ms = r->prof.rows[p].prepare_ms = ssg_now_ms() - t0;
        r->prepared[p] = 1;
    }
    if (!e)
        e = ssg_node_run_prepared(n->desc, &ctx, n->params, r->consts[p], &io, n->runs_on,
                                  &r->t[p]);
    if (!e)
        ssg_profile_add(&r->prof, p, &r->t[p]);
    r->t[p].ms += prepare_ms;
    if (e && r->diags->count == 0)
        ssg_diag_at(r->diags, e, n->loc, "node '%s' (%s) failed: %s", n->name, n->desc->name,
                    ssg_err_text(e));
    return e;
}

static void print_timings(const struct run *r, double total)
{
    FILE *log = r->opt->log ? r->opt->log : stdout;
    const struct ssg_graph *g = r->g;
    fprintf(log, "%-16s %-12s %-4s %10s %10s %10s\n", "node", "type", "on", "ms", "gpu ms",
            "xfer ms");
    for (int p = 0; p < g->order_count; p++) {
        const struct gnode *n = &g->nodes[g->order[p]];
        const struct ssg_node_timing *t = &r->t[p];
        char gpu[32] = "-", xfer[32] = "-";
        if (n->runs_on == SSG_BACKEND_GL)
            snprintf(gpu, sizeof gpu, "%.2f", t->gpu_ms);
        if (t->transfer_ms > 0)
            snprintf(xfer, sizeof xfer, "%.2f", t->transfer_ms);
        fprintf(log, "%-16s %-12s %-4s %10.2f %10s %10s\n", n->name, n->desc->name,
                ssg_backend_name(n->runs_on), t->ms, gpu, xfer);
    }
    fprintf(log, "%-16s %-12s %-4s %10.2f %10s %10s   (%dx%d, %d threads, peak images %.1f MB)\n",
            "total", "", "", total, "", "", g->width, g->height, omp_get_max_threads(),
            (double)ssg_pool_peak_bytes(r->pool) / (1024.0 * 1024.0));
    if (r->uses_gl)
        fprintf(log, "GL: %s\n", ssg_gl_describe());
}

static int graph_uses_gl(const struct ssg_graph *g)
{
    for (int p = 0; p < g->order_count; p++)
        if (g->nodes[g->order[p]].runs_on == SSG_BACKEND_GL)
            return 1;
    return 0;
}

/* The profile's rows and the per-position arrays of a run; 0 on out of memory. */
static int run_init(struct run *r)
{
    const struct ssg_graph *g = r->g;
    int count = g->order_count ? g->order_count : 1;
    r->pool = ssg_pool_create();
    r->t = calloc((size_t)count, sizeof *r->t);
    r->consts = calloc((size_t)count, sizeof *r->consts);
    r->prepared = calloc((size_t)count, 1);
    if (!r->pool || !r->t || !r->consts || !r->prepared || !ssg_profile_init(&r->prof, g->order_count))
        return 0;
    for (int p = 0; p < g->order_count; p++) {
        const struct gnode *n = &g->nodes[g->order[p]];
        r->prof.rows[p] = (struct ssg_profile_row){n->name, n->desc->name,
                                                   ssg_backend_name(n->runs_on), 0,
                                                   0, r->prof.rows[p].min, 0, 0, 0, 0};
    }
    r->prof.width = g->width, r->prof.height = g->height;
    r->prof.threads = omp_get_max_threads();
    return 1;
}

static void run_free(struct run *r)
{
    release_all(r);
    ssg_pool_destroy(&r->pool); /* deletes the textures too: GL is still open */
    for (int p = 0; r->consts && p < r->g->order_count; p++)
        free(r->consts[p]);
    free(r->consts);
    free(r->prepared);
    free(r->t);
    ssg_profile_free(&r->prof);
}

/* One frame: every node in order, images given back after their last reader. Sinks
   (write, compare) run in the last frame only: a real-time frame shows its image rather
   than writing files, and the frame time is that of the passes. */
static enum ssg_err run_frame(struct run *r, int frame, int frames)
{
    enum ssg_err e = SSG_OK;
    double sum = 0;
    for (int p = 0; p < r->g->order_count && !e; p++) {
        int sink = r->g->nodes[r->g->order[p]].desc->is_sink;
        if (!sink || frame == frames - 1)
            e = run_node(r, p, frame);
        release_after(r, p);
        if (!sink)
            sum += r->t[p].ms - (frame == 0 ? r->prof.rows[p].prepare_ms : 0) +
                   r->t[p].transfer_ms;
    }
    if (!e)
        ssg_profile_frame(&r->prof, sum);
    return e;
}

static void fill_stats(const struct run *r, struct ssg_run_stats *s)
{
    const struct ssg_profile *p = &r->prof;
    memset(s, 0, sizeof *s);
    s->frames = p->frames;
    s->frame_avg_ms = p->frames ? p->frame_sum / p->frames : 0;
    s->frame_min_ms = p->frames ? p->frame_min : 0;
    s->frame_max_ms = p->frame_max;
    for (int i = 0; i < p->rows_count && i < SSG_RUN_NODES_MAX; i++) {
        struct ssg_run_node_time *n = &s->nodes[s->node_count++];
        snprintf(n->name, sizeof n->name, "%s", p->rows[i].name);
        n->avg_ms = p->rows[i].calls ? p->rows[i].sum / p->rows[i].calls : 0;
    }
    for (int i = 0; i < r->metrics.count && i < SSG_RUN_METRICS_MAX; i++) {
        struct ssg_run_metric *m = &s->metrics[s->metric_count++];
        snprintf(m->node, sizeof m->node, "%s", r->metrics.items[i].node);
        snprintf(m->name, sizeof m->name, "%s", r->metrics.items[i].name);
        m->value = r->metrics.items[i].value;
    }
}

/* Timings or the profile, metrics, and the files they go to. */
static enum ssg_err report(struct run *r, int frames, double total)
{
    FILE *log = r->opt->log ? r->opt->log : stdout;
    enum ssg_err e = SSG_OK;
    if (!r->opt->quiet) {
        if (frames > 1)
            ssg_profile_print(&r->prof, log);
        else
            print_timings(r, total);
        if (frames > 1 && r->uses_gl)
            fprintf(log, "GL: %s\n", ssg_gl_describe());
        ssg_metrics_print(&r->metrics, log);
    }
    if (r->metrics.count) {
        char path[1100];
        snprintf(path, sizeof path, "%s/metrics.json", out_dir(r));
        e = ssg_make_dirs(out_dir(r), r->diags);
        if (!e)
            e = ssg_metrics_write_json(&r->metrics, path, r->diags);
    }
    if (!e && r->opt->profile_json)
        e = ssg_profile_write_json(&r->prof, r->opt->profile_json, r->diags);
    if (!e && r->opt->stats)
        fill_stats(r, r->opt->stats);
    return e;
}

enum ssg_err ssg_graph_run(struct ssg_graph *g, const struct ssg_run_options *options,
                           struct ssg_diags *diags)
{
    struct ssg_run_options defaults = {0};
    struct run r = {.g = g, .opt = options ? options : &defaults, .diags = diags,
                    .uses_gl = graph_uses_gl(g)};
    if (r.opt->threads > 0)
        omp_set_num_threads(r.opt->threads);
    if (!run_init(&r)) {
        run_free(&r);
        return SSG_E_NOMEM;
    }
    if (r.uses_gl && ssg_gl_open(diags)) {
        run_free(&r);
        return SSG_E_BACKEND;
    }
    int frames = r.opt->frames > 1 ? r.opt->frames : 1;
    enum ssg_err e = SSG_OK;
    double t0 = ssg_now_ms();
    for (int f = 0; f < frames && !e; f++)
        e = run_frame(&r, f, frames);
    if (!e)
        e = report(&r, frames, ssg_now_ms() - t0);
    run_free(&r);
    if (r.uses_gl)
        ssg_gl_close();
    return e;
}
