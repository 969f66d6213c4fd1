/* main.c - the ssgraph command line, a thin layer over libssgraph (ssgraph.h).
 *
 *   ssgraph run FILE [options]        validate, then run a graph and write its outputs
 *   ssgraph check FILE [options]      validate only (no meshes or images are loaded)
 *   ssgraph node NAME --in port=FILE[:LAYER]... [--set p=v]... [--out DIR]
 *   ssgraph compare A B [--mask M] [--json] [--peak P]
 *   ssgraph nodes | describe NODE | docs
 * Exit status: 0 success, 1 invalid input or failed run, 2 bad command line. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "lang/files.h"
#include "ssgraph.h"

enum { MAX_SETS = 256, MAX_INPUTS = 24, EXIT_INVALID = 1, EXIT_USAGE = 2 };

struct options {
    const char *file;                /* graph file, or node name for `node` */
    struct ssg_overrides ov;
    const char *sets[MAX_SETS];
    const char *inputs[MAX_INPUTS];  /* `node`: port=file[:layer] */
    int input_count;
    const char *out_dir;
    int threads;
    int quiet;
    float fov;                       /* `node`: vertical fov, degrees */
    int frames;                      /* `run`: frames to profile, 0 = one */
    const char *profile_json;        /* `run`: where the profile goes */
    const char *sweeps[SSG_BENCH_MAX_SWEEPS]; /* `bench`: node.param=v1,v2,... */
    int sweep_count;
    const char *time_node;           /* `bench`: the node bench.md times */
    const char *error_metric;        /* `bench`: node.metric of the Pareto plot */
    int plot;                        /* `bench`: draw the plots */
    const char *reference, *image;   /* `bench`: NODE.PORT truth and image to compare */
    int stereo;                      /* `run`: two eyes */
    float ipd;                       /* `run --stereo`: eye distance, scene units */
};

static const char *const usage_text =
    "usage: ssgraph <command> [arguments]\n"
    "\n"
    "commands:\n"
    "  run FILE        validate and run a graph; writes into --out (default out/)\n"
    "  check FILE      validate a graph and its scene without running it (FILE.scene:\n"
    "                  validate a scene and load its meshes)\n"
    "  node NAME       run one node on image files (--in port=file.exr[:layer])\n"
    "  compare A B     RMSE, MAE, PSNR, SSIM of image A against reference B (FILE[:LAYER];\n"
    "                  --mask M, --json, --peak P; diff image: node compare --in ...)\n"
    "  bench FILE      run a graph for every combination of --sweep NODE.PARAM=V1,V2,...\n"
    "                  (up to 4; --frames N each, default 5); writes bench.csv, bench.md\n"
    "                  and bench.json into --out, a row per cell as it finishes; the\n"
    "                  table shows --time NODE's ms (default: the whole frame); --plot\n"
    "                  draws ms against the first sweep and --error NODE.METRIC against\n"
    "                  ms (a Pareto view) as PNG with gnuplot; --reference NODE.PORT\n"
    "                  --image NODE.PORT adds each cell's error against that truth;\n"
    "                  --stereo times both eyes of every cell (1080x1200 unless --size)\n"
    "  nodes           list the nodes\n"
    "  describe NODE   ports, parameters, defaults, ranges and method of a node\n"
    "  docs            the Markdown reference of every node\n"
    "\n"
    "options of run, check and node:\n"
    "  --scene FILE        use this scene instead of the graph's\n"
    "  --size WxH          frame size in pixels instead of the graph's\n"
    "  --set NODE.P=VALUE  override a parameter or input (repeatable; for `node`: P=VALUE)\n"
    "  --seed N            seed of every pseudo-random choice (default: the graph's, or 1)\n"
    "  --out DIR           output directory (default out)\n"
    "  --threads N         worker threads (default: all cores); never changes the result\n"
    "  --backend cpu|gl    run every node there (gl: OpenGL 4.5 through EGL on a GPU, else\n"
    "                      OSMesa; nodes without GL stay on the CPU); default: the graph's\n"
    "                      `backend` line and its nodes' backend= arguments, else cpu\n"
    "  --quiet             do not print per-node timings\n"
    "  --frames N          (run) run the graph N times (each node prepares once) and print\n"
    "                      a per-node profile: calls, avg/min/max ms, share of the frame\n"
    "  --profile-json FILE (run) write that profile (or one frame's) as JSON\n"
    "  --stereo            (run) both eyes of a head-mounted display, 1080x1200 each unless\n"
    "                      --size, into --out/left and --out/right; prints both eyes' time\n"
    "  --ipd D             (run --stereo) distance between the eyes, scene units (0.064)\n"
    "  --in PORT=FILE[:LAYER]  (node) bind an image file, or one EXR layer of it, to a port\n"
    "  --fov DEGREES       (node) vertical field of view of the frame (default 45)\n"
    "  --help, --version\n";

