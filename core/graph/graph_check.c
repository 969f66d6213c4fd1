/* graph_check.c - whole-graph validation before anything runs (graph.h): references,
 * required inputs and parameters, reachability from a sink, cycles, port types and image
 * shapes; then the run order and each output's last reader, so the executor can give an
 * image back to the pool as soon as nothing else reads it. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graph/graph.h"
#include "graph/image.h"

struct checker {
    struct ssg_graph *g;
    struct ssg_diags *diags;
    enum ssg_err first;
    unsigned char *inferred; /* per node: shapes known; NULL = every producer's are (a
                                prev() input then takes them as they stand) */
};

static void fail(struct checker *c, enum ssg_err e)
{
    if (!c->first)
        c->first = e;
}

static void output_names(const struct ssg_node_desc *d, char *buf, size_t len)
{
    size_t n = 0;
    buf[0] = 0;
    for (int i = 0; i < d->output_count && n < len; i++)
        n += (size_t)snprintf(buf + n, len - n, "%s%s", i ? ", " : "", d->outputs[i].name);
    if (!d->output_count)
        snprintf(buf, len, "none: it is a sink");
}

static void resolve(struct checker *c, struct gconn *conn)
{
    if (!conn->ref)
        return;
    const struct ssg_value *v = &conn->value;
    int producer = ssg_graph_find(c->g, v->text, v->len);
    if (producer < 0) {
        ssg_diag_at(c->diags, SSG_E_UNKNOWN_NAME, v->loc, "no node named '%.*s' (in '%s')",
                    (int)v->len, v->text, conn->ref);
        fail(c, SSG_E_UNKNOWN_NAME);
        return;
    }
    const struct ssg_node_desc *d = c->g->nodes[producer].desc;
    int port = ssg_port_find(d->outputs, d->output_count, v->member, v->member_len);
    if (port < 0) {
        char names[256];
        output_names(d, names, sizeof names);
        ssg_diag_at(c->diags, SSG_E_UNKNOWN_PORT, v->member_loc, "node '%.*s' (%s) has no "
                    "output '%.*s' (expected one of: %s)", (int)v->len, v->text, d->name,
                    (int)v->member_len, v->member, names);
        fail(c, SSG_E_UNKNOWN_PORT);
        return;
    }
    conn->node = producer;
    conn->port = port;
}

static void check_required(struct checker *c, struct gnode *n)
{
    const struct ssg_node_desc *d = n->desc;
    for (int i = 0; i < d->input_count; i++) {
        if (d->inputs[i].optional || n->in[i].ref)
            continue;
        char types[64];
        ssg_type_names(d->inputs[i].types, types, sizeof types);
        ssg_diag_at(c->diags, SSG_E_MISSING_INPUT, n->loc, "node '%s' (%s) needs input '%s' "
                    "(%s), which is not connected (expected %s=node.port)", n->name, d->name,
                    d->inputs[i].name, types, d->inputs[i].name);
        fail(c, SSG_E_MISSING_INPUT);
    }
    for (int i = 0; i < d->params.count; i++) {
        if (!d->params.params[i].required || (i < (int)sizeof n->param_set && n->param_set[i]))
            continue;
        ssg_diag_at(c->diags, SSG_E_MISSING_INPUT, n->loc, "node '%s' (%s) needs parameter "
                    "'%s' (%s)", n->name, d->name, d->params.params[i].name,
                    d->params.params[i].help);
        fail(c, SSG_E_MISSING_INPUT);
    }
}

/* Calls fn for every connected input (ports, then extras) of node n. */
#define FOR_EACH_INPUT(n, conn)                                                             \
    for (int k_ = 0; k_ < SSG_MAX_PORTS + (n)->extra_count; k_++)                           \
        for (struct gconn *conn = k_ < SSG_MAX_PORTS ? &(n)->in[k_]                         \
                                                     : &(n)->extra[k_ - SSG_MAX_PORTS];     \
             conn; conn = NULL)                                                             \
            if (conn->node >= 0)
/* The same, without prev() inputs: the edges that order a frame. A prev() edge reads the
   frame before, so it neither orders the graph nor makes a cycle (graph_history.h). */
