/* watch.h - a polling file watcher for a graph and everything it reads (watch.c), and the
 * `ssgraph run --watch` loop on it (watch_run.c). The viewer's server (cli/view/) reloads
 * with the same watcher.
 *
 * A watcher keeps a snapshot of each file it watches: whether it exists, its mtime (ns),
 * size and inode. ssg_cli_watch_changed() compares the files on disk with it: a file
 * edited, removed, re-created or replaced (an editor's save by rename) has changed.
 * Typical use:
 *     w = ssg_cli_watch_new(path);                    before the first load reads it
 *     e = ssg_graph_load(path, &ov, &g, &d);
 *     ssg_cli_watch_load(w, g, &ov);                  g NULL when the load failed
 *     every 300 ms: if ((file = ssg_cli_watch_changed(w))) reload, then watch_load again
 * The set of files comes from the public API (ssg_graph_files): the graph file, its
 * includes, the scene and lights files and the models, textures and environment image
 * they name. A file whose snapshot exists keeps it across ssg_cli_watch_load, so an edit
 * made while a reload was reading the files is still seen by the next poll (the snapshot
 * is what changed() saw before the reload, not what was there after it).
 * Not thread-safe: one thread owns a watcher. Plain C on POSIX stat(); no inotify, so it
 * works on every file system (network and container mounts too). */
#ifndef SSG_CLI_WATCH_H
#define SSG_CLI_WATCH_H

#include "ssgraph.h"

struct ssg_cli_args;
struct ssg_cli_watch;

/* A watcher of the graph file `top` (the path as the load is given it), which it snapshots
 * now and always watches. NULL when out of memory. */
struct ssg_cli_watch *ssg_cli_watch_new(const char *top);
/* Frees it and sets *w to NULL. */
void ssg_cli_watch_free(struct ssg_cli_watch **w);

/* After a load: watches the files `graph` depends on, or, when graph is NULL (the load
 * failed), those ssg_graph_parse of the top file reads so far together with ov's scene
 * and lights overrides (ov may be NULL) and what they name; the top file always. Files no
 * longer named stop being watched. 0, or -1 when out of memory (the watcher then watches
 * what it watched before). */
int ssg_cli_watch_load(struct ssg_cli_watch *w, const struct ssg_graph *graph,
                       const struct ssg_overrides *ov);

/* The first watched file (in ssg_graph_files order) that is not as its snapshot says, or
 * NULL when none is. Every snapshot is brought up to date, so each change is reported
 * once. The string is the watcher's, valid until the next ssg_cli_watch_load or free. */
const char *ssg_cli_watch_changed(struct ssg_cli_watch *w);

/* How many files it watches; file i's path (NULL out of range). */
int ssg_cli_watch_count(const struct ssg_cli_watch *w);
const char *ssg_cli_watch_file(const struct ssg_cli_watch *w, int i);

/* ---- `ssgraph run --watch` (watch_run.c) */

/* One load and run of the graph with the command line's options; the watcher is told of
 * the load (ssg_cli_watch_load) before the run. Problems go to diags. */
typedef enum ssg_err (*ssg_cli_watch_run_fn)(const struct ssg_cli_args *a,
                                             struct ssg_cli_watch *w,
                                             struct ssg_diags *diags);

/* Runs the graph once, then polls its files every 300 ms and runs it again (a fresh load:
 * the same overrides) after each change, printing which file changed and, after each run,
 * "watch: run N done" or "watch: run N failed" (with the diagnostics on stderr) to stdout.
 * A failed load or run keeps it waiting for the next change. SIGINT or SIGTERM end it
 * with exit status 0: between runs at once, during a run after removing the run's
 * temporary files (ssg_tmp_remove_all), so no output is left half written. Returns the
 * exit status (1 when the watcher cannot be made). */
int ssg_cli_run_watch(const struct ssg_cli_args *a, ssg_cli_watch_run_fn run);

#endif
