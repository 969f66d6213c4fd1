/* test_probe_light.c - the `probe_light` node (hybrid AO's global pass) on G-buffers and
 * shadow maps of small scenes (made by the gbuffer and shadowmaps nodes, tested on their
 * own), against what the paper's global part must do:
 * - without maps: out is exactly albedo / pi * sum_i max(0, N.l_i) E_i and visibility 1;
 * - an open floor is fully lit with the default offsets, and shadows itself in part with
 *   no offset at all (the artefact the paper's shift behind the occluder removes, fig. 1);
 * - a box's shadow falls exactly where its silhouette along the light says (no jitter),
 *   and the jitter turns the shadow's edge into a mix of lit and shadowed pixels (fig. 8);
 * - a large offset lets the light through a thin plate over the floor (light bleeding,
 *   figs. 1 and 7), a small one does not;
 * - a zero-thickness wall on a floor, lit from behind at a grazing angle: with the default
 *   normal offset its shadow reaches to within a texel of its foot (the old slope-scaled
 *   depth offset let the light through over several texels), and the floor beside it that
 *   the light grazes does not shadow itself;
 * - a shadow-map count that is not the light count is refused;
 * - CPU and GL agree within the descriptor's bound (gl_parity.h). */
#include <string.h>

#include "check.h"
#include "gl_parity.h"
#include "gbuffer/gbuffer.h"
#include "probe_light/probe_light.h"
#include "scene_node.h"
#include "shadowmaps/shadowmaps.h"
#include "common/trace.h"

extern const struct ssg_node_desc ssg_node_gbuffer;

enum { W = 96, H = 72 };
static const struct ssg_frame FRAME = {W, H, 45, 0.05f, 100, 1, 0, 0, 0};

struct gbuf {
    struct ssg_image *out[SSG_GBUFFER_OUTPUTS]; /* gbuffer's outputs in port order (back,
                                                   motion: NULL, not read) */
    float rot[9], eye[3];     /* view -> world */
};

static struct gbuf gbuffer(const struct ssg_scene *s)
{
    struct gbuf g = {0};
    for (int i = 0; i < 6; i++)
        g.out[i] = ssg_image_create(W, H, i == SSG_GBUFFER_OUT_DEPTH ? 1 : 3);
    void *params = node_params(&ssg_node_gbuffer, NULL, 0);
    CHECK_EQ(node_run_scene(&ssg_node_gbuffer, s, &FRAME, params, NULL, g.out,
                            SSG_BACKEND_CPU), SSG_OK);
    free(params);
    ssg_camera_frame(&s->camera, g.rot, g.eye);
    return g;
}

static void gbuf_free(struct gbuf *g)
{
    for (int i = 0; i < 6; i++)
        ssg_image_destroy(&g->out[i]);
}


static struct ssg_image *maps_of(const struct ssg_scene *s, const struct ssg_image *lights,
                                 int res)
{
    char set[32];
    snprintf(set, sizeof set, "resolution=%d", res);
    const char *sets[] = {set};
    void *params = node_params(&ssg_node_shadowmaps, sets, 1);
    struct ssg_image *out[1] = {ssg_image_create(res, res, lights->width)};
    const struct ssg_image *in[1] = {lights};
    CHECK_EQ(node_run_scene(&ssg_node_shadowmaps, s, &FRAME, params, in, out,
                            SSG_BACKEND_CPU), SSG_OK);
    free(params);
    return out[0];
}

/* probe_light's out (0) and visibility (1) into res[2]. */
/* 1: light() leaves albedo unconnected (out is a white receiver's E / pi). */
static int white_receiver;

