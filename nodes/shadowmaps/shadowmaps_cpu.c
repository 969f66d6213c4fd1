/* shadowmaps_cpu.c - CPU side of the `shadowmaps` node (method in README.md): each map
 * is a depth-only rasterisation of every triangle of the scene, sampled at the texel
 * centres as GL's raster samples them.
 *
 * Why not Embree: a map is a grid of parallel rays, the one case where a rasteriser does
 * less work than a ray tracer. At 128 maps of 512^2 of the courtyard (70 k triangles) one
 * Embree ray per texel took 205 ms a frame on 2 threads; this takes 45-55 ms, because
 * most of a fine mesh's triangles are smaller than a texel and are dropped, 256 at a time
 * in vector code, after their bounding box (no texel centre inside), and a large one
 * fills its rows as spans. Same errors against reference_gi on 11 scenes x 2 probes.
 *
 * Exactness: vertices are snapped to 1/256 texel (the fixed point GPUs use) and coverage
 * is decided by integer edge functions (nodes/common/raster.h, shared with lightmaps_cpu.c),
 * so two triangles sharing an edge cover a centre on it both (the test is inclusive and the
 * shared edge's function is the exact negation): no cracks. Both faces count. Depth is
 * affine over an orthographic map: a centre's depth comes from the plane through the three
 * unsnapped vertices, in double, kept within their depths (snapping moves a vertex up to
 * 1/512 texel, which under a grazing light would move depths by 20 times that). Each map
 * is one band's alone and a texel keeps the minimum, so the maps do not depend on the
 * thread count or the triangle order. A dense mesh is drawn as its proxy, within about a
 * quarter texel of it (common/raster.h, scene/proxy.h): a million-triangle sphere's 384 maps took
 * 1.7 s, its 7 k-triangle proxy's take a few ms. An alpha-masked mesh's texels ask its mask
 * (scene/coverage.h) where the texel's ray meets the triangle: a leaf's shadow has holes
 * where the leaf has. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "common/raster.h"
#include "scene/coverage.h"
#include "scene/scene.h"
#include "shadowmaps.h"

enum { SUB = SSG_RASTER_SUB, MAX_BANDS = 8, BLOCK = 256 };

struct job {
    const struct ssg_scene *scene;
    const struct ssg_shadow_frame *frames; /* one per light */
    const struct ssg_image *lights;        /* the light list (row 1: irradiances) */
    struct ssg_image *maps;
    int res, lights_per_band;
    int most_vertices;                     /* of the largest mesh: the scratch per band */
    char *scratch;                         /* per band: its map-space vertices */
};

/* A band's vertices on a map: x, y in 1/SUB texels, the same unsnapped, depth. */
struct verts {
    int32_t *x, *y;
    float *fx, *fy, *d;
};
enum { VERTEX_BYTES = 20 };

/* One mesh's vertices on light f's map: texel coordinates (clamped just outside the map,
   NaN to its edge, so the integer maths cannot overflow), snapped and not, and depth below
   the map's plane. */
SSG_VECTOR_CLONES
static void to_map(const struct ssg_shadow_frame *f, int res, const struct ssg_mesh *m,
                   const struct verts *out)
{
    int32_t *restrict x = out->x, *restrict y = out->y;
    float *restrict ux = out->fx, *restrict uy = out->fy, *restrict d = out->d;
    const float scale = 0.5f * (float)res / f->radius, half = 0.5f * (float)res;
    const float lo = -1.0f, hi = (float)res + 1.0f;
    const float *restrict p = m->positions;
    for (int v = 0; v < m->vertex_count; v++) {
        float dx = p[3 * v] - f->origin[0], dy = p[3 * v + 1] - f->origin[1];
        float dz = p[3 * v + 2] - f->origin[2];
        float fx = (dx * f->u[0] + dy * f->u[1] + dz * f->u[2]) * scale + half;
        float fy = (dx * f->v[0] + dy * f->v[1] + dz * f->v[2]) * scale + half;
        fx = fx > lo ? (fx < hi ? fx : hi) : lo;
        fy = fy > lo ? (fy < hi ? fy : hi) : lo;
        ux[v] = fx, uy[v] = fy;
        x[v] = (int32_t)floorf(fx * (float)SUB + 0.5f);
        y[v] = (int32_t)floorf(fy * (float)SUB + 0.5f);
        d[v] = -(dx * f->l[0] + dy * f->l[1] + dz * f->l[2]);
    }
}

struct vertex {
    int64_t x, y;     /* snapped, 1/SUB texels: coverage */
    double fx, fy, d; /* unsnapped, texels, and depth: the depth plane */
};

/* The triangle's depth plane: depth at centre (X, Y) = z + X dx + Y dy, and the range
   of its vertices' depths. 0 when its unsnapped projection has no area. */
