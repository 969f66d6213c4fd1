/* bench_out.c - what `ssgraph bench` writes of its cells (bench_cells.h): bench.csv,
 * bench.json and bench.md after every cell, and the gnuplot pictures at the end. A time
 * shown is the median of a cell's runs with the fastest and slowest beside it: the mean
 * carries the first run's one-off costs (fresh memory), the median is the steady rate. */
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_cells.h"
#include "plot.h"
#include "ssgraph.h"
#include "text_out.h"

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

/* Each node's times, as the CSV's columns and the JSON's objects of these names carry them
   ("ao=1.2;g=0.4"); node_ms is the average, as it was before the median came. */
static const struct {
    const char *name;
    size_t offset; /* of the double in struct ssg_run_node */
} node_times[] = {
    {"node_median_ms", offsetof(struct ssg_run_node, median_ms)},
    {"node_min_ms", offsetof(struct ssg_run_node, min_ms)},
    {"node_max_ms", offsetof(struct ssg_run_node, max_ms)},
    {"node_ms", offsetof(struct ssg_run_node, avg_ms)},
};
enum { NODE_TIMES = sizeof node_times / sizeof node_times[0] };

static double node_time(const struct ssg_run_node *n, int t)
{
    double v;
    memcpy(&v, (const char *)n + node_times[t].offset, sizeof v);
    return v;
}

static void csv_header(const struct bench *b, FILE *f)
{
    fputs("cell", f);
    for (int k = 0; k < b->n; k++) {
        fputc(',', f);
        ssg_csv_field(f, b->sweeps[k].key);
    }
    fputs(",status,frames,frame_median_ms,frame_min_ms,frame_max_ms,frame_avg_ms", f);
    for (int t = 0; t < NODE_TIMES; t++)
        fprintf(f, ",%s", node_times[t].name);
    fputs(",metrics,error\n", f);
}

/* "g=1.2;ao=0.7": every node's time t (node_times) of a cell. */
static void nodes_text(const struct cell *c, int t, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = 0;
    for (int i = 0; i < c->stats.node_count && used < len; i++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s=%.4f", i ? ";" : "",
                                 c->stats.nodes[i].name, node_time(&c->stats.nodes[i], t));
}

static void csv_row(const struct bench *b, int ci, FILE *f)
{
    const struct cell *c = &b->cells[ci];
    char text[2048];
    fprintf(f, "%d", ci);
    for (int k = 0; k < b->n; k++) {
        fputc(',', f);
        ssg_csv_field(f, ssg_bench_value(b, c, k));
    }
    fprintf(f, ",%s,%d,%.4f,%.4f,%.4f,%.4f", c->ok ? "ok" : "error", c->stats.frames,
            c->stats.frame_median_ms, c->stats.frame_min_ms, c->stats.frame_max_ms,
            c->stats.frame_avg_ms);
    for (int t = 0; t < NODE_TIMES; t++) {
        nodes_text(c, t, text, sizeof text);
        fputc(',', f);
        ssg_csv_field(f, text);
    }
    metrics_text(c, text, sizeof text);
    fputc(',', f);
    ssg_csv_field(f, text);
    fputc(',', f);
    ssg_csv_field(f, c->ok ? "" : c->error);
    fputc('\n', f);
}

/* A JSON key "node.metric" (names from a merged shard may hold anything: escaped). */
static void json_metric_key(FILE *f, const struct ssg_run_metric *m)
{
    char key[sizeof m->node + sizeof m->name + 1];
    snprintf(key, sizeof key, "%s.%s", m->node, m->name);
    ssg_json_string(f, key);
    fputs(": ", f);
}

/* The metrics, exact, so that a merge writes the same tables; JSON has no infinity (the
   PSNR of identical images): "inf", "-inf" and "nan" are strings. */
