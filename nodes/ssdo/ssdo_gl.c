/* ssdo_gl.c - GL side of the `ssdo` node (method in ssdo.c, shader ssdo.glsl): one pass,
 * one invocation per pixel, every mode, the bounce, the lights and the environment. The
 * projection of this resolution comes from prepare(), dw = pi / sum N.w from the pixel's
 * own sample loop (in the CPU's order: the same float sum); what
 * the CPU kernel works out once per run (the cap's factor) comes from the same C
 * expression here, so both backends start from the same bits. Lights and the environment cube are prepare()'s view-space consts:
 * the lights as uniform arrays, the cube (18 KiB) in a storage buffer. The `bounce` node
 * runs the same shader (bounce_gl.c) through ssg_ssdo_gl_bind_geometry. */
#include <math.h>
#include <stdlib.h>

#include "gl/gl.h"
#include "ssdo.h"

void ssg_ssdo_gl_bind_geometry(struct ssg_gl_pass *p, const struct ssg_io *io,
                               const struct ssg_ssdo_geom *g, const struct ssg_projection *proj)
{
    const struct ssg_image *pos = io->in[SSG_SSDO_IN_POSITION];
    const struct ssg_projection sp = *proj;
    ssg_gl_input(p, "position", pos);
    ssg_gl_input(p, "normal", io->in[SSG_SSDO_IN_NORMAL]);
    ssg_gl_input(p, "kernel", io->in[SSG_SSDO_IN_KERNEL]);
    ssg_gl_input(p, "rotation", io->in[SSG_SSDO_IN_ROTATION]);
    ssg_gl_input(p, "depth", io->in[SSG_SSDO_IN_DEPTH]);
    ssg_gl_input(p, "albedo", io->in[SSG_SSDO_IN_ALBEDO]);
    ssg_gl_input(p, "light", io->in[SSG_SSDO_IN_LIGHT]);
    ssg_gl_float(p, "radius", g->radius);
    ssg_gl_float(p, "bias", g->bias);
    ssg_gl_float(p, "cap", g->max_screen_radius / sp.f); /* ssg_ssdo_setup's expression */
    ssg_gl_int(p, "capped", g->max_screen_radius > 0.0f);
    ssg_gl_float(p, "strength", g->strength);
    ssg_gl_float(p, "min_distance", g->min_distance);
    ssg_gl_projection(p, "proj", &sp);
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
    const int out_channels = c->out_channels;
    const struct ssg_image *pos = io->in[SSG_SSDO_IN_POSITION];
    const struct ssg_image *cnt = io->in[SSG_SSDO_IN_COUNT];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "ssdo.glsl", NULL);
    ssg_ssdo_gl_bind_geometry(&p, io, &c->p.g, &c->proj);
    ssg_gl_input(&p, "count", cnt);
    ssg_gl_output(&p, "dst", io->out[0]);
    ssg_gl_output(&p, "dst_bounce", io->out[1]);
    ssg_gl_int(&p, "do_bounce", c->p.bounce);
    ssg_gl_int(&p, "radiance", c->p.mode == SSG_SSDO_MODE_RADIANCE);
    ssg_gl_int(&p, "out_channels", out_channels);
    ssg_gl_int(&p, "lobe", c->p.lobe);
    ssg_gl_float(&p, "power", c->p.power);
    bind_light(&p, c);
    ssg_gl_dispatch(&p, pos->width, pos->height);
    return ssg_gl_pass_end(&p);
}
