/* test_rsm_vis.c - `rsm` with visibility=true on maps made by hand (rsm_maps.h), under a
 * point light at (0, 2, 0): four texels of the floor below it (cell 1: four VPLs on a
 * square around p, facing up), a square occluder of side 1 at y = 1 straight above them,
 * and two receivers:
 *   a  above the occluder at p + (0, 1.6, 0), facing down: every segment to a VPL crosses
 *      the occluder, so its bounce is 0 with visibility, and the unshadowed sum (not 0)
 *      without;
 *   b  beside the VPLs at p + (1.2, 0.4, 0), facing them: every segment stays below
 *      y = 0.4, below the occluder, so its bounce is the same bits as without.
 * Both in the exact sum (every VPL tested) and with the control variate (samples=2 of the
 * four, vis_draws=1: the tested draw's light, taken vis_stride = 2 times off the two
 * draws' sum, leaves 0 for a, whose four terms are equal by symmetry, to rounding; and
 * nothing for b, whose tested draw is visible). And the scene without the occluder:
 * nothing changes for a either. */
#include <stdio.h>

#include "rsm_maps.h"

static const char *const LIGHT = "camera(position=[0, 1, 4], target=[0, 1, 0])\n"
                                 "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
                                 "point_light(position=[0, 2, 0])\n";

/* The scene, with the occluder centred above p when `occluder`. */
static struct ssg_scene *scene(const float p[3], int occluder)
{
    char text[512];
    int n = snprintf(text, sizeof text, "%s", LIGHT);
    if (occluder)
        snprintf(text + n, sizeof text - n, "plane(center=[%.6f, 1, %.6f], normal=[0, -1, 0], "
                 "size=[1, 0, 1])\n", p[0], p[2]);
    return scene_from_text("rsm_vis", text);
}

/* Texels (5..6, 9..10) of the cube's face 3 (down) at depth 2: floor points on a square
   (the face is parallel to the floor); p = the square's centre. */
static void floor_texels(struct maps *m, float p[3])
{
    const float up[3] = {0, 1, 0}, phi[3] = {0.3f, 0.2f, 0.1f};
    for (int k = 0; k < 3; k++)
        p[k] = 0.0f;
    for (int y = 9; y <= 10; y++)
        for (int x = 5; x <= 6; x++) {
            float q[3];
            maps_set(m, 3, x, y, 2.0f, up, phi, q);
            for (int k = 0; k < 3; k++)
                p[k] += 0.25f * q[k];
        }
}

static void check_case(const char *const *on, const char *const *off, int count)
{
    float p[3];
    struct ssg_scene *first = scene((const float[3]){0, 0, 0}, 0);
    if (!first)
        return;
    struct maps m = maps_make(first, 16);
    floor_texels(&m, p);
    CHECK(fabsf(p[1]) < 1e-4f); /* the texels lie on the floor */
    struct ssg_scene *s = scene(p, 1);
    struct gbuf g = gbuf_make(first, 2, 1);
    gbuf_set(&g, 0, (const float[3]){p[0], 1.6f, p[2]}, (const float[3]){0, -1, 0});
    gbuf_set(&g, 1, (const float[3]){p[0] + 1.2f, 0.4f, p[2]}, (const float[3]){-1, 0, 0});
    struct ssg_image *lit = rsm_run(s, &m, &g, 0, 1, off, count, SSG_BACKEND_CPU);
    struct ssg_image *shadowed = rsm_run(s, &m, &g, 0, 1, on, count + 1, SSG_BACKEND_CPU);
    struct ssg_image *open = rsm_run(first, &m, &g, 0, 1, on, count + 1, SSG_BACKEND_CPU);
    for (int c = 0; c < 3; c++) {
        CHECK(px(lit, c, 0) > 0.0f && px(lit, c, 1) > 0.0f);
        CHECK(px(shadowed, c, 0) <= 1e-6f * px(lit, c, 0)); /* a: behind the occluder */
        CHECK(px(shadowed, c, 1) == px(lit, c, 1));    /* b: a clear line */
        CHECK(px(open, c, 0) == px(lit, c, 0));        /* no occluder: a sees them all */
    }
    fprintf(stderr, "%s: a %g -> %g, b %g\n", on[count - 1], px(lit, 0, 0),
            px(shadowed, 0, 0), px(lit, 0, 1));
    ssg_image_destroy(&lit);
    ssg_image_destroy(&shadowed);
    ssg_image_destroy(&open);
    gbuf_free(&g);
    maps_free(&m);
    ssg_scene_destroy(&s);
    ssg_scene_destroy(&first);
}

int main(void)
{
    const char *exact[] = {"cell=1", "samples=0", "visibility=true"};
    check_case(exact, exact, 2);
    const char *tested[] = {"cell=1", "samples=2", "vis_draws=1", "visibility=true"};
    check_case(tested, tested, 3);
    return check_report();
}
