/* probe_light_cpu.c - CPU side of the `probe_light` node (method in README.md). Rows of
 * the G-buffer in fixed bands; in a band, chunks of CHUNK pixels are loaded once and every
 * light is applied to the whole chunk before the next, so a light's frame, irradiance and
 * map stay hot while the inner loop over pixels runs branch-free (vectorised, the map
 * read a gather; compiled per instruction set, SSG_VECTOR_CLONES). The courtyard's 128
 * lights at 720p: 320-360 ms a frame with the scalar loop this replaced, 45-50 ms now on 2
 * threads, the same bits. Chunk columns outside, a band's rows inside, as ssdo_cpu.c.
 * Soft lookups (soft_visibility) run the same way, one loop a tap. */
#include "common/vector_loops.h" /* first: see there */
#include <stdlib.h>

#include "common/luminance.h"
#include "probe_light.h"

enum { CHUNK = 64, PART = 16 };

struct job {
    const struct ssg_probe_light_consts *c;
    const struct ssg_io *io;
    const float *frames;   /* SSG_PROBE_LIGHT_FRAME per light */
    const float *cos_sin;  /* jitter rotation per light */
    int count, res, w, h;
    float offset_world;    /* offset in depth units: offset texels x 2 radius / res */
    float slope_world;     /* slope_offset texels in depth units */
    float normal_world;    /* normal_offset texels in scene units */
    float noise_radius;    /* from ctx->params, not the consts: a change of it alone
                              reruns without prepare() (check_params, probe_light.c) */
    int taps, search_taps; /* soft lookups (cone_tan > 0): taps of filter and search */
    float search;          /* the blocker search's radius, texels */
    int n;                 /* interleave: a chunk's pixels are n apart, its lights n^2 */
    const int *lit;        /* the lights that carry something, interleave cell by cell,
                              each cell's in light order (lit_lights) */
    const int *lit_start;  /* cell c's are lit[lit_start[c] .. lit_start[c + 1] - 1] */
};

struct chunk {
    float px[CHUNK], py[CHUNK], pz[CHUNK], nx[CHUNK], ny[CHUNK], nz[CHUNK];
    float jx[CHUNK], jy[CHUNK];                    /* the tile's jitter, in texels */
    float sum[3][CHUNK], lum_lit[CHUNK], lum_all[CHUNK];
    int32_t at[CHUNK];                             /* one light: the texel each pixel reads */
    float d[CHUNK];                                /* the pixel's depth, -inf: lit */
    float add[CHUNK];                              /* the depth offset there */
    float v[CHUNK];                                /* its visibility, 1 or 0 */
    /* soft lookups, one light: the lifted point's texel and depth, the receiver plane's
       depth per texel along x and y, the blockers' summed height and count, then the
       penumbra's radius (texels) and the filter's lit taps */
    float x[CHUNK], y[CHUNK], gx[CHUNK], gy[CHUNK], hsum[CHUNK], hcnt[CHUNK], rp[CHUNK];
    float ref[CHUNK];                              /* one tap: its receiver depth */
};

static inline __attribute__((always_inline)) void
load_chunk(const struct job *j, int y, int x0, int len, struct chunk *restrict k)
{
    const struct ssg_image *pos = j->io->in[SSG_PROBE_LIGHT_IN_POSITION];
    const struct ssg_image *nrm = j->io->in[SSG_PROBE_LIGHT_IN_NORMAL];
    size_t at = (size_t)y * j->w + x0, plane = (size_t)j->w * j->h;
    int tile = j->c->p.noise_tile, row = (y % tile) * tile, cells = tile * tile, n = j->n;
    int column = x0 % tile; /* (x0 + n i) mod tile, stepped: no division a pixel */
    for (int i = 0; i < len; i++) {
        size_t q = at + (size_t)n * i; /* pixel x0 + n i */
        k->px[i] = pos->data[q], k->py[i] = pos->data[plane + q];
        k->pz[i] = pos->data[2 * plane + q];
        k->nx[i] = nrm->data[q], k->ny[i] = nrm->data[plane + q];
        k->nz[i] = nrm->data[2 * plane + q];
        int cell = row + column;
        k->jx[i] = j->noise_radius * j->c->noise[cell];
        k->jy[i] = j->noise_radius * j->c->noise[cells + cell];
        column += n % tile;
        column -= column >= tile ? tile : 0;
        k->sum[0][i] = k->sum[1][i] = k->sum[2][i] = 0.0f;
        k->lum_lit[i] = k->lum_all[i] = 0.0f;
    }
}

