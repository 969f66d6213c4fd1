/* behind.h - files written behind the frames of a sequence (issue 47): a sink that writes
 * files (write) hands a self-contained job (its own copies of the images, the paths, the
 * metadata) to one worker thread and returns, so the next frame's passes run while the
 * frame before is compressed and written. Jobs run one at a time in the order given, so
 * files appear in frame order; at most `depth` wait or run at once (a job given while the
 * queue is full waits for room: memory stays bounded when writing is slower than the
 * frames). The first job that fails stops the queue: the jobs after it are freed unrun,
 * and its error and messages come back from the next ssg_behind_submit or
 * ssg_behind_finish, on the caller's thread. A job's own parallel loops (EXR chunks, PNG
 * rows) run on a team of `threads`, the worker's own; a file's bytes never depend on the
 * thread count (imageio.h).
 *
 * Thread safety: one caller thread gives jobs and finishes; the worker only runs them.
 * A job must not read anything the caller changes after handing it over. */
#ifndef SSG_BEHIND_H
#define SSG_BEHIND_H

#include "ssgraph.h"

struct ssg_behind;

/* What a job does on the worker: write its files, report problems to diags (its own,
   handed back to the caller when it fails). */
typedef enum ssg_err (*ssg_behind_run_fn)(void *job, struct ssg_diags *diags);
/* Frees a job, run or not. */
typedef void (*ssg_behind_free_fn)(void *job);

/* A queue and its worker thread, whose jobs' parallel loops take `threads` threads; NULL
   when either cannot be made (the caller then writes in the frame, as without one). */
struct ssg_behind *ssg_behind_create(int depth, int threads);

/* Hands a job over (the queue owns it from here, whatever the result). Returns an earlier
   job's failure, with its messages appended to diags; the job is then freed unrun. */
enum ssg_err ssg_behind_submit(struct ssg_behind *b, ssg_behind_run_fn run,
                               ssg_behind_free_fn free_job, void *job,
                               struct ssg_diags *diags);

/* A job that ran without failure, handed back (the caller owns it again) so that its
   memory, already touched, serves the next one instead of fresh pages that fault on first
   write; NULL when none is kept. Only jobs freed by free_job are handed back. One is
   kept; the rest are freed as they finish. */
void *ssg_behind_spare(struct ssg_behind *b, ssg_behind_free_fn free_job);

/* Jobs handed over and jobs finished without failure, since the queue was made. */
long ssg_behind_submitted(const struct ssg_behind *b);
long ssg_behind_done(struct ssg_behind *b);

/* Waits until every job handed over has run (or was dropped after a failure); returns
   the first failure, its messages appended to diags, as ssg_behind_submit does. */
enum ssg_err ssg_behind_finish(struct ssg_behind *b, struct ssg_diags *diags);

/* Finishes (dropping any failure), stops the worker and frees the queue; *b = NULL. */
void ssg_behind_destroy(struct ssg_behind **b);

#endif