#define FOR_EACH_SAME_FRAME_INPUT(n, conn) FOR_EACH_INPUT(n, conn) if (!conn->value.prev)

/* Marks node i and everything it reads as live, with an explicit stack: a chain of a
   hundred thousand nodes must not recurse that deep. */
static int mark_live(struct ssg_graph *g, int i)
{
    size_t cap = 64, top = 0;
    int *stack = malloc(cap * sizeof *stack);
    if (!stack)
        return 0;
    stack[top++] = i;
    while (top) {
        struct gnode *n = &g->nodes[stack[--top]];
        if (n->live)
            continue;
        n->live = 1;
        FOR_EACH_INPUT(n, conn) {
            if (g->nodes[conn->node].live)
                continue;
            if (top == cap) {
                int *grown = realloc(stack, 2 * cap * sizeof *stack);
                if (!grown) {
                    free(stack);
                    return 0;
                }
                stack = grown;
                cap *= 2;
            }
            stack[top++] = conn->node;
        }
    }
    free(stack);
    return 1;
}

/* Follows inputs among unordered nodes from `start` until one repeats: that is a cycle. */
static void report_cycle(struct checker *c, const int *unordered, int start)
{
    struct ssg_graph *g = c->g;
    int *seen = calloc((size_t)g->count, sizeof *seen);
    int path[64], len = 0, at = start;
    if (!seen)
        return;
    while (!seen[at] && len < 64) {
        seen[at] = len + 1;
        path[len++] = at;
        int nxt = -1;
        FOR_EACH_SAME_FRAME_INPUT(&g->nodes[at], conn)
        if (nxt < 0 && unordered[conn->node]) nxt = conn->node;
        if (nxt < 0)
            break;
        at = nxt;
    }
    char text[512];
    size_t n = 0;
    int from = seen[at] ? seen[at] - 1 : 0;
    for (int i = len - 1; i >= from && n < sizeof text; i--)
        n += (size_t)snprintf(text + n, sizeof text - n, "%s -> ", g->nodes[path[i]].name);
    if (n < sizeof text)
        snprintf(text + n, sizeof text - n, "%s", g->nodes[path[len - 1]].name);
    ssg_diag_at(c->diags, SSG_E_CYCLE, g->nodes[at].loc, "the graph has a cycle: %s (expected "
                "every node to depend only on nodes that do not depend on it; prev(node.port) reads "
                "the previous frame's image and makes no cycle)", text);
    fail(c, SSG_E_CYCLE);
    free(seen);
}

/* A binary min-heap of node indices: the ready nodes, earliest-defined first. */
struct heap {
    int *v;
    int n;
};

static void heap_push(struct heap *h, int x)
{
    int i = h->n++;
    for (; i > 0 && h->v[(i - 1) / 2] > x; i = (i - 1) / 2)
        h->v[i] = h->v[(i - 1) / 2];
    h->v[i] = x;
}

static int heap_pop(struct heap *h)
{
    int top = h->v[0], last = h->v[--h->n], i = 0;
    for (;;) {
        int c = 2 * i + 1;
        if (c >= h->n)
            break;
        if (c + 1 < h->n && h->v[c + 1] < h->v[c])
            c++;
        if (h->v[c] >= last)
            break;
        h->v[i] = h->v[c];
        i = c;
    }
    if (h->n)
        h->v[i] = last;
    return top;
}

/* The consumers of every node, as one array (CSR): the readers of node p are
   reader[first[p]] .. reader[first[p + 1] - 1], one entry per connection. */
struct readers {
    int *first, *reader;
};

