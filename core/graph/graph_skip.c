/* graph_skip.c - skipping the passes of a frame whose work nothing uses (graph_skip.h).
 *
 * Before each node it would run, the executor asks ssg_skip_decide. Two passes over the
 * rest of the frame's order answer it:
 *   forward, which outputs will be all +0: known for the nodes before p (as they ran or
 *     were skipped, or from the frame they last ran in when kept), and for p and after
 *     predicted from the descriptors: an output is zero with its zero_with input, and
 *     zero_outputs looks at the inputs already made (a node after p sees only those);
 *   backward, which outputs will be used: a sink uses all it reads, as does a prev()
 *     reader, and a requested output is used; a node runs when one of its outputs is used
 *     and not zero, and then uses every input but those ignored_inputs names for the
 *     zero ones and those that only feed outputs nobody uses or that are zero anyway.
 * Each prediction is an exact claim of the descriptors, or a "not known" that keeps a
 * node running, so a skipped node's used outputs are the +0 its run would have made. The
 * answer is the same for any thread count; a zero_outputs answer needs its inputs on the
 * CPU, so where they were made on GL it is "not known" and nothing is skipped for it. */
#include <stdlib.h>

#include "graph/gl_backend.h"
#include "graph/graph_skip.h"

struct ssg_skip {
    int count;         /* nodes of the graph */
    int *pos;          /* per node index: run position, -1 = not live */
    unsigned *known;   /* per node index: outputs all +0 as it last ran or was skipped */
    unsigned *zero;    /* per node index: this decision's zero outputs (known before p) */
    unsigned *used;    /* per node index: outputs whose pixels something that runs uses */
    unsigned *read;    /* per node index: outputs something that runs reads at all */
};

struct ssg_skip *ssg_skip_create(const struct ssg_graph *g)
{
    struct ssg_skip *s = calloc(1, sizeof *s);
    size_t n = (size_t)(g->count > 0 ? g->count : 1);
    if (!s || !(s->pos = malloc(n * sizeof *s->pos)) ||
        !(s->known = calloc(n, sizeof *s->known)) || !(s->zero = calloc(n, sizeof *s->zero)) ||
        !(s->used = calloc(n, sizeof *s->used)) || !(s->read = calloc(n, sizeof *s->read))) {
        ssg_skip_free(&s);
        return NULL;
    }
    s->count = g->count;
    for (int i = 0; i < g->count; i++)
        s->pos[i] = -1;
    for (int p = 0; p < g->order_count; p++)
        s->pos[g->order[p]] = p;
    return s;
}

void ssg_skip_free(struct ssg_skip **s)
{
    if (!*s)
        return;
    free((*s)->pos);
    free((*s)->known);
    free((*s)->zero);
    free((*s)->used);
    free((*s)->read);
    free(*s);
    *s = NULL;
}

static unsigned all_outputs(const struct gnode *n)
{
    return n->desc->output_count >= 32 ? ~0u : (1u << n->desc->output_count) - 1u;
}

/* 1 when the image connected by c is known to be all +0 in this decision. */
static int conn_zero(const struct ssg_skip *s, const struct gconn *c)
{
    return c->node >= 0 && !c->value.prev && (s->zero[c->node] >> c->port & 1u);
}

/* The outputs of node i (at position q >= p) predicted all +0: by zero_with, and by
   zero_outputs on the inputs made before position p. */
static unsigned predict(const struct ssg_skip *s, const struct ssg_graph *g, int i, int p)
{
    const struct gnode *n = &g->nodes[i];
    const struct ssg_node_desc *d = n->desc;
    unsigned mask = 0;
    for (int k = 0; d->zero_with && k < d->output_count; k++) {
        int src = d->zero_with[k];
        if (src >= 0 && (n->in[src].node < 0 || conn_zero(s, &n->in[src])))
            mask |= 1u << k;
    }
    if (d->zero_outputs) {
        const struct ssg_image *in[SSG_MAX_PORTS] = {0};
        unsigned connected = 0;
        for (int k = 0; k < d->input_count && k < SSG_MAX_PORTS; k++) {
            const struct gconn *c = &n->in[k];
            connected |= (unsigned)(c->node >= 0) << k;
            const struct ssg_image *im = c->node >= 0 && !c->value.prev &&
                                                 s->pos[c->node] < p
                                             ? g->nodes[c->node].out_img[c->port]
                                             : NULL;
            /* pixels only the GL copy holds are not looked at: not known (so a graph
               whose lightprobe runs on GL skips nothing; downloading every input to
               decide would cost more than it saves) */
            in[k] = im && (!im->gpu || im->gpu->cpu_valid) ? im : NULL;
        }
        mask |= d->zero_outputs(n->params, in, connected);
    }
    return mask & all_outputs(n);
}

