/* test_gl_direct_light.c - CPU/GL parity of `direct_light` on the Cornell box (its own
 * point light, six cube faces, PCF across the faces' edges) and on the same box under a
 * directional light with soft shadows (sun_angle), on the same CPU G-buffer and maps,
 * and both with contact shadows, within the descriptor's bound (gl_parity.h): 4x what these cases measure on llvmpipe,
 * max 5.1e-6 (the sun's soft visibility), mean 1.1e-8. A tap's 0/1 test would flip where
 * the backends round a texel coordinate or a depth apart (one bilinear tap of 12: up to
 * 0.08 of a pixel's light); none does on llvmpipe, and a driver where some do needs a
 * bound of its own. */
#include <math.h>

#include "check.h"
#include "common/trace.h"
#include "gl_parity.h"
#include "light_maps.h"

enum { W = 96, H = 72 };
static const struct ssg_frame FRAME = {W, H, 40, 0.05f, 20, 1, 0, 0, 0};

static void parity(const char *name, const char *lights, const char *const *sets, int n,
                   const char *fit, int res)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load_lit("examples/cornell.scene", lights, 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!s)
        return;
    struct ssg_image *g[SSG_GBUFFER_OUTPUTS], *m[3], *cpu[2], *gl[2];
    gbuffer_of(s, &FRAME, g);
    CHECK_EQ(maps_fit(s, &FRAME, res, SSG_LIGHTMAP_OWN_ONLY, fit, SSG_BACKEND_CPU, m), SSG_OK);
    CHECK_EQ(direct_of(s, &FRAME, g, m[0], sets, n, SSG_BACKEND_CPU, cpu), SSG_OK);
    CHECK_EQ(direct_of(s, &FRAME, g, m[0], sets, n, SSG_BACKEND_GL, gl), SSG_OK);
    for (int k = 0; k < 2; k++) {
        double peak = 0; /* the case does light some pixels */
        for (size_t i = 0; i < (size_t)W * H * (size_t)cpu[k]->channels; i++)
            peak = fmax(peak, cpu[k]->data[i]);
        CHECK(peak > 0);
        parity_check_output("direct_light", name, k ? "visibility" : "out", cpu[k], gl[k],
                            parity_tol_of("direct_light"));
    }
    images_free(g, SSG_GBUFFER_OUTPUTS);
    images_free(m, 3);
    images_free(cpu, 2);
    images_free(gl, 2);
    ssg_scene_destroy(&s);
}

int main(void)
{
    parity("point", NULL, NULL, 0, "scene", 256);
    const char *soft[] = {"sun_angle=2", "samples=16"};
    parity("sun", "examples/lights/sun.scene", soft, 2, "scene", 256);
    /* the sun's map fitted to the view, read with the same fit */
    const char *fitted[] = {"fit=view"};
    parity("sun fitted", "examples/lights/sun.scene", fitted, 1, "view", 256);
    /* contact shadows: the march over the G-buffer, the crossing's checks, for the sun
       and the point light, on maps of 64 texels, whose offsets leave lines for the march
       to darken (about 200 of these pixels at 96 x 72; 2 at 256 texels) */
    const char *contact[] = {"fit=view", "contact=8"};
    parity("sun contact", "examples/lights/sun.scene", contact, 2, "view", 64);
    const char *contact_point[] = {"contact=8"};
    parity("point contact", NULL, contact_point, 1, "scene", 64);
    return check_report();
}