struct plane {
    double z, dx, dy, lo, hi;
};

static int depth_plane(const struct vertex *a, const struct vertex *b, const struct vertex *c,
                       struct plane *p)
{
    double e1x = b->fx - a->fx, e1y = b->fy - a->fy, e2x = c->fx - a->fx, e2y = c->fy - a->fy;
    double g1 = b->d - a->d, g2 = c->d - a->d, den = e1x * e2y - e1y * e2x;
    if (den == 0.0)
        return 0;
    p->dx = (g1 * e2y - g2 * e1y) / den;
    p->dy = (g2 * e1x - g1 * e2x) / den;
    p->z = a->d + (0.5 - a->fx) * p->dx + (0.5 - a->fy) * p->dy; /* at centre (0, 0) */
    p->lo = fmin(a->d, fmin(b->d, c->d));
    p->hi = fmax(a->d, fmax(b->d, c->d));
    return 1;
}

/* The plane's depth at centre X of a row whose depth at X = 0 is zy, kept within the
   triangle's vertex depths. */
static inline __attribute__((always_inline)) float plane_depth(const struct plane *pl,
                                                              double zy, int64_t X)
{
    double zd = zy + (double)X * pl->dx;
    return (float)(zd > pl->lo ? (zd < pl->hi ? zd : pl->hi) : pl->lo);
}

/* A masked mesh being drawn on one light's map: whose texels ask its coverage. */
struct mask {
    const struct ssg_scene *scene;
    const struct ssg_shadow_frame *frame;
    int mesh;
};

/* 1 when triangle tri of the masked mesh is a surface where texel (X, Y)'s ray (from the
   map's plane along -l) meets it. */
static int texel_covered(const struct mask *k, int res, int tri, int64_t X, int64_t Y)
{
    float o[3];
    ssg_shadow_texel_origin(k->frame, res, (int)X, (int)Y, o);
    double od[3] = {o[0], o[1], o[2]};
    double d[3] = {-k->frame->l[0], -k->frame->l[1], -k->frame->l[2]};
    float u, v;
    ssg_ray_barycentrics(&k->scene->meshes[k->mesh], tri, od, d, &u, &v);
    return ssg_mesh_covers(k->scene, k->mesh, tri, u, v);
}

/* Every texel centre of the map inside triangle (a, b, c) keeps the smaller of its depth
   and the triangle's depth there; with a mask, only where triangle tri covers it. */
static inline __attribute__((always_inline)) void
triangle(float *map, int res, struct vertex a, struct vertex b, struct vertex c,
         const struct mask *mask, int tri)
{
    int64_t x[3] = {a.x, b.x, c.x}, y[3] = {a.y, b.y, c.y};
    struct ssg_raster_tri t;
    if (!ssg_raster_setup(x, y, res, 0, res, &t))
        return; /* no centre in the box (most triangles of a fine mesh), or edge-on */
    const struct vertex *v[3] = {&a, &b, &c};
    struct plane pl;
    if (!depth_plane(v[t.order[0]], v[t.order[1]], v[t.order[2]], &pl))
        return;
    for (int64_t Y = t.y0; Y <= t.y1; Y++) {
        int64_t x0, x1;
        if (!ssg_raster_span(&t, Y, &x0, &x1))
            continue;
        double zy = pl.z + (double)Y * pl.dy;
        float *row = map + Y * res;
        if (mask) { /* the rare masked mesh: a texel asks before it keeps the depth */
            for (int64_t X = x0; X <= x1; X++) {
                float z = plane_depth(&pl, zy, X);
                if (z < row[X] && texel_covered(mask, res, tri, X, Y))
                    row[X] = z;
            }
            continue;
        }
        for (int64_t X = x0; X <= x1; X++) { /* branch-free: the compiler vectorises it */
            float z = plane_depth(&pl, zy, X);
            row[X] = z < row[X] ? z : row[X];
        }
    }
}

static struct vertex vertex_at(const struct verts *v, uint32_t i)
{
    return (struct vertex){v->x[i], v->y[i], v->fx[i], v->fy[i], v->d[i]};
}

/* The triangles t0..t0+count-1 of a mesh with a texel centre in their bounding box, into
   list (offsets from t0); returns how many. A vector loop over the block (the vertex
   reads are gathers) and a branch-free compaction: a fine mesh's triangles mostly fall
   between centres, and deciding that one at a time cost a mispredicted branch each. */
static inline __attribute__((always_inline)) int
with_centres(const uint32_t *restrict idx, int t0, int count, const struct verts *v,
                        int res, int32_t *restrict list)
{
    const int32_t *restrict x = v->x, *restrict y = v->y;
    int32_t keep[BLOCK];
    for (int t = 0; t < count; t++) {
        uint32_t i = idx[3 * (t0 + t)], k = idx[3 * (t0 + t) + 1], l = idx[3 * (t0 + t) + 2];
        keep[t] = ssg_raster_box_has_centre(x[i], x[k], x[l], y[i], y[k], y[l], res, 0, res);
    }
    int n = 0;
    for (int t = 0; t < count; t++) {
        list[n] = t;
        n += keep[t];
    }
    return n;
}

