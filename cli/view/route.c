/* route.c - what each path of `ssgraph view` answers (route.h; docs/viewer-api.md). */
#define _DEFAULT_SOURCE /* open_memstream, strdup */
#include "route.h"

#include <microhttpd.h>
#include <stdlib.h>
#include <string.h>

#include "../text_out.h"
#include "api.h"
#include "reference.h"
#include "view.h"

static const char *JSON = "application/json";

/* An answer of one JSON field, {"key": "text"}. */
static void json_field(struct view_answer *a, int status, const char *key, const char *text)
{
    *a = (struct view_answer){.status = status, .type = JSON};
    FILE *f = open_memstream(&a->body, &a->len);
    if (!f)
        return;
    fputs("{", f);
    ssg_json_string(f, key);
    fputs(":", f);
    ssg_json_string(f, text);
    fputs("}\n", f);
    fclose(f);
}

void view_answer_error(struct view_answer *a, int status, const char *why)
{
    json_field(a, status, "error", why);
}

/* An error answer carrying the diagnostics as `ssgraph run` prints them. */
static void diags_error(struct view_answer *a, int status, const struct ssg_diags *d,
                        enum ssg_err e)
{
    char *text = view_diags_text(d, e);
    view_answer_error(a, status, text ? text : ssg_err_text(e));
    free(text);
}

static void answer(struct view_answer *a, const char *type, char *body, size_t len)
{
    *a = (struct view_answer){.status = MHD_HTTP_OK, .type = type, .body = body, .len = len};
    if (!body)
        view_answer_error(a, MHD_HTTP_INTERNAL_SERVER_ERROR, "out of memory");
}

/* The session's state as JSON (GET /api/state, and the answer to every change). */
static void state_answer(const struct view_session *s, struct view_answer *a)
{
    size_t len = 0;
    char *body = view_state_json(s, &len);
    answer(a, JSON, body, len);
}

static const char *arg(const struct view_request *req, const char *name)
{
    return MHD_lookup_connection_value(req->connection, MHD_GET_ARGUMENT_KIND, name);
}

static const char *content_type(const char *name)
{
    const char *dot = strrchr(name, '.');
    if (dot && !strcmp(dot, ".html"))
        return "text/html; charset=utf-8";
    if (dot && !strcmp(dot, ".js"))
        return "text/javascript; charset=utf-8";
    if (dot && !strcmp(dot, ".css"))
        return "text/css; charset=utf-8";
    return "text/plain; charset=utf-8";
}

/* One of the embedded page files, by its name; 0 when there is none. */
static int page_file(const char *path, struct view_answer *a)
{
    const char *name = !strcmp(path, "/") ? "index.html" : path + 1;
    for (const struct ssg_view_file *f = ssg_view_files; f->name; f++) {
        if (strcmp(f->name, name))
            continue;
        answer(a, content_type(name), strdup(f->text), strlen(f->text));
        a->set_cookie = !strcmp(name, "index.html");
        return 1;
    }
    return 0;
}

static void state(struct view_session *s, const struct view_request *req,
                  struct view_answer *a)
{
    const char *since = arg(req, "since");
    if (since && strtoul(since, NULL, 10) == s->generation) {
        *a = (struct view_answer){.status = MHD_HTTP_NO_CONTENT, .type = JSON};
        return;
    }
    state_answer(s, a);
}

static void image(struct view_session *s, const struct view_request *req,
                  struct view_answer *a)
{
    const char *port = arg(req, "port"), *preview = arg(req, "preview");
    if (!port) {
        view_answer_error(a, MHD_HTTP_BAD_REQUEST, "expected ?port=NODE.PORT");
        return;
    }
    struct ssg_diags d = {0};
    size_t len = 0;
    char *body = view_image_bytes(s, port, preview && !strcmp(preview, "1"), &len, &d);
    if (body)
        answer(a, "application/octet-stream", body, len);
    else
        diags_error(a, MHD_HTTP_NOT_FOUND, &d, ssg_diags_first(&d));
}

static void metrics(struct view_session *s, const struct view_request *req,
                    struct view_answer *a)
{
    const char *ref = arg(req, "ref"), *pa = arg(req, "a"), *pb = arg(req, "b");
    if (!ref || !pa) {
        view_answer_error(a, MHD_HTTP_BAD_REQUEST, "expected ?ref=NODE.PORT&a=NODE.PORT"
                          "[&b=NODE.PORT]");
        return;
    }
    struct ssg_diags d = {0};
    size_t len = 0;
    char *body = view_metrics_json(s, ref, pa, pb && *pb ? pb : NULL, &len, &d);
    if (body)
        answer(a, JSON, body, len);
    else
        diags_error(a, MHD_HTTP_BAD_REQUEST, &d, ssg_diags_first(&d));
}

