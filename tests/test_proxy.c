/* test_proxy.c - the map rasterisers' simplified meshes (core/scene/proxy.h), on a floor,
 * a box and a sphere of 16,128 triangles (radius 0.5, centre (0, 0.5, 0)):
 * - a proxy keeps only original vertices (all on the sphere) and every point of its
 *   triangles lies within the level's error of the sphere; the sphere has at most half its triangles, the box and the floor
 *   (too small) are the originals' arrays; a request finer than the finest level, or an
 *   alpha-masked sphere, gets the scene itself;
 * - levels do not depend on the order they are asked for (a fresh scene asked the coarse
 *   level first gives the same bytes);
 * - the sphere's shadow map straight down holds the closed-form depth of a sphere,
 *   (the map plane's height above the centre) - sqrt(r^2 - rho^2), its error times the
 *   cosine (the surface's distance) within a quarter texel over the cap (rho < 0.8 r), on
 *   the CPU and on GL, and the two maps agree;
 * - the sun's light map (an orthographic face) of a 65 k-triangle sphere puts each texel
 *   of its lit cap on the sphere within an eighth of a texel along its ray, on both
 *   backends; in both map nodes the proxy is drawn (depths differ from proxy=false's);
 * - the courtyard's bunny in 32 environment lights' maps: the CPU's and GL's depths,
 *   normals and fluxes agree but at silhouette ties (both draw the same proxy). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "light_maps.h"
#include "scene_node.h"
#include "common/shadowmap.h"
#include "scene/proxy.h"
#include "shadowmaps/shadowmaps.h"

static const struct ssg_frame FRAME = {64, 48, 45, 0.05f, 100, 1, 0, 0, 0};

#define SPHERE_SCENE(material_line, sphere_material)                                      \
    "camera(position=[0, 2, 3], target=[0, 0, 0])\n" material_line                        \
    "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"                        \
    "box(center=[1.2, 0.25, 0], size=[0.5, 0.5, 0.5])\n"                                  \
    "sphere(center=[0, 0.5, 0], radius=0.5, subdivisions=64" sphere_material ")\n"

static const char *const SPHERE = SPHERE_SCENE("", "");
static const char *const MASKED = SPHERE_SCENE(
    "leaf = material(albedo=[0.5, 0.5, 0.5], alpha_mode=mask, opacity=0.9)\n",
    ", material=leaf");
enum { SPHERE_MESH = 2 };
static const float CENTRE[3] = {0, 0.5f, 0}, RADIUS = 0.5f;

/* The largest distance from the sphere of a point of a triangle of m (barycentric steps
   of 1/8 over each), and how many vertices are off it. */
static double worst_sag(const struct ssg_mesh *m, int *off_sphere)
{
    double worst = 0.0;
    *off_sphere = 0;
    for (int v = 0; v < m->vertex_count; v++) {
        double d = 0;
        for (int k = 0; k < 3; k++)
            d += pow(m->positions[3 * v + k] - CENTRE[k], 2);
        *off_sphere += fabs(sqrt(d) - RADIUS) > 1e-5;
    }
    for (int t = 0; t < m->triangle_count; t++) {
        const float *p[3];
        for (int k = 0; k < 3; k++)
            p[k] = &m->positions[3 * m->indices[3 * t + k]];
        for (int a = 0; a <= 8; a++)
            for (int b = 0; a + b <= 8; b++) {
                double w[3] = {a / 8.0, b / 8.0, (8 - a - b) / 8.0}, d = 0;
                for (int k = 0; k < 3; k++)
                    d += pow(w[0] * p[0][k] + w[1] * p[1][k] + w[2] * p[2][k] - CENTRE[k], 2);
                double sag = RADIUS - sqrt(d);
                worst = sag > worst ? sag : worst;
            }
    }
    return worst;
}

