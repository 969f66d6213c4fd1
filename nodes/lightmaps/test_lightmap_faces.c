/* test_lightmap_faces.c - the faces of nodes/common/lightmap.h that `lightmaps` renders and
 * `direct_light` and `rsm` read, checked against the header's conventions by hand:
 * - each of a point light's six cube faces, in the stated order (+x, -x, +y, -y, +z, -z),
 *   has u x v = axis, exactly;
 * - a known world direction from the light lands on each face at the texel worked out
 *   below from OpenGL's cube-map table, and the texel's ray at depth 1 is that direction;
 * - a directional light's orthographic face has u x v = -axis (ssg_shadow_frame_make's
 *   u x v = l, axis = -l).
 * Why u x v = +axis: face +z is the identity frame (u = x, v = y, axis = z), right-handed;
 * the other five are the same 90 degree camera turned, and a rotation keeps handedness, so
 * every face has u x v = +axis. A face mirrored (u or v negated, or the two swapped) has
 * u x v = -axis and shows its image flipped. It is also OpenGL's cube-map convention
 * (OpenGL 4.6, sec. 8.13, table 8.19) with t negated on every face (here row 0 is at -v):
 * GL's (s, t, major axis) is left-handed on all six faces, ours right-handed on all six.
 * Every node reads the faces from this one table (on GL too), so a mirrored face passes the
 * nodes' own and parity tests: only these checks see it. */
#include <math.h>

#include "check.h"
#include "common/lightmap.h"
#include "scenes.h"

static void cross(const float a[3], const float b[3], float c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* Face k of a point light at L, maps of side 8. A direction d from L falls on the face of
   its largest component; with z = |that component| = 1 it has a = d.u, b = d.v, so
   texel coordinate x = (a + 1) 4, y = (b + 1) 4 (not floored): a = 0.375 is x = 5.5, the
   centre of texel 5; -0.375 is 2.5, 0.625 is 6.5, -0.625 is 1.5. By GL's table (sc, tc
   for each major axis; ours a = sc, b = -tc):
     +x  d ( 1, .625, .375): sc = -rz = -.375, tc = -ry = -.625 -> a -.375, b .625 -> (2.5, 6.5)
     -x  d (-1, .625, .375): sc = +rz =  .375, tc = -ry        -> a  .375, b .625 -> (5.5, 6.5)
     +y  d (.375,  1, .625): sc = +rx =  .375, tc = +rz =  .625 -> a .375, b -.625 -> (5.5, 1.5)
     -y  d (.375, -1, .625): sc = +rx,         tc = -rz = -.625 -> a .375, b  .625 -> (5.5, 6.5)
     +z  d (.375, .625,  1): sc = +rx,         tc = -ry = -.625 -> a .375, b  .625 -> (5.5, 6.5)
     -z  d (.375, .625, -1): sc = -rx = -.375, tc = -ry        -> a -.375, b .625 -> (2.5, 6.5)
   Every value is a short binary fraction: the float results are exact. */
static const float DIR[6][3] = {{1, 0.625f, 0.375f},  {-1, 0.625f, 0.375f},
                                {0.375f, 1, 0.625f},  {0.375f, -1, 0.625f},
                                {0.375f, 0.625f, 1},  {0.375f, 0.625f, -1}};
static const float TEXEL[6][2] = {{2.5f, 6.5f}, {5.5f, 6.5f}, {5.5f, 1.5f},
                                  {5.5f, 6.5f}, {5.5f, 6.5f}, {2.5f, 6.5f}};

