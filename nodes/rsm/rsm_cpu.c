/* rsm_cpu.c - CPU side of the `rsm` node (method in README.md): the VPL slots of the maps in row
 * bands, the list and its CDF on the node's thread (a running sum: one order, whatever the
 * threads), then every pixel's draws in row bands. Each pixel depends on its own inputs
 * and the list alone, so the output is the same for every thread count. The list and the
 * draws are kept in the node's scratch while the maps and the constants they come from
 * stand (vpl_list): a moving camera does not make them again. */
#include "common/vector_loops.h" /* first: see there */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "rsm.h"
#include "scene/distance.h"
#include "scene/scene.h"

struct cells_job {
    const struct ssg_rsm_consts *c;
    const struct ssg_io *io;
    float *slots;
    _Atomic int failed; /* a band ran out of memory */
};

static void cell_rows(void *user, int y0, int y1)
{
    struct cells_job *j = user;
    if (!ssg_rsm_cells(j->c, j->io->in[SSG_RSM_IN_MAP_DEPTH]->data,
                       j->io->in[SSG_RSM_IN_MAP_NORMAL]->data,
                       j->io->in[SSG_RSM_IN_MAP_FLUX]->data, y0, y1, j->slots))
        j->failed = 1;
}

struct job {
    const struct ssg_rsm_consts *c;
    const struct ssg_io *io;
    const float *list;
    const int *pick;  /* SSG_RSM_TILE^2 x samples draws (ssg_rsm_list) */
    int count, w, h;
    const struct ssg_distance *distance; /* the scene's distance field (visibility on) */
    const float *field; /* its voxels */
    float far2;         /* the least d^2 with sqrtf(d^2) >= 2 min_distance: from there on
                           the fade is exactly 1 (far_squared) */
};

/* A band's rows: two of the tile's, so that a chunk holds a tile cell's pixels of two rows
   (80 at 1280x720's quarter resolution, 40 at 640x360's), not one row's: the draws' set-up
   and the batched traces are shared by twice the pixels (rsm 21.2 -> 17.4 ms at 1280x720,
   8.5 -> 7.3 at 640x360 on the orbit, 5 pairs; issue 47's third pass). Each pixel is computed alone, so this changes no
   value. */
enum { CHUNK = 96, BAND_ROWS = 2 * SSG_RSM_TILE };

/* Pixels that share a tile cell, so the same draws: every SSG_RSM_TILE-th of rows
   SSG_RSM_TILE apart. */
struct chunk {
    size_t at[CHUNK];                /* their index in the planes */
    float x[3][CHUNK], n[3][CHUNK];  /* the receivers, world */
    float sum[3][CHUNK];
    int bg[CHUNK];
};

/* 1 when receiver i of the chunk sees VPL v (ssg_rsm_visible). */
static int visible_from(const struct job *j, const struct chunk *k, int i, const float *v)
{
    const float x[3] = {k->x[0][i], k->x[1][i], k->x[2][i]};
    const float n[3] = {k->n[0][i], k->n[1][i], k->n[2][i]};
    return ssg_rsm_visible(j->c, j->field, x, n, v, v + 3);
}

/* The receivers (pixels k->at[0 .. len - 1]) in world space: x = eye + rot^T p,
   n = rot^T n_view. */
static void load_chunk(const struct job *j, int len, struct chunk *restrict k)
{
    const struct ssg_rsm_consts *c = j->c;
    const float *pos = j->io->in[SSG_RSM_IN_POSITION]->data;
    const float *nrm = j->io->in[SSG_RSM_IN_NORMAL]->data;
    size_t plane = (size_t)j->w * j->h;
    for (int i = 0; i < len; i++) {
        size_t at = k->at[i];
        float p[3] = {pos[at], pos[plane + at], pos[2 * plane + at]};
        float n[3] = {nrm[at], nrm[plane + at], nrm[2 * plane + at]};
        k->bg[i] = n[0] == 0.0f && n[1] == 0.0f && n[2] == 0.0f;
        for (int r = 0; r < 3; r++) {
            k->x[r][i] = c->eye[r] + c->rot[r] * p[0] + c->rot[3 + r] * p[1] +
                         c->rot[6 + r] * p[2];
            k->n[r][i] = c->rot[r] * n[0] + c->rot[3 + r] * n[1] + c->rot[6 + r] * n[2];
            k->sum[r][i] = 0.0f;
        }
    }
}

