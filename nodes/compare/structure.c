/* structure.c - the structure measure of the `compare` node (structure.h; definition in
 * README.md): d = G(m (a - b)) / G(m b) over the pixels where the reference is smooth at
 * G's scale and no edge lies within 3 sigma, m = 1 on the compared pixels.
 *
 * Every blur is a separable Gaussian cut at 3 sigma over zero-padded planes (a pixel
 * outside the image or not compared weighs 0, so G(m x) / G(m) is x's mean over the
 * compared pixels only). Each output value is one sum in tap order, whatever the band: the
 * bits do not depend on the threads. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "graph/node.h"
#include "structure.h"

enum { ROWS_PER_BAND = 32 };

/* The planes, w * h floats each, in one allocation. */
enum { P_M, P_E, P_B, P_MS, P_ES, P_BS, P_M2, P_B2, P_TMP, PLANES };

struct blur {
    const float *in;
    float *out, *tmp;
    const float *g; /* 2r + 1 taps, summing to 1 */
    int r, w, h;
};

static void blur_rows(void *user, int y0, int y1)
{
    const struct blur *b = user;
    for (int y = y0; y < y1; y++) {
        const float *in = b->in + (size_t)y * (size_t)b->w;
        float *out = b->tmp + (size_t)y * (size_t)b->w;
        for (int x = 0; x < b->w; x++) {
            int t0 = x - b->r < 0 ? b->r - x : 0;
            int t1 = x + b->r >= b->w ? b->r + b->w - 1 - x : 2 * b->r;
            float s = 0.0f;
            for (int t = t0; t <= t1; t++)
                s += b->g[t] * in[x + t - b->r];
            out[x] = s;
        }
    }
}

static void blur_columns(void *user, int y0, int y1)
{
    const struct blur *b = user;
    size_t w = (size_t)b->w;
    for (int y = y0; y < y1; y++) {
        float *out = b->out + (size_t)y * w;
        memset(out, 0, w * sizeof(float));
        for (int t = 0; t <= 2 * b->r; t++) {
            int ry = y + t - b->r;
            if (ry < 0 || ry >= b->h)
                continue;
            const float *in = b->tmp + (size_t)ry * w;
            for (size_t x = 0; x < w; x++)
                out[x] += b->g[t] * in[x];
        }
    }
}

/* out = G(in), deviation s px; tmp: a scratch plane. -1 when out of memory. */
static int gauss(const float *in, float *out, float *tmp, int w, int h, double s)
{
    int r = (int)ceil(3.0 * s);
    float *g = malloc((size_t)(2 * r + 1) * sizeof(float));
    if (!g)
        return -1;
    double sum = 0;
    for (int t = -r; t <= r; t++)
        sum += exp(-(double)t * t / (2.0 * s * s));
    for (int t = -r; t <= r; t++)
        g[t + r] = (float)(exp(-(double)t * t / (2.0 * s * s)) / sum);
    struct blur b = {.in = in, .out = out, .tmp = tmp, .g = g, .r = r, .w = w, .h = h};
    ssg_parallel_rows(h, ROWS_PER_BAND, blur_rows, &b);
    ssg_parallel_rows(h, ROWS_PER_BAND, blur_columns, &b);
    free(g);
    return 0;
}

/* 1 when compared pixel i has a 4-neighbour outside the image, not compared, or across a
   depth jump: the blur must not mix two surfaces, nor a surface with what lies beyond. */
static int is_edge(const struct ssg_structure_input *in, int x, int y)
{
    static const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    size_t i = (size_t)y * (size_t)in->w + (size_t)x;
    for (int k = 0; k < 4; k++) {
        int nx = x + dx[k], ny = y + dy[k];
        if (nx < 0 || ny < 0 || nx >= in->w || ny >= in->h)
            return 1;
        size_t n = (size_t)ny * (size_t)in->w + (size_t)nx;
        if (!in->on[n])
            return 1;
        if (in->depth) {
            float z = in->depth[i], zn = in->depth[n];
            if (fabsf(z - zn) > SSG_STRUCTURE_DEPTH_JUMP * fminf(z, zn))
                return 1;
        }
    }
    return 0;
}

/* dst[k step] = 1 where src has a 1 within r places of k along one line of n. */
static void dilate_line(const unsigned char *src, unsigned char *dst, int n, size_t step,
                        int r)
{
    for (int k = 0; k < n; k++) {
        unsigned char v = 0;
        for (int t = k - r < 0 ? 0 : k - r; t <= k + r && t < n && !v; t++)
            v = src[(size_t)t * step];
        dst[(size_t)k * step] = v;
    }
}

/* near[i] = 1 where an edge pixel lies in the (2r + 1)^2 square around i: the edges
   marked, then dilated along rows and along columns. -1 when out of memory. */