SSG_VECTOR_CLONES
static void draw_mesh(float *map, int res, const struct ssg_mesh *m, const struct verts *v,
                      const struct mask *mask)
{
    const uint32_t *idx = m->indices;
    int32_t list[BLOCK];
    for (int t0 = 0; t0 < m->triangle_count; t0 += BLOCK) {
        int count = m->triangle_count - t0 < BLOCK ? m->triangle_count - t0 : BLOCK;
        int n = with_centres(idx, t0, count, v, res, list);
        for (int s = 0; s < n; s++) {
            int t = t0 + list[s];
            triangle(map, res, vertex_at(v, idx[3 * t]), vertex_at(v, idx[3 * t + 1]),
                     vertex_at(v, idx[3 * t + 2]), mask, t);
        }
    }
}

/* 1 when light i carries irradiance: a dark light's map stays empty (README.md). */
static int light_carries(const struct ssg_image *lights, int i)
{
    const int n = lights->width;
    for (int c = 0; c < 3; c++)
        if (ssg_image_plane(lights, c)[n + i] != 0.0f) /* row 1 of channel c */
            return 1;
    return 0;
}

static void draw_map(const struct job *j, int light, const struct verts *v)
{
    const int res = j->res;
    float *map = ssg_image_plane(j->maps, light);
    for (size_t i = 0; i < (size_t)res * res; i++)
        map[i] = SSG_SHADOW_EMPTY;
    if (!light_carries(j->lights, light))
        return;
    for (int mi = 0; mi < j->scene->mesh_count; mi++) {
        const struct ssg_mesh *m = &j->scene->meshes[mi];
        struct mask mask = {j->scene, &j->frames[light], mi};
        to_map(&j->frames[light], res, m, v);
        draw_mesh(map, res, m, v, ssg_mesh_masked(j->scene, mi) ? &mask : NULL);
    }
}

/* Maps y0..y1 (the band's lights), with the band's own vertex scratch. */
static void map_band(void *user, int y0, int y1)
{
    const struct job *j = user;
    size_t n = (size_t)j->most_vertices;
    char *mine = j->scratch + (size_t)(y0 / j->lights_per_band) * n * VERTEX_BYTES;
    struct verts v = {(int32_t *)mine, (int32_t *)mine + n, (float *)mine + 2 * n,
                      (float *)mine + 3 * n, (float *)mine + 4 * n};
    for (int light = y0; light < y1; light++)
        draw_map(j, light, &v);
}

enum ssg_err ssg_shadowmaps_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io)
{
    const struct ssg_shadowmaps_params *p = consts;
    enum ssg_err e = ssg_shadowmaps_check_run(ctx, p, io);
    if (e)
        return e;
    const struct ssg_image *lights = io->in[0];
    struct ssg_bounding_sphere sphere = ssg_scene_bounding_sphere(ctx->scene);
    int carries = 0; /* a list of dark lights (a scene without environment) draws nothing:
                        no proxy is worth making for it */
    for (int i = 0; i < lights->width && !carries; i++)
        carries = light_carries(lights, i);
    struct ssg_scene view;
    const struct ssg_scene *drawn = ssg_raster_scene(
        ctx, p->proxy && carries ? 2.0f * sphere.radius / (float)io->out[0]->width : INFINITY,
        &view);
    if (!drawn)
        return SSG_E_NOMEM;
    int n = lights->width, most = 0;
    for (int mi = 0; mi < drawn->mesh_count; mi++) {
        int c = drawn->meshes[mi].vertex_count;
        most = c > most ? c : most;
    }
    int per_band = (n + MAX_BANDS - 1) / MAX_BANDS, bands = (n + per_band - 1) / per_band;
    struct job j = {drawn, NULL, lights, io->out[0], io->out[0]->width, per_band, most, NULL};
    j.scratch = ssg_node_scratch(ctx, (size_t)bands * (size_t)(most ? most : 1) * VERTEX_BYTES);
    struct ssg_shadow_frame *frames = malloc(sizeof *frames * (size_t)n);
    if (!frames || !j.scratch) {
        free(frames);
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    }
    for (int i = 0; i < n; i++) {
        float l[3];
        for (int c = 0; c < 3; c++)
            l[c] = ssg_image_plane(lights, c)[i]; /* row 0 of channel c */
        frames[i] = ssg_shadow_frame_make(&sphere, l);
    }
    j.frames = frames;
    ssg_parallel_rows(n, per_band, map_band, &j);
    free(frames);
    return SSG_OK;
}
