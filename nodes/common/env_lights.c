/* env_lights.c - the directions of the environment's lights and the irradiance each
 * carries (env_lights.h): the `lightprobe` node's list, the `lightmaps` node's faces.
 *
 * Irradiance: every probe texel gives its radiance times its exact solid angle to its
 * nearest light (largest dot product, lowest index on ties), so the lights' irradiances
 * are the integrals of the probe over their Voronoi regions and add up to the integral
 * over the sphere. The paper gives no rule for a light's intensity; this one keeps the
 * total exact for both samplings, which a per-sample estimate L(d_i) / (N pdf(d_i)) would
 * only do in expectation.
 *
 * The nearest-light search is exact but cheap: the sphere is cut into a coarse lat-long
 * grid of cells, and each cell keeps only the lights that can be nearest to some direction
 * in it. For a cell of centre c whose directions lie within rho of c, and whose nearest
 * light is at angle t from c, every direction d of the cell has a light within t + rho,
 * so light j can win at d only if angle(c, l_j) <= t + 2 rho (triangle inequality). The
 * candidates are kept in index order, so ties resolve as a search over all lights would. */
#include <stdlib.h>
#include <string.h>

#include "common/env_lights.h"

enum {
    CELLS_W = 64, CELLS_H = 32,  /* the candidate grid (5.6 degree cells) */
    CONST_W = 256, CONST_H = 128, /* the grid a constant environment is integrated on */
    BAND_ROWS = 4                 /* probe rows per parallel band (fixed: deterministic) */
};

/* The Fibonacci lattice of ssg_env_lights_fibonacci (elevation share (i + 0.5) / M, azimuth
 * share i / golden ratio mod 1) warped through the probe's CDF: where the probe is flat
 * the lights spread as evenly as the uniform set, which Hammersley points (rows of lights
 * at one elevation each) did not. The last round(uniform_share N) lights are the uniform
 * set of that many, so the probe's dim parts keep lights of their own. */
void ssg_env_lights_importance(const struct ssg_env *env, int count, float uniform_share,
                               float *dirs)
{
    if (!env->has_image) { /* a constant's luminance CDF is the uniform one */
        ssg_env_lights_fibonacci(count, dirs);
        return;
    }
    int uniform = (int)lroundf(uniform_share * (float)count), warped = count - uniform;
    ssg_env_lights_fibonacci(uniform, dirs + 3 * warped);
    const double azimuth_step = 0.5 * (3.0 - sqrt(5.0)); /* golden angle / 2 pi */
    for (int i = 0; i < warped; i++) {
        float rgb[3];
        double azimuth = (double)i * azimuth_step;
        float u_row = (float)(((double)i + 0.5) / warped);
        float u_col = (float)(azimuth - floor(azimuth));
        /* ssg_env_sample: u2 picks the row (elevation), u1 the column (azimuth) */
        ssg_env_sample(env, u_col, u_row, dirs + 3 * i, rgb);
    }
}

void ssg_env_lights_fibonacci(int count, float *dirs)
{
    const double golden = M_PI * (3.0 - sqrt(5.0));
    for (int i = 0; i < count; i++) {
        float *d = dirs + 3 * i;
        double y = 1.0 - (2.0 * i + 1.0) / count;
        double r = sqrt(fmax(0.0, 1.0 - y * y)), phi = golden * i;
        d[0] = (float)(r * cos(phi));
        d[1] = (float)y;
        d[2] = (float)(r * sin(phi));
    }
}

/* The probe as a grid of texels: the image, or a constant on CONST_W x CONST_H. */
struct probe {
    int w, h;
    const float *rgb; /* w x h x 3 interleaved; NULL = `constant` everywhere */
    float constant[3];
};

/* Candidate lights of every cell, CSR: cell k's are list[start[k] .. start[k + 1]). */
struct cells {
    int start[CELLS_W * CELLS_H + 1];
    int *list;
};

