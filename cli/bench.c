/* bench.c - `ssgraph bench FILE --sweep node.param=v1,v2,... [--sweep ...]`: the graph is
 * loaded once (a live graph, once per scene) and run for every combination of the
 * sweeps' values set on it (the cross product, first sweep outermost), each cell over `frames` frames with every node prepared once; its
 * frame time (median, min, max, average) and the metrics its compare nodes report go to
 * <out>/bench.csv (rewritten whole after every cell, so an interrupted bench keeps the
 * cells it finished), <out>/bench.json and <out>/bench.md (rewritten whole after every
 * cell; the table is shaped like the documents': rows the first sweep, columns the
 * second, one table per value of the others). A cell that fails is reported and recorded
 * with its message; the others still run. Progress: a bar on a terminal, lines
 * otherwise. This file parses, checks and runs the cells; bench_out.c writes them. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench_cells.h"
#include "report.h"
#include "ssgraph.h"

/* "node.param=v1,v2" into a sweep; 0 with a message when malformed. */
static int parse_sweep(const char *spec, struct sweep *s)
{
    const char *eq = strchr(spec, '=');
    size_t klen = eq ? (size_t)(eq - spec) : 0;
    if (!eq || klen == 0 || klen >= sizeof s->key || !memchr(spec, '.', klen) ||
        strlen(eq + 1) >= sizeof s->text) {
        fprintf(stderr, "ssgraph: error: --sweep expects node.param=v1,v2,..., got '%s'\n",
                spec);
        return 0;
    }
    memcpy(s->key, spec, klen);
    s->key[klen] = 0;
    snprintf(s->text, sizeof s->text, "%s", eq + 1);
    s->count = 0;
    for (char *tok = strtok(s->text, ","); tok; tok = strtok(NULL, ",")) {
        if (s->count == MAX_VALUES || !*tok) {
            fprintf(stderr, "ssgraph: error: --sweep '%s': 1 to %d non-empty values\n", spec,
                    MAX_VALUES);
            return 0;
        }
        s->values[s->count++] = tok;
    }
    if (s->count == 0)
        fprintf(stderr, "ssgraph: error: --sweep '%s' has no values\n", spec);
    return s->count > 0;
}

/* Two or more --scene: the scenes are the outermost sweep, "scene" (one more dimension of
   the cross product: every other value runs on every scene). 0 with a message when that
   makes too many sweeps or values. */
static int scene_sweep(struct bench *b)
{
    const struct ssg_bench_request *q = b->req;
    if (q->scene_count < 2)
        return 1;
    if (q->sweep_count + 1 > SSG_BENCH_MAX_SWEEPS || q->scene_count > MAX_VALUES) {
        fprintf(stderr, "ssgraph: error: several --scene make one more sweep: at most %d "
                "--sweep then, and %d scenes\n", SSG_BENCH_MAX_SWEEPS - 1, MAX_VALUES);
        return 0;
    }
    b->scene_axis = 1;
    b->n = q->sweep_count + 1;
    snprintf(b->sweeps[0].key, sizeof b->sweeps[0].key, "scene");
    b->sweeps[0].count = q->scene_count;
    for (int v = 0; v < q->scene_count; v++)
        b->sweeps[0].values[v] = q->scenes[v];
    return 1;
}

/* The number of cells of the cross product; 0 with a message past MAX_CELLS. */
static int count_cells(const struct bench *b)
{
    long long cells = 1;
    for (int k = 0; k < b->n; k++)
        cells *= b->sweeps[k].count;
    if (cells <= MAX_CELLS)
        return (int)cells;
    fprintf(stderr, "ssgraph: error: the sweeps make %lld cells; at most %d in one bench "
            "(expected fewer values, or several benches)\n", cells, MAX_CELLS);
    return 0;
}

/* The cells of the cross product, first sweep outermost. */
int ssg_bench_make_cells(struct bench *b)
{
    b->cells = calloc((size_t)b->cell_count, sizeof *b->cells);
    if (!b->cells) {
        fprintf(stderr, "ssgraph: error: out of memory for %d bench cells\n", b->cell_count);
        return 0;
    }
    for (int c = 0; c < b->cell_count; c++) {
        int rest = c;
        for (int k = b->n - 1; k >= 0; k--) {
            b->cells[c].index[k] = rest % b->sweeps[k].count;
            rest /= b->sweeps[k].count;
        }
    }
    return 1;
}

