/* tune_out.c - what `ssgraph tune` prints and writes (tune_state.h): a line per
 * evaluation, the best setting at the end, and tune.csv, tune.json and tuned.graph after
 * every evaluation. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ssgraph.h"
#include "text_out.h"
#include "tune_state.h"

void ssg_tune_format(const struct tune_param *p, double v, char *buf, size_t len)
{
    if (p->integer)
        snprintf(buf, len, "%.0f", round(v));
    else
        snprintf(buf, len, "%.6g", v);
}

void ssg_tune_scene_name(const struct tune *t, int s, char *buf, size_t len)
{
    const char *path = t->scenes[s];
    if (!path) {
        snprintf(buf, len, "scene");
        return;
    }
    const char *base = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    const char *dot = strrchr(base, '.');
    snprintf(buf, len, "%.*s", (int)(dot && dot != base ? dot - base : (long)strlen(base)),
             base);
}

/* "h.bias=0.05 h.strength=1.2" */
static void values_text(const struct tune *t, const struct tune_eval *ev, char *buf,
                        size_t len)
{
    size_t used = 0;
    buf[0] = 0;
    for (int k = 0; k < t->n && used < len; k++) {
        char value[64];
        ssg_tune_format(&t->params[k], ev->values[k], value, sizeof value);
        used += (size_t)snprintf(buf + used, len - used, "%s%s=%s", k ? " " : "",
                                 t->params[k].key, value);
    }
}

void ssg_tune_print_eval(const struct tune *t, int i, FILE *f)
{
    const struct tune_eval *ev = &t->evals[i];
    char values[1200];
    values_text(t, ev, values, sizeof values);
    fprintf(f, "tune: eval %d/%d %s |", i + 1, t->budget, values);
    for (int s = 0; s < t->scene_count && isfinite(ev->errors[s]); s++) {
        char name[256];
        ssg_tune_scene_name(t, s, name, sizeof name);
        fprintf(f, " %s %.6f", name, ev->errors[s]);
    }
    if (ev->error[0])
        fprintf(f, " FAILED: %s\n", ev->error);
    else
        fprintf(f, " | mean %.6f%s\n", ev->mean, t->best == i ? " (best)" : "");
}

void ssg_tune_print_best(const struct tune *t, FILE *f)
{
    const struct tune_eval *best = &t->evals[t->best], *start = &t->evals[0];
    char values[1200];
    values_text(t, best, values, sizeof values);
    fprintf(f, "tune: best of %d evaluations (eval %d): %s\n", t->count, t->best + 1, values);
    for (int s = 0; s < t->scene_count; s++)
        fprintf(f, "  %-40s %.6f  (start %.6f)\n", t->scenes[s] ? t->scenes[s] : "scene",
                best->errors[s], start->errors[s]);
    fprintf(f, "  %-40s %.6f  (start %.6f, %+.1f%%)\n", "mean", best->mean, start->mean,
            start->mean > 0 ? 100.0 * (best->mean - start->mean) / start->mean : 0.0);
}

static void write_csv(FILE *f, const void *user)
{
    const struct tune *t = user;
    fputs("eval", f);
    for (int k = 0; k < t->n; k++)
        fprintf(f, ",%s", t->params[k].key);
    for (int s = 0; s < t->scene_count; s++) {
        fputc(',', f);
        ssg_csv_field(f, t->scenes[s] ? t->scenes[s] : "scene");
    }
    fputs(",mean,status,error\n", f);
    for (int i = 0; i < t->count; i++) {
        const struct tune_eval *ev = &t->evals[i];
        fprintf(f, "%d", i + 1);
        for (int k = 0; k < t->n; k++) {
            char value[64];
            ssg_tune_format(&t->params[k], ev->values[k], value, sizeof value);
            fprintf(f, ",%s", value);
        }
        for (int s = 0; s < t->scene_count; s++)
            isfinite(ev->errors[s]) ? fprintf(f, ",%.9g", ev->errors[s]) : fputs(",", f);
        isfinite(ev->mean) ? fprintf(f, ",%.9g", ev->mean) : fputs(",", f);
        fprintf(f, ",%s,", ev->error[0] ? "error" : "ok");
        ssg_csv_field(f, ev->error);
        fputc('\n', f);
    }
}

/* {"h.bias": 0.05, ...} and {"examples/a.scene": 0.04, ...} of one evaluation. */
static void json_eval(const struct tune *t, int i, FILE *f)
{
    const struct tune_eval *ev = &t->evals[i];
    fprintf(f, "{\"eval\": %d, \"values\": {", i + 1);
    for (int k = 0; k < t->n; k++) {
        fputs(k ? ", " : "", f);
        ssg_json_string(f, t->params[k].key);
        fputs(": ", f);
        ssg_json_number(f, ev->values[k]);
    }
    fputs("}, \"errors\": {", f);
    for (int s = 0; s < t->scene_count; s++) {
        fputs(s ? ", " : "", f);
        ssg_json_string(f, t->scenes[s] ? t->scenes[s] : "scene");
        fputs(": ", f);
        ssg_json_number(f, ev->errors[s]);
    }
    fputs("}, \"mean\": ", f);
    ssg_json_number(f, ev->mean);
    fputs(", \"error\": ", f);
    ssg_json_string(f, ev->error);
    fputc('}', f);
}

