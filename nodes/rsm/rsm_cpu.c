/* rsm_cpu.c - CPU side of the `rsm` node (method in rsm.c): the VPL slots of the maps in row
 * bands, the list and its CDF on the node's thread (a running sum: one order, whatever the
 * threads), then every pixel's draws in row bands. Each pixel depends on its own inputs
 * and the list alone, so the output is the same for every thread count. */
#include <stdint.h>

#include "rsm.h"

struct cells_job {
    const struct ssg_rsm_consts *c;
    const struct ssg_io *io;
    float *slots;
};

static void cell_rows(void *user, int y0, int y1)
{
    const struct cells_job *j = user;
    ssg_rsm_cells(j->c, j->io->in[SSG_RSM_IN_MAP_DEPTH]->data,
                  j->io->in[SSG_RSM_IN_MAP_NORMAL]->data, j->io->in[SSG_RSM_IN_MAP_FLUX]->data,
                  y0, y1, j->slots);
}

struct job {
    const struct ssg_rsm_consts *c;
    const struct ssg_io *io;
    const float *list;
    const int *first;
    int count, w, h;
};

/* The receiver in world space: x = eye + rot^T p, n = rot^T n_view. */
static void to_world(const struct ssg_rsm_consts *c, const float p[3], const float n[3],
                     float x[3], float nx[3])
{
    for (int i = 0; i < 3; i++) {
        x[i] = c->eye[i] + c->rot[i] * p[0] + c->rot[3 + i] * p[1] + c->rot[6 + i] * p[2];
        nx[i] = c->rot[i] * n[0] + c->rot[3 + i] * n[1] + c->rot[6 + i] * n[2];
    }
}

/* VPL v's irradiance x pi at x (normal nx), times `scale`, into sum: Phi cos_v cos_x /
   (d^2 max(d^2, r2)) x fade(d) (rsm.c). */
static inline void add_vpl(const struct ssg_rsm_consts *c, const float *v, const float x[3],
                           const float nx[3], float scale, float sum[3])
{
    float d[3] = {v[0] - x[0], v[1] - x[1], v[2] - x[2]};
    float d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    float cs = -(v[3] * d[0] + v[4] * d[1] + v[5] * d[2]);
    float cr = nx[0] * d[0] + nx[1] * d[1] + nx[2] * d[2];
    if (!(d2 > 0.0f) || !(cs > 0.0f) || !(cr > 0.0f))
        return;
    float g = cs * cr / (d2 * (d2 > v[9] ? d2 : v[9]));
    float m = c->p.min_distance;
    if (m > 0.0f) {
        float t = (sqrtf(d2) - m) / m;
        t = t < 0.0f ? 0.0f : t > 1.0f ? 1.0f : t;
        g = g * (t * t * (3.0f - 2.0f * t));
    }
    float k = scale * g;
    for (int i = 0; i < 3; i++)
        sum[i] += k * v[6 + i];
}

/* The pixel's sum of Phi x G over the VPLs: all of them, or `samples` stratified draws. */
static void gather(const struct job *j, int px, int py, const float x[3], const float nx[3],
                   float sum[3])
{
    const struct ssg_rsm_consts *c = j->c;
    const int S = c->p.samples, n = j->count;
    if (S == 0 || S >= n) {
        for (int i = 0; i < n; i++)
            add_vpl(c, j->list + (size_t)i * SSG_RSM_SLOT, x, nx, 1.0f, sum);
        return;
    }
    float total = j->list[(size_t)(n - 1) * SSG_RSM_SLOT + 11];
    float o = c->offset[(py % SSG_RSM_TILE) * SSG_RSM_TILE + px % SSG_RSM_TILE];
    float step = c->inv_samples * total;
    for (int k = 0; k < S; k++) {
        float u = ((float)k + o) * c->inv_samples * total;
        int i = ssg_rsm_search(j->list, j->first[k], j->first[k + 1], u);
        const float *v = j->list + (size_t)i * SSG_RSM_SLOT;
        add_vpl(c, v, x, nx, step / v[10], sum);
    }
}

static void rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    const struct ssg_image *pos = j->io->in[SSG_RSM_IN_POSITION];
    const struct ssg_image *nrm = j->io->in[SSG_RSM_IN_NORMAL];
    const struct ssg_image *alb = j->io->in[SSG_RSM_IN_ALBEDO];
    float *out = j->io->out[SSG_RSM_OUT_OUT]->data;
    size_t plane = (size_t)j->w * j->h;
    for (int y = y0; y < y1; y++)
        for (int x = 0; x < j->w; x++) {
            size_t at = (size_t)y * j->w + x;
            float p[3], n[3], xw[3], nw[3], sum[3] = {0.0f, 0.0f, 0.0f};
            for (int k = 0; k < 3; k++) {
                p[k] = pos->data[k * plane + at];
                n[k] = nrm->data[k * plane + at];
            }
            int bg = n[0] == 0.0f && n[1] == 0.0f && n[2] == 0.0f;
            if (!bg && j->count > 0) {
                to_world(j->c, p, n, xw, nw);
                gather(j, x, y, xw, nw, sum);
            }
            for (int k = 0; k < 3; k++) {
                float a = alb ? alb->data[k * plane + at] : 1.0f;
                out[k * plane + at] = bg ? 0.0f : a * (sum[k] * 0.101321184f); /* 1 / pi^2 */
            }
        }
}

enum ssg_err ssg_rsm_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                             const struct ssg_io *io)
{
    const struct ssg_rsm_consts *c = consts;
    size_t slot_floats = (size_t)c->slots * SSG_RSM_SLOT;
    size_t bytes = 2 * slot_floats * sizeof(float) +
                   sizeof(int) * (size_t)(c->p.samples + 1);
    float *slots = ssg_node_scratch(ctx, bytes);
    if (!slots)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory");
    float *list = slots + slot_floats;
    int *first = (int *)(list + slot_floats);
    struct cells_job cj = {c, io, slots};
    ssg_parallel_rows(c->faces * c->cells, 2, cell_rows, &cj);
    const struct ssg_image *pos = io->in[SSG_RSM_IN_POSITION];
    struct job j = {c, io, list, first, ssg_rsm_list(c, slots, list, first), pos->width,
                    pos->height};
    ssg_parallel_rows(pos->height, 4, rows, &j);
    return SSG_OK;
}
