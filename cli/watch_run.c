/* watch_run.c - `ssgraph run --watch` (watch.h): run, then poll the graph's files and run
 * again after each change, until SIGINT or SIGTERM. */
#include <signal.h>
#include <stdio.h>
#include <time.h>
#include <unistd.h>

#include "options.h"
#include "watch.h"

enum { POLL_MS = 300 };

static volatile sig_atomic_t stop;   /* a SIGINT or SIGTERM came: end between runs */
static volatile sig_atomic_t in_run; /* a run is writing: a signal ends it at once */

/* During a run its temporaries are removed and the process ends (exit 0: the user asked
   for the end, and every file the run renamed into place is whole); between runs the
   loop sees `stop` when its sleep is interrupted, or at the next poll. */
static void on_signal(int sig)
{
    (void)sig;
    stop = 1;
    if (in_run) {
        ssg_tmp_remove_all();
        _exit(0);
    }
}

/* Replaces ssg_tmp_remove_on_signals' SIGINT and SIGTERM handlers (which die of the
   signal); SIGHUP and SIGPIPE keep theirs. No SA_RESTART: the sleep returns early. */
static void catch_signals(void)
{
    struct sigaction sa = {0};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

static void pause_ms(int ms)
{
    struct timespec t = {ms / 1000, (long)(ms % 1000) * 1000000L};
    nanosleep(&t, NULL); /* interrupted by a signal: the caller checks `stop` */
}

/* One load and run, its diagnostics printed; the line saying how it went. Nothing when a
   signal came first. */
static void run_and_tell(const struct ssg_cli_args *a, ssg_cli_watch_run_fn run,
                         struct ssg_cli_watch *w, int number)
{
    static struct ssg_diags d; /* some 25 KB: kept off the stack */
    d = (struct ssg_diags){0};
    in_run = 1;
    if (stop) { /* a signal between the poll and here */
        in_run = 0;
        return;
    }
    enum ssg_err e = run(a, w, &d);
    in_run = 0;
    ssg_diags_print(&d, stderr);
    if (e && d.count == 0)
        fprintf(stderr, "ssgraph: error: %s\n", ssg_err_text(e));
    fflush(stderr);
    printf("watch: run %d %s; watching %d files for changes (Ctrl-C ends)\n", number,
           e ? "failed" : "done", ssg_cli_watch_count(w));
    fflush(stdout);
}

int ssg_cli_run_watch(const struct ssg_cli_args *a, ssg_cli_watch_run_fn run)
{
    struct ssg_cli_watch *w = ssg_cli_watch_new(a->files[0]);
    if (!w) {
        fprintf(stderr, "ssgraph: error: %s\n", ssg_err_text(SSG_E_NOMEM));
        return 1;
    }
    catch_signals();
    for (int number = 1; !stop; number++) {
        run_and_tell(a, run, w, number);
        const char *changed = NULL;
        while (!stop && !(changed = ssg_cli_watch_changed(w)))
            pause_ms(POLL_MS);
        if (changed && !stop) {
            printf("watch: %s changed: running again\n", changed);
            fflush(stdout);
        }
    }
    ssg_cli_watch_free(&w);
    return 0;
}
