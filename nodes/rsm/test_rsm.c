/* test_rsm.c - the `rsm` node (one bounce from reflective shadow maps) on maps made by hand:
 * - one non-empty texel and a few receivers: the closed form Phi / pi cos cos / (d^2
 *   max(d^2, A / pi)) / pi, with and without albedo, the clamp where the receiver touches
 *   the sender, 0 behind either surface and for background pixels;
 * - a uniformly emitting disc (radiosity B) on an orthographic face under receivers at
 *   height h facing it: E close to B r^2 / (r^2 + h^2) for several cell sizes;
 * - the exact VPL sum (cell 1) against the texel sum computed here, with min_distance:
 *   senders nearer than it removed, the smooth fade up to twice it;
 * - samples at least the VPL count is the exact sum; fewer: the mean over seeds within a
 *   few standard errors of it, with a non-zero spread, and the same bits on 1 and 2
 *   threads;
 * - maps of another face count than the scene's lights need are refused. */
#include <omp.h>
#include <string.h>

#include "rsm_maps.h"

static const char *const CAMERA = "camera(position=[0, 1, 4], target=[0, 1, 0])\n"
                                  "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n";

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The closed form of one patch (x_p, n_p, Phi, area A) at receiver x (normal n): E / pi,
   E = Phi / pi max(0, n_p.(x - x_p)) max(0, n.(x_p - x)) / (d^2 max(d^2, A / pi)) x fade. */
static double patch_term(const float xp[3], const float np[3], double phi, double area,
                         const float x[3], const float n[3], double m)
{
    double d[3], nn[3], npd[3];
    double ln = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
    for (int k = 0; k < 3; k++) {
        d[k] = (double)x[k] - xp[k];
        nn[k] = n[k] / ln;
        npd[k] = np[k];
    }
    double d2 = dot3(d, d), cs = dot3(npd, d), cr = -dot3(nn, d);
    if (cs <= 0 || cr <= 0)
        return 0;
    double fade = 1;
    if (m > 0) {
        double t = (sqrt(d2) - m) / m;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        fade = t * t * (3 - 2 * t);
    }
    double r2 = area / M_PI;
    return phi / M_PI * cs * cr / (d2 * (d2 > r2 ? d2 : r2)) * fade / M_PI;
}

/* A cube texel's surface area (rsm_vpl.c's rule, here in double). */
static double cube_area(const struct maps *m, int f, int x, int y, const float p[3],
                        const float n[3])
{
    double a = 2.0 * (x + 0.5) / m->res - 1, b = 2.0 * (y + 0.5) / m->res - 1;
    double q = 1 + a * a + b * b, s = 2.0 / m->res, omega = s * s / (q * sqrt(q));
    double d[3], nn[3];
    for (int k = 0; k < 3; k++) {
        d[k] = (double)p[k] - m->face[f].origin[k];
        nn[k] = n[k];
    }
    double r2 = dot3(d, d), c = fabs(dot3(nn, d)) / sqrt(r2);
    return omega * r2 / (c > 0.1 ? c : 0.1);
}

