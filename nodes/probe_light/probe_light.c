/* probe_light.c - the `probe_light` node's descriptor, check and prepare: the global part of
 * Knuth and Kohlhammer's hybrid AO. The method, its sources and choices: README.md here. */
#include <stdio.h>

#include "probe_light.h"
#include "common/random.h"
#include "scene/scene.h"
#include "common/trace.h"

static const double GOLDEN_ANGLE = 2.39996322972865332; /* pi (3 - sqrt 5) */

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    (void)params;
    (void)frame;
    const struct ssg_shape *lights = &in[SSG_PROBE_LIGHT_IN_LIGHTS];
    const struct ssg_shape *maps = &in[SSG_PROBE_LIGHT_IN_SHADOWMAPS];
    if (lights->width > SSG_LIGHTS_MAX) {
        snprintf(why, why_len, "lights has %d lights, at most %d", lights->width,
                 SSG_LIGHTS_MAX);
        return SSG_E_SIZE;
    }
    if (maps->channels && maps->channels != lights->width) {
        snprintf(why, why_len, "shadowmaps has %d maps but lights has %d lights: connect "
                 "the shadowmaps node made from the same light list", maps->channels,
                 lights->width);
        return SSG_E_CHANNELS;
    }
    if (!ssg_shape_same_size(&in[SSG_PROBE_LIGHT_IN_POSITION],
                             &in[SSG_PROBE_LIGHT_IN_NORMAL]) ||
        (in[SSG_PROBE_LIGHT_IN_ALBEDO].channels &&
         !ssg_shape_same_size(&in[SSG_PROBE_LIGHT_IN_POSITION],
                              &in[SSG_PROBE_LIGHT_IN_ALBEDO]))) {
        snprintf(why, why_len, "position, normal and albedo must have one size");
        return SSG_E_SIZE;
    }
    out[0].width = out[1].width = in[SSG_PROBE_LIGHT_IN_POSITION].width;
    out[0].height = out[1].height = in[SSG_PROBE_LIGHT_IN_POSITION].height;
    return SSG_OK;
}

/* tile^2 offsets spread evenly over the unit disc (Vogel's spiral: radius sqrt((k + 0.5) /
   n), angle k golden angles plus a seeded turn), on the tile by a seeded permutation. */
static void make_noise(int tile, uint64_t seed, float *noise)
{
    int n = tile * tile, perm[SSG_PROBE_LIGHT_MAX_TILE * SSG_PROBE_LIGHT_MAX_TILE];
    uint64_t state = seed ^ 0x3C6EF372FE94F82Bull;
    double turn = 2.0 * M_PI * ssg_random_unit(&state);
    ssg_random_permutation(&state, perm, n);
    for (int k = 0; k < n; k++) {
        double r = sqrt((k + 0.5) / n), a = turn + GOLDEN_ANGLE * k;
        noise[perm[k]] = (float)(r * cos(a));
        noise[n + perm[k]] = (float)(r * sin(a));
    }
}

/* The soft lookups' taps: n offsets spread evenly over the unit disc (Vogel's spiral, as
   the jitter's but fixed: every pixel reads the same pattern, turned per light, so no
   pixel differs from its neighbour by chance). The first is the centre: a thin occluder
   right over the pixel (a wall seen edge-on) is never missed by the blocker search, and
   the filter's first tap is the search's first (read once). */
static void make_taps(int n, float *tap)
{
    for (int k = 0; k < n; k++) {
        double r = sqrt(k / (n - 0.5)), a = GOLDEN_ANGLE * k;
        tap[k] = (float)(r * cos(a));
        tap[n + k] = (float)(r * sin(a));
    }
}

/* tan of the cone a light of N stands for: N uniform lights (lightprobe's default) each
   gather the solid angle 4 pi / N, a cap of half-angle acos(1 - 2 / N); times softness,
   at most 45 degrees (a list of very few lights would otherwise make hemispheres). */