static void json_metrics(const struct cell *c, FILE *f)
{
    fputs("\"metrics\": {", f);
    for (int i = 0; i < c->stats.metric_count; i++) {
        const struct ssg_run_metric *m = &c->stats.metrics[i];
        fputs(i ? ", " : "", f);
        json_metric_key(f, m);
        fprintf(f, isfinite(m->value) ? "%.17g" : "\"%g\"", m->value);
    }
    fputs("}", f);
}

static void json_cell(const struct bench *b, int ci, FILE *f)
{
    const struct cell *c = &b->cells[ci];
    fprintf(f, "    {\"cell\": %d, \"values\": {", ci);
    for (int k = 0; k < b->n; k++) {
        fprintf(f, "%s", k ? ", " : "");
        ssg_json_string(f, b->sweeps[k].key);
        fputs(": ", f);
        ssg_json_string(f, ssg_bench_value(b, c, k));
    }
    fprintf(f, "}, \"status\": \"%s\", \"frames\": %d, \"frame_median_ms\": %.6g, "
            "\"frame_min_ms\": %.6g, \"frame_max_ms\": %.6g, \"frame_avg_ms\": %.6g, ",
            c->ok ? "ok" : "error", c->stats.frames, c->stats.frame_median_ms,
            c->stats.frame_min_ms, c->stats.frame_max_ms, c->stats.frame_avg_ms);
    json_metrics(c, f);
    for (int t = 0; t < NODE_TIMES; t++) {
        fprintf(f, ", \"%s\": {", node_times[t].name);
        for (int i = 0; i < c->stats.node_count; i++) {
            fputs(i ? ", " : "", f);
            ssg_json_string(f, c->stats.nodes[i].name);
            fprintf(f, ": %.6g", node_time(&c->stats.nodes[i], t));
        }
        fputs("}", f);
    }
    fputs(", \"error\": ", f);
    ssg_json_string(f, c->ok ? "" : c->error);
    fputs("}", f);
}

static void write_json(FILE *f, const void *user)
{
    const struct bench *b = user;
    fputs("{\n  \"graph\": ", f);
    ssg_json_string(f, b->req->graph);
    fputs(",\n  \"sweeps\": [", f);
    for (int k = 0; k < b->n; k++) {
        fprintf(f, "%s{\"key\": ", k ? ", " : "");
        ssg_json_string(f, b->sweeps[k].key);
        fputs(", \"values\": [", f);
        for (int v = 0; v < b->sweeps[k].count; v++) {
            fputs(v ? ", " : "", f);
            ssg_json_string(f, b->sweeps[k].values[v]);
        }
        fputs("]}", f);
    }
    fputs("],\n  \"time_node\": ", f);
    ssg_json_string(f, b->req->time_node ? b->req->time_node : "");
    fputs(",\n  \"error_metric\": ", f);
    ssg_json_string(f, b->req->error_metric ? b->req->error_metric : "");
    fputs(",\n  \"reference\": ", f);
    ssg_json_string(f, b->req->reference ? b->req->reference : "");
    fputs(",\n  \"definition\": ", f);
    ssg_json_string(f, b->definition);
    fprintf(f, ",\n  \"definition_hash\": \"%s\",\n  \"shard\": {\"index\": %d, \"count\": %d},"
            "\n  \"cells_total\": %d,\n  \"cells\": [\n", b->definition_hash, b->shard_index,
            b->shard_count, b->cell_count);
    int written = 0;
    for (int ci = 0; ci < b->cell_count; ci++) {
        if (!b->cells[ci].ran)
            continue;
        fputs(written++ ? ",\n" : "", f);
        json_cell(b, ci, f);
    }
    fputs(written ? "\n  ]\n}\n" : "  ]\n}\n", f);
}

struct ssg_bench_ms ssg_bench_shown_ms(const struct bench *b, const struct cell *c)
{
    for (int i = 0; b->req->time_node && i < c->stats.node_count; i++) {
        const struct ssg_run_node *n = &c->stats.nodes[i];
        if (!strcmp(n->name, b->req->time_node))
            return (struct ssg_bench_ms){n->median_ms, n->min_ms, n->max_ms};
    }
    return (struct ssg_bench_ms){c->stats.frame_median_ms, c->stats.frame_min_ms,
                                 c->stats.frame_max_ms};
}

