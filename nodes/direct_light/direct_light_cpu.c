/* direct_light_cpu.c - CPU side of the `direct_light` node (method in README.md).
 * Rows in fixed bands; a band's rows in chunks of CHUNK pixels. Per light, the unshadowed
 * irradiance of the whole chunk is one vectorised loop (nodes/common/direct.h, the
 * G-buffer's own code); only the pixels it reaches run the shadow filter (gathers from
 * the maps, per pixel), and the sums are again straight loops. A pixel depends only on
 * its own inputs: the result does not depend on the threads. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdlib.h>

#include "common/direct.h"
#include "common/luminance.h"
#include "direct_light.h"

enum { CHUNK = 64, ROWS_PER_BAND = 8, EARLY = 4 };

struct job {
    const struct ssg_direct_light_consts *c;
    const struct ssg_io *io;
    const float *maps; /* the depth planes, face f at f R^2 */
    int w, h;
};

struct chunk {
    float px[CHUNK], py[CHUNK], pz[CHUNK], nx[CHUNK], ny[CHUNK], nz[CHUNK];
    float e[CHUNK], v[CHUNK];               /* one light: irradiance, visibility */
    float lx[CHUNK], ly[CHUNK], lz[CHUNK];  /* one light: unit direction to it */
    float sum[3][CHUNK], lum_lit[CHUNK], lum_all[CHUNK];
};

/* A cube face's texel (x, y), maybe past its edge, as the depth along face f's axis of
   the nearest surface on its ray: read on the face its direction falls on (a texel past
   the edge: the neighbour's depth z' at direction d, d's axis part 1 on f, is z' / (d .
   axis') on f). */
static float cube_depth(const struct job *j, int first, int f, int x, int y)
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

/* Where the receiver is on a light's maps: its face, texel coordinates and distance, and
   its plane, so that each tap compares against the receiver's own distance along the
   tap's ray ("receiver plane depth bias", Isidoro, GDC 2006): a flat receiver never
   shadows itself, whatever the disc's radius. */
struct lookup {
    const struct ssg_direct_light_light *l;
    int f;        /* face of the light (0 for a directional one) */
    float x, y;   /* texel coordinates on it */
    float r;      /* distance: along the ray (point) or depth (directional) */
    float z;      /* depth along the face's axis (the maps' measure) */
    float texel;  /* a texel at the receiver, scene units */
    float bias;   /* the constant offset, scene units */
    float gx, gy; /* directional: the receiver plane's depth change a texel along x, y */
    float n[3];   /* point: the receiver's normal and n . (q - light) */
    float nq;
};

/* The occluder's depth along the lookup face's axis at its texel (x, y), SSG_SHADOW_EMPTY
   where the map has none or (directional, a spot's one face) the texel is off the map. */
static float occluder(const struct job *j, const struct lookup *k, int x, int y)
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
   face, less the offset: a tap is lit where the occluder is at least this far. Kept
   within SSG_DIRECT_LIGHT_MAX_SLOPE texels a texel of the centre's (a grazing plane), and
   tap_slope texels more a texel of the tap's distance from the centre: where the surface
   bends towards the light within the disc (a concave corner: a step's tread meeting the
   next riser) the plane alone would shadow the corner over the disc's radius. */
