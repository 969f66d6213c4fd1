/* direct_light_lanes.c - the PCF taps of one light over a chunk's lit pixels at once
 * (direct_light_cpu.h, "Why lanes"): a tap for every lane is one straight loop, its map
 * reads gathers, so the receiver-plane limits (two square roots and three divisions a tap)
 * run in vector lanes instead of one dependent chain a pixel. A lane whose four texels are
 * not all on its face (past a cube face's edge, across a tile's, off the map) takes the
 * per-pixel dl_bilinear_test instead, the same operations. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>

#include "direct_light_cpu.h"

enum { EARLY = 4 };

/* How the lanes read a light's maps: texel (x, y) of the lane's face at base + y res + x,
   or of a tiled map (tiles a side, res = 1 << shift) at its tile's face; or not at all
   (every tap per pixel): maps too large for int indices, tiles of another side, res < 2. */
enum reads { READ_FACE, READ_TILES, READ_NONE };

struct taps_in {
    const float *maps;
    int res, side, tiles, shift, first; /* side: of the whole map; first: its element 0 */
    float slope;                        /* tap_slope */
};

void dl_lane_lookup(const struct dl_lanes *L, const struct ssg_direct_light_light *l, int a,
                    struct dl_lookup *k)
{
    *k = (struct dl_lookup){.l = l, .f = L->f[a], .x = L->x[a], .y = L->y[a], .r = L->r[a],
                            .z = L->z[a], .texel = L->texel[a], .bias = L->bias[a],
                            .gx = L->gx[a], .gy = L->gy[a], .nq = L->nq[a]};
    for (int c = 0; c < 3; c++)
        k->n[c] = L->n[c][a];
}

/* Tap (tx, ty) of the unit disc for every lane: its bilinear PCF value added to the
   lane's sum, but where a lane's texels are not all on its face, its texel coordinates
   into (xs, ys) and slow = 1 instead (0 added: the sum stays, never -0). Whether any is. point, tiled: the light's kind and map, constants
   where this is inlined, so each loop is straight. */
static inline __attribute__((always_inline)) int
tap_lanes(struct dl_lanes *restrict L, const struct taps_in *in, float tx, float ty,
          int point, int reads, int pow2, float *restrict xs, float *restrict ys,
          int *restrict slow)
{
    int any = 0;
    const int res = in->res, mask = res - 1, last = in->side - 1;
    for (int a = 0; a < L->count; a++) {
        float ox = L->cs[a] * tx - L->sn[a] * ty;
        float oy = L->sn[a] * tx + L->cs[a] * ty;
        float x = L->x[a] + L->radius[a] * ox, y = L->y[a] + L->radius[a] * oy;
        float fx = x - 0.5f, fy = y - 0.5f, x0 = floorf(fx), y0 = floorf(fy);
        float wx = fx - x0, wy = fy - y0, limit;
        if (point) {
            const float n[3] = {L->n[0][a], L->n[1][a], L->n[2][a]};
            const float axis[3] = {L->axis[0][a], L->axis[1][a], L->axis[2][a]};
            const float u[3] = {L->u[0][a], L->u[1][a], L->u[2][a]};
            const float v[3] = {L->v[0][a], L->v[1][a], L->v[2][a]};
            limit = dl_point_limit(x, y, L->x[a], L->y[a], L->r[a], L->texel[a], L->bias[a],
                                   in->slope, n, L->nq[a], axis, u, v, L->half[a], res, pow2);
        } else {
            limit = dl_directional_limit(x, y, L->x[a], L->y[a], L->r[a], L->texel[a],
                                         L->bias[a], in->slope, L->gx[a], L->gy[a]);
        }
        int ix = (int)x0, iy = (int)y0;
        int ok = (reads != READ_NONE) & (ix >= 0) & (iy >= 0) & (ix < last) & (iy < last);
        if (reads == READ_TILES) /* all four in one tile */
            ok &= ((ix & mask) != mask) & ((iy & mask) != mask);
        ix = ok ? ix : 0, iy = ok ? iy : 0;
        int at = reads == READ_TILES
                     ? in->first + ((iy >> in->shift) * in->tiles + (ix >> in->shift)) * res * res +
                           (iy & mask) * res + (ix & mask)
                     : L->base[a] + iy * res + ix;
        const float *m = in->maps;
        float t00 = limit <= m[at] ? 1.0f : 0.0f, t10 = limit <= m[at + 1] ? 1.0f : 0.0f;
        float t01 = limit <= m[at + res] ? 1.0f : 0.0f;
        float t11 = limit <= m[at + res + 1] ? 1.0f : 0.0f;
        float val = dl_blend(wx, wy, t00, t10, t01, t11);
        L->sum[a] += ok ? val : 0.0f;
        xs[a] = x, ys[a] = y, slow[a] = !ok, any |= !ok;
    }
    return any;
}

