/* options.h - the command line's commands and options (options.c): one table of the
 * commands (name, arguments, help) and one of every option (long and short name, argument,
 * the commands it applies to, help, how its value is taken), which parse argv, write the
 * usage text (`ssgraph help`) and each command's own (`ssgraph help run`, `run --help`).
 * An option given to a command it does not apply to is a usage error. Values come as
 * `--size 64x48`, `--size=64x48`, `-o FILE` or `-oFILE`; `--` ends the options.
 * Ownership: the parsed arguments point into argv (or into the args' own buffers). */
#ifndef SSG_CLI_OPTIONS_H
#define SSG_CLI_OPTIONS_H

#include <stdio.h>

#include "bench.h"
#include "tune.h"
#include "ssgraph.h"

/* The commands that take options, as bits of an option's mask. */
enum ssg_cli_command {
    SSG_CLI_RUN = 1u << 0,
    SSG_CLI_CHECK = 1u << 1,
    SSG_CLI_NODE = 1u << 2,
    SSG_CLI_BENCH = 1u << 3,
    SSG_CLI_COMPARE = 1u << 4,
    SSG_CLI_TUNE = 1u << 5,
    SSG_CLI_DOT = 1u << 6,
    SSG_CLI_NODES = 1u << 7,
    SSG_CLI_DESCRIBE = 1u << 8,
    SSG_CLI_DOCS = 1u << 9,
    SSG_CLI_HELP = 1u << 10,
    SSG_CLI_LAYERS = 1u << 11,
    SSG_CLI_EXTRACT = 1u << 12,
    SSG_CLI_VIEW = 1u << 13,
};

enum { SSG_CLI_MAX_FILES = 1024, SSG_CLI_MAX_SETS = 256, SSG_CLI_MAX_INPUTS = 24, SSG_CLI_EXIT_USAGE = 2,
       SSG_CLI_SET_TEXT = 8192 };

/* What the command line said; zero-initialised, then defaults, by ssg_cli_parse. */
struct ssg_cli_args {
    const char *files[SSG_CLI_MAX_FILES]; /* positional: FILE (node, describe: NODE; help:
                                        COMMAND); compare: A and B; bench --merge: the
                                        shard folders */
    int file_count;
    struct ssg_overrides ov;         /* --scene (the last), --size, --set, --seed, --backend */
    const char *scenes[SSG_TUNE_MAX_SCENES]; /* tune: every --scene, in order */
    int scene_count;
    const char *sets[SSG_CLI_MAX_SETS];
    int seed;                        /* --seed; -1 = the graph's own */
    int guard;                       /* --guard, px; -1 = the graph's own */
    const char *inputs[SSG_CLI_MAX_INPUTS]; /* node: --in port=file[:layer] */
    int input_count;
    const char *out_dir;             /* --out; default "out" */
    int threads;                     /* --threads; 0 = all cores */
    int quiet;                       /* run, node: --quiet, -q: no table, no progress, no
                                        `wrote` lines */
    int verbose;                     /* run, node: --verbose, -v: also the resolved
                                        parameters and sizes */
    const char *output;              /* run, node, dot: --output, -o FILE */
    int help;                        /* --help, -h: the command's usage, nothing run */
    char set_text[SSG_CLI_SET_TEXT]; /* the --set values rewritten with quotes (bare
                                        strings) or added by -o; sets point here */
    size_t set_text_used;            /* bytes of set_text in use */
    float fov;                       /* node: --fov, degrees; 0 = the default */
    int frames;                      /* run, bench: --frames; 0 = the command's default */
    const char *profile_json;        /* run: --profile-json */
    const char *sweeps[SSG_BENCH_MAX_SWEEPS]; /* bench: node.param=v1,v2,... */
    int sweep_count;
    const char *time_node;           /* bench: --time */
    const char *error_metric;        /* bench: --error */
    int plot;                        /* bench: --plot */
    const char *shard;               /* bench: --shard I/N, as written */
    int merge;                       /* bench: --merge */
    const char *reference, *image;   /* bench, tune: --reference, --image (NODE.PORT);
                                        view: --reference FILE.exr */
    const char *params[SSG_TUNE_MAX_PARAMS]; /* tune: --param node.p=lo:hi[:log] */
    int param_count;
    int evals;                       /* tune: --evals; 0 = its default */
    int stereo;                      /* run, bench: --stereo */
    float ipd;                       /* run, bench: --ipd, scene units; default 0.064 */
    const char *mask;                /* compare: --mask FILE[:LAYER]; bench, tune: NODE.PORT */
    const char *peak;                /* compare: --peak, checked positive; NULL = 1 */
    const char *depth;               /* compare: --depth FILE[:LAYER]; NULL = no structure */
    int json;                        /* compare: --json */
    int port;                        /* view: --port; 0 = a free one */
    const char *show;                /* run: --show NODE.PORT[,...], as written */
    const char *tonemap;             /* run (--show), extract: --tonemap of the PNGs; NULL =
                                        the write node's default (aces) */
    float exposure;                  /* run (--show), extract: --exposure, stops; 0 */
    int watch;                       /* run: --watch: run again on each change (watch.h) */
};

/* The command of that name ("run"); 0 when there is none. */
int ssg_cli_command_find(const char *name, enum ssg_cli_command *command);
/* Its name ("run"); "?" for a value that is not one command. */
const char *ssg_cli_command_name(enum ssg_cli_command command);

/* Parses the arguments after the command into *a. Returns 0, or prints the usage error
 * (unknown option, an option of another command, a bad value, a missing or extra
 * positional argument) to stderr and returns SSG_CLI_EXIT_USAGE. With --help anywhere
 * before `--`, returns 0 with a->help set and checks nothing else. */
int ssg_cli_parse(enum ssg_cli_command command, int argc, char **argv,
                  struct ssg_cli_args *a);

/* Prints "ssgraph: error: <message>" and the hint to `ssgraph help COMMAND` (the command
 * ssg_cli_parse was last given, else `ssgraph help`); returns SSG_CLI_EXIT_USAGE. */
int ssg_cli_usage_error(const char *fmt, const char *arg);

/* The whole usage text (commands, then the options of the table grouped by the commands
 * they apply to). */
void ssg_cli_usage(FILE *stream);

/* One command's usage: its synopsis, what it does, and only its options. */
void ssg_cli_command_usage(enum ssg_cli_command command, FILE *stream);

/* A copy of text kept in a->set_text (the --set entries the command line makes: a bare
 * string quoted, -o's file name); NULL when it does not fit. */
const char *ssg_cli_keep(struct ssg_cli_args *a, const char *text);

#endif
