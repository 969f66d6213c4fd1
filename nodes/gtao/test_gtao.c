/* test_gtao.c - the `gtao` node on tiny G-buffers ray-cast from planes (planes.h), against
 * the closed forms of docs/analytic.md.
 *
 * Why GTAO is exactly 1 on an open plane: every sample is a point of the plane, brought
 * back onto the slice along the tangent plane (gtao/README), so its horizon cosine is the
 * tangent's up to float rounding, which is below the node's 1e-5 margin; both sides then
 * sit at the hemisphere's limits, where the node adds exactly the open value it divides
 * by.
 *
 * Why the wall converges to case 3: in a slice, the rays between the floor's tangent and
 * the highest wall point within R, W*, meet the wall between its foot E and W*, nearer
 * than max(|PE|, |PW*|) <= R (the distance along a segment is convex), and the rays above
 * W* miss it within R. So the slice's occluded directions are exactly those below its
 * horizon, the height-field assumption holds, and the analytic cosine-weighted inner
 * integral over slices tends to docs/analytic.md case 3, 1 - (acos c - c sqrt(1 - c^2)) / pi,
 * c = a / R, as slices and steps grow. What is left with finite ones: the horizon is the
 * highest SAMPLE, up to one step below W* (too bright by at most the integrand over one
 * step, O(1 / steps)); the slice sum is a midpoint-like quadrature over the half circle
 * (O(1 / slices^2) for a smooth integrand, but the slices that just reach the wall have a
 * kink); the rounding of samples to pixels. The tolerance below is stated for the case
 * and was measured (printed with GTAO_DEBUG=1).
 *
 * Under a ceiling (case 2) the height-field assumption fails: the ceiling points within R
 * are near the normal, and the rays between them and the floor's tangent go out under the
 * ceiling farther than R, but a horizon calls them occluded. GTAO without the thickness
 * heuristic is therefore darker than (h / D)^2 there; thickness > 0 lets the lower
 * samples beyond the nearest ceiling points pull the horizon back down, which brightens
 * it towards the closed form (test_ceiling). */
#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"

