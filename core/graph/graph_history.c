/* graph_history.c - the previous frame's images for prev(node.port) inputs
 * (graph_history.h): one slot per port read that way, double-buffered by handing the
 * port's last image over to the slot when its node writes the next one. */
#include <stdlib.h>
#include <string.h>

#include "graph/gl_backend.h"
#include "graph/graph_history.h"
#include "graph/image.h"

struct slot {
    int node, port;          /* the port read through prev() */
    struct ssg_image *hist;  /* the frame before, once the node has written this frame's;
                                NULL = none */
    struct ssg_image *zero;  /* all zero, of the port's shape: what a reader gets when
                                there is no previous frame; NULL = not made yet */
    int current_valid;       /* 1 = the node's out_img was written since the last reset */
    long written;            /* the frame (ssg_history.frame) in which the node last began
                                writing the port */
};

struct ssg_history {
    struct slot *slots;
    int count;
    long frame;              /* frames begun, the current one included */
    int cut;                 /* 1 = a cut is pending: the next frame has no history */
};

static struct slot *find_slot(const struct ssg_history *h, int node, int port)
{
    for (int i = 0; h && i < h->count; i++)
        if (h->slots[i].node == node && h->slots[i].port == port)
            return &h->slots[i];
    return NULL;
}

/* Visits the connections of node n that are written prev(node.port). */
#define FOR_EACH_PREV(n, conn)                                                              \
    for (int k_ = 0; k_ < ssg_gnode_conn_count(n); k_++)                                    \
        for (const struct gconn *conn = ssg_gnode_conn(n, k_); conn; conn = NULL)           \
            if (conn->node >= 0 && conn->value.prev)

/* One slot per distinct port that a live node reads through prev(); 0 on out of memory. */
static int make_slots(struct ssg_graph *g)
{
    int most = 0;
    for (int p = 0; p < g->order_count; p++)
        FOR_EACH_PREV(&g->nodes[g->order[p]], conn) most++;
    if (!most)
        return 1;
    struct ssg_history *h = calloc(1, sizeof *h);
    if (!h || !(h->slots = calloc((size_t)most, sizeof *h->slots))) {
        free(h);
        return 0;
    }
    for (int p = 0; p < g->order_count; p++)
        FOR_EACH_PREV(&g->nodes[g->order[p]], conn) if (!find_slot(h, conn->node, conn->port))
            h->slots[h->count++] = (struct slot){.node = conn->node, .port = conn->port};
    g->history = h;
    return 1;
}

/* The slot's port has no previous frame from now on. */
static void forget(struct slot *s, struct ssg_pool *pool)
{
    ssg_pool_release(pool, s->hist);
    s->hist = NULL;
    s->current_valid = 0;
}

static int same_shape(const struct ssg_image *im, const struct ssg_shape *s)
{
    return im->width == s->width && im->height == s->height && im->channels == s->channels;
}

enum ssg_err ssg_history_begin(struct ssg_graph *g, struct ssg_pool *pool)
{
    if (!g->history && !make_slots(g))
        return SSG_E_NOMEM;
    struct ssg_history *h = g->history;
    if (!h || !g->live)
        return SSG_OK; /* a run that is not kept starts with empty slots */
    for (int p = 0; p < g->order_count; p++) {
        struct gnode *n = &g->nodes[g->order[p]];
        for (int i = 0; i < h->count; i++) {
            struct slot *s = &h->slots[i];
            if (s->node != g->order[p])
                continue;
            const struct ssg_shape *shape = &n->out_shape[s->port];
            if (!g->live->kept[p] || (s->hist && !same_shape(s->hist, shape)))
                forget(s, pool);
            if (s->zero && !same_shape(s->zero, shape)) {
                ssg_pool_release(pool, s->zero);
                s->zero = NULL;
            }
        }
    }
    return SSG_OK; /* its readers run in every frame (graph_redo.c) */
}

