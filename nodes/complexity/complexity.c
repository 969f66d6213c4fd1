/* complexity.c - the `complexity` node: a per-pixel sample count from the local scene
 * complexity, for the `count` input of ssao, hbao and ssdo.
 *
 * Method: Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", section 4.3
 * (preprocessing, figure 5): "a weight is calculated to define the number of sampling
 * points ... Areas where the changes in normal and depth values are bigger are given a
 * higher weight. Planes ... will have much smaller weight"; the weight is a gradient
 * magnitude of normals and depth, computed "in much lower resolutions" (wider areas
 * around discontinuities, cheaper), optionally combining several resolutions. The counts
 * are whole Halton periods (section 4.2, eq. 8: with period N_g every prefix of k N_g
 * kernel samples is quasi-uniform), the paper's 20, 30, 40 or 50 (table 1).
 *
 * Mapping (ours; the paper gives none). For each resolution r = 0..resolutions-1 the
 * frame is cut into cells of side s = scale 2^r px. Each cell keeps the mean of its
 * surface pixels' normal n, view-space point P (reconstructed from the depth with the
 * camera, node.h) and depth d; a cell without surface pixels is empty. For a non-empty
 * cell C and its non-empty 4-neighbours B:
 *   g_n = sum_B |n_C - n_B|                      (normal gradient)
 *   g_d = sum_B |n^_C . (P_B - P_C)| / d_C       (depth gradient relative to depth)
 * n^_C the unit mean normal. g_d is the depth change that C's own tangent plane does not
 * explain: the mean of points of one plane lies on that plane whatever the cell's
 * coverage, so on any plane, tilted or not, both gradients vanish (up to float rounding),
 * as the paper asks; a depth step between parallel surfaces gives step / depth per
 * neighbour across it, a crease both terms. Then
 *   t = max(clamp((g_n - normal_threshold) normal_gain, 0, 1),
 *           clamp((g_d - depth_threshold) depth_gain, 0, 1)),
 * 0 for an empty cell. A pixel reads its own cell on every grid (nearest, no filtering)
 * and takes w = the max over the grids: the coarser grids widen the marked band around a
 * discontinuity. With L levels, count = levels[min(L - 1, floor(w L))]: flat gets the
 * lowest level, a gradient threshold + 1/gain or more the highest. Background pixels
 * (depth <= 0 or not finite, or a zero normal, node.h) get the lowest level; empty
 * neighbours (background) add nothing, so a silhouette against the sky is not complex.
 * Deterministic: every value depends on the inputs only, sums run in pixel order. */
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

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    struct ssg_complexity_consts *c = consts;
    char why[256];
    c->p = *(const struct ssg_complexity_params *)params;
    /* prepare() may be reached without check() (a hand-built run). */
    if (c->p.levels.count < 1 || c->p.levels.count > SSG_INTS_MAX || c->p.period < 1 ||
        (c->p.scale != 1 && c->p.scale != 2 && c->p.scale != 4 && c->p.scale != 8) ||
        c->p.resolutions < 1 || c->p.resolutions > SSG_COMPLEXITY_MAX_RESOLUTIONS ||
        check_levels(&c->p, why, sizeof why) != SSG_OK)
        return ssg_node_fail(ctx, SSG_E_VALUE, "invalid parameters");
    return ssg_sampling_projection(ctx, &ctx->in_shape[SSG_COMPLEXITY_IN_DEPTH], &c->proj);
}

static const struct ssg_param_desc params[] = {
    {.name = "levels", SSG_FIELD_INTS(struct ssg_complexity_params, levels),
     .def_ints = {20, 30, 40, 50},
     .def_ints_count = 4,
     .min_count = 1,
     .max_count = SSG_INTS_MAX,
     .min = 1,
     .max = 1024,
     .unit = "samples",
     .help = "sample counts, ascending, each a multiple of period (Szentandrasi table 1)"},
    {.name = "period", SSG_FIELD_INT(struct ssg_complexity_params, period), .def = 10, .min = 1,
     .max = 1024, .unit = "samples",
     .help = "Halton period N_g of the kernel (eq. 8): counts are whole periods"},
    {.name = "scale", SSG_FIELD_INT(struct ssg_complexity_params, scale), .def = 4, .min = 1,
     .max = SSG_COMPLEXITY_MAX_SCALE, .unit = "px",
     .help = "cell side of the grid the gradients are taken on: 1, 2, 4 or 8"},
    {.name = "resolutions", SSG_FIELD_INT(struct ssg_complexity_params, resolutions), .def = 1,
     .min = 1, .max = SSG_COMPLEXITY_MAX_RESOLUTIONS,
     .help = "grids combined by max: cells of scale, 2 scale, ... px"},
    {.name = "normal_threshold",
     SSG_FIELD_FLOAT(struct ssg_complexity_params, normal_threshold), .def = 0.1, .min = 0,
     .max = 8, .help = "sum over neighbour cells of |n - n_nb| below which a cell is flat"},
    {.name = "normal_gain", SSG_FIELD_FLOAT(struct ssg_complexity_params, normal_gain),
     .def = 2, .min = 0, .max = 1e6,
     .help = "weight = (gradient - threshold) gain, clamped to [0, 1]"},
    {.name = "depth_threshold", SSG_FIELD_FLOAT(struct ssg_complexity_params, depth_threshold),
     .def = 0.02, .min = 0, .max = 1e6,
     .help = "sum of |n . (P_nb - P)| / depth (depth change off the "
             "tangent plane, relative) below which a cell is flat"},
    {.name = "depth_gain", SSG_FIELD_FLOAT(struct ssg_complexity_params, depth_gain), .def = 10,
     .min = 0, .max = 1e6, .help = "weight = (gradient - threshold) gain, clamped to [0, 1]"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_COMPLEXITY_IN_DEPTH] = {.name = "depth", .types = SSG_T_SCALAR,
     .doc = "linear depth (0 = background)"},
    [SSG_COMPLEXITY_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR,
     .doc = "unit view-space normal"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_COMPLEXITY_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_COMPLEXITY_OUT_COUNT] = {.name = "count", .types = SSG_T_SCALAR,
     .doc = "per-pixel sample count, one of levels (for ssao/hbao/ssdo.count)"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_COMPLEXITY_OUTPUTS, "one entry a port enumerator");

const struct ssg_node_desc ssg_node_complexity = {
    .name = "complexity",
    .summary = "per-pixel sample count from normal and depth gradients on coarse grids",
    .method = "Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 4.3 "
              "and fig. 5 (preprocessing: gradient magnitude of normals and depth at "
              "lower resolutions decides the number of samples), sec. 4.2 eq. 8 (counts "
              "in whole Halton periods), table 1 (20, 30, 40 or 50 samples)",
    .doc = "On grids of cells of scale, 2 scale, ... px (resolutions grids), each cell "
           "averages its surface pixels' normal, point and depth. Its normal gradient "
           "g_n = sum over non-empty 4-neighbours of |n - n_nb|, its depth gradient g_d = "
           "sum of |n^ . (P_nb - P)| / depth (depth change off its tangent plane, "
           "relative): both 0 on any plane. t = max(clamp((g_n - normal_threshold) "
           "normal_gain, 0, 1), clamp((g_d - depth_threshold) depth_gain, 0, 1)); a pixel "
           "takes w = max over grids of its cell's t, and count = levels[min(L-1, "
           "floor(w L))]. Background pixels get the lowest level.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_complexity_params),
    .consts_size = sizeof(struct ssg_complexity_consts),
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_complexity_run_cpu,
    .run_gl = ssg_complexity_run_gl,
};
