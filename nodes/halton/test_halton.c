/* test_halton.c - the `halton` node: radical inverse values of eq. 6 worked out by hand,
 * the period property of eq. 8, the first kernel samples' values worked out by hand (of
 * frame 0 and frame 1: the properties alone hold wherever the sequence starts), kernel
 * geometry (hemisphere, length, direction density),
 * determinism, seed dependence of the rotation tile, and rejection of bad parameters. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "halton/halton.h"
#include "graph/node.h"
#include "ssgraph.h"

static struct ssg_frame frame_seed(uint64_t seed)
{
    return (struct ssg_frame){64, 64, 45.0f, 0.05f, 100.0f, seed, 0, 0, 0};
}

/* Runs halton with the given settings; returns the error code, outputs in *out. */
static enum ssg_err run(const char *const *sets, int count, uint64_t seed,
                        struct ssg_outputs *out)
{
    struct ssg_diags diags = {0};
    struct ssg_frame frame = frame_seed(seed);
    enum ssg_err e = ssg_node_run("halton", NULL, 0, sets, count, &frame, out, &diags);
    return e;
}

/* The node's descriptor, and in *p its default parameters with `set` applied (NULL:
   none); NULL (a failed CHECK) when the node is missing. For the tests that call
   prepare() themselves. */
static const struct ssg_node_desc *defaults(struct ssg_halton_params *p, const char *set)
{
    const struct ssg_node_desc *d = ssg_node_find("halton", 6);
    CHECK(d != NULL);
    if (!d)
        return NULL;
    ssg_params_defaults(d->params, p);
    struct ssg_diags diags = {0};
    if (set)
        CHECK_EQ(ssg_param_set_text(d->params, p, set, "<test>", "halton", &diags), SSG_OK);
    return d;
}

static void test_radical_inverse(void)
{
    /* Section 4.2's own example: 50 = 110010b -> 0.010011b = 0.296875, and its
       neighbours 16, 32 and 64 indices on. */
    CHECK(ssg_halton_radical_inverse(50, 2) == 0.296875);
    CHECK(ssg_halton_radical_inverse(50 + 16, 2) == 0.2578125);
    CHECK(ssg_halton_radical_inverse(50 + 32, 2) == 0.2890625);
    CHECK(ssg_halton_radical_inverse(50 + 64, 2) == 0.3046875);
    CHECK(ssg_halton_radical_inverse(0, 2) == 0.0);
    CHECK(ssg_halton_radical_inverse(1, 2) == 0.5);
    CHECK(ssg_halton_radical_inverse(6, 2) == 0.375); /* 110b -> 0.011b */
    /* Base 3: 1 -> 1/3, 2 -> 2/3, 3 = 10 -> 1/9, 5 = 12 -> 2/3 + 1/9 = 7/9,
       7 = 21 -> 1/3 + 2/9 = 5/9, 50 = 1212 -> 2/3 + 1/9 + 2/27 + 1/81 = 70/81. */
    CHECK(ssg_halton_radical_inverse(1, 3) == 1.0 / 3.0);
    CHECK(ssg_halton_radical_inverse(2, 3) == 2.0 / 3.0);
    CHECK(ssg_halton_radical_inverse(3, 3) == 1.0 / 9.0);
    CHECK(ssg_halton_radical_inverse(5, 3) == 7.0 / 9.0);
    CHECK(ssg_halton_radical_inverse(7, 3) == 5.0 / 9.0);
    CHECK(ssg_halton_radical_inverse(50, 3) == 70.0 / 81.0);
    /* Base 5: 7 = 12 -> 2/5 + 1/25 = 11/25. */
    CHECK(ssg_halton_radical_inverse(7, 5) == 11.0 / 25.0);
}

