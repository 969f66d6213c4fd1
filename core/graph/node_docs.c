/* node_docs.c - docs/nodes.md: the Markdown reference of every node, printed from the
 * descriptor tables (ports, parameters, defaults, ranges, method), with a glossary of the
 * port types and, per node, the graph files that use it.
 *
 * "Used by" is read from a folder of graphs (the repository's graphs/ and its
 * sub-folders, one level deep): each file is parsed, not searched as text, so a node named
 * in a comment does not count, and a graph uses what the graphs it includes use. A file
 * that does not parse is left out: the graph tests report it. */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graph/node.h"
#include "lang/arena.h"
#include "lang/parse.h"

#define GRAPHS_MAX 256

/* The graph files under a folder: their paths and, for each, the set of node types it
   calls, its includes' calls counted (bit i: the registry's node i). */
struct graph_uses {
    int count;
    char *paths[GRAPHS_MAX];
    uint64_t calls[GRAPHS_MAX];
};

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

/* Adds the .graph files of dir (and of its sub-folders while depth > 0). */
static void collect(struct graph_uses *u, const char *dir, int depth)
{
    DIR *d = opendir(dir);
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)) && u->count < GRAPHS_MAX) {
        char path[2048];
        int n = snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (e->d_name[0] == '.' || n < 0 || n >= (int)sizeof path)
            continue;
        if (ends_with(e->d_name, ".graph"))
            u->paths[u->count++] = strdup(path);
        else if (depth > 0)
            collect(u, path, depth - 1);
    }
    closedir(d);
}

static int by_path(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The node types the graph file at path calls, and those of the files it includes (a few
   levels: an include cycle is the graph loader's error to report, not ours). */
static uint64_t graph_calls(const char *path, int depth)
{
    struct ssg_arena arena = {0};
    struct ssg_diags quiet = {0};
    struct ssg_file f = {0};
    uint64_t calls = 0;
    if (depth > 0 && ssg_parse_file(&arena, path, (struct ssg_loc){0}, &f, &quiet) == SSG_OK) {
        for (int i = 0; i < f.count; i++) {
            const struct ssg_stmt *st = &f.stmts[i];
            if (st->kind == SSG_S_CALL) {
                for (int n = 0; n < ssg_node_count() && n < 64; n++)
                    if (ssg_tok_eq(st->callee, st->callee_len, ssg_node_at(n)->name))
                        calls |= (uint64_t)1 << n;
            } else if (st->kind == SSG_S_DIRECTIVE && ssg_tok_eq(st->name, st->name_len,
                       "include") && st->arg_count == 1 &&
                       st->args[0].value.kind == SSG_V_STRING) {
                char included[4096];
                ssg_path_resolve(path, st->args[0].value.text, included, sizeof included);
                calls |= graph_calls(included, depth - 1);
            }
        }
    }
    ssg_arena_free(&arena);
    return calls;
}

static void uses_load(struct graph_uses *u, const char *dir)
{
    memset(u, 0, sizeof *u);
    if (!dir)
        return;
    collect(u, dir, 1);
    qsort(u->paths, (size_t)u->count, sizeof u->paths[0], by_path);
    for (int i = 0; i < u->count; i++)
        u->calls[i] = graph_calls(u->paths[i], 4);
}

static void uses_free(struct graph_uses *u)
{
    for (int i = 0; i < u->count; i++)
        free(u->paths[i]);
}

static void markdown_used_by(const struct graph_uses *u, int node, FILE *stream)
{
    if (!u->count)
        return;
    int n = 0;
    for (int i = 0; i < u->count; i++)
        if (node < 64 && (u->calls[i] >> node & 1))
            fprintf(stream, "%s`%s`", n++ ? ", " : "*Used by:* ", u->paths[i]);
    fprintf(stream, "%s\n\n", n ? "" : "*Used by:* no bundled graph");
}

static void markdown_glossary(FILE *stream)
{
    fprintf(stream, "## Port types\n\nEvery port carries one of these; an input that "
                    "accepts several lists them as `a|b`. Frame-sized images are as large "
                    "as the frame and its guard band, planar float (`core/ssgraph.h`).\n\n"
                    "| type | what it holds |\n|---|---|\n");
    for (int bit = 0; ssg_type_name(bit); bit++)
        fprintf(stream, "| `%s` | %s |\n", ssg_type_name(bit), ssg_type_doc(bit));
    fprintf(stream, "\n");
}

static void markdown_ports(const char *title, const struct ssg_port_desc *ports, int count,
                           FILE *stream)
{
    if (count == 0)
        return;
    fprintf(stream, "**%s**\n\n| port | type | description |\n|---|---|---|\n", title);
    for (int i = 0; i < count; i++) {
        char types[64];
        ssg_type_names(ports[i].types, types, sizeof types);
        fprintf(stream, "| `%s` | %s | %s%s |\n", ports[i].name,
                ports[i].same_as ? ports[i].same_as : types, ports[i].doc,
                ports[i].optional    ? " (optional)"
                : ports[i].on_demand ? " (computed only when read)"
                                     : "");
    }
    fprintf(stream, "\n");
}

static void markdown_node(int index, const struct graph_uses *u, FILE *stream)
{
    const struct ssg_node_desc *d = ssg_node_at(index);
    int doc_len;
    const char *doc = ssg_node_doc(d, &doc_len);
    fprintf(stream, "## %s\n\n%s\n\n%.*s\n\n*Method:* %s\n\n*Backends:* %s\n\n", d->name,
            d->summary, doc_len, doc, d->method, ssg_node_backends(d));
    markdown_used_by(u, index, stream);
    markdown_ports("Inputs", d->inputs, d->input_count, stream);
    markdown_ports("Outputs", d->outputs, d->output_count, stream);
    if (d->params.count) {
        fprintf(stream, "**Parameters**\n\n| name | type | default | accepts | "
                        "description |\n|---|---|---|---|---|\n");
        for (int p = 0; p < d->params.count; p++)
            ssg_param_markdown(&d->params.params[p], stream);
        fprintf(stream, "\n");
    }
}

void ssg_nodes_markdown(FILE *stream, const char *graphs_dir)
{
    if (!stream)
        return;
    struct graph_uses *uses = malloc(sizeof *uses);
    if (!uses)
        return;
    uses_load(uses, graphs_dir);
    fprintf(stream, "# Node reference\n\nGenerated by `ssgraph docs` (run in the repository "
                    "root, where it reads `graphs/` for the \"Used by\" lines) from the "
                    "descriptor tables in `nodes/`; do not edit by hand. A number "
                    "parameter's \"accepts\" gives the range it must lie in, then its useful "
                    "range (\"slider\"): what `ssgraph view`'s slider spans and a value "
                    "normally takes; a value outside it that is in range is still taken.\n\n");
    markdown_glossary(stream);
    for (int i = 0; i < ssg_node_count(); i++)
        markdown_node(i, uses, stream);
    uses_free(uses);
    free(uses);
}