/* The cells and the statistics each holds. */
void ssg_bench_free_cells(struct bench *b)
{
    for (int c = 0; b->cells && c < b->cell_count; c++)
        ssg_run_stats_free(&b->cells[c].stats);
    free(b->cells);
    b->cells = NULL;
}

/* A cell's run options: request q, output folder dir, its stats. */
#define RUN_OPTIONS(q, dir, st)                                                             \
    {.out_dir = (dir), .threads = (q)->threads, .frames = (q)->frames > 0 ? (q)->frames : 5, \
     .stats = (st), .progress = isatty(fileno(stderr)) ? ssg_report_progress : NULL}

static enum ssg_err run_graph_once(const char *graph, const struct ssg_overrides *ov,
                                   const struct ssg_bench_request *q, const char *dir,
                                   struct ssg_run_stats *stats, struct ssg_diags *d)
{
    struct ssg_run_options ro = RUN_OPTIONS(q, dir, stats);
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load(graph, ov, &g, d);
    if (!e)
        e = ssg_graph_run(g, &ro, d);
    ssg_graph_destroy(&g);
    return e;
}

/* A stereo cell's times are both eyes' (a stereo frame renders both): each statistic the
   sum of the eyes' (the median of the sums is not at hand; the eyes' runs are alike); its
   metrics are the left eye's. */
static void add_eye(struct ssg_run_stats *both, const struct ssg_run_stats *right)
{
    both->frame_avg_ms += right->frame_avg_ms;
    both->frame_min_ms += right->frame_min_ms;
    both->frame_max_ms += right->frame_max_ms;
    both->frame_median_ms += right->frame_median_ms;
    for (int i = 0; i < both->node_count && i < right->node_count; i++) {
        both->nodes[i].avg_ms += right->nodes[i].avg_ms;
        both->nodes[i].median_ms += right->nodes[i].median_ms;
        both->nodes[i].min_ms += right->nodes[i].min_ms;
        both->nodes[i].max_ms += right->nodes[i].max_ms;
    }
}

/* The --set lines of a run: the user's, then key=value of each sweep k whose index[k] is
   not negative. */
struct cell_sets {
    const char *sets[256 + SSG_BENCH_MAX_SWEEPS];
    char own[SSG_BENCH_MAX_SWEEPS][1200];
};

static struct ssg_overrides cell_overrides(const struct bench *b, const int *index,
                                           struct cell_sets *cs)
{
    const struct ssg_bench_request *q = b->req;
    int n = 0;
    for (int i = 0; i < q->ov->set_count && n < 256; i++)
        cs->sets[n++] = q->ov->sets[i];
    struct ssg_overrides ov = *q->ov;
    for (int k = 0; k < b->n; k++) {
        if (index[k] < 0)
            continue;
        if (k == 0 && b->scene_axis) {
            ov.scene = b->sweeps[0].values[index[0]];
            continue;
        }
        snprintf(cs->own[k], sizeof cs->own[k], "%s=%s", b->sweeps[k].key,
                 b->sweeps[k].values[index[k]]);
        cs->sets[n++] = cs->own[k];
    }
    ov.sets = cs->sets;
    ov.set_count = n;
    return ov;
}

/* With only_alone: reports value v of sweep k and returns 1 if it fails with the other
   sweeps at the graph's own values, else 0; without: reports it with the first cell of it
   that fails. */