static double cone_tan_of(int count, double softness)
{
    double half = softness * acos(1.0 - 2.0 / (count > 1 ? count : 1));
    return tan(half < M_PI / 4 ? half : M_PI / 4);
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_probe_light_params *p = params;
    struct ssg_probe_light_consts *c = consts;
    enum ssg_err e = ssg_trace_camera(ctx, c->rot, c->eye);
    if (e)
        return e;
    c->p = *p;
    c->sphere = ssg_scene_bounding_sphere(ctx->scene);
    make_noise(p->noise_tile, ctx->frame ? ctx->frame->seed : 1, c->noise);
    const struct ssg_shape *maps = &ctx->in_shape[SSG_PROBE_LIGHT_IN_SHADOWMAPS];
    c->u.count = ctx->in_shape[SSG_PROBE_LIGHT_IN_LIGHTS].width;
    c->u.res = maps->channels ? maps->width : 0;
    c->frame_res = c->u.res ? c->u.res : 1;
    float texel = c->u.res ? 2.0f * c->sphere.radius / (float)c->u.res : 0.0f;
    c->u.texel = texel;
    c->u.cone_tan = p->softness > 0 && c->u.res ? (float)(cone_tan_of(c->u.count, p->softness) /
                                                      texel) : 0.0f;
    make_taps(p->taps, c->tap);
    make_taps(p->search_taps, c->tap + 2 * p->taps);
    c->u.offset_world = c->p.offset * texel;
    c->u.slope_world = c->p.slope_offset * texel;
    c->u.normal_world = c->p.normal_offset * texel;
    ssg_probe_light_rotations(c->u.count, c->cos_sin);
    return SSG_OK;
}

/* noise_radius is read by the runs alone (p_noise_radius on GL, ctx->params on the CPU):
   a change of it alone keeps prepare()'s camera, noise tile and rotations (node.h). */
static unsigned check_params(const void *old_params, const void *new_params)
{
    return SSG_PARAMS_ONLY_CHANGED(struct ssg_probe_light_params, old_params, new_params,
                                   noise_radius)
               ? SSG_RECOMPUTE_RUN
               : SSG_RECOMPUTE_PREPARE;
}

static void rotate(const float rot[9], const float w[3], float out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = rot[3 * i] * w[0] + rot[3 * i + 1] * w[1] + rot[3 * i + 2] * w[2];
}

void ssg_probe_light_frame(const struct ssg_probe_light_consts *c, const float l[3], int res,
                           float frame[SSG_PROBE_LIGHT_FRAME])
{
    struct ssg_shadow_frame f = ssg_shadow_frame_make(&c->sphere, l);
    float s = 0.5f * (float)res / f.radius;
    float e[3] = {c->eye[0] - f.origin[0], c->eye[1] - f.origin[1], c->eye[2] - f.origin[2]};
    float ru[3], rv[3], rl[3];
    rotate(c->rot, f.u, ru);
    rotate(c->rot, f.v, rv);
    rotate(c->rot, f.l, rl);
    for (int k = 0; k < 3; k++) {
        frame[k] = s * ru[k];
        frame[4 + k] = s * rv[k];
        frame[8 + k] = -rl[k];
        frame[12 + k] = rl[k];
    }
    frame[3] = s * (e[0] * f.u[0] + e[1] * f.u[1] + e[2] * f.u[2]) + 0.5f * (float)res;
    frame[7] = s * (e[0] * f.v[0] + e[1] * f.v[1] + e[2] * f.v[2]) + 0.5f * (float)res;
    frame[11] = -(e[0] * f.l[0] + e[1] * f.l[1] + e[2] * f.l[2]);
    frame[15] = 0.0f;
}

void ssg_probe_light_rotations(int count, float *cos_sin)
{
    for (int i = 0; i < count; i++) {
        double a = GOLDEN_ANGLE * i;
        cos_sin[2 * i] = (float)cos(a);
        cos_sin[2 * i + 1] = (float)sin(a);
    }
}