static int readers_build(const struct ssg_graph *g, struct readers *r)
{
    r->first = calloc((size_t)g->count + 1, sizeof *r->first);
    size_t edges = 0;
    for (int i = 0; r->first && i < g->count; i++)
        FOR_EACH_SAME_FRAME_INPUT(&g->nodes[i], conn) r->first[conn->node + 1]++, edges++;
    r->reader = malloc((edges ? edges : 1) * sizeof *r->reader);
    int *fill = calloc((size_t)g->count + 1, sizeof *fill);
    if (!r->first || !r->reader || !fill) {
        free(fill);
        return 0;
    }
    for (int p = 0; p < g->count; p++)
        r->first[p + 1] += r->first[p];
    for (int i = 0; i < g->count; i++)
        FOR_EACH_SAME_FRAME_INPUT(&g->nodes[i], conn)
        r->reader[r->first[conn->node] + fill[conn->node]++] = i;
    free(fill);
    return 1;
}

/* Kahn's algorithm over live nodes, taking the earliest-defined ready node first so the
 * run order is stable and follows the file where it can; O(E log V) with the heap. */
static void order_nodes(struct checker *c)
{
    struct ssg_graph *g = c->g;
    int *waiting = calloc((size_t)g->count + 1, sizeof *waiting); /* unfinished inputs */
    struct heap ready = {malloc(((size_t)g->count + 1) * sizeof(int)), 0};
    struct readers r = {0};
    if (!g->order) /* the node count never changes: a live graph's re-checks reuse it */
        g->order = ssg_arena_alloc(&g->arena, (size_t)(g->count ? g->count : 1) *
                                                  sizeof *g->order);
    if (!waiting || !ready.v || !g->order || !readers_build(g, &r)) {
        fail(c, SSG_E_NOMEM);
        goto done;
    }
    for (int i = 0; i < g->count; i++) {
        FOR_EACH_SAME_FRAME_INPUT(&g->nodes[i], conn) waiting[i]++;
        if (g->nodes[i].live && !waiting[i])
            heap_push(&ready, i);
    }
    g->order_count = 0;
    while (ready.n) {
        int i = heap_pop(&ready);
        g->order[g->order_count++] = i;
        for (int k = r.first[i]; k < r.first[i + 1]; k++)
            if (--waiting[r.reader[k]] == 0 && g->nodes[r.reader[k]].live)
                heap_push(&ready, r.reader[k]);
    }
    for (int i = 0; i < g->count; i++)
        waiting[i] = g->nodes[i].live && waiting[i] > 0; /* now: 1 = stuck on a cycle */
    for (int i = 0; i < g->count; i++) {
        if (waiting[i]) {
            report_cycle(c, waiting, i);
            break;
        }
    }
done:
    free(waiting);
    free(ready.v);
    free(r.first);
    free(r.reader);
}

/* 1 when conn is a prev() input whose producer's shapes are not known yet (its own
   output, a later node's, in the first of two passes): it counts as unconnected then. */
static int prev_pending(const struct checker *c, const struct gconn *conn)
{
    return conn->node >= 0 && conn->value.prev && c->inferred && !c->inferred[conn->node];
}

static int check_type(struct checker *c, const struct gnode *n, const char *port,
                      unsigned accepted, const struct gconn *conn, struct ssg_shape *shape)
{
    *shape = c->g->nodes[conn->node].out_shape[conn->port];
    if (shape->type & accepted)
        return 1;
    /* No type: the producer's own check failed and was reported; a second message here
       (and one for every node after it) would only bury the first. */
    if (shape->type == 0)
        return 0;
    char want[64], got[64];
    ssg_type_names(accepted, want, sizeof want);
    ssg_type_names(shape->type, got, sizeof got);
    ssg_diag_at(c->diags, SSG_E_TYPE, conn->value.loc, "input '%s' of node '%s' (%s) expects "
                "%s, but '%s' is %s", port, n->name, n->desc->name, want, conn->ref, got);
    fail(c, SSG_E_TYPE);
    return 0;
}

/* An extra input of a node that wants them all at its first input's size (write's
   layers in one EXR part): refused here, before anything runs. */
static int check_extra_size(struct checker *c, const struct gnode *n, int i,
                            const struct ssg_shape *s)
{
    const struct ssg_shape *main = &n->in_shape[0];
    if (!n->desc->extra_same_size || n->in[0].node < 0 ||
        (s->width == main->width && s->height == main->height))
        return 1;
    ssg_diag_at(c->diags, SSG_E_SIZE, n->extra[i].value.loc, "input '%s' of node '%s' (%s) "
                "is %dx%d, but its first input '%s' is %dx%d (expected every input at the "
                "same size; upsample or downsample it first)", n->extra_names[i], n->name,
                n->desc->name, s->width, s->height, n->in[0].ref, main->width, main->height);
    fail(c, SSG_E_SIZE);
    return 0;
}