static int refuse_value(const struct bench *b, int k, int v, int only_alone)
{
    int index[SSG_BENCH_MAX_SWEEPS];
    for (int i = 0; i < SSG_BENCH_MAX_SWEEPS; i++)
        index[i] = i == k ? v : -1;
    for (int ci = 0; !only_alone && ci < b->cell_count; ci++) {
        if (b->cells[ci].index[k] == v) {
            memcpy(index, b->cells[ci].index, sizeof index);
            break;
        }
    }
    struct cell_sets cs;
    struct ssg_overrides ov = cell_overrides(b, index, &cs);
    struct ssg_diags d = {0};
    if (ssg_graph_check(b->graph, &ov, &d) == SSG_OK)
        return 0;
    if (k == 0 && b->scene_axis)
        fprintf(stderr, "ssgraph: error: --scene %s does not load with the graph %s:\n",
                b->sweeps[0].values[v], b->req->graph);
    else
        fprintf(stderr, "ssgraph: error: --sweep %s: value '%s' does not fit the graph %s in "
                "any cell:\n", b->sweeps[k].key, b->sweeps[k].values[v], b->req->graph);
    ssg_diags_print(&d, stderr);
    return 1;
}

/* Every cell is checked against the graph (its scene's text too, not its assets) before
   the first one runs, and a sweep value that fits in no cell is refused with the graph's
   complaint: a typo in a key, a value out of range. A value that only some combinations
   refuse (two parameters that must agree) still runs; those cells are recorded as failed. */
static int check_sweeps(const struct bench *b)
{
    unsigned char *fits = calloc((size_t)b->cell_count, 1);
    if (!fits) {
        fprintf(stderr, "ssgraph: error: out of memory checking %d cells\n", b->cell_count);
        return 0;
    }
    for (int ci = 0; ci < b->cell_count; ci++) {
        struct cell_sets cs;
        struct ssg_overrides ov = cell_overrides(b, b->cells[ci].index, &cs);
        struct ssg_diags d = {0};
        fits[ci] = ssg_graph_check(b->graph, &ov, &d) == SSG_OK;
    }
    /* Of the values that fit no cell, blame first one that fails even alone (the others
       at the graph's own values): with a misspelt key every cell fails, and the values of
       the other sweeps are not to blame. */
    int ok = 1;
    for (int pass = 0; pass < 2 && ok; pass++) {
        for (int k = 0; k < b->n && ok; k++) {
            for (int v = 0; v < b->sweeps[k].count && ok; v++) {
                int any = 0;
                for (int ci = 0; ci < b->cell_count && !any; ci++)
                    any = b->cells[ci].index[k] == v && fits[ci];
                if (!any)
                    ok = !refuse_value(b, k, v, pass == 0);
            }
        }
    }
    free(fits);
    return ok;
}

/* A live graph (ssg_graph_keep) that the cells share: loaded once per scene, then each
   cell's values set on it (ssg_graph_set: --set's parsing and checks, a fresh load's
   bytes, tests/test_live.c), so a cell no longer pays the scene, its BVH and the
   G-buffer's setup again. Only for runs of several frames (every node runs in each: the
   frame time is the whole graph's, as with a fresh load) without --stereo or
   --reference; anything the live graph cannot take (an input swept, a value refused, a
   load that fails with the graph's own values) runs that cell from a fresh load, as
   before, which then reports the error. */
struct live_cells {
    struct ssg_graph *g;
    int scene;                          /* the scene value it was loaded with */
    int applied[SSG_BENCH_MAX_SWEEPS];  /* value each sweep's key holds now, -1 = own */
};

static int live_fits(const struct ssg_bench_request *q)
{
    return !q->stereo && !q->reference && (q->frames <= 0 || q->frames > 1);
}

/* The live graph for cell c, loaded (or reloaded for another scene) and set to its values;
   NULL when it cannot be. */
static struct ssg_graph *live_graph(const struct bench *b, struct live_cells *l,
                                    const struct cell *c)
{
    int scene = b->scene_axis ? c->index[0] : 0;
    struct ssg_diags quiet = {0};
    if (l->g && scene != l->scene)
        ssg_graph_destroy(&l->g);
    if (!l->g) {
        int own[SSG_BENCH_MAX_SWEEPS];
        for (int k = 0; k < SSG_BENCH_MAX_SWEEPS; k++)
            own[k] = k == 0 && b->scene_axis ? scene : -1;
        struct cell_sets cs;
        struct ssg_overrides ov = cell_overrides(b, own, &cs);
        if (ssg_graph_load(b->graph, &ov, &l->g, &quiet) || ssg_graph_keep(l->g, 0, &quiet))
            ssg_graph_destroy(&l->g);
        l->scene = scene;
        for (int k = 0; k < SSG_BENCH_MAX_SWEEPS; k++)
            l->applied[k] = -1;
    }
    for (int k = b->scene_axis; l->g && k < b->n; k++) {
        if (l->applied[k] == c->index[k])
            continue; /* unchanged: its node keeps its prepared constants */
        if (ssg_graph_set(l->g, b->sweeps[k].key, ssg_bench_value(b, c, k), &quiet))
            return NULL; /* the graph stays as it was (ssg_graph_set) */
        l->applied[k] = c->index[k];
    }
    return l->g;
}