static void test_period_property(void)
{
    /* Eq. 8: |Phi_b(i) - Phi_b(i + m N_g)| < b^-k for N_g = l b^k. */
    static const int bases[] = {2, 3, 5, 7};
    int violations = 0, cases = 0;
    for (int bi = 0; bi < 4; bi++) {
        int b = bases[bi];
        for (int k = 0; k <= 3; k++) {
            int bk = 1;
            for (int t = 0; t < k; t++)
                bk *= b;
            for (int l = 1; l <= 4; l++)
                for (int m = 1; m <= 5; m++)
                    for (int i = 0; i < 300; i++) {
                        uint64_t ng = (uint64_t)l * (uint64_t)bk;
                        double d = fabs(ssg_halton_radical_inverse((uint64_t)i, b) -
                                        ssg_halton_radical_inverse(i + (uint64_t)m * ng, b));
                        cases++;
                        violations += !(d < 1.0 / bk);
                    }
        }
    }
    CHECK(cases > 0);
    CHECK_EQ(violations, 0);
    CHECK_EQ(ssg_halton_period_digits(10, 2), 1);
    CHECK_EQ(ssg_halton_period_digits(10, 5), 1);
    CHECK_EQ(ssg_halton_period_digits(40, 2), 3);
    CHECK_EQ(ssg_halton_period_digits(7, 2), 0);
}

/* Length and unit direction of kernel sample i. */
static double sample_len(const struct ssg_image *k, int i, double dir[3])
{
    double s[3];
    for (int c = 0; c < 3; c++)
        s[c] = k->data[c * k->width + i];
    double len = sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
    for (int c = 0; c < 3; c++)
        dir[c] = s[c] / len;
    return len;
}

/* The paper's example: bases 2 and 5, period 10. Every block of 10 samples meets each of
   the 2 x 5 cells once, sample r of block j shares its cell with sample r of block 0, and
   the node's kernel really is made of those points. */
static void test_period_kernel(void)
{
    const char *sets[] = {"count=40", "bases=[2,5]", "period=10", "mapping=cosine",
                          "falloff=1", "min_scale=0.1"};
    struct ssg_halton_params p = {.count = 40, .bases = {2, {2, 5}}, .offset = 1,
                                  .period = 10, .mapping = SSG_HALTON_COSINE, .falloff = 1,
                                  .min_scale = 0.1f, .pattern = 4};
    struct ssg_outputs out;
    CHECK_EQ(run(sets, SSG_COUNT(sets), 1, &out), SSG_OK);
    if (out.count < 1)
        return;
    for (int block = 0; block < 4; block++) {
        int seen[10] = {0};
        for (int r = 0; r < 10; r++) {
            double u[3], u0[3];
            ssg_halton_point(&p, block * 10 + r, u);
            ssg_halton_point(&p, r, u0);
            int cell = (int)(u[0] * 2) * 5 + (int)(u[1] * 5);
            seen[cell]++;
            CHECK(fabs(u[0] - u0[0]) < 1.0 / 2 && fabs(u[1] - u0[1]) < 1.0 / 5);
            CHECK((int)(u[0] * 2) == (int)(u0[0] * 2) && (int)(u[1] * 5) == (int)(u0[1] * 5));
            /* Length coordinate: same stratum 1/10 wide in every block. */
            CHECK((int)(u[2] * 10) == r);
        }
        for (int c = 0; c < 10; c++)
            CHECK_EQ(seen[c], 1);
    }
    /* Over all blocks the length coordinates are exactly (m + 0.5) / count. */
    int hit[40] = {0};
    for (int i = 0; i < 40; i++) {
        double u[3];
        ssg_halton_point(&p, i, u);
        double m = u[2] * 40 - 0.5;
        CHECK_NEAR(m, floor(m + 0.5), 1e-9);
        int mi = (int)floor(m + 0.5);
        if (mi >= 0 && mi < 40)
            hit[mi]++;
    }
    for (int i = 0; i < 40; i++)
        CHECK_EQ(hit[i], 1);
    /* The kernel is the cosine map of these points: recover (u0, u1, t) from it.
       Cosine: z = len sqrt(1 - u0), azimuth 2 pi u1, len = 0.1 + 0.9 t. */
    const struct ssg_image *k = out.images[0];
    for (int i = 0; i < 40; i++) {
        double u[3], dir[3];
        ssg_halton_point(&p, i, u);
        double len = sample_len(k, i, dir);
        CHECK_NEAR(len, 0.1 + 0.9 * u[2], 1e-5);
        CHECK_NEAR(1.0 - dir[2] * dir[2], u[0], 1e-5);
        if (u[0] > 1e-3) {
            double az = atan2(dir[1], dir[0]) / (2 * M_PI);
            az -= floor(az);
            double daz = fabs(az - u[1]);
            CHECK(daz < 1e-5 || fabs(daz - 1.0) < 1e-5);
        }
    }
    ssg_outputs_release(&out);
}

