/* test_direct_light_taps.c - the PCF / PCSS tap disc that direct_light's prepare() makes
 * (README.md "Filtering": a Vogel disc, tap k at radius sqrt((k + 0.5) / n) and angle k
 * golden angles, in the unit disc) against values worked out by hand, as test_halton.c
 * checks the radical inverse: the four taps of n = 4, the first three of the default
 * n = 12, the one tap of n = 1; and for every n the disc's mean squared radius 1/2 (a
 * uniform unit disc's), which the half-step gives exactly. Both backends read these
 * constants, so a slip here passes every CPU/GL parity test: only this test sees it. */
#include <math.h>

#include "check.h"
#include "direct_light/direct_light.h"
#include "scenes.h"

/* The taps of `samples` taps into c (prepare() on a point light's six faces). */
static int taps_of(const struct ssg_scene *s, int samples,
                   struct ssg_direct_light_consts *c)
{
    const struct ssg_node_desc *d = &ssg_node_direct_light;
    struct ssg_direct_light_params p;
    ssg_params_defaults(d->params, &p);
    p.samples = samples;
    struct ssg_shape in[SSG_DIRECT_LIGHT_INPUTS] = {
        [SSG_DIRECT_LIGHT_IN_POSITION] = {16, 16, 3, SSG_T_VECTOR},
        [SSG_DIRECT_LIGHT_IN_NORMAL] = {16, 16, 3, SSG_T_VECTOR},
        [SSG_DIRECT_LIGHT_IN_ALBEDO] = {16, 16, 3, SSG_T_COLOR},
        [SSG_DIRECT_LIGHT_IN_MAPS] = {32, 32, 6, SSG_T_LIGHTMAPS}};
    enum ssg_err e = prepare_on(d, s, in, &p, c);
    CHECK_EQ(e, SSG_OK);
    return e == SSG_OK;
}

/* Tap k of c is (x, y), to float rounding. */
static void check_tap(const struct ssg_direct_light_consts *c, int k, double x, double y)
{
    const float *t = &c->taps[2 * k];
    if (!(fabs(t[0] - x) <= 1e-6 && fabs(t[1] - y) <= 1e-6))
        fprintf(stderr, "n = %d, tap %d: (%.7f, %.7f), by hand (%.7f, %.7f)\n", c->p.samples,
                k, t[0], t[1], x, y);
    CHECK_NEAR(t[0], x, 1e-6);
    CHECK_NEAR(t[1], y, 1e-6);
}

static void test_by_hand(const struct ssg_scene *s)
{
    static struct ssg_direct_light_consts c;
    /* n = 4. Radii sqrt((k + 0.5) / 4): sqrt(1/8) = 0.3535534, sqrt(3/8) = 0.6123724,
       sqrt(5/8) = 0.7905694, sqrt(7/8) = 0.9354143. Angles k x 137.50776 degrees (the
       golden angle pi (3 - sqrt 5) = 2.3999632 rad): 0, 137.50776, 275.01553,
       412.52329 = 52.52329; their (cos, sin): (1, 0), (-0.7373689, 0.6754903),
       (0.0874257, -0.9961710), (0.6084389, 0.7936008). Taps r (cos, sin): */
    if (!taps_of(s, 4, &c))
        return;
    check_tap(&c, 0, 0.3535534, 0.0);
    check_tap(&c, 1, -0.4515444, 0.4136516);  /* 0.6123724 x (-0.7373689, 0.6754903) */
    check_tap(&c, 2, 0.0691161, -0.7875424);  /* 0.7905694 x (0.0874257, -0.9961710) */
    check_tap(&c, 3, 0.5691424, 0.7423455);   /* 0.9354143 x (0.6084389, 0.7936008) */
    /* n = 12 (the default): radii sqrt(1/24) = 0.2041241, sqrt(3/24) = 0.3535534,
       sqrt(5/24) = 0.4564355, the same angles. */
    if (!taps_of(s, 12, &c))
        return;
    check_tap(&c, 0, 0.2041241, 0.0);
    check_tap(&c, 1, -0.2606993, 0.2388219);  /* 0.3535534 x (-0.7373689, 0.6754903) */
    check_tap(&c, 2, 0.0399042, -0.4546878);  /* 0.4564355 x (0.0874257, -0.9961710) */
    /* n = 1: one tap at radius sqrt(1/2), not the disc's centre. */
    if (!taps_of(s, 1, &c))
        return;
    check_tap(&c, 0, 0.7071068, 0.0);
}

/* The mean of r^2 over the n taps is sum (k + 0.5) / n^2 = (n^2 / 2) / n^2 = 1/2 for every
   n, the mean squared radius of the uniform unit disc (every tap holds an equal-area ring);
   sqrt(k / n) would give (n - 1) / (2 n). And every tap lies inside the unit disc. */
static void test_second_moment(const struct ssg_scene *s)
{
    static struct ssg_direct_light_consts c;
    int outside = 0, off = 0; /* taps at r >= 1; n whose mean r^2 is not 1/2 */
    for (int n = 1; n <= SSG_DIRECT_LIGHT_MAX_SAMPLES; n++) {
        if (!taps_of(s, n, &c))
            return;
        double m = 0;
        for (int k = 0; k < n; k++) {
            double r2 = (double)c.taps[2 * k] * c.taps[2 * k] +
                        (double)c.taps[2 * k + 1] * c.taps[2 * k + 1];
            outside += !(r2 < 1.0);
            m += r2 / n;
        }
        if (fabs(m - 0.5) > 1e-6 && off++ == 0)
            fprintf(stderr, "n = %d: mean squared tap radius %.7f, not 1/2\n", n, m);
    }
    CHECK_EQ(outside, 0);
    CHECK_EQ(off, 0);
}

int main(void)
{
    struct ssg_scene *s = scene_from_text(
        "dl_taps", "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                   "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
                   "point_light(position=[0, 1, 0], intensity=1)\n");
    if (s) {
        test_by_hand(s);
        test_second_moment(s);
        ssg_scene_destroy(&s);
    }
    return check_report();
}
