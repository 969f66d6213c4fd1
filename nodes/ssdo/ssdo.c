/* ssdo.c - the `ssdo` node's descriptor, check and prepare: screen-space directional
 * occlusion with one optional indirect bounce. Method and conventions: README.md. */
#include <stdio.h>
#include <string.h>

#include "scene/scene.h"
#include "ssdo.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_ssdo_params *p = params;
    const int has_albedo = in[SSG_SSDO_IN_ALBEDO].channels != 0;
    if (p->mode == SSG_SSDO_MODE_RADIANCE && !has_albedo) {
        snprintf(why, why_len, "mode radiance needs input 'albedo' (out = albedo / pi * "
                 "incoming light)");
        return SSG_E_MISSING_INPUT;
    }
    if (p->bounce && (!has_albedo || in[SSG_SSDO_IN_LIGHT].channels == 0)) {
        snprintf(why, why_len, "bounce=true needs inputs 'albedo' (the receiver) and "
                 "'light' (the senders' radiance)");
        return SSG_E_MISSING_INPUT;
    }
    if (p->channels != 1 && p->channels != 3) {
        snprintf(why, why_len, "channels must be 1 (luminance) or 3 (per channel), got %d",
                 p->channels);
        return SSG_E_VALUE;
    }
    enum ssg_err e = ssg_ssdo_check_shapes(in, &in[SSG_SSDO_IN_COUNT], why, why_len);
    if (e)
        return e;
    const struct ssg_shape *pos = &in[SSG_SSDO_IN_POSITION];
    int color = p->mode == SSG_SSDO_MODE_RADIANCE || p->channels == 3;
    out[0] = (struct ssg_shape){pos->width, pos->height, color ? 3 : 1,
                                color ? SSG_T_COLOR : SSG_T_SCALAR};
    out[1] = (struct ssg_shape){pos->width, pos->height, 3, SSG_T_COLOR};
    return SSG_OK;
}

/* The scene's lights in view space: view = R (world - eye). */
static enum ssg_err prepare_lights(const struct ssg_node_ctx *ctx, const float rot[9],
                                   struct ssg_ssdo_consts *c)
{
    const struct ssg_scene *s = ctx->scene;
    if (s->light_count > SSG_SSDO_MAX_LIGHTS) {
        return ssg_node_fail(ctx, SSG_E_SCENE,
                             "the scene has %d lights, at most %d are supported",
                             s->light_count, SSG_SSDO_MAX_LIGHTS);
    }
    c->light_count = s->light_count;
    for (int l = 0; l < s->light_count; l++) {
        const struct ssg_light *sl = &s->lights[l];
        struct ssg_ssdo_light *vl = &c->lights[l];
        float d[3];
        vl->directional = sl->kind == SSG_LIGHT_DIRECTIONAL;
        vl->cone_scale = sl->cone_scale, vl->cone_offset = sl->cone_offset;
        for (int i = 0; i < 3; i++) {
            d[i] = vl->directional ? -sl->direction[i]
                                   : sl->position[i] - s->camera.position[i];
            vl->rgb[i] = sl->color[i] * sl->intensity;
        }
        for (int r = 0; r < 3; r++) {
            vl->v[r] = rot[3 * r] * d[0] + rot[3 * r + 1] * d[1] + rot[3 * r + 2] * d[2];
            vl->axis[r] = rot[3 * r] * sl->direction[0] + rot[3 * r + 1] * sl->direction[1] +
                          rot[3 * r + 2] * sl->direction[2];
        }
        float len = sqrtf(vl->v[0] * vl->v[0] + vl->v[1] * vl->v[1] + vl->v[2] * vl->v[2]);
        for (int i = 0; vl->directional && len > 0.0f && i < 3; i++)
            vl->v[i] /= len;
    }
    return SSG_OK;
}

