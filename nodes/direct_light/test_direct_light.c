/* test_direct_light.c - the `direct_light` node on G-buffers and maps of small scenes (the
 * gbuffer and lightmaps nodes, tested on their own):
 * - a box above a floor under the sun: a floor point under the box's centre gets nothing,
 *   one far from it exactly gbuffer's direct light (visibility 1);
 * - a zero-thickness wall on a floor, lit from behind at a grazing angle by a directional
 *   and by a point light: the shadow reaches its foot, the floor beside it is fully lit;
 * - a point light over an open floor, the PCF disc wide: no seam where the disc crosses
 *   the cube's edges (the floor is lit everywhere);
 * - soft shadows (light_size) widen the penumbra of a raised box;
 * - contact shadows: a wall under a ceiling that the ceiling shades whole (by hand: every
 *   ray from the wall meets the ceiling) is dark everywhere with contact, where the map's
 *   offsets alone leave a lit band under the ceiling; the faces of a lit two-step stair
 *   keep the light the maps give them (no contact shadow past a step's edge);
 * - bad input: a light of zero intensity (black, no NaN), a point light in a closed box
 *   (the floor outside dark), a directional light parallel to a wall, a scene without
 *   lights (out 0, visibility 1), maps of another face count (refused). */
#include <math.h>
#include <string.h>

#include "check.h"
#include "common/trace.h"
#include "light_maps.h"
#include "reference_gi/reference_gi.h"

extern const struct ssg_node_desc ssg_node_reference_gi;

enum { W = 96, H = 72 };
static const struct ssg_frame FRAME = {W, H, 45, 0.05f, 100, 1, 0, 0, 0};

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
/* The scene of the contact tests: the Cornell box's camera, a floor, and what `more` adds,
   lit by l = (0, 0.75, 0.66) (towards the light), maps of `res`, direct_light with the
   given contact. */
static int contact_make(struct lit *l, const char *name, const char *more, int res,
                        const char *contact)
{
    char text[1024];
    snprintf(text, sizeof text,
             "camera(position=[0, 1, 3.9], target=[0, 1, 0], fov=40)\n"
             "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n%s"
             "directional_light(direction=[0, -0.75, -0.66], intensity=2)\n", more);
    const char *sets[] = {contact};
    return lit_make(l, name, text, res, sets, 1);
}

/* A back wall (z = -1, facing +z) under a ceiling (y = 2, z in [-1, 1]): the ray from a wall
   point at height y meets y = 2 at z = -1 + 0.88 (2 - y), within the ceiling, so the whole
   wall is in shadow. Maps of 64 texels (0.09 scene units) make the offsets' leak under the
   ceiling a few pixels tall. Returns the wall's lit pixels (away from its sides, where the
   ceiling's shadow ends, and from the floor). */
static int crease_lit_wall_pixels(const char *contact)
{
    struct lit l;
    if (!contact_make(&l, "dl_crease",
                      "plane(center=[0, 1, -1], normal=[0, 0, 1], size=[2, 0, 2])\n"
                      "plane(center=[0, 2, 0], normal=[0, -1, 0], size=[2, 0, 2])\n", 64,
                      contact))
        return -1;
    int lit = 0, wall = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float w[3];
            if (!world_of(&l, x, y, w) || fabsf(w[2] + 1.0f) > 1e-3f || fabsf(w[0]) > 0.7f ||
                w[1] < 0.5f)
                continue;
            wall++;
            lit += px_at(l.r[1], 0, x, y) > 0.0f;
        }
    CHECK(wall > 500);
    lit_free(&l);
    return lit;
}

/* Two steps lit from the front: a low box (top y = 0.4, front z = 0.2) and a high one
   behind it (top y = 0.8, riser at z = -0.2). Nothing stands between the faces the camera
   sees and the light, so contact shadows must leave their light as the maps give it: the
   march runs past the low step's edge behind the high tread's extension, in open air. */
static void stairs_unshadowed(void)
{
    static const char *const STAIRS = "box(center=[0, 0.2, 0], size=[1.2, 0.4, 0.4])\n"
                                      "box(center=[0, 0.4, -0.4], size=[1.2, 0.8, 0.4])\n";
    struct lit plain, contact;
    if (!contact_make(&plain, "dl_stairs", STAIRS, 256, "contact=0"))
        return;
    if (!contact_make(&contact, "dl_stairs", STAIRS, 256, "contact=8")) {
        lit_free(&plain);
        return;
    }
    int faces = 0, darker = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float w[3];
            if (!world_of(&plain, x, y, w) || fabsf(w[0]) > 0.55f)
                continue;
            int low_top = fabsf(w[1] - 0.4f) < 1e-3f && w[2] > -0.2f;
            int riser = fabsf(w[2] + 0.2f) < 1e-3f && w[1] > 0.4f;
            int high_top = fabsf(w[1] - 0.8f) < 1e-3f;
            if (!(low_top || riser || high_top))
                continue;
            faces++;
            darker += px_at(contact.r[1], 0, x, y) != px_at(plain.r[1], 0, x, y);
        }
    fprintf(stderr, "stairs: %d of %d step pixels darker with contact\n", darker, faces);
    CHECK(faces > 150);
    CHECK_EQ(darker, 0);
    lit_free(&plain);
    lit_free(&contact);
}