/* The consts end in the lights' rotations: 2 floats a light of the list. */
static size_t consts_size_of(const void *params, const struct ssg_shape *in)
{
    (void)params;
    return sizeof(struct ssg_probe_light_consts) +
           sizeof(float) * 2 * (size_t)in[SSG_PROBE_LIGHT_IN_LIGHTS].width;
}

SSG_PARAMS_TABLE(params, ssg_probe_light_params, SSG_PROBE_LIGHT_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_probe_light_uniforms, SSG_PROBE_LIGHT_UNIFORMS);

SSG_PORT_TABLE(inputs, SSG_PROBE_LIGHT_IN);
SSG_PORT_TABLE(outputs, SSG_PROBE_LIGHT_OUT);

/* Flops per pixel (node.h), by reading probe_light_cpu.c: per light about 15 for the
   cosine and the sums, 45 more with hard shadow-map lookups (the normal offset, the light-space
   projection, the jitter, the slope-scaled depth test); about 20 a pixel to store. Lights
   behind a whole chunk are skipped, so this counts every light: an upper bound. */
static double probe_light_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_probe_light_consts *c = consts;
    (void)in;
    /* soft lookups: 55 to set a light up (point, depth, receiver slope), about 15 a tap,
       taps + search_taps taps (the filter and the search) */
    double shadow = c->u.cone_tan > 0.0f ? 55.0 + 15.0 * (c->p.taps + c->p.search_taps) : 45.0;
    return 20.0 + c->u.count * (15.0 + (c->u.res > 0 ? shadow : 0.0));
}

/* `out` is all +0 when every light carries nothing (lightprobe missing=dark on a scene
   without an environment) and no albedo multiplies the sum: probe_light_cpu.c then adds
   no light to any pixel, and so does the shader (an albedo of inf or a negative one would
   make NaN or -0 of that +0). The list (shadowmap.h): row 1 of each channel the lights'
   irradiance. */
static unsigned zero_outputs(const void *node_params, const struct ssg_image *const *in,
                             unsigned connected)
{
    (void)node_params;
    const struct ssg_image *l = in[SSG_PROBE_LIGHT_IN_LIGHTS];
    if (!l || (connected >> SSG_PROBE_LIGHT_IN_ALBEDO & 1u))
        return 0;
    int n = l->width;
    for (int c = 0; c < l->channels; c++)
        for (int i = 0; i < n; i++)
            if (l->data[(size_t)c * 2 * (size_t)n + (size_t)n + (size_t)i] != 0.0f)
                return 0;
    return 1u << SSG_PROBE_LIGHT_OUT_OUT;
}

const struct ssg_node_desc ssg_node_probe_light = {
    .name = "probe_light",
    .summary = "hybrid AO global part: a light list through its shadow maps (Knuth/Kohlhammer)",
    .method = "Knuth and Kohlhammer, A Hybrid Ambient Occlusion Technique for Dynamic Scenes, "
              "sec. 3 and 4, figs. 1, 5 and 8: sum over lights of shadow-map visibility x "
              "Lambert x irradiance, the test shifted behind the occluder, jittered lookups "
              "from a tiled noise texture (values and formula ours: the paper gives none); "
              "by default each light a cone of its share of the sphere, looked up as "
              "percentage-closer soft shadows (Fernando 2005)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_probe_light_params),
    .consts_size_of = consts_size_of,
    SSG_NODE_UNIFORMS(uniforms, struct ssg_probe_light_consts, u),
    .reads = SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS | SSG_READS_CAMERA,
    .zero_outputs = zero_outputs,
    .check = check,
    .prepare = prepare,
    .check_params = check_params,
    .flops_per_pixel = probe_light_flops,
    .run_cpu = ssg_probe_light_run_cpu,
    .run_gl = ssg_probe_light_run_gl,
    .parity = {.max = 0, .mean = 0}, /* bit-exact on llvmpipe (test_probe_light.c) */
};
