/* api.c - the bodies of the viewer's answers (api.h). */
#define _DEFAULT_SOURCE /* open_memstream, mkstemp */
#include "api.h"

#include <math.h>
#include <spawn.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "../text_out.h"

extern char **environ;

static void json_vec3(FILE *f, const float v[3])
{
    fprintf(f, "[%.9g,%.9g,%.9g]", v[0], v[1], v[2]);
}

static void json_camera(FILE *f, const struct view_session *s)
{
    if (!s->has_camera) {
        fputs("null", f);
        return;
    }
    fputs("{\"position\":", f);
    json_vec3(f, s->camera.position);
    fputs(",\"target\":", f);
    json_vec3(f, s->camera.target);
    fputs(",\"up\":", f);
    json_vec3(f, s->camera.up);
    fprintf(f, ",\"fov_y\":%.9g}", s->camera.fov_y);
}

/* A number parameter's bound, or null when it has none. */
static void json_bound(FILE *f, const struct ssg_param_info *p, double v)
{
    if (p->bounded)
        ssg_json_number(f, v);
    else
        fputs("null", f);
}

static void json_param(FILE *f, const struct ssg_graph *g, int node, const char *type, int k)
{
    char value[1024];
    struct ssg_param_info p;
    ssg_graph_node_param(g, node, k, value, sizeof value);
    ssg_node_param_info(type, k, &p);
    fputs("{\"name\":", f);
    ssg_json_string(f, p.name);
    fputs(",\"type\":", f);
    ssg_json_string(f, p.type);
    fputs(",\"value\":", f);
    ssg_json_string(f, value);
    fputs(",\"min\":", f);
    json_bound(f, &p, p.min);
    fputs(",\"max\":", f);
    json_bound(f, &p, p.max);
    /* the useful range, the slider's (min, max where the row has none); null, null for a
       number with neither */
    if (p.soft_max > p.soft_min) {
        fputs(",\"soft_min\":", f);
        ssg_json_number(f, p.soft_min);
        fputs(",\"soft_max\":", f);
        ssg_json_number(f, p.soft_max);
    } else {
        fputs(",\"soft_min\":null,\"soft_max\":null", f);
    }
    fputs(",\"unit\":", f);
    if (p.unit)
        ssg_json_string(f, p.unit);
    else
        fputs("null", f);
    fputs(",\"choices\":", f);
    if (p.choices) {
        for (int c = 0; p.choices[c]; c++) {
            fputs(c ? "," : "[", f);
            ssg_json_string(f, p.choices[c]);
        }
        fputs("]", f);
    } else {
        fputs("null", f);
    }
    fputs(",\"doc\":", f);
    ssg_json_string(f, p.doc ? p.doc : "");
    fputs("}", f);
}

static void json_ports(FILE *f, const struct ssg_graph *g, int node, int outputs)
{
    int first = 1;
    fputs("[", f);
    for (int k = 0; k < ssg_graph_port_count(g, node); k++) {
        struct ssg_port_info p;
        ssg_graph_port_inspect(g, node, k, &p);
        if (p.output != outputs)
            continue;
        fputs(first ? "{\"port\":" : ",{\"port\":", f);
        first = 0;
        ssg_json_string(f, p.name);
        fputs(",\"type\":", f);
        ssg_json_string(f, p.type);
        if (outputs) { /* image: the last run has it (an unread on-demand output has not) */
            fprintf(f, ",\"channels\":%d,\"image\":%s}", p.channels,
                    p.has_image ? "true" : "false");
            continue;
        }
        fprintf(f, ",\"optional\":%s,\"from\":", p.optional ? "true" : "false");
        if (p.from[0])
            ssg_json_string(f, p.from);
        else
            fputs("null", f);
        fputs("}", f);
    }
    fputs("]", f);
}

/* The node type's one-line summary. */
static const char *summary(const char *type)
{
    for (int i = 0; type && i < ssg_node_count(); i++)
        if (!strcmp(ssg_node_name(i), type))
            return ssg_node_summary(i);
    return "";
}

/* What the last run did with the node: its entry of the stats, or NULL. */
static const struct ssg_run_node *ran(const struct view_session *s, const char *name)
{
    for (int i = 0; i < s->stats.node_count; i++)
        if (!strcmp(s->stats.nodes[i].name, name))
            return &s->stats.nodes[i];
    return NULL;
}

static void json_node(FILE *f, const struct view_session *s, const struct ssg_graph *g, int i)
{
    struct ssg_node_info n;
    ssg_graph_node_inspect(g, i, &n);
    const struct ssg_run_node *r = ran(s, n.name);
    fputs("{\"name\":", f);
    ssg_json_string(f, n.name);
    fputs(",\"type\":", f);
    ssg_json_string(f, n.type ? n.type : "");
    fputs(",\"backend\":", f);
    ssg_json_string(f, n.backend);
    fprintf(f, ",\"live\":%s,\"ran\":%s,\"ms\":", r ? "true" : "false",
            r && r->calls ? "true" : "false");
    ssg_json_number(f, r && r->calls ? r->ms : 0.0);
    fputs(",\"why\":", f); /* why it ran or was kept (docs/development.md) */
    ssg_json_string(f, r && r->why ? r->why : "");
    fputs(",\"doc\":", f);
    ssg_json_string(f, summary(n.type));
    fputs(",\"params\":[", f);
    for (int k = 0; k < n.param_count; k++) {
        if (k)
            fputs(",", f);
        json_param(f, g, i, n.type, k);
    }
    fputs("],\"inputs\":", f);
    json_ports(f, g, i, 0);
    fputs(",\"outputs\":", f);
    json_ports(f, g, i, 1);
    fputs("}", f);
}

