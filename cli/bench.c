/* bench.c - `ssgraph bench FILE --sweep node.param=v1,v2,... [--sweep ...]`: the graph is
 * loaded and run for every combination of the sweeps' values (the cross product, first
 * sweep outermost), each cell over `frames` frames with every node prepared once; its
 * frame time (average, min, max) and the metrics its compare nodes report go to
 * <out>/bench.csv (rewritten whole after every cell, so an interrupted bench keeps the
 * cells it finished), <out>/bench.json and <out>/bench.md (rewritten whole after every
 * cell; the table is shaped like the documents': rows the first sweep, columns the
 * second, one table per value of the others). A cell that fails is reported and recorded
 * with its message; the others still run. Progress: a bar on a terminal, lines
 * otherwise. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench.h"
#include "lang/files.h"
#include "lang/diag.h"
#include "plot.h"

/* At most 64 values a sweep, and at most MAX_CELLS cells in one bench: each finished cell
   rewrites bench.json and bench.md whole, and a sweep that big is hours of work that is
   better split (checked before anything is allocated). */
enum { MAX_VALUES = 64, MAX_CELLS = 10000 };

struct sweep {
    char key[128];                    /* node.param */
    char text[1024];                  /* the values, split in place */
    const char *values[MAX_VALUES];
    int count;
};

struct cell {
    int index[SSG_BENCH_MAX_SWEEPS];  /* value index per sweep */
    int ok;
    char error[512];
    struct ssg_run_stats stats;
};

struct bench {
    const struct ssg_bench_request *req;
    const char *graph;                /* what runs: the graph, or bench.graph around it */
    char graph_buf[1200];
    struct sweep sweeps[SSG_BENCH_MAX_SWEEPS];
    int n;                            /* sweeps */
    struct cell *cells;
    int cell_count, done;
};

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
static int make_cells(struct bench *b)
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

static const char *value_of(const struct bench *b, const struct cell *c, int k)
{
    return b->sweeps[k].values[c->index[k]];
}

/* With --reference: <out>/bench.graph, the graph plus a compare node `bench_reference` of
   --image against --reference, whose metrics every cell then reports. */
static int write_reference_graph(const struct ssg_bench_request *q, char *path, size_t len)
{
    char abs[4096];
    if (!realpath(q->graph, abs)) {
        fprintf(stderr, "ssgraph: error: %s: cannot open the graph\n", q->graph);
        return 0;
    }
    snprintf(path, len, "%s/bench.graph", q->out_dir);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "ssgraph: error: cannot write %s\n", path);
        return 0;
    }
    fprintf(f, "# made by ssgraph bench --reference: the graph, and its image compared with "
               "the reference\ninclude \"%s\"\nbench_reference = compare(%s, %s)\n", abs,
            q->image, q->reference);
    return fclose(f) == 0;
}

static enum ssg_err run_graph_once(const char *graph, const struct ssg_overrides *ov,
                                   const struct ssg_bench_request *q, const char *dir,
                                   struct ssg_run_stats *stats, struct ssg_diags *d)
{
    struct ssg_run_options ro = {.out_dir = dir, .threads = q->threads, .quiet = 1,
                                 .frames = q->frames > 0 ? q->frames : 5, .stats = stats};
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load(graph, ov, &g, d);
    if (!e)
        e = ssg_graph_run(g, &ro, d);
    ssg_graph_destroy(&g);
    return e;
}

/* A stereo cell's times are both eyes' (a stereo frame renders both); its metrics are
   the left eye's. */
static void add_eye(struct ssg_run_stats *both, const struct ssg_run_stats *right)
{
    both->frame_avg_ms += right->frame_avg_ms;
    both->frame_min_ms += right->frame_min_ms;
    both->frame_max_ms += right->frame_max_ms;
    for (int i = 0; i < both->node_count && i < right->node_count; i++)
        both->nodes[i].avg_ms += right->nodes[i].avg_ms;
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
    for (int k = 0; k < b->n; k++) {
        if (index[k] < 0)
            continue;
        snprintf(cs->own[k], sizeof cs->own[k], "%s=%s", b->sweeps[k].key,
                 b->sweeps[k].values[index[k]]);
        cs->sets[n++] = cs->own[k];
    }
    struct ssg_overrides ov = *q->ov;
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

/* One cell: the graph with the user's --set and the cell's values, run `frames` times
   (for each eye with --stereo). */
static void run_cell(const struct bench *b, int ci, struct cell *c)
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
        e = run_graph_once(b->graph, &ov, q, dir, eye ? &st : &c->stats, &d);
        if (!e && eye)
            add_eye(&c->stats, &st);
    }
    c->ok = e == SSG_OK;
    if (!c->ok)
        snprintf(c->error, sizeof c->error, "%s", d.count ? d.items[0].message : ssg_err_text(e));
}

