/* test_live.c - live graphs (ssgraph.h: ssg_graph_keep, ssg_graph_set, ssg_graph_output):
 *   - any sequence of sets and runs on a kept graph gives the bytes of a fresh load with the
 *     final settings (a seeded random sequence a graph and backend, several outputs
 *     compared, CPU and GL);
 *   - a set re-runs only the node and what follows it: after a change to the filter, the
 *     G-buffer and the AO node are not run again (calls 0 in the stats), the filter is;
 *   - a node's check_params (probe_light: noise_radius is read by its runs alone): such a
 *     set runs the node again without prepare() (its stats' prepare_ms exactly 0), a set
 *     of another parameter prepares it again; the random walks on hybrid.graph mix both;
 *   - a set of a shape-changing parameter (halton's count: the kernel's width) re-prepares
 *     the readers (ssao's 1 / K), and still gives a fresh load's bytes;
 *   - a bad set (unknown node, unknown parameter, an input, a value out of range) is an
 *     error that leaves the graph as it was;
 *   - a new camera (ssg_graph_set_view) changes the image, the old one back restores its
 *     bytes, and impossible cameras are refused; the random walks on hybrid.graph and
 *     rsm.graph move the camera too (a fresh load then gets that camera before its run);
 *   - after a new camera the nodes whose reads leave out the camera (node.h) do not run
 *     (lightprobe, shadowmaps, halton, lightmaps: calls 0), those that read it do;
 *   - the memory limit evicts, and evicted nodes run again with the same bytes;
 *   - rsm's VPL list, kept while the light maps stand (node.h's in_made), is made again
 *     when new lights remake the maps though rsm's own constants stay the same. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scratch.h"
#include "ssgraph.h"

#define SIZE_W 40
#define SIZE_H 28

struct choice {
    const char *key;
    const char *values[4];
};

/* Parameters of graphs/ssao.graph and graphs/hbao.graph worth changing, early and late. */
static const struct choice ssao_choices[] = {
    {"ao.radius", {"0.25", "0.5", "0.8", NULL}},
    {"ao.power", {"1", "2", "3", NULL}},
    {"ao.mode", {"hemisphere", "sphere", "disc", NULL}},
    {"b.size", {"5", "9", "13", NULL}},
    {"k.count", {"8", "16", "12", NULL}},
    {"img.ambient", {"0.3", "0.6", "1", NULL}},
};
static const struct choice hbao_choices[] = {
    {"h.radius", {"0.3", "0.5", "0.9", NULL}},
    {"h.steps", {"3", "6", "9", NULL}},
    {"h.directions", {"4", "8", "6", NULL}},
    {"b.size", {"5", "9", "11", NULL}},
};

/* The walks' camera moves: this key is no parameter; its value picks a view of views_of(). */
#define VIEW_KEY "@view"
#define VIEW_COUNT 3
#define SSG_COUNT(arr) ((int)(sizeof(arr) / sizeof((arr)[0])))

/* hybrid.graph: probe_light's noise_radius is run-only (its check_params), offset is not;
   noise_radius twice, so the walks change it often. */
static const struct choice hybrid_choices[] = {
    {"glob.noise_radius", {"0", "0.5", "2", NULL}},
    {"glob.offset", {"0.3", "0.5", "1", NULL}},
    {"glob.noise_radius", {"1", "3", "0.25", NULL}},
    {"ao.radius", {"0.1", "0.15", "0.3", NULL}},
    {"loc.size", {"5", "9", "13", NULL}},
    {VIEW_KEY, {"1", "2", "0", NULL}},
    {VIEW_KEY, {"2", "1", "0", NULL}},
};

/* rsm.graph: the light maps do not read the camera, the rest does. */
static const struct choice rsm_choices[] = {
    {VIEW_KEY, {"1", "2", "0", NULL}},
    {"b.samples", {"16", "32", "0", NULL}},
    {VIEW_KEY, {"2", "0", "1", NULL}},
    {"dl.filter", {"0", "1", "2", NULL}},
};

