/* proxy.c - simplified stand-ins of a scene's dense meshes for the map rasterisers
 * (proxy.h): levels built on demand, finest first, and kept with the scene. */
#include "scene/proxy.h"

#include <math.h>
#include <meshoptimizer.h>
#include <pthread.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "scene/coverage.h"
#include "scene/scene_shapes.h"

enum { LEVELS = SSG_PROXY_FINEST + 1 };

/* One level: a mesh per scene mesh, owned[i] 1 where it is a simplified copy (else the
   original's arrays, shared); built 1 once made (never changed after). */
struct level {
    struct ssg_mesh *meshes;
    unsigned char *owned;
    int built, differs; /* differs: a mesh is not the scene's own (here or finer) */
};

struct ssg_scene_proxies {
    pthread_mutex_t lock;
    float radius; /* R of proxy.h, 0 until the first call measures it */
    struct level level[LEVELS];
};

struct ssg_scene_proxies *ssg_scene_proxies_new(void)
{
    struct ssg_scene_proxies *p = calloc(1, sizeof *p);
    if (p && pthread_mutex_init(&p->lock, NULL) != 0) {
        free(p);
        p = NULL;
    }
    return p;
}

static void level_free(struct level *lv, int mesh_count)
{
    for (int i = 0; lv->meshes && i < mesh_count; i++)
        if (lv->owned[i])
            ssg_mesh_free(&lv->meshes[i]);
    free(lv->meshes);
    free(lv->owned);
    memset(lv, 0, sizeof *lv);
}


/* Half the diagonal of the box around every vertex of the scene. */
static float scene_radius(const struct ssg_scene *s)
{
    float lo[3], hi[3];
    ssg_scene_bounds(s, lo, hi);
    double d2 = 0.0;
    for (int c = 0; c < 3; c++)
        d2 += hi[c] > lo[c] ? (double)(hi[c] - lo[c]) * (hi[c] - lo[c]) : 0.0;
    return (float)(0.5 * sqrt(d2));
}

/* src's kept vertices, `floats` floats each, into a new array (NULL for NULL): remap[v] is
   v's new number, ~0u where dropped (meshoptimizer's remap). */
static float *gather(const float *src, int floats, const unsigned *remap, int vertices,
                     int kept, int *failed)
{
    if (!src)
        return NULL;
    float *out = malloc(sizeof(float) * (size_t)floats * (size_t)(kept ? kept : 1));
    if (out)
        meshopt_remapVertexBuffer(out, src, (size_t)vertices, sizeof(float) * (size_t)floats,
                                  remap);
    *failed |= !out;
    return out;
}

/* The proxy's own vertex normals: the area-weighted normals of its triangles at each
   vertex, turned to the side of the vertex's original normal. A proxy's triangle spans
   what many did (a column's flutes), and the original normals at its corners then point
   along its surface, not off it: a light map would send the far bounce's light sideways. A
   vertex whose triangles cancel keeps its original normal. */
static void proxy_normals(struct ssg_mesh *m)
{
    size_t n = 3 * (size_t)m->vertex_count;
    double *sum = calloc(n ? n : 1, sizeof *sum);
    if (!sum)
        return; /* the original normals, a little less apt */
    for (int t = 0; t < m->triangle_count; t++) {
        const uint32_t *tri = &m->indices[3 * (size_t)t];
        const float *a = &m->positions[3 * tri[0]], *b = &m->positions[3 * tri[1]];
        const float *c = &m->positions[3 * tri[2]];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double f[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                       e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; k++)
            for (int j = 0; j < 3; j++)
                sum[3 * tri[k] + j] += f[j];
    }
    for (size_t v = 0; v < n; v += 3) {
        double len = sqrt(sum[v] * sum[v] + sum[v + 1] * sum[v + 1] + sum[v + 2] * sum[v + 2]);
        float *o = &m->normals[v];
        double side = sum[v] * o[0] + sum[v + 1] * o[1] + sum[v + 2] * o[2];
        if (len > 0.0)
            for (int j = 0; j < 3; j++)
                o[j] = (float)((side < 0.0 ? -sum[v + j] : sum[v + j]) / len);
    }
    free(sum);
}

