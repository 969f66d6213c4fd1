/* options.c - the command line's options as one table (options.h): each row names the
 * option, its argument, the commands it applies to, its help and how its value is taken,
 * so that parsing, the usage texts and the check that an option belongs to the command
 * all read the same row. The commands are commands.c's table. */
#include <errno.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "options.h"

struct option;
/* Takes the option's value (NULL for a flag) into *a; 0, or a usage error's exit code. */
typedef int (*take_fn)(struct ssg_cli_args *a, const struct option *opt, const char *value);

struct option {
    const char *name;     /* "--size" */
    char short_name;      /* 'o' for -o; 0 = none */
    const char *arg;      /* "WxH" in the usage; NULL = a flag, which takes no value */
    unsigned commands;    /* enum ssg_cli_command bits it applies to */
    const char *help;     /* usage text; each '\n' starts an indented line */
    take_fn take;
    size_t field;         /* offsetof(struct ssg_cli_args, ...) that take fills */
    size_t count;         /* lists: offsetof the int counting the entries */
    double lo, hi;        /* numbers: range (integers inclusive, decimals exclusive);
                             lists: hi = most entries */
    const char *expects;  /* a bad value is told "<name> expects <this>" */
};

enum { HELP_COLUMN = 22 }; /* where an option's help starts in the usage text */

#define FIELD(a, opt, type) ((type *)((char *)(a) + (opt)->field))

/* The command being parsed, whose usage a usage error points at; NULL = none yet. */
static const char *hint_command;

int ssg_cli_usage_error(const char *fmt, const char *arg)
{
    fprintf(stderr, "ssgraph: error: ");
    fprintf(stderr, fmt, arg);
    fprintf(stderr, "\n(run 'ssgraph help%s%s' for usage)\n", hint_command ? " " : "",
            hint_command ? hint_command : "");
    return SSG_CLI_EXIT_USAGE;
}

