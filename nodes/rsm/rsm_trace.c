/* rsm_trace.c - many visibility traces of the `rsm` node at once (ssg_rsm_trace_all, rsm.h):
 * the sphere traces of ssg_rsm_visible run in SSG_RSM_LANES lanes stepped together by one
 * branch-free vector loop (the voxel loads one gather), each finished lane refilled from
 * the list. A trace alone waits on every voxel load, and the scalar lockstep it replaces
 * branched on every step's outcome; here only a finished lane costs a branch. Each lane
 * makes ssg_rsm_trace_step's float operations in its order, so every result is the same
 * bit as the trace run alone. */
#include "common/vector_loops.h" /* first: see there */

#include "rsm.h"
#include "scene/distance.h"

/* GCC's vector extensions: each operation is the scalar one lane by lane (IEEE, no
   contraction in C11 mode), on AVX2 one instruction, on SSE4 two. */
typedef float vfloat __attribute__((vector_size(32)));
typedef int vint __attribute__((vector_size(32)));
typedef unsigned vuint __attribute__((vector_size(32)));
enum { WIDTH = 8, VECTORS = SSG_RSM_LANES / WIDTH };
/* The helpers below take and return such vectors but are always inlined into the clones:
   no call passes one, so the baseline's ABI warning for them does not apply. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
_Static_assert(SSG_RSM_LANES % WIDTH == 0 && SSG_RSM_LANES <= 32,
               "lanes: whole vectors, one bit each in an unsigned");

/* The lanes' traces, one vector a field of struct ssg_rsm_trace per WIDTH lanes. */
struct lanes {
    vfloat p[3][VECTORS], u[3][VECTORS], t[VECTORS], end[VECTORS];
    vint out[VECTORS];   /* -1 once the trace was in an empty voxel, else 0 */
    vint state[VECTORS]; /* the last step's outcome: -1 going, 1 visible, 0 blocked */
    int who[SSG_RSM_LANES]; /* the trace's index in the list; -1: an idle lane */
};

/* (int)floorf(a) lane by lane: the truncation, less one where it lies above a. Exact
   wherever floorf's result fits an int; elsewhere both are outside the grid. */
static inline __attribute__((always_inline)) vint floor_int(vfloat a)
{
    vint i = __builtin_convertvector(a, vint);
    vint above = __builtin_convertvector(i, vfloat) > a;
    return (vint)((vuint)i + (vuint)above);
}

/* a where mask (-1), else b. */
static inline __attribute__((always_inline)) vfloat pick(vint mask, vfloat a, vfloat b)
{
    return (vfloat)(((vint)a & mask) | ((vint)b & ~mask));
}

/* Each lane's voxel distance: the float field's, or (bricked) the root of the bricked
   square, the same float (distance.h); voxel 0 where not in. */
static inline __attribute__((always_inline)) vfloat
distances(const struct ssg_distance *f, int bricked, vint x, vint y, vint z, vint in)
{
    vfloat dist;
    if (bricked) {
        const vuint b0 = (vuint){0} + (unsigned)f->bricks[0];
        const vuint b1 = (vuint){0} + (unsigned)f->bricks[1];
        vuint ux = (vuint)x, uy = (vuint)y, uz = (vuint)z;
        vuint brick = ((uz >> 1) * b1 + (uy >> 2)) * b0 + (ux >> 2);
        vuint at = brick * SSG_DISTANCE_BRICK + ((uz & 1) * 16 + (uy & 3) * 4 + (ux & 3));
        at &= (vuint)in; /* unsigned: no overflow where not in */
        for (int k = 0; k < WIDTH; k++)
            dist[k] = f->root[f->square[at[k]]];
    } else {
        const vuint n0 = (vuint){0} + (unsigned)f->n[0], n1 = (vuint){0} + (unsigned)f->n[1];
        vuint at = ((vuint)z * n1 + (vuint)y) * n0 + (vuint)x;
        at &= (vuint)in;
        for (int k = 0; k < WIDTH; k++)
            dist[k] = f->d[at[k]];
    }
    return dist;
}

/* One ssg_rsm_trace_step of every lane; returns the lanes that ended (idle lanes
   included), lane k as bit k. Outside the grid a lane reads voxel 0 and takes the distance 1: not occupied
   (the trace is out) and a step of one voxel, as the scalar step's branch makes them. */
