/* test_gl_misc.c - CPU/GL parity (gl_parity.h) of the small nodes `halton`, `complexity`
 * and `combine`.
 *
 * halton: prepare() makes the kernel and the tile on the CPU for both backends and the GL
 * side only copies them, so the outputs must be bit-identical (tolerance 0) for every
 * option (bases, period, mapping, falloff, pattern side, frame seed).
 * complexity: the cell means are summed in double in pixel order with the CPU's
 * expressions and the weights use its float expressions unfused (`precise`), so on
 * llvmpipe, whose float sqrt and division round as C's do, the counts are identical
 * (measured 0), hence tolerance 0. (A GPU with approximate sqrt or division could move a
 * weight lying within an ulp of a level boundary by one level.) Every case but the
 * one-level one must use several levels on the CPU, so no case compares constants.
 * Inputs: the corner (crease), a depth step, an open sky, and a wavy surface with smooth
 * gradients (weights between 0 and 1, so every level boundary is crossed) holding
 * background, infinite-depth and NaN-normal pixels; every scale, 1 to 4 resolutions,
 * level counts 1 to 8, odd sizes and a subsampled G-buffer (projection scaled).
 * combine: one multiply-add per term in the CPU's order, unfused; llvmpipe matches bit for
 * bit (measured 0). Every optional input alone and together, modulation of 1 and 3
 * channels, darken_indirect on and off, ambient and its colour.
 * Each node's bound is its descriptor's (gl_parity.h's parity_tol_of): 0 for all three. */
#include <math.h>

#include "check.h"
#include "planes.h"
#include "gl_parity.h" /* after planes.h: its G-buffer helpers */

/* ---- halton ---- */

static void halton_cases(void)
{
    const struct parity_tol exact = parity_tol_of("halton");
    struct ssg_frame f = {64, 48, 45.0f, 0.05f, 100.0f, 7, 0, 0, 0};
    const char *def[] = {"count=16"};
    parity_node("default seed 7", "halton", NULL, 0, def, 1, &f, exact);
    const char *three[] = {"count=60", "bases=[2, 3, 5]", "period=30", "mapping=uniform",
                           "falloff=1", "pattern=8"};
    parity_node("3 bases period", "halton", NULL, 0, three, 6, &f, exact);
    f.seed = 12345;
    const char *wide[] = {"count=1024", "bases=[5, 7]", "offset=0", "min_scale=0",
                          "falloff=0.5", "pattern=64"};
    parity_node("1024 x 64 seed", "halton", NULL, 0, wide, 6, &f, exact);
    const char *one[] = {"count=1", "pattern=1", "period=0"};
    parity_node("1 x 1", "halton", NULL, 0, one, 3, &f, exact);
    const char *blue[] = {"rotations=blue_noise", "pattern=64"};
    parity_node("blue noise 64", "halton", NULL, 0, blue, 2, &f, exact);
    const char *latin[] = {"rotations=interleaved", "pattern=5"};
    parity_node("interleaved 5", "halton", NULL, 0, latin, 2, &f, exact);
    const char *shifted[] = {"lengths=shifted", "falloff=1", "pattern=8", "period=12",
                             "count=48"};
    parity_node("shifted lengths", "halton", NULL, 0, shifted, 5, &f, exact);
}

/* ---- complexity ---- */

/* Fronto-parallel surfaces at depth 5 left of column 37 (inside a cell at every scale)
   and 6 right of it, normals +z: only the depth term sees the step. */
static void depth_step(struct gbuf *g)
{
    *g = (struct gbuf){NULL, ssg_image_create(W, H, 3), ssg_image_create(W, H, 1), NULL};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            g->depth->data[o] = x < 37 ? 5.0f : 6.0f;
            g->nrm->data[2 * (size_t)W * H + o] = 1.0f;
        }
}

/* A wavy surface with smoothly turning normals (intermediate weights), a background
   corner, and single pixels of infinite depth or NaN normal (not surface). */