/* The mesh of src's vertices that the `count` indices use, renumbered in first-use order. */
static enum ssg_err compact(const struct ssg_mesh *src, const uint32_t *indices, size_t count,
                            struct ssg_mesh *out)
{
    unsigned *remap = malloc(sizeof(unsigned) * (size_t)(src->vertex_count ? src->vertex_count : 1));
    uint32_t *idx = malloc(sizeof(uint32_t) * (count ? count : 1));
    if (!remap || !idx) {
        free(remap);
        free(idx);
        return SSG_E_NOMEM;
    }
    size_t kept = meshopt_optimizeVertexFetchRemap(remap, indices, count,
                                                   (size_t)src->vertex_count);
    meshopt_remapIndexBuffer(idx, indices, count, remap);
    int failed = 0, n = src->vertex_count, k = (int)kept;
    *out = (struct ssg_mesh){.vertex_count = k, .triangle_count = (int)(count / 3),
                             .indices = idx, .material = src->material};
    out->positions = gather(src->positions, 3, remap, n, k, &failed);
    out->normals = gather(src->normals, 3, remap, n, k, &failed);
    out->uvs = gather(src->uvs, 2, remap, n, k, &failed);
    out->tangents = gather(src->tangents, 4, remap, n, k, &failed);
    out->colors = gather(src->colors, 3, remap, n, k, &failed);
    free(remap);
    if (failed)
        ssg_mesh_free(out);
    else if (out->normals)
        proxy_normals(out);
    return failed ? SSG_E_NOMEM : SSG_OK;
}

/* Triangles a piece of a large mesh is simplified in: pieces run in parallel, each with
   the cut between pieces locked so that they still meet; the next coarser level, a piece
   or a few, simplifies across the cuts. */
enum { PIECE = 65536 };

/* Triangles [t0, t0 + count) of m simplified to `error` (scene units), their open borders
   locked when lock is 1, into dst (m's vertex numbers): the indices written, or SIZE_MAX
   without memory. Only the piece's own vertices go to meshoptimizer, so its work follows
   the piece, not the mesh. */
static size_t simplify_piece(const struct ssg_mesh *m, size_t t0, size_t count, float error,
                             int lock, uint32_t *dst)
{
    const uint32_t *src = m->indices + 3 * t0;
    size_t n = 3 * count, vertices = (size_t)m->vertex_count, got = SIZE_MAX;
    unsigned *remap = malloc(sizeof(unsigned) * (vertices ? vertices : 1));
    unsigned *local = malloc(sizeof(unsigned) * 2 * (n ? n : 1));
    size_t kept = remap && local ? meshopt_optimizeVertexFetchRemap(remap, src, n, vertices) : 0;
    int failed = !remap || !local;
    float *pos = failed ? NULL : gather(m->positions, 3, remap, m->vertex_count, (int)kept,
                                        &failed);
    unsigned *back = malloc(sizeof(unsigned) * (kept ? kept : 1));
    if (!failed && back) {
        meshopt_remapIndexBuffer(local, src, n, remap);
        for (size_t v = 0; v < vertices; v++) /* a piece's vertex back to the mesh's */
            if (remap[v] != ~0u)
                back[remap[v]] = (unsigned)v;
        float scale = meshopt_simplifyScale(pos, kept, 3 * sizeof(float));
        unsigned *out = local + n;
        got = scale > 0.0f ? meshopt_simplify(out, local, n, pos, kept, 3 * sizeof(float), 0,
                                              error / scale,
                                              lock ? meshopt_SimplifyLockBorder : 0, NULL)
                           : 0;
        if (!(scale > 0.0f)) /* a piece without extent: kept as it is */
            memcpy(out, local, sizeof(unsigned) * (got = n));
        for (size_t i = 0; i < got; i++)
            dst[i] = back[out[i]];
    }
    free(remap), free(local), free(pos), free(back);
    return got;
}

/* A mesh being simplified in pieces (piece_rows). */
struct pieces {
    const struct ssg_mesh *from;
    float error;
    int count;       /* pieces */
    uint32_t *dst;   /* piece i writes from 3 i PIECE on */
    size_t *got;     /* per piece: indices written, SIZE_MAX without memory */
};

static void piece_rows(void *user, int i0, int i1)
{
    struct pieces *p = user;
    for (int i = i0; i < i1; i++) {
        size_t t0 = (size_t)i * PIECE, left = (size_t)p->from->triangle_count - t0;
        p->got[i] = simplify_piece(p->from, t0, left < PIECE ? left : PIECE, p->error,
                                   p->count > 1, p->dst + 3 * t0);
    }
}

/* from simplified with an error of at most `error` (scene units) into *out, its pieces on
   `parallel`'s threads (NULL: this one); *simplified 0 (and *out a copy of from's struct,
   sharing its arrays) where that would not halve its triangles. */
