/* test_complexity.c - the `complexity` node (Szentandrasi section 4.3, mapping in
 * nodes/complexity/complexity.c) on G-buffers ray-cast from planes (tests/planes.h).
 *
 * What is exact and why:
 * - On one plane every cell mean normal equals the plane's normal (a mean of equal floats,
 *   to an ulp) and every cell's mean point lies on the plane (a mean of points of a plane),
 *   so both gradients are float rounding (~1e-6, against thresholds 0.1 and 0.02): an open
 *   plane's interior gets exactly the lowest level, tilted or not, up to its horizon.
 * - Across a 90-degree crease |n_A - n_B| = sqrt(2) = 1.41 > normal_threshold + 1 /
 *   normal_gain = 0.6, so a cell next to a cell of the other face (or a cell holding both)
 *   gets t = 1, the highest level: the normal sum of the mixed cell is at least
 *   alpha sqrt(2) + (1 - alpha) sqrt(2) = 1.41 over its two neighbours across the crease.
 * - A depth step from 5 to 6 between fronto-parallel planes (equal normals) gives
 *   g_d >= 1 / 6 = 0.17 > depth_threshold + 1 / depth_gain = 0.12: the highest level,
 *   and with depth_gain = 0 the lowest (it is the depth term that found it). */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"

static const float LEVELS[4] = {20, 30, 40, 50};

/* Runs complexity on g; returns the count image (owned) or NULL. */
static struct ssg_image *complexity(const struct gbuf *g, const char *const *sets, int n)
{
    struct ssg_binding b[2] = {{"depth", g->depth}, {"normal", g->nrm}};
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("complexity", b, 2, sets, n, &f, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    return out.images[0];
}

static int is_level(float v)
{
    for (int i = 0; i < 4; i++)
        if (v == LEVELS[i])
            return 1;
    return 0;
}

/* 1 when every pixel of the (2 r + 1)^2 window around (x, y) that is inside the frame
   shows plane `which` (-1: background). */
static int window_is(const struct gbuf *g, int x, int y, int r, int which)
{
    for (int v = y - r; v <= y + r; v++)
        for (int u = x - r; u <= x + r; u++)
            if (u >= 0 && v >= 0 && u < W && v < H && g->which[(size_t)v * W + u] != which)
                return 0;
    return 1;
}

/* The corner with the crease on a cell boundary (H = 256: the edge projects between rows
   127 and 128) and inside a cell (H = 254: between 126 and 127). Interior: pixels whose
   window of +-2 s px is one plane (their cell and its neighbours are then one plane).
   Crease: pixels with the other face within 1 px. */
static void test_corner(int height, int resolutions, int *top_count)
{
    W = 96, H = height;
    struct scene s;
    corner_scene(&s);
    struct gbuf g;
    cast(&s, &g);
    char res[32];
    snprintf(res, sizeof res, "resolutions=%d", resolutions);
    const char *sets[] = {res};
    struct ssg_image *c = complexity(&g, sets, 1);
    const int reach = 2 * 4 << (resolutions - 1);
    int bad_level = 0, interior = 0, interior_low = 0, crease = 0, crease_top = 0, top = 0;
    for (int y = 0; c && y < H; y++)
        for (int x = 0; x < W; x++) {
            float v = c->data[(size_t)y * W + x];
            int which = g.which[(size_t)y * W + x];
            bad_level += !is_level(v);
            top += v == 50.0f;
            if (window_is(&g, x, y, reach, which)) {
                interior++;
                interior_low += v == 20.0f;
            }
            if (!window_is(&g, x, y, 1, which)) {
                crease++;
                crease_top += v == 50.0f;
            }
        }
    CHECK_EQ(bad_level, 0);
    CHECK(interior > W * H / 2);
    CHECK_EQ(interior_low, interior);
    CHECK(crease >= 2 * W);
    CHECK_EQ(crease_top, crease);
    *top_count = top;
    ssg_image_destroy(&c);
    release(&g);
}

/* A step: depth 5 left of the middle, 6 right of it, normals +z. */
static void test_depth_step(void)
{
    W = 64, H = 48;
    struct gbuf g = {ssg_image_create(W, H, 3), ssg_image_create(W, H, 3),
                     ssg_image_create(W, H, 1), calloc((size_t)W * H, sizeof(int))};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            g.depth->data[o] = x < W / 2 ? 5.0f : 6.0f;
            g.nrm->data[2 * (size_t)W * H + o] = 1.0f;
            g.which[o] = x < W / 2 ? 0 : 1;
        }
    struct ssg_image *c = complexity(&g, NULL, 0);
    const char *off[] = {"depth_gain=0"};
    struct ssg_image *n = complexity(&g, off, 1);
    int step = 0, step_top = 0, step_off = 0, interior = 0, interior_low = 0;
    for (int y = 0; c && n && y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            if (x == W / 2 - 1 || x == W / 2) {
                step++;
                step_top += c->data[o] == 50.0f;
                step_off += n->data[o] == 20.0f;
            } else if (window_is(&g, x, y, 8, g.which[o])) {
                interior++;
                interior_low += c->data[o] == 20.0f;
            }
        }
    CHECK_EQ(step, 2 * H);
    CHECK_EQ(step_top, step);
    CHECK_EQ(step_off, step);
    CHECK(interior > 0);
    CHECK_EQ(interior_low, interior);
    ssg_image_destroy(&c);
    ssg_image_destroy(&n);
    release(&g);
}

