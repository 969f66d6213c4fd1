/* test_gl_ssao.c - CPU/GL parity of `ssao` (gl_parity.h) on G-buffers ray-cast from planes
 * (planes.h): every mode and range check, with and without the rotation tile, the depth
 * input, the count input (with values below 1, above the kernel, fractions and NaN),
 * max_screen_radius, power, non-unit normals, background pixels and a subsampled frame.
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
#include "gl_parity.h"
#include "planes.h"

/* The corner of planes.h plus, for background pixels, a floor with a wall on its left
   under an open sky. */
static void sky_scene(struct scene *s)
{
    *s = (struct scene){.count = 2};
    plane_at(&s->pl[0], 0, 1, 0.2, 0, -1, -5);  /* floor */
    plane_at(&s->pl[1], 1, 0, 0.3, -1.5, 0, -5); /* wall on the left, facing right */
}

static void halton(const char *count, struct ssg_image **kernel, struct ssg_image **rot)
{
    struct ssg_diags d = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out = {0};
    const char *sets[] = {count};
    CHECK_EQ(ssg_node_run("halton", NULL, 0, sets, 1, &f, &out, &d), SSG_OK);
    *kernel = out.images[0];
    *rot = out.images[1];
}

/* Per-pixel counts over the whole range the node accepts: below 1, fractions (half up),
   above the kernel, NaN. */
static struct ssg_image *count_image(int k)
{
    struct ssg_image *c = ssg_image_create(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float v = (float)((x * 7 + y * 3) % (k + 4)) - 1.5f;
            c->data[y * W + x] = (x + y) % 23 == 0 ? NAN : v;
        }
    return c;
}

struct inputs {
    struct gbuf g;
    struct ssg_image *kernel, *rot, *count, *nrm2; /* nrm2: normals scaled by 2 */
};

/* Binds position, normal (unless `opt` has "n"), kernel, then the optional inputs asked
   for in `opt` ("r" rotation, "d" depth, "c" count, "2" the non-unit normals). */
static int bind(const struct inputs *in, const char *opt, struct ssg_binding *b)
{
    int n = 0;
    b[n++] = (struct ssg_binding){"position", in->g.pos};
    if (!strchr(opt, 'n'))
        b[n++] = (struct ssg_binding){"normal", strchr(opt, '2') ? in->nrm2 : in->g.nrm};
    b[n++] = (struct ssg_binding){"kernel", in->kernel};
    if (strchr(opt, 'r'))
        b[n++] = (struct ssg_binding){"rotation", in->rot};
    if (strchr(opt, 'd'))
        b[n++] = (struct ssg_binding){"depth", in->g.depth};
    if (strchr(opt, 'c'))
        b[n++] = (struct ssg_binding){"count", in->count};
    return n;
}

static void run_case(const struct inputs *in, const char *label, const char *opt,
                     const char *const *sets, int set_count, const struct ssg_frame *f,
                     struct parity_tol tol)
{
    struct ssg_binding b[6];
    int n = bind(in, opt, b);
    parity_node(label, "ssao", b, n, sets, set_count, f, tol);
    /* Parity of images of ones would prove nothing: each case darkens some of its
       surface pixels on the CPU. */
    struct ssg_outputs cpu = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("ssao", b, n, sets, set_count, f, &cpu, &d), SSG_OK);
    int lit, dark = count_not_one(&in->g, cpu.images[0]);
    double mean = mean_over(cpu.images[0], in->g.which, 0, 0, W, H, 0, &lit);
    fprintf(stderr, "    %d of %d not 1, mean %.3f\n", dark, W * H, mean);
    CHECK(dark > W * H / 200);
    ssg_outputs_release(&cpu);
}

static void load_inputs(struct inputs *in, void (*scene_fn)(struct scene *))
{
    struct scene s;
    scene_fn(&s);
    cast(&s, &in->g);
    halton("count=16", &in->kernel, &in->rot);
    in->count = count_image(16);
    in->nrm2 = ssg_image_create(W, H, 3);
    for (size_t i = 0; i < (size_t)W * H * 3; i++)
        in->nrm2->data[i] = 2.0f * in->g.nrm->data[i];
}

static void free_inputs(struct inputs *in)
{
    release(&in->g);
    ssg_image_destroy(&in->kernel);
    ssg_image_destroy(&in->rot);
    ssg_image_destroy(&in->count);
    ssg_image_destroy(&in->nrm2);
}

static void hemisphere_cases(const struct inputs *in, struct parity_tol tol)
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

static void free_cases(const struct inputs *in, struct parity_tol tol)
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
    /* Measured on llvmpipe (Mesa): max 1.8e-7, mean 1.3e-8, all from pow (power != 1);
       every other case is bit-exact. A GPU whose division rounds otherwise may flip
       single samples (see the file header) and needs looser bounds. */
    const struct parity_tol tol = {.border = 0, .max_abs = 5e-7, .mean_abs = 5e-8};
    struct inputs in;
    load_inputs(&in, corner_scene);
    hemisphere_cases(&in, tol);
    free_cases(&in, tol);
    free_inputs(&in);

    load_inputs(&in, sky_scene);
    hemisphere_cases(&in, tol);
    free_cases(&in, tol);
    /* The G-buffer as a 2x subsampled frame: the projection scaled by 2 is the one it
       was cast with. */
    struct ssg_frame big = frame();
    big.width *= 2, big.height *= 2;
    const char *def[] = {"radius=1.5"};
    run_case(&in, "hemi subsampled", "rd", def, 1, &big, tol);
    free_inputs(&in);
    return check_report();
}
