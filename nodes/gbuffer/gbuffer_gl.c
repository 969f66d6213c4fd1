/* gbuffer_gl.c - GL side of the `gbuffer` node (method in README.md): the scene is
 * rasterised into a visibility buffer (mesh and triangle per pixel, core/gl/gl_scene.h,
 * gbuffer_raster.glsl), then one compute pass (gbuffer.glsl) casts each pixel's ray at
 * its triangle and writes the first layer's six outputs with the CPU kernel's formulas.
 * When `back` is read, a depth peel (gbuffer_peel.glsl) and a second cast
 * (gbuffer_back.glsl) give the second layer; when `motion` is read, a pass of its own
 * (gbuffer_motion.glsl) makes it from the first layer's depth. The scene on GL is the
 * run's (uploaded once for all its nodes); the lights and the environment's irradiance
 * table go in as they are in the scene. The shaders read the parameters and prepare()'s
 * constants by the tables (#pragma ssg_params, ssg_consts: gbuffer.h's rows, each marked
 * with the shaders that read it) and write their outputs by ssg_gl_ports (each port marked
 * with the pass that writes it); by hand are only the images between the passes: the
 * visibility buffer `ids` and the first layer's depth `first`. */
#include <stdlib.h>
#include <string.h>

#include "scene/env.h"
#include "gbuffer.h"
#include "gl/gl.h"
#include "gl/gl_scene.h"
#include "scene/scene.h"

enum { LIGHT_FLOATS = 16, LIGHT_BINDING = 5, ENV_BINDING = 6 };

/* The lights as gbuffer.glsl reads them (16 floats each); NULL when out of memory. */
static float *pack_lights(const struct ssg_scene *s)
{
    float *f = calloc((size_t)s->light_count * LIGHT_FLOATS + 1, sizeof *f);
    for (int i = 0; f && i < s->light_count; i++) {
        const struct ssg_light *l = &s->lights[i];
        float *o = &f[i * LIGHT_FLOATS];
        for (int k = 0; k < 3; k++)
            o[k] = l->position[k], o[3 + k] = l->direction[k], o[6 + k] = l->color[k];
        o[9] = l->intensity;
        o[10] = l->kind == SSG_LIGHT_DIRECTIONAL ? 1.0f : 0.0f;
        o[11] = l->cone_scale, o[12] = l->cone_offset;
    }
    return f;
}

/* The shading pass writes direct and environment light whether read or not (they are on
   demand for the CPU kernel, gbuffer.h): an unread one gets a scratch image, so that its
   stores never land in another output's image unit. */
static enum ssg_err shade_pass(const struct ssg_node_ctx *ctx,
                               const struct ssg_gbuffer_consts *c,
                               const struct ssg_image *ids, const struct ssg_io *io);

static enum ssg_err shade(const struct ssg_node_ctx *ctx, const struct ssg_gbuffer_consts *c,
                          const struct ssg_image *ids, const struct ssg_io *io)
{
    static const int lit[2] = {SSG_GBUFFER_OUT_DIRECT, SSG_GBUFFER_OUT_ENVIRONMENT};
    struct ssg_image *out[SSG_GBUFFER_OUTPUTS], *scratch[2] = {NULL, NULL};
    memcpy(out, io->out, sizeof out);
    enum ssg_err e = SSG_OK;
    for (int i = 0; i < 2 && !e; i++)
        if (!out[lit[i]]) {
            scratch[i] = ssg_gl_scratch(ctx, ids->width, ids->height, 3);
            out[lit[i]] = scratch[i];
            e = scratch[i] ? SSG_OK : SSG_E_NOMEM;
        }
    struct ssg_io with_light = *io;
    with_light.out = out;
    if (!e)
        e = shade_pass(ctx, c, ids, &with_light);
    for (int i = 0; i < 2; i++)
        ssg_gl_scratch_release(&scratch[i]);
    return e;
}