static void test_one_texel(void)
{
    char text[512];
    snprintf(text, sizeof text, "%spoint_light(position=[0, 2, 0], color=[1, 1, 1], "
             "intensity=1)\n", CAMERA);
    struct ssg_scene *s = scene_from_text("rsm_one", text);
    if (!s)
        return;
    struct maps m = maps_make(s, 16);
    CHECK_EQ(m.faces, 6);
    float nl = sqrtf(0.2f * 0.2f + 1 + 0.1f * 0.1f);
    const float n[3] = {0.2f / nl, 1 / nl, 0.1f / nl}, phi[3] = {0.3f, 0.2f, 0.1f};
    float p[3];
    maps_set(&m, 3, 5, 9, 1.5f, n, phi, p);
    double area = cube_area(&m, 3, 5, 9, p, n);
    /* receivers: in front, touching (the clamp), behind the sender, background, facing
       away, far */
    const float off[6][3] = {{1, 0.8f, 0.3f}, {0.02f, 0.01f, 0}, {0, -0.5f, 0}, {0, 0, 0},
                             {1, 0.8f, 0.3f}, {-2, 1.5f, 1}};
    const float nr[6][3] = {{-1, -0.2f, -0.5f}, {-1, 0, 0.2f}, {0, 1, 0}, {0, 0, 0},
                            {1, 0, 0}, {2, -1.5f, -1}};
    struct gbuf g = gbuf_make(s, 6, 1);
    float x[6][3];
    for (int i = 0; i < 6; i++) {
        for (int k = 0; k < 3; k++)
            x[i][k] = p[k] + off[i][k];
        if (i != 3)
            gbuf_set(&g, i, x[i], nr[i]);
    }
    CHECK(0.02 * 0.02 + 0.01 * 0.01 < area / M_PI); /* receiver 1 is inside the clamp */
    const char *exact[] = {"samples=0"};
    for (int albedo = 0; albedo < 2; albedo++)
        for (int run = 0; run < 2; run++) {
            struct ssg_image *out = rsm_run(s, &m, &g, albedo, 1, exact, run, SSG_BACKEND_CPU);
            for (int i = 0; i < 6; i++)
                for (int c = 0; c < 3; c++) {
                    double a = albedo ? px(g.albedo, c, i) : 1.0;
                    double want = i == 3 ? 0 : a * patch_term(p, n, phi[c], area, x[i],
                                                              nr[i], 0);
                    double got = px(out, c, i);
                    CHECK(fabs(got - want) <= 1e-5 * fabs(want) + 1e-12);
                    if (i == 2 || i == 3 || i == 4)
                        CHECK(got == 0.0f);
                    else
                        CHECK(got > 0.0f);
                }
            ssg_image_destroy(&out);
        }
    gbuf_free(&g);
    maps_free(&m);
    ssg_scene_destroy(&s);
}

/* The disc of radius r about the origin on the floor y = 0, radiosity B = (1, 0.5, 0.25),
   on the orthographic face of a light straight down; `tilt` turns each texel's normal a
   little and scales its flux by a pattern (for the sampling tests). */
static void disc_maps(struct maps *m, float r, int tilt)
{
    const struct ssg_lightmap_face *f = &m->face[0];
    float s = 2.0f * f->half / (float)m->res;
    for (int y = 0; y < m->res; y++)
        for (int x = 0; x < m->res; x++) {
            float p[3];
            ssg_lightmap_texel_point(f, m->res, x, y, f->origin[1], p);
            if (p[0] * p[0] + p[2] * p[2] > r * r)
                continue;
            float w = tilt ? 1.0f + 0.8f * sinf(3.0f * p[0]) * cosf(5.0f * p[2]) : 1.0f;
            float n[3] = {tilt ? 0.3f * sinf(7.0f * p[2]) : 0, 1, tilt ? 0.2f * p[0] : 0};
            float nl = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (int k = 0; k < 3; k++)
                n[k] /= nl;
            const float phi[3] = {w * s * s, 0.5f * w * s * s, 0.25f * w * s * s};
            maps_set(m, 0, x, y, f->origin[1], n, phi, NULL);
        }
}

static struct ssg_scene *sun_scene(void)
{
    char text[512];
    snprintf(text, sizeof text, "%sdirectional_light(direction=[0, -1, 0], color=[1, 1, 1], "
             "intensity=1)\n", CAMERA);
    return scene_from_text("rsm_sun", text);
}