/* Kernel sample i of k against the point len * (x, y, z) with (x, y, z) a unit direction
   worked out by hand; 2e-7 covers the float rounding of values below 1. */
static void check_sample(const char *what, const struct ssg_image *k, int i, double len,
                         double x, double y, double z)
{
    const double want[3] = {len * x, len * y, len * z};
    int bad = 0;
    for (int c = 0; c < 3; c++) {
        CHECK_NEAR(k->data[c * k->width + i], want[c], 2e-7);
        bad += !(fabs(k->data[c * k->width + i] - want[c]) <= 2e-7);
    }
    if (bad)
        fprintf(stderr, "  %s, sample %d: (%.7f, %.7f, %.7f), expected (%.7f, %.7f, %.7f)\n",
                what, i, k->data[i], k->data[k->width + i], k->data[2 * k->width + i],
                want[0], want[1], want[2]);
}

/* The first samples' values, worked out by hand from eq. 6 and the mappings of halton.c,
   so that a sequence shifted by one index (every property above holds wherever the
   sequence starts) fails. Default count 16, bases [2, 3], falloff 2, min_scale 0.1; the
   Halton index of sample i is offset + i, the length coordinate (no third base)
   t = (i + 1/2) / 16, so len = 0.1 + 0.9 t^2: 0.1 + 0.9 / 1024 for sample 0 and
   0.1 + 8.1 / 1024 for sample 1, whatever the offset.
   offset 1 (the default), sample 0 = index 1: phi_2(1) = 1/2, phi_3(1) = 1/3, so the
   azimuth is 2 pi / 3 (cos -1/2, sin sqrt(3)/2);
     cosine (default): sin theta = sqrt(u0) = sqrt(1/2), cos theta = sqrt(1 - u0) =
       sqrt(1/2): direction (-sqrt(2)/4, sqrt(6)/4, sqrt(2)/2);
     uniform: cos theta = 1 - u0 = 1/2, sin theta = sqrt(3)/2:
       direction (-sqrt(3)/4, 3/4, 1/2).
   sample 1 = index 2: phi_2(2) = 1/4, phi_3(2) = 2/3, azimuth 4 pi / 3 (cos -1/2,
   sin -sqrt(3)/2);
     cosine: sin theta = 1/2, cos theta = sqrt(3)/2: (-1/4, -sqrt(3)/4, sqrt(3)/2);
     uniform: cos theta = 3/4, sin theta = sqrt(7)/4: (-sqrt(7)/8, -sqrt(21)/8, 3/4).
   offset 0, sample 0 = index 0: phi(0) = 0 in every base, the point (0, 0): straight up
   the normal in either mapping, (0, 0, 1).
   With a third base 5 the length is Halton too: t = phi_5(1) = 1/5 for sample 0 at
   offset 1, phi_5(2) = 2/5 for sample 1, so len = 0.1 + 0.9 / 25 and 0.1 + 0.9 * 4 / 25. */
