/* test_reference_ao.c - the `reference_ao` node against the closed forms of
 * docs/analytic.md, on scenes written here as .scene files into SSG_TMP.
 *
 * "Infinite" planes are 1000 x 1000 scene units, centred near the tested points (which
 * lie within 1.5 units of the origin): a ray would have to travel about 500 units to see
 * past an edge, which only the tests that lift the distance limit allow, and there the
 * escaping fraction is below 1e-5 (far below their tolerances).
 *
 * The G-buffer fed to the node is made here: world points and normals, turned into view
 * space with ssg_camera_view_matrix of a camera that is deliberately not axis-aligned, so
 * the node's view -> world transform is exercised. The node traces from o = p + e (n + v)
 * (v the unit vector from p to the camera, reference_ao.c), so its exact answer is the
 * obscurance of o; the expected values below are the closed forms evaluated at o (for
 * the default e = 1e-3 that moves them by ~1e-3, within the tolerances anyway).
 *
 * Tolerances (docs/analytic.md case 5): a pixel's estimate from N rays has standard error at
 * most sqrt(V (1 - V) / N), and the mean over P pixels at most sqrt(sum V (1 - V)) /
 * (P sqrt N); both are checked within 4 standard errors. (The node's stratified samples
 * do better than independent ones; the bound holds a fortiori. Sampling is
 * deterministic, so a pass is reproducible, not lucky.) Values that are exactly 0 or 1
 * (nothing or everything within reach) are checked exactly. */
#include <float.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "reference_ao/reference_ao.h"
#include "scenes.h"

extern const struct ssg_node_desc ssg_node_reference_ao;

enum { W = 16, H = 8, P = W * H };

/* A camera off every axis, above and in front of the tested region (x > 0 side). */
static const char *oblique_camera =
    "camera(position=[2.5, 1.7, 3.1], target=[0, 0.2, 0], up=[0, 1, 0], fov=50)\n";

static const char *material = "m = material(albedo=[0.5, 0.5, 0.5])\n";

static const char *floor_plane =
    "plane(material=m, center=[0, 0, 0], normal=[0, 1, 0], size=[1000, 0, 1000])\n";

/* Points of one test: world positions and normals, background where fg is 0. */
struct points {
    int fg[P];
    double p[P][3], n[P][3];
};

/* What the node is given and what it should trace from. */
struct input {
    struct ssg_image *pos, *nrm;
    double o[P][3]; /* the ray origin the node documents, world */
};

/* The test's scene: camera, the material m, then the shapes. */
static struct ssg_scene *load_scene(const char *name, const char *camera, const char *shapes)
{
    char text[2000];
    snprintf(text, sizeof text, "%s%s%s", camera, material, shapes);
    return scene_from_text(name, text);
}

/* View-space images of the points, and the documented origins o = p + e (n + v). */
static void make_input(const struct ssg_scene *s, const struct points *pts, double offset,
                       struct input *in)
{
    float m[16];
    ssg_camera_view_matrix(&s->camera, m);
    in->pos = ssg_image_create(W, H, 3);
    in->nrm = ssg_image_create(W, H, 3);
    for (int i = 0; i < P; i++) {
        if (!pts->fg[i])
            continue; /* background: position 0, normal 0 */
        const double *p = pts->p[i], *n = pts->n[i];
        double v[3], len = 0, scale = 0;
        for (int r = 0; r < 3; r++) {
            double pv = m[12 + r], nv = 0;
            for (int k = 0; k < 3; k++) {
                pv += m[4 * k + r] * p[k];
                nv += m[4 * k + r] * n[k];
            }
            ssg_image_plane(in->pos, r)[i] = (float)pv;
            ssg_image_plane(in->nrm, r)[i] = (float)nv;
            v[r] = s->camera.position[r] - p[r];
            len += v[r] * v[r];
            scale = fmax(scale, fabs(p[r]));
        }
        /* the node's floor on the offset stays below it for these small coordinates */
        CHECK(1024.0 * FLT_EPSILON * fmax(scale, sqrt(len)) < offset);
        for (int r = 0; r < 3; r++)
            in->o[i][r] = p[r] + offset * (n[r] + v[r] / sqrt(len));
    }
}