static void wavy(struct gbuf *g)
{
    g->depth = ssg_image_create(W, H, 1);
    g->nrm = ssg_image_create(W, H, 3);
    g->pos = NULL;
    g->which = NULL;
    size_t plane = (size_t)W * H;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            double n[3] = {0.6 * sin(0.21 * x), 0.5 * cos(0.17 * y + 0.03 * x), 1.0};
            double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            int sky = x + 2 * y < W / 4;
            g->depth->data[o] = sky ? 0.0f : (float)(4.0 + 0.5 * sin(0.13 * x) * cos(0.09 * y));
            for (int c = 0; c < 3; c++)
                g->nrm->data[c * plane + o] = sky ? 0.0f : (float)(n[c] / len);
            if ((x * 13 + y * 7) % 97 == 0)
                g->depth->data[o] = INFINITY;
            if ((x * 5 + y * 11) % 89 == 0)
                g->nrm->data[o] = NAN;
        }
}

/* Distinct values in a 1-channel image (up to 9 counted). */
static int distinct(const struct ssg_image *im)
{
    float seen[9];
    int n = 0;
    for (size_t i = 0; i < (size_t)im->width * im->height && n < 9; i++) {
        int k = 0;
        while (k < n && seen[k] != im->data[i])
            k++;
        if (k == n)
            seen[n++] = im->data[i];
    }
    return n;
}

/* Parity on g, which is released; the CPU result must use at least `levels` levels, so
   that no case compares two images of one value. */
static void complexity_case(const char *label, struct gbuf *g, const char *const *sets, int n,
                            const struct ssg_frame *f, int levels)
{
    struct ssg_binding b[2] = {{"depth", g->depth}, {"normal", g->nrm}};
    parity_node(label, "complexity", b, 2, sets, n, f, parity_tol_of("complexity"));
    struct ssg_outputs cpu = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("complexity", b, 2, sets, n, f, &cpu, &d), SSG_OK);
    if (cpu.count == 1) {
        fprintf(stderr, "    %d levels used\n", distinct(cpu.images[0]));
        CHECK(distinct(cpu.images[0]) >= levels);
    }
    ssg_outputs_release(&cpu);
    release(g);
}

static void complexity_cases(void)
{
    W = 100, H = 75; /* cells cut at the right and bottom edges for every scale */
    struct ssg_frame f = frame();
    struct gbuf g;
    const char *def[] = {"period=10"};
    parity_cast(corner_scene, &g);
    complexity_case("corner default", &g, def, 1, &f, 2);
    const char *fine[] = {"scale=1", "resolutions=4", "levels=[10, 20]"};
    parity_cast(corner_scene, &g);
    complexity_case("corner s1 r4", &g, fine, 3, &f, 2);
    const char *step[] = {"scale=2", "resolutions=2", "normal_gain=0"};
    depth_step(&g);
    complexity_case("step s2 r2", &g, step, 3, &f, 2);
    const char *sky[] = {"scale=8", "resolutions=3", "levels=[8, 16, 24, 32, 40, 48, 56, 64]",
                         "period=8"};
    parity_cast(parity_sky_scene, &g);
    complexity_case("sky s8 r3 L8", &g, sky, 4, &f, 2);
    const char *soft[] = {"scale=2", "normal_gain=1.3", "depth_gain=3",
                          "levels=[10, 20, 30, 40, 50, 60, 70]"};
    wavy(&g);
    complexity_case("wavy s2 L7", &g, soft, 4, &f, 7);
    const char *coarse[] = {"scale=4", "resolutions=4", "normal_threshold=0.2",
                            "normal_gain=0.5", "depth_threshold=0.005", "depth_gain=2"};
    wavy(&g);
    complexity_case("wavy s4 r4", &g, coarse, 6, &f, 4);
    const char *single[] = {"levels=[30]", "scale=1"};
    wavy(&g);
    complexity_case("wavy one level", &g, single, 2, &f, 1);
    /* Half the frame's size: the projection is the frame's divided by 2 (node.h). */
    W = 64, H = 48;
    struct ssg_frame big = {128, 96, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    wavy(&g);
    complexity_case("wavy subsampled", &g, soft, 4, &big, 7);
    const char *sub[] = {"scale=1", "resolutions=2"};
    parity_cast(corner_scene, &g);
    complexity_case("corner subsampled", &g, sub, 2, &big, 2);
}

/* ---- combine ---- */

static struct ssg_image *noise_image(int w, int h, int channels, unsigned seed, float scale)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (size_t i = 0; i < (size_t)w * h * channels; i++) {
        seed = seed * 1664525u + 1013904223u;
        im->data[i] = scale * (float)(seed >> 8) / 16777216.0f;
    }
    return im;
}