static void infer_node(struct checker *c, struct gnode *n)
{
    const struct ssg_node_desc *d = n->desc;
    int ok = 1, pending = 0;
    for (int i = 0; i < d->input_count; i++)
        if (prev_pending(c, &n->in[i]))
            n->in_shape[i] = (struct ssg_shape){0}, pending = 1;
        else if (n->in[i].node >= 0)
            ok &= check_type(c, n, d->inputs[i].name, d->inputs[i].types, &n->in[i],
                             &n->in_shape[i]);
    for (int i = 0; i < n->extra_count; i++) {
        struct ssg_shape s;
        if (prev_pending(c, &n->extra[i]))
            continue;
        if (n->extra[i].node >= 0 && check_type(c, n, n->extra_names[i], SSG_T_IMAGE,
                                                &n->extra[i], &s) &&
            check_extra_size(c, n, i, &s))
            n->extra_types[i] = s.type;
        else
            ok = 0;
    }
    if (!ok) {
        memset(n->out_shape, 0, sizeof n->out_shape); /* its readers stay quiet */
        return;
    }
    char why[400];
    enum ssg_err e = ssg_shapes_infer(d, n->params, &c->g->frame, n->in_shape, n->out_shape,
                                      why, sizeof why);
    if (!e && d->check_scene && c->g->scene) {
        why[0] = '\0';
        e = d->check_scene(n->params, c->g->scene, n->in_shape, n->out_shape, why,
                           sizeof why);
        if (!e && why[0] && !pending) /* a warning (node.h) */
            ssg_diag_warn(c->diags, SSG_E_SCENE, n->loc, "node '%s' (%s): %s", n->name,
                          d->name, why);
    }
    if (e && pending) /* the quiet first pass: a check that needs the prev() input's shape
                         (history = prev(out) of out's size) cannot pass yet; the default
                         shapes (same_as, frame size) stand in until the second pass */
        return;
    if (e) {
        ssg_diag_at(c->diags, e, n->loc, "node '%s' (%s): %s", n->name, d->name, why);
        fail(c, e);
        memset(n->out_shape, 0, sizeof n->out_shape); /* its readers stay quiet */
    }
}

static int has_prev(const struct ssg_graph *g)
{
    for (int p = 0; p < g->order_count; p++)
        FOR_EACH_INPUT(&g->nodes[g->order[p]], conn) if (conn->value.prev) return 1;
    return 0;
}

/* prev(x) has x's shape: a prev() input that came out otherwise (its node's output feeds
   back into its own shape) is refused where it is written. */
static void check_prev_shapes(struct checker *c)
{
    for (int p = 0; p < c->g->order_count; p++) {
        const struct gnode *n = &c->g->nodes[c->g->order[p]];
        for (int i = 0; i < n->desc->input_count; i++) {
            const struct gconn *conn = &n->in[i];
            if (conn->node < 0 || !conn->value.prev)
                continue;
            const struct ssg_shape *a = &n->in_shape[i];
            const struct ssg_shape *b = &c->g->nodes[conn->node].out_shape[conn->port];
            if (b->type == 0 && !c->first) { /* its check failed only in the quiet pass */
                ssg_diag_at(c->diags, SSG_E_SIZE, conn->value.loc, "input '%s' of node '%s' "
                            "(%s) reads %s, whose shape cannot be found without it "
                            "(expected a node whose output shape does not come from its own "
                            "prev() input)", n->desc->inputs[i].name, n->name, n->desc->name,
                            conn->ref);
                fail(c, SSG_E_SIZE);
                continue;
            }
            if (b->type == 0 || (a->width == b->width && a->height == b->height &&
                                 a->channels == b->channels && a->type == b->type))
                continue;
            ssg_diag_at(c->diags, SSG_E_SIZE, conn->value.loc, "input '%s' of node '%s' "
                        "(%s) reads %s as %dx%dx%d, but the port is %dx%dx%d (expected a "
                        "shape that does not depend on its own history)",
                        n->desc->inputs[i].name, n->name, n->desc->name, conn->ref,
                        a->width, a->height, a->channels, b->width, b->height, b->channels);
            fail(c, SSG_E_SIZE);
        }
    }
}