static void free_input(struct input *in)
{
    ssg_image_destroy(&in->pos);
    ssg_image_destroy(&in->nrm);
}

/* Runs the node the way the executor does (scenes.h). */
static enum ssg_err run(const struct ssg_scene *s, const struct input *in, int rays,
                        double max_distance, double offset, uint64_t seed,
                        struct ssg_image **out)
{
    struct ssg_frame frame = {W, H, 50, 0.05f, 100, seed, 0, 0, 0};
    struct ssg_reference_ao_params p;
    ssg_params_defaults(ssg_node_reference_ao.params, &p);
    p.rays = rays;
    p.max_distance = (float)max_distance;
    p.offset = (float)offset;
    *out = undefined_image(W, H, 1);
    const struct ssg_image *ins[2] = {in->pos, in->nrm};
    return run_prepared(&ssg_node_reference_ao, s, &frame, &p, ins, out);
}

/* Background pixels are 1; every foreground pixel equals want exactly. */
static void check_exact(const struct ssg_image *out, const struct points *pts, float want)
{
    int wrong = 0;
    for (int i = 0; i < P; i++)
        wrong += out->data[i] != (pts->fg[i] ? want : 1.0f);
    CHECK_EQ(wrong, 0);
}

/* Per pixel within 4 standard errors of want[i], and the mean within 4 of its own. */
static void check_stat(const struct ssg_image *out, const struct points *pts,
                       const double *want, int rays)
{
    double sum = 0, sum_want = 0, var = 0;
    int count = 0, wrong = 0;
    for (int i = 0; i < P; i++) {
        if (!pts->fg[i]) {
            wrong += out->data[i] != 1.0f;
            continue;
        }
        double v = want[i] * (1.0 - want[i]);
        if (fabs(out->data[i] - want[i]) > 4.0 * sqrt(v / rays)) {
            fprintf(stderr, "pixel %d: %.5f, expected %.5f\n", i, out->data[i], want[i]);
            wrong++;
        }
        sum += out->data[i], sum_want += want[i], var += v, count++;
    }
    CHECK_EQ(wrong, 0);
    CHECK(count > 0);
    CHECK_NEAR(sum / count, sum_want / count, 4.0 * sqrt(var / rays) / count);
}

/* Floor points on a grid over [-0.5, 0.5]^2 (x, z), normal up; two background pixels. */
static void floor_grid(struct points *pts, double x_fixed, int fix_x)
{
    memset(pts, 0, sizeof *pts);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            int i = y * W + x;
            pts->fg[i] = i != 5 && i != P - 3;
            pts->p[i][0] = fix_x ? x_fixed : -0.5 + (x + 0.5) / W;
            pts->p[i][2] = -0.5 + (y + 0.5 + (fix_x ? x * H : 0)) / (fix_x ? P : H);
            pts->n[i][1] = 1.0;
        }
}

/* docs/analytic.md case 2: V = (h / D)^2 under a parallel ceiling at height h (D > h). */
static double ceiling_v(double h, double d)
{
    return d > h ? (h / d) * (h / d) : 1.0;
}

/* docs/analytic.md case 3: a point at distance a from an infinitely tall wall. */
static double wall_v(double a, double d)
{
    double c = a / d;
    return c >= 1.0 ? 1.0 : 1.0 - (acos(c) - c * sqrt(1.0 - c * c)) / M_PI;
}