static void flip(struct view_session *s, const struct view_request *req, struct view_answer *a)
{
    const char *pa = arg(req, "a"), *pb = arg(req, "b");
    if (!pa || !pb) {
        view_answer_error(a, MHD_HTTP_BAD_REQUEST, "expected ?a=NODE.PORT&b=NODE.PORT");
        return;
    }
    struct ssg_diags d = {0};
    size_t len = 0;
    char *body = view_flip_bytes(s, pa, pb, &len, &d);
    if (body)
        answer(a, "application/octet-stream", body, len);
    else
        diags_error(a, MHD_HTTP_BAD_REQUEST, &d, ssg_diags_first(&d));
}

static void graph_svg(struct view_session *s, const struct view_request *req,
                      struct view_answer *a)
{
    (void)req;
    struct ssg_diags d = {0};
    size_t len = 0;
    char *body = view_graph_svg(s, &len, &d);
    if (body)
        answer(a, "image/svg+xml", body, len);
    else
        diags_error(a, MHD_HTTP_SERVICE_UNAVAILABLE, &d, ssg_diags_first(&d));
}

/* After a change: the new state, or the refusal with its diagnostics. */
static void changed(struct view_session *s, enum ssg_err e, const struct ssg_diags *d,
                    struct view_answer *a)
{
    if (e) {
        diags_error(a, MHD_HTTP_BAD_REQUEST, d, e);
        return;
    }
    state_answer(s, a);
}

/* The value of `name=` in a form body "a=1&b=2" into out; 0 when absent. */
static int form_value(const char *body, const char *name, char *out, size_t len)
{
    size_t n = strlen(name);
    for (const char *p = body; p && *p; p = strchr(p, '&'), p = p ? p + 1 : NULL) {
        if (strncmp(p, name, n) || p[n] != '=')
            continue;
        size_t v = strcspn(p + n + 1, "&");
        if (v >= len)
            return 0;
        memcpy(out, p + n + 1, v);
        out[v] = '\0';
        return 1;
    }
    return 0;
}

static int form_vec3(const char *body, const char *name, float v[3])
{
    char text[256], end;
    return form_value(body, name, text, sizeof text) &&
           sscanf(text, "%f,%f,%f%c", &v[0], &v[1], &v[2], &end) == 3;
}

static void camera(struct view_session *s, const struct view_request *req,
                   struct view_answer *a)
{
    struct ssg_view v;
    char fov[64], preview[8] = "0", end;
    if (!form_vec3(req->body, "position", v.position) ||
        !form_vec3(req->body, "target", v.target) || !form_vec3(req->body, "up", v.up) ||
        !form_value(req->body, "fov", fov, sizeof fov) ||
        sscanf(fov, "%f%c", &v.fov_y, &end) != 1) {
        view_answer_error(a, MHD_HTTP_BAD_REQUEST, "expected position=x,y,z&target=x,y,z&"
                          "up=x,y,z&fov=DEGREES[&preview=1]");
        return;
    }
    form_value(req->body, "preview", preview, sizeof preview);
    struct ssg_diags d = {0};
    enum ssg_err e = view_session_camera(s, &v, !strcmp(preview, "1"), &d);
    changed(s, e, &d, a);
}

/* A save (as variant, or the edited graph): {"path": ...}, or why not (409 when the name
   exists). */
static void save_with(struct view_session *s, const struct view_request *req,
                      struct view_answer *a,
                      enum ssg_err (*save_as)(struct view_session *s, const char *name,
                                              char *path, size_t len, struct ssg_diags *d))
{
    char name[128] = "", path[1024];
    struct ssg_diags d = {0};
    form_value(req->body, "name", name, sizeof name);
    enum ssg_err e = save_as(s, name, path, sizeof path, &d);
    if (e)
        diags_error(a, e == SSG_E_IO ? MHD_HTTP_CONFLICT : MHD_HTTP_BAD_REQUEST, &d, e);
    else
        json_field(a, MHD_HTTP_OK, "path", path);
}

static void save(struct view_session *s, const struct view_request *req,
                 struct view_answer *a)
{
    save_with(s, req, a, view_session_save);
}

/* The body is "path=" and the path, raw to its end (a path may hold '&' and '='): 404 when
   the file cannot be read, 400 when it is not an EXR of the frame's size. */
