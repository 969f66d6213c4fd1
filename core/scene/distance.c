/* distance.c - the scene's coarse distance field (distance.h): conservative voxelisation of
 * every triangle, then the exact Euclidean distance transform of the occupied voxels. Works
 * in grid coordinates (world minus lo, over the voxel side), where voxel (i, j, k) is the
 * cube [i, i + 1] x [j, j + 1] x [k, k + 1]. Every scene load with triangles builds it, so
 * it is made on all threads (slabs of slices, then lines of the transform: the same field
 * whatever their number) and rejects most voxels by the triangle's plane first: on
 * cornell.scene (96 voxels a side, 2 threads) about 98 -> 43 ms, median of 8 loads
 * (issue 47's third pass). */
#include <float.h>
#include <math.h>
#include <omp.h>
#include <stdlib.h>

#include "scene/distance.h"
#include "scene/scene.h"

#define FAR 1e20 /* the transform's infinity: no occupied voxel on this line yet */

/* 1 when the triangle t (grid coordinates) overlaps the cube of half side h at c:
   Akenine-Moller's separating axes, the box's three, the triangle's normal and the nine
   cross products of a box axis with an edge. The normal is tested first: most voxels of a
   large slanted triangle's bounding box lie off its plane, and that one test rejects them.
   Each axis's test is computed from the same values in any order, so the answer is the
   same. */
static int overlaps(const float t[3][3], const float c[3], float h)
{
    float v[3][3], e[3][3];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            v[i][k] = t[i][k] - c[k];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++)
            e[i][k] = v[(i + 1) % 3][k] - v[i][k];
    float n[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                  e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    float d = n[0] * v[0][0] + n[1] * v[0][1] + n[2] * v[0][2];
    if (!(fabsf(d) <= h * (fabsf(n[0]) + fabsf(n[1]) + fabsf(n[2]))))
        return 0;
    for (int k = 0; k < 3; k++) {
        float lo = fminf(v[0][k], fminf(v[1][k], v[2][k]));
        float hi = fmaxf(v[0][k], fmaxf(v[1][k], v[2][k]));
        if (lo > h || hi < -h)
            return 0;
    }
    for (int i = 0; i < 3; i++)     /* edge */
        for (int a = 0; a < 3; a++) { /* box axis: axis = unit(a) x e_i */
            int b = (a + 1) % 3, c2 = (a + 2) % 3;
            float ax[3] = {0, 0, 0};
            ax[b] = -e[i][c2];
            ax[c2] = e[i][b];
            float p[3], r = h * (fabsf(ax[0]) + fabsf(ax[1]) + fabsf(ax[2]));
            for (int j = 0; j < 3; j++)
                p[j] = ax[0] * v[j][0] + ax[1] * v[j][1] + ax[2] * v[j][2];
            if (fminf(p[0], fminf(p[1], p[2])) > r || fmaxf(p[0], fmaxf(p[1], p[2])) < -r)
                return 0;
        }
    return 1;
}

static int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* Marks (d = 0) every voxel of slices z0 .. z1 - 1 that triangle t touches; a triangle
   inside one voxel needs no test. The cube grows by a thousandth of a voxel so that a
   triangle on a voxel face marks both voxels (a plane on a boundary must not fall between
   them). */
static void mark(struct ssg_distance *f, const float t[3][3], int z0, int z1)
{
    int i0[3], i1[3];
    for (int k = 0; k < 3; k++) {
        float lo = fminf(t[0][k], fminf(t[1][k], t[2][k]));
        float hi = fmaxf(t[0][k], fmaxf(t[1][k], t[2][k]));
        i0[k] = clampi((int)floorf(lo - 1e-3f), 0, f->n[k] - 1);
        i1[k] = clampi((int)floorf(hi + 1e-3f), 0, f->n[k] - 1);
    }
    i0[2] = i0[2] > z0 ? i0[2] : z0;
    i1[2] = i1[2] < z1 - 1 ? i1[2] : z1 - 1;
    for (int z = i0[2]; z <= i1[2]; z++)
        for (int y = i0[1]; y <= i1[1]; y++)
            for (int x = i0[0]; x <= i1[0]; x++) {
                float c[3] = {x + 0.5f, y + 0.5f, z + 0.5f};
                size_t at = ((size_t)z * f->n[1] + y) * f->n[0] + x;
                if (f->d[at] != 0.0f && overlaps(t, c, 0.5f + 1e-3f))
                    f->d[at] = 0.0f;
            }
}