static inline __attribute__((always_inline)) unsigned
step_lanes(const struct ssg_rsm_consts *c, const struct ssg_distance *f, int bricked,
           struct lanes *restrict l)
{
    const vint n0 = (vint){0} + c->grid_n[0], n1 = (vint){0} + c->grid_n[1];
    const vint n2 = (vint){0} + c->grid_n[2];
    const vfloat one = (vfloat){0} + 1.0f, zero = (vfloat){0};
    const vuint bit = {1, 2, 4, 8, 16, 32, 64, 128};
    vuint ended = (vuint){0};
    for (int v = 0; v < VECTORS; v++) {
        vfloat t = l->t[v];
        vint x = floor_int(l->p[0][v] + l->u[0][v] * t);
        vint y = floor_int(l->p[1][v] + l->u[1][v] * t);
        vint z = floor_int(l->p[2][v] + l->u[2][v] * t);
        vint in = (x >= 0) & (x < n0) & (y >= 0) & (y < n1) & (z >= 0) & (z < n2);
        vfloat dist = pick(in, distances(f, bricked, x, y, z, in), one);
        vint blocked = (dist == zero) & l->out[v];
        vint going = l->t[v] < l->end[v];
        vint state = (going & ~blocked) | (~going & 1); /* -1, 0 or 1 */
        l->state[v] = state;
        l->out[v] |= dist != zero;
        vfloat step = dist - one;
        l->t[v] = t + pick(step > one, step, one);
        ended |= (vuint)(state >= 0) & (bit << (unsigned)(WIDTH * v));
    }
    ended |= __builtin_shufflevector(ended, ended, 4, 5, 6, 7, 0, 1, 2, 3);
    ended |= __builtin_shufflevector(ended, ended, 2, 3, 0, 1, 2, 3, 0, 1);
    ended |= __builtin_shufflevector(ended, ended, 1, 0, 1, 0, 1, 0, 1, 0);
    return ended[0];
}

/* Lane k takes trace i of the list, or idles (ends at once, every step) past its end. */
static void fill(struct lanes *l, int k, const struct ssg_rsm_trace *tr, int i, int n)
{
    const struct ssg_rsm_trace *r = i < n ? &tr[i] : &(struct ssg_rsm_trace){.end = 0.0f};
    int v = k / WIDTH, e = k % WIDTH;
    for (int a = 0; a < 3; a++) {
        l->p[a][v][e] = r->p[a];
        l->u[a][v][e] = r->u[a];
    }
    l->t[v][e] = r->t;
    l->end[v][e] = r->end;
    l->out[v][e] = r->out ? -1 : 0;
    l->who[k] = i < n ? i : -1;
}

/* Steps the lanes until one not idle ends, from the bricked squares or the float field;
   returns the lanes that ended, less the idle ones. */
SSG_VECTOR_CLONES
static unsigned step_bricked(const struct ssg_rsm_consts *c, const struct ssg_distance *f,
                             struct lanes *restrict l, unsigned idle)
{
    unsigned ended;
    while (!(ended = step_lanes(c, f, 1, l) & ~idle))
        ;
    return ended;
}

SSG_VECTOR_CLONES
static unsigned step_flat(const struct ssg_rsm_consts *c, const struct ssg_distance *f,
                          struct lanes *restrict l, unsigned idle)
{
    unsigned ended;
    while (!(ended = step_lanes(c, f, 0, l) & ~idle))
        ;
    return ended;
}

void ssg_rsm_trace_all(const struct ssg_rsm_consts *c, const struct ssg_distance *f,
                       const struct ssg_rsm_trace *tr, int n, unsigned char *seen)
{
    struct lanes l;
    int next = 0;
    unsigned idle = 0; /* lanes past the list's end, bit k lane k */
    for (int k = 0; k < SSG_RSM_LANES; k++, next++) {
        fill(&l, k, tr, next, n);
        idle |= (unsigned)(next >= n) << k;
    }
    const unsigned all = SSG_RSM_LANES == 32 ? ~0u : (1u << SSG_RSM_LANES) - 1;
    while (idle != all) {
        unsigned ended = f->square ? step_bricked(c, f, &l, idle) : step_flat(c, f, &l, idle);
        for (; ended; ended &= ended - 1) {
            int k = __builtin_ctz(ended);
            seen[l.who[k]] = (unsigned char)l.state[k / WIDTH][k % WIDTH];
            fill(&l, k, tr, next, n);
            idle |= (unsigned)(next >= n) << k;
            next += next < n;
        }
    }
}
