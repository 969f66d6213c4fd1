/* tune.h - `ssgraph tune` (tune.c): a search over number parameters of a graph for the
 * lowest mean error of one of its images against one of its references over several
 * scenes, each reference computed once; every evaluation written to tune.csv and
 * tune.json as it finishes, the best values as tuned.graph. */
#ifndef SSG_CLI_TUNE_H
#define SSG_CLI_TUNE_H

#include "ssgraph.h"

#define SSG_TUNE_MAX_SCENES 16
#define SSG_TUNE_MAX_PARAMS 8 /* = SSG_SEARCH_MAX_DIMS (tune_search.h) */

struct ssg_tune_request {
    const char *graph;                /* the graph file */
    const struct ssg_overrides *ov;   /* --size, --set, --seed, --backend (scene: below) */
    const char *const *scenes;        /* --scene files; none = the graph's own scene */
    int scene_count;
    const char *const *params;        /* "node.param=lo:hi" or "node.param=lo:hi:log" */
    int param_count;
    const char *reference;            /* NODE.PORT: the truth, computed once per scene */
    const char *image;                /* NODE.PORT: the image compared with it */
    const char *mask;                 /* NODE.PORT: pixels counted where over 0.5; NULL =
                                         every pixel */
    int evals;                        /* most evaluations; 0 = 40 */
    int threads;                      /* 0 = all cores */
    const char *out_dir;              /* tune.csv, tune.json, tuned.graph */
    int quiet;                        /* 1 = errors only: no evaluation lines, no best, no
                                         wrote lines (the files hold them) */
    int verbose;                      /* 1 = also each scene's reference time */
};

/* Runs the tune; returns the process exit code: 0 done, 1 bad input (a parameter, range,
 * port or scene the graph refuses) or a failed evaluation or write (what was written
 * before stays), 2 a missing option. */
int ssg_tune_main(const struct ssg_tune_request *req);

#endif
