/* main.c - the ssgraph command line, a thin layer over libssgraph (ssgraph.h).
 *
 *   ssgraph run FILE [options]        validate, then run a graph and write its outputs
 *   ssgraph check FILE [options]      validate only (no meshes or images are loaded)
 *   ssgraph node NAME --in port=FILE[:LAYER]... [--set p=v]... [--out DIR | -o FILE]
 *   ssgraph compare A B [--mask M] [--depth D] [--json] [--peak P]
 *   ssgraph bench FILE --sweep NODE.PARAM=V1,V2,... [options]
 *   ssgraph tune FILE --reference NODE.PORT --image NODE.PORT --param NODE.P=LO:HI ...
 *   ssgraph dot FILE [-o FILE.dot]
 *   ssgraph layers FILE.exr | extract FILE.exr LAYER -o OUT.png|OUT.exr
 *   ssgraph nodes | describe NODE | docs | help [COMMAND] | --version
 * The commands and their usage come from commands.c, the options from one table
 * (options.c); what a run printed comes back from the library as statistics and is
 * printed by report.c; each file written is named on a `wrote PATH` line (not with
 * --quiet).
 * Exit status: 0 success, 1 invalid input or failed run, 2 bad command line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "bench.h"
#include "check_kind.h"
#include "graph_info.h"
#include "layers.h"
#include "view/view.h"
#include "options.h"
#include "report.h"
#include "show.h"
#include "ssgraph.h"
#include "version.h"
#include "watch.h"

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
   progress bar is drawn only on a terminal (stderr); the `wrote` lines go to stdout; with
   --quiet neither. With --watch, `watch` is told of each load (watch.h). */
static enum ssg_err run_once(const struct ssg_cli_args *a, float eye, const char *out_dir,
                             double *frame_ms, struct ssg_cli_watch *watch,
                             struct ssg_diags *d)
{
    struct ssg_overrides ov = a->ov;
    ov.eye_offset = eye * 0.5f * a->ipd;
    struct ssg_graph *g = NULL;
    struct ssg_run_stats st = {0};
    static struct ssg_cli_show show; /* --show (checked by cmd_run) */
    struct ssg_run_options ro = {
        .out_dir = out_dir, .threads = a->threads, .frames = a->frames, .stats = &st,
        .progress = !a->quiet && isatty(fileno(stderr)) ? ssg_report_progress : NULL,
        .log = a->quiet || eye != 0.0f ? NULL : ssg_report_log, /* stereo: its join's */
    };
    if (a->show && !ssg_cli_show_parse(a->show, &show))
        ssg_cli_show_request(&show, &ov, &ro);
    enum ssg_err e = ssg_graph_load(a->files[0], &ov, &g, d);
    if (watch) /* what to watch next: this graph's files, or a failed one's (NULL) */
        ssg_cli_watch_load(watch, g, &ov);
    if (!e) {
        if (a->verbose && !a->quiet)
            ssg_cli_print_resolved(g, stdout);
        e = ssg_graph_run(g, &ro, d);
        if (!e && a->show)
            e = ssg_cli_show_write(&show, g, out_dir, a->tonemap, a->exposure, a->quiet, d);
        enum ssg_err shown = show_run(a, &st, d);
        e = e ? e : shown;
    }
    if (frame_ms)
        *frame_ms = st.frame_avg_ms;
    ssg_cli_show_free(&show);
    ssg_run_stats_free(&st);
    ssg_graph_destroy(&g);
    return e;
}

/* --stereo: the graph for the left and the right eye (1080 x 1200 each unless --size, as
   the HTC Vive's panels in the thesis's section 5.2), one multi-view EXR per write output
   with NAME_left.png and NAME_right.png beside it, and the time of both. */
