/* test_camera_deps.c - the guard that keeps node.h's `reads` honest for the camera and the
 * lights.
 *
 * A node whose reads leave out SSG_READS_CAMERA keeps its outputs when a live graph's
 * camera moves (ssg_graph_set_view), as long as its producers keep theirs. A wrong declaration
 * would show a stale image, and only after a camera move. So, for each graph below, on the
 * CPU and on GL, the test loads it fresh three times, at its own camera and at two others
 * (moved with a narrower field of view; turned), runs each, and requires that every
 * output of every node a camera move would keep (no SSG_READS_CAMERA, and every producer
 * kept too: exactly what ssg_graph_set_view keeps) has the same bytes at all three.
 * Fresh loads, not a live graph: what is compared is what the node computes, not what the
 * live graph chose to reuse.
 *
 * The guard cannot be bypassed by forgetting it: every node type in the registry that
 * leaves out the camera must have been checked in at least one graph below, or the
 * test fails naming it (a node that declares it and appears in none of these graphs needs
 * a graph here that uses it). And it cannot pass vacuously: the camera must change what
 * the G-buffer sees in each graph.
 *
 * The lights (ssg_graph_set_lights) likewise: each graph of light_cases is loaded under
 * two light sets, and every node that leaves out SSG_READS_LIGHTS and got the same bytes
 * on every input in both must give the same bytes on every output; every node type that
 * reads the scene but not its lights must be checked so, and the lights must change a
 * port of each graph. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "graph/graph.h"

#define SIZE_W 40
#define SIZE_H 28
#define VIEWS 3

/* A graph, smaller settings for a quick test, and an output that must see the camera. */
struct guard_case {
    const char *graph;
    const char *sets[3];
    int set_count;
    const char *camera_port;
};
static const struct guard_case cases[] = {
    {"graphs/hybrid.graph", {"lp.count=16", "sm.resolution=64"}, 2, "g.depth"},
    {"graphs/rsm.graph", {"lm.resolution=64", "b.samples=32"}, 2, "g.depth"},
    {"graphs/ssao.graph", {NULL}, 0, "g.depth"},
};

static char out_dir[1024];

/* A fresh load of the case on `backend` at the test's size, or NULL. */
static struct ssg_graph *load(const struct guard_case *c, const char *backend,
                              struct ssg_diags *d)
{
    struct ssg_overrides ov = {.width = SIZE_W, .height = SIZE_H, .seed = -1,
                               .backend = backend, .sets = c->sets,
                               .set_count = c->set_count};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(c->graph, &ov, &g, d), SSG_OK);
    return g;
}

/* A fresh load of the case on `backend`, at views[v] (0 = the graph's own), kept and run. */
static struct ssg_graph *run_at(const struct guard_case *c, const char *backend,
                                const struct ssg_view *views, int v)
{
    struct ssg_diags d = {0};
    struct ssg_graph *g = load(c, backend, &d);
    if (g && v > 0)
        CHECK_EQ(ssg_graph_set_view(g, &views[v], &d), SSG_OK);
    if (g)
        CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    struct ssg_run_options opt = {.out_dir = out_dir, .threads = 2};
    if (g)
        CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return g;
}

/* The graph's view and two others (moved sideways with a narrower field of view; turned). */
static int views_of(const struct guard_case *c, const char *backend,
                    struct ssg_view views[VIEWS])
{
    struct ssg_diags d = {0};
    struct ssg_graph *g = load(c, backend, &d);
    int ok = g && ssg_graph_view(g, &views[0], &d) == SSG_OK;
    CHECK(ok);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
    views[1] = views[0], views[2] = views[0];
    views[1].position[0] += 0.4f, views[1].position[1] += 0.1f;
    views[1].fov_y = views[0].fov_y * 0.8f;
    views[2].target[0] -= 0.5f, views[2].target[1] += 0.2f;
    views[2].up[0] += 0.1f;
    return ok;
}

/* kept[i] = 1 for each node a camera move keeps: reads no camera and every producer
   kept (the transitive closure, in run order so producers come first). */
