/* test_gl_ssao.c - CPU/GL parity of `ssao` (gl_parity.h) on G-buffers ray-cast from planes
 * (planes.h): every mode and range check, with and without the rotation tile, the depth
 * input, the count input (with values below 1, above the kernel, fractions and NaN),
 * max_screen_radius, power, non-unit normals, background pixels and a subsampled frame;
 * and every mode with a tile of length offsets (halton lengths=shifted).
 *
 * Where differences come from: the shader does the CPU's operations in its order without
 * fused multiply-adds (`precise`), and takes the per-run factors (1 / K, the cap over f)
 * from the same C expressions, so on llvmpipe the only difference is GLSL's pow against
 * powf (cases with power != 1: a few ulp). Non-unit normals are normalised per pixel here,
 * per chunk of 128 pixels on the CPU (all of a chunk once one is not unit): where a chunk
 * mixes both, its unit normals may move by an ulp there and not here. A GPU whose division
 * or sqrt rounds otherwise than C's can put a sample's projection on the neighbouring pixel
 * and flip that one sample's test (1 / K of a pixel's value, more with a small count). */
#include <math.h>

#include "check.h"
#include "planes.h"
#include "gl_parity.h" /* after planes.h: its G-buffer helpers */

/* Binds position, normal (unless `opt` has "n"), kernel, then the optional inputs asked
   for in `opt` ("r" rotation, "d" depth, "c" count, "2" the non-unit normals). */
static int bind(const struct parity_inputs *in, const char *opt, struct ssg_binding *b)
{
    const struct ssg_image *normal = strchr(opt, '2') ? in->nrm2 : in->g.nrm;
    const struct parity_input t[] = {
        {0, "position", in->g.pos},
        {0, "normal", strchr(opt, 'n') ? NULL : normal},
        {0, "kernel", in->kernel},
        {'r', "rotation", in->rot},
        {'d', "depth", in->g.depth},
        {'c', "count", in->count},
    };
    return parity_bind(t, 6, opt, b);
}

static void run_case(const struct parity_inputs *in, const char *label, const char *opt,
                     const char *const *sets, int set_count, const struct ssg_frame *f,
                     struct parity_tol tol)
{
    struct ssg_binding b[6];
    int n = bind(in, opt, b);
    parity_node(label, "ssao", b, n, sets, set_count, f, tol);
    parity_check_darkens("ssao", &in->g, b, n, sets, set_count, f);
}

/* The inputs on scene_fn's planes, halton's kernel and tile made with hsets. */
static void load_inputs_with(struct parity_inputs *in, void (*scene_fn)(struct scene *),
                             const char *const *hsets, int hcount)
{
    *in = (struct parity_inputs){0};
    struct ssg_frame f = frame();
    parity_cast(scene_fn, &in->g);
    parity_halton(&f, hsets, hcount, &in->kernel, &in->rot);
    in->count = parity_count_image(W, H, 16);
    in->nrm2 = parity_scaled(in->g.nrm, 2.0f);
}

static void load_inputs(struct parity_inputs *in, void (*scene_fn)(struct scene *))
{
    const char *sets[] = {"count=16"};
    load_inputs_with(in, scene_fn, sets, 1);
}

/* Every mode with each pixel's sample lengths moved by the tile's third plane. */
static void shifted_cases(struct parity_tol tol)
{
    const char *hsets[] = {"count=16", "falloff=1", "lengths=shifted"};
    struct parity_inputs in;
    load_inputs_with(&in, corner_scene, hsets, 3);
    CHECK_EQ(in.rot->channels, 4);
    const char *def[] = {"radius=1.5"};
    run_case(&in, "hemi shifted", "rd", def, 1, NULL, tol);
    const char *sph[] = {"mode=sphere", "radius=1.5", "range_check=hard"};
    run_case(&in, "sphere shifted", "nrc", sph, 3, NULL, tol);
    const char *disc[] = {"mode=disc", "radius=1.5", "power=3"};
    run_case(&in, "disc shifted", "nr", disc, 3, NULL, tol);
    parity_inputs_free(&in);
}

static void hemisphere_cases(const struct parity_inputs *in, struct parity_tol tol)
{
    const char *def[] = {"radius=1.5"};
    run_case(in, "hemi smooth rot", "r", def, 1, NULL, tol);
    const char *none[] = {"mode=hemisphere", "range_check=none", "radius=1.2", "bias=0.01"};
    run_case(in, "hemi none depth", "d", none, 4, NULL, tol);
    const char *hard[] = {"range_check=hard", "power=2", "radius=2", "max_screen_radius=12"};
    run_case(in, "hemi hard rdc cap", "rdc", hard, 4, NULL, tol);
    const char *smooth[] = {"range_check=smooth", "radius=2.5", "power=0.5"};
    run_case(in, "hemi smooth rc nonunit", "rc2", smooth, 3, NULL, tol);
}

static void free_cases(const struct parity_inputs *in, struct parity_tol tol)
{
    const char *sph[] = {"mode=sphere", "radius=1.5"};
    run_case(in, "sphere smooth rot", "r", sph, 2, NULL, tol);
    const char *sph2[] = {"mode=sphere", "range_check=hard", "radius=2",
                          "max_screen_radius=12"};
    run_case(in, "sphere hard dc cap", "ndc", sph2, 4, NULL, tol);
    const char *disc[] = {"mode=disc", "radius=1.5"};
    run_case(in, "disc smooth rot", "nr", disc, 2, NULL, tol);
    const char *disc2[] = {"mode=disc", "range_check=none", "radius=1.2", "power=3"};
    run_case(in, "disc none d", "nd", disc2, 4, NULL, tol);
    const char *disc3[] = {"mode=disc", "range_check=hard", "radius=2",
                           "max_screen_radius=12"};
    run_case(in, "disc hard rdc cap", "nrdc", disc3, 4, NULL, tol);
}

int main(void)
{
    W = 96, H = 72;
    /* The descriptor's bound (ssao.c). Measured on llvmpipe (Mesa): max 1.8e-7, mean
       1.3e-8, all from pow (power != 1); every other case is bit-exact. A GPU whose
       division rounds otherwise may flip single samples (see the file header) and needs
       looser bounds. */
    const struct parity_tol tol = parity_tol_of("ssao");
    struct parity_inputs in;
    load_inputs(&in, corner_scene);
    hemisphere_cases(&in, tol);
    free_cases(&in, tol);
    parity_inputs_free(&in);

    load_inputs(&in, parity_sky_scene);
    hemisphere_cases(&in, tol);
    free_cases(&in, tol);
    struct ssg_frame big = parity_subsampled_frame();
    const char *def[] = {"radius=1.5"};
    run_case(&in, "hemi subsampled", "rd", def, 1, &big, tol);
    parity_inputs_free(&in);
    shifted_cases(tol);
    return check_report();
}
