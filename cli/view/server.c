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
 * - only the embedded page files are served: no path reaches the disk; the one write
 *   (save as variant) goes beside the graph under a checked name. */
#define _DEFAULT_SOURCE
#include "view.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <microhttpd.h>
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "route.h"
#include "session.h"

enum { BODY_MAX = 64 * 1024, TOKEN_HEX = 32, POLL_MS = 300 };

struct server {
    struct view_session session;
    pthread_mutex_t lock;
    char token[TOKEN_HEX + 1];
    unsigned port;
    struct MHD_Daemon *daemon;
};

/* A request's body, gathered across MHD's calls. */
struct request {
    char *body;
    size_t len;
    int too_big;
};

static volatile sig_atomic_t stop_requested;

static void on_signal(int sig)
{
    (void)sig;
    stop_requested = 1;
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
    struct view_request req = {.method = method, .path = url, .body = q->body ? q->body : "",
                               .connection = c};
    struct view_answer a;
    pthread_mutex_lock(&sv->lock);
    view_route(&sv->session, &req, &a);
    pthread_mutex_unlock(&sv->lock);
    return send_answer(c, &a, sv);
}

static void request_done(void *cls, struct MHD_Connection *c, void **con_cls,
                         enum MHD_RequestTerminationCode code)
{
    (void)cls, (void)c, (void)code;
    struct request *q = *con_cls;
    if (q) {
        free(q->body);
        free(q);
    }
    *con_cls = NULL;
}

static struct MHD_Daemon *start(struct server *sv, unsigned port)
{
    struct sockaddr_in addr = {.sin_family = AF_INET, .sin_port = htons((uint16_t)port)};
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return MHD_start_daemon(
        MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_POLL | MHD_USE_ERROR_LOG, (uint16_t)port,
        NULL, NULL, handle, sv, MHD_OPTION_SOCK_ADDR, (struct sockaddr *)&addr,
        MHD_OPTION_NOTIFY_COMPLETED, request_done, sv,
        MHD_OPTION_CONNECTION_LIMIT, (unsigned)64, MHD_OPTION_CONNECTION_TIMEOUT,
        (unsigned)30, MHD_OPTION_CONNECTION_MEMORY_LIMIT, (size_t)(256 * 1024),
        MHD_OPTION_END);
}

static void sleep_ms(int ms)
{
    struct timespec t = {ms / 1000, (long)(ms % 1000) * 1000000L};
    nanosleep(&t, NULL);
}

/* Until a signal: every POLL_MS the watcher looks at the graph's files. */
static void serve(struct server *sv)
{
    while (!stop_requested) {
        sleep_ms(POLL_MS);
        pthread_mutex_lock(&sv->lock);
        view_session_poll(&sv->session);
        pthread_mutex_unlock(&sv->lock);
    }
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
    pthread_mutex_init(&sv.lock, NULL);
    struct sigaction sa = {.sa_handler = on_signal};
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);
    sv.daemon = start(&sv, (unsigned)args->port);
    const union MHD_DaemonInfo *info =
        sv.daemon ? MHD_get_daemon_info(sv.daemon, MHD_DAEMON_INFO_BIND_PORT) : NULL;
    if (!info) {
        fprintf(stderr, "ssgraph: error: view: cannot listen on 127.0.0.1:%d\n", args->port);
        view_session_close(&sv.session);
        return 1;
    }
    sv.port = info->port;
    printf("ssgraph view: http://127.0.0.1:%u/?token=%s\n", sv.port, sv.token);
    fflush(stdout);
    serve(&sv);
    MHD_stop_daemon(sv.daemon);
    view_session_close(&sv.session);
    pthread_mutex_destroy(&sv.lock);
    return 0;
}
