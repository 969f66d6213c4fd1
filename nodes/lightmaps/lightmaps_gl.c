/* lightmaps_gl.c - GL side of the `lightmaps` node (method in README.md): the run's scene
 * (core/gl/gl_scene.h) is drawn once per face into that face's layers of
 * the depth, normal and flux images (ssg_gl_scene_draw_stacks) by lightmaps.glsl, which
 * reads the faces prepare() packed from a storage buffer and the resolution by the
 * parameter table (#pragma ssg_params). Dense meshes are drawn as the CPU side draws them,
 * as proxies (common/raster.h). */
#include "gl/gl.h"
#include "common/raster.h"
#include "gl/gl_scene.h"
#include "scene/scene.h"
#include "lightmaps.h"

enum ssg_err ssg_lightmaps_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io)
{
    const struct ssg_lightmaps_consts *c = consts;
    struct ssg_scene view;
    struct ssg_node_ctx drawn = *ctx; /* the GL scene of the view, as on the CPU */
    drawn.scene = ssg_raster_scene(ctx, c->texel, &view);
    if (!drawn.scene)
        return SSG_E_NOMEM;
    struct ssg_gl_pass pass;
    ssg_gl_raster_begin(&pass, &drawn, "lightmaps.glsl");
    ssg_gl_buffer(&pass, SSG_GL_SCENE_BINDING + SSG_GL_SCENE_BUFFERS, c->face_floats,
                  sizeof(float) * SSG_LIGHTMAPS_FACE_FLOATS * (size_t)c->count);
    ssg_gl_scene_bind(&pass);
    const struct ssg_gl_stack stacks[SSG_LIGHTMAPS_OUTPUTS] = {
        {io->out[SSG_LIGHTMAPS_OUT_DEPTH], 1, SSG_SHADOW_EMPTY},
        {io->out[SSG_LIGHTMAPS_OUT_NORMAL], 3, 0.0f},
        {io->out[SSG_LIGHTMAPS_OUT_FLUX], 3, 0.0f},
    };
    return ssg_gl_scene_draw_stacks(&pass, stacks, SSG_LIGHTMAPS_OUTPUTS, c->count);
}
