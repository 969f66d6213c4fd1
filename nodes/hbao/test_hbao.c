/* test_hbao.c - the `hbao` node on tiny G-buffers ray-cast here from planes, with answers
 * known in closed form.
 *
 * Scenes are convex "air" regions bounded by planes (the camera inside), so the visible
 * surface along a ray is the nearest plane the ray leaves the region through. Pixels are
 * cast through their centres with the inverse of the projection in core/graph/node.h.
 *
 * Why HBAO is exactly 1 on an open plane: every sample is a point of the plane, so its
 * offset H from the pixel's point lies in the tangent plane; the node brings samples
 * that the rounding to pixels moved off the slice back along the tangent plane
 * (hbao/README), so their elevation in the slice equals the tangent's up to float rounding of
 * the reconstruction; any bias above that rounding leaves no slice term, and the node
 * adds exact zeros.
 *
 * The wall (docs/analytic.md case 3 geometry): a floor point at distance a from an infinite
 * wall, seen in the inner corner of two planes at 45 degrees to the view axis. In the
 * image's centre column (an odd frame width puts a pixel centre on the axis) V has no x
 * component, so e1 = x (the edge direction) and the slice of azimuth pi/2 is the vertical
 * plane through the eye, perpendicular to the edge, marched straight up the column: its
 * samples are exact surface points of that plane. There the floor and the wall are two
 * perpendicular lines through the edge point E, |PE| = a, and the highest point within R
 * is the wall point at distance R, at angle phi = acos(a / R) above the floor: the slice
 * term is sin(t + phi) - sin(t + bias) (t the tangent elevation), for falloff none.
 *
 * The continuous limit (many directions, falloff none): azimuths are uniform about V and
 * eq. 3.1's measure is the solid angle, so HBAO tends to 1 - (solid angle above the floor
 * of the directions that hit the wall within R) / (2 pi) wherever each slice's occluded
 * directions start at the floor, which holds in the centre column (test_wall_limit).
 * That solid angle is rotation invariant, so work about the floor normal: at azimuth psi
 * from the wall's normal the wall within R subtends elevations [0, acos(a / (R cos psi))]
 * for |psi| < acos(a / R), and
 *   (1 / 2 pi) int sqrt(1 - c^2 / cos^2 psi) dpsi = (1 / 2 pi) pi (1 - c) = (1 - c) / 2,
 * (c = a / R; with s = sin psi the integral is int sqrt(k^2 - s^2) / (1 - s^2) ds over
 * |s| < k = sqrt(1 - c^2), which is pi (1 - sqrt(1 - k^2))). So HBAO -> (1 + c) / 2:
 * the uniform-weighted counterpart of case 3's cosine-weighted 1 - (acos c -
 * c sqrt(1 - c^2)) / pi; they agree at the edge (1/2) and from a = R on (1), and the test
 * checks both that and the ordering between (uniform weighting is darker). */
#include <math.h>
#include <omp.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"

