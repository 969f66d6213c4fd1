/* test_ssao_modes.c - the `ssao` node's normal-free modes (mode=sphere and mode=disc) on
 * the plane G-buffers of planes.h, run through ssao_planes.h like the hemisphere mode's
 * tests in test_ssao.c. Kept apart from those because their claims rest on a different
 * argument: samples in opposite pairs, of which at most one can be behind a plane, and
 * the rescale by 2 in ssao/README. */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"
#include "ssao_planes.h"

/* The normal-free modes on open planes: exactly 1 after the rescale by 2 (ssao/README), with
   and without the normal input (which they do not read), with every range check.
   sphere: each kernel sample s comes with -s, and of two opposite points at most one is
   behind a plane through P; the other is in front of it and, as for the hemisphere
   (ssao_planes.h), unoccluded because bias exceeds the lookup error: at most count of the
   2 count samples are occluded, so 2 - occluded / count >= 1, clamped to 1. disc: the
   samples are opposite pixel offsets, and 1 / depth is affine over a plane's image, so
   at most one of two is nearer than the pixel. */
static void test_modes_open_planes(const struct ssg_image *kernel, const struct ssg_image *rot)
{
    struct scene scenes[3] = {{.count = 1}, {.count = 1}, {.count = 1}};
    plane_at(&scenes[0].pl[0], 0, 0, 1, 0, 0, -5);
    plane_at(&scenes[1].pl[0], 0, 0.4, 1, 0, 0, -5);
    plane_at(&scenes[2].pl[0], -0.35, 0.25, 1, 0, 0, -4);
    static const char *const modes[] = {"mode=sphere", "mode=disc"};
    static const char *const ranges[] = {"range_check=none", "range_check=hard",
                                         "range_check=smooth"};
    for (int i = 0; i < 3; i++) {
        struct gbuf g;
        cast(&scenes[i], &g);
        CHECK(depth_bound(&scenes[i]) < 0.02 - 1e-3);
        for (int m = 0; m < 2; m++)
            for (int r = 0; r < 3; r++) {
                const char *sets[] = {modes[m], ranges[r], "radius=0.5"};
                struct ssg_image *ao = ssao(&g, kernel, rot, r == 1 ? NO_NORMAL : 0, sets, 3);
                if (ao) {
                    int bad = count_not_one(&g, ao);
                    CHECK_EQ(bad, 0);
                    if (bad)
                        fprintf(stderr, "  plane %d, %s, %s\n", i, modes[m], ranges[r]);
                }
                ssg_image_destroy(&ao);
            }
        release(&g);
    }
}

/* The normal-free modes in the corner: floor rows by the edge darker than rows out of
   reach (40 px further down, beyond both the sphere's radius and the disc's 31 px),
   which are exactly 1, as is the open floor alone; 1 and 2 threads give the same bytes;
   without a normal input the same result. The hemisphere mode refuses to run without a
   normal, with SSG_E_MISSING_INPUT. The darkening is mild with this short kernel
   (lengths from 0.05): samples just below the floor, within the bias of it, are spared,
   which lifts the open-floor baseline above 1 before the clamp (observed: sphere 0.94,
   disc 0.92 by the edge; test_sphere_closed_form quantifies it). */
static void test_modes_corner(const struct ssg_image *kernel, const struct ssg_image *rot)
{
    struct scene s;
    corner_scene(&s);
    struct gbuf g, gf;
    cast(&s, &g);
    struct scene floor_only = {.count = 1};
    floor_only.pl[0] = s.pl[0];
    cast(&floor_only, &gf);
    static const char *const modes[] = {"mode=sphere", "mode=disc"};
    for (int m = 0; m < 2; m++) {
        const char *sets[] = {modes[m], "radius=0.5"};
        omp_set_num_threads(1);
        struct ssg_image *one = ssao(&g, kernel, rot, 0, sets, 2);
        omp_set_num_threads(2);
        struct ssg_image *two = ssao(&g, kernel, rot, 0, sets, 2);
        struct ssg_image *free_ = ssao(&g, kernel, rot, NO_NORMAL, sets, 2);
        struct ssg_image *open = ssao(&gf, kernel, rot, 0, sets, 2);
        if (one && two && free_ && open) {
            CHECK(memcmp(one->data, two->data, sizeof(float) * W * H) == 0);
            CHECK(memcmp(one->data, free_->data, sizeof(float) * W * H) == 0);
            int n_near, n_far;
            double v_near = mean_over(two, g.which, 0, H / 2, W, H / 2 + 4, 0, &n_near);
            double v_far = mean_over(two, g.which, 0, H / 2 + 40, W, H / 2 + 44, 0, &n_far);
            CHECK(n_near == 4 * W && n_far == 4 * W);
            CHECK(v_near < v_far - 0.03);
            CHECK(v_far == 1.0);
            CHECK_EQ(count_not_one(&gf, open), 0);
            if (getenv("SSAO_DEBUG"))
                fprintf(stderr, "%s corner: near %.4f far %.4f\n", modes[m], v_near, v_far);
        }
        ssg_image_destroy(&one);
        ssg_image_destroy(&two);
        ssg_image_destroy(&free_);
        ssg_image_destroy(&open);
    }
    struct ssg_binding b[2] = {{"position", g.pos}, {"kernel", kernel}};
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    CHECK_EQ(ssg_node_run("ssao", b, 2, NULL, 0, &f, &out, &diags), SSG_E_MISSING_INPUT);
    ssg_outputs_release(&out);
    release(&gf);
    release(&g);
}