/* tap_lanes for each kind of light and map, each its own vector loop. */
SSG_VECTOR_CLONES
static int tap_values(struct dl_lanes *restrict L, const struct taps_in *in, float tx,
                      float ty, int point, int reads, float *restrict xs, float *restrict ys,
                      int *restrict slow)
{
    const int pow2 = (in->res & (in->res - 1)) == 0;
    if (point && reads == READ_FACE && pow2)
        return tap_lanes(L, in, tx, ty, 1, READ_FACE, 1, xs, ys, slow);
    else if (point && reads == READ_FACE)
        return tap_lanes(L, in, tx, ty, 1, READ_FACE, 0, xs, ys, slow);
    else if (point)
        return tap_lanes(L, in, tx, ty, 1, READ_NONE, 0, xs, ys, slow);
    else if (reads == READ_FACE)
        return tap_lanes(L, in, tx, ty, 0, READ_FACE, 0, xs, ys, slow);
    else if (reads == READ_TILES)
        return tap_lanes(L, in, tx, ty, 0, READ_TILES, 0, xs, ys, slow);
    else
        return tap_lanes(L, in, tx, ty, 0, READ_NONE, 0, xs, ys, slow);
}

/* How the lanes read light l's maps (enum reads). */
static int reads_of(const struct dl_job *j, const struct ssg_direct_light_light *l,
                    struct taps_in *in)
{
    const int res = j->c->u.res;
    *in = (struct taps_in){j->maps, res, res * l->tiles, l->tiles, 0, l->face * res * res,
                           j->c->p.tap_slope};
    if (!j->map_index || res < 2)
        return READ_NONE;
    if (l->tiles == 1 || l->point)
        return READ_FACE;
    while ((1 << in->shift) < res)
        in->shift++;
    return (1 << in->shift) == res ? READ_TILES : READ_NONE;
}

/* Tap i (of the disc's taps, outermost first) added to every lane's sum. */
static void add_tap(const struct dl_job *j, const struct ssg_direct_light_light *l,
                    const struct taps_in *in, int reads, struct dl_lanes *L, int i)
{
    const int s = j->c->p.samples - 1 - i;
    float xs[DL_CHUNK], ys[DL_CHUNK];
    int slow[DL_CHUNK];
    if (!tap_values(L, in, j->c->taps[2 * s], j->c->taps[2 * s + 1], l->point, reads, xs, ys,
                    slow))
        return;
    for (int a = 0; a < L->count; a++) {
        if (slow[a]) {
            struct dl_lookup k;
            dl_lane_lookup(L, l, a, &k);
            L->sum[a] += dl_bilinear_test(j, &k, xs[a], ys[a]);
        }
    }
}

/* Lane a moved to lane b (b <= a). */
static void lane_move(struct dl_lanes *L, int a, int b)
{
    L->pixel[b] = L->pixel[a], L->f[b] = L->f[a], L->base[b] = L->base[a];
    L->x[b] = L->x[a], L->y[b] = L->y[a], L->r[b] = L->r[a], L->z[b] = L->z[a];
    L->texel[b] = L->texel[a], L->bias[b] = L->bias[a], L->gx[b] = L->gx[a];
    L->gy[b] = L->gy[a], L->nq[b] = L->nq[a], L->half[b] = L->half[a];
    for (int c = 0; c < 3; c++) {
        L->n[c][b] = L->n[c][a], L->axis[c][b] = L->axis[c][a];
        L->u[c][b] = L->u[c][a], L->v[c][b] = L->v[c][a];
    }
    L->cs[b] = L->cs[a], L->sn[b] = L->sn[a], L->radius[b] = L->radius[a];
    L->sum[b] = L->sum[a];
}

/* The lanes' sums over taps [from, to) of the disc's taps, outermost first. */
static void add_taps(const struct dl_job *j, const struct ssg_direct_light_light *l,
                     struct dl_lanes *L, int from, int to)
{
    struct taps_in in;
    const int reads = reads_of(j, l, &in);
    for (int i = from; i < to; i++)
        add_tap(j, l, &in, reads, L, i);
}

/* The per-pixel visibility's order: the outermost EARLY taps first (the Vogel disc's
   last); where they all agree the pixel is taken as wholly lit or wholly shadowed (most
   pixels: away from a shadow's edge), else every tap counts. A lane without a blocker
   (radius < 0) is lit. Each step keeps the lanes still open at the front, in order. */
void dl_lanes_visibility(const struct dl_job *j, int li, struct dl_lanes *L,
                         struct dl_pixels *px)
{
    const struct ssg_direct_light_light *l = &j->c->light[li];
    const int taps = j->c->p.samples, early = taps >= 2 * EARLY ? EARLY : 0;
    int open = 0;
    for (int a = 0; a < L->count; a++) {
        if (L->radius[a] < 0.0f)
            px->v[L->pixel[a]] = 1.0f;
        else if (open++ != a)
            lane_move(L, a, open - 1);
    }
    L->count = open;
    if (early) {
        add_taps(j, l, L, 0, early);
        open = 0;
        for (int a = 0; a < L->count; a++) {
            if (L->sum[a] == 0.0f || L->sum[a] == (float)early)
                px->v[L->pixel[a]] = L->sum[a] / (float)early;
            else if (open++ != a)
                lane_move(L, a, open - 1);
        }
        L->count = open;
    }
    add_taps(j, l, L, early, taps);
    for (int a = 0; a < L->count; a++)
        px->v[L->pixel[a]] = L->sum[a] / (float)taps;
}
