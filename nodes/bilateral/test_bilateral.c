/* test_bilateral.c - the `bilateral` node: constants stay constant, the weights are the
 * documented ones, depth steps and normal creases are not blurred across, background
 * passes through untouched, noise on a flat region drops by the factor its spatial
 * weights predict, and the result does not depend on the thread count. The separable
 * form (separable=true) matches the documented two 1D passes, equals the full filter where
 * the weights factor, stays within the bound its weights give on a tilted noisy plane,
 * keeps depth steps and is deterministic. A tent window removes a pattern of its period. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "bilateral_inputs.h"

static void test_constant(void)
{
    enum { W = 40, H = 30 };
    struct images im = make(W, H, 3);
    size_t plane = W * H;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            im.in->data[o] = 0.37f;
            im.in->data[plane + o] = 2.5f;
            im.in->data[2 * plane + o] = -1.0f;
            im.depth->data[o] = (float)(2.0 + 0.03 * x + 0.01 * y * y); /* curved */
            set_normal(im.normal, o, sin(0.1 * x), 0.2, 1.0);
        }
    const char *sets[] = {"size=7"};
    struct ssg_image *out = filter(&im, 1, sets, 1);
    if (out) {
        CHECK_EQ(out->channels, 3);
        double worst = 0;
        for (size_t o = 0; o < plane; o++) {
            worst = fmax(worst, fabs(out->data[o] - 0.37));
            worst = fmax(worst, fabs(out->data[plane + o] - 2.5) / 2.5);
            worst = fmax(worst, fabs(out->data[2 * plane + o] + 1.0));
        }
        /* A normalised mean of equal values: a few float roundings. */
        CHECK(worst < 1e-6);
    }
    ssg_image_destroy(&out);
    release(&im);
}

/* A 3 x 1 image: the centre's result is the weighted mean of the documented weights
   exp(-dx^2 / (2 s^2)) * exp(-(dd / (sigma_d d))^2 / 2) * (n.n')^p. Powers of two and
   other powers take different code paths; both are checked. */
static void test_weights(void)
{
    struct images im = make(3, 1, 1);
    const float values[3] = {1.0f, 0.0f, 3.0f};
    const float depths[3] = {2.1f, 2.0f, 1.96f};
    const double angle[3] = {0.3, 0.0, -0.5}; /* normal tilt about y, radians */
    for (int x = 0; x < 3; x++) {
        im.in->data[x] = values[x];
        im.depth->data[x] = depths[x];
        set_normal(im.normal, (size_t)x, sin(angle[x]), 0, cos(angle[x]));
    }
    static const int powers[] = {4, 3, 0};
    for (int k = 0; k < 3; k++) {
        char power[32];
        snprintf(power, sizeof power, "normal_power=%d", powers[k]);
        const char *sets[] = {"size=3", "sigma_spatial=1.5", "sigma_depth=0.05", power};
        struct ssg_image *out = filter(&im, 1, sets, 4);
        if (out) {
            double num = 0, den = 0;
            for (int x = 0; x < 3; x++) {
                double dx = x - 1, dd = (double)depths[x] - depths[1];
                double w = exp(-dx * dx / (2 * 1.5 * 1.5)) *
                           exp(-0.5 * pow(dd / (0.05 * depths[1]), 2)) *
                           pow(cos(angle[x]), powers[k]);
                num += w * values[x];
                den += w;
            }
            /* exp and ln are polynomial approximations good to a few 1e-7 relative. */
            CHECK_NEAR(out->data[1], num / den, 1e-5);
        }
        ssg_image_destroy(&out);
    }
    release(&im);
}

/* A depth step (1 | 2) carrying a value step (0 | 1): with sigma_depth 0.05 the weights
   across are exp(-200) and exp(-50), so nothing crosses. */
static void test_depth_step(void)
{
    enum { W = 32, H = 16 };
    struct images im = make(W, H, 1);
    fill_depth_step(&im);
    const char *sets[] = {"size=9"};
    struct ssg_image *out = filter(&im, 1, sets, 1);
    if (out) {
        double worst = 0;
        for (size_t o = 0; o < (size_t)W * H; o++)
            worst = fmax(worst, fabs(out->data[o] - im.in->data[o]));
        CHECK(worst < 1e-6);
    }
    /* Without the depth term's help (a huge sigma_depth) it does blur: the test can
       fail. */
    const char *loose[] = {"size=9", "sigma_depth=1000"};
    struct ssg_image *blur = filter(&im, 1, loose, 2);
    if (blur)
        CHECK(blur->data[(size_t)(H / 2) * W + W / 2 - 1] > 0.1f);
    ssg_image_destroy(&out);
    ssg_image_destroy(&blur);
    release(&im);
}