static void kept_by_camera_move(const struct ssg_graph *g, unsigned char *kept)
{
    for (int p = 0; p < g->order_count; p++) {
        const struct gnode *n = &g->nodes[g->order[p]];
        int keep = !(ssg_gnode_reads(g, n) & SSG_READS_CAMERA);
        for (int k = 0; k < ssg_gnode_conn_count(n); k++) {
            const struct gconn *in = ssg_gnode_conn(n, k);
            if (in->node >= 0 && !kept[in->node])
                keep = 0;
        }
        kept[g->order[p]] = (unsigned char)keep;
    }
}

static int same_image(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && a->width == b->width && a->height == b->height &&
           a->channels == b->channels &&
           !memcmp(a->data, b->data,
                   (size_t)a->width * (size_t)a->height * (size_t)a->channels * sizeof(float));
}

/* 1 when `port` of the graphs at view 0 and view v hold the same bytes (or neither has
   it: an on-demand output nothing reads); *compared = 1 when both had it. */
static int port_same(struct ssg_graph *a, struct ssg_graph *b, const char *port,
                     int *compared)
{
    struct ssg_image *x = NULL, *y = NULL;
    struct ssg_diags quiet = {0};
    enum ssg_err ea = ssg_graph_output(a, port, &x, &quiet);
    enum ssg_err eb = ssg_graph_output(b, port, &y, &quiet);
    int same = ea == eb && (ea != SSG_OK || same_image(x, y));
    *compared = ea == SSG_OK && eb == SSG_OK;
    ssg_image_destroy(&x);
    ssg_image_destroy(&y);
    return same;
}

/* Compares every output of every kept node of `a` with `b`; marks the types checked. */
static void compare_kept(struct ssg_graph *a, struct ssg_graph *b, const char *what,
                         unsigned char *covered)
{
    unsigned char *kept = calloc((size_t)a->count + 1, 1);
    CHECK(kept != NULL);
    if (!kept)
        return;
    kept_by_camera_move(a, kept);
    for (int i = 0; i < a->count; i++) {
        const struct gnode *n = &a->nodes[i];
        int compared = 0;
        for (int k = 0; kept[i] && k < n->desc->output_count; k++) {
            char port[256];
            int both = 0;
            snprintf(port, sizeof port, "%s.%s", n->name, n->desc->outputs[k].name);
            int same = port_same(a, b, port, &both);
            compared += both;
            if (!same)
                fprintf(stderr, "%s: %s (%s, does not read the camera) changed with the "
                        "camera\n", what, port, n->desc->name);
            CHECK(same);
        }
        for (int t = 0; compared && t < ssg_node_count(); t++)
            if (ssg_node_at(t) == n->desc)
                covered[t] = 1;
    }
    free(kept);
}

static void guard_case(const struct guard_case *c, const char *backend, unsigned char *covered)
{
    struct ssg_view views[VIEWS];
    if (!views_of(c, backend, views))
        return;
    struct ssg_graph *home = run_at(c, backend, views, 0);
    for (int v = 1; home && v < VIEWS; v++) {
        struct ssg_graph *moved = run_at(c, backend, views, v);
        if (!moved)
            continue;
        char what[256];
        snprintf(what, sizeof what, "%s %s view %d", c->graph, backend, v);
        int both = 0; /* the camera did change the frame */
        CHECK(!port_same(home, moved, c->camera_port, &both) && both);
        compare_kept(home, moved, what, covered);
        ssg_graph_destroy(&moved);
    }
    ssg_graph_destroy(&home);
}

/* A graph, smaller settings, and a port the lights must change. */
struct light_case {
    const char *graph;
    const char *sets[3];
    int set_count;
    const char *lit_port;
};
static const struct light_case light_cases[] = {
    {"graphs/ao_error.graph", {"ref.rays=16"}, 1, "g.direct"},
    {"graphs/gi.graph", {"lm.resolution=64", "lb.resolution=32", "sm.resolution=64"}, 3,
     "g.direct"},
};
static const char *const light_files[] = {"examples/lights/sun.scene",
                                          "examples/lights/sky.scene"};

/* A fresh load of the case under light file l, kept and run on `backend`, or NULL. */
static struct ssg_graph *run_lit(const struct light_case *c, const char *backend, int l)
{
    /* the lit port asked for beside the sinks: an on-demand output (gbuffer.direct) is
       made only where something reads it */
    const char *lit[1] = {c->lit_port};
    struct ssg_overrides ov = {.width = SIZE_W, .height = SIZE_H, .seed = -1,
                               .backend = backend, .sets = c->sets,
                               .set_count = c->set_count, .lights = light_files[l],
                               .outputs = lit, .output_count = 1, .keep_sinks = 1};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(c->graph, &ov, &g, &d), SSG_OK);
    if (g)
        CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    struct ssg_run_options opt = {.out_dir = out_dir, .threads = 2};
    if (g && ssg_graph_run(g, &opt, &d) != SSG_OK)
        ssg_graph_destroy(&g);
    ssg_diags_print(&d, stderr);
    return g;
}

