/* complexity.c - the `complexity` node's descriptor, check and prepare: a per-pixel sample
 * count from normal and depth gradients on coarse grids. Method: README.md in this folder. */
#include <stdio.h>

#include "common/sampling.h"
#include "complexity.h"

static enum ssg_err check_levels(const struct ssg_complexity_params *p, char *why,
                                 size_t why_len)
{
    for (int i = 0; i < p->levels.count; i++) {
        int v = p->levels.v[i];
        if (p->period > 0 && v % p->period != 0) {
            snprintf(why, why_len, "level %d is not a multiple of period %d (a count must "
                     "be whole Halton periods, eq. 8)", v, p->period);
            return SSG_E_VALUE;
        }
        if (i > 0 && v <= p->levels.v[i - 1]) {
            snprintf(why, why_len, "levels must be ascending (more samples for more "
                     "complexity); %d follows %d", v, p->levels.v[i - 1]);
            return SSG_E_VALUE;
        }
    }
    return SSG_OK;
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_complexity_params *p = params;
    const struct ssg_shape *dep = &in[SSG_COMPLEXITY_IN_DEPTH];
    const struct ssg_shape *nrm = &in[SSG_COMPLEXITY_IN_NORMAL];
    if (dep->channels != 1 || nrm->channels != 3 || !ssg_shape_same_size(dep, nrm)) {
        snprintf(why, why_len, "depth (1 channel) and normal (3 channels) must be one size");
        return SSG_E_SIZE;
    }
    if (p->scale != 1 && p->scale != 2 && p->scale != 4 && p->scale != 8) {
        snprintf(why, why_len, "scale must be 1, 2, 4 or 8, got %d", p->scale);
        return SSG_E_VALUE;
    }
    enum ssg_err e = check_levels(p, why, why_len);
    if (e)
        return e;
    /* The count image belongs to the G-buffer it was made from (maybe subsampled). */
    out[0] = (struct ssg_shape){dep->width, dep->height, 1, SSG_T_SCALAR};
    return SSG_OK;
}

/* The grids' layout for the inputs' size, and the camera, for both backends. */
static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_complexity_consts *c = consts;
    const struct ssg_shape *dep = &ctx->in_shape[SSG_COMPLEXITY_IN_DEPTH];
    c->p = *(const struct ssg_complexity_params *)params;
    c->grids = c->p.resolutions;
    for (int r = 0; r < c->grids; r++) {
        struct ssg_complexity_grid *g = &c->grid[r];
        g->side = c->p.scale << r;
        g->gw = (dep->width + g->side - 1) / g->side;
        g->gh = (dep->height + g->side - 1) / g->side;
    }
    return ssg_sampling_projection(ctx, dep, &c->proj);
}

SSG_PARAMS_TABLE(params, ssg_complexity_params, SSG_COMPLEXITY_PARAMS);
SSG_UNIFORMS_AT_TABLE(uniforms, ssg_complexity_consts, SSG_COMPLEXITY_UNIFORMS);

SSG_PORT_TABLE(inputs, SSG_COMPLEXITY_IN);
SSG_PORT_TABLE(outputs, SSG_COMPLEXITY_OUT);

const struct ssg_node_desc ssg_node_complexity = {
    .name = "complexity",
    .summary = "per-pixel sample count from normal and depth gradients on coarse grids",
    .method = "Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 4.3 "
              "and fig. 5 (preprocessing: gradient magnitude of normals and depth at "
              "lower resolutions decides the number of samples), sec. 4.2 eq. 8 (counts "
              "in whole Halton periods), table 1 (20, 30, 40 or 50 samples)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_complexity_params),
    .consts_size = sizeof(struct ssg_complexity_consts),
    .uniforms = SSG_TABLE(uniforms), /* uniforms_offset 0: rows of the consts' own fields */
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_complexity_run_cpu,
    .run_gl = ssg_complexity_run_gl,
    .parity = {.max = 0, .mean = 0}, /* bit-exact on llvmpipe (test_gl_misc.c) */
};
