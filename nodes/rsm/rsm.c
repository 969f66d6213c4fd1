/* rsm.c - the `rsm` node's descriptor, check and prepare: one diffuse bounce of the scene's
 * lights from their reflective shadow maps. Method and conventions: README.md. */
#include <stdio.h>
#include <stdlib.h>

#include "rsm.h"
#include "common/random.h"
#include "common/trace.h"
#include "scene/distance.h"
#include "scene/scene.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_rsm_params *p = params;
    (void)frame;
    struct ssg_lightmap_sources src = {p->own, p->environment, 1};
    enum ssg_err e = ssg_lightmap_sources_check(src, why, why_len);
    if (e)
        return e;
    const struct ssg_shape *pos = &in[SSG_RSM_IN_POSITION];
    const struct ssg_shape *d = &in[SSG_RSM_IN_MAP_DEPTH], *n = &in[SSG_RSM_IN_MAP_NORMAL],
                           *f = &in[SSG_RSM_IN_MAP_FLUX];
    if (!ssg_shape_same_size(pos, &in[SSG_RSM_IN_NORMAL]) ||
        (in[SSG_RSM_IN_ALBEDO].channels && !ssg_shape_same_size(pos, &in[SSG_RSM_IN_ALBEDO]))) {
        snprintf(why, why_len, "position, normal and albedo must have one size");
        return SSG_E_SIZE;
    }
    if (!ssg_shape_same_size(d, n) || !ssg_shape_same_size(d, f) || d->width != d->height) {
        snprintf(why, why_len, "map_depth, map_normal and map_flux must be square maps of one "
                 "size (the lightmaps node's outputs)");
        return SSG_E_SIZE;
    }
    if (n->channels != 3 * d->channels || f->channels != 3 * d->channels) {
        snprintf(why, why_len, "map_depth has %d faces, so map_normal and map_flux need %d "
                 "channels (they have %d and %d)", d->channels, 3 * d->channels, n->channels,
                 f->channels);
        return SSG_E_CHANNELS;
    }
    out[0].width = pos->width;
    out[0].height = pos->height;
    return SSG_OK;
}

/* Index of (x, y) in an 8 x 8 Bayer matrix, 0..63. */
static int bayer(int x, int y)
{
    int v = 0;
    for (int bit = 0; bit < 3; bit++) {
        int xb = (x >> bit) & 1, yb = (y >> bit) & 1;
        v |= ((xb ^ yb) << (2 * (2 - bit) + 1)) | (yb << (2 * (2 - bit)));
    }
    return v;
}

static void make_offsets(uint64_t seed, float *offset)
{
    uint64_t state = seed ^ 0x5851F42D4C957F2Dull;
    double shift = ssg_random_unit(&state);
    int sx = (int)(ssg_splitmix64(&state) % SSG_RSM_TILE);
    int sy = (int)(ssg_splitmix64(&state) % SSG_RSM_TILE);
    for (int y = 0; y < SSG_RSM_TILE; y++)
        for (int x = 0; x < SSG_RSM_TILE; x++) {
            int b = bayer((x + sx) % SSG_RSM_TILE, (y + sy) % SSG_RSM_TILE);
            double o = (b + 0.5) / (SSG_RSM_TILE * SSG_RSM_TILE) + shift;
            float v = (float)(o - floor(o));
            offset[y * SSG_RSM_TILE + x] = v < 1.0f ? v : 0.99999994f;
        }
}

static void pack_face(const struct ssg_lightmap_face *f, int res, float *out)
{
    for (int k = 0; k < 3; k++) {
        out[k] = f->origin[k];
        out[3 + k] = f->u[k];
        out[6 + k] = f->v[k];
        out[9 + k] = f->axis[k];
    }
    float s = 2.0f * f->half / (float)res;
    out[12] = f->half;
    out[13] = (float)f->ortho;
    out[14] = f->ortho ? s * s : 0.0f;
    out[15] = 0.0f;
}

