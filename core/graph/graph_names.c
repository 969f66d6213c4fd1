/* graph_names.c - the graph's table of node names (graph.h): open addressing over the
 * node indices, at most half full, so that building and checking a graph of n nodes
 * look names up in O(1) each and stay linear in n. */
#include <string.h>

#include "graph/graph.h"

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
