/* hbao.c - the `hbao` node's descriptor, check and prepare (with the directions' count
 * order): horizon-based ambient occlusion. Method, geometry and sources: README.md here. */
#include <math.h>

#include "common/horizon.h"
#include "hbao.h"

/* Farthest-point order of m positions on a circle of m (distance min(|a - b|,
   m - |a - b|)), starting at 0, ties to the lowest index: order[r] is the r-th. */
static void spread_order(int m, int *order)
{
    int used[SSG_HBAO_MAX_DIRECTIONS] = {0};
    order[0] = 0;
    used[0] = 1;
    for (int r = 1; r < m; r++) {
        int best = -1, best_dist = -1;
        for (int k = 0; k < m; k++) {
            int dist = m;
            for (int q = 0; !used[k] && q < r; q++) {
                int d = k > order[q] ? k - order[q] : order[q] - k;
                d = d < m - d ? d : m - d;
                dist = d < dist ? d : dist;
            }
            if (!used[k] && dist > best_dist)
                best = k, best_dist = dist;
        }
        order[r] = best;
        used[best] = 1;
    }
}

/* dir_rank of the consts (file header): pairs ranked on the half circle, or directions
   on the whole circle when their number is odd. */
static void rank_directions(int nd, int *rank)
{
    int order[SSG_HBAO_MAX_DIRECTIONS];
    if (nd % 2 == 0) {
        spread_order(nd / 2, order);
        for (int r = 0; r < nd / 2; r++) {
            rank[order[r]] = 2 * r;
            rank[order[r] + nd / 2] = 2 * r + 1;
        }
    } else {
        spread_order(nd, order);
        for (int r = 0; r < nd; r++)
            rank[order[r]] = r;
    }
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    return ssg_sampling_check_ao(&in[SSG_HBAO_IN_POSITION], &in[SSG_HBAO_IN_NORMAL], NULL,
                                 &in[SSG_HBAO_IN_ROTATION], &in[SSG_HBAO_IN_DEPTH],
                                 &in[SSG_HBAO_IN_COUNT], out, why, why_len);
}

/* The consts with e1 for the G-buffer's columns. */
static size_t consts_size_of(const void *params, const struct ssg_shape *in)
{
    return ssg_horizon_consts_size(sizeof(struct ssg_hbao_consts), &in[SSG_HBAO_IN_POSITION]);
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_hbao_consts *c = consts;
    const struct ssg_hbao_params *q = &c->p;
    c->p = *(const struct ssg_hbao_params *)params;
    enum ssg_err e = ssg_horizon_frame(ctx, &ctx->in_shape[SSG_HBAO_IN_POSITION],
                                       &c->proj, &c->invf, c->e1);
    c->u.r2 = q->radius * q->radius;
    c->u.inv_radius = 1.0f / q->radius;
    c->u.inv_steps = 1.0f / (float)q->steps;
    c->u.scale = q->strength / (float)q->directions;
    c->u.cos_bias = (float)cos(q->bias);
    c->u.sin_bias = (float)sin(q->bias);
    ssg_horizon_angles(q->directions, 2.0 * M_PI, 0.0, c->dir_cos, c->dir_sin);
    rank_directions(q->directions, c->dir_rank);
    return e;
}

static const char *const ssg_hbao_falloff_choices[] = {"linear", "none", NULL};
SSG_PARAMS_TABLE(params, ssg_hbao_params, SSG_HBAO_PARAMS);
SSG_UNIFORMS_TABLE(uniforms, ssg_hbao_uniforms, SSG_HBAO_UNIFORMS);

SSG_PORT_TABLE(inputs, SSG_HBAO_IN);
SSG_PORT_TABLE(outputs, SSG_HBAO_OUT);

/* Flops per pixel (node.h), by reading hbao_cpu.c: per direction about 20 for its step
   and tangent, per step about 25 (place, index, the horizon's tangent, falloff, max),
   about 40 per pixel for its frame and the finish. */
static double hbao_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_hbao_consts *c = consts;
    return 40.0 + c->p.directions * (20.0 + 25.0 * c->p.steps);
}

const struct ssg_node_desc ssg_node_hbao = {
    .name = "hbao",
    .summary = "horizon-based screen-space ambient occlusion",
    .method = "Bavoil, Sainz and Dimitrov, Image-Space Horizon-Based Ambient Occlusion "
              "(SIGGRAPH 2008), as in Belonogov, Global Illumination methods in simulated "
              "VR environments, sec. 3.3.1, eq. 3.1-3.2 (W = max(0, 1 - r/R), per-sample "
              "horizon terms, angle bias, rotated directions)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_hbao_params),
    .consts_size_of = consts_size_of,
    SSG_NODE_UNIFORMS(uniforms, struct ssg_hbao_consts, u),
    .reads = SSG_READS_INPUTS | SSG_READS_CAMERA,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = hbao_flops,
    .run_cpu = ssg_hbao_run_cpu,
    .run_gl = ssg_hbao_run_gl,
    .parity = {.max = 0, .mean = 0}, /* bit-exact on llvmpipe (test_gl_hbao.c) */
};