static int usage_error(const char *fmt, const char *arg)
{
    fprintf(stderr, "ssgraph: error: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n(run 'ssgraph --help' for usage)\n");
    return EXIT_USAGE;
}

static int parse_int(const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

static int parse_size(const char *s, int *w, int *h)
{
    char buf[64];
    long lw, lh;
    const char *x = strchr(s, 'x');
    if (!x || x - s >= (long)sizeof buf)
        return 0;
    memcpy(buf, s, (size_t)(x - s));
    buf[x - s] = 0;
    if (!parse_int(buf, 1, 16384, &lw) || !parse_int(x + 1, 1, 16384, &lh))
        return 0;
    *w = (int)lw;
    *h = (int)lh;
    return 1;
}

/* One option with its value at argv[*i + 1]; returns 0 on success, else an exit code. */
static int take_option(struct options *o, int argc, char **argv, int *i)
{
    const char *opt = argv[*i];
    if (!strcmp(opt, "--quiet") || !strcmp(opt, "--plot") || !strcmp(opt, "--stereo")) {
        *(opt[2] == 'q' ? &o->quiet : opt[2] == 'p' ? &o->plot : &o->stereo) = 1;
        return 0;
    }
    if (*i + 1 >= argc)
        return usage_error("option '%s' needs a value", opt);
    const char *val = argv[++*i];
    long n;
    if (!strcmp(opt, "--scene")) {
        o->ov.scene = val;
    } else if (!strcmp(opt, "--size")) {
        if (!parse_size(val, &o->ov.width, &o->ov.height))
            return usage_error("--size expects WIDTHxHEIGHT with 1..16384 each, got '%s'", val);
    } else if (!strcmp(opt, "--set")) {
        if (o->ov.set_count == MAX_SETS)
            return usage_error("too many --set options (at most 256), at '%s'", val);
        o->sets[o->ov.set_count++] = val;
    } else if (!strcmp(opt, "--in")) {
        if (o->input_count == MAX_INPUTS)
            return usage_error("too many --in options (at most 24), at '%s'", val);
        o->inputs[o->input_count++] = val;
    } else if (!strcmp(opt, "--seed")) {
        if (!parse_int(val, 0, 2147483647L, &n))
            return usage_error("--seed expects an integer 0..2147483647, got '%s'", val);
        o->ov.seed = n;
    } else if (!strcmp(opt, "--threads")) {
        if (!parse_int(val, 1, 1024, &n))
            return usage_error("--threads expects an integer 1..1024, got '%s'", val);
        o->threads = (int)n;
    } else if (!strcmp(opt, "--fov")) {
        char *end;
        o->fov = strtof(val, &end);
        if (*end || !(o->fov > 0 && o->fov < 180))
            return usage_error("--fov expects degrees in (0, 180), got '%s'", val);
    } else if (!strcmp(opt, "--backend")) {
        if (strcmp(val, "cpu") && strcmp(val, "gl"))
            return usage_error("--backend expects cpu or gl, got '%s'", val);
        o->ov.backend = val;
    } else if (!strcmp(opt, "--out")) {
        o->out_dir = val;
    } else if (!strcmp(opt, "--frames")) {
        if (!parse_int(val, 1, 1000000, &n))
            return usage_error("--frames expects an integer 1..1000000, got '%s'", val);
        o->frames = (int)n;
    } else if (!strcmp(opt, "--sweep")) {
        if (o->sweep_count == SSG_BENCH_MAX_SWEEPS)
            return usage_error("at most 4 --sweep options, at '%s'", val);
        o->sweeps[o->sweep_count++] = val;
    } else if (!strcmp(opt, "--ipd")) {
        char *end;
        o->ipd = strtof(val, &end);
        if (*end || !(o->ipd > 0 && o->ipd < 1e6))
            return usage_error("--ipd expects a positive distance in scene units, got '%s'", val);
    } else if (!strcmp(opt, "--reference")) {
        o->reference = val;
    } else if (!strcmp(opt, "--image")) {
        o->image = val;
    } else if (!strcmp(opt, "--time")) {
        o->time_node = val;
    } else if (!strcmp(opt, "--error")) {
        o->error_metric = val;
    } else if (!strcmp(opt, "--profile-json")) {
        o->profile_json = val;
    } else {
        return usage_error("unknown option '%s'", opt);
    }
    return 0;
}

static int parse_options(struct options *o, int argc, char **argv)
{
    memset(o, 0, sizeof *o);
    o->ov.seed = -1;
    o->ov.sets = o->sets;
    o->out_dir = "out";
    o->ipd = 0.064f;
    for (int i = 0; i < argc; i++) {
        if (argv[i][0] == '-' && argv[i][1] == '-') {
            int rc = take_option(o, argc, argv, &i);
            if (rc)
                return rc;
        } else if (!o->file) {
            o->file = argv[i];
        } else {
            return usage_error("unexpected argument '%s'", argv[i]);
        }
    }
    if (!o->file)
        return usage_error("%s", "missing FILE (or NODE) argument");
    return 0;
}

static int report(struct ssg_diags *d, enum ssg_err e)
{
    ssg_diags_print(d, stderr);
    if (e && d->count == 0)
        fprintf(stderr, "ssgraph: error: %s\n", ssg_err_text(e));
    return e ? EXIT_INVALID : 0;
}

/* One graph run with the command line's options into out_dir (eye: 0, or -1/+1 for the
   left/right eye of --stereo); stats as the run measured them. */
static enum ssg_err run_once(const struct options *o, float eye, const char *out_dir,
                             struct ssg_run_stats *stats, struct ssg_diags *d)
{
    struct ssg_overrides ov = o->ov;
    ov.eye_offset = eye * 0.5f * o->ipd;
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load(o->file, &ov, &g, d);
    if (!e) {
        struct ssg_run_options ro = {.out_dir = out_dir, .threads = o->threads,
                                     .quiet = o->quiet, .log = stdout, .frames = o->frames,
                                     .profile_json = o->profile_json, .stats = stats};
        e = ssg_graph_run(g, &ro, d);
    }
    ssg_graph_destroy(&g);
    return e;
}

/* --stereo: the graph for the left and the right eye (1080 x 1200 each unless --size, as
   the HTC Vive's panels in the thesis's section 5.2), each into its own folder, and the
   time of both. */
static int cmd_stereo(struct options o)
{
    struct ssg_diags d = {0};
    struct ssg_run_stats st[2];
    char dir[2][1100];
    const char *names[2] = {"left", "right"};
    if (!o.ov.width)
        o.ov.width = 1080, o.ov.height = 1200;
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < 2 && !e; i++) {
        snprintf(dir[i], sizeof dir[i], "%s/%s", o.out_dir, names[i]);
        if (!o.quiet)
            printf("%s eye (camera moved %+g along its right axis):\n", names[i],
                   (i ? 0.5 : -0.5) * o.ipd);
        e = run_once(&o, i ? 1.0f : -1.0f, dir[i], &st[i], &d);
    }
    if (!e) {
        double both = st[0].frame_avg_ms + st[1].frame_avg_ms;
        printf("stereo %dx%d per eye, ipd %g: left %.2f ms + right %.2f ms = %.2f ms per "
               "stereo frame (%.1f fps)\n", o.ov.width, o.ov.height, o.ipd,
               st[0].frame_avg_ms, st[1].frame_avg_ms, both, both > 0 ? 1000.0 / both : 0.0);
    }
    return report(&d, e);
}