/* The metric the tables show and the Pareto plot draws: --error, bench_reference.rmse with
   --reference, else the first metric of the first finished cell that reported one (named
   in the table and on the axis, so a reader knows which); "" when there is none. */
static void error_name(const struct bench *b, char *name, size_t len)
{
    const struct ssg_bench_request *q = b->req;
    snprintf(name, len, "%s", q->error_metric ? q->error_metric
                              : q->reference  ? "bench_reference.rmse"
                                              : "");
    for (int ci = 0; !name[0] && ci < b->cell_count; ci++) {
        const struct cell *c = &b->cells[ci];
        if (c->ran && c->ok && c->stats.metric_count)
            snprintf(name, len, "%s.%s", c->stats.metrics[0].node, c->stats.metrics[0].name);
    }
}

/* The cell's value of the metric `name` (error_name); NAN when it has none. */
static double error_of(const struct cell *c, const char *name)
{
    for (int i = 0; name[0] && i < c->stats.metric_count; i++) {
        const struct ssg_run_metric *m = &c->stats.metrics[i];
        size_t len = strlen(m->node);
        if (!strncmp(name, m->node, len) && name[len] == '.' && !strcmp(name + len + 1, m->name))
            return m->value;
    }
    return NAN;
}

/* One Markdown cell: "12.34 [12.10-13.02] ms" (median [fastest-slowest], as the progress
   lines write it) plus the error metric, or the failure. */
static void md_cell(const struct bench *b, const struct cell *c, const char *err_name, FILE *f)
{
    if (!c->ok) {
        fputs(" failed |", f);
        return;
    }
    struct ssg_bench_ms ms = ssg_bench_shown_ms(b, c);
    fprintf(f, " %.2f [%.2f-%.2f] ms", ms.median, ms.min, ms.max);
    double err = error_of(c, err_name);
    if (!isnan(err))
        fprintf(f, ", %.4g", err);
    fputs(" |", f);
}

int ssg_bench_noisy(const struct bench *b, const struct cell *c)
{
    if (!c->ran || !c->ok)
        return 0;
    struct ssg_bench_ms ms = ssg_bench_shown_ms(b, c);
    return ms.min > 0 && ms.median > SSG_BENCH_SPREAD * ms.min;
}

int ssg_bench_noisy_count(const struct bench *b)
{
    int noisy = 0;
    for (int ci = 0; ci < b->cell_count; ci++)
        noisy += ssg_bench_noisy(b, &b->cells[ci]);
    return noisy;
}

/* After the tables: the cells whose median is over SSG_BENCH_SPREAD times their fastest. */
static void md_noisy(const struct bench *b, FILE *f)
{
    int noisy = ssg_bench_noisy_count(b);
    if (!noisy)
        return;
    fprintf(f, "\n**%d cell%s ran with the median frame over %.0fx the fastest**: the machine "
            "was busy, or the frames differ in work (a camera path), so %s median may "
            "mislead by as much; rerun on a quiet machine before comparing:", noisy,
            noisy > 1 ? "s" : "", SSG_BENCH_SPREAD, noisy > 1 ? "their" : "its");
    for (int ci = 0; ci < b->cell_count; ci++) {
        const struct cell *c = &b->cells[ci];
        if (!ssg_bench_noisy(b, c))
            continue;
        struct ssg_bench_ms ms = ssg_bench_shown_ms(b, c);
        fputs("\n-", f);
        for (int k = 0; k < b->n; k++)
            fprintf(f, " %s=%s", b->sweeps[k].key, ssg_bench_value(b, c, k));
        fprintf(f, "%s: %.2f [%.2f-%.2f] ms (median %.1fx the fastest)",
                b->n ? "" : " the graph", ms.median, ms.min, ms.max, ms.median / ms.min);
    }
    fputc('\n', f);
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
    char err[200];
    error_name(b, err, sizeof err);
    fprintf(f, "# ssgraph bench %s\n\nms %s%s (the median of each cell's frames [fastest-"
            "slowest])%s%s.\n", b->req->graph,
            b->req->time_node ? "of node " : "per frame",
            b->req->time_node ? b->req->time_node : "", err[0] ? " and " : "", err);
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
                if (b->cells[ci].ran)
                    md_cell(b, &b->cells[ci], err, f);
                else
                    fputs(" |", f);
            }
        }
        fputc('\n', f);
    }
    md_noisy(b, f);
}

