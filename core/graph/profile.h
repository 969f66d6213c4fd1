/* profile.h - the per-node profile of a graph run over several frames (`ssgraph run
 * --frames N`): for every node its calls, average, minimum and maximum milliseconds, its
 * share of the frame (sinks, which run in the last frame only, have none), its one-off
 * prepare() time, and on GL the timer queries' average; handed to the caller in struct
 * ssg_run_stats (ssgraph.h), which `ssgraph run` prints as a profiler's table. */
#ifndef SSG_PROFILE_H
#define SSG_PROFILE_H

#include "graph/exec.h"

/* Every value of a series, in order, for its median. */
struct ssg_series {
    double *v;
    int n, cap;
};

struct ssg_profile_row {
    const char *name, *type, *backend; /* node instance, node type, "cpu" or "gl" */
    int calls;
    double sum, min, max;  /* ms of its runs, prepare excluded */
    struct ssg_series runs; /* the same, each run's */
    double prepare_ms;     /* its one prepare() */
    double gpu_sum, xfer_sum;
    double bytes, flops;   /* a run's (exec.h, ssg_node_cost); flops -1 = undeclared */
};

struct ssg_profile {
    int rows_count, frames;
    struct ssg_profile_row *rows;          /* in run order */
    double frame_sum, frame_min, frame_max; /* ms of a whole frame (every node's run) */
    struct ssg_series frame_ms;             /* each frame's */
    int width, height, threads;
};

/* Rows for `count` nodes (names filled by the caller); 0 on out of memory. */
int ssg_profile_init(struct ssg_profile *p, int count);
void ssg_profile_free(struct ssg_profile *p);
/* Adds one run of row r; 0 on out of memory. */
int ssg_profile_add(struct ssg_profile *p, int r, const struct ssg_node_timing *t);
/* Adds one frame's total; 0 on out of memory. */
int ssg_profile_frame(struct ssg_profile *p, double ms);
/* Fills the frame and node parts of *s (zeroed by the caller) from the profile and the
 * last frame's timing of each row; 0 on out of memory (what it allocated stays in *s, for
 * ssg_run_stats_free). */
int ssg_profile_stats(const struct ssg_profile *p, const struct ssg_node_timing *last,
                      struct ssg_run_stats *s);

#endif