static int cmd_stereo(struct ssg_cli_args a)
{
    struct ssg_diags d = {0};
    double ms[2] = {0, 0};
    char dir[2][1100];
    const char *names[2] = {"left", "right"};
    if (!a.ov.width)
        a.ov.width = 1080, a.ov.height = 1200;
    enum ssg_err e = SSG_OK;
    /* each eye into a hidden folder of the output folder, then one multi-view EXR per
       EXR and NAME_left/NAME_right per other file (ssgraph.h, ssg_stereo_join) */
    const char *dirs[2] = {dir[0], dir[1]};
    for (int i = 0; i < 2; i++)
        snprintf(dir[i], sizeof dir[i], "%s/.stereo-%s-%ld", a.out_dir, names[i],
                 (long)getpid());
    ssg_stereo_sweep(a.out_dir); /* the folders of a run that was killed */
    for (int i = 0; i < 2 && !e; i++) {
        if (!a.quiet)
            printf("%s eye (camera moved %+g along its right axis):\n", names[i],
                   (i ? 0.5 : -0.5) * a.ipd);
        e = run_once(&a, i ? 1.0f : -1.0f, dir[i], &ms[i], NULL, &d);
    }
    if (e)
        ssg_stereo_discard(dirs, 2);
    else
        e = ssg_stereo_join(a.out_dir, dirs, names, 2, a.quiet ? NULL : ssg_report_log, NULL,
                            &d);
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
    if (is_scene) /* the scene's bounds, triangles, camera and lights too */
        return conclude(&d, ssg_scene_summary(file, stdout, &d));
    if (ssg_cli_is_model(file)) /* its meshes, up axis and a scene to place it in */
        return conclude(&d, ssg_model_summary(file, stdout, &d));
    const char *kind = ssg_cli_not_checkable(file);
    if (kind) {
        fprintf(stderr, "%s: error: %s, not a graph, a scene or a model: `ssgraph check` "
                "takes a graph file (text, such as graphs/ssao.graph), a .scene file or a "
                "model (.gltf, .glb, .obj, .ply, .fbx, .3ds, .stl, .dae, ...)%s\n", file, kind,
                strstr(kind, "image") ? "; `ssgraph layers FILE` lists an image's layers" : "");
        return EXIT_INVALID;
    }
    enum ssg_err e = ssg_graph_check(file, &a->ov, &d);
    if (!e)
        printf("%s: ok\n", file);
    return conclude(&d, e);
}

/* -o DIR/NAME.exr: the run writes into DIR, and the graph's first write node is named
   NAME (a --set after the command line's own, so it wins). */
static int output_of_run(struct ssg_cli_args *a)
{
    char name[128], set[1200], dir[1024];
    const char *file = a->output, *slash = strrchr(file, '/');
    const char *base = slash ? slash + 1 : file;
    size_t len = strlen(base);
    if (len <= 4 || strcmp(base + len - 4, ".exr") || strpbrk(base, "\"\\"))
        return ssg_cli_usage_error("-o expects DIR/NAME.exr (the EXR of the graph's first "
                                   "write node), got '%s'", file);
    int found = ssg_cli_first_write(a->files[0], name, sizeof name);
    if (found < 0)
        return 0; /* the graph does not parse: its load says why */
    if (!found)
        return ssg_cli_usage_error("-o names the EXR of the graph's first write node, but "
                                   "%s has none", a->files[0]);
    snprintf(dir, sizeof dir, "%.*s", slash ? (int)(slash - file) : 1, slash ? file : ".");
    snprintf(set, sizeof set, "%s.name=\"%.*s\"", name, (int)(len - 4), base);
    const char *kept_set = ssg_cli_keep(a, set), *kept_dir = ssg_cli_keep(a, dir[0] ? dir : "/");
    if (!kept_set || !kept_dir || a->ov.set_count >= SSG_CLI_MAX_SETS)
        return ssg_cli_usage_error("%s", "too many --set options for -o");
    a->sets[a->ov.set_count++] = kept_set;
    a->out_dir = kept_dir;
    return 0;
}

/* One run of --watch (watch.h). */
static enum ssg_err watched_run(const struct ssg_cli_args *a, struct ssg_cli_watch *w,
                                struct ssg_diags *d)
{
    return run_once(a, 0.0f, a->out_dir, NULL, w, d);
}

/* --profile-json is written after the run: a path that cannot take it (a folder, a
   missing folder) is refused before the run writes anything (a FIFO or a device is
   written into). The run makes --out first, so a profile directly in an --out that does
   not exist yet is left to it. */
static int profile_refused(const struct ssg_cli_args *a, struct ssg_diags *d)
{
    const char *p = a->profile_json, *slash = strrchr(p, '/');
    size_t out = strlen(a->out_dir);
    while (out > 1 && a->out_dir[out - 1] == '/')
        out--;
    size_t len = strlen(p);
    while (len > 1 && p[len - 1] == '/')
        len--;
    if (len == out && !strncmp(p, a->out_dir, out)) /* a folder the run is about to make */
        return ssg_cli_usage_error("--profile-json %s names the --out folder itself: give a "
                                   "file in it, e.g. --profile-json OUT/profile.json", p) != 0;
    struct stat st;
    if (slash && (size_t)(slash - p) == out && !strncmp(p, a->out_dir, out) &&
        stat(a->out_dir, &st) != 0)
        return 0;
    return ssg_output_check(p, "profile", 1, d) != SSG_OK;
}