/* The inputs of a node that runs whose pixels it uses. */
static unsigned inputs_used(const struct ssg_skip *s, const struct gnode *n, unsigned live)
{
    const struct ssg_node_desc *d = n->desc;
    unsigned used = d->input_count >= 32 ? ~0u : (1u << d->input_count) - 1u;
    if (d->ignored_inputs) {
        unsigned zero_in = 0;
        for (int k = 0; k < d->input_count; k++)
            zero_in |= (unsigned)conn_zero(s, &n->in[k]) << k;
        used &= ~d->ignored_inputs(n->params, zero_in);
    }
    /* an input that feeds only outputs nobody uses, or that come out zero, is unused */
    for (int k = 0; d->zero_with && k < d->output_count; k++)
        if (d->zero_with[k] >= 0)
            used &= ~(1u << d->zero_with[k]);
    for (int k = 0; d->zero_with && k < d->output_count; k++)
        if (d->zero_with[k] >= 0 && (live >> k & 1u))
            used |= 1u << d->zero_with[k];
    return used;
}

/* A node that runs: marks what it reads, and uses, on its producers. */
static void mark_inputs(struct ssg_skip *s, const struct gnode *n, unsigned live)
{
    unsigned used = inputs_used(s, n, live);
    for (int k = 0; k < ssg_gnode_conn_count(n); k++) {
        const struct gconn *c = ssg_gnode_conn(n, k);
        if (c->node < 0 || c->value.prev)
            continue; /* prev() readers are marked for the whole run (mark_fixed) */
        s->read[c->node] |= 1u << c->port;
        if (k >= SSG_MAX_PORTS || (used >> k & 1u)) /* extra inputs: a sink's, all used */
            s->used[c->node] |= 1u << c->port;
    }
}

/* Outputs used whatever runs: read through prev() (the next frame's history) or
   requested by the caller. */
static void mark_fixed(struct ssg_skip *s, const struct ssg_graph *g)
{
    for (int q = 0; q < g->order_count; q++) {
        const struct gnode *n = &g->nodes[g->order[q]];
        for (int k = 0; k < ssg_gnode_conn_count(n); k++) {
            const struct gconn *c = ssg_gnode_conn(n, k);
            if (c->node >= 0 && c->value.prev) {
                s->read[c->node] |= 1u << c->port;
                s->used[c->node] |= 1u << c->port;
            }
        }
    }
    for (int k = 0; k < g->wanted_count; k++) {
        s->read[g->wanted[k].node] |= 1u << g->wanted[k].port;
        s->used[g->wanted[k].node] |= 1u << g->wanted[k].port;
    }
}

int ssg_skip_decide(struct ssg_skip *s, const struct ssg_graph *g, int p, unsigned *fill)
{
    for (int q = 0; q < p; q++)
        s->zero[g->order[q]] = s->known[g->order[q]];
    for (int q = p; q < g->order_count; q++)
        s->zero[g->order[q]] = predict(s, g, g->order[q], p);
    for (int q = 0; q < g->order_count; q++)
        s->used[g->order[q]] = s->read[g->order[q]] = 0;
    mark_fixed(s, g);
    int runs = 1;
    for (int q = g->order_count - 1; q >= p; q--) {
        int i = g->order[q];
        const struct gnode *n = &g->nodes[i];
        unsigned live = s->used[i] & ~s->zero[i]; /* used outputs not known to be zero */
        runs = n->desc->is_sink || n->desc->supplied || live != 0;
        if (runs && q > p)
            mark_inputs(s, n, live);
    }
    int i = g->order[p];
    *fill = s->read[i];
    s->known[i] = runs ? s->zero[i] : all_outputs(&g->nodes[i]);
    return !runs;
}
