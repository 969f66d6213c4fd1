/* test_direct_light.c - the `direct_light` node on G-buffers and maps of small scenes (the
 * gbuffer and lightmaps nodes, tested on their own):
 * - a box above a floor under the sun: a floor point under the box's centre gets nothing,
 *   one far from it exactly gbuffer's direct light (visibility 1);
 * - a zero-thickness wall on a floor, lit from behind at a grazing angle by a directional
 *   and by a point light: the shadow reaches its foot, the floor beside it is fully lit;
 * - a point light over an open floor, the PCF disc wide: no seam where the disc crosses
 *   the cube's edges (the floor is lit everywhere);
 * - soft shadows (light_size) widen the penumbra of a raised box;
 * - bad input: a light of zero intensity (black, no NaN), a point light in a closed box
 *   (the floor outside dark), a directional light parallel to a wall, a scene without
 *   lights (out 0, visibility 1), maps of another face count (refused). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "common/trace.h"
#include "light_maps.h"

enum { W = 96, H = 72 };
static const struct ssg_frame FRAME = {W, H, 45, 0.05f, 100, 1, 0};

/* A scene with its G-buffer, maps and direct light (sets applied). */
struct lit {
    struct ssg_scene *s;
    struct ssg_image *g[SSG_GBUFFER_OUTPUTS], *m[3], *r[2];
    float rot[9], eye[3];
};

static int lit_make(struct lit *l, const char *name, const char *text, int res,
                    const char *const *sets, int set_count)
{
    memset(l, 0, sizeof *l);
    l->s = scene_from_text(name, text);
    if (!l->s)
        return 0;
    gbuffer_of(l->s, &FRAME, l->g);
    CHECK_EQ(maps_of(l->s, &FRAME, res, SSG_BACKEND_CPU, l->m), SSG_OK);
    CHECK_EQ(direct_of(l->s, &FRAME, l->g, l->m[0], sets, set_count, SSG_BACKEND_CPU, l->r),
             SSG_OK);
    ssg_camera_frame(&l->s->camera, l->rot, l->eye);
    return 1;
}

static void lit_free(struct lit *l)
{
    images_free(l->g, SSG_GBUFFER_OUTPUTS);
    images_free(l->m, 3);
    images_free(l->r, 2);
    ssg_scene_destroy(&l->s);
}

/* The world point of pixel (x, y); 0 for background. */
static int world_of(const struct lit *l, int x, int y, float w[3])
{
    const struct ssg_image *n = l->g[SSG_GBUFFER_OUT_NORMAL];
    if (px_at(n, 0, x, y) == 0 && px_at(n, 1, x, y) == 0 && px_at(n, 2, x, y) == 0)
        return 0;
    float v[3];
    for (int c = 0; c < 3; c++)
        v[c] = px_at(l->g[SSG_GBUFFER_OUT_POSITION], c, x, y);
    for (int k = 0; k < 3; k++)
        w[k] = l->eye[k] + l->rot[k] * v[0] + l->rot[3 + k] * v[1] + l->rot[6 + k] * v[2];
    return 1;
}

static void test_box_under_sun(void)
{
    struct lit l;
    if (!lit_make(&l, "dl_box", "camera(position=[0, 2.5, 2.5], target=[0, 0, 0])\n"
                                "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
                                "box(center=[0, 0.8, 0], size=[0.8, 0.2, 0.8])\n"
                                "directional_light(direction=[0, -1, 0], color=[1, 0.8, 0.6], "
                                "intensity=2)\n", 256, NULL, 0))
        return;
    int under = 0, far = 0;
    double worst = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float w[3];
            if (!world_of(&l, x, y, w) || w[1] > 1e-3f)
                continue;
            float r = fmaxf(fabsf(w[0]), fabsf(w[2]));
            if (r < 0.2f) {
                under++;
                CHECK_EQ(px_at(l.r[1], 0, x, y), 0.0f);
                CHECK_EQ(px_at(l.r[0], 0, x, y), 0.0f);
            } else if (r > 0.6f) {
                far++;
                CHECK_EQ(px_at(l.r[1], 0, x, y), 1.0f);
                for (int c = 0; c < 3; c++) {
                    double d = px_at(l.g[SSG_GBUFFER_OUT_DIRECT], c, x, y);
                    worst = fmax(worst, fabs(px_at(l.r[0], c, x, y) - d) / d);
                }
            }
        }
    fprintf(stderr, "box under the sun: %d floor px under it dark, %d far ones off gbuffer's "
            "direct by %.2g (relative) at most\n", under, far, worst);
    CHECK(under > 20 && far > 200);
    CHECK(worst < 1e-6);
    lit_free(&l);
}