static void test_cube_faces(const struct ssg_scene *s)
{
    struct ssg_lightmap_face f[SSG_LIGHTMAP_FACES_MAX];
    CHECK_EQ(ssg_lightmap_faces(s, SSG_LIGHTMAP_OWN_ONLY, f, SSG_LIGHTMAP_FACES_MAX), 6);
    const float *L = s->lights[0].position;
    for (int k = 0; k < 6; k++) {
        float c[3], axis[3] = {0, 0, 0};
        axis[k / 2] = k % 2 ? -1.0f : 1.0f; /* +x, -x, +y, -y, +z, -z */
        cross(f[k].u, f[k].v, c);
        CHECK_EQ(f[k].ortho, 0);
        for (int i = 0; i < 3; i++) {
            CHECK(f[k].axis[i] == axis[i]);
            CHECK(c[i] == f[k].axis[i]); /* u x v = axis */
        }
        if (!(c[0] == f[k].axis[0] && c[1] == f[k].axis[1] && c[2] == f[k].axis[2]))
            fprintf(stderr, "face %d: u x v = (%g, %g, %g), axis (%g, %g, %g): mirrored\n",
                    k, c[0], c[1], c[2], f[k].axis[0], f[k].axis[1], f[k].axis[2]);
        CHECK_EQ(ssg_lightmap_cube_face(DIR[k]), k);
        float p[3] = {L[0] + DIR[k][0], L[1] + DIR[k][1], L[2] + DIR[k][2]}, q[3];
        float x = -1, y = -1, z = -1;
        CHECK(ssg_lightmap_project(&f[k], 8, p, &x, &y, &z));
        if (!(x == TEXEL[k][0] && y == TEXEL[k][1] && z == 1.0f))
            fprintf(stderr, "face %d: direction (%g, %g, %g) at texel (%g, %g) depth %g, "
                    "by hand (%g, %g) depth 1\n", k, DIR[k][0], DIR[k][1], DIR[k][2], x, y, z,
                    TEXEL[k][0], TEXEL[k][1]);
        CHECK(x == TEXEL[k][0]);
        CHECK(y == TEXEL[k][1]);
        CHECK(z == 1.0f);
        /* the texel's ray at depth 1 runs back along the direction */
        ssg_lightmap_texel_point(&f[k], 8, (int)TEXEL[k][0], (int)TEXEL[k][1], 1.0f, q);
        for (int i = 0; i < 3; i++)
            CHECK(q[i] == p[i]);
    }
}

/* The orthographic face: u x v = -axis (to float rounding; u, v come from l by formula). */
static void test_ortho_face(const struct ssg_scene *s)
{
    struct ssg_lightmap_face f[SSG_LIGHTMAP_FACES_MAX];
    CHECK_EQ(ssg_lightmap_faces(s, SSG_LIGHTMAP_OWN_ONLY, f, SSG_LIGHTMAP_FACES_MAX), 1);
    float c[3];
    cross(f[0].u, f[0].v, c);
    CHECK_EQ(f[0].ortho, 1);
    for (int i = 0; i < 3; i++)
        CHECK_NEAR(c[i], -f[0].axis[i], 1e-6);
}

/* The view fit (lightmap.h, SSG_LIGHTMAP_FIT_VIEW) by hand. The sun straight down, l = +y:
   ssg_shadow_frame_make gives u = +x, v = -z (Duff et al. with l = (0, 1, 0): sign 1,
   a = -1, b = 0). The scene's box is x, z in [-20, 20], y in [0, 1]. A camera at height 10
   looking straight down with a 90 degree square frame sees, at distance d, the square of
   half side d; clipped to the box (d from 9 to 10) the widest is the floor's, d = 10: the
   square x, z in [cx - 10, cx + 10] x [-10, 10] for a camera above (cx, 10, 0). Its
   smallest square in the light's plane is itself, side 20, not turned; with the padding of
   8 texels a side at R = 64 the map's half side is 10 x 64 / 48 = 40 / 3, centred over
   (cx, 0): the floor's corner (cx + 10, 0, 10) lands at texel x = (10 / (40 / 3) + 1) 32 =
   56 = R - 8, y = (-10 / (40 / 3) + 1) 32 = 8 (v = -z). The depth axis and the plane stay
   the scene fit's. The same camera turned 45 degrees about the vertical (up along
   (1, 0, -1)) sees that square turned, and the fit turns with it: half side 40 / 3 again
   (unturned it would need 10 sqrt 2 x 64 / 48) and u = (u + v) / sqrt 2. A camera looking
   up sees none of the box: the scene fit stays. */
