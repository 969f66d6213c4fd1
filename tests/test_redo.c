/* test_redo.c - the one rule for what runs again (core/graph/graph_redo.c), seen from the
 * public interface: on a kept gi.graph (light maps, shadow maps, the probe's lights, an
 * SSDO near field on halton's samples) the camera, then the lights, then a parameter, then
 * the frame change in turn, and after each run
 *   - each node's `why` in the run statistics says exactly what the rule says: the
 *     readers of what changed ran for that reason, their readers because an input ran,
 *     everything else was kept (0 calls);
 *   - the final image has the bytes of a fresh load with the same camera, lights and set;
 * a refused change (a lights file that does not load) leaves everything kept; and a run
 * of four frames on a camera orbit reports the light maps as run once and kept three
 * times, the G-buffer as run for a moved camera in each later frame. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "ssgraph.h"

#define GRAPH "graphs/gi.graph"
#define PORT "gi.out"

static const char *const sets[] = {"lm.resolution=64", "lb.resolution=32",
                                   "sm.resolution=64"};
static char out_dir[1024];

/* A change and what it must make each node do: "name=why" pairs, the rest kept. */
struct expect {
    const char *node;
    const char *why;
};

static struct ssg_graph *load(const char *lights, const char *extra_set)
{
    const char *all[4] = {sets[0], sets[1], sets[2], extra_set};
    struct ssg_overrides ov = {.width = 48, .height = 32, .seed = -1, .sets = all,
                               .set_count = extra_set ? 4 : 3, .lights = lights};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(GRAPH, &ov, &g, &d), SSG_OK);
    if (g)
        CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return g;
}

/* Runs g (one frame, or `frames`), into *stats; 1 when it ran. */
static int run(struct ssg_graph *g, int frames, struct ssg_run_stats *stats)
{
    struct ssg_diags d = {0};
    struct ssg_run_options opt = {.out_dir = out_dir, .threads = 2, .stats = stats,
                                  .frames = frames};
    enum ssg_err e = ssg_graph_run(g, &opt, &d);
    ssg_diags_print(&d, stderr);
    CHECK_EQ(e, SSG_OK);
    return e == SSG_OK;
}

static const struct ssg_run_node *node_of(const struct ssg_run_stats *s, const char *name)
{
    for (int i = 0; i < s->node_count; i++)
        if (!strcmp(s->nodes[i].name, name))
            return &s->nodes[i];
    return NULL;
}

/* Every node named in `want` ran for that reason; every other non-sink was kept. */
static void check_why(const struct ssg_run_stats *s, const struct expect *want, int count,
                      const char *step)
{
    for (int i = 0; i < s->node_count; i++) {
        const struct ssg_run_node *n = &s->nodes[i];
        const char *expected = "kept";
        for (int k = 0; k < count; k++)
            if (!strcmp(want[k].node, n->name))
                expected = want[k].why;
        if (!strcmp(n->type, "write"))
            expected = "sink";
        int ok = n->why && !strcmp(n->why, expected) &&
                 (n->calls == 0) == !strcmp(expected, "kept");
        if (!ok)
            fprintf(stderr, "%s: node %s (%s) says '%s' with %d calls, expected '%s'\n", step,
                    n->name, n->type, n->why ? n->why : "(null)", n->calls, expected);
        CHECK(ok);
    }
}

/* PORT of g and of a fresh load (lights, extra_set, view) hold the same bytes. */
static void check_fresh(struct ssg_graph *g, const char *lights, const char *extra_set,
                        const struct ssg_view *view, const char *step)
{
    struct ssg_graph *f = load(lights, extra_set);
    struct ssg_diags d = {0};
    struct ssg_run_stats unused = {0};
    if (f && view)
        CHECK_EQ(ssg_graph_set_view(f, view, &d), SSG_OK);
    struct ssg_image *a = NULL, *b = NULL;
    if (f && run(f, 1, &unused)) {
        CHECK_EQ(ssg_graph_output(g, PORT, &a, &d), SSG_OK);
        CHECK_EQ(ssg_graph_output(f, PORT, &b, &d), SSG_OK);
    }
    int same = a && b && a->width == b->width && a->height == b->height &&
               !memcmp(a->data, b->data, (size_t)a->width * (size_t)a->height *
                                             (size_t)a->channels * sizeof(float));
    if (!same)
        fprintf(stderr, "%s: %s differs from a fresh load's\n", step, PORT);
    CHECK(same);
    ssg_diags_print(&d, stderr);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_run_stats_free(&unused);
    ssg_graph_destroy(&f);
}

