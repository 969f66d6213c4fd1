/* test_alpha_mask.c - an alpha-masked quad is a surface only where its mask says, to every
 * path that finds surfaces (issue 45's first test): tests/fixtures/alpha_mask.scene's 1 x 1
 * quad at height 0.5, whose texture's alpha covers exactly its x <= 0 half (the scene's
 * comment works it out), over a floor lit straight from above. The graph
 * (tests/fixtures/alpha_mask.graph) runs on the CPU and on GL, and on the CPU once more
 * with the quad opaque (alpha_mask_opaque.scene), and the answers are checked by hand:
 * - the G-buffer: the quad shows on its covered half only (about half the opaque quad's
 *   pixels, none with x > 0), and the floor shows through the other half;
 * - the sun's light map (lightmaps, through direct_light): the floor under the covered
 *   half is in shadow, under the hole fully lit;
 * - reference_ao (Embree's filter functions): at the floor under the quad's middle line
 *   half the rays that the opaque quad stops pass (by symmetry about x = 0);
 * - CPU and GL see the same mask (the same quad pixels, within a few at its edges). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "check.h"
#include "scene_node.h"
#include "scene/scene.h"
#include "ssgraph.h"

enum { W = 96, H = 96 };
static char tmp[512];

/* One run's layers as world-space points and values per pixel. */
struct frame {
    float world[W * H][3]; /* the G-buffer's point, world space; background: NaN */
    float albedo_g[W * H], direct[W * H], ao[W * H];
};

static struct ssg_image *layer(const char *dir, const char *name)
{
    char path[800];
    snprintf(path, sizeof path, "%s/mask.exr", dir);
    struct ssg_diags d = {0};
    struct ssg_image *im = NULL;
    CHECK_EQ(ssg_image_read(path, name, &im, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    CHECK(im && im->width == W && im->height == H);
    return im && im->width == W && im->height == H ? im : NULL;
}

/* Runs the graph into tmp/label and reads it back; view-space positions become world ones
   through the scene's camera (world = R^T (view - t), the view matrix being rigid). */
static int load_frame(const char *label, const char *scene, const char *backend,
                      struct frame *f)
{
    char dir[600];
    snprintf(dir, sizeof dir, "%s/%s", tmp, label);
    CHECK_EQ(graph_run_on("tests/fixtures/alpha_mask.graph", scene, backend, dir), SSG_OK);
    struct ssg_image *pos = layer(dir, "position"), *alb = layer(dir, "albedo");
    struct ssg_image *dl = layer(dir, "direct"), *ao = layer(dir, "ao");
    struct ssg_scene *s = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_scene_load(scene ? scene : "tests/fixtures/alpha_mask.scene", 0, &s, &d),
             SSG_OK);
    int ok = pos && alb && dl && ao && s;
    float m[16];
    if (s)
        ssg_camera_view_matrix(&s->camera, m);
    for (size_t i = 0; ok && i < (size_t)W * H; i++) {
        float v[3], t[3] = {m[12], m[13], m[14]};
        for (int c = 0; c < 3; c++)
            v[c] = ssg_image_plane(pos, c)[i] - t[c];
        int background = ssg_image_plane(alb, 0)[i] == 0.0f && ssg_image_plane(alb, 1)[i] == 0.0f;
        for (int r = 0; r < 3; r++) /* column r of R is (m[4r], m[4r+1], m[4r+2]) */
            f->world[i][r] = background ? NAN
                                        : m[4 * r] * v[0] + m[4 * r + 1] * v[1] + m[4 * r + 2] * v[2];
        f->albedo_g[i] = ssg_image_plane(alb, 1)[i];
        f->direct[i] = ssg_image_plane(dl, 0)[i];
        f->ao[i] = ssg_image_plane(ao, 0)[i];
    }
    ssg_image_destroy(&pos), ssg_image_destroy(&alb), ssg_image_destroy(&dl);
    ssg_image_destroy(&ao);
    ssg_scene_destroy(&s);
    return ok;
}

static int is_quad(const struct frame *f, size_t i)
{
    return fabsf(f->albedo_g[i] - 0.6f) < 1e-3f;
}

static int is_floor(const struct frame *f, size_t i)
{
    return !is_quad(f, i) && fabsf(f->world[i][1]) < 1e-3f;
}

static int quad_pixels(const struct frame *f)
{
    int n = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        n += is_quad(f, i);
    return n;
}

/* Where the eye's ray to floor point p crosses the quad's plane (y = 0.5): x, z. */
static void through_quad(const float p[3], float *x, float *z)
{
    const float eye[3] = {0, 2.2f, 2.2f}, s = (2.2f - 0.5f) / 2.2f;
    *x = eye[0] + s * (p[0] - eye[0]);
    *z = eye[2] + s * (p[2] - eye[2]);
}

/* The G-buffer: the quad only where covered, the floor through the hole. */
static void check_gbuffer(const char *label, const struct frame *f, int opaque_pixels)
{
    int quad = quad_pixels(f), past_mask = 0, through_hole = 0, through_cover = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        past_mask += is_quad(f, i) && f->world[i][0] > 0.01f;
        if (!is_floor(f, i))
            continue;
        float x, z;
        through_quad(f->world[i], &x, &z);
        if (fabsf(z) < 0.45f && fabsf(x) < 0.45f) {
            through_hole += x > 0.03f;
            through_cover += x < -0.03f;
        }
    }
    fprintf(stderr, "%s: quad %d px (opaque %d), quad past x = 0: %d, floor seen through the "
            "hole %d, through the covered half %d\n", label, quad, opaque_pixels, past_mask,
            through_hole, through_cover);
    CHECK(quad >= 0.42 * opaque_pixels && quad <= 0.58 * opaque_pixels);
    CHECK_EQ(past_mask, 0);
    CHECK(through_hole >= 0.3 * quad);
    CHECK_EQ(through_cover, 0);
}