/* A V-shaped crease: depth continuous (5 + 0.02 |x - c|), normals 90 degrees apart on
   the two sides, values 0 | 1. The normal term (n.n' = 0) stops the blur; without it the
   depth term alone (differences under 1.6% at the crease) lets it through. */
static void test_crease(void)
{
    enum { W = 32, H = 16 };
    struct images im = make(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            int left = x < W / 2;
            im.in->data[o] = left ? 0.0f : 1.0f;
            im.depth->data[o] = (float)(5.0 + 0.02 * fabs(x + 0.5 - W / 2));
            set_normal(im.normal, o, left ? -1 : 1, 0, 1);
        }
    const char *with[] = {"size=9", "normal_power=16"};
    const char *without[] = {"size=9", "normal_power=0"};
    struct ssg_image *a = filter(&im, 1, with, 2);
    struct ssg_image *b = filter(&im, 1, without, 2);
    struct ssg_image *c = filter(&im, 0, with, 2); /* no normal input: no normal term */
    if (a && b && c) {
        double worst = 0;
        for (size_t o = 0; o < (size_t)W * H; o++)
            worst = fmax(worst, fabs(a->data[o] - im.in->data[o]));
        CHECK(worst < 1e-6);
        size_t edge = (size_t)(H / 2) * W + W / 2 - 1;
        CHECK(b->data[edge] > 0.1f);
        CHECK(memcmp(b->data, c->data, sizeof(float) * W * H) == 0);
    }
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&c);
    release(&im);
}

/* Background (depth 0) keeps its value and lends none: a region of 100s beside a
   surface of 0.5s changes neither. */
static void test_background(void)
{
    enum { W = 24, H = 24 };
    struct images im = make(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            int bg = x + y < W;
            im.in->data[o] = bg ? 100.0f : 0.5f;
            im.depth->data[o] = bg ? 0.0f : 3.0f;
            set_normal(im.normal, o, 0, 0, bg ? 0 : 1);
        }
    const char *sets[] = {"size=9"};
    struct ssg_image *out = filter(&im, 1, sets, 1);
    if (out) {
        double worst = 0;
        for (size_t o = 0; o < (size_t)W * H; o++)
            worst = fmax(worst, fabs(out->data[o] - im.in->data[o]));
        CHECK(worst < 1e-6);
    }
    ssg_image_destroy(&out);
    release(&im);
}

/* Gaussian noise of variance s^2 on a fronto-parallel plane: depth and normal weights are
   1, so each output is sum w_q x_q / sum w_q with the spatial weights w, of variance
   F s^2, F = sum w^2 / (sum w)^2. The sample variance over N interior pixels of this
   correlated Gaussian field has relative standard error sqrt(2 sum_l rho(l)^2 / N), rho
   the weights' normalised autocorrelation; the tolerance is four of those. */
