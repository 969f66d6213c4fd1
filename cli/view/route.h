/* route.h - what each path of `ssgraph view` answers (route.c), apart from HTTP: the server
 * (server.c) has checked the token, Host and Origin and gathered the body. */
#ifndef SSG_CLI_VIEW_ROUTE_H
#define SSG_CLI_VIEW_ROUTE_H

#include <stddef.h>

#include "session.h"

struct MHD_Connection;

struct view_request {
    const char *method;                /* "GET", "POST" */
    const char *path;                  /* "/api/state" */
    const char *body;                  /* NUL-terminated; "" without one */
    struct MHD_Connection *connection; /* for its query arguments */
};

struct view_answer {
    int status;       /* HTTP status */
    const char *type; /* Content-Type */
    char *body;       /* malloc'd (the server frees it) */
    size_t len;
    int set_cookie;   /* 1 = set the token cookie (the page itself) */
};

/* Answers one request. */
void view_route(struct view_session *s, const struct view_request *req, struct view_answer *a);

/* An error answer: {"error": why}. */
void view_answer_error(struct view_answer *a, int status, const char *why);

#endif
