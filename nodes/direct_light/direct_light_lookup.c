/* direct_light_lookup.c - the CPU kernel's map reads for one pixel (direct_light_cpu.h):
 * where a receiver falls on a light's maps, its blocker search (PCSS) and one bilinear
 * PCF tap, wherever it falls (past a cube face's edge, across tiles, off the map). The
 * lanes (direct_light_lanes.c) make the same operations for the common taps. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>

#include "direct_light_cpu.h"

/* A cube face's texel (x, y), maybe past its edge, as the depth along face f's axis of
   the nearest surface on its ray: read on the face its direction falls on (a texel past
   the edge: the neighbour's depth z' at direction d, d's axis part 1 on f, is z' / (d .
   axis') on f). */
static float cube_depth(const struct dl_job *j, int first, int f, int x, int y)
{
    const int res = j->c->u.res;
    if (x >= 0 && y >= 0 && x < res && y < res)
        return j->maps[((size_t)(first + f) * res + y) * res + x];
    const struct ssg_lightmap_face *face = &j->c->faces[first + f];
    float a = 2.0f * ((float)x + 0.5f) / (float)res - 1.0f;
    float b = 2.0f * ((float)y + 0.5f) / (float)res - 1.0f;
    float d[3];
    for (int k = 0; k < 3; k++)
        d[k] = face->axis[k] + a * face->u[k] + b * face->v[k];
    int g = first + ssg_lightmap_cube_face(d);
    const struct ssg_lightmap_face *o = &j->c->faces[g];
    float z = d[0] * o->axis[0] + d[1] * o->axis[1] + d[2] * o->axis[2];
    float ga = (d[0] * o->u[0] + d[1] * o->u[1] + d[2] * o->u[2]) / z;
    float gb = (d[0] * o->v[0] + d[1] * o->v[1] + d[2] * o->v[2]) / z;
    int gx = (int)floorf((ga + 1.0f) * 0.5f * (float)res);
    int gy = (int)floorf((gb + 1.0f) * 0.5f * (float)res);
    gx = gx < 0 ? 0 : gx > res - 1 ? res - 1 : gx;
    gy = gy < 0 ? 0 : gy > res - 1 ? res - 1 : gy;
    return j->maps[((size_t)g * res + gy) * res + gx] / z;
}

/* The occluder's depth along the lookup face's axis at its texel (x, y), SSG_SHADOW_EMPTY
   where the map has none or (directional, a spot's one face) the texel is off the map. */
static float occluder(const struct dl_job *j, const struct dl_lookup *k, int x, int y)
{
    const int res = j->c->u.res;
    if (k->l->cube)
        return cube_depth(j, k->l->face, k->f, x, y);
    const int tiles = k->l->tiles, side = res * tiles;
    if (x < 0 || y < 0 || x >= side || y >= side) /* off the map; a spot: outside its cone */
        return SSG_SHADOW_EMPTY;
    int f = k->l->face + (tiles > 1 ? ssg_lightmap_tile_texel(tiles, res, &x, &y) : 0);
    return j->maps[((size_t)f * res + y) * res + x];
}

/* The receiver's distance along the ray of texel coordinates (x, y) of the lookup's
   face, less the offsets (dl_point_limit): a tap is lit where the occluder is at least
   this far. */
static float tap_limit(const struct dl_job *j, const struct dl_lookup *k, float x, float y)
{
    const float slope = j->c->p.tap_slope;
    if (!k->l->point)
        return dl_directional_limit(x, y, k->x, k->y, k->r, k->texel, k->bias, slope, k->gx,
                                    k->gy);
    const struct ssg_lightmap_face *f = &j->c->faces[k->l->face + k->f];
    return dl_point_limit(x, y, k->x, k->y, k->r, k->texel, k->bias, slope, k->n, k->nq,
                          f->axis, f->u, f->v, f->half, j->c->u.res, 0);
}

float dl_bilinear_test(const struct dl_job *j, const struct dl_lookup *k, float x, float y)
{
    float fx = x - 0.5f, fy = y - 0.5f, x0 = floorf(fx), y0 = floorf(fy);
    float wx = fx - x0, wy = fy - y0, limit = tap_limit(j, k, x, y);
    int ix = (int)x0, iy = (int)y0;
    float t00 = limit <= occluder(j, k, ix, iy) ? 1.0f : 0.0f;
    float t10 = limit <= occluder(j, k, ix + 1, iy) ? 1.0f : 0.0f;
    float t01 = limit <= occluder(j, k, ix, iy + 1) ? 1.0f : 0.0f;
    float t11 = limit <= occluder(j, k, ix + 1, iy + 1) ? 1.0f : 0.0f;
    return dl_blend(wx, wy, t00, t10, t01, t11);
}

/* The PCF radius in texels: `filter`, widened by the penumbra of the blockers found
   within the light's footprint (PCSS); 0 > radius: no blocker, fully lit. */
float dl_filter_radius(const struct dl_job *j, const struct dl_lookup *k, float cs, float sn)
{
    const struct ssg_direct_light_consts *c = j->c;
    float filter = c->p.filter, spread = k->l->spread;
    if (!(spread > 0.0f))
        return filter;
    float search = k->l->point ? spread / k->texel : k->r * spread / k->texel;
    search = search > filter ? search : filter;
    search = search < SSG_DIRECT_LIGHT_MAX_RADIUS ? search : SSG_DIRECT_LIGHT_MAX_RADIUS;
    float sum = 0.0f;
    int n = 0;
    for (int s = 0; s < c->p.samples; s++) {
        float ox = cs * c->taps[2 * s] - sn * c->taps[2 * s + 1];
        float oy = sn * c->taps[2 * s] + cs * c->taps[2 * s + 1];
        float x = k->x + search * ox, y = k->y + search * oy;
        float d = occluder(j, k, (int)floorf(x), (int)floorf(y));
        if (d < tap_limit(j, k, x, y))
            sum += d, n++;
    }
    if (n == 0)
        return -1.0f;
    float blocker = sum / (float)n;
    float penumbra = k->l->point ? spread * (k->z - blocker) / blocker
                                 : spread * (k->z - blocker);
    float r = filter + 0.5f * penumbra / k->texel;
    return r < SSG_DIRECT_LIGHT_MAX_RADIUS ? r : SSG_DIRECT_LIGHT_MAX_RADIUS;
}
