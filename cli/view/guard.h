/* guard.h - a deadline for every request of `ssgraph view` (guard.c), so that connections
 * that never finish a request cannot take the server from the page.
 *
 * Why a deadline, and not a per-client limit or MHD's timeout alone: every client of the
 * viewer is on this machine (it listens on 127.0.0.1, and any local program may connect
 * from 127.0.0.2 as well), so a limit per address cannot tell the page from a program that
 * opens hundreds of connections; and MHD's connection timeout counts idle time only, so a
 * client that sends a header line every few seconds (slowloris) is never timed out. The
 * server therefore takes many connections (server.c: thousands, on epoll, with
 * RLIMIT_NOFILE raised to match), and this guard gives each request VIEW_GUARD_MS from the
 * moment its connection opened or its last answer went out to deliver all of its headers
 * and body, and its answer as long again to be read. A connection past that is shut down
 * (shutdown(2) of its socket: MHD's thread sees the end and closes it as usual). An idle
 * keep-alive connection is closed the same way, as MHD's timeout would; the page polls
 * every 500 ms and a browser opens a new connection when one was closed.
 *
 * The guard's clock stops while the server works on a request: one thread answers every
 * request in turn, so while a graph runs for seconds no other connection is read, and they
 * must not be blamed for that.
 *
 * Thread safety: every function may be called from any thread (one mutex inside). MHD's
 * thread calls view_guard_notify and the busy/idle/restart calls, the watcher
 * view_guard_sweep. A socket is shut down only while MHD holds it open: MHD calls
 * view_guard_notify(MHD_CONNECTION_NOTIFY_CLOSED) before it closes the descriptor, and that
 * takes the same mutex as the sweep. */
#ifndef SSG_CLI_VIEW_GUARD_H
#define SSG_CLI_VIEW_GUARD_H

#include <microhttpd.h>

enum { VIEW_GUARD_MS = 4000 }; /* per request, and per answer: on 127.0.0.1 either takes ms */

struct view_guard;

/* NULL on out of memory. */
struct view_guard *view_guard_new(void);
void view_guard_free(struct view_guard **guard);

/* The MHD_OPTION_NOTIFY_CONNECTION callback, with the guard as cls: starts and ends the
 * tracking of a connection. One that cannot be tracked (out of memory) is shut down. */
void view_guard_notify(void *cls, struct MHD_Connection *c, void **socket_context,
                       enum MHD_ConnectionNotificationCode code);

/* The server starts working on c's request: the clock stops (no connection's time runs). */
void view_guard_busy(struct view_guard *guard, struct MHD_Connection *c);
/* The answer to c is queued: the clock runs again; c has VIEW_GUARD_MS to read it. */
void view_guard_idle(struct view_guard *guard, struct MHD_Connection *c);
/* c's request is over (its answer sent, MHD_OPTION_NOTIFY_COMPLETED): its next request
 * has VIEW_GUARD_MS from now. */
void view_guard_restart(struct view_guard *guard, struct MHD_Connection *c);

/* Shuts down every connection past its deadline; returns how many it shut down now. */
int view_guard_sweep(struct view_guard *guard);

#endif