/* Runs hbao on g; returns the output image (owned) or NULL. */
static struct ssg_image *hbao(const struct gbuf *g, const struct ssg_image *rotation,
                              int use_depth, const char *const *sets, int set_count)
{
    struct ssg_binding b[4] = {{"position", g->pos}, {"normal", g->nrm}};
    int nb = 2;
    if (rotation)
        b[nb++] = (struct ssg_binding){"rotation", rotation};
    if (use_depth)
        b[nb++] = (struct ssg_binding){"depth", g->depth};
    /* The tests were derived for the paper's settings (the defaults before issue 15 tuned
       them for accuracy): pinned first, so each test's closed form holds whatever the
       shipped defaults; the caller's sets come after and win. */
    static const char *const pinned[] = {"steps=4", "bias=0.1", "strength=1",
                                         "falloff=linear"};
    const char *all[PIN_SETS_MAX];
    int n = pin_sets(all, pinned, 4, sets, set_count);
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("hbao", b, nb, all, n, &f, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    CHECK_EQ(out.count, 1);
    return out.images[0];
}

/* Open planes facing the camera, tilted, and tilted both ways: exactly 1 everywhere,
   with and without the rotation pattern, for the default bias and for a tenth of it,
   with either falloff and with many directions and steps. */
static void test_open_planes(const struct ssg_image *rot)
{
    struct scene scenes[3] = {{.count = 1}, {.count = 1}, {.count = 1}};
    plane_at(&scenes[0].pl[0], 0, 0, 1, 0, 0, -5);
    plane_at(&scenes[1].pl[0], 0, 0.4, 1, 0, 0, -5);
    plane_at(&scenes[2].pl[0], -0.35, 0.25, 1, 0, 0, -4);
    static const char *const variants[][3] = {
        {"radius=0.5", "bias=0.1", "falloff=linear"},
        {"radius=0.5", "bias=0.01", "falloff=linear"},
        {"radius=0.5", "bias=0.01", "falloff=none"},
        {"radius=1.5", "directions=12", "steps=8"},
    };
    for (int i = 0; i < 3; i++) {
        struct gbuf g;
        cast(&scenes[i], &g);
        for (int v = 0; v < SSG_COUNT(variants); v++)
            for (int r = 0; r < 2; r++) {
                struct ssg_image *ao = hbao(&g, r ? rot : NULL, 0, variants[v], 3);
                if (ao) {
                    int bad = count_not_one(&g, ao);
                    CHECK_EQ(bad, 0);
                    if (bad)
                        fprintf(stderr, "  plane %d, variant %d, rotation %d\n", i, v, r);
                }
                ssg_image_destroy(&ao);
            }
        release(&g);
    }
}

/* A floor 0.3 below the camera reaching the horizon: the sky above it is background,
   which is 1 and never occludes the floor (which is open, so exactly 1 as well). */
static void test_background(const struct ssg_image *rot)
{
    struct scene s = {.count = 1};
    plane_at(&s.pl[0], 0, 1, 0, 0, -0.3, 0);
    struct gbuf g;
    cast(&s, &g);
    const char *sets[] = {"radius=2"};
    struct ssg_image *ao = hbao(&g, rot, 0, sets, 1);
    if (ao) {
        int bg = 0, bg_ones = 0;
        for (size_t i = 0; i < (size_t)W * H; i++)
            if (g.which[i] < 0) {
                bg++;
                bg_ones += ao->data[i] == 1.0f;
            }
        CHECK(bg > W * H / 3);
        CHECK_EQ(bg_ones, bg);
        CHECK_EQ(count_not_one(&g, ao), 0);
    }
    ssg_image_destroy(&ao);
    release(&g);
}

/* Distance from the floor point seen at pixel o to the wall plane. */
static double wall_distance(const struct scene *s, const struct gbuf *g, size_t o)
{
    double p[3] = {g->pos->data[o], g->pos->data[(size_t)W * H + o],
                   g->pos->data[2 * (size_t)W * H + o]};
    return dot3(s->pl[1].n, p) - dot3(s->pl[1].n, s->pl[1].p0);
}

/* The corner with the everyday settings: darker near the edge than far from it, exactly
   1 out of the wall's reach and on the open floor alone; the same bytes with 1 and 2
   threads, and with a depth input equal to -position.z. */
static void test_corner(const struct ssg_image *rot)
{
    struct scene s;
    corner_scene(&s);
    struct gbuf g;
    cast(&s, &g);
    const char *sets[] = {"radius=0.5"};
    struct ssg_image *ao = hbao(&g, rot, 0, sets, 1), *open = NULL;
    if (ao) {
        /* Floor rows next to the edge against rows 40 px further down. */
        int n_near, n_far;
        double v_near = mean_over(ao, g.which, 0, H / 2, W, H / 2 + 4, 0, &n_near);
        double v_far = mean_over(ao, g.which, 0, H / 2 + 40, W, H / 2 + 44, 0, &n_far);
        CHECK(n_near == 4 * W && n_far == 4 * W);
        CHECK(v_near < v_far - 0.1);
        /* Floor pixels farther than R from the wall see no sample of it: exactly 1. */
        int out_of_reach = 0, ones = 0;
        for (size_t o = 0; o < (size_t)W * H; o++)
            if (g.which[o] == 0 && wall_distance(&s, &g, o) > 0.5) {
                out_of_reach++;
                ones += ao->data[o] == 1.0f;
            }
        CHECK(out_of_reach > W * H / 8);
        CHECK_EQ(ones, out_of_reach);
    }
    /* The same pixels on the floor alone. */
    struct scene floor_only = {.count = 1};
    floor_only.pl[0] = s.pl[0];
    struct gbuf gf;
    cast(&floor_only, &gf);
    open = hbao(&gf, rot, 0, sets, 1);
    if (open)
        CHECK_EQ(count_not_one(&gf, open), 0);
    omp_set_num_threads(1);
    struct ssg_image *one = hbao(&g, rot, 0, sets, 1);
    omp_set_num_threads(2);
    struct ssg_image *two = hbao(&g, rot, 0, sets, 1);
    if (one && two)
        CHECK(memcmp(one->data, two->data, sizeof(float) * W * H) == 0);
    const char *none[] = {"radius=0.5", "falloff=none", "directions=7", "steps=5"};
    omp_set_num_threads(1);
    struct ssg_image *one_n = hbao(&g, rot, 0, none, 4);
    omp_set_num_threads(2);
    struct ssg_image *two_n = hbao(&g, rot, 0, none, 4);
    if (one_n && two_n)
        CHECK(memcmp(one_n->data, two_n->data, sizeof(float) * W * H) == 0);
    struct ssg_image *with_depth = hbao(&g, rot, 1, sets, 1);
    if (two && with_depth)
        CHECK(memcmp(two->data, with_depth->data, sizeof(float) * W * H) == 0);
    ssg_image_destroy(&one);
    ssg_image_destroy(&two);
    ssg_image_destroy(&one_n);
    ssg_image_destroy(&two_n);
    ssg_image_destroy(&with_depth);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&open);
    release(&gf);
    release(&g);
}

