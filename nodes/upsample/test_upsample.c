/* test_upsample.c - the `upsample` node (joint bilateral upsampling, Kopf et al. 2007):
 * a half-resolution step edge comes back without crossing its depth edge, a smooth ramp
 * is reproduced within the bias its Gaussian taps give (worked out below), constants stay
 * exactly constant, the weights are the documented ones (the formula in double), a pixel
 * none of the taps sampled takes the tap of closest depth, background is 0, and 1 and 2
 * threads give the same bits. The second image (in2 -> out2) is exactly what upsampling it
 * alone gives, `out` does not change with it, and out2 is 0 when in2 is unconnected. */
#include <math.h>
#include <omp.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

/* Full-res guide (depth, normal) and low-res image with its depth and normal. */
struct set {
    struct ssg_image *depth, *normal, *in, *low_depth, *low_normal;
};

static void free_set(struct set *s)
{
    ssg_image_destroy(&s->depth);
    ssg_image_destroy(&s->normal);
    ssg_image_destroy(&s->in);
    ssg_image_destroy(&s->low_depth);
    ssg_image_destroy(&s->low_normal);
}

/* Runs upsample on the set, with `in2` bound when not NULL; returns out and, when out2 is
   not NULL, stores out2 there. */
static struct ssg_image *upsample2(const struct set *s, const struct ssg_image *in2,
                                   const char *const *sets, int set_count,
                                   struct ssg_image **out2)
{
    struct ssg_binding b[6] = {{"in", s->in}, {"depth", s->depth}, {"low_depth", s->low_depth}};
    int n = 3;
    if (s->normal) {
        b[n++] = (struct ssg_binding){"normal", s->normal};
        b[n++] = (struct ssg_binding){"low_normal", s->low_normal};
    }
    if (in2)
        b[n++] = (struct ssg_binding){"in2", in2};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("upsample", b, n, sets, set_count, NULL, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    CHECK_EQ(out.count, 2);
    struct ssg_image *first = out.images[0];
    out.images[0] = NULL;
    if (out2) {
        *out2 = out.images[1];
        out.images[1] = NULL;
    }
    ssg_outputs_release(&out);
    return first;
}

static struct ssg_image *upsample(const struct set *s, const char *const *sets, int set_count)
{
    return upsample2(s, NULL, sets, set_count, NULL);
}

static int same_bits(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && a->width == b->width && a->height == b->height &&
           a->channels == b->channels &&
           memcmp(a->data, b->data, sizeof(float) * (size_t)a->width * (size_t)a->height *
                                        (size_t)a->channels) == 0;
}

/* The second image shares the weights: with in2 connected, out is bit for bit the out of
   the same set without it, and out2 bit for bit the out of the set with in2 as its `in`
   (same guides, so the same weights and fallback taps); unconnected, out2 is all 0 in
   out's shape. Exact equality is the claim (no tolerance): the channels are independent
   sums of the same float operations. It can fail: a weight computed differently for in2
   (or a tap read from the wrong plane) changes bits. */
static void check_second(struct set *s, const struct ssg_image *in2, const char *const *sets,
                         int set_count)
{
    struct ssg_image *alone = upsample2(s, NULL, sets, set_count, NULL), *zero = NULL;
    struct ssg_image *again = upsample2(s, NULL, sets, set_count, &zero), *out2 = NULL;
    struct ssg_image *both = upsample2(s, in2, sets, set_count, &out2);
    struct set t = *s;
    t.in = (struct ssg_image *)in2;
    struct ssg_image *ref2 = upsample2(&t, NULL, sets, set_count, NULL);
    CHECK(same_bits(alone, both));
    CHECK(same_bits(alone, again));
    CHECK(same_bits(out2, ref2));
    if (out2 && ref2) /* not vacuous: in2's upsampled values are not in's */
        CHECK(out2->channels == 3 && !same_bits(out2, alone));
    if (zero && alone) {
        CHECK(zero->width == alone->width && zero->height == alone->height &&
              zero->channels == alone->channels);
        int nonzero = 0;
        for (size_t i = 0; i < (size_t)zero->width * zero->height * zero->channels; i++)
            nonzero += zero->data[i] != 0.0f;
        CHECK_EQ(nonzero, 0);
    }
    ssg_image_destroy(&alone);
    ssg_image_destroy(&zero);
    ssg_image_destroy(&again);
    ssg_image_destroy(&out2);
    ssg_image_destroy(&both);
    ssg_image_destroy(&ref2);
}



static void set_normal(struct ssg_image *n, size_t o, double x, double y, double z)
{
    double len = sqrt(x * x + y * y + z * z);
    size_t plane = (size_t)n->width * (size_t)n->height;
    n->data[o] = (float)(x / len);
    n->data[plane + o] = (float)(y / len);
    n->data[2 * plane + o] = (float)(z / len);
}

static uint64_t rng_state = 777;
static double uniform01(void)
{
    rng_state = rng_state * 6364136223846793005ull + 1442695040888963407ull;
    return ((double)(rng_state >> 11) + 0.5) * 0x1.0p-53;
}

/* A near rectangle (depth 1, value 0) over a far plane (depth 2, value 1), edges at odd
   columns and rows so that 2 x 2 blocks straddle them. The low-res depth comes from
   `downsample`, the low-res value matches it (0 where the low depth is 1). Seen from the
   far side a near tap weighs exp(-0.5 (1 / (0.05 * 2))^2) = exp(-50) ~ 2e-22 of a far one,
   the other way exp(-200) (below 1e-30: 0); every pixel keeps its side's value exactly up
   to float rounding (1e-6), so the edge stays where the full-res depth has it, 0 px away.
   With the depth term switched off (sigma_depth 1000) the edge does blur: the test can
   fail. */
static void test_step(void)
{
    enum { FW = 40, FH = 30, NX = 17, NY = 13 };
    struct set s = {.depth = ssg_image_create(FW, FH, 1)};
    for (int y = 0; y < FH; y++)
        for (int x = 0; x < FW; x++)
            s.depth->data[(size_t)y * FW + (size_t)x] = x < NX && y < NY ? 1.0f : 2.0f;
    struct ssg_binding b[1] = {{"depth", s.depth}};
    struct ssg_diags diags = {0};
    struct ssg_outputs low;
    CHECK_EQ(ssg_node_run("downsample", b, 1, NULL, 0, NULL, &low, &diags), SSG_OK);
    s.low_depth = low.images[0];
    low.images[0] = NULL;
    ssg_outputs_release(&low);
    int lw = s.low_depth->width, lh = s.low_depth->height;
    CHECK_EQ(lw, FW / 2);
    s.in = ssg_image_create(lw, lh, 1);
    for (int i = 0; i < lw * lh; i++)
        s.in->data[i] = s.low_depth->data[i] == 1.0f ? 0.0f : 1.0f;
    struct ssg_image *out = upsample(&s, NULL, 0);
    if (out) {
        CHECK_EQ(out->width, FW);
        CHECK_EQ(out->height, FH);
        double worst = 0;
        for (int y = 0; y < FH; y++)
            for (int x = 0; x < FW; x++) {
                double want = x < NX && y < NY ? 0.0 : 1.0;
                worst = fmax(worst, fabs(out->data[(size_t)y * FW + (size_t)x] - want));
            }
        CHECK(worst < 1e-6);
    }
    const char *loose[] = {"sigma_depth=1000"};
    struct ssg_image *blur = upsample(&s, loose, 1);
    if (blur) /* the far pixel beside the edge takes some of the near side's 0 */
        CHECK(blur->data[(size_t)(NY / 2) * FW + NX] < 0.9f);
    ssg_image_destroy(&out);
    ssg_image_destroy(&blur);
    /* a colour in2 beside the scalar in, with and without the depth term */
    struct ssg_image *in2 = ssg_image_create(lw, lh, 3);
    for (int i = 0; i < 3 * lw * lh; i++)
        in2->data[i] = (float)uniform01();
    check_second(&s, in2, NULL, 0);
    check_second(&s, in2, loose, 1);
    ssg_image_destroy(&in2);
    free_set(&s);
}

/* A smooth ramp on a plane of constant depth: the low-res pixel (X, Y) holds the ramp
   r(x, y) = 0.2 + 0.01 x + 0.005 y at its block's first pixel (2X, 2Y), the one
   `downsample` keeps when a block's depths are equal and the one upsample finds there. The
   depth term is 1 (flat plane: slope 0), so the output is the ramp at the Gaussian-weighted
   mean of the sample positions, sigma 1 low-res px = 2 full-res px. An even coordinate has
   its samples at -2, 0, +2: no bias; an odd one at -3, -1, +1 with weights e^-1.125,
   e^-0.125, e^-0.125, whose mean offset is -3 e^-1.125 / (e^-1.125 + 2 e^-0.125) =
   -0.4661 full-res px. So |out - r(x, y)| <= 0.4661 (0.01 + 0.005) + 1e-6 away from the
   border (taps cut off there), at most 1e-6 where x and y are both even, and the largest
   error is that bias, not 0. */
static void test_ramp(void)
{
    enum { FW = 48, FH = 36 };
    struct set s = {.depth = ssg_image_create(FW, FH, 1),
                    .in = ssg_image_create(FW / 2, FH / 2, 1),
                    .low_depth = ssg_image_create(FW / 2, FH / 2, 1)};
    for (int i = 0; i < FW * FH; i++)
        s.depth->data[i] = 3.0f;
    for (int y = 0; y < FH / 2; y++)
        for (int x = 0; x < FW / 2; x++) {
            size_t o = (size_t)y * (FW / 2) + (size_t)x;
            s.low_depth->data[o] = 3.0f;
            s.in->data[o] = (float)(0.2 + 0.01 * (2 * x) + 0.005 * (2 * y));
        }
    struct ssg_image *out = upsample(&s, NULL, 0);
    if (out) {
        double worst = 0, worst_even = 0;
        for (int y = 4; y < FH - 4; y++)
            for (int x = 4; x < FW - 4; x++) {
                double want = 0.2 + 0.01 * x + 0.005 * y;
                double err = fabs(out->data[(size_t)y * FW + (size_t)x] - want);
                worst = fmax(worst, err);
                if (x % 2 == 0 && y % 2 == 0)
                    worst_even = fmax(worst_even, err);
            }
        CHECK(worst <= 0.4661 * 0.015 + 1e-6);
        CHECK(worst > 0.5 * 0.4661 * 0.015);
        CHECK(worst_even <= 1e-6);
    }
    ssg_image_destroy(&out);
    free_set(&s);
}

/* Depth of full-res pixel (x, y) of a w x h image, 0 outside (the formula's). */
static double depth_or_0(const struct ssg_image *d, int x, int y)
{
    if (x < 0 || y < 0 || x >= d->width || y >= d->height)
        return 0.0;
    return d->data[(size_t)y * (size_t)d->width + (size_t)x];
}

/* The README's slope: the one-sided difference of smaller magnitude over surface
   neighbours (lo, hi > 0), ties hi - d, 0 when neither is a surface or it is steeper
   than 0.25 d. */
static double slope_of(double d, double lo, double hi)
{
    double f = hi > 0 ? hi - d : INFINITY, b = lo > 0 ? d - lo : INFINITY;
    double s = fabs(f) <= fabs(b) ? f : b;
    return fabs(s) <= 0.25 * d ? s : 0.0;
}

/* The README's sample position of low-res pixel (qx, qy) at depth dq, factor 2: the first
   full-res pixel of its block (row-major) of depth dq, else the block's centre. */
static void sample_at(const struct ssg_image *d, int qx, int qy, double dq, double *sx,
                      double *sy)
{
    *sx = 2 * qx + 0.5, *sy = 2 * qy + 0.5;
    for (int y = 2 * qy; y < 2 * qy + 2; y++)
        for (int x = 2 * qx; x < 2 * qx + 2; x++)
            if (dq > 0 && depth_or_0(d, x, y) == dq) {
                *sx = x, *sy = y;
                return;
            }
}

/* The documented weights, in double, on random depths and normals (factor 2, size 5, a
   general normal power and a power of two), half the low-res depths copied from a pixel
   of their block (so that the sample positions are found there), the rest not (centre):
   |node - formula| < 1e-5 (polynomial exp and ln, a few 1e-7 relative per weight). */
static double formula_at(const struct set *s, int x, int y, int ch, int power)
{
    enum { R = 2 };
    const int fw = s->depth->width, lw = s->in->width, lh = s->in->height;
    size_t o = (size_t)y * fw + (size_t)x, fp = (size_t)fw * s->depth->height;
    size_t lp = (size_t)lw * lh;
    double dp = s->depth->data[o];
    double gx = slope_of(dp, depth_or_0(s->depth, x - 1, y), depth_or_0(s->depth, x + 1, y));
    double gy = slope_of(dp, depth_or_0(s->depth, x, y - 1), depth_or_0(s->depth, x, y + 1));
    double num = 0, den = 0;
    for (int qy = y / 2 - R; qy <= y / 2 + R; qy++)
        for (int qx = x / 2 - R; qx <= x / 2 + R; qx++) {
            if (qx < 0 || qx >= lw || qy < 0 || qy >= lh)
                continue;
            size_t q = (size_t)qy * lw + (size_t)qx;
            double sx, sy, c = 0, dq = s->low_depth->data[q];
            sample_at(s->depth, qx, qy, dq, &sx, &sy);
            double rx = x - sx, ry = y - sy, plane = dp - (gx * rx + gy * ry);
            double dd = (dq - plane) / (0.03 * dp);
            for (int k = 0; k < 3; k++)
                c += (double)s->normal->data[k * fp + o] * s->low_normal->data[k * lp + q];
            double w = exp(-(rx * rx + ry * ry) / (2 * 2.6 * 2.6)) * exp(-0.5 * dd * dd) *
                       pow(fmax(c, 0), power);
            num += w * s->in->data[ch * lp + q];
            den += w;
        }
    return num / den;
}

static void test_formula(void)
{
    enum { FW = 21, FH = 15, LW = 11, LH = 8 };
    struct set s = {ssg_image_create(FW, FH, 1), ssg_image_create(FW, FH, 3),
                    ssg_image_create(LW, LH, 3), ssg_image_create(LW, LH, 1),
                    ssg_image_create(LW, LH, 3)};
    for (int i = 0; i < FW * FH; i++) {
        s.depth->data[i] = (float)(2.0 + 0.1 * uniform01());
        set_normal(s.normal, (size_t)i, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    for (int i = 0; i < LW * LH; i++) {
        for (int c = 0; c < 3; c++)
            s.in->data[(size_t)c * LW * LH + (size_t)i] = (float)uniform01();
        int qx = i % LW, qy = i / LW, px = 2 * qx + i % 2, py = 2 * qy + (i / 3) % 2;
        s.low_depth->data[i] = i % 4 < 2 && px < FW && py < FH
                                   ? s.depth->data[(size_t)py * FW + (size_t)px]
                                   : (float)(2.0 + 0.1 * uniform01());
        set_normal(s.low_normal, (size_t)i, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    static const int powers[] = {5, 8};
    for (int k = 0; k < 2; k++) {
        char power[32];
        snprintf(power, sizeof power, "normal_power=%d", powers[k]);
        const char *sets[] = {"size=5", "sigma_spatial=1.3", "sigma_depth=0.03", power};
        struct ssg_image *out = upsample(&s, sets, 4);
        if (!out)
            continue;
        double worst = 0;
        for (int y = 0; y < FH; y++)
            for (int x = 0; x < FW; x++)
                for (int ch = 0; ch < 3; ch++)
                    worst = fmax(worst, fabs(out->data[(size_t)ch * FW * FH +
                                                       (size_t)y * FW + (size_t)x] -
                                             formula_at(&s, x, y, ch, powers[k])));
        CHECK(worst < 1e-5);
        ssg_image_destroy(&out);
    }
    free_set(&s);
}

/* A constant image stays exactly constant on every surface pixel, whatever the depths,
   edges and normals (the sums are relative to the centre tap, so equal values add exact
   zeros); full-res background is 0. Colour input, with normals. */
static void test_constant(void)
{
    enum { FW = 37, FH = 23, LW = 19, LH = 12 };
    struct set s = {ssg_image_create(FW, FH, 1), ssg_image_create(FW, FH, 3),
                    ssg_image_create(LW, LH, 3), ssg_image_create(LW, LH, 1),
                    ssg_image_create(LW, LH, 3)};
    for (int i = 0; i < FW * FH; i++) {
        s.depth->data[i] = i % 11 == 0 ? 0.0f : (float)(1.0 + 3.0 * uniform01());
        set_normal(s.normal, (size_t)i, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    for (int i = 0; i < LW * LH; i++) {
        const float c[3] = {0.37f, 2.5f, -1.0f};
        for (int ch = 0; ch < 3; ch++)
            s.in->data[(size_t)ch * LW * LH + (size_t)i] = c[ch];
        s.low_depth->data[i] = i % 7 == 0 ? 0.0f : (float)(1.0 + 3.0 * uniform01());
        set_normal(s.low_normal, (size_t)i, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    struct ssg_image *out = upsample(&s, NULL, 0);
    if (out) {
        CHECK_EQ(out->channels, 3);
        int wrong = 0;
        size_t fp = FW * FH;
        for (size_t o = 0; o < fp; o++) {
            int bg = s.depth->data[o] == 0.0f;
            wrong += out->data[o] != (bg ? 0.0f : 0.37f);
            wrong += out->data[fp + o] != (bg ? 0.0f : 2.5f);
            wrong += out->data[2 * fp + o] != (bg ? 0.0f : -1.0f);
        }
        CHECK_EQ(wrong, 0);
    }
    ssg_image_destroy(&out);
    free_set(&s);
}

/* Pixels none of the taps sampled, over low-res depths 5, 6 / 7, 8 (values 10, 20 / 30,
   40), full-res depths (rows top down; 0 = background)
       1 0 100 0
       0 6  0  6
       6 6  6  6
       6 6  6  0
   Pixel (0,0) at depth 1 and (2,0) at depth 100 have only background beside them (their
   planes are flat: slope 0) and no weight (exp(-0.5 (4 / 0.05)^2) = 0): they take the tap
   of closest depth, 10 and 40. Pixel (1,2) at depth 6 is a normal case: the 6 (value 20,
   taken at (3,1), 5 full-res px^2 away: e^-0.625) dominates, the 5 and 7 weigh e^-5.9 and
   e^-5.6 (depth 1/6 off: e^-5.56), the 8 e^-22, moving it by well under 0.5. Pixel (3,3) is
   background: 0. With all taps background (low depth 0) the pixel's own block, the
   centre tap, is taken. */
static void test_fallback(void)
{
    struct set s = {.depth = ssg_image_create(4, 4, 1), .in = ssg_image_create(2, 2, 1),
                    .low_depth = ssg_image_create(2, 2, 1)};
    static const float low_depth[4] = {5, 6, 7, 8}, values[4] = {10, 20, 30, 40};
    static const float depth[16] = {1, 0, 100, 0, 0, 6, 0, 6, 6, 6, 6, 6, 6, 6, 6, 0};
    memcpy(s.depth->data, depth, sizeof depth);
    memcpy(s.low_depth->data, low_depth, sizeof low_depth);
    memcpy(s.in->data, values, sizeof values);
    struct ssg_image *out = upsample(&s, NULL, 0);
    if (out) {
        CHECK(out->data[0] == 10.0f);
        CHECK(out->data[2] == 40.0f);
        CHECK(out->data[15] == 0.0f); /* background */
        CHECK_NEAR(out->data[9], 20.0, 0.5); /* depth 6: the 6 dominates */
        ssg_image_destroy(&out);
    }
    for (int i = 0; i < 4; i++)
        s.low_depth->data[i] = 0.0f;
    out = upsample(&s, NULL, 0);
    if (out) {
        CHECK(out->data[0] == 10.0f);  /* block (0,0)'s centre tap */
        CHECK(out->data[10] == 40.0f); /* pixel (2,2): block (1,1) */
        ssg_image_destroy(&out);
    }
    free_set(&s);
}

static void test_threads(void)
{
    enum { FW = 301, FH = 77, LW = 151, LH = 39 };
    struct set s = {ssg_image_create(FW, FH, 1), ssg_image_create(FW, FH, 3),
                    ssg_image_create(LW, LH, 3), ssg_image_create(LW, LH, 1),
                    ssg_image_create(LW, LH, 3)};
    for (int i = 0; i < FW * FH; i++) {
        s.depth->data[i] = (float)(1.0 + 0.2 * uniform01());
        set_normal(s.normal, (size_t)i, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    for (int i = 0; i < LW * LH; i++) {
        for (int c = 0; c < 3; c++)
            s.in->data[(size_t)c * LW * LH + (size_t)i] = (float)uniform01();
        s.low_depth->data[i] = (float)(1.0 + 0.2 * uniform01());
        set_normal(s.low_normal, (size_t)i, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    const char *sets[] = {"size=5"};
    omp_set_num_threads(1);
    struct ssg_image *one = upsample(&s, sets, 1);
    omp_set_num_threads(2);
    struct ssg_image *two = upsample(&s, sets, 1);
    if (one && two)
        CHECK(memcmp(one->data, two->data, sizeof(float) * 3 * FW * FH) == 0);
    ssg_image_destroy(&one);
    ssg_image_destroy(&two);
    free_set(&s);
}

/* The random-depth case of test_threads (random depths and normals, size 5) with a scalar
   in and a colour in2, and the fallback case (pixels no tap sampled) with a colour in2:
   see check_second. */
static void test_second(void)
{
    enum { FW = 301, FH = 77, LW = 151, LH = 39 };
    struct set s = {ssg_image_create(FW, FH, 1), ssg_image_create(FW, FH, 3),
                    ssg_image_create(LW, LH, 1), ssg_image_create(LW, LH, 1),
                    ssg_image_create(LW, LH, 3)};
    struct ssg_image *in2 = ssg_image_create(LW, LH, 3);
    for (int i = 0; i < FW * FH; i++) {
        s.depth->data[i] = i % 13 == 0 ? 0.0f : (float)(1.0 + 0.2 * uniform01());
        set_normal(s.normal, (size_t)i, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    for (int i = 0; i < LW * LH; i++) {
        s.in->data[i] = (float)uniform01();
        for (int c = 0; c < 3; c++)
            in2->data[(size_t)c * LW * LH + (size_t)i] = (float)uniform01();
        s.low_depth->data[i] = i % 17 == 0 ? 0.0f : (float)(1.0 + 0.2 * uniform01());
        set_normal(s.low_normal, (size_t)i, uniform01() - 0.5, uniform01() - 0.5, 1.0);
    }
    const char *sets[] = {"size=5"}, *tight[] = {"sigma_depth=0.001"};
    check_second(&s, in2, sets, 1);
    check_second(&s, in2, tight, 1); /* many pixels fall back: no tap within ~1% depth */
    ssg_image_destroy(&in2);
    free_set(&s);

    struct set f = {.depth = ssg_image_create(4, 4, 1), .in = ssg_image_create(2, 2, 1),
                    .low_depth = ssg_image_create(2, 2, 1)};
    static const float low_depth[4] = {5, 6, 7, 8};
    for (int i = 0; i < 16; i++)
        f.depth->data[i] = i == 15 ? 0.0f : (float)(1.0 + 9.0 * uniform01());
    memcpy(f.low_depth->data, low_depth, sizeof low_depth);
    in2 = ssg_image_create(2, 2, 3);
    for (int i = 0; i < 4; i++)
        f.in->data[i] = (float)uniform01();
    for (int i = 0; i < 12; i++)
        in2->data[i] = (float)uniform01();
    check_second(&f, in2, NULL, 0);
    ssg_image_destroy(&in2);
    free_set(&f);
}

/* in2 must be the size of in. */
static void test_second_rejects(void)
{
    struct set s = {.depth = ssg_image_create(8, 8, 1), .in = ssg_image_create(4, 4, 1),
                    .low_depth = ssg_image_create(4, 4, 1)};
    struct ssg_image *in2 = ssg_image_create(3, 4, 3);
    struct ssg_binding b[4] = {{"in", s.in}, {"depth", s.depth}, {"low_depth", s.low_depth},
                               {"in2", in2}};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    CHECK_EQ(ssg_node_run("upsample", b, 4, NULL, 0, NULL, &out, &diags), SSG_E_SIZE);
    ssg_image_destroy(&in2);
    free_set(&s);
}

static void test_rejects(void)
{
    struct set s = {.depth = ssg_image_create(8, 8, 1), .normal = ssg_image_create(8, 8, 3),
                    .in = ssg_image_create(3, 3, 1), .low_depth = ssg_image_create(3, 3, 1)};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    struct ssg_binding b[4] = {{"in", s.in}, {"depth", s.depth}, {"low_depth", s.low_depth},
                               {"normal", s.normal}};
    /* 8 -> 3 is factor 3 (ceil(8 / 3) = 3); 8 -> 5 is no integer factor. */
    CHECK_EQ(ssg_node_run("upsample", b, 3, NULL, 0, NULL, &out, &diags), SSG_OK);
    ssg_outputs_release(&out);
    CHECK_EQ(ssg_node_run("upsample", b, 4, NULL, 0, NULL, &out, &diags),
             SSG_E_MISSING_INPUT); /* normal without low_normal */
    struct set t = {.depth = ssg_image_create(8, 8, 1), .in = ssg_image_create(5, 5, 1),
                    .low_depth = ssg_image_create(5, 5, 1)};
    struct ssg_binding c[3] = {{"in", t.in}, {"depth", t.depth}, {"low_depth", t.low_depth}};
    CHECK_EQ(ssg_node_run("upsample", c, 3, NULL, 0, NULL, &out, &diags), SSG_E_SIZE);
    const char *even[] = {"size=4"};
    CHECK_EQ(ssg_node_run("upsample", b, 3, even, 1, NULL, &out, &diags), SSG_E_VALUE);
    free_set(&s);
    free_set(&t);
}

int main(void)
{
    test_step();
    test_ramp();
    test_formula();
    test_constant();
    test_fallback();
    test_threads();
    test_rejects();
    test_second();
    test_second_rejects();
    return check_report();
}