/* Every live node's shapes, in run order. A prev() input read before its producer runs
   (the node's own output, a later node's) needs shapes not known yet: a first, quiet
   pass takes such inputs as unconnected to find them, the second reads them and reports.
   Without prev() inputs: the one pass there always was. */
static void infer_all(struct checker *c)
{
    struct ssg_graph *g = c->g;
    if (has_prev(g)) {
        struct ssg_diags *quiet = calloc(1, sizeof *quiet);
        struct checker first = {g, quiet, SSG_OK, calloc((size_t)g->count + 1, 1)};
        for (int p = 0; quiet && first.inferred && p < g->order_count; p++) {
            infer_node(&first, &g->nodes[g->order[p]]);
            first.inferred[g->order[p]] = 1;
        }
        if (!quiet || !first.inferred)
            fail(c, SSG_E_NOMEM);
        free(first.inferred);
        free(quiet);
    }
    for (int p = 0; p < g->order_count; p++)
        infer_node(c, &g->nodes[g->order[p]]);
    check_prev_shapes(c);
}

static void last_readers(struct ssg_graph *g)
{
    for (int p = 0; p < g->order_count; p++)
        for (int k = 0; k < SSG_MAX_PORTS; k++)
            g->nodes[g->order[p]].last_reader[k] = -1;
    for (int p = 0; p < g->order_count; p++) {
        struct gnode *n = &g->nodes[g->order[p]];
        FOR_EACH_INPUT(n, conn) g->nodes[conn->node].last_reader[conn->port] = p;
    }
    /* A port read through prev() is kept past the frame: it becomes the next one's
       history (graph_history.c). */
    for (int p = 0; p < g->order_count; p++) {
        struct gnode *n = &g->nodes[g->order[p]];
        FOR_EACH_INPUT(n, conn) if (conn->value.prev)
            g->nodes[conn->node].last_reader[conn->port] = g->order_count;
    }
    /* A requested output is read after the last position: kept until the run hands it
       out. */
    for (int k = 0; k < g->wanted_count; k++)
        g->nodes[g->wanted[k].node].last_reader[g->wanted[k].port] = g->order_count;
}

/* Where each node runs: --backend for all, else the node's backend=, else the graph's
 * `backend`; GL falls back to the CPU for a node without a GL side unless the node itself
 * asked for GL. */
static void resolve_backend(struct checker *c, struct gnode *n)
{
    enum ssg_backend want = c->g->forced ? c->g->forced
                            : n->backend ? n->backend
                            : c->g->backend ? c->g->backend
                                            : SSG_BACKEND_CPU;
    if (want == SSG_BACKEND_GL && !n->desc->run_gl && !c->g->forced && n->backend) {
        ssg_diag_at(c->diags, SSG_E_BACKEND, n->backend_loc, "node '%s' (%s) has no GL "
                    "implementation (expected backend=cpu; reference, compare and write nodes "
                    "run on the CPU)", n->name, n->desc->name);
        fail(c, SSG_E_BACKEND);
    }
    n->runs_on = want == SSG_BACKEND_GL && n->desc->run_gl ? SSG_BACKEND_GL : SSG_BACKEND_CPU;
}

/* Live nodes that would write the same file (output_files): every file they name,
   sorted by name, then by position in the file, so each clash is reported once, at its
   later node. */
struct written {
    char file[SSG_FILE_NAME_MAX];
    int node;
};

static int by_file(const void *a, const void *b)
{
    const struct written *wa = a, *wb = b;
    int s = strcmp(wa->file, wb->file);
    return s ? s : wa->node - wb->node;
}

enum { FILES_PER_NODE = 4 };