static void test_disc(void)
{
    struct ssg_scene *s = sun_scene();
    if (!s)
        return;
    struct maps m = maps_make(s, 256);
    CHECK_EQ(m.faces, 1);
    const float r = 1.0f, hs[3] = {0.5f, 1.0f, 2.0f}, down[3] = {0, -1, 0};
    disc_maps(&m, r, 0);
    struct gbuf g = gbuf_make(s, 3, 1);
    for (int i = 0; i < 3; i++)
        gbuf_set(&g, i, (const float[3]){0, hs[i], 0}, down);
    const char *sets[][2] = {{"samples=0", "cell=1"}, {"samples=0", "cell=4"},
                             {"samples=0", "cell=16"}};
    for (int v = 0; v < 3; v++) {
        struct ssg_image *out = rsm_run(s, &m, &g, 0, 1, sets[v], 2, SSG_BACKEND_CPU);
        for (int i = 0; i < 3; i++) {
            double want = r * r / (r * r + hs[i] * hs[i]) / M_PI;
            for (int c = 0; c < 3; c++) {
                double b = c == 0 ? 1 : c == 1 ? 0.5 : 0.25, got = px(out, c, i) / b;
                if (c == 0)
                    fprintf(stderr, "disc %s h %.1f: E / pi %.5f, closed form %.5f (%+.2f %%)"
                            "\n", sets[v][1], hs[i], got, want, 100 * (got / want - 1));
                CHECK(fabs(got / want - 1) < (v < 2 ? 0.01 : 0.03));
            }
        }
        ssg_image_destroy(&out);
    }
    gbuf_free(&g);
    maps_free(&m);
    ssg_scene_destroy(&s);
}

/* Receivers spread over the space above the disc, facing about down (for the sums). */
static void spread_receivers(struct gbuf *g)
{
    for (int i = 0; i < g->w * g->h; i++) {
        float x[3] = {-1.2f + 0.31f * (float)(i % 8), 0.15f + 0.2f * (float)(i / 8),
                      0.7f * sinf((float)i)};
        float n[3] = {0.4f * cosf(2.0f * (float)i), -1, 0.3f * sinf(3.0f * (float)i)};
        gbuf_set(g, i, x, n);
    }
}

/* The texel sum of rsm.c (cell 1) computed here in double, with min_distance m. */
static double texel_sum(const struct maps *mp, const float x[3], const float n[3], int c,
                        double m)
{
    const struct ssg_lightmap_face *f = &mp->face[0];
    double s = 2.0 * f->half / mp->res, sum = 0;
    size_t plane = (size_t)mp->res * mp->res;
    for (int y = 0; y < mp->res; y++)
        for (int xx = 0; xx < mp->res; xx++) {
            size_t at = (size_t)y * mp->res + xx;
            float phi[3], np[3], p[3];
            for (int k = 0; k < 3; k++) {
                phi[k] = mp->flux->data[k * plane + at];
                np[k] = mp->normal->data[k * plane + at];
            }
            if (!(phi[0] + phi[1] + phi[2] > 0))
                continue;
            ssg_lightmap_texel_point(f, mp->res, xx, y, mp->depth->data[at], p);
            double cosine = fabs(np[0] * f->axis[0] + np[1] * f->axis[1] + np[2] * f->axis[2]);
            double area = s * s / (cosine > 0.1 ? cosine : 0.1);
            sum += patch_term(p, np, phi[c], area, x, n, m);
        }
    return sum;
}

static void receiver(const struct gbuf *g, int i, float x[3], float n[3])
{
    /* back to world from the view-space G-buffer: x = eye + rot^T p */
    size_t plane = (size_t)g->w * g->h;
    for (int k = 0; k < 3; k++) {
        x[k] = g->eye[k];
        n[k] = 0;
        for (int r = 0; r < 3; r++) {
            x[k] += g->rot[3 * r + k] * g->position->data[r * plane + i];
            n[k] += g->rot[3 * r + k] * g->normal->data[r * plane + i];
        }
    }
}

/* The sun scene with a disc of 64 x 64 maps and 8 x 2 receivers spread over it: the
   sampling tests' case. 0 when the scene does not load. */
struct disc_case {
    struct ssg_scene *s;
    struct maps m;
    struct gbuf g;
};

