/* rsm.h - the `rsm` node (README.md): one diffuse bounce of the scene's own lights gathered from
 * their reflective shadow maps (nodes/common/lightmap.h). Shared by both backends: the
 * constants prepare() makes, the virtual point lights (VPLs) every run makes from the maps
 * and the layout both backends store them in (rsm_vpl.c on the CPU, rsm_cells.glsl and
 * rsm_list.glsl on GL, the same float operations in the same order).
 *
 * VPL slots. Face f of the maps is cut into C x C cells of `cell` x `cell` texels (C =
 * ceil(R / cell)); a cell's non-empty texels fall into 6 bins by the dominant axis of their
 * normal (ssg_lightmap_cube_face), so that a cell across a corner gives one VPL a wall, not
 * one with a mean normal pointing into the room. Slot s = ((f C + cy) C + cx) 6 + bin, laid
 * out on a (6 C) x (F C) grid: x = 6 cx + bin, y = f C + cy. A slot whose bin holds no flux
 * is empty; the list keeps the non-empty slots in slot order with the running sum of their
 * weights (the CDF). Thread safety: everything here is pure. */
#ifndef SSG_RSM_H
#define SSG_RSM_H

#include <math.h>

#include "graph/node.h"
#include "common/lightmap.h"

/* Ports, one row each (graph/node.h): enumerator, name, types, doc, further fields. On GL
   the maps are read by the cells pass (rsm_cells.glsl), the rest by the gather (rsm.glsl):
   .gl_in says which, and ssg_gl_ports binds each in its own. */
#define SSG_RSM_IN(X)                                                                      \
    X(SSG_RSM_IN_POSITION, "position", SSG_T_VECTOR,                                       \
      "view-space position (gbuffer or downsample), any size", .gl_in = "rsm.glsl")        \
    X(SSG_RSM_IN_NORMAL, "normal", SSG_T_VECTOR, "unit view-space normal, 0 = background", \
      .gl_in = "rsm.glsl")                                                                 \
    X(SSG_RSM_IN_MAP_DEPTH, "map_depth", SSG_T_LIGHTMAPS,                                  \
      "the lights' map depths (lightmaps.depth)", .gl_in = "rsm_cells.glsl")               \
    X(SSG_RSM_IN_MAP_NORMAL, "map_normal", SSG_T_LIGHTMAPS,                                \
      "the lights' map normals (lightmaps.normal)", .gl_in = "rsm_cells.glsl")             \
    X(SSG_RSM_IN_MAP_FLUX, "map_flux", SSG_T_LIGHTMAPS,                                    \
      "the lights' reflected flux (lightmaps.flux)", .gl_in = "rsm_cells.glsl")            \
    X(SSG_RSM_IN_ALBEDO, "albedo", SSG_T_COLOR,                                            \
      "diffuse albedo of the receivers; unconnected: out is the bounce a white receiver "  \
      "sends, E / pi",                                                                     \
      .optional = 1, .gl_in = "rsm.glsl")
#define SSG_RSM_OUT(X)                                                                     \
    X(SSG_RSM_OUT_OUT, "out", SSG_T_COLOR,                                                 \
      "one-bounce radiance albedo x E / pi (E / pi without albedo), linear RGB, "          \
      "unoccluded",                                                                        \
      .lit = 1, .gl_in = "rsm.glsl")
SSG_PORT_ENUM(ssg_rsm_input, SSG_RSM_IN, SSG_RSM_INPUTS);
SSG_PORT_ENUM(ssg_rsm_output, SSG_RSM_OUT, SSG_RSM_OUTPUTS);

enum { SSG_RSM_BINS = 6 };      /* VPLs a cell may give: one a dominant normal axis */
enum { SSG_RSM_TILE = 8 };      /* side of the interleaved offset tile, px */
enum { SSG_RSM_SLOT = 12 };     /* floats a VPL slot holds (below) */
enum { SSG_RSM_CELL_FLOATS = 11 }; /* of them, what the cell pass writes: all but the CDF */
enum { SSG_RSM_SAMPLES_MAX = 4096 };
/* Iterations one GL invocation's loops may make: llvmpipe ends a loop after 65535 (its
   LP_MAX_TGSI_LOOP_ITERATIONS), silently; the long walks are split into dispatches of at
   most this many. */
enum { SSG_RSM_GL_ITERATIONS = 32768 };
/* The surface area of a texel is its footprint across the ray over |cos(n, ray)|, the
   cosine floored here so that a grazing texel's area stays finite. */
#define SSG_RSM_MIN_COSINE 0.1f