/* One cell: the graph with the user's --set and the cell's values, run `frames` times
   (for each eye with --stereo). */
static void run_cell(const struct bench *b, struct live_cells *l, int ci, struct cell *c)
{
    const struct ssg_bench_request *q = b->req;
    char dir[1100];
    struct cell_sets cs;
    struct ssg_overrides ov = cell_overrides(b, c->index, &cs);
    struct ssg_diags d = {0};
    enum ssg_err e = SSG_OK;
    for (int eye = 0; eye < (q->stereo ? 2 : 1) && !e; eye++) {
        struct ssg_run_stats st;
        snprintf(dir, sizeof dir, "%s/cells/%d%s", q->out_dir, ci,
                 q->stereo ? (eye ? "/right" : "/left") : "");
        ov.eye_offset = q->stereo ? (eye ? 0.5f : -0.5f) * q->ipd : 0.0f;
        struct ssg_graph *g = live_fits(q) ? live_graph(b, l, c) : NULL;
        if (q->reference) /* scored against the cached reference (bench_reference.c) */
            e = ssg_bench_run_compared(b, &ov, q->frames > 0 ? q->frames : 5,
                                       eye ? &st : &c->stats, &d);
        else if (g)
            e = ssg_graph_run(g, &(struct ssg_run_options)RUN_OPTIONS(q, dir, &c->stats), &d);
        else
            e = run_graph_once(b->graph, &ov, q, dir, eye ? &st : &c->stats, &d);
        if (!e && eye)
            add_eye(&c->stats, &st);
        if (eye)
            ssg_run_stats_free(&st);
    }
    c->ok = e == SSG_OK;
    if (!c->ok)
        snprintf(c->error, sizeof c->error, "%s",
                 d.count ? d.items[0].message : ssg_err_text(e));
}

/* The cells of this shard: those below cell_count whose index % N is I. */
static int shard_cells(const struct bench *b)
{
    int left = b->cell_count - b->shard_index;
    return left > 0 ? (left + b->shard_count - 1) / b->shard_count : 0;
}

static void progress(const struct bench *b, int ci, FILE *f, int tty)
{
    const struct cell *c = &b->cells[ci];
    char what[512] = "";
    size_t used = 0;
    for (int k = 0; k < b->n && used < sizeof what; k++)
        used += (size_t)snprintf(what + used, sizeof what - used, "%s%s=%s", k ? " " : "",
                                 b->sweeps[k].key, ssg_bench_value(b, c, k));
    char result[2000];
    struct ssg_bench_ms ms = ssg_bench_shown_ms(b, c);
    if (c->ok) /* the median [fastest-slowest], as bench.md writes it */
        snprintf(result, sizeof result, "%.2f [%.2f-%.2f] ms%s%s", ms.median, ms.min, ms.max,
                 b->req->time_node ? " " : "", b->req->time_node ? b->req->time_node : "");
    else
        snprintf(result, sizeof result, "FAILED: %s", c->error);
    for (int i = 0; b->req->verbose && c->ok && i < c->stats.node_count; i++) {
        size_t len = strlen(result);
        snprintf(result + len, sizeof result - len, "%s%s %.2f", i ? ", " : " (",
                 c->stats.nodes[i].name, c->stats.nodes[i].median_ms);
        if (i + 1 == c->stats.node_count && strlen(result) + 2 < sizeof result)
            strcat(result, ")");
    }
    if (!tty) {
        fprintf(f, "bench: cell %d/%d %s: %s\n", ci + 1, b->cell_count, what, result);
        return;
    }
    int width = 30, mine = shard_cells(b), filled = width * b->done / (mine ? mine : 1);
    fprintf(f, "\r[%.*s%*s] %d/%d %s: %s\033[K", filled, "##############################",
            width - filled, "", ci + 1, b->cell_count, what, result);
    if (b->done == mine || !c->ok)
        fputc('\n', f);
    fflush(f);
}

