/* lightmaps_cpu.c - CPU side of the `lightmaps` node (method in README.md).
 *
 * Two passes. 1: every vertex of the scene onto every face, snapped to 1/SUB texel (the
 * fixed point GPUs use), in parallel over faces. 2: in parallel over strips of STRIP rows
 * of every face (so one directional light's single face still keeps every thread busy),
 * every triangle is rasterised into the strip by nodes/common/raster.h (integer edge
 * functions with an inclusive test: two triangles sharing an edge both cover a centre on
 * it, no cracks; both faces count; triangles without a texel centre in their box dropped
 * a block at a time in vector code), keeping per texel the nearest depth and the
 * triangle's number; then each texel with a triangle intersects its own ray with it for
 * the barycentrics, and reads the shading normal and albedo there (nodes/common/surface.h,
 * as the G-buffer does). A strip's texels are its own, the triangles go in scene order
 * and a tie keeps the first: the maps do not depend on the thread count.
 *
 * Depth is exact on the texel's ray: the plane through the triangle's three (unsnapped)
 * vertices meets the ray of centre (a, b) at z = d0 / (n . (a, b, 1)) on a cube face (1/z
 * is affine in a, b) and z = (d0 - n_u h a - n_v h b) / n_z on an orthographic one, in
 * double, kept within the vertices' depths. A cube face projects a vertex at a = du / z:
 * a triangle with a vertex behind the near plane or beyond |a|, |b| <= GUARD is clipped
 * in face space against those planes first (the rare slow path), so the fixed-point
 * coordinates stay within a few map widths. An alpha-masked mesh's texels ask its mask
 * (scene/coverage.h) where their ray meets the triangle before they keep it: a leaf is a
 * leaf to a light as it is to the camera. Dense meshes are drawn as their proxies, within about
 * a quarter of the finest texel that meets them (common/raster.h, scene/proxy.h). */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "common/raster.h"
#include "common/surface.h"
#include "scene/coverage.h"
#include "scene/scene.h"
#include "lightmaps.h"

enum { SUB = SSG_RASTER_SUB, STRIP = 16, BLOCK = 256, MAX_POLY = 9 };
#define GUARD 4.0f /* |a|, |b| of a cube face's fast-path vertex: texels in [-1.5 R, 2.5 R] */

struct job {
    const struct ssg_lightmaps_consts *c;
    const struct ssg_scene *scene;
    const struct ssg_io *io;
    int64_t *first_tri;  /* per mesh: its first triangle's global number; [mesh_count] all */
    int64_t *first_vert; /* per mesh: its first vertex's global number */
    int64_t verts;       /* vertices in all meshes */
    int32_t *sx, *sy;    /* per face, per vertex: snapped texel coordinates, 1/SUB */
    uint8_t *ok;         /* per face, per vertex: clip outcode, 0 = the fast path */
    int32_t *ids;        /* per face, per texel: global triangle number, -1 = none */
    int rows, strips;    /* rows a strip (STRIP or more), strips a face */
};

/* Face space of world point p: du, dv along u, v, z along the axis. */
static void to_face(const struct ssg_lightmap_face *f, const float *p, double q[3])
{
    double d[3] = {(double)p[0] - f->origin[0], (double)p[1] - f->origin[1],
                   (double)p[2] - f->origin[2]};
    /* a perspective face's u and v in units of its half-width: from here on every
       perspective face is drawn as a cube face (a = q0 / q2) */
    double w = f->ortho ? 1.0 : 1.0 / f->half;
    q[0] = (d[0] * f->u[0] + d[1] * f->u[1] + d[2] * f->u[2]) * w;
    q[1] = (d[0] * f->v[0] + d[1] * f->v[1] + d[2] * f->v[2]) * w;
    q[2] = d[0] * f->axis[0] + d[1] * f->axis[1] + d[2] * f->axis[2];
}

