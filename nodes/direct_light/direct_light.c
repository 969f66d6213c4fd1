/* direct_light.c - the `direct_light` node: the direct light of the scene's own point and
 * directional lights on a view-space G-buffer, shadowed through their maps (`lightmaps`,
 * nodes/common/lightmap.h):
 *   out = albedo / pi * sum_i V_i E_i,  E_i = colour_i x the G-buffer's irradiance
 *         (nodes/common/direct.h: I max(0, N.L) / d^2 a point light, E max(0, N.L) a
 *         directional one),
 *   visibility = sum_i V_i lum(E_i) / sum_i lum(E_i)  (1 where no light arrives).
 * Where no map blocks a light (V = 1) out is the G-buffer's `direct` for matte materials:
 * the G-buffer carries no specular colour or shininess, so the Blinn-Phong highlight of
 * gbuffer.direct is not here (out is its diffuse part).
 *
 * Shadow test (Williams 1978), per light: the point p moves along its normal by
 * normal_offset x sin(N, L) texels ("normal offset shadows", Holbert, GDC 2011; see
 * probe_light.c for why this and not a slope-scaled offset: no leak at a wall's foot),
 * then is lit by a map texel whose surface is at least as far from the light as it, less
 * `offset` texels. A texel is 2 half / R scene units on an orthographic face and 2 d / R
 * at distance d on a cube face. Filtering: percentage-closer (Reeves, Salesin and Cook,
 * "Rendering Antialiased Shadows with Depth Maps", SIGGRAPH 1987) over `samples` taps of
 * a Vogel disc (radius sqrt((k + 0.5) / n), angle k golden angles) of radius `filter`
 * texels, each tap a bilinear blend of its four texels' 0/1 tests, the disc turned per
 * pixel by interleaved gradient noise (direct_light.h). On a cube, distances are compared
 * along the ray (the texel's depth z times |(a, b, 1)|), and a texel past the face's edge
 * is read on the neighbouring face through its direction, so the disc crosses cube edges
 * without a seam. Soft shadows (PCSS, Fernando, "Percentage-Closer Soft Shadows",
 * SIGGRAPH 2005 sketch): light_size > 0 (point lights, diameter in scene units) or
 * sun_angle > 0 (directional lights, angular diameter): a blocker search over the same
 * taps within the light's footprint (light_size / texel a point light, d tan(angle) /
 * texel the sun, d the receiver's depth), the blockers' mean distance d_b, then the PCF
 * radius grows to filter + penumbra / 2 with penumbra = light_size (d_r - d_b) / d_b
 * (point) or (d_r - d_b) tan(angle) (sun), in texels at the receiver, at most
 * SSG_DIRECT_LIGHT_MAX_RADIUS. */
#include <stdio.h>

#include "direct_light.h"
#include "scene/scene.h"
#include "common/trace.h"

static const double GOLDEN_ANGLE = 2.39996322972865332; /* pi (3 - sqrt 5) */

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    (void)params, (void)frame;
    if (!ssg_shape_same_size(&in[SSG_DIRECT_LIGHT_IN_POSITION],
                             &in[SSG_DIRECT_LIGHT_IN_NORMAL]) ||
        !ssg_shape_same_size(&in[SSG_DIRECT_LIGHT_IN_POSITION],
                             &in[SSG_DIRECT_LIGHT_IN_ALBEDO])) {
        snprintf(why, why_len, "position, normal and albedo must have one size");
        return SSG_E_SIZE;
    }
    for (int i = 0; i < SSG_DIRECT_LIGHT_OUTPUTS; i++) {
        out[i].width = in[SSG_DIRECT_LIGHT_IN_POSITION].width;
        out[i].height = in[SSG_DIRECT_LIGHT_IN_POSITION].height;
    }
    return SSG_OK;
}

