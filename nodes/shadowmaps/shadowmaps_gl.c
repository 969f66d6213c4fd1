/* shadowmaps_gl.c - GL side of the `shadowmaps` node (method in README.md): the run's scene
 * (core/gl/gl_scene.h) is drawn once per light into that light's layer of the
 * output texture array by shadowmaps.glsl, which reads the light's direction from the
 * light list itself, so the list never has to come back to the CPU. It draws the scene's proxy view, as the CPU
 * side does (common/raster.h). */
#include "gl/gl.h"
#include <math.h>

#include "common/raster.h"
#include "gl/gl_scene.h"
#include "scene/scene.h"
#include "shadowmaps.h"

enum ssg_err ssg_shadowmaps_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io)
{
    const struct ssg_shadowmaps_params *p = consts;
    enum ssg_err e = ssg_shadowmaps_check_run(ctx, p, io);
    if (e)
        return e;
    struct ssg_bounding_sphere sphere = ssg_scene_bounding_sphere(ctx->scene);
    struct ssg_scene view;
    struct ssg_node_ctx drawn = *ctx; /* the GL scene of the view (common/raster.h) */
    drawn.scene = ssg_raster_scene(
        ctx, p->proxy ? 2.0f * sphere.radius / (float)io->out[0]->width : INFINITY, &view);
    if (!drawn.scene)
        return SSG_E_NOMEM;
    struct ssg_gl_pass pass;
    ssg_gl_raster_begin(&pass, &drawn, "shadowmaps.glsl");
    ssg_gl_input(&pass, "lights", io->in[0]);
    ssg_gl_vec3(&pass, "centre", sphere.centre);
    ssg_gl_float(&pass, "radius", sphere.radius);
    return ssg_gl_scene_draw_layers(&pass, io->out[0], SSG_SHADOW_EMPTY);
}