char *view_state_json(const struct view_session *s, size_t *len)
{
    char *text = NULL;
    FILE *f = open_memstream(&text, len);
    if (!f)
        return NULL;
    struct ssg_graph_info info;
    ssg_graph_inspect(s->g, &info);
    fprintf(f, "{\"generation\":%u,\"graph\":", s->generation);
    ssg_json_string(f, info.path);
    fputs(",\"scene\":", f);
    ssg_json_string(f, info.scene);
    fputs(",\"backend\":", f);
    ssg_json_string(f, s->args->ov.backend ? s->args->ov.backend : "graph");
    fprintf(f, ",\"size\":[%d,%d],\"preview\":[%d,%d],\"frame\":%d,\"last_run\":\"%s\","
            "\"error\":", s->width, s->height, s->preview_width, s->preview_height, s->frame,
            s->last_preview ? "preview" : "full");
    if (s->error)
        ssg_json_string(f, s->error);
    else
        fputs("null", f);
    fputs(",\"reference_file\":", f); /* reference.h: "file:PATH" */
    if (s->ref_port)
        ssg_json_string(f, s->ref_port);
    else
        fputs("null", f);
    fputs(",\"camera\":", f);
    json_camera(f, s);
    fprintf(f, ",\"edited\":%s,\"unsaved_edits\":%d", s->text ? "true" : "false", s->edits);
    fputs(",\"frame_ms\":", f);
    ssg_json_number(f, s->stats.frame_avg_ms);
    fputs(",\"total_ms\":", f);
    ssg_json_number(f, s->stats.total_ms);
    fputs(",\"nodes\":[", f);
    /* A node the preview ran is one of the full graph's: the same file order. */
    for (int i = 0; i < info.node_count; i++) {
        if (i)
            fputs(",", f);
        json_node(f, s, s->g, i);
    }
    fputs("]}\n", f);
    if (fclose(f)) {
        free(text);
        return NULL;
    }
    return text;
}

static void put_u32(unsigned char *p, uint32_t v)
{
    for (int i = 0; i < 4; i++)
        p[i] = (unsigned char)(v >> (8 * i));
}

/* An image as GET /api/image's bytes (api.h), of run `generation`; NULL when out of memory. */
static char *image_bytes(const struct ssg_image *img, unsigned generation, size_t *len,
                         struct ssg_diags *d)
{
    size_t w = (size_t)img->width, h = (size_t)img->height, c = (size_t)img->channels;
    size_t plane = w * h;
    unsigned char *out = malloc(20 + plane * c * sizeof(float));
    if (!out) {
        view_fail(d, SSG_E_NOMEM, "out of memory for %zux%zu pixels", w, h);
        return NULL;
    }
    memcpy(out, "SSGI", 4);
    put_u32(out + 4, (uint32_t)w);
    put_u32(out + 8, (uint32_t)h);
    put_u32(out + 12, (uint32_t)c);
    put_u32(out + 16, generation);
    float *px = (float *)(void *)(out + 20); /* 20 is a multiple of 4 */
    /* The library's images are planar; the page reads interleaved pixels. The host is
       little-endian (x86-64, arm64), as the format says. */
    for (size_t i = 0; i < plane; i++)
        for (size_t k = 0; k < c; k++)
            px[i * c + k] = img->data[k * plane + i];
    *len = 20 + plane * c * sizeof(float);
    return (char *)out;
}

char *view_image_bytes(struct view_session *s, const char *port, int preview, size_t *len,
                       struct ssg_diags *d)
{
    struct ssg_image *img;
    if (view_session_image(s, port, preview, &img, d))
        return NULL;
    char *out = image_bytes(img, s->generation, len, d);
    ssg_image_destroy(&img);
    return out;
}

/* The compare node on port a against port ref (full size), with the parameter `set`
   ("flip=off": no FLIP, which costs 0.3 s at 640x360 and which the RMSE and SSIM do not
   need); its outputs, the caller releases them. */
static enum ssg_err compare_ports(struct view_session *s, const char *a,
                                  const struct ssg_image *ref, const char *set,
                                  struct ssg_outputs *out, struct ssg_diags *d)
{
    struct ssg_image *img;
    enum ssg_err e = view_session_image(s, a, 0, &img, d);
    if (e)
        return e;
    struct ssg_binding in[2] = {{"a", img}, {"b", ref}};
    e = ssg_node_run("compare", in, 2, &set, 1, NULL, out, d);
    ssg_image_destroy(&img);
    return e;
}

