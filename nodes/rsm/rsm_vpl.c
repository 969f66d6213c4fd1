/* rsm_vpl.c - the virtual point lights of the `rsm` node (layout in rsm.h, method in README.md),
 * made on the CPU; rsm_cells.glsl and rsm_list.glsl make the same floats on GL, with the
 * same operations in the same order. */
#include "common/vector_loops.h" /* first: see there */
#include <stdlib.h>
#include <string.h>

#include "rsm.h"

/* Sums a cell's texels into their bin: flux-weighted position and normal, flux, area. */
struct cell_sums {
    float pw[SSG_RSM_BINS][3], nw[SSG_RSM_BINS][3], flux[SSG_RSM_BINS][3];
    float area[SSG_RSM_BINS], w[SSG_RSM_BINS];
};

/* One texel row of a face, texel by texel (a vector loop; the order of operations of
   ssg_lightmap_texel_point and rsm_cells.glsl): the weight w (0: empty), the world point,
   the normal's bin and the surface area (the footprint across the ray, orthographic
   (2 half / R)^2 or cube solid angle x distance^2, over |cos(n, ray)| floored at
   SSG_RSM_MIN_COSINE). */
struct texel_row {
    float *w, *p[3], *n[3], *area, *phi[3], *z, *a;
    int *bin;
};

/* The normal's bin: the cube face it points at (ties to the lower index). */
static inline int bin_of(float n0, float n1, float n2)
{
    return ssg_lightmap_cube_face((const float[3]){n0, n1, n2});
}

/* The inputs of a row (weights, normals, flux) and the bins: the same for both kinds. */
static inline __attribute__((always_inline)) void
row_inputs(const float *depth, const float *normal, const float *flux, size_t plane,
           size_t row, int f, int res, const struct texel_row *t)
{
    const float *z = depth + f * plane + row;
    for (int k = 0; k < 3; k++)
        for (int x = 0; x < res; x++) {
            t->phi[k][x] = flux[(3 * f + k) * plane + row + x];
            t->n[k][x] = normal[(3 * f + k) * plane + row + x];
        }
    for (int x = 0; x < res; x++) {
        t->z[x] = z[x];
        t->a[x] = 2.0f * ((float)x + 0.5f) / (float)res - 1.0f;
    }
    for (int x = 0; x < res; x++) {
        float w = t->phi[0][x] + t->phi[1][x] + t->phi[2][x];
        t->w[x] = (w > 0.0f) & (z[x] < 0.5f * SSG_SHADOW_EMPTY) ? w : 0.0f;
        t->bin[x] = bin_of(t->n[0][x], t->n[1][x], t->n[2][x]);
    }
}

SSG_VECTOR_CLONES
static void texel_row(const struct ssg_rsm_consts *c, const float *depth, const float *normal,
                      const float *flux, int f, int y, const struct texel_row *t)
{
    const int res = c->res;
    const struct ssg_lightmap_face *fc = &c->face_s[f];
    const float *fl = &c->face[16 * f];
    size_t plane = (size_t)res * res, row = (size_t)y * res;
    const float *restrict z = t->z, *restrict ta = t->a;
    const float b = 2.0f * ((float)y + 0.5f) / (float)res - 1.0f;
    const float o0 = fc->origin[0], o1 = fc->origin[1], o2 = fc->origin[2];
    const float u0 = fc->u[0], u1 = fc->u[1], u2 = fc->u[2];
    const float v0 = fc->v[0], v1 = fc->v[1], v2 = fc->v[2];
    const float a0 = fc->axis[0], a1 = fc->axis[1], a2 = fc->axis[2], half = fc->half;
    row_inputs(depth, normal, flux, plane, row, f, res, t);
    float *restrict p0 = t->p[0], *restrict p1 = t->p[1], *restrict p2 = t->p[2];
    const float *restrict n0 = t->n[0], *restrict n1 = t->n[1], *restrict n2 = t->n[2];
    float *restrict area = t->area;
    if (fc->ortho) {
        const float texel = fl[14];
        for (int x = 0; x < res; x++) {
            float a = ta[x], zx = z[x];
            p0[x] = o0 + half * (a * u0 + b * v0) + zx * a0;
            p1[x] = o1 + half * (a * u1 + b * v1) + zx * a1;
            p2[x] = o2 + half * (a * u2 + b * v2) + zx * a2;
            float cosine = fabsf(n0[x] * a0 + n1[x] * a1 + n2[x] * a2);
            area[x] = texel / (cosine > SSG_RSM_MIN_COSINE ? cosine : SSG_RSM_MIN_COSINE);
        }
        return;
    }
    const float s = 2.0f * half / (float)res, h2 = half * half;
    for (int x = 0; x < res; x++) {
        /* half a and half b: exact for a cube face (half 1) */
        float a = ta[x], ha = half * a, hb = half * b, zx = z[x];
        p0[x] = o0 + zx * (a0 + ha * u0 + hb * v0);
        p1[x] = o1 + zx * (a1 + ha * u1 + hb * v1);
        p2[x] = o2 + zx * (a2 + ha * u2 + hb * v2);
        float d0 = p0[x] - o0, d1 = p1[x] - o1, d2 = p2[x] - o2;
        float r2 = d0 * d0 + d1 * d1 + d2 * d2;
        float cosine = fabsf(n0[x] * d0 + n1[x] * d1 + n2[x] * d2) / sqrtf(r2);
        /* ssg_lightmap_texel_solid_angle */
        float q = 1.0f + h2 * (a * a + b * b), omega = s * s / (q * sqrtf(q));
        area[x] = omega * r2 / (cosine > SSG_RSM_MIN_COSINE ? cosine : SSG_RSM_MIN_COSINE);
    }
}

