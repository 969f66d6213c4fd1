/* test_gl_scene.c - the scene on GL (core/gl/gl_scene.h) is the run's, not a node's:
 *   - the four nodes of gi.graph that draw it (gbuffer, two lightmaps, shadowmaps) over two
 *     frames upload it once: a live graph's holder (graph.h, ssg_live.gl) counts one;
 *   - a live graph keeps it across runs: a new camera runs gbuffer again on the same
 *     upload, and gbuffer's outputs then are a fresh load's with that camera, byte for
 *     byte (the kept scene draws as a fresh one does);
 *   - a fresh run and a node run alone free theirs (ASan's leak check in the sanitizer
 *     build; graph_run.c and exec.c clear it at their end). */
#include <string.h>

#include "check.h"
#include "graph/graph.h"
#include "ssgraph.h"

/* What gi.graph's scene users make; only they and their producers run, at small sizes. */
static const char *const wanted[] = {"g.depth", "lm.depth", "sm.maps", "lb.flux"};
static const char *const sets[] = {"lm.resolution=64", "lb.resolution=32", "lp.count=8",
                                   "sm.resolution=64"};
enum { WANTED = 4 };

static struct ssg_graph *load(struct ssg_diags *d)
{
    struct ssg_overrides ov = {.width = 64, .height = 48, .seed = -1, .backend = "gl",
                               .sets = sets, .set_count = 4, .outputs = wanted,
                               .output_count = WANTED};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load("graphs/gi.graph", &ov, &g, d), SSG_OK);
    return g;
}

/* Runs g for `frames` frames; out[] gets the wanted outputs (the caller destroys them). */
static enum ssg_err run(struct ssg_graph *g, int frames, struct ssg_image **out,
                        struct ssg_run_stats *stats, struct ssg_diags *d)
{
    struct ssg_run_options opt = {.frames = frames, .outputs = out, .stats = stats};
    return ssg_graph_run(g, &opt, d);
}

static int same_image(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && a->width == b->width && a->height == b->height &&
           a->channels == b->channels &&
           !memcmp(a->data, b->data, (size_t)a->width * (size_t)a->height *
                                         (size_t)a->channels * sizeof *a->data);
}

static int calls_of(const struct ssg_run_stats *s, const char *node)
{
    for (int i = 0; i < s->node_count; i++)
        if (!strcmp(s->nodes[i].name, node))
            return s->nodes[i].calls;
    return -1;
}

static void destroy_all(struct ssg_image **out)
{
    for (int k = 0; k < WANTED; k++)
        ssg_image_destroy(&out[k]);
}

/* The wanted outputs of a fresh load seen from `view`. */
static void fresh_from(const struct ssg_view *view, struct ssg_image **out)
{
    struct ssg_diags d = {0};
    struct ssg_graph *g = load(&d);
    if (g)
        CHECK_EQ(ssg_graph_set_view(g, view, &d), SSG_OK);
    if (g)
        CHECK_EQ(run(g, 1, out, NULL, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

int main(void)
{
    struct ssg_diags d = {0};
    struct ssg_graph *g = load(&d);
    if (!g || ssg_graph_keep(g, 0, &d) != SSG_OK) {
        ssg_diags_print(&d, stderr);
        ssg_graph_destroy(&g);
        return check_report();
    }
    struct ssg_image *out[WANTED] = {0}, *fresh[WANTED] = {0};
    CHECK_EQ(run(g, 2, out, NULL, &d), SSG_OK);
    CHECK_EQ(g->live->gl.uploads, 1); /* four nodes, two frames */
    CHECK(g->live->gl.scene != NULL);
    destroy_all(out);

    struct ssg_view home, moved;
    CHECK_EQ(ssg_graph_view(g, &home, &d), SSG_OK);
    moved = home;
    moved.position[0] += 0.3f;
    CHECK_EQ(ssg_graph_set_view(g, &moved, &d), SSG_OK);
    struct ssg_run_stats stats;
    CHECK_EQ(run(g, 1, out, &stats, &d), SSG_OK);
    CHECK_EQ(calls_of(&stats, "g"), 1); /* it drew the scene again ... */
    CHECK_EQ(g->live->gl.uploads, 1);   /* ... from the kept upload */
    ssg_run_stats_free(&stats);
    fresh_from(&moved, fresh);
    for (int k = 0; k < WANTED; k++)
        CHECK(same_image(out[k], fresh[k]));
    destroy_all(out);
    destroy_all(fresh);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
    return check_report();
}
