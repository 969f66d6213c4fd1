/* test_normal_map.c - tangent-space normal maps (issue 45), against answers worked out by
 * hand:
 * - tests/fixtures/normal_map.scene: a glTF quad facing +y whose normal map tilts its
 *   normal towards +x, under a sun along (-1, -1, 0). The G-buffer's direct light on the
 *   quad is albedo / pi x the cosine of the tilted normal (0.9896, where the quad's own
 *   normal gives 0.7071), and its normal is the tilted one, on the CPU and on GL alike;
 *   with the file's own tangents (normal_map_tangents.scene: TANGENT (0, 0, 1, 1)) the same
 *   map tilts it towards +z instead; a scene file's material with the same map as a PNG
 *   (normal_map_lines.scene, read as data, not sRGB) tilts it as the glTF does;
 * - ssg_mesh_tangents: the quad gets the tangent +x and bitangent sign -1 (cross(n, t) =
 *   -z, and v grows along +z); a plane shape facing +z and a UV sphere get unit tangents
 *   orthogonal to their normals, along the direction their u grows. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "scene_node.h"
#include "scene/scene.h"
#include "scene/scene_shapes.h"
#include "ssgraph.h"

enum { W = 48, H = 48 };
static const double PI = 3.14159265358979323846, HALF_SQRT2 = 0.70710678118654752440;
static char tmp[512];

/* The normal map's texel as stored, (204, 128, 230) / 255, as a tangent-space normal
   (x, y, z), in the world: x t + y b + z n with n = +y and the given t and b. */
static void tilted_normal(const double t[3], const double b[3], double n[3])
{
    const double rgb[3] = {204 / 255.0, 128 / 255.0, 230 / 255.0};
    double m[3] = {2 * rgb[0] - 1, 2 * rgb[1] - 1, 2 * rgb[2] - 1}, w[3];
    for (int i = 0; i < 3; i++)
        w[i] = m[0] * t[i] + m[1] * b[i] + m[2] * (i == 1);
    double len = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    for (int i = 0; i < 3; i++)
        n[i] = w[i] / len;
}

/* The G-buffer of `scene` (normal_map.graph) on `backend`: on every quad pixel the normal of
   the frame (t, b) tilted by the map, and the direct light of that normal. */
static void check_frame(const char *label, const char *scene, const char *backend,
                        const double t[3], const double b[3])
{
    char dir[600], path[700];
    snprintf(dir, sizeof dir, "%s/%s_%s", tmp, label, backend);
    struct ssg_diags d = {0};
    CHECK_EQ(graph_run_on("tests/fixtures/normal_map.graph", scene, backend, dir), SSG_OK);
    snprintf(path, sizeof path, "%s/normal_map.exr", dir);
    struct ssg_image *direct = NULL, *normal = NULL;
    CHECK_EQ(ssg_image_read(path, NULL, &direct, &d), SSG_OK);
    CHECK_EQ(ssg_image_read(path, "normal", &normal, &d), SSG_OK);
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load(scene, 0, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!direct || !normal || !s) {
        ssg_image_destroy(&direct), ssg_image_destroy(&normal), ssg_scene_destroy(&s);
        return;
    }
    double n[3], l[3] = {HALF_SQRT2, HALF_SQRT2, 0};
    tilted_normal(t, b, n);
    double want = 0.5 / PI * (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]);
    float m[16];
    ssg_camera_view_matrix(&s->camera, m);
    int quad = 0, direct_bad = 0, normal_bad = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        float v[3] = {ssg_image_plane(normal, 0)[i], ssg_image_plane(normal, 1)[i],
                      ssg_image_plane(normal, 2)[i]};
        if (v[0] == 0 && v[1] == 0 && v[2] == 0)
            continue; /* background */
        quad++;
        direct_bad += fabs(ssg_image_plane(direct, 0)[i] - want) > 2e-5;
        for (int r = 0; r < 3; r++) /* world = R^T view; column r of R is m[4r..4r+2] */
            normal_bad += fabs(m[4 * r] * v[0] + m[4 * r + 1] * v[1] + m[4 * r + 2] * v[2] -
                               n[r]) > 1e-4;
    }
    fprintf(stderr, "%s %s: %d quad pixels, direct %.6f expected (untilted %.6f): %d off; "
            "normal (%.4f, %.4f, %.4f): %d components off\n", label, backend, quad, want,
            0.5 / PI * HALF_SQRT2, direct_bad, n[0], n[1], n[2], normal_bad);
    CHECK(quad > W * H / 4);
    CHECK_EQ(direct_bad, 0);
    CHECK_EQ(normal_bad, 0);
    ssg_image_destroy(&direct), ssg_image_destroy(&normal);
    ssg_scene_destroy(&s);
}

