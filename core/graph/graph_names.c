/* graph_names.c - the graph's table of node names (graph.h): open addressing over the
 * node indices, at most half full, so that building and checking a graph of n nodes
 * look names up in O(1) each and stay linear in n; and the messages that list a node's
 * names (what a key could have been). */
#include <stdio.h>
#include <string.h>

#include "graph/graph.h"
#include "lang/diag.h"
#include "lang/params.h"

static unsigned name_hash(const char *name, size_t len)
{
    unsigned h = 2166136261u; /* FNV-1a */
    for (size_t i = 0; i < len; i++)
        h = (h ^ (unsigned char)name[i]) * 16777619u;
    return h;
}

int ssg_graph_find(const struct ssg_graph *g, const char *name, size_t len)
{
    if (!g->name_cap)
        return -1;
    unsigned mask = (unsigned)g->name_cap - 1;
    for (unsigned s = name_hash(name, len) & mask; g->name_slots[s]; s = (s + 1) & mask)
        if (ssg_tok_eq(name, len, g->nodes[g->name_slots[s] - 1].name))
            return g->name_slots[s] - 1;
    return -1;
}

static void name_insert(struct ssg_graph *g, int index)
{
    const char *name = g->nodes[index].name;
    unsigned mask = (unsigned)g->name_cap - 1;
    unsigned s = name_hash(name, strlen(name)) & mask;
    while (g->name_slots[s])
        s = (s + 1) & mask;
    g->name_slots[s] = index + 1;
}

int ssg_graph_name_add(struct ssg_graph *g, int index)
{
    if (2 * (index + 1) > g->name_cap) {
        int cap = g->name_cap ? 2 * g->name_cap : 64;
        int *slots = ssg_arena_alloc(&g->arena, (size_t)cap * sizeof *slots); /* zeroed */
        if (!slots)
            return 0;
        g->name_slots = slots;
        g->name_cap = cap;
        for (int i = 0; i < index; i++)
            name_insert(g, i);
    }
    name_insert(g, index);
    return 1;
}

/* ---- messages that list names ---- */

void ssg_node_names(char *buf, size_t len)
{
    size_t n = 0;
    buf[0] = 0;
    for (int i = 0; i < ssg_node_count() && n < len; i++)
        n += (size_t)snprintf(buf + n, len - n, "%s%s", i ? ", " : "", ssg_node_name(i));
}

/* "a, b, c" of count names (the i-th from name_at), or "(none)". */
static void join_names(const struct gnode *n, int count,
                       const char *(*name_at)(const struct gnode *, int), char *buf, size_t len)
{
    size_t k = 0;
    snprintf(buf, len, "(none)");
    for (int i = 0; i < count && k < len; i++)
        k += (size_t)snprintf(buf + k, len - k, "%s%s", i ? ", " : "", name_at(n, i));
}

static const char *input_name(const struct gnode *n, int i)
{
    return n->desc->inputs[i].name;
}

static const char *extra_name(const struct gnode *n, int i)
{
    return n->extra_names[i];
}

enum ssg_err ssg_graph_unknown_key(struct ssg_diags *diags, const struct gnode *n,
                                   const char *key, size_t len, struct ssg_loc loc)
{
    char params[512], ports[256];
    ssg_param_names(n->desc->params, params, sizeof params);
    join_names(n, n->desc->input_count, input_name, ports, sizeof ports);
    ssg_diag_at(diags, SSG_E_UNKNOWN_PARAM, loc, "unknown parameter or input '%.*s' for node "
                "'%s' (%s) (expected an input: %s; or a parameter: %s)", (int)len, key,
                n->name, n->desc->name, ports, params);
    return SSG_E_UNKNOWN_PARAM;
}

/* `set out.in = x` on a write node (whose first input is `image`) used to add a layer
   named `in` silently. */
enum ssg_err ssg_graph_set_adds(struct ssg_diags *diags, const struct gnode *n,
                                const char *key, size_t len, struct ssg_loc loc)
{
    char ports[256], layers[512];
    join_names(n, n->desc->input_count, input_name, ports, sizeof ports);
    join_names(n, n->extra_count, extra_name, layers, sizeof layers);
    ssg_diag_at(diags, SSG_E_UNKNOWN_PARAM, loc, "'set' cannot add input '%.*s' to node '%s' "
                "(%s): set changes what the node's call defines (expected an input: %s; or "
                "one of its named inputs: %s); a new one goes into the call, or an 'add "
                "%s.%.*s = node.port' line", (int)len, key, n->name, n->desc->name, ports,
                layers, n->name, (int)len, key);
    return SSG_E_UNKNOWN_PARAM;
}