static int cmd_run(const struct options *o, int check_only)
{
    struct ssg_diags d = {0};
    size_t len = strlen(o->file);
    if (check_only) {
        int is_scene = len > 6 && !strcmp(o->file + len - 6, ".scene");
        enum ssg_err e = is_scene ? ssg_scene_check(o->file, &d)
                                  : ssg_graph_check(o->file, &o->ov, &d);
        if (!e)
            printf("%s: ok\n", o->file);
        return report(&d, e);
    }
    if (o->stereo)
        return cmd_stereo(*o);
    return report(&d, run_once(o, 0.0f, o->out_dir, NULL, &d));
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

static int check_inputs(const struct options *o)
{
    for (int i = 0; i < o->input_count; i++) {
        const char *eq = strchr(o->inputs[i], '=');
        if (!eq || eq == o->inputs[i] || eq - o->inputs[i] >= 64 || !eq[1])
            return usage_error("--in expects PORT=FILE[:LAYER], got '%s'", o->inputs[i]);
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

static int cmd_node(const struct options *o)
{
    struct ssg_diags d = {0};
    struct ssg_binding bind[MAX_INPUTS] = {{0}};
    char ports[MAX_INPUTS][64];
    enum ssg_err e = SSG_OK;
    int rc = check_inputs(o);
    if (rc)
        return rc;
    for (int i = 0; i < o->input_count; i++) {
        enum ssg_err r = read_input(o->inputs[i], &bind[i], ports[i], sizeof ports[i], &d);
        if (r && !e)
            e = r;
    }
    struct ssg_frame frame = {o->ov.width, o->ov.height, o->fov, 0, 0,
                              o->ov.seed >= 0 ? (uint64_t)o->ov.seed : 1};
    struct ssg_outputs out = {0};
    const char *sets[MAX_SETS + 1];
    int set_count = o->ov.set_count;
    memcpy(sets, o->sets, (size_t)set_count * sizeof *sets);
    char backend[32];
    if (o->ov.backend) {
        snprintf(backend, sizeof backend, "backend=%s", o->ov.backend);
        sets[set_count++] = backend;
    }
    if (!e)
        e = ssg_node_run(o->file, bind, o->input_count, sets, set_count, &frame, &out, &d);
    if (!e)
        e = write_outputs(&out, o->out_dir, &d);
    if (!e)
        print_metrics(&out, 0);
    ssg_outputs_release(&out);
    for (int i = 0; i < o->input_count; i++)
        ssg_image_destroy((struct ssg_image **)&bind[i].image);
    return report(&d, e);
}

/* `compare A B ...`: what cmd_compare reads from the command line. */
struct compare_args {
    const char *files[3]; /* a, b, mask (NULL = every pixel), each FILE[:LAYER] */
    const char *peak;     /* --peak P, then "peak=P" for the node (default 1) */
    int json;             /* 1 = one line of JSON instead of the table */
};

static int parse_compare(struct compare_args *c, int argc, char **argv, char *peak, size_t len)
{
    int n = 0;
    memset(c, 0, sizeof *c);
    for (int i = 0; i < argc; i++) {
        const char *arg = argv[i], **slot = !strcmp(arg, "--mask") ? &c->files[2]
                                          : !strcmp(arg, "--peak") ? &c->peak : NULL;
        if (slot && i + 1 >= argc)
            return usage_error("option '%s' needs a value", arg);
        if (slot)
            *slot = argv[++i];
        else if (!strcmp(arg, "--json"))
            c->json = 1;
        else if (arg[0] == '-' && arg[1] == '-')
            return usage_error("unknown option '%s'", arg);
        else if (n < 2)
            c->files[n++] = arg;
        else
            return usage_error("unexpected argument '%s'", arg);
    }
    char *end;
    if (c->peak && (!(strtod(c->peak, &end) > 0) || *end || end == c->peak))
        return usage_error("--peak expects a positive number, got '%s'", c->peak);
    snprintf(peak, len, "peak=%s", c->peak ? c->peak : "1");
    c->peak = peak;
    return n == 2 ? 0 : usage_error("%s", "compare expects two image files: A B");
}

static int cmd_compare(int argc, char **argv)
{
    static const char *const ports[3] = {"a", "b", "mask"};
    struct compare_args c;
    char peak[64], specs[3][1100], names[3][64];
    int rc = parse_compare(&c, argc, argv, peak, sizeof peak);
    if (rc)
        return rc;
    struct ssg_diags d = {0};
    struct ssg_binding bind[3] = {{0}};
    int count = c.files[2] ? 3 : 2;
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < count; i++) {
        snprintf(specs[i], sizeof specs[i], "%s=%s", ports[i], c.files[i]);
        enum ssg_err r = read_input(specs[i], &bind[i], names[i], sizeof names[i], &d);
        if (r && !e)
            e = r;
    }
    struct ssg_outputs out = {0};
    if (!e)
        e = ssg_node_run("compare", bind, count, &c.peak, 1, NULL, &out, &d);
    if (!e)
        print_metrics(&out, c.json);
    ssg_outputs_release(&out);
    for (int i = 0; i < count; i++)
        ssg_image_destroy((struct ssg_image **)&bind[i].image);
    return report(&d, e);
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

int main(int argc, char **argv)
{
    ssg_tmp_remove_on_signals(); /* a killed run leaves no half-written temporary */
    if (argc < 2 || wants_help(argc, argv)) {
        fputs(usage_text, argc < 2 ? stderr : stdout);
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
        ssg_nodes_markdown(stdout);
        return 0;
    }
    if (!strcmp(cmd, "describe"))
        return argc == 3 ? cmd_describe(argv[2]) : usage_error("%s", "describe expects NODE");
    if (!strcmp(cmd, "compare"))
        return cmd_compare(argc - 2, argv + 2);
    if (strcmp(cmd, "run") && strcmp(cmd, "check") && strcmp(cmd, "node") &&
        strcmp(cmd, "bench"))
        return usage_error("unknown command '%s'", cmd);
    struct options o;
    int rc = parse_options(&o, argc - 2, argv + 2);
    if (rc)
        return rc;
    if (!strcmp(cmd, "node"))
        return cmd_node(&o);
    if (!strcmp(cmd, "bench")) {
        struct ssg_bench_request req = {o.file, &o.ov, o.sweeps, o.sweep_count, o.frames,
                                        o.threads, o.out_dir, o.time_node, o.error_metric,
                                        o.plot, o.reference, o.image, o.stereo, o.ipd};
        if (o.stereo && !o.ov.width)
            o.ov.width = 1080, o.ov.height = 1200;
        return ssg_bench_main(&req);
    }
    return cmd_run(&o, !strcmp(cmd, "check"));
}