/* "rmse=0.0213;ssim=0.91" style: every metric of a cell as node.name=value. */
static void metrics_text(const struct cell *c, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = 0;
    for (int i = 0; i < c->stats.metric_count && used < len; i++) {
        const struct ssg_run_metric *m = &c->stats.metrics[i];
        used += (size_t)snprintf(buf + used, len - used, "%s%s.%s=%.6g", i ? ";" : "",
                                 m->node, m->name, m->value);
    }
}

static void csv_field(FILE *f, const char *text)
{
    fputc('"', f);
    for (; *text; text++) {
        if (*text == '"')
            fputc('"', f);
        fputc(*text, f);
    }
    fputc('"', f);
}

static void csv_header(const struct bench *b, FILE *f)
{
    fputs("cell", f);
    for (int k = 0; k < b->n; k++)
        fprintf(f, ",%s", b->sweeps[k].key);
    fputs(",status,frames,frame_avg_ms,frame_min_ms,frame_max_ms,node_ms,metrics,error\n", f);
}

/* "g=1.2;ao=0.7": every node's average ms of a cell. */
static void nodes_text(const struct cell *c, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = 0;
    for (int i = 0; i < c->stats.node_count && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s=%.4f", i ? ";" : "",
                                 c->stats.nodes[i].name, c->stats.nodes[i].avg_ms);
}

static void csv_row(const struct bench *b, int ci, FILE *f)
{
    const struct cell *c = &b->cells[ci];
    char metrics[2048], nodes[2048];
    metrics_text(c, metrics, sizeof metrics);
    nodes_text(c, nodes, sizeof nodes);
    fprintf(f, "%d", ci);
    for (int k = 0; k < b->n; k++) {
        fputc(',', f);
        csv_field(f, value_of(b, c, k));
    }
    fprintf(f, ",%s,%d,%.4f,%.4f,%.4f,", c->ok ? "ok" : "error", c->stats.frames,
            c->stats.frame_avg_ms, c->stats.frame_min_ms, c->stats.frame_max_ms);
    csv_field(f, nodes);
    fputc(',', f);
    csv_field(f, metrics);
    fputc(',', f);
    csv_field(f, c->ok ? "" : c->error);
    fputc('\n', f);
}

static void json_string(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            fprintf(f, "\\%c", *s);
        else if ((unsigned char)*s < 0x20)
            fprintf(f, "\\u%04x", *s);
        else
            fputc(*s, f);
    }
    fputc('"', f);
}

static void json_cell(const struct bench *b, int ci, FILE *f)
{
    const struct cell *c = &b->cells[ci];
    fprintf(f, "    {\"cell\": %d, \"values\": {", ci);
    for (int k = 0; k < b->n; k++) {
        fprintf(f, "%s", k ? ", " : "");
        json_string(f, b->sweeps[k].key);
        fputs(": ", f);
        json_string(f, value_of(b, c, k));
    }
    fprintf(f, "}, \"status\": \"%s\", \"frames\": %d, \"frame_avg_ms\": %.6g, "
            "\"frame_min_ms\": %.6g, \"frame_max_ms\": %.6g, \"metrics\": {",
            c->ok ? "ok" : "error", c->stats.frames, c->stats.frame_avg_ms,
            c->stats.frame_min_ms, c->stats.frame_max_ms);
    for (int i = 0; i < c->stats.metric_count; i++) {
        const struct ssg_run_metric *m = &c->stats.metrics[i];
        fprintf(f, "%s\"%s.%s\": ", i ? ", " : "", m->node, m->name);
        if (isfinite(m->value)) /* JSON has no inf: a PSNR of identical images is null */
            fprintf(f, "%.9g", m->value);
        else
            fputs("null", f);
    }
    fputs("}, \"node_ms\": {", f);
    for (int i = 0; i < c->stats.node_count; i++)
        fprintf(f, "%s\"%s\": %.6g", i ? ", " : "", c->stats.nodes[i].name,
                c->stats.nodes[i].avg_ms);
    fputs("}, \"error\": ", f);
    json_string(f, c->ok ? "" : c->error);
    fputs("}", f);
}