static void json_params(const struct tune *t, FILE *f)
{
    fputs("  \"params\": [", f);
    for (int k = 0; k < t->n; k++) {
        const struct tune_param *p = &t->params[k];
        fprintf(f, "%s\n    {\"key\": ", k ? "," : "");
        ssg_json_string(f, p->key);
        fprintf(f, ", \"lo\": %.9g, \"hi\": %.9g, \"log\": %s, \"integer\": %s, \"start\": "
                "%.9g}", p->lo, p->hi, p->log ? "true" : "false",
                p->integer ? "true" : "false", p->start);
    }
    fputs("\n  ],\n", f);
}

static void write_json(FILE *f, const void *user)
{
    const struct tune *t = user;
    const struct ssg_tune_request *q = t->req;
    const char *fields[4][2] = {{"graph", q->graph}, {"reference", q->reference},
                                {"image", q->image}, {"mask", q->mask ? q->mask : ""}};
    fputs("{\n", f);
    for (int i = 0; i < 4; i++) {
        fprintf(f, "  \"%s\": ", fields[i][0]);
        ssg_json_string(f, fields[i][1]);
        fputs(",\n", f);
    }
    fputs("  \"scenes\": [", f);
    for (int s = 0; s < t->scene_count; s++) {
        fputs(s ? ", " : "", f);
        ssg_json_string(f, t->scenes[s] ? t->scenes[s] : "scene");
    }
    fputs("],\n", f);
    json_params(t, f);
    fprintf(f, "  \"budget\": %d,\n  \"evals\": [", t->budget);
    for (int i = 0; i < t->count; i++) {
        fputs(i ? ",\n    " : "\n    ", f);
        json_eval(t, i, f);
    }
    fputs(t->count ? "\n  ],\n  \"best\": " : "],\n  \"best\": ", f);
    if (t->best >= 0)
        json_eval(t, t->best, f);
    else
        fputs("null", f);
    fputs("\n}\n", f);
}

/* The graph by its absolute path (tuned.graph need not sit beside it), the user's --set
   lines and the best values as set lines, and the frame directives the tune used, so that
   running it with one of the scenes gives that scene's error. */
/* The path of file `to` as seen from folder `from` (both absolute, without "." or ".."
   parts): "../graphs/ssao.graph". An include names the graph relative to tuned.graph, so
   the output folder and the repository can move together (an absolute include broke on
   any other machine). */
static void relative_path(const char *from, const char *to, char *out, size_t len)
{
    char dir[4200];
    snprintf(dir, sizeof dir, "%s%s", from, strcmp(from, "/") ? "/" : "");
    size_t common = 0; /* the longest shared prefix that ends at a '/' */
    for (size_t i = 0; dir[i] && dir[i] == to[i]; i++)
        if (dir[i] == '/')
            common = i + 1;
    size_t used = 0;
    out[0] = 0;
    for (const char *p = dir + common; *p && used + 4 < len; p++)
        if (*p == '/')
            used += (size_t)snprintf(out + used, len - used, "../");
    snprintf(out + used, len - used, "%s", to + common);
}

/* q->graph as tuned.graph in out_dir must include it: relative when both resolve, else
   as given. Written as a graph string: '"' and '\' escaped. */
static void include_line(FILE *f, const struct ssg_tune_request *q)
{
    char graph[4096], dir[4096], rel[8192];
    if (realpath(q->graph, graph) && realpath(q->out_dir, dir))
        relative_path(dir, graph, rel, sizeof rel);
    else
        snprintf(rel, sizeof rel, "%s", q->graph);
    fputs("include \"", f);
    for (const char *p = rel; *p; p++) {
        if (*p == '"' || *p == '\\')
            fputc('\\', f);
        fputc(*p, f);
    }
    fputs("\"\n", f);
}

static void write_graph(FILE *f, const void *user)
{
    const struct tune *t = user;
    const struct ssg_tune_request *q = t->req;
    const struct tune_eval *best = &t->evals[t->best];
    fprintf(f, "# made by ssgraph tune: %s with the values of evaluation %d of %d, the lowest "
            "mean RMSE of %s against %s%s%s (%.6g) over:\n", q->graph, t->best + 1, t->count,
            q->image, q->reference, q->mask ? " over " : "", q->mask ? q->mask : "",
            best->mean);
    for (int s = 0; s < t->scene_count; s++)
        fprintf(f, "#   %s (%.6g)\n", t->scenes[s] ? t->scenes[s] : "its own scene",
                best->errors[s]);
    include_line(f, q);
    if (q->ov->width > 0)
        fprintf(f, "size %d %d\n", q->ov->width, q->ov->height);
    if (q->ov->seed >= 0)
        fprintf(f, "seed %lld\n", (long long)q->ov->seed);
    if (q->ov->backend)
        fprintf(f, "backend %s\n", q->ov->backend);
    for (int i = 0; i < q->ov->set_count; i++)
        fprintf(f, "set %s\n", q->ov->sets[i]);
    for (int k = 0; k < t->n; k++) {
        char value[64];
        ssg_tune_format(&t->params[k], best->values[k], value, sizeof value);
        fprintf(f, "set %s = %s\n", t->params[k].key, value);
    }
}

enum ssg_err ssg_tune_save(const struct tune *t, struct ssg_diags *d)
{
    char path[1100];
    snprintf(path, sizeof path, "%s/tune.csv", t->req->out_dir);
    enum ssg_err e = ssg_write_text_file(path, "tune table", write_csv, t, d);
    snprintf(path, sizeof path, "%s/tune.json", t->req->out_dir);
    if (!e)
        e = ssg_write_text_file(path, "tune results", write_json, t, d);
    snprintf(path, sizeof path, "%s/tuned.graph", t->req->out_dir);
    if (!e && t->best >= 0)
        e = ssg_write_text_file(path, "tuned graph", write_graph, t, d);
    return e;
}