static void test_open_plane(void)
{
    struct ssg_scene *s = load_scene("open", oblique_camera, floor_plane);
    if (!s)
        return;
    struct points pts;
    struct input in;
    struct ssg_image *out = NULL;
    floor_grid(&pts, 0, 0);
    make_input(s, &pts, 1e-3, &in);
    const double distances[] = {0.5, 1e4};
    for (int k = 0; k < 2; k++) {
        CHECK_EQ(run(s, &in, 256, distances[k], 1e-3, 1, &out), SSG_OK);
        check_exact(out, &pts, 1.0f);
        ssg_image_destroy(&out);
    }
    free_input(&in);
    ssg_scene_destroy(&s);
}

static void test_ceiling(void)
{
    const double h = 0.5;
    struct ssg_scene *s = load_scene("ceiling", oblique_camera,
        "plane(material=m, center=[0, 0, 0], normal=[0, 1, 0], size=[1000, 0, 1000])\n"
        "plane(material=m, center=[0, 0.5, 0], normal=[0, -1, 0], size=[1000, 0, 1000])\n");
    if (!s)
        return;
    struct points pts;
    struct input in;
    struct ssg_image *out = NULL;
    double want[P];
    floor_grid(&pts, 0, 0);
    make_input(s, &pts, 1e-3, &in);
    CHECK_NEAR(ceiling_v(0.5, 1), 0.25, 1e-12); /* the examples of docs/analytic.md */
    CHECK_NEAR(ceiling_v(0.5, 2), 0.0625, 1e-12);
    const double distances[] = {1.0, 2.0};
    for (int k = 0; k < 2; k++) {
        const int rays = 1024;
        for (int i = 0; i < P; i++) /* the ceiling seen from o is h - o.y away */
            want[i] = ceiling_v(h - in.o[i][1], distances[k]);
        CHECK_EQ(run(s, &in, rays, distances[k], 1e-3, 1, &out), SSG_OK);
        check_stat(out, &pts, want, rays);
        ssg_image_destroy(&out);
    }
    /* nothing within reach below the ceiling (o is at most 2e above the floor) */
    CHECK_EQ(run(s, &in, 256, h - 3e-3, 1e-3, 1, &out), SSG_OK);
    check_exact(out, &pts, 1.0f);
    ssg_image_destroy(&out);
    free_input(&in);
    ssg_scene_destroy(&s);
}

static const char *wall_shapes =
    "plane(material=m, center=[0, 0, 0], normal=[0, 1, 0], size=[1000, 0, 1000])\n"
    "plane(material=m, center=[0, 0, 0], normal=[1, 0, 0], size=[1000, 0, 1000])\n";

static void test_wall(void)
{
    struct ssg_scene *s = load_scene("wall", oblique_camera, wall_shapes);
    if (!s)
        return;
    struct points pts;
    struct input in;
    struct ssg_image *out = NULL;
    double want[P];
    CHECK_NEAR(wall_v(0.3, 0.5), 0.8576, 5e-5); /* the examples of docs/analytic.md */
    CHECK_NEAR(wall_v(0.3, 1.0), 0.6881, 5e-5);
    floor_grid(&pts, 0.3, 1); /* every point 0.3 from the wall, z spread over [-0.5, 0.5] */
    make_input(s, &pts, 1e-3, &in);
    const double distances[] = {0.5, 1.0};
    for (int k = 0; k < 2; k++) {
        const int rays = 1024;
        for (int i = 0; i < P; i++) /* o.x: the wall seen from o; o.y does not matter */
            want[i] = wall_v(in.o[i][0], distances[k]);
        CHECK_EQ(run(s, &in, rays, distances[k], 1e-3, 1, &out), SSG_OK);
        check_stat(out, &pts, want, rays);
        ssg_image_destroy(&out);
    }
    free_input(&in);
    ssg_scene_destroy(&s);
    /* The inner edge (a = 0) without a distance limit: V = 1/2. The points lie on the
       wall's plane too, exactly (an axis-aligned camera makes view -> world exact), as on
       the Cornell box's receding edges: only the move towards the camera keeps their rays
       from hitting that plane at t = 0. */
    s = load_scene("edge", "camera(position=[0.5, 2, 0], target=[0.5, 0, 0], "
                   "up=[0, 0, -1], fov=50)\n", wall_shapes);
    if (!s)
        return;
    floor_grid(&pts, 0.0, 1);
    make_input(s, &pts, 1e-3, &in);
    for (int i = 0; i < P; i++)
        want[i] = 0.5;
    CHECK_EQ(run(s, &in, 1024, 1e4, 1e-3, 1, &out), SSG_OK);
    check_stat(out, &pts, want, 1024);
    ssg_image_destroy(&out);
    free_input(&in);
    ssg_scene_destroy(&s);
}