static void test_levels(void)
{
    struct ssg_scene *s = scene_from_text("proxy_sphere", SPHERE);
    if (!s)
        return;
    const struct ssg_mesh *sphere = &s->meshes[SPHERE_MESH];
    struct ssg_scene fine, coarse, none;
    CHECK_EQ(ssg_scene_proxy(s, 0.02f, NULL, &fine), SSG_OK);
    CHECK_EQ(ssg_scene_proxy(s, 0.08f, NULL, &coarse), SSG_OK);
    CHECK_EQ(ssg_scene_proxy(s, 1e-5f, NULL, &none), SSG_OK);
    CHECK(fine.proxy_of == s && coarse.proxy_of == s && none.proxy_of == NULL);
    CHECK(none.meshes == s->meshes);
    CHECK(ssg_scene_proxy_error(&fine) <= 0.02f && ssg_scene_proxy_error(&fine) > 0.01f);
    CHECK(ssg_scene_proxy_error(&coarse) <= 0.08f && ssg_scene_proxy_error(&coarse) > 0.04f);
    const struct ssg_scene *views[2] = {&fine, &coarse};
    for (int i = 0; i < 2; i++) {
        const struct ssg_scene *v = views[i];
        const struct ssg_mesh *p = &v->meshes[SPHERE_MESH];
        int off = 0;
        double sag = worst_sag(p, &off), bound = ssg_scene_proxy_error(v);
        fprintf(stderr, "level %.4g: sphere %d -> %d triangles, %d vertices off the sphere, "
                "worst sag %.3g (bound %.3g)\n", bound, sphere->triangle_count,
                p->triangle_count, off, sag, bound);
        CHECK(2 * p->triangle_count <= sphere->triangle_count && p->triangle_count > 100);
        CHECK_EQ(off, 0);
        CHECK(sag <= bound);
        for (int m = 0; m < SPHERE_MESH; m++) /* floor and box: too small, shared */
            CHECK(v->meshes[m].indices == s->meshes[m].indices);
        CHECK_EQ(p->material, sphere->material);
    }
    CHECK(coarse.meshes[SPHERE_MESH].triangle_count < fine.meshes[SPHERE_MESH].triangle_count);
    /* The coarse level again, on a fresh scene that asks it first: the same bytes. */
    struct ssg_scene *t = scene_from_text("proxy_sphere2", SPHERE);
    struct ssg_scene again;
    if (t && ssg_scene_proxy(t, 0.08f, NULL, &again) == SSG_OK) {
        const struct ssg_mesh *a = &coarse.meshes[SPHERE_MESH], *b = &again.meshes[SPHERE_MESH];
        CHECK_EQ(a->triangle_count, b->triangle_count);
        CHECK(a->triangle_count == b->triangle_count &&
              !memcmp(a->indices, b->indices, 12 * (size_t)a->triangle_count) &&
              !memcmp(a->positions, b->positions, 12 * (size_t)a->vertex_count));
    }
    ssg_scene_destroy(&t);
    ssg_scene_destroy(&s);
    struct ssg_scene *m = scene_from_text("proxy_masked", MASKED);
    struct ssg_scene masked;
    if (m && ssg_scene_proxy(m, 0.08f, NULL, &masked) == SSG_OK)
        CHECK(masked.proxy_of == NULL && masked.meshes == m->meshes); /* nothing to simplify */
    ssg_scene_destroy(&m);
}

static struct ssg_image *straight_down_map(const struct ssg_scene *s, int res, int proxy,
                                           enum ssg_backend backend)
{
    const float down[1][3] = {{0, 1, 0}};
    struct ssg_image *l = light_list(down, 1);
    char set[32];
    snprintf(set, sizeof set, "resolution=%d", res);
    const char *sets[] = {set, proxy ? "proxy=true" : "proxy=false"};
    void *params = node_params(&ssg_node_shadowmaps, sets, 2);
    struct ssg_image *out[1] = {ssg_image_create(res, res, 1)};
    const struct ssg_image *in[1] = {l};
    CHECK_EQ(node_run_scene(&ssg_node_shadowmaps, s, &FRAME, params, in, out, backend), SSG_OK);
    free(params);
    ssg_image_destroy(&l);
    return out[0];
}