static enum ssg_err simplify(const struct ssg_mesh *from, float error,
                             ssg_proxy_parallel parallel, struct ssg_mesh *out,
                             int *simplified)
{
    *out = *from, *simplified = 0;
    size_t count = 3 * (size_t)from->triangle_count;
    int n = from->triangle_count >= 2 * PIECE ? (from->triangle_count + PIECE - 1) / PIECE : 1;
    struct pieces job = {from, error, n, malloc(sizeof(uint32_t) * count),
                         calloc((size_t)n, sizeof(size_t))};
    enum ssg_err e = job.dst && job.got ? SSG_OK : SSG_E_NOMEM;
    if (!e && parallel)
        parallel(n, 1, piece_rows, &job);
    else if (!e)
        piece_rows(&job, 0, n);
    size_t total = 0; /* the pieces' indices moved together, in piece order */
    for (int i = 0; i < n && !e; i++) {
        if (job.got[i] == SIZE_MAX)
            e = SSG_E_NOMEM;
        else
            memmove(job.dst + total, job.dst + 3 * (size_t)i * PIECE,
                    sizeof(uint32_t) * job.got[i]);
        total += e ? 0 : job.got[i];
    }
    if (!e && 2 * total <= count) {
        e = compact(from, job.dst, total, out);
        *simplified = e == SSG_OK;
        if (e)
            *out = *from;
    }
    free(job.dst);
    free(job.got);
    return e;
}

/* Builds level k from level k + 1 (or from the scene at the finest), each mesh with half
   the level's error (proxy.h). Call with the lock held. */
static enum ssg_err build_level(const struct ssg_scene *s, struct ssg_scene_proxies *p, int k,
                               ssg_proxy_parallel parallel)
{
    struct level *lv = &p->level[k];
    const struct ssg_mesh *from = k == SSG_PROXY_FINEST ? s->meshes : p->level[k + 1].meshes;
    size_t n = (size_t)s->mesh_count;
    lv->meshes = calloc(n + 1, sizeof *lv->meshes);
    lv->owned = calloc(n + 1, 1);
    if (!lv->meshes || !lv->owned) {
        level_free(lv, 0);
        return SSG_E_NOMEM;
    }
    const float error = 0.125f * ldexpf(p->radius, -k);
    for (int i = 0; i < s->mesh_count; i++) {
        int done = 0;
        lv->meshes[i] = from[i];
        if (!ssg_proxy_mesh_dense(s, i))
            continue;
        if (simplify(&from[i], error, parallel, &lv->meshes[i], &done) != SSG_OK) {
            level_free(lv, s->mesh_count);
            return SSG_E_NOMEM;
        }
        lv->owned[i] = (unsigned char)done;
    }
    for (int i = 0; i < s->mesh_count; i++)
        lv->differs |= lv->meshes[i].indices != s->meshes[i].indices;
    lv->built = 1;
    return SSG_OK;
}

int ssg_proxy_mesh_dense(const struct ssg_scene *scene, int mesh)
{
    return scene->meshes[mesh].triangle_count >= SSG_PROXY_MIN_TRIANGLES &&
           !ssg_mesh_masked(scene, mesh);
}

/* The level of max_error (proxy.h), -1 for none. */
static int level_of(float radius, float max_error)
{
    if (!(max_error > 0.0f) || !(radius > 0.0f))
        return -1;
    double ratio = (double)radius / (double)max_error; /* 0 for an infinite error */
    if (ratio > 0x1p30)
        return -1;
    int k = ratio > 1.0 ? (int)ceil(log2(ratio)) : 0;
    return k > SSG_PROXY_FINEST ? -1 : k;
}

enum ssg_err ssg_scene_proxy(const struct ssg_scene *scene, float max_error,
                             ssg_proxy_parallel parallel, struct ssg_scene *view)
{
    const struct ssg_scene *s = scene->proxy_of ? scene->proxy_of : scene;
    struct ssg_scene_proxies *p = s->proxies;
    *view = *s;
    if (!p || s->mesh_count == 0)
        return SSG_OK;
    enum ssg_err e = SSG_OK;
    pthread_mutex_lock(&p->lock);
    if (p->radius == 0.0f)
        p->radius = scene_radius(s);
    int k = level_of(p->radius, max_error);
    for (int j = SSG_PROXY_FINEST; k >= 0 && j >= k && !e; j--)
        if (!p->level[j].built)
            e = build_level(s, p, j, parallel);
    if (!e && k >= 0 && p->level[k].differs) {
        view->meshes = p->level[k].meshes;
        view->proxy_of = s;
        view->proxy_error = ldexpf(p->radius, -k);
        view->proxies = NULL;
        view->rt = NULL; /* rays go to the scene itself, never to a proxy */
    }
    pthread_mutex_unlock(&p->lock);
    return e;
}

float ssg_scene_proxy_error(const struct ssg_scene *view)
{
    return view->proxy_of ? view->proxy_error : 0.0f;
}

void ssg_scene_proxies_release(struct ssg_scene *scene)
{
    struct ssg_scene_proxies *p = scene->proxies;
    if (!p)
        return;
    for (int k = 0; k < LEVELS; k++)
        level_free(&p->level[k], scene->mesh_count);
    pthread_mutex_destroy(&p->lock);
    free(p);
    scene->proxies = NULL;
}
