/* guard.c - deadlines for the viewer's connections (guard.h). */
#define _DEFAULT_SOURCE
#include "guard.h"

#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <time.h>

/* One open connection. */
struct tracked {
    int fd;                      /* its socket, open until MHD_CONNECTION_NOTIFY_CLOSED */
    int64_t since;               /* guard clock, ns: its request or answer started */
    int shut;                    /* 1 = shut down by the sweep already */
    struct tracked *prev, *next; /* the guard's list */
};

struct view_guard {
    pthread_mutex_t lock;
    struct tracked *head;
    int busy;          /* 1 = the server works on a request: the clock stands */
    int64_t busy_from; /* monotonic ns it started */
    int64_t paused;    /* ns the clock stood in all, so far */
};

static int64_t monotonic_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (int64_t)t.tv_sec * 1000000000 + t.tv_nsec;
}

/* Monotonic time less the time the server spent working on requests; under the lock. */
static int64_t guard_clock(const struct view_guard *g)
{
    return (g->busy ? g->busy_from : monotonic_ns()) - g->paused;
}

struct view_guard *view_guard_new(void)
{
    struct view_guard *g = calloc(1, sizeof *g);
    if (g && pthread_mutex_init(&g->lock, NULL)) {
        free(g);
        g = NULL;
    }
    return g;
}

void view_guard_free(struct view_guard **guard)
{
    struct view_guard *g = *guard;
    if (!g)
        return;
    while (g->head) { /* none are left after MHD_stop_daemon; freed all the same */
        struct tracked *t = g->head;
        g->head = t->next;
        free(t);
    }
    pthread_mutex_destroy(&g->lock);
    free(g);
    *guard = NULL;
}

static void track(struct view_guard *g, struct MHD_Connection *c, void **socket_context)
{
    const union MHD_ConnectionInfo *info =
        MHD_get_connection_info(c, MHD_CONNECTION_INFO_CONNECTION_FD);
    struct tracked *t = info ? calloc(1, sizeof *t) : NULL;
    if (!t) { /* a connection no deadline would end is not served */
        if (info)
            shutdown(info->connect_fd, SHUT_RDWR);
        return;
    }
    t->fd = info->connect_fd;
    pthread_mutex_lock(&g->lock);
    t->since = guard_clock(g);
    t->next = g->head;
    if (g->head)
        g->head->prev = t;
    g->head = t;
    pthread_mutex_unlock(&g->lock);
    *socket_context = t;
}

static void untrack(struct view_guard *g, void **socket_context)
{
    struct tracked *t = *socket_context;
    if (!t)
        return;
    pthread_mutex_lock(&g->lock);
    if (t->prev)
        t->prev->next = t->next;
    else
        g->head = t->next;
    if (t->next)
        t->next->prev = t->prev;
    pthread_mutex_unlock(&g->lock);
    free(t);
    *socket_context = NULL;
}

void view_guard_notify(void *cls, struct MHD_Connection *c, void **socket_context,
                       enum MHD_ConnectionNotificationCode code)
{
    if (code == MHD_CONNECTION_NOTIFY_STARTED)
        track(cls, c, socket_context);
    else if (code == MHD_CONNECTION_NOTIFY_CLOSED)
        untrack(cls, socket_context);
}

static struct tracked *tracked_of(struct MHD_Connection *c)
{
    const union MHD_ConnectionInfo *info =
        MHD_get_connection_info(c, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
    return info ? info->socket_context : NULL;
}

void view_guard_busy(struct view_guard *g, struct MHD_Connection *c)
{
    (void)c; /* the clock of every connection stands */
    pthread_mutex_lock(&g->lock);
    if (!g->busy) {
        g->busy = 1;
        g->busy_from = monotonic_ns();
    }
    pthread_mutex_unlock(&g->lock);
}

void view_guard_idle(struct view_guard *g, struct MHD_Connection *c)
{
    struct tracked *t = tracked_of(c);
    pthread_mutex_lock(&g->lock);
    if (g->busy) {
        g->paused += monotonic_ns() - g->busy_from;
        g->busy = 0;
    }
    if (t)
        t->since = guard_clock(g);
    pthread_mutex_unlock(&g->lock);
}

void view_guard_restart(struct view_guard *g, struct MHD_Connection *c)
{
    struct tracked *t = tracked_of(c);
    if (!t)
        return;
    pthread_mutex_lock(&g->lock);
    t->since = guard_clock(g);
    pthread_mutex_unlock(&g->lock);
}

int view_guard_sweep(struct view_guard *g)
{
    int count = 0;
    pthread_mutex_lock(&g->lock);
    int64_t now = guard_clock(g);
    for (struct tracked *t = g->head; t; t = t->next) {
        if (t->shut || now - t->since <= (int64_t)VIEW_GUARD_MS * 1000000)
            continue;
        /* SHUT_RDWR: MHD's next read sees the end and closes the connection itself */
        shutdown(t->fd, SHUT_RDWR);
        t->shut = 1;
        count++;
    }
    pthread_mutex_unlock(&g->lock);
    return count;
}