struct combine_inputs {
    struct ssg_image *direct, *albedo, *ao, *indirect, *mod1, *mod3, *env, *far, *irr;
};

/* Binds direct and albedo, then the optional inputs named in `opt`: "a" ao, "i" indirect,
   "m" 1-channel modulation, "M" 3-channel modulation, "e" environment, "f" far_visibility,
   "r" irradiance. */
static int bind_combine(const struct combine_inputs *in, const char *opt, struct ssg_binding *b)
{
    const struct parity_input t[] = {
        {0, "direct", in->direct},
        {0, "albedo", in->albedo},
        {'a', "ambient_occlusion", in->ao},
        {'i', "indirect", in->indirect},
        {'m', "modulation", in->mod1},
        {'M', "modulation", in->mod3},
        {'e', "environment", in->env},
        {'f', "far_visibility", in->far},
        {'r', "irradiance", in->irr},
    };
    return parity_bind(t, 9, opt, b);
}

static void combine_case(const struct combine_inputs *in, const char *label, const char *opt,
                         const char *const *sets, int n)
{
    const struct parity_tol exact = parity_tol_of("combine");
    struct ssg_binding b[9];
    struct ssg_frame f = {W, H, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
    parity_node(label, "combine", b, bind_combine(in, opt, b), sets, n, &f, exact);
}

static void combine_cases(void)
{
    W = 67, H = 45;
    struct combine_inputs in = {
        noise_image(W, H, 3, 1, 2.0f), noise_image(W, H, 3, 2, 1.0f),
        noise_image(W, H, 1, 3, 1.0f), noise_image(W, H, 3, 4, 0.7f),
        noise_image(W, H, 1, 5, 1.2f), noise_image(W, H, 3, 6, 1.2f),
        noise_image(W, H, 3, 7, 1.5f), noise_image(W, H, 1, 8, 1.0f),
        noise_image(W, H, 3, 9, 0.8f)};
    for (int i = 0; i < W; i++) /* some pixels the far field blocks completely */
        in.far->data[W * 7 + i] = 0.0f;
    for (int i = 0; i < W * 5; i++) /* background rows: albedo and light 0 */
        for (int c = 0; c < 3; c++)
            in.direct->data[c * W * H + i] = in.albedo->data[c * W * H + i] = 0.0f;
    const char *none[] = {"ambient=0.3"};
    combine_case(&in, "required only", "", none, 1);
    combine_case(&in, "ao", "a", none, 1);
    combine_case(&in, "indirect", "i", none, 1);
    combine_case(&in, "environment", "e", none, 1);
    combine_case(&in, "mod1 darken", "mi", none, 1);
    const char *light[] = {"ambient=0", "darken_indirect=false"};
    combine_case(&in, "mod3 env ind keep", "Mei", light, 2);
    const char *all[] = {"ambient=1.7", "ambient_color=[0.2, 0.5, 2]"};
    combine_case(&in, "all mod3", "aiMe", all, 2);
    const char *keep[] = {"ambient=2.5", "ambient_color=[1, 0.25, 0]", "darken_indirect=0"};
    combine_case(&in, "all mod1 keep", "aime", keep, 3);
    combine_case(&in, "far mod1", "mief", light, 2);
    const char *far_all[] = {"ambient=0.4", "far_bounce=false"};
    combine_case(&in, "far mod3 ao no far bounce", "aMeif", far_all, 2);
    combine_case(&in, "far alone", "ef", none, 1);
    combine_case(&in, "irradiance ao mod1", "amr", none, 1);
    combine_case(&in, "irradiance far", "aMefr", far_all, 2);
    const char *shadowed[] = {"ambient=0.2", "darken_direct=false"};
    combine_case(&in, "shadowed direct far irradiance", "amefri", shadowed, 2);
    combine_case(&in, "shadowed direct", "mi", shadowed, 2);
    /* the environment as a white receiver's E / pi (probe_light without albedo) */
    const char *white[] = {"ambient=0.3", "environment_albedo=true", "far_bounce=false"};
    combine_case(&in, "environment albedo far irradiance", "amefri", white, 3);
    combine_case(&in, "environment albedo", "ae", white, 3);
    struct ssg_image **im = &in.direct;
    for (int i = 0; i < 9; i++)
        ssg_image_destroy(&im[i]);
}

int main(void)
{
    halton_cases();
    complexity_cases();
    combine_cases();
    return check_report();
}