static int near_edges(const struct ssg_structure_input *in, int r, unsigned char *near)
{
    size_t w = (size_t)in->w, n = w * (size_t)in->h;
    unsigned char *e = malloc(n + 1);
    if (!e)
        return -1;
    for (int y = 0; y < in->h; y++)
        for (int x = 0; x < in->w; x++)
            e[(size_t)y * w + (size_t)x] = in->on[(size_t)y * w + (size_t)x] && is_edge(in, x, y);
    for (int y = 0; y < in->h; y++)
        dilate_line(e + (size_t)y * w, near + (size_t)y * w, in->w, 1, r);
    for (int x = 0; x < in->w; x++)
        dilate_line(near + x, e + x, in->h, w, r);
    memcpy(near, e, n);
    free(e);
    return 0;
}

/* The weight m, m (a - b) and m b of the channels' mean, 0 where not compared (a NaN
   there must not leak in). */
static void fill_planes(const struct ssg_structure_input *in, float *const *p)
{
    size_t n = (size_t)in->w * (size_t)in->h;
    for (size_t i = 0; i < n; i++) {
        float a = 0.0f, b = 0.0f;
        for (int c = 0; c < in->channels; c++)
            a += in->test[c][i], b += in->ref[c][i];
        int on = in->on[i];
        p[P_M][i] = on ? 1.0f : 0.0f;
        p[P_E][i] = on ? (a - b) / (float)in->channels : 0.0f;
        p[P_B][i] = on ? b / (float)in->channels : 0.0f;
    }
}

/* 1 when pixel i is measured: compared, no edge near, G(b) > 0 and the reference smooth
   at the scale: |G(b) - G2(b)| <= tau G2(b), G2 of deviation 2 sigma. */
static int measured(const struct ssg_structure_input *in, float *const *p,
                    const unsigned char *near, size_t i)
{
    if (!in->on[i] || near[i] || !(p[P_BS][i] > 0.0f) || !(p[P_B2][i] > 0.0f))
        return 0;
    double gb = (double)p[P_BS][i] / p[P_MS][i], gb2 = (double)p[P_B2][i] / p[P_M2][i];
    return fabs(gb - gb2) <= in->smooth * gb2;
}

/* d over the measured pixels into map (0 elsewhere), then its statistics, in row order. */
static void statistics(const struct ssg_structure_input *in, float *const *p,
                       const unsigned char *near, float *map, struct ssg_structure_result *r)
{
    size_t n = (size_t)in->w * (size_t)in->h;
    double lo = INFINITY, hi = -INFINITY, sum = 0, sq = 0;
    long long count = 0;
    for (size_t i = 0; i < n; i++) {
        map[i] = 0.0f;
        if (!measured(in, p, near, i))
            continue;
        double d = (double)p[P_ES][i] / (double)p[P_BS][i];
        map[i] = (float)d;
        lo = d < lo ? d : lo, hi = d > hi ? d : hi;
        sum += d, count++;
    }
    double mean = count ? sum / (double)count : NAN;
    for (size_t i = 0; i < n; i++)
        if (measured(in, p, near, i))
            sq += ((double)map[i] - mean) * ((double)map[i] - mean);
    r->pixels = count;
    r->pp = count ? hi - lo : NAN;
    r->rms = count ? sqrt(sq / (double)count) : NAN;
}

int ssg_structure_measure(const struct ssg_structure_input *in, float *map,
                          struct ssg_structure_result *r)
{
    size_t n = (size_t)in->w * (size_t)in->h;
    float *all = malloc((PLANES * n + 1) * sizeof(float));
    unsigned char *near = malloc(n + 1);
    float *own = map ? NULL : malloc((n + 1) * sizeof(float));
    int rc = all && near && (map || own) ? 0 : -1;
    float *p[PLANES];
    for (int k = 0; k < PLANES && all; k++)
        p[k] = all + (size_t)k * n;
    if (!rc) {
        fill_planes(in, p);
        double s = in->sigma;
        rc = near_edges(in, (int)ceil(3.0 * s), near);
        rc = rc ? rc : gauss(p[P_M], p[P_MS], p[P_TMP], in->w, in->h, s);
        rc = rc ? rc : gauss(p[P_E], p[P_ES], p[P_TMP], in->w, in->h, s);
        rc = rc ? rc : gauss(p[P_B], p[P_BS], p[P_TMP], in->w, in->h, s);
        rc = rc ? rc : gauss(p[P_M], p[P_M2], p[P_TMP], in->w, in->h, 2.0 * s);
        rc = rc ? rc : gauss(p[P_B], p[P_B2], p[P_TMP], in->w, in->h, 2.0 * s);
    }
    if (!rc)
        statistics(in, p, near, map ? map : own, r);
    free(all), free(near), free(own);
    return rc;
}