/* A graph, the outputs compared with a fresh load's, and sets every load of it gets. */
struct graph_case {
    const char *graph;
    const char *ports[3];
    const char *base[2]; /* smaller than the graph's: a quick test */
    int base_count;
};
static const struct graph_case SSAO = {.graph = "graphs/ssao.graph",
                                       .ports = {"img.out", "b.out", "g.depth"}};
static const struct graph_case HBAO = {.graph = "graphs/hbao.graph",
                                       .ports = {"img.out", "b.out", "g.depth"}};
static const struct graph_case HYBRID = {"graphs/hybrid.graph",
                                         {"img.out", "glob.out", "glob.visibility"},
                                         {"lp.count=16", "sm.resolution=64"}, 2};
static const struct graph_case RSM = {"graphs/rsm.graph", {"img.out", "dl.out", "b.out"},
                                      {"lm.resolution=64", "b.samples=32"}, 2};

static struct ssg_overrides base_overrides(const char *backend)
{
    return (struct ssg_overrides){.width = SIZE_W, .height = SIZE_H, .seed = -1,
                                  .backend = backend};
}

static char out_dir[1024]; /* the test's scratch folder (SSG_TMP) */

static int run_quiet(struct ssg_graph *g, const char *unused, struct ssg_run_stats *stats,
                     struct ssg_diags *d)
{
    (void)unused;
    struct ssg_run_options opt = {.out_dir = out_dir, .threads = 2, .stats = stats};
    return ssg_graph_run(g, &opt, d);
}