char *view_flip_bytes(struct view_session *s, const char *a, const char *b, size_t *len,
                      struct ssg_diags *d)
{
    struct ssg_image *ref;
    if (view_session_image(s, b, 0, &ref, d))
        return NULL;
    struct ssg_outputs out = {0};
    enum ssg_err e = compare_ports(s, a, ref, "flip=auto", &out, d);
    ssg_image_destroy(&ref);
    char *bytes = NULL;
    for (int i = 0; !e && i < out.count; i++)
        if (!strcmp(out.names[i], "flip"))
            bytes = image_bytes(out.images[i], s->generation, len, d);
    if (!e && !bytes && !d->count)
        view_fail(d, SSG_E_RUN, "the compare node made no flip map");
    ssg_outputs_release(&out);
    return bytes;
}

/* RMSE and SSIM of port `port` against the image ref, as JSON, through the compare node. */
static enum ssg_err json_score(FILE *f, struct view_session *s, const struct ssg_image *ref,
                               const char *port, struct ssg_diags *d)
{
    struct ssg_outputs out = {0};
    enum ssg_err e = compare_ports(s, port, ref, "flip=off", &out, d);
    if (e)
        return e;
    double rmse = NAN, ssim = NAN;
    for (int i = 0; i < out.metric_count; i++) {
        if (!strcmp(out.metric_names[i], "rmse"))
            rmse = out.metric_values[i];
        else if (!strcmp(out.metric_names[i], "ssim"))
            ssim = out.metric_values[i];
    }
    ssg_outputs_release(&out);
    fputs("{\"rmse\":", f);
    ssg_json_number(f, rmse);
    fputs(",\"ssim\":", f);
    ssg_json_number(f, ssim);
    fputs("}", f);
    return SSG_OK;
}

char *view_metrics_json(struct view_session *s, const char *ref, const char *a, const char *b,
                        size_t *len, struct ssg_diags *d)
{
    struct ssg_image *truth;
    if (view_session_image(s, ref, 0, &truth, d))
        return NULL;
    char *text = NULL;
    FILE *f = open_memstream(&text, len);
    enum ssg_err e = f ? SSG_OK : SSG_E_NOMEM;
    if (f) {
        fputs("{\"a\":", f);
        e = json_score(f, s, truth, a, d);
        fputs(",\"b\":", f);
        if (!e && b)
            e = json_score(f, s, truth, b, d);
        else
            fputs("null", f);
        fputs("}\n", f);
        if (fclose(f) && !e)
            e = SSG_E_NOMEM;
    }
    ssg_image_destroy(&truth);
    if (e) {
        free(text);
        return NULL;
    }
    return text;
}

/* Reads all of fd into a malloc'd buffer; NULL on failure. */
static char *read_all(int fd, size_t *len)
{
    size_t cap = 1 << 16, n = 0;
    char *buf = malloc(cap);
    ssize_t got;
    while (buf && (got = read(fd, buf + n, cap - n)) > 0) {
        n += (size_t)got;
        if (n == cap) {
            char *bigger = cap < (64u << 20) ? realloc(buf, cap *= 2) : NULL;
            if (!bigger)
                free(buf);
            buf = bigger;
        }
    }
    *len = n;
    return buf;
}

/* `dot -Tsvg FILE` with its standard output read back; NULL when dot cannot run. */
static char *run_dot(const char *dot_file, size_t *len, int *status)
{
    int pipe_fd[2];
    if (pipe(pipe_fd))
        return NULL;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipe_fd[1], 1);
    posix_spawn_file_actions_addclose(&actions, pipe_fd[0]);
    /* Fixed arguments, no shell: nothing of the graph reaches a command line. */
    char *argv[] = {"dot", "-Tsvg", (char *)dot_file, NULL};
    pid_t pid;
    int spawned = posix_spawnp(&pid, "dot", &actions, NULL, argv, environ) == 0;
    posix_spawn_file_actions_destroy(&actions);
    close(pipe_fd[1]);
    char *svg = spawned ? read_all(pipe_fd[0], len) : NULL;
    close(pipe_fd[0]);
    *status = -1;
    if (spawned)
        waitpid(pid, status, 0);
    return svg;
}

char *view_graph_svg(const struct view_session *s, size_t *len, struct ssg_diags *d)
{
    const char *tmpdir = getenv("TMPDIR");
    char dot_file[512];
    snprintf(dot_file, sizeof dot_file, "%s/ssgraph-view-XXXXXX",
             tmpdir && *tmpdir && strlen(tmpdir) < 400 ? tmpdir : P_tmpdir);
    int fd = mkstemp(dot_file);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) {
        if (fd >= 0)
            close(fd);
        view_fail(d, SSG_E_IO, "cannot write the graph's DOT into a temporary file");
        return NULL;
    }
    ssg_graph_dot(s->g, f);
    fclose(f);
    int status;
    char *svg = run_dot(dot_file, len, &status);
    unlink(dot_file);
    if (!svg || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        free(svg);
        view_fail(d, SSG_E_IO, "Graphviz's `dot -Tsvg` failed (is the graphviz package "
                  "installed?)");
        return NULL;
    }
    return svg;
}
