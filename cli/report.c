/* report.c - printing a graph run's statistics, progress and notices (report.h). The
 * formats are those the library printed before it handed them out, column for column:
 * scripts (bench/bench.py) and tests read them. */
#include <stdio.h>
#include <string.h>

#include "peak.h"
#include "report.h"
#include "ssgraph.h"

enum { BAR = 30 }; /* width of the progress bar in characters */

/* The libraries the process loaded once (graph/profile.h), each on a line of its own after
   the nodes, so that no node is charged for them: "load  OpenImageIO module  452.10". */
static void print_loads(FILE *f, int name_width)
{
    struct ssg_load l[SSG_LOADS_MAX];
    int n = ssg_loads(l, SSG_LOADS_MAX);
    for (int i = 0; i < n; i++)
        fprintf(f, "%-*s %-17s %10.2f\n", name_width, "load", l[i].what, l[i].ms);
}

/* One frame: every node's last run, the one-off loads, then the whole run's wall clock. */
static void print_timings(const struct ssg_run_stats *s, FILE *f)
{
    fprintf(f, "%-16s %-12s %-4s %10s %10s %10s  %s\n", "node", "type", "on", "ms", "gpu ms",
            "xfer ms", "why");
    for (int i = 0; i < s->node_count; i++) {
        const struct ssg_run_node *n = &s->nodes[i];
        char gpu[32] = "-", xfer[32] = "-";
        if (!strcmp(n->backend, "gl"))
            snprintf(gpu, sizeof gpu, "%.2f", n->gpu_ms);
        if (n->transfer_ms > 0)
            snprintf(xfer, sizeof xfer, "%.2f", n->transfer_ms);
        if (n->kept) /* its outputs stood: no time of this run */
            fprintf(f, "%-16s %-12s %-4s %10s %10s %10s  %s\n", n->name, n->type, n->backend,
                    "-", "-", "-", n->why);
        else
            fprintf(f, "%-16s %-12s %-4s %10.2f %10s %10s  %s\n", n->name, n->type,
                    n->backend, n->ms, gpu, xfer, n->why);
    }
    print_loads(f, 16);
    fprintf(f, "%-16s %-12s %-4s %10.2f %10s %10s   (%dx%d, %d threads, peak images %.1f MB)\n",
            "total", "", "", s->total_ms, "", "", s->width, s->height, s->threads,
            (double)s->peak_pool_bytes / (1024.0 * 1024.0));
}

/* A node ran or was kept in every frame: a pass, under the frame in the tree; else a
   sink. */
static int in_frame(const struct ssg_run_stats *s, const struct ssg_run_node *n)
{
    return n->calls + n->kept == s->frames;
}

/* The roofline columns of a row: GB/s, GFLOP/s, bound and the fraction of it. */
static void rate_columns(const struct ssg_run_stats *s, const struct ssg_run_node *n,
                         const struct ssg_peak *peak, char *out, size_t len)
{
    struct ssg_rates r;
    char gflops[32] = "-", frac[16] = "-";
    ssg_rates_of(n, s->threads, peak, &r);
    if (r.gflops >= 0)
        snprintf(gflops, sizeof gflops, "%.2f", r.gflops);
    if (r.fraction >= 0)
        snprintf(frac, sizeof frac, "%.0f%%", 100.0 * r.fraction);
    snprintf(out, len, " %8.2f %8s %-7s %6s", r.gbps, gflops, r.bound ? r.bound : "-", frac);
}