/* The sphere's cap in the map against the closed form. */
static void check_cap(const struct ssg_scene *s, const struct ssg_image *m, int res,
                     const char *what)
{
    const float down[3] = {0, 1, 0};
    struct ssg_bounding_sphere b = ssg_scene_bounding_sphere(s);
    struct ssg_shadow_frame f = ssg_shadow_frame_make(&b, down);
    const double texel = 2.0 * b.radius / res;
    int cap = 0, bad = 0;
    double worst = 0;
    for (int y = 0; y < res; y++)
        for (int x = 0; x < res; x++) {
            float o[3];
            ssg_shadow_texel_origin(&f, res, x, y, o);
            double rho = hypot(o[0] - CENTRE[0], o[2] - CENTRE[2]);
            if (rho >= 0.8 * RADIUS)
                continue;
            double want = o[1] - CENTRE[1] - sqrt(RADIUS * RADIUS - rho * rho);
            double cosine = sqrt(1.0 - rho * rho / (RADIUS * RADIUS));
            double e = fabs(m->data[(size_t)y * res + x] - want) * cosine; /* to the surface */
            worst = e > worst ? e : worst;
            cap++, bad += e > 0.25 * texel;
        }
    fprintf(stderr, "%s: %d cap texels, worst distance from the sphere %.3g (a quarter texel: "
            "%.3g), %d over\n", what, cap, worst, 0.25 * texel, bad);
    CHECK(cap > 1000);
    CHECK_EQ(bad, 0);
}

static void test_shadow_map(void)
{
    struct ssg_scene *s = scene_from_text("proxy_sphere", SPHERE);
    if (!s)
        return;
    const int res = 256;
    struct ssg_image *cpu = straight_down_map(s, res, 1, SSG_BACKEND_CPU);
    struct ssg_image *gl = straight_down_map(s, res, 1, SSG_BACKEND_GL);
    struct ssg_image *full = straight_down_map(s, res, 0, SSG_BACKEND_CPU);
    check_cap(s, cpu, res, "shadow map, cpu");
    check_cap(s, gl, res, "shadow map, gl");
    size_t differ = 0, moved = 0;
    for (size_t i = 0; i < (size_t)res * res; i++) {
        differ += fabsf(cpu->data[i] - gl->data[i]) > 1e-4f;
        moved += fabsf(cpu->data[i] - full->data[i]) > 1e-4f;
    }
    fprintf(stderr, "shadow map: %zu texels differ between cpu and gl, %zu from proxy=false's "
            "(the proxy is drawn)\n", differ, moved);
    CHECK(differ <= (size_t)res * res / 1000);
    CHECK(moved > 100);
    ssg_image_destroy(&cpu);
    ssg_image_destroy(&gl);
    ssg_image_destroy(&full);
    ssg_scene_destroy(&s);
}

/* The sun's light map (own light, fitted to the scene) with or without proxies. */
static void sun_maps(const struct ssg_scene *s, int res, int proxy, enum ssg_backend backend,
                     struct ssg_image *out[3])
{
    char set[32];
    snprintf(set, sizeof set, "resolution=%d", res);
    const char *sets[] = {set, proxy ? "proxy=true" : "proxy=false"};
    void *params = node_params(&ssg_node_lightmaps, sets, 2);
    out[0] = ssg_image_create(res, res, 1);
    out[1] = ssg_image_create(res, res, 3);
    out[2] = ssg_image_create(res, res, 3);
    CHECK_EQ(node_run_scene(&ssg_node_lightmaps, s, &FRAME, params, NULL, out, backend),
             SSG_OK);
    free(params);
}

/* A denser sphere (65,024 triangles) in the sun's 128^2 light map straight down: each
   texel's depth puts its point on the sphere within an eighth of a texel (the bound of a
   light map's proxy, along the ray: the surface's distance / cos) where the sphere faces
   the light (cos > 0.6), on both backends, and the proxy is drawn (depths differ from
   proxy=false's). */
