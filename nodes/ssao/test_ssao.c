/* test_ssao.c - the `ssao` node's hemisphere mode on tiny G-buffers ray-cast here from
 * planes (planes.h, ssao_planes.h), with answers known in closed form; the normal-free
 * modes are test_ssao_modes.c.
 *
 * Scenes are convex "air" regions bounded by planes (the camera inside), so the visible
 * surface along a ray is the nearest plane the ray leaves the region through. Pixels are
 * cast through their centres with the inverse of the projection in core/graph/node.h.
 * Open planes are exactly 1 because the bias exceeds the depth lookup's error (see
 * ssao_planes.h).
 *
 * Why the corner has a closed form: a sample S = P + l R w is behind a plane at
 * perpendicular distance a from P exactly when the ray from P along w meets the plane
 * within l R, so the fraction of unoccluded samples is, in expectation over cosine
 * directions, docs/analytic.md case 3 with D = l R, averaged over the kernel's lengths. The
 * bias and the pixel lookup can only spare samples that are behind the plane by less than
 * (bias + bound) * |ray|, so the node's value lies between that average at a and at
 * a + that margin, up to the Monte Carlo error of the kernel (four standard errors,
 * docs/analytic.md 5). */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"
#include "ssao_planes.h"

static void test_open_planes(const struct ssg_image *kernel, const struct ssg_image *rot)
{
    struct scene scenes[3] = {{.count = 1}, {.count = 1}, {.count = 1}};
    plane_at(&scenes[0].pl[0], 0, 0, 1, 0, 0, -5);          /* facing the camera */
    plane_at(&scenes[1].pl[0], 0, 0.4, 1, 0, 0, -5);        /* tilted up */
    plane_at(&scenes[2].pl[0], -0.35, 0.25, 1, 0, 0, -4);   /* tilted both ways */
    for (int i = 0; i < 3; i++) {
        struct gbuf g;
        cast(&scenes[i], &g);
        double bound = depth_bound(&scenes[i]);
        /* The default bias (0.02) must cover the lookup error for "exactly 1" to be a
           claim about SSAO rather than about a lucky bias. */
        CHECK(bound < 0.02 - 1e-3);
        for (int range = 0; range < 3; range++) {
            static const char *const modes[] = {"range_check=none", "range_check=hard",
                                                "range_check=smooth"};
            const char *sets[] = {modes[range], "radius=0.5"};
            struct ssg_image *ao = ssao(&g, kernel, rot, 0, sets, 2);
            if (ao)
                CHECK_EQ(count_not_one(&g, ao), 0);
            ssg_image_destroy(&ao);
        }
        release(&g);
    }
}

/* docs/analytic.md case 3: visibility at horizontal distance a from an infinite wall with a
   hard maximum distance D (cosine weighting). */
static double wall_visibility(double a, double d)
{
    double c = a / d;
    if (c >= 1)
        return 1;
    return 1 - (acos(c) - c * sqrt(1 - c * c)) / M_PI;
}

/* Case 3 averaged over the kernel's sample lengths (|s| = l, D = l R). */
static double wall_model(const struct ssg_image *k, double a, double radius)
{
    double v = 0;
    for (int i = 0; i < k->width; i++) {
        double x = k->data[i], y = k->data[k->width + i], z = k->data[2 * k->width + i];
        v += wall_visibility(a, radius * sqrt(x * x + y * y + z * z));
    }
    return v / k->width;
}

static double standard_error(double v, int n)
{
    return sqrt(v * (1 - v) / n);
}

/* Case 3 averaged over the lengths of several kernels. */
static double wall_model_all(struct ssg_image *const *k, int nk, double a, double radius)
{
    double v = 0;
    for (int i = 0; i < nk; i++)
        v += wall_model(k[i], a, radius);
    return v / nk;
}

/* The corner against docs/analytic.md case 3. Four kernels of 1024 samples at consecutive
   Halton blocks (offsets 1, 1025, ...) make one 4096-sample estimate per pixel (the mean
   of their results), for a tolerance of four standard errors of 4096 samples. A frame
   64 px wide suffices: the floor's rows each lie at one distance from the wall (the
   depth along a row is constant on a plane through the x axis) and the centre column's
   samples stay within 31 px of it. */