static void test_fixed_values(void)
{
    const double len0 = 0.1 + 0.9 / 1024, len1 = 0.1 + 8.1 / 1024;
    const double r2 = sqrt(2.0), r3 = sqrt(3.0), r6 = sqrt(6.0), r7 = sqrt(7.0);
    const struct {
        const char *sets[2]; /* NULL: the defaults (offset 1, cosine) */
        int sample;
        double len, x, y, z; /* len * (x, y, z), (x, y, z) a unit direction */
    } cases[] = {
        {{NULL}, 0, len0, -r2 / 4, r6 / 4, r2 / 2},
        {{NULL}, 1, len1, -0.25, -r3 / 4, r3 / 2},
        {{"offset=1", "mapping=cosine"}, 0, len0, -r2 / 4, r6 / 4, r2 / 2},
        {{"offset=1", "mapping=cosine"}, 1, len1, -0.25, -r3 / 4, r3 / 2},
        {{"offset=1", "mapping=uniform"}, 0, len0, -r3 / 4, 0.75, 0.5},
        {{"offset=1", "mapping=uniform"}, 1, len1, -r7 / 8, -sqrt(21.0) / 8, 0.75},
        {{"offset=0", "mapping=cosine"}, 0, len0, 0, 0, 1},
        {{"offset=0", "mapping=uniform"}, 0, len0, 0, 0, 1},
        {{"bases=[2,3,5]"}, 0, 0.1 + 0.9 / 25, -r2 / 4, r6 / 4, r2 / 2},
        {{"bases=[2,3,5]"}, 1, 0.1 + 0.9 * 4 / 25, -0.25, -r3 / 4, r3 / 2},
    };
    for (int i = 0; i < SSG_COUNT(cases); i++) {
        int n = !cases[i].sets[0] ? 0 : !cases[i].sets[1] ? 1 : 2;
        struct ssg_outputs out;
        CHECK_EQ(run(cases[i].sets, n, 1, &out), SSG_OK);
        if (out.count == 2) {
            char what[64];
            snprintf(what, sizeof what, "%s%s%s", n ? cases[i].sets[0] : "defaults",
                     n > 1 ? " " : "", n > 1 ? cases[i].sets[1] : "");
            check_sample(what, out.images[0], cases[i].sample, cases[i].len, cases[i].x,
                         cases[i].y, cases[i].z);
        }
        ssg_outputs_release(&out);
    }
}

/* Frame 1 of a sequence (README.md, "Frames"): sample 0 is Halton index offset + count =
   17 = 10001b = 122 in base 3, so u0 = 0.10001b = 17/32 and u1 = 0.221 (base 3) = 25/27;
   its length coordinate is the midpoint moved by the golden-ratio turn,
   t = frac(1/2 + 1/phi) / 16 = (1/phi - 1/2) / 16. Cosine direction: sin theta =
   sqrt(17/32), cos theta = sqrt(15/32), azimuth 2 pi 25/27. */
static void test_frame_one(void)
{
    struct ssg_halton_params p;
    const struct ssg_node_desc *d = defaults(&p, NULL);
    if (!d)
        return;
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame_seed(1);
    struct ssg_node_ctx ctx = {.desc = d, .instance = "h", .frame = &f, .out_dir = "out",
                               .diags = &diags};
    static struct ssg_halton_consts c;
    static float kernel[3 * 16], pattern[2 * 16];
    CHECK_EQ(d->prepare(&ctx, &p, &c), SSG_OK);
    ssg_halton_frame(&c, 1, kernel, pattern);
    double t = (0.61803398874989485 - 0.5) / 16, len = 0.1 + 0.9 * t * t;
    double st = sqrt(17.0 / 32), az = 2 * M_PI * 25 / 27;
    struct ssg_image k = {.width = 16, .height = 1, .channels = 3, .data = kernel};
    check_sample("frame 1", &k, 0, len, st * cos(az), st * sin(az), sqrt(15.0 / 32));
}

static void test_kernel_geometry(void)
{
    static const char *const mappings[] = {"mapping=cosine", "mapping=uniform"};
    static const char *const counts[] = {"count=1", "count=16", "count=1024"};
    for (int m = 0; m < 2; m++)
        for (int c = 0; c < 3; c++) {
            const char *sets[] = {mappings[m], counts[c], "bases=[2,3,5]"};
            struct ssg_outputs out;
            CHECK_EQ(run(sets, 3, 7, &out), SSG_OK);
            if (out.count != 2)
                continue;
            const struct ssg_image *k = out.images[0];
            CHECK_EQ(k->height, 1);
            CHECK_EQ(k->channels, 3);
            int bad = 0;
            for (int i = 0; i < k->width; i++) {
                float x = k->data[i], y = k->data[k->width + i], z = k->data[2 * k->width + i];
                bad += !(z >= 0.0f) || !(x * x + y * y + z * z <= 1.0f + 1e-6f) ||
                       !(x * x + y * y + z * z >= 0.1f * 0.1f * (1 - 1e-6f));
            }
            CHECK_EQ(bad, 0);
            ssg_outputs_release(&out);
        }
}

