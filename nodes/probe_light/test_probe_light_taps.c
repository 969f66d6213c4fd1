/* test_probe_light_taps.c - the constants probe_light's prepare() makes for both backends,
 * against values worked out by hand (a slip in them passes every CPU/GL parity test):
 * - the soft lookups' taps (README.md: Vogel's spiral with the first tap at the centre,
 *   radius sqrt(k / (n - 0.5)), angle k golden angles), the filter's then the search's;
 * - the cone of a light of N, tan(softness x acos(1 - 2 / N)) capped at 45 degrees, per
 *   texel of the maps;
 * - the jitter tile's offsets: whatever the seed's turn and permutation, their mean
 *   squared radius is a uniform unit disc's, 1/2, and each lies inside it. */
#include <math.h>

#include "check.h"
#include "probe_light/probe_light.h"
#include "scene_node.h"

enum { LIGHTS_MAX = 2, RES = 64 };

/* prepare() for `lights` lights with maps of side RES, with `sets`, into *c. */
static int prepare_with(const struct ssg_scene *s, int lights, const char *const *sets,
                        int set_count, struct ssg_probe_light_consts *c)
{
    struct ssg_shape in[SSG_PROBE_LIGHT_INPUTS] = {
        [SSG_PROBE_LIGHT_IN_POSITION] = {16, 16, 3, SSG_T_VECTOR},
        [SSG_PROBE_LIGHT_IN_NORMAL] = {16, 16, 3, SSG_T_VECTOR},
        [SSG_PROBE_LIGHT_IN_LIGHTS] = {lights, 2, 3, SSG_T_LIGHTS},
        [SSG_PROBE_LIGHT_IN_SHADOWMAPS] = {RES, RES, lights, SSG_T_SHADOWMAPS}};
    void *params = node_params(&ssg_node_probe_light, sets, set_count);
    enum ssg_err e = prepare_on(&ssg_node_probe_light, s, in, params, c);
    free(params);
    CHECK_EQ(e, SSG_OK);
    return e == SSG_OK;
}

static struct ssg_probe_light_consts *consts_alloc(void)
{
    return calloc(1, sizeof(struct ssg_probe_light_consts) + 2 * sizeof(float) * LIGHTS_MAX);
}

/* Tap k of a set of n taps at t (x plane, then y plane) is (x, y), to float rounding. */
static void check_tap(const float *t, int n, int k, double x, double y)
{
    if (!(fabs(t[k] - x) <= 1e-6 && fabs(t[n + k] - y) <= 1e-6))
        fprintf(stderr, "n = %d, tap %d: (%.7f, %.7f), by hand (%.7f, %.7f)\n", n, k, t[k],
                t[n + k], x, y);
    CHECK_NEAR(t[k], x, 1e-6);
    CHECK_NEAR(t[n + k], y, 1e-6);
}

/* Filter taps n = 4: radii sqrt(k / 3.5) = 0, 0.5345225, 0.7559289, 0.9258201; search
   taps n = 3: sqrt(k / 2.5) = 0, 0.6324555, 0.8944272. Angles k x 137.50776 degrees (the
   golden angle), (cos, sin) = (1, 0), (-0.7373689, 0.6754903), (0.0874257, -0.9961710),
   (0.6084389, 0.7936008); tap = r (cos, sin). */
static void test_taps(const struct ssg_scene *s, struct ssg_probe_light_consts *c)
{
    const char *sets[] = {"taps=4", "search_taps=3"};
    if (!prepare_with(s, 1, sets, 2, c))
        return;
    const float *filter = c->tap, *search = c->tap + 2 * 4;
    check_tap(filter, 4, 0, 0.0, 0.0);
    check_tap(filter, 4, 1, -0.3941402, 0.3610647);
    check_tap(filter, 4, 2, 0.0660876, -0.7530345);
    check_tap(filter, 4, 3, 0.5633049, 0.7347315); /* the last on the unit circle */
    check_tap(search, 3, 0, 0.0, 0.0);
    check_tap(search, 3, 1, -0.4663530, 0.4272176);
    check_tap(search, 3, 2, 0.0781959, -0.8910025);
}

/* The cone's tan x the texel (cone_tan is per texel of 2 radius / RES): N = 2, softness
   0.25: 0.25 acos(0) = pi / 8, tan 0.4142136 (sqrt 2 - 1); N = 1, softness 0.1: 0.1 acos(-1)
   = 18 degrees, tan 0.3249197; N = 1, softness 0.5: 90 degrees, capped at 45, tan 1;
   softness 0: hard lookups, 0. */
static void test_cone(const struct ssg_scene *s, struct ssg_probe_light_consts *c)
{
    const struct { int lights; const char *set; double tan; } cases[] = {
        {2, "softness=0.25", 0.4142136}, {1, "softness=0.1", 0.3249197},
        {1, "softness=0.5", 1.0}, {2, "softness=0", 0.0}};
    for (int i = 0; i < 4; i++) {
        const char *sets[] = {cases[i].set};
        if (!prepare_with(s, cases[i].lights, sets, 1, c))
            return;
        CHECK_NEAR(c->u.texel, 2.0 * c->sphere.radius / RES, 1e-7);
        CHECK_NEAR(c->u.cone_tan * c->u.texel, cases[i].tan, 1e-6);
    }
}

/* The jitter: tile^2 offsets of a Vogel disc (radius sqrt((k + 0.5) / n)), so their mean
   r^2 is sum (k + 0.5) / n^2 = 1/2 for every tile and seed. */
static void test_noise(const struct ssg_scene *s, struct ssg_probe_light_consts *c)
{
    for (int tile = 1; tile <= SSG_PROBE_LIGHT_MAX_TILE; tile += 3) {
        char set[32];
        snprintf(set, sizeof set, "noise_tile=%d", tile);
        const char *sets[] = {set};
        if (!prepare_with(s, 1, sets, 1, c))
            return;
        int n = tile * tile, outside = 0;
        double m = 0;
        for (int k = 0; k < n; k++) {
            double r2 = (double)c->noise[k] * c->noise[k] +
                        (double)c->noise[n + k] * c->noise[n + k];
            outside += !(r2 < 1.0);
            m += r2 / n;
        }
        CHECK_EQ(outside, 0);
        CHECK_NEAR(m, 0.5, 1e-6);
    }
}

int main(void)
{
    struct ssg_scene *s = scene_from_text(
        "pl_taps", "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                   "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n");
    struct ssg_probe_light_consts *c = consts_alloc();
    if (s && c) {
        test_taps(s, c);
        test_cone(s, c);
        test_noise(s, c);
    }
    free(c);
    ssg_scene_destroy(&s);
    return check_report();
}