/* The wall's shadow on the floor (|x| < 0.1, 0 < z < 0.4): the farthest lit pixel from the
   wall, in the map's texels; and the lit share of the floor well beside it. */
static void wall_foot(const char *light, const char *what, float texel_at_foot)
{
    char text[800];
    snprintf(text, sizeof text, "camera(position=[0, 0.5, 0.8], target=[0, 0, 0.15])\n"
             "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
             "plane(center=[0, 0.5, 0], normal=[0, 0, 1], size=[0.3, 0, 1])\n%s\n", light);
    struct lit l;
    if (!lit_make(&l, "dl_wall", text, 512, NULL, 0))
        return;
    double leak = 0;
    int shadow = 0, side = 0, side_lit = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float w[3];
            if (!world_of(&l, x, y, w) || w[1] > 1e-3f)
                continue;
            float v = px_at(l.r[1], 0, x, y);
            if (fabsf(w[0]) < 0.1f && w[2] > 0.0f && w[2] < 0.4f) {
                shadow++;
                leak = v > 0.5f && w[2] > leak ? w[2] : leak;
            } else if (fabsf(w[0]) > 0.3f && w[2] > -0.5f && w[2] < 0.3f) {
                side++;
                side_lit += v == 1.0f;
            }
        }
    fprintf(stderr, "wall foot, %s: %d px in the shadow, lit up to %.2f texels from the foot; "
            "%d of %d beside it fully lit\n", what, shadow, leak / texel_at_foot, side_lit,
            side);
    CHECK(shadow > 300 && side > 100);
    CHECK(leak / texel_at_foot <= 1.5);
    CHECK_EQ(side_lit, side);
    lit_free(&l);
}

static void test_wall_foot(void)
{
    /* the sphere of the floor (4 x 4) and wall: radius ~2.9, texel 2 r / 512 */
    wall_foot("directional_light(direction=[0, -0.35, 1], intensity=2)", "sun",
              2 * 2.87f / 512);
    /* the light 1.9 behind the wall, 0.7 up: a texel at the foot is 2 d / R */
    wall_foot("point_light(position=[0, 0.7, -1.9], intensity=4)", "point light",
              2 * 2.03f / 512);
}

/* An open floor under a point light with a wide PCF disc: every floor pixel the light
   reaches is fully lit, across the cube's face edges too. */
static void test_cube_seams(void)
{
    const char *sets[] = {"filter=6", "samples=32"};
    struct lit l;
    if (!lit_make(&l, "dl_seams", "camera(position=[0, 3, 3], target=[0, 0, 0])\n"
                                  "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[6, 0, 6])\n"
                                  "point_light(position=[0.1, 0.4, -0.2], intensity=2)\n",
                  64, sets, 2))
        return;
    int floor = 0, dark = 0;
    float least = 1.0f;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float w[3];
            if (!world_of(&l, x, y, w))
                continue;
            floor++;
            /* the bilinear footprint may cost a grazing pixel a fraction of a tap */
            dark += px_at(l.r[1], 0, x, y) < 0.99f;
            least = fminf(least, px_at(l.r[1], 0, x, y));
        }
    fprintf(stderr, "open floor under a point light, PCF 6 texels: %d of %d px below 0.99 "
            "lit, the least %.4f\n", dark, floor, least);
    CHECK(floor > 3000);
    CHECK_EQ(dark, 0);
    lit_free(&l);
}

/* The penumbra of a box 0.6 above the floor: pixels neither lit nor dark. */
static int penumbra(const char *size)
{
    const char *sets[] = {size};
    struct lit l;
    if (!lit_make(&l, "dl_soft", "camera(position=[0, 2.5, 2.5], target=[0, 0, 0])\n"
                                 "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
                                 "box(center=[0, 0.6, 0], size=[0.6, 0.1, 0.6])\n"
                                 "point_light(position=[0, 1.6, 0], intensity=2)\n",
                  256, sets, 1))
        return 0;
    int n = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        n += l.r[1]->data[i] > 0.02f && l.r[1]->data[i] < 0.98f;
    lit_free(&l);
    return n;
}