/* VPL v's irradiance x pi at receiver i over its flux, times `scale`: Phi cos_v cos_x /
   (d^2 max(d^2, r2)) x fade(d) / Phi (README.md), 0 behind either surface; the fade over
   m = min_distance when `fade` (a constant where a loop must vectorise: GCC leaves a
   condition it cannot fold a branch in the loop). Branch-free (a select, never a NaN added), so the
   loops over the pixels that call it vectorise. */
static inline __attribute__((always_inline)) float
vpl_weight(const float *restrict v, float scale, int fade, float m,
           const struct chunk *restrict k, int i)
{
    float dx = v[0] - k->x[0][i], dy = v[1] - k->x[1][i], dz = v[2] - k->x[2][i];
    float d2 = dx * dx + dy * dy + dz * dz;
    float cs = -(v[3] * dx + v[4] * dy + v[5] * dz);
    float cr = k->n[0][i] * dx + k->n[1][i] * dy + k->n[2][i] * dz;
    float g = cs * cr / (d2 * (d2 > v[9] ? d2 : v[9]));
    if (fade) {
        float t = (sqrtf(d2) - m) / m;
        t = t < 0.0f ? 0.0f : t > 1.0f ? 1.0f : t;
        g = g * (t * t * (3.0f - 2.0f * t));
    }
    int ok = (d2 > 0.0f) & (cs > 0.0f) & (cr > 0.0f);
    return ok ? scale * g : 0.0f;
}

/* VPL v's term at every receiver of the chunk into the sums; each pixel's sum runs in draw
   order, as on GL. */
static inline __attribute__((always_inline)) void
add_terms(const float *restrict v, float scale, int fade, float m, int len,
          struct chunk *restrict k)
{
    for (int i = 0; i < len; i++) {
        float w = vpl_weight(v, scale, fade, m, k, i);
        k->sum[0][i] += w * v[6];
        k->sum[1][i] += w * v[7];
        k->sum[2][i] += w * v[8];
    }
}

/* 1 when a receiver of the chunk lies nearer VPL v than sqrtf(d^2) = 2 min_distance. Out
   of line: inlined, its result kept GCC from vectorising the faded loop it chooses. */
SSG_VECTOR_CLONES __attribute__((noinline)) static int
any_near(const float *restrict v, float far2, int len, const struct chunk *restrict k)
{
    int near = 0;
    for (int i = 0; i < len; i++) {
        float dx = v[0] - k->x[0][i], dy = v[1] - k->x[1][i], dz = v[2] - k->x[2][i];
        near |= dx * dx + dy * dy + dz * dz < far2; /* vpl_weight's d2 */
    }
    return near;
}

/* add_terms; where every receiver is far enough for the fade to be exactly 1 (most VPLs of
   most chunks), without it: its square root and division are half the loop's time. */
static inline __attribute__((always_inline)) void
add_vpl(const struct job *j, const float *restrict v, float scale, int len,
        struct chunk *restrict k)
{
    const float m = j->c->p.min_distance;
    if (m > 0.0f && any_near(v, j->far2, len, k))
        add_terms(v, scale, 1, m, len, k);
    else
        add_terms(v, scale, 0, 0.0f, len, k);
}

/* The same with each term's visibility (visibility on, every draw tested): one trace per
   pixel where the term is not 0, so not a vector loop. */
static void add_vpl_visible(const struct job *j, const float *v, float scale, int len,
                            struct chunk *k)
{
    for (int i = 0; i < len; i++) {
        const float m = j->c->p.min_distance;
        float w = vpl_weight(v, scale, m > 0.0f, m, k, i);
        if (w > 0.0f && !visible_from(j, k, i, v))
            w = 0.0f;
        k->sum[0][i] += w * v[6];
        k->sum[1][i] += w * v[7];
        k->sum[2][i] += w * v[8];
    }
}

/* Every VPL (samples 0 or at least the count), or the tile cell's draws, each weighted
   1 / (S pdf) = total / (S w). With visibility on every draw tested, each term is
   shadowed; with vis_stride > 1 the sum stays unshadowed here (shadow_subtract corrects it). */
