/* test_combine.c - the `combine` node called through its descriptor on tiny images with
 * answers worked out by hand: out = direct + ambient * ambient_color * albedo * ao
 * + indirect, AO missing = 1, indirect missing = 0, background stays 0, the SSDO
 * combinations (modulation, environment, darken_indirect), sizes checked, the same bits
 * for any thread count. */
#include <omp.h>
#include <string.h>

#include "check.h"
#include "combine/combine.h"
#include "graph/exec.h"
#include "lang/diag.h"

extern const struct ssg_node_desc ssg_node_combine;

/* A 3-channel image whose pixel i has value v[c][i] in plane c. */
static struct ssg_image *rgb(int w, int h, const float *r, const float *g, const float *b)
{
    struct ssg_image *im = ssg_image_create(w, h, 3);
    size_t n = (size_t)w * (size_t)h * sizeof(float);
    memcpy(ssg_image_plane(im, 0), r, n);
    memcpy(ssg_image_plane(im, 1), g, n);
    memcpy(ssg_image_plane(im, 2), b, n);
    return im;
}

struct run {
    struct ssg_diags diags;
    struct ssg_frame frame;
    struct ssg_node_ctx ctx;
    const struct ssg_image *in[SSG_COMBINE_INPUTS];
    struct ssg_image *out[1];
    struct ssg_io io;
};

static void run_init(struct run *r, int w, int h)
{
    memset(r, 0, sizeof *r);
    r->frame = (struct ssg_frame){.width = w, .height = h, .fov_y = 45, .near_z = 0.05f,
                                  .far_z = 100, .seed = 1};
    r->ctx = (struct ssg_node_ctx){
        .desc = &ssg_node_combine, .instance = "img", .frame = &r->frame, .diags = &r->diags};
    r->out[0] = ssg_image_create(w, h, 3);
    r->io = (struct ssg_io){.in = r->in, .out = r->out};
}

/* As the executor runs it: shapes read off the bound images and checked by check(), then
   the images verified against them and the kernel run. */
static enum ssg_err run_combine(struct run *r, const struct ssg_combine_params *p)
{
    static struct ssg_io_shapes s;
    char why[256];
    ssg_io_shapes_of(&ssg_node_combine, &r->io, &s);
    enum ssg_err e = ssg_shapes_infer(&ssg_node_combine, p, &r->frame, s.in, s.out, why,
                                      sizeof why);
    if (e) {
        ssg_diag_at(&r->diags, e, (struct ssg_loc){0}, "%s", why);
        return e;
    }
    ssg_node_ctx_set_shapes(&r->ctx, &s);
    struct ssg_node_timing t;
    return ssg_node_execute(&ssg_node_combine, &r->ctx, p, &r->io, SSG_BACKEND_CPU, &t);
}

static void test_descriptor(void)
{
    const struct ssg_node_desc *d = &ssg_node_combine;
    CHECK(strcmp(d->name, "combine") == 0);
    CHECK_EQ(d->input_count, SSG_COMBINE_INPUTS);
    CHECK(strcmp(d->inputs[SSG_COMBINE_IN_DIRECT].name, "direct") == 0);
    CHECK(strcmp(d->inputs[SSG_COMBINE_IN_ALBEDO].name, "albedo") == 0);
    CHECK(strcmp(d->inputs[SSG_COMBINE_IN_AMBIENT_OCCLUSION].name, "ambient_occlusion") == 0);
    CHECK(strcmp(d->inputs[SSG_COMBINE_IN_INDIRECT].name, "indirect") == 0);
    CHECK(!d->inputs[SSG_COMBINE_IN_DIRECT].optional &&
          !d->inputs[SSG_COMBINE_IN_ALBEDO].optional);
    CHECK(d->inputs[SSG_COMBINE_IN_AMBIENT_OCCLUSION].optional &&
          d->inputs[SSG_COMBINE_IN_INDIRECT].optional);
    CHECK_EQ(d->inputs[SSG_COMBINE_IN_AMBIENT_OCCLUSION].types, SSG_T_SCALAR);
    CHECK_EQ(d->output_count, 1);
    CHECK_EQ(d->outputs[0].types, SSG_T_COLOR);
    CHECK_EQ(d->consts_size, sizeof(struct ssg_combine_consts));
    CHECK_EQ(d->params_size, sizeof(struct ssg_combine_params));
    CHECK(d->method && strstr(d->method, "3.1"));

    struct ssg_combine_params p;
    memset(&p, 0xff, sizeof p);
    ssg_params_defaults(d->params, &p);
    CHECK_NEAR(p.ambient, 0.3, 1e-7);
    for (int c = 0; c < 3; c++)
        CHECK_NEAR(p.ambient_color[c], 1.0, 0.0);
    struct ssg_diags diags = {0};
    CHECK_EQ(ssg_param_set_text(d->params, &p, "ambient=2.5", "<test>", "combine", &diags),
             SSG_OK);
    CHECK_NEAR(p.ambient, 2.5, 0.0);
    CHECK_EQ(ssg_param_set_text(d->params, &p, "ambient=11", "<test>", "combine", &diags),
             SSG_E_RANGE);
    CHECK_EQ(ssg_param_set_text(d->params, &p, "ambient_color=[1, 0.5, 0]", "<test>",
                                "combine", &diags),
             SSG_OK);
    CHECK_NEAR(p.ambient_color[1], 0.5, 0.0);
}

