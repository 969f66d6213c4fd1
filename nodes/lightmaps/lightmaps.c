/* lightmaps.c - the `lightmaps` node's descriptor, checks and prepare: shadow and reflective
 * shadow maps of the scene's own lights. Method and conventions: README.md. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "graph/image.h"
#include "scene/proxy.h"
#include "scene/scene.h"
#include "scene/scene_shapes.h"
#include "lightmaps.h"
#include "common/env_lights.h"

/* The lights the parameters ask for. */
static struct ssg_lightmap_sources sources(const struct ssg_lightmaps_params *p)
{
    return (struct ssg_lightmap_sources){p->own, p->environment, p->tiles};
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_lightmaps_params *p = params;
    (void)frame, (void)in;
    enum ssg_err e = ssg_lightmap_sources_check(sources(p), why, why_len);
    if (e)
        return e;
    static const int per_face[SSG_LIGHTMAPS_OUTPUTS] = {1, 3, 3};
    for (int i = 0; i < SSG_LIGHTMAPS_OUTPUTS; i++)
        out[i] = (struct ssg_shape){p->resolution, p->resolution, per_face[i],
                                    SSG_T_LIGHTMAPS};
    return SSG_OK;
}

/* The scene's face count sets the channels; refused over the image limits. */
static enum ssg_err check_scene(const void *params, const struct ssg_scene *scene,
                                const struct ssg_shape *in, struct ssg_shape *out, char *why,
                                size_t why_len)
{
    const struct ssg_lightmaps_params *p = params;
    (void)in;
    long long f = ssg_lightmap_face_count(scene, sources(p)), r = p->resolution;
    if (f > SSG_LIGHTMAP_FACES_MAX) {
        snprintf(why, why_len, "the lights need %lld map faces (own lights: 6 a point light, "
                 "tiles^2 a directional light; plus %d environment lights), at most %d fit the normal "
                 "and flux images' %d channels: lower environment or the light count", f,
                 p->environment, SSG_LIGHTMAP_FACES_MAX, SSG_IMAGE_MAX_CHANNELS);
        return SSG_E_SIZE;
    }
    if (3 * f * r * r > SSG_IMAGE_MAX_FLOATS) {
        snprintf(why, why_len, "%lld faces of %lld x %lld need %.1f GiB for the normal and "
                 "flux images each, over the limit of %.1f GiB an image "
                 "(SSG_IMAGE_MAX_FLOATS): lower the resolution or the light count", f, r, r,
                 (double)(3 * f * r * r) * 4.0 / (1 << 30),
                 (double)SSG_IMAGE_MAX_FLOATS * 4.0 / (1 << 30));
        return SSG_E_SIZE;
    }
    out[SSG_LIGHTMAPS_OUT_DEPTH].channels = (int)f;
    out[SSG_LIGHTMAPS_OUT_NORMAL].channels = 3 * (int)f;
    out[SSG_LIGHTMAPS_OUT_FLUX].channels = 3 * (int)f;
    return SSG_OK;
}

/* The flux factor of each face (lightmap.h): orthographic E (2 half / R)^2, cube I (the
   texel's solid angle is applied per texel). env_e: the environment lights' irradiances
   (3 a light), NULL without environment light. */
static void face_flux(const struct ssg_scene *s, const struct ssg_lightmaps_consts *c,
                      int f, const double *env_e, float flux[3])
{
    const struct ssg_lightmap_face *face = &c->faces[f];
    float area = 1.0f;
    if (face->ortho) {
        float side = 2.0f * face->half / (float)c->res;
        area = side * side;
    }
    int env = ssg_lightmap_face_env(face);
    for (int k = 0; k < 3; k++) {
        float e = 0.0f;
        if (env >= 0)
            e = env_e ? (float)env_e[3 * env + k] : 0.0f;
        else if (face->light >= 0)
            e = s->lights[face->light].color[k] * s->lights[face->light].intensity;
        flux[k] = e * area;
    }
}

/* The environment lights' irradiances (env_lights.h's regions of their directions),
   3 a light, into *e (malloc'd); *e stays NULL when there are none or the scene has no
   environment light (its faces then stay empty). */