static void test_noise(void)
{
    enum { W = 256, H = 256, SIZE = 9, R = SIZE / 2 };
    const double sigma_s = SIZE / 3.0, s = 0.1;
    struct images im = make(W, H, 1);
    for (size_t o = 0; o < (size_t)W * H; o++) {
        im.in->data[o] = (float)(0.5 + s * gaussian());
        im.depth->data[o] = 3.0f;
        set_normal(im.normal, o, 0, 0, 1);
    }
    double w[SIZE][SIZE], sum = 0, sum2 = 0;
    for (int dy = -R; dy <= R; dy++)
        for (int dx = -R; dx <= R; dx++) {
            w[dy + R][dx + R] = exp(-(dx * dx + dy * dy) / (2 * sigma_s * sigma_s));
            sum += w[dy + R][dx + R];
            sum2 += w[dy + R][dx + R] * w[dy + R][dx + R];
        }
    double factor = sum2 / (sum * sum), rho2 = 0;
    for (int ly = -2 * R; ly <= 2 * R; ly++)
        for (int lx = -2 * R; lx <= 2 * R; lx++) {
            double c = 0;
            for (int y = 0; y < SIZE; y++)
                for (int x = 0; x < SIZE; x++) {
                    int y2 = y + ly, x2 = x + lx;
                    if (y2 >= 0 && y2 < SIZE && x2 >= 0 && x2 < SIZE)
                        c += w[y][x] * w[y2][x2];
                }
            rho2 += (c / sum2) * (c / sum2);
        }
    const char *sets[] = {"size=9"};
    struct ssg_image *out = filter(&im, 1, sets, 1);
    if (out) {
        double mean = 0, var = 0;
        int n = 0;
        for (int y = R; y < H - R; y++)
            for (int x = R; x < W - R; x++)
                mean += out->data[(size_t)y * W + (size_t)x], n++;
        mean /= n;
        for (int y = R; y < H - R; y++)
            for (int x = R; x < W - R; x++) {
                double d = out->data[(size_t)y * W + (size_t)x] - mean;
                var += d * d;
            }
        var /= n - 1;
        double expected = factor * s * s, rel_se = sqrt(2 * rho2 / n);
        CHECK_NEAR(var / expected, 1.0, 4 * rel_se);
        if (getenv("BILATERAL_DEBUG"))
            fprintf(stderr, "noise: factor %.5f, ratio %.4f, tolerance %.4f\n", factor,
                    var / expected, 4 * rel_se);
        CHECK(factor < 0.05); /* it is a real reduction: about 1/69 for size 9 */
    }
    ssg_image_destroy(&out);
    release(&im);
}