/* One slot (floats, in this order): [0..2] position (world, flux-weighted), [3..5] unit
   normal (world, flux-weighted), [6..8] RGB flux Phi (W, summed), [9] r2 = area / pi (the
   squared radius of a disc of the cell's surface area, the floor of d^2), [10] weight
   w = Phi.r + Phi.g + Phi.b, [11] the CDF (the list only: the sum of w up to here). */

/* The parameters, one row each (lang/params.h). The struct below and the table in rsm.c
   are made from these rows; the GL passes read those not host_only as p_<field> (#pragma
   ssg_params), each in the shader its .gl_in names. */
#define SSG_RSM_PARAMS(P)                                                                  \
    P(INT, samples,                                                                        \
      "VPLs drawn per pixel in proportion to their flux (stratified, weighted by 1 / pdf); " \
      "0, or at least the VPL count, sums every VPL exactly",                              \
      .def = 64, .min = 0, .max = SSG_RSM_SAMPLES_MAX, .soft_min = 1, .soft_max = 1024,    \
      .gl_in = "rsm.glsl")                                                                 \
    P(INT, cell,                                                                           \
      "side of the map cells merged into VPLs (per dominant normal axis): larger is "      \
      "fewer, coarser VPLs; 1 = one VPL a texel",                                          \
      .def = 4, .min = 1, .max = 128, .soft_min = 1, .soft_max = 32, .unit = "texels",     \
      .gl_in = "rsm_cells.glsl")                                                           \
    P(FLOAT, min_distance,                                                                 \
      "senders nearer than this give nothing, fading in smoothly up to twice it, so a "    \
      "screen-space pass can own the near field (weight 1 - fade); 0 = none excluded",     \
      .def = 0, .min = 0, .max = 1e6, .soft_min = 0, .soft_max = 1, .unit = "world units", \
      .gl_in = "rsm.glsl")                                                                 \
    P(BOOL, own, "the maps hold the scene's own lights (lightmaps' own, the same value)",  \
      .def = 1, .host_only = 1)                                                            \
    P(INT, environment,                                                                    \
      "the maps hold this many environment lights (lightmaps' environment, the same "      \
      "value)",                                                                            \
      .def = 0, .min = 0, .max = SSG_LIGHTMAP_ENV_MAX, .soft_min = 0, .soft_max = 128,     \
      .unit = "lights", .host_only = 1)                                                    \
    P(BOOL, visibility,                                                                    \
      "test the segment from the receiver to each tested VPL in the scene's distance "     \
      "field (scene/distance.h), so the bounce no longer reaches through boxes and walls", \
      .def = 0, .host_only = 1)                                                            \
    P(INT, vis_draws,                                                                      \
      "draws a pixel tests for visibility (one of every samples / vis_draws, which one "   \
      "turning over the pixel's tile): the blocked ones' light, counted samples / "        \
      "vis_draws times, is taken off its bounce; 0 = every draw, exactly",                 \
      .def = 16, .min = 0, .max = SSG_RSM_SAMPLES_MAX, .soft_min = 0, .soft_max = 64,      \
      .host_only = 1)                                                                      \
    P(FLOAT, vis_start,                                                                    \
      "the trace starts this far off the receiver (along its normal and the segment) and " \
      "ends this far off the VPL, so their own surfaces do not occlude them",              \
      .def = 1.5, .min = 0, .max = 8, .soft_min = 0, .soft_max = 8, .unit = "voxels",      \
      .gl_in = "rsm.glsl")                                                                 \
    P(BOOL, turn,                                                                          \
      "a new offset tile every frame (the seed mixed with the frame index), so a temporal " \
      "node after the filter gathers other draws each frame; off, every frame makes the "  \
      "same draws (a still camera keeps the result)",                                     \
      .def = 0, .host_only = 1)
SSG_PARAMS_STRUCT(ssg_rsm_params, SSG_RSM_PARAMS);