/* 2 x 2 by hand. Defaults: ambient 0.3, colour white. */
static void test_known_values(void)
{
    struct run r;
    run_init(&r, 2, 2);
    float dr[4] = {0.5f, 0, 1, 0}, dg[4] = {0.25f, 0, 0, 0}, db[4] = {0, 0, 0, 0};
    float ar[4] = {1, 0.5f, 0, 0}, ag[4] = {0.5f, 0.5f, 0, 0}, ab[4] = {0.25f, 1, 0};
    struct ssg_image *direct = rgb(2, 2, dr, dg, db), *albedo = rgb(2, 2, ar, ag, ab);
    struct ssg_image *ao = ssg_image_create(2, 2, 1);
    float aov[4] = {1, 0.5f, 0.25f, 0};
    memcpy(ao->data, aov, sizeof aov);
    struct ssg_combine_params p;
    ssg_params_defaults(ssg_node_combine.params, &p);
    r.in[SSG_COMBINE_IN_DIRECT] = direct;
    r.in[SSG_COMBINE_IN_ALBEDO] = albedo;
    r.in[SSG_COMBINE_IN_AMBIENT_OCCLUSION] = ao;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    const float *o0 = ssg_image_plane(r.out[0], 0), *o1 = ssg_image_plane(r.out[0], 1),
                *o2 = ssg_image_plane(r.out[0], 2);
    /* pixel 0: ao 1 -> direct + 0.3 * albedo */
    CHECK_NEAR(o0[0], 0.8, 1e-6);
    CHECK_NEAR(o1[0], 0.4, 1e-6);
    CHECK_NEAR(o2[0], 0.075, 1e-6);
    /* pixel 1: ao 0.5 -> 0.15 * albedo */
    CHECK_NEAR(o0[1], 0.075, 1e-6);
    CHECK_NEAR(o1[1], 0.075, 1e-6);
    CHECK_NEAR(o2[1], 0.15, 1e-6);
    /* pixel 2: no albedo: direct only */
    CHECK_NEAR(o0[2], 1.0, 0.0);
    CHECK_NEAR(o1[2], 0.0, 0.0);
    /* pixel 3: background (direct 0, albedo 0) stays exactly 0 */
    CHECK_EQ(o0[3], 0);
    CHECK_EQ(o1[3], 0);
    CHECK_EQ(o2[3], 0);

    /* No AO: the ambient term is unoccluded (ao = 1). Tinted, stronger ambient. */
    r.in[SSG_COMBINE_IN_AMBIENT_OCCLUSION] = NULL;
    p.ambient = 2.0f;
    p.ambient_color[0] = 1.0f;
    p.ambient_color[1] = 0.5f;
    p.ambient_color[2] = 0.0f;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    CHECK_NEAR(o0[1], 1.0, 1e-6);  /* 0 + 2 * 1 * 0.5 */
    CHECK_NEAR(o1[1], 0.5, 1e-6);  /* 0 + 2 * 0.5 * 0.5 */
    CHECK_NEAR(o2[1], 0.0, 0.0);   /* blue ambient is off */
    CHECK_NEAR(o0[0], 2.5, 1e-6);  /* 0.5 + 2 * 1 * 1 */

    /* Indirect light is added as is. */
    float ir[4] = {0.1f, 0.2f, 0.3f, 0.4f}, ig[4] = {1, 1, 1, 1}, ib[4] = {0, 0, 0, 5};
    struct ssg_image *indirect = rgb(2, 2, ir, ig, ib);
    r.in[SSG_COMBINE_IN_INDIRECT] = indirect;
    r.in[SSG_COMBINE_IN_AMBIENT_OCCLUSION] = ao;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    CHECK_NEAR(o0[1], 0.5 + 0.2, 1e-6); /* 2 * 1 * 0.5 * ao 0.5, + 0.2 */
    CHECK_NEAR(o1[1], 0.25 + 1, 1e-6);
    CHECK_NEAR(o2[3], 5.0, 0.0);        /* background with indirect only */
    CHECK_EQ(r.diags.count, 0);

    ssg_image_destroy(&direct);
    ssg_image_destroy(&albedo);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&indirect);
    ssg_image_destroy(&r.out[0]);
}