/* Which draw of each vis_stride a tile cell tests, from its offset (rsm.h's vis_phase). */
static void set_phases(struct ssg_rsm_consts *c)
{
    for (int t = 0; t < SSG_RSM_TILE * SSG_RSM_TILE; t++)
        c->vis_phase[t] = (int)(c->offset[t] * (SSG_RSM_TILE * SSG_RSM_TILE)) % c->vis_stride;
}

/* Which draws test visibility (rsm.h's vis_stride, vis_tested) and the distance field's
   grid, from the scene. A scene without triangles has nothing to occlude: vis stays 0. */
static void prepare_visibility(const struct ssg_scene *scene, const struct ssg_rsm_params *p,
                               struct ssg_rsm_consts *c)
{
    const struct ssg_distance *f = scene->distance;
    c->vis = p->visibility && f;
    int S = p->samples, T = p->vis_draws;
    c->vis_stride = T == 0 || T >= S ? 1 : S / T;
    c->vis_tested = S / c->vis_stride;
    for (int k = 0; f && k < 3; k++) {
        c->grid_n[k] = f->n[k];
        c->grid_lo[k] = f->lo[k];
    }
    c->grid_inv = f ? 1.0f / f->voxel : 0.0f;
    set_phases(c);
}

/* The seed of a frame's offset tile: the graph's, or with turn=true that mixed with the
   frame index (a Weyl step, then make_offsets' own mixing), a new tile every frame. */
static uint64_t tile_seed(const struct ssg_node_ctx *ctx, const struct ssg_rsm_params *p)
{
    uint64_t seed = ctx->frame ? ctx->frame->seed : 1;
    if (p->turn)
        seed ^= (uint64_t)(ctx->frame_index + 1) * 0x9E3779B97F4A7C15ull;
    return seed;
}

enum ssg_err ssg_rsm_run_frame(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io, ssg_rsm_backend_run run)
{
    const struct ssg_rsm_consts *c = consts;
    if (!c->p.turn)
        return run(ctx, c, io);
    struct ssg_rsm_consts *turned = malloc(sizeof *turned);
    if (!turned)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    *turned = *c;
    make_offsets(tile_seed(ctx, &c->p), turned->offset);
    set_phases(turned);
    enum ssg_err e = run(ctx, turned, io);
    free(turned);
    return e;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_rsm_params *p = params;
    struct ssg_rsm_consts *c = consts;
    if (!ctx->scene)
        return ssg_node_fail(ctx, SSG_E_SCENE, "needs a loaded scene (its lights' faces)");
    c->p = *p;
    ssg_camera_frame(&ctx->scene->camera, c->rot, c->eye);
    const struct ssg_shape *maps = &ctx->in_shape[SSG_RSM_IN_MAP_DEPTH];
    struct ssg_lightmap_sources src = {p->own, p->environment, 1};
    int want = ssg_lightmap_faces(ctx->scene, src, c->face_s, SSG_LIGHTMAP_FACES_MAX);
    if (want < 0)
        return ssg_node_fail(ctx, SSG_E_SCENE, "the own lights and %d environment lights need "
                             "more than %d map faces", p->environment, SSG_LIGHTMAP_FACES_MAX);
    if (maps->channels != want)
        return ssg_node_fail(ctx, SSG_E_SCENE, "the maps have %d faces but %s%s%d "
                             "environment lights need %d: connect the lightmaps node of the "
                             "same scene and give rsm its own and environment values",
                             maps->channels, p->own ? "the scene's own lights" : "",
                             p->own ? " and " : "", p->environment, want);
    c->faces = want;
    c->res = maps->width;
    c->cells = (c->res + p->cell - 1) / p->cell;
    /* GL keeps the slots on a (6 C) x (F C) grid of one texture: 16384 a side at most */
    if ((long)SSG_RSM_BINS * c->cells > 16384 || (long)c->faces * c->cells > 16384)
        return ssg_node_fail(ctx, SSG_E_VALUE, "%d faces of %d x %d cells are too many VPL "
                             "slots: raise cell", c->faces, c->cells, c->cells);
    /* GL counts the list in a float: exact below 2^24 */
    if ((long)c->faces * c->cells * c->cells * SSG_RSM_BINS >= (1L << 24))
        return ssg_node_fail(ctx, SSG_E_VALUE, "%d faces of %d x %d cells are too many VPL "
                             "slots: raise cell", c->faces, c->cells, c->cells);
    c->slots = c->faces * c->cells * c->cells * SSG_RSM_BINS;
    c->grid_w = SSG_RSM_BINS * c->cells;
    c->grid_h = c->faces * c->cells;
    c->gl_list_rows = SSG_RSM_GL_ITERATIONS / c->grid_w;
    for (int f = 0; f < c->faces; f++)
        pack_face(&c->face_s[f], c->res, &c->face[16 * f]);
    make_offsets(tile_seed(ctx, p), c->offset);
    c->inv_samples = p->samples > 0 ? 1.0f / (float)p->samples : 0.0f;
    prepare_visibility(ctx->scene, p, c);
    return SSG_OK;
}