/* docs/analytic.md case 4, seen by a camera straight above the floor centre (so o = p + 2e n
   exactly there): nothing within L/2, everything within sqrt(3/2) L. */
static void test_box(double side)
{
    char camera[200], shapes[200];
    snprintf(camera, sizeof camera, "camera(position=[0, %g, 0], target=[0, 0, 0], "
             "up=[0, 0, -1], fov=50)\n", 0.8 * side);
    snprintf(shapes, sizeof shapes, "box(material=m, center=[0, %g, 0], size=[%g, %g, %g])\n",
             0.5 * side, side, side, side);
    struct ssg_scene *s = load_scene("box", camera, shapes);
    if (!s)
        return;
    struct points pts;
    struct input in;
    struct ssg_image *out = NULL;
    memset(&pts, 0, sizeof pts);
    for (int i = 0; i < P; i++) { /* one point, 126 different rotations of the samples */
        pts.fg[i] = i != 5 && i != P - 3;
        pts.n[i][1] = 1.0;
    }
    make_input(s, &pts, 1e-3, &in);
    CHECK_EQ(run(s, &in, 1024, 0.5 * side, 1e-3, 1, &out), SSG_OK);
    check_exact(out, &pts, 1.0f);
    ssg_image_destroy(&out);
    CHECK_EQ(run(s, &in, 1024, sqrt(1.5) * side, 1e-3, 1, &out), SSG_OK);
    check_exact(out, &pts, 0.0f);
    ssg_image_destroy(&out);
    free_input(&in);
    ssg_scene_destroy(&s);
}

/* Same seed: same bytes; another seed: other bytes; 1 and 2 threads: same bytes. */
static void test_determinism(void)
{
    struct ssg_scene *s = load_scene("wall_det", oblique_camera, wall_shapes);
    if (!s)
        return;
    struct points pts;
    struct input in;
    struct ssg_image *a = NULL, *b = NULL, *c = NULL, *one = NULL, *two = NULL;
    floor_grid(&pts, 0.3, 1);
    make_input(s, &pts, 1e-3, &in);
    CHECK_EQ(run(s, &in, 64, 1.0, 1e-3, 1, &a), SSG_OK);
    CHECK_EQ(run(s, &in, 64, 1.0, 1e-3, 1, &b), SSG_OK);
    CHECK_EQ(run(s, &in, 64, 1.0, 1e-3, 2, &c), SSG_OK);
    CHECK_EQ(memcmp(a->data, b->data, sizeof(float) * P), 0);
    CHECK(memcmp(a->data, c->data, sizeof(float) * P) != 0);
    int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    CHECK_EQ(run(s, &in, 64, 1.0, 1e-3, 7, &one), SSG_OK);
    omp_set_num_threads(2);
    CHECK_EQ(run(s, &in, 64, 1.0, 1e-3, 7, &two), SSG_OK);
    omp_set_num_threads(threads);
    CHECK_EQ(memcmp(one->data, two->data, sizeof(float) * P), 0);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&c);
    ssg_image_destroy(&one);
    ssg_image_destroy(&two);
    free_input(&in);
    ssg_scene_destroy(&s);
}