/* Every triangle marked, each thread in its own slab of z slices (so no voxel is written
   by two threads; which voxels are marked does not depend on the split). */
static void voxelise(struct ssg_distance *f, const struct ssg_mesh *meshes, int count)
{
    float inv = 1.0f / f->voxel;
#pragma omp parallel
    {
        int parts = omp_get_num_threads(), me = omp_get_thread_num();
        int z0 = (int)((long)f->n[2] * me / parts), z1 = (int)((long)f->n[2] * (me + 1) / parts);
        for (int m = 0; m < count; m++) {
            const struct ssg_mesh *mesh = &meshes[m];
            for (int i = 0; i < mesh->triangle_count; i++) {
                float t[3][3];
                for (int j = 0; j < 3; j++)
                    for (int k = 0; k < 3; k++)
                        t[j][k] =
                            (mesh->positions[3 * mesh->indices[3 * i + j] + k] - f->lo[k]) *
                            inv;
                if (z0 < z1)
                    mark(f, t, z0, z1);
            }
        }
    }
}

/* Felzenszwalb and Huttenlocher's 1-D transform: d[q] = min_p (q - p)^2 + g[p], the lower
   envelope of the parabolas rooted at p (v their roots, z the envelope's breaks). */
static void transform_line(const double *g, int n, double *d, int *v, double *z)
{
    int k = 0;
    v[0] = 0;
    z[0] = -FAR;
    z[1] = FAR;
    for (int q = 1; q < n; q++) {
        double s;
        for (;;) { /* ends at k = 0 at the latest: z[0] = -FAR is below every break */
            int p = v[k];
            s = ((g[q] + (double)q * q) - (g[p] + (double)p * p)) / (2.0 * (q - p));
            if (s > z[k])
                break;
            k--;
        }
        v[++k] = q;
        z[k] = s;
        z[k + 1] = FAR;
    }
    k = 0;
    for (int q = 0; q < n; q++) {
        while (z[k + 1] < q)
            k++;
        d[q] = (double)(q - v[k]) * (q - v[k]) + g[v[k]];
    }
}

/* One axis of the transform over the grid of squared distances sq, line by line: line L
   starts at voxel (L mod stride) + (L / stride) stride n[axis], the voxels whose coordinate
   along the axis is 0. Lines are independent, so they are shared among the threads with
   the same result; each thread has its own work rows (work: 5 len + 2 doubles a thread).
   (Walking the starts replaced a test of every voxel with a division.) */
static void transform_axis(double *sq, const int n[3], int axis, double *work_all)
{
    const size_t stride = axis == 0 ? 1 : axis == 1 ? (size_t)n[0] : (size_t)n[0] * n[1];
    const size_t total = (size_t)n[0] * n[1] * n[2];
    const int len = n[axis];
    const long lines = (long)(total / (size_t)len);
#pragma omp parallel
    {
        double *work = work_all + (size_t)omp_get_thread_num() * (5 * (size_t)len + 2);
        double *g = work, *d = work + len, *z = work + 2 * len;
        int *v = (int *)(work + 3 * len + 1);
#pragma omp for schedule(static)
        for (long L = 0; L < lines; L++) {
            size_t start = (size_t)L % stride + (size_t)L / stride * stride * (size_t)len;
            for (int q = 0; q < len; q++)
                g[q] = sq[start + q * stride];
            transform_line(g, len, d, v, z);
            for (int q = 0; q < len; q++)
                sq[start + q * stride] = d[q];
        }
    }
}

static enum ssg_err distances(struct ssg_distance *f)
{
    size_t total = (size_t)f->n[0] * f->n[1] * f->n[2];
    int longest = f->n[0] > f->n[1] ? f->n[0] : f->n[1];
    longest = longest > f->n[2] ? longest : f->n[2];
    double *sq = malloc(sizeof *sq * total);
    double *work = malloc(sizeof *work * (5 * (size_t)longest + 2) *
                          (size_t)omp_get_max_threads());
    if (!sq || !work) {
        free(sq);
        free(work);
        return SSG_E_NOMEM;
    }
    for (size_t i = 0; i < total; i++)
        sq[i] = f->d[i] == 0.0f ? 0.0 : FAR;
    for (int axis = 0; axis < 3; axis++)
        transform_axis(sq, f->n, axis, work);
    for (size_t i = 0; i < total; i++)
        f->d[i] = (float)sqrt(sq[i]);
    free(sq);
    free(work);
    return SSG_OK;
}

