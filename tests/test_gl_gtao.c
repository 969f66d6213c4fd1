/* test_gl_gtao.c - CPU/GL parity of `gtao` (gl_parity.h) on G-buffers ray-cast from planes
 * (planes.h): both outputs, with and without the rotation tile and the depth input, hard
 * and faded falloff, thickness, power, max_screen_radius, odd slice counts, non-unit
 * normals, background pixels and a subsampled frame.
 *
 * Where differences come from: the shader does the CPU's operations in its order without
 * fused multiply-adds (`precise`) and reads the per-column basis, slice table and falloff
 * factors prepare() made, so the march (which samples, which horizons) is the same; the
 * transcendental functions (atan, acos, cos, sin) of llvmpipe need not round as the C
 * library's do, which moves the inner integral by a few ulps of its terms. */
#include <math.h>

#include "check.h"
#include "planes.h"
#include "gl_parity.h" /* after planes.h: its G-buffer helpers */

static void run_case(const struct parity_inputs *in, const char *label, const char *opt,
                     const char *const *sets, int set_count, const struct ssg_frame *f,
                     struct parity_tol tol)
{
    const struct parity_input t[] = {
        {0, "position", in->g.pos},
        {0, "normal", strchr(opt, '2') ? in->nrm2 : in->g.nrm},
        {'r', "rotation", in->rot},
        {'d', "depth", in->g.depth},
    };
    struct ssg_binding b[4];
    int n = parity_bind(t, 4, opt, b);
    parity_node(label, "gtao", b, n, sets, set_count, f, tol);
    parity_check_darkens("gtao", &in->g, b, n, sets, set_count, f);
}

static void load_inputs(struct parity_inputs *in, void (*scene_fn)(struct scene *))
{
    *in = (struct parity_inputs){0};
    struct ssg_frame f = frame();
    parity_cast(scene_fn, &in->g);
    parity_halton(&f, NULL, 0, NULL, &in->rot);
    in->nrm2 = parity_scaled(in->g.nrm, 2.0f);
}

static void cases(const struct parity_inputs *in, struct parity_tol tol)
{
    const char *def[] = {"radius=1.5"};
    run_case(in, "default rd", "rd", def, 1, NULL, tol);
    const char *fall[] = {"slices=3", "steps=6", "radius=1.2", "falloff=0.5"};
    run_case(in, "3x6 falloff d", "d", fall, 4, NULL, tol);
    const char *thick[] = {"slices=5", "radius=1.5", "thickness=0.4", "power=2"};
    run_case(in, "5 thick power r2", "r2", thick, 4, NULL, tol);
    const char *cap[] = {"slices=8", "steps=12", "radius=2", "max_screen_radius=20"};
    run_case(in, "8x12 cap r", "r", cap, 4, NULL, tol);
}

int main(void)
{
    W = 96, H = 72;
    /* Measured on llvmpipe (Mesa 22.3): max 9.5e-5, mean 1.9e-5 over these cases (the
       transcendental functions); the descriptor states max 2e-4. */
    const struct parity_tol tol = {.border = 0, .max_abs = 2e-4, .mean_abs = 4e-5};
    struct parity_inputs in;
    load_inputs(&in, corner_scene);
    cases(&in, tol);
    parity_inputs_free(&in);

    load_inputs(&in, parity_sky_scene);
    cases(&in, tol);
    struct ssg_frame big = parity_subsampled_frame();
    const char *def[] = {"radius=1.5"};
    run_case(&in, "default subsampled", "rd", def, 1, &big, tol);
    parity_inputs_free(&in);
    return check_report();
}
