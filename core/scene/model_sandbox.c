/* model_sandbox.c - ssg_model_sandbox (model.h): an import in a child process, under a
 * wall-clock and an address-space limit, its result sent back through a pipe.
 *
 * Why a process: the pre-checks (model_check.c) close the holes known today, but Assimp
 * reads dozens of formats and was never written for hostile input; a stack overflow, an
 * endless loop or a 15 GB allocation inside it cannot be caught in the process it happens
 * in. In a child it becomes an error naming the file: the parent waits on the pipe until
 * the deadline (then kills the child) and reads how the child ended from waitpid.
 *
 * The pipe carries our own format, native byte order (both ends are this binary): an
 * 8-byte length of what follows, then the error code, the message, the up axis and, when
 * asked for, the model: per mesh its counts and arrays, then the materials, textures and
 * camera. Every count the parent reads is checked against the bytes still announced before
 * anything is allocated, and every index against its mesh, so even a child gone wrong
 * cannot make the parent allocate or index beyond what it sent.
 *
 * fork() in a threaded process: the child runs only the importer (Assimp uses no threads
 * and no OpenMP) and leaves by _exit, so it never touches the parent's stdio buffers,
 * atexit handlers or OpenMP pool. The CLI's signal handlers (which remove the parent's
 * temporary files) are reset in the child. Under AddressSanitizer, which reserves terabytes
 * of address space, RLIMIT_AS cannot be set: there the pre-checks stand alone for memory. */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "scene/model.h"
#include "scene/model_wire.h"

#if defined(__SANITIZE_ADDRESS__)
#define SSG_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SSG_ASAN 1
#endif
#endif
#ifndef SSG_ASAN
#define SSG_ASAN 0
#endif

/* A limit from the environment: a non-negative number, else the default. */
static double env_limit(const char *name, double fallback)
{
    const char *text = getenv(name);
    char *end;
    double v = text && text[0] ? strtod(text, &end) : -1.0;
    return v >= 0.0 && isfinite(v) && text && *end == 0 ? v : fallback;
}

void ssg_model_limits_default(long long file_bytes, struct ssg_model_limits *limits)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    double half_mib = pages > 0 && page > 0 ? (double)pages * (double)page / 2.0 / 1048576.0
                                            : 4096.0;
    /* A 1 GB OBJ takes Assimp minutes to triangulate and weld: the time grows with it */
    limits->seconds = env_limit("SSGRAPH_MODEL_TIMEOUT",
                                60.0 + (double)(file_bytes > 0 ? file_bytes : 0) / 4194304.0);
    limits->bytes = (long long)(env_limit("SSGRAPH_MODEL_MEMORY", half_mib) * 1048576.0);
}

/* The child's address space may grow by `bytes` beyond what it inherited (the parent's
   libraries, thread stacks and images are already mapped, and count). */
static void limit_memory(long long bytes)
{
    if (SSG_ASAN || bytes <= 0)
        return;
    unsigned long long pages = 0;
    FILE *f = fopen("/proc/self/statm", "r");
    if (f) {
        if (fscanf(f, "%llu", &pages) != 1)
            pages = 0;
        fclose(f);
    }
    struct rlimit r;
    r.rlim_cur = r.rlim_max =
        (rlim_t)(pages * (unsigned long long)sysconf(_SC_PAGESIZE) + (unsigned long long)bytes);
    setrlimit(RLIMIT_AS, &r);
}