/* Lights and environment of the scene in view space; without a scene none and white. */
static enum ssg_err prepare_light(const struct ssg_node_ctx *ctx, struct ssg_ssdo_consts *c)
{
    const struct ssg_scene *s = ctx->scene;
    c->env = SSG_SSDO_ENV_CONSTANT;
    c->light_count = 0;
    if (!s) {
        c->env_rgb[0] = c->env_rgb[1] = c->env_rgb[2] = 1.0f;
        return SSG_OK;
    }
    float m[16], rot[9], to_world[9];
    ssg_camera_view_matrix(&s->camera, m);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) {
            rot[3 * r + k] = m[4 * k + r];      /* world -> view, row-major */
            to_world[3 * k + r] = m[4 * k + r]; /* its transpose */
        }
    enum ssg_err e = prepare_lights(ctx, rot, c);
    if (e)
        return e;
    const struct ssg_env *env = s->env;
    if (!env || !env->has_light) {
        c->env_rgb[0] = c->env_rgb[1] = c->env_rgb[2] = 0.0f;
    } else if (!env->has_image) {
        memcpy(c->env_rgb, env->constant, sizeof c->env_rgb);
    } else {
        c->env = SSG_SSDO_ENV_CUBE;
        ssg_env_cube_build(env, to_world, &c->cube);
    }
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_ssdo_consts *c = consts;
    c->p = *(const struct ssg_ssdo_params *)params;
    enum ssg_err e =
        ssg_sampling_projection(ctx, &ctx->in_shape[SSG_SSDO_IN_POSITION], &c->proj);
    if (e)
        return e;
    c->g = ssg_ssdo_geom_of(&c->p, c->proj.f);
    c->out_channels = ctx->out_shape[0].channels;
    return prepare_light(ctx, c);
}

static const char *const ssg_ssdo_mode_choices[] = {"modulation", "radiance", NULL};
SSG_PARAMS_TABLE(params, ssg_ssdo_params, SSG_SSDO_PARAMS);
SSG_UNIFORMS_AT_TABLE(uniforms, ssg_ssdo_consts, SSG_SSDO_UNIFORMS);
SSG_PORT_TABLE(inputs, SSG_SSDO_IN);
SSG_PORT_TABLE(outputs, SSG_SSDO_OUT);

/* Flops per pixel (node.h), by reading ssdo_cpu.c and ssdo_sampling.h: per kernel sample
   about 45 (placing and the depth test as ssao, the environment weight, the survivors'
   range check and bounce spread over all samples) and 10 a light for its lobe; per pixel
   about 120 for the frame, the finish and the bounce, and 20 a light. A probe adds about
   30 a sample for its cube lookup. */
static double ssdo_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_ssdo_consts *c = consts;
    double per_sample = 45.0 + 10.0 * c->light_count + (c->env == SSG_SSDO_ENV_CUBE ? 30 : 0);
    return 120.0 + 20.0 * c->light_count + per_sample * in[SSG_SSDO_IN_KERNEL].width;
}

const struct ssg_node_desc ssg_node_ssdo = {
    .name = "ssdo",
    .summary = "screen-space directional occlusion (modulation or radiance) with one "
               "indirect bounce",
    .method = "Ritschel, Grosch and Seidel, Approximating Dynamic Global Illumination in "
              "Image Space (I3D 2009), as in Szentandrasi, Modern Methods of Realistic "
              "Lighting in Real Time, sec. 3.2 eq. 1-4 and sec. 4.1 (one-step modulation "
              "factor), and Belonogov, Global Illumination methods in simulated VR "
              "environments, ch. 4",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_ssdo_params),
    .consts_size = sizeof(struct ssg_ssdo_consts),
    .uniforms = SSG_TABLE(uniforms), /* uniforms_offset 0: rows of the consts' own fields */
    .reads = SSG_READS_INPUTS | SSG_READS_LIGHTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = ssdo_flops,
    .run_cpu = ssg_ssdo_run_cpu,
    .run_gl = ssg_ssdo_run_gl,
    .parity = {.max = 7e-7, .mean = 6e-8}, /* test_gl_ssdo.c: 1.8e-7, 1.5e-8 (pow): 4x */
};