/* Point P of the floor seen at image point (u, v), in double: the test's own ray cast. */
static void floor_point(const struct scene *s, double u, double v, double p[3])
{
    double dir[3];
    ray(u, v, dir);
    double t = plane_depth(s, 0, dir);
    for (int c = 0; c < 3; c++)
        p[c] = t * dir[c];
}

/* Visible point at image point (u, v) and its plane. */
static int surface_point(const struct scene *s, double u, double v, double p[3])
{
    double dir[3];
    int which;
    ray(u, v, dir);
    double t = visible_depth(s, dir, &which);
    for (int c = 0; c < 3; c++)
        p[c] = t * dir[c];
    return which;
}

static void sub3(const double a[3], const double b[3], double out[3])
{
    for (int c = 0; c < 3; c++)
        out[c] = a[c] - b[c];
}

/* Sine of the elevation of H over the plane perpendicular to V. */
static double elevation(const double h[3], const double v[3])
{
    return dot3(h, v) / sqrt(dot3(h, h));
}

/* The slice marched up the centre column from floor pixel row y (hbao README's geometry with
   V = (0, vy, vz), e1 = x, D = e2 = V x e1 = (0, vz, -vy)). Returns the sines of the
   tangent elevation t, of the horizon h* of the continuous march (the wall point at
   distance R, or t when the wall is out of reach), of the horizon h_lo of the lowest
   sample the node's march can end on (one step plus one pixel of rounding below h*),
   and the distance a of P from the wall. Independent of the node's code: the step
   length f R / (max(depth - R, depth / 2) steps) px along the unnormalised screen
   direction is the documented one (hbao/README), the points come from this file's ray cast. */
struct slice_ref {
    double sin_t, cos_t, sin_h, sin_h_lo, a;
};

