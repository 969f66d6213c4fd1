/* graph_redo.c - the one rule for what runs again (graph.h, docs/development.md).
 *
 * A node's outputs from before stand while nothing it depends on changed. What it depends
 * on is its producers' outputs, its parameters and shapes, and what its descriptor says it
 * reads (node.h, enum ssg_reads: the scene, its lights, the camera, the frame). Every event
 * that changes one of them calls ssg_redo or ssg_redo_reading here, with the level of work
 * the change needs (enum ssg_recompute: run < prepare < history) and the reason, which the
 * run statistics report; nothing else clears a node's state. In a run, a node then runs
 * when its outputs are not kept (the reason recorded with the event) or a producer ran in
 * this frame; else it is kept (ssg_redo_decide).
 *
 * The events, and where they come from:
 *   a parameter set        ssg_graph_set (graph_live.c): that node, at the level its
 *                          check_params asks for; every node whose shapes moved, history
 *   a new view             ssg_graph_set_view: the camera's readers, history
 *   new lights             ssg_graph_set_lights: the lights' readers, prepare
 *   a supplied image       ssg_graph_supply: that node, prepare
 *   a camera path's move   graph_run.c, each frame: the camera's readers, prepare
 *   another frame          graph_run.c, each frame: the frame's readers, run
 *   prev() readers         graph_run.c, each frame: they accumulate, run
 *   the memory limit       graph_live.c's eviction: run */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graph/graph.h"
#include "graph/graph_history.h"

static const char *const why_text[SSG_WHY_COUNT] = {
    [SSG_WHY_KEPT] = "kept",
    [SSG_WHY_FIRST] = "first run",
    [SSG_WHY_SHAPE] = "shape changed",
    [SSG_WHY_PARAM] = "parameter changed",
    [SSG_WHY_SUPPLIED] = "new image supplied",
    [SSG_WHY_LIGHTS] = "lights changed",
    [SSG_WHY_CAMERA] = "camera moved",
    [SSG_WHY_FRAME] = "new frame",
    [SSG_WHY_HISTORY] = "reads prev()",
    [SSG_WHY_EVICTED] = "evicted",
    [SSG_WHY_FAILED] = "last run failed",
    [SSG_WHY_SEQUENCE] = "not kept in a sequence",
    [SSG_WHY_INPUT] = "input ran",
    [SSG_WHY_SINK] = "sink",
    [SSG_WHY_NO_FILES] = "not run: no files",
    [SSG_WHY_SKIPPED] = "skipped: zero or unused",
};

const char *ssg_why_text(enum ssg_why why)
{
    return why >= 0 && why < SSG_WHY_COUNT ? why_text[why] : "?";
}

void ssg_redo(struct ssg_graph *g, struct ssg_live *l, int p, unsigned level, enum ssg_why why)
{
    if (!l->why[p] || why < l->why[p]) /* the first cause in enum order is the one told */
        l->why[p] = (unsigned char)why;
    l->kept[p] = 0;
    if (level >= SSG_RECOMPUTE_PREPARE) {
        free(l->consts[p]);
        l->consts[p] = NULL;
        l->prepared[p] = 0;
    }
    if (level >= SSG_RECOMPUTE_HISTORY)
        ssg_history_forget_node(g, l->pool, g->order[p]);
}

void ssg_redo_reading(struct ssg_graph *g, struct ssg_live *l, unsigned changed,
                      unsigned level, enum ssg_why why)
{
    for (int p = 0; p < g->order_count; p++)
        if (ssg_gnode_reads(g, &g->nodes[g->order[p]]) & changed)
            ssg_redo(g, l, p, level, why);
}

enum ssg_why ssg_redo_decide(const struct ssg_graph *g, const struct ssg_live *l, int p,
                             const unsigned char *ran, int *producer)
{
    const struct gnode *n = &g->nodes[g->order[p]];
    *producer = -1;
    /* A sink's files are this run's: write always runs. A sink that only reports metrics
       (compare) and was kept (a live graph's one-frame run, ssg_redo_after) runs again
       only when an input ran or it was changed; its metrics are reported again. */
    if (n->desc->is_sink && (n->desc->output_files || !l->kept[p]))
        return SSG_WHY_SINK;
    enum ssg_why why = l->kept[p] ? SSG_WHY_KEPT : l->why[p] ? l->why[p] : SSG_WHY_FIRST;
    if (why != SSG_WHY_KEPT && why != SSG_WHY_SEQUENCE)
        return why; /* its own event comes before its producers' */
    for (int k = 0; k < ssg_gnode_conn_count(n); k++) {
        const struct gconn *c = ssg_gnode_conn(n, k);
        if (c->node >= 0 && ran[c->node]) {
            *producer = c->node;
            return SSG_WHY_INPUT;
        }
    }
    return why;
}

void ssg_redo_after(struct ssg_live *l, int p, int keep, enum ssg_err e)
{
    l->kept[p] = e == SSG_OK && keep;
    l->why[p] = (unsigned char)(e ? SSG_WHY_FAILED : keep ? SSG_WHY_KEPT : SSG_WHY_SEQUENCE);
    l->made[p] = ++l->serial; /* a failed run may have left its outputs half made too */
}

unsigned long long ssg_redo_made(const struct ssg_graph *g, const struct ssg_live *l,
                                 const struct gconn *c)
{
    if (c->node < 0 || c->value.prev)
        return 0; /* prev(): the frame before's image, whatever its producer did since */
    for (int p = 0; p < g->order_count && p < l->count; p++)
        if (g->order[p] == c->node)
            return l->made[p];
    return 0;
}

/* Appends "text" or "text xN" to buf, comma-separated. */
static void add_count(char *buf, size_t len, const char *text, int count)
{
    size_t used = strlen(buf);
    if (count <= 0 || used + 1 >= len)
        return;
    snprintf(buf + used, len - used, count > 1 ? "%s%s x%d" : "%s%s", used ? ", " : "", text,
             count);
}

void ssg_why_summary(const int *counts, const char *producer, char *buf, size_t len)
{
    buf[0] = '\0';
    for (int w = 1; w < SSG_WHY_COUNT; w++) {
        char text[96];
        if (w == SSG_WHY_INPUT && producer)
            snprintf(text, sizeof text, "input %s ran", producer);
        else
            snprintf(text, sizeof text, "%s", why_text[w]);
        add_count(buf, len, text, counts[w]);
    }
    add_count(buf, len, why_text[SSG_WHY_KEPT], counts[SSG_WHY_KEPT]); /* last: not a run */
}