/* Signed distance of x from plane i, positive in the air. */
static double plane_distance(const struct scene *s, int i, const double x[3])
{
    double d[3] = {x[0] - s->pl[i].p0[0], x[1] - s->pl[i].p0[1], x[2] - s->pl[i].p0[2]};
    return dot3(s->pl[i].n, d);
}

/* The sphere mode in the corner, exactly and in expectation. Exactly: the test places
   every sample itself (ssao/README: r times the kernel sample and its reflection, turned
   about the view axis by the pixel's tile angle) and classifies it: in the air
   (unoccluded, the bias covers the lookup error), behind the floor or the wall by more
   than the margin of test_corner_closed_form in test_ssao.c (occluded: its depth
   exceeds the visible surface's by more than bias + bound), or in between (either). The
   node's value must lie in the resulting bracket of clamp(2 - occluded / count, 0, 1).
   In expectation, with a uniform kernel (mapping = uniform: each pair's member above
   the floor is uniform over the upper hemisphere), one member of every pair is under
   the floor and the other behind the wall with probability (1 - a / l) / 2 for length
   l > a, so the paper's rescaled value is 1 - mean over samples of (1 - a / l)^+ / 2:
   (1 + a / l) / 2 for one length, 1/2 at the edge. The node must meet that within four
   standard errors plus the bracket's width (the margin's spared samples). Lengths from
   0.6 R keep the margin small against them. 96 px wide: the samples of the centre
   column stay on screen. */
static void test_sphere_closed_form(void)
{
    enum { COUNT = 512 };
    int saved_w = W;
    const double radius = 0.5, bias = 0.02;
    struct scene s;
    struct gbuf g;
    double margin = corner_cast(96, bias, &s, &g, NULL);
    const char *ksets[] = {"count=512", "bases=[2,3,5]", "mapping=uniform", "min_scale=0.6"};
    struct ssg_image *rot = NULL, *kernel = kernel_of(ksets, 4, &rot);
    const char *sets[] = {"mode=sphere", "radius=0.5", "bias=0.02", "range_check=none"};
    struct ssg_image *ao = kernel ? ssao(&g, kernel, rot, NO_NORMAL, sets, 4) : NULL;
    int tested = 0, n = rot ? rot->width : 1;
    for (int y = H / 2; ao && y < H; y++) {
        int x = W / 2;
        size_t o = (size_t)y * W + (size_t)x;
        if (g.which[o] != 0)
            continue;
        double p[3] = {g.pos->data[o], g.pos->data[W * H + o], g.pos->data[2 * W * H + o]};
        size_t cell = (size_t)(y % n) * n + (size_t)(x % n);
        double co = rot->data[cell], si = rot->data[(size_t)n * n + cell];
        int sure = 0, maybe = 0;
        double expect = 0, var = 0;
        for (int i = 0; i < COUNT; i++) {
            double kx = kernel->data[i], ky = kernel->data[COUNT + i];
            double kz = kernel->data[2 * COUNT + i];
            double off[3] = {radius * (co * kx - si * ky), radius * (si * kx + co * ky),
                             radius * kz};
            for (int m = 0; m < 2; m++) {
                double q[3];
                for (int c = 0; c < 3; c++)
                    q[c] = p[c] + (m ? -off[c] : off[c]);
                double behind = -fmin(plane_distance(&s, 0, q), plane_distance(&s, 1, q));
                sure += behind > margin;
                maybe += behind > 0 && behind <= margin;
            }
            double l = radius * sqrt(kx * kx + ky * ky + kz * kz);
            double a = plane_distance(&s, 1, p), pw = a < l ? (1 - a / l) / 2 : 0;
            expect += pw;
            var += pw * (1 - pw);
        }
        double hi = fmin(fmax(2.0 - (double)sure / COUNT, 0), 1);
        double lo = fmin(fmax(2.0 - (double)(sure + maybe) / COUNT, 0), 1);
        double v = ao->data[o], model = 1 - expect / COUNT, se = sqrt(var) / COUNT;
        int inside = v >= lo - 1e-6 && v <= hi + 1e-6;
        int near_model = fabs(v - model) <= 4 * se + (hi - lo) + 1e-6;
        CHECK(inside);
        CHECK(near_model);
        if (!inside || !near_model || getenv("SSAO_DEBUG"))
            fprintf(stderr, "  sphere a=%.4f: ssao %.4f, bracket [%.4f, %.4f], model %.4f "
                    "+- %.4f\n", plane_distance(&s, 1, p), v, lo, hi, model, 4 * se);
        tested++;
    }
    CHECK(tested > 10);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&kernel);
    ssg_image_destroy(&rot);
    release(&g);
    W = saved_w;
}

int main(void)
{
    const char *ksets[] = {"count=16"};
    struct ssg_image *rot = NULL, *kernel = kernel_of(ksets, 1, &rot);
    if (kernel) {
        test_modes_open_planes(kernel, rot);
        test_modes_corner(kernel, rot);
    }
    test_sphere_closed_form();
    ssg_image_destroy(&kernel);
    ssg_image_destroy(&rot);
    return check_report();
}