static void print_profile_row(const struct ssg_run_stats *s, const struct ssg_run_node *n,
                              const struct ssg_peak *peak, FILE *f)
{
    char gpu[32] = "-", share[16] = "     -", name[64], rates[80];
    if (!strcmp(n->backend, "gl"))
        snprintf(gpu, sizeof gpu, "%.2f", n->gpu_avg_ms);
    if (n->calls == s->frames && s->frame_avg_ms > 0)
        snprintf(share, sizeof share, "%5.1f%%", 100.0 * n->share);
    snprintf(name, sizeof name, "%s%s", in_frame(s, n) ? "  " : "", n->name);
    rate_columns(s, n, peak, rates, sizeof rates);
    fprintf(f, "%-18s %-12s %-4s %6d %10.2f %10.2f %10.2f %7s %10s %10.2f%s  %s\n", name,
            n->type, n->backend, n->calls, n->avg_ms, n->min_ms, n->max_ms, share, gpu,
            n->prepare_ms, rates, n->why);
}

/* A profiler's tree: the frame at the root, the passes under it, then the sinks that ran
   once after the last frame; last, the peaks the bound column used. */
static void print_profile(const struct ssg_run_stats *s, FILE *f)
{
    double frame = s->frame_avg_ms;
    struct ssg_peak peak;
    char path[4096] = "";
    int have_peak = ssg_peak_load(&peak);
    ssg_peak_path(path, sizeof path);
    fprintf(f, "%-18s %-12s %-4s %6s %10s %10s %10s %7s %10s %10s %8s %8s %-7s %6s  %s\n",
            "node", "type", "on", "calls", "avg ms", "min ms", "max ms", "share", "gpu ms",
            "prepare ms", "GB/s", "GFLOP/s", "bound", "%bound", "why");
    double median = s->frame_median_ms;
    fprintf(f, "%-18s %-12s %-4s %6d %10.2f %10.2f %10.2f %6.1f%%   (%dx%d, %d threads, "
            "%.1f fps; median frame %.2f ms, %.1f fps)\n", "frame", "", "", s->frames, frame,
            s->frame_min_ms, s->frame_max_ms, 100.0, s->width, s->height, s->threads,
            frame > 0 ? 1000.0 / frame : 0.0, median, median > 0 ? 1000.0 / median : 0.0);
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < s->node_count; i++)
            if (in_frame(s, &s->nodes[i]) == !pass)
                print_profile_row(s, &s->nodes[i], have_peak ? &peak : NULL, f);
    print_loads(f, 18);
    if (have_peak)
        fprintf(f, "bound: each image read or written once against %.1f GB/s, declared flops "
                "against %.1f GFLOP/s (%d threads; %s)\n", peak.gbps, peak.gflops,
                peak.threads, path);
    else
        fprintf(f, "bound: no peaks measured (run the build's `peak` once; it caches them in "
                "%s)\n", path[0] ? path : "$SSGRAPH_PEAK");
}

static void print_metrics(const struct ssg_run_stats *s, FILE *f)
{
    if (s->metric_count == 0)
        return;
    fprintf(f, "%-16s %-12s %12s\n", "metrics of", "name", "value");
    for (int i = 0; i < s->metric_count; i++) {
        const struct ssg_run_metric *m = &s->metrics[i];
        fprintf(f, "%-16s %-12s %12.6g\n", m->node, m->name, m->value);
    }
}

void ssg_report_print(const struct ssg_run_stats *s, FILE *f)
{
    if (s->frames > 1)
        print_profile(s, f);
    else
        print_timings(s, f);
    if (s->gl)
        fprintf(f, "GL: %s\n", s->gl);
    print_metrics(s, f);
}

/* "loads": the process's one-off library loads, each with its ms (graph/profile.h). */
static void write_loads_json(FILE *f)
{
    struct ssg_load l[SSG_LOADS_MAX];
    int n = ssg_loads(l, SSG_LOADS_MAX);
    fputs("  \"loads\": [", f);
    for (int i = 0; i < n; i++)
        fprintf(f, "%s{\"what\": \"%s\", \"ms\": %.6g}", i ? ", " : "", l[i].what, l[i].ms);
    fputs("]\n", f);
}