static void test_corner_closed_form(void)
{
    enum { KERNELS = 4 };
    int saved_w = W;
    const double radius = 0.5, bias = 0.02;
    struct scene s;
    struct gbuf g;
    double bound, margin = corner_cast(64, bias, &s, &g, &bound);
    if (getenv("SSAO_DEBUG"))
        fprintf(stderr, "corner: depth bound %.5f, margin %.5f\n", bound, margin);
    const char *sets[] = {"radius=0.5", "bias=0.02", "range_check=none"};
    struct ssg_image *kernel[KERNELS] = {0}, *rot[KERNELS] = {0}, *ao[KERNELS] = {0};
    int ok = 1;
    for (int k = 0; k < KERNELS; k++) {
        char offset[32];
        snprintf(offset, sizeof offset, "offset=%d", 1 + 1024 * k);
        const char *ksets[] = {"count=1024", "bases=[2,3,5]", offset};
        kernel[k] = kernel_of(ksets, 3, &rot[k]);
        ao[k] = kernel[k] ? ssao(&g, kernel[k], rot[k], 0, sets, 3) : NULL;
        ok &= ao[k] != NULL;
    }
    if (ok) {
        /* Along the centre column: floor pixels at distance a from the wall. */
        int x = W / 2, tested = 0, far_ones = 0, far_total = 0, near_n = 0;
        double near_max = 0;
        const int n = 1024 * KERNELS;
        for (int y = 0; y < H; y++) {
            size_t o = (size_t)y * W + (size_t)x;
            if (g.which[o] != 0)
                continue;
            double p[3] = {g.pos->data[o], g.pos->data[W * H + o], g.pos->data[2 * W * H + o]};
            double a = dot3(s.pl[1].n, p) - dot3(s.pl[1].n, s.pl[1].p0);
            double v = 0;
            for (int k = 0; k < KERNELS; k++)
                v += ao[k]->data[o];
            v /= KERNELS;
            if (a >= radius) {
                far_total++;
                far_ones += v == 1.0;
                continue;
            }
            double lo = wall_model_all(kernel, KERNELS, a, radius);
            double hi = wall_model_all(kernel, KERNELS, a + margin, radius);
            double tol_lo = 4 * standard_error(lo, n), tol_hi = 4 * standard_error(hi, n);
            int inside = v >= lo - tol_lo && v <= hi + tol_hi;
            CHECK(inside);
            if (!inside || getenv("SSAO_DEBUG"))
                fprintf(stderr, "  corner a=%.4f: ssao %.4f, expected [%.4f, %.4f] "
                        "(before tolerance [%.4f, %.4f])\n", a, v, lo - tol_lo, hi + tol_hi,
                        lo, hi);
            tested++;
            if (a < 0.1) {
                near_max = fmax(near_max, v);
                near_n++;
            }
        }
        CHECK(tested > 10);
        CHECK(far_total > 10);
        /* No sample reaches the wall from a >= radius: exactly open, given bound < bias. */
        CHECK_EQ(far_ones, far_total);
        /* Every pixel near the edge is darker than every far one. */
        CHECK(near_n > 0 && near_max < 1.0);
    }
    for (int k = 0; k < KERNELS; k++) {
        ssg_image_destroy(&kernel[k]);
        ssg_image_destroy(&rot[k]);
        ssg_image_destroy(&ao[k]);
    }
    release(&g);
    W = saved_w;
}

/* The corner with the everyday kernel: the open floor alone is 1 where the corner is
   dark; 1 and 2 threads give the same bytes; a depth input equal to -position.z gives
   the same result as none. */