static enum ssg_err env_irradiance(const struct ssg_scene *s, int count, double **e)
{
    *e = NULL;
    if (count == 0 || !s->env || !s->env->has_light)
        return SSG_OK;
    float dirs[3 * SSG_LIGHTMAP_ENV_MAX];
    ssg_lightmap_env_directions(s, count, dirs);
    *e = malloc(sizeof(double) * 3 * (size_t)count);
    enum ssg_err err = *e ? ssg_env_lights_regions(s->env, dirs, count, *e) : SSG_E_NOMEM;
    if (err) {
        free(*e);
        *e = NULL;
    }
    return err;
}

static int has_flux(const float flux[3])
{
    return flux[0] > 0.0f || flux[1] > 0.0f || flux[2] > 0.0f;
}

/* The faces as lightmaps.glsl reads them (lightmaps.h); radius: the scene's. */
static void pack_faces(const struct ssg_scene *s, struct ssg_lightmaps_consts *c,
                       float radius)
{
    for (int i = 0; i < c->count; i++) {
        const struct ssg_lightmap_face *face = &c->faces[i];
        float *o = c->face_floats + (size_t)i * SSG_LIGHTMAPS_FACE_FLOATS;
        for (int k = 0; k < 3; k++) {
            o[k] = face->origin[k], o[3 + k] = face->u[k], o[6 + k] = face->v[k];
            o[9 + k] = face->axis[k], o[14 + k] = c->flux[i][k];
        }
        /* an own light's map is drawn even when it is dark (its shadows still count); an
           environment light's only when it carries light */
        int drawn = face->light >= 0 ||
                    (ssg_lightmap_face_env(face) >= 0 && has_flux(c->flux[i]));
        o[12] = face->half, o[13] = (float)face->ortho, o[17] = (float)drawn;
        o[18] = radius;
        /* the spot's cone (ssg_cone_falloff; a point light's passes everything) */
        const struct ssg_light *l = face->light >= 0 ? &s->lights[face->light] : NULL;
        o[19] = l ? l->cone_scale : 0.0f, o[20] = l ? l->cone_offset : 1.0f;
        for (int k = 0; k < 3; k++)
            o[21 + k] = l ? l->direction[k] : 0.0f;
    }
}

static float box_distance(const float lo[3], const float hi[3], const float o[3])
{
    float d2 = 0.0f;
    for (int k = 0; k < 3; k++) {
        float out = fmaxf(fmaxf(lo[k] - o[k], o[k] - hi[k]), 0.0f);
        d2 += out * out;
    }
    return sqrtf(d2);
}

static int face_drawn(const struct ssg_lightmaps_consts *c, int f)
{
    return c->face_floats[(size_t)f * SSG_LIGHTMAPS_FACE_FLOATS + 17] != 0.0f;
}

/* The finest texel of the drawn faces where they meet a dense mesh (one a proxy may
   simplify, scene/proxy.h): an orthographic face's texels are 2 half / R wide everywhere,
   a perspective face's 2 half d / R at distance d from its light, d from the nearest dense
   mesh's box (0 for a light inside one: the scene is then drawn as it is). */