static void write_json(FILE *f, const void *user)
{
    const struct ssg_run_stats *s = user;
    struct ssg_peak peak;
    int have_peak = ssg_peak_load(&peak);
    fprintf(f, "{\n  \"frames\": %d, \"width\": %d, \"height\": %d, \"threads\": %d,\n",
            s->frames, s->width, s->height, s->threads);
    fprintf(f, "  \"frame\": {\"avg_ms\": %.6g, \"min_ms\": %.6g, \"max_ms\": %.6g, "
            "\"median_ms\": %.6g},\n", s->frame_avg_ms, s->frame_min_ms, s->frame_max_ms,
            s->frame_median_ms);
    if (have_peak)
        fprintf(f, "  \"peak\": {\"threads\": %d, \"gflops\": %.6g, \"gbps\": %.6g},\n",
                peak.threads, peak.gflops, peak.gbps);
    else
        fputs("  \"peak\": null,\n", f);
    fputs("  \"nodes\": [", f);
    for (int i = 0; i < s->node_count; i++) {
        const struct ssg_run_node *n = &s->nodes[i];
        char share[32] = "null"; /* sinks run once, outside the frame */
        char flops[32] = "null", gflops[32] = "null", bound[16] = "null", frac[32] = "null";
        struct ssg_rates r;
        ssg_rates_of(n, s->threads, have_peak ? &peak : NULL, &r);
        if (n->flops >= 0) {
            snprintf(flops, sizeof flops, "%.0f", n->flops);
            snprintf(gflops, sizeof gflops, "%.6g", r.gflops);
        }
        if (r.bound) {
            snprintf(bound, sizeof bound, "\"%s\"", r.bound);
            snprintf(frac, sizeof frac, "%.6g", r.fraction);
        }
        if (n->calls == s->frames && s->frame_avg_ms > 0)
            snprintf(share, sizeof share, "%.6g", n->share);
        fprintf(f, "%s\n    {\"name\": \"%s\", \"type\": \"%s\", \"backend\": \"%s\", "
                "\"calls\": %d, \"avg_ms\": %.6g, \"min_ms\": %.6g, \"max_ms\": %.6g, "
                "\"median_ms\": %.6g, \"share\": %s, \"gpu_avg_ms\": %.6g, \"transfer_avg_ms\": %.6g, "
                "\"prepare_ms\": %.6g, \"bytes\": %.0f, \"flops\": %s, \"gbps\": %.6g, "
                "\"gflops\": %s, \"bound\": %s, \"fraction_of_bound\": %s, \"kept\": %d, "
                "\"why\": \"%s\"}",
                i ? "," : "", n->name, n->type, n->backend, n->calls, n->avg_ms, n->min_ms,
                n->max_ms, n->median_ms, share, n->gpu_avg_ms, n->transfer_avg_ms, n->prepare_ms, n->bytes,
                flops, r.gbps, gflops, bound, frac, n->kept, n->why);
    }
    fputs("\n  ],\n", f);
    write_loads_json(f);
    fputs("}\n", f);
}

enum ssg_err ssg_report_write_json(const struct ssg_run_stats *stats, const char *path,
                                   struct ssg_diags *diags)
{
    return ssg_write_text_stream(path, "profile", write_json, stats, diags);
}

/* The library reports each rise of the whole percentage, so every event is drawn; the
   last one ends the bar's line. */
void ssg_report_progress(void *user, const struct ssg_progress_event *event)
{
    (void)user;
    int pct = (int)(event->fraction * 100.0 + 1e-6);
    char bar[BAR + 1];
    for (int i = 0; i < BAR; i++)
        bar[i] = i < pct * BAR / 100 ? '#' : '.';
    bar[BAR] = '\0';
    fprintf(stderr, "\r%s '%s' [%s] %3d%%", event->type, event->instance, bar, pct);
    if (event->done)
        fputc('\n', stderr);
    fflush(stderr);
}

void ssg_report_log(void *user, const char *line)
{
    (void)user;
    printf("%s\n", line);
    fflush(stdout); /* a long run's files are named as they appear, also through a pipe */
}