static void fit_case(const char *camera, float cx, float turn, int fitted)
{
    char text[600];
    snprintf(text, sizeof text, "%s\nplane(center=[0, 0, 0], normal=[0, 1, 0], "
             "size=[40, 0, 40])\nbox(center=[0, 0.5, 0], size=[1, 1, 1])\n"
             "directional_light(direction=[0, -1, 0])\n", camera);
    struct ssg_scene *s = scene_from_text("lm_fit_view", text);
    if (!s)
        return;
    const struct ssg_frame frame = {64, 64, 90, 1, 20, 1, 0, 0, 0};
    struct ssg_lightmap_view view = {&frame, &s->camera, 64};
    struct ssg_lightmap_face scene_fit[1], f[1];
    CHECK_EQ(ssg_lightmap_faces(s, SSG_LIGHTMAP_OWN_ONLY, scene_fit, 1), 1);
    CHECK_EQ(ssg_lightmap_faces_fit(s, SSG_LIGHTMAP_OWN_ONLY, SSG_LIGHTMAP_FIT_VIEW, &view, f,
                                    1), 1);
    float half = fitted ? 40.0f / 3.0f : scene_fit[0].half;
    float c = cosf(turn), sn = sinf(turn);
    CHECK_NEAR(f[0].half, half, 1e-4);
    CHECK_NEAR(f[0].origin[0], fitted ? cx : scene_fit[0].origin[0], 1e-4);
    CHECK_NEAR(f[0].origin[1], scene_fit[0].origin[1], 1e-6);
    CHECK_NEAR(f[0].origin[2], scene_fit[0].origin[2], 1e-4);
    for (int k = 0; k < 3; k++) {
        CHECK(f[0].axis[k] == scene_fit[0].axis[k]);
        CHECK_NEAR(f[0].u[k], c * scene_fit[0].u[k] + sn * scene_fit[0].v[k], 1e-5);
        CHECK_NEAR(f[0].v[k], -sn * scene_fit[0].u[k] + c * scene_fit[0].v[k], 1e-5);
    }
    if (fitted && turn == 0.0f) {
        float corner[3] = {cx + 10.0f, 0.0f, 10.0f}, x = -1, y = -1, z = -1;
        CHECK(ssg_lightmap_project(&f[0], 64, corner, &x, &y, &z));
        CHECK_NEAR(x, 56.0f, 1e-3);
        CHECK_NEAR(y, 8.0f, 1e-3);
    }
    ssg_scene_destroy(&s);
}

static void test_fit_view(void)
{
    fit_case("camera(position=[0, 10, 0], target=[0, 0, 0], up=[0, 0, -1], fov=90, "
             "near=1, far=20)", 0.0f, 0.0f, 1);
    fit_case("camera(position=[3, 10, 0], target=[3, 0, 0], up=[0, 0, -1], fov=90, "
             "near=1, far=20)", 3.0f, 0.0f, 1);
    fit_case("camera(position=[0, 10, 0], target=[0, 0, 0], up=[1, 0, -1], fov=90, "
             "near=1, far=20)", 0.0f, (float)(M_PI / 4), 1);
    fit_case("camera(position=[0, 10, 0], target=[0, 20, 0], up=[0, 0, -1], fov=90, "
             "near=1, far=5)", 0.0f, 0.0f, 0);
}

int main(void)
{
    test_fit_view();
    const char *base = "camera(position=[0, 2, 3], target=[0, 0, 0])\n"
                       "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n";
    char text[400];
    snprintf(text, sizeof text, "%spoint_light(position=[0.5, 1, -0.25])\n", base);
    struct ssg_scene *s = scene_from_text("lm_cube_faces", text);
    if (s)
        test_cube_faces(s);
    ssg_scene_destroy(&s);
    snprintf(text, sizeof text, "%sdirectional_light(direction=[0.3, -1, 0.2])\n", base);
    s = scene_from_text("lm_ortho_face", text);
    if (s)
        test_ortho_face(s);
    ssg_scene_destroy(&s);
    return check_report();
}