static void check_output_clash(struct checker *c)
{
    struct ssg_graph *g = c->g;
    int writers = 0;
    for (int i = 0; i < g->count; i++)
        writers += g->nodes[i].live && g->nodes[i].desc->output_files;
    struct written *w = malloc(((size_t)writers * FILES_PER_NODE + 1) * sizeof *w);
    int n = 0;
    if (!w) {
        fail(c, SSG_E_NOMEM);
        return;
    }
    for (int i = 0; i < g->count; i++) {
        const struct gnode *node = &g->nodes[i];
        if (!node->live || !node->desc->output_files)
            continue;
        char files[FILES_PER_NODE][SSG_FILE_NAME_MAX];
        int k = node->desc->output_files(node->params, 0, files, FILES_PER_NODE);
        for (int f = 0; f < k; f++) {
            memcpy(w[n].file, files[f], sizeof w[n].file);
            w[n++].node = i;
        }
    }
    qsort(w, (size_t)n, sizeof *w, by_file);
    for (int k = 1; k < n; k++) {
        if (strcmp(w[k - 1].file, w[k].file) || w[k - 1].node == w[k].node)
            continue;
        const struct gnode *first = &g->nodes[w[k - 1].node], *again = &g->nodes[w[k].node];
        int line, col;
        ssg_loc_linecol(first->loc, &line, &col);
        ssg_diag_at(c->diags, SSG_E_DUPLICATE, again->loc, "node '%s' (%s) writes '%s', as "
                    "node '%s' at %s:%d:%d does: its file would replace the other's "
                    "(expected a different name)", again->name, again->desc->name, w[k].file,
                    first->name, first->loc.src ? first->loc.src->path : "?", line, col);
        fail(c, SSG_E_DUPLICATE);
    }
    free(w);
}

enum ssg_err ssg_graph_reinfer(struct ssg_graph *g, struct ssg_diags *diags)
{
    struct checker c = {g, diags, SSG_OK, NULL};
    infer_all(&c);
    return c.first;
}

enum ssg_err ssg_graph_validate(struct ssg_graph *g, struct ssg_diags *diags)
{
    struct checker c = {g, diags, SSG_OK, NULL};
    int sinks = 0;
    for (int i = 0; i < g->count; i++) {
        struct gnode *n = &g->nodes[i];
        for (int k = 0; k < SSG_MAX_PORTS; k++)
            resolve(&c, &n->in[k]);
        for (int k = 0; k < n->extra_count; k++)
            resolve(&c, &n->extra[k]);
        check_required(&c, n);
        resolve_backend(&c, n);
    }
    /* Requested outputs replace the sinks: only what they need is live; unless the caller
       kept the sinks (ssg_overrides.keep_sinks). */
    for (int i = 0; i < g->count; i++) {
        struct gnode *n = &g->nodes[i];
        if (n->desc->is_sink && (!g->wanted_count || g->keep_sinks)) {
            sinks++;
            n->live = 0; /* mark_live walks only into nodes not yet live */
            if (!mark_live(g, i))
                fail(&c, SSG_E_NOMEM);
        }
    }
    for (int k = 0; k < g->wanted_count; k++) {
        if (g->wanted[k].value.prev) { /* the run hands out this frame's images */
            ssg_diag_at(diags, SSG_E_USAGE, g->wanted[k].value.loc, "an output cannot be "
                        "%s (expected node.port)", g->wanted[k].ref);
            fail(&c, SSG_E_USAGE);
            continue;
        }
        resolve(&c, &g->wanted[k]);
        if (g->wanted[k].node >= 0 && !mark_live(g, g->wanted[k].node))
            fail(&c, SSG_E_NOMEM);
    }
    if (!sinks && !g->wanted_count) {
        ssg_diag_file(diags, SSG_E_VALUE, g->path, "the graph writes nothing (expected at "
                      "least one write(node.port, \"name\"))");
        fail(&c, SSG_E_VALUE);
    }
    order_nodes(&c);
    check_output_clash(&c);
    if (c.first)
        return c.first;
    infer_all(&c);
    last_readers(g);
    return c.first;
}