/* Fills the bricked squares (distance.h); 0 when a distance is not the root of an integer
   below 65535 that gives it back. */
static int fill_squares(struct ssg_distance *f)
{
    for (int z = 0; z < f->n[2]; z++)
        for (int y = 0; y < f->n[1]; y++)
            for (int x = 0; x < f->n[0]; x++) {
                float d = ssg_distance_at(f, x, y, z);
                double q = nearbyint((double)d * d);
                if (!(q < 65535.0) || (float)sqrt(q) != d)
                    return 0;
                f->square[ssg_distance_brick_at(f, x, y, z)] = (uint16_t)q;
                f->root[(int)q] = d;
            }
    return 1;
}

/* The bricked squares, or none (NULL) where they cannot hold the field or out of memory. */
static void brick(struct ssg_distance *f)
{
    for (int k = 0; k < 3; k++)
        f->bricks[k] = k == 2 ? (f->n[k] + 1) / 2 : (f->n[k] + 3) / 4;
    f->square = calloc((size_t)f->bricks[0] * f->bricks[1] * f->bricks[2] * SSG_DISTANCE_BRICK,
                       sizeof *f->square);
    f->root = malloc(sizeof *f->root * 65535);
    if (!f->square || !f->root || !fill_squares(f)) {
        free(f->square);
        free(f->root);
        f->square = NULL;
        f->root = NULL;
    }
}

/* The grid over the meshes' bounds: 0 when they hold no triangle. */
static int lay_out(struct ssg_distance *f, const struct ssg_mesh *meshes, int count, int res)
{
    float lo[3] = {FLT_MAX, FLT_MAX, FLT_MAX}, hi[3] = {-FLT_MAX, -FLT_MAX, -FLT_MAX};
    int any = 0;
    for (int m = 0; m < count; m++)
        for (int i = 0; i < 3 * meshes[m].triangle_count; i++) {
            const float *p = &meshes[m].positions[3 * meshes[m].indices[i]];
            for (int k = 0; k < 3; k++) {
                lo[k] = fminf(lo[k], p[k]);
                hi[k] = fmaxf(hi[k], p[k]);
            }
            any = 1;
        }
    if (!any)
        return 0;
    float extent = fmaxf(hi[0] - lo[0], fmaxf(hi[1] - lo[1], hi[2] - lo[2]));
    f->voxel = extent > 0.0f ? extent / (float)res : 1.0f;
    for (int k = 0; k < 3; k++) {
        int inner = (int)ceilf((hi[k] - lo[k]) / f->voxel);
        f->n[k] = (inner > 1 ? inner : 1) + 2 * SSG_DISTANCE_MARGIN;
        f->lo[k] = lo[k] - SSG_DISTANCE_MARGIN * f->voxel;
    }
    return 1;
}

enum ssg_err ssg_distance_build(const struct ssg_mesh *meshes, int count, int res,
                                struct ssg_distance **out)
{
    *out = NULL;
    struct ssg_distance *f = calloc(1, sizeof *f);
    if (!f)
        return SSG_E_NOMEM;
    if (!lay_out(f, meshes, count, res > 0 ? res : 1)) {
        free(f);
        return SSG_OK;
    }
    size_t total = (size_t)f->n[0] * f->n[1] * f->n[2];
    f->d = malloc(sizeof *f->d * total);
    enum ssg_err e = f->d ? SSG_OK : SSG_E_NOMEM;
    if (!e) {
        for (size_t i = 0; i < total; i++)
            f->d[i] = 1.0f; /* any nonzero: not occupied yet */
        voxelise(f, meshes, count);
        e = distances(f);
    }
    if (!e)
        brick(f);
    if (e)
        ssg_distance_destroy(&f);
    *out = f;
    return e;
}

void ssg_distance_destroy(struct ssg_distance **field)
{
    if (!*field)
        return;
    free((*field)->d);
    free((*field)->square);
    free((*field)->root);
    free(*field);
    *field = NULL;
}
