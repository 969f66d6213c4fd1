/* tune.c - `ssgraph tune GRAPH --reference NODE.PORT --image NODE.PORT --param
 * node.p=lo:hi[:log] ... --scene A --scene B ...`: finds the parameter values with the
 * lowest mean error of the image against the reference over the scenes.
 *
 * The error of a scene is the RMSE of the compare node (as bench --reference reports it),
 * over the --mask pixels when one is given. The reference (and the mask) of each scene is
 * computed once, before the search, by loading the graph with only those outputs
 * requested (ssg_overrides.outputs): a 256-ray reference_ao costs far more than the AO being
 * tuned. Each scene's graph is then loaded once, with only the image requested, and kept
 * live (ssg_graph_keep): an evaluation sets the values (ssg_graph_set) and runs it, so only
 * the tuned nodes and what follows them run again, and the graph's own writes, compares
 * and reference never do; the bytes are those of a fresh load with the values as --set
 * lines (tests/test_live.c). A parameter of a node the reference reads is refused: the
 * cached reference would be wrong.
 *
 * Bad input is found before the first evaluation and exits 1 with the graph's own message:
 * a parameter the graph lacks or that is no number, a range it refuses, a port it lacks, a
 * scene that does not load (the tune stops rather than skip it: a mean over fewer scenes
 * is another objective). An evaluation that fails later is recorded with its message and
 * stops the tune (exit 1); the files keep every evaluation before it. The search itself is
 * tune_search.c; the printing and the files tune_out.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "report.h"
#include "ssgraph.h"
#include "tune_search.h"
#include "tune_state.h"

enum { DEFAULT_EVALS = 40, EXIT_INVALID = 1, EXIT_USAGE = 2 };

static int refuse(const char *what, const char *spec, const char *why)
{
    fprintf(stderr, "ssgraph: error: %s '%s': %s\n", what, spec, why);
    return 0;
}

/* "node.p=lo:hi[:log]" into p (key, range, scale); 0 with a message when malformed. */
static int parse_param(const char *spec, struct tune_param *p)
{
    const char *eq = strchr(spec, '=');
    size_t klen = eq ? (size_t)(eq - spec) : 0;
    if (!eq || !klen || klen >= sizeof p->key || !memchr(spec, '.', klen))
        return refuse("--param", spec, "expected node.param=lo:hi or node.param=lo:hi:log");
    memcpy(p->key, spec, klen);
    p->key[klen] = 0;
    char *end;
    p->lo = strtod(eq + 1, &end);
    if (end == eq + 1 || *end != ':')
        return refuse("--param", spec, "expected a number lo, then ':hi'");
    const char *hi = end + 1;
    p->hi = strtod(hi, &end);
    if (end == hi || (*end && strcmp(end, ":log")))
        return refuse("--param", spec, "expected a number hi, then nothing or ':log'");
    p->log = *end != 0;
    if (!isfinite(p->lo) || !isfinite(p->hi) || !(p->lo < p->hi))
        return refuse("--param", spec, "empty or reversed range (expected lo < hi)");
    if (p->log && !(p->lo > 0))
        return refuse("--param", spec, "a log range needs lo > 0");
    return 1;
}

/* The value of unit coordinate u in p's range (log-mapped when asked), rounded as the
   graph will read it: integers to integers, decimals to 6 significant digits. */
static double param_value(const struct tune_param *p, double u)
{
    double v = p->log ? p->lo * pow(p->hi / p->lo, u) : p->lo + u * (p->hi - p->lo);
    char text[64];
    ssg_tune_format(p, v < p->lo ? p->lo : v > p->hi ? p->hi : v, text, sizeof text);
    return strtod(text, NULL);
}

static double param_unit(const struct tune_param *p, double v)
{
    double u = p->log ? log(v / p->lo) / log(p->hi / p->lo) : (v - p->lo) / (p->hi - p->lo);
    return u < 0 ? 0 : u > 1 ? 1 : u;
}

/* The search's snap: each coordinate moved onto the value the graph really gets, so two
   points that round alike are one point (evaluated once). */
static void snap(void *user, double *x)
{
    const struct tune *t = user;
    for (int k = 0; k < t->n; k++)
        x[k] = param_unit(&t->params[k], param_value(&t->params[k], x[k]));
}

/* The graph loaded with ov and run, the requested outputs into images; *stats (if not
   NULL) what ran. */
static enum ssg_err run_outputs(const struct tune *t, const struct ssg_overrides *ov,
                                struct ssg_image **images, struct ssg_run_stats *stats,
                                struct ssg_diags *d)
{
    struct ssg_run_options ro = {.out_dir = t->req->out_dir, .threads = t->req->threads,
                                 .stats = stats, .outputs = images,
                                 .progress = isatty(fileno(stderr)) ? ssg_report_progress
                                                                    : NULL};
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load(t->req->graph, ov, &g, d);
    if (!e)
        e = ssg_graph_run(g, &ro, d);
    ssg_graph_destroy(&g);
    return e;
}

