/* direct_light_gl.c - GL side of the `direct_light` node (method in README.md): one compute
 * pass, direct_light.glsl, reading the faces, lights and taps prepare() made (the CPU's
 * bytes, in storage buffers); ports and parameters are bound by the descriptor's tables. */
#include "gl/gl.h"
#include "direct_light.h"

_Static_assert(sizeof(struct ssg_lightmap_face) == 60, "direct_light.glsl's Face");
_Static_assert(sizeof(struct ssg_direct_light_light) == 72, "direct_light.glsl's Light");

enum ssg_err ssg_direct_light_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                     const struct ssg_io *io)
{
    const struct ssg_direct_light_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_DIRECT_LIGHT_IN_POSITION];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "direct_light.glsl", NULL);
    ssg_gl_ports(&p, io);
    ssg_gl_buffer(&p, 0, c->faces, sizeof c->faces[0] * (size_t)c->face_count);
    ssg_gl_buffer(&p, 1, c->light, sizeof c->light[0] * (size_t)(c->u.lights ? c->u.lights : 1));
    ssg_gl_buffer(&p, 2, c->taps, sizeof(float) * 2 * (size_t)c->p.samples);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
