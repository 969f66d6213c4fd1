/* graph_info.c - the command line's look at a graph's structure (graph_info.h): DOT, the
 * first write node, quoting bare --set strings and -v's resolved parameters. */
#include <stdlib.h>
#include <string.h>

#include "graph/graph.h"
#include "graph/node.h"
#include "graph_info.h"
#include "lang/files.h"
#include "lang/params.h"

/* The graph at path parsed and built (includes, set lines), not validated and without its
   scene; NULL when it cannot be read at all. Errors go to diags, *e the first. */
static struct ssg_graph *build(const char *path, struct ssg_diags *diags, enum ssg_err *e)
{
    struct ssg_graph *g = calloc(1, sizeof *g);
    if (!g) {
        *e = SSG_E_NOMEM;
        return NULL;
    }
    *e = ssg_graph_build(g, path, NULL, diags);
    return g;
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
    fprintf(f, " [label=\"%.*s -> %s\"];\n", (int)c->value.member_len, c->value.member, into);
}

static void write_dot(FILE *f, const void *user)
{
    const struct ssg_graph *g = user;
    const char *base = strrchr(g->path, '/');
    base = base ? base + 1 : g->path;
    fputs("digraph ", f);
    dot_id(f, base, strcspn(base, "."));
    fputs(" {\n  rankdir=LR;\n  node [shape=box, fontname=\"Helvetica\"];\n"
          "  edge [fontname=\"Helvetica\", fontsize=10];\n", f);
    for (int i = 0; i < g->count; i++) {
        const struct gnode *n = &g->nodes[i];
        fputs("  ", f);
        dot_id(f, n->name, strlen(n->name));
        fprintf(f, " [label=\"%s\\n(%s)\"];\n", n->name, n->desc->name);
    }
    for (int i = 0; i < g->count; i++) {
        const struct gnode *n = &g->nodes[i];
        for (int k = 0; k < n->desc->input_count; k++)
            dot_edge(f, n, &n->in[k], n->desc->inputs[k].name);
        for (int k = 0; k < n->extra_count; k++)
            dot_edge(f, n, &n->extra[k], n->extra_names[k]);
    }
    fputs("}\n", f);
}

enum ssg_err ssg_cli_dot(const char *path, const char *out_path, struct ssg_diags *diags)
{
    enum ssg_err e;
    struct ssg_graph *g = build(path, diags, &e);
    const char *slash = out_path ? strrchr(out_path, '/') : NULL;
    if (!e && slash && slash > out_path) {
        char dir[1100];
        snprintf(dir, sizeof dir, "%.*s", (int)(slash - out_path), out_path);
        e = ssg_make_dirs(dir, diags);
    }
    if (!e && out_path)
        e = ssg_write_text_file(out_path, "DOT graph", write_dot, g, diags);
    else if (!e)
        write_dot(stdout, g);
    ssg_graph_destroy(&g);
    return e;
}

int ssg_cli_first_write(const char *path, char *name, size_t len)
{
    struct ssg_diags quiet = {0};
    enum ssg_err e;
    struct ssg_graph *g = build(path, &quiet, &e);
    int found = g && !e ? 0 : -1;
    for (int i = 0; found == 0 && i < g->count; i++)
        if (!strcmp(g->nodes[i].desc->name, "write")) {
            snprintf(name, len, "%s", g->nodes[i].name);
            found = 1;
        }
    ssg_graph_destroy(&g);
    return found;
}

/* The parameter `key` (len bytes) of a node type is a string. */
static int is_string_param(const struct ssg_node_desc *desc, const char *key, size_t len)
{
    int index = desc ? ssg_param_find(desc->params, key, len) : -1;
    return index >= 0 && desc->params.params[index].type == SSG_P_STRING;
}

/* The node type a --set entry names: `node`'s own, or the graph's instance before the dot
   (*key then starts after it). */
static const struct ssg_node_desc *set_target(const struct ssg_graph *g,
                                              const struct ssg_node_desc *node,
                                              const char **key)
{
    if (node)
        return node;
    const char *dot = strchr(*key, '.');
    int index = dot ? ssg_graph_find(g, *key, (size_t)(dot - *key)) : -1;
    if (index < 0)
        return NULL;
    *key = dot + 1;
    return g->nodes[index].desc;
}