static void test_corner(const struct ssg_image *kernel, const struct ssg_image *rot)
{
    struct scene s;
    corner_scene(&s);
    struct gbuf g;
    cast(&s, &g);
    const char *sets[] = {"radius=0.5", "bias=0.02", "range_check=none"};
    struct ssg_image *ao = ssao(&g, kernel, rot, 0, sets, 3), *open = NULL;
    if (ao) {
        /* Floor rows next to the edge (a < 0.1) are darker on average than floor rows
           out of the wall's reach (a > radius, 40 rows down), which are exactly 1. */
        int n_near, n_far;
        double v_near = mean_over(ao, g.which, 0, H / 2, W, H / 2 + 4, 0, &n_near);
        double v_far = mean_over(ao, g.which, 0, H / 2 + 40, W, H / 2 + 44, 0, &n_far);
        CHECK(n_near == 4 * W && n_far == 4 * W);
        CHECK(v_near < v_far);
        CHECK(v_far == 1.0);
    }
    /* The same pixels on an open face (the floor alone) are 1. */
    struct scene floor_only = {.count = 1};
    floor_only.pl[0] = s.pl[0];
    struct gbuf gf;
    cast(&floor_only, &gf);
    open = ssao(&gf, kernel, rot, 0, sets, 3);
    if (open)
        CHECK_EQ(count_not_one(&gf, open), 0);
    const char *smooth[] = {"radius=0.5"};
    omp_set_num_threads(1);
    struct ssg_image *one = ssao(&g, kernel, rot, 0, smooth, 1);
    omp_set_num_threads(2);
    struct ssg_image *two = ssao(&g, kernel, rot, 0, smooth, 1);
    if (one && two)
        CHECK(memcmp(one->data, two->data, sizeof(float) * W * H) == 0);
    struct ssg_image *with_depth = ssao(&g, kernel, rot, 1, smooth, 1);
    if (one && with_depth)
        CHECK(memcmp(one->data, with_depth->data, sizeof(float) * W * H) == 0);
    ssg_image_destroy(&one);
    ssg_image_destroy(&two);
    ssg_image_destroy(&with_depth);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&open);
    release(&gf);
    release(&g);
}

/* A floor 0.3 below the camera, open or under a ceiling 0.3 above it (h = 0.6 < radius 2,
   so case 2 of docs/analytic.md predicts occlusion). The floor is seen at a grazing angle
   (depth_bound is far above any bias) and many samples over the ceiling leave the screen,
   so the closed form does not predict SSAO here: only the ordering is claimed, with the
   same parameters for both. Also: the background above the open floor's horizon is 1. */
static void test_floor_ceiling(const struct ssg_image *kernel, const struct ssg_image *rot)
{
    struct scene open = {.count = 1}, covered = {.count = 2};
    plane_at(&open.pl[0], 0, 1, 0, 0, -0.3, 0);
    covered.pl[0] = open.pl[0];
    plane_at(&covered.pl[1], 0, -1, 0, 0, 0.3, 0);
    struct gbuf go, gc;
    cast(&open, &go);
    cast(&covered, &gc);
    const char *sets[] = {"radius=2"};
    struct ssg_image *ao_open = ssao(&go, kernel, rot, 0, sets, 1);
    struct ssg_image *ao_cov = ssao(&gc, kernel, rot, 0, sets, 1);
    if (ao_open && ao_cov) {
        /* A patch of floor below the image centre, depths about 2.8 to 5.3, where the
           ceiling above the samples is on screen. */
        int n1, n2;
        double v_open = mean_over(ao_open, go.which, W / 2 - 16, H / 2 + 17, W / 2 + 16,
                                  H / 2 + 33, 0, &n1);
        double v_cov = mean_over(ao_cov, gc.which, W / 2 - 16, H / 2 + 17, W / 2 + 16,
                                 H / 2 + 33, 0, &n2);
        CHECK(n1 == 32 * 16 && n2 == 32 * 16);
        CHECK(v_cov < v_open);
        int bg = 0, bg_ones = 0;
        for (size_t i = 0; i < (size_t)W * H; i++)
            if (go.which[i] < 0) {
                bg++;
                bg_ones += ao_open->data[i] == 1.0f;
            }
        CHECK(bg > W * H / 3);
        CHECK_EQ(bg_ones, bg);
    }
    ssg_image_destroy(&ao_open);
    ssg_image_destroy(&ao_cov);
    release(&go);
    release(&gc);
}

/* A near object in front of a far wall: the left half at depth 2, the right at 5 (a
   G-buffer written directly). Wall pixels next to the step see the near half over their
   samples. Without a range check that occludes them; with the hard check (3 > radius) it
   does not; the smooth one weights it by smoothstep(0.5 / 3) = 0.0741. Also checks the
   power and max_screen_radius parameters on the same scene. */