/* Pixel i of the chunk on light f's map: its N.l (cosine), sin(N, l), and its point moved
   along the normal by normal_world sin(N, l) (the normal offset, README.md) as texel x, y
   and depth d. Both lookups start here. */
struct lifted {
    float cosine, sine, x, y, d;
};

static inline __attribute__((always_inline)) struct lifted
lift(const float *restrict f, float normal_world, const struct chunk *restrict k, int i)
{
    struct lifted o;
    o.cosine = k->nx[i] * f[12] + k->ny[i] * f[13] + k->nz[i] * f[14];
    float w = o.cosine > 0.0f ? o.cosine : 0.0f, c2 = 1.0f - w * w;
    o.sine = sqrtf(c2 > 0.0f ? c2 : 0.0f);
    float up = normal_world * o.sine;
    float qx = k->px[i] + up * k->nx[i], qy = k->py[i] + up * k->ny[i];
    float qz = k->pz[i] + up * k->nz[i];
    o.x = qx * f[0] + qy * f[1] + qz * f[2] + f[3];
    o.y = qx * f[4] + qy * f[5] + qz * f[6] + f[7];
    o.d = qx * f[8] + qy * f[9] + qz * f[10] + f[11];
    return o;
}

/* The depth offset of a lifted point (README.md): offset + slope x tan(N, l), the tangent
   0 where the light is behind the surface and at most SSG_PROBE_LIGHT_MAX_SLOPE. */
static inline __attribute__((always_inline)) float
depth_offset(struct lifted o, float offset, float slope)
{
    float q = o.sine / o.cosine; /* sin / cos where it counts; no trapping maths */
    float tangent = o.cosine > 0.0f ? q : 0.0f;
    tangent = tangent < SSG_PROBE_LIGHT_MAX_SLOPE ? tangent : SSG_PROBE_LIGHT_MAX_SLOPE;
    return offset + slope * tangent;
}

/* Light li's visibility of every pixel of the chunk, 1 or 0, into k->v: one loop finds
   each pixel's texel and the depth it must not exceed, a second reads the map there (a
   gather, which GCC vectorises only in a loop of its own) and compares. */
static inline __attribute__((always_inline)) void
light_visibility(const struct job *j, const float *restrict f, const float *restrict map,
                 float cr, float sr, int len, struct chunk *restrict k)
{
    const int res = j->res;
    const float fres = (float)res, normal_world = j->normal_world;
    const float offset = j->offset_world, slope = j->slope_world;
    for (int i = 0; i < len; i++) {
        struct lifted o = lift(f, normal_world, k, i);
        float x = o.x, y = o.y;
        x += cr * k->jx[i] - sr * k->jy[i];
        y += sr * k->jx[i] + cr * k->jy[i];
        int inside = (x >= 0.0f) & (y >= 0.0f) & (x < fres) & (y < fres);
        /* outside the map: lit, whatever the texel 0 it reads holds */
        k->at[i] = inside ? (int32_t)y * res + (int32_t)x : 0; /* res^2 < 2^31 */
        k->d[i] = inside ? o.d : -INFINITY;
        k->add[i] = depth_offset(o, offset, slope);
    }
    for (int i = 0; i < len; i++)
        k->v[i] = k->d[i] <= map[k->at[i]] + k->add[i] ? 1.0f : 0.0f;
}

/* Soft lookups, one light (README.md): each pixel's lifted point on the map (the normal
   offset as light_visibility's, no jitter), its depth, the depth offset, and the slope of
   its receiver plane in depth per texel, (N.u, N.v) / (s^2 N.l) (the map's scale s =
   1 / texel), clamped to tan 10 as the slope offset is: a tap beside the pixel is
   compared with its own surface there, not with the pixel's depth. */
