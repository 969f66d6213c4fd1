/* test_timeline.c - runs of several frames along a camera path (docs/time.md):
 *   - determinism: every frame's EXR of a 3-frame sequence (write sequence=true, the
 *     camera path of examples/cornell_path.scene) has the same bytes with 1 and 2 threads;
 *   - the camera really moves: frames 0 and 2 differ, and frame 2 has the bytes of a
 *     one-frame run of a scene whose `camera` line is the path's camera at frame 2
 *     (ssg_graph_camera_at);
 *   - ssg_graph_set_frame: frame 2 run alone has the same bytes again, also on a kept
 *     graph (ssg_graph_keep) that ran frame 0 first (its camera readers run again);
 *   - history_reset: 1 in frame 0 and at a cut of the path, 0 between; prev_camera is the
 *     frame before's (ssg_time_begin, what the executor hands each node);
 *   - a scene without a path keeps its camera in every frame. */
#include <string.h>

#include "check.h"
#include "scratch.h"
#include "graph/graph.h"
#include "scene/camera_path.h"

#define SCENE "examples/cornell_path.scene"

/* 1 when the two files exist and hold the same bytes (compared a block at a time). */
static int same_file(const char *a, const char *b)
{
    FILE *x = fopen(a, "rb"), *y = fopen(b, "rb");
    int same = x && y;
    unsigned char bx[4096], by[4096];
    while (same) {
        size_t nx = fread(bx, 1, sizeof bx, x), ny = fread(by, 1, sizeof by, y);
        same = nx == ny && memcmp(bx, by, nx) == 0;
        if (nx < sizeof bx)
            break;
    }
    if (x)
        fclose(x);
    if (y)
        fclose(y);
    return same;
}

/* The whole of a text file, NUL-terminated, malloc'd; NULL when unreadable. */
static char *read_text(const char *path)
{
    FILE *f = fopen(path, "rb");
    char *text = f ? calloc(1, 1 << 16) : NULL;
    if (text && fread(text, 1, (1 << 16) - 1, f) == 0) {
        free(text);
        text = NULL;
    }
    if (f)
        fclose(f);
    return text;
}

/* graphs/ssao.graph on `scene` at 48x32, `frames` frames into dir; 0 on success. With
   first < 0: a kept graph (ssg_graph_keep) runs frame 0, then frame -first alone. */
static int run(const char *scene, int frames, int threads, int sequence, const char *dir,
               int first)
{
    const char *sets[] = {"out.sequence=true"};
    struct ssg_overrides ov = {.scene = scene, .width = 48, .height = 32, .seed = -1,
                               .sets = sets, .set_count = sequence};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load("graphs/ssao.graph", &ov, &g, &d);
    struct ssg_run_options ro = {.out_dir = dir, .threads = threads, .frames = frames};
    if (!e && first < 0) {
        e = ssg_graph_keep(g, 0, &d);
        if (!e)
            e = ssg_graph_run(g, &ro, &d); /* frame 0, its outputs kept */
        first = -first;
    }
    if (!e && first)
        e = ssg_graph_set_frame(g, first, &d);
    if (!e)
        e = ssg_graph_run(g, &ro, &d);
    if (e)
        ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
    return e;
}

static void test_sequence(void)
{
    const char *one = tmp_path("t1"), *two = tmp_path("t2");
    CHECK_EQ(run(SCENE, 3, 1, 1, one, 0), 0);
    CHECK_EQ(run(SCENE, 3, 2, 1, two, 0), 0);
    char a[1200], b[1200];
    for (int f = 0; f < 3; f++) {
        snprintf(a, sizeof a, "%s/ssao_%04d.exr", one, f);
        snprintf(b, sizeof b, "%s/ssao_%04d.exr", two, f);
        CHECK(same_file(a, b));
    }
    snprintf(a, sizeof a, "%s/ssao_0000.exr", one);
    snprintf(b, sizeof b, "%s/ssao_0002.exr", one);
    CHECK(!same_file(a, b));
    snprintf(a, sizeof a, "%s/ssao_0003.exr", one);
    FILE *none = fopen(a, "rb");
    CHECK(none == NULL); /* three frames, three files */
    if (none)
        fclose(none);
}

/* The path scene with its camera line replaced by frame 2's camera and the path dropped. */
static const char *still_scene(void)
{
    struct ssg_overrides ov = {.scene = SCENE, .width = 48, .height = 32, .seed = -1};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    struct ssg_view v = {0};
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), 0);
    CHECK_EQ(ssg_graph_camera_at(g, 2, &v, &d), 0);
    ssg_graph_destroy(&g);
    char *text = read_text(SCENE);
    CHECK(text != NULL);
    if (!text)
        return NULL;
    static char out[16384];
    int len = snprintf(out, sizeof out, "camera(position=[%.9g, %.9g, %.9g], target=[%.9g, "
                       "%.9g, %.9g], up=[%.9g, %.9g, %.9g], fov=%.9g, near=0.05, far=20)\n",
                       v.position[0], v.position[1], v.position[2], v.target[0],
                       v.target[1], v.target[2], v.up[0], v.up[1], v.up[2], v.fov_y);
    for (char *line = strtok(text, "\n"); line; line = strtok(NULL, "\n"))
        if (strncmp(line, "camera", 6) && strncmp(line, "frame_rate", 10))
            len += snprintf(out + len, sizeof out - (size_t)len, "%s\n", line);
    free(text);
    return write_file("still.scene", out);
}