/* The user's overrides for scene s, with extra --set lines after the user's own. */
struct tune_sets {
    const char *sets[256 + SSG_TUNE_MAX_PARAMS];
    char own[SSG_TUNE_MAX_PARAMS][200];
};

static struct ssg_overrides scene_overrides(const struct tune *t, int s, struct tune_sets *ts,
                                            int extra)
{
    const struct ssg_overrides *user = t->req->ov;
    int n = 0;
    for (int i = 0; i < user->set_count && n < 256; i++)
        ts->sets[n++] = user->sets[i];
    for (int k = 0; k < extra; k++)
        ts->sets[n++] = ts->own[k];
    struct ssg_overrides ov = *user;
    ov.scene = t->scenes[s];
    ov.sets = ts->sets;
    ov.set_count = n;
    return ov;
}

/* Stops with the graph's messages under a line saying what they are about. */
static int refused(const char *what, const struct ssg_diags *d)
{
    fprintf(stderr, "ssgraph: error: %s:\n", what);
    ssg_diags_print(d, stderr);
    return 0;
}

/* The graph loads with each scene (its text: meshes load with the references) and has
   the ports; each --param names a number parameter of the graph: its value with the
   first scene is the start, and an integer's range is rounded inwards. */
static int check_params(struct tune *t)
{
    const struct ssg_tune_request *q = t->req;
    const char *outs[3] = {q->image, q->reference, q->mask};
    struct tune_sets ts;
    struct ssg_overrides ov;
    struct ssg_diags d = {0};
    char what[1400];
    for (int s = t->scene_count - 1; s >= 0; s--) {
        ov = scene_overrides(t, s, &ts, 0);
        ov.outputs = outs;
        ov.output_count = q->mask ? 3 : 2;
        snprintf(what, sizeof what, "%s does not load with scene %s, --image %s, --reference "
                 "%s%s%s", q->graph, t->scenes[s] ? t->scenes[s] : "(its own)", q->image,
                 q->reference, q->mask ? ", --mask " : "", q->mask ? q->mask : "");
        if (ssg_graph_check(q->graph, &ov, &d))
            return refused(what, &d);
    }
    struct ssg_graph *g = NULL;
    ov.output_count = 1; /* ov is the first scene's */
    if (ssg_graph_load(q->graph, &ov, &g, &d))
        return refused(what, &d);
    int ok = 1;
    for (int k = 0; k < t->n && ok; k++) {
        struct tune_param *p = &t->params[k];
        snprintf(what, sizeof what, "--param %s", q->params[k]);
        ok = ssg_graph_param(g, p->key, &p->start, &p->integer, &d) == SSG_OK ||
             refused(what, &d);
        if (ok && p->integer) {
            p->lo = ceil(p->lo);
            p->hi = floor(p->hi);
            if (!(p->lo < p->hi))
                ok = refuse("--param", q->params[k], "an integer parameter needs two "
                            "integers in its range (expected lo < hi after rounding)");
        }
    }
    ssg_graph_destroy(&g);
    return ok;
}

/* Both ends of every range are values the graph accepts (its parameter's own range). */
static int check_ranges(struct tune *t)
{
    for (int k = 0; k < t->n; k++) {
        for (int end = 0; end < 2; end++) {
            struct tune_sets ts;
            char value[64];
            ssg_tune_format(&t->params[k], end ? t->params[k].hi : t->params[k].lo, value,
                            sizeof value);
            snprintf(ts.own[0], sizeof ts.own[0], "%s=%s", t->params[k].key, value);
            struct ssg_overrides ov = scene_overrides(t, 0, &ts, 1);
            struct ssg_diags d = {0};
            char what[400];
            snprintf(what, sizeof what, "--param %s: the graph refuses %s",
                     t->req->params[k], value);
            if (ssg_graph_check(t->req->graph, &ov, &d))
                return refused(what, &d);
        }
    }
    return 1;
}

/* A tuned node among those the reference ran: its cached image would be stale. */
static int reference_independent(const struct tune *t, const struct ssg_run_stats *st)
{
    for (int k = 0; k < t->n; k++) {
        const char *key = t->params[k].key;
        size_t len = (size_t)(strchr(key, '.') - key);
        for (int i = 0; i < st->node_count; i++) {
            if (strlen(st->nodes[i].name) != len || strncmp(st->nodes[i].name, key, len))
                continue;
            fprintf(stderr, "ssgraph: error: --param %s: node '%.*s' is part of --reference "
                    "%s, which tune computes once (expected a parameter of a node only "
                    "--image reads)\n", key, (int)len, key, t->req->reference);
            return 0;
        }
    }
    return 1;
}

