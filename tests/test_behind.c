/* test_behind.c - a sequence's files written behind its frames (core/graph/behind.h):
 *   - the queue runs jobs in the order given, never holds more than its depth, and after a
 *     job fails drops the rest unrun and hands the failure back once, with its messages;
 *     a job that ran is handed back for reuse (one at a time, only to its own kind);
 *   - a 3-frame sequence (written behind) gives the bytes each frame gives when run alone
 *     (a one-frame run writes in the frame), tells every file on the caller's thread in
 *     frame order, and only once the file is there;
 *   - a frame whose file cannot be written fails the run with a message naming it, the
 *     frames after it are not written, and nothing half-written or temporary is left. */
#include <dirent.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "check.h"
#include "graph/behind.h"
#include "lang/diag.h"
#include "ssgraph.h"

enum { FRAMES = 3, JOBS = 12, DEPTH = 2 };

/* ---- the queue alone ---- */

struct order {
    pthread_mutex_t lock;
    int ran[JOBS], count; /* ids in the order run */
    int alive, most_alive; /* jobs made and not yet freed */
    int fail_at;          /* the id that fails; -1 = none */
};

struct job {
    struct order *o;
    int id;
};

static enum ssg_err job_run(void *data, struct ssg_diags *diags)
{
    struct job *j = data;
    struct timespec wait = {0, j->id % 3 ? 200000 : 2000000}; /* some slower than the caller */
    nanosleep(&wait, NULL);
    pthread_mutex_lock(&j->o->lock);
    j->o->ran[j->o->count++] = j->id;
    pthread_mutex_unlock(&j->o->lock);
    if (j->id == j->o->fail_at) {
        ssg_diag_file(diags, SSG_E_IO, "job", "job %d failed", j->id);
        return SSG_E_IO;
    }
    return SSG_OK;
}

static void job_free(void *data)
{
    struct job *j = data;
    pthread_mutex_lock(&j->o->lock);
    j->o->alive--;
    pthread_mutex_unlock(&j->o->lock);
    free(j);
}

static struct job *job_make(struct order *o, int id)
{
    struct job *j = malloc(sizeof *j);
    CHECK(j != NULL);
    if (!j)
        exit(1);
    *j = (struct job){.o = o, .id = id};
    pthread_mutex_lock(&o->lock);
    if (++o->alive > o->most_alive)
        o->most_alive = o->alive;
    pthread_mutex_unlock(&o->lock);
    return j;
}

/* JOBS jobs through a queue of DEPTH, job fail_at failing; returns the first submit that
   reported a failure (-1 = none). */
static int run_jobs(struct order *o, struct ssg_diags *d, enum ssg_err *finished)
{
    struct ssg_behind *b = ssg_behind_create(DEPTH, 1);
    CHECK(b != NULL);
    if (!b)
        exit(1);
    int refused = -1;
    for (int id = 0; id < JOBS; id++)
        if (ssg_behind_submit(b, job_run, job_free, job_make(o, id), d) && refused < 0)
            refused = id;
    *finished = ssg_behind_finish(b, d);
    CHECK_EQ(ssg_behind_submitted(b), refused < 0 ? JOBS : refused);
    CHECK_EQ(ssg_behind_done(b), o->fail_at < 0 ? JOBS : o->fail_at);
    ssg_behind_destroy(&b);
    CHECK(b == NULL);
    return refused;
}