static float dot3(const float *a, const float *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* The cosine below which no light can be nearest anywhere in cell (cx, cy). */
static float cell_threshold(const float *dirs, int count, int cx, int cy, float c[3])
{
    ssg_env_direction(((float)cx + 0.5f) / CELLS_W, ((float)cy + 0.5f) / CELLS_H, c);
    float best = -2.0f;
    for (int j = 0; j < count; j++) {
        float d = dot3(c, dirs + 3 * j);
        best = d > best ? d : best;
    }
    double t0 = M_PI * cy / CELLS_H, t1 = M_PI * (cy + 1) / CELLS_H;
    double max_sin = t0 <= 0.5 * M_PI && t1 >= 0.5 * M_PI ? 1.0 : fmax(sin(t0), sin(t1));
    double rho = 0.5 * M_PI / CELLS_H + max_sin * M_PI / CELLS_W;
    double limit = acos(fmin(1.0, (double)best)) + 2.0 * rho + 1e-4;
    return limit >= M_PI ? -2.0f : (float)cos(limit);
}

static enum ssg_err build_cells(const float *dirs, int count, struct cells *cells)
{
    int cap = 4 * count + CELLS_W * CELLS_H, used = 0;
    cells->list = malloc(sizeof(int) * (size_t)cap);
    for (int k = 0; cells->list && k < CELLS_W * CELLS_H; k++) {
        float c[3];
        float thr = cell_threshold(dirs, count, k % CELLS_W, k / CELLS_W, c);
        cells->start[k] = used;
        for (int j = 0; j < count; j++) {
            if (dot3(c, dirs + 3 * j) < thr)
                continue;
            if (used == cap) {
                cap *= 2;
                int *grown = realloc(cells->list, sizeof(int) * (size_t)cap);
                if (!grown) {
                    free(cells->list);
                    cells->list = NULL;
                    break;
                }
                cells->list = grown;
            }
            cells->list[used++] = j;
        }
    }
    cells->start[CELLS_W * CELLS_H] = used;
    return cells->list ? SSG_OK : SSG_E_NOMEM;
}

struct job {
    const struct probe *probe;
    const float *dirs;
    int count;
    const struct cells *cells;
    double *band_sums; /* per band: 3 N sums */
};

static int nearest(const struct job *j, const float d[3], int cell)
{
    int best = -1;
    float best_dot = -3.0f;
    for (int k = j->cells->start[cell]; k < j->cells->start[cell + 1]; k++) {
        int i = j->cells->list[k];
        float v = dot3(d, j->dirs + 3 * i);
        if (v > best_dot) {
            best_dot = v;
            best = i;
        }
    }
    return best;
}

static void integrate_rows(void *user, int y0, int y1)
{
    const struct job *j = user;
    const struct probe *p = j->probe;
    double *sums = j->band_sums + (size_t)(y0 / BAND_ROWS) * 3 * (size_t)j->count;
    for (int y = y0; y < y1; y++) {
        double omega = 2.0 * M_PI / p->w * (cos(M_PI * y / p->h) - cos(M_PI * (y + 1) / p->h));
        float v = ((float)y + 0.5f) / (float)p->h;
        int cy = (int)(v * CELLS_H);
        for (int x = 0; x < p->w; x++) {
            float u = ((float)x + 0.5f) / (float)p->w, d[3];
            ssg_env_direction(u, v, d);
            int i = nearest(j, d, cy * CELLS_W + (int)(u * CELLS_W));
            const float *rgb = p->rgb ? p->rgb + 3 * ((size_t)y * p->w + x) : p->constant;
            for (int c = 0; c < 3 && i >= 0; c++)
                sums[3 * i + c] += (double)rgb[c] * omega;
        }
    }
}

enum ssg_err ssg_env_lights_regions(const struct ssg_env *env, const float *dirs, int count,
                                    double *irradiance)
{
    struct probe p = {env->width, env->height, env->radiance, {0, 0, 0}};
    if (!env->has_image || !env->radiance) {
        p = (struct probe){CONST_W, CONST_H, NULL, {0, 0, 0}};
        memcpy(p.constant, env->constant, sizeof p.constant);
    }
    struct cells *cells = malloc(sizeof *cells);
    if (!cells)
        return SSG_E_NOMEM;
    enum ssg_err e = build_cells(dirs, count, cells);
    int bands = (p.h + BAND_ROWS - 1) / BAND_ROWS;
    double *sums = e ? NULL : calloc((size_t)bands * 3 * (size_t)count, sizeof(double));
    if (!e && sums) {
        struct job j = {&p, dirs, count, cells, sums};
        ssg_parallel_rows(p.h, BAND_ROWS, integrate_rows, &j);
        memset(irradiance, 0, sizeof(double) * 3 * (size_t)count);
        for (int b = 0; b < bands; b++) /* in band order: the same sums for any threads */
            for (int k = 0; k < 3 * count; k++)
                irradiance[k] += sums[(size_t)b * 3 * count + k];
    } else if (!e) {
        e = SSG_E_NOMEM;
    }
    free(sums);
    free(cells->list);
    free(cells);
    return e;
}