/* ", a, b, c" of the graph's nodes (with metrics only: those whose type reports some). */
static void node_list(const struct ssg_graph *g, int with_metrics, char *buf, size_t len)
{
    struct ssg_graph_info info;
    ssg_graph_inspect(g, &info);
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < info.node_count && used < len; i++) {
        struct ssg_node_info n;
        if (ssg_graph_node_inspect(g, i, &n) || (with_metrics && !ssg_node_metric(n.type, 0)))
            continue;
        used += (size_t)snprintf(buf + used, len - used, "%s%s", used ? ", " : "", n.name);
    }
}

/* ", rmse, mae" of what node type `type` reports. */
static void metric_list(const char *type, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int k = 0; ssg_node_metric(type, k) && used < len; k++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", k ? ", " : "",
                                 ssg_node_metric(type, k));
}

/* The type whose metrics --error's NODE reports: bench_reference's (with --reference) are a
   compare's; NULL when NODE is no node of g. */
static const char *metric_node_type(const struct bench *b, const struct ssg_graph *g,
                                    const char *node)
{
    struct ssg_node_info n;
    if (b->req->reference && !strcmp(node, "bench_reference"))
        return "compare";
    return ssg_graph_node_inspect(g, ssg_graph_node_index(g, node), &n) ? NULL : n.type;
}

/* --error NODE.METRIC: a node of the graph (or bench_reference) and a metric its type
   reports; 0 with the names it could be. */
static int check_error_metric(const struct bench *b, const struct ssg_graph *g)
{
    const char *spec = b->req->error_metric, *dot = strchr(spec, '.');
    char node[128], list[2048];
    snprintf(node, sizeof node, "%.*s", dot ? (int)(dot - spec) : 0, spec);
    const char *type = dot && dot - spec < (long)sizeof node ? metric_node_type(b, g, node)
                                                             : NULL;
    for (int k = 0; type && ssg_node_metric(type, k); k++)
        if (!strcmp(ssg_node_metric(type, k), dot + 1))
            return 1;
    if (type && ssg_node_metric(type, 0)) {
        metric_list(type, list, sizeof list);
        fprintf(stderr, "ssgraph: error: --error '%s': node '%s' (%s) reports no metric '%s' "
                "(expected one of: %s)\n", spec, node, type, dot + 1, list);
        return 0;
    }
    node_list(g, 1, list, sizeof list);
    fprintf(stderr, "ssgraph: error: --error '%s': expected NODE.METRIC, NODE a node of %s "
            "that reports metrics (%s%s%s)\n", spec, b->graph, list[0] ? "one of: " : "none "
            "does: add a compare node", list, b->req->reference ? ", or bench_reference" : "");
    return 0;
}

/* --time and --error name what the graph has: checked before anything runs or is written
   (a misspelt name used to be found after the first cell, or never). */
static int check_names(const struct bench *b)
{
    const struct ssg_bench_request *q = b->req;
    if (!q->time_node && !q->error_metric)
        return 1;
    struct ssg_diags quiet = {0};
    struct ssg_graph *g = NULL;
    if (ssg_graph_parse(b->graph, &g, &quiet) != SSG_OK) {
        ssg_graph_destroy(&g);
        return 1; /* check_sweeps reports what is wrong with the graph */
    }
    int ok = 1;
    if (q->time_node && ssg_graph_node_index(g, q->time_node) < 0) {
        char list[2048];
        node_list(g, 0, list, sizeof list);
        fprintf(stderr, "ssgraph: error: --time '%s' is not a node of %s (expected one of: "
                "%s)\n", q->time_node, b->graph, list);
        ok = 0;
    }
    if (ok && q->error_metric)
        ok = check_error_metric(b, g);
    ssg_graph_destroy(&g);
    return ok;
}