static void test_threads(void)
{
    enum { W = 120, H = 77 };
    struct images im = make(W, H, 3);
    for (size_t o = 0; o < (size_t)W * H; o++) {
        for (int c = 0; c < 3; c++)
            im.in->data[(size_t)c * W * H + o] = (float)uniform01();
        im.depth->data[o] = (float)(1.0 + 0.2 * uniform01());
        set_normal(im.normal, o, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    const char *sets[] = {"size=11"};
    omp_set_num_threads(1);
    struct ssg_image *one = filter(&im, 1, sets, 1);
    omp_set_num_threads(2);
    struct ssg_image *two = filter(&im, 1, sets, 1);
    if (one && two)
        CHECK(memcmp(one->data, two->data, sizeof(float) * 3 * W * H) == 0);
    ssg_image_destroy(&one);
    ssg_image_destroy(&two);
    release(&im);
}

/* --- separable form (Belonogov eq. 4.6, 4.7) --- */

/* Depth d(x, y) = d0 + a x + b y, values 0.5 + 0.1 N(0, 1), normals all +z. */
static struct images tilted_plane(int w, int h, double a, double b)
{
    struct images im = make(w, h, 1);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t o = (size_t)y * (size_t)w + (size_t)x;
            im.in->data[o] = (float)(0.5 + 0.1 * gaussian());
            im.depth->data[o] = (float)(3.0 + a * x + b * y);
            set_normal(im.normal, o, 0, 0, 1);
        }
    return im;
}

/* The weight of tap q seen from centre c without the normal term (normals are equal). */
static double weight(const struct images *im, size_t c, size_t q, double dist2, double sigma_s,
                     double sigma_d)
{
    double dc = im->depth->data[c], dd = (double)im->depth->data[q] - dc;
    return exp(-dist2 / (2 * sigma_s * sigma_s)) * exp(-0.5 * pow(dd / (sigma_d * dc), 2));
}

/* The effective normalised weights of both forms for pixel (x, y), size x size, in double:
   full[t] = w(p, q) / sum w; sep[t] = v(dy) / V * h_row(dx) / H_row, the row pass centred
   at (x, y + dy) and the column pass at p (Belonogov eq. 4.6, 4.7). Taps outside the image
   get 0. */
static void effective_weights(const struct images *im, int x, int y, int size, double sigma_s,
                              double sigma_d, double *full, double *sep)
{
    const int r = size / 2, w = im->in->width, h = im->in->height;
    double fsum = 0, vsum = 0, v[64];
    size_t c = (size_t)y * (size_t)w + (size_t)x;
    for (int dy = -r; dy <= r; dy++) {
        int qy = y + dy;
        v[dy + r] = 0;
        if (qy < 0 || qy >= h) {
            for (int dx = -r; dx <= r; dx++)
                full[(dy + r) * size + dx + r] = sep[(dy + r) * size + dx + r] = 0;
            continue;
        }
        size_t row_c = (size_t)qy * (size_t)w + (size_t)x;
        v[dy + r] = weight(im, c, row_c, dy * dy, sigma_s, sigma_d);
        vsum += v[dy + r];
        double hsum = 0;
        for (int dx = -r; dx <= r; dx++) {
            int qx = x + dx;
            double wf = 0, wh = 0;
            if (qx >= 0 && qx < w) {
                size_t q = (size_t)qy * (size_t)w + (size_t)qx;
                wf = weight(im, c, q, dx * dx + dy * dy, sigma_s, sigma_d);
                wh = weight(im, row_c, q, dx * dx, sigma_s, sigma_d);
            }
            full[(dy + r) * size + dx + r] = wf;
            sep[(dy + r) * size + dx + r] = wh;
            fsum += wf;
            hsum += wh;
        }
        for (int dx = -r; dx <= r; dx++)
            sep[(dy + r) * size + dx + r] *= v[dy + r] / hsum;
    }
    for (int t = 0; t < size * size; t++) {
        full[t] /= fsum;
        sep[t] /= vsum;
    }
}

/* Where the depth varies along x only and the normals are equal, every row pass has the
   same weights as the matching row of the full window, so the two forms are the same
   weighted mean (the spatial Gaussian factors exactly, and image borders clip both to
   the same rectangle): they agree to float rounding and the polynomial exp (a few 1e-7
   relative per weight; 1e-5 on values within 0.5 +- 0.6). Sizes 11, 21 and the maximum
   63. */
static void test_separable_exact(void)
{
    enum { WS = 80, HS = 70 };
    struct images im = tilted_plane(WS, HS, 0.02, 0.0);
    static const char *const sizes[] = {"size=11", "size=21", "size=63"};
    for (int k = 0; k < 3; k++) {
        const char *full_sets[] = {sizes[k]};
        const char *sep_sets[] = {sizes[k], "separable=true"};
        struct ssg_image *full = filter(&im, 1, full_sets, 1);
        struct ssg_image *sep = filter(&im, 1, sep_sets, 2);
        if (full && sep) {
            double worst = 0;
            for (size_t o = 0; o < (size_t)WS * HS; o++)
                worst = fmax(worst, fabs(full->data[o] - sep->data[o]));
            CHECK(worst < 1e-5);
        }
        ssg_image_destroy(&full);
        ssg_image_destroy(&sep);
    }
    release(&im);
}

/* A plane tilted in x and y with noise: the depth Gaussian has a cross term in dx dy that
   no product of 1D weights holds, and each row pass is normalised on its own, so the forms
   differ. Both node outputs must match their formulas evaluated in double (1e-5, as
   above); and since both are normalised means of the same values, sep - full =
   sum (u_q - w_q)(x_q - full), bounded by eps max_q |x_q - full| with eps the largest
   relative difference |u_q / w_q - 1| of the two effective weights at that pixel. That
   bound (plus the 2e-5 rounding of the two outputs) is the stated tolerance. */
static void test_separable_tilt(void)
{
    enum { WS = 40, HS = 36, SIZE = 11, R = SIZE / 2 };
    const double sigma_s = SIZE / 3.0, sigma_d = 0.05;
    struct images im = tilted_plane(WS, HS, 0.012, 0.008);
    const char *full_sets[] = {"size=11"};
    const char *sep_sets[] = {"size=11", "separable=true"};
    struct ssg_image *full = filter(&im, 0, full_sets, 1);
    struct ssg_image *sep = filter(&im, 0, sep_sets, 2);
    if (full && sep) {
        double err_full = 0, err_sep = 0, excess = -INFINITY, worst_diff = 0;
        double wf[SIZE * SIZE], ws[SIZE * SIZE];
        for (int y = 0; y < HS; y++)
            for (int x = 0; x < WS; x++) {
                effective_weights(&im, x, y, SIZE, sigma_s, sigma_d, wf, ws);
                double rf = 0, rs = 0, eps = 0;
                for (int t = 0; t < SIZE * SIZE; t++) {
                    int qx = x + t % SIZE - R, qy = y + t / SIZE - R;
                    if (qx < 0 || qx >= WS || qy < 0 || qy >= HS)
                        continue;
                    double v = im.in->data[(size_t)qy * WS + (size_t)qx];
                    rf += wf[t] * v;
                    rs += ws[t] * v;
                    eps = fmax(eps, fabs(ws[t] / wf[t] - 1));
                }
                double spread = 0;
                for (int t = 0; t < SIZE * SIZE; t++) {
                    int qx = x + t % SIZE - R, qy = y + t / SIZE - R;
                    if (qx >= 0 && qx < WS && qy >= 0 && qy < HS)
                        spread = fmax(spread,
                                      fabs(im.in->data[(size_t)qy * WS + (size_t)qx] - rf));
                }
                size_t o = (size_t)y * WS + (size_t)x;
                double diff = fabs(sep->data[o] - full->data[o]);
                err_full = fmax(err_full, fabs(full->data[o] - rf));
                err_sep = fmax(err_sep, fabs(sep->data[o] - rs));
                excess = fmax(excess, diff - (eps * spread + 2e-5));
                worst_diff = fmax(worst_diff, diff);
            }
        CHECK(err_full < 1e-5);
        CHECK(err_sep < 1e-5);
        CHECK(excess <= 0);
        CHECK(worst_diff > 1e-4); /* the forms really differ here: the test can tell */
        if (getenv("BILATERAL_DEBUG"))
            fprintf(stderr, "tilt: full err %.2g, sep err %.2g, max |sep - full| %.4f, "
                    "excess over bound %.4f\n", err_full, err_sep, worst_diff, excess);
    }
    ssg_image_destroy(&full);
    ssg_image_destroy(&sep);
    release(&im);
}

/* A near square (depth 1, value 0) in the top-left quarter of a far plane (depth 2,
   value 1): edges along both axes, so both passes meet one. Weights across are exp(-200)
   (seen from the near side) and exp(-50) (from the far side) times a spatial weight
   <= 1, so nothing crosses: values move only by the rounding of 441-term float sums of
   values up to 2 (a few 1e-6; tolerance 1e-5, where a crossing moves them by 0.1 and
   more), in either form. */
static void test_separable_step(void)
{
    enum { WS = 40, HS = 32 };
    struct images im = make(WS, HS, 3);
    for (int y = 0; y < HS; y++)
        for (int x = 0; x < WS; x++) {
            size_t o = (size_t)y * WS + (size_t)x;
            int near = x < WS / 2 && y < HS / 2;
            for (int c = 0; c < 3; c++)
                im.in->data[(size_t)c * WS * HS + o] = near ? 0.0f : 1.0f + 0.5f * c;
            im.depth->data[o] = near ? 1.0f : 2.0f;
            set_normal(im.normal, o, 0, 0, 1);
        }
    const char *full_sets[] = {"size=21"};
    const char *sep_sets[] = {"size=21", "separable=true"};
    struct ssg_image *full = filter(&im, 1, full_sets, 1);
    struct ssg_image *sep = filter(&im, 1, sep_sets, 2);
    if (full && sep) {
        double worst_full = 0, worst_sep = 0;
        for (size_t o = 0; o < (size_t)3 * WS * HS; o++) {
            worst_full = fmax(worst_full, fabs(full->data[o] - im.in->data[o]));
            worst_sep = fmax(worst_sep, fabs(sep->data[o] - im.in->data[o]));
        }
        if (getenv("BILATERAL_DEBUG"))
            fprintf(stderr, "step: full %.3g, sep %.3g\n", worst_full, worst_sep);
        CHECK(worst_full < 1e-5);
        CHECK(worst_sep < 1e-5);
    }
    /* Without the depth term it does blur across, in the separable form too. */
    const char *loose[] = {"size=21", "separable=true", "sigma_depth=1000"};
    struct ssg_image *blur = filter(&im, 1, loose, 3);
    if (blur)
        CHECK(blur->data[(size_t)(HS / 4) * WS + WS / 2 - 1] > 0.1f);
    ssg_image_destroy(&full);
    ssg_image_destroy(&sep);
    ssg_image_destroy(&blur);
    release(&im);
}

/* Background passes through the separable form too, and 1 and 2 threads give the same
   bits (size 21, 3 channels, random depths and normals, some background). */
static void test_separable_threads(void)
{
    enum { WS = 131, HS = 67 };
    struct images im = make(WS, HS, 3);
    for (size_t o = 0; o < (size_t)WS * HS; o++) {
        for (int c = 0; c < 3; c++)
            im.in->data[(size_t)c * WS * HS + o] = (float)uniform01();
        im.depth->data[o] = o % 13 == 0 ? 0.0f : (float)(1.0 + 0.2 * uniform01());
        set_normal(im.normal, o, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    const char *sets[] = {"size=21", "separable=true"};
    omp_set_num_threads(1);
    struct ssg_image *one = filter(&im, 1, sets, 2);
    omp_set_num_threads(2);
    struct ssg_image *two = filter(&im, 1, sets, 2);
    if (one && two) {
        CHECK(memcmp(one->data, two->data, sizeof(float) * 3 * WS * HS) == 0);
        double worst = 0;
        for (size_t o = 0; o < (size_t)WS * HS; o += 13)
            for (int c = 0; c < 3; c++)
                worst = fmax(worst, fabs(one->data[(size_t)c * WS * HS + o] -
                                         im.in->data[(size_t)c * WS * HS + o]));
        CHECK(worst == 0); /* background: passed through untouched */
    }
    ssg_image_destroy(&one);
    ssg_image_destroy(&two);
    release(&im);
}

/* window=tent of size 2 P - 1 on a flat plane: a pattern of period P in x and y (rsm's
   interleaved tile, P = 8) leaves a constant, its mean, wherever the window lies inside
   the image: the tent is a box of P convolved with itself, so it averages whole periods.
   The default Gaussian of the same size keeps a part of it (a check that the pattern is
   one a filter could keep). Full and separable windows alike. */
static void test_tent_period(void)
{
    enum { W = 48, H = 40, P = 8 };
    struct images im = make(W, H, 1);
    double mean = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            float v = (float)((x % P) * 7 % P + 3 * ((y * 5) % P)) / 32.0f;
            im.in->data[o] = v;
            im.depth->data[o] = 3.0f;
            set_normal(im.normal, o, 0, 0, 1);
            mean += x < P && y < P ? v / (P * P) : 0.0;
        }
    const char *tent[2][3] = {{"size=15", "window=tent", "separable=false"},
                              {"size=15", "window=tent", "separable=true"}};
    const char *gauss[] = {"size=15"};
    for (int k = 0; k < 2; k++) {
        struct ssg_image *out = filter(&im, 1, tent[k], 3);
        struct ssg_image *g = filter(&im, 1, gauss, 1);
        double worst = 0, gworst = 0;
        for (int y = P - 1; out && g && y < H - P + 1; y++)
            for (int x = P - 1; x < W - P + 1; x++) {
                worst = fmax(worst, fabs(out->data[y * W + x] - mean));
                gworst = fmax(gworst, fabs(g->data[y * W + x] - mean));
            }
        CHECK(worst < 1e-5);  /* the tent: the period's mean, to rounding */
        CHECK(gworst > 1e-3); /* the Gaussian: a trace of the pattern */
        ssg_image_destroy(&out);
        ssg_image_destroy(&g);
    }
    release(&im);
}

static void test_rejects(void)
{
    struct images im = make(8, 8, 1);
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    const char *even[] = {"size=8"};
    struct ssg_binding b[2] = {{"in", im.in}, {"depth", im.depth}};
    CHECK_EQ(ssg_node_run("bilateral", b, 2, even, 1, NULL, &out, &diags), SSG_E_VALUE);
    ssg_outputs_release(&out);
    CHECK_EQ(ssg_node_run("bilateral", b, 1, NULL, 0, NULL, &out, &diags),
             SSG_E_MISSING_INPUT);
    ssg_outputs_release(&out);
    release(&im);
}

int main(void)
{
    test_constant();
    test_weights();
    test_depth_step();
    test_crease();
    test_background();
    test_noise();
    test_threads();
    test_separable_exact();
    test_separable_tilt();
    test_separable_step();
    test_separable_threads();
    test_tent_period();
    test_rejects();
    return check_report();
}