static void reference(struct view_session *s, const struct view_request *req,
                      struct view_answer *a)
{
    if (strncmp(req->body, "path=", 5)) {
        view_answer_error(a, MHD_HTTP_BAD_REQUEST, "expected path=FILE.exr");
        return;
    }
    struct ssg_diags d = {0};
    enum ssg_err e = view_reference_open(s, req->body + 5, &d);
    if (e)
        diags_error(a, e == SSG_E_IO ? MHD_HTTP_NOT_FOUND : MHD_HTTP_BAD_REQUEST, &d, e);
    else
        state_answer(s, a);
}

/* POST /api/save_path: name=NAME&keys=... (campath.c). The keys are the body's last field
   (their text may be long: up to the 64 KiB body). */
static void save_path(struct view_session *s, const struct view_request *req,
                      struct view_answer *a)
{
    char name[128] = "", path[1024];
    const char *keys = strstr(req->body, "&keys=");
    struct ssg_diags d = {0};
    form_value(req->body, "name", name, sizeof name);
    enum ssg_err e = keys ? view_session_save_path(s, name, keys + 6, path, sizeof path, &d)
                          : view_fail(&d, SSG_E_USAGE, "expected name=NAME&keys=...");
    if (e) {
        diags_error(a, e == SSG_E_IO ? MHD_HTTP_CONFLICT : MHD_HTTP_BAD_REQUEST, &d, e);
        return;
    }
    json_field(a, MHD_HTTP_OK, "path", path);
}

static void set(struct view_session *s, const struct view_request *req, struct view_answer *a)
{
    struct ssg_diags d = {0};
    changed(s, view_session_set(s, req->body, &d), &d, a);
}

static void frame(struct view_session *s, const struct view_request *req,
                  struct view_answer *a)
{
    char text[32], end;
    int n;
    if (!form_value(req->body, "frame", text, sizeof text) ||
        sscanf(text, "%d%c", &n, &end) != 1 || n < 0) {
        view_answer_error(a, MHD_HTTP_BAD_REQUEST, "expected frame=N (0 or more)");
        return;
    }
    struct ssg_diags d = {0};
    changed(s, view_session_frame(s, n, &d), &d, a);
}

/* The graph editor (docs/viewer-api.md, "Editing the graph"). */
static void edit(struct view_session *s, const struct view_request *req, struct view_answer *a)
{
    struct ssg_diags d = {0};
    changed(s, view_session_edit(s, req->body, &d), &d, a);
}

static void edit_discard(struct view_session *s, const struct view_request *req,
                         struct view_answer *a)
{
    (void)req;
    struct ssg_diags d = {0};
    changed(s, view_session_discard(s, &d), &d, a);
}

static void edit_save(struct view_session *s, const struct view_request *req,
                      struct view_answer *a)
{
    save_with(s, req, a, view_session_save_edited);
}

static void types(struct view_session *s, const struct view_request *req,
                  struct view_answer *a)
{
    (void)s, (void)req;
    size_t len = 0;
    char *body = view_types_json(&len);
    answer(a, JSON, body, len);
}

/* Every path of the interface and the one method it takes. */
static const struct route {
    const char *path;
    int post; /* 0 = GET (or HEAD) */
    void (*answer)(struct view_session *s, const struct view_request *req,
                   struct view_answer *a);
} routes[] = {
    {"/api/state", 0, state},     {"/api/image", 0, image},     {"/api/metrics", 0, metrics},
    {"/api/graph.svg", 0, graph_svg}, {"/api/set", 1, set},
    {"/api/camera", 1, camera},   {"/api/save", 1, save},       {"/api/frame", 1, frame},
    {"/api/flip", 0, flip},       {"/api/reference", 1, reference},
    {"/api/save_path", 1, save_path},
    {"/api/types", 0, types},     {"/api/edit", 1, edit},       {"/api/edit/save", 1, edit_save},
    {"/api/edit/discard", 1, edit_discard},
};

void view_route(struct view_session *s, const struct view_request *req, struct view_answer *a)
{
    int get = !strcmp(req->method, "GET") || !strcmp(req->method, "HEAD");
    int post = !strcmp(req->method, "POST");
    if (get && page_file(req->path, a))
        return;
    for (size_t i = 0; i < sizeof routes / sizeof routes[0]; i++) {
        if (strcmp(routes[i].path, req->path))
            continue;
        if (routes[i].post ? post : get)
            routes[i].answer(s, req, a);
        else
            view_answer_error(a, MHD_HTTP_METHOD_NOT_ALLOWED,
                              routes[i].post ? "expected POST" : "expected GET");
        return;
    }
    if (get || post)
        view_answer_error(a, MHD_HTTP_NOT_FOUND, "no such path (docs/viewer-api.md lists them)");
    else
        view_answer_error(a, MHD_HTTP_METHOD_NOT_ALLOWED, "only GET and POST");
}
