/* test_run_report.c - what a graph run reports through the public API (ssgraph.h) instead
 * of printing: the statistics (one entry per node of the run order, names and types as in
 * the graph, times that add up), the progress callback (on the caller's thread, rising to
 * done once per run of the long node) and the log callback (the files the run wrote); that
 * ssg_run_stats_free leaves a zeroed struct; and that a library loaded inside a node's run
 * (graph/profile.h: the OpenImageIO module met at the first JPEG) is reported as a load of
 * its own, not charged to the node, while one loaded before the run is charged to no node. */
#include <pthread.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "graph/profile.h"
#include "ssgraph.h"

enum { FRAMES = 2, MAX_LINES = 16 };

struct seen {
    pthread_t caller;
    int events, done, off_thread, out_of_order;
    double last_fraction;
    char last_instance[64], last_type[64];
    int lines;
    char line[MAX_LINES][1200];
};

static void on_progress(void *user, const struct ssg_progress_event *ev)
{
    struct seen *s = user;
    s->events++;
    s->off_thread += !pthread_equal(pthread_self(), s->caller);
    s->out_of_order += ev->fraction < s->last_fraction || ev->fraction > 1.0;
    s->last_fraction = ev->done ? 0.0 : ev->fraction; /* the next node run starts again */
    if (ev->done) {
        s->done++;
        CHECK_NEAR(ev->fraction, 1.0, 1e-12);
    }
    snprintf(s->last_instance, sizeof s->last_instance, "%s", ev->instance);
    snprintf(s->last_type, sizeof s->last_type, "%s", ev->type);
}

static void on_log(void *user, const char *line)
{
    struct seen *s = user;
    CHECK(pthread_equal(pthread_self(), s->caller));
    if (s->lines < MAX_LINES)
        snprintf(s->line[s->lines++], sizeof s->line[0], "%s", line);
}

static int logged(const struct seen *s, const char *line)
{
    for (int i = 0; i < s->lines; i++)
        if (!strcmp(s->line[i], line))
            return 1;
    return 0;
}

/* A graph of a pass, a long pass that reports progress, and two sinks, on a camera orbit:
   both passes read the camera, so each runs in every frame (a still camera would keep
   them after the first, core/graph/graph_redo.c). */
static void write_graph(const char *path)
{
    char cwd[900] = ".";
    FILE *f = fopen(path, "w");
    CHECK(f != NULL && getcwd(cwd, sizeof cwd) != NULL);
    if (!f)
        return;
    fprintf(f, "scene \"%s/examples/cornell_orbit.scene\"\nsize 24 16\n"
               "g   = gbuffer()\n"
               "ref = reference_ao(g.position, g.normal, rays=4, max_distance=0.5)\n"
               "c   = compare(ref.out, ref.out)\n"
               "out = write(ref.out, \"t\", depth=g.depth)\n",
            cwd);
    fclose(f);
}

static const char *type_of(const char *name)
{
    static const char *const pairs[][2] = {
        {"g", "gbuffer"}, {"ref", "reference_ao"}, {"c", "compare"}, {"out", "write"}};
    for (int i = 0; i < 4; i++)
        if (!strcmp(name, pairs[i][0]))
            return pairs[i][1];
    return "?";
}

static void check_nodes(const struct ssg_run_stats *st)
{
    double shares = 0;
    CHECK_EQ(st->node_count, 4);
    for (int i = 0; i < st->node_count; i++) {
        const struct ssg_run_node *n = &st->nodes[i];
        int sink = !strcmp(n->name, "c") || !strcmp(n->name, "out");
        CHECK(!strcmp(n->type, type_of(n->name)));
        CHECK(!strcmp(n->backend, "cpu"));
        CHECK(n->ms >= 0 && n->gpu_ms == 0 && n->transfer_ms == 0 && n->prepare_ms >= 0);
        CHECK_EQ(n->calls, sink ? 1 : FRAMES);
        CHECK(!strcmp(n->why, sink ? "sink" : "first run, camera moved"));
        CHECK(n->min_ms >= 0 && n->min_ms <= n->avg_ms && n->avg_ms <= n->max_ms);
        CHECK(sink ? n->share == 0 : n->share >= 0);
        shares += n->share;
    }
    CHECK(!strcmp(st->nodes[0].name, "g")); /* every other node reads it */
    if (st->frame_avg_ms > 0)
        CHECK_NEAR(shares, 1.0, 1e-9);
}