/* No scene, bad parameters, mismatched inputs: located errors, no crash. */
static void test_errors(void)
{
    struct points pts;
    struct input in;
    struct ssg_image *out = NULL;
    struct ssg_scene *s = load_scene("open_err", oblique_camera, floor_plane);
    if (!s)
        return;
    floor_grid(&pts, 0, 0);
    make_input(s, &pts, 1e-3, &in);
    CHECK_EQ(run(NULL, &in, 16, 0.5, 1e-3, 1, &out), SSG_E_SCENE);
    ssg_image_destroy(&out);
    /* Out-of-range parameters are refused where they are read, by the table's ranges. */
    const char *bad[] = {"rays=0", "rays=65537", "max_distance=0", "offset=-1"};
    for (int i = 0; i < 4; i++) {
        struct ssg_reference_ao_params p;
        struct ssg_diags diags = {0};
        ssg_params_defaults(ssg_node_reference_ao.params, &p);
        CHECK_EQ(ssg_param_set_text(ssg_node_reference_ao.params, &p, bad[i], "<test>",
                                    "reference_ao", &diags),
                 SSG_E_RANGE);
    }
    struct ssg_shape shapes[2] = {{W, H, 3, SSG_T_VECTOR}, {W, H, 3, SSG_T_VECTOR}};
    check_sizes(&ssg_node_reference_ao, shapes, 1, 1, 1);
    free_input(&in);
    ssg_scene_destroy(&s);
}

/* Shading normals that lean past the surface (smooth-shaded meshes at grazing angles):
   points on a small floating square whose given normal is tilted by alpha from its face.
   A direction below the square's plane enters the surface, so it is blocked; nothing else
   is in the scene, so every direction above it is open. Projected onto the shading
   normal's disk (Malley), the blocked directions are the points with x > 0 outside the
   ellipse x^2 / cos^2(alpha) + y^2 = 1: area pi/2 - pi cos(alpha)/2, so
   V = (1 + cos alpha) / 2 exactly (0.75 at 60 degrees), whatever the distance limit and
   the origin offset. The offset is large here (0.05, over the square's 0.1 half-size
   for the rays leaving below at under 27 degrees): traced from the raised origin, those
   rays pass beside the square, which is what counted them as open before the horizon
   came from the face normal. */
static void test_tilted_normals(void)
{
    const double alpha = 60.0 * M_PI / 180.0, offset = 0.05;
    struct ssg_scene *s = load_scene("tilted", oblique_camera,
        "plane(material=m, center=[0, 0.2, 0], normal=[0, 1, 0], size=[0.2, 0, 0.2])\n");
    if (!s)
        return;
    struct points pts;
    memset(&pts, 0, sizeof pts);
    double want[P];
    for (int i = 0; i < P; i++) {
        pts.fg[i] = 1;
        pts.p[i][0] = -0.06 + 0.12 * ((i % W) + 0.5) / W;
        pts.p[i][1] = 0.2;
        pts.p[i][2] = -0.06 + 0.12 * ((i / W) + 0.5) / H;
        /* tilted about z, towards +x or -x: both sides of the square */
        pts.n[i][0] = (i % 2 ? 1 : -1) * sin(alpha);
        pts.n[i][1] = cos(alpha);
        want[i] = 0.5 * (1.0 + cos(alpha));
    }
    struct input in;
    struct ssg_image *out = NULL;
    make_input(s, &pts, offset, &in);
    CHECK_EQ(run(s, &in, 4096, 1e4, offset, 1, &out), SSG_OK);
    if (out)
        check_stat(out, &pts, want, 4096);
    ssg_image_destroy(&out);
    free_input(&in);
    ssg_scene_destroy(&s);
}

int main(void)
{
    test_open_plane();
    test_tilted_normals();
    test_ceiling();
    test_wall();
    test_box(1.0);
    test_box(3.0);
    test_determinism();
    test_errors();
    return check_report();
}