static void light(const struct ssg_scene *s, const struct gbuf *g,
                  const struct ssg_image *lights, const struct ssg_image *maps,
                  const char *const *sets, int set_count, enum ssg_backend backend,
                  struct ssg_image *res[2])
{
    res[0] = ssg_image_create(W, H, 3);
    res[1] = ssg_image_create(W, H, 1);
    const struct ssg_image *in[5] = {g->out[SSG_GBUFFER_OUT_POSITION],
                                     g->out[SSG_GBUFFER_OUT_NORMAL],
                                     white_receiver ? NULL : g->out[SSG_GBUFFER_OUT_ALBEDO],
                                     lights, maps};
    void *params = node_params(&ssg_node_probe_light, sets, set_count);
    CHECK_EQ(node_run_scene(&ssg_node_probe_light, s, &FRAME, params, in, res, backend),
             SSG_OK);
    free(params);
}

static float at(const struct ssg_image *im, int c, int x, int y)
{
    return im->data[((size_t)c * im->height + y) * im->width + x];
}

/* The world point of pixel (x, y); 0 for background. */
static int world_of(const struct gbuf *g, int x, int y, float w[3])
{
    const struct ssg_image *n = g->out[SSG_GBUFFER_OUT_NORMAL];
    if (at(n, 0, x, y) == 0 && at(n, 1, x, y) == 0 && at(n, 2, x, y) == 0)
        return 0;
    float p[3];
    for (int c = 0; c < 3; c++)
        p[c] = at(g->out[SSG_GBUFFER_OUT_POSITION], c, x, y);
    for (int i = 0; i < 3; i++)
        w[i] = g->eye[i] + g->rot[i] * p[0] + g->rot[3 + i] * p[1] + g->rot[6 + i] * p[2];
    return 1;
}

static const char *const CAMERA = "camera(position=[0, 2, 3], target=[0, 0, 0])\n";

static void parity_case(const struct ssg_scene *s, const struct gbuf *g,
                        const struct ssg_image *l, const struct ssg_image *m,
                        const char *const *sets, int set_count, const char *name);

/* max(0, N.l) of pixel (x, y) for light i of the list l (world directions, planes). */
static float cosine_of(const struct gbuf *g, const struct ssg_image *l, int i, int x, int y)
{
    int n = l->width;
    float lw[3] = {l->data[i], l->data[2 * n + i], l->data[4 * n + i]}, c = 0;
    for (int k = 0; k < 3; k++)
        c += at(g->out[SSG_GBUFFER_OUT_NORMAL], k, x, y) *
             (g->rot[3 * k] * lw[0] + g->rot[3 * k + 1] * lw[1] + g->rot[3 * k + 2] * lw[2]);
    return c > 0 ? c : 0;
}

/* A box on a floor, and four lights of which one lies below the floor. */
static const float FOUR[4][3] = {{0, 1, 0}, {1, 1, 0}, {-1, 0.3f, 1}, {0, -1, 0.2f}};

static struct ssg_scene *box_on_floor(const char *name)
{
    char text[512];
    snprintf(text, sizeof text, "%splane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
             "box(center=[0, 0.25, 0], size=[0.5, 0.5, 0.5])\n", CAMERA);
    return scene_from_text(name, text);
}

static void test_unshadowed_sum(void)
{
    struct ssg_scene *s = box_on_floor("sum");
    if (!s)
        return;
    struct gbuf g = gbuffer(s);
    struct ssg_image *l = light_list(FOUR, 4), *r[2];
    light(s, &g, l, NULL, NULL, 0, SSG_BACKEND_CPU, r);
    double worst = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float sum = 0;
            for (int i = 0; i < 4; i++)
                sum += cosine_of(&g, l, i, x, y);
            for (int c = 0; c < 3; c++) {
                double want = at(g.out[SSG_GBUFFER_OUT_ALBEDO], c, x, y) / M_PI * sum * (c + 1);
                double e = fabs(at(r[0], c, x, y) - want) / (want > 1e-3 ? want : 1e-3);
                worst = e > worst ? e : worst;
            }
            CHECK(at(r[1], 0, x, y) == 1.0f);
        }
    fprintf(stderr, "no shadow maps: largest relative error %.3g\n", worst);
    CHECK(worst < 1e-5);
    /* Without albedo: the same light on a white receiver, out x albedo = the out above
       (the same float products but for the albedo's place in them). */
    struct ssg_image *w[2];
    white_receiver = 1;
    light(s, &g, l, NULL, NULL, 0, SSG_BACKEND_CPU, w);
    white_receiver = 0;
    double off = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        for (int c = 0; c < 3; c++) {
            double a = ssg_image_plane(g.out[SSG_GBUFFER_OUT_ALBEDO], c)[i];
            double e = fabs(a * ssg_image_plane(w[0], c)[i] - ssg_image_plane(r[0], c)[i]);
            off = e > off ? e : off;
        }
    fprintf(stderr, "no albedo: albedo x out off by %.3g at most\n", off);
    CHECK(off < 1e-6);
    CHECK(memcmp(w[1]->data, r[1]->data, sizeof(float) * W * H) == 0);
    for (int i = 0; i < 2; i++)
        ssg_image_destroy(&r[i]), ssg_image_destroy(&w[i]);
    ssg_image_destroy(&l);
    gbuf_free(&g);
    ssg_scene_destroy(&s);
}