static void write_json(FILE *f, const void *user)
{
    const struct bench *b = user;
    fputs("{\n  \"graph\": ", f);
    json_string(f, b->req->graph);
    fputs(",\n  \"sweeps\": [", f);
    for (int k = 0; k < b->n; k++) {
        fprintf(f, "%s{\"key\": ", k ? ", " : "");
        json_string(f, b->sweeps[k].key);
        fputs(", \"values\": [", f);
        for (int v = 0; v < b->sweeps[k].count; v++) {
            fputs(v ? ", " : "", f);
            json_string(f, b->sweeps[k].values[v]);
        }
        fputs("]}", f);
    }
    fprintf(f, "],\n  \"cells_total\": %d,\n  \"cells\": [\n", b->cell_count);
    for (int ci = 0; ci < b->done; ci++) {
        json_cell(b, ci, f);
        fputs(ci + 1 < b->done ? ",\n" : "\n", f);
    }
    fputs("  ]\n}\n", f);
}

/* The ms a table shows for a cell: the --time node's average, else the frame's. */
static double shown_ms(const struct bench *b, const struct cell *c)
{
    for (int i = 0; b->req->time_node && i < c->stats.node_count; i++)
        if (!strcmp(c->stats.nodes[i].name, b->req->time_node))
            return c->stats.nodes[i].avg_ms;
    return c->stats.frame_avg_ms;
}

static double error_of(const struct bench *b, const struct cell *c);

/* One Markdown cell: "12.34 ms" plus the error metric (error_of), or the failure. */
static void md_cell(const struct bench *b, const struct cell *c, FILE *f)
{
    if (!c->ok) {
        fputs(" failed |", f);
        return;
    }
    fprintf(f, " %.2f ms", shown_ms(b, c));
    double err = error_of(b, c);
    if (!isnan(err))
        fprintf(f, ", %.4g", err);
    fputs(" |", f);
}

/* The values of sweeps 2.. that table t (of their combinations, last sweep fastest) shows. */
static void md_title(const struct bench *b, int t, FILE *f)
{
    int stride = 1;
    for (int k = b->n - 1; k >= 2; k--)
        stride *= b->sweeps[k].count;
    for (int k = 2; k < b->n; k++) {
        stride /= b->sweeps[k].count;
        fprintf(f, "%s%s = %s", k > 2 ? ", " : "\n", b->sweeps[k].key,
                b->sweeps[k].values[(t / stride) % b->sweeps[k].count]);
    }
    fputs(b->n > 2 ? ":\n" : "", f);
}

/* Tables: rows the first sweep, columns the second (or one column), one table per value
   combination of the other sweeps; cells not run yet are blank. Cell (i0, i1, t) is
   (i0 * columns + i1) * tables + t, as make_cells numbers them. */
static void write_md(FILE *f, const void *user)
{
    const struct bench *b = user;
    int rows = b->n ? b->sweeps[0].count : 1, cols = b->n > 1 ? b->sweeps[1].count : 1;
    int tables = b->cell_count / (rows * cols);
    const char *err = b->req->error_metric ? b->req->error_metric
                      : b->req->reference ? "bench_reference.rmse"
                                          : "the first metric a compare node reported";
    fprintf(f, "# ssgraph bench %s\n\nms %s%s (average over each cell's frames) and %s, if "
            "any.\n", b->req->graph, b->req->time_node ? "of node " : "per frame",
            b->req->time_node ? b->req->time_node : "", err);
    for (int t = 0; t < tables; t++) {
        md_title(b, t, f);
        fprintf(f, "\n| %s |", b->n ? b->sweeps[0].key : "graph");
        for (int col = 0; col < cols; col++)
            fprintf(f, " %s%s%s |", b->n > 1 ? b->sweeps[1].key : "ms", b->n > 1 ? " = " : "",
                    b->n > 1 ? b->sweeps[1].values[col] : "");
        fputs("\n|---|", f);
        for (int col = 0; col < cols; col++)
            fputs("---|", f);
        for (int r = 0; r < rows; r++) {
            fprintf(f, "\n| %s |", b->n ? b->sweeps[0].values[r] : "");
            for (int col = 0; col < cols; col++) {
                int ci = (r * cols + col) * tables + t;
                if (ci < b->done)
                    md_cell(b, &b->cells[ci], f);
                else
                    fputs(" |", f);
            }
        }
        fputc('\n', f);
    }
}

