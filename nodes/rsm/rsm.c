/* rsm.c - the `rsm` node: one diffuse bounce of every point and directional light of the
 * scene, beyond the screen, gathered from the lights' reflective shadow maps (Dachsbacher
 * and Stamminger, "Reflective Shadow Maps", I3D 2005). Per pixel of a view-space G-buffer
 * of any resolution (in practice a half or quarter one from `downsample`):
 *
 *   E(x) = sum over texels p of Phi_p / pi x max(0, n_p . (x - x_p)) max(0, n_x . (x_p - x))
 *          / (d^2 max(d^2, A_p / pi)) x fade(d),   d = |x_p - x|
 *   out  = albedo x E / pi   (albedo connected; otherwise E / pi)
 *
 * the paper's eq. 1 (sec. 3) with the 1/pi of a Lambertian sender (nodes/common/lightmap.h
 * states the units: Phi_p the flux the patch reflects, W). x_p is the texel's world point
 * from its depth (ssg_lightmap_texel_point). The paper's d^4 is d^2 x d^2; one d^2 is
 * clamped to at least A_p / pi, the squared radius of a disc of the patch's own surface
 * area A_p, so that no patch gives a receiver more than its radiosity Phi_p / A_p times the
 * cosines (what an infinite plane of that radiosity gives) where the point-light law
 * diverges (sec. 3 "near the light" artefacts the paper hides by sampling only away from
 * the receiver). fade(d) = 1 for min_distance m = 0; otherwise 0 for d <= m, 1 for
 * d >= 2 m, smoothstep t^2 (3 - 2 t), t = (d - m) / m, between: a screen-space pass that
 * weights its own near-field bounce by 1 - fade(d) counts every sender once.
 *
 * No visibility between sender and receiver: RSM's own limitation (sec. 3, "we ignore
 * occlusion for the indirect light sources"): light reaches through walls and boxes. The
 * pipeline darkens the bounce with a screen-space visibility (the AO of the same frame).
 *
 * Importance sampling (sec. 4 samples the map around the receiver's projection, which only
 * a directional light's single map allows; ours draws from every face by flux instead).
 * Once per run the maps become virtual point lights (rsm.h): each face is cut into cells of
 * `cell` x `cell` texels, a cell's texels binned by their normal's dominant axis, each bin
 * one VPL with the bin's summed flux and area and its flux-weighted position and normal;
 * empty bins are dropped. The VPL list carries the CDF of w = Phi.r + Phi.g + Phi.b. Per
 * pixel, `samples` draws u_k = (k + o) / S x total, k = 0..S-1 (stratified), pick the VPL
 * whose CDF interval holds u_k, each weighted by 1 / (S pdf) = total / (S w): unbiased for
 * the VPL sum. The offset o is the pixel's in an 8 x 8 Bayer tile ((b + 0.5) / 64, b the
 * Bayer index, shifted mod 1 and over the tile by the frame's seed): neighbours draw
 * different strata, which the upsampling's joint bilateral filter averages (interleaved
 * sampling, Keller and Heidrich 2001). The pixels of one tile cell make the same draws, so
 * the 64 x S searches of the CDF are made once a run and a pixel only evaluates its draws
 * (which also lets the CPU run 64 such pixels of a row as one vector loop). samples = 0, or at least the VPL count, is the exact
 * VPL sum; with cell = 1 that is the texel sum above. */
#include <stdio.h>

#include "rsm.h"
#include "common/random.h"
#include "common/trace.h"
#include "scene/scene.h"

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    (void)params;
    (void)frame;
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

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_rsm_params *p = params;
    struct ssg_rsm_consts *c = consts;
    if (!ctx->scene)
        return ssg_node_fail(ctx, SSG_E_SCENE, "needs a loaded scene (its lights' faces)");
    c->p = *p;
    ssg_camera_frame(&ctx->scene->camera, c->rot, c->eye);
    const struct ssg_shape *maps = &ctx->in_shape[SSG_RSM_IN_MAP_DEPTH];
    int want = ssg_lightmap_faces(ctx->scene, c->face_s, SSG_LIGHTMAP_FACES_MAX);
    if (want < 0)
        return ssg_node_fail(ctx, SSG_E_SCENE, "the scene's lights need more than %d map "
                             "faces", SSG_LIGHTMAP_FACES_MAX);
    if (maps->channels != want)
        return ssg_node_fail(ctx, SSG_E_SCENE, "the maps have %d faces but the scene's "
                             "lights need %d: connect the lightmaps node of the same scene",
                             maps->channels, want);
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
    for (int f = 0; f < c->faces; f++)
        pack_face(&c->face_s[f], c->res, &c->face[16 * f]);
    make_offsets(ctx->frame ? ctx->frame->seed : 1, c->offset);
    c->inv_samples = p->samples > 0 ? 1.0f / (float)p->samples : 0.0f;
    return SSG_OK;
}

