/* reference_gi.c - the `reference_gi` node's descriptor, check and prepare: path-traced
 * ground truth for SSDO. The method, its sources and conventions: README.md here. */
#include <stdio.h>

#include "scene/env.h"
#include "reference_gi.h"
#include "scene/scene.h"
#include "common/trace.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    (void)params, (void)frame;
    const struct ssg_shape *pos = &in[SSG_REFERENCE_GI_IN_POSITION];
    const struct ssg_shape *nrm = &in[SSG_REFERENCE_GI_IN_NORMAL];
    const struct ssg_shape *alb = &in[SSG_REFERENCE_GI_IN_ALBEDO];
    if (pos->channels != 3 || nrm->channels != 3 || alb->channels != 3 ||
        !ssg_shape_same_size(pos, nrm) || !ssg_shape_same_size(pos, alb)) {
        snprintf(why, why_len, "position, normal and albedo must be 3-channel images of one "
                 "size");
        return SSG_E_SIZE;
    }
    /* Runs at the G-buffer's resolution. */
    for (int i = 0; i < 3; i++)
        out[i] = (struct ssg_shape){pos->width, pos->height, 3, SSG_T_COLOR};
    return SSG_OK;
}

/* The Hammersley tables of n points (README.md, sampling). */
static void make_table(struct ssg_reference_gi_table *t, int n)
{
    ssg_hammersley_disk(n, t->u, t->c, t->s);
    for (int i = 0; i < n; i++) {
        t->v[i] = (float)ssg_radical_inverse((uint32_t)i, 2);
        t->e1[i] = (float)ssg_radical_inverse((uint32_t)i, 3);
        t->e2[i] = (float)ssg_radical_inverse((uint32_t)i, 5);
    }
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_reference_gi_consts *c = consts;
    const struct ssg_scene *s = ctx->scene;
    c->p = *(const struct ssg_reference_gi_params *)params;
    enum ssg_err e = ssg_trace_camera(ctx, c->rot, c->eye);
    if (e)
        return e;
    c->seed = ctx->frame->seed;
    c->use_env = c->p.environment && s->env && s->env->has_light;
    make_table(&c->t, c->p.samples);
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_reference_gi_params, SSG_REFERENCE_GI_PARAMS);

SSG_PORT_TABLE(inputs, SSG_REFERENCE_GI_IN);
SSG_PORT_TABLE(outputs, SSG_REFERENCE_GI_OUT);

const struct ssg_node_desc ssg_node_reference_gi = {
    .name = "reference_gi",
    .summary = "ground-truth direct light with shadows plus one diffuse bounce (Embree)",
    .method = "the rendering equation (Belonogov sec. 2.1, eq. 2.1) for Lambertian surfaces "
              "after one bounce: the integrals SSDO approximates (Szentandrasi sec. 3.2.1 "
              "eq. 1 and sec. 3.2.2 eq. 3) by ray casting, with environment importance "
              "sampling, cosine-weighted bounce paths (Malley) and a Hammersley set with "
              "per-pixel Cranley-Patterson rotation",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_reference_gi_params),
    .consts_size = sizeof(struct ssg_reference_gi_consts),
    .reads = SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_reference_gi_run_cpu,
};
