/* main.c - the ssgraph command line, a thin layer over libssgraph (ssgraph.h).
 *
 *   ssgraph run FILE [options]        validate, then run a graph and write its outputs
 *   ssgraph check FILE [options]      validate only (no meshes or images are loaded)
 *   ssgraph node NAME --in port=FILE[:LAYER]... [--set p=v]... [--out DIR]
 *   ssgraph compare A B [--mask M] [--json] [--peak P]
 *   ssgraph bench FILE --sweep NODE.PARAM=V1,V2,... [options]
 *   ssgraph tune FILE --reference NODE.PORT --image NODE.PORT --param NODE.P=LO:HI ...
 *   ssgraph nodes | describe NODE | docs
 * The options and the usage text come from one table (options.c); what a run printed
 * comes back from the library as statistics and is printed by report.c.
 * Exit status: 0 success, 1 invalid input or failed run, 2 bad command line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "bench.h"
#include "lang/files.h"
#include "options.h"
#include "report.h"
#include "ssgraph.h"

enum { EXIT_INVALID = 1, EXIT_USAGE = SSG_CLI_EXIT_USAGE };

static int conclude(struct ssg_diags *d, enum ssg_err e)
{
    ssg_diags_print(d, stderr);
    if (e && d->count == 0)
        fprintf(stderr, "ssgraph: error: %s\n", ssg_err_text(e));
    return e ? EXIT_INVALID : 0;
}

/* Prints the run's statistics (unless --quiet) and writes --profile-json. */
static enum ssg_err show_run(const struct ssg_cli_args *a, const struct ssg_run_stats *st,
                             struct ssg_diags *d)
{
    if (st->frames > 0 && !a->quiet)
        ssg_report_print(st, stdout);
    return a->profile_json ? ssg_report_write_json(st, a->profile_json, d) : SSG_OK;
}

/* One graph run with the command line's options into out_dir (eye: 0, or -1/+1 for the
   left/right eye of --stereo), printed; *frame_ms (if not NULL) its frame time. The
   progress bar is drawn only on a terminal, as the notices of --verbose go to stderr. */
static enum ssg_err run_once(const struct ssg_cli_args *a, float eye, const char *out_dir,
                             double *frame_ms, struct ssg_diags *d)
{
    struct ssg_overrides ov = a->ov;
    ov.eye_offset = eye * 0.5f * a->ipd;
    struct ssg_graph *g = NULL;
    struct ssg_run_stats st = {0};
    enum ssg_err e = ssg_graph_load(a->files[0], &ov, &g, d);
    if (!e) {
        struct ssg_run_options ro = {
            .out_dir = out_dir, .threads = a->threads, .frames = a->frames, .stats = &st,
            .progress = isatty(fileno(stderr)) ? ssg_report_progress : NULL,
            .log = a->verbose ? ssg_report_log : NULL,
        };
        e = ssg_graph_run(g, &ro, d);
        enum ssg_err shown = show_run(a, &st, d);
        e = e ? e : shown;
    }
    if (frame_ms)
        *frame_ms = st.frame_avg_ms;
    ssg_run_stats_free(&st);
    ssg_graph_destroy(&g);
    return e;
}

/* --stereo: the graph for the left and the right eye (1080 x 1200 each unless --size, as
   the HTC Vive's panels in the thesis's section 5.2), each into its own folder, and the
   time of both. */
static int cmd_stereo(struct ssg_cli_args a)
{
    struct ssg_diags d = {0};
    double ms[2] = {0, 0};
    char dir[2][1100];
    const char *names[2] = {"left", "right"};
    if (!a.ov.width)
        a.ov.width = 1080, a.ov.height = 1200;
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < 2 && !e; i++) {
        snprintf(dir[i], sizeof dir[i], "%s/%s", a.out_dir, names[i]);
        if (!a.quiet)
            printf("%s eye (camera moved %+g along its right axis):\n", names[i],
                   (i ? 0.5 : -0.5) * a.ipd);
        e = run_once(&a, i ? 1.0f : -1.0f, dir[i], &ms[i], &d);
    }
    if (!e) {
        double both = ms[0] + ms[1];
        printf("stereo %dx%d per eye, ipd %g: left %.2f ms + right %.2f ms = %.2f ms per "
               "stereo frame (%.1f fps)\n", a.ov.width, a.ov.height, a.ipd, ms[0], ms[1],
               both, both > 0 ? 1000.0 / both : 0.0);
    }
    return conclude(&d, e);
}

static int cmd_check(const struct ssg_cli_args *a)
{
    struct ssg_diags d = {0};
    const char *file = a->files[0];
    size_t len = strlen(file);
    int is_scene = len > 6 && !strcmp(file + len - 6, ".scene");
    enum ssg_err e = is_scene ? ssg_scene_check(file, &d) : ssg_graph_check(file, &a->ov, &d);
    if (!e)
        printf("%s: ok\n", file);
    return conclude(&d, e);
}