/* The frame index only with turn=true. */
static unsigned reads_of(const void *params, const struct ssg_scene *scene)
{
    const struct ssg_rsm_params *p = params;
    (void)scene;
    return SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS | SSG_READS_CAMERA |
           (p->turn ? SSG_READS_FRAME : 0u);
}

SSG_PARAMS_TABLE(params, ssg_rsm_params, SSG_RSM_PARAMS);
SSG_UNIFORMS_AT_TABLE(uniforms, ssg_rsm_consts, SSG_RSM_UNIFORMS);
SSG_PORT_TABLE(inputs, SSG_RSM_IN);
SSG_PORT_TABLE(outputs, SSG_RSM_OUT);

/* Flops per pixel (node.h), by reading rsm_cpu.c: about 40 for the pixel's world frame and
   output, per draw about 30 for the VPL's term (the searches are per run, not per pixel);
   with visibility, per tested draw the term again, about 30 to set up the trace and about
   15 a step, some 20 steps in a room (measured on the Cornell box's field). samples = 0
   counts every slot: an upper bound. */
static double rsm_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_rsm_consts *c = consts;
    (void)in;
    int draws = c->p.samples > 0 ? c->p.samples : c->slots;
    int tested = c->vis_stride == 1 ? draws : c->vis_tested;
    return 40.0 + 30.0 * draws + (c->vis ? 360.0 * tested : 0.0);
}

const struct ssg_node_desc ssg_node_rsm = {
    .name = "rsm",
    .summary = "one diffuse bounce of the scene's lights from reflective shadow maps (VPLs)",
    .method = "Dachsbacher and Stamminger, Reflective Shadow Maps, I3D 2005, sec. 3 eq. 1 "
              "(the map's texels as pixel lights, no occlusion between sender and receiver); "
              "texels merged into VPLs and drawn by flux (stratified, 1 / pdf) instead of "
              "the paper's screen-space pattern around the receiver's projection; "
              "visibility=true adds the occlusion the paper leaves out, sphere traced in a "
              "distance field of the scene (Hart 1996)",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_rsm_params),
    .consts_size = sizeof(struct ssg_rsm_consts),
    .uniforms = SSG_TABLE(uniforms), /* uniforms_offset 0: rows of the consts' own fields */
    .reads = SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS | SSG_READS_CAMERA |
             SSG_READS_FRAME,
    .reads_of = reads_of,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = rsm_flops,
    .run_cpu = ssg_rsm_run_cpu,
    .run_gl = ssg_rsm_run_gl,
    .parity = {.max = 0, .mean = 0}, /* bit-exact on llvmpipe (test_gl_rsm.c) */
};