/* Mean cos(theta) of the directions. Cosine-weighted: E = 2/3, Var = 1/2 - 4/9 = 1/18;
   uniform: E = 1/2, Var = 1/3 - 1/4 = 1/12. Tolerance: four standard errors of an
   N-sample mean (docs/analytic.md 5); a quasi-random set does at least as well as random. */
static void test_direction_density(void)
{
    const int n = 1024;
    const char *cos_sets[] = {"count=1024", "mapping=cosine"};
    const char *uni_sets[] = {"count=1024", "mapping=uniform"};
    struct ssg_outputs oc, ou;
    CHECK_EQ(run(cos_sets, 2, 1, &oc), SSG_OK);
    CHECK_EQ(run(uni_sets, 2, 1, &ou), SSG_OK);
    if (oc.count != 2 || ou.count != 2)
        return;
    double mc = 0, mu = 0, dir[3];
    for (int i = 0; i < n; i++) {
        sample_len(oc.images[0], i, dir);
        mc += dir[2];
        sample_len(ou.images[0], i, dir);
        mu += dir[2];
    }
    mc /= n;
    mu /= n;
    CHECK_NEAR(mc, 2.0 / 3.0, 4.0 * sqrt(1.0 / 18.0 / n));
    CHECK_NEAR(mu, 0.5, 4.0 * sqrt(1.0 / 12.0 / n));
    /* Lengths: falloff 2, min_scale 0.1 by default, t = (i + 0.5) / n without a third
       base -> mean length 0.1 + 0.9 * E[t^2] = 0.1 + 0.9 / 3 = 0.4 (exact midpoint rule
       error 0.9 / (12 n^2)). */
    double ml = 0;
    for (int i = 0; i < n; i++)
        ml += sample_len(oc.images[0], i, dir);
    CHECK_NEAR(ml / n, 0.4, 1e-5);
    ssg_outputs_release(&oc);
    ssg_outputs_release(&ou);
}

