/* server.c - the HTTP side of `ssgraph view` (view.h), on GNU libmicrohttpd: one server
 * thread answers every request in turn (the graph is not thread-safe; many clients just
 * queue), under a lock the main thread's file watcher takes too. The safety rules, each
 * checked before anything else is read:
 * - it listens on 127.0.0.1 only;
 * - every request carries the session's random token (query, header or cookie);
 * - Host must name 127.0.0.1 or localhost at our port, and an Origin, when there is one,
 *   the same: a page of another site that points its own name at 127.0.0.1 (DNS
 *   rebinding) is refused;
 * - bodies are at most BODY_MAX bytes, headers at most what MHD's memory limit holds;
 * - it stays answering while other local programs hold connections open (idle, or
 *   trickling a header line every few seconds): it takes thousands of connections and
 *   gives each request a deadline (guard.h says why that and not a per-client limit);
 * - SIGINT or SIGTERM ends it within STOP_MS (a graph run that does not end by then is
 *   not waited for);
 * - only the embedded page files are served: no path reaches the disk; the one write
 *   (save as variant) goes beside the graph under a checked name. */
#define _DEFAULT_SOURCE
#include "view.h"

#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <microhttpd.h>
#include <pthread.h>
#include <semaphore.h>
#include <signal.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

#include "guard.h"
#include "route.h"
#include "session.h"

enum {
    BODY_MAX = 64 * 1024,
    TOKEN_HEX = 32,
    POLL_MS = 300,           /* the file watcher's and the guard's period */
    STOP_MS = 1500,          /* after a signal, the most an orderly stop may take */
    CONNECTIONS_MAX = 8192,  /* at most, when RLIMIT_NOFILE allows it */
    FDS_SPARE = 256,         /* descriptors left for the graph's files, threads, `dot` */
};

struct server {
    struct view_session session;
    pthread_mutex_t lock;    /* the session's: every request and the watcher take it */
    int stopping;            /* under lock: 1 = answer no more requests (503) */
    char token[TOKEN_HEX + 1];
    unsigned port;
    atomic_int serving;      /* 1 once the daemon started (mhd_log) */
    struct MHD_Daemon *daemon;
    struct view_guard *guard;
    sem_t wake_main;         /* posted by a signal: the main loop ends */
    sem_t wake_stopper;      /* posted by a signal, or at the end without one */
    sem_t stopped;           /* posted when the orderly stop is done */
};

/* A request's body, gathered across MHD's calls. */
struct request {
    char *body;
    size_t len;
    int too_big;
};

static volatile sig_atomic_t stop_requested;
static struct server *signalled; /* the server the signal handler wakes */

/* Async-signal-safe: a flag and two sem_post calls. */
static void on_signal(int sig)
{
    (void)sig;
    if (stop_requested)
        return;
    stop_requested = 1;
    sem_post(&signalled->wake_main);
    sem_post(&signalled->wake_stopper);
}

static int make_token(char *token)
{
    unsigned char bytes[TOKEN_HEX / 2];
    int fd = open("/dev/urandom", O_RDONLY | O_CLOEXEC);
    int ok = fd >= 0 && read(fd, bytes, sizeof bytes) == (ssize_t)sizeof bytes;
    if (fd >= 0)
        close(fd);
    for (size_t i = 0; ok && i < sizeof bytes; i++)
        snprintf(token + 2 * i, 3, "%02x", bytes[i]);
    return ok;
}

/* Compares in time independent of where they differ. */
static int same_token(const char *given, const char *token)
{
    if (!given || strlen(given) != TOKEN_HEX)
        return 0;
    unsigned diff = 0;
    for (int i = 0; i < TOKEN_HEX; i++)
        diff |= (unsigned char)given[i] ^ (unsigned char)token[i];
    return diff == 0;
}

/* 1 when value is "<scheme>127.0.0.1:PORT" or "<scheme>localhost:PORT". */
static int local_name(const char *value, const char *scheme, unsigned port)
{
    char a[64], b[64];
    snprintf(a, sizeof a, "%s127.0.0.1:%u", scheme, port);
    snprintf(b, sizeof b, "%slocalhost:%u", scheme, port);
    return value && (!strcmp(value, a) || !strcmp(value, b));
}

static const char *header(struct MHD_Connection *c, const char *name)
{
    return MHD_lookup_connection_value(c, MHD_HEADER_KIND, name);
}

