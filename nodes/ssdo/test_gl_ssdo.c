/* test_gl_ssdo.c - CPU/GL parity of `ssdo` (gl_parity.h) on G-buffers ray-cast from planes
 * (planes.h): modulation with 1 and 3 channels, radiance, bounce=true, the rotation tile,
 * the depth input, the count input (values below 1, above the kernel, fractions, NaN),
 * max_screen_radius, min_distance, lobes, non-unit normals, background pixels, a
 * subsampled frame and a tile of length offsets (halton lengths=shifted). Without a scene the node sees a constant white environment; the
 * lights and the environment come from a scene (prepare() reads ctx->scene), so those
 * cases load a small scene whose camera is the planes' one (at the origin looking down
 * -z: view space is world space) and run the node's descriptor on both backends with it:
 * a point and a directional light with a coloured constant sky, and the courtyard probe
 * (the environment cube).
 *
 * Where differences come from: the shader does the CPU's operations in its order without
 * fused multiply-adds (`precise`) and takes the per-run factors (the cap over f, the
 * table of 2 pi / n rounded from double) from the same C expressions, so on llvmpipe
 * every case is bit-exact but where GLSL's pow rounds otherwise than powf (power != 1:
 * max 1.8e-7). One known difference the cases avoid: non-unit
 * normals are normalised per pixel here and per chunk of 128 pixels on the CPU (all of a
 * chunk once one is not unit), so where a chunk mixes both, its unit normals may move by
 * an ulp there and not here (the non-unit case scales every normal). The bound (the
 * descriptor's) is a small factor over llvmpipe's; a driver that rounds otherwise, or a
 * GPU whose division or sqrt is not correctly rounded (which can put a sample's
 * projection on the neighbouring pixel and flip that one sample's test, 1 / n of a
 * pixel's sums), needs its own. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "check.h"
#include "graph/exec.h"
#include "graph/gl_backend.h"
#include "planes.h"
#include "gl_parity.h" /* after planes.h: its G-buffer helpers */
#include "scene/scene.h"
#include "scenes.h"
#include "ssdo/ssdo.h"

extern const struct ssg_node_desc ssg_node_ssdo;

/* Binds position, normal, kernel, then the optional inputs asked for in `opt` ("r"
   rotation, "d" depth, "c" count, "a" albedo, "l" light, "2" the non-unit normals), in
   the node's port order. */
static int bind(const struct parity_inputs *in, const char *opt, struct ssg_binding *b)
{
    const struct parity_input t[] = {
        {0, "position", in->g.pos},
        {0, "normal", strchr(opt, '2') ? in->nrm2 : in->g.nrm},
        {0, "kernel", in->kernel},
        {'r', "rotation", in->rot},
        {'d', "depth", in->g.depth},
        {'a', "albedo", in->albedo},
        {'l', "light", in->light},
        {'c', "count", in->count},
    };
    return parity_bind(t, 8, opt, b);
}

/* Parity of one case; the CPU's out must not be flat (not all 1 in modulation, some
   bounce where asked for), or parity would prove nothing. */
static void run_case(const struct parity_inputs *in, const char *label, const char *opt,
                     const char *const *sets, int set_count, const struct ssg_frame *f,
                     struct parity_tol tol)
{
    struct ssg_binding b[8];
    int n = bind(in, opt, b);
    parity_node(label, "ssdo", b, n, sets, set_count, f, tol);
    struct ssg_outputs cpu = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run("ssdo", b, n, sets, set_count, f, &cpu, &d), SSG_OK);
    if (cpu.count != 2)
        return;
    int dark = count_not_one(&in->g, cpu.images[0]), lit = 0, floor;
    for (size_t i = 0; i < (size_t)W * H; i++)
        lit += cpu.images[1]->data[i] > 0.0f;
    double mean = mean_over(cpu.images[0], in->g.which, 0, 0, W, H, 0, &floor);
    fprintf(stderr, "    out: %d of %d not 1, floor mean %.3f; bounce: %d > 0\n", dark,
            W * H, mean, lit);
    CHECK(dark > W * H / 200);
    if (strchr(opt, 'l'))
        CHECK(lit > W * H / 200);
    ssg_outputs_release(&cpu);
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
    in->count = parity_count_image(W, H, 16);
    in->nrm2 = parity_scaled(in->g.nrm, 2.0f);
    in->albedo = parity_colour_field(W, H, 0.2f, 0.6f);
    in->light = parity_colour_field(W, H, 0.5f, 2.0f);
}

static void load_inputs(struct parity_inputs *in, void (*scene_fn)(struct scene *))
{
    load_inputs_as(in, scene_fn, 0);
}

