/* behind.c - the queue of files written behind a sequence's frames (behind.h): a ring of
 * at most `depth` jobs, one worker thread that runs them in order, one mutex and two
 * condition variables (room for the caller, work for the worker). */
#include <omp.h>
#include <pthread.h>
#include <stdlib.h>

#include "graph/behind.h"

/* Finished jobs kept for reuse: one is enough for a frame a job (the next frame's takes
   it back), and each holds a frame's copies. */
enum { SPARES = 1 };

struct job {
    ssg_behind_run_fn run;
    ssg_behind_free_fn free_job;
    void *data;
};

struct ssg_behind {
    pthread_t worker;
    pthread_mutex_t lock;
    pthread_cond_t changed; /* a job was queued or finished, or the queue is stopping */
    struct job *ring;
    struct job *spare;      /* jobs run without failure, kept for ssg_behind_spare */
    int spare_count;
    int threads; /* OpenMP threads of a job's parallel loops */
    int depth, head, count; /* jobs waiting or running: ring[head .. head + count) */
    long submitted, done;
    int stopping;
    enum ssg_err failed;      /* the first failure; later jobs are dropped */
    int failure_told;         /* its messages went to a caller already */
    struct ssg_diags failure; /* the failing job's messages */
};

/* Appends what `from` recorded to `to` (both plain lists: ssgraph.h). */
static void append_diags(struct ssg_diags *to, const struct ssg_diags *from)
{
    if (!to)
        return;
    for (int i = 0; i < from->count && to->count < SSG_DIAGS_MAX; i++)
        to->items[to->count++] = from->items[i];
    to->total += from->total;
}

/* The failure, told once: the first caller to ask gets its messages. Under the lock. */
static enum ssg_err take_failure(struct ssg_behind *b, struct ssg_diags *diags)
{
    if (b->failed && !b->failure_told) {
        append_diags(diags, &b->failure);
        b->failure_told = 1;
    }
    return b->failed;
}

/* Runs the job at the head outside the lock; its result decides the rest of the queue. A
   job that ran well is kept as a spare while there is room, else freed, outside the lock
   (giving back a frame's pages takes a while) but before its place in the queue is, so
   the jobs alive never exceed the queue's depth and the spare. */
static void run_head(struct ssg_behind *b)
{
    struct job j = b->ring[b->head];
    int dropped = b->failed != SSG_OK;
    pthread_mutex_unlock(&b->lock);
    struct ssg_diags diags = {0};
    enum ssg_err e = dropped ? SSG_OK : j.run(j.data, &diags);
    pthread_mutex_lock(&b->lock);
    int keep = !e && !dropped && b->spare_count < SPARES;
    if (keep)
        b->spare[b->spare_count++] = j;
    if (e && !b->failed) {
        b->failed = e;
        b->failure = diags;
    } else if (!e && !dropped) {
        b->done++;
    }
    if (!keep) {
        pthread_mutex_unlock(&b->lock);
        j.free_job(j.data);
        pthread_mutex_lock(&b->lock);
    }
    b->head = (b->head + 1) % b->depth;
    b->count--;
    pthread_cond_broadcast(&b->changed);
}

static void *work(void *arg)
{
    struct ssg_behind *b = arg;
    /* a job's parallel loops (EXR chunks, PNG rows) on as many threads as the frames'
       passes: the files' bytes are the same on any number */
    omp_set_num_threads(b->threads);
    pthread_mutex_lock(&b->lock);
    for (;;) {
        while (!b->count && !b->stopping)
            pthread_cond_wait(&b->changed, &b->lock);
        if (!b->count)
            break; /* stopping, nothing left */
        run_head(b);
    }
    pthread_mutex_unlock(&b->lock);
    return NULL;
}

struct ssg_behind *ssg_behind_create(int depth, int threads)
{
    struct ssg_behind *b = calloc(1, sizeof *b);
    if (!b)
        return NULL;
    b->depth = depth > 0 ? depth : 1;
    b->threads = threads > 0 ? threads : 1;
    b->ring = calloc((size_t)b->depth, sizeof *b->ring);
    b->spare = calloc(SPARES, sizeof *b->spare);
    if (!b->ring || !b->spare) {
        free(b->ring);
        free(b->spare);
        free(b);
        return NULL;
    }
    int made = 0; /* 1: lock, 2: condition, 3: thread */
    if (pthread_mutex_init(&b->lock, NULL) == 0 && ++made &&
        pthread_cond_init(&b->changed, NULL) == 0 && ++made &&
        pthread_create(&b->worker, NULL, work, b) == 0)
        return b;
    if (made >= 2)
        pthread_cond_destroy(&b->changed);
    if (made >= 1)
        pthread_mutex_destroy(&b->lock);
    free(b->ring);
    free(b->spare);
    free(b);
    return NULL;
}

enum ssg_err ssg_behind_submit(struct ssg_behind *b, ssg_behind_run_fn run,
                               ssg_behind_free_fn free_job, void *job,
                               struct ssg_diags *diags)
{
    pthread_mutex_lock(&b->lock);
    while (b->count == b->depth && !b->failed)
        pthread_cond_wait(&b->changed, &b->lock);
    enum ssg_err e = take_failure(b, diags);
    if (!e) {
        b->ring[(b->head + b->count) % b->depth] =
            (struct job){.run = run, .free_job = free_job, .data = job};
        b->count++;
        b->submitted++;
        pthread_cond_broadcast(&b->changed);
    }
    pthread_mutex_unlock(&b->lock);
    if (e)
        free_job(job);
    return e;
}

void *ssg_behind_spare(struct ssg_behind *b, ssg_behind_free_fn free_job)
{
    void *job = NULL;
    pthread_mutex_lock(&b->lock);
    for (int i = b->spare_count - 1; i >= 0 && !job; i--)
        if (b->spare[i].free_job == free_job) {
            job = b->spare[i].data;
            b->spare[i] = b->spare[--b->spare_count];
        }
    pthread_mutex_unlock(&b->lock);
    return job;
}

long ssg_behind_submitted(const struct ssg_behind *b)
{
    return b->submitted; /* written by the caller's thread only */
}

long ssg_behind_done(struct ssg_behind *b)
{
    pthread_mutex_lock(&b->lock);
    long done = b->done;
    pthread_mutex_unlock(&b->lock);
    return done;
}

enum ssg_err ssg_behind_finish(struct ssg_behind *b, struct ssg_diags *diags)
{
    pthread_mutex_lock(&b->lock);
    while (b->count)
        pthread_cond_wait(&b->changed, &b->lock);
    enum ssg_err e = take_failure(b, diags);
    pthread_mutex_unlock(&b->lock);
    return e;
}

void ssg_behind_destroy(struct ssg_behind **bp)
{
    struct ssg_behind *b = *bp;
    if (!b)
        return;
    pthread_mutex_lock(&b->lock);
    b->stopping = 1;
    pthread_cond_broadcast(&b->changed);
    pthread_mutex_unlock(&b->lock);
    pthread_join(b->worker, NULL); /* it runs what is left first */
    for (int i = 0; i < b->spare_count; i++)
        b->spare[i].free_job(b->spare[i].data);
    free(b->spare);
    pthread_cond_destroy(&b->changed);
    pthread_mutex_destroy(&b->lock);
    free(b->ring);
    free(b);
    *bp = NULL;
}