static void test_soft(void)
{
    int hard = penumbra("light_size=0"), soft = penumbra("light_size=0.3");
    fprintf(stderr, "penumbra pixels: %d hard, %d with light_size 0.3\n", hard, soft);
    CHECK(soft > 3 * hard && soft > 100);
}

/* Every output pixel finite; out all 0 when `black`, visibility all 1 when `clear`. */
static void check_outputs(const struct lit *l, int black, int clear)
{
    int bad = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        for (int c = 0; c < 3; c++)
            bad += !isfinite(l->r[0]->data[c * W * H + i]) ||
                   (black && l->r[0]->data[c * W * H + i] != 0.0f);
        bad += !isfinite(l->r[1]->data[i]) || (clear && l->r[1]->data[i] != 1.0f);
    }
    CHECK_EQ(bad, 0);
}

static void test_bad_input(void)
{
    struct lit l;
    const char *floor = "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                        "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n";
    char text[600];
    snprintf(text, sizeof text, "%spoint_light(position=[0, 1, 0], intensity=0)\n", floor);
    if (lit_make(&l, "dl_zero", text, 64, NULL, 0))
        check_outputs(&l, 1, 1), lit_free(&l);
    if (lit_make(&l, "dl_none", floor, 16, NULL, 0))
        check_outputs(&l, 1, 1), lit_free(&l);
    /* a point light inside a closed box over the floor: the floor outside is dark */
    snprintf(text, sizeof text, "%sbox(center=[0, 1, 0], size=[1, 1, 1])\n"
             "point_light(position=[0, 1, 0], intensity=3)\n", floor);
    if (lit_make(&l, "dl_closed", text, 64, NULL, 0)) {
        check_outputs(&l, 1, 0);
        double lit = 0;
        for (size_t i = 0; i < (size_t)W * H; i++)
            lit += l.g[SSG_GBUFFER_OUT_DIRECT]->data[i];
        CHECK(lit > 1.0); /* unshadowed, the floor would be lit */
        lit_free(&l);
    }
    /* the sun along a wall: the wall gets nothing, the floor beside it all */
    snprintf(text, sizeof text, "%splane(center=[0, 0.5, 0], normal=[1, 0, 0], "
             "size=[1, 0, 1])\ndirectional_light(direction=[0, -1, 0], intensity=2)\n", floor);
    if (lit_make(&l, "dl_parallel", text, 128, NULL, 0)) {
        check_outputs(&l, 0, 0);
        int side = 0, dark = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                float w[3];
                if (world_of(&l, x, y, w) && w[1] < 1e-3f && fabsf(w[0]) > 0.1f)
                    side++, dark += px_at(l.r[1], 0, x, y) != 1.0f;
            }
        CHECK(side > 1000);
        CHECK_EQ(dark, 0);
        lit_free(&l);
    }
}

static void test_wrong_maps(void)
{
    struct ssg_scene *s = scene_from_text(
        "dl_wrong", "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                    "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
                    "point_light(position=[0, 1, 0], intensity=1)\n");
    if (!s)
        return;
    struct ssg_image *g[SSG_GBUFFER_OUTPUTS], *r[2], *maps = ssg_image_create(16, 16, 1);
    gbuffer_of(s, &FRAME, g);
    CHECK_EQ(direct_of(s, &FRAME, g, maps, NULL, 0, SSG_BACKEND_CPU, r), SSG_E_SCENE);
    struct ssg_shape in[4] = {{0}}, out[2];
    char why[300];
    in[SSG_DIRECT_LIGHT_IN_MAPS] = (struct ssg_shape){16, 16, 1, SSG_T_LIGHTMAPS};
    CHECK_EQ(ssg_node_direct_light.check_scene(NULL, s, in, out, why, sizeof why),
             SSG_E_CHANNELS);
    fprintf(stderr, "maps of 1 face for a point light: %s\n", why);
    in[SSG_DIRECT_LIGHT_IN_MAPS].channels = 6;
    CHECK_EQ(ssg_node_direct_light.check_scene(NULL, s, in, out, why, sizeof why), SSG_OK);
    images_free(g, SSG_GBUFFER_OUTPUTS);
    images_free(r, 2);
    ssg_image_destroy(&maps);
    ssg_scene_destroy(&s);
}

int main(void)
{
    test_box_under_sun();
    test_wall_foot();
    test_cube_seams();
    test_soft();
    test_bad_input();
    test_wrong_maps();
    return check_report();
}