/* Adds texels [x0, x1) of a computed row to their bins. */
static void add_texels(const struct texel_row *t, int x0, int x1, struct cell_sums *s)
{
    for (int x = x0; x < x1; x++) {
        float w = t->w[x];
        if (!(w > 0.0f))
            continue;
        int b = t->bin[x];
        for (int k = 0; k < 3; k++) {
            s->pw[b][k] += w * t->p[k][x];
            s->nw[b][k] += w * t->n[k][x];
            s->flux[b][k] += t->phi[k][x];
        }
        s->area[b] += t->area[x];
        s->w[b] += w;
    }
}

/* Bin b of the sums into one slot (all zero when the bin holds no flux). */
static void finish_slot(const struct cell_sums *s, int b, float *slot)
{
    for (int k = 0; k < SSG_RSM_SLOT; k++)
        slot[k] = 0.0f;
    if (!(s->w[b] > 0.0f))
        return;
    const float *nw = s->nw[b];
    float len = sqrtf(nw[0] * nw[0] + nw[1] * nw[1] + nw[2] * nw[2]);
    for (int k = 0; k < 3; k++) {
        slot[k] = s->pw[b][k] / s->w[b];
        slot[3 + k] = nw[k] / len;
        slot[6 + k] = s->flux[b][k];
    }
    slot[9] = s->area[b] * 0.318309886f; /* area / pi */
    slot[10] = slot[6] + slot[7] + slot[8];
}

/* A grid row's cells: each texel row of theirs computed once (texel_row), then added to
   its cells in order, so every cell sums its texels row by row as rsm_cells.glsl does. */
int ssg_rsm_cells(const struct ssg_rsm_consts *c, const float *depth, const float *normal,
                  const float *flux, int y0, int y1, float *slots)
{
    const int C = c->cells, cell = c->p.cell, res = c->res;
    /* 12 rows of res floats (w, p, n, area, phi), the bins, C cells' sums */
    size_t bytes = sizeof(float) * 14 * (size_t)res + sizeof(int) * (size_t)res +
                   sizeof(struct cell_sums) * (size_t)C;
    float *mem = malloc(bytes);
    if (!mem)
        return 0;
    struct texel_row t = {.w = mem, .area = mem + res};
    for (int k = 0; k < 3; k++) {
        t.p[k] = mem + (size_t)(2 + k) * res;
        t.n[k] = mem + (size_t)(5 + k) * res;
        t.phi[k] = mem + (size_t)(8 + k) * res;
    }
    t.z = mem + (size_t)11 * res;
    t.a = mem + (size_t)12 * res;
    t.bin = (int *)(mem + (size_t)14 * res);
    struct cell_sums *sums = (struct cell_sums *)(t.bin + res);
    for (int gy = y0; gy < y1; gy++) {
        int f = gy / C, cy = gy % C;
        memset(sums, 0, sizeof *sums * (size_t)C);
        for (int y = cy * cell; y < (cy + 1) * cell && y < res; y++) {
            texel_row(c, depth, normal, flux, f, y, &t);
            for (int cx = 0; cx < C; cx++)
                add_texels(&t, cx * cell, (cx + 1) * cell < res ? (cx + 1) * cell : res,
                           &sums[cx]);
        }
        /* the row's slots that the list keeps, packed (rsm.h), then an end */
        float *row = slots + (size_t)gy * C * SSG_RSM_BINS * SSG_RSM_SLOT;
        int kept = 0;
        for (int cx = 0; cx < C; cx++)
            for (int b = 0; b < SSG_RSM_BINS; b++) {
                float *slot = row + (size_t)kept * SSG_RSM_SLOT;
                if (sums[cx].w[b] > 0.0f) {
                    finish_slot(&sums[cx], b, slot);
                    kept += slot[10] > 0.0f;
                }
            }
        if (kept < C * SSG_RSM_BINS)
            row[(size_t)kept * SSG_RSM_SLOT + 10] = 0.0f;
    }
    free(mem);
    return 1;
}

int ssg_rsm_pick(const struct ssg_rsm_consts *c, const float *list, int count, int t, int k)
{
    float total = list[(size_t)(count - 1) * SSG_RSM_SLOT + 11];
    float u = ((float)k + c->offset[t]) * c->inv_samples * total;
    return ssg_rsm_search(list, 0, count - 1, u);
}

int ssg_rsm_list(const struct ssg_rsm_consts *c, const float *slots, float *list, int *pick)
{
    int count = 0, row = c->cells * SSG_RSM_BINS;
    float cdf = 0.0f;
    for (int s = 0; s < c->slots; s++) {
        const float *slot = slots + (size_t)s * SSG_RSM_SLOT;
        if (!(slot[10] > 0.0f)) { /* the end of its row's packed slots */
            s = (s / row + 1) * row - 1;
            continue;
        }
        float *v = list + (size_t)count * SSG_RSM_SLOT;
        for (int k = 0; k < 11; k++)
            v[k] = slot[k];
        cdf += slot[10];
        v[11] = cdf;
        count++;
    }
    const int S = c->p.samples;
    for (int t = 0; S > 0 && S < count && t < SSG_RSM_TILE * SSG_RSM_TILE; t++)
        for (int k = 0; k < S; k++)
            pick[t * S + k] = ssg_rsm_pick(c, list, count, t, k);
    return count;
}