static inline __attribute__((always_inline)) void
soft_setup(const struct job *j, const float *restrict f, int len, struct chunk *restrict k)
{
    const float normal_world = j->normal_world, offset = j->offset_world;
    const float slope = j->slope_world, texel = j->c->u.texel;
    const float tt = texel * texel, gmax = SSG_PROBE_LIGHT_MAX_SLOPE * texel;
    for (int i = 0; i < len; i++) {
        struct lifted o = lift(f, normal_world, k, i);
        float cosine = o.cosine;
        k->x[i] = o.x, k->y[i] = o.y, k->d[i] = o.d;
        float nu = k->nx[i] * f[0] + k->ny[i] * f[1] + k->nz[i] * f[2];
        float nv = k->nx[i] * f[4] + k->ny[i] * f[5] + k->nz[i] * f[6];
        float gx = nu * tt / cosine, gy = nv * tt / cosine;
        gx = cosine > 0.0f ? gx : 0.0f, gy = cosine > 0.0f ? gy : 0.0f;
        k->gx[i] = gx > gmax ? gmax : (gx < -gmax ? -gmax : gx);
        k->gy[i] = gy > gmax ? gmax : (gy < -gmax ? -gmax : gy);
        k->add[i] = depth_offset(o, offset, slope);
        k->hsum[i] = k->hcnt[i] = 0.0f, k->v[i] = 0.0f;
    }
}

/* One tap of every pixel at (ox, oy) texels from its point times scale[i] (NULL: 1): the
   texel it reads and the depth its receiver plane has there (-inf outside the map: lit). */
static inline __attribute__((always_inline)) void
soft_tap(const struct job *j, float ox, float oy, const float *restrict scale, int i0,
         int i1, struct chunk *restrict k)
{
    const int res = j->res;
    const float fres = (float)res;
    for (int i = i0; i < i1; i++) {
        float r = scale ? scale[i] : 1.0f, sx = r * ox, sy = r * oy;
        float x = k->x[i] + sx, y = k->y[i] + sy;
        int inside = (x >= 0.0f) & (y >= 0.0f) & (x < fres) & (y < fres);
        k->at[i] = inside ? (int32_t)y * res + (int32_t)x : 0;
        k->ref[i] = inside ? k->d[i] + (k->gx[i] * sx + k->gy[i] * sy) : -INFINITY;
    }
}

/* Light li's visibility of every pixel of the chunk, between 0 and 1, into k->v: the
   blockers in the search disc (taps deeper than the map plus the offset), their mean
   height over the receiver H; a penumbra of H x cone_tan texels (at least 1, at most the
   search radius) filtered by as many taps (PCSS, Fernando 2005). No blocker: lit; every
   tap a blocker: in the umbra (the filter's disc lies inside the search's), dark. A part
   of PART pixels without one in a penumbra skips the filter: the same values, less work
   (a light's penumbrae are bands a few pixels wide). */
