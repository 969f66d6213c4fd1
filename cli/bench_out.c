/* bench_out.c - what `ssgraph bench` writes of its cells (bench_cells.h): bench.csv,
 * bench.json and bench.md after every cell, and the gnuplot pictures at the end. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench_cells.h"
#include "lang/files.h"
#include "plot.h"
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
        ssg_csv_field(f, ssg_bench_value(b, c, k));
    }
    fprintf(f, ",%s,%d,%.4f,%.4f,%.4f,", c->ok ? "ok" : "error", c->stats.frames,
            c->stats.frame_avg_ms, c->stats.frame_min_ms, c->stats.frame_max_ms);
    ssg_csv_field(f, nodes);
    fputc(',', f);
    ssg_csv_field(f, metrics);
    fputc(',', f);
    ssg_csv_field(f, c->ok ? "" : c->error);
    fputc('\n', f);
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
    fprintf(f, "}, \"status\": \"%s\", \"frames\": %d, \"frame_avg_ms\": %.6g, "
            "\"frame_min_ms\": %.6g, \"frame_max_ms\": %.6g, \"metrics\": {",
            c->ok ? "ok" : "error", c->stats.frames, c->stats.frame_avg_ms,
            c->stats.frame_min_ms, c->stats.frame_max_ms);
    for (int i = 0; i < c->stats.metric_count; i++) {
        const struct ssg_run_metric *m = &c->stats.metrics[i];
        fprintf(f, "%s\"%s.%s\": ", i ? ", " : "", m->node, m->name);
        /* exact, so that a merge writes the same tables; JSON has no infinity (the PSNR of
           identical images): "inf", "-inf" and "nan" are strings */
        fprintf(f, isfinite(m->value) ? "%.17g" : "\"%g\"", m->value);
    }
    fputs("}, \"node_ms\": {", f);
    for (int i = 0; i < c->stats.node_count; i++)
        fprintf(f, "%s\"%s\": %.6g", i ? ", " : "", c->stats.nodes[i].name,
                c->stats.nodes[i].avg_ms);
    fputs("}, \"error\": ", f);
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

double ssg_bench_shown_ms(const struct bench *b, const struct cell *c)
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
    fprintf(f, " %.2f ms", ssg_bench_shown_ms(b, c));
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
                if (b->cells[ci].ran)
                    md_cell(b, &b->cells[ci], f);
                else
                    fputs(" |", f);
            }
        }
        fputc('\n', f);
    }
}

static void write_csv(FILE *f, const void *user)
{
    const struct bench *b = user;
    csv_header(b, f);
    for (int ci = 0; ci < b->cell_count; ci++)
        if (b->cells[ci].ran)
            csv_row(b, ci, f);
}

enum ssg_err ssg_bench_save(const struct bench *b, struct ssg_diags *d)
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
    for (int ci = 0; ci < b->cell_count; ci++) {
        const struct cell *c = &b->cells[ci];
        char *end;
        if (!c->ran)
            continue;
        double x = b->n ? strtod(ssg_bench_value(b, c, 0), &end) : ci;
        if (!c->ok || (b->n && *end))
            continue;
        size_t used = 0;
        series[n][0] = 0;
        for (int k = 1; k < b->n; k++)
            used += (size_t)snprintf(series[n] + used, 300 - used, "%s%s=%s", k > 1 ? " " : "",
                                     b->sweeps[k].key, ssg_bench_value(b, c, k));
        if (b->n < 2)
            snprintf(series[n], 300, "%s", b->req->time_node ? b->req->time_node : "frame");
        pts[n] = (struct ssg_plot_point){
            .x = x, .ms = ssg_bench_shown_ms(b, c), .err = error_of(b, c), .series = series[n]};
        used = 0;
        for (int k = 0; k < b->n; k++)
            used += (size_t)snprintf(pts[n].label + used, sizeof pts[n].label - used, "%s%s",
                                     k ? "," : "", ssg_bench_value(b, c, k));
        n++;
    }
    return n;
}

int ssg_bench_draw_plots(const struct bench *b)
{
    struct ssg_plot_point *pts = calloc((size_t)b->cell_count + 1, sizeof *pts);
    char(*series)[300] = calloc((size_t)b->cell_count + 1, sizeof *series);
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
        int ms_rc = ssg_plot_ms(b->req->out_dir, "bench_ms", title,
                                b->n ? b->sweeps[0].key : "cell", ylabel, pts, n);
        rc |= ms_rc;
        if (!ms_rc && !b->req->quiet)
            printf("wrote %s/bench_ms.png\n", b->req->out_dir);
        int errors = 0;
        for (int i = 0; i < n; i++)
            errors += !isnan(pts[i].err);
        snprintf(title, sizeof title, "%s: error against ms (Pareto view)", b->req->graph);
        int pareto_rc = errors ? ssg_plot_pareto(b->req->out_dir, "bench_pareto", title,
                                                 b->req->error_metric ? b->req->error_metric
                                                                      : "first metric", pts, n)
                               : 0;
        rc |= pareto_rc;
        if (errors && !pareto_rc && !b->req->quiet)
            printf("wrote %s/bench_pareto.png\n", b->req->out_dir);
        else if (!errors && !b->req->quiet)
            fprintf(stderr, "bench: no %s in the cells: no Pareto plot (add a compare node)\n",
                    b->req->error_metric ? b->req->error_metric : "metric");
    }
    free(pts);
    free(series);
    return rc;
}
