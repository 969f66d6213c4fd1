/* api_graph_info.c - a graph's structure and current values through the public interface
 * (ssgraph.h, "Looking into a graph"): what the command line prints of a graph (dot, -v,
 * bench's reference key) without reaching into struct ssg_graph, and the GL context a run
 * would open (--version). Reads the graph only; never changes it. */
#include <stdlib.h>
#include <string.h>

#include "graph/gl_backend.h"
#include "graph/graph.h"
#include "lang/diag.h"
#include "lang/params.h"

enum ssg_err ssg_graph_parse(const char *path, struct ssg_graph **out, struct ssg_diags *diags)
{
    if (out)
        *out = NULL;
    if (ssg_api_null(diags, "ssg_graph_parse", "path, out", 2, path, out))
        return SSG_E_USAGE;
    struct ssg_graph *g = calloc(1, sizeof *g);
    if (!g) {
        ssg_diag_file(diags, SSG_E_NOMEM, path, "out of memory reading the graph");
        return SSG_E_NOMEM;
    }
    *out = g;
    return ssg_graph_build(g, path, NULL, diags);
}

void ssg_graph_inspect(const struct ssg_graph *g, struct ssg_graph_info *info)
{
    *info = (struct ssg_graph_info){.path = g->path ? g->path : "",
                                    .scene = g->scene_path, .lights = g->lights_path,
                                    .frame = g->frame, .node_count = g->count,
                                    .run_count = g->order ? g->order_count : 0};
}

enum ssg_err ssg_graph_node_inspect(const struct ssg_graph *g, int index,
                                    struct ssg_node_info *info)
{
    if (index < 0 || index >= g->count) {
        *info = (struct ssg_node_info){0};
        return SSG_E_USAGE;
    }
    const struct gnode *n = &g->nodes[index];
    *info = (struct ssg_node_info){.name = n->name, .type = n->desc ? n->desc->name : NULL,
                                   .backend = ssg_backend_name(n->runs_on),
                                   .param_count = n->desc ? n->desc->params.count : 0};
    return SSG_OK;
}

int ssg_graph_run_node(const struct ssg_graph *g, int position)
{
    return g->order && position >= 0 && position < g->order_count ? g->order[position] : -1;
}

int ssg_graph_node_index(const struct ssg_graph *g, const char *name)
{
    return ssg_graph_find(g, name, strlen(name));
}

const char *ssg_graph_node_param(const struct ssg_graph *g, int index, int k, char *value,
                                 size_t len)
{
    if (len)
        value[0] = '\0';
    if (index < 0 || index >= g->count)
        return NULL;
    const struct gnode *n = &g->nodes[index];
    if (!n->desc || !n->params || k < 0 || k >= n->desc->params.count)
        return NULL;
    ssg_param_format(&n->desc->params.params[k], n->params, value, len);
    return n->desc->params.params[k].name;
}

const char *ssg_node_metric(const char *node, int k)
{
    const struct ssg_node_desc *desc = node ? ssg_node_find(node, strlen(node)) : NULL;
    for (int i = 0; desc && desc->metrics && desc->metrics[i]; i++)
        if (i == k)
            return desc->metrics[i];
    return NULL;
}

const char *ssg_node_param_type(const char *node, const char *param)
{
    const struct ssg_node_desc *desc = ssg_node_find(node, strlen(node));
    int k = desc ? ssg_param_find(desc->params, param, strlen(param)) : -1;
    return k >= 0 ? ssg_param_type_name(&desc->params.params[k]) : NULL;
}

/* A DOT identifier in quotes (names are the graph's identifiers; quoted all the same). */
static void dot_id(FILE *f, const char *s, size_t len)
{
    fputc('"', f);
    for (size_t i = 0; i < len && s[i]; i++) {
        if (s[i] == '"' || s[i] == '\\')
            fputc('\\', f);
        fputc(s[i], f);
    }
    fputc('"', f);
}

/* One edge into node n from the reference c (producer.port), to its input `into`. */
static void dot_edge(FILE *f, const struct gnode *n, const struct gconn *c, const char *into)
{
    if (!c->ref)
        return;
    fputs("  ", f);
    dot_id(f, c->value.text, c->value.len);
    fputs(" -> ", f);
    dot_id(f, n->name, strlen(n->name));
    fprintf(f, " [label=\"%s%.*s -> %s\"%s];\n", c->value.prev ? "prev " : "",
            (int)c->value.member_len, c->value.member, into,
            c->value.prev ? ", style=dashed" : ""); /* the previous frame's: no ordering */
}

void ssg_graph_dot(const struct ssg_graph *g, FILE *f)
{
    const char *path = g->path ? g->path : "";
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    fputs("digraph ", f);
    dot_id(f, base, strcspn(base, "."));
    fputs(" {\n  rankdir=LR;\n  node [shape=box, fontname=\"Helvetica\"];\n"
          "  edge [fontname=\"Helvetica\", fontsize=10];\n", f);
    for (int i = 0; i < g->count; i++) {
        const struct gnode *n = &g->nodes[i];
        fputs("  ", f);
        dot_id(f, n->name, strlen(n->name));
        fprintf(f, " [label=\"%s\\n(%s)\"];\n", n->name, n->desc ? n->desc->name : "?");
    }
    for (int i = 0; i < g->count; i++) {
        const struct gnode *n = &g->nodes[i];
        for (int k = 0; n->desc && k < n->desc->input_count; k++)
            dot_edge(f, n, &n->in[k], n->desc->inputs[k].name);
        for (int k = 0; k < n->extra_count; k++)
            dot_edge(f, n, &n->extra[k], n->extra_names[k]);
    }
    fputs("}\n", f);
}

enum ssg_err ssg_gl_info(char *text, size_t len, struct ssg_diags *diags)
{
    if (len)
        text[0] = '\0';
    enum ssg_err e = ssg_gl_open(diags);
    if (e)
        return e;
    snprintf(text, len, "%s", ssg_gl_describe());
    ssg_gl_close();
    return SSG_OK;
}