/* The SSDO combinations on one pixel of known values: one step (modulation darkens
   direct, environment and, by default, the bounce), one step without darkening the
   bounce, a 3-channel modulation, and AO darkening the environment light (SSAO). */
static void test_ssdo_combinations(void)
{
    struct run r;
    run_init(&r, 1, 1);
    float d[3] = {0.4f, 0.2f, 0.1f}, a[3] = {0.5f, 0.5f, 0.5f}, e[3] = {0.1f, 0.2f, 0.3f};
    float b[3] = {0.05f, 0.01f, 0.0f}, m3[3] = {0.5f, 0.25f, 1.0f};
    struct ssg_image *direct = rgb(1, 1, &d[0], &d[1], &d[2]);
    struct ssg_image *albedo = rgb(1, 1, &a[0], &a[1], &a[2]);
    struct ssg_image *env = rgb(1, 1, &e[0], &e[1], &e[2]);
    struct ssg_image *bounce = rgb(1, 1, &b[0], &b[1], &b[2]);
    struct ssg_image *mod3 = rgb(1, 1, &m3[0], &m3[1], &m3[2]);
    struct ssg_image *mod1 = ssg_image_create(1, 1, 1), *ao = ssg_image_create(1, 1, 1);
    mod1->data[0] = 0.6f;
    ao->data[0] = 0.3f;
    struct ssg_combine_params p;
    ssg_params_defaults(ssg_node_combine.params, &p);
    CHECK_EQ(p.darken_indirect, 1);
    p.ambient = 0;
    r.in[SSG_COMBINE_IN_DIRECT] = direct;
    r.in[SSG_COMBINE_IN_ALBEDO] = albedo;
    r.in[SSG_COMBINE_IN_ENVIRONMENT] = env;
    r.in[SSG_COMBINE_IN_INDIRECT] = bounce;
    r.in[SSG_COMBINE_IN_MODULATION] = mod1;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    for (int c = 0; c < 3; c++) /* M (direct + environment + bounce) */
        CHECK_NEAR(ssg_image_plane(r.out[0], c)[0], 0.6 * (d[c] + e[c] + b[c]), 1e-6);
    p.darken_indirect = 0;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    for (int c = 0; c < 3; c++)
        CHECK_NEAR(ssg_image_plane(r.out[0], c)[0], 0.6 * (d[c] + e[c]) + b[c], 1e-6);
    r.in[SSG_COMBINE_IN_MODULATION] = mod3;
    p.darken_indirect = 1;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    for (int c = 0; c < 3; c++)
        CHECK_NEAR(ssg_image_plane(r.out[0], c)[0], m3[c] * (d[c] + e[c] + b[c]), 1e-6);
    /* SSAO-modulated ambient from the environment: direct + ao * environment. */
    r.in[SSG_COMBINE_IN_MODULATION] = NULL;
    r.in[SSG_COMBINE_IN_INDIRECT] = NULL;
    r.in[SSG_COMBINE_IN_AMBIENT_OCCLUSION] = ao;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    for (int c = 0; c < 3; c++)
        CHECK_NEAR(ssg_image_plane(r.out[0], c)[0], d[c] + 0.3 * e[c], 1e-6);
    /* A 2-channel modulation is refused. */
    struct ssg_image *mod2 = ssg_image_create(1, 1, 2);
    r.in[SSG_COMBINE_IN_MODULATION] = mod2;
    CHECK_EQ(run_combine(&r, &p), SSG_E_CHANNELS);
    struct ssg_image *all[] = {direct, albedo, env, bounce, mod3, mod1, ao, mod2, r.out[0]};
    for (int i = 0; i < SSG_COUNT(all); i++)
        ssg_image_destroy(&all[i]);
}

/* With far_visibility V the environment is darkened by min(1, M / V), not by M (a near
   occluder both see is counted once), and far_bounce adds albedo max(0, M - V) own. */
