/* test_gbuffer_back.c - the `gbuffer` node's second depth layer, `back` (gbuffer.c), on
 * scenes with known answers, on both backends (the CPU's second Embree ray and GL's depth
 * peel must each meet them), then CPU/GL parity on the example scenes.
 *
 * Analytic cases, a camera at the origin looking down -z, so a ray's depth is its t:
 * - a closed box (z from -2.75 to -3.25) in front of a wall (z = -5): inside the box's
 *   silhouette back is where the ray leaves the box (3.25 through its back face, less
 *   where it leaves through a side: a slab test gives both), never the wall (the third
 *   layer); on the wall around it +inf (nothing behind the wall); background 0;
 * - a single plane: +inf wherever it is seen (the no-second-surface value);
 * - two parallel planes (z = -2 and z = -4): 4 where the near one is seen, +inf on the far.
 * Pixels whose ray passes within 0.2 % of an edge of the box or of a plane are left out
 * (a pixel centre on an edge belongs to either side). Expected depths hold to 1e-5
 * relative (float rounding of t). Also: an unbound `back` (NULL, as the executor leaves it
 * when nothing reads it) leaves every other output bit-identical, and a graph run binds
 * `back` only when a node reads it: its peak of pooled images is one scalar image larger
 * then (node.h's on_demand).
 *
 * Parity on the example scenes at 160 x 120: a pixel agrees when both backends give 0,
 * both +inf, or finite values within 2e-5 relative (measured worst on llvmpipe: 4.5e-6 on
 * the bunny, 3e-7 elsewhere: Moller-Trumbore against Embree's test on one triangle). Pixels where the two pick
 * different second surfaces (silhouettes and creases of the second layer, where the
 * rasteriser's fill rule and Embree's watertight test break a tie at a pixel centre
 * differently, and where the first layers already differ) are counted; none need be left
 * out on the panel, the table and the Cornell box, 3 of 19200 (0.0002) on the bunny; each
 * scene is held to 0.001. */
#include <string.h>

#include "check.h"
#include "gbuffer/gbuffer.h"
#include "scene_node.h"

extern const struct ssg_node_desc ssg_node_gbuffer;

enum { W = 64, H = 48 };
static const struct ssg_frame FRAME = {W, H, 60, 0.1f, 100, 1, 0, 0, 0};

static const char *const cam =
    "camera(position=[0, 0, 0], target=[0, 0, -1], up=[0, 1, 0], fov=60, near=0.1, far=100)\n"
    "m = material(albedo=[0.5, 0.5, 0.5])\n";

struct layers {
    struct ssg_image *out[SSG_GBUFFER_OUTPUTS];
};

static void layers_free(struct layers *l)
{
    for (int i = 0; i < SSG_GBUFFER_OUTPUTS; i++)
        ssg_image_destroy(&l->out[i]);
}

/* Every output of gbuffer on `backend`; with_back 0 leaves `back` unbound. */
static struct layers render(const struct ssg_scene *s, const struct ssg_frame *f,
                            enum ssg_backend backend, int with_back)
{
    struct layers l = {{0}};
    for (int i = 0; i < SSG_GBUFFER_OUTPUTS; i++) {
        int scalar = i == SSG_GBUFFER_OUT_DEPTH || i == SSG_GBUFFER_OUT_BACK;
        if (i != SSG_GBUFFER_OUT_BACK || with_back)
            l.out[i] = ssg_image_create(f->width, f->height, scalar ? 1 : 3);
    }
    void *params = node_params(&ssg_node_gbuffer, NULL, 0);
    CHECK_EQ(node_run_scene(&ssg_node_gbuffer, s, f, params, NULL, l.out, backend), SSG_OK);
    free(params);
    return l;
}

/* The ray of pixel (x, y) with view z = -1 (camera at the origin, no rotation). */
static void pixel_dir(int x, int y, float d[3])
{
    struct ssg_projection p = ssg_frame_projection(&FRAME);
    d[0] = ((float)x + 0.5f - p.cx) / p.f;
    d[1] = -((float)y + 0.5f - p.cy) / p.f;
    d[2] = -1.0f;
}

/* An axis-aligned box [lo, hi] on the ray t d: entry and exit t (slab test), and how close
   the ray passes to an edge, relative (0 on an edge; < 0 a miss). */
static double slab(const float d[3], const double lo[3], const double hi[3], double *t0,
                   double *t1)
{
    *t0 = 0, *t1 = INFINITY;
    for (int a = 0; a < 3; a++) {
        double u = lo[a] / d[a], v = hi[a] / d[a];
        *t0 = fmax(*t0, fmin(u, v));
        *t1 = fmin(*t1, fmax(u, v));
    }
    if (!(*t0 < *t1))
        return -1;
    /* At entry and exit the point lies on one face (its own axis is at distance 0): the
       margin is its distance to that face's border, the second smallest of the three. */
    double margin = INFINITY;
    for (int e = 0; e < 2; e++) {
        double r[3];
        for (int a = 0; a < 3; a++) {
            double p = (e ? *t1 : *t0) * d[a];
            r[a] = fmin(p - lo[a], hi[a] - p) / (hi[a] - lo[a]);
        }
        double lo2 = fmin(r[0], r[1]), hi2 = fmax(r[0], r[1]);
        double second = r[2] <= lo2 ? lo2 : fmin(r[2], hi2);
        margin = fmin(margin, second);
    }
    return margin;
}