static void test_queue(void)
{
    struct order o = {.lock = PTHREAD_MUTEX_INITIALIZER, .fail_at = -1};
    struct ssg_diags d = {0};
    enum ssg_err finished;
    CHECK_EQ(run_jobs(&o, &d, &finished), -1);
    CHECK_EQ(finished, SSG_OK);
    CHECK_EQ(o.count, JOBS);
    for (int i = 0; i < o.count; i++)
        CHECK_EQ(o.ran[i], i);
    CHECK_EQ(o.alive, 0);
    /* DEPTH queued or running, one kept for reuse, and the one the caller is handing over */
    CHECK(o.most_alive <= DEPTH + 2);
    CHECK_EQ(d.count, 0);

    struct order f = {.lock = PTHREAD_MUTEX_INITIALIZER, .fail_at = 4};
    struct ssg_diags fd = {0};
    int refused = run_jobs(&f, &fd, &finished);
    CHECK(refused > 4 && refused <= 4 + DEPTH + 1); /* told at a later hand-over */
    CHECK_EQ(finished, SSG_E_IO); /* and again at the end, its messages once */
    CHECK_EQ(f.count, 5);         /* nothing after the failure ran */
    CHECK_EQ(f.alive, 0);         /* every job freed, run or not */
    CHECK_EQ(fd.count, 1);
    CHECK(fd.count == 1 && strstr(fd.items[0].message, "job 4 failed"));
}

static void other_free(void *data)
{
    free(data);
}

/* The last job that ran comes back once, to a caller that frees jobs as it does. */
static void test_spare(void)
{
    struct order o = {.lock = PTHREAD_MUTEX_INITIALIZER, .fail_at = -1};
    struct ssg_diags d = {0};
    struct ssg_behind *b = ssg_behind_create(DEPTH, 1);
    CHECK(b != NULL);
    if (!b)
        return;
    CHECK(ssg_behind_spare(b, job_free) == NULL); /* nothing ran yet */
    for (int id = 0; id < 3; id++)
        CHECK_EQ(ssg_behind_submit(b, job_run, job_free, job_make(&o, id), &d), SSG_OK);
    CHECK_EQ(ssg_behind_finish(b, &d), SSG_OK);
    CHECK(ssg_behind_spare(b, other_free) == NULL);
    struct job *j = ssg_behind_spare(b, job_free);
    CHECK(j != NULL && j->id >= 0 && j->id < 3);
    CHECK(ssg_behind_spare(b, job_free) == NULL); /* one is kept */
    CHECK_EQ(o.alive, 1);
    if (j)
        job_free(j);
    ssg_behind_destroy(&b);
    CHECK_EQ(o.alive, 0);
}

/* ---- through the executor ---- */

struct told {
    pthread_t caller;
    int off_thread, lines, missing;
    char line[2 * FRAMES][1200];
};

static void on_log(void *user, const char *line)
{
    struct told *t = user;
    struct stat st;
    t->off_thread += !pthread_equal(pthread_self(), t->caller);
    t->missing += strncmp(line, "wrote ", 6) || stat(line + 6, &st) != 0;
    if (t->lines < 2 * FRAMES)
        snprintf(t->line[t->lines++], sizeof t->line[0], "%s", line);
}

static void write_graph(const char *path)
{
    char cwd[900] = ".";
    FILE *f = fopen(path, "w");
    CHECK(f != NULL && getcwd(cwd, sizeof cwd) != NULL);
    if (!f)
        return;
    fprintf(f, "scene \"%s/examples/cornell_orbit.scene\"\nsize 40 24\n"
               "g   = gbuffer()\n"
               "k   = halton(count=8, bases=[2, 3])\n"
               "ao  = ssao(g.position, g.normal, kernel=k.samples, rotation=k.rotation)\n"
               "out = write(ao.out, \"t\", normal=g.normal, depth=g.depth, sequence=true)\n",
            cwd);
    fclose(f);
}

static struct ssg_graph *load(const char *graph)
{
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(graph, NULL, &g, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!g)
        exit(check_report());
    return g;
}

static int same_file(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    int same = fa && fb;
    for (int ca = 0, cb = 0; same && ca != EOF; same = ca == cb)
        ca = fgetc(fa), cb = fgetc(fb);
    if (fa)
        fclose(fa);
    if (fb)
        fclose(fb);
    return same;
}

