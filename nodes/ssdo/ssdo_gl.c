/* ssdo_gl.c - GL side of the `ssdo` node (method in README.md, shader ssdo.glsl): one pass,
 * one invocation per pixel, every mode, the bounce, the lights and the environment. Ports
 * and parameters are bound by the descriptor's tables; the rest is prepare()'s: the
 * projection of this resolution, the radius cap, the lights as uniform arrays and the
 * environment cube (18 KiB) in a storage buffer, all view-space consts, so both backends
 * start from the same bits. dw = pi / sum N.w comes from the pixel's own sample loop (in
 * the CPU's order: the same float sum). The `bounce` node runs the same shader
 * (bounce_gl.c) through ssg_ssdo_gl_bind_geometry. */
#include "gl/gl.h"
#include "ssdo.h"

void ssg_ssdo_gl_bind_geometry(struct ssg_gl_pass *p, const struct ssg_ssdo_geom *g,
                               const struct ssg_projection *proj)
{
    ssg_gl_float(p, "cap", g->cap);
    ssg_gl_int(p, "capped", g->capped);
    ssg_gl_projection(p, "proj", proj);
}

/* Lights as uniform arrays, the environment as a constant or the cube. */
static void bind_light(struct ssg_gl_pass *p, const struct ssg_ssdo_consts *c)
{
    int dir[SSG_SSDO_MAX_LIGHTS];
    float v[3 * SSG_SSDO_MAX_LIGHTS], rgb[3 * SSG_SSDO_MAX_LIGHTS];
    for (int l = 0; l < c->light_count; l++) {
        dir[l] = c->lights[l].directional;
        for (int i = 0; i < 3; i++) {
            v[3 * l + i] = c->lights[l].v[i];
            rgb[3 * l + i] = c->lights[l].rgb[i];
        }
    }
    ssg_gl_int(p, "light_count", c->light_count);
    ssg_gl_ints(p, "light_dir", c->light_count, dir);
    ssg_gl_floats(p, "light_v", 3 * c->light_count, v);
    ssg_gl_floats(p, "light_rgb", 3 * c->light_count, rgb);
    ssg_gl_int(p, "env", c->env);
    ssg_gl_vec3(p, "env_rgb", c->env_rgb);
    if (c->env == SSG_SSDO_ENV_CUBE)
        ssg_gl_buffer(p, 1, c->cube.rgb, sizeof c->cube.rgb);
    else
        ssg_gl_buffer(p, 1, c->env_rgb, sizeof c->env_rgb); /* bound, never read */
}

enum ssg_err ssg_ssdo_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    const struct ssg_ssdo_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_SSDO_IN_POSITION];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "ssdo.glsl", NULL);
    ssg_gl_ports(&p, io);
    ssg_ssdo_gl_bind_geometry(&p, &c->g, &c->proj);
    ssg_gl_int(&p, "out_channels", c->out_channels);
    bind_light(&p, c);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