/* Pass 1 for one face: every vertex's snapped texel coordinates and fast-path flag. */
SSG_VECTOR_CLONES
static void project_face(const struct job *j, int fi)
{
    const struct ssg_lightmap_face *f = &j->c->faces[fi];
    const float res = (float)j->c->res, near_z = j->c->u.near_z;
    const float inv_half = 1.0f / f->half, w = f->ortho ? 1.0f : inv_half; /* to_face's */
    for (int mi = 0; mi < j->scene->mesh_count; mi++) {
        const struct ssg_mesh *m = &j->scene->meshes[mi];
        size_t at = (size_t)fi * (size_t)j->verts + (size_t)j->first_vert[mi];
        int32_t *restrict sx = j->sx + at, *restrict sy = j->sy + at;
        uint8_t *restrict ok = j->ok + at;
        const float *restrict p = m->positions;
        for (int v = 0; v < m->vertex_count; v++) {
            float dx = p[3 * v] - f->origin[0], dy = p[3 * v + 1] - f->origin[1];
            float dz = p[3 * v + 2] - f->origin[2];
            float du = (dx * f->u[0] + dy * f->u[1] + dz * f->u[2]) * w;
            float dv = (dx * f->v[0] + dy * f->v[1] + dz * f->v[2]) * w;
            float z = dx * f->axis[0] + dy * f->axis[1] + dz * f->axis[2];
            float s = f->ortho ? inv_half : 1.0f / (z > near_z ? z : near_z);
            float a = du * s, b = dv * s, gz = GUARD * z;
            /* the outcode of the clip planes z >= near, |du|, |dv| <= GUARD z (face space,
               so that it holds behind the light too); 0 = the fast path */
            int code = (z < near_z) | (du > gz) << 1 | (-du > gz) << 2 | (dv > gz) << 3 |
                       (-dv > gz) << 4;
            code = f->ortho ? 0 : code;
            a = code ? 0.0f : a, b = code ? 0.0f : b;
            sx[v] = (int32_t)floorf((a + 1.0f) * 0.5f * res * (float)SUB + 0.5f);
            sy[v] = (int32_t)floorf((b + 1.0f) * 0.5f * res * (float)SUB + 0.5f);
            ok[v] = (uint8_t)code;
        }
    }
}

static void project_faces(void *user, int f0, int f1)
{
    for (int f = f0; f < f1; f++)
        project_face(user, f);
}

/* A triangle's depth on the texel rays: z = (d0 - ka a - kb b) / (kz + qa a + qb b) with
   (a, b) the centre's face coordinates, kept in [lo, hi]. */
struct plane {
    double d0, ka, kb, kz, qa, qb, lo, hi;
};