/* The reference (and mask) of every scene, once; a scene that fails stops the tune. */
static int compute_references(struct tune *t)
{
    const struct ssg_tune_request *q = t->req;
    const char *outs[2] = {q->reference, q->mask};
    for (int s = 0; s < t->scene_count; s++) {
        struct tune_sets ts;
        struct ssg_overrides ov = scene_overrides(t, s, &ts, 0);
        ov.outputs = outs;
        ov.output_count = q->mask ? 2 : 1;
        struct ssg_image *im[2] = {NULL, NULL};
        struct ssg_run_stats st = {0};
        struct ssg_diags d = {0};
        char name[256], what[600];
        ssg_tune_scene_name(t, s, name, sizeof name);
        snprintf(what, sizeof what, "the reference %s of scene %s", q->reference,
                 t->scenes[s] ? t->scenes[s] : "(the graph's)");
        int ok = run_outputs(t, &ov, im, &st, &d) == SSG_OK || refused(what, &d);
        ok = ok && reference_independent(t, &st);
        if (ok && q->verbose)
            fprintf(stderr, "tune: reference %s of %s: %.0f ms\n", q->reference, name,
                    st.total_ms);
        t->ref[s] = im[0];
        t->mask[s] = im[1];
        ssg_run_stats_free(&st);
        if (!ok)
            return 0;
    }
    return 1;
}

/* The compare node's RMSE of image against the reference of scene s (over its mask). */
static enum ssg_err scene_rmse(const struct tune *t, int s, const struct ssg_image *image,
                               double *rmse, struct ssg_diags *d)
{
    struct ssg_binding bind[3] = {{"a", image}, {"b", t->ref[s]}, {"mask", t->mask[s]}};
    const char *sets[1] = {"peak=1"};
    struct ssg_outputs out = {0};
    enum ssg_err e = ssg_node_run("compare", bind, t->mask[s] ? 3 : 2, sets, 1, NULL, &out, d);
    *rmse = NAN;
    for (int i = 0; !e && i < out.metric_count; i++)
        if (!strcmp(out.metric_names[i], "rmse"))
            *rmse = out.metric_values[i];
    ssg_outputs_release(&out);
    return e;
}

/* Scene s's live graph with the values of ts.own (n of them, "node.p=value") set, run,
   its image into *im. Loaded on first use with the user's overrides and only the image. */
static enum ssg_err run_live(struct tune *t, int s, const struct tune_sets *ts,
                             struct ssg_image **im, struct ssg_diags *d)
{
    enum ssg_err e = SSG_OK;
    if (!t->live[s]) {
        struct tune_sets own;
        struct ssg_overrides ov = scene_overrides(t, s, &own, 0);
        ov.outputs = &t->req->image;
        ov.output_count = 1;
        e = ssg_graph_load(t->req->graph, &ov, &t->live[s], d);
        if (!e)
            e = ssg_graph_keep(t->live[s], 0, d);
    }
    for (int k = 0; k < t->n && !e; k++) {
        char key[200];
        snprintf(key, sizeof key, "%s", ts->own[k]);
        char *eq = strchr(key, '=');
        *eq = 0;
        e = ssg_graph_set(t->live[s], key, eq + 1, d);
    }
    struct ssg_run_options ro = {.out_dir = t->req->out_dir, .threads = t->req->threads,
                                 .outputs = im,
                                 .progress = isatty(fileno(stderr)) ? ssg_report_progress
                                                                    : NULL};
    return e ? e : ssg_graph_run(t->live[s], &ro, d);
}

/* The evaluation's failure as one line: the first message with its place. */
static void record_failure(struct tune_eval *ev, enum ssg_err e, const struct ssg_diags *d,
                           const char *scene)
{
    const struct ssg_diag *m = d->count ? &d->items[0] : NULL;
    if (m && m->line)
        snprintf(ev->error, sizeof ev->error, "%.200s: %s:%d:%d: %s", scene, m->file, m->line,
                 m->column, m->message);
    else
        snprintf(ev->error, sizeof ev->error, "%.200s: %s", scene, m ? m->message : ssg_err_text(e));
}

/* One evaluation: the image of every scene with the values x (snapped) and its error; the
   line printed and the files rewritten. NaN (stop) when a scene or a write fails. */