static struct slice_ref up_slice(const struct scene *s, int y, double radius, int steps)
{
    struct ssg_frame f = frame();
    struct ssg_projection pr = ssg_frame_projection(&f);
    struct slice_ref r;
    double p[3], q[3], h[3];
    floor_point(s, pr.cx, y + 0.5, p);
    double len = sqrt(dot3(p, p));
    double v[3] = {-p[0] / len, -p[1] / len, -p[2] / len};
    double d[3] = {0, v[2], -v[1]};
    const double *n = s->pl[0].n;
    double vn = dot3(v, n), dn = dot3(d, n), rho = sqrt(vn * vn + dn * dn);
    r.sin_t = -dn / rho;
    r.cos_t = vn / rho;
    r.a = dot3(s->pl[1].n, p) - dot3(s->pl[1].n, s->pl[1].p0);
    r.sin_h = r.sin_h_lo = r.sin_t;
    if (r.a >= radius)
        return r;
    /* In the plane x = 0 the edge is E = (0, 0, -5), the floor the points (0, y, -5 - y)
       (y < 0), the wall (0, y, y - 5) (y > 0); P = (0, yp, -5 - yp), and the wall point
       at distance R has 2 y^2 + 2 yp^2 = R^2. */
    double yw = sqrt(radius * radius / 2 - p[1] * p[1]);
    double w[3] = {0, yw, yw - 5};
    sub3(w, p, h);
    r.sin_h = elevation(h, v);
    /* Independent check of the geometry: the wall point is phi = acos(a / R) above the
       floor within the slice, so its elevation is t + phi. */
    double phi = acos(r.a / radius);
    CHECK_NEAR(r.sin_h, r.sin_t * cos(phi) + r.cos_t * sin(phi), 1e-9);
    /* Screen rows: the march step in rows, and the lowest point the last sample within
       R can be on. */
    double depth = -p[2], den = fmax(depth - radius, depth / 2);
    double av = -(y + 0.5 - pr.cy) / pr.f;
    double step_rows = pr.f * radius / (den * steps) * fabs(d[1] + av * d[2]);
    double v_w = pr.cy - pr.f * w[1] / -w[2];
    double v_lo = v_w + step_rows + 1.0;
    if (v_lo < y + 0.5 && surface_point(s, pr.cx, v_lo, q) == 1) {
        sub3(q, p, h);
        r.sin_h_lo = fmax(elevation(h, v), r.sin_t);
    }
    return r;
}

/* HBAO slice by slice against the closed form, on the wall of the corner, in the centre
   column of a frame of odd width (so its pixel centres lie in the plane x = 0): with 4
   directions and no rotation the slices are the row (theta = 0, pi: open floor, no term)
   and the column (pi / 2 up to the wall, 3 pi / 2 down the open floor), whose samples
   are exact surface points of the slice. With falloff none the node gives
   1 - (sin h - sin(t + bias))^+ / 4 with h its highest sample within R: between the
   horizon h_lo one step below the continuous one and that continuous one, h*, which is
   t + acos(a / R) (above). Float reconstruction moves sines by far less than the 1e-4
   allowed. Floor pixels farther than R from the wall are exactly 1. Steps 4 (the
   default) and 32 (a bracket a few hundredths wide). */
static void test_wall_slices(void)
{
    int saved_w = W;
    W = 63;
    struct scene s;
    corner_scene(&s);
    struct gbuf g;
    cast(&s, &g);
    const double radius = 0.5, bias = 0.05;
    static const char *const step_sets[] = {"steps=4", "steps=32"};
    for (int v = 0; v < 2; v++) {
        const int steps = v ? 32 : 4;
        const char *sets[] = {"radius=0.5", "bias=0.05", "falloff=none", "directions=4",
                              step_sets[v]};
        struct ssg_image *ao = hbao(&g, NULL, 0, sets, 5);
        if (!ao)
            continue;
        int x = W / 2, near = 0, far = 0, far_ones = 0;
        double widest = 0;
        for (int y = H / 2; y < H; y++) {
            size_t o = (size_t)y * W + (size_t)x;
            if (g.which[o] != 0)
                continue;
            struct slice_ref r = up_slice(&s, y, radius, steps);
            double stb = r.sin_t * cos(bias) + r.cos_t * sin(bias);
            if (r.a >= radius) {
                far++;
                far_ones += ao->data[o] == 1.0f;
                continue;
            }
            double lo = 1 - fmax(r.sin_h - stb, 0) / 4, hi = 1 - fmax(r.sin_h_lo - stb, 0) / 4;
            int inside = ao->data[o] >= lo - 1e-4 && ao->data[o] <= hi + 1e-4;
            CHECK(inside);
            if (!inside || getenv("HBAO_DEBUG"))
                fprintf(stderr, "  steps %d, a = %.4f: hbao %.6f, expected [%.6f, %.6f]\n",
                        steps, r.a, ao->data[o], lo, hi);
            if (r.a > 0.05 && r.a < 0.45)
                widest = fmax(widest, hi - lo);
            near++;
        }
        CHECK(near > 10);
        CHECK(far > 10);
        CHECK_EQ(far_ones, far);
        if (steps == 32)
            CHECK(widest < 0.03);
        ssg_image_destroy(&ao);
    }
    release(&g);
    W = saved_w;
}

