/* test_jitter.c - a graph's `jitter N` line (graph_time.c, docs/time.md): frame f's
 * sub-pixel offset is the Halton point (2, 3) of index f mod N + 1 less 0.5, in the
 * projection every node reads (ssg_frame_projection); none without the line. On a kept
 * graph with a still camera the G-buffer changes from frame to frame and repeats after N
 * frames, byte for byte; what reads no camera (rsm's light maps) still runs once in a
 * sequence; and the same frame run on its own gives the same bytes as in a sequence, on
 * the CPU and on GL. End to end: a surface pixel holds the point the unjittered projection
 * puts at its centre plus the offset, a still camera's motion stays exactly 0, and GL's
 * rasteriser sees the surfaces the CPU's rays do (it fails when the raster ignores the
 * offset: 92 of 1200 depths differ).
 * (The line's errors: test_graph.c.) */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene/radical_inverse.h"
#include "graph/graph.h"

static struct ssg_graph *load_on(const char *jitter_line, const char *backend)
{
    char text[512];
    snprintf(text, sizeof text, "include \"rsm.graph\"\n%s\nsize 40 30\n", jitter_line);
    struct ssg_overrides ov = {.seed = -1, .backend = backend};
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_load_text("graphs/jitter_test.graph", text, &ov, &g, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return g;
}

static struct ssg_graph *load(const char *jitter_line)
{
    return load_on(jitter_line, "cpu");
}

/* The offsets of frames 0 .. 9 under jitter 4, and the projection's principal point. */
static void test_sequence(void)
{
    struct ssg_graph *g = load("jitter 4");
    if (!g)
        return;
    struct ssg_time_step step;
    for (int f = 0; f < 10; f++) {
        ssg_time_begin(g, f, f == 0, 10, 0, &step);
        uint64_t i = (uint64_t)(f % 4) + 1;
        float jx = (float)(ssg_halton_radical_inverse(i, 2) - 0.5);
        float jy = (float)(ssg_halton_radical_inverse(i, 3) - 0.5);
        CHECK(g->frame.jitter_x == jx && g->frame.jitter_y == jy);
        struct ssg_projection p = ssg_frame_projection(&g->frame);
        CHECK(p.cx == 20.0f - jx && p.cy == 15.0f - jy);
        float ask[2] = {9, 9}; /* what an engine asks for before the frame (ssgraph.h) */
        struct ssg_diags d = {0};
        CHECK_EQ(ssg_graph_jitter_at(g, f, ask, &d), SSG_OK);
        CHECK(ask[0] == jx && ask[1] == jy);
        ssg_time_end(g, f);
    }
    /* the first four: (0, -1/6), (-1/4, 1/6), (1/4, -7/18), (-3/8, -1/18) */
    ssg_time_begin(g, 1, 1, 1, 0, &step);
    CHECK_NEAR(g->frame.jitter_x, -0.25, 1e-7);
    CHECK_NEAR(g->frame.jitter_y, 1.0 / 6.0, 1e-7);
    ssg_graph_destroy(&g);
    g = load("");
    if (!g)
        return;
    for (int f = 0; f < 3; f++) {
        ssg_time_begin(g, f, f == 0, 3, 0, &step);
        CHECK(g->frame.jitter_x == 0.0f && g->frame.jitter_y == 0.0f);
        float ask[2] = {9, 9};
        struct ssg_diags d = {0};
        CHECK_EQ(ssg_graph_jitter_at(g, f, ask, &d), SSG_OK);
        CHECK(ask[0] == 0.0f && ask[1] == 0.0f);
        CHECK_EQ(ssg_graph_jitter_at(g, -1, ask, &d), SSG_E_VALUE);
    }
    ssg_graph_destroy(&g);
}

static const struct ssg_run_node *node_of(const struct ssg_run_stats *s, const char *name)
{
    for (int i = 0; i < s->node_count; i++)
        if (!strcmp(s->nodes[i].name, name))
            return &s->nodes[i];
    return NULL;
}

/* A 5-frame sequence of a still camera: the G-buffer runs every frame (its pixels move),
   the light maps once. */
static void test_sequence_runs(void)
{
    struct ssg_graph *g = load("jitter 4");
    if (!g)
        return;
    struct ssg_diags d = {0};
    struct ssg_run_stats s = {0};
    struct ssg_run_options opt = {.frames = 5, .no_files = 1, .stats = &s};
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    const struct ssg_run_node *gb = node_of(&s, "g"), *lm = node_of(&s, "lm");
    CHECK(gb && gb->calls == 5);
    CHECK(lm && lm->calls == 1);
    ssg_run_stats_free(&s);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

static struct ssg_image *depth_at(struct ssg_graph *g, int frame)
{
    struct ssg_diags d = {0};
    struct ssg_image *im = NULL;
    struct ssg_run_options opt = {.no_files = 1};
    CHECK_EQ(ssg_graph_set_frame(g, frame, &d), SSG_OK);
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    CHECK_EQ(ssg_graph_output(g, "g.depth", &im, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return im;
}

static int same(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && !memcmp(a->data, b->data, sizeof(float) * (size_t)a->width * a->height);
}

/* A kept graph stepped through frames 0 .. 4: each frame's depth differs from the one
   before, frame 4 repeats frame 0, and a fresh graph run at frame 2 alone matches; on the
   CPU's ray caster and on GL's rasteriser alike. */
static void test_frames_repeat(const char *backend)
{
    struct ssg_graph *g = load_on("jitter 4", backend);
    if (!g)
        return;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    struct ssg_image *im[5];
    for (int f = 0; f < 5; f++)
        im[f] = depth_at(g, f);
    for (int f = 1; f < 5; f++)
        CHECK(!same(im[f], im[f - 1]));
    CHECK(same(im[4], im[0]));
    struct ssg_graph *fresh = load_on("jitter 4", backend);
    if (fresh) {
        CHECK_EQ(ssg_graph_keep(fresh, 0, &d), SSG_OK);
        struct ssg_image *two = depth_at(fresh, 2);
        CHECK(same(two, im[2]));
        ssg_image_destroy(&two);
        ssg_graph_destroy(&fresh);
    }
    for (int f = 0; f < 5; f++)
        ssg_image_destroy(&im[f]);
    ssg_graph_destroy(&g);
}

/* What the offset means, end to end on the CPU: in frame 1 of `jitter 4` every surface
   pixel (x, y) holds the point that the unjittered projection puts at (x + 0.5 + jx,
   y + 0.5 + jy); and with a still camera the motion is exactly 0 (both frames' positions
   are taken with this frame's offset: motion between unjittered positions). */
static void test_meaning(void)
{
    char text[256];
    snprintf(text, sizeof text, "include \"gi_temporal.graph\"\njitter 4\nsize 40 30\n");
    struct ssg_overrides ov = {.seed = -1, .backend = "cpu"};
    struct ssg_graph *g = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_graph_load_text("graphs/jitter_test.graph", text, &ov, &g, &d), SSG_OK);
    if (!g) {
        ssg_diags_print(&d, stderr);
        return;
    }
    CHECK_EQ(ssg_graph_keep(g, 0, &d), SSG_OK);
    struct ssg_image *first = depth_at(g, 0), *depth = depth_at(g, 1);
    struct ssg_image *pos = NULL, *motion = NULL;
    CHECK_EQ(ssg_graph_output(g, "g.position", &pos, &d), SSG_OK);
    CHECK_EQ(ssg_graph_output(g, "g.motion", &motion, &d), SSG_OK);
    const float jx = -0.25f, jy = 1.0f / 6.0f; /* index 2 of bases 2 and 3, less 0.5 */
    struct ssg_frame still = g->frame;
    still.jitter_x = still.jitter_y = 0.0f;
    struct ssg_projection p = ssg_frame_projection(&still);
    double worst = 0, moved = 0;
    int surfaces = 0;
    for (int y = 0; pos && motion && depth && y < 30; y++)
        for (int x = 0; x < 40; x++) {
            size_t i = (size_t)y * 40 + (size_t)x, n = 40 * 30;
            if (!(depth->data[i] > 0.0f))
                continue;
            float vx = pos->data[i], vy = pos->data[n + i], vz = pos->data[2 * n + i];
            double px = p.cx + p.f * vx / -vz, py = p.cy - p.f * vy / -vz;
            worst = fmax(worst, fmax(fabs(px - (x + 0.5 + jx)), fabs(py - (y + 0.5 + jy))));
            moved = fmax(moved, fmax(fabs(motion->data[i]), fabs(motion->data[n + i])));
            surfaces++;
        }
    CHECK(surfaces > 600);
    CHECK(worst < 1e-3);
    CHECK(moved == 0.0);
    CHECK(first && depth && memcmp(first->data, depth->data, sizeof(float) * 40 * 30));
    ssg_image_destroy(&first);
    ssg_image_destroy(&depth);
    ssg_image_destroy(&pos);
    ssg_image_destroy(&motion);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
}

/* GL's rasteriser decides which surface a pixel sees from the jittered projection too:
   its depth agrees with the CPU's ray caster at frame 1 of `jitter 4` but for a few
   silhouette pixels (a rasteriser that ignored the offset would differ along every edge). */
static void test_gl_raster(void)
{
    struct ssg_image *d[2] = {NULL, NULL};
    const char *backend[2] = {"cpu", "gl"};
    for (int b = 0; b < 2; b++) {
        struct ssg_graph *g = load_on("jitter 4", backend[b]);
        struct ssg_diags dg = {0};
        if (!g)
            return;
        CHECK_EQ(ssg_graph_keep(g, 0, &dg), SSG_OK);
        d[b] = depth_at(g, 1);
        ssg_graph_destroy(&g);
    }
    int differ = 0;
    for (size_t i = 0; d[0] && d[1] && i < 40 * 30; i++)
        differ += fabsf(d[0]->data[i] - d[1]->data[i]) > 1e-3f * (d[0]->data[i] + 1e-3f);
    printf("gl raster: %d of 1200 depths differ from the CPU's at frame 1\n", differ);
    CHECK(differ < 8);
    ssg_image_destroy(&d[0]);
    ssg_image_destroy(&d[1]);
}

int main(void)
{
    test_meaning();
    test_gl_raster();
    test_sequence();
    test_sequence_runs();
    test_frames_repeat("cpu");
    test_frames_repeat("gl");
    return check_report();
}