/* The square |x|, |y| <= half at depth z: 1 inside, 0 outside, -1 within the margin. */
static int on_square(const float d[3], double z, double half)
{
    double m = fmin(half - fabs(z * d[0]), half - fabs(z * d[1])) / half;
    return fabs(m) < 2e-3 ? -1 : m > 0;
}

static int near_rel(double got, double want)
{
    if (isinf(want))
        return isinf(got) && got > 0;
    return fabs(got - want) <= 1e-5 * fmax(1.0, fabs(want));
}

struct expect {
    double depth, back; /* < 0: leave the pixel out */
};

/* Checks depth and back of every pixel the scene function decides; prints the counts. */
static void check_layers(const char *label, const struct layers *l,
                         struct expect (*want)(const float d[3]))
{
    int bad = 0, checked = 0, inf = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float d[3];
            pixel_dir(x, y, d);
            struct expect e = want(d);
            if (e.depth < 0)
                continue;
            size_t i = (size_t)y * W + (size_t)x;
            double gd = l->out[SSG_GBUFFER_OUT_DEPTH]->data[i];
            double gb = l->out[SSG_GBUFFER_OUT_BACK]->data[i];
            int ok = near_rel(gd, e.depth) && near_rel(gb, e.back);
            if (!ok && bad++ < 5)
                fprintf(stderr, "%s: pixel (%d, %d) depth %g back %g, expected %g %g\n",
                        label, x, y, gd, gb, e.depth, e.back);
            checked++;
            inf += isinf(e.back);
        }
    fprintf(stderr, "%s: %d pixels checked (%d with back +inf), %d wrong\n", label, checked,
            inf, bad);
    CHECK_EQ(bad, 0);
    CHECK(checked > W * H / 2);
}

static struct expect box_wall(const float d[3])
{
    const double lo[3] = {-0.5, -0.5, -3.25}, hi[3] = {0.5, 0.5, -2.75};
    double t0, t1, m = slab(d, lo, hi, &t0, &t1);
    if (m >= 0 && m < 2e-3)
        return (struct expect){-1, -1};
    if (m > 0)
        return (struct expect){t0, t1};
    int wall = on_square(d, 5.0, 2.0);
    return wall < 0 ? (struct expect){-1, -1}
                    : wall ? (struct expect){5.0, INFINITY} : (struct expect){0, 0};
}

static struct expect one_plane(const float d[3])
{
    int wall = on_square(d, 5.0, 2.0);
    return wall < 0 ? (struct expect){-1, -1}
                    : wall ? (struct expect){5.0, INFINITY} : (struct expect){0, 0};
}

static struct expect two_planes(const float d[3])
{
    int near = on_square(d, 2.0, 0.5), far = on_square(d, 4.0, 2.0);
    if (near < 0 || far < 0)
        return (struct expect){-1, -1};
    return near ? (struct expect){2.0, 4.0}
                : far ? (struct expect){4.0, INFINITY} : (struct expect){0, 0};
}

static void analytic(const char *name, const char *shapes, struct expect (*want)(const float *))
{
    char text[1200];
    snprintf(text, sizeof text, "%s%s", cam, shapes);
    struct ssg_scene *s = scene_from_text(name, text);
    if (!s)
        return;
    static const enum ssg_backend backends[2] = {SSG_BACKEND_CPU, SSG_BACKEND_GL};
    for (int b = 0; b < 2; b++) {
        char label[96];
        snprintf(label, sizeof label, "%s %s", name, b ? "gl" : "cpu");
        struct layers l = render(s, &FRAME, backends[b], 1);
        check_layers(label, &l, want);
        layers_free(&l);
    }
    ssg_scene_destroy(&s);
}

/* `back` unbound: the first layer's outputs are the very bits they are with it. */
static void unbound_changes_nothing(void)
{
    char text[1200];
    snprintf(text, sizeof text, "%s%s", cam,
             "box(material=m, center=[0, 0, -3], size=[1, 1, 0.5])\n"
             "plane(material=m, center=[0, 0, -5], normal=[0, 0, 1], size=[4, 0, 4])\n"
             "point_light(position=[0, 1, -1], color=[1, 1, 1], intensity=2)\n");
    struct ssg_scene *s = scene_from_text("back_unbound", text);
    if (!s)
        return;
    struct layers with = render(s, &FRAME, SSG_BACKEND_CPU, 1);
    struct layers without = render(s, &FRAME, SSG_BACKEND_CPU, 0);
    for (int i = 0; i < SSG_GBUFFER_OUT_BACK; i++) {
        const struct ssg_image *a = with.out[i], *b = without.out[i];
        CHECK(!memcmp(a->data, b->data,
                      sizeof(float) * (size_t)a->width * a->height * a->channels));
    }
    layers_free(&with);
    layers_free(&without);
    ssg_scene_destroy(&s);
}

