/* test_gl_direct_light.c - CPU/GL parity of `direct_light` on the Cornell box (its own
 * point light, six cube faces, PCF across the faces' edges) and on the same box under a
 * directional light with soft shadows (sun_angle), on the same CPU G-buffer and maps. A
 * tap's 0/1 test flips where the backends round a texel coordinate or a depth apart, so
 * the bound is on the mean, with a loose one on the largest difference (one bilinear tap
 * of 12: 0.1 of the scale). Measured on llvmpipe: max 3e-6, mean 1e-8 of the scale. */
#include <math.h>

#include "check.h"
#include "common/trace.h"
#include "light_maps.h"

enum { W = 96, H = 72 };
static const struct ssg_frame FRAME = {W, H, 40, 0.05f, 20, 1, 0};

static void parity(const char *name, const char *lights, const char *const *sets, int n)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load_lit("examples/cornell.scene", lights, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!s)
        return;
    struct ssg_image *g[SSG_GBUFFER_OUTPUTS], *m[3], *cpu[2], *gl[2];
    gbuffer_of(s, &FRAME, g);
    CHECK_EQ(maps_of(s, &FRAME, 256, SSG_BACKEND_CPU, m), SSG_OK);
    CHECK_EQ(direct_of(s, &FRAME, g, m[0], sets, n, SSG_BACKEND_CPU, cpu), SSG_OK);
    CHECK_EQ(direct_of(s, &FRAME, g, m[0], sets, n, SSG_BACKEND_GL, gl), SSG_OK);
    for (int k = 0; k < 2; k++) {
        double mx = 0, mean = 0, scale = 0;
        size_t count = (size_t)W * H * (size_t)cpu[k]->channels;
        for (size_t i = 0; i < count; i++) {
            double e = fabs((double)cpu[k]->data[i] - gl[k]->data[i]);
            mx = e > mx ? e : mx;
            mean += isfinite(e) ? e : 1e9;
            scale = fmax(scale, fabs(cpu[k]->data[i]));
        }
        mean /= (double)count;
        fprintf(stderr, "parity direct_light %s %-10s max %.3g (tol %.3g) mean %.3g (tol "
                "%.3g)\n", name, k ? "visibility" : "out", mx, 0.1 * scale, mean,
                1e-5 * scale);
        CHECK(mx <= 0.1 * scale);
        CHECK(mean <= 1e-5 * scale);
    }
    images_free(g, SSG_GBUFFER_OUTPUTS);
    images_free(m, 3);
    images_free(cpu, 2);
    images_free(gl, 2);
    ssg_scene_destroy(&s);
}

int main(void)
{
    parity("point", NULL, NULL, 0);
    const char *soft[] = {"sun_angle=2", "samples=16"};
    parity("sun", "examples/lights/sun.scene", soft, 2);
    return check_report();
}
