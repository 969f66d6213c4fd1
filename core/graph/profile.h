/* profile.h - the per-node profile of a graph run over several frames (`ssgraph run
 * --frames N`): for every node its calls, average, minimum and maximum milliseconds, its
 * share of the frame (sinks, which run in the last frame only, have none), its one-off
 * prepare() time, and on GL the timer queries' average; handed to the caller in struct
 * ssg_run_stats (ssgraph.h), which `ssgraph run` prints as a profiler's table.
 *
 * One-off loads: libraries a process opens at run time, once (the OpenImageIO module on
 * the first image of a format only it reads; the GL library), are noted where they happen
 * (ssg_load_note, thread-safe) and kept for the process. A node run that contains one is
 * not charged for it: ssg_profile_add takes it out of the node's times, and the report
 * prints each load on a line of its own (ssg_loads). The frame totals still contain a load
 * that happened inside a pass (none does today: the GL library opens before the first
 * frame, the module inside a sink or before the run). */
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
    double load_ms;        /* one-off loads inside its last run, taken out of its times */
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

/* SSG_LOADS_MAX and struct ssg_load: in ssgraph.h (public). */

/* Notes that `what` (a static string) was loaded from t0_ms to t1_ms (ssg_now_ms).
 * Thread-safe; call it once per load. */
void ssg_load_note(const char *what, double t0_ms, double t1_ms);

/* ssg_loads: in ssgraph.h (public). */

#endif