static void check_stats(const struct ssg_run_stats *st)
{
    CHECK_EQ(st->frames, FRAMES);
    CHECK(st->frame_min_ms >= 0 && st->frame_min_ms <= st->frame_avg_ms &&
          st->frame_avg_ms <= st->frame_max_ms);
    CHECK(st->frame_min_ms <= st->frame_median_ms && st->frame_median_ms <= st->frame_max_ms);
    CHECK(st->total_ms >= st->frame_avg_ms);
    CHECK_EQ(st->width, 24);
    CHECK_EQ(st->height, 16);
    CHECK(st->threads >= 1);
    CHECK(st->peak_pool_bytes >= 24 * 16 * sizeof(float));
    CHECK(st->gl == NULL);
    check_nodes(st);
    CHECK(st->metric_count >= 4); /* compare: rmse, mae, psnr, ssim */
    for (int i = 0; i < st->metric_count; i++)
        CHECK(!strcmp(st->metrics[i].node, "c"));
}

static void check_callbacks(const struct seen *s, const char *dir)
{
    char want[1200];
    CHECK_EQ(s->off_thread, 0);
    CHECK_EQ(s->out_of_order, 0);
    CHECK_EQ(s->done, FRAMES); /* reference_ao runs every frame */
    CHECK(s->events >= FRAMES && s->events <= FRAMES * 102);
    CHECK(!strcmp(s->last_instance, "ref"));
    CHECK(!strcmp(s->last_type, "reference_ao"));
    const char *files[] = {"t.exr", "t.png", "metrics.json"};
    for (int i = 0; i < 3; i++) {
        snprintf(want, sizeof want, "wrote %s/%s", dir, files[i]);
        CHECK(logged(s, want));
    }
}

/* A profile of one node that ran 10 ms up to now, 4 of them loading a library, and before
   it a load outside any run (at start-up). */
static void test_loads(void)
{
    struct ssg_load before[SSG_LOADS_MAX], after[SSG_LOADS_MAX];
    int known = ssg_loads(before, SSG_LOADS_MAX);
    double now = ssg_now_ms();
    ssg_load_note("start-up library", now - 1000.0, now - 990.0);
    ssg_load_note("node library", now - 6.0, now - 2.0);
    CHECK_EQ(ssg_loads(after, SSG_LOADS_MAX), known + 2);
    CHECK(!strcmp(after[known + 1].what, "node library"));
    CHECK_NEAR(after[known + 1].ms, 4.0, 1e-9);

    struct ssg_profile p;
    CHECK(ssg_profile_init(&p, 1));
    p.rows[0] = (struct ssg_profile_row){.name = "w", .type = "write", .backend = "cpu",
                                         .min = p.rows[0].min};
    struct ssg_node_timing t = {.ms = 10.0};
    CHECK(ssg_profile_add(&p, 0, &t));
    CHECK(ssg_profile_frame(&p, 0.0));
    struct ssg_run_stats st = {0};
    CHECK(ssg_profile_stats(&p, &t, &st));
    CHECK_EQ(st.node_count, 1);
    if (st.node_count == 1) {
        CHECK_NEAR(st.nodes[0].ms, 6.0, 1e-6); /* the start-up load is no node's */
        CHECK_NEAR(st.nodes[0].avg_ms, 6.0, 1e-6);
        CHECK_NEAR(st.nodes[0].max_ms, 6.0, 1e-6);
    }
    ssg_run_stats_free(&st);
    ssg_profile_free(&p);
}

int main(void)
{
    char dir[1024], graph[1100];
    test_loads();
    const char *tmp = getenv("SSG_TMP");
    snprintf(dir, sizeof dir, "%s", tmp ? tmp : CHECK_TMP_ROOT "/ssg_test_run_report");
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_make_dirs(dir, &d), SSG_OK);
    snprintf(graph, sizeof graph, "%s/report.graph", dir);
    write_graph(graph);

    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load(graph, NULL, &g, &d), SSG_OK);
    if (!g) {
        ssg_diags_print(&d, stderr);
        return check_report();
    }
    struct seen seen = {.caller = pthread_self()};
    struct ssg_run_stats st;
    memset(&st, 0xff, sizeof st); /* the run must zero it before filling */
    struct ssg_run_options opt = {.out_dir = dir, .frames = FRAMES, .stats = &st,
                                  .progress = on_progress, .log = on_log, .user = &seen};
    CHECK_EQ(ssg_graph_run(g, &opt, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    check_stats(&st);
    check_callbacks(&seen, dir);

    ssg_run_stats_free(&st);
    CHECK(st.nodes == NULL && st.metrics == NULL && st.node_count == 0 && st.frames == 0);
    ssg_run_stats_free(&st); /* a zeroed struct: nothing */
    ssg_run_stats_free(NULL);

    /* Without stats or callbacks the run is as quiet and still succeeds. */
    struct ssg_run_options bare = {.out_dir = dir};
    CHECK_EQ(ssg_graph_run(g, &bare, &d), SSG_OK);
    ssg_graph_destroy(&g);
    return check_report();
}