static void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* The slice term (sin h* - sin(t + bias))^+ of azimuth theta about V for floor point P
   (continuous march, falloff none): the floor ray along the slice's tangent meets the
   wall at E; the wall's line in the slice rises from E; h* is its point at distance R
   (the highest within R: along a line not through P the elevation seen from P is
   monotonic). 0 when the tangent leads away from the wall or the line stays out of R. */
static double slice_term(const struct scene *s, const double p[3], double theta,
                         double radius, double bias, int steps, double *term_lo)
{
    const double *nf = s->pl[0].n, *nw = s->pl[1].n;
    double len = sqrt(dot3(p, p));
    double v[3] = {-p[0] / len, -p[1] / len, -p[2] / len}, e1[3], e2[3], d[3], m[3];
    *term_lo = 0;
    /* e1 = normalize(y x V) = (vz, 0, -vx) / |..|, e2 = V x e1 (hbao/README). */
    double h1 = sqrt(v[2] * v[2] + v[0] * v[0]);
    e1[0] = v[2] / h1, e1[1] = 0, e1[2] = -v[0] / h1;
    cross3(v, e1, e2);
    for (int c = 0; c < 3; c++)
        d[c] = cos(theta) * e1[c] + sin(theta) * e2[c];
    double vn = dot3(v, nf), dn = dot3(d, nf), rho = sqrt(vn * vn + dn * dn);
    double sin_t = -dn / rho, cos_t = vn / rho;
    double stb = sin_t * cos(bias) + cos_t * sin(bias);
    double t[3] = {(vn * d[0] - dn * v[0]) / rho, (vn * d[1] - dn * v[1]) / rho,
                   (vn * d[2] - dn * v[2]) / rho};
    double toward = dot3(nw, t);
    if (!(toward < 0))
        return 0;
    double lambda = (dot3(nw, s->pl[1].p0) - dot3(nw, p)) / toward, e[3], w[3], pe[3];
    for (int c = 0; c < 3; c++)
        e[c] = p[c] + lambda * t[c];
    cross3(v, d, m);
    cross3(m, nw, w);
    double wl = sqrt(dot3(w, w)), sgn = dot3(nf, w) > 0 ? 1 : -1;
    for (int c = 0; c < 3; c++)
        w[c] *= sgn / wl;
    /* |E - P + mu w|^2 = R^2: mu^2 + 2 mu (pe.w) + |pe|^2 - R^2 = 0, largest root. */
    sub3(e, p, pe);
    double bq = dot3(pe, w), cq = dot3(pe, pe) - radius * radius, disc = bq * bq - cq;
    if (disc < 0)
        return 0;
    double mu = -bq + sqrt(disc);
    if (mu < 0)
        return 0;
    double hvec[3], wp[3];
    for (int c = 0; c < 3; c++) {
        hvec[c] = pe[c] + mu * w[c];
        wp[c] = p[c] + hvec[c];
    }
    double term = fmax(elevation(hvec, v) - stb, 0);
    /* The march: screen direction (su, sv) of D, step f R |(su, sv)| / (den steps) px
       (hbao/README). The last sample within R lies at most one step and one pixel diagonal
       (rounding at both ends) nearer P along the line than W*: the wall point seen
       there bounds the node's horizon from below. */
    struct ssg_frame f = frame();
    struct ssg_projection pr = ssg_frame_projection(&f);
    double depth = -p[2], den = fmax(depth - radius, depth / 2);
    double au = p[0] / depth, av = p[1] / depth;
    double su = d[0] + au * d[2], sv = -(d[1] + av * d[2]), sl = sqrt(su * su + sv * sv);
    double step = pr.f * radius / (den * steps) * sl;
    double up = pr.cx + pr.f * p[0] / depth, vp = pr.cy - pr.f * p[1] / depth;
    double uw = pr.cx + pr.f * wp[0] / -wp[2], vw = pr.cy - pr.f * wp[1] / -wp[2];
    double dist = ((uw - up) * su + (vw - vp) * sv) / sl - step - sqrt(2.0);
    double q[3];
    if (dist > 0 && surface_point(s, up + dist * su / sl, vp + dist * sv / sl, q) == 1) {
        sub3(q, p, hvec);
        *term_lo = fmax(elevation(hvec, v) - stb, 0);
    }
    return term;
}