static void test_far_field(void)
{
    struct run r;
    run_init(&r, 2, 1);
    float d[2] = {0.4f, 0.4f}, a[2] = {0.5f, 0.8f}, e[2] = {0.3f, 0.3f}, b[2] = {0.05f, 0.0f};
    struct ssg_image *direct = rgb(2, 1, d, d, d), *albedo = rgb(2, 1, a, a, a);
    struct ssg_image *env = rgb(2, 1, e, e, e), *bounce = rgb(2, 1, b, b, b);
    struct ssg_image *mod = ssg_image_create(2, 1, 1), *far = ssg_image_create(2, 1, 1);
    mod->data[0] = 0.6f, far->data[0] = 0.8f; /* near darker than far: M rules */
    mod->data[1] = 0.9f, far->data[1] = 0.5f; /* far darker: the far field rules */
    struct ssg_combine_params p;
    ssg_params_defaults(ssg_node_combine.params, &p);
    CHECK_EQ(p.far_bounce, 1);
    p.ambient = 0;
    r.in[SSG_COMBINE_IN_DIRECT] = direct;
    r.in[SSG_COMBINE_IN_ALBEDO] = albedo;
    r.in[SSG_COMBINE_IN_ENVIRONMENT] = env;
    r.in[SSG_COMBINE_IN_INDIRECT] = bounce;
    r.in[SSG_COMBINE_IN_MODULATION] = mod;
    r.in[SSG_COMBINE_IN_FAR_VISIBILITY] = far;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    double own0 = 0.6 * 0.4 + (0.6 / 0.8) * 0.3, own1 = 0.9 * 0.4 + 1.0 * 0.3;
    for (int c = 0; c < 3; c++) {
        const float *o = ssg_image_plane(r.out[0], c);
        CHECK_NEAR(o[0], own0 + 0.6 * 0.05, 1e-6);               /* M < V: no far bounce */
        CHECK_NEAR(o[1], own1 + 0.8 * (0.9 - 0.5) * own1, 1e-6); /* fills M - V */
    }
    p.far_bounce = 0;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    CHECK_NEAR(ssg_image_plane(r.out[0], 1)[1], own1, 1e-6);
    far->data[0] = 0.0f; /* nothing reaches: the (zero) environment is not divided by 0 */
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    CHECK_NEAR(ssg_image_plane(r.out[0], 0)[0], 0.6 * 0.4 + 0.3 + 0.6 * 0.05, 1e-6);
    /* A far bounce as irradiance: albedo x irradiance, darkened by M and ao, added to both
       forms. */
    struct ssg_image *ao = ssg_image_create(2, 1, 1);
    float e2[2] = {0.2f, 0.1f};
    struct ssg_image *irr = rgb(2, 1, e2, e2, e2);
    ao->data[0] = 0.5f, ao->data[1] = 1.0f;
    r.in[SSG_COMBINE_IN_AMBIENT_OCCLUSION] = ao;
    r.in[SSG_COMBINE_IN_IRRADIANCE] = irr;
    r.in[SSG_COMBINE_IN_ENVIRONMENT] = NULL;
    r.in[SSG_COMBINE_IN_FAR_VISIBILITY] = NULL;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    CHECK_NEAR(ssg_image_plane(r.out[0], 2)[0], 0.6 * 0.4 + 0.6 * 0.05 + 0.6 * 0.5 * 0.5 * 0.2,
               1e-6);
    CHECK_NEAR(ssg_image_plane(r.out[0], 2)[1], 0.9 * 0.4 + 0.9 * 0.0 + 0.9 * 0.8 * 0.1, 1e-6);
    /* darken_direct=false: direct as given; with a far field and irradiance, the far
       bounce fills M - V with the environment's part alone (irradiance carries the
       direct lights' far bounce). */
    p.darken_direct = 0;
    p.far_bounce = 1;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    CHECK_NEAR(ssg_image_plane(r.out[0], 0)[0], 0.4 + 0.6 * 0.05 + 0.6 * 0.5 * 0.5 * 0.2, 1e-6);
    r.in[SSG_COMBINE_IN_ENVIRONMENT] = env;
    r.in[SSG_COMBINE_IN_FAR_VISIBILITY] = far;
    far->data[1] = 0.5f;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    double env1 = 1.0 * 1.0 * 0.3; /* q = min(1, 0.9 / 0.5) = 1, ao 1 */
    CHECK_NEAR(ssg_image_plane(r.out[0], 1)[1],
               0.4 + env1 + 0.9 * 0.0 + 0.8 * (0.9 - 0.5) * env1 + 0.9 * 1.0 * 0.8 * 0.1, 1e-6);
    /* environment_albedo: the environment is a white receiver's E / pi, times the albedo
       here (0.5 and 0.8), with and without a far field */
    p.environment_albedo = 1;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    double env_a = 0.8 * 0.3;
    CHECK_NEAR(ssg_image_plane(r.out[0], 1)[1],
               0.4 + env_a + 0.8 * (0.9 - 0.5) * env_a + 0.9 * 1.0 * 0.8 * 0.1, 1e-6);
    r.in[SSG_COMBINE_IN_FAR_VISIBILITY] = NULL;
    CHECK_EQ(run_combine(&r, &p), SSG_OK);
    CHECK_NEAR(ssg_image_plane(r.out[0], 0)[0],
               0.4 + 0.6 * 0.5 * 0.5 * 0.3 + 0.6 * 0.05 + 0.6 * 0.5 * 0.5 * 0.2, 1e-6);
    struct ssg_image *all[] = {direct, albedo, env, bounce, mod, far, ao, irr, r.out[0]};
    for (int i = 0; i < SSG_COUNT(all); i++)
        ssg_image_destroy(&all[i]);
}