static double step_depth(int x, int y, int unused)
{
    return x < W / 2 ? 2.0 : 5.0;
}

static void test_step(const struct ssg_image *kernel)
{
    struct gbuf g = gbuf_from_depth(step_depth, 0);
    const char *none[] = {"range_check=none", "radius=0.5"};
    const char *hard[] = {"range_check=hard", "radius=0.5"};
    const char *smooth[] = {"range_check=smooth", "radius=0.5"};
    struct ssg_image *a = ssao(&g, kernel, NULL, 0, none, 2);
    struct ssg_image *b = ssao(&g, kernel, NULL, 0, hard, 2);
    struct ssg_image *c = ssao(&g, kernel, NULL, 0, smooth, 2);
    if (a && b && c) {
        size_t o = (size_t)(H / 2) * W + W / 2; /* first far pixel right of the step */
        double occ_none = 1 - a->data[o], occ_smooth = 1 - c->data[o];
        CHECK(occ_none > 0.2);
        CHECK_EQ(b->data[o], 1.0f);
        /* Every sample counted fully by "none" counts 0.0741 in "smooth", and no other
           sample is occluded at all. */
        double t = 0.5 / 3.0;
        CHECK_NEAR(occ_smooth, occ_none * t * t * (3 - 2 * t), 1e-5);
        /* The near half is in front of everything: open. */
        CHECK_EQ(a->data[(size_t)(H / 2) * W + W / 4], 1.0f);
    }
    /* power: out = visibility^power. */
    const char *squared[] = {"range_check=none", "radius=0.5", "power=2"};
    struct ssg_image *p = ssao(&g, kernel, NULL, 0, squared, 3);
    if (a && p) {
        double worst = 0;
        for (size_t i = 0; i < (size_t)W * H; i++)
            worst = fmax(worst, fabs(p->data[i] - (double)a->data[i] * a->data[i]));
        CHECK(worst < 1e-6);
    }
    /* max_screen_radius: 10 px right of the step the wall's samples reach the near half
       (radius 0.5 at depth 5 projects to 0.5 f / 5 = 31 px); capped at 8 px they cannot
       (r becomes 8 * 5 / f), so the pixel is open. */
    const char *capped[] = {"range_check=none", "radius=0.5", "max_screen_radius=8"};
    struct ssg_image *m = ssao(&g, kernel, NULL, 0, capped, 3);
    if (a && m) {
        size_t o = (size_t)(H / 2) * W + W / 2 + 10;
        CHECK(a->data[o] < 1.0f);
        CHECK_EQ(m->data[o], 1.0f);
        CHECK(m->data[(size_t)(H / 2) * W + W / 2] < 1.0f); /* right at the step: still */
    }
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&c);
    ssg_image_destroy(&p);
    ssg_image_destroy(&m);
    release(&g);
}

/* Wrong input shapes are refused with a code, not read out of bounds. */
static void test_rejects(const struct ssg_image *kernel)
{
    struct ssg_image *pos = ssg_image_create(8, 8, 3), *nrm = ssg_image_create(8, 4, 3);
    struct ssg_binding b[3] = {{"position", pos}, {"normal", nrm}, {"kernel", kernel}};
    struct ssg_diags diags = {0};
    struct ssg_frame f = {8, 8, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_outputs out;
    CHECK(ssg_node_run("ssao", b, 3, NULL, 0, &f, &out, &diags) != SSG_OK);
    ssg_outputs_release(&out);
    const char *bad[] = {"radius=0"};
    b[1].image = pos;
    CHECK_EQ(ssg_node_run("ssao", b, 3, bad, 1, &f, &out, &diags), SSG_E_RANGE);
    ssg_outputs_release(&out);
    ssg_image_destroy(&pos);
    ssg_image_destroy(&nrm);
}

int main(void)
{
    const char *ksets[] = {"count=16"};
    struct ssg_image *rot = NULL, *kernel = kernel_of(ksets, 1, &rot);
    if (kernel) {
        test_open_planes(kernel, rot);
        test_floor_ceiling(kernel, rot);
        test_step(kernel);
        test_rejects(kernel);
        test_corner(kernel, rot);
    }
    test_corner_closed_form();
    ssg_image_destroy(&kernel);
    ssg_image_destroy(&rot);
    return check_report();
}