/* The cases without a scene (constant white environment, no lights). */
static void plain_cases(const struct parity_inputs *in, struct parity_tol tol)
{
    const char *def[] = {"radius=1.5"};
    run_case(in, "mod1 rot", "r", def, 1, NULL, tol);
    const char *m3[] = {"channels=3", "radius=1.2", "bias=0.01", "bounce=true",
                        "strength=4", "power=2"};
    run_case(in, "mod3 bounce depth power", "dal", m3, 6, NULL, tol);
    const char *rad[] = {"mode=radiance", "radius=2", "max_screen_radius=12", "bounce=true",
                         "min_distance=0.3"};
    run_case(in, "radiance cap count", "rdcal", rad, 5, NULL, tol);
    const char *cnt[] = {"radius=1.5", "bounce=true", "strength=2", "power=1.5"};
    run_case(in, "mod1 count bounce power", "rcal", cnt, 4, NULL, tol);
    const char *nu[] = {"channels=3", "radius=2.5"};
    run_case(in, "mod3 nonunit", "r2", nu, 2, NULL, tol);
}

/* ---- Lights and environment: a scene's, through the node's descriptor. ---- */

/* A scene whose camera is the planes' (view space = world space) with the given light
   lines; one far plane, since the lights and environment are all prepare() reads. Written
   to $SSG_TMP/gl_ssdo.scene by scenes.h; an unwritable file fails a CHECK too. */
static struct ssg_scene *load_scene(const char *lights)
{
    char text[1200];
    snprintf(text, sizeof text,
             "camera(position=[0, 0, 0], target=[0, 0, -1], up=[0, 1, 0], fov=45, "
             "near=0.05, far=100)\n"
             "plane(center=[0, 0, -50], normal=[0, 0, 1], size=[1, 0, 1])\n%s",
             lights);
    struct ssg_scene *s = scene_from_text("gl_ssdo", text);
    CHECK(s != NULL);
    return s;
}

/* Runs the node on one backend with the scene (what ssg_node_run does, which has none). */
static enum ssg_err run_with_scene(const struct ssg_scene *scene, const struct ssg_io *io,
                                   const void *params, enum ssg_backend backend)
{
    struct ssg_frame fr = frame();
    struct ssg_diags d = {0};
    struct ssg_node_ctx ctx = {.desc = &ssg_node_ssdo, .instance = "ssdo", .frame = &fr,
                               .scene = scene, .out_dir = ".", .diags = &d};
    struct ssg_io_shapes shapes;
    ssg_io_shapes_of(&ssg_node_ssdo, io, &shapes);
    ssg_node_ctx_set_shapes(&ctx, &shapes);
    struct ssg_node_timing t;
    enum ssg_err e = SSG_OK;
    if (backend == SSG_BACKEND_GL && (e = ssg_gl_open(&d))) {
        ssg_diags_print(&d, stderr);
        return e;
    }
    e = ssg_node_execute(&ssg_node_ssdo, &ctx, params, io, backend, &t);
    if (backend == SSG_BACKEND_GL) {
        double ms = 0;
        for (int i = 0; i < 2 && !e; i++)
            e = ssg_gl_to_cpu(io->out[i], &ms, &d);
        for (int i = 0; i < 2; i++)
            ssg_gl_image_free(io->out[i]);
        for (int i = 0; i < ssg_node_ssdo.input_count; i++)
            if (io->in[i])
                ssg_gl_image_free((struct ssg_image *)io->in[i]);
        ssg_gl_close();
    }
    ssg_diags_print(&d, stderr);
    return e;
}