/* interleave=2 without maps: pixel (x, y) takes light (y mod 2) 2 + x mod 2 of the four
   alone, weighted 4: albedo / pi x 4 max(0, N.l) E; and with maps, CPU and GL alike. */
static void test_interleave(void)
{
    struct ssg_scene *s = box_on_floor("interleave");
    if (!s)
        return;
    struct gbuf g = gbuffer(s);
    struct ssg_image *l = light_list(FOUR, 4), *r[2];
    const char *sets[] = {"interleave=2"};
    light(s, &g, l, NULL, sets, 1, SSG_BACKEND_CPU, r);
    double worst = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int c = 0; c < 3; c++) {
                double want = at(g.out[SSG_GBUFFER_OUT_ALBEDO], c, x, y) / M_PI * 4 *
                              cosine_of(&g, l, (y % 2) * 2 + x % 2, x, y) * (c + 1);
                double e = fabs(at(r[0], c, x, y) - want) / (want > 1e-3 ? want : 1e-3);
                worst = e > worst ? e : worst;
            }
    fprintf(stderr, "interleave 2: largest relative error %.3g\n", worst);
    CHECK(worst < 1e-5);
    struct ssg_image *m = maps_of(s, l, 128);
    parity_case(s, &g, l, m, sets, 1, "interleave 2");
    for (int i = 0; i < 2; i++)
        ssg_image_destroy(&r[i]);
    ssg_image_destroy(&m);
    ssg_image_destroy(&l);
    gbuf_free(&g);
    ssg_scene_destroy(&s);
}

/* Lit and not-fully-lit floor pixels of an open floor under 12 lights. */
static void count_floor(const struct ssg_image *vis, int *lit, int *dark)
{
    *lit = *dark = 0;
    for (int i = 0; i < W * H; i++)
        if (vis->data[i] >= 0.9999f)
            (*lit)++;
        else
            (*dark)++;
}

static void test_open_floor(void)
{
    char text[512];
    snprintf(text, sizeof text, "%splane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n",
             CAMERA);
    struct ssg_scene *s = scene_from_text("open", text);
    if (!s)
        return;
    struct gbuf g = gbuffer(s);
    float dirs[12][3];
    for (int i = 0; i < 12; i++) { /* elevations from 80 down to 8 degrees */
        double el = (80.0 - 6.5 * i) * M_PI / 180, az = 2.4 * i;
        dirs[i][0] = (float)(cos(el) * cos(az));
        dirs[i][1] = (float)sin(el);
        dirs[i][2] = (float)(cos(el) * sin(az));
    }
    struct ssg_image *l = light_list(dirs, 12), *m = maps_of(s, l, 256), *r[2], *z[2];
    light(s, &g, l, m, NULL, 0, SSG_BACKEND_CPU, r);
    const char *none[] = {"offset=0", "slope_offset=0", "normal_offset=0", "noise_radius=0",
                          "softness=0"};
    light(s, &g, l, m, none, 5, SSG_BACKEND_CPU, z);
    int lit, dark, zlit, zdark;
    count_floor(r[1], &lit, &dark);
    count_floor(z[1], &zlit, &zdark);
    fprintf(stderr, "open floor: defaults %d lit / %d not; no offset %d lit / %d not\n", lit,
            dark, zlit, zdark);
    CHECK_EQ(dark, 0);
    for (int i = 0; i < W * H; i++) /* soft lookups (the default): exactly unshadowed */
        CHECK(r[1]->data[i] == 1.0f);
    CHECK(zdark > W * H / 20); /* self-shadowing without the shift */
    for (int i = 0; i < 2; i++) {
        ssg_image_destroy(&r[i]);
        ssg_image_destroy(&z[i]);
    }
    ssg_image_destroy(&m);
    ssg_image_destroy(&l);
    gbuf_free(&g);
    ssg_scene_destroy(&s);
}

