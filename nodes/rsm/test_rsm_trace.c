/* test_rsm_trace.c - ssg_rsm_trace_all (rsm_trace.c), the CPU's many traces at once, gives
 * every trace the outcome ssg_rsm_visible gives it alone, bit for bit, in the Cornell box's
 * distance field: for pseudo-random segments between points of the room (both outcomes
 * must occur, so the check cannot pass on an empty room) and for lists shorter than the
 * lanes, as long as them and longer, so that idle lanes and refills both run; from the
 * field's bricked squares and from its floats alone. */
#include <stdio.h>

#include "check.h"
#include "rsm/rsm.h"
#include "scene/distance.h"
#include "scene/scene.h"

enum { SEGMENTS = 3000 };

static unsigned next_random(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return *s >> 8;
}

/* A point of the box [-1, 1] x [0, 2] x [-1, 1] and a unit normal, pseudo-random. */
static void random_end(unsigned *s, float p[3], float n[3])
{
    const float lo[3] = {-1, 0, -1};
    float len = 0.0f;
    for (int k = 0; k < 3; k++) {
        p[k] = lo[k] + 2.0f * (float)next_random(s) / (float)(1u << 24);
        n[k] = (float)next_random(s) / (float)(1u << 23) - 1.0f;
        len += n[k] * n[k];
    }
    for (int k = 0; k < 3; k++)
        n[k] /= sqrtf(len);
}

static struct ssg_rsm_consts consts_of(const struct ssg_distance *f)
{
    struct ssg_rsm_consts c = {.p.vis_start = 1.5f, .grid_inv = 1.0f / f->voxel};
    for (int k = 0; k < 3; k++) {
        c.grid_n[k] = f->n[k];
        c.grid_lo[k] = f->lo[k];
    }
    return c;
}

/* The first n traces of the list at once against each alone; returns how many are blocked. */
static int check_list(const struct ssg_rsm_consts *c, const struct ssg_distance *field,
                      const struct ssg_rsm_trace *tr, const int *alone, int n)
{
    static unsigned char seen[SEGMENTS];
    for (int i = 0; i < n; i++)
        seen[i] = 7;
    ssg_rsm_trace_all(c, field, tr, n, seen);
    int blocked = 0, wrong = 0;
    for (int i = 0; i < n; i++) {
        wrong += seen[i] != alone[i];
        blocked += seen[i] == 0;
    }
    CHECK_EQ(wrong, 0);
    return blocked;
}

int main(void)
{
    struct ssg_diags d = {0};
    struct ssg_scene *s = NULL;
    CHECK_EQ(ssg_scene_load("examples/cornell.scene", 1, &s, &d), SSG_OK);
    ssg_diags_print(&d, stderr);
    if (!s || !s->distance)
        return check_report();
    const struct ssg_rsm_consts c = consts_of(s->distance);
    const float *field = s->distance->d;
    struct ssg_distance flat = *s->distance;
    flat.square = NULL; /* the float field alone */
    CHECK(s->distance->square != NULL);
    static struct ssg_rsm_trace tr[SEGMENTS];
    static int alone[SEGMENTS];
    unsigned seed = 12345u;
    int n = 0;
    while (n < SEGMENTS) {
        float x[3], nx[3], y[3], ny[3];
        random_end(&seed, x, nx);
        random_end(&seed, y, ny);
        if (ssg_rsm_trace_begin(&c, x, nx, y, ny, &tr[n]))
            continue; /* too short to trace */
        alone[n++] = ssg_rsm_visible(&c, field, x, nx, y, ny);
    }
    const int lengths[] = {0, 1, SSG_RSM_LANES - 1, SSG_RSM_LANES, SSG_RSM_LANES + 1, SEGMENTS};
    int blocked = 0;
    for (size_t k = 0; k < sizeof lengths / sizeof lengths[0]; k++) {
        blocked = check_list(&c, s->distance, tr, alone, lengths[k]);
        CHECK_EQ(check_list(&c, &flat, tr, alone, lengths[k]), blocked);
    }
    fprintf(stderr, "%d segments, %d blocked\n", SEGMENTS, blocked);
    CHECK(blocked > SEGMENTS / 20 && blocked < SEGMENTS - SEGMENTS / 20);
    ssg_scene_destroy(&s);
    return check_report();
}