/* ssdo's parameters: the defaults, then `sets` (owned by the caller, free()). */
static void *ssdo_params(const char *const *sets, int set_count)
{
    void *params = calloc(1, ssg_node_ssdo.params_size);
    ssg_params_defaults(ssg_node_ssdo.params, params);
    struct ssg_diags d = {0};
    for (int i = 0; i < set_count; i++)
        CHECK_EQ(ssg_param_set_text(ssg_node_ssdo.params, params, sets[i], "<test>", "ssdo",
                                    &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    return params;
}

/* One case with a scene: params from `sets`, inputs from `opt` as bind() reads it. */
static void scene_case(const struct parity_inputs *in, const struct ssg_scene *scene,
                       const char *label, const char *opt, const char *const *sets,
                       int set_count, struct parity_tol tol)
{
    struct ssg_binding b[8];
    int n = bind(in, opt, b);
    const struct ssg_image *ins[8] = {0};
    for (int i = 0; i < n; i++)
        ins[ssg_port_find(ssg_node_ssdo.inputs, ssg_node_ssdo.input_count, b[i].port,
                          strlen(b[i].port))] = b[i].image;
    void *params = ssdo_params(sets, set_count);
    const struct ssg_ssdo_params *sp = params;
    const int ch = sp->mode == SSG_SSDO_MODE_RADIANCE || sp->channels == 3 ? 3 : 1;
    struct ssg_image *cpu[2] = {ssg_image_create(W, H, ch), ssg_image_create(W, H, 3)};
    struct ssg_image *gl[2] = {ssg_image_create(W, H, ch), ssg_image_create(W, H, 3)};
    struct ssg_io io_cpu = {.in = ins, .out = cpu}, io_gl = {.in = ins, .out = gl};
    CHECK_EQ(run_with_scene(scene, &io_cpu, params, SSG_BACKEND_CPU), SSG_OK);
    CHECK_EQ(run_with_scene(scene, &io_gl, params, SSG_BACKEND_GL), SSG_OK);
    parity_check_output("ssdo", label, "out", cpu[0], gl[0], tol);
    parity_check_output("ssdo", label, "bounce", cpu[1], gl[1], tol);
    int dark = count_not_one(&in->g, cpu[0]);
    fprintf(stderr, "    out: %d of %d not 1\n", dark, W * H);
    CHECK(dark > W * H / 200);
    for (int i = 0; i < 2; i++) {
        ssg_image_destroy(&cpu[i]);
        ssg_image_destroy(&gl[i]);
    }
    free(params);
}

static void scene_cases(const struct parity_inputs *in, struct parity_tol tol)
{
    struct ssg_scene *lights = load_scene(
        "point_light(position=[1, 2, -3], color=[1, 0.8, 0.6], intensity=5)\n"
        "directional_light(direction=[-0.5, -1, -0.3], color=[0.5, 0.6, 1], intensity=1)\n"
        "environment(color=[0.6, 0.7, 0.9], intensity=0.4)\n");
    if (lights) {
        const char *m1[] = {"radius=1.5"};
        scene_case(in, lights, "mod1 lights rot", "r", m1, 1, tol);
        const char *m3[] = {"channels=3", "radius=1.5", "lobe=13", "bounce=true"};
        scene_case(in, lights, "mod3 lights lobe13", "rdal", m3, 4, tol);
        const char *rc[] = {"mode=radiance", "radius=2", "lobe=1"};
        scene_case(in, lights, "radiance lights count", "rca", rc, 3, tol);
    }
    ssg_scene_destroy(&lights);
    char cwd[400], text[800]; /* the probe by absolute path: the scene is in $SSG_TMP */
    if (!getcwd(cwd, sizeof cwd))
        cwd[0] = '\0';
    snprintf(text, sizeof text,
             "point_light(position=[-1, 1, -2], color=[1, 1, 1], intensity=3)\n"
             "environment(image=\"%s/examples/probes/courtyard.exr\", intensity=1)\n", cwd);
    struct ssg_scene *cube = load_scene(text);
    if (cube) {
        const char *m3[] = {"channels=3", "radius=1.5"};
        scene_case(in, cube, "mod3 cube rot", "r", m3, 2, tol);
        const char *m1[] = {"radius=2", "bounce=true", "lobe=64"};
        scene_case(in, cube, "mod1 cube count", "rcdal", m1, 3, tol);
        const char *rad[] = {"mode=radiance", "radius=1.5"};
        scene_case(in, cube, "radiance cube", "ra", rad, 2, tol);
    }
    ssg_scene_destroy(&cube);
}

int main(void)
{
    W = 96, H = 72;
    /* The descriptor's bound (ssdo.c): 4x what these cases measure on llvmpipe, max
       1.8e-7, mean 1.5e-8, from pow (power != 1); the rest is bit-exact. */
    const struct parity_tol tol = parity_tol_of("ssdo");
    struct parity_inputs in;
    load_inputs(&in, corner_scene);
    plain_cases(&in, tol);
    scene_cases(&in, tol);
    parity_inputs_free(&in);

    load_inputs(&in, parity_sky_scene);
    plain_cases(&in, tol);
    scene_cases(&in, tol);
    struct ssg_frame big = parity_subsampled_frame();
    const char *def[] = {"radius=1.5", "bounce=true"};
    run_case(&in, "mod1 subsampled", "rdal", def, 2, &big, tol);
    parity_inputs_free(&in);

    /* Each pixel's sample lengths moved by the tile's third plane. */
    load_inputs_as(&in, corner_scene, 1);
    CHECK_EQ(in.rot->channels, 4);
    plain_cases(&in, tol);
    parity_inputs_free(&in);
    return check_report();
}
