/* graph_info.c - the command line's look at a graph's structure (graph_info.h): DOT, the
 * first write node, quoting bare --set strings and -v's resolved parameters. */
#include <stdlib.h>
#include <string.h>

#include "graph_info.h"

/* The graph at path parsed and built (includes, set lines), not validated and without its
   scene; NULL when it cannot be read at all. Errors go to diags, *e the first. */
static struct ssg_graph *build(const char *path, struct ssg_diags *diags, enum ssg_err *e)
{
    struct ssg_graph *g = NULL;
    *e = ssg_graph_parse(path, &g, diags);
    return g;
}

static void write_dot(FILE *f, const void *user)
{
    ssg_graph_dot(user, f);
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
        e = ssg_write_text_stream(out_path, "DOT graph", write_dot, g, diags);
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
    struct ssg_graph_info info = {0};
    if (!found)
        ssg_graph_inspect(g, &info);
    for (int i = 0; found == 0 && i < info.node_count; i++) {
        struct ssg_node_info n;
        ssg_graph_node_inspect(g, i, &n);
        if (n.type && !strcmp(n.type, "write")) {
            snprintf(name, len, "%s", n.name);
            found = 1;
        }
    }
    ssg_graph_destroy(&g);
    return found;
}

/* The parameter `key` (len bytes) of node type `type` is a string. */
static int is_string_param(const char *type, const char *key, size_t len)
{
    char param[128];
    if (!type || len >= sizeof param)
        return 0;
    snprintf(param, sizeof param, "%.*s", (int)len, key);
    const char *kind = ssg_node_param_type(type, param);
    return kind && !strcmp(kind, "string");
}

/* The node type a --set entry names: `node`'s own, or the graph's instance before the dot
   (*key then starts after it). */
static const char *set_target(const struct ssg_graph *g, const char *node, const char **key)
{
    if (node)
        return node;
    const char *dot = strchr(*key, '.');
    char name[128];
    if (!dot || (size_t)(dot - *key) >= sizeof name)
        return NULL;
    snprintf(name, sizeof name, "%.*s", (int)(dot - *key), *key);
    struct ssg_node_info n;
    if (ssg_graph_node_inspect(g, ssg_graph_node_index(g, name), &n))
        return NULL;
    *key = dot + 1;
    return n.type;
}

/* A --sweep of a string parameter with bare values: "w.name=a,b" -> "w.name=\"a\",\"b\""
   (bench splits at the commas and sets each value as written). */
static int quote_sweep(struct ssg_cli_args *a, const struct ssg_graph *g, int k)
{
    const char *key = a->sweeps[k], *eq = strchr(key, '=');
    const char *desc = eq ? set_target(g, NULL, &key) : NULL;
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
    const char *node = NULL; /* `node`'s type (unknown: no parameter is a string) */
    if (command == SSG_CLI_NODE)
        node = a->files[0];
    else if (a->ov.set_count || a->sweep_count)
        g = build(a->files[0], &quiet, &e);
    int rc = 0;
    for (int i = 0; i < a->ov.set_count && (g || node) && !rc; i++) {
        const char *key = a->sets[i], *eq = strchr(key, '=');
        const char *desc = eq ? set_target(g, node, &key) : NULL;
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
    struct ssg_graph_info info;
    ssg_graph_inspect(g, &info);
    const struct ssg_frame *fr = &info.frame;
    fprintf(f, "graph %s: %dx%d, guard %d, seed %llu, fov %.6g, near %.6g, far %.6g, scene %s",
            info.path, fr->width, fr->height, fr->guard, (unsigned long long)fr->seed,
            fr->fov_y, fr->near_z, fr->far_z, info.scene[0] ? info.scene : "(none)");
    if (info.lights[0])
        fprintf(f, ", lights %s", info.lights);
    fputc('\n', f);
    ssg_cli_print_node_params(g, f);
}

void ssg_cli_print_node_params(const struct ssg_graph *g, FILE *f)
{
    struct ssg_graph_info info;
    ssg_graph_inspect(g, &info);
    for (int p = 0; p < info.run_count; p++) {
        int index = ssg_graph_run_node(g, p);
        struct ssg_node_info n;
        ssg_graph_node_inspect(g, index, &n);
        fprintf(f, "  %-16s %-12s %-4s", n.name, n.type, n.backend);
        for (int k = 0; k < n.param_count; k++) {
            char value[256];
            const char *name = ssg_graph_node_param(g, index, k, value, sizeof value);
            fprintf(f, " %s=%s", name, value);
        }
        fputc('\n', f);
    }
}