static int disc_case_make(struct disc_case *c)
{
    if (!(c->s = sun_scene()))
        return 0;
    c->m = maps_make(c->s, 64);
    disc_maps(&c->m, 1.0f, 1);
    c->g = gbuf_make(c->s, 8, 2);
    spread_receivers(&c->g);
    return 1;
}

static void disc_case_free(struct disc_case *c)
{
    gbuf_free(&c->g);
    maps_free(&c->m);
    ssg_scene_destroy(&c->s);
}

static void test_texel_sum_and_min_distance(void)
{
    struct disc_case dc;
    if (!disc_case_make(&dc))
        return;
    const double dists[3] = {0, 0.3, 0.6};
    for (int v = 0; v < 3; v++) {
        char md[64];
        snprintf(md, sizeof md, "min_distance=%g", dists[v]);
        const char *sets[] = {"samples=0", "cell=1", md};
        struct ssg_image *out = rsm_run(dc.s, &dc.m, &dc.g, 1, 1, sets, 3, SSG_BACKEND_CPU);
        double worst = 0;
        for (int i = 0; i < dc.g.w * dc.g.h; i++) {
            float x[3], n[3];
            receiver(&dc.g, i, x, n);
            for (int c = 0; c < 3; c++) {
                double want = px(dc.g.albedo, c, i) * texel_sum(&dc.m, x, n, c, dists[v]);
                double e = fabs(px(out, c, i) - want) / (want > 1e-6 ? want : 1e-6);
                worst = e > worst ? e : worst;
            }
        }
        fprintf(stderr, "texel sum, min_distance %.1f: largest relative error %.3g\n",
                dists[v], worst);
        CHECK(worst < 1e-4);
        ssg_image_destroy(&out);
    }
    /* a receiver nearer every sender than min_distance gets exactly 0 */
    struct gbuf near = gbuf_make(dc.s, 1, 1);
    gbuf_set(&near, 0, (const float[3]){0, 0.1f, 0}, (const float[3]){0, -1, 0});
    const char *far[] = {"samples=0", "min_distance=1.5"};
    struct ssg_image *out = rsm_run(dc.s, &dc.m, &near, 0, 1, far, 2, SSG_BACKEND_CPU);
    CHECK(px(out, 0, 0) == 0.0f && px(out, 1, 0) == 0.0f && px(out, 2, 0) == 0.0f);
    ssg_image_destroy(&out);
    gbuf_free(&near);
    disc_case_free(&dc);
}

/* Cells of 2 x 2 texels holding flux: the VPL count at cell=2 (one bin each: the normals
   stay within 45 degrees of up). */
static int vpl_count(const struct maps *m)
{
    int n = 0;
    for (int cy = 0; cy < m->res / 2; cy++)
        for (int cx = 0; cx < m->res / 2; cx++) {
            int any = 0;
            for (int y = 2 * cy; y < 2 * cy + 2; y++)
                for (int x = 2 * cx; x < 2 * cx + 2; x++)
                    any |= m->flux->data[(size_t)y * m->res + x] > 0;
            n += any;
        }
    return n;
}