static void run_to(struct ssg_graph *g, const char *dir, int frames, struct told *t,
                   enum ssg_err want)
{
    struct ssg_diags d = {0};
    struct ssg_run_options opt = {.out_dir = dir, .frames = frames, .log = on_log, .user = t};
    CHECK_EQ(ssg_graph_run(g, &opt, &d), want);
    if (!want)
        ssg_diags_print(&d, stderr);
    else
        CHECK(d.count >= 1 && strstr(d.items[0].file, "t_0001.exr") != NULL);
}

static void test_sequence(const char *root, const char *graph)
{
    char behind[1100], alone[1100], a[1200], b[1200];
    snprintf(behind, sizeof behind, "%s/behind", root);
    snprintf(alone, sizeof alone, "%s/alone", root);
    struct told t = {.caller = pthread_self()}, t1 = {.caller = pthread_self()};
    struct ssg_graph *g = load(graph);
    run_to(g, behind, FRAMES, &t, SSG_OK);
    ssg_graph_destroy(&g);
    for (int f = 0; f < FRAMES; f++) { /* one frame a run: written in the frame */
        struct ssg_diags d = {0};
        g = load(graph);
        CHECK_EQ(ssg_graph_set_frame(g, f, &d), SSG_OK);
        run_to(g, alone, 1, &t1, SSG_OK);
        ssg_graph_destroy(&g);
    }
    CHECK_EQ(t.off_thread, 0);
    CHECK_EQ(t.missing, 0);
    CHECK_EQ(t.lines, 2 * FRAMES);
    for (int f = 0; f < FRAMES; f++)
        for (int k = 0; k < 2; k++) {
            const char *ext = k ? "png" : "exr";
            snprintf(a, sizeof a, "%s/t_%04d.%s", behind, f, ext);
            snprintf(b, sizeof b, "%s/t_%04d.%s", alone, f, ext);
            CHECK(same_file(a, b));
            char want[1300];
            snprintf(want, sizeof want, "wrote %s", a);
            CHECK(f * 2 + k < t.lines && !strcmp(t.line[f * 2 + k], want));
        }
}

/* Frame 1's EXR cannot be renamed into place (a folder holds its name). */
static void test_failure(const char *root, const char *graph)
{
    char dir[1100], blocker[1200], path[1300];
    snprintf(dir, sizeof dir, "%s/fails", root);
    snprintf(blocker, sizeof blocker, "%s/t_0001.exr", dir);
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_make_dirs(blocker, &d), SSG_OK);
    struct told t = {.caller = pthread_self()};
    struct ssg_graph *g = load(graph);
    run_to(g, dir, FRAMES + 2, &t, SSG_E_IO);
    ssg_graph_destroy(&g);
    CHECK_EQ(t.off_thread, 0);
    CHECK_EQ(t.missing, 0);
    snprintf(path, sizeof path, "%s/t_0000.exr", dir);
    CHECK(access(path, F_OK) == 0);
    for (int f = 2; f < FRAMES + 2; f++) {
        snprintf(path, sizeof path, "%s/t_%04d.exr", dir, f);
        CHECK(access(path, F_OK) != 0);
        snprintf(path, sizeof path, "%s/t_%04d.png", dir, f);
        CHECK(access(path, F_OK) != 0);
    }
    DIR *listing = opendir(dir);
    CHECK(listing != NULL);
    for (struct dirent *e; listing && (e = readdir(listing));)
        CHECK(e->d_name[0] != '.' || !strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."));
    if (listing)
        closedir(listing);
}

int main(void)
{
    char root[1024], graph[1100];
    const char *tmp = getenv("SSG_TMP");
    snprintf(root, sizeof root, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_behind");
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_make_dirs(root, &d), SSG_OK);
    snprintf(graph, sizeof graph, "%s/seq.graph", root);
    write_graph(graph);
    test_queue();
    test_spare();
    test_sequence(root, graph);
    test_failure(root, graph);
    return check_report();
}
