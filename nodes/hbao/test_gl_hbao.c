/* test_gl_hbao.c - CPU/GL parity of `hbao` (gl_parity.h) on G-buffers ray-cast from planes
 * (planes.h): both falloffs, even (paired) and odd numbers of directions, with and without
 * the rotation tile, the depth input and the count input (values below 1, above the
 * number of directions, fractions and NaN), max_screen_radius, strength, bias 0,
 * non-unit normals, background pixels and a subsampled frame.
 *
 * Where differences come from: the shader does the CPU's operations in its order without
 * fused multiply-adds (`precise`) and gets the per-column basis and the per-run factors
 * from the same C code, so on llvmpipe it is bit-exact. What could differ elsewhere: the
 * step jitter's angle is a float atan in GLSL (double on the CPU), and a GPU's division
 * and sqrt need not round as C's do; a step's rounding to a pixel can then land on the
 * neighbouring pixel and change that pixel's horizon in one direction. */
#include <math.h>

#include "check.h"
#include "planes.h"
#include "gl_parity.h" /* after planes.h: its G-buffer helpers */

/* Per-pixel direction counts over the whole range the node accepts (a pattern of its own,
   not gl_parity.h's: hbao's counts are directions, kept as they were measured). */
static struct ssg_image *count_image(int nd)
{
    struct ssg_image *c = ssg_image_create(W, H, 1);
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float v = (float)((x * 5 + y * 3) % (nd + 4)) - 1.5f;
            c->data[y * W + x] = (x + 2 * y) % 19 == 0 ? NAN : v;
        }
    return c;
}

/* Binds position and normal, then the optional inputs asked for in `opt` ("r" rotation,
   "d" depth, "c" count, "2" the non-unit normals). */
static int bind(const struct parity_inputs *in, const char *opt, struct ssg_binding *b)
{
    const struct parity_input t[] = {
        {0, "position", in->g.pos},
        {0, "normal", strchr(opt, '2') ? in->nrm2 : in->g.nrm},
        {'r', "rotation", in->rot},
        {'d', "depth", in->g.depth},
        {'c', "count", in->count},
    };
    return parity_bind(t, 5, opt, b);
}

static void run_case(const struct parity_inputs *in, const char *label, const char *opt,
                     const char *const *sets, int set_count, const struct ssg_frame *f,
                     struct parity_tol tol)
{
    struct ssg_binding b[5];
    int n = bind(in, opt, b);
    parity_node(label, "hbao", b, n, sets, set_count, f, tol);
    parity_check_darkens("hbao", &in->g, b, n, sets, set_count, f);
}

static void load_inputs(struct parity_inputs *in, void (*scene_fn)(struct scene *))
{
    *in = (struct parity_inputs){0};
    struct ssg_frame f = frame();
    parity_cast(scene_fn, &in->g);
    parity_halton(&f, NULL, 0, NULL, &in->rot);
    in->count = count_image(8);
    in->nrm2 = parity_scaled(in->g.nrm, 2.0f);
}

static void cases(const struct parity_inputs *in, struct parity_tol tol)
{
    const char *def[] = {"radius=1.5"};
    run_case(in, "linear rot depth", "rd", def, 1, NULL, tol);
    const char *none[] = {"falloff=none", "directions=6", "radius=1.2"};
    run_case(in, "none 6 dirs d", "d", none, 3, NULL, tol);
    const char *odd[] = {"directions=5", "steps=6", "radius=1.5", "strength=2"};
    run_case(in, "linear 5 dirs rc", "rc", odd, 4, NULL, tol);
    const char *cnt[] = {"falloff=none", "radius=2", "bias=0", "max_screen_radius=12"};
    run_case(in, "none rdc cap bias 0", "rdc", cnt, 4, NULL, tol);
    const char *odd2[] = {"falloff=none", "directions=7", "steps=3", "radius=1.5"};
    run_case(in, "none 7 dirs c nonunit", "c2", odd2, 4, NULL, tol);
    const char *many[] = {"directions=16", "steps=8", "radius=2", "max_screen_radius=20"};
    run_case(in, "linear 16x8 rc cap", "rc", many, 4, NULL, tol);
}

int main(void)
{
    W = 96, H = 72;
    /* The descriptor's bound (hbao.c): 0, as measured on llvmpipe in every case. */
    const struct parity_tol tol = parity_tol_of("hbao");
    struct parity_inputs in;
    load_inputs(&in, corner_scene);
    cases(&in, tol);
    parity_inputs_free(&in);

    load_inputs(&in, parity_sky_scene);
    cases(&in, tol);
    struct ssg_frame big = parity_subsampled_frame();
    const char *def[] = {"radius=1.5"};
    run_case(&in, "linear subsampled", "rd", def, 1, &big, tol);
    parity_inputs_free(&in);
    return check_report();
}
