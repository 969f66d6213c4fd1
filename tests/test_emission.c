/* test_emission.c - emissive surfaces (issue 45), against a closed form:
 * tests/fixtures/emitter.scene's square of radiance 1 at height 0.5 over a floor of albedo
 * 0.5, no lights (the scene's comment works the numbers out).
 * - reference_gi: the floor under the square's centre reflects 0.27706 (the
 *   point-to-square form factor), as its bounce; the square seen directly is its own
 *   radiance in `out`; there is no direct light;
 * - gbuffer's emission (on the CPU and on GL alike) is 1 on the square and 0 elsewhere, and
 *   combine adds it to the frame as it is. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scene_node.h"
#include "scratch.h"
#include "scene/scene.h"
#include "ssgraph.h"

enum { W = 64, H = 48 };

struct frame {
    struct ssg_image *out, *bounce, *direct, *position, *emission, *combined;
    float m[16]; /* the camera's view matrix */
};

static int run(const char *backend, struct frame *f)
{
    char dir[600];
    snprintf(dir, sizeof dir, "%s", tmp_path(backend));
    CHECK_EQ(graph_run_on("tests/fixtures/emitter.graph", NULL, backend, dir), SSG_OK);
    f->out = exr_layer(dir, "emitter.exr", NULL);
    f->bounce = exr_layer(dir, "emitter.exr", "bounce");
    f->direct = exr_layer(dir, "emitter.exr", "direct");
    f->position = exr_layer(dir, "emitter.exr", "position");
    f->emission = exr_layer(dir, "emitter.exr", "emission");
    f->combined = exr_layer(dir, "emitter.exr", "frame");
    scene_view_matrix("tests/fixtures/emitter.scene", f->m);
    return f->out && f->bounce && f->direct && f->position && f->emission && f->combined;
}

static void release(struct frame *f)
{
    ssg_image_destroy(&f->out), ssg_image_destroy(&f->bounce), ssg_image_destroy(&f->direct);
    ssg_image_destroy(&f->position), ssg_image_destroy(&f->emission);
    ssg_image_destroy(&f->combined);
}

static float px(const struct ssg_image *im, int c, size_t i)
{
    return ssg_image_plane(im, c)[i];
}

/* The form factor from a point to a parallel rectangle a x b at distance h, one corner
   straight above the point (Howell's catalogue, C-11):
   F = 1/(2 pi) [X / sqrt(1+X^2) atan(Y / sqrt(1+X^2)) + Y / sqrt(1+Y^2) atan(X / sqrt(1+Y^2))]
   with X = a / h, Y = b / h. */
static double corner_factor(double a, double b, double h)
{
    double x = a / h, y = b / h, sx = sqrt(1 + x * x), sy = sqrt(1 + y * y);
    return (x / sx * atan(y / sx) + y / sy * atan(x / sy)) / (2 * 3.14159265358979);
}

/* The floor's reflected radiance at (x, 0, z) under the square: albedo 0.5 x radiance 1 x
   the form factor of the four rectangles the point's vertical cuts the square into. */
static double floor_radiance(double x, double z)
{
    double f = 0;
    for (int i = 0; i < 4; i++)
        f += corner_factor(0.5 + (i & 1 ? x : -x), 0.5 + (i & 2 ? z : -z), 0.5);
    return 0.5 * f;
}

static void check_truth(const struct frame *f)
{
    double sum = 0, want = 0, direct = 0;
    int n = 0, lamp = 0, lamp_ok = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        float w[3];
        direct = fmax(direct, fabs(px(f->direct, 0, i)));
        if (!pixel_world(f->position, f->m, i, w))
            continue;
        if (fabsf(w[1] - 0.5f) < 1e-3f) { /* the square's underside: its own radiance */
            lamp++;
            lamp_ok += fabsf(px(f->out, 0, i) - 1.0f) < 1e-6f;
        } else if (fabsf(w[1]) < 1e-3f && fabsf(w[0]) < 0.3f && fabsf(w[2]) < 0.3f) {
            sum += px(f->bounce, 0, i);
            want += floor_radiance(w[0], w[2]);
            n++;
        }
    }
    double got = n ? sum / n : 0;
    want = n ? want / n : 0;
    fprintf(stderr, "reference_gi: floor under the square %.5f over %d px (closed form %.5f; "
            "at the centre %.5f), "
            "square seen directly %d/%d px at 1, largest direct %.3g\n", got, n, want,
            floor_radiance(0, 0),
            lamp_ok, lamp, direct);
    CHECK(n >= 20 && lamp >= 20);
    CHECK_NEAR(floor_radiance(0, 0), 0.27706, 1e-5); /* the scene comment's number */
    CHECK_NEAR(got, want, 0.01 * want);
    CHECK_EQ(lamp_ok, lamp);
    CHECK_NEAR(direct, 0, 0);
}

/* The G-buffer's emission: 1 on the square, 0 elsewhere; the frame adds it. */
static void check_gbuffer(const char *backend, const struct frame *f)
{
    int bad = 0, lamp = 0;
    for (size_t i = 0; i < (size_t)W * H; i++) {
        float w[3];
        int on = pixel_world(f->position, f->m, i, w) && fabsf(w[1] - 0.5f) < 1e-3f;
        lamp += on;
        for (int c = 0; c < 3; c++) {
            bad += px(f->emission, c, i) != (on ? 1.0f : 0.0f);
            bad += on && px(f->combined, c, i) != 1.0f;
        }
    }
    fprintf(stderr, "%s: gbuffer.emission on %d square px, %d values off\n", backend, lamp, bad);
    CHECK(lamp >= 20);
    CHECK_EQ(bad, 0);
}

int main(void)
{
    setup_tmp("emission");
    struct frame cpu = {0}, gl = {0};
    if (run("cpu", &cpu)) {
        check_truth(&cpu);
        check_gbuffer("cpu", &cpu);
    }
    if (run("gl", &gl))
        check_gbuffer("gl", &gl);
    release(&cpu);
    release(&gl);
    return check_report();
}