static enum ssg_err shade_pass(const struct ssg_node_ctx *ctx,
                               const struct ssg_gbuffer_consts *c,
                               const struct ssg_image *ids, const struct ssg_io *io)
{
    const struct ssg_scene *s = ctx->scene;
    float *lights = pack_lights(s);
    if (!lights)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the lights");
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "gbuffer.glsl", NULL);
    ssg_gl_scene_bind(&p);
    ssg_gl_buffer(&p, LIGHT_BINDING, lights,
                  (size_t)s->light_count * LIGHT_FLOATS * sizeof(float));
    if (c->env_mode == 2) /* the irradiance table (prepare_gl, gbuffer.c) */
        ssg_gl_buffer(&p, ENV_BINDING, s->env->irradiance, sizeof s->env->irradiance);
    else
        ssg_gl_buffer(&p, ENV_BINDING, NULL, 0);
    ssg_gl_input(&p, "ids", ids);
    ssg_gl_ports(&p, io);
    ssg_gl_dispatch(&p, ids->width, ids->height);
    free(lights);
    return ssg_gl_pass_end(&p);
}

/* The second layer (README.md, `back`): a depth peel against the first layer's depth
   into `ids` (its first use is over), then the ray cast at the triangle it found. */
static enum ssg_err peel(const struct ssg_node_ctx *ctx, const struct ssg_gl_camera *cam,
                         struct ssg_image *ids, const struct ssg_io *io)
{
    const struct ssg_image *first = io->out[SSG_GBUFFER_OUT_DEPTH];
    struct ssg_gl_pass r;
    ssg_gl_raster_begin(&r, ctx, "gbuffer_peel.glsl");
    ssg_gl_input(&r, "first", first);
    enum ssg_err e = ssg_gl_scene_draw_pass(&r, cam, ids);
    if (e)
        return e;
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "gbuffer_back.glsl", NULL);
    ssg_gl_scene_bind(&p);
    ssg_gl_input(&p, "ids", ids);
    ssg_gl_input(&p, "first", first);
    ssg_gl_ports(&p, io);
    ssg_gl_dispatch(&p, ids->width, ids->height);
    return ssg_gl_pass_end(&p);
}

/* Motion to the previous frame (README.md, `motion`) from the depth the shading pass wrote. */
static enum ssg_err motion(const struct ssg_node_ctx *ctx, const struct ssg_io *io)
{
    const struct ssg_image *first = io->out[SSG_GBUFFER_OUT_DEPTH];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "gbuffer_motion.glsl", NULL);
    ssg_gl_input(&p, "first", first);
    ssg_gl_ports(&p, io);
    ssg_gl_dispatch(&p, first->width, first->height);
    return ssg_gl_pass_end(&p);
}

/* Emission (gbuffer.h, `emission`, on demand) at the triangle the visibility pass found. */
static enum ssg_err emission(const struct ssg_node_ctx *ctx, const struct ssg_image *ids,
                             const struct ssg_io *io)
{
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, SSG_GBUFFER_GL_EMISSION, NULL);
    ssg_gl_scene_bind(&p);
    ssg_gl_input(&p, "ids", ids);
    ssg_gl_ports(&p, io);
    ssg_gl_dispatch(&p, ids->width, ids->height);
    return ssg_gl_pass_end(&p);
}

enum ssg_err ssg_gbuffer_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    const struct ssg_gbuffer_consts *c = consts;
    int w = io->out[SSG_GBUFFER_OUT_DEPTH]->width, h = io->out[SSG_GBUFFER_OUT_DEPTH]->height;
    const struct ssg_gl_camera cam = {c->rot, c->eye, c->proj, c->near_z, c->far_z};
    struct ssg_image *ids = ssg_gl_scratch(ctx, w, h, 2);
    if (!ids)
        return SSG_E_NOMEM;
    enum ssg_err e = ssg_gl_scene_draw(ctx, "gbuffer_raster.glsl", &cam, ids);
    if (!e)
        e = shade(ctx, c, ids, io);
    if (!e && io->out[SSG_GBUFFER_OUT_EMISSION]) /* on demand, before the peel reuses ids */
        e = emission(ctx, ids, io);
    if (!e && io->out[SSG_GBUFFER_OUT_BACK]) /* on demand: only when something reads it */
        e = peel(ctx, &cam, ids, io);
    if (!e && io->out[SSG_GBUFFER_OUT_MOTION]) /* likewise */
        e = motion(ctx, io);
    ssg_gl_scratch_release(&ids);
    return e;
}