/* Mean of the slice terms over n azimuths 2 pi k / n (the node's, without rotation),
   and of their lower bounds. */
static double slice_mean(const struct scene *s, const double p[3], int n, double radius,
                         double bias, int steps, double *mean_lo)
{
    double sum = 0, sum_lo = 0;
    for (int k = 0; k < n; k++) {
        double lo;
        sum += slice_term(s, p, 2 * M_PI * k / n, radius, bias, steps, &lo);
        sum_lo += lo;
    }
    *mean_lo = sum_lo / n;
    return sum / n;
}

static double case3(double c)
{
    return c >= 1 ? 1 : 1 - (acos(c) - c * sqrt(1 - c * c)) / M_PI;
}

/* The continuous limit (header): with 32 azimuths, 16 steps, no bias and falloff none,
   in the centre column of the corner. Checked in three layers:
   1. the derivation: this file's own quadrature of the slice terms over 4096 azimuths
      equals (1 + c) / 2 within 1e-3 (its quadrature error is ~1e-5);
   2. the node against the same quadrature over its 32 azimuths, bracketed by the
      continuous horizon and the horizon one step lower (slice_term), widened by 0.01
      for the rounding of samples to pixel centres: each sample moves by at most half a
      pixel diagonal (0.0115 scene units at depth 5 here, 2.5% of R) off its slice and
      is projected back along the tangent plane, which is exact for the floor but moves
      a wall sample's elevation by up to a few hundredths in one slice, with either sign
      from slice to slice (an estimate, not a proof: observed at most 0.005);
   3. against docs/analytic.md case 3: equal at the edge (both 1/2, within the allowances),
      and darker (uniform weighting) for 0.1 <= c <= 0.9, where case 3 exceeds
      (1 + c) / 2 by 0.02 to 0.06. */
static void test_wall_limit(void)
{
    int saved_w = W;
    W = 127; /* the march reaches ~40 px; the centre column's slices stay on screen */
    struct scene s;
    corner_scene(&s);
    struct gbuf g;
    cast(&s, &g);
    const double radius = 0.5, rounding = 0.01;
    const char *sets[] = {"radius=0.5", "bias=0", "falloff=none", "directions=32",
                          "steps=16"};
    struct ssg_image *ao = hbao(&g, NULL, 0, sets, 5);
    struct ssg_frame f = frame();
    struct ssg_projection pr = ssg_frame_projection(&f);
    int tested = 0, edge = 0, darker = 0;
    for (int y = H / 2; ao && y < H; y++) {
        size_t o = (size_t)y * W + (size_t)(W / 2);
        if (g.which[o] != 0)
            continue;
        double p[3];
        floor_point(&s, pr.cx, y + 0.5, p);
        double a = dot3(s.pl[1].n, p) - dot3(s.pl[1].n, s.pl[1].p0), c = a / radius;
        if (c >= 1)
            continue;
        double lo32, lo4k;
        double q32 = 1 - slice_mean(&s, p, 32, radius, 0, 16, &lo32);
        double q4k = 1 - slice_mean(&s, p, 4096, radius, 0, 16, &lo4k);
        double node = ao->data[o], closed = (1 + c) / 2;
        CHECK_NEAR(q4k, closed, 1e-3);
        int inside = node >= q32 - rounding && node <= 1 - lo32 + rounding;
        CHECK(inside);
        if (!inside || getenv("HBAO_DEBUG"))
            fprintf(stderr, "  a = %.4f: hbao %.5f, expected [%.5f, %.5f] +- %.2f; "
                    "(1 + c) / 2 = %.5f, case 3 = %.5f\n", a, node, q32, 1 - lo32, rounding,
                    closed, case3(c));
        if (c < 0.05) {
            CHECK_NEAR(node, 0.5, 0.05);
            CHECK_NEAR(case3(c), 0.5, 0.05);
            edge++;
        }
        if (c >= 0.1 && c <= 0.9) {
            CHECK(closed < case3(c) - 0.015);
            CHECK(node < case3(c));
            darker++;
        }
        tested++;
    }
    CHECK(tested > 20);
    CHECK(edge > 0);
    CHECK(darker > 10);
    ssg_image_destroy(&ao);
    release(&g);
    W = saved_w;
}