static int cmd_run(const struct ssg_cli_args *a)
{
    struct ssg_diags d = {0};
    if (a->stereo)
        return cmd_stereo(*a);
    return conclude(&d, run_once(a, 0.0f, a->out_dir, NULL, &d));
}

/* `--in port=file[:layer]` into a binding; the image is owned by the caller. The spec's
 * form was checked by check_inputs. */
static enum ssg_err read_input(const char *spec, struct ssg_binding *b, char *port, size_t len,
                               struct ssg_diags *d)
{
    const char *eq = strchr(spec, '=');
    memcpy(port, spec, (size_t)(eq - spec));
    port[eq - spec] = 0;
    char path[1024];
    snprintf(path, sizeof path, "%s", eq + 1);
    char *colon = strrchr(path, ':');
    const char *layer = NULL;
    if (colon && !strchr(colon, '/')) {
        *colon = 0;
        layer = colon + 1;
    }
    struct ssg_image *im = NULL;
    enum ssg_err e = ssg_image_read(path, layer, &im, d);
    b->port = port;
    b->image = im;
    return e;
}

static int check_inputs(const struct ssg_cli_args *a)
{
    for (int i = 0; i < a->input_count; i++) {
        const char *eq = strchr(a->inputs[i], '=');
        if (!eq || eq == a->inputs[i] || eq - a->inputs[i] >= 64 || !eq[1])
            return ssg_cli_usage_error("--in expects PORT=FILE[:LAYER], got '%s'",
                                       a->inputs[i]);
    }
    return 0;
}

static enum ssg_err write_outputs(const struct ssg_outputs *out, const char *dir,
                                  struct ssg_diags *d)
{
    enum ssg_err made = ssg_make_dirs(dir, d);
    if (made)
        return made;
    for (int i = 0; i < out->count; i++) {
        char path[1200];
        snprintf(path, sizeof path, "%s/%s.exr", dir, out->names[i]);
        enum ssg_err e = ssg_image_write(path, out->images[i], d);
        if (e)
            return e;
        printf("wrote %s (%dx%d, %d channels)\n", path, out->images[i]->width,
               out->images[i]->height, out->images[i]->channels);
    }
    return SSG_OK;
}

/* The metrics as `name value` lines, or as one line of JSON (non-finite: null). */
static void print_metrics(const struct ssg_outputs *out, int json)
{
    for (int i = 0; i < out->metric_count && !json; i++)
        printf("%-7s %.9g\n", out->metric_names[i], out->metric_values[i]);
    for (int i = 0; i < out->metric_count && json; i++) {
        printf("%s\"%s\":", i ? "," : "{", out->metric_names[i]);
        if (isfinite(out->metric_values[i]))
            printf("%.9g", out->metric_values[i]);
        else
            fputs("null", stdout);
    }
    if (json)
        puts(out->metric_count ? "}" : "{}");
}

static int cmd_node(const struct ssg_cli_args *a)
{
    struct ssg_diags d = {0};
    struct ssg_binding bind[SSG_CLI_MAX_INPUTS] = {{0}};
    char ports[SSG_CLI_MAX_INPUTS][64];
    enum ssg_err e = SSG_OK;
    int rc = check_inputs(a);
    if (rc)
        return rc;
    for (int i = 0; i < a->input_count; i++) {
        enum ssg_err r = read_input(a->inputs[i], &bind[i], ports[i], sizeof ports[i], &d);
        if (r && !e)
            e = r;
    }
    struct ssg_frame frame = {.width = a->ov.width, .height = a->ov.height, .fov_y = a->fov,
                              .seed = a->ov.seed >= 0 ? (uint64_t)a->ov.seed : 1};
    struct ssg_outputs out = {0};
    const char *sets[SSG_CLI_MAX_SETS + 1];
    int set_count = a->ov.set_count;
    memcpy(sets, a->sets, (size_t)set_count * sizeof *sets);
    char backend[32];
    if (a->ov.backend) {
        snprintf(backend, sizeof backend, "backend=%s", a->ov.backend);
        sets[set_count++] = backend;
    }
    if (!e)
        e = ssg_node_run(a->files[0], bind, a->input_count, sets, set_count, &frame, &out, &d);
    if (!e)
        e = write_outputs(&out, a->out_dir, &d);
    if (!e)
        print_metrics(&out, 0);
    ssg_outputs_release(&out);
    for (int i = 0; i < a->input_count; i++)
        ssg_image_destroy((struct ssg_image **)&bind[i].image);
    return conclude(&d, e);
}