static const struct ssg_param_desc params[] = {
    {.name = "samples", SSG_FIELD_INT(struct ssg_rsm_params, samples), .def = 64, .min = 0,
     .max = SSG_RSM_SAMPLES_MAX,
     .help = "VPLs drawn per pixel in proportion to their flux (stratified, weighted by "
             "1 / pdf); 0, or at least the VPL count, sums every VPL exactly"},
    {.name = "cell", SSG_FIELD_INT(struct ssg_rsm_params, cell), .def = 4, .min = 1,
     .max = 128, .unit = "texels",
     .help = "side of the map cells merged into VPLs (per dominant normal axis): larger is "
             "fewer, coarser VPLs; 1 = one VPL a texel"},
    {.name = "min_distance", SSG_FIELD_FLOAT(struct ssg_rsm_params, min_distance), .def = 0,
     .min = 0, .max = 1e6, .unit = "world units",
     .help = "senders nearer than this give nothing, fading in smoothly up to twice it, so a "
             "screen-space pass can own the near field (weight 1 - fade); 0 = none excluded"},
};

static const struct ssg_port_desc inputs[] = {
    [SSG_RSM_IN_POSITION] = {.name = "position", .types = SSG_T_VECTOR,
                             .doc = "view-space position (gbuffer or downsample), any size"},
    [SSG_RSM_IN_NORMAL] = {.name = "normal", .types = SSG_T_VECTOR,
                           .doc = "unit view-space normal, 0 = background"},
    [SSG_RSM_IN_MAP_DEPTH] = {.name = "map_depth", .types = SSG_T_LIGHTMAPS,
                              .doc = "the lights' map depths (lightmaps.depth)"},
    [SSG_RSM_IN_MAP_NORMAL] = {.name = "map_normal", .types = SSG_T_LIGHTMAPS,
                               .doc = "the lights' map normals (lightmaps.normal)"},
    [SSG_RSM_IN_MAP_FLUX] = {.name = "map_flux", .types = SSG_T_LIGHTMAPS,
                             .doc = "the lights' reflected flux (lightmaps.flux)"},
    [SSG_RSM_IN_ALBEDO] = {.name = "albedo", .types = SSG_T_COLOR, .optional = 1,
                           .doc = "diffuse albedo of the receivers; unconnected: out is the "
                                  "bounce a white receiver sends, E / pi"},
};
_Static_assert(SSG_COUNT(inputs) == SSG_RSM_INPUTS, "one entry a port enumerator");

static const struct ssg_port_desc outputs[] = {
    [SSG_RSM_OUT_OUT] = {.name = "out", .types = SSG_T_COLOR, .lit = 1,
                         .doc = "one-bounce radiance albedo x E / pi (E / pi without albedo), "
                                "linear RGB, unoccluded"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_RSM_OUTPUTS, "one entry a port enumerator");

/* Flops per pixel (node.h), by reading rsm_cpu.c: about 40 for the pixel's world frame and
   output, per draw about 30 for the VPL's term (the searches are per run, not per pixel).
   samples = 0 counts every slot: an upper bound. */
static double rsm_flops(const void *consts, const struct ssg_shape *in)
{
    const struct ssg_rsm_consts *c = consts;
    (void)in;
    return 40.0 + 30.0 * (c->p.samples > 0 ? c->p.samples : c->slots);
}

const struct ssg_node_desc ssg_node_rsm = {
    .name = "rsm",
    .summary = "one diffuse bounce of the scene's lights from reflective shadow maps (VPLs)",
    .method = "Dachsbacher and Stamminger, Reflective Shadow Maps, I3D 2005, sec. 3 eq. 1 "
              "(the map's texels as pixel lights, no occlusion between sender and receiver); "
              "texels merged into VPLs and drawn by flux (stratified, 1 / pdf) instead of "
              "the paper's screen-space pattern around the receiver's projection",
    .doc = "Gathers the light the scene's point and directional lights reflect once off "
           "every surface their maps see (lightmaps: depth, normal, flux), whether or not "
           "it is on screen: E = sum of Phi / pi cos_sender cos_receiver / (d^2 max(d^2, "
           "A / pi)) over VPLs made of cell x cell texels, `samples` of them drawn per "
           "pixel by flux. No visibility between sender and receiver (RSM's limitation): "
           "darken the result with the frame's AO. out = albedo x E / pi, or E / pi without "
           "albedo, so that a graph can run it at low resolution, upsample and multiply by "
           "the full-resolution albedo. min_distance leaves the near field (d < "
           "min_distance, faded up to 2 min_distance) to a screen-space pass.",
    SSG_NODE_PORTS(inputs, outputs),
    SSG_NODE_PARAMS(params, struct ssg_rsm_params),
    .consts_size = sizeof(struct ssg_rsm_consts),
    .needs_scene = 1,
    .check = check,
    .prepare = prepare,
    .flops_per_pixel = rsm_flops,
    .run_cpu = ssg_rsm_run_cpu,
    .run_gl = ssg_rsm_run_gl,
};
