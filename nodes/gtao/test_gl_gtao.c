/* test_gl_gtao.c - CPU/GL parity of `gtao` (gl_parity.h) on G-buffers ray-cast from planes
 * (planes.h): both outputs, with and without the rotation tile and the depth input, hard
 * and faded falloff, thickness, power, max_screen_radius, odd slice counts, non-unit
 * normals, background pixels, a subsampled frame and the back input (a made-up second
 * layer: finite thicknesses of 2 to 20 % of the depth in most 8 x 8 blocks, +inf in
 * every third).
 *
 * Where differences come from: the shader does the CPU's operations in its order without
 * fused multiply-adds (`precise`) and reads the per-column basis, slice table and falloff
 * factors prepare() made, so the march (which samples, which horizons) is the same; the
 * transcendental functions (atan, acos, cos, sin) of llvmpipe need not round as the C
 * library's do, which moves the inner integral by a few ulps of its terms. The shaders' acos
 * itself is checked on its own by test_glsl_acos.c. */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "gl/gl.h"
#include "graph/gl_backend.h"
#include "gtao/gtao.h"
#include "planes.h"
#include "gl_parity.h" /* after planes.h: its G-buffer helpers */

extern const struct ssg_node_desc ssg_node_gtao;

static struct ssg_image *back_layer; /* the back input of the cases that ask for 'b' */

/* A second layer for g: depth times 1.02 to 1.2 by column, +inf in every third 8 x 8
   block, 0 on background (gbuffer's conventions). */
static struct ssg_image *make_back(const struct gbuf *g, int w, int h)
{
    struct ssg_image *b = ssg_image_create(w, h, 1);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t i = (size_t)y * (size_t)w + (size_t)x;
            float d = g->depth->data[i];
            float thick = d * (1.02f + 0.18f * (float)(x % 7) / 6.0f);
            b->data[i] = d > 0.0f ? ((x / 8 + y / 8) % 3 == 0 ? INFINITY : thick) : 0.0f;
        }
    return b;
}

static void run_case(const struct parity_inputs *in, const char *label, const char *opt,
                     const char *const *sets, int set_count, const struct ssg_frame *f,
                     struct parity_tol tol)
{
    const struct parity_input t[] = {
        {0, "position", in->g.pos},
        {0, "normal", strchr(opt, '2') ? in->nrm2 : in->g.nrm},
        {'r', "rotation", in->rot},
        {'d', "depth", in->g.depth},
        {'b', "back", back_layer},
    };
    struct ssg_binding b[5];
    int n = parity_bind(t, 5, opt, b);
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
    run_case(in, "default back rdb", "rdb", def, 1, NULL, tol);
    run_case(in, "3x6 falloff back db", "db", fall, 4, NULL, tol);
    /* Per-frame samples (docs/time.md): frame 3's turned slices and shifted noise. */
    const char *f0[] = {"radius=1.5", "frame=0"}, *f3[] = {"radius=1.5", "frame=3"};
    run_case(in, "default rd frame 0", "rd", f0, 2, NULL, tol);
    run_case(in, "default rd frame 3", "rd", f3, 2, NULL, tol);
    const char *fall3[] = {"slices=3", "steps=6", "radius=1.2", "falloff=0.5", "frame=3"};
    run_case(in, "3x6 falloff back db frame 3", "db", fall3, 5, NULL, tol);
}

int main(void)
{
    W = 96, H = 72;
    /* The descriptor's bound (gtao.c): 4x what these cases measure on llvmpipe (max
       3.0e-7, mean 3.3e-8). */
    const struct parity_tol tol = parity_tol_of("gtao");
    struct parity_inputs in;
    load_inputs(&in, corner_scene);
    back_layer = make_back(&in.g, W, H);
    cases(&in, tol);
    ssg_image_destroy(&back_layer);
    parity_inputs_free(&in);

    load_inputs(&in, parity_sky_scene);
    back_layer = make_back(&in.g, W, H);
    cases(&in, tol);
    ssg_image_destroy(&back_layer);
    struct ssg_frame big = parity_subsampled_frame();
    const char *def[] = {"radius=1.5"};
    run_case(&in, "default subsampled", "rd", def, 1, &big, tol);
    parity_inputs_free(&in);
    return check_report();
}