/* Why the request may not be answered, or NULL when it may. */
static const char *refusal(const struct server *sv, struct MHD_Connection *c)
{
    if (!local_name(header(c, "Host"), "", sv->port))
        return "Host must be 127.0.0.1 or localhost at this port";
    const char *origin = header(c, "Origin");
    if (origin && !local_name(origin, "http://", sv->port))
        return "a request from another origin";
    const char *token = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "token");
    if (!token)
        token = header(c, "X-SSG-Token");
    if (!token)
        token = MHD_lookup_connection_value(c, MHD_COOKIE_KIND, "ssg_token");
    return same_token(token, sv->token) ? NULL : "a missing or wrong token";
}

static enum MHD_Result send_answer(struct MHD_Connection *c, const struct view_answer *a,
                                   const struct server *sv)
{
    struct MHD_Response *r = MHD_create_response_from_buffer(a->len, a->body,
                                                             MHD_RESPMEM_MUST_FREE);
    if (!r) {
        free(a->body);
        return MHD_NO;
    }
    MHD_add_response_header(r, "Content-Type", a->type);
    MHD_add_response_header(r, "Cache-Control", "no-store");
    MHD_add_response_header(r, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(r, "Content-Security-Policy",
                            "default-src 'self'; img-src 'self' data:; style-src 'self' "
                            "'unsafe-inline'; frame-ancestors 'none'");
    if (a->set_cookie) {
        char cookie[128];
        snprintf(cookie, sizeof cookie, "ssg_token=%s; HttpOnly; SameSite=Strict; Path=/",
                 sv->token);
        MHD_add_response_header(r, "Set-Cookie", cookie);
    }
    enum MHD_Result ok = MHD_queue_response(c, (unsigned)a->status, r);
    MHD_destroy_response(r);
    return ok;
}

static enum MHD_Result refuse(struct MHD_Connection *c, int status, const char *why,
                              const struct server *sv)
{
    struct view_answer a;
    view_answer_error(&a, status, why);
    return send_answer(c, &a, sv);
}

/* Gathers the body; 1 while more is to come (the call is answered with MHD_YES). */
static int gather(struct request *q, const char *data, size_t *size)
{
    if (!*size)
        return 0;
    if (!q->too_big && q->len + *size <= BODY_MAX) {
        char *grown = realloc(q->body, q->len + *size + 1);
        if (grown) {
            memcpy(grown + q->len, data, *size);
            q->body = grown;
            q->len += *size;
            q->body[q->len] = '\0';
        } else {
            q->too_big = 1;
        }
    } else {
        q->too_big = 1;
    }
    *size = 0;
    return 1;
}

/* Routes a whole request under the session's lock; the guard's clock stands meanwhile. */
static enum MHD_Result answer_request(struct server *sv, struct MHD_Connection *c,
                                      const struct view_request *req)
{
    struct view_answer a;
    view_guard_busy(sv->guard, c);
    pthread_mutex_lock(&sv->lock);
    if (sv->stopping)
        view_answer_error(&a, MHD_HTTP_SERVICE_UNAVAILABLE, "the viewer is stopping");
    else
        view_route(&sv->session, req, &a);
    pthread_mutex_unlock(&sv->lock);
    enum MHD_Result ok = send_answer(c, &a, sv);
    view_guard_idle(sv->guard, c);
    return ok;
}

static enum MHD_Result handle(void *cls, struct MHD_Connection *c, const char *url,
                              const char *method, const char *version, const char *data,
                              size_t *data_size, void **con_cls)
{
    (void)version;
    struct server *sv = cls;
    struct request *q = *con_cls;
    if (!q) { /* the headers: refuse early, before any body is read */
        const char *why = refusal(sv, c);
        if (why)
            return refuse(c, MHD_HTTP_FORBIDDEN, why, sv);
        const char *length = header(c, "Content-Length");
        if (length && strtoull(length, NULL, 10) > BODY_MAX)
            return refuse(c, MHD_HTTP_CONTENT_TOO_LARGE, "the body is over 64 KiB", sv);
        if (!(q = calloc(1, sizeof *q)))
            return MHD_NO;
        *con_cls = q;
        return MHD_YES;
    }
    if (gather(q, data, data_size))
        return MHD_YES;
    if (q->too_big)
        return refuse(c, MHD_HTTP_CONTENT_TOO_LARGE, "the body is over 64 KiB", sv);
    /* The routes read the body as a C string: a NUL would cut it there, and what follows
       ("name=ok\0/../../evil") would go unchecked and unseen. */
    if (q->body && memchr(q->body, '\0', q->len))
        return refuse(c, MHD_HTTP_BAD_REQUEST, "the body holds a NUL byte", sv);
    struct view_request req = {.method = method, .path = url, .body = q->body ? q->body : "",
                               .connection = c};
    return answer_request(sv, c, &req);
}

static void request_done(void *cls, struct MHD_Connection *c, void **con_cls,
                         enum MHD_RequestTerminationCode code)
{
    (void)code;
    struct server *sv = cls;
    struct request *q = *con_cls;
    if (q) {
        free(q->body);
        free(q);
    }
    *con_cls = NULL;
    view_guard_restart(sv->guard, c);
}

/* How many connections the server takes: as many as the descriptors allow (the soft
 * RLIMIT_NOFILE raised to the hard one), less FDS_SPARE, at most CONNECTIONS_MAX. Idle
 * connections cost MHD nothing on epoll; the guard ends the ones that hold a request open,
 * so a local program must open more than this many within VIEW_GUARD_MS to make the page
 * wait (and then only until the guard closes them). */
static unsigned connection_limit(void)
{
    struct rlimit r;
    if (getrlimit(RLIMIT_NOFILE, &r))
        return 64;
    rlim_t want = CONNECTIONS_MAX + FDS_SPARE;
    if (r.rlim_cur != RLIM_INFINITY && r.rlim_cur < want) {
        struct rlimit raised = r;
        raised.rlim_cur = r.rlim_max == RLIM_INFINITY || r.rlim_max > want ? want : r.rlim_max;
        if (!setrlimit(RLIMIT_NOFILE, &raised))
            r = raised;
    }
    if (r.rlim_cur != RLIM_INFINITY && r.rlim_cur < want)
        return r.rlim_cur > 2 * FDS_SPARE ? (unsigned)(r.rlim_cur - FDS_SPARE) : 64;
    return CONNECTIONS_MAX;
}

/* MHD's messages: those of the start (a port in use) are the user's; once it serves, they
 * are about clients that went away or that the guard closed, as many as a hostile program
 * opens connections, and stay out of the terminal. */
static void mhd_log(void *cls, const char *fmt, va_list ap)
{
    struct server *sv = cls;
    if (atomic_load(&sv->serving))
        return;
    fputs("ssgraph: view: libmicrohttpd: ", stderr);
    vfprintf(stderr, fmt, ap);
}

/* One polling thread (the graph is not thread-safe: requests queue), epoll where there is
 * one (MHD_USE_AUTO; no FD_SETSIZE bound). No per-address limit: every client is local
 * (guard.h). MHD's timeout (idle time only) backs the guard's deadline up. */
static struct MHD_Daemon *start(struct server *sv, unsigned port)
{
    struct sockaddr_in addr = {.sin_family = AF_INET, .sin_port = htons((uint16_t)port)};
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return MHD_start_daemon(
        MHD_USE_AUTO_INTERNAL_THREAD | MHD_USE_ERROR_LOG, (uint16_t)port, NULL, NULL, handle,
        sv, MHD_OPTION_EXTERNAL_LOGGER, mhd_log, sv, /* first: MHD says so otherwise */
        MHD_OPTION_SOCK_ADDR, (struct sockaddr *)&addr, MHD_OPTION_NOTIFY_COMPLETED,
        request_done, sv, MHD_OPTION_NOTIFY_CONNECTION, view_guard_notify, sv->guard,
        MHD_OPTION_CONNECTION_LIMIT, connection_limit(), MHD_OPTION_CONNECTION_TIMEOUT,
        (unsigned)(2 * VIEW_GUARD_MS / 1000), MHD_OPTION_CONNECTION_MEMORY_LIMIT,
        (size_t)(256 * 1024), MHD_OPTION_END);
}

/* t + ms, as sem_timedwait takes it (CLOCK_REALTIME). */
static struct timespec after_ms(int ms)
{
    struct timespec t;
    clock_gettime(CLOCK_REALTIME, &t);
    t.tv_sec += ms / 1000;
    t.tv_nsec += (long)(ms % 1000) * 1000000L;
    if (t.tv_nsec >= 1000000000L) {
        t.tv_sec++;
        t.tv_nsec -= 1000000000L;
    }
    return t;
}

/* 0 when sem was posted before ms passed. */
static int wait_ms(sem_t *sem, int ms)
{
    struct timespec until = after_ms(ms);
    int rc;
    while ((rc = sem_timedwait(sem, &until)) && errno == EINTR)
        ;
    return rc;
}

/* Until a signal: every POLL_MS the guard ends overdue connections and the watcher looks
 * at the graph's files. */
static void serve(struct server *sv)
{
    while (!stop_requested) {
        view_guard_sweep(sv->guard);
        if (!wait_ms(&sv->wake_main, POLL_MS))
            break;
        pthread_mutex_lock(&sv->lock);
        view_session_poll(&sv->session);
        pthread_mutex_unlock(&sv->lock);
    }
}

/* After a signal, waits STOP_MS for the orderly stop (the main thread's); when it is not
 * done by then (a graph run holds the lock: a run cannot be interrupted), the process
 * exits at once, with the status of an orderly stop. Nothing is lost that a graceful stop
 * would keep: the viewer writes no output files, and a variant is written whole or not
 * at all (variant.c). */
static void *stopper(void *arg)
{
    struct server *sv = arg;
    while (sem_wait(&sv->wake_stopper) && errno == EINTR)
        ;
    if (!stop_requested || !wait_ms(&sv->stopped, STOP_MS))
        return NULL;
    static const char msg[] = "ssgraph view: a request is still running: exiting without "
                              "waiting for it\n";
    ssize_t ignored = write(2, msg, sizeof msg - 1);
    (void)ignored;
    _exit(0);
}

/* Stops answering (requests still queued get 503), then stops MHD: it closes every
 * connection and joins its thread, which no request holds any more. */
static void stop(struct server *sv)
{
    pthread_mutex_lock(&sv->lock);
    sv->stopping = 1;
    pthread_mutex_unlock(&sv->lock);
    MHD_stop_daemon(sv->daemon);
    sv->daemon = NULL;
}

static int listen_and_serve(struct server *sv, const struct ssg_cli_args *args)
{
    sv->daemon = start(sv, (unsigned)args->port);
    const union MHD_DaemonInfo *info =
        sv->daemon ? MHD_get_daemon_info(sv->daemon, MHD_DAEMON_INFO_BIND_PORT) : NULL;
    if (!info) {
        fprintf(stderr, "ssgraph: error: view: cannot listen on 127.0.0.1:%d\n", args->port);
        if (sv->daemon)
            MHD_stop_daemon(sv->daemon);
        return 1;
    }
    sv->port = info->port;
    atomic_store(&sv->serving, 1);
    printf("ssgraph view: http://127.0.0.1:%u/?token=%s\n", sv->port, sv->token);
    fflush(stdout);
    serve(sv);
    stop(sv);
    return 0;
}

int ssg_cli_view(const struct ssg_cli_args *args)
{
    static struct server sv; /* the session holds the set list: kept off the stack */
    if (!make_token(sv.token)) {
        fprintf(stderr, "ssgraph: error: view: cannot read /dev/urandom for a token\n");
        return 1;
    }
    if (view_session_open(&sv.session, args))
        return 1;
    if (!(sv.guard = view_guard_new())) {
        fprintf(stderr, "ssgraph: error: view: out of memory\n");
        view_session_close(&sv.session);
        return 1;
    }
    pthread_mutex_init(&sv.lock, NULL);
    sem_init(&sv.wake_main, 0, 0);
    sem_init(&sv.wake_stopper, 0, 0);
    sem_init(&sv.stopped, 0, 0);
    pthread_t stopper_thread;
    int have_stopper = !pthread_create(&stopper_thread, NULL, stopper, &sv);
    signalled = &sv;
    struct sigaction sa = {.sa_handler = on_signal};
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);
    int status = listen_and_serve(&sv, args);
    sem_post(&sv.stopped);
    sem_post(&sv.wake_stopper); /* ends the stopper when no signal came */
    if (have_stopper)
        pthread_join(stopper_thread, NULL);
    view_session_close(&sv.session);
    view_guard_free(&sv.guard);
    pthread_mutex_destroy(&sv.lock);
    return status;
}