/* The sun's map: shadow under the covered half, full light under the hole. Unshadowed, the
   floor's direct light is albedo x irradiance / pi = 0.8 / pi. */
static void check_shadow(const char *label, const struct frame *f)
{
    const float lit = 0.8f / 3.14159265f;
    int dark = 0, dark_ok = 0, bright = 0, bright_ok = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        const float *p = f->world[i];
        if (!is_floor(f, i) || fabsf(p[0]) > 0.4f || fabsf(p[2]) > 0.4f)
            continue;
        if (p[0] < -0.1f)
            dark++, dark_ok += f->direct[i] < 0.02f * lit;
        else if (p[0] > 0.1f)
            bright++, bright_ok += f->direct[i] > 0.98f * lit;
    }
    fprintf(stderr, "%s: floor under the covered half %d px, %d dark; under the hole %d px, "
            "%d lit\n", label, dark, dark_ok, bright, bright_ok);
    CHECK(dark >= 20 && bright >= 20);
    CHECK_EQ(dark_ok, dark);
    CHECK_EQ(bright_ok, bright);
}

/* reference_ao: on the floor under the quad's middle line (x = 0) the masked quad stops half
   the rays the opaque one stops (the covered half is the mirror image of the hole). */
static void check_ao(const struct frame *masked, const struct frame *opaque)
{
    double occluded_masked = 0, occluded_opaque = 0;
    int n = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        const float *p = masked->world[i];
        if (!is_floor(masked, i) || !is_floor(opaque, i) || fabsf(p[0]) > 0.04f ||
            p[2] < 0.1f || p[2] > 0.35f)
            continue;
        occluded_masked += 1.0 - masked->ao[i];
        occluded_opaque += 1.0 - opaque->ao[i];
        n++;
    }
    double ratio = occluded_opaque > 0 ? occluded_masked / occluded_opaque : 0;
    fprintf(stderr, "reference_ao at x = 0 under the quad (%d px): occluded %.4f masked, "
            "%.4f opaque, ratio %.3f (expected 0.5)\n", n, n ? occluded_masked / n : 0,
            n ? occluded_opaque / n : 0, ratio);
    CHECK(n >= 4);
    CHECK(occluded_opaque / (n ? n : 1) > 0.2);
    CHECK_NEAR(ratio, 0.5, 0.05);
}

/* CPU and GL find the same quad pixels (a few may differ on its edges). */
static void check_parity(const struct frame *cpu, const struct frame *gl)
{
    int differ = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        differ += is_quad(cpu, i) != is_quad(gl, i);
    fprintf(stderr, "CPU and GL: %d quad pixels differ\n", differ);
    CHECK(differ <= 4);
}

int main(void)
{
    const char *dir = getenv("SSG_TMP");
    snprintf(tmp, sizeof tmp, "%s", dir && dir[0] ? dir : CHECK_TMP_ROOT "/test_alpha_mask");
    mkdir(tmp, 0755);
    struct frame *cpu = calloc(1, sizeof *cpu), *gl = calloc(1, sizeof *gl);
    struct frame *opaque = calloc(1, sizeof *opaque);
    if (cpu && gl && opaque && load_frame("cpu", NULL, "cpu", cpu) &&
        load_frame("gl", NULL, "gl", gl) &&
        load_frame("opaque", "tests/fixtures/alpha_mask_opaque.scene", "cpu", opaque)) {
        int full = quad_pixels(opaque);
        check_gbuffer("cpu", cpu, full);
        check_gbuffer("gl", gl, full);
        check_shadow("cpu", cpu);
        check_shadow("gl", gl);
        check_ao(cpu, opaque);
        check_parity(cpu, gl);
    } else {
        CHECK(0);
    }
    free(cpu), free(gl), free(opaque);
    return check_report();
}