static int depth_plane(const struct ssg_lightmap_face *f, const double q[3][3], double near_z,
                       struct plane *pl)
{
    double e1[3], e2[3], n[3];
    for (int k = 0; k < 3; k++)
        e1[k] = q[1][k] - q[0][k], e2[k] = q[2][k] - q[0][k];
    n[0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[2] = e1[0] * e2[1] - e1[1] * e2[0];
    pl->d0 = n[0] * q[0][0] + n[1] * q[0][1] + n[2] * q[0][2];
    if (f->ortho) { /* n . (h a, h b, z) = d0 */
        *pl = (struct plane){pl->d0, n[0] * f->half, n[1] * f->half, n[2], 0, 0, 0, 0};
    } else { /* n . z (a, b, 1) = d0 */
        *pl = (struct plane){pl->d0, 0, 0, n[2], n[0], n[1], 0, 0};
    }
    pl->lo = fmin(q[0][2], fmin(q[1][2], q[2][2]));
    pl->hi = fmax(q[0][2], fmax(q[1][2], q[2][2]));
    pl->lo = f->ortho ? pl->lo : fmax(pl->lo, near_z);
    return n[0] != 0.0 || n[1] != 0.0 || n[2] != 0.0;
}

/* A strip of one face being drawn: rows [y0, y1) of its depth plane and ids. */
struct strip {
    float *depth;
    int32_t *ids;
    int res, y0, y1;
};

/* The world ray of texel (x, y) of face f at resolution res: origin o, direction d. */
static void texel_ray(const struct ssg_lightmap_face *f, int res, int64_t x, int64_t y,
                      double o[3], double d[3])
{
    double a = 2.0 * ((double)x + 0.5) / res - 1.0, b = 2.0 * ((double)y + 0.5) / res - 1.0;
    for (int k = 0; k < 3; k++) {
        d[k] = f->ortho ? f->axis[k] : f->axis[k] + f->half * a * f->u[k] + f->half * b * f->v[k];
        o[k] = f->ortho ? f->origin[k] + f->half * (a * f->u[k] + b * f->v[k]) : f->origin[k];
    }
}

/* A masked mesh's triangle being drawn into a face: its texels ask the mask. */
struct mask {
    const struct ssg_scene *scene;
    const struct ssg_lightmap_face *face;
    int mesh, tri;
};

static int texel_covered(const struct mask *k, int res, int64_t x, int64_t y)
{
    double o[3], d[3];
    float u, v;
    texel_ray(k->face, res, x, y, o, d);
    ssg_ray_barycentrics(&k->scene->meshes[k->mesh], k->tri, o, d, &u, &v);
    return ssg_mesh_covers(k->scene, k->mesh, k->tri, u, v);
}

/* Every centre of the strip inside the snapped triangle (x[k], y[k]) keeps the nearer of
   its depth and the plane's, and the triangle's number id when nearer; with a mask, only
   where the triangle covers it. */
static void fill(const struct strip *s, const int64_t x[3], const int64_t y[3],
                 const struct plane *pl, int32_t id, const struct mask *mask)
{
    struct ssg_raster_tri t;
    if (!ssg_raster_setup(x, y, s->res, s->y0, s->y1, &t))
        return;
    const double scale = 2.0 / s->res;
    for (int64_t Y = t.y0; Y <= t.y1; Y++) {
        int64_t x0, x1;
        if (!ssg_raster_span(&t, Y, &x0, &x1))
            continue;
        double b = ((double)Y + 0.5) * scale - 1.0;
        double num = pl->d0 - pl->kb * b, den = pl->kz + pl->qb * b;
        float *row = s->depth + (Y - s->y0) * s->res;
        int32_t *ids = s->ids + (Y - s->y0) * s->res;
        for (int64_t X = x0; X <= x1; X++) {
            double a = ((double)X + 0.5) * scale - 1.0;
            double zd = (num - pl->ka * a) / (den + pl->qa * a);
            zd = zd > pl->lo ? (zd < pl->hi ? zd : pl->hi) : pl->lo; /* NaN: lo */
            float z = (float)zd;
            if (z < row[X] && (!mask || texel_covered(mask, s->res, X, Y)))
                row[X] = z, ids[X] = id;
        }
    }
}

/* The polygon of q[0..n) on the inner side of plane k . q >= 0 (k: 4 floats, w last). */
static int clip_plane(const double (*q)[3], int n, const double k[4], double (*out)[3])
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        const double *a = q[i], *b = q[(i + 1) % n];
        double da = k[0] * a[0] + k[1] * a[1] + k[2] * a[2] + k[3];
        double db = k[0] * b[0] + k[1] * b[1] + k[2] * b[2] + k[3];
        if (da >= 0.0)
            for (int c = 0; c < 3; c++)
                out[m][c] = a[c];
        m += da >= 0.0;
        if ((da >= 0.0) != (db >= 0.0)) {
            double t = da / (da - db);
            for (int c = 0; c < 3; c++)
                out[m][c] = a[c] + t * (b[c] - a[c]);
            m++;
        }
    }
    return m;
}

/* The slow path: a cube face's triangle clipped to z >= near and |a|, |b| <= GUARD in face
   space, then drawn as a fan with the whole triangle's depth plane. */
static void fill_clipped(const struct strip *s, const double q[3][3], double near_z,
                         const struct plane *pl, int32_t id, const struct mask *mask)
{
    const double g = GUARD, planes[5][4] = {{0, 0, 1, -near_z}, {-1, 0, g, 0}, {1, 0, g, 0},
                                            {0, -1, g, 0}, {0, 1, g, 0}};
    double a[MAX_POLY][3], b[MAX_POLY][3];
    int n = 3;
    for (int i = 0; i < 3; i++)
        for (int c = 0; c < 3; c++)
            a[i][c] = q[i][c];
    for (int p = 0; p < 5 && n > 0; p++) {
        n = clip_plane((const double(*)[3])a, n, planes[p], b);
        for (int i = 0; i < n; i++)
            for (int c = 0; c < 3; c++)
                a[i][c] = b[i][c];
    }
    const double half = 0.5 * s->res * SUB;
    int64_t x[MAX_POLY], y[MAX_POLY];
    for (int i = 0; i < n; i++) {
        x[i] = (int64_t)floor((a[i][0] / a[i][2] + 1.0) * half + 0.5);
        y[i] = (int64_t)floor((a[i][1] / a[i][2] + 1.0) * half + 0.5);
    }
    for (int i = 1; i + 1 < n; i++) {
        int64_t tx[3] = {x[0], x[i], x[i + 1]}, ty[3] = {y[0], y[i], y[i + 1]};
        fill(s, tx, ty, pl, id, mask);
    }
}