static void write_csv(FILE *f, const void *user)
{
    const struct bench *b = user;
    csv_header(b, f);
    for (int ci = 0; ci < b->cell_count; ci++)
        if (b->cells[ci].ran)
            csv_row(b, ci, f);
}

/* The three tables, in the order they are written, checked and named. */
static const struct {
    const char *name, *what;
    void (*fill)(FILE *f, const void *b);
} tables[] = {{"bench.csv", "bench table", write_csv},
              {"bench.json", "bench results", write_json},
              {"bench.md", "bench table", write_md}};
enum { TABLE_COUNT = sizeof tables / sizeof tables[0] };

static void table_path(const char *out_dir, int i, char *path, size_t len)
{
    snprintf(path, len, "%s/%s", out_dir, tables[i].name);
}

enum ssg_err ssg_bench_save(const struct bench *b, struct ssg_diags *d)
{
    char path[1200];
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < TABLE_COUNT && !e; i++) {
        table_path(b->req->out_dir, i, path, sizeof path);
        e = ssg_write_text_file(path, tables[i].what, tables[i].fill, b, d);
    }
    return e;
}

enum ssg_err ssg_bench_check_tables(const char *out_dir, struct ssg_diags *d)
{
    char path[1200];
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < TABLE_COUNT && !e; i++) {
        table_path(out_dir, i, path, sizeof path);
        e = ssg_output_check(path, tables[i].what, 0, d);
    }
    return e;
}

void ssg_bench_print_tables(const char *out_dir)
{
    for (int i = 0; i < TABLE_COUNT; i++)
        printf("wrote %s/%s\n", out_dir, tables[i].name);
}

static int by_series(const void *a, const void *b)
{
    const struct ssg_plot_point *p = a, *q = b;
    int s = strcmp(p->series, q->series);
    return s ? s : (p->x > q->x) - (p->x < q->x);
}

/* Appends printf text at *used in buf (size bytes, at least 4); text that does not fit is
   cut and the whole ends in "...", so a cut name reads as cut. */
static void append(char *buf, size_t size, size_t *used, const char *fmt, ...)
{
    if (*used + 1 >= size)
        return; /* full (and already marked) */
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(buf + *used, size - *used, fmt, ap);
    va_end(ap);
    if (n < 0)
        buf[*used] = '\0';
    else if ((size_t)n < size - *used)
        *used += (size_t)n;
    else {
        *used = size - 1;
        memcpy(buf + size - 4, "...", 4);
    }
}

enum { SERIES_MAX = 300 }; /* bytes of a series name, "..." when cut */

/* The sweep on the x axis: the first --sweep. With several --scene the scenes are sweep 0
   (file names, never numbers: with them on the axis nothing could be plotted) and each
   scene is a series; scenes alone are numbered on the axis. */
static int x_sweep(const struct bench *b)
{
    return b->scene_axis && b->n > 1 ? 1 : 0;
}

/* A successful cell as a plot point: x the x sweep's value (must be a number; a scene's
   index), series the other sweeps' values, label every value; 0 when it is none. */
