/* test_gltf_lights.c - a glTF file's own lights (KHR_lights_punctual, issue 45):
 * - tests/fixtures/gltf_lights.scene (the file's point, directional and spot lights)
 *   renders as gltf_lights_lines.scene, which drops the file's lights (lights=false) and
 *   writes the same three as scene lines: the G-buffer's direct light and direct_light's
 *   shadowed one agree to float rounding;
 * - the file's lights are read in world space (the point's node translation, the
 *   directional node's -Z turned straight down, the spot's -Z turned 70 degrees down and
 *   its cone from radians), with no warning;
 * - a lights file (--lights) replaces them as it replaces the scene's own lines. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene_node.h"
#include "scratch.h"
#include "scene/scene.h"
#include "ssgraph.h"


static struct ssg_image *render(const char *scene, const char *label, const char *layer)
{
    char dir[600], path[700];
    snprintf(dir, sizeof dir, "%s", tmp_path(label));
    struct ssg_diags d = {0};
    CHECK_EQ(graph_run_on("tests/fixtures/gltf_lights.graph", scene, "cpu", dir), SSG_OK);
    snprintf(path, sizeof path, "%s/lights.exr", dir);
    struct ssg_image *im = NULL;
    CHECK_EQ(ssg_image_read(path, layer, &im, &d), SSG_OK);
    return im;
}

static void check_same_image(const char *layer)
{
    struct ssg_image *a = render("tests/fixtures/gltf_lights.scene", "file", layer);
    struct ssg_image *b = render("tests/fixtures/gltf_lights_lines.scene", "lines", layer);
    double worst = 0, brightest = 0;
    for (size_t i = 0; a && b && i < 3 * (size_t)a->width * a->height; i++) {
        worst = fmax(worst, fabs((double)a->data[i] - b->data[i]));
        brightest = fmax(brightest, a->data[i]);
    }
    fprintf(stderr, "%s: the file's lights against the same lines: largest difference %.3g "
            "(brightest %.3g)\n", layer ? layer : "direct_light", worst, brightest);
    CHECK(a && b && brightest > 0.1);
    CHECK(worst <= 1e-6 * brightest);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

static void check_lights_read(void)
{
    struct ssg_scene *s = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_scene_load("tests/fixtures/gltf_lights.scene", 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    CHECK_EQ(d.warning_count, 0);
    if (s) {
        CHECK_EQ(s->light_count, 3);
        CHECK(s->light_count == 3 && s->lights[0].kind == SSG_LIGHT_POINT &&
              s->lights[1].kind == SSG_LIGHT_DIRECTIONAL && s->lights[2].kind == SSG_LIGHT_SPOT);
        if (s->light_count == 3) {
            CHECK_NEAR(s->lights[0].position[1], 1.2, 1e-6);
            CHECK_NEAR(s->lights[0].color[2], 0.25, 0);
            CHECK_NEAR(s->lights[0].intensity, 2, 0);
            CHECK_NEAR(s->lights[1].direction[1], -1, 1e-6);
            CHECK_NEAR(s->lights[1].intensity, 0.5, 0);
            CHECK_NEAR(s->lights[2].position[1], 2, 1e-6);
            CHECK_NEAR(s->lights[2].direction[1], -sin(70 * M_PI / 180), 1e-6);
            CHECK_NEAR(s->lights[2].direction[2], -cos(70 * M_PI / 180), 1e-6);
            CHECK_NEAR(s->lights[2].cos_inner, cos(0.3), 1e-6);
            CHECK_NEAR(s->lights[2].cos_outer, cos(0.6), 1e-6);
        }
        CHECK(s->models[0].ignored[0] == 0);
    }
    ssg_scene_destroy(&s);
    /* a lights file relights the scene: the file's lights go with its own lines */
    d = (struct ssg_diags){0};
    CHECK_EQ(ssg_scene_load_lit("tests/fixtures/gltf_lights.scene", "examples/lights/sun.scene",
                                1, &s, &d), SSG_OK);
    if (s)
        CHECK_EQ(s->light_count, 1);
    ssg_scene_destroy(&s);
}

int main(void)
{
    setup_tmp("gltf_lights");
    check_lights_read();
    check_same_image(NULL);
    check_same_image("gbuffer_direct");
    return check_report();
}