static void test_determinism_and_seed(void)
{
    struct ssg_halton_params p;
    const struct ssg_node_desc *d = defaults(&p, "pattern=8");
    if (!d)
        return;
    struct ssg_diags diags = {0};
    struct ssg_frame f1 = frame_seed(1), f2 = frame_seed(2);
    struct ssg_node_ctx ctx1 = {.desc = d, .instance = "h", .frame = &f1, .out_dir = "out",
                                .diags = &diags};
    struct ssg_node_ctx ctx2 = ctx1;
    ctx2.frame = &f2;
    static struct ssg_halton_consts a, b, c;
    memset(&a, 0x55, sizeof a); /* padding and unused tails must not matter: compare */
    memset(&b, 0xAA, sizeof b); /* only the used part below */
    CHECK_EQ(d->prepare(&ctx1, &p, &a), SSG_OK);
    CHECK_EQ(d->prepare(&ctx1, &p, &b), SSG_OK);
    CHECK_EQ(d->prepare(&ctx2, &p, &c), SSG_OK);
    CHECK_EQ(a.count, 16);
    CHECK_EQ(a.n, 8);
    CHECK(memcmp(a.kernel, b.kernel, sizeof(float) * 3 * 16) == 0);
    CHECK(memcmp(a.pattern, b.pattern, sizeof(float) * 2 * 64) == 0);
    /* The seed changes the tile, not the kernel. */
    CHECK(memcmp(a.kernel, c.kernel, sizeof(float) * 3 * 16) == 0);
    CHECK(memcmp(a.pattern, c.pattern, sizeof(float) * 2 * 64) != 0);
    /* Tile entries are unit (cos, sin) pairs at 64 distinct angles. */
    int bad = 0, dup = 0;
    for (int i = 0; i < 64; i++) {
        float co = a.pattern[i], si = a.pattern[64 + i];
        bad += fabsf(co * co + si * si - 1.0f) > 1e-5f;
        for (int j = 0; j < i; j++)
            dup += fabsf(co - a.pattern[j]) < 1e-6f && fabsf(si - a.pattern[64 + j]) < 1e-6f;
    }
    CHECK_EQ(bad, 0);
    CHECK_EQ(dup, 0);
    /* And they are the van der Corput set Phi_2(k), k = 0 .. 63, turned by the seeded
       shift (halton_pattern.c): Phi_2 of 0 .. 2^6 - 1 is exactly {j / 64}, so every angle
       is (j + w) / 64 of a turn with one w for all. Distinct unit angles alone hold for
       any 64 indices (one index on, Phi_2(64) = 1/128 breaks the spacing). */
    int off_grid = 0;
    double w0 = 0;
    for (int i = 0; i < 64; i++) {
        double turn = atan2(a.pattern[64 + i], a.pattern[i]) / (2 * M_PI) * 64;
        double w = turn - floor(turn);
        if (i == 0)
            w0 = w;
        double dw = fabs(w - w0);
        off_grid += fmin(dw, 1 - dw) > 1e-4;
    }
    CHECK_EQ(off_grid, 0);
    /* Through the public runner too: the outputs are the prepared bytes. */
    const char *sets[] = {"pattern=8"};
    struct ssg_outputs o1, o2;
    CHECK_EQ(run(sets, 1, 1, &o1), SSG_OK);
    CHECK_EQ(run(sets, 1, 1, &o2), SSG_OK);
    if (o1.count == 2 && o2.count == 2) {
        CHECK_EQ(o1.images[1]->width, 8);
        CHECK_EQ(o1.images[1]->height, 8);
        CHECK_EQ(o1.images[1]->channels, 2);
        CHECK(memcmp(o1.images[0]->data, a.kernel, sizeof(float) * 3 * 16) == 0);
        CHECK(memcmp(o1.images[1]->data, a.pattern, sizeof(float) * 2 * 64) == 0);
        CHECK(memcmp(o1.images[1]->data, o2.images[1]->data, sizeof(float) * 2 * 64) == 0);
    }
    ssg_outputs_release(&o1);
    ssg_outputs_release(&o2);
}

static void test_rejects(void)
{
    static const char *const bad[][3] = {
        {"bases=[2,4]", NULL, NULL},            /* 4 is not prime */
        {"bases=[3,3]", NULL, NULL},            /* not coprime */
        {"bases=[2,3,9]", NULL, NULL},          /* 9 is not prime */
        {"period=7", NULL, NULL},               /* 2 and 3 do not divide 7 */
        {"period=6", "count=16", NULL},         /* 16 is not whole periods of 6 */
        {"bases=[2,5]", "period=10", "count=25"},
        {"bases=[2,3,5]", "period=6", "count=12"}, /* 5 does not divide 6 */
    };
    for (int i = 0; i < SSG_COUNT(bad); i++) {
        int n = bad[i][1] ? (bad[i][2] ? 3 : 2) : 1;
        struct ssg_outputs out;
        CHECK_EQ(run(bad[i], n, 1, &out), SSG_E_VALUE);
        ssg_outputs_release(&out);
    }
    /* Range errors come from the parameter table. */
    const char *big[] = {"count=2000"};
    struct ssg_outputs out;
    CHECK_EQ(run(big, 1, 1, &out), SSG_E_RANGE);
    ssg_outputs_release(&out);
    const char *ok[] = {"bases=[2,3]", "period=6", "count=12"};
    CHECK_EQ(run(ok, 3, 1, &out), SSG_OK);
    ssg_outputs_release(&out);
}

int main(void)
{
    test_radical_inverse();
    test_period_property();
    test_period_kernel();
    test_fixed_values();
    test_frame_one();
    test_kernel_geometry();
    test_direction_density();
    test_determinism_and_seed();
    test_rejects();
    return check_report();
}