static void test_sampling(void)
{
    struct disc_case dc;
    if (!disc_case_make(&dc))
        return;
    int count = vpl_count(&dc.m), np = dc.g.w * dc.g.h;
    fprintf(stderr, "sampling: %d VPLs\n", count);
    char all[32];
    snprintf(all, sizeof all, "samples=%d", count);
    const char *exact_sets[] = {"samples=0", "cell=2"}, *all_sets[] = {all, "cell=2"};
    struct ssg_image *exact = rsm_run(dc.s, &dc.m, &dc.g, 1, 1, exact_sets, 2, SSG_BACKEND_CPU);
    struct ssg_image *every = rsm_run(dc.s, &dc.m, &dc.g, 1, 1, all_sets, 2, SSG_BACKEND_CPU);
    CHECK(memcmp(exact->data, every->data, sizeof(float) * 3 * (size_t)np) == 0);
    enum { SEEDS = 40 };
    const char *few[] = {"samples=16", "cell=2"};
    double sum[3 * 16] = {0}, sq[3 * 16] = {0};
    for (int seed = 1; seed <= SEEDS; seed++) {
        struct ssg_image *o = rsm_run(dc.s, &dc.m, &dc.g, 1, (uint64_t)seed, few, 2, SSG_BACKEND_CPU);
        for (int k = 0; k < 3 * np; k++) {
            sum[k] += o->data[k];
            sq[k] += (double)o->data[k] * o->data[k];
        }
        if (seed == 1) { /* the same bits on 1 and 2 threads */
            omp_set_num_threads(1);
            struct ssg_image *one = rsm_run(dc.s, &dc.m, &dc.g, 1, 1, few, 2, SSG_BACKEND_CPU);
            omp_set_num_threads(2);
            CHECK(memcmp(one->data, o->data, sizeof(float) * 3 * (size_t)np) == 0);
            ssg_image_destroy(&one);
        }
        ssg_image_destroy(&o);
    }
    double worst = 0, spread = 0;
    for (int k = 0; k < 3 * np; k++) {
        double mean = sum[k] / SEEDS, var = (sq[k] / SEEDS - mean * mean) * SEEDS / (SEEDS - 1);
        double se = sqrt(var > 0 ? var / SEEDS : 0), z = fabs(mean - exact->data[k]) /
                                                          (se + 1e-6 * exact->data[k] + 1e-12);
        worst = z > worst ? z : worst;
        spread += se / (exact->data[k] + 1e-12);
    }
    fprintf(stderr, "sampling: 16 of %d VPLs, %d seeds: largest |mean - exact| %.2f standard "
            "errors, mean relative standard error %.3g\n", count, SEEDS, worst,
            spread / (3 * np));
    CHECK(worst < 4.0);
    CHECK(spread / (3 * np) > 1e-4); /* the draws do differ between seeds */
    ssg_image_destroy(&exact);
    ssg_image_destroy(&every);
    disc_case_free(&dc);
}

/* turn=true: each frame draws with its own tile, so frames differ and their mean over
   frames, with one seed, is the exact VPL sum within a few standard errors (the seeds'
   check above, over frames); turn=false gives every frame the same bytes. (test_gl_rsm.c
   checks that GL turns the same tile.) */
static void test_turn(void)
{
    struct disc_case dc;
    if (!disc_case_make(&dc))
        return;
    int np = dc.g.w * dc.g.h;
    size_t bytes = sizeof(float) * 3 * (size_t)np;
    const char *exact_sets[] = {"samples=0", "cell=2"};
    const char *still[] = {"samples=16", "cell=2"};
    const char *turned[] = {"samples=16", "cell=2", "turn=true"};
    struct ssg_image *exact = rsm_run(dc.s, &dc.m, &dc.g, 1, 1, exact_sets, 2, SSG_BACKEND_CPU);
    struct ssg_image *a = rsm_run_at(dc.s, &dc.m, &dc.g, 1, 1, 0, still, 2, SSG_BACKEND_CPU);
    struct ssg_image *b = rsm_run_at(dc.s, &dc.m, &dc.g, 1, 1, 5, still, 2, SSG_BACKEND_CPU);
    CHECK(memcmp(a->data, b->data, bytes) == 0);
    enum { FRAMES = 40 };
    double sum[3 * 16] = {0}, sq[3 * 16] = {0};
    int differ = 0;
    for (int f = 0; f < FRAMES; f++) {
        struct ssg_image *o = rsm_run_at(dc.s, &dc.m, &dc.g, 1, 1, f, turned, 3, SSG_BACKEND_CPU);
        differ += memcmp(o->data, a->data, bytes) != 0;
        for (int k = 0; k < 3 * np; k++) {
            sum[k] += o->data[k];
            sq[k] += (double)o->data[k] * o->data[k];
        }
        ssg_image_destroy(&o);
    }
    double worst = 0;
    for (int k = 0; k < 3 * np; k++) {
        double mean = sum[k] / FRAMES, var = (sq[k] / FRAMES - mean * mean) * FRAMES / (FRAMES - 1);
        double se = sqrt(var > 0 ? var / FRAMES : 0);
        double z = fabs(mean - exact->data[k]) / (se + 1e-6 * exact->data[k] + 1e-12);
        worst = z > worst ? z : worst;
    }
    fprintf(stderr, "turn: %d of %d frames differ from the still tile; largest |mean over "
            "frames - exact| %.2f standard errors\n", differ, FRAMES, worst);
    CHECK(differ >= FRAMES - 2);
    CHECK(worst < 4.0);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&exact);
    disc_case_free(&dc);
}