/* The triangles t0..t0+count-1 of a mesh that may cover a centre of the strip (or need the
   slow path), into list; returns how many (raster.h: shadowmaps_cpu.c does the same). */
static inline __attribute__((always_inline)) int
candidates(const uint32_t *restrict idx, int t0, int count, const int32_t *restrict x,
           const int32_t *restrict y, const uint8_t *restrict ok, int res, int y0, int y1,
           int32_t *restrict list)
{
    int32_t keep[BLOCK];
    for (int t = 0; t < count; t++) {
        uint32_t i = idx[3 * (t0 + t)], k = idx[3 * (t0 + t) + 1], l = idx[3 * (t0 + t) + 2];
        /* fast: no vertex outside a clip plane; out: all outside one (dropped) */
        int32_t fast = (ok[i] | ok[k] | ok[l]) == 0, out = (ok[i] & ok[k] & ok[l]) != 0;
        int32_t box = ssg_raster_box_has_centre(x[i], x[k], x[l], y[i], y[k], y[l], res, y0, y1);
        keep[t] = (fast & box) | ((fast | out) ^ 1);
    }
    int n = 0;
    for (int t = 0; t < count; t++) {
        list[n] = t;
        n += keep[t];
    }
    return n;
}

/* One triangle into the strip: its depth plane, then the fast or the slow path. */
static void draw_triangle(const struct job *j, const struct strip *s, int fi, int mi, int t,
                          const int32_t *x, const int32_t *y, const uint8_t *ok)
{
    const struct ssg_lightmap_face *f = &j->c->faces[fi];
    const struct ssg_mesh *m = &j->scene->meshes[mi];
    const uint32_t *tri = &m->indices[3 * (size_t)t];
    double q[3][3];
    for (int k = 0; k < 3; k++)
        to_face(f, &m->positions[3 * (size_t)tri[k]], q[k]);
    struct plane pl;
    if (!depth_plane(f, (const double(*)[3])q, j->c->u.near_z, &pl))
        return;
    int32_t id = (int32_t)(j->first_tri[mi] + t);
    struct mask mask = {j->scene, f, mi, t};
    const struct mask *masked = ssg_mesh_masked(j->scene, mi) ? &mask : NULL;
    if ((ok[tri[0]] | ok[tri[1]] | ok[tri[2]]) == 0) {
        int64_t tx[3] = {x[tri[0]], x[tri[1]], x[tri[2]]};
        int64_t ty[3] = {y[tri[0]], y[tri[1]], y[tri[2]]};
        fill(s, tx, ty, &pl, id, masked);
    } else if (!f->ortho && fmax(q[0][2], fmax(q[1][2], q[2][2])) >= j->c->u.near_z) {
        fill_clipped(s, (const double(*)[3])q, j->c->u.near_z, &pl, id, masked);
    }
}

SSG_VECTOR_CLONES
static void draw_strip(const struct job *j, int fi, const struct strip *s)
{
    int32_t list[BLOCK];
    for (int mi = 0; mi < j->scene->mesh_count; mi++) {
        const struct ssg_mesh *m = &j->scene->meshes[mi];
        size_t at = (size_t)fi * (size_t)j->verts + (size_t)j->first_vert[mi];
        const int32_t *x = j->sx + at, *y = j->sy + at;
        const uint8_t *ok = j->ok + at;
        for (int t0 = 0; t0 < m->triangle_count; t0 += BLOCK) {
            int count = m->triangle_count - t0 < BLOCK ? m->triangle_count - t0 : BLOCK;
            int n = candidates(m->indices, t0, count, x, y, ok, s->res, s->y0, s->y1, list);
            for (int k = 0; k < n; k++)
                draw_triangle(j, s, fi, mi, t0 + list[k], x, y, ok);
        }
    }
}