static float tap_limit(const struct job *j, const struct lookup *k, float x, float y)
{
    float dx = x - k->x, dy = y - k->y, m = k->texel * SSG_DIRECT_LIGHT_MAX_SLOPE *
                                             (fabsf(dx) + fabsf(dy) + 1.0f);
    float t;
    if (!k->l->point) {
        t = k->r + k->gx * dx + k->gy * dy;
    } else {
        const struct ssg_lightmap_face *f = &j->c->faces[k->l->face + k->f];
        float a = 2.0f * x / (float)j->c->u.res - 1.0f, b = 2.0f * y / (float)j->c->u.res - 1.0f;
        float d[3], len2 = 0.0f, nd = 0.0f, ha = f->half * a, hb = f->half * b;
        for (int i = 0; i < 3; i++) {
            d[i] = f->axis[i] + ha * f->u[i] + hb * f->v[i];
            len2 += d[i] * d[i], nd += k->n[i] * d[i];
        }
        float len = sqrtf(len2);
        nd /= len;
        t = nd < 0.0f ? k->nq / nd : k->r + m; /* the tap's ray meets the plane at t */
        t = t < k->r + m ? (t > k->r - m ? t : k->r - m) : k->r + m;
        t -= k->bias + k->texel * j->c->p.tap_slope * sqrtf(dx * dx + dy * dy);
        return t / len; /* along the ray -> along the face's axis, as the map */
    }
    t = t < k->r + m ? (t > k->r - m ? t : k->r - m) : k->r + m;
    return t - k->bias - k->texel * j->c->p.tap_slope * sqrtf(dx * dx + dy * dy);
}

/* The bilinear blend of the four tests around texel coordinates (x, y). */
static float bilinear_test(const struct job *j, const struct lookup *k, float x, float y)
{
    float fx = x - 0.5f, fy = y - 0.5f, x0 = floorf(fx), y0 = floorf(fy);
    float wx = fx - x0, wy = fy - y0, limit = tap_limit(j, k, x, y);
    int ix = (int)x0, iy = (int)y0;
    float t00 = limit <= occluder(j, k, ix, iy) ? 1.0f : 0.0f;
    float t10 = limit <= occluder(j, k, ix + 1, iy) ? 1.0f : 0.0f;
    float t01 = limit <= occluder(j, k, ix, iy + 1) ? 1.0f : 0.0f;
    float t11 = limit <= occluder(j, k, ix + 1, iy + 1) ? 1.0f : 0.0f;
    return (1.0f - wy) * ((1.0f - wx) * t00 + wx * t10) + wy * ((1.0f - wx) * t01 + wx * t11);
}

/* The PCF radius in texels: `filter`, widened by the penumbra of the blockers found
   within the light's footprint (PCSS); 0 > radius: no blocker, fully lit. */
static float filter_radius(const struct job *j, const struct lookup *k, float cs, float sn)
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

/* A texel of light l's maps at the receiver p, scene units: the map's own (directional) or
   2 d / R at distance d (a cube face). The offsets and the contact march's reach scale
   with it. */