/* Every vertex's tangent: unit, orthogonal to its normal, w = +-1; returns the worst. */
static double tangent_error(const struct ssg_mesh *m)
{
    double worst = 0;
    for (int v = 0; v < m->vertex_count; v++) {
        const float *t = &m->tangents[4 * v], *n = &m->normals[3 * v];
        double len = sqrt((double)t[0] * t[0] + (double)t[1] * t[1] + (double)t[2] * t[2]);
        worst = fmax(worst, fabs(len - 1));
        worst = fmax(worst, fabs((double)t[0] * n[0] + (double)t[1] * n[1] + (double)t[2] * n[2]));
        worst = fmax(worst, fabs(fabs(t[3]) - 1));
    }
    return worst;
}

static void check_tangents(void)
{
    struct ssg_scene *s = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_scene_load("tests/fixtures/normal_map.scene", 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (s) {
        const struct ssg_mesh *q = &s->meshes[0];
        CHECK(q->tangents != NULL);
        for (int v = 0; q->tangents && v < q->vertex_count; v++) {
            CHECK_NEAR(q->tangents[4 * v], 1, 1e-6);
            CHECK_NEAR(q->tangents[4 * v + 1], 0, 1e-6);
            CHECK_NEAR(q->tangents[4 * v + 2], 0, 1e-6);
            CHECK_NEAR(q->tangents[4 * v + 3], -1, 0);
        }
    }
    ssg_scene_destroy(&s);
    /* a plane facing +z: local x stays x, the local +z (v) turns to -y: t = +x,
       cross(n, t) = cross(z, x) = +y, v grows along -y: w = -1 */
    struct ssg_mesh plane = {0}, sphere = {0};
    const float c[3] = {0, 0, 0}, size[3] = {2, 0, 2}, nz[3] = {0, 0, 1};
    CHECK_EQ(ssg_shape_plane(c, size, nz, &plane), SSG_OK);
    CHECK_EQ(ssg_mesh_tangents(&plane), SSG_OK);
    if (plane.tangents) {
        CHECK_NEAR(plane.tangents[0], 1, 1e-6);
        CHECK_NEAR(plane.tangents[1], 0, 1e-6);
        CHECK_NEAR(plane.tangents[2], 0, 1e-6);
        CHECK_NEAR(plane.tangents[3], -1, 0);
    }
    CHECK_EQ(ssg_shape_sphere(c, 1, 16, &sphere), SSG_OK);
    CHECK_EQ(ssg_mesh_tangents(&sphere), SSG_OK);
    double err = sphere.tangents ? tangent_error(&sphere) : 1;
    fprintf(stderr, "sphere tangents: worst of |len - 1|, |t.n|, ||w| - 1| = %.3g\n", err);
    CHECK(err < 1e-5);
    ssg_mesh_free(&plane);
    ssg_mesh_free(&sphere);
}

/* A normal map must be data a reader gives as stored: anything else is refused, naming it. */
static void check_not_data(void)
{
    const char *bad = "tests/fixtures/garbage.png";
    struct ssg_image *im = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_image_read_data(bad, &im, &d), SSG_E_IMAGE);
    CHECK(im == NULL && d.count > 0 && strstr(d.items[0].file, "garbage.png") != NULL);
}

int main(void)
{
    const char *dir = getenv("SSG_TMP");
    snprintf(tmp, sizeof tmp, "%s", dir && dir[0] ? dir : CHECK_TMP_ROOT "/test_normal_map");
    mkdir(tmp, 0755);
    /* tangents made from the uvs: t = +x, b = +z; from the file's TANGENT: t = +z, b = +x */
    const double x[3] = {1, 0, 0}, z[3] = {0, 0, 1};
    const char *made = "tests/fixtures/normal_map.scene";
    const char *given = "tests/fixtures/normal_map_tangents.scene";
    check_frame("made", made, "cpu", x, z);
    check_frame("made", made, "gl", x, z);
    check_frame("given", given, "cpu", z, x);
    check_frame("given", given, "gl", z, x);
    /* a scene file's material with the same map as a PNG: the plane's uvs give t = +x */
    const char *lines = "tests/fixtures/normal_map_lines.scene";
    check_frame("lines", lines, "cpu", x, z);
    check_frame("lines", lines, "gl", x, z);
    check_not_data();
    check_tangents();
    return check_report();
}
