/* direct_light.c - the `direct_light` node's descriptor, checks and prepare: the scene's own
 * lights on a G-buffer, shadowed through their maps. Method and conventions: README.md. */
#include <stdio.h>

#include "direct_light.h"
#include "scene/scene.h"
#include "common/sampling.h"
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

/* The maps direct_light reads: the own lights', directional ones in `tiles`. */
static struct ssg_lightmap_sources sources(const struct ssg_direct_light_params *p)
{
    return (struct ssg_lightmap_sources){1, 0, p->tiles};
}

/* The maps must be this scene's (check_scene of node.h). */
static enum ssg_err check_scene(const void *params, const struct ssg_scene *scene,
                                const struct ssg_shape *in, struct ssg_shape *out, char *why,
                                size_t why_len)
{
    const struct ssg_direct_light_params *p = params;
    (void)out;
    int need = ssg_lightmap_face_count(scene, sources(p));
    int have = in[SSG_DIRECT_LIGHT_IN_MAPS].channels;
    if (have != need) {
        snprintf(why, why_len, "maps has %d faces but the scene's lights need %d (6 a point "
                 "light or a spot wider than 60 degrees, tiles^2 = %d a directional light, "
                 "1 a narrower spot): connect the depth output of a lightmaps node of the "
                 "same scene with own=true, environment=0 and the same tiles (direct_light "
                 "reads the own lights' maps only)", have, need, p->tiles * p->tiles);
        return SSG_E_CHANNELS;
    }
    return SSG_OK;
}

/* The lights of the scene in map order, each with its first face. */
static void make_lights(const struct ssg_scene *s, struct ssg_direct_light_consts *c)
{
    c->u.lights = 0;
    for (int f = 0; f < c->face_count; f++) {
        const struct ssg_lightmap_face *face = &c->faces[f];
        if (face->light < 0 || (f > 0 && c->faces[f - 1].light == face->light))
            continue;
        const struct ssg_light *l = &s->lights[face->light];
        struct ssg_direct_light_light *d = &c->light[c->u.lights++];
        *d = (struct ssg_direct_light_light){.point = !face->ortho, .face = f,
                                             .cube = !face->ortho &&
                                                     ssg_lightmap_light_faces(l, 1) > 1,
                                             .tiles = face->ortho ? c->p.tiles : 1,
                                             .cone_scale = l->cone_scale,
                                             .cone_offset = l->cone_offset};
        for (int k = 0; k < 3; k++) {
            d->pos[k] = l->position[k];
            d->dir[k] = l->direction[k];
            d->color[k] = l->color[k];
        }
        d->intensity = l->intensity;
        d->texel = 2.0f * face->half / (float)c->u.res;
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
    int need = ssg_lightmap_face_count(ctx->scene, sources(p));
    if (maps->channels != need) /* a graph refuses it first (check_scene) */
        return ssg_node_fail(ctx, SSG_E_SCENE, "maps has %d faces but the scene's lights "
                             "need %d: connect the depth output of a lightmaps node of the "
                             "same scene", maps->channels, need);
    c->p = *p;
    c->u.res = maps->width;
    c->face_count = need;
    struct ssg_lightmap_view view = {ctx->frame, &ctx->scene->camera, maps->width};
    if (ssg_lightmap_faces_fit(ctx->scene, sources(p), p->fit, &view, c->faces,
                               SSG_LIGHTMAP_FACES_MAX) < 0)
        return ssg_node_fail(ctx, SSG_E_SCENE, "the scene's lights need more than %d map "
                             "faces", SSG_LIGHTMAP_FACES_MAX);
    ssg_camera_frame(&ctx->scene->camera, c->u.rot, c->u.eye);
    if (ssg_sampling_projection(ctx, &ctx->in_shape[SSG_DIRECT_LIGHT_IN_POSITION], &c->u.proj))
        return SSG_E_VALUE;
    for (int k = 0; k < p->samples; k++) {
        double r = sqrt((k + 0.5) / p->samples), a = GOLDEN_ANGLE * k;
        c->taps[2 * k] = (float)(r * cos(a));
        c->taps[2 * k + 1] = (float)(r * sin(a));
    }
    make_lights(ctx->scene, c);
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_direct_light_params, SSG_DIRECT_LIGHT_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_direct_light_uniforms, SSG_DIRECT_LIGHT_UNIFORMS);
SSG_PORT_TABLE(inputs, SSG_DIRECT_LIGHT_IN);
SSG_PORT_TABLE(outputs, SSG_DIRECT_LIGHT_OUT);

const struct ssg_node_desc ssg_node_direct_light = {
    .name = "direct_light",
    .summary = "direct light of the scene's own lights with shadows (PCF, optional PCSS)",
    .method = "Williams 1978 (shadow maps); Reeves, Salesin and Cook, SIGGRAPH 1987 (PCF); "
              "Fernando, Percentage-Closer Soft Shadows, SIGGRAPH 2005 (blocker search, "
              "penumbra = size (d_r - d_b) / d_b); Holbert, GDC 2011 (normal offset)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_direct_light_params),
    .consts_size = sizeof(struct ssg_direct_light_consts),
    SSG_NODE_UNIFORMS(uniforms, struct ssg_direct_light_consts, u),
    .reads = SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS | SSG_READS_CAMERA,
    .check = check,
    .check_scene = check_scene,
    .prepare = prepare,
    .run_cpu = ssg_direct_light_run_cpu,
    .run_gl = ssg_direct_light_run_gl,
    .parity = {.max = 2e-5, .mean = 4.4e-8}, /* test_gl_direct_light.c: 5.1e-6, 1.1e-8: 4x */
};