/* The lights of the scene in map order, each with its first face. */
static void make_lights(const struct ssg_scene *s, struct ssg_direct_light_consts *c)
{
    c->lights = 0;
    for (int f = 0; f < ssg_lightmap_face_count(s); f++) {
        const struct ssg_lightmap_face *face = &c->faces[f];
        if (face->light < 0 || (f > 0 && c->faces[f - 1].light == face->light))
            continue;
        const struct ssg_light *l = &s->lights[face->light];
        struct ssg_direct_light_light *d = &c->light[c->lights++];
        *d = (struct ssg_direct_light_light){.point = !face->ortho, .face = f};
        for (int k = 0; k < 3; k++) {
            d->pos[k] = l->position[k];
            d->dir[k] = l->direction[k];
            d->color[k] = l->color[k];
        }
        d->intensity = l->intensity;
        d->texel = face->ortho ? 2.0f * face->half / (float)c->res : 2.0f / (float)c->res;
        d->spread = face->ortho ? tanf(c->p.sun_angle * (float)(M_PI / 180.0))
                                : c->p.light_size;
    }
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_direct_light_params *p = params;
    struct ssg_direct_light_consts *c = consts;
    if (!ctx->scene)
        return ssg_node_fail(ctx, SSG_E_SCENE, "needs a scene");
    const struct ssg_shape *maps = &ctx->in_shape[SSG_DIRECT_LIGHT_IN_MAPS];
    int need = ssg_lightmap_face_count(ctx->scene);
    if (maps->channels != need)
        return ssg_node_fail(ctx, SSG_E_CHANNELS, "maps has %d faces but the scene's lights "
                             "need %d (6 a point light, 1 a directional light): connect the "
                             "depth output of a lightmaps node of the same scene",
                             maps->channels, need);
    c->p = *p;
    c->res = maps->width;
    if (ssg_lightmap_faces(ctx->scene, c->faces, SSG_LIGHTMAP_FACES_MAX) < 0)
        return ssg_node_fail(ctx, SSG_E_SIZE, "more than %d map faces",
                             SSG_LIGHTMAP_FACES_MAX);
    ssg_camera_frame(&ctx->scene->camera, c->rot, c->eye);
    for (int k = 0; k < p->samples; k++) {
        double r = sqrt((k + 0.5) / p->samples), a = GOLDEN_ANGLE * k;
        c->taps[2 * k] = (float)(r * cos(a));
        c->taps[2 * k + 1] = (float)(r * sin(a));
    }
    make_lights(ctx->scene, c);
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "samples", SSG_FIELD_INT(struct ssg_direct_light_params, samples), .def = 12,
     .min = 1, .max = SSG_DIRECT_LIGHT_MAX_SAMPLES, .unit = "taps",
     .help = "percentage-closer taps a light (a Vogel disc turned per pixel), each a "
             "bilinear blend of four tests"},
    {.name = "filter", SSG_FIELD_FLOAT(struct ssg_direct_light_params, filter), .def = 1.5,
     .min = 0, .max = SSG_DIRECT_LIGHT_MAX_RADIUS, .unit = "texels",
     .help = "radius of the PCF disc: wider softens the map's stair steps; 0 = one bilinear "
             "test"},
    {.name = "offset", SSG_FIELD_FLOAT(struct ssg_direct_light_params, offset), .def = 0.5,
     .min = 0, .max = 1000, .unit = "texels",
     .help = "constant depth offset of the test (map rounding); larger leaks light under "
             "thin occluders"},
    {.name = "normal_offset", SSG_FIELD_FLOAT(struct ssg_direct_light_params, normal_offset),
     .def = 2, .min = 0, .max = 1000, .unit = "texels",
     .help = "the lookup point moves along the normal by normal_offset x sin(N, L) texels: "
             "no self-shadowing where the light grazes, no leak at a wall's foot"},
    {.name = "light_size", SSG_FIELD_FLOAT(struct ssg_direct_light_params, light_size),
     .def = 0, .min = 0, .max = 1e6, .unit = "scene units",
     .help = "point lights' diameter: > 0 gives contact-hardening soft shadows (PCSS); "
             "0 = hard"},
    {.name = "sun_angle", SSG_FIELD_FLOAT(struct ssg_direct_light_params, sun_angle),
     .def = 0, .min = 0, .max = 45, .unit = "degrees",
     .help = "directional lights' angular diameter (the sun: 0.53): > 0 gives PCSS soft "
             "shadows; 0 = hard"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_DIRECT_LIGHT_IN_POSITION] = {.name = "position", .types = SSG_T_VECTOR,
                                      .doc = "view-space position (gbuffer)"},
    [SSG_DIRECT_LIGHT_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR,
                                    .doc = "unit view-space normal, 0 = background (gbuffer)"},
    [SSG_DIRECT_LIGHT_IN_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR,
                                    .doc = "diffuse albedo, linear RGB (gbuffer)"},
    [SSG_DIRECT_LIGHT_IN_MAPS] = {.name = "maps", .types = SSG_T_LIGHTMAPS,
                                  .doc = "the depth of the scene's lights' maps (lightmaps)"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_DIRECT_LIGHT_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_DIRECT_LIGHT_OUT_OUT] = {.name = "out", .types = SSG_T_COLOR, .lit = 1,
     .doc = "albedo / pi x the shadowed irradiance of the scene's lights (gbuffer.direct "
            "with shadows, diffuse part)"},
    [SSG_DIRECT_LIGHT_OUT_VISIBILITY] = {.name = "visibility", .types = SSG_T_SCALAR,
     .doc = "the luminance-weighted share of the unshadowed direct light that arrives, 1 "
            "where none would"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_DIRECT_LIGHT_OUTPUTS, "one entry a port enumerator");

const struct ssg_node_desc ssg_node_direct_light = {
    .name = "direct_light",
    .summary = "direct light of the scene's own lights with shadows (PCF, optional PCSS)",
    .method = "Williams 1978 (shadow maps); Reeves, Salesin and Cook, SIGGRAPH 1987 (PCF); "
              "Fernando, Percentage-Closer Soft Shadows, SIGGRAPH 2005 (blocker search, "
              "penumbra = size (d_r - d_b) / d_b); Holbert, GDC 2011 (normal offset)",
    .doc = "Lights a view-space G-buffer by the scene's point and directional lights, each "
           "through its maps (the depth output of lightmaps): out = albedo / pi * sum V_i "
           "E_i with E_i the G-buffer's irradiance (the same code as gbuffer.direct, whose "
           "specular highlight is not here: the G-buffer has no specular colour). V_i is "
           "a percentage-closer filter of `samples` bilinear taps on a disc of `filter` "
           "texels, turned per pixel, the point moved along its normal by normal_offset "
           "texels x sin(N, L) and tested with `offset` texels of slack; cube taps past a "
           "face's edge read the neighbouring face. light_size (point lights) or sun_angle "
           "(directional) > 0 widen the disc with the blockers' distance (PCSS): sharp "
           "contact shadows, soft far ones. visibility is the lit share of the pixel's "
           "unshadowed direct light.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_direct_light_params),
    .consts_size = sizeof(struct ssg_direct_light_consts),
    .needs_scene = 1,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_direct_light_run_cpu,
};