/* The mesh of global triangle number id (first_tri is increasing). */
static int mesh_of(const struct job *j, int32_t id)
{
    int lo = 0, hi = j->scene->mesh_count - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (j->first_tri[mid] <= id)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/* What the light's flux through texel (x, y) of face fi is per unit of its colour x
   intensity: 1 on an orthographic face, the texel's solid angle x the spot's falloff
   along its ray on a perspective one (the falloff is 1 for a point light). */
static float texel_weight(const struct job *j, int fi, int x, int y)
{
    const struct ssg_lightmap_face *f = &j->c->faces[fi];
    if (f->ortho)
        return 1.0f;
    const struct ssg_light *light = &j->scene->lights[f->light];
    float omega = ssg_lightmap_texel_solid_angle(f->half, j->c->res, x, y);
    if (light->kind == SSG_LIGHT_POINT)
        return omega;
    float p[3], w[3], len = 0.0f;
    ssg_lightmap_texel_point(f, j->c->res, x, y, 1.0f, p);
    for (int k = 0; k < 3; k++)
        w[k] = p[k] - f->origin[k], len += w[k] * w[k];
    for (int k = 0; k < 3; k++)
        w[k] /= sqrtf(len);
    return omega * ssg_light_cone(light, w);
}

/* The normal and flux of texel (x, y) of face fi, whose nearest triangle is id and whose
   weight is omega (texel_weight). */
static void resolve_texel(const struct job *j, int fi, int x, int y, int32_t id, float omega,
                          float n[3], float flux[3])
{
    const struct ssg_lightmap_face *f = &j->c->faces[fi];
    double o[3], d[3];
    const int res = j->c->res;
    texel_ray(f, res, x, y, o, d);
    struct ssg_hit h = {.mesh = mesh_of(j, id)};
    h.triangle = (int)(id - j->first_tri[h.mesh]);
    ssg_ray_barycentrics(&j->scene->meshes[h.mesh], h.triangle, o, d, &h.u, &h.v);
    ssg_hit_normal(j->scene, &h, 0, n);
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0f)) { /* degenerate vertex normals: the triangle's own */
        ssg_hit_normal(j->scene, &h, 1, n);
        len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    float towards = n[0] * (float)d[0] + n[1] * (float)d[1] + n[2] * (float)d[2];
    float s = (towards > 0.0f ? -1.0f : 1.0f) / (len > 0.0f ? len : 1.0f);
    float albedo[3];
    ssg_hit_albedo(j->scene, &h, albedo);
    for (int k = 0; k < 3; k++) {
        n[k] *= s;
        flux[k] = albedo[k] * j->c->flux[fi][k] * omega;
    }
}

/* 1 when every point of triangle id has one normal and one albedo: equal vertex normals,
   an untextured material (a plane, a box's side). */
static int uniform_triangle(const struct job *j, int32_t id)
{
    int mi = mesh_of(j, id);
    const struct ssg_mesh *m = &j->scene->meshes[mi];
    const uint32_t *tri = &m->indices[3 * (size_t)(id - j->first_tri[mi])];
    const float *n = m->normals;
    int same = 1;
    for (int k = 0; k < 3; k++)
        same &= n[3 * tri[0] + k] == n[3 * tri[1] + k] && n[3 * tri[0] + k] == n[3 * tri[2] + k];
    return same && (j->scene->materials[m->material].texture < 0 || !m->uvs);
}

/* Normal and flux of the strip's texels from their triangles. A run of texels on one
   uniform triangle (uniform_triangle) reuses its normal and albedo: the whole cost of a
   flat scene's maps was this per-texel surface lookup (the Cornell box's 6 x 512^2: 110-180
   -> 65 ms on 2 threads of a loaded machine; the raster alone takes 12 ms). */
static void resolve_strip(const struct job *j, int fi, const struct strip *s)
{
    const int res = s->res;
    struct ssg_image *nrm_img = j->io->out[SSG_LIGHTMAPS_OUT_NORMAL];
    struct ssg_image *flx_img = j->io->out[SSG_LIGHTMAPS_OUT_FLUX];
    if (!nrm_img && !flx_img)
        return; /* depth alone is read (direct_light): no surface lookups at all */
    float *nrm[3], *flx[3], spare[3];
    for (int k = 0; k < 3; k++) { /* an unread one: written into a spare float, per texel */
        nrm[k] = nrm_img ? ssg_image_plane(nrm_img, 3 * fi + k) : &spare[k];
        flx[k] = flx_img ? ssg_image_plane(flx_img, 3 * fi + k) : &spare[k];
    }
    const size_t nrm_step = nrm_img ? 1 : 0, flx_step = flx_img ? 1 : 0;
    int32_t last = -1;
    int reuse = 0;
    float n0[3] = {0, 0, 0}, unit[3] = {0, 0, 0}; /* the last texel's normal, flux / omega */
    for (int y = s->y0; y < s->y1; y++)
        for (int x = 0; x < res; x++) {
            size_t at = (size_t)y * res + x;
            int32_t id = s->ids[(size_t)(y - s->y0) * res + x];
            float n[3] = {0, 0, 0}, flux[3] = {0, 0, 0};
            float omega = id >= 0 ? texel_weight(j, fi, x, y) : 0.0f; /* once a texel */
            if (id >= 0 && id == last && reuse) {
                for (int k = 0; k < 3; k++)
                    n[k] = n0[k], flux[k] = unit[k] * omega;
            } else if (id >= 0) {
                resolve_texel(j, fi, x, y, id, omega, n, flux);
                reuse = omega > 0.0f && uniform_triangle(j, id); /* 0 beyond a spot's cone */
                for (int k = 0; k < 3; k++)
                    n0[k] = n[k], unit[k] = flux[k] / omega;
            }
            last = id;
            for (int k = 0; k < 3; k++)
                nrm[k][at * nrm_step] = n[k], flx[k][at * flx_step] = flux[k];
        }
}