static void test_light_map(enum ssg_backend backend)
{
    static const char *const SUN =
        "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
        "directional_light(direction=[0, -1, 0], color=[1, 1, 1], intensity=1)\n"
        "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
        "sphere(center=[0, 0.5, 0], radius=0.5, subdivisions=128)\n";
    struct ssg_scene *s = scene_from_text("proxy_sun", SUN);
    if (!s)
        return;
    const int res = 128;
    struct ssg_image *maps[3] = {NULL, NULL, NULL}, *full[3] = {NULL, NULL, NULL};
    sun_maps(s, res, 1, backend, maps);
    sun_maps(s, res, 0, backend, full);
    struct ssg_lightmap_face face;
    struct ssg_lightmap_view view = {&FRAME, &s->camera, res};
    CHECK_EQ(ssg_lightmap_faces_fit(s, SSG_LIGHTMAP_OWN_ONLY, SSG_LIGHTMAP_FIT_SCENE, &view,
                                    &face, 1), 1);
    const double texel = 2.0 * face.half / res;
    int cap = 0, bad = 0, moved = 0;
    double worst = 0;
    for (int y = 0; maps[0] && full[0] && y < res; y++)
        for (int x = 0; x < res; x++) {
            float p[3];
            ssg_lightmap_texel_point(&face, res, x, y, px_at(maps[0], 0, x, y), p);
            double d[3] = {p[0] - CENTRE[0], p[1] - CENTRE[1], p[2] - CENTRE[2]};
            double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (d[1] < 0.6 * RADIUS || fabs(r - RADIUS) > 0.2 * RADIUS)
                continue; /* not the sphere's lit cap (the floor) */
            double e = fabs(r - RADIUS) / (d[1] / r);
            worst = e > worst ? e : worst;
            cap++, bad += e > 0.125 * texel;
            moved += fabsf(px_at(maps[0], 0, x, y) - px_at(full[0], 0, x, y)) > 1e-5f;
        }
    fprintf(stderr, "light map (%s): %d cap texels, worst distance from the sphere %.3g (an "
            "eighth of a texel: %.3g), %d over; %d moved from proxy=false's\n",
            backend == SSG_BACKEND_GL ? "gl" : "cpu", cap, worst, 0.125 * texel, bad, moved);
    CHECK(cap > 200);
    CHECK_EQ(bad, 0);
    CHECK(moved > 20);
    images_free(maps, 3);
    images_free(full, 3);
    ssg_scene_destroy(&s);
}

/* The courtyard's bunny (69,666 triangles) in 32 environment lights' maps: CPU and GL draw
   the same proxy, so their texels see the same surface. */
static void test_parity(void)
{
    struct ssg_scene *s = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_scene_load("examples/courtyard.scene", 1, &s, &d), SSG_OK);
    if (!s)
        return;
    struct ssg_image *cpu[3] = {NULL, NULL, NULL}, *gl[3] = {NULL, NULL, NULL};
    const struct ssg_lightmap_sources env = {0, 32, 1};
    CHECK_EQ(maps_with(s, &FRAME, 128, env, SSG_BACKEND_CPU, cpu), SSG_OK);
    CHECK_EQ(maps_with(s, &FRAME, 128, env, SSG_BACKEND_GL, gl), SSG_OK);
    for (int i = 0; i < 3 && cpu[i] && gl[i]; i++) {
        size_t n = (size_t)cpu[i]->width * cpu[i]->height * cpu[i]->channels, differ = 0;
        for (size_t k = 0; k < n; k++)
            differ += fabs((double)cpu[i]->data[k] - gl[i]->data[k]) > 1e-3;
        fprintf(stderr, "courtyard maps %d: %zu of %zu values differ by over 1e-3 between cpu "
                "and gl (tol 1e-4 of them)\n", i, differ, n);
        CHECK(differ <= n / 10000); /* measured: 1, 3 and 25 (silhouette ties); the same
                                       with proxy=false */
    }
    images_free(cpu, 3);
    images_free(gl, 3);
    ssg_scene_destroy(&s);
}

int main(void)
{
    test_levels();
    test_shadow_map();
    test_light_map(SSG_BACKEND_CPU);
    test_light_map(SSG_BACKEND_GL);
    test_parity();
    return check_report();
}