static float receiver_texel(const struct ssg_direct_light_light *light, const float p[3])
{
    if (!light->point)
        return light->texel;
    float d[3] = {p[0] - light->pos[0], p[1] - light->pos[1], p[2] - light->pos[2]};
    return light->texel * sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* The receiver p (normal n, unit direction l to the light) on light l's maps, moved along
   its normal first (the normal offset). */
static void locate(const struct job *j, const struct ssg_direct_light_light *light,
                   const float p[3], const float n[3], const float l[3], struct lookup *k)
{
    const struct ssg_direct_light_consts *c = j->c;
    float cosine = n[0] * l[0] + n[1] * l[1] + n[2] * l[2], c2 = 1.0f - cosine * cosine;
    float sine = sqrtf(c2 > 0.0f ? c2 : 0.0f);
    k->l = light;
    k->texel = receiver_texel(light, p);
    float lift = c->p.normal_offset * k->texel * sine, q[3], z;
    for (int i = 0; i < 3; i++)
        q[i] = p[i] + lift * n[i];
    k->f = 0, k->x = k->y = 0.0f;
    if (light->point) {
        float d[3] = {q[0] - light->pos[0], q[1] - light->pos[1], q[2] - light->pos[2]};
        k->f = light->cube ? ssg_lightmap_cube_face(d) : 0;
        k->r = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    const struct ssg_lightmap_face *f = &c->faces[light->face + k->f];
    ssg_lightmap_project(f, c->u.res, q, &k->x, &k->y, &z);
    k->r = light->point ? k->r : z;
    k->z = z;
    k->bias = c->p.offset * k->texel;
    /* the receiver plane: n . (X - q) = 0 */
    float nu = n[0] * f->u[0] + n[1] * f->u[1] + n[2] * f->u[2];
    float nv = n[0] * f->v[0] + n[1] * f->v[1] + n[2] * f->v[2];
    k->gx = k->texel * nu / cosine, k->gy = k->texel * nv / cosine;
    k->nq = 0.0f;
    for (int i = 0; i < 3; i++) {
        k->n[i] = n[i];
        k->nq += n[i] * (q[i] - light->pos[i]);
    }
}

/* The G-buffer pixel that image point (u, w) falls in, into *b; 0 when off the image. */
static int pixel_at(const struct job *j, float u, float w, size_t *b)
{
    if (!(u >= 0.0f && w >= 0.0f && u < (float)j->w && w < (float)j->h))
        return 0;
    *b = (size_t)(int)w * j->w + (size_t)(int)u;
    return 1;
}

/* Whether pixel b of normal planes nrm (plane floats apart) is a surface (normal not 0). */
static int is_surface(const float *nrm, size_t plane, size_t b)
{
    return nrm[b] != 0.0f || nrm[plane + b] != 0.0f || nrm[2 * plane + b] != 0.0f;
}

/* Pixel (u, w) of the G-buffer as a plane: its view-space point and the geometric normal
   of its surface, unit, turned towards the camera, from its neighbours' points (along each
   axis the one-sided difference whose depth changes least, the lower side on a tie, which
   stays on the pixel's own surface beside an edge). Not the shading normal: a mesh's
   interpolated normals tilt away from its flat triangles, and a march just above a
   triangle would pass "behind" the plane they make. 0 when off the image, background,
   without a surface neighbour on either axis, or seen nearly edge-on (cosine to the view
   ray under SSG_DIRECT_LIGHT_CONTACT_GRAZING, a silhouette: no plane there).
   direct_light.glsl's pixel_plane makes the same operations. */
static int pixel_plane(const struct job *j, float u, float w, float pt[3], float n[3])
{
    size_t b;
    if (!pixel_at(j, u, w, &b))
        return 0;
    const float *pos = j->io->in[SSG_DIRECT_LIGHT_IN_POSITION]->data;
    const float *nrm = j->io->in[SSG_DIRECT_LIGHT_IN_NORMAL]->data;
    const size_t plane = (size_t)j->w * j->h;
    const int x = (int)(b % (size_t)j->w), y = (int)(b / (size_t)j->w);
    for (int i = 0; i < 3; i++)
        pt[i] = pos[i * plane + b];
    if (!is_surface(nrm, plane, b))
        return 0;
    float e[2][3];
    for (int axis = 0; axis < 2; axis++) {
        int best = 0;
        float best_dz = INFINITY;
        for (int side = -1; side <= 1; side += 2) {
            int nx = axis ? x : x + side, ny = axis ? y + side : y;
            if (nx < 0 || ny < 0 || nx >= j->w || ny >= j->h)
                continue;
            size_t o = (size_t)ny * j->w + (size_t)nx;
            if (!is_surface(nrm, plane, o))
                continue;
            float dz = fabsf(pos[2 * plane + o] - pt[2]);
            if (dz < best_dz) {
                best_dz = dz, best = side;
                for (int i = 0; i < 3; i++)
                    e[axis][i] = (pos[i * plane + o] - pt[i]) * (float)side;
            }
        }
        if (!best)
            return 0;
    }
    float c[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                  e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    float len2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    float facing = -(c[0] * pt[0] + c[1] * pt[1] + c[2] * pt[2]);
    float dist2 = pt[0] * pt[0] + pt[1] * pt[1] + pt[2] * pt[2];
    const float g2 = SSG_DIRECT_LIGHT_CONTACT_GRAZING * SSG_DIRECT_LIGHT_CONTACT_GRAZING;
    if (!(facing * facing > g2 * len2 * dist2))
        return 0;
    float s = (facing < 0.0f ? -1.0f : 1.0f) / sqrtf(len2);
    for (int i = 0; i < 3; i++)
        n[i] = c[i] * s;
    return 1;
}

/* How far view-space point q lies behind the plane (pt, n), away from the camera. */
static float behind(const float q[3], const float pt[3], const float n[3])
{
    return -(n[0] * (q[0] - pt[0]) + n[1] * (q[1] - pt[1]) + n[2] * (q[2] - pt[2]));
}

/* Whether view-space point q lies behind the plane of the pixel (u, w)'s point and its
   shading normal: the cheap half of the test (the pixel's own six values), which most of a
   march in free space fails, so that pixel_plane's geometric normal (five pixels' reads)
   is made only where it can count. */
static int behind_shading(const struct job *j, float u, float w, const float q[3])
{
    size_t b;
    if (!pixel_at(j, u, w, &b))
        return 0;
    const float *pos = j->io->in[SSG_DIRECT_LIGHT_IN_POSITION]->data;
    const float *nrm = j->io->in[SSG_DIRECT_LIGHT_IN_NORMAL]->data;
    const size_t plane = (size_t)j->w * j->h;
    const float pt[3] = {pos[b], pos[plane + b], pos[2 * plane + b]};
    const float n[3] = {nrm[b], nrm[plane + b], nrm[2 * plane + b]};
    return behind(q, pt, n) > 0.0f;
}

/* The contact shadow of pixel (x, y) towards unit world direction l (README.md, "Contact
   shadows"): march from the pixel's view-space point over `reach` scene units in
   SSG_DIRECT_LIGHT_CONTACT_STEPS steps. A step whose point lies behind the plane of the
   surface it projects to has crossed that plane since the last step; the crossing is an
   occluder only where the G-buffer shows a surface there (the crossing lies within a step
   of the plane of the pixel it projects to): past a step's edge the march runs behind the
   tread's extension in open air, and is not shadowed. An occluder crossed d behind shadows by
   min(1, d / soft); none, once d exceeds the reach (a thin object in front). Returns the
   light that passes, 1 - the largest shadow. */
static float contact_visibility(const struct job *j, int x, int y, const float l[3],
                                float reach)
{
    const struct ssg_direct_light_consts *c = j->c;
    const float *r = c->u.rot;
    const float *pos = j->io->in[SSG_DIRECT_LIGHT_IN_POSITION]->data;
    const size_t plane = (size_t)j->w * j->h, at = (size_t)y * j->w + (size_t)x;
    float p[3], v[3];
    for (int i = 0; i < 3; i++) {
        p[i] = pos[i * plane + at];
        v[i] = r[3 * i] * l[0] + r[3 * i + 1] * l[1] + r[3 * i + 2] * l[2];
    }
    const float f = c->u.proj.f, cx = c->u.proj.cx, cy = c->u.proj.cy;
    const float step = reach / (float)SSG_DIRECT_LIGHT_CONTACT_STEPS, soft = 0.125f * reach;
    float shadow = 0.0f;
    for (int s = 1; s <= SSG_DIRECT_LIGHT_CONTACT_STEPS; s++) {
        float t = step * (float)s, q[3], pt[3], n[3], xp[3], pt2[3], n2[3];
        for (int i = 0; i < 3; i++)
            q[i] = p[i] + t * v[i];
        if (!(q[2] < 0.0f))
            break; /* behind the camera */
        float u = cx + f * q[0] / -q[2], w = cy - f * q[1] / -q[2];
        if (!behind_shading(j, u, w, q) || !pixel_plane(j, u, w, pt, n))
            continue;
        float d = behind(q, pt, n);
        if (!(d > 0.0f && d < reach))
            continue;
        /* the crossing: where the last step's segment meets the plane */
        float before = behind((float[3]){q[0] - step * v[0], q[1] - step * v[1],
                                         q[2] - step * v[2]}, pt, n);
        float a = before < 0.0f ? before / (before - d) : 0.0f;
        for (int i = 0; i < 3; i++)
            xp[i] = q[i] - step * v[i] + a * step * v[i];
        if (!(xp[2] < 0.0f) ||
            !pixel_plane(j, cx + f * xp[0] / -xp[2], cy - f * xp[1] / -xp[2], pt2, n2))
            continue;
        if (!(fabsf(behind(xp, pt2, n2)) < step))
            continue; /* the crossing is not on a surface the camera sees */
        float o = d / soft;
        o = o < 1.0f ? o : 1.0f;
        shadow = o > shadow ? o : shadow;
        if (shadow == 1.0f)
            break; /* no later step can shadow more */
    }
    return 1.0f - shadow;
}

/* Light `light`'s visibility at pixel (x, y): PCF over the turned Vogel disc. */
static float visibility(const struct job *j, const struct ssg_direct_light_light *light,
                        int index, int x, int y, const float p[3], const float n[3],
                        const float l[3])
{
    const struct ssg_direct_light_consts *c = j->c;
    struct lookup k;
    locate(j, light, p, n, l, &k);
    float turn = ssg_direct_light_turn(x, y) + 0.618034f * (float)index;
    float angle = 2.0f * (float)M_PI * (turn - floorf(turn));
    float cs = cosf(angle), sn = sinf(angle);
    float radius = filter_radius(j, &k, cs, sn);
    if (radius < 0.0f)
        return 1.0f;
    /* The outermost EARLY taps first (the Vogel disc's last): where they all agree the
       pixel is taken as wholly lit or wholly shadowed (most pixels: away from a shadow's
       edge), else every tap counts. */
    const int taps = c->p.samples, early = taps >= 2 * EARLY ? EARLY : 0;
    float sum = 0.0f;
    for (int i = 0; i < taps; i++) {
        int s = taps - 1 - i;
        float ox = cs * c->taps[2 * s] - sn * c->taps[2 * s + 1];
        float oy = sn * c->taps[2 * s] + cs * c->taps[2 * s + 1];
        sum += bilinear_test(j, &k, k.x + radius * ox, k.y + radius * oy);
        if (i + 1 == early && (sum == 0.0f || sum == (float)early))
            return sum / (float)early;
    }
    return sum / (float)taps;
}

/* The chunk's world positions and normals (background: normal 0). */
SSG_VECTOR_CLONES
static void load(const struct job *j, int y, int x0, int len, struct chunk *restrict k)
{
    const struct ssg_image *pos = j->io->in[SSG_DIRECT_LIGHT_IN_POSITION];
    const struct ssg_image *nrm = j->io->in[SSG_DIRECT_LIGHT_IN_NORMAL];
    const float *r = j->c->u.rot, *eye = j->c->u.eye;
    size_t at = (size_t)y * j->w + x0, plane = (size_t)j->w * j->h;
    for (int i = 0; i < len; i++) {
        float vx = pos->data[at + i], vy = pos->data[plane + at + i];
        float vz = pos->data[2 * plane + at + i];
        float mx = nrm->data[at + i], my = nrm->data[plane + at + i];
        float mz = nrm->data[2 * plane + at + i];
        k->px[i] = eye[0] + r[0] * vx + r[3] * vy + r[6] * vz;
        k->py[i] = eye[1] + r[1] * vx + r[4] * vy + r[7] * vz;
        k->pz[i] = eye[2] + r[2] * vx + r[5] * vy + r[8] * vz;
        k->nx[i] = r[0] * mx + r[3] * my + r[6] * mz;
        k->ny[i] = r[1] * mx + r[4] * my + r[7] * mz;
        k->nz[i] = r[2] * mx + r[5] * my + r[8] * mz;
        k->sum[0][i] = k->sum[1][i] = k->sum[2][i] = 0.0f;
        k->lum_lit[i] = k->lum_all[i] = 0.0f;
    }
}

/* Light li's unshadowed irradiance over the chunk: the G-buffer's formulas. */
SSG_VECTOR_CLONES
static int irradiance(const struct ssg_direct_light_light *l, int len, struct chunk *restrict k)
{
    int any = 0;
    const struct ssg_direct_cone cone = {{l->dir[0], l->dir[1], l->dir[2]}, l->cone_scale,
                                         l->cone_offset};
    for (int i = 0; i < len; i++) {
        float d[3];
        k->e[i] = l->point ? ssg_point_irradiance(l->pos, &cone, l->intensity, k->px[i], k->py[i],
                                                  k->pz[i], k->nx[i], k->ny[i], k->nz[i], d)
                           : ssg_directional_irradiance(l->dir, l->intensity, k->nx[i], k->ny[i],
                                                        k->nz[i], d);
        k->lx[i] = d[0], k->ly[i] = d[1], k->lz[i] = d[2];
        any |= k->e[i] > 0.0f;
    }
    return any;
}

static void add_light(const struct job *j, int li, int y, int x0, int len,
                      struct chunk *restrict k)
{
    const struct ssg_direct_light_light *l = &j->c->light[li];
    if (!irradiance(l, len, k))
        return; /* a light behind the whole chunk adds exact zeros */
    for (int i = 0; i < len; i++) {
        float p[3] = {k->px[i], k->py[i], k->pz[i]}, n[3] = {k->nx[i], k->ny[i], k->nz[i]};
        float d[3] = {k->lx[i], k->ly[i], k->lz[i]};
        k->v[i] = k->e[i] > 0.0f ? visibility(j, l, li, x0 + i, y, p, n, d) : 0.0f;
    }
    for (int i = 0; i < len && j->c->p.contact > 0.0f; i++) {
        if (!(k->v[i] > 0.0f))
            continue; /* the maps shadow it already */
        float p[3] = {k->px[i], k->py[i], k->pz[i]}, d[3] = {k->lx[i], k->ly[i], k->lz[i]};
        float reach = j->c->p.contact * receiver_texel(l, p);
        k->v[i] *= contact_visibility(j, x0 + i, y, d, reach);
    }
    const float el = ssg_luminance(l->color[0], l->color[1], l->color[2]);
    for (int i = 0; i < len; i++) {
        float lit = k->v[i] * k->e[i];
        k->sum[0][i] += lit * l->color[0], k->sum[1][i] += lit * l->color[1];
        k->sum[2][i] += lit * l->color[2];
        k->lum_lit[i] += lit * el, k->lum_all[i] += k->e[i] * el;
    }
}

static void store(const struct job *j, int y, int x0, int len, const struct chunk *restrict k)
{
    const struct ssg_image *alb = j->io->in[SSG_DIRECT_LIGHT_IN_ALBEDO];
    const struct ssg_image *nrm = j->io->in[SSG_DIRECT_LIGHT_IN_NORMAL];
    size_t at = (size_t)y * j->w + x0, plane = (size_t)j->w * j->h;
    float *out = j->io->out[SSG_DIRECT_LIGHT_OUT_OUT]->data;
    float *vis = j->io->out[SSG_DIRECT_LIGHT_OUT_VISIBILITY]->data;
    const float inv_pi = (float)(1.0 / M_PI);
    for (int i = 0; i < len; i++) {
        int bg = !is_surface(nrm->data, plane, at + i);
        for (int c = 0; c < 3; c++)
            out[c * plane + at + i] =
                bg ? 0.0f : alb->data[c * plane + at + i] * inv_pi * k->sum[c][i];
        vis[at + i] = bg || !(k->lum_all[i] > 0.0f) ? 1.0f : k->lum_lit[i] / k->lum_all[i];
    }
}

static void rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    struct chunk k;
    for (int y = y0; y < y1; y++)
        for (int x0 = 0; x0 < j->w; x0 += CHUNK) {
            int len = j->w - x0 < CHUNK ? j->w - x0 : CHUNK;
            load(j, y, x0, len, &k);
            for (int li = 0; li < j->c->u.lights; li++)
                add_light(j, li, y, x0, len, &k);
            store(j, y, x0, len, &k);
        }
}

enum ssg_err ssg_direct_light_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io)
{
    (void)ctx;
    const struct ssg_image *pos = io->in[SSG_DIRECT_LIGHT_IN_POSITION];
    struct job j = {consts, io, io->in[SSG_DIRECT_LIGHT_IN_MAPS]->data, pos->width,
                    pos->height};
    ssg_parallel_rows(pos->height, ROWS_PER_BAND, rows, &j);
    return SSG_OK;
}