/* 1 when the two EXRs hold the same pixels, bit for bit (their headers name different
   scene files), and their PNG previews the same bytes. */
static int same_pixels(const char *a, const char *b)
{
    struct ssg_image *x = NULL, *y = NULL;
    struct ssg_diags d = {0};
    int same = !ssg_image_read(a, NULL, &x, &d) && !ssg_image_read(b, NULL, &y, &d) &&
               x->width == y->width && x->height == y->height && x->channels == y->channels &&
               memcmp(x->data, y->data, (size_t)x->width * (size_t)x->height *
                                            (size_t)x->channels * sizeof(float)) == 0;
    ssg_image_destroy(&x), ssg_image_destroy(&y);
    char pa[1200], pb[1200];
    snprintf(pa, sizeof pa, "%.*s.png", (int)strlen(a) - 4, a);
    snprintf(pb, sizeof pb, "%.*s.png", (int)strlen(b) - 4, b);
    return same && same_file(pa, pb);
}

static void test_frame_camera(void)
{
    const char *scene = still_scene(), *dir = tmp_path("still"), *live = tmp_path("at2");
    /* frame 2 of a still camera: the same samples (halton turns them per frame,
       docs/time.md) at the path's camera of frame 2 */
    CHECK_EQ(run(scene, 1, 2, 1, dir, 2), 0);
    char a[1200], b[1200];
    snprintf(a, sizeof a, "%s/ssao_0002.exr", dir);
    snprintf(b, sizeof b, "%s/ssao_0002.exr", tmp_path("t1"));
    CHECK(same_pixels(a, b));
    CHECK_EQ(run(SCENE, 1, 2, 1, live, 2), 0); /* frame 2 alone (ssg_graph_set_frame) */
    snprintf(a, sizeof a, "%s/ssao_0002.exr", live);
    CHECK(same_file(a, b));
    /* a kept graph that ran frame 0: the camera's readers run again for frame 2 */
    const char *kept = tmp_path("kept");
    CHECK_EQ(run(SCENE, 1, 2, 1, kept, -2), 0);
    snprintf(a, sizeof a, "%s/ssao_0002.exr", kept);
    CHECK(same_file(a, b));
}

/* A two-piece path (a cut at 0.1 s: frame 3 at 30 fps) on a loaded graph: what each
   frame's nodes are told. */
static void test_history_reset(void)
{
    const char *scene = write_file("cut.scene",
                                   "camera_key(time=0, position=[0,1,4], target=[0,1,0])\n"
                                   "camera_key(time=0.05, position=[0.5,1,4], target=[0,1,0])\n"
                                   "camera_key(time=0.1, position=[2,1,3], target=[0,1,0], "
                                   "cut=true)\n"
                                   "camera_key(time=1, position=[3,1,3], target=[0,1,0])\n"
                                   "plane(size=[4,0,4])\n"
                                   "point_light(position=[0,2,0])\n");
    struct ssg_overrides ov = {.scene = scene, .width = 16, .height = 16, .seed = -1};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), 0);
    if (!g)
        return;
    const int expect_reset[6] = {1, 0, 0, 1, 0, 0};
    struct ssg_camera before = g->scene->camera;
    for (int f = 0; f < 6; f++) {
        struct ssg_time_step step;
        int moved = ssg_time_begin(g, f, f == 0, 6, 0, &step);
        CHECK_EQ(step.reset, expect_reset[f]);
        CHECK_EQ(moved, f > 0); /* every frame of this path moves the camera */
        CHECK_NEAR(step.time_s, f / 30.0, 1e-7);
        const struct ssg_camera *prev = step.reset ? &g->scene->camera : &before;
        CHECK(!ssg_camera_differs(&step.prev, prev));
        before = g->scene->camera;
        ssg_time_end(g, f);
    }
    /* a live graph: the next frame follows on, another frame is a cut */
    struct ssg_time_step step;
    ssg_time_begin(g, 6, 1, 1, 1, &step);
    CHECK_EQ(step.reset, 0);
    ssg_time_end(g, 6);
    ssg_time_begin(g, 2, 1, 1, 1, &step);
    CHECK_EQ(step.reset, 1);
    ssg_graph_destroy(&g);
}

static void test_static_camera(void)
{
    struct ssg_overrides ov = {.scene = "examples/cornell.scene", .width = 16, .height = 16,
                               .seed = -1};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    CHECK_EQ(ssg_graph_load("graphs/ssao.graph", &ov, &g, &d), 0);
    if (!g)
        return;
    struct ssg_camera c = g->scene->camera;
    for (int f = 0; f < 4; f++) {
        struct ssg_time_step step;
        CHECK_EQ(ssg_time_begin(g, f, f == 0, 4, 0, &step), 0);
        CHECK_EQ(step.reset, f == 0);
        CHECK(!ssg_camera_differs(&c, &g->scene->camera));
        ssg_time_end(g, f);
    }
    struct ssg_view v;
    CHECK_EQ(ssg_graph_camera_at(g, 7, &v, &d), 0);
    CHECK(v.position[2] == c.position[2]);
    CHECK_EQ(ssg_graph_camera_at(g, -1, &v, &d), SSG_E_VALUE);
    ssg_graph_destroy(&g);
}

int main(void)
{
    setup_tmp("timeline");
    test_sequence();
    test_frame_camera();
    test_history_reset();
    test_static_camera();
    return check_report();
}