/* A --sweep of a string parameter with bare values: "w.name=a,b" -> "w.name=\"a\",\"b\""
   (bench splits at the commas and sets each value as written). */
static int quote_sweep(struct ssg_cli_args *a, const struct ssg_graph *g, int k)
{
    const char *key = a->sweeps[k], *eq = strchr(key, '=');
    const struct ssg_node_desc *desc = eq ? set_target(g, NULL, &key) : NULL;
    if (!desc || key > eq || !is_string_param(desc, key, (size_t)(eq - key)) ||
        strpbrk(eq + 1, "\"\n"))
        return 0;
    char quoted[1200];
    size_t used = (size_t)snprintf(quoted, sizeof quoted, "%.*s", (int)(eq + 1 - a->sweeps[k]),
                                   a->sweeps[k]);
    for (const char *v = eq + 1; used < sizeof quoted;) {
        size_t n = strcspn(v, ",");
        used += (size_t)snprintf(quoted + used, sizeof quoted - used, "%s\"%.*s\"",
                                 v == eq + 1 ? "" : ",", (int)n, v);
        if (!v[n])
            break;
        v += n + 1;
    }
    const char *kept = used < sizeof quoted ? ssg_cli_keep(a, quoted) : NULL;
    if (!kept)
        return ssg_cli_usage_error("--sweep '%s' is too long to quote", a->sweeps[k]);
    a->sweeps[k] = kept;
    return 0;
}

int ssg_cli_quote_sets(struct ssg_cli_args *a, enum ssg_cli_command command)
{
    struct ssg_diags quiet = {0};
    enum ssg_err e = SSG_OK;
    struct ssg_graph *g = NULL;
    const struct ssg_node_desc *node = NULL;
    if (command == SSG_CLI_NODE)
        node = ssg_node_find(a->files[0], strlen(a->files[0]));
    else if (a->ov.set_count || a->sweep_count)
        g = build(a->files[0], &quiet, &e);
    int rc = 0;
    for (int i = 0; i < a->ov.set_count && (g || node) && !rc; i++) {
        const char *key = a->sets[i], *eq = strchr(key, '=');
        const struct ssg_node_desc *desc = eq ? set_target(g, node, &key) : NULL;
        if (!desc || key > eq || !is_string_param(desc, key, (size_t)(eq - key)) ||
            eq[1] == '"' || strpbrk(eq + 1, "\"\n"))
            continue;
        char quoted[1200];
        snprintf(quoted, sizeof quoted, "%.*s\"%s\"", (int)(eq + 1 - a->sets[i]), a->sets[i],
                 eq + 1);
        const char *kept = ssg_cli_keep(a, quoted);
        if (!kept)
            rc = ssg_cli_usage_error("%s", "too many --set values to quote");
        else
            a->sets[i] = kept;
    }
    for (int k = 0; k < a->sweep_count && g && !rc; k++)
        rc = quote_sweep(a, g, k);
    ssg_graph_destroy(&g);
    return rc;
}

void ssg_cli_print_resolved(const struct ssg_graph *g, FILE *f)
{
    const struct ssg_frame *fr = &g->frame;
    fprintf(f, "graph %s: %dx%d, guard %d, seed %llu, fov %.6g, near %.6g, far %.6g, scene %s",
            g->path, fr->width, fr->height, fr->guard, (unsigned long long)fr->seed,
            fr->fov_y, fr->near_z, fr->far_z, g->scene_path[0] ? g->scene_path : "(none)");
    if (g->lights_path[0])
        fprintf(f, ", lights %s", g->lights_path);
    fputc('\n', f);
    ssg_cli_print_node_params(g, f);
}

void ssg_cli_print_node_params(const struct ssg_graph *g, FILE *f)
{
    for (int p = 0; p < g->order_count; p++) {
        const struct gnode *n = &g->nodes[g->order[p]];
        fprintf(f, "  %-16s %-12s %-4s", n->name, n->desc->name,
                ssg_backend_name(n->runs_on));
        for (int k = 0; k < n->desc->params.count; k++) {
            char value[256];
            ssg_param_format(&n->desc->params.params[k], n->params, value, sizeof value);
            fprintf(f, " %s=%s", n->desc->params.params[k].name, value);
        }
        fputc('\n', f);
    }
}
