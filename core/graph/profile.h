/* profile.h - the per-node profile of a graph run over several frames (`ssgraph run
 * --frames N`): for every node its calls, average, minimum and maximum milliseconds, its
 * share of the frame (sinks, which run in the last frame only, have none), its one-off
 * prepare() time, and on GL the timer queries' average,
 * printed as a table like a GPU profiler's and written as JSON (--profile-json). */
#ifndef SSG_PROFILE_H
#define SSG_PROFILE_H

#include <stdio.h>

#include "graph/exec.h"

struct ssg_profile_row {
    const char *name, *type, *backend; /* node instance, node type, "cpu" or "gl" */
    int calls;
    double sum, min, max;  /* ms of its runs, prepare excluded */
    double prepare_ms;     /* its one prepare() */
    double gpu_sum, xfer_sum;
};

struct ssg_profile {
    int rows_count, frames;
    struct ssg_profile_row *rows;          /* in run order */
    double frame_sum, frame_min, frame_max; /* ms of a whole frame (every node's run) */
    int width, height, threads;
};

/* Rows for `count` nodes (names filled by the caller); 0 on out of memory. */
int ssg_profile_init(struct ssg_profile *p, int count);
void ssg_profile_free(struct ssg_profile *p);
/* Adds one run of row r. */
void ssg_profile_add(struct ssg_profile *p, int r, const struct ssg_node_timing *t);
/* Adds one frame's total. */
void ssg_profile_frame(struct ssg_profile *p, double ms);
void ssg_profile_print(const struct ssg_profile *p, FILE *stream);
/* The profile as JSON at path, whole or not at all. */
enum ssg_err ssg_profile_write_json(const struct ssg_profile *p, const char *path,
                                    struct ssg_diags *diags);

#endif
