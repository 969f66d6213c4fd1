/* planes.h - synthetic G-buffers for AO tests: a scene of up to MAX_PLANES infinite planes,
 * ray cast analytically at pixel centres with the frame conventions of core/graph/node.h
 * (view-space position and normal, linear depth, background 0) and the exact projection of
 * ssg_frame_projection. Header-only, shared by the ssao and hbao tests; W and H are each
 * test's own frame size. */
#ifndef SSG_TEST_PLANES_H
#define SSG_TEST_PLANES_H

#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

enum { MAX_PLANES = 3 };

/* Frame size of the current test (tests narrow it for closed-form checks). */
static int W = 128, H = 256;

struct plane {
    double n[3];  /* unit normal, pointing into the air */
    double p0[3]; /* a point on the plane */
};

struct scene {
    struct plane pl[MAX_PLANES];
    int count;
};

struct gbuf {
    struct ssg_image *pos, *nrm, *depth;
    int *which; /* plane index per pixel, -1 = background */
};

static struct ssg_frame frame(void)
{
    return (struct ssg_frame){W, H, 45.0f, 0.05f, 100.0f, 1, 0, 0, 0};
}

static double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* View ray through image point (u, v) in pixels, scaled to depth 1 (z = -1). */
static void ray(double u, double v, double dir[3])
{
    struct ssg_frame f = frame();
    struct ssg_projection p = ssg_frame_projection(&f);
    dir[0] = (u - p.cx) / p.f;
    dir[1] = -(v - p.cy) / p.f;
    dir[2] = -1.0;
}

/* Depth of plane i along dir (z = -1 scaled), or INFINITY when the ray never leaves the
   air through it. */
static double plane_depth(const struct scene *s, int i, const double dir[3])
{
    double nd = dot3(s->pl[i].n, dir);
    return nd < 0 ? dot3(s->pl[i].n, s->pl[i].p0) / nd : INFINITY;
}

static double visible_depth(const struct scene *s, const double dir[3], int *which)
{
    double best = INFINITY;
    *which = -1;
    for (int i = 0; i < s->count; i++) {
        double t = plane_depth(s, i, dir);
        if (t < best) {
            best = t;
            *which = i;
        }
    }
    return best;
}

static void cast(const struct scene *s, struct gbuf *g)
{
    g->pos = ssg_image_create(W, H, 3);
    g->nrm = ssg_image_create(W, H, 3);
    g->depth = ssg_image_create(W, H, 1);
    g->which = calloc((size_t)W * H, sizeof(int));
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double dir[3];
            int which;
            ray(x + 0.5, y + 0.5, dir);
            double t = visible_depth(s, dir, &which);
            size_t o = (size_t)y * W + (size_t)x;
            if (which < 0 || !(t < 1e6)) {
                g->which[o] = -1;
                continue; /* background: zeros */
            }
            g->which[o] = which;
            for (int c = 0; c < 3; c++) {
                g->pos->data[(size_t)c * W * H + o] = (float)(t * dir[c]);
                g->nrm->data[(size_t)c * W * H + o] = (float)s->pl[which].n[c];
            }
            g->depth->data[o] = (float)t;
        }
}

static void release(struct gbuf *g)
{
    ssg_image_destroy(&g->pos);
    ssg_image_destroy(&g->nrm);
    ssg_image_destroy(&g->depth);
    free(g->which);
}

static void plane_at(struct plane *p, double nx, double ny, double nz, double px, double py,
                     double pz)
{
    double len = sqrt(nx * nx + ny * ny + nz * nz);
    p->n[0] = nx / len, p->n[1] = ny / len, p->n[2] = nz / len;
    p->p0[0] = px, p->p0[1] = py, p->p0[2] = pz;
}

/* An inner 90-degree corner: two faces at 45 degrees to the view axis meeting along a
   horizontal edge 5 units away; the camera looks into it. Plane 0 is the floor. */
static void corner_scene(struct scene *s)
{
    *s = (struct scene){.count = 2};
    plane_at(&s->pl[0], 0, 1, 1, 0, 0, -5);  /* floor, facing up and towards us */
    plane_at(&s->pl[1], 0, -1, 1, 0, 0, -5); /* wall, facing down and towards us */
}


/* Parameter sets for a node run: `pinned` first, then the caller's `sets` (later sets win,
   so a caller still overrides what is pinned), into all[0 .. cap); returns how many. Node
   tests pin the settings their closed forms were derived for, so that a change of the
   node's shipped defaults leaves them valid. */
enum { PIN_SETS_MAX = 24 };
static inline int pin_sets(const char **all, const char *const *pinned, int pinned_count,
                           const char *const *sets, int set_count)
{
    int n = 0;
    CHECK(pinned_count + set_count <= PIN_SETS_MAX);
    for (int i = 0; i < pinned_count && n < PIN_SETS_MAX; i++)
        all[n++] = pinned[i];
    for (int i = 0; i < set_count && n < PIN_SETS_MAX; i++)
        all[n++] = sets[i];
    return n;
}
/* The `halton` node's rotation tile for this test's frame (its kernel dropped), owned;
   NULL when the node fails (which fails a CHECK of the including test). */
static inline struct ssg_image *halton_rotation(void)
{
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    if (ssg_node_run("halton", NULL, 0, NULL, 0, &f, &out, &diags) != SSG_OK)
        return NULL;
    ssg_image_destroy(&out.images[0]);
    return out.images[1];
}

/* Counts pixels showing a surface whose value is not exactly 1. */
static inline int count_not_one(const struct gbuf *g, const struct ssg_image *ao)
{
    int n = 0;
    for (size_t i = 0; i < (size_t)W * H; i++)
        n += g->which[i] >= 0 && ao->data[i] != 1.0f;
    return n;
}

static inline double mean_over(const struct ssg_image *ao, const int *which, int x0, int y0,
                               int x1, int y1, int plane, int *count)
{
    double sum = 0;
    *count = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            size_t o = (size_t)y * W + (size_t)x;
            if (which[o] == plane) {
                sum += ao->data[o];
                (*count)++;
            }
        }
    return *count ? sum / *count : 0;
}

#endif