static void progress(const struct bench *b, int ci, FILE *f, int tty)
{
    const struct cell *c = &b->cells[ci];
    char what[512] = "";
    size_t used = 0;
    for (int k = 0; k < b->n && used < sizeof what; k++)
        used += (size_t)snprintf(what + used, sizeof what - used, "%s%s=%s", k ? " " : "",
                                 b->sweeps[k].key, value_of(b, c, k));
    char result[600];
    if (c->ok)
        snprintf(result, sizeof result, "%.2f ms%s%s", shown_ms(b, c),
                 b->req->time_node ? " " : "", b->req->time_node ? b->req->time_node : "");
    else
        snprintf(result, sizeof result, "FAILED: %s", c->error);
    if (!tty) {
        fprintf(f, "bench: cell %d/%d %s: %s\n", ci + 1, b->cell_count, what, result);
        return;
    }
    int width = 30, filled = width * (ci + 1) / b->cell_count;
    fprintf(f, "\r[%.*s%*s] %d/%d %s: %s\033[K", filled, "##############################",
            width - filled, "", ci + 1, b->cell_count, what, result);
    if (ci + 1 == b->cell_count || !c->ok)
        fputc('\n', f);
    fflush(f);
}

static void write_csv(FILE *f, const void *user)
{
    const struct bench *b = user;
    csv_header(b, f);
    for (int ci = 0; ci < b->done; ci++)
        csv_row(b, ci, f);
}

/* After each cell: bench.csv, bench.json and bench.md rewritten whole, each through a
   temporary and a rename (files.h), so an interrupted bench keeps every finished cell and
   no file is ever half-written or written through a planted link. */
static enum ssg_err save(const struct bench *b, struct ssg_diags *d)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/bench.csv", b->req->out_dir);
    if (ssg_write_text_file(path, "bench table", write_csv, b, d))
        return SSG_E_IO;
    snprintf(path, sizeof path, "%s/bench.json", b->req->out_dir);
    enum ssg_err e = ssg_write_text_file(path, "bench results", write_json, b, d);
    snprintf(path, sizeof path, "%s/bench.md", b->req->out_dir);
    return e ? e : ssg_write_text_file(path, "bench table", write_md, b, d);
}

/* Whether the --time node (if any) is among the nodes a cell ran. */
static int knows_time_node(const struct bench *b, const struct cell *c)
{
    int found = !b->req->time_node;
    for (int i = 0; i < c->stats.node_count && !found; i++)
        found = !strcmp(c->stats.nodes[i].name, b->req->time_node);
    return found;
}

/* The cell's value of --error (or its first metric); NAN when it has none. */
static double error_of(const struct bench *b, const struct cell *c)
{
    for (int i = 0; i < c->stats.metric_count; i++) {
        char key[100];
        snprintf(key, sizeof key, "%s.%s", c->stats.metrics[i].node, c->stats.metrics[i].name);
        const char *want = b->req->error_metric ? b->req->error_metric
                           : b->req->reference ? "bench_reference.rmse" : NULL;
        if (!want || !strcmp(key, want))
            return c->stats.metrics[i].value;
    }
    return NAN;
}

static int by_series(const void *a, const void *b)
{
    const struct ssg_plot_point *p = a, *q = b;
    int s = strcmp(p->series, q->series);
    return s ? s : (p->x > q->x) - (p->x < q->x);
}

/* The successful cells as plot points: x the first sweep's value (must be a number),
   series the other sweeps' values. */
static int plot_points(const struct bench *b, struct ssg_plot_point *pts, char (*series)[300])
{
    int n = 0;
    for (int ci = 0; ci < b->done; ci++) {
        const struct cell *c = &b->cells[ci];
        char *end;
        double x = b->n ? strtod(value_of(b, c, 0), &end) : ci;
        if (!c->ok || (b->n && *end))
            continue;
        size_t used = 0;
        series[n][0] = 0;
        for (int k = 1; k < b->n; k++)
            used += (size_t)snprintf(series[n] + used, 300 - used, "%s%s=%s", k > 1 ? " " : "",
                                     b->sweeps[k].key, value_of(b, c, k));
        if (b->n < 2)
            snprintf(series[n], 300, "%s", b->req->time_node ? b->req->time_node : "frame");
        pts[n] = (struct ssg_plot_point){x, shown_ms(b, c), error_of(b, c), series[n], ""};
        used = 0;
        for (int k = 0; k < b->n; k++)
            used += (size_t)snprintf(pts[n].label + used, sizeof pts[n].label - used, "%s%s",
                                     k ? "," : "", value_of(b, c, k));
        n++;
    }
    return n;
}

