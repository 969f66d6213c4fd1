/* rsm_vpl.c - the virtual point lights of the `rsm` node (layout in rsm.h, method in rsm.c),
 * made on the CPU; rsm_cells.glsl and rsm_list.glsl make the same floats on GL, with the
 * same operations in the same order. */
#include "rsm.h"

/* Sums a cell's texels into their bin: flux-weighted position and normal, flux, area. */
struct cell_sums {
    float pw[SSG_RSM_BINS][3], nw[SSG_RSM_BINS][3], flux[SSG_RSM_BINS][3];
    float area[SSG_RSM_BINS], w[SSG_RSM_BINS];
};

/* The surface area of texel (x, y) of face f, at point p with normal n: its footprint across
   the ray (orthographic: (2 half / R)^2; cube: solid angle x distance^2) over |cos(n, ray)|,
   floored at SSG_RSM_MIN_COSINE. */
static float texel_area(const struct ssg_rsm_consts *c, int f, int x, int y, const float p[3],
                        const float n[3])
{
    const struct ssg_lightmap_face *fc = &c->face_s[f];
    const float *fl = &c->face[16 * f];
    if (fc->ortho) {
        float cosine = fabsf(n[0] * fc->axis[0] + n[1] * fc->axis[1] + n[2] * fc->axis[2]);
        return fl[14] / (cosine > SSG_RSM_MIN_COSINE ? cosine : SSG_RSM_MIN_COSINE);
    }
    float d[3] = {p[0] - fc->origin[0], p[1] - fc->origin[1], p[2] - fc->origin[2]};
    float r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    float cosine = fabsf(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / sqrtf(r2);
    float omega = ssg_lightmap_texel_solid_angle(c->res, x, y);
    return omega * r2 / (cosine > SSG_RSM_MIN_COSINE ? cosine : SSG_RSM_MIN_COSINE);
}

/* Adds texel (x, y) of face f to its bin, when it holds flux. */
static void add_texel(const struct ssg_rsm_consts *c, const float *depth, const float *normal,
                      const float *flux, int f, int x, int y, struct cell_sums *s)
{
    size_t plane = (size_t)c->res * c->res, at = (size_t)y * c->res + x;
    float z = depth[(size_t)f * plane + at];
    float phi[3], n[3], p[3];
    for (int k = 0; k < 3; k++) {
        phi[k] = flux[(size_t)(3 * f + k) * plane + at];
        n[k] = normal[(size_t)(3 * f + k) * plane + at];
    }
    float w = phi[0] + phi[1] + phi[2];
    if (!(w > 0.0f) || !(z < 0.5f * SSG_SHADOW_EMPTY))
        return;
    ssg_lightmap_texel_point(&c->face_s[f], c->res, x, y, z, p);
    int b = ssg_lightmap_cube_face(n);
    for (int k = 0; k < 3; k++) {
        s->pw[b][k] += w * p[k];
        s->nw[b][k] += w * n[k];
        s->flux[b][k] += phi[k];
    }
    s->area[b] += texel_area(c, f, x, y, p, n);
    s->w[b] += w;
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

void ssg_rsm_cells(const struct ssg_rsm_consts *c, const float *depth, const float *normal,
                   const float *flux, int y0, int y1, float *slots)
{
    const int C = c->cells, cell = c->p.cell, res = c->res;
    for (int gy = y0; gy < y1; gy++) {
        int f = gy / C, cy = gy % C;
        for (int cx = 0; cx < C; cx++) {
            struct cell_sums s = {0};
            for (int y = cy * cell; y < (cy + 1) * cell && y < res; y++)
                for (int x = cx * cell; x < (cx + 1) * cell && x < res; x++)
                    add_texel(c, depth, normal, flux, f, x, y, &s);
            float *slot = slots + ((size_t)gy * C + cx) * SSG_RSM_BINS * SSG_RSM_SLOT;
            for (int b = 0; b < SSG_RSM_BINS; b++)
                finish_slot(&s, b, slot + (size_t)b * SSG_RSM_SLOT);
        }
    }
}

int ssg_rsm_pick(const struct ssg_rsm_consts *c, const float *list, int count, int t, int k)
{
    float total = list[(size_t)(count - 1) * SSG_RSM_SLOT + 11];
    float u = ((float)k + c->offset[t]) * c->inv_samples * total;
    return ssg_rsm_search(list, 0, count - 1, u);
}

int ssg_rsm_list(const struct ssg_rsm_consts *c, const float *slots, float *list, int *pick)
{
    int count = 0;
    float cdf = 0.0f;
    for (int s = 0; s < c->slots; s++) {
        const float *slot = slots + (size_t)s * SSG_RSM_SLOT;
        if (!(slot[10] > 0.0f))
            continue;
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