static inline __attribute__((always_inline)) void
soft_visibility(const struct job *j, const float *restrict f, const float *restrict map,
                float cr, float sr, int len, struct chunk *restrict k)
{
    const int n = j->taps, m = j->search_taps;
    const float *tap = j->c->tap, *stap = tap + 2 * n, search = j->search;
    const float cone = j->c->u.cone_tan;
    soft_setup(j, f, len, k);
    for (int t = 0; t < m; t++) {
        float ox = cr * stap[t] - sr * stap[m + t], oy = sr * stap[t] + cr * stap[m + t];
        soft_tap(j, search * ox, search * oy, NULL, 0, len, k);
        for (int i = 0; i < len; i++) {
            float h = k->ref[i] - map[k->at[i]];
            int blocked = h > k->add[i];
            k->hsum[i] += blocked ? h : 0.0f;
            k->hcnt[i] += blocked ? 1.0f : 0.0f;
            k->v[i] = t == 0 ? (blocked ? 0.0f : 1.0f) : k->v[i];
        }
    }
    const float all = (float)m;
    for (int i = 0; i < len; i++) {
        float r = k->hsum[i] / (k->hcnt[i] > 0.0f ? k->hcnt[i] : 1.0f) * cone;
        k->rp[i] = r > 1.0f ? (r < search ? r : search) : 1.0f;
    }
    for (int i0 = 0; i0 < len; i0 += PART) {
        int i1 = len - i0 < PART ? len : i0 + PART;
        int32_t any = 0; /* a pixel of the part in a penumbra: some blockers, not all */
        for (int i = i0; i < i1; i++)
            any |= (k->hcnt[i] > 0.0f) & (k->hcnt[i] < all);
        for (int t = 1; any && t < n; t++) { /* tap 0, the centre, is the search's */
            float ox = cr * tap[t] - sr * tap[n + t], oy = sr * tap[t] + cr * tap[n + t];
            soft_tap(j, ox, oy, k->rp, i0, i1, k);
            for (int i = i0; i < i1; i++)
                k->v[i] += k->ref[i] - map[k->at[i]] > k->add[i] ? 0.0f : 1.0f;
        }
    }
    const float share = 1.0f / (float)n;
    for (int i = 0; i < len; i++)
        k->v[i] = k->hcnt[i] < all ? (k->hcnt[i] > 0.0f ? k->v[i] * share : 1.0f) : 0.0f;
}

/* Light li's share of every pixel of the chunk. */
static inline __attribute__((always_inline)) void add_light(const struct job *j, int li,
                                                            int len, struct chunk *restrict k)
{
    const float *f = j->frames + (size_t)li * SSG_PROBE_LIGHT_FRAME;
    const struct ssg_image *lights = j->io->in[SSG_PROBE_LIGHT_IN_LIGHTS];
    const struct ssg_image *maps = j->io->in[SSG_PROBE_LIGHT_IN_SHADOWMAPS];
    int n = j->count;
    float er = lights->data[n + li], eg = lights->data[3 * n + li],
          eb = lights->data[5 * n + li];
    float el = ssg_luminance(er, eg, eb), cr = j->cos_sin[2 * li], sr = j->cos_sin[2 * li + 1];
    if (er == 0.0f && eg == 0.0f && eb == 0.0f)
        return; /* a light that carries nothing (lightprobe missing=dark) adds exact zeros */
    /* A light behind every pixel of the chunk adds exact zeros: skip it (half the lights
       for a floor, whatever the backend, with the same sums). */
    int32_t facing = 0; /* an integer OR vectorises; a float max did not (45 % of the node) */
    for (int i = 0; i < len; i++) {
        float cosine = k->nx[i] * f[12] + k->ny[i] * f[13] + k->nz[i] * f[14];
        facing |= cosine > 0.0f;
    }
    if (!facing)
        return;
    if (maps && j->c->u.cone_tan > 0.0f)
        soft_visibility(j, f, ssg_image_plane(maps, li), cr, sr, len, k);
    else if (maps)
        light_visibility(j, f, ssg_image_plane(maps, li), cr, sr, len, k);
    for (int i = 0; i < len; i++) {
        float cosine = k->nx[i] * f[12] + k->ny[i] * f[13] + k->nz[i] * f[14];
        float w = cosine > 0.0f ? cosine : 0.0f;
        float lit = maps ? k->v[i] * w : w;
        k->sum[0][i] += lit * er, k->sum[1][i] += lit * eg, k->sum[2][i] += lit * eb;
        k->lum_lit[i] += lit * el, k->lum_all[i] += w * el;
    }
}

static inline __attribute__((always_inline)) void
store_chunk(const struct job *j, int y, int x0, int len, const struct chunk *restrict k)
{
    const struct ssg_image *alb = j->io->in[SSG_PROBE_LIGHT_IN_ALBEDO];
    size_t at = (size_t)y * j->w + x0, plane = (size_t)j->w * j->h;
    float *out = j->io->out[0]->data, *vis = j->io->out[1]->data;
    const float weight = (float)(j->n * j->n); /* each light stands for n^2 (interleave) */
    for (int i = 0; i < len; i++) {
        size_t q = at + (size_t)j->n * i;
        int bg = k->nx[i] == 0.0f && k->ny[i] == 0.0f && k->nz[i] == 0.0f;
        for (int c = 0; c < 3; c++) /* no albedo: a white receiver's */
            out[c * plane + q] =
                bg ? 0.0f
                   : (alb ? alb->data[c * plane + q] : 1.0f) * (float)(1.0 / M_PI) *
                         (k->sum[c][i] * weight);
        vis[q] = bg || !(k->lum_all[i] > 0.0f) ? 1.0f : k->lum_lit[i] / k->lum_all[i];
    }
}