/* Runs gtao on g; returns out and (when bent is not NULL) bent_normal, owned. */
static struct ssg_image *gtao(const struct gbuf *g, const struct ssg_image *rotation,
                              int use_depth, const char *const *sets, int set_count,
                              struct ssg_image **bent)
{
    struct ssg_binding b[4] = {{"position", g->pos}, {"normal", g->nrm}};
    int nb = 2;
    if (rotation)
        b[nb++] = (struct ssg_binding){"rotation", rotation};
    if (use_depth)
        b[nb++] = (struct ssg_binding){"depth", g->depth};
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("gtao", b, nb, sets, set_count, &f, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    CHECK_EQ(out.count, 2);
    if (bent)
        *bent = out.images[1];
    else
        ssg_image_destroy(&out.images[1]);
    return out.images[0];
}

static int debug(void) { return getenv("GTAO_DEBUG") != NULL; }

/* An open surface is 1 up to float rounding: a sample of P's own plane can pass the
   node's 1e-5 margin on the horizon cosine in a near-grazing slice, which moves the
   result by a few ulps (measured: at most 2.4e-7 below 1). */
#define OPEN_MIN (1.0f - 1e-6f)

/* Surface pixels whose value is below `min`. */
static int count_below(const struct gbuf *g, const struct ssg_image *ao, float min)
{
    int n = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        n += g->which[i] >= 0 && !(ao->data[i] >= min);
    return n;
}

/* Open planes facing the camera and tilted: 1 everywhere up to float rounding, with and without the
   rotation pattern, for several settings; the bent normal is the normal within the
   error of the slice quadrature. */
static void test_open_planes(const struct ssg_image *rot)
{
    struct scene scenes[3] = {{.count = 1}, {.count = 1}, {.count = 1}};
    plane_at(&scenes[0].pl[0], 0, 0, 1, 0, 0, -5);
    plane_at(&scenes[1].pl[0], 0, 0.4, 1, 0, 0, -5);
    plane_at(&scenes[2].pl[0], -0.35, 0.25, 1, 0, 0, -4);
    static const char *const variants[][3] = {
        {"radius=0.5", "slices=4", "steps=8"},
        {"radius=1.5", "slices=3", "falloff=0.5"},
        {"radius=0.5", "slices=7", "thickness=0.5"},
    };
    for (int i = 0; i < 3; i++) {
        struct gbuf g;
        cast(&scenes[i], &g);
        for (int v = 0; v < SSG_COUNT(variants); v++)
            for (int r = 0; r < 2; r++) {
                struct ssg_image *bent = NULL;
                struct ssg_image *ao = gtao(&g, r ? rot : NULL, 0, variants[v], 3, &bent);
                if (!ao)
                    continue;
                int bad = count_below(&g, ao, OPEN_MIN);
                CHECK_EQ(bad, 0);
                double worst = 0;
                for (size_t o = 0; o < (size_t)W * H; o++)
                    for (int c = 0; c < 3; c++) {
                        size_t k = (size_t)c * W * H + o;
                        worst = fmax(worst, fabs(bent->data[k] - g.nrm->data[k]));
                    }
                /* Open horizons: each slice adds 4/3 (D.N) D + 2/3 (V.N) V, whose sum over
                   2 or more slices evenly spread on the half circle is 2 slices / 3 N: the
                   normal up to rounding. */
                CHECK(worst < 1e-5);
                if (bad || debug())
                    fprintf(stderr, "  plane %d, variant %d, rotation %d: %d below 1 - 1e-6, "
                            "%d not exactly 1, bent off by %.4f\n", i, v, r, bad,
                            count_not_one(&g, ao), worst);
                ssg_image_destroy(&ao);
                ssg_image_destroy(&bent);
            }
        release(&g);
    }
}

/* A floor under an open sky: background is exactly 1 with a zero bent normal, the floor 1
   up to float rounding. */
static void test_background(const struct ssg_image *rot)
{
    struct scene s = {.count = 1};
    plane_at(&s.pl[0], 0, 1, 0, 0, -0.3, 0);
    struct gbuf g;
    cast(&s, &g);
    const char *sets[] = {"radius=2"};
    struct ssg_image *bent = NULL, *ao = gtao(&g, rot, 0, sets, 1, &bent);
    if (ao) {
        int bg = 0, bg_ok = 0;
        for (size_t i = 0; i < (size_t)W * H; i++)
            if (g.which[i] < 0) {
                bg++;
                bg_ok += ao->data[i] == 1.0f && bent->data[i] == 0.0f &&
                         bent->data[(size_t)W * H + i] == 0.0f &&
                         bent->data[2 * (size_t)W * H + i] == 0.0f;
            }
        CHECK(bg > W * H / 3);
        CHECK_EQ(bg_ok, bg);
        CHECK_EQ(count_below(&g, ao, OPEN_MIN), 0);
    }
    ssg_image_destroy(&ao);
    ssg_image_destroy(&bent);
    release(&g);
}

static double wall_distance(const struct scene *s, const struct gbuf *g, size_t o)
{
    double p[3] = {g->pos->data[o], g->pos->data[(size_t)W * H + o],
                   g->pos->data[2 * (size_t)W * H + o]};
    return dot3(s->pl[1].n, p) - dot3(s->pl[1].n, s->pl[1].p0);
}

static int same(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b &&
           memcmp(a->data, b->data, sizeof(float) * (size_t)a->width * a->height *
                                        (size_t)a->channels) == 0;
}

/* The corner with the default settings: darker near the edge than far from it, 1 (up to
   float rounding) out of the wall's reach; the same bytes (both outputs) with 1 and 2 threads and with a
   depth input equal to -position.z; the bent normal leans away from the wall. */
static void test_corner(const struct ssg_image *rot)
{
    struct scene s;
    corner_scene(&s);
    struct gbuf g;
    cast(&s, &g);
    const char *sets[] = {"radius=0.5"};
    struct ssg_image *b1 = NULL, *b2 = NULL, *b3 = NULL;
    omp_set_num_threads(1);
    struct ssg_image *one = gtao(&g, rot, 0, sets, 1, &b1);
    omp_set_num_threads(2);
    struct ssg_image *two = gtao(&g, rot, 0, sets, 1, &b2);
    struct ssg_image *dep = gtao(&g, rot, 1, sets, 1, &b3);
    CHECK(same(one, two) && same(b1, b2));
    CHECK(same(two, dep) && same(b2, b3));
    if (two) {
        int n_near, n_far;
        double v_near = mean_over(two, g.which, 0, H / 2, W, H / 2 + 4, 0, &n_near);
        double v_far = mean_over(two, g.which, 0, H / 2 + 40, W, H / 2 + 44, 0, &n_far);
        CHECK(v_near < v_far - 0.1);
        int out_of_reach = 0, ones = 0, near = 0, leaning = 0;
        for (size_t o = 0; o < (size_t)W * H; o++) {
            if (g.which[o] != 0)
                continue;
            double a = wall_distance(&s, &g, o);
            if (a > 0.5) {
                out_of_reach++;
                ones += two->data[o] >= OPEN_MIN;
            } else if (a < 0.2) {
                /* The wall faces (0, -1, 1), N.n_wall = 0: leaning away raises bent.n_wall. */
                double bn = (-b2->data[(size_t)W * H + o] + b2->data[2 * (size_t)W * H + o]) /
                            sqrt(2.0);
                near++;
                leaning += bn > 0.0;
            }
        }
        CHECK(out_of_reach > W * H / 8);
        CHECK_EQ(ones, out_of_reach);
        CHECK(near > 0 && leaning > near * 9 / 10);
    }
    struct ssg_image *imgs[] = {one, two, dep, b1, b2, b3};
    for (int i = 0; i < 6; i++)
        ssg_image_destroy(&imgs[i]);
    release(&g);
}

static double case3(double c)
{
    return c >= 1 ? 1 : 1 - (acos(c) - c * sqrt(1 - c * c)) / M_PI;
}

/* Floor pixels of the corner's centre columns against docs/analytic.md case 3 (header):
   with 16 slices x 32 steps each pixel within 0.03 of the closed form; with the defaults
   (8 x 12) and the rotation tile, the mean error over each band of a within 0.03 and each
   pixel within 0.1. Also falloff: fading samples near R can only brighten. */
static void test_wall(const struct ssg_image *rot)
{
    struct scene s;
    corner_scene(&s);
    struct gbuf g;
    cast(&s, &g);
    const char *fine[] = {"radius=0.5", "slices=16", "steps=32"};
    const char *def[] = {"radius=0.5"};
    const char *fall[] = {"radius=0.5", "falloff=0.5"};
    struct ssg_image *f = gtao(&g, NULL, 0, fine, 3, NULL), *d = gtao(&g, rot, 0, def, 1, NULL);
    struct ssg_image *fa = gtao(&g, rot, 0, fall, 2, NULL);
    double worst_f = 0, worst_d = 0, band_sum[5] = {0};
    int band_n[5] = {0}, tested = 0, brighter = 0;
    for (int y = H / 2; f && d && fa && y < H; y++)
        for (int x = W / 4; x < 3 * W / 4; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            double c = wall_distance(&s, &g, o) / 0.5;
            if (g.which[o] != 0 || c >= 1)
                continue;
            double ref = case3(c), ef = f->data[o] - ref, ed = d->data[o] - ref;
            worst_f = fmax(worst_f, fabs(ef));
            worst_d = fmax(worst_d, fabs(ed));
            band_sum[(int)(c * 5)] += ed;
            band_n[(int)(c * 5)]++;
            brighter += fa->data[o] >= d->data[o];
            tested++;
        }
    if (debug())
        fprintf(stderr, "  wall: 16x32 worst %.4f, defaults worst %.4f\n", worst_f, worst_d);
    CHECK(tested > 100);
    CHECK(worst_f < 0.03);
    CHECK(worst_d < 0.1);
    CHECK_EQ(brighter, tested);
    for (int b = 0; b < 5; b++) {
        double mean = band_n[b] ? band_sum[b] / band_n[b] : 0;
        if (debug())
            fprintf(stderr, "  c in [%.1f, %.1f): %d px, mean error %+.4f\n", b / 5.0,
                    (b + 1) / 5.0, band_n[b], mean);
        CHECK(band_n[b] > 10);
        CHECK(fabs(mean) < 0.03);
    }
    ssg_image_destroy(&f);
    ssg_image_destroy(&d);
    ssg_image_destroy(&fa);
    release(&g);
}

/* Floor under a ceiling h = 0.6 above it, R = 1 (case 2: V = (h / R)^2 = 0.36), at floor
   pixels about 3 units away (rows H/2 + 28 .. H/2 + 36 of a 256-wide frame, the middle
   columns), where every ceiling point within R of them is on screen: the height field
   calls the rays under the ceiling occluded, so GTAO is darker than the closed form
   (header; measured 0.341 with 8 x 16), but not by much: those rays lie near the
   tangent, where the cosine weight is small. */
static void test_ceiling(const struct ssg_image *rot)
{
    int saved_w = W;
    W = 256;
    struct scene s = {.count = 2};
    plane_at(&s.pl[0], 0, 1, 0, 0, -0.3, 0);
    plane_at(&s.pl[1], 0, -1, 0, 0, 0.3, 0);
    struct gbuf g;
    cast(&s, &g);
    const char *sets[] = {"radius=1", "slices=8", "steps=16"};
    struct ssg_image *a = gtao(&g, rot, 0, sets, 3, NULL);
    if (a) {
        int n, x0 = W / 2 - 16, x1 = W / 2 + 16, y0 = H / 2 + 28, y1 = H / 2 + 36;
        double v = mean_over(a, g.which, x0, y0, x1, y1, 0, &n);
        if (debug())
            fprintf(stderr, "  ceiling: closed form 0.36, gtao %.4f\n", v);
        CHECK(n > 100);
        CHECK(v < 0.36 && v > 0.30);
    }
    ssg_image_destroy(&a);
    release(&g);
    W = saved_w;
}

/* A thin occluder: a wall 5 units away facing the camera, with a rod 2 px wide (about
   0.03 units) standing 0.3 in front of it down the middle columns. The height field
   (thickness 0) takes the rod for a solid ridge reaching back to the wall and darkens the
   wall beside it; with thickness > 0 the wall samples beyond the rod pull the horizon
   back down, so it is brighter there; out of the rod's reach both are 1. */
static void test_thin(const struct ssg_image *rot)
{
    struct scene s = {.count = 1};
    plane_at(&s.pl[0], 0, 0, 1, 0, 0, -5);
    struct gbuf g;
    cast(&s, &g);
    const float rod = 4.7f;
    for (int y = 0; y < H; y++)
        for (int x = W / 2 - 1; x < W / 2 + 1; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            double dir[3];
            ray(x + 0.5, y + 0.5, dir);
            for (int c = 0; c < 3; c++)
                g.pos->data[(size_t)c * W * H + o] = (float)(rod * dir[c]);
            g.depth->data[o] = rod;
            g.which[o] = 1;
        }
    const char *thick0[] = {"radius=0.5"};
    const char *thick[] = {"radius=0.5", "thickness=0.5"};
    struct ssg_image *a = gtao(&g, rot, 0, thick0, 1, NULL), *b = gtao(&g, rot, 0, thick, 2, NULL);
    if (a && b) {
        int n1, n2, n3, n4;
        double a_near = mean_over(a, g.which, W / 2 - 8, 0, W / 2 - 2, H, 0, &n1);
        double b_near = mean_over(b, g.which, W / 2 - 8, 0, W / 2 - 2, H, 0, &n2);
        double a_far = mean_over(a, g.which, 0, 0, 8, H, 0, &n3);
        double b_far = mean_over(b, g.which, 0, 0, 8, H, 0, &n4);
        if (debug())
            fprintf(stderr, "  thin rod: beside it %.4f (thickness 0), %.4f (0.5); far %.6f, "
                    "%.6f\n", a_near, b_near, a_far, b_far);
        CHECK(a_near < 0.95);
        CHECK(b_near > a_near + 0.02);
        CHECK(a_far >= OPEN_MIN && b_far >= OPEN_MIN);
    }
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    release(&g);
}

/* Wrong shapes and parameters are refused with a code. */
static void test_rejects(void)
{
    struct ssg_image *pos = ssg_image_create(8, 8, 3), *nrm = ssg_image_create(8, 4, 3);
    struct ssg_binding b[2] = {{"position", pos}, {"normal", nrm}};
    struct ssg_diags diags = {0};
    struct ssg_frame f = {8, 8, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_outputs out;
    CHECK(ssg_node_run("gtao", b, 2, NULL, 0, &f, &out, &diags) != SSG_OK);
    ssg_outputs_release(&out);
    b[1].image = pos;
    const char *bad[] = {"thickness=1"};
    CHECK_EQ(ssg_node_run("gtao", b, 2, bad, 1, &f, &out, &diags), SSG_E_RANGE);
    ssg_outputs_release(&out);
    const char *many[] = {"slices=33"};
    CHECK_EQ(ssg_node_run("gtao", b, 2, many, 1, &f, &out, &diags), SSG_E_RANGE);
    ssg_outputs_release(&out);
    CHECK_EQ(ssg_node_run("gtao", b, 1, NULL, 0, &f, &out, &diags), SSG_E_MISSING_INPUT);
    ssg_outputs_release(&out);
    ssg_image_destroy(&pos);
    ssg_image_destroy(&nrm);
}

int main(void)
{
    struct ssg_image *rot = halton_rotation();
    CHECK(rot != NULL);
    test_open_planes(rot);
    test_background(rot);
    test_corner(rot);
    test_wall(rot);
    test_ceiling(rot);
    test_thin(rot);
    test_rejects();
    ssg_image_destroy(&rot);
    return check_report();
}