static _Noreturn void run_child(int fd, const char *path, ssg_model_import_fn import,
                                const struct ssg_model_limits *limits, int want_model)
{
    const int reset[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
    for (size_t i = 0; i < sizeof reset / sizeof reset[0]; i++)
        signal(reset[i], SIG_DFL);
    limit_memory(limits->bytes);
    if (limits->seconds > 0) /* the parent kills it first; this is for a parent gone */
        alarm((unsigned)fmin(ceil(limits->seconds) + 5.0, 1e9));
    struct ssg_gltf *g = NULL;
    struct ssg_model_up up = {.axis = -1, .sign = 1};
    char why[1024] = "";
    enum ssg_err e = import(path, want_model ? &g : NULL, &up, why, sizeof why);
    ssg_wire_send(fd, e, why, &up, e ? NULL : g);
    _exit(0);
}

/* Why the child gave no result, into why. */
static enum ssg_err explain(const char *path, const struct ssg_wire *w,
                            const struct ssg_model_limits *limits, char *why, size_t why_len)
{
    if (w->ending == SSG_WIRE_TIMEOUT) {
        snprintf(why, why_len, "%s: the model importer ran out of time (%g s; "
                 "SSGRAPH_MODEL_TIMEOUT=SECONDS sets the limit)", path, limits->seconds);
        return SSG_E_GLTF;
    }
    if (w->reaped && WIFSIGNALED(w->status)) {
        int sig = WTERMSIG(w->status);
        snprintf(why, why_len, "%s: the model importer crashed (signal %d, %s)%s", path, sig,
                 strsignal(sig), sig == SIGKILL ? ": out of memory?" : "");
        return SSG_E_GLTF;
    }
    if (w->ending == SSG_WIRE_NOMEM) {
        snprintf(why, why_len, "%s: out of memory receiving the model", path);
        return SSG_E_NOMEM;
    }
    if (w->ending == SSG_WIRE_CORRUPT)
        snprintf(why, why_len, "%s: the model importer sent back a malformed result", path);
    else
        snprintf(why, why_len, "%s: the model importer ended without a result (exit status "
                 "%d)", path, w->reaped && WIFEXITED(w->status) ? WEXITSTATUS(w->status) : -1);
    return SSG_E_GLTF;
}

/* The child's own out-of-memory error, with the limit that caused it. */
static void explain_memory(const char *path, const struct ssg_model_limits *limits, char *why,
                           size_t why_len)
{
    if (limits->bytes > 0 && !SSG_ASAN)
        snprintf(why, why_len, "%s: the model importer ran out of memory (limit %lld MiB; "
                 "SSGRAPH_MODEL_MEMORY=MIB sets it)", path, limits->bytes >> 20);
}

/* Ends the child (killing it unless it is done) and collects its status. */
static void reap(pid_t pid, struct ssg_wire *w)
{
    if (w->reaped)
        return;
    if (w->ending != SSG_WIRE_OK)
        kill(pid, SIGKILL);
    while (waitpid(pid, &w->status, 0) < 0 && errno == EINTR)
        ;
    w->reaped = 1;
}

enum ssg_err ssg_model_sandbox(const char *path, ssg_model_import_fn import,
                               const struct ssg_model_limits *limits, struct ssg_gltf **out,
                               struct ssg_model_up *up, char *why, size_t why_len)
{
    int fds[2];
    if (out)
        *out = NULL;
    if (pipe(fds)) {
        snprintf(why, why_len, "%s: cannot make a pipe to the model importer: %s", path,
                 strerror(errno));
        return SSG_E_IO;
    }
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        run_child(fds[1], path, import, limits, out != NULL);
    }
    close(fds[1]);
    if (pid < 0) {
        close(fds[0]);
        snprintf(why, why_len, "%s: cannot start the model importer's process: %s", path,
                 strerror(errno));
        return SSG_E_IO;
    }
    struct ssg_wire w = {.fd = fds[0], .pid = pid,
                         .deadline = limits->seconds > 0 ? ssg_wire_now() + limits->seconds : 0};
    enum ssg_err e = ssg_wire_receive(&w, out, up, why, why_len);
    reap(pid, &w);
    close(fds[0]);
    if (w.ending != SSG_WIRE_OK)
        return explain(path, &w, limits, why, why_len);
    if (e == SSG_E_NOMEM)
        explain_memory(path, limits, why, why_len);
    return e;
}