static int plot_point(const struct bench *b, int ci, const char *err_name,
                      struct ssg_plot_point *p, char *series)
{
    const struct cell *c = &b->cells[ci];
    const int xk = x_sweep(b);
    char *end = NULL;
    if (!c->ran || !c->ok)
        return 0;
    double x = !b->n ? ci : b->scene_axis && xk == 0 ? c->index[0]
                                                      : strtod(ssg_bench_value(b, c, xk), &end);
    if (end && *end)
        return 0;
    size_t used = 0;
    series[0] = '\0';
    for (int k = 0; k < b->n; k++)
        if (k != xk)
            append(series, SERIES_MAX, &used, "%s%s=%s", used ? " " : "", b->sweeps[k].key,
                   ssg_bench_value(b, c, k));
    if (b->n < 2)
        append(series, SERIES_MAX, &used, "%s", b->req->time_node ? b->req->time_node
                                                                  : "frame");
    struct ssg_bench_ms ms = ssg_bench_shown_ms(b, c);
    *p = (struct ssg_plot_point){.x = x, .ms = ms.median, .lo = ms.min, .hi = ms.max,
                                 .err = error_of(c, err_name), .series = series};
    used = 0;
    for (int k = 0; k < b->n; k++)
        append(p->label, sizeof p->label, &used, "%s%s", k ? "," : "", ssg_bench_value(b, c, k));
    return 1;
}

/* bench_ms.png, and bench_pareto.png when cells have the error metric (err_name, named on
   its axis); *rc becomes 1 when one fails. */
static void draw_both(const struct bench *b, const char *err_name, struct ssg_plot_point *pts,
                      int n, int *rc)
{
    const char *what = b->req->time_node ? b->req->time_node : "frame";
    char title[600], ms_label[300];
    const char *x_name = b->n ? b->sweeps[x_sweep(b)].key : "cell";
    snprintf(title, sizeof title, "%s: ms against %s", b->req->graph, x_name);
    snprintf(ms_label, sizeof ms_label, "ms (%s, median; bars: fastest to slowest)", what);
    int ms_rc = ssg_plot_ms(b->req->out_dir, "bench_ms", title, x_name, ms_label, pts, n);
    *rc |= ms_rc;
    if (!ms_rc && !b->req->quiet)
        printf("wrote %s/bench_ms.png\n", b->req->out_dir);
    int errors = 0;
    for (int i = 0; i < n; i++)
        errors += !isnan(pts[i].err);
    if (!errors) {
        if (!b->req->quiet)
            fprintf(stderr, "bench: no %s in the cells: no Pareto plot (add a compare node)\n",
                    err_name[0] ? err_name : "metric");
        return;
    }
    snprintf(title, sizeof title, "%s: error against ms (Pareto view)", b->req->graph);
    snprintf(ms_label, sizeof ms_label, "ms (%s, median)", what);
    int pareto_rc = ssg_plot_pareto(b->req->out_dir, "bench_pareto", title, ms_label,
                                    err_name, pts, n);
    *rc |= pareto_rc;
    if (!pareto_rc && !b->req->quiet)
        printf("wrote %s/bench_pareto.png\n", b->req->out_dir);
}

int ssg_bench_draw_plots(const struct bench *b)
{
    struct ssg_plot_point *pts = calloc((size_t)b->cell_count + 1, sizeof *pts);
    char *series = calloc((size_t)b->cell_count + 1, SERIES_MAX);
    char err_name[200];
    error_name(b, err_name, sizeof err_name);
    int n = 0, rc = 0;
    for (int ci = 0; pts && series && ci < b->cell_count; ci++)
        n += plot_point(b, ci, err_name, &pts[n], series + (size_t)n * SERIES_MAX);
    if (n == 0) {
        fprintf(stderr, "ssgraph: error: nothing to plot (no finished cell, or the values "
                "of --sweep %s are not numbers)\n", b->n ? b->sweeps[x_sweep(b)].key : "");
        rc = 1;
    } else {
        qsort(pts, (size_t)n, sizeof *pts, by_series);
        draw_both(b, err_name, pts, n, &rc);
    }
    free(pts);
    free(series);
    return rc;
}