struct ssg_rsm_consts {
    struct ssg_rsm_params p;
    float rot[9], eye[3];   /* view -> world: world = eye + rot^T view */
    int faces, res;         /* the maps' face count F and side R */
    int cells;              /* cells per face side C = ceil(R / cell) */
    int slots;              /* F C C 6 */
    int grid_w, grid_h;     /* the slot grid: 6 C x F C */
    int gl_list_rows;       /* rows of the slot grid one GL dispatch of the list walk takes
                               (SSG_RSM_GL_ITERATIONS / grid_w) */
    /* per face, 16 floats: origin[3], u[3], v[3], axis[3], half (perspective: tan of half
       the field of view), ortho, texel area across
       the ray (orthographic; cube: 0, per texel), unused */
    float face[16 * SSG_LIGHTMAP_FACES_MAX];
    struct ssg_lightmap_face face_s[SSG_LIGHTMAP_FACES_MAX]; /* the same faces, for C */
    /* the per-pixel offset of the stratified draws, tile^2 values in [0, 1) */
    float offset[SSG_RSM_TILE * SSG_RSM_TILE];
    float inv_samples;      /* 1 / samples (0 when samples = 0) */
    int vis;                /* 1 = visibility on and the scene has triangles to test */
    int vis_stride;         /* draw k is tested when k % vis_stride = the tile cell's
                               vis_phase and k / vis_stride < vis_tested; 1 = every draw
                               (so is an exact sum) */
    int vis_tested;         /* draws tested a pixel */
    int vis_phase[SSG_RSM_TILE * SSG_RSM_TILE]; /* per tile cell: draw t vis_stride + phase
                               is its t-th tested one; floor(64 offset) mod vis_stride
                               (rsm.c's prepare_visibility, after the offsets) */
    int grid_n[3];          /* the distance field's voxels a side (scene/distance.h) */
    float grid_lo[3];       /* its world corner */
    float grid_inv;         /* 1 / its voxel side: world units to voxels */
};

/* The constants the GL passes read (#pragma ssg_consts), rows over the consts' own fields
   (lang/params.h's SSG_UNIFORMS_AT_TABLE): kind, GLSL name, field, doc, the shaders. */
#define SSG_RSM_UNIFORMS(U)                                                                \
    U(MAT3, rot, rot, "view -> world rotation", .gl_in = "rsm.glsl")                        \
    U(VEC3, eye, eye, "the camera's world position", .gl_in = "rsm.glsl")                  \
    U(INT, res, res, "the maps' side R", .gl_in = "rsm_cells.glsl")                        \
    U(INT, ncells, cells, "cells per face side C", .gl_in = "rsm_cells.glsl")              \
    U(INT, rows, gl_list_rows, "slot grid rows a dispatch of the list walk takes",          \
      .gl_in = "rsm_list.glsl")                                                            \
    U(FLOAT, inv_samples, inv_samples, "1 / samples (0: exact)",                           \
      .gl_in = "rsm_picks.glsl rsm.glsl")                                                  \
    U(INT, vis, vis, "1 = visibility tested", .gl_in = "rsm.glsl")                          \
    U(INT, vis_stride, vis_stride, "every vis_stride-th draw tested", .gl_in = "rsm.glsl") \
    U(INT, vis_tested, vis_tested, "draws tested a pixel", .gl_in = "rsm.glsl")            \
    U(INT, grid_nx, grid_n[0], "the distance field's voxels on x", .gl_in = "rsm.glsl")    \
    U(INT, grid_ny, grid_n[1], "... on y", .gl_in = "rsm.glsl")                            \
    U(INT, grid_nz, grid_n[2], "... on z", .gl_in = "rsm.glsl")                            \
    U(VEC3, grid_lo, grid_lo, "its world corner", .gl_in = "rsm.glsl")                     \
    U(FLOAT, grid_inv, grid_inv, "1 / its voxel side", .gl_in = "rsm.glsl")

/* Builds the slots of rows y in [y0, y1) of the (6 C) x (F C) slot grid (every bin of the
   row's cells) from the maps' planes; `slots` holds SSG_RSM_SLOT floats a slot, [11] left
   0, a grid row's 6 C places packed: the row's slots that are not empty (w > 0) first, in
   slot order, then one whose w is 0 where they are fewer (the rest not written: most
   bins are empty, and writing and reading them all was most of the list's time). Returns
   0 when out of memory (its working rows), 1 otherwise. */
int ssg_rsm_cells(const struct ssg_rsm_consts *c, const float *depth, const float *normal,
                  const float *flux, int y0, int y1, float *slots);

/* Compacts the non-empty slots (ssg_rsm_cells' packed rows) into list (in slot order, CDF
   filled), returns their count n. When 0 < samples < n, pick[t S + k] gets draw k of
   every pixel at cell t of the offset tile (ssg_rsm_pick). */
int ssg_rsm_list(const struct ssg_rsm_consts *c, const float *slots, float *list, int *pick);

/* Draw k of tile cell t: the VPL whose CDF interval holds u = (k + offset[t]) / S x total,
   the smallest i with cdf_i > u (its last VPL when rounding puts u at the total). Every
   pixel of one tile cell makes the same draws, so they are searched once a run. */
int ssg_rsm_pick(const struct ssg_rsm_consts *c, const float *list, int count, int t, int k);