/* Box on a floor, one light along (1, 2, 0): the floor is shadowed exactly for x in
   (-0.5, -0.25), |z| < 0.25 (the top's edge projects 0.25 towards -x). */
static void test_box_shadow(void)
{
    char text[512];
    snprintf(text, sizeof text, "%splane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
             "box(center=[0, 0.25, 0], size=[0.5, 0.5, 0.5])\n", CAMERA);
    struct ssg_scene *s = scene_from_text("box", text);
    if (!s)
        return;
    struct gbuf g = gbuffer(s);
    const float dirs[1][3] = {{1, 2, 0}};
    struct ssg_image *l = light_list(dirs, 1), *m = maps_of(s, l, 512), *r[2], *j[2];
    const char *sharp[] = {"noise_radius=0", "softness=0"};
    const char *noisy[] = {"noise_radius=4", "softness=0"};
    light(s, &g, l, m, sharp, 2, SSG_BACKEND_CPU, r);
    light(s, &g, l, m, noisy, 2, SSG_BACKEND_CPU, j);
    const float margin = 0.04f; /* ~2 texels of the 512 map over the floor's sphere */
    int in = 0, out = 0, wrong = 0, edge = 0, edge_lit = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float w[3];
            if (!world_of(&g, x, y, w) || w[1] > 1e-3f)
                continue; /* floor pixels only */
            float v = at(r[1], 0, x, y);
            int inside = w[0] > -0.5f + margin && w[0] < -0.25f - margin &&
                         fabsf(w[2]) < 0.25f - margin;
            int outside = w[0] < -0.5f - margin || fabsf(w[2]) > 0.25f + margin;
            in += inside, out += outside;
            wrong += (inside && v != 0.0f) || (outside && v != 1.0f);
            if (fabsf(w[0] + 0.5f) < 0.02f && fabsf(w[2]) < 0.2f) { /* the far edge */
                edge++;
                edge_lit += at(j[1], 0, x, y) > 0.5f;
            }
        }
    fprintf(stderr, "box shadow: %d pixels inside, %d outside, %d wrong; jittered edge: %d of "
            "%d lit\n", in, out, wrong, edge_lit, edge);
    CHECK(in > 20 && out > 1000);
    CHECK_EQ(wrong, 0);
    CHECK(edge_lit > 0 && edge_lit < edge); /* a dithered edge, not a step */
    for (int i = 0; i < 2; i++) {
        ssg_image_destroy(&r[i]);
        ssg_image_destroy(&j[i]);
    }
    ssg_image_destroy(&m);
    ssg_image_destroy(&l);
    gbuf_free(&g);
    ssg_scene_destroy(&s);
}

/* A scene from text under one light in direction dir, with its G-buffer and one shadow
   map of res texels a side; ok 0 when the scene did not load. */
struct one_light {
    int ok;
    struct ssg_scene *s;
    struct gbuf g;
    struct ssg_image *lights, *maps;
    float texel; /* the map's texel, scene units */
};