/* A floor below the horizon, the sky (background) above: a strongly tilted open plane
   and background everywhere else, so the whole frame is the lowest level, with every
   scale and two resolutions (the cells at the horizon are part floor, part sky; their
   mean point still lies on the floor). */
static void test_floor_and_background(void)
{
    W = 80, H = 64;
    struct scene s = {.count = 1};
    plane_at(&s.pl[0], 0, 1, 0, 0, -1, 0);
    struct gbuf g;
    cast(&s, &g);
    int background = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        background += g.which[i] < 0;
    CHECK(background > W * H / 4);
    static const char *scales[] = {"scale=1", "scale=2", "scale=4", "scale=8"};
    for (int k = 0; k < 4; k++) {
        const char *sets[] = {scales[k], "resolutions=2"};
        struct ssg_image *c = complexity(&g, sets, 2);
        int low = 0;
        for (size_t i = 0; c && i < (size_t)W * H; i++)
            low += c->data[i] == 20.0f;
        CHECK_EQ(low, W * H);
        ssg_image_destroy(&c);
    }
    release(&g);
}

/* Parameters that cannot be whole Halton periods or a grid are refused with their code. */
static void test_rejects(void)
{
    W = 16, H = 16;
    struct scene s = {.count = 1};
    plane_at(&s.pl[0], 0, 0, 1, 0, 0, -5);
    struct gbuf g;
    cast(&s, &g);
    struct ssg_binding b[2] = {{"depth", g.depth}, {"normal", g.nrm}};
    struct ssg_frame f = frame();
    const char *bad[][2] = {{"levels=[20, 35]", "period=10"}, {"levels=[30, 20]", "period=10"},
                            {"scale=3", "period=10"}};
    for (int k = 0; k < 3; k++) {
        struct ssg_diags diags = {0};
        struct ssg_outputs out;
        CHECK_EQ(ssg_node_run("complexity", b, 2, bad[k], 2, &f, &out, &diags), SSG_E_VALUE);
        ssg_outputs_release(&out);
    }
    /* Custom levels in another period are fine and used as given. */
    const char *ok[] = {"levels=[8, 16]", "period=8"};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    CHECK_EQ(ssg_node_run("complexity", b, 2, ok, 2, &f, &out, &diags), SSG_OK);
    if (out.count == 1)
        CHECK_EQ(out.images[0]->data[0], 8);
    ssg_outputs_release(&out);
    release(&g);
}

/* The same bytes for 1, 2 and 3 threads on an odd frame of many bands (151 x 133: 9 bands of
   16 pixel rows, the last of 5; with two grids, cell rows in bands of 4), the corner seen
   with a tilt so that levels change along both axes. The per-cell sums lie within one band
   (no sum crosses bands), so this guards the bands' cuts and what each band writes. */
static void test_threads(void)
{
    W = 151, H = 133;
    struct scene s = {.count = 2};
    plane_at(&s.pl[0], 0.2, 1, 1, 0, 0, -5);
    plane_at(&s.pl[1], -0.3, -1, 1, 0, 0, -5);
    struct gbuf g;
    cast(&s, &g);
    const char *sets[] = {"resolutions=2"};
    omp_set_num_threads(1);
    struct ssg_image *one = complexity(&g, sets, 1);
    int top = 0; /* the crease's top level, between the open faces' lowest */
    for (size_t i = 0; one && i < (size_t)W * H; i++)
        top += one->data[i] == 50.0f;
    CHECK(top > W && top < W * H / 2);
    for (int k = 0; one && k < 6; k++) {
        omp_set_num_threads(2 + k % 2);
        struct ssg_image *other = complexity(&g, sets, 1);
        CHECK(other && memcmp(one->data, other->data, sizeof(float) * W * H) == 0);
        ssg_image_destroy(&other);
    }
    ssg_image_destroy(&one);
    release(&g);
}

int main(void)
{
    int top1 = 0, top2 = 0, top_mid = 0;
    (void)count_not_one; /* planes.h helpers this test does not need */
    (void)mean_over;
    test_corner(256, 1, &top1);
    test_corner(254, 1, &top_mid);
    test_corner(256, 2, &top2);
    /* Two grids (scale 4 and 8) mark a wider band around the crease than one. */
    CHECK(top2 > top1);
    test_depth_step();
    test_floor_and_background();
    test_rejects();
    test_threads();
    return check_report();
}