SSG_VECTOR_CLONES
static void chunk(const struct job *j, int y, int x0, int len, struct chunk *restrict k)
{
    load_chunk(j, y, x0, len, k);
    /* the lights of the pixels' interleave cell, i mod n^2 = (y mod n) n + x0 mod n, that
       carry something (the others add exact zeros) */
    const int n = j->n, cell = (y % n) * n + x0 % n;
    for (int q = j->lit_start[cell]; q < j->lit_start[cell + 1]; q++)
        add_light(j, j->lit[q], len, k);
    store_chunk(j, y, x0, len, k);
}

/* Chunks of CHUNK pixels n apart (interleave n: pixels of one tile column, which take the
   same lights), their columns outside, the band's rows inside. */
static void rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    const int n = j->n;
    for (int b0 = 0; b0 < j->w; b0 += CHUNK * n)
        for (int x0 = b0; x0 < b0 + n && x0 < j->w; x0++) {
            int len = (j->w - x0 + n - 1) / n; /* pixels x0 + n i left in the row */
            len = len < CHUNK ? len : CHUNK;
            for (int y = y0; y < y1; y++)
                chunk(j, y, x0, len, &k);
        }
}

/* The lights that carry something (not black: add_light's test), grouped by interleave
   cell (light i in cell i mod n^2), in light order within each: a dark probe's lights
   (lightprobe missing=dark) were most of a frame's node time, each chunk testing them
   all. lit holds count ints, lit_start n^2 + 1. */
static void lit_lights(const float *lights, int count, int n, int *lit, int *lit_start)
{
    int q = 0;
    for (int cell = 0; cell < n * n; cell++) {
        lit_start[cell] = q;
        for (int li = cell; li < count; li += n * n) {
            float er = lights[count + li], eg = lights[3 * count + li],
                  eb = lights[5 * count + li];
            if (!(er == 0.0f && eg == 0.0f && eb == 0.0f))
                lit[q++] = li;
        }
    }
    lit_start[n * n] = q;
}

enum ssg_err ssg_probe_light_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                     const struct ssg_io *io)
{
    const struct ssg_probe_light_consts *c = consts;
    const int count = c->u.count, res = c->u.res;
    const struct ssg_probe_light_params *p = ctx->params;
    const int n = p->interleave;
    float *frames = malloc(sizeof(float) * SSG_PROBE_LIGHT_FRAME * (size_t)count);
    int *lit = malloc(sizeof(int) * ((size_t)count + (size_t)n * n + 1));
    if (!frames || !lit) {
        free(frames);
        free(lit);
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    }
    const float *l = io->in[SSG_PROBE_LIGHT_IN_LIGHTS]->data;
    for (int i = 0; i < count; i++) {
        float dir[3] = {l[i], l[2 * count + i], l[4 * count + i]};
        ssg_probe_light_frame(c, dir, c->frame_res, frames + SSG_PROBE_LIGHT_FRAME * i);
    }
    lit_lights(l, count, n, lit, lit + count);
    const struct ssg_image *pos = io->in[SSG_PROBE_LIGHT_IN_POSITION];
    struct job j = {c, io, frames, c->cos_sin, count, res, pos->width, pos->height,
                    c->u.offset_world, c->u.slope_world, c->u.normal_world, p->noise_radius,
                    c->p.taps, c->p.search_taps, c->p.search_radius, n, lit, lit + count};
    ssg_parallel_rows(pos->height, 16, rows, &j);
    free(frames);
    free(lit);
    return SSG_OK;
}
