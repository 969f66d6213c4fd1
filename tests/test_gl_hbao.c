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
#include "gl_parity.h"
#include "planes.h"

/* A floor with a wall on its left under an open sky: background pixels and a crease. */
static void sky_scene(struct scene *s)
{
    *s = (struct scene){.count = 2};
    plane_at(&s->pl[0], 0, 1, 0.2, 0, -1, -5);  /* floor */
    plane_at(&s->pl[1], 1, 0, 0.3, -1.5, 0, -5); /* wall on the left, facing right */
}

static struct ssg_image *rotation_pattern(void)
{
    struct ssg_diags d = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out = {0};
    CHECK_EQ(ssg_node_run("halton", NULL, 0, NULL, 0, &f, &out, &d), SSG_OK);
    ssg_image_destroy(&out.images[0]);
    return out.images[1];
}

/* Per-pixel direction counts over the whole range the node accepts. */
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

struct inputs {
    struct gbuf g;
    struct ssg_image *rot, *count, *nrm2; /* nrm2: normals scaled by 2 */
};

/* Binds position and normal, then the optional inputs asked for in `opt` ("r" rotation,
   "d" depth, "c" count, "2" the non-unit normals). */
static int bind(const struct inputs *in, const char *opt, struct ssg_binding *b)
{
    int n = 0;
    b[n++] = (struct ssg_binding){"position", in->g.pos};
    b[n++] = (struct ssg_binding){"normal", strchr(opt, '2') ? in->nrm2 : in->g.nrm};
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
    struct ssg_binding b[5];
    int n = bind(in, opt, b);
    parity_node(label, "hbao", b, n, sets, set_count, f, tol);
    /* Parity of images of ones would prove nothing: each case darkens some of its
       surface pixels on the CPU. */
    struct ssg_outputs cpu = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("hbao", b, n, sets, set_count, f, &cpu, &d), SSG_OK);
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
    in->rot = rotation_pattern();
    in->count = count_image(8);
    in->nrm2 = ssg_image_create(W, H, 3);
    for (size_t i = 0; i < (size_t)W * H * 3; i++)
        in->nrm2->data[i] = 2.0f * in->g.nrm->data[i];
}

static void free_inputs(struct inputs *in)
{
    release(&in->g);
    ssg_image_destroy(&in->rot);
    ssg_image_destroy(&in->count);
    ssg_image_destroy(&in->nrm2);
}

static void cases(const struct inputs *in, struct parity_tol tol)
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
    /* Measured on llvmpipe (Mesa): 0 in every case; the bounds allow float rounding. */
    const struct parity_tol tol = {.border = 0, .max_abs = 2.4e-7, .mean_abs = 2.4e-8};
    struct inputs in;
    load_inputs(&in, corner_scene);
    cases(&in, tol);
    free_inputs(&in);

    load_inputs(&in, sky_scene);
    cases(&in, tol);
    /* The G-buffer as a 2x subsampled frame: the projection scaled by 2 is the one it
       was cast with. */
    struct ssg_frame big = frame();
    big.width *= 2, big.height *= 2;
    const char *def[] = {"radius=1.5"};
    run_case(&in, "linear subsampled", "rd", def, 1, &big, tol);
    free_inputs(&in);
    return check_report();
}
