/* complexity_cpu.c - CPU pass of the `complexity` node (method and mapping in README.md;
 * Szentandrasi section 4.3).
 *
 * Three passes, each over fixed bands of rows (ssg_parallel_rows), so the result does not
 * depend on the thread count: per grid the cell means (sums in pixel order, in double so
 * that a plane's mean point lies on the plane to well below the thresholds), per grid the
 * cell weights from the 4-neighbours, then per pixel the max over the grids and the level.
 * The grids are small (1/16 of the frame at scale 4), so the cost is about one read of
 * depth and normal per grid. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "complexity.h"

enum { ROWS_PER_BAND = 16, CELL_ROWS_PER_BAND = 4 };

/* One grid of cells of side s px: per cell the means of the surface pixels (normal n,
   point P, depth d; d = 0 for an empty cell) and the weight t. */
struct grid {
    int s, gw, gh;
    float *n[3], *p[3], *d, *t;
};

struct job {
    const struct ssg_complexity_consts *c;
    const float *depth, *nrm[3];
    float *out;
    int w, h;
    float f, cx, cy;    /* projection of this resolution */
    struct grid g[SSG_COMPLEXITY_MAX_RESOLUTIONS];
    int grids;
    int cur;            /* the grid the cell passes work on */
};

/* A surface pixel (node.h): depth > 0 and finite, non-zero normal. */
static int is_surface(const struct job *j, size_t o)
{
    float d = j->depth[o];
    float nn = j->nrm[0][o] * j->nrm[0][o] + j->nrm[1][o] * j->nrm[1][o] +
               j->nrm[2][o] * j->nrm[2][o];
    return d > 0.0f && d <= 3.0e38f && nn > 1e-12f;
}

/* Means of one cell over its surface pixels, in pixel order. */
static void cell_means(const struct job *j, const struct grid *g, int gx, int gy)
{
    double sn[3] = {0, 0, 0}, sp[3] = {0, 0, 0}, sd = 0;
    int m = 0;
    int x1 = (gx + 1) * g->s < j->w ? (gx + 1) * g->s : j->w;
    int y1 = (gy + 1) * g->s < j->h ? (gy + 1) * g->s : j->h;
    for (int y = gy * g->s; y < y1; y++)
        for (int x = gx * g->s; x < x1; x++) {
            size_t o = (size_t)y * (size_t)j->w + (size_t)x;
            if (!is_surface(j, o))
                continue;
            double d = j->depth[o];
            sp[0] += d * ((x + 0.5 - j->cx) / j->f);
            sp[1] += d * (-(y + 0.5 - j->cy) / j->f);
            sp[2] -= d;
            sd += d;
            for (int ch = 0; ch < 3; ch++)
                sn[ch] += j->nrm[ch][o];
            m++;
        }
    size_t c = (size_t)gy * (size_t)g->gw + (size_t)gx;
    for (int ch = 0; ch < 3; ch++) {
        g->n[ch][c] = m ? (float)(sn[ch] / m) : 0.0f;
        g->p[ch][c] = m ? (float)(sp[ch] / m) : 0.0f;
    }
    g->d[c] = m ? (float)(sd / m) : 0.0f;
}

static void means_rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    const struct grid *g = &j->g[j->cur];
    for (int gy = y0; gy < y1; gy++)
        for (int gx = 0; gx < g->gw; gx++)
            cell_means(j, g, gx, gy);
}

static float clamp01(float v)
{
    return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
}

/* t of one non-empty cell (README.md): normal and relative depth gradients over the
   non-empty 4-neighbours, in the order left, right, up, down. */
