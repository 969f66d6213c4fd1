/* gbuffer.c - the `gbuffer` node's descriptor and prepare: the G-buffer of deferred
 * shading by ray casting. The method, its sources and conventions: README.md here. */
#include "gbuffer.h"

#include <string.h>

#include "common/trace.h"
#include "scene/env.h"
#include "scene/scene.h"

/* 1 when two cameras have the very same pose (position, target, up bit for bit). */
static int same_pose(const struct ssg_camera *a, const struct ssg_camera *b)
{
    return !memcmp(a->position, b->position, sizeof a->position) &&
           !memcmp(a->target, b->target, sizeof a->target) && !memcmp(a->up, b->up, sizeof a->up);
}

/* The previous camera seen from this one (gbuffer.h, README.md `motion`): a point at view
   position q here is at world eye + rot^T q, so at rp (eye - ep + rot^T q) in the
   previous view (rp, ep that camera's rotation and position), summed in double. The same
   pose gives the exact identity and no move rather than the float rows' rounding (1e-7),
   so a still camera has exactly zero motion. The previous focal length is the frame's
   unless the previous camera's field of view differs (a zoom along a path). */
static void prepare_motion(const struct ssg_node_ctx *ctx, struct ssg_gbuffer_consts *c)
{
    const struct ssg_camera *cur = &ctx->scene->camera;
    const struct ssg_camera *prev = ctx->prev_camera ? ctx->prev_camera : cur;
    struct ssg_frame pf = *ctx->frame;
    if (prev->fov_y != cur->fov_y)
        pf.fov_y = prev->fov_y;
    c->prev_f = ssg_frame_projection(&pf).f;
    float rp[9], ep[3];
    ssg_camera_frame(prev, rp, ep);
    int same = same_pose(prev, cur);
    for (int r = 0; r < 3; r++) {
        double move = 0.0;
        for (int k = 0; k < 3; k++) {
            double m = 0.0;
            for (int i = 0; i < 3; i++)
                m += (double)rp[3 * r + i] * c->rot[3 * k + i];
            c->m_rot[3 * r + k] = same ? (float)(r == k) : (float)m;
            move += (double)rp[3 * r + k] * ((double)c->eye[k] - ep[k]);
        }
        c->m_move[r] = same ? 0.0f : (float)move;
    }
}

/* What the GL shaders read of the scene's lights and environment (gbuffer.h): the light
   count, the environment's mode (black, constant as pi * radiance like ssg_env_irradiance,
   or the irradiance table, whose poles are values of their own) and the peel's gap. */
static void prepare_gl(const struct ssg_scene *s, struct ssg_gbuffer_consts *c)
{
    const struct ssg_env *env = s->env;
    c->light_count = s->light_count;
    c->env_mode = !env || !env->has_light ? 0 : env->has_image ? 2 : 1;
    for (int k = 0; k < 3; k++) {
        c->env_constant[k] = c->env_mode == 1 ? (float)M_PI * env->constant[k] : 0.0f;
        c->env_pole[0][k] = c->env_mode == 2 ? env->irradiance_pole[0][k] : 0.0f;
        c->env_pole[1][k] = c->env_mode == 2 ? env->irradiance_pole[1][k] : 0.0f;
    }
    c->gap = SSG_GBUFFER_BACK_GAP;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_gbuffer_consts *c = consts;
    c->p = *(const struct ssg_gbuffer_params *)params;
    enum ssg_err e = ssg_trace_camera(ctx, c->rot, c->eye);
    if (e)
        return e;
    c->proj = ssg_frame_projection(ctx->frame);
    if (ctx->frame->width < 1 || ctx->frame->height < 1 || !(c->proj.f > 0) ||
        !(ctx->frame->near_z > 0) || !(ctx->frame->far_z > ctx->frame->near_z)) {
        return ssg_node_fail(ctx, SSG_E_VALUE, "the frame "
                    "needs a size, a field of view and 0 < near < far");
    }
    c->inv_f = 1.0f / c->proj.f;
    c->near_z = ctx->frame->near_z;
    c->far_z = ctx->frame->far_z;
    prepare_motion(ctx, c);
    prepare_gl(ctx->scene, c);
    return SSG_OK;
}

static const char *const ssg_gbuffer_normals_choices[] = {"smooth", "face", NULL};
SSG_PARAMS_TABLE(params, ssg_gbuffer_params, SSG_GBUFFER_PARAMS);

SSG_PORT_TABLE(outputs, SSG_GBUFFER_OUT);
SSG_UNIFORMS_AT_TABLE(uniforms, ssg_gbuffer_consts, SSG_GBUFFER_UNIFORMS);

/* Flops per pixel (node.h), by reading gbuffer_cpu.c, for one light: about 10 for the
   ray, 35 for the normal, frame and hit point, 35 a light (Lambert and Blinn-Phong), 25
   for the environment and the stores' products. Embree's traversal is not counted. */
static double gbuffer_flops(const void *consts, const struct ssg_shape *in)
{
    (void)consts, (void)in;
    return 105.0;
}

const struct ssg_node_desc ssg_node_gbuffer = {
    .name = "gbuffer",
    .summary = "view-space G-buffer and direct light by ray casting the scene (Embree)",
    .method = "deferred-shading G-buffer (Knuth and Kohlhammer, sec. 4, fig. 10; Belonogov, "
              "sec. 4.5) by primary ray casting; Lambert + Blinn-Phong direct light (Blinn "
              "1977), no shadows",
    SSG_NODE_OUTPUTS(outputs),
    SSG_NODE_PARAMS(params, struct ssg_gbuffer_params),
    .consts_size = sizeof(struct ssg_gbuffer_consts),
    .uniforms = SSG_TABLE(uniforms), /* uniforms_offset 0: rows of the consts' own fields */
    .reads = SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS | SSG_READS_CAMERA,
    .prepare = prepare,
    .flops_per_pixel = gbuffer_flops,
    .run_cpu = ssg_gbuffer_run_cpu,
    .run_gl = ssg_gbuffer_run_gl,
};