/* The camera, the lights, a parameter, a bad lights file, the frame: each in turn. */
static void changes_in_turn(void)
{
    struct ssg_graph *g = load(NULL, NULL);
    struct ssg_run_stats s = {0};
    struct ssg_diags d = {0};
    if (!g || !run(g, 1, &s))
        return;
    const struct ssg_run_node *first = node_of(&s, "lm");
    CHECK(first && first->why && !strcmp(first->why, "first run"));
    ssg_run_stats_free(&s);

    struct ssg_view view;
    CHECK_EQ(ssg_graph_view(g, &view, &d), SSG_OK);
    view.position[0] += 0.3f, view.target[1] += 0.1f;
    CHECK_EQ(ssg_graph_set_view(g, &view, &d), SSG_OK);
    static const struct expect camera[] = {
        {"g", "camera moved"}, {"dl", "camera moved"}, {"h", "camera moved"},
        {"hp", "camera moved"}, {"hpf", "camera moved"}, {"glob", "camera moved"},
        {"glit", "camera moved"},
        {"gdo", "camera moved"}, {"gf", "camera moved"}, {"gd", "camera moved"},
        {"grsm", "camera moved"}, {"grf", "camera moved"}, {"gru", "camera moved"},
        {"gi", "camera moved"}};
    if (run(g, 1, &s))
        check_why(&s, camera, (int)(sizeof camera / sizeof camera[0]), "a new camera");
    ssg_run_stats_free(&s);
    check_fresh(g, NULL, NULL, &view, "a new camera");

    const char *sky = "examples/lights/sky.scene";
    CHECK_EQ(ssg_graph_set_lights(g, sky, &d), SSG_OK);
    /* the Cornell box's own light is a point light (six map faces), the sky has none: the
       light maps' shapes move, which is told before the lights themselves; so do the
       probe's maps (one texel each without environment light, 512 under the sky) */
    static const struct expect lights[] = {
        {"g", "lights changed"}, {"lm", "shape changed"}, {"dl", "shape changed"},
        {"lp", "lights changed"}, {"sm", "shape changed"}, {"h", "input g ran"},
        {"hp", "shape changed"}, {"hpf", "input hp ran"}, {"glob", "input hpf ran"},
        {"glit", "input dl ran"},
        {"gdo", "lights changed"}, {"gf", "input gdo ran"}, {"gd", "input g ran"},
        {"lb", "shape changed"}, {"grsm", "shape changed"}, {"grf", "input grsm ran"},
        {"gru", "input grf ran"}, {"gi", "input dl ran"}};
    if (run(g, 1, &s))
        check_why(&s, lights, (int)(sizeof lights / sizeof lights[0]), "new lights");
    ssg_run_stats_free(&s);
    check_fresh(g, sky, NULL, &view, "new lights");

    CHECK_EQ(ssg_graph_set(g, "gdo.radius", "0.4", &d), SSG_OK);
    static const struct expect param[] = {
        {"gdo", "parameter changed"}, {"gf", "input gdo ran"}, {"gi", "input gf ran"}};
    if (run(g, 1, &s))
        check_why(&s, param, 3, "a parameter");
    ssg_run_stats_free(&s);
    check_fresh(g, sky, "gdo.radius=0.4", &view, "a parameter");

    struct ssg_diags refused = {0};
    CHECK(ssg_graph_set_lights(g, "examples/lights/no_such.scene", &refused) != SSG_OK);
    CHECK(refused.count > 0);
    if (run(g, 1, &s))
        check_why(&s, NULL, 0, "a refused lights file");
    ssg_run_stats_free(&s);

    CHECK_EQ(ssg_graph_set_frame(g, 1, &d), SSG_OK);
    static const struct expect frame[] = {
        {"gk", "new frame"}, {"gdo", "input gk ran"}, {"gf", "input gdo ran"},
        {"gi", "input gf ran"}};
    if (run(g, 1, &s))
        check_why(&s, frame, 4, "the next frame");
    ssg_run_stats_free(&s);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

/* Four frames of an orbit: what reads no camera runs once. */
static void orbit_sequence(void)
{
    struct ssg_overrides ov = {.width = 48, .height = 32, .seed = -1, .sets = sets,
                               .set_count = 3, .scene = "examples/cornell_orbit.scene"};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(GRAPH, &ov, &g, &d), SSG_OK);
    struct ssg_run_stats s = {0};
    if (g && run(g, 4, &s)) {
        static const struct expect want[] = {
            /* the box has no environment: the probe's lights carry nothing, so nothing
               uses their shadow maps, skipped once and kept (tests/test_skip.c) */
            {"lm", "first run, kept x3"}, {"sm", "skipped: zero or unused, kept x3"},
            {"lb", "first run, kept x3"}, {"lp", "first run, kept x3"},
            {"g", "first run, camera moved x3"}, {"gk", "first run, new frame x3"},
            {"out", "sink"}};
        for (int k = 0; k < (int)(sizeof want / sizeof want[0]); k++) {
            const struct ssg_run_node *n = node_of(&s, want[k].node);
            int ok = n && n->why && !strcmp(n->why, want[k].why);
            if (!ok)
                fprintf(stderr, "orbit: node %s says '%s', expected '%s'\n", want[k].node,
                        n && n->why ? n->why : "(none)", want[k].why);
            CHECK(ok);
        }
        const struct ssg_run_node *lm = node_of(&s, "lm");
        CHECK(lm && lm->calls == 1 && lm->kept == 3);
    }
    ssg_run_stats_free(&s);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

/* Four frames under a sun: gi.graph's direct-light maps are fitted to the view
   (lightmaps fit=view), so on an orbit they are made again for each moved camera, and
   only then: the reflective shadow maps (fit=scene) and, with a still camera, the fitted
   maps too are made once. */
static void sun_sequence(const char *scene, const struct expect *want, int count)
{
    struct ssg_overrides ov = {.width = 48, .height = 32, .seed = -1, .sets = sets,
                               .set_count = 3, .scene = scene,
                               .lights = "examples/lights/sun.scene"};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(GRAPH, &ov, &g, &d), SSG_OK);
    struct ssg_run_stats s = {0};
    int ran = g && run(g, 4, &s);
    for (int k = 0; ran && k < count; k++) {
        const struct ssg_run_node *n = node_of(&s, want[k].node);
        int ok = n && n->why && !strcmp(n->why, want[k].why);
        if (!ok)
            fprintf(stderr, "%s under the sun: node %s says '%s', expected '%s'\n", scene,
                    want[k].node, n && n->why ? n->why : "(none)", want[k].why);
        CHECK(ok);
    }
    ssg_run_stats_free(&s);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

static void sun_sequences(void)
{
    static const struct expect orbit[] = {
        {"lm", "first run, camera moved x3"}, {"dl", "first run, camera moved x3"},
        {"lb", "first run, kept x3"}};
    static const struct expect still[] = {
        {"lm", "first run, kept x3"}, {"dl", "first run, kept x3"},
        {"lb", "first run, kept x3"}};
    sun_sequence("examples/cornell_orbit.scene", orbit, 3);
    sun_sequence("examples/cornell.scene", still, 3);
}

int main(void)
{
    const char *tmp = getenv("SSG_TMP");
    snprintf(out_dir, sizeof out_dir, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_redo");
    changes_in_turn();
    orbit_sequence();
    sun_sequences();
    return check_report();
}