int ssg_history_reads_prev(const struct gnode *n)
{
    FOR_EACH_PREV(n, conn) return 1;
    return 0;
}

void ssg_history_forget_node(struct ssg_graph *g, struct ssg_pool *pool, int node)
{
    for (int i = 0; g->history && i < g->history->count; i++)
        if (g->history->slots[i].node == node)
            forget(&g->history->slots[i], pool);
}

void ssg_history_frame(struct ssg_graph *g, struct ssg_pool *pool)
{
    struct ssg_history *h = g->history;
    if (!h)
        return;
    h->frame++;
    for (int i = 0; h->cut && i < h->count; i++)
        forget(&h->slots[i], pool);
    h->cut = 0;
}

int ssg_history_keep(struct ssg_graph *g, struct ssg_pool *pool, struct gnode *n, int port)
{
    struct slot *s = find_slot(g->history, (int)(n - g->nodes), port);
    if (!s)
        return 0;
    ssg_pool_release(pool, s->hist);
    s->hist = s->current_valid ? n->out_img[port] : NULL;
    if (!s->current_valid)
        ssg_pool_release(pool, n->out_img[port]);
    n->out_img[port] = NULL;
    s->current_valid = 1;
    s->written = g->history->frame;
    return 1;
}

/* The image of the slot's port in the previous frame: its history once its node has
   begun this frame, else its node's current image; NULL when there is none. */
static const struct ssg_image *previous(const struct ssg_graph *g, const struct slot *s)
{
    const struct gnode *p = &g->nodes[s->node];
    const struct ssg_image *im = s->written == g->history->frame ? s->hist
                                 : s->current_valid               ? p->out_img[s->port]
                                                                  : NULL;
    return im && same_shape(im, &p->out_shape[s->port]) ? im : NULL;
}

/* The slot's zero image, made on first use; NULL when out of memory. */
static const struct ssg_image *zero_image(const struct ssg_graph *g, struct ssg_pool *pool,
                                          struct slot *s)
{
    if (s->zero)
        return s->zero;
    const struct ssg_shape *shape = &g->nodes[s->node].out_shape[s->port];
    s->zero = ssg_pool_acquire(pool, shape->width, shape->height, shape->channels);
    if (!s->zero)
        return NULL;
    memset(s->zero->data, 0, (size_t)shape->width * (size_t)shape->height *
                                 (size_t)shape->channels * sizeof *s->zero->data);
    ssg_gl_mark_written(s->zero, 0); /* the CPU copy is current: GL uploads it if read */
    return s->zero;
}

enum ssg_err ssg_history_bind(struct ssg_graph *g, struct ssg_pool *pool, const struct gnode *n,
                              const struct ssg_image **in, const struct ssg_image **extra,
                              int *reset)
{
    *reset = -1;
    FOR_EACH_PREV(n, conn) {
        struct slot *s = find_slot(g->history, conn->node, conn->port);
        const struct ssg_image *im = s ? previous(g, s) : NULL;
        if (*reset < 0)
            *reset = 0;
        if (!im) {
            *reset = 1;
            if (!s || !(im = zero_image(g, pool, s)))
                return SSG_E_NOMEM;
        }
        if (k_ < SSG_MAX_PORTS)
            in[k_] = im;
        else
            extra[k_ - SSG_MAX_PORTS] = im;
    }
    return SSG_OK;
}

void ssg_history_cut(struct ssg_graph *g)
{
    if (g->history)
        g->history->cut = 1;
}

void ssg_history_free(struct ssg_graph *g, struct ssg_pool *pool)
{
    struct ssg_history *h = g->history;
    if (!h)
        return;
    for (int i = 0; i < h->count; i++) {
        ssg_pool_release(pool, h->slots[i].hist);
        ssg_pool_release(pool, h->slots[i].zero);
    }
    free(h->slots);
    free(h);
    g->history = NULL;
}