/* Whether the --time node (if any) is among the nodes a cell ran. */
static int knows_time_node(const struct bench *b, const struct cell *c)
{
    int found = !b->req->time_node;
    for (int i = 0; i < c->stats.node_count && !found; i++)
        found = !strcmp(c->stats.nodes[i].name, b->req->time_node);
    return found;
}

int ssg_bench_main(const struct ssg_bench_request *req)
{
    struct bench b = {.req = req, .n = req->sweep_count, .graph = req->graph};
    if (!req->reference != !req->image || (req->mask && !req->reference)) {
        fprintf(stderr, "ssgraph: error: --reference NODE.PORT and --image NODE.PORT go "
                "together (the image each cell makes and the truth it is compared with), "
                "and --mask NODE.PORT needs them\n");
        return 2;
    }
    /* Paths inside it are built in fixed buffers of 1100 to 1200 bytes: refuse a longer one
       rather than write to a truncated name. */
    if (strlen(req->out_dir) > 1000) {
        fprintf(stderr, "ssgraph: error: --out path is longer than 1000 bytes\n");
        return 2;
    }
    if (!scene_sweep(&b))
        return 2;
    for (int k = b.scene_axis; k < b.n; k++)
        if (!parse_sweep(req->sweeps[k - b.scene_axis], &b.sweeps[k]))
            return 2;
    if (!(b.cell_count = count_cells(&b)))
        return 2;
    if (!ssg_bench_parse_shard(&b, req->shard) || !ssg_bench_define(&b))
        return 1;
    if (!check_names(&b))
        return 2;
    struct ssg_diags d = {0};
    if (!ssg_bench_make_cells(&b))
        return 1;
    if (!check_sweeps(&b)) {
        ssg_bench_free_cells(&b);
        return 2;
    }
    enum ssg_err e = ssg_make_dirs(req->out_dir, &d);
    if (!e)
        e = ssg_bench_check_tables(req->out_dir, &d);
    int tty = isatty(fileno(stderr)), failed = 0;
    struct live_cells live = {0};
    for (int ci = b.shard_index; ci < b.cell_count && !e; ci += b.shard_count) {
        run_cell(&b, &live, ci, &b.cells[ci]);
        b.cells[ci].ran = 1;
        b.done++;
        failed += !b.cells[ci].ok;
        if (!req->quiet)
            progress(&b, ci, stderr, tty);
        e = ssg_bench_save(&b, &d);
        if (!e && b.cells[ci].ok && !knows_time_node(&b, &b.cells[ci])) {
            /* a node of the graph (check_names) that no cell runs: none of its outputs
               is read by a sink, or by --image with --reference */
            fprintf(stderr, "ssgraph: error: --time '%s': the node does not run in %s's "
                    "cells (nothing they write or compare reads it)\n", req->time_node,
                    req->graph);
            failed = -1;
            break;
        }
    }
    ssg_graph_destroy(&live.g);
    ssg_diags_print(&d, stderr);
    if (!e && failed >= 0 && b.done > 0 && !req->quiet) { /* "wrote" only what was */
        if (b.shard_count > 1)
            printf("bench: shard %d/%d: %d of the %d cells, %d failed\n", b.shard_index,
                   b.shard_count, b.done, b.cell_count, failed);
        else
            printf("bench: %d cells, %d failed\n", b.cell_count, failed);
        ssg_bench_print_tables(req->out_dir);
        fflush(stdout);
        int noisy = ssg_bench_noisy_count(&b);
        if (noisy)
            fprintf(stderr, "ssgraph: warning: %d of the %d cells ran with the median frame "
                    "over %.0fx the fastest (a busy machine, or frames that differ in work): "
                    "their medians may mislead by as much (listed in %s/bench.md); rerun on a "
                    "quiet machine before comparing\n", noisy, b.done, SSG_BENCH_SPREAD,
                    req->out_dir);
    }
    if (!e && failed >= 0 && req->plot && ssg_bench_draw_plots(&b))
        e = SSG_E_IO;
    ssg_bench_free_cells(&b);
    return failed < 0 ? 2 : e || failed ? 1 : 0;
}