static float finest_texel(const struct ssg_scene *s, const struct ssg_lightmaps_consts *c)
{
    float nearest = INFINITY, texel = INFINITY;
    int perspective = 0; /* only a drawn perspective face needs the meshes' boxes */
    for (int f = 0; f < c->count; f++)
        perspective |= !c->faces[f].ortho && face_drawn(c, f);
    for (int i = 0; perspective && i < s->mesh_count; i++) {
        if (!ssg_proxy_mesh_dense(s, i))
            continue;
        float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        ssg_mesh_bounds(&s->meshes[i], lo, hi);
        for (int f = 0; f < c->count; f++)
            if (!c->faces[f].ortho && face_drawn(c, f))
                nearest = fminf(nearest, box_distance(lo, hi, c->faces[f].origin));
    }
    for (int f = 0; f < c->count; f++) {
        const struct ssg_lightmap_face *face = &c->faces[f];
        float width = 2.0f * face->half / (float)c->res;
        if (face_drawn(c, f))
            texel = fminf(texel, face->ortho ? width : width * nearest);
    }
    return texel;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_lightmaps_params *p = params;
    struct ssg_lightmaps_consts *c = consts;
    if (!ctx->scene)
        return ssg_node_fail(ctx, SSG_E_VALUE, "needs a scene");
    c->res = p->resolution;
    struct ssg_lightmap_view view = {ctx->frame, &ctx->scene->camera, p->resolution};
    c->count = ssg_lightmap_faces_fit(ctx->scene, sources(p), p->fit, &view, c->faces,
                                      SSG_LIGHTMAP_FACES_MAX);
    if (c->count < 0 || c->count != ctx->out_shape[SSG_LIGHTMAPS_OUT_DEPTH].channels)
        return ssg_node_fail(ctx, SSG_E_SCENE, "the scene's lights need %d map faces, the "
                             "depth image bound has %d channels (a graph sizes it itself)",
                             ssg_lightmap_face_count(ctx->scene, sources(p)),
                             ctx->out_shape[SSG_LIGHTMAPS_OUT_DEPTH].channels);
    double *env_e;
    if (env_irradiance(ctx->scene, p->environment, &env_e))
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the environment's lights");
    struct ssg_bounding_sphere sphere = ssg_scene_bounding_sphere(ctx->scene);
    c->u.near_z = SSG_LIGHTMAPS_NEAR * sphere.radius;
    c->u.far_z = 0.0f;
    for (int f = 0; f < c->count; f++) {
        face_flux(ctx->scene, c, f, env_e, c->flux[f]);
        const float *o = c->faces[f].origin;
        float d[3] = {o[0] - sphere.centre[0], o[1] - sphere.centre[1], o[2] - sphere.centre[2]};
        float far = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + sphere.radius;
        c->u.far_z = far * 1.01f > c->u.far_z ? far * 1.01f : c->u.far_z;
    }
    free(env_e);
    pack_faces(ctx->scene, c, sphere.radius);
    /* a light map's texels place the far bounce's lights, whose light near a contact
       follows their position closely: proxies held 4x closer than a shadow map's */
    c->texel = p->proxy ? 0.25f * finest_texel(ctx->scene, c) : INFINITY;
    return SSG_OK;
}

/* The camera only where a directional light's map follows it (a point light's cube does
   not): without a scene, the camera too. */
static unsigned reads_of(const void *params, const struct ssg_scene *scene)
{
    const struct ssg_lightmaps_params *p = params;
    int follows = p->fit == SSG_LIGHTMAP_FIT_VIEW && p->own;
    for (int i = 0; follows && scene && i < scene->light_count; i++)
        if (scene->lights[i].kind == SSG_LIGHT_DIRECTIONAL)
            return SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS | SSG_READS_CAMERA;
    return SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS |
           (follows && !scene ? SSG_READS_CAMERA : 0);
}

SSG_PARAMS_TABLE(params, ssg_lightmaps_params, SSG_LIGHTMAPS_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_lightmaps_uniforms, SSG_LIGHTMAPS_UNIFORMS);
SSG_PORT_TABLE(outputs, SSG_LIGHTMAPS_OUT);

const struct ssg_node_desc ssg_node_lightmaps = {
    .name = "lightmaps",
    .summary = "shadow and reflective shadow maps of the scene's point, spot and directional lights",
    .method = "Williams 1978 (shadow maps); a cube of six faces a point light (Gerasimov, GPU "
              "Gems ch. 12); Dachsbacher and Stamminger, Reflective Shadow Maps, I3D 2005, "
              "sec. 3 (depth, normal, flux per texel); faces of nodes/common/lightmap.h",
    SSG_NODE_OUTPUTS(outputs),
    SSG_NODE_PARAMS(params, struct ssg_lightmaps_params),
    .consts_size = sizeof(struct ssg_lightmaps_consts),
    SSG_NODE_UNIFORMS(uniforms, struct ssg_lightmaps_consts, u),
    /* the lights' own views, in world space; fit=view follows the camera (reads_of) */
    .reads = SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS | SSG_READS_CAMERA,
    .reads_of = reads_of,
    .check = check,
    .check_scene = check_scene,
    .prepare = prepare,
    .run_cpu = ssg_lightmaps_run_cpu,
    .run_gl = ssg_lightmaps_run_gl,
};