/* ssg_cli_usage_error for messages with several parts. */
static int usage_errorf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static int usage_errorf(const char *fmt, ...)
{
    char text[1200];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    return ssg_cli_usage_error("%s", text);
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

static int take_flag(struct ssg_cli_args *a, const struct option *opt, const char *value)
{
    (void)value;
    *FIELD(a, opt, int) = 1;
    return 0;
}

static int take_text(struct ssg_cli_args *a, const struct option *opt, const char *value)
{
    *FIELD(a, opt, const char *) = value;
    return 0;
}

static int take_int(struct ssg_cli_args *a, const struct option *opt, const char *value)
{
    long n;
    if (!parse_int(value, (long)opt->lo, (long)opt->hi, &n))
        return usage_errorf("%s expects an integer %ld..%ld, got '%s'", opt->name,
                            (long)opt->lo, (long)opt->hi, value);
    *FIELD(a, opt, int) = (int)n;
    return 0;
}

/* A decimal strictly between lo and hi. */
static int take_float(struct ssg_cli_args *a, const struct option *opt, const char *value)
{
    char *end;
    float v = strtof(value, &end);
    if (*end || end == value || !(v > opt->lo && v < opt->hi))
        return usage_errorf("%s expects %s, got '%s'", opt->name, opt->expects, value);
    *FIELD(a, opt, float) = v;
    return 0;
}

/* A positive number kept as written (the node parses it again). */
static int take_positive_text(struct ssg_cli_args *a, const struct option *opt,
                              const char *value)
{
    char *end;
    if (!(strtod(value, &end) > 0) || *end || end == value)
        return usage_errorf("%s expects %s, got '%s'", opt->name, opt->expects, value);
    return take_text(a, opt, value);
}

/* A repeatable option: one more entry of an array of strings. */
static int take_list(struct ssg_cli_args *a, const struct option *opt, const char *value)
{
    int *count = (int *)((char *)a + opt->count);
    if (*count >= (int)opt->hi)
        return usage_errorf("too many %s options (at most %d), at '%s'", opt->name,
                            (int)opt->hi, value);
    FIELD(a, opt, const char *)[(*count)++] = value;
    return 0;
}

static int take_size(struct ssg_cli_args *a, const struct option *opt, const char *value)
{
    char buf[64];
    long w, h;
    const char *x = strchr(value, 'x');
    int ok = x && x - value < (long)sizeof buf;
    if (ok) {
        memcpy(buf, value, (size_t)(x - value));
        buf[x - value] = 0;
        ok = parse_int(buf, 1, 16384, &w) && parse_int(x + 1, 1, 16384, &h);
    }
    if (!ok)
        return usage_errorf("%s expects %s, got '%s'", opt->name, opt->expects, value);
    a->ov.width = (int)w;
    a->ov.height = (int)h;
    return 0;
}

/* --scene: the scene of run, check and bench (the last one given), and every one of
   tune's list. */
static int take_scene(struct ssg_cli_args *a, const struct option *opt, const char *value)
{
    a->ov.scene = value;
    return take_list(a, opt, value);
}

static int take_backend(struct ssg_cli_args *a, const struct option *opt, const char *value)
{
    if (strcmp(value, "cpu") && strcmp(value, "gl"))
        return usage_errorf("%s expects %s, got '%s'", opt->name, opt->expects, value);
    return take_text(a, opt, value);
}

static int take_tonemap(struct ssg_cli_args *a, const struct option *opt, const char *value)
{
    if (strcmp(value, "clamp") && strcmp(value, "reinhard") && strcmp(value, "aces"))
        return usage_errorf("%s expects %s, got '%s'", opt->name, opt->expects, value);
    return take_text(a, opt, value);
}

#define OF(member) offsetof(struct ssg_cli_args, member)
#define ALL_GRAPH \
    (SSG_CLI_RUN | SSG_CLI_CHECK | SSG_CLI_NODE | SSG_CLI_BENCH | SSG_CLI_TUNE | SSG_CLI_VIEW)

/* In the order of the usage text, which starts a heading where the commands change. */
static const struct option options[] = {
    {.name = "--size", .arg = "WxH", .commands = ALL_GRAPH, .take = take_size,
     .expects = "WIDTHxHEIGHT with 1..16384 each",
     .help = "frame size in pixels instead of the graph's"},
    {.name = "--set", .arg = "NODE.P=VALUE", .commands = ALL_GRAPH, .take = take_list,
     .field = OF(sets), .count = OF(ov.set_count), .hi = SSG_CLI_MAX_SETS,
     .help = "override a parameter or input (repeatable; for `node`: P=VALUE)"},
    {.name = "--seed", .arg = "N", .commands = ALL_GRAPH, .take = take_int,
     .field = OF(seed), .lo = 0, .hi = 2147483647,
     .help = "seed of every pseudo-random choice (default: the graph's, or 1)"},
    {.name = "--backend", .arg = "cpu|gl", .commands = ALL_GRAPH, .take = take_backend,
     .field = OF(ov.backend), .expects = "cpu or gl",
     .help = "run every node there (gl: OpenGL 4.5 through EGL on a GPU, else\n"
             "OSMesa; nodes without GL stay on the CPU); default: the graph's\n"
             "`backend` line and its nodes' backend= arguments, else cpu"},
    {.name = "--scene", .arg = "FILE",
     .commands = SSG_CLI_RUN | SSG_CLI_CHECK | SSG_CLI_BENCH | SSG_CLI_TUNE | SSG_CLI_VIEW,
     .take = take_scene, .field = OF(scenes), .count = OF(scene_count),
     .hi = SSG_TUNE_MAX_SCENES,
     .help = "use this scene instead of the graph's (tune: repeatable, the\n"
             "error is the mean over them; bench: two or more are a sweep,\n"
             "`scene`, the outermost)"},
    {.name = "--lights", .arg = "FILE",
     .commands = SSG_CLI_RUN | SSG_CLI_CHECK | SSG_CLI_BENCH | SSG_CLI_TUNE | SSG_CLI_VIEW,
     .take = take_text, .field = OF(ov.lights),
     .help = "replace the scene's lights and environment with those of FILE, a\n"
             "scene file of light lines and environment only\n"
             "(examples/lights/: sun, sky, courtyard, spot); default: the graph's\n"
             "`lights` line, else the scene's own"},
    {.name = "--guard", .arg = "G",
     .commands = SSG_CLI_RUN | SSG_CLI_CHECK | SSG_CLI_BENCH | SSG_CLI_TUNE | SSG_CLI_VIEW,
     .take = take_int, .field = OF(guard), .lo = 0, .hi = SSG_GUARD_MAX,
     .help = "render G pixels of guard band around the frame (instead of the\n"
             "graph's `guard` line): screen-space AO sees occluders just outside\n"
             "the frame; outputs and metrics stay frame-sized"},
    {.name = "--out", .arg = "DIR",
     .commands = SSG_CLI_RUN | SSG_CLI_NODE | SSG_CLI_BENCH | SSG_CLI_TUNE | SSG_CLI_VIEW,
     .take = take_text, .field = OF(out_dir),
     .help = "output directory (default out)"},
    {.name = "--threads", .arg = "N",
     .commands = SSG_CLI_RUN | SSG_CLI_BENCH | SSG_CLI_TUNE | SSG_CLI_VIEW,
     .take = take_int, .field = OF(threads), .lo = 1, .hi = 1024,
     .help = "worker threads (default: all cores); never changes the result"},
    {.name = "--frames", .arg = "N", .commands = SSG_CLI_RUN | SSG_CLI_BENCH,
     .take = take_int, .field = OF(frames), .lo = 1, .hi = 1000000,
     .help = "run N frames (frame f at time f / fps: a scene's camera path\n"
             "moves the camera, docs/time.md; write sequence=true writes each);\n"
             "run prints a per-node profile: calls, avg/min/max ms, share of\n"
             "the frame; bench times each cell over N frames (default 5)"},
    {.name = "--stereo", .commands = SSG_CLI_RUN | SSG_CLI_BENCH, .take = take_flag,
     .field = OF(stereo),
     .help = "both eyes of a head-mounted display, 1080x1200 each unless\n"
             "--size; run: one multi-view EXR per output (views left, right)\n"
             "and NAME_left/NAME_right.png (docs/exr.md); bench: --out/left\n"
             "and --out/right; prints both eyes' time"},
    {.name = "--ipd", .arg = "D", .commands = SSG_CLI_RUN | SSG_CLI_BENCH, .take = take_float,
     .field = OF(ipd), .lo = 0, .hi = 1e6, .expects = "a positive distance in scene units",
     .help = "(with --stereo) distance between the eyes, scene units (0.064)"},
    {.name = "--quiet", .short_name = 'q',
     .commands = SSG_CLI_RUN | SSG_CLI_NODE | SSG_CLI_BENCH | SSG_CLI_TUNE,
     .take = take_flag, .field = OF(quiet),
     .help = "print no table, no progress, no summary and no `wrote PATH` lines\n"
             "(errors still go to stderr)"},
    {.name = "--verbose", .short_name = 'v',
     .commands = SSG_CLI_RUN | SSG_CLI_NODE | SSG_CLI_BENCH | SSG_CLI_TUNE,
     .take = take_flag, .field = OF(verbose),
     .help = "also print what the run resolved: size, seed, scene, backend and\n"
             "every node's parameters (run); each output's size (node); every\n"
             "node's ms per cell (bench); each scene's reference time (tune)"},
    {.name = "--output", .short_name = 'o', .arg = "FILE",
     .commands = SSG_CLI_RUN | SSG_CLI_NODE | SSG_CLI_DOT | SSG_CLI_EXTRACT,
     .take = take_text, .field = OF(output),
     .help = "the main output: run: DIR/NAME.exr names the first write node's\n"
             "EXR (its PNG beside it; the run's other files go to DIR too);\n"
             "node: the first output's EXR (others: FILE_<port>.exr); dot: the\n"
             "DOT file (default: stdout); extract: OUT.png or OUT.exr"},
    {.name = "--profile-json", .arg = "FILE", .commands = SSG_CLI_RUN, .take = take_text,
     .field = OF(profile_json),
     .help = "write that profile (or one frame's) as JSON"},
    {.name = "--show", .arg = "NODE.PORT[,...]", .commands = SSG_CLI_RUN, .take = take_text,
     .field = OF(show),
     .help = "also write these ports (up to 8) as <out>/NODE.PORT.png and .exr,\n"
             "framed and previewed as a write node would; the graph runs as it\n"
             "is (its own files too)"},
    {.name = "--tonemap", .arg = "CURVE", .commands = SSG_CLI_RUN | SSG_CLI_EXTRACT,
     .take = take_tonemap, .field = OF(tonemap), .expects = "clamp, reinhard or aces",
     .help = "the PNG's tone curve (run: of --show's): clamp, reinhard or aces\n"
             "(default aces, as the write node's)"},
    {.name = "--exposure", .arg = "STOPS", .commands = SSG_CLI_RUN | SSG_CLI_EXTRACT,
     .take = take_float, .field = OF(exposure), .lo = -21, .hi = 21,
     .expects = "stops in (-21, 21)",
     .help = "the PNG's values times 2^STOPS before tone mapping (default 0)"},
    {.name = "--watch", .commands = SSG_CLI_RUN, .take = take_flag, .field = OF(watch),
     .help = "run, then every 300 ms look whether the graph, its includes, the\n"
             "scene, lights, models or images changed, and run again when one\n"
             "did (a failed load prints its errors and waits); Ctrl-C ends (0)"},
    {.name = "--in", .arg = "PORT=FILE[:LAYER]", .commands = SSG_CLI_NODE, .take = take_list,
     .field = OF(inputs), .count = OF(input_count), .hi = SSG_CLI_MAX_INPUTS,
     .help = "bind an image file, or one EXR layer of it, to a port"},
    {.name = "--fov", .arg = "DEGREES", .commands = SSG_CLI_NODE, .take = take_float,
     .field = OF(fov), .lo = 0, .hi = 180, .expects = "degrees in (0, 180)",
     .help = "vertical field of view of the frame (default: the first input's\n"
             "recorded one, else 45)"},
    {.name = "--sweep", .arg = "NODE.PARAM=V1,V2,...", .commands = SSG_CLI_BENCH,
     .take = take_list, .field = OF(sweeps), .count = OF(sweep_count),
     .hi = SSG_BENCH_MAX_SWEEPS,
     .help = "one parameter's values (repeatable, up to 4)"},
    {.name = "--time", .arg = "NODE", .commands = SSG_CLI_BENCH, .take = take_text,
     .field = OF(time_node),
     .help = "the node whose ms the table shows (default: the whole frame)"},
    {.name = "--error", .arg = "NODE.METRIC", .commands = SSG_CLI_BENCH, .take = take_text,
     .field = OF(error_metric),
     .help = "the error shown and plotted (default: the first metric)"},
    {.name = "--plot", .commands = SSG_CLI_BENCH, .take = take_flag, .field = OF(plot),
     .help = "draw bench_ms.png and bench_pareto.png with gnuplot"},
    {.name = "--shard", .arg = "I/N", .commands = SSG_CLI_BENCH, .take = take_text,
     .field = OF(shard),
     .help = "run only the cells whose index modulo N is I (0 <= I < N); the\n"
             "files record the sweep and the shard for --merge (docs/cluster.md)"},
    {.name = "--merge", .commands = SSG_CLI_BENCH, .take = take_flag, .field = OF(merge),
     .help = "the arguments are shard folders of one sweep: check they cover\n"
             "every cell once and write the tables (and --plot) into --out"},
    {.name = "--reference", .arg = "NODE.PORT|FILE",
     .commands = SSG_CLI_BENCH | SSG_CLI_TUNE | SSG_CLI_VIEW, .take = take_text,
     .field = OF(reference),
     .help = "bench, tune: the truth NODE.PORT each cell's (tune: evaluation's)\n"
             "--image is compared with; tune computes it once per scene;\n"
             "view: an EXR FILE at the frame size, offered as B and as the\n"
             "metrics' reference beside the graph's ports"},
    {.name = "--image", .arg = "NODE.PORT", .commands = SSG_CLI_BENCH | SSG_CLI_TUNE,
     .take = take_text, .field = OF(image),
     .help = "the image compared with --reference"},
    {.name = "--param", .arg = "NODE.P=LO:HI[:log]", .commands = SSG_CLI_TUNE,
     .take = take_list, .field = OF(params), .count = OF(param_count),
     .hi = SSG_TUNE_MAX_PARAMS,
     .help = "a number parameter tune searches within [LO, HI] (repeatable;\n"
             ":log: searched on a log scale, LO > 0; integers are rounded)"},
    {.name = "--evals", .arg = "N", .commands = SSG_CLI_TUNE, .take = take_int,
     .field = OF(evals), .lo = 1, .hi = 10000,
     .help = "most evaluations (each runs --image on every scene; default 40)"},
    {.name = "--mask", .arg = "M", .commands = SSG_CLI_BENCH | SSG_CLI_COMPARE | SSG_CLI_TUNE,
     .take = take_text, .field = OF(mask),
     .help = "count only the pixels where M is over 0.5: compare: FILE[:LAYER];\n"
             "bench, tune: NODE.PORT of the graph (g.depth: pixels with a surface)"},
    {.name = "--peak", .arg = "P", .commands = SSG_CLI_COMPARE, .take = take_positive_text,
     .field = OF(peak), .expects = "a positive number",
     .help = "the signal's peak for the PSNR (default 1)"},
    {.name = "--depth", .arg = "D", .commands = SSG_CLI_COMPARE, .take = take_text,
     .field = OF(depth),
     .help = "FILE[:LAYER], the reference's view depth: also report the structure\n"
             "measure (structure_pp, structure_rms, structure_pixels) away from its jumps"},
    {.name = "--json", .commands = SSG_CLI_COMPARE, .take = take_flag, .field = OF(json),
     .help = "the metrics as one line of JSON"},
    {.name = "--port", .arg = "N", .commands = SSG_CLI_VIEW, .take = take_int,
     .field = OF(port), .lo = 0, .hi = 65535,
     .help = "the port to listen on, on 127.0.0.1 only (default 0: a free one)"},
};
enum { OPTION_COUNT = sizeof options / sizeof options[0] };

/* "run, check and node": the commands of a mask, as a sentence's list. */
static void command_list(unsigned mask, char *buf, size_t len)
{
    int total = 0, n = 0;
    size_t used = 0;
    buf[0] = 0;
    for (unsigned m = mask; m; m &= m - 1)
        total++;
    for (int c = 0; c < ssg_cli_command_count; c++) {
        if (!(mask & ssg_cli_commands[c].command) || used >= len)
            continue;
        n++;
        used += (size_t)snprintf(buf + used, len - used, "%s%s",
                                 n == 1 ? "" : n == total ? " and " : ", ",
                                 ssg_cli_commands[c].name);
    }
}

/* Text with each '\n' followed by an indent of `column` spaces. */
static void indented(const char *text, int column, FILE *f)
{
    for (const char *p = text; *p; p++) {
        fputc(*p, f);
        if (*p == '\n')
            fprintf(f, "%*s", column, "");
    }
}

/* "  -o, --output FILE   help", the help's further lines indented to its column. */
static void usage_option(const struct option *o, FILE *f)
{
    char head[80], alias[8] = "";
    if (o->short_name)
        snprintf(alias, sizeof alias, "-%c, ", o->short_name);
    snprintf(head, sizeof head, "%s%s%s%s", alias, o->name, o->arg ? " " : "",
             o->arg ? o->arg : "");
    int width = (int)strlen(head) <= HELP_COLUMN - 3 ? HELP_COLUMN - 3 : (int)strlen(head) + 1;
    fprintf(f, "  %-*s ", width, head);
    indented(o->help, HELP_COLUMN, f);
    fputc('\n', f);
}

static const struct ssg_cli_command_info *command_info(enum ssg_cli_command command)
{
    for (int c = 0; c < ssg_cli_command_count; c++)
        if (ssg_cli_commands[c].command == command)
            return &ssg_cli_commands[c];
    return NULL;
}

void ssg_cli_usage(FILE *f)
{
    fputs("usage: ssgraph <command> [arguments] [options]\n\ncommands:\n", f);
    for (int c = 0; c < ssg_cli_command_count; c++) {
        const struct ssg_cli_command_info *ci = &ssg_cli_commands[c];
        char head[40];
        snprintf(head, sizeof head, "%s %s", ci->name, ci->args);
        fprintf(f, "  %-15s ", head);
        indented(ci->summary, 18, f);
        fputc('\n', f);
    }
    for (int i = 0; i < OPTION_COUNT; i++) {
        if (i == 0 || options[i].commands != options[i - 1].commands) {
            char list[160];
            command_list(options[i].commands, list, sizeof list);
            fprintf(f, "\noptions of %s:\n", list);
        }
        usage_option(&options[i], f);
    }
    fputs("\n  -h, --help          a command's usage: ssgraph help COMMAND, ssgraph COMMAND "
          "--help\n  --version           the version and the build's features\n"
          "\nexit status: 0 success, 1 invalid input or failed run, 2 bad command line\n",
          f);
}

void ssg_cli_command_usage(enum ssg_cli_command command, FILE *f)
{
    const struct ssg_cli_command_info *ci = command_info(command);
    if (!ci)
        return;
    int any = 0;
    for (int i = 0; i < OPTION_COUNT; i++)
        any |= (options[i].commands & command) != 0;
    fprintf(f, "usage: ssgraph %s%s%s%s\n\n%s\n\noptions:\n", ci->name, ci->args[0] ? " " : "",
            ci->args, any ? " [options]" : "", ci->help);
    for (int i = 0; i < OPTION_COUNT; i++)
        if (options[i].commands & command)
            usage_option(&options[i], f);
    fputs("  -h, --help          this usage\n", f);
}

int ssg_cli_command_find(const char *name, enum ssg_cli_command *command)
{
    for (int c = 0; c < ssg_cli_command_count; c++)
        if (!strcmp(name, ssg_cli_commands[c].name)) {
            *command = ssg_cli_commands[c].command;
            return 1;
        }
    return 0;
}

const char *ssg_cli_command_name(enum ssg_cli_command command)
{
    const struct ssg_cli_command_info *ci = command_info(command);
    return ci ? ci->name : "?";
}

const char *ssg_cli_keep(struct ssg_cli_args *a, const char *text)
{
    size_t len = strlen(text) + 1;
    if (len > sizeof a->set_text - a->set_text_used)
        return NULL;
    char *kept = a->set_text + a->set_text_used;
    memcpy(kept, text, len);
    a->set_text_used += len;
    return kept;
}

/* The option an argument names: "--name", "--name=value", "-o", "-oVALUE"; *value is the
   value given in the same argument, else NULL. */
static const struct option *find_option(const char *arg, const char **value, char *name,
                                        size_t len)
{
    *value = NULL;
    if (arg[1] == '-') {
        const char *eq = strchr(arg, '=');
        size_t n = eq ? (size_t)(eq - arg) : strlen(arg);
        snprintf(name, len, "%.*s", (int)n, arg);
        *value = eq ? eq + 1 : NULL;
        for (int i = 0; i < OPTION_COUNT; i++)
            if (!strcmp(options[i].name, name))
                return &options[i];
        return NULL;
    }
    snprintf(name, len, "-%c", arg[1]);
    for (int i = 0; i < OPTION_COUNT; i++)
        if (options[i].short_name && options[i].short_name == arg[1]) {
            *value = arg[2] ? arg + 2 : NULL;
            return &options[i];
        }
    return NULL;
}

/* The option at argv[*i] and its value (in the same argument after '=', else argv[*i + 1],
   then skipped); short flags may come together, as getopt reads them: -qv, -qo FILE. */
static int take_option(enum ssg_cli_command command, int argc, char **argv, int *i,
                       struct ssg_cli_args *a)
{
    char name[64];
    const char *value, *arg = argv[*i];
    const struct option *opt = find_option(arg, &value, name, sizeof name);
    for (;;) {
        if (!opt)
            return ssg_cli_usage_error("unknown option '%s'", name);
        if (!(opt->commands & command)) {
            char list[160];
            command_list(opt->commands, list, sizeof list);
            return usage_errorf("option '%s' does not apply to '%s' (it is an option of %s)",
                                opt->name, ssg_cli_command_name(command), list);
        }
        if (opt->arg || !value || arg[1] == '-' || value[0] == '-')
            break;
        int rc = opt->take(a, opt, NULL); /* a short flag, more short options after it */
        if (rc)
            return rc;
        arg = value - 1; /* find_option reads the option's letter at arg[1] */
        opt = find_option(arg, &value, name, sizeof name);
    }
    if (!opt->arg && value)
        return usage_errorf("option '%s' takes no value, got '%s'", opt->name, argv[*i]);
    if (opt->arg && !value) {
        if (*i + 1 >= argc)
            return ssg_cli_usage_error("option '%s' needs a value", opt->name);
        value = argv[++*i];
    }
    return opt->take(a, opt, value);
}

static void defaults(struct ssg_cli_args *a)
{
    memset(a, 0, sizeof *a);
    a->seed = -1;
    a->guard = -1;
    a->ipd = 0.064f;
    a->ov.sets = a->sets;
}

/* The positional arguments the command wants. */
static int check_positional(enum ssg_cli_command command, const struct ssg_cli_args *a)
{
    const struct ssg_cli_command_info *ci = command_info(command);
    if (a->file_count >= ci->min_args)
        return 0;
    if (command == SSG_CLI_COMPARE)
        return ssg_cli_usage_error("%s", "compare expects two image files: A B");
    return usage_errorf("%s expects %s", ci->name, ci->args);
}

static int is_help(const char *arg)
{
    return !strcmp(arg, "--help") || !strcmp(arg, "-h");
}

int ssg_cli_parse(enum ssg_cli_command command, int argc, char **argv,
                  struct ssg_cli_args *a)
{
    int most = command_info(command)->max_args, options_end = argc;
    hint_command = ssg_cli_command_name(command);
    defaults(a);
    for (int i = 0; i < argc && options_end == argc; i++) {
        if (!strcmp(argv[i], "--"))
            options_end = i;
        else if (is_help(argv[i]))
            a->help = 1;
    }
    if (a->help)
        return 0;
    for (int i = 0; i < argc; i++) {
        int rc = 0;
        if (i < options_end && argv[i][0] == '-' && argv[i][1])
            rc = take_option(command, options_end, argv, &i, a);
        else if (i == options_end)
            continue;
        else if (a->file_count < most)
            a->files[a->file_count++] = argv[i];
        else
            rc = ssg_cli_usage_error("unexpected argument '%s'", argv[i]);
        if (rc)
            return rc;
    }
    if (a->output && a->out_dir)
        return usage_errorf("-o %s and --out %s both say where '%s' writes; give one",
                            a->output, a->out_dir, ssg_cli_command_name(command));
    if (!a->out_dir)
        a->out_dir = "out";
    a->ov.seed = a->seed;
    a->ov.guard_given = a->guard >= 0;
    a->ov.guard = a->guard;
    return check_positional(command, a);
}