static int draw_plots(const struct bench *b)
{
    struct ssg_plot_point *pts = calloc((size_t)b->done + 1, sizeof *pts);
    char(*series)[300] = calloc((size_t)b->done + 1, sizeof *series);
    int n = pts && series ? plot_points(b, pts, series) : 0, rc = 0;
    if (n == 0) {
        fprintf(stderr, "ssgraph: error: nothing to plot (no finished cell, or the first "
                "sweep's values are not numbers)\n");
        rc = 1;
    } else {
        qsort(pts, (size_t)n, sizeof *pts, by_series);
        char title[600], ylabel[200];
        snprintf(title, sizeof title, "%s: ms against %s", b->req->graph,
                 b->n ? b->sweeps[0].key : "cell");
        snprintf(ylabel, sizeof ylabel, "ms (%s)", b->req->time_node ? b->req->time_node
                                                                     : "frame");
        rc |= ssg_plot_ms(b->req->out_dir, "bench_ms", title, b->n ? b->sweeps[0].key : "cell",
                          ylabel, pts, n);
        int errors = 0;
        for (int i = 0; i < n; i++)
            errors += !isnan(pts[i].err);
        snprintf(title, sizeof title, "%s: error against ms (Pareto view)", b->req->graph);
        if (errors)
            rc |= ssg_plot_pareto(b->req->out_dir, "bench_pareto", title,
                                  b->req->error_metric ? b->req->error_metric
                                                       : "first metric", pts, n);
        else
            fprintf(stderr, "bench: no %s in the cells: no Pareto plot (add a compare node)\n",
                    b->req->error_metric ? b->req->error_metric : "metric");
    }
    free(pts);
    free(series);
    return rc;
}

int ssg_bench_main(const struct ssg_bench_request *req)
{
    struct bench b = {.req = req, .n = req->sweep_count, .graph = req->graph};
    if (!req->reference != !req->image) {
        fprintf(stderr, "ssgraph: error: --reference NODE.PORT and --image NODE.PORT go "
                "together (the image each cell makes and the truth it is compared with)\n");
        return 2;
    }
    /* Paths inside it are built in fixed buffers of 1100 to 1200 bytes: refuse a longer one
       rather than write to a truncated name. */
    if (strlen(req->out_dir) > 1000) {
        fprintf(stderr, "ssgraph: error: --out path is longer than 1000 bytes\n");
        return 2;
    }
    for (int k = 0; k < b.n; k++)
        if (!parse_sweep(req->sweeps[k], &b.sweeps[k]))
            return 2;
    if (!(b.cell_count = count_cells(&b)))
        return 2;
    struct ssg_diags d = {0};
    if (req->reference) {
        if (ssg_make_dirs(req->out_dir, &d) ||
            !write_reference_graph(req, b.graph_buf, sizeof b.graph_buf)) {
            ssg_diags_print(&d, stderr);
            return 1;
        }
        b.graph = b.graph_buf;
    }
    if (!make_cells(&b))
        return 1;
    if (!check_sweeps(&b)) {
        free(b.cells);
        return 2;
    }
    enum ssg_err e = ssg_make_dirs(req->out_dir, &d);
    int tty = isatty(fileno(stderr)), failed = 0;
    for (int ci = 0; ci < b.cell_count && !e; ci++) {
        run_cell(&b, ci, &b.cells[ci]);
        b.done = ci + 1;
        failed += !b.cells[ci].ok;
        progress(&b, ci, stderr, tty);
        e = save(&b, &d);
        if (!e && b.cells[ci].ok && !knows_time_node(&b, &b.cells[ci])) {
            fprintf(stderr, "ssgraph: error: --time '%s' is not a node of %s\n",
                    req->time_node, req->graph);
            failed = -1;
            break;
        }
    }
    ssg_diags_print(&d, stderr);
    if (!e && failed >= 0)
        fprintf(stderr, "bench: %d cells, %d failed; wrote %s/bench.csv, bench.md, bench.json\n",
                b.cell_count, failed, req->out_dir);
    if (!e && failed >= 0 && req->plot && draw_plots(&b))
        e = SSG_E_IO;
    free(b.cells);
    return failed < 0 ? 2 : e || failed ? 1 : 0;
}
