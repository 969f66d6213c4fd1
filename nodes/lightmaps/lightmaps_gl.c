/* lightmaps_gl.c - GL side of the `lightmaps` node (method in lightmaps.c): the scene is
 * uploaded (nodes/common/gl_raster.h) and drawn once per face into that face's layers of
 * the depth, normal and flux images (ssg_gl_scene_draw_stacks) by lightmaps.glsl, which
 * reads the faces prepare() made from a storage buffer. */
#include <stdlib.h>

#include "gl/gl.h"
#include "common/gl_raster.h"
#include "lightmaps.h"

enum { FACE_FLOATS = 20 }; /* lightmaps.glsl's FACE */

/* The faces as lightmaps.glsl reads them. */
static float *face_floats(const struct ssg_lightmaps_consts *c)
{
    float *f = calloc((size_t)c->count * FACE_FLOATS, sizeof *f);
    for (int i = 0; f && i < c->count; i++) {
        const struct ssg_lightmap_face *face = &c->faces[i];
        float *o = f + (size_t)i * FACE_FLOATS;
        for (int k = 0; k < 3; k++) {
            o[k] = face->origin[k], o[3 + k] = face->u[k], o[6 + k] = face->v[k];
            o[9 + k] = face->axis[k], o[14 + k] = c->flux[i][k];
        }
        o[12] = face->half, o[13] = (float)face->ortho, o[17] = face->light >= 0;
    }
    return f;
}

enum ssg_err ssg_lightmaps_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                  const struct ssg_io *io)
{
    const struct ssg_lightmaps_consts *c = consts;
    struct ssg_gl_scene *scene = NULL;
    enum ssg_err e = ssg_gl_scene_upload(ctx, ctx->scene, &scene);
    if (e)
        return e;
    float *faces = face_floats(c);
    if (!faces) {
        ssg_gl_scene_free(&scene);
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    }
    struct ssg_gl_pass pass;
    ssg_gl_raster_begin(&pass, ctx, "lightmaps.glsl");
    ssg_gl_buffer(&pass, SSG_GL_SCENE_BINDING + SSG_GL_SCENE_BUFFERS, faces,
                  sizeof(float) * FACE_FLOATS * (size_t)c->count);
    ssg_gl_scene_bind(scene);
    ssg_gl_int(&pass, "res", c->res);
    ssg_gl_float(&pass, "near_z", c->near_z);
    ssg_gl_float(&pass, "far_z", c->far_z);
    const struct ssg_gl_stack stacks[SSG_LIGHTMAPS_OUTPUTS] = {
        {io->out[SSG_LIGHTMAPS_OUT_DEPTH], 1, SSG_SHADOW_EMPTY},
        {io->out[SSG_LIGHTMAPS_OUT_NORMAL], 3, 0.0f},
        {io->out[SSG_LIGHTMAPS_OUT_FLUX], 3, 0.0f},
    };
    e = ssg_gl_scene_draw_stacks(&pass, scene, stacks, SSG_LIGHTMAPS_OUTPUTS, c->count);
    free(faces);
    ssg_gl_scene_free(&scene);
    return e;
}
