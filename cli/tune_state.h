/* tune_state.h - what the two halves of `ssgraph tune` share (private to cli/): tune.c
 * checks the request, computes the references and evaluates points; tune_out.c prints
 * each evaluation and writes tune.csv, tune.json and tuned.graph. */
#ifndef SSG_CLI_TUNE_STATE_H
#define SSG_CLI_TUNE_STATE_H

#include <stdio.h>

#include "tune.h"

struct tune_param {
    char key[128];                    /* node.param */
    double lo, hi;                    /* the searched range (integers: rounded inwards) */
    int log;                          /* 1 = searched on a log scale (lo > 0) */
    int integer;                      /* 1 = an integer parameter: values rounded */
    double start;                     /* the graph's own value */
};

struct tune_eval {
    double values[SSG_TUNE_MAX_PARAMS]; /* as passed to the graph */
    double errors[SSG_TUNE_MAX_SCENES]; /* RMSE per scene; NaN = not computed */
    double mean;                      /* over the scenes; NaN when the evaluation failed */
    char error[1100];                 /* why it failed ("" = it did not) */
};

struct tune {
    const struct ssg_tune_request *req;
    struct tune_param params[SSG_TUNE_MAX_PARAMS];
    int n;                            /* params */
    const char *scenes[SSG_TUNE_MAX_SCENES]; /* NULL = the graph's own */
    int scene_count;
    struct ssg_image *ref[SSG_TUNE_MAX_SCENES], *mask[SSG_TUNE_MAX_SCENES];
    struct ssg_graph *live[SSG_TUNE_MAX_SCENES]; /* each scene's graph, loaded once with only
                                                    the image live and kept between
                                                    evaluations (ssg_graph_keep) */
    struct tune_eval *evals;          /* in the order they ran */
    int count, budget;
    int best;                         /* index into evals; -1 = none succeeded yet */
};

/* A parameter's value as the graph is given it ("%.6g", integers without decimals). */
void ssg_tune_format(const struct tune_param *p, double v, char *buf, size_t len);

/* The scene's short name for the evaluation lines ("cornell"). */
void ssg_tune_scene_name(const struct tune *t, int s, char *buf, size_t len);

/* One line for evaluation i: its number, values, per-scene errors and mean. */
void ssg_tune_print_eval(const struct tune *t, int i, FILE *f);

/* The best evaluation's values and per-scene errors against the first's (the start). */
void ssg_tune_print_best(const struct tune *t, FILE *f);

/* tune.csv and tune.json rewritten whole, and tuned.graph when an evaluation succeeded,
 * each through a temporary and a rename (files.h): an interrupted or failing tune keeps
 * every evaluation it finished. */
enum ssg_err ssg_tune_save(const struct tune *t, struct ssg_diags *d);

#endif
