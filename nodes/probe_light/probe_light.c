/* probe_light.c - the `probe_light` node: the global part of Knuth and Kohlhammer's hybrid
 * AO. Per pixel of a view-space G-buffer, the light of every directional light of a light
 * list (`lightprobe`) that its shadow map (`shadowmaps`) does not block:
 *   out = albedo / pi * sum_i V_i max(0, N.l_i) E_i
 *   visibility = sum_i V_i max(0, N.l_i) lum(E_i) / sum_i max(0, N.l_i) lum(E_i)
 * (1 where no light reaches the pixel; background pixels: out 0, visibility 1).
 *
 * Method: sec. 3 "Global part", sec. 4 and fig. 5 (the lighting stage reads the light list,
 * the shadow map list and the G-buffer, and transforms each point into shadow map space),
 * fig. 1 (the shadow's test moved a short way behind the occluder so the occluder's front
 * does not shadow itself: lit when depth <= map + offset) and fig. 8 (noise added to the
 * shadow map sample position, stored in a small tiled texture, for smoother shadows at the
 * price of a larger offset). The paper gives no values and no formula: the offsets and the
 * noise radius are in map texels (every map has the same texel, nodes/common/shadowmap.h).
 * A lookup lands up to e = 0.7 texel (rounding) + noise_radius from the pixel's own texel,
 * where its own surface is e tan(N, l) texels deeper when the light grazes it. A depth
 * offset that large (a slope-scaled bias, up to 21 texels at tan 10) hides that
 * self-shadowing but lets light through a zero-thickness wall over that many texels: the
 * leak at a wall's foot (issue 16: 0.33 where the truth is 0.04 in the Cornell box's
 * seams). So the point is moved instead, along its normal by normal_offset x sin(N, l)
 * texels before the lookup ("normal offset shadows", Holbert, GDC 2011): its own surface
 * then lies normal_offset / cos(N, l) x sin(N, l) >= e tan(N, l) behind it along l, for
 * every angle, while an occluder across a seam stays in front of it (moving along the
 * floor's normal does not bring a floor point nearer the wall). What is left is the
 * constant `offset` (depth rounding of the map) and e tan of the occluder's own slope: a
 * wall leaks over about offset + e texels, not 20. slope_offset (default 0) keeps the old
 * slope-scaled term for those who want it. The
 * tile holds offsets spread over the unit disc (a Vogel spiral placed by a seeded
 * permutation), rotated for light i by i golden angles so that one pixel's lookups differ
 * across lights; one nearest-texel comparison per light, no filtering. Without shadow maps
 * every V_i = 1: the paper's figure 11 panel without self-shadowing. */
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
        !ssg_shape_same_size(&in[SSG_PROBE_LIGHT_IN_POSITION],
                             &in[SSG_PROBE_LIGHT_IN_ALBEDO])) {
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

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_probe_light_params *p = params;
    struct ssg_probe_light_consts *c = consts;
    enum ssg_err e = ssg_trace_camera(ctx, c->rot, c->eye);
    if (e)
        return e;
    if (p->noise_tile < 1 || p->noise_tile > SSG_PROBE_LIGHT_MAX_TILE)
        return ssg_node_fail(ctx, SSG_E_VALUE, "noise_tile out of range");
    c->p = *p;
    c->sphere = ssg_scene_bounding_sphere(ctx->scene);
    make_noise(p->noise_tile, ctx->frame ? ctx->frame->seed : 1, c->noise);
    const struct ssg_shape *maps = &ctx->in_shape[SSG_PROBE_LIGHT_IN_SHADOWMAPS];
    c->count = ctx->in_shape[SSG_PROBE_LIGHT_IN_LIGHTS].width;
    c->res = maps->channels ? maps->width : 0;
    float texel = c->res ? 2.0f * c->sphere.radius / (float)c->res : 0.0f;
    c->offset_world = c->p.offset * texel;
    c->slope_world = c->p.slope_offset * texel;
    c->normal_world = c->p.normal_offset * texel;
    ssg_probe_light_rotations(c->count, c->cos_sin);
    return SSG_OK;
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

static const struct ssg_param_desc params[] = {
    {.name = "offset", SSG_FIELD_FLOAT(struct ssg_probe_light_params, offset), .def = 0.5,
     .min = 0, .max = 1000, .unit = "texels",
     .help = "a point is lit when its depth <= the map's + offset (fig. 1): larger hides "
             "self-shadowing, lets light through thin occluders"},
    {.name = "slope_offset", SSG_FIELD_FLOAT(struct ssg_probe_light_params, slope_offset),
     .def = 0, .min = 0, .max = 1000, .unit = "texels",
     .help = "more depth offset where the light grazes the surface: + slope_offset x "
             "tan(N, l) texels (tan up to 10); leaks through thin walls, normal_offset is "
             "the default remedy"},
    {.name = "normal_offset", SSG_FIELD_FLOAT(struct ssg_probe_light_params, normal_offset),
     .def = 2, .min = 0, .max = 1000, .unit = "texels",
     .help = "the lookup point moves along the normal by normal_offset x sin(N, l) texels: "
             "no self-shadowing where the light grazes, no leak at a wall's foot (>= 0.7 + "
             "noise_radius)"},
    {.name = "noise_radius", SSG_FIELD_FLOAT(struct ssg_probe_light_params, noise_radius),
     .def = 1, .min = 0, .max = 64, .unit = "texels",
     .help = "jitter of the map lookup (fig. 8): smoother shadows, needs a larger offset; "
             "0 = none"},
    {.name = "noise_tile", SSG_FIELD_INT(struct ssg_probe_light_params, noise_tile), .def = 4,
     .min = 1, .max = SSG_PROBE_LIGHT_MAX_TILE, .unit = "px",
     .help = "side of the tiled jitter pattern"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_PROBE_LIGHT_IN_POSITION] = {.name = "position", .types = SSG_T_VECTOR,
                                  .doc = "view-space position (gbuffer)"},
    [SSG_PROBE_LIGHT_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR,
                                .doc = "unit view-space normal, 0 = background (gbuffer)"},
    [SSG_PROBE_LIGHT_IN_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR,
                                .doc = "diffuse albedo, linear RGB (gbuffer)"},
    [SSG_PROBE_LIGHT_IN_LIGHTS] = {.name = "lights", .types = SSG_T_LIGHTS,
                                .doc = "light list (lightprobe)"},
    [SSG_PROBE_LIGHT_IN_SHADOWMAPS] = {.name = "shadowmaps", .types = SSG_T_SHADOWMAPS,
     .optional = 1, .doc = "one map per light (shadowmaps); unconnected: no shadows"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_PROBE_LIGHT_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_PROBE_LIGHT_OUT_OUT] = {.name = "out", .types = SSG_T_COLOR,
     .doc = "albedo / pi * sum of shadowed Lambert light, linear RGB (like "
            "gbuffer.environment, with self-shadowing)"},
    [SSG_PROBE_LIGHT_OUT_VISIBILITY] = {.name = "visibility", .types = SSG_T_SCALAR,
     .doc = "the lit fraction of the pixel's light (luminance-weighted), comparable with AO"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_PROBE_LIGHT_OUTPUTS, "one entry a port enumerator");

/* Flops per pixel (node.h), by reading probe_light_cpu.c: per light about 15 for the
   cosine and the sums, 45 more with shadow maps (the normal offset, the light-space
   projection, the jitter, the slope-scaled depth test); about 20 a pixel to store. Lights
   behind a whole chunk are skipped, so this counts every light: an upper bound. */
static double probe_light_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_probe_light_consts *c = consts;
    (void)in;
    return 20.0 + c->count * (15.0 + (c->res > 0 ? 45.0 : 0.0));
}

const struct ssg_node_desc ssg_node_probe_light = {
    .name = "probe_light",
    .summary = "hybrid AO global part: a light list through its shadow maps (Knuth/Kohlhammer)",
    .method = "Knuth and Kohlhammer, A Hybrid Ambient Occlusion Technique for Dynamic Scenes, "
              "sec. 3 and 4, figs. 1, 5 and 8: sum over lights of shadow-map visibility x "
              "Lambert x irradiance, the test shifted behind the occluder, jittered lookups "
              "from a tiled noise texture (values and formula ours: the paper gives none)",
    .doc = "Lights every pixel by every light of the list that reaches it: out = albedo / pi "
           "* sum_i V_i max(0, N.l_i) E_i, with V_i from light i's shadow map: the point is "
           "lit when its depth along the light is at most the map's depth plus `offset` "
           "texels, read at its texel moved by a jitter of up to `noise_radius` texels from "
           "a noise_tile x noise_tile pattern, turned per light. Larger offset and noise "
           "give smoother shadows and less self-shadowing but let light bleed under thin "
           "occluders (fig. 1, 7), which the local part (ssao mode=sphere) darkens again; "
           "`visibility` is the lit share of the pixel's light. Without shadow maps it is "
           "the unshadowed lighting of the same lights.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_probe_light_params),
    .consts_size = sizeof(struct ssg_probe_light_consts),
    .needs_scene = 1,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = probe_light_flops,
    .run_cpu = ssg_probe_light_run_cpu,
    .run_gl = ssg_probe_light_run_gl,
};
