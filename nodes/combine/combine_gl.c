/* combine_gl.c - GL side of the `combine` node (equation in combine.c, shader
 * combine.glsl): one pass, one invocation per pixel and all three channels. Unconnected
 * optional inputs are bound as zero images with their `_bound` flag off, and the shader
 * then uses the CPU's stand-ins (ao and modulation 1, environment and indirect 0). The
 * ambient factor k = ambient * ambient_color is the CPU's C expression, passed as is. */
#include "combine.h"
#include "gl/gl.h"

enum ssg_err ssg_combine_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    const struct ssg_combine_params *prm = consts;
    struct ssg_image *out = io->out[0];
    const struct ssg_image *mod = io->in[SSG_COMBINE_IN_MODULATION];
    float k[3];
    for (int c = 0; c < 3; c++)
        k[c] = prm->ambient * prm->ambient_color[c];
    struct ssg_gl_pass p;
    ssg_gl_pass_begin(&p, ctx, "combine.glsl", NULL);
    ssg_gl_input(&p, "direct", io->in[SSG_COMBINE_IN_DIRECT]);
    ssg_gl_input(&p, "albedo", io->in[SSG_COMBINE_IN_ALBEDO]);
    ssg_gl_input(&p, "ao", io->in[SSG_COMBINE_IN_AMBIENT_OCCLUSION]);
    ssg_gl_input(&p, "indirect", io->in[SSG_COMBINE_IN_INDIRECT]);
    ssg_gl_input(&p, "modulation", mod);
    ssg_gl_input(&p, "environment", io->in[SSG_COMBINE_IN_ENVIRONMENT]);
    ssg_gl_input(&p, "far_visibility", io->in[SSG_COMBINE_IN_FAR_VISIBILITY]);
    ssg_gl_int(&p, "far_bounce", prm->far_bounce);
    ssg_gl_output(&p, "dst", out);
    ssg_gl_int(&p, "modulation_last", mod && mod->channels == 3 ? 2 : 0);
    ssg_gl_int(&p, "darken_indirect", prm->darken_indirect);
    ssg_gl_int(&p, "indirect_albedo", prm->indirect_albedo);
    ssg_gl_vec3(&p, "k", k);
    ssg_gl_dispatch(&p, out->width, out->height);
    return ssg_gl_pass_end(&p);
}
