/* tune_search.c - the optimiser of `ssgraph tune` (tune_search.h): start point, Halton
 * design, compass search with halving steps; every distinct (snapped) point evaluated at
 * most once. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "tune_search.h"

/* The compass's first step, a quarter of the box: wide enough to leave the start's basin,
   narrow enough that the design's best point is refined rather than jumped away from. */
#define FIRST_STEP 0.25

struct state {
    struct ssg_search *s;
    double *points;  /* the distinct points evaluated, dims each */
    double *values;
    int count;
    double best_at[SSG_SEARCH_MAX_DIMS]; /* the best point before its snap (s->best: after) */
};

static double clamp01(double v)
{
    return v < 0 ? 0 : v > 1 ? 1 : v;
}

static int running(const struct ssg_search *s)
{
    return s->evaluations < s->budget && !s->stopped;
}

/* Index of x among the points evaluated, or -1. */
static int find(const struct state *st, const double *x)
{
    int dims = st->s->dims;
    for (int i = 0; i < st->count; i++) {
        int same = 1;
        for (int k = 0; k < dims && same; k++)
            same = st->points[i * dims + k] == x[k];
        if (same)
            return i;
    }
    return -1;
}

/* f at x clamped into the box (in place) and snapped; a snapped point seen before is
   looked up. The caller keeps x unsnapped: its steps stay on an exact dyadic lattice, so a
   step and its reverse come back to the very same point (snapping each position would let
   rounding drift make near-copies of points already evaluated). +inf once the budget is
   spent or f stopped the search. */
static double evaluate(struct state *st, double *point)
{
    struct ssg_search *s = st->s;
    double x[SSG_SEARCH_MAX_DIMS];
    for (int k = 0; k < s->dims; k++)
        x[k] = point[k] = clamp01(point[k]);
    if (s->snap)
        s->snap(s->user, x);
    int seen = find(st, x);
    if (seen >= 0)
        return st->values[seen];
    if (!running(s))
        return INFINITY;
    double v = s->f(s->user, x);
    s->evaluations++;
    if (isnan(v)) {
        s->stopped = 1;
        return INFINITY;
    }
    memcpy(&st->points[st->count * s->dims], x, (size_t)s->dims * sizeof *x);
    st->values[st->count++] = v;
    if (v < s->best_value) {
        s->best_value = v;
        memcpy(s->best, x, (size_t)s->dims * sizeof *x);
        memcpy(st->best_at, point, (size_t)s->dims * sizeof *x);
    }
    return v;
}

/* Phi_b(i): the digits of i in base b mirrored behind the point. */
static double radical_inverse(unsigned i, unsigned base)
{
    double inv = 1.0 / base, scale = inv, r = 0;
    for (; i; i /= base, scale *= inv)
        r += (double)(i % base) * scale;
    return r;
}

/* Points 1..count of the Halton sequence in the first primes as bases: spread over the
   box without clumps, and the same every time. At most 2 dims + 1, and a fifth of the
   budget, so the local search keeps most of it. */
static void design(struct state *st)
{
    static const unsigned primes[SSG_SEARCH_MAX_DIMS] = {2, 3, 5, 7, 11, 13, 17, 19};
    struct ssg_search *s = st->s;
    int count = 2 * s->dims + 1 < s->budget / 5 ? 2 * s->dims + 1 : s->budget / 5;
    for (int i = 1; i <= count && running(s); i++) {
        double x[SSG_SEARCH_MAX_DIMS];
        for (int k = 0; k < s->dims; k++)
            x[k] = radical_inverse((unsigned)i, primes[k]);
        evaluate(st, x);
    }
}

/* Polls x +- h along each axis, the last successful direction first; moves to the first
   improvement, else halves h. */
static void compass(struct state *st)
{
    struct ssg_search *s = st->s;
    int dirs = 2 * s->dims, first = 0;
    double x[SSG_SEARCH_MAX_DIMS], fx = s->best_value;
    double min_step = s->min_step > 0 ? s->min_step : 1.0 / 512;
    memcpy(x, st->best_at, sizeof x);
    for (double h = FIRST_STEP; h >= min_step && running(s);) {
        int moved = 0;
        for (int t = 0; t < dirs && !moved && running(s); t++) {
            int d = (first + t) % dirs;
            double y[SSG_SEARCH_MAX_DIMS];
            memcpy(y, x, sizeof y);
            y[d / 2] += d % 2 ? -h : h;
            double v = evaluate(st, y);
            if (v < fx) {
                memcpy(x, y, sizeof x);
                fx = v;
                first = d;
                moved = 1;
            }
        }
        if (!moved)
            h /= 2;
    }
}

int ssg_search_run(struct ssg_search *s)
{
    struct state st = {.s = s};
    s->best_value = INFINITY;
    s->evaluations = 0;
    s->stopped = 0;
    st.points = malloc((size_t)s->budget * (size_t)s->dims * sizeof *st.points);
    st.values = malloc((size_t)s->budget * sizeof *st.values);
    if (!st.points || !st.values) {
        free(st.points);
        free(st.values);
        return -1;
    }
    double x[SSG_SEARCH_MAX_DIMS];
    memcpy(x, s->start, sizeof x);
    memcpy(s->best, x, sizeof x);
    evaluate(&st, x);
    design(&st);
    if (isfinite(s->best_value))
        compass(&st);
    free(st.points);
    free(st.values);
    return 0;
}
