/* report.h - what `ssgraph run` prints of a graph run (report.c): the one-frame timing
 * table or the profile over the frames, the GL context, the metrics, the profile as JSON,
 * the run's notices (the files it wrote) on stdout and its progress on stderr. The
 * library prints nothing; all of it comes from struct ssg_run_stats and the callbacks of
 * struct ssg_run_options. */
#ifndef SSG_CLI_REPORT_H
#define SSG_CLI_REPORT_H

#include <stdio.h>

#include "ssgraph.h"

/* The timing table (one frame) or the profile (several), with a `load` line for each
 * library the process loaded once (graph/profile.h: the OpenImageIO module), then "GL: ..."
 * when a node ran on GL, then the metrics, as `ssgraph run` has always printed them. */
void ssg_report_print(const struct ssg_run_stats *stats, FILE *stream);

/* The profile of the stats as JSON at path, whole or not at all (--profile-json), with the
 * process's one-off loads as "loads": [{"what": ..., "ms": ...}]. */
enum ssg_err ssg_report_write_json(const struct ssg_run_stats *stats, const char *path,
                                   struct ssg_diags *diags);

/* A progress callback (ssg_progress_fn) drawing a bar on stderr, for a terminal: the
 * caller installs it only when stderr is one. `user` is unused. */
void ssg_report_progress(void *user, const struct ssg_progress_event *event);

/* A log callback (ssg_log_fn) printing each line to stdout: today the `wrote PATH` line
 * of each file a run writes, as it is written, before the table. `user` is unused. */
void ssg_report_log(void *user, const char *line);

#endif
