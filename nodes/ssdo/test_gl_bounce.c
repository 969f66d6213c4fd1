/* test_gl_bounce.c - CPU/GL parity of `bounce` (gl_parity.h) on G-buffers ray-cast from
 * planes (planes.h): with and without the rotation tile and the depth input,
 * max_screen_radius, min_distance (automatic and given), strength, background pixels, a
 * subsampled frame and a tile of length offsets (halton lengths=shifted); and, as on the CPU, bounce's GL output is exactly ssdo's GL bounce
 * output for the same inputs (both run ssdo.glsl's sampling).
 *
 * Where differences come from: the shader does ssdo_sampling.h's operations in its order
 * without fused multiply-adds (`precise`), the per-run factors from the same C
 * expressions: bit-exact on llvmpipe. A GPU whose division or sqrt rounds otherwise than
 * C's can put a sample's projection on the neighbouring pixel and flip that one sample's
 * occlusion (one sender more or less), and needs looser bounds. */
#include <string.h>

#include "check.h"
#include "planes.h"
#include "gl_parity.h" /* after planes.h: its G-buffer helpers */

/* Binds the required inputs, then "r" rotation and "d" depth when `opt` has them. */
static int bind(const struct parity_inputs *in, const char *opt, struct ssg_binding *b)
{
    const struct parity_input t[] = {
        {0, "position", in->g.pos},
        {0, "normal", in->g.nrm},
        {0, "kernel", in->kernel},
        {0, "albedo", in->albedo},
        {0, "light", in->light},
        {'r', "rotation", in->rot},
        {'d', "depth", in->g.depth},
    };
    return parity_bind(t, 7, opt, b);
}

/* Parity of one case; the CPU's bounce must reach some pixels, and bounce on GL must be
   ssdo's bounce output on GL, bit for bit. */
static void run_case(const struct parity_inputs *in, const char *label, const char *opt,
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

/* The inputs on scene_fn's planes; with `shifted` halton's tile carries length offsets
   (lengths=shifted, which needs falloff=1). */
static void load_inputs_as(struct parity_inputs *in, void (*scene_fn)(struct scene *),
                           int shifted)
{
    *in = (struct parity_inputs){0};
    struct ssg_frame f = frame();
    const char *sets[] = {"count=16", "mapping=uniform", "falloff=1", "lengths=shifted"};
    parity_cast(scene_fn, &in->g);
    parity_halton(&f, sets, shifted ? 4 : 2, &in->kernel, &in->rot);
    in->albedo = parity_colour_field(W, H, 0.2f, 0.6f);
    in->light = parity_colour_field(W, H, 0.5f, 2.0f);
}

static void load_inputs(struct parity_inputs *in, void (*scene_fn)(struct scene *))
{
    load_inputs_as(in, scene_fn, 0);
}

static void cases(const struct parity_inputs *in, struct parity_tol tol)
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
    W = 96, H = 72;
    /* The descriptor's bound (ssdo/bounce.c): 0, as measured on llvmpipe in every case;
       a driver that rounds otherwise needs its own (file header). */
    const struct parity_tol tol = parity_tol_of("bounce");
    struct parity_inputs in;
    load_inputs(&in, corner_scene);
    cases(&in, tol);
    parity_inputs_free(&in);
    load_inputs(&in, parity_sky_scene);
    cases(&in, tol);
    struct ssg_frame big = parity_subsampled_frame();
    const char *def[] = {"radius=1.5", "strength=2"};
    run_case(&in, "subsampled", "rd", def, 2, &big, tol);
    parity_inputs_free(&in);
    load_inputs_as(&in, corner_scene, 1); /* sample lengths moved per pixel */
    CHECK_EQ(in.rot->channels, 4);
    cases(&in, tol);
    parity_inputs_free(&in);
    return check_report();
}