/* The smallest i in [lo, hi] with list[i].cdf > u, hi when none is. */
static inline int ssg_rsm_search(const float *list, int lo, int hi, float u)
{
    while (lo < hi) {
        int mid = (lo + hi) >> 1;
        if (list[(size_t)mid * SSG_RSM_SLOT + 11] > u)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* 1 when the segment from the receiver x (unit normal nx) to the VPL at y (unit normal ny)
   crosses no occupied voxel of the distance field `field` (README.md, "Visibility"): a
   sphere trace in voxel units from vis_start off x to vis_start off y, each step the
   voxel's distance less one voxel (its centre's, not the point's), one voxel at least;
   outside the grid, one voxel. Occupied voxels block only after the trace was in an
   empty one (before, they are the receiver's own surfaces). rsm.glsl's visible() makes
   the same operations. */
/* One trace's state (ssg_rsm_trace_begin, ssg_rsm_trace_step): split so the CPU can run
   several independent traces in lockstep (their voxel loads overlap instead of waiting on
   one another) with each trace's float operations the same as one alone. */
struct ssg_rsm_trace {
    float p[3], u[3], t, end;
    int out;    /* 1 once the trace was in an empty voxel: the occupied voxels before are
                   the receiver's own surfaces' (a step, a corner), not an occluder */
};

/* Starts a trace; returns 1 when the segment is too short to test (visible), 0 otherwise. */
static inline int ssg_rsm_trace_begin(const struct ssg_rsm_consts *c, const float x[3],
                                      const float nx[3], const float y[3], const float ny[3],
                                      struct ssg_rsm_trace *r)
{
    const float a = c->p.vis_start, inv = c->grid_inv;
    float d[3];
    for (int k = 0; k < 3; k++) {
        r->p[k] = (x[k] - c->grid_lo[k]) * inv + nx[k] * a;
        d[k] = ((y[k] - c->grid_lo[k]) * inv + ny[k] * a) - r->p[k];
    }
    float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    r->end = len - a;
    if (!(r->end > a))
        return 1; /* too near to tell from the surfaces' own voxels */
    for (int k = 0; k < 3; k++)
        r->u[k] = d[k] / len;
    r->t = a;
    r->out = 0;
    return 0;
}

/* One step of a begun trace: -1 while it goes on, 1 when it reached the end (visible), 0
   when it landed in an occluder. */
static inline int ssg_rsm_trace_step(const struct ssg_rsm_consts *c, const float *field,
                                     struct ssg_rsm_trace *r)
{
    if (!(r->t < r->end))
        return 1;
    int i[3], in = 1;
    for (int k = 0; k < 3; k++) {
        i[k] = (int)floorf(r->p[k] + r->u[k] * r->t);
        in &= i[k] >= 0 && i[k] < c->grid_n[k];
    }
    float step = 1.0f;
    if (in) {
        float dist = field[((size_t)i[2] * c->grid_n[1] + i[1]) * c->grid_n[0] + i[0]];
        if (dist == 0.0f && r->out)
            return 0;
        r->out |= dist != 0.0f;
        step = dist - 1.0f > 1.0f ? dist - 1.0f : 1.0f;
    } else {
        r->out = 1;
    }
    r->t += step;
    return -1;
}

static inline int ssg_rsm_visible(const struct ssg_rsm_consts *c, const float *field,
                                  const float x[3], const float nx[3], const float y[3],
                                  const float ny[3])
{
    struct ssg_rsm_trace r;
    if (ssg_rsm_trace_begin(c, x, nx, y, ny, &r))
        return 1;
    int seen;
    while ((seen = ssg_rsm_trace_step(c, field, &r)) < 0)
        ;
    return seen;
}

/* A backend's run with this frame's constants: `consts` itself, or with turn=true a copy
   whose offset tile and vis_phase are the frame's. */
typedef enum ssg_err (*ssg_rsm_backend_run)(const struct ssg_node_ctx *ctx,
                                            const struct ssg_rsm_consts *c,
                                            const struct ssg_io *io);
enum ssg_err ssg_rsm_run_frame(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io, ssg_rsm_backend_run run);

/* Runs the n begun traces tr (ssg_rsm_trace_begin returned 0 for each) to their ends in
   the scene's distance field (its bricked squares where it has them),
   SSG_RSM_LANES at a time (rsm_trace.c); seen[i] = trace i's outcome, 1 visible or 0
   blocked, the bits ssg_rsm_trace_step gives it alone. Traces of nearby segments next to
   each other in tr share their voxels' cache lines. */
enum { SSG_RSM_LANES = 32 };
struct ssg_distance;
void ssg_rsm_trace_all(const struct ssg_rsm_consts *c, const struct ssg_distance *field,
                       const struct ssg_rsm_trace *tr, int n, unsigned char *seen);

enum ssg_err ssg_rsm_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io);
enum ssg_err ssg_rsm_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                            const struct ssg_io *io);

extern const struct ssg_node_desc ssg_node_rsm;

#endif