static int cmd_run(struct ssg_cli_args *a)
{
    struct ssg_diags d = {0};
    int rc = a->output ? output_of_run(a) : 0;
    struct ssg_cli_show show;
    if (!rc && a->show && a->stereo)
        rc = ssg_cli_usage_error("%s", "--show writes one view's ports: not with --stereo");
    if (!rc && a->show)
        rc = ssg_cli_show_parse(a->show, &show);
    if (!rc && a->watch && a->stereo)
        rc = ssg_cli_usage_error("%s", "--watch runs one view: not with --stereo");
    if (!rc && (a->tonemap || a->exposure != 0.0f) && !a->show)
        rc = ssg_cli_usage_error("%s", "--tonemap and --exposure are the PNGs' of --show: "
                                 "give --show NODE.PORT");
    if (rc)
        return rc;
    if (a->profile_json && profile_refused(a, &d))
        return conclude(&d, SSG_E_IO);
    if (a->stereo)
        return cmd_stereo(*a);
    if (a->watch)
        return ssg_cli_run_watch(a, watched_run);
    return conclude(&d, run_once(a, 0.0f, a->out_dir, NULL, NULL, &d));
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

/* Where output i of a node run goes: <out>/<port>.exr, or with -o FILE.exr the first
   output FILE.exr and each other FILE_<port>.exr; *dir_len: the bytes of its folder. */
static void output_path(const struct ssg_cli_args *a, const struct ssg_outputs *out, int i,
                        char *path, size_t len, size_t *dir_len)
{
    if (!a->output)
        snprintf(path, len, "%s/%s.exr", a->out_dir, out->names[i]);
    else if (i == 0)
        snprintf(path, len, "%s", a->output);
    else
        snprintf(path, len, "%.*s_%s.exr", (int)(strlen(a->output) - 4), a->output,
                 out->names[i]);
    const char *slash = strrchr(path, '/');
    *dir_len = slash ? (size_t)(slash - path) : 0;
}

static enum ssg_err write_outputs(const struct ssg_outputs *out, const struct ssg_cli_args *a,
                                  struct ssg_diags *d)
{
    for (int i = 0; i < out->count; i++) {
        char path[1200], dir[1200];
        size_t dir_len;
        output_path(a, out, i, path, sizeof path, &dir_len);
        snprintf(dir, sizeof dir, "%.*s", (int)dir_len, path);
        enum ssg_err e = dir_len ? ssg_make_dirs(dir, d) : SSG_OK;
        if (!e)
            e = ssg_image_write(path, out->images[i], d);
        if (e)
            return e;
        if (!a->quiet)
            printf("wrote %s", path);
        if (!a->quiet && a->verbose)
            printf(" (%dx%d, %d channels)", out->images[i]->width, out->images[i]->height,
                   out->images[i]->channels);
        if (!a->quiet)
            putchar('\n');
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
    size_t olen = a->output ? strlen(a->output) : 0;
    if (!rc && a->output && (olen <= 4 || strcmp(a->output + olen - 4, ".exr")))
        rc = ssg_cli_usage_error("-o expects FILE.exr (the node's first output), got '%s'",
                                 a->output);
    if (rc)
        return rc;
    for (int i = 0; i < a->input_count; i++) {
        enum ssg_err r = read_input(a->inputs[i], &bind[i], ports[i], sizeof ports[i], &d);
        if (r && !e)
            e = r;
    }
    struct ssg_frame frame = {.width = a->ov.width, .height = a->ov.height, .fov_y = a->fov,
                              .seed = a->ov.seed >= 0 ? (uint64_t)a->ov.seed : 1};
    /* the camera of the first input that records one (io/imageio.h): --fov is for foreign
       files, and wins when given */
    for (int i = 0; i < a->input_count && a->fov <= 0; i++)
        if (ssg_exr_frame_read(strchr(a->inputs[i], '=') + 1, &frame))
            break;
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
        e = write_outputs(&out, a, &d);
    if (!e && !a->quiet)
        print_metrics(&out, 0);
    ssg_outputs_release(&out);
    for (int i = 0; i < a->input_count; i++)
        ssg_image_destroy((struct ssg_image **)&bind[i].image);
    return conclude(&d, e);
}

/* `compare A B`: the compare node on the two images (and --mask), its metrics printed. */
static int cmd_compare(const struct ssg_cli_args *a)
{
    static const char *const ports[4] = {"a", "b", "mask", "depth"};
    const char *files[4] = {a->files[0], a->files[1], a->mask, a->depth};
    char peak[64], specs[4][1100], names[4][64];
    snprintf(peak, sizeof peak, "peak=%s", a->peak ? a->peak : "1");
    const char *sets[2] = {peak, "structure=true"};
    struct ssg_diags d = {0};
    struct ssg_binding bind[4] = {{0}};
    int count = 0;
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < 4; i++) {
        if (!files[i])
            continue;
        snprintf(specs[i], sizeof specs[i], "%s=%s", ports[i], files[i]);
        enum ssg_err r = read_input(specs[i], &bind[count++], names[i], sizeof names[i], &d);
        if (r && !e)
            e = r;
    }
    struct ssg_outputs out = {0};
    if (!e)
        e = ssg_node_run("compare", bind, count, sets, a->depth ? 2 : 1, NULL, &out, &d);
    if (!e)
        print_metrics(&out, a->json);
    ssg_outputs_release(&out);
    for (int i = 0; i < count; i++)
        ssg_image_destroy((struct ssg_image **)&bind[i].image);
    return conclude(&d, e);
}

/* The first option given that bench --merge would ignore (it runs nothing: the graph, the
   sweep, the timed node, the metric and the reference are the shards'), or NULL. A silently
   ignored option let a misspelled --error pass. */
static const char *merge_ignores(const struct ssg_cli_args *a)
{
    const struct {
        int given;
        const char *name;
    } options[] = {
        {a->sweep_count > 0, "--sweep"}, {a->shard != NULL, "--shard"},
        {a->scene_count > 0, "--scene"}, {a->ov.lights != NULL, "--lights"},
        {a->ov.width > 0, "--size"}, {a->ov.set_count > 0, "--set"},
        {a->seed >= 0, "--seed"}, {a->guard >= 0, "--guard"},
        {a->ov.backend != NULL, "--backend"}, {a->frames > 0, "--frames"},
        {a->threads > 0, "--threads"}, {a->stereo, "--stereo"},
        {a->time_node != NULL, "--time"}, {a->error_metric != NULL, "--error"},
        {a->reference != NULL, "--reference"}, {a->image != NULL, "--image"},
        {a->mask != NULL, "--mask"},
    };
    for (size_t i = 0; i < sizeof options / sizeof options[0]; i++)
        if (options[i].given)
            return options[i].name;
    return NULL;
}

static int cmd_bench(struct ssg_cli_args *a)
{
    if (!a->merge && a->file_count != 1)
        return ssg_cli_usage_error("%s", "bench expects one graph FILE (or --merge DIR...)");
    const char *ignored = a->merge ? merge_ignores(a) : NULL;
    if (ignored)
        return ssg_cli_usage_error("bench --merge takes the graph, sweep, timed node, metric "
                                   "and reference from its shards' bench.json: it takes no "
                                   "%s (only --out, --plot, --quiet and --verbose)", ignored);
    if (a->stereo && !a->ov.width)
        a->ov.width = 1080, a->ov.height = 1200;
    struct ssg_bench_request req = {
        .graph = a->files[0], .ov = &a->ov, .sweeps = a->sweeps,
        .sweep_count = a->sweep_count, .frames = a->frames, .threads = a->threads,
        .out_dir = a->out_dir, .time_node = a->time_node, .error_metric = a->error_metric,
        .plot = a->plot, .reference = a->reference, .image = a->image, .stereo = a->stereo,
        .ipd = a->ipd, .mask = a->mask, .quiet = a->quiet, .verbose = a->verbose,
        .shard = a->shard, .merge_dirs = a->files, .merge_count = a->file_count,
        .scenes = a->scenes, .scene_count = a->scene_count,
    };
    return a->merge ? ssg_bench_merge(&req) : ssg_bench_main(&req);
}

static int cmd_tune(const struct ssg_cli_args *a)
{
    struct ssg_tune_request req = {
        .graph = a->files[0], .ov = &a->ov, .scenes = a->scenes,
        .scene_count = a->scene_count, .params = a->params, .param_count = a->param_count,
        .reference = a->reference, .image = a->image, .mask = a->mask, .evals = a->evals,
        .threads = a->threads, .out_dir = a->out_dir, .quiet = a->quiet, .verbose = a->verbose,
    };
    return ssg_tune_main(&req);
}

/* `dot FILE`: the graph as Graphviz, to stdout or -o FILE. */
static int cmd_dot(const struct ssg_cli_args *a)
{
    struct ssg_diags d = {0};
    enum ssg_err e = ssg_cli_dot(a->files[0], a->output, &d);
    if (!e && a->output)
        printf("wrote %s\n", a->output);
    return conclude(&d, e);
}

/* `layers FILE`, `extract FILE LAYER -o OUT.png|OUT.exr` (layers.h). */
static int cmd_layers(const struct ssg_cli_args *a, enum ssg_cli_command command)
{
    struct ssg_diags d = {0};
    if (command == SSG_CLI_LAYERS)
        return conclude(&d, ssg_cli_layers(a->files[0], stdout, &d));
    size_t n = a->output ? strlen(a->output) : 0;
    if (n <= 4 || (strcmp(a->output + n - 4, ".png") && strcmp(a->output + n - 4, ".exr")))
        return ssg_cli_usage_error("extract writes -o OUT.png or OUT.exr, got '%s'",
                                   a->output ? a->output : "no -o");
    enum ssg_err e = ssg_cli_extract(a->files[0], a->files[1], a->output, a->tonemap,
                                     a->exposure, &d);
    if (!e)
        printf("wrote %s\n", a->output);
    return conclude(&d, e);
}

static int cmd_help(const struct ssg_cli_args *a)
{
    enum ssg_cli_command command;
    if (!a->file_count) {
        ssg_cli_usage(stdout);
        return 0;
    }
    if (!ssg_cli_command_find(a->files[0], &command))
        return ssg_cli_usage_error("unknown command '%s' (see 'ssgraph help')", a->files[0]);
    ssg_cli_command_usage(command, stdout);
    return 0;
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

/* docs [nodes|scenes]: the generated references (docs/nodes.md, docs/scenes.md). Nodes
   list the graphs of ./graphs that use them, so run it in the repository root. */
static int cmd_docs(const char *which)
{
    if (!which || !strcmp(which, "nodes")) {
        ssg_nodes_markdown(stdout, "graphs");
        return 0;
    }
    if (!strcmp(which, "scenes")) {
        ssg_scenes_markdown(stdout);
        return 0;
    }
    fprintf(stderr, "ssgraph: error: docs: unknown reference '%s' (expected nodes or scenes)\n",
            which);
    return EXIT_USAGE;
}

enum { TAKES_SETS = SSG_CLI_RUN | SSG_CLI_CHECK | SSG_CLI_NODE | SSG_CLI_BENCH | SSG_CLI_TUNE |
                    SSG_CLI_VIEW };

/* A command on its parsed arguments (its usage for --help). */
static int run_command(enum ssg_cli_command command, int argc, char **argv)
{
    static struct ssg_cli_args a; /* some 12 KB: kept off the stack */
    int rc = ssg_cli_parse(command, argc, argv, &a);
    if (!rc && a.help) {
        ssg_cli_command_usage(command, stdout);
        return 0;
    }
    if (!rc && (command & TAKES_SETS) && (a.ov.set_count || a.sweep_count))
        rc = ssg_cli_quote_sets(&a, command);
    if (rc)
        return rc;
    switch (command) {
    case SSG_CLI_RUN: return cmd_run(&a);
    case SSG_CLI_CHECK: return cmd_check(&a);
    case SSG_CLI_NODE: return cmd_node(&a);
    case SSG_CLI_BENCH: return cmd_bench(&a);
    case SSG_CLI_COMPARE: return cmd_compare(&a);
    case SSG_CLI_TUNE: return cmd_tune(&a);
    case SSG_CLI_DOT: return cmd_dot(&a);
    case SSG_CLI_NODES: return cmd_nodes();
    case SSG_CLI_DESCRIBE: return cmd_describe(a.files[0]);
    case SSG_CLI_DOCS: return cmd_docs(a.file_count ? a.files[0] : NULL);
    case SSG_CLI_HELP: return cmd_help(&a);
    case SSG_CLI_LAYERS:
    case SSG_CLI_EXTRACT: return cmd_layers(&a, command);
    case SSG_CLI_VIEW: return ssg_cli_view(&a);
    }
    return EXIT_USAGE;
}

int main(int argc, char **argv)
{
    ssg_tmp_remove_on_signals(); /* a killed run leaves no half-written temporary */
    const char *cmd = argc < 2 ? "" : argv[1];
    if (argc < 2 || !strcmp(cmd, "--help") || !strcmp(cmd, "-h")) {
        ssg_cli_usage(argc < 2 ? stderr : stdout);
        return argc < 2 ? EXIT_USAGE : 0;
    }
    if (!strcmp(cmd, "--version"))
        return ssg_cli_version();
    enum ssg_cli_command command;
    if (!ssg_cli_command_find(cmd, &command))
        return ssg_cli_usage_error("unknown command '%s'", cmd);
    return run_command(command, argc - 2, argv + 2);
}