/* `compare A B`: the compare node on the two images (and --mask), its metrics printed. */
static int cmd_compare(const struct ssg_cli_args *a)
{
    static const char *const ports[3] = {"a", "b", "mask"};
    const char *files[3] = {a->files[0], a->files[1], a->mask};
    char peak[64], specs[3][1100], names[3][64];
    snprintf(peak, sizeof peak, "peak=%s", a->peak ? a->peak : "1");
    const char *sets[1] = {peak};
    struct ssg_diags d = {0};
    struct ssg_binding bind[3] = {{0}};
    int count = a->mask ? 3 : 2;
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < count; i++) {
        snprintf(specs[i], sizeof specs[i], "%s=%s", ports[i], files[i]);
        enum ssg_err r = read_input(specs[i], &bind[i], names[i], sizeof names[i], &d);
        if (r && !e)
            e = r;
    }
    struct ssg_outputs out = {0};
    if (!e)
        e = ssg_node_run("compare", bind, count, sets, 1, NULL, &out, &d);
    if (!e)
        print_metrics(&out, a->json);
    ssg_outputs_release(&out);
    for (int i = 0; i < count; i++)
        ssg_image_destroy((struct ssg_image **)&bind[i].image);
    return conclude(&d, e);
}

static int cmd_bench(struct ssg_cli_args *a)
{
    if (a->stereo && !a->ov.width)
        a->ov.width = 1080, a->ov.height = 1200;
    struct ssg_bench_request req = {
        .graph = a->files[0], .ov = &a->ov, .sweeps = a->sweeps,
        .sweep_count = a->sweep_count, .frames = a->frames, .threads = a->threads,
        .out_dir = a->out_dir, .time_node = a->time_node, .error_metric = a->error_metric,
        .plot = a->plot, .reference = a->reference, .image = a->image, .stereo = a->stereo,
        .ipd = a->ipd, .mask = a->mask,
    };
    return ssg_bench_main(&req);
}

static int cmd_tune(const struct ssg_cli_args *a)
{
    struct ssg_tune_request req = {
        .graph = a->files[0], .ov = &a->ov, .scenes = a->scenes,
        .scene_count = a->scene_count, .params = a->params, .param_count = a->param_count,
        .reference = a->reference, .image = a->image, .mask = a->mask, .evals = a->evals,
        .threads = a->threads, .out_dir = a->out_dir,
    };
    return ssg_tune_main(&req);
}

static int cmd_nodes(void)
{
    for (int i = 0; i < ssg_node_count(); i++)
        printf("%-12s %s\n", ssg_node_name(i), ssg_node_summary(i));
    return 0;
}

static int cmd_describe(const char *node)
{
    if (ssg_node_describe(node, stdout) == SSG_OK)
        return 0;
    fprintf(stderr, "ssgraph: error: unknown node '%s' (see 'ssgraph nodes')\n", node);
    return EXIT_INVALID;
}

static int wants_help(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h"))
            return 1;
    return 0;
}

/* A command that takes options, on its parsed arguments. */
static int run_command(enum ssg_cli_command command, int argc, char **argv)
{
    struct ssg_cli_args a;
    int rc = ssg_cli_parse(command, argc, argv, &a);
    if (rc)
        return rc;
    switch (command) {
    case SSG_CLI_RUN: return cmd_run(&a);
    case SSG_CLI_CHECK: return cmd_check(&a);
    case SSG_CLI_NODE: return cmd_node(&a);
    case SSG_CLI_BENCH: return cmd_bench(&a);
    case SSG_CLI_COMPARE: return cmd_compare(&a);
    case SSG_CLI_TUNE: return cmd_tune(&a);
    }
    return EXIT_USAGE;
}

int main(int argc, char **argv)
{
    ssg_tmp_remove_on_signals(); /* a killed run leaves no half-written temporary */
    if (argc < 2 || wants_help(argc, argv)) {
        ssg_cli_usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? EXIT_USAGE : 0;
    }
    const char *cmd = argv[1];
    if (!strcmp(cmd, "--version")) {
        printf("ssgraph %s\n", SSG_VERSION);
        return 0;
    }
    if (!strcmp(cmd, "nodes"))
        return cmd_nodes();
    if (!strcmp(cmd, "docs")) {
        ssg_nodes_markdown(stdout, "graphs");
        return 0;
    }
    if (!strcmp(cmd, "describe"))
        return argc == 3 ? cmd_describe(argv[2])
                         : ssg_cli_usage_error("%s", "describe expects NODE");
    enum ssg_cli_command command;
    if (!ssg_cli_command_find(cmd, &command))
        return ssg_cli_usage_error("unknown command '%s'", cmd);
    return run_command(command, argc - 2, argv + 2);
}