static void strips(void *user, int i0, int i1)
{
    const struct job *j = user;
    const int res = j->c->res;
    for (int i = i0; i < i1; i++) {
        int fi = i / j->strips, y0 = (i % j->strips) * j->rows;
        struct strip s = {ssg_image_plane(j->io->out[SSG_LIGHTMAPS_OUT_DEPTH], fi) +
                              (size_t)y0 * res,
                          j->ids + ((size_t)fi * res + y0) * res, res, y0,
                          y0 + j->rows < res ? y0 + j->rows : res};
        for (size_t k = 0; k < (size_t)(s.y1 - y0) * res; k++)
            s.depth[k] = SSG_SHADOW_EMPTY, s.ids[k] = -1;
        if (j->c->face_floats[(size_t)fi * SSG_LIGHTMAPS_FACE_FLOATS + 17] != 0.0f)
            draw_strip(j, fi, &s); /* a face with a light (lightmaps.h) */
        resolve_strip(j, fi, &s);
    }
}

/* Offsets of every mesh's vertices and triangles in the global numbering. */
static int number_meshes(struct job *j, int64_t *tris)
{
    int64_t v = 0, t = 0;
    for (int mi = 0; mi < j->scene->mesh_count; mi++) {
        j->first_vert[mi] = v, j->first_tri[mi] = t;
        v += j->scene->meshes[mi].vertex_count;
        t += j->scene->meshes[mi].triangle_count;
    }
    j->first_vert[j->scene->mesh_count] = v, j->first_tri[j->scene->mesh_count] = t;
    j->verts = v, *tris = t;
    return t < INT32_MAX;
}

enum ssg_err ssg_lightmaps_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                   const struct ssg_io *io)
{
    const struct ssg_lightmaps_consts *c = consts;
    struct ssg_scene view; /* dense meshes as proxies (common/raster.h) */
    struct job j = {.c = c, .scene = ssg_raster_scene(ctx, c->texel, &view), .io = io};
    if (!j.scene)
        return SSG_E_NOMEM;
    const int res = c->res, faces = c->count;
    int64_t tris = 0;
    size_t meshes = (size_t)j.scene->mesh_count + 1;
    j.first_tri = malloc(2 * meshes * sizeof(int64_t));
    if (!j.first_tri)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    j.first_vert = j.first_tri + meshes;
    if (!number_meshes(&j, &tris)) {
        free(j.first_tri);
        return ssg_node_fail(ctx, SSG_E_VALUE, "the scene has 2^31 triangles or more");
    }
    size_t nv = (size_t)faces * (size_t)j.verts, texels = (size_t)faces * res * res;
    char *mem = ssg_node_scratch(ctx, nv * 9 + texels * 4 + 64);
    if (!mem) {
        free(j.first_tri);
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for %zu map texels", texels);
    }
    j.ids = (int32_t *)mem;
    j.sx = j.ids + texels, j.sy = j.sx + nv;
    j.ok = (uint8_t *)(j.sy + nv);
    /* Strips of STRIP rows keep both threads busy on a single face; with many faces a
       strip per face (or a few) is enough, and each strip scans every triangle once. The
       maps are the same for any strip height (triangles are drawn in one order). */
    j.rows = STRIP;
    while (j.rows < res && (long)faces * ((res + 2 * j.rows - 1) / (2 * j.rows)) >= 16)
        j.rows *= 2;
    j.strips = (res + j.rows - 1) / j.rows;
    ssg_parallel_rows(faces, 1, project_faces, &j);
    ssg_parallel_rows(faces * j.strips, 1, strips, &j);
    free(j.first_tri);
    return SSG_OK;
}