SSG_VECTOR_CLONES
static void gather(const struct job *j, const int *pick, int len, struct chunk *restrict k)
{
    const struct ssg_rsm_consts *c = j->c;
    const int S = c->p.samples, n = j->count;
    const int each = c->vis && (S == 0 || S >= n || c->vis_stride == 1);
    if (S == 0 || S >= n) {
        for (int i = 0; i < n; i++) {
            if (each)
                add_vpl_visible(j, j->list + (size_t)i * SSG_RSM_SLOT, 1.0f, len, k);
            else
                add_vpl(j, j->list + (size_t)i * SSG_RSM_SLOT, 1.0f, len, k);
        }
        return;
    }
    float total = j->list[(size_t)(n - 1) * SSG_RSM_SLOT + 11];
    float step = c->inv_samples * total;
    for (int s = 0; s < S; s++) {
        const float *v = j->list + (size_t)pick[s] * SSG_RSM_SLOT;
        if (each)
            add_vpl_visible(j, v, step / v[10], len, k);
        else
            add_vpl(j, v, step / v[10], len, k);
    }
}

enum { VIS_BATCH = 8 }; /* tested draws whose traces at a chunk's pixels run together */

/* A batch of tested draws at every pixel of a chunk: their terms, the begun traces (draw by
   draw, pixel by pixel: the lanes running together trace from neighbouring pixels to one
   VPL, through the same voxels), each one's term index b CHUNK + i and the outcomes. */
struct tested {
    float w[VIS_BATCH][CHUNK];
    struct ssg_rsm_trace tr[VIS_BATCH * CHUNK];
    int term[VIS_BATCH * CHUNK];
    unsigned char outcome[VIS_BATCH * CHUNK]; /* by trace */
    unsigned char seen[VIS_BATCH * CHUNK];    /* by term: 1 visible or not traced */
};

/* The batch's terms at every pixel, as gather weighs them: a vector loop. */
SSG_VECTOR_CLONES
static void tested_weights(const struct ssg_rsm_consts *c, const float *const *v,
                           const float *scale, int nb, int len, const struct chunk *restrict k,
                           float (*restrict w)[CHUNK])
{
    const float m = c->p.min_distance;
    for (int b = 0; b < nb; b++)
        if (m > 0.0f)
            for (int i = 0; i < len; i++)
                w[b][i] = vpl_weight(v[b], scale[b], 1, m, k, i);
        else
            for (int i = 0; i < len; i++)
                w[b][i] = vpl_weight(v[b], scale[b], 0, 0.0f, k, i);
}

/* Begins the trace of every term of the batch that is not 0; returns their count. */
static int begin_traces(const struct job *j, const struct chunk *k, const float *const *v,
                        int nb, int len, struct tested *s)
{
    int n = 0;
    for (int b = 0; b < nb; b++)
        for (int i = 0; i < len; i++) {
            s->seen[b * CHUNK + i] = 1;
            if (!(s->w[b][i] > 0.0f))
                continue;
            const float x[3] = {k->x[0][i], k->x[1][i], k->x[2][i]};
            const float nx[3] = {k->n[0][i], k->n[1][i], k->n[2][i]};
            if (!ssg_rsm_trace_begin(j->c, x, nx, v[b], v[b] + 3, &s->tr[n]))
                s->term[n++] = b * CHUNK + i;
        }
    return n;
}

/* Visibility by a control variate: each pixel's unshadowed sum less the occluded light of
   its tested draws (one of every vis_stride, at the tile cell's phase), each scaled by
   vis_stride (README.md, "Visibility"); unbiased over the tile, clamped at 0 where the
   few tested draws overshoot. Every pixel of the chunk tests the same draws. Out of line,
   so a profile shows its cost apart. */
__attribute__((noinline)) static void shadow_subtract(const struct job *j, const int *pick,
                                                      int phase, int len, struct chunk *k,
                                                      struct tested *s)
{
    const struct ssg_rsm_consts *c = j->c;
    float total = j->list[(size_t)(j->count - 1) * SSG_RSM_SLOT + 11];
    float step = c->inv_samples * total;
    const float stride = (float)c->vis_stride;
    for (int t0 = 0; t0 < c->vis_tested; t0 += VIS_BATCH) {
        int nb = c->vis_tested - t0 < VIS_BATCH ? c->vis_tested - t0 : VIS_BATCH;
        const float *v[VIS_BATCH];
        float scale[VIS_BATCH];
        for (int b = 0; b < nb; b++) {
            v[b] = j->list + (size_t)pick[(t0 + b) * c->vis_stride + phase] * SSG_RSM_SLOT;
            scale[b] = step / v[b][10];
        }
        tested_weights(c, v, scale, nb, len, k, s->w);
        int n = begin_traces(j, k, v, nb, len, s);
        ssg_rsm_trace_all(c, j->distance, s->tr, n, s->outcome);
        for (int q = 0; q < n; q++)
            s->seen[s->term[q]] = s->outcome[q];
        for (int i = 0; i < len; i++) /* each pixel's terms in draw order, as rsm.glsl */
            for (int b = 0; b < nb; b++)
                for (int ch = 0; !s->seen[b * CHUNK + i] && ch < 3; ch++)
                    k->sum[ch][i] = k->sum[ch][i] - stride * (s->w[b][i] * v[b][6 + ch]);
    }
    for (int i = 0; i < len; i++)
        for (int ch = 0; ch < 3; ch++)
            k->sum[ch][i] = k->sum[ch][i] > 0.0f ? k->sum[ch][i] : 0.0f;
}

