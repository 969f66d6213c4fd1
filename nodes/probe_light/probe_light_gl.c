/* probe_light_gl.c - GL side of the `probe_light` node (method in README.md): a first
 * pass turns the light list into every light's frame (probe_light_frames.glsl, the floats
 * of ssg_probe_light_frame) in a scratch image, so the list never returns to the CPU; the
 * second (probe_light.glsl) lights every pixel, reading every port (bound by the table),
 * the parameters (#pragma ssg_params) and prepare()'s constants (#pragma ssg_consts), and
 * the frames. The jitter tile and the per-light rotations are the CPU's floats, in storage
 * buffers. The first pass's uniforms are bound by hand: the node's constants' table serves
 * the second shader, and the frames pass is the node's inner step (a scratch image the
 * light pass reads), as a loop value of a multi-pass node is. */
#include <stdlib.h>

#include "gl/gl.h"
#include "probe_light.h"

static void frames_pass(const struct ssg_node_ctx *ctx, const struct ssg_probe_light_consts *c,
                        const struct ssg_image *lights, struct ssg_image *frames,
                        struct ssg_gl_pass *p)
{
    ssg_gl_pass_begin(p, ctx, "probe_light_frames.glsl", NULL);
    ssg_gl_input(p, "lights", lights);
    ssg_gl_output(p, "frames", frames);
    ssg_gl_floats(p, "rot", 9, c->rot);
    ssg_gl_vec3(p, "eye", c->eye);
    ssg_gl_vec3(p, "centre", c->sphere.centre);
    ssg_gl_float(p, "radius", c->sphere.radius);
    ssg_gl_int(p, "frame_res", c->frame_res);
    ssg_gl_dispatch(p, lights->width, 1);
}

static void light_pass(const struct ssg_node_ctx *ctx, const struct ssg_probe_light_consts *c,
                       const struct ssg_io *io, const struct ssg_image *frames,
                       struct ssg_gl_pass *p)
{
    const struct ssg_image *pos = io->in[SSG_PROBE_LIGHT_IN_POSITION];
    size_t tile = (size_t)c->p.noise_tile;
    ssg_gl_pass_begin(p, ctx, "probe_light.glsl", NULL);
    ssg_gl_ports(p, io);
    ssg_gl_input(p, "frames", frames);
    ssg_gl_buffer(p, 0, c->cos_sin, sizeof(float) * 2 * (size_t)c->u.count);
    ssg_gl_buffer(p, 1, c->noise, sizeof(float) * 2 * tile * tile);
    ssg_gl_buffer(p, 2, c->tap, sizeof(float) * 2 * (size_t)(c->p.taps + c->p.search_taps));
    ssg_gl_dispatch(p, pos->width, pos->height);
}

enum ssg_err ssg_probe_light_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io)
{
    const struct ssg_probe_light_consts *c = consts;
    struct ssg_image *frames = ssg_gl_scratch(ctx, c->u.count, 1, SSG_PROBE_LIGHT_FRAME);
    if (!frames)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    enum ssg_err e;
    struct ssg_gl_pass p;
    frames_pass(ctx, c, io->in[SSG_PROBE_LIGHT_IN_LIGHTS], frames, &p);
    if (!(e = ssg_gl_pass_end(&p))) {
        light_pass(ctx, c, io, frames, &p);
        e = ssg_gl_pass_end(&p);
    }
    ssg_gl_scratch_release(&frames);
    return e;
}