/* The linear falloff weighs each rise of the horizon by 1 - r / R <= 1: by the edge of
   the corner it darkens, less than falloff none; out of reach both are 1. */
static void test_falloff(void)
{
    struct scene s;
    corner_scene(&s);
    struct gbuf g;
    cast(&s, &g);
    const char *lin[] = {"radius=0.5", "falloff=linear", "steps=8"};
    const char *none[] = {"radius=0.5", "falloff=none", "steps=8"};
    struct ssg_image *a = hbao(&g, NULL, 0, lin, 3), *b = hbao(&g, NULL, 0, none, 3);
    if (a && b) {
        int n1, n2, n3, n4;
        double lin_near = mean_over(a, g.which, 0, H / 2, W, H / 2 + 4, 0, &n1);
        double none_near = mean_over(b, g.which, 0, H / 2, W, H / 2 + 4, 0, &n2);
        double lin_far = mean_over(a, g.which, 0, H / 2 + 40, W, H / 2 + 44, 0, &n3);
        double none_far = mean_over(b, g.which, 0, H / 2 + 40, W, H / 2 + 44, 0, &n4);
        CHECK(none_near < lin_near - 0.05);
        CHECK(lin_near < 0.95);
        CHECK_EQ(lin_far, 1.0);
        CHECK_EQ(none_far, 1.0);
        int not_darker = 0;
        for (size_t i = 0; i < (size_t)W * H; i++)
            not_darker += a->data[i] < b->data[i] - 1e-6f;
        CHECK_EQ(not_darker, 0);
    }
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    release(&g);
}

/* Wrong input shapes and parameters are refused with a code, not read out of bounds. */
static void test_rejects(void)
{
    struct ssg_image *pos = ssg_image_create(8, 8, 3), *nrm = ssg_image_create(8, 4, 3);
    struct ssg_image *dep = ssg_image_create(8, 8, 3);
    struct ssg_binding b[3] = {{"position", pos}, {"normal", nrm}, {"depth", dep}};
    struct ssg_diags diags = {0};
    struct ssg_frame f = {8, 8, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    struct ssg_outputs out;
    CHECK(ssg_node_run("hbao", b, 2, NULL, 0, &f, &out, &diags) != SSG_OK);
    ssg_outputs_release(&out);
    b[1].image = pos;
    CHECK(ssg_node_run("hbao", b, 3, NULL, 0, &f, &out, &diags) != SSG_OK);
    ssg_outputs_release(&out);
    const char *bad[] = {"radius=0"};
    CHECK_EQ(ssg_node_run("hbao", b, 2, bad, 1, &f, &out, &diags), SSG_E_RANGE);
    ssg_outputs_release(&out);
    const char *many[] = {"directions=65"};
    CHECK_EQ(ssg_node_run("hbao", b, 2, many, 1, &f, &out, &diags), SSG_E_RANGE);
    ssg_outputs_release(&out);
    CHECK_EQ(ssg_node_run("hbao", b, 1, NULL, 0, &f, &out, &diags), SSG_E_MISSING_INPUT);
    ssg_outputs_release(&out);
    ssg_image_destroy(&pos);
    ssg_image_destroy(&nrm);
    ssg_image_destroy(&dep);
}

int main(void)
{
    struct ssg_image *rot = halton_rotation();
    CHECK(rot != NULL);
    test_open_planes(rot);
    test_background(rot);
    test_corner(rot);
    test_wall_slices();
    test_wall_limit();
    test_falloff();
    test_rejects();
    ssg_image_destroy(&rot);
    return check_report();
}