static struct one_light one_light(const char *name, const char *text, const float dir[3],
                                  int res)
{
    struct one_light o = {0};
    o.s = scene_from_text(name, text);
    if (!o.s)
        return o;
    o.g = gbuffer(o.s);
    const float dirs[1][3] = {{dir[0], dir[1], dir[2]}};
    o.lights = light_list(dirs, 1);
    o.maps = maps_of(o.s, o.lights, res);
    o.texel = 2 * ssg_scene_bounding_sphere(o.s).radius / (float)res;
    o.ok = 1;
    return o;
}

static void one_light_free(struct one_light *o)
{
    ssg_image_destroy(&o->maps);
    ssg_image_destroy(&o->lights);
    gbuf_free(&o->g);
    ssg_scene_destroy(&o->s);
}

/* A plate 0.1 above the floor, the light straight down: the floor under it is dark with
   a small offset and lit once the offset exceeds the gap (light bleeding). */
static void test_bleeding(void)
{
    const float down[3] = {0, 1, 0};
    struct one_light o = one_light("plate", "camera(position=[0, 0.06, 2], "
                                   "target=[0, 0.03, 0])\n"
                                   "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
                                   "box(center=[0, 0.11, 0], size=[1.5, 0.02, 1.5])\n",
                                   down, 256);
    if (!o.ok)
        return;
    float texel = o.texel; /* gap 0.1 = ~4.5 texels */
    double mean[2] = {0, 0};
    int n = 0;
    for (int k = 0; k < 2; k++) {
        char off[48];
        snprintf(off, sizeof off, "offset=%g", k ? 0.2 / texel : 1.5);
        const char *sets[] = {off, "noise_radius=0", "softness=0"};
        struct ssg_image *r[2];
        light(o.s, &o.g, o.lights, o.maps, sets, 3, SSG_BACKEND_CPU, r);
        n = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                float w[3];
                if (world_of(&o.g, x, y, w) && w[1] < 1e-3f && fabsf(w[0]) < 0.6f &&
                    fabsf(w[2]) < 0.6f)
                    mean[k] += at(r[1], 0, x, y), n++;
            }
        mean[k] /= n > 0 ? n : 1;
        for (int i = 0; i < 2; i++)
            ssg_image_destroy(&r[i]);
    }
    fprintf(stderr, "under the plate (%d px): visibility %.3f with offset 1.5 texels, %.3f "
            "with %.1f texels\n", n, mean[0], mean[1], 0.2 / texel);
    CHECK(n > 50);
    CHECK(mean[0] < 0.01);
    CHECK(mean[1] > 0.99);
    one_light_free(&o);
}

/* Farthest lit floor pixel in the wall's shadow (|x| < 0.1, 0 < z < 0.4), in texels from
   the wall, and the lit share of the floor beside the shadow (|x| > 0.2). */
static void wall_foot_leak(const struct gbuf *g, const struct ssg_image *vis, float texel,
                           double *leak, double *side_lit, int *shadow_px, int *side_px)
{
    double far = 0;
    int lit = 0;
    *shadow_px = *side_px = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float w[3];
            if (!world_of(g, x, y, w) || w[1] > 1e-3f)
                continue; /* floor pixels only */
            float v = at(vis, 0, x, y);
            if (fabsf(w[0]) < 0.1f && w[2] > 0.0f && w[2] < 0.4f) {
                (*shadow_px)++;
                far = v > 0.5f && w[2] > far ? w[2] : far;
            } else if (fabsf(w[0]) > 0.2f) {
                (*side_px)++;
                lit += v == 1.0f;
            }
        }
    *leak = far / texel;
    *side_lit = *side_px ? (double)lit / *side_px : 0;
}

/* A zero-thickness wall standing on a floor, one light behind it 19 degrees above the
   horizon: the floor in front of the wall is in its shadow right up to its foot. */
