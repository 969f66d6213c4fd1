/* ssdo_gl.c - GL side of the `ssdo` node (method in README.md, shader ssdo.glsl): one pass,
 * one invocation per pixel, every mode, the bounce, the lights and the environment. Ports,
 * parameters and prepare()'s constants (the projection of this resolution, the radius
 * cap, the light count, the environment's kind and colour) are bound by the descriptor's
 * tables; the lights (prepare()'s structs as they are) and the environment cube (18 KiB)
 * are storage buffers. All are view-space consts, so both backends start from the same
 * bits. dw = pi / sum N.w comes from the pixel's own sample loop (in the CPU's order: the
 * same float sum). The `bounce` node runs the same shader (bounce_gl.c). */
#include "gl/gl.h"
#include "ssdo.h"

enum ssg_err ssg_ssdo_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    const struct ssg_ssdo_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_SSDO_IN_POSITION];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "ssdo.glsl", NULL);
    ssg_gl_ports(&p, io);
    ssg_gl_buffer(&p, 2, c->lights, sizeof c->lights[0] * (size_t)c->light_count);
    if (c->env == SSG_SSDO_ENV_CUBE)
        ssg_gl_buffer(&p, 1, c->cube.rgb, sizeof c->cube.rgb);
    else
        ssg_gl_buffer(&p, 1, c->env_rgb, sizeof c->env_rgb); /* bound, never read */
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