static void test_refusals(void)
{
    char text[512];
    snprintf(text, sizeof text, "%spoint_light(position=[0, 2, 0])\n", CAMERA);
    struct ssg_scene *point = scene_from_text("rsm_point", text), *sun = sun_scene();
    if (!point || !sun)
        return;
    struct maps m = maps_make(sun, 8); /* 1 face; the point light needs 6 */
    struct gbuf g = gbuf_make(point, 2, 2);
    struct ssg_frame frame = {2, 2, 45, 0.05f, 100, 1, 0, 0, 0};
    struct ssg_image *out[1] = {ssg_image_create(2, 2, 3)};
    const struct ssg_image *in[SSG_RSM_INPUTS] = {g.position, g.normal, m.depth, m.normal,
                                                  m.flux, NULL};
    void *params = node_params(&ssg_node_rsm, NULL, 0);
    CHECK_EQ(node_run_scene(&ssg_node_rsm, point, &frame, params, in, out, SSG_BACKEND_CPU),
             SSG_E_SCENE);
    free(params);
    /* The sun's one face read as environment maps: 2 environment lights need 2 faces (own
       false), and with own lights 1 + 2; environment 1 alone matches the face count. */
    in[2] = m.depth, in[3] = m.normal, in[4] = m.flux;
    const char *env2[] = {"own=false", "environment=2"}, *both[] = {"environment=2"};
    const char *env1[] = {"own=false", "environment=1"};
    const struct { const char *const *sets; int n; enum ssg_err want; } cases[] = {
        {env2, 2, SSG_E_SCENE}, {both, 1, SSG_E_SCENE}, {env1, 2, SSG_OK}};
    for (int i = 0; i < 3; i++) {
        params = node_params(&ssg_node_rsm, cases[i].sets, cases[i].n);
        CHECK_EQ(node_run_scene(&ssg_node_rsm, sun, &frame, params, in, out, SSG_BACKEND_CPU),
                 cases[i].want);
        free(params);
    }
    /* nothing to gather from */
    const char *none[] = {"own=false"};
    params = node_params(&ssg_node_rsm, none, 1);
    struct ssg_shape shapes[SSG_RSM_INPUTS], o[1];
    for (int i = 0; i < SSG_RSM_INPUTS; i++)
        shapes[i] = in[i] ? (struct ssg_shape){in[i]->width, in[i]->height, in[i]->channels,
                                               0}
                          : (struct ssg_shape){0};
    char why[200];
    CHECK_EQ(ssg_node_rsm.check(params, &frame, shapes, o, why, sizeof why), SSG_E_VALUE);
    fprintf(stderr, "rsm own=false environment=0: %s\n", why);
    free(params);
    ssg_image_destroy(&out[0]);
    gbuf_free(&g);
    maps_free(&m);
    ssg_scene_destroy(&point);
    ssg_scene_destroy(&sun);
}

int main(void)
{
    omp_set_num_threads(2);
    test_one_texel();
    test_disc();
    test_texel_sum_and_min_distance();
    test_sampling();
    test_turn();
    test_refusals();
    return check_report();
}