static void test_wall_foot(void)
{
    const float behind[3] = {0, 0.35f, -1};
    struct one_light o = one_light("wall_foot", "camera(position=[0, 0.5, 0.8], "
                                   "target=[0, 0, 0.15])\n"
                                   "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
                                   "plane(center=[0, 0.5, 0], normal=[0, 0, 1], "
                                   "size=[0.3, 0, 1])\n", behind, 512);
    if (!o.ok)
        return;
    /* the hard lookup's offsets: one light alone is no patch of a sphere to soften */
    const char *old[] = {"softness=0", "offset=1.5", "slope_offset=2", "normal_offset=0"};
    double leak[2], side[2];
    int shadow_px = 0, side_px = 0;
    for (int k = 0; k < 2; k++) {
        struct ssg_image *r[2];
        light(o.s, &o.g, o.lights, o.maps, old, k ? 4 : 1, SSG_BACKEND_CPU, r);
        wall_foot_leak(&o.g, r[1], o.texel, &leak[k], &side[k], &shadow_px, &side_px);
        for (int i = 0; i < 2; i++)
            ssg_image_destroy(&r[i]);
    }
    fprintf(stderr, "wall foot (%d px in the shadow, %d beside): light reaches %.2f texels "
            "into the shadow with the normal offset, %.2f with the slope-scaled offset; beside it "
            "%.3f and %.3f lit\n", shadow_px, side_px, leak[0], leak[1], side[0], side[1]);
    CHECK(shadow_px > 300 && side_px > 300);
    CHECK(leak[0] <= 1.0);  /* within the map's texel of the foot */
    CHECK(leak[1] > 3.0);   /* what the defaults fixed: the test can fail */
    CHECK(side[0] == 1.0);  /* no self-shadowing where the light grazes the floor */
    one_light_free(&o);
}

/* Soft lookups: the box of test_box_shadow seen from near its shadow's far edge (x = -0.5,
   made by the top edge 0.559 from the floor along the light (1, 2, 0)), one light whose
   cone is softness x pi (one light: acos(1 - 2 / 1) = pi). The penumbra across that edge,
   the floor pixels neither lit nor dark, must be as wide as the cone makes it: full
   width 2 x 0.559 tan(half-angle) across the light, / sin 63.4 degrees on the floor. */
static double penumbra_width(const struct one_light *o, double softness, double *expect)
{
    char set[40];
    snprintf(set, sizeof set, "softness=%g", softness);
    /* one light: a dense search, wide enough for the 10 texels of the wider penumbra */
    const char *sets[] = {set, "taps=16", "search_taps=16", "search_radius=16"};
    struct ssg_image *r[2];
    light(o->s, &o->g, o->lights, o->maps, sets, 4, SSG_BACKEND_CPU, r);
    double lo = 1e9, hi = -1e9;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float w[3], v = at(r[1], 0, x, y);
            if (!world_of(&o->g, x, y, w) || w[1] > 1e-3f || fabsf(w[2]) > 0.1f ||
                w[0] > -0.3f || !(v > 0.02f && v < 0.98f))
                continue; /* floor pixels of the far edge's penumbra only */
            lo = w[0] < lo ? w[0] : lo;
            hi = w[0] > hi ? w[0] : hi;
        }
    for (int i = 0; i < 2; i++)
        ssg_image_destroy(&r[i]);
    *expect = 2.0 * 0.559 * tan(softness * M_PI) / sin(atan(2.0));
    return hi - lo;
}

static void test_penumbra(void)
{
    const float dir[3] = {1, 2, 0};
    struct one_light o = one_light("penumbra", "camera(position=[-0.5, 0.5, 0.6], "
                                   "target=[-0.5, 0, 0])\n"
                                   "plane(center=[0, 0, 0], normal=[0, 1, 0], size=[4, 0, 4])\n"
                                   "box(center=[0, 0.25, 0], size=[0.5, 0.5, 0.5])\n", dir, 512);
    if (!o.ok)
        return;
    double want[2], got[2];
    got[0] = penumbra_width(&o, 0.03, &want[0]);
    got[1] = penumbra_width(&o, 0.06, &want[1]);
    fprintf(stderr, "penumbra: %.3f wide at 5.4 degrees (cone: %.3f), %.3f at 10.8 (%.3f)\n",
            got[0], want[0], got[1], want[1]);
    for (int k = 0; k < 2; k++)
        CHECK(got[k] > 0.75 * want[k] && got[k] < 1.25 * want[k]);
    CHECK(got[1] > 1.6 * got[0] && got[1] < 2.4 * got[0]); /* it follows the angle */
    one_light_free(&o);
}