/* Inputs that do not fit the output are reported, not read out of bounds. */
static void test_mismatch(void)
{
    struct run r;
    run_init(&r, 4, 3);
    struct ssg_image *direct = ssg_image_create(4, 3, 3), *albedo = ssg_image_create(4, 3, 3);
    struct ssg_image *small = ssg_image_create(4, 2, 1), *gray = ssg_image_create(4, 3, 1);
    struct ssg_combine_params p;
    ssg_params_defaults(ssg_node_combine.params, &p);
    r.in[SSG_COMBINE_IN_DIRECT] = direct;
    r.in[SSG_COMBINE_IN_ALBEDO] = albedo;
    r.in[SSG_COMBINE_IN_AMBIENT_OCCLUSION] = small;
    CHECK_EQ(run_combine(&r, &p), SSG_E_SIZE);
    CHECK_EQ(r.diags.count, 1);
    CHECK(strstr(r.diags.items[0].message, "ambient_occlusion") != NULL);
    r.in[SSG_COMBINE_IN_AMBIENT_OCCLUSION] = NULL;
    r.in[SSG_COMBINE_IN_ALBEDO] = gray;
    CHECK_EQ(run_combine(&r, &p), SSG_E_CHANNELS);
    CHECK_EQ(r.diags.items[1].code, SSG_E_CHANNELS);
    ssg_image_destroy(&direct);
    ssg_image_destroy(&albedo);
    ssg_image_destroy(&small);
    ssg_image_destroy(&gray);
    ssg_image_destroy(&r.out[0]);
}

/* A frame taller than one band, run with 1 and 3 threads: every pixel matches the
   equation and both runs give the same bits. */
static void test_bands_and_threads(void)
{
    enum { W = 13, H = 37 };
    struct ssg_image *direct = ssg_image_create(W, H, 3), *albedo = ssg_image_create(W, H, 3);
    struct ssg_image *ao = ssg_image_create(W, H, 1);
    for (int i = 0; i < W * H * 3; i++) {
        direct->data[i] = (float)(i % 17) * 0.0625f;
        albedo->data[i] = (float)(i % 11) * 0.09375f;
    }
    for (int i = 0; i < W * H; i++)
        ao->data[i] = (float)(i % 5) * 0.25f;
    struct ssg_combine_params p;
    ssg_params_defaults(ssg_node_combine.params, &p);
    struct run r1, r3;
    run_init(&r1, W, H);
    run_init(&r3, W, H);
    struct run *runs[2] = {&r1, &r3};
    for (int k = 0; k < 2; k++) {
        runs[k]->in[SSG_COMBINE_IN_DIRECT] = direct;
        runs[k]->in[SSG_COMBINE_IN_ALBEDO] = albedo;
        runs[k]->in[SSG_COMBINE_IN_AMBIENT_OCCLUSION] = ao;
        omp_set_num_threads(k == 0 ? 1 : 3);
        CHECK_EQ(run_combine(runs[k], &p), SSG_OK);
    }
    CHECK(memcmp(r1.out[0]->data, r3.out[0]->data, sizeof(float) * W * H * 3) == 0);
    int bad = 0;
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < W * H; i++) {
            float want = ssg_image_plane(direct, c)[i] +
                         0.3f * ssg_image_plane(albedo, c)[i] * ao->data[i];
            bad += fabsf(ssg_image_plane(r1.out[0], c)[i] - want) > 1e-6f;
        }
    CHECK_EQ(bad, 0);
    ssg_image_destroy(&direct);
    ssg_image_destroy(&albedo);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&r1.out[0]);
    ssg_image_destroy(&r3.out[0]);
}

int main(void)
{
    test_descriptor();
    test_known_values();
    test_ssdo_combinations();
    test_far_field();
    test_mismatch();
    test_bands_and_threads();
    return check_report();
}