/* 1 when every connected input of node n holds the same bytes in a and b. */
static int same_inputs(struct ssg_graph *a, struct ssg_graph *b, const struct gnode *n)
{
    for (int k = 0; k < ssg_gnode_conn_count(n); k++) {
        const struct gconn *in = ssg_gnode_conn(n, k);
        if (in->node < 0)
            continue;
        const struct gnode *src = &a->nodes[in->node];
        char port[256];
        int both = 0;
        snprintf(port, sizeof port, "%s.%s", src->name, src->desc->outputs[in->port].name);
        if (!port_same(a, b, port, &both) || !both)
            return 0;
    }
    return 1;
}

/* Every node that does not read the lights and saw the same inputs under both light sets
   gives the same outputs; marks the types checked. */
static void light_case(const struct light_case *c, const char *backend, unsigned char *covered)
{
    struct ssg_graph *a = run_lit(c, backend, 0), *b = run_lit(c, backend, 1);
    int both = 0;
    CHECK(a && b && !port_same(a, b, c->lit_port, &both) && both);
    for (int i = 0; a && b && i < a->count; i++) {
        const struct gnode *n = &a->nodes[i];
        if ((ssg_node_reads(n->desc) & SSG_READS_LIGHTS) || n->desc->is_sink ||
            !same_inputs(a, b, n))
            continue;
        int compared = 0;
        for (int k = 0; k < n->desc->output_count; k++) {
            char port[256];
            int had = 0;
            snprintf(port, sizeof port, "%s.%s", n->name, n->desc->outputs[k].name);
            int same = port_same(a, b, port, &had);
            compared += had;
            if (!same)
                fprintf(stderr, "%s %s: %s (%s, does not read the lights) changed with "
                        "them\n", c->graph, backend, port, n->desc->name);
            CHECK(same);
        }
        for (int t = 0; compared && t < ssg_node_count(); t++)
            if (ssg_node_at(t) == n->desc)
                covered[t] = 1;
    }
    ssg_graph_destroy(&a);
    ssg_graph_destroy(&b);
}

/* Every node type that leaves out `bit` (and, for the lights, reads the scene: the
   types where the declaration is a claim) was checked in a graph. */
static void require_covered(const unsigned char *covered, unsigned bit, unsigned among,
                            const char *what)
{
    for (int t = 0; t < ssg_node_count(); t++) {
        unsigned reads = ssg_node_reads(ssg_node_at(t));
        int claims = !(reads & bit) && (reads & among) == among;
        if (claims && !covered[t])
            fprintf(stderr, "node '%s' does not read %s but no graph of "
                    "tests/test_camera_deps.c checks it: add one that uses it\n",
                    ssg_node_at(t)->name, what);
        CHECK(!claims || covered[t]);
    }
}

int main(void)
{
    const char *tmp = getenv("SSG_TMP");
    snprintf(out_dir, sizeof out_dir, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_camera_deps");
    int types = ssg_node_count();
    unsigned char *covered = calloc((size_t)types + 1, 1);
    unsigned char *lit_covered = calloc((size_t)types + 1, 1);
    CHECK(covered != NULL && lit_covered != NULL);
    if (!covered || !lit_covered)
        return check_report();
    static const char *const backends[] = {"cpu", "gl"};
    for (int b = 0; b < 2; b++) {
        for (int c = 0; c < (int)(sizeof cases / sizeof cases[0]); c++)
            guard_case(&cases[c], backends[b], covered);
        for (int c = 0; c < (int)(sizeof light_cases / sizeof light_cases[0]); c++)
            light_case(&light_cases[c], backends[b], lit_covered);
    }
    require_covered(covered, SSG_READS_CAMERA, SSG_READS_INPUTS, "the camera");
    require_covered(lit_covered, SSG_READS_LIGHTS, SSG_READS_SCENE, "the lights");
    free(covered);
    free(lit_covered);
    return check_report();
}