/* Peak pooled bytes of a graph writing gbuffer's depth, and its back when read_back. */
static size_t peak_bytes(int read_back)
{
    char path[1100], out[1100]; /* scene_node_path's buffer is reused by each call */
    snprintf(path, sizeof path, "%s", scene_node_path(read_back ? "reads_back.graph"
                                                                : "no_back.graph"));
    snprintf(out, sizeof out, "%s", scene_node_path("peak"));
    FILE *f = fopen(path, "w");
    if (!f)
        return 0;
    fprintf(f, "scene \"%s/examples/cornell.scene\"\nsize 64 48\ng = gbuffer()\n"
            "out = write(g.depth, \"d\", png=0%s)\n", SSG_SOURCE_DIR,
            read_back ? ", back=g.back" : "");
    fclose(f);
    struct ssg_run_stats stats = {0};
    struct ssg_overrides ov = {.seed = -1};
    struct ssg_run_options opt = {.out_dir = out, .stats = &stats};
    struct ssg_diags d = {0};
    struct ssg_graph *g = NULL;
    enum ssg_err e = ssg_graph_load(path, &ov, &g, &d);
    if (!e)
        e = ssg_graph_run(g, &opt, &d);
    ssg_diags_print(&d, stderr);
    ssg_graph_destroy(&g);
    CHECK_EQ(e, SSG_OK);
    size_t peak = stats.peak_pool_bytes;
    ssg_run_stats_free(&stats);
    return peak;
}

static void bound_only_when_read(void)
{
    size_t without = peak_bytes(0), with = peak_bytes(1);
    fprintf(stderr, "peak pooled images: %zu bytes without a reader of back, %zu with\n",
            without, with);
    CHECK_EQ(with - without, 64 * 48 * sizeof(float));
}

/* 1 when the backends agree on pixel i's second layer (see the file comment). */
static int agree(float cpu, float gl)
{
    if (cpu == 0.0f || gl == 0.0f || isinf(cpu) || isinf(gl))
        return cpu == gl;
    return fabs((double)cpu - gl) <= 2e-5 * fabs((double)cpu);
}

static void parity(const char *scene_path, double max_fraction)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(scene_path, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!s)
        return;
    struct ssg_frame f = {160, 120, s->camera.fov_y, s->camera.near_z, s->camera.far_z, 1, 0, 0, 0};
    struct layers c = render(s, &f, SSG_BACKEND_CPU, 1), g = render(s, &f, SSG_BACKEND_GL, 1);
    size_t n = (size_t)f.width * (size_t)f.height, other = 0, inf = 0;
    double worst = 0;
    const float *cb = c.out[SSG_GBUFFER_OUT_BACK]->data, *gb = g.out[SSG_GBUFFER_OUT_BACK]->data;
    for (size_t i = 0; i < n; i++) {
        if (!agree(cb[i], gb[i])) {
            other++;
            continue;
        }
        inf += isinf(cb[i]);
        if (cb[i] > 0.0f && !isinf(cb[i]))
            worst = fmax(worst, fabs((double)cb[i] - gb[i]) / cb[i]);
    }
    double fraction = (double)other / (double)n;
    fprintf(stderr, "parity back %-28s other surface %zu px = %.4f (tol %.4f), +inf %zu px, "
            "worst rel %.3g\n", scene_path, other, fraction, max_fraction, inf, worst);
    CHECK(fraction <= max_fraction);
    layers_free(&c);
    layers_free(&g);
    ssg_scene_destroy(&s);
}

int main(void)
{
    analytic("back_box_wall",
             "box(material=m, center=[0, 0, -3], size=[1, 1, 0.5])\n"
             "plane(material=m, center=[0, 0, -5], normal=[0, 0, 1], size=[4, 0, 4])\n",
             box_wall);
    analytic("back_one_plane",
             "plane(material=m, center=[0, 0, -5], normal=[0, 0, 1], size=[4, 0, 4])\n",
             one_plane);
    analytic("back_two_planes",
             "plane(material=m, center=[0, 0, -2], normal=[0, 0, 1], size=[1, 0, 1])\n"
             "plane(material=m, center=[0, 0, -4], normal=[0, 0, 1], size=[4, 0, 4])\n",
             two_planes);
    unbound_changes_nothing();
    bound_only_when_read();
    parity("examples/thin_panel.scene", 0.001);
    parity("examples/table.scene", 0.001);
    parity("examples/cornell.scene", 0.001);
    parity("examples/bunny.scene", 0.001);
    return check_report();
}
