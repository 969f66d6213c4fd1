/* reference_ao.c - the `reference_ao` node's descriptor, check and prepare: ground-truth
 * ambient obscurance by ray casting the scene with Embree. Method: README.md in this folder. */
#include <stdio.h>

#include "reference_ao.h"
#include "common/trace.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_shape *pos = &in[SSG_REFERENCE_AO_IN_POSITION];
    const struct ssg_shape *nrm = &in[SSG_REFERENCE_AO_IN_NORMAL];
    if (pos->channels != 3 || nrm->channels != 3 || pos->width != nrm->width ||
        pos->height != nrm->height) {
        snprintf(why, why_len, "position and normal must be 3-channel images of one size");
        return SSG_E_SIZE;
    }
    /* Runs at the G-buffer's resolution. */
    out[0] = (struct ssg_shape){pos->width, pos->height, 1, SSG_T_SCALAR};
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_reference_ao_consts *c = consts;
    c->p = *(const struct ssg_reference_ao_params *)params;
    enum ssg_err e = ssg_trace_camera(ctx, c->rot, c->eye);
    if (e)
        return e;
    c->seed = ctx->frame->seed;
    ssg_hammersley_disk(c->p.rays, c->u, c->c, c->s);
    return SSG_OK;
}

SSG_PARAMS_TABLE(params, ssg_reference_ao_params, SSG_REFERENCE_AO_PARAMS);
SSG_PORT_TABLE(inputs, SSG_REFERENCE_AO_IN);
SSG_PORT_TABLE(outputs, SSG_REFERENCE_AO_OUT);

const struct ssg_node_desc ssg_node_reference_ao = {
    .name = "reference_ao",
    .summary = "ground-truth ambient obscurance by ray casting the scene (Embree)",
    .method = "Belonogov, Global Illumination methods in simulated VR environments, sec. "
              "2.2.3, eq. 2.5-2.7 (cosine-weighted, distance-limited visibility), by Monte "
              "Carlo ray casting with a Hammersley set (Szentandrasi sec. 4.2, eq. 5-7), "
              "Malley's method and per-pixel Cranley-Patterson rotation",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_reference_ao_params),
    .consts_size = sizeof(struct ssg_reference_ao_consts),
    .reads = SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_reference_ao_run_cpu,
};
