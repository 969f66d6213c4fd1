/* test_gl_bounce.c - CPU/GL parity of `bounce` (gl_parity.h) on G-buffers ray-cast from
 * planes (planes.h): with and without the rotation tile and the depth input,
 * max_screen_radius, min_distance (automatic and given), strength, background pixels and a
 * subsampled frame; and, as on the CPU, bounce's GL output is exactly ssdo's GL bounce
 * output for the same inputs (both run ssdo.glsl's sampling).
 *
 * Where differences come from: the shader does ssdo_sampling.h's operations in its order
 * without fused multiply-adds (`precise`), the per-run factors from the same C
 * expressions: bit-exact on llvmpipe. A GPU whose division or sqrt rounds otherwise than
 * C's can put a sample's projection on the neighbouring pixel and flip that one sample's
 * occlusion (one sender more or less), and needs looser bounds. */
#include <string.h>

#include "check.h"
#include "gl_parity.h"
#include "planes.h"

/* The corner of planes.h plus, for background pixels, a floor with a wall on its left
   under an open sky. */
static void sky_scene(struct scene *s)
{
    *s = (struct scene){.count = 2};
    plane_at(&s->pl[0], 0, 1, 0.2, 0, -1, -5);   /* floor */
    plane_at(&s->pl[1], 1, 0, 0.3, -1.5, 0, -5); /* wall on the left, facing right */
}

/* A smooth colour field, so that each sender's light and each receiver differ. */
static struct ssg_image *colour_field(float base, float gain)
{
    struct ssg_image *im = ssg_image_create(W, H, 3);
    for (int c = 0; c < 3; c++)
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
                im->data[((size_t)c * H + y) * W + x] =
                    base + gain * (float)((x * (c + 1) + y * (3 - c)) % 17) / 17.0f;
    return im;
}

struct inputs {
    struct gbuf g;
    struct ssg_image *kernel, *rot, *albedo, *light;
};

/* Binds the required inputs, then "r" rotation and "d" depth when `opt` has them. */
static int bind(const struct inputs *in, const char *opt, struct ssg_binding *b)
{
    int n = 0;
    b[n++] = (struct ssg_binding){"position", in->g.pos};
    b[n++] = (struct ssg_binding){"normal", in->g.nrm};
    b[n++] = (struct ssg_binding){"kernel", in->kernel};
    b[n++] = (struct ssg_binding){"albedo", in->albedo};
    b[n++] = (struct ssg_binding){"light", in->light};
    if (strchr(opt, 'r'))
        b[n++] = (struct ssg_binding){"rotation", in->rot};
    if (strchr(opt, 'd'))
        b[n++] = (struct ssg_binding){"depth", in->g.depth};
    return n;
}

/* Parity of one case; the CPU's bounce must reach some pixels, and bounce on GL must be
   ssdo's bounce output on GL, bit for bit. */
static void run_case(const struct inputs *in, const char *label, const char *opt,
                     const char *const *sets, int set_count, const struct ssg_frame *f,
                     struct parity_tol tol)
{
    struct ssg_binding b[7];
    int n = bind(in, opt, b);
    parity_node(label, "bounce", b, n, sets, set_count, f, tol);
    const char *gl_sets[8], *ssdo_sets[8];
    memcpy(gl_sets, sets, sizeof(*sets) * (size_t)set_count);
    memcpy(ssdo_sets, sets, sizeof(*sets) * (size_t)set_count);
    gl_sets[set_count] = "backend=gl";
    ssdo_sets[set_count] = "backend=gl";
    ssdo_sets[set_count + 1] = "bounce=true";
    struct ssg_outputs gl = {0}, ssdo = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("bounce", b, n, gl_sets, set_count + 1, f, &gl, &d), SSG_OK);
    CHECK_EQ(ssg_node_run("ssdo", b, n, ssdo_sets, set_count + 2, f, &ssdo, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (gl.count == 1 && ssdo.count == 2) {
        size_t bytes = sizeof(float) * 3 * (size_t)W * H, lit = 0;
        CHECK(memcmp(gl.images[0]->data, ssdo.images[1]->data, bytes) == 0);
        for (size_t i = 0; i < (size_t)W * H; i++)
            lit += gl.images[0]->data[i] > 0.0f;
        int floor;
        double mean = mean_over(gl.images[0], in->g.which, 0, 0, W, H, 0, &floor);
        fprintf(stderr, "    %zu of %d pixels receive a bounce, floor mean %.4f\n", lit,
                W * H, mean);
        CHECK(lit > (size_t)W * H / 200);
    }
    ssg_outputs_release(&gl);
    ssg_outputs_release(&ssdo);
}

static void load_inputs(struct inputs *in, void (*scene_fn)(struct scene *))
{
    struct scene s;
    scene_fn(&s);
    cast(&s, &in->g);
    struct ssg_diags d = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out = {0};
    const char *sets[] = {"count=16", "mapping=uniform"};
    CHECK_EQ(ssg_node_run("halton", NULL, 0, sets, 2, &f, &out, &d), SSG_OK);
    in->kernel = out.images[0];
    in->rot = out.images[1];
    in->albedo = colour_field(0.2f, 0.6f);
    in->light = colour_field(0.5f, 2.0f);
}

static void free_inputs(struct inputs *in)
{
    release(&in->g);
    ssg_image_destroy(&in->kernel);
    ssg_image_destroy(&in->rot);
    ssg_image_destroy(&in->albedo);
    ssg_image_destroy(&in->light);
}

static void cases(const struct inputs *in, struct parity_tol tol)
{
    const char *def[] = {"radius=1.5"};
    run_case(in, "rot", "r", def, 1, NULL, tol);
    const char *dep[] = {"radius=1.2", "bias=0.01", "strength=4"};
    run_case(in, "depth strength", "d", dep, 3, NULL, tol);
    const char *cap[] = {"radius=2", "max_screen_radius=12", "min_distance=0.3"};
    run_case(in, "rot depth cap min_dist", "rd", cap, 3, NULL, tol);
}

int main(void)
{
    (void)count_not_one; /* planes.h's test of AO outputs; a bounce is no factor */
    W = 96, H = 72;
    /* Measured on llvmpipe (Mesa): bit-exact (max 0) in every case; the bounds leave
       room for a few ulp of a driver that rounds otherwise (file header). */
    const struct parity_tol tol = {.border = 0, .max_abs = 1e-6, .mean_abs = 1e-7};
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
    const char *def[] = {"radius=1.5", "strength=2"};
    run_case(&in, "subsampled", "rd", def, 2, &big, tol);
    free_inputs(&in);
    return check_report();
}