static float cell_weight(const struct ssg_complexity_params *p, const struct grid *g,
                         int gx, int gy)
{
    static const int dx[4] = {-1, 1, 0, 0}, dy[4] = {0, 0, -1, 1};
    size_t c = (size_t)gy * (size_t)g->gw + (size_t)gx;
    float n[3] = {g->n[0][c], g->n[1][c], g->n[2][c]};
    float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    float inv = len > 1e-6f ? 1.0f / len : 0.0f;
    float gn = 0.0f, gd = 0.0f;
    for (int k = 0; k < 4; k++) {
        int bx = gx + dx[k], by = gy + dy[k];
        if (bx < 0 || by < 0 || bx >= g->gw || by >= g->gh)
            continue;
        size_t b = (size_t)by * (size_t)g->gw + (size_t)bx;
        if (!(g->d[b] > 0.0f))
            continue;
        float e0 = n[0] - g->n[0][b], e1 = n[1] - g->n[1][b], e2 = n[2] - g->n[2][b];
        gn += sqrtf(e0 * e0 + e1 * e1 + e2 * e2);
        float off = n[0] * (g->p[0][b] - g->p[0][c]) + n[1] * (g->p[1][b] - g->p[1][c]) +
                    n[2] * (g->p[2][b] - g->p[2][c]);
        gd += fabsf(off) * inv;
    }
    gd /= g->d[c];
    float tn = clamp01((gn - p->normal_threshold) * p->normal_gain);
    float td = clamp01((gd - p->depth_threshold) * p->depth_gain);
    return tn > td ? tn : td;
}

static void weight_rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    const struct grid *g = &j->g[j->cur];
    for (int gy = y0; gy < y1; gy++)
        for (int gx = 0; gx < g->gw; gx++) {
            size_t c = (size_t)gy * (size_t)g->gw + (size_t)gx;
            g->t[c] = g->d[c] > 0.0f ? cell_weight(&j->c->p, g, gx, gy) : 0.0f;
        }
}

/* Per pixel: w = max over the grids of its cell's t, then the level. */
static void pixel_rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    const struct ssg_ints *lv = &j->c->p.levels;
    for (int y = y0; y < y1; y++)
        for (int x = 0; x < j->w; x++) {
            size_t o = (size_t)y * (size_t)j->w + (size_t)x;
            float w = 0.0f;
            for (int r = 0; is_surface(j, o) && r < j->grids; r++) {
                const struct grid *g = &j->g[r];
                float t = g->t[(size_t)(y / g->s) * (size_t)g->gw + (size_t)(x / g->s)];
                w = t > w ? t : w;
            }
            int level = (int)(w * (float)lv->count);
            level = level < lv->count - 1 ? level : lv->count - 1;
            j->out[o] = (float)lv->v[level];
        }
}

/* One allocation for every grid's planes (8 floats a cell), laid out as prepare() said;
   NULL when out of memory. */
static float *alloc_grids(struct job *j)
{
    size_t total = 0;
    for (int r = 0; r < j->grids; r++) {
        struct grid *g = &j->g[r];
        g->s = j->c->grid[r].side;
        g->gw = j->c->grid[r].gw;
        g->gh = j->c->grid[r].gh;
        total += (size_t)g->gw * (size_t)g->gh * 8;
    }
    float *mem = malloc(total * sizeof *mem), *at = mem;
    for (int r = 0; mem && r < j->grids; r++) {
        struct grid *g = &j->g[r];
        size_t cells = (size_t)g->gw * (size_t)g->gh;
        for (int ch = 0; ch < 3; ch++) {
            g->n[ch] = at + (size_t)ch * cells;
            g->p[ch] = at + (size_t)(3 + ch) * cells;
        }
        g->d = at + 6 * cells;
        g->t = at + 7 * cells;
        at += 8 * cells;
    }
    return mem;
}

enum ssg_err ssg_complexity_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                    const struct ssg_io *io)
{
    const struct ssg_complexity_consts *c = consts;
    const struct ssg_image *dep = io->in[SSG_COMPLEXITY_IN_DEPTH];
    const struct ssg_image *nrm = io->in[SSG_COMPLEXITY_IN_NORMAL];
    struct job j = {.c = c, .depth = dep->data, .out = io->out[0]->data, .w = dep->width,
                    .h = dep->height, .grids = c->grids};
    for (int ch = 0; ch < 3; ch++)
        j.nrm[ch] = ssg_image_plane(nrm, ch);
    j.f = c->proj.f;
    j.cx = c->proj.cx;
    j.cy = c->proj.cy;
    float *mem = alloc_grids(&j);
    if (!mem)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the grids");
    for (j.cur = 0; j.cur < j.grids; j.cur++) {
        ssg_parallel_rows(j.g[j.cur].gh, CELL_ROWS_PER_BAND, means_rows, &j);
        ssg_parallel_rows(j.g[j.cur].gh, CELL_ROWS_PER_BAND, weight_rows, &j);
    }
    ssg_parallel_rows(j.h, ROWS_PER_BAND, pixel_rows, &j);
    free(mem);
    return SSG_OK;
}