/* Pixels of direct light D off the truth T (reference_gi's direct term: one shadow ray a
   light, exact for the sun) by more than a quarter of the lit value: too dark where the
   truth is lit (*dark), too bright where it is in shadow (*leak). */
static void count_off(const struct ssg_image *d, const struct ssg_image *t, int *dark,
                      int *leak)
{
    *dark = *leak = 0;
    size_t plane = (size_t)d->width * d->height;
    for (size_t i = 0; i < plane; i++) {
        float a = d->data[plane + i], b = t->data[plane + i]; /* green */
        *dark += b > 0.05f && a < 0.75f * b;
        *leak += b < 0.01f && a > 0.05f;
    }
}

/* A whole example scene under the sun (gi.graph's direct_light: the map fitted to the view,
   filter 0.75, normal offset 1) against the truth, without and with contact shadows. */
static void contact_against_truth(const char *scene, int out[4])
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load_lit(scene, "examples/lights/sun.scene", 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!s)
        return;
    const struct ssg_frame frame = {160, 120, s->camera.fov_y, s->camera.near_z,
                                    s->camera.far_z, 1, 0, 0, 0};
    struct ssg_image *g[SSG_GBUFFER_OUTPUTS], *m[3], *r[2], *t[3];
    gbuffer_of(s, &frame, g);
    CHECK_EQ(maps_fit(s, &frame, 256, SSG_LIGHTMAP_OWN_ONLY, "view", SSG_BACKEND_CPU, m),
             SSG_OK);
    const char *ref_sets[] = {"samples=1"};
    void *ref = node_params(&ssg_node_reference_gi, ref_sets, 1);
    for (int k = 0; k < 3; k++)
        t[k] = ssg_image_create(frame.width, frame.height, 3);
    const struct ssg_image *in[3] = {g[SSG_GBUFFER_OUT_POSITION], g[SSG_GBUFFER_OUT_NORMAL],
                                     g[SSG_GBUFFER_OUT_ALBEDO]};
    CHECK_EQ(node_run_scene(&ssg_node_reference_gi, s, &frame, ref, in, t, SSG_BACKEND_CPU),
             SSG_OK);
    free(ref);
    for (int c = 0; c < 2; c++) {
        const char *sets[] = {"fit=view", "filter=0.75", "normal_offset=1",
                              c ? "contact=8" : "contact=0"};
        CHECK_EQ(direct_of(s, &frame, g, m[0], sets, 4, SSG_BACKEND_CPU, r), SSG_OK);
        count_off(r[0], t[SSG_REFERENCE_GI_OUT_DIRECT], &out[2 * c], &out[2 * c + 1]);
        images_free(r, 2);
    }
    images_free(g, SSG_GBUFFER_OUTPUTS);
    images_free(m, 3);
    images_free(t, 3);
    ssg_scene_destroy(&s);
}

static void test_contact(void)
{
    int lit_plain = crease_lit_wall_pixels("contact=0");
    int lit_contact = crease_lit_wall_pixels("contact=8");
    fprintf(stderr, "wall under a ceiling: %d wall px lit without contact, %d with\n",
            lit_plain, lit_contact);
    CHECK(lit_plain > 20); /* the leak the offsets leave, which contact is for */
    CHECK_EQ(lit_contact, 0);
    stairs_unshadowed();
    /* Against the truth: most of the Cornell box's lit lines under its ceiling and along
       its walls go, and on the pyramids (steps seen from above, the sun from the side)
       contact shadows darken at most a tenth more lit pixels than the map alone (without
       the check that the crossing is on a surface the camera sees, the march shadowed
       risers past the treads' edges). */
    int cornell[4] = {0}, pyramids[4] = {0};
    contact_against_truth("examples/cornell.scene", cornell);
    contact_against_truth("examples/pyramids.scene", pyramids);
    fprintf(stderr, "against the truth, too dark / too bright px without -> with contact: "
            "cornell %d / %d -> %d / %d, pyramids %d / %d -> %d / %d\n", cornell[0],
            cornell[1], cornell[2], cornell[3], pyramids[0], pyramids[1], pyramids[2],
            pyramids[3]);
    /* measured: cornell 30 / 198 -> 30 / 42, pyramids 114 / 71 -> 120 / 40; without the
       crossing's check the pyramids' too dark ones were 126, the Cornell box's 37 */
    CHECK(cornell[3] < cornell[1] / 2);
    CHECK(cornell[2] <= cornell[0]);
    CHECK(pyramids[3] < pyramids[1]);
    CHECK(10 * pyramids[2] <= 11 * pyramids[0]);
}

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
    char why[400];
    void *params = node_params(&ssg_node_direct_light, NULL, 0);
    in[SSG_DIRECT_LIGHT_IN_MAPS] = (struct ssg_shape){16, 16, 1, SSG_T_LIGHTMAPS};
    CHECK_EQ(ssg_node_direct_light.check_scene(params, s, in, out, why, sizeof why),
             SSG_E_CHANNELS);
    fprintf(stderr, "maps of 1 face for a point light: %s\n", why);
    in[SSG_DIRECT_LIGHT_IN_MAPS].channels = 6;
    CHECK_EQ(ssg_node_direct_light.check_scene(params, s, in, out, why, sizeof why), SSG_OK);
    free(params);
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
    test_contact();
    test_bad_input();
    test_wrong_maps();
    return check_report();
}