static double objective(void *user, const double *x)
{
    struct tune *t = user;
    struct tune_eval *ev = &t->evals[t->count];
    struct tune_sets ts;
    for (int k = 0; k < t->n; k++) {
        char value[64];
        ev->values[k] = param_value(&t->params[k], x[k]);
        ssg_tune_format(&t->params[k], ev->values[k], value, sizeof value);
        snprintf(ts.own[k], sizeof ts.own[k], "%s=%s", t->params[k].key, value);
    }
    struct ssg_diags d = {0};
    enum ssg_err e = SSG_OK;
    double sum = 0;
    for (int s = 0; s < t->scene_count; s++)
        ev->errors[s] = NAN;
    for (int s = 0; s < t->scene_count && !e; s++) {
        struct ssg_image *im = NULL;
        e = run_live(t, s, &ts, &im, &d);
        if (!e)
            e = scene_rmse(t, s, im, &ev->errors[s], &d);
        ssg_image_destroy(&im);
        sum += ev->errors[s];
        if (e)
            record_failure(ev, e, &d, t->scenes[s] ? t->scenes[s] : "(the graph's scene)");
    }
    ev->mean = e ? NAN : sum / t->scene_count;
    t->count++;
    if (!e && (t->best < 0 || ev->mean < t->evals[t->best].mean))
        t->best = t->count - 1;
    if (!t->req->quiet)
        ssg_tune_print_eval(t, t->count - 1, stdout);
    fflush(stdout);
    ssg_diags_print(&d, stderr);
    struct ssg_diags saved = {0};
    enum ssg_err w = ssg_tune_save(t, &saved);
    ssg_diags_print(&saved, stderr);
    return e || w ? NAN : ev->mean;
}

/* The search over the unit box from the graph's own values. */
static int search(struct tune *t)
{
    struct ssg_search s = {.dims = t->n, .budget = t->budget, .f = objective, .snap = snap,
                           .user = t};
    for (int k = 0; k < t->n; k++)
        s.start[k] = param_unit(&t->params[k], t->params[k].start);
    if (ssg_search_run(&s)) {
        fprintf(stderr, "ssgraph: error: out of memory for %d evaluations\n", t->budget);
        return 0;
    }
    return !s.stopped;
}

static void free_tune(struct tune *t)
{
    for (int s = 0; s < t->scene_count; s++) {
        ssg_image_destroy(&t->ref[s]);
        ssg_image_destroy(&t->mask[s]);
        ssg_graph_destroy(&t->live[s]);
    }
    free(t->evals);
}

/* Options that must be there (usage errors), then each --param's form. */
static int check_request(const struct ssg_tune_request *q, struct tune *t)
{
    if (!q->reference || !q->image || !q->param_count) {
        fprintf(stderr, "ssgraph: error: tune needs --reference NODE.PORT, --image NODE.PORT "
                "and at least one --param NODE.P=LO:HI\n(run 'ssgraph --help' for usage)\n");
        return EXIT_USAGE;
    }
    if (strlen(q->out_dir) > 1000) {
        fprintf(stderr, "ssgraph: error: --out path is longer than 1000 bytes\n");
        return EXIT_USAGE;
    }
    t->n = q->param_count;
    for (int k = 0; k < t->n; k++)
        if (!parse_param(q->params[k], &t->params[k]))
            return EXIT_INVALID;
    t->scene_count = q->scene_count ? q->scene_count : 1;
    for (int s = 0; s < q->scene_count; s++)
        t->scenes[s] = q->scenes[s];
    return 0;
}

int ssg_tune_main(const struct ssg_tune_request *req)
{
    struct tune t = {.req = req, .best = -1, .budget = req->evals > 0 ? req->evals
                                                                       : DEFAULT_EVALS};
    int rc = check_request(req, &t);
    if (rc)
        return rc;
    struct ssg_diags d = {0};
    if (!check_params(&t) || !check_ranges(&t) || !compute_references(&t) ||
        ssg_make_dirs(req->out_dir, &d)) {
        ssg_diags_print(&d, stderr);
        free_tune(&t);
        return EXIT_INVALID;
    }
    t.evals = calloc((size_t)t.budget, sizeof *t.evals);
    int ok = t.evals && search(&t);
    if (!t.evals)
        fprintf(stderr, "ssgraph: error: out of memory for %d evaluations\n", t.budget);
    if (t.best >= 0 && !req->quiet)
        ssg_tune_print_best(&t, stdout);
    if (!ok && t.count && t.evals[t.count - 1].error[0])
        fprintf(stderr, "ssgraph: error: tune stopped at evaluation %d of %d (%s); the files "
                "keep the evaluations before it\n", t.count, t.budget,
                t.evals[t.count - 1].error);
    for (int i = 0; t.count && !req->quiet && i < 3; i++)
        if (i < 2 || t.best >= 0)
            printf("wrote %s/%s\n", req->out_dir,
                   (const char *[]){"tune.csv", "tune.json", "tuned.graph"}[i]);
    free_tune(&t);
    return ok ? 0 : EXIT_INVALID;
}