/* A load of the case with its base sets, then `sets` (the last of a key wins). */
static struct ssg_graph *load_case(const struct graph_case *gc, const char *backend,
                                   const char **sets, int count, int with_outputs)
{
    const char *all[16];
    int n = 0;
    for (int k = 0; k < gc->base_count; k++)
        all[n++] = gc->base[k];
    for (int k = 0; k < count && n < 16; k++)
        all[n++] = sets[k];
    struct ssg_overrides ov = base_overrides(backend);
    ov.sets = all, ov.set_count = n;
    if (with_outputs)
        ov.outputs = gc->ports, ov.output_count = 3;
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_load(gc->graph, &ov, &g, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return g;
}

/* The fresh load's images of the case's ports with the sets in `sets`, the camera `view`
   and the lights file `lights` (NULL: the graph's own). */
static void fresh_outputs(const struct graph_case *gc, const char *backend, const char **sets,
                          int count, const struct ssg_view *view, const char *lights,
                          struct ssg_image **images)
{
    struct ssg_graph *g = load_case(gc, backend, sets, count, 1);
    struct ssg_diags d = {0};
    if (view) /* the camera set before the first run: every node reads it fresh */
        CHECK_EQ(ssg_graph_set_view(g, view, &d), SSG_OK);
    if (lights) /* likewise the lights */
        CHECK_EQ(ssg_graph_set_lights(g, lights, &d), SSG_OK);
    struct ssg_run_options opt = {.out_dir = out_dir, .threads = 2, .outputs = images};
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

static int same_image(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && a->width == b->width && a->height == b->height &&
           a->channels == b->channels &&
           !memcmp(a->data, b->data,
                   (size_t)a->width * (size_t)a->height * (size_t)a->channels * sizeof(float));
}

/* Compares the kept graph's outputs with a fresh load's under the same settings. */
static void expect_fresh_lit_bytes(struct ssg_graph *g, const struct graph_case *gc,
                                   const char *backend, const char **sets, int count,
                                   const struct ssg_view *view, const char *lights,
                                   const char *when)
{
    struct ssg_image *fresh[3] = {0};
    fresh_outputs(gc, backend, sets, count, view, lights, fresh);
    for (int k = 0; k < 3; k++) {
        struct ssg_image *live = NULL;
        struct ssg_diags d = {0};
        CHECK_EQ(ssg_graph_output(g, gc->ports[k], &live, &d), SSG_OK);
        if (!same_image(live, fresh[k]))
            fprintf(stderr, "%s %s %s: %s differs from a fresh load\n", gc->graph, backend,
                    when, gc->ports[k]);
        CHECK(same_image(live, fresh[k]));
        ssg_image_destroy(&live);
        ssg_image_destroy(&fresh[k]);
    }
}

static void expect_fresh_view_bytes(struct ssg_graph *g, const struct graph_case *gc,
                                    const char *backend, const char **sets, int count,
                                    const struct ssg_view *view, const char *when)
{
    expect_fresh_lit_bytes(g, gc, backend, sets, count, view, NULL, when);
}

static void expect_fresh_bytes(struct ssg_graph *g, const struct graph_case *gc,
                               const char *backend, const char **sets, int count,
                               const char *when)
{
    expect_fresh_view_bytes(g, gc, backend, sets, count, NULL, when);
}

/* The graph's own view and two others: moved sideways with a narrower field of view, and
   turned (another target, up tilted). */
static void views_of(struct ssg_graph *g, struct ssg_view views[VIEW_COUNT])
{
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_view(g, &views[0], &d), SSG_OK);
    views[1] = views[0], views[2] = views[0];
    views[1].position[0] += 0.4f;
    views[1].fov_y = views[0].fov_y * 0.8f;
    views[2].target[0] -= 0.5f, views[2].target[1] += 0.2f;
    views[2].up[0] += 0.1f;
}

static const struct ssg_run_node *node_of(const struct ssg_run_stats *s, const char *node);

static int calls_of(const struct ssg_run_stats *s, const char *node)
{
    const struct ssg_run_node *n = node_of(s, node);
    return n ? n->calls : -1;
}

/* A seeded random walk of sets and runs; after each run the kept outputs must be a fresh
   load's. The sets accumulate as --set would (the last value of a key wins). */
static void random_walk(const struct graph_case *gc, const char *backend,
                        const struct choice *choices, int choice_count, unsigned seed)
{
    struct ssg_graph *g = load_case(gc, backend, NULL, 0, 0);
    struct ssg_diags d = {0};
    struct ssg_view views[VIEW_COUNT];
    views_of(g, views);
    const struct ssg_view *view = NULL; /* the graph's own until the walk moves it */
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    char sets[8][64];
    const char *set_list[8];
    int set_count = 0, moves = 0;
    srand(seed);
    for (int step = 0; step < 4; step++) {
        const struct choice *c = &choices[rand() % choice_count];
        const char *value = c->values[rand() % 3];
        if (!strcmp(c->key, VIEW_KEY)) {
            view = &views[atoi(value)];
            moves++;
            CHECK_EQ(ssg_graph_set_view(g, view, &d), SSG_OK);
        } else {
            CHECK_EQ(ssg_graph_set(g, c->key, value, &d), SSG_OK);
            snprintf(sets[set_count], sizeof sets[0], "%s=%s", c->key, value);
            set_list[set_count] = sets[set_count];
            set_count++;
        }
        if (rand() % 3 == 0 && step < 3)
            continue; /* two sets before one run */
        CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
        char when[32];
        snprintf(when, sizeof when, "step %d", step);
        expect_fresh_view_bytes(g, gc, backend, set_list, set_count, view, when);
    }
    int has_views = 0; /* the seed must make a walk that has view choices move the camera */
    for (int k = 0; k < choice_count; k++)
        has_views |= !strcmp(choices[k].key, VIEW_KEY);
    if (has_views && moves == 0)
        fprintf(stderr, "%s %s seed %u: the walk never moved the camera\n", gc->graph,
                backend, seed);
    CHECK(!has_views || moves > 0);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

/* A late change runs the late node and what follows; the early ones are reused. */
static void only_what_changed_runs(const char *backend)
{
    struct ssg_overrides ov = base_overrides(backend);
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    struct ssg_run_stats s = {0};
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), SSG_OK);
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK);
    CHECK(calls_of(&s, "g") == 1 && calls_of(&s, "ao") == 1);
    ssg_run_stats_free(&s);
    CHECK_EQ(ssg_graph_set(g, "b.size", "5", &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK);
    CHECK_EQ(calls_of(&s, "g"), 0);
    CHECK_EQ(calls_of(&s, "k"), 0);
    CHECK_EQ(calls_of(&s, "ao"), 0);
    CHECK_EQ(calls_of(&s, "b"), 1);
    CHECK_EQ(calls_of(&s, "img"), 1);
    CHECK_EQ(calls_of(&s, "out"), 1); /* sinks always run */
    ssg_run_stats_free(&s);
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK); /* nothing changed */
    CHECK(calls_of(&s, "b") == 0 && calls_of(&s, "img") == 0);
    ssg_run_stats_free(&s);
    const char *sets[] = {"b.size=5"};
    expect_fresh_bytes(g, &SSAO, backend, sets, 1, "after b.size");
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