static void test_count_mismatch(void)
{
    void *params = node_params(&ssg_node_probe_light, NULL, 0);
    struct ssg_shape in[5] = {{W, H, 3, SSG_T_VECTOR}, {W, H, 3, SSG_T_VECTOR},
                              {W, H, 3, SSG_T_COLOR}, {16, 2, 3, SSG_T_LIGHTS},
                              {64, 64, 8, SSG_T_SHADOWMAPS}};
    struct ssg_shape out[2] = {{W, H, 3, SSG_T_COLOR}, {W, H, 1, SSG_T_SCALAR}};
    char why[256] = "";
    CHECK_EQ(ssg_node_probe_light.check(params, &FRAME, in, out, why, sizeof why),
             SSG_E_CHANNELS);
    fprintf(stderr, "refused: %s\n", why);
    CHECK(strstr(why, "8 maps but lights has 16") != NULL);
    free(params);
}

/* CPU and GL on one G-buffer, light list and maps, with the parameters sets. */
static void parity_case(const struct ssg_scene *s, const struct gbuf *g,
                        const struct ssg_image *l, const struct ssg_image *m,
                        const char *const *sets, int set_count, const char *name)
{
    struct ssg_image *cpu[2], *gl[2];
    light(s, g, l, m, sets, set_count, SSG_BACKEND_CPU, cpu);
    light(s, g, l, m, sets, set_count, SSG_BACKEND_GL, gl);
    /* Measured on llvmpipe: identical (max 0), hard and soft, and so is the descriptor's
       bound. A binary test that flips where a driver rounds a texel coordinate or a depth
       otherwise than the CPU would move one light's share of a pixel (~1/24 of it here, a
       tap's share of that with soft lookups): such a driver needs a bound of its own. */
    for (int k = 0; k < 2; k++)
        parity_check_output("probe_light", name, k ? "visibility" : "out", cpu[k], gl[k],
                            parity_tol_of("probe_light"));
    for (int i = 0; i < 2; i++) {
        ssg_image_destroy(&cpu[i]);
        ssg_image_destroy(&gl[i]);
    }
}

static void test_parity(void)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load("examples/courtyard.scene", 1, &s, &d), SSG_OK);
    if (!s)
        return;
    struct gbuf g = gbuffer(s);
    float dirs[24][3];
    for (int i = 0; i < 24; i++) { /* a spiral over the upper hemisphere and a few below */
        double y = 1.0 - (2.0 * i + 1.0) / 20, r = sqrt(fmax(0, 1 - y * y)), a = 2.4 * i;
        dirs[i][0] = (float)(r * cos(a)), dirs[i][1] = (float)y,
        dirs[i][2] = (float)(r * sin(a));
    }
    struct ssg_image *l = light_list(dirs, 24), *m = maps_of(s, l, 256);
    const char *hard[] = {"softness=0"};
    parity_case(s, &g, l, m, NULL, 0, "soft");
    parity_case(s, &g, l, m, hard, 1, "hard");
    white_receiver = 1; /* the shader's unbound albedo */
    parity_case(s, &g, l, m, NULL, 0, "white");
    white_receiver = 0;
    ssg_image_destroy(&m);
    ssg_image_destroy(&l);
    gbuf_free(&g);
    ssg_scene_destroy(&s);
}

int main(void)
{
    test_unshadowed_sum();
    test_interleave();
    test_open_floor();
    test_box_shadow();
    test_bleeding();
    test_wall_foot();
    test_penumbra();
    test_count_mismatch();
    test_parity();
    return check_report();
}