static void store_chunk(const struct job *j, int len, const struct chunk *restrict k)
{
    const struct ssg_image *alb = j->io->in[SSG_RSM_IN_ALBEDO];
    float *out = j->io->out[SSG_RSM_OUT_OUT]->data;
    size_t plane = (size_t)j->w * j->h;
    for (int i = 0; i < len; i++) {
        size_t at = k->at[i];
        for (int r = 0; r < 3; r++) {
            float a = alb ? alb->data[r * plane + at] : 1.0f;
            /* E / pi = sum / pi^2 */
            out[r * plane + at] = k->bg[i] ? 0.0f : a * (k->sum[r][i] * 0.101321184f);
        }
    }
}

/* Visibility by the control variate: on, sampled and not every draw tested. */
static int subtracted(const struct job *j)
{
    const int S = j->c->p.samples;
    return j->c->vis && S > 0 && S < j->count && j->c->vis_stride > 1;
}

/* The least float x with sqrtf(x) >= 2 m (m > 0): at d^2 >= x, (sqrtf(d^2) - m) / m >= 1
   in floats too (each rounding is monotonic), so the fade's smoothstep is exactly 1. */
static float far_squared(float m)
{
    const float two_m = 2.0f * m;
    float x = two_m * two_m;
    while (sqrtf(x) < two_m)
        x = nextafterf(x, INFINITY);
    while (x > 0.0f && sqrtf(nextafterf(x, 0.0f)) >= two_m)
        x = nextafterf(x, 0.0f);
    return x;
}

/* The chunk's len pixels, those of tile cell t: their draws, visibility, result. */
static void run_chunk(const struct job *j, int t, int len, struct chunk *k, struct tested *s)
{
    const int *pick = j->pick + (size_t)t * j->c->p.samples;
    load_chunk(j, len, k);
    if (j->count > 0)
        gather(j, pick, len, k);
    if (j->count > 0 && subtracted(j))
        shadow_subtract(j, pick, j->c->vis_phase[t], len, k, s);
    store_chunk(j, len, k);
}

/* Jobs r0 .. r1 - 1 of ssg_parallel_rows: job r is tile column r mod SSG_RSM_TILE of band
   r / SSG_RSM_TILE (BAND_ROWS rows), so that there are as many jobs as 4-row bands were
   (a machine of many cores keeps them busy) while each chunk holds two rows. */
static void rows(void *user, int r0, int r1)
{
    const struct job *j = user;
    struct chunk k;
    struct tested s;
    for (int r = r0; r < r1; r++) {
        const int tx = r % SSG_RSM_TILE, y0 = r / SSG_RSM_TILE * BAND_ROWS;
        const int y1 = y0 + BAND_ROWS < j->h ? y0 + BAND_ROWS : j->h;
        for (int ty = 0; ty < SSG_RSM_TILE && y0 + ty < y1 && tx < j->w; ty++) {
            const int t = ((y0 + ty) % SSG_RSM_TILE) * SSG_RSM_TILE + tx;
            int len = 0;
            for (int y = y0 + ty; y < y1; y += SSG_RSM_TILE)
                for (int x = tx; x < j->w; x += SSG_RSM_TILE) {
                    k.at[len++] = (size_t)y * j->w + (size_t)x;
                    if (len == CHUNK) {
                        run_chunk(j, t, len, &k, &s);
                        len = 0;
                    }
                }
            if (len > 0)
                run_chunk(j, t, len, &k, &s);
        }
    }
}

/* What the VPL list and the draws are made from: the maps (the serials of the runs that
   made them, node.h's in_made) and the constants ssg_rsm_cells, ssg_rsm_list and
   ssg_rsm_pick read. While it stands the list is not made again: a moving camera re-runs
   rsm every frame, but the light maps of a static scene, and so the list, stay. */