/* A new camera changes the image; the old camera back gives the first run's bytes again.
   Bad cameras are refused and change nothing. */
static void camera_moves_and_returns(const char *backend)
{
    struct ssg_overrides ov = base_overrides(backend);
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    struct ssg_view home, moved;
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), SSG_OK);
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(ssg_graph_view(g, &home, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    struct ssg_image *first = NULL, *other = NULL;
    CHECK_EQ(ssg_graph_output(g, "img.out", &first, &d), SSG_OK);
    moved = home;
    moved.position[0] += 0.4f;
    moved.fov_y = home.fov_y * 0.8f;
    CHECK_EQ(ssg_graph_set_view(g, &moved, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    CHECK_EQ(ssg_graph_output(g, "img.out", &other, &d), SSG_OK);
    CHECK(!same_image(first, other));
    ssg_image_destroy(&other);
    struct ssg_view bad = home;
    bad.up[0] = bad.target[0] - bad.position[0], bad.up[1] = bad.target[1] - bad.position[1];
    bad.up[2] = bad.target[2] - bad.position[2];
    struct ssg_diags refused = {0};
    CHECK_EQ(ssg_graph_set_view(g, &bad, &refused), SSG_E_VALUE);
    bad = home, bad.fov_y = 180;
    CHECK_EQ(ssg_graph_set_view(g, &bad, &refused), SSG_E_VALUE);
    ssg_diags_print(&refused, stderr);
    CHECK_EQ(ssg_graph_set_view(g, &home, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    CHECK_EQ(ssg_graph_output(g, "img.out", &other, &d), SSG_OK);
    CHECK(same_image(first, other));
    ssg_image_destroy(&first);
    ssg_image_destroy(&other);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

/* halton's count is the kernel's width: ssao's prepared 1 / K must be made again. */
static void shape_change_reprepares(const char *backend)
{
    struct ssg_overrides ov = base_overrides(backend);
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), SSG_OK);
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    CHECK_EQ(ssg_graph_set(g, "k.count", "8", &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    const char *sets[] = {"k.count=8"};
    expect_fresh_bytes(g, &SSAO, backend, sets, 1, "after k.count");
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

static const struct ssg_run_node *node_of(const struct ssg_run_stats *s, const char *node)
{
    for (int i = 0; i < s->node_count; i++)
        if (!strcmp(s->nodes[i].name, node))
            return &s->nodes[i];
    return NULL;
}

/* probe_light's check_params: a set of noise_radius alone runs the node again on its
   prepared constants (its stats' prepare_ms exactly 0: prepare() was not called; the
   profile's row starts at 0 every run), a set of offset prepares it again (prepare_ms
   > 0); both give a fresh load's bytes. The light list and maps before it are reused. */
static void run_only_change_keeps_prepare(const char *backend)
{
    struct ssg_graph *g = load_case(&HYBRID, backend, NULL, 0, 0);
    struct ssg_diags d = {0};
    struct ssg_run_stats s = {0};
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK);
    CHECK(node_of(&s, "glob") && node_of(&s, "glob")->prepare_ms > 0);
    ssg_run_stats_free(&s);
    CHECK_EQ(ssg_graph_set(g, "glob.noise_radius", "2.5", &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK);
    const struct ssg_run_node *glob = node_of(&s, "glob");
    CHECK(glob && glob->calls == 1);
    CHECK(glob && glob->prepare_ms == 0.0); /* not prepared again */
    CHECK(calls_of(&s, "lp") == 0 && calls_of(&s, "sm") == 0 && calls_of(&s, "g") == 0);
    CHECK_EQ(calls_of(&s, "img"), 1);
    ssg_run_stats_free(&s);
    const char *sets[] = {"glob.noise_radius=2.5", "glob.offset=0.8"};
    expect_fresh_bytes(g, &HYBRID, backend, sets, 1, "after glob.noise_radius");
    CHECK_EQ(ssg_graph_set(g, "glob.offset", "0.8", &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK);
    glob = node_of(&s, "glob");
    CHECK(glob && glob->calls == 1 && glob->prepare_ms > 0); /* offset: prepared again */
    ssg_run_stats_free(&s);
    expect_fresh_bytes(g, &HYBRID, backend, sets, 2, "after glob.offset");
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

/* After a new camera only the nodes that read it run again: those that declare
   no camera keep their outputs (calls 0), and the image is a fresh load's with
   that camera. `skipped` and `ran` name nodes of the case's graph. */
static void camera_skips_independent(const struct graph_case *gc, const char *backend,
                                     const char *const *skipped, const char *const *ran)
{
    struct ssg_graph *g = load_case(gc, backend, NULL, 0, 0);
    struct ssg_diags d = {0};
    struct ssg_run_stats s = {0};
    struct ssg_view views[VIEW_COUNT];
    views_of(g, views);
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    CHECK_EQ(ssg_graph_set_view(g, &views[1], &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK);
    for (int k = 0; skipped[k]; k++)
        if (calls_of(&s, skipped[k]) != 0)
            fprintf(stderr, "%s %s: %s ran after a camera move\n", gc->graph, backend,
                    skipped[k]);
    for (int k = 0; skipped[k]; k++)
        CHECK_EQ(calls_of(&s, skipped[k]), 0);
    for (int k = 0; ran[k]; k++)
        CHECK_EQ(calls_of(&s, ran[k]), 1);
    ssg_run_stats_free(&s);
    expect_fresh_view_bytes(g, gc, backend, NULL, 0, &views[1], "after a camera move");
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

static void camera_moves_skip(const char *backend)
{
    static const char *const hybrid_skipped[] = {"lp", "sm", "k", NULL};
    static const char *const hybrid_ran[] = {"g", "glob", "ao", "loc", "img", NULL};
    static const char *const rsm_skipped[] = {"lm", NULL};
    static const char *const rsm_ran[] = {"g", "dl", "d", "b", "img", NULL};
    camera_skips_independent(&HYBRID, backend, hybrid_skipped, hybrid_ran);
    camera_skips_independent(&RSM, backend, rsm_skipped, rsm_ran);
}

static void bad_sets_change_nothing(void)
{
    struct ssg_overrides ov = base_overrides("cpu");
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), SSG_OK);
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    struct ssg_diags bad = {0};
    CHECK_EQ(ssg_graph_set(g, "nosuch.radius", "1", &bad), SSG_E_UNKNOWN_NAME);
    CHECK_EQ(ssg_graph_set(g, "ao.raduis", "1", &bad), SSG_E_UNKNOWN_PARAM);
    CHECK_EQ(ssg_graph_set(g, "ao.depth", "g.depth", &bad), SSG_E_UNKNOWN_PARAM);
    CHECK(ssg_graph_set(g, "ao.radius", "-3", &bad) != SSG_OK);
    CHECK(ssg_graph_set(g, "b.size", "4", &bad) != SSG_OK); /* even: check() refuses */
    CHECK(ssg_graph_set(g, "ao.mode", "cube", &bad) != SSG_OK);
    ssg_diags_print(&bad, stderr);
    CHECK(bad.count >= 6);
    double radius = 0;
    CHECK_EQ(ssg_graph_param(g, "ao.radius", &radius, NULL, &d), SSG_OK);
    CHECK_NEAR(radius, 0.5, 1e-7);
    struct ssg_run_stats s = {0};
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK);
    CHECK(calls_of(&s, "ao") == 0 && calls_of(&s, "b") == 0); /* nothing was dirtied */
    ssg_run_stats_free(&s);
    expect_fresh_bytes(g, &SSAO, "cpu", NULL, 0, "after bad sets");
    struct ssg_image *none = NULL;
    CHECK(ssg_graph_output(g, "ao.nosuch", &none, &bad) != SSG_OK && none == NULL);
    ssg_graph_destroy(&g);
}

/* A limit smaller than one frame's images evicts; the next run redoes the evicted nodes
   and gives the same bytes. */
static void memory_limit_evicts(void)
{
    struct ssg_overrides ov = base_overrides("cpu");
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    struct ssg_run_stats s = {0};
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), SSG_OK);
    CHECK_EQ(ssg_graph_keep(g, (size_t)SIZE_W * SIZE_H * 4 * 8, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK);
    CHECK_EQ(calls_of(&s, "g"), 1); /* the G-buffer's 7 planes and more: evicted */
    ssg_run_stats_free(&s);
    struct ssg_image *img = NULL;
    CHECK_EQ(ssg_graph_output(g, "img.out", &img, &d), SSG_OK);
    ssg_image_destroy(&img);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

/* rsm keeps its VPL list while the light maps stand (ctx.in_made; a camera move runs it on
   the kept list: camera_skips_independent on rsm.graph). New lights in the same place
   leave rsm's constants as they were, so only the maps' serials tell that the list must
   be made again: the light maps and rsm run, with a fresh load's bytes. */
static void rsm_list_follows_the_maps(void)
{
    const char *lights = write_file(
        "bluer.lights", "point_light(position=[0, 1.9, 0], color=[0.6, 0.8, 1], intensity=4)\n");
    struct ssg_graph *g = load_case(&RSM, "cpu", NULL, 0, 0);
    struct ssg_diags d = {0};
    struct ssg_run_stats s = {0};
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, NULL, &d), SSG_OK);
    CHECK_EQ(ssg_graph_set_lights(g, lights, &d), SSG_OK);
    CHECK_EQ(run_quiet(g, NULL, &s, &d), SSG_OK);
    CHECK(calls_of(&s, "lm") == 1 && calls_of(&s, "b") == 1);
    ssg_run_stats_free(&s);
    expect_fresh_lit_bytes(g, &RSM, "cpu", NULL, 0, NULL, lights, "after new lights");
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

int main(void)
{
    const char *tmp = getenv("SSG_TMP");
    snprintf(out_dir, sizeof out_dir, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_live");
    setup_tmp("test_live"); /* write_file's folder */
    only_what_changed_runs("cpu");
    bad_sets_change_nothing();
    shape_change_reprepares("cpu");
    camera_moves_and_returns("cpu");
    camera_moves_and_returns("gl");
    shape_change_reprepares("gl");
    memory_limit_evicts();
    random_walk(&SSAO, "cpu", ssao_choices, 6, 7);
    random_walk(&HBAO, "cpu", hbao_choices, 4, 11);
    random_walk(&HYBRID, "cpu", hybrid_choices, SSG_COUNT(hybrid_choices), 13);
    random_walk(&RSM, "cpu", rsm_choices, SSG_COUNT(rsm_choices), 23);
    rsm_list_follows_the_maps();
    camera_moves_skip("cpu");
    run_only_change_keeps_prepare("cpu");
    only_what_changed_runs("gl");
    random_walk(&SSAO, "gl", ssao_choices, 6, 5);
    random_walk(&HBAO, "gl", hbao_choices, 4, 3);
    random_walk(&HYBRID, "gl", hybrid_choices, SSG_COUNT(hybrid_choices), 2);
    random_walk(&RSM, "gl", rsm_choices, SSG_COUNT(rsm_choices), 19);
    camera_moves_skip("gl");
    run_only_change_keeps_prepare("gl");
    return check_report();
}
