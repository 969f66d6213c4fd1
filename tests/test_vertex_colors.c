/* test_vertex_colors.c - glTF COLOR_0 multiplies the base colour (issue 45) on every path
 * that reads albedo: tests/fixtures/vertex_colors.scene's quad (base colour 0.8, every
 * vertex (1, 0.5, 0.25, 1)) has the G-buffer albedo (0.8, 0.4, 0.2) on the CPU and on GL,
 * and the light map's flux (lightmaps, which reads albedo at its texels) is that albedo
 * times the light's, on both. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "scene_node.h"
#include "light_maps.h"
#include "scene/scene.h"
#include "ssgraph.h"

static char tmp[512];

static const char *const GRAPH = "tests/fixtures/vertex_colors.graph";

static void check_backend(const char *backend)
{
    char dir[600], path[700];
    snprintf(dir, sizeof dir, "%s/%s", tmp, backend);
    struct ssg_diags d = {0};
    CHECK_EQ(graph_run_on(GRAPH, NULL, backend, dir), SSG_OK);
    snprintf(path, sizeof path, "%s/colors.exr", dir);
    struct ssg_image *albedo = NULL, *maps[3] = {NULL, NULL, NULL};
    CHECK_EQ(ssg_image_read(path, "albedo", &albedo, &d), SSG_OK);
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load("tests/fixtures/vertex_colors.scene", 1, &s, &d), SSG_OK);
    const struct ssg_frame frame = {32, 24, 40, 0.05f, 20, 1, 0, 0, 0};
    const struct ssg_lightmap_sources own = {1, 0, 1};
    enum ssg_backend b = strcmp(backend, "gl") ? SSG_BACKEND_CPU : SSG_BACKEND_GL;
    if (s)
        CHECK_EQ(maps_fit(s, &frame, 64, own, "scene", b, maps), SSG_OK);
    const struct ssg_image *flux = maps[2];
    const double want[3] = {0.8, 0.4, 0.2};
    int quad = 0, bad = 0, lit = 0, flux_bad = 0;
    for (size_t i = 0; albedo && i < (size_t)albedo->width * albedo->height; i++) {
        if (ssg_image_plane(albedo, 0)[i] == 0.0f)
            continue; /* background */
        quad++;
        for (int c = 0; c < 3; c++)
            bad += fabs(ssg_image_plane(albedo, c)[i] - want[c]) > 1e-6;
    }
    /* the sun's one face straight down: every texel on the quad sends albedo x the light */
    for (size_t i = 0; flux && i < (size_t)flux->width * flux->height; i++) {
        float r = ssg_image_plane(flux, 0)[i];
        if (r == 0.0f)
            continue;
        lit++;
        for (int c = 0; c < 3; c++) /* the ratios of the channels are the albedo's */
            flux_bad += fabs(ssg_image_plane(flux, c)[i] / r - want[c] / want[0]) > 1e-5;
    }
    fprintf(stderr, "%s: %d quad px, %d albedo values off; %d light-map texels, %d off\n",
            backend, quad, bad, lit, flux_bad);
    CHECK(quad > 100 && lit > 100);
    CHECK_EQ(bad, 0);
    CHECK_EQ(flux_bad, 0);
    ssg_image_destroy(&albedo);
    if (maps[0])
        images_free(maps, 3);
    ssg_scene_destroy(&s);
}

int main(void)
{
    const char *dir = getenv("SSG_TMP");
    snprintf(tmp, sizeof tmp, "%s", dir && dir[0] ? dir : CHECK_TMP_ROOT "/test_vertex_colors");
    mkdir(tmp, 0755);
    check_backend("cpu");
    check_backend("gl");
    return check_report();
}