struct list_key {
    unsigned long long made[3];
    int faces, res, cells, slots, grid_w, grid_h, cell, samples;
    float inv_samples, offset[SSG_RSM_TILE * SSG_RSM_TILE];
    struct ssg_lightmap_face face[SSG_LIGHTMAP_FACES_MAX];
};

/* The head of the node's scratch: the key of the list that follows it, and its length. */
struct list_head {
    struct list_key key;
    int valid, count;
};

/* The key of this run's list; 0 when it cannot be kept (a map's serial is unknown). */
static int make_key(const struct ssg_node_ctx *ctx, const struct ssg_rsm_consts *c,
                    struct list_key *k)
{
    memset(k, 0, sizeof *k); /* padding too: keys are compared with memcmp */
    const int ports[3] = {SSG_RSM_IN_MAP_DEPTH, SSG_RSM_IN_MAP_NORMAL, SSG_RSM_IN_MAP_FLUX};
    for (int i = 0; i < 3; i++)
        if (!ctx->in_made || !(k->made[i] = ctx->in_made[ports[i]]))
            return 0;
    k->faces = c->faces, k->res = c->res, k->cells = c->cells, k->slots = c->slots;
    k->grid_w = c->grid_w, k->grid_h = c->grid_h, k->cell = c->p.cell;
    k->samples = c->p.samples, k->inv_samples = c->inv_samples;
    memcpy(k->offset, c->offset, sizeof k->offset);
    memcpy(k->face, c->face_s, sizeof k->face[0] * (size_t)c->faces);
    return 1;
}

/* The list and draws into the scratch after head (made again unless head's key is this
   run's); their count, or -1 when out of memory. */
static int vpl_list(const struct ssg_node_ctx *ctx, const struct ssg_rsm_consts *c,
                    const struct ssg_io *io, struct list_head *head, int fresh,
                    float *slots, float *list, int *pick)
{
    static _Thread_local struct list_key key; /* 40 KB: not on the stack */
    int keep = make_key(ctx, c, &key);
    if (keep && !fresh && head->valid && memcmp(&head->key, &key, sizeof key) == 0)
        return head->count;
    head->valid = 0;
    struct cells_job cj = {c, io, slots, 0};
    ssg_parallel_rows(c->grid_h, 2, cell_rows, &cj);
    if (cj.failed)
        return -1;
    head->count = ssg_rsm_list(c, slots, list, pick);
    head->key = key;
    head->valid = keep;
    return head->count;
}

/* One run with the frame's constants (ssg_rsm_run_frame). */
static enum ssg_err run(const struct ssg_node_ctx *ctx, const struct ssg_rsm_consts *c,
                        const struct ssg_io *io)
{
    size_t slot_floats = (size_t)c->slots * SSG_RSM_SLOT;
    size_t head_bytes = (sizeof(struct list_head) + 63) / 64 * 64;
    size_t bytes = head_bytes + 2 * slot_floats * sizeof(float) +
                   sizeof(int) * SSG_RSM_TILE * SSG_RSM_TILE * (size_t)c->p.samples;
    /* a scratch made anew (none kept, or too small: ssg_node_scratch replaces it) holds no
       list; its bytes are not even set */
    int fresh = !ctx->scratch || !ctx->scratch->data || ctx->scratch->bytes < bytes;
    struct list_head *head = ssg_node_scratch(ctx, bytes);
    if (!head)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    float *slots = (float *)((char *)head + head_bytes), *list = slots + slot_floats;
    int *pick = (int *)(list + slot_floats);
    int count = vpl_list(ctx, c, io, head, fresh, slots, list, pick);
    if (count < 0)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    const struct ssg_image *pos = io->in[SSG_RSM_IN_POSITION];
    struct job j = {c, io, list, pick, count, pos->width,
                    pos->height, c->vis ? ctx->scene->distance : NULL,
                    c->vis ? ctx->scene->distance->d : NULL,
                    c->p.min_distance > 0.0f ? far_squared(c->p.min_distance) : 0.0f};
    const int bands = (pos->height + BAND_ROWS - 1) / BAND_ROWS;
    ssg_parallel_rows(bands * SSG_RSM_TILE, 1, rows, &j);
    return SSG_OK;
}

enum ssg_err ssg_rsm_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    return ssg_rsm_run_frame(ctx, consts, io, run);
}
