/* ssao_planes.h - running the `ssao` node on the plane G-buffers of planes.h, shared by
 * test_ssao.c (the hemisphere mode) and test_ssao_modes.c (the normal-free sphere and disc
 * modes) and test_ao_samples.c: its Halton kernel, one call of the node, a G-buffer
 * written from a depth per pixel, and the bound on the depth lookup's error that lets
 * those tests claim exact answers. Header-only, like planes.h.
 *
 * Why SSAO can be exactly 1 on an open plane: a sample S above the plane lies between the
 * camera and the plane along its own ray, so the true depth there is >= -S.z. The node
 * reads the depth at the centre of S's pixel instead; the difference is at most the
 * depth's variation over one pixel, depth_bound below (worked out exactly from the scene).
 * With bias > bound no sample of an open plane is occluded. */
#ifndef SSG_TEST_SSAO_PLANES_H
#define SSG_TEST_SSAO_PLANES_H

#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"

/* Flag for ssao()'s use_depth argument: run without the normal input. */
enum { NO_NORMAL = 2 };

/* Largest |depth(q) - depth(centre)| over points q of any pixel showing a surface: the
   visible depth is the lower envelope of functions 1 / (linear in u, v), so along a pixel
   edge its extremes are at corners or where two planes cross; inside, on a crossing line
   or in one plane's region, it is monotone along lines and peaks on the border. */
static inline double depth_bound(const struct scene *s)
{
    double bound = 0;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double dir[3], cu = x + 0.5, cv = y + 0.5;
            int which;
            ray(cu, cv, dir);
            double dc = visible_depth(s, dir, &which);
            if (which < 0)
                continue;
            /* Corners, then the crossings of each pair of planes on each edge. */
            double pts[4 + 4 * 3][2];
            int np = 0;
            static const double cx[4] = {0, 1, 1, 0}, cy[4] = {0, 0, 1, 1};
            for (int k = 0; k < 4; k++) {
                pts[np][0] = x + cx[k];
                pts[np++][1] = y + cy[k];
            }
            for (int a = 0; a < s->count; a++)
                for (int b = a + 1; b < s->count; b++)
                    for (int k = 0; k < 4; k++) {
                        /* Edge from corner k to k+1: where (n_a.p_a)(n_b.d) =
                           (n_b.p_b)(n_a.d), linear in the edge parameter. */
                        double u0 = x + cx[k], v0 = y + cy[k];
                        double u1 = x + cx[(k + 1) % 4], v1 = y + cy[(k + 1) % 4];
                        double d0[3], d1[3];
                        ray(u0, v0, d0);
                        ray(u1, v1, d1);
                        double ca = dot3(s->pl[a].n, s->pl[a].p0);
                        double cb = dot3(s->pl[b].n, s->pl[b].p0);
                        double f0 = ca * dot3(s->pl[b].n, d0) - cb * dot3(s->pl[a].n, d0);
                        double f1 = ca * dot3(s->pl[b].n, d1) - cb * dot3(s->pl[a].n, d1);
                        if ((f0 < 0) != (f1 < 0) && np < 16) {
                            double t = f0 / (f0 - f1);
                            pts[np][0] = u0 + t * (u1 - u0);
                            pts[np++][1] = v0 + t * (v1 - v0);
                        }
                    }
            for (int k = 0; k < np; k++) {
                int w2;
                ray(pts[k][0], pts[k][1], dir);
                double dq = visible_depth(s, dir, &w2);
                if (w2 < 0 || !(dq < 1e6))
                    return INFINITY; /* a pixel reaching the horizon: no bound */
                bound = fmax(bound, fabs(dq - dc));
            }
        }
    return bound;
}

/* A G-buffer of the current W x H frame written from a depth per pixel centre,
   depth(x, y, arg): position = depth times the pixel's ray, normal +z, every pixel a
   surface of plane 0. For scenes no set of planes makes (a step, an occluder with a
   hole); release() frees it. */
static inline struct gbuf gbuf_from_depth(double (*depth)(int x, int y, int arg), int arg)
{
    struct gbuf g = {ssg_image_create(W, H, 3), ssg_image_create(W, H, 3),
                     ssg_image_create(W, H, 1), calloc((size_t)W * H, sizeof(int))};
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            double dir[3], t = depth(x, y, arg);
            ray(x + 0.5, y + 0.5, dir);
            size_t o = (size_t)y * W + (size_t)x;
            for (int c = 0; c < 3; c++)
                g.pos->data[(size_t)c * W * H + o] = (float)(t * dir[c]);
            g.nrm->data[2 * (size_t)W * H + o] = 1.0f;
            g.depth->data[o] = (float)t;
        }
    return g;
}

/* Longest view ray per unit depth in the frame: |(u, v, -1)| at a corner. */
static inline double max_ray_length(void)
{
    double dir[3];
    ray(0, 0, dir);
    return sqrt(dot3(dir, dir));
}

static inline struct ssg_image *kernel_of(const char *const *sets, int count,
                                          struct ssg_image **rotation)
{
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("halton", NULL, 0, sets, count, &f, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK)
        return NULL;
    *rotation = out.images[1];
    return out.images[0];
}

/* Runs ssao on g; returns the output image (owned) or NULL. use_depth: 1 = bind the
   depth input, | NO_NORMAL = leave the normal unbound. */
static inline struct ssg_image *ssao(const struct gbuf *g, const struct ssg_image *kernel,
                                     const struct ssg_image *rotation, int use_depth,
                                     const char *const *sets, int set_count)
{
    struct ssg_binding b[5] = {{"position", g->pos}, {"normal", g->nrm}, {"kernel", kernel}};
    int nb = 3;
    if (use_depth & NO_NORMAL)
        b[1] = b[--nb];
    if (rotation)
        b[nb++] = (struct ssg_binding){"rotation", rotation};
    if (use_depth & 1)
        b[nb++] = (struct ssg_binding){"depth", g->depth};
    /* The tests were derived for the paper's settings (the defaults before issue 15 tuned
       them for accuracy): pinned first, so each test's closed form holds whatever the
       shipped defaults; the caller's sets come after and win. */
    static const char *const pinned[] = {"bias=0.02", "power=1", "range_check=smooth"};
    const char *all[PIN_SETS_MAX];
    int n = pin_sets(all, pinned, 3, sets, set_count);
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("ssao", b, nb, all, n, &f, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    return out.images[0];
}

/* The corner (planes.h) cast W = width pixels wide, for the closed-form tests; the caller
   restores W. Returns the margin by which a sample behind a plane may still count as
   unoccluded: (bias + the lookup error) times the longest ray. The lookup error itself,
   checked to be below the bias, goes to *bound unless that is NULL. */
static inline double corner_cast(int width, double bias, struct scene *s, struct gbuf *g,
                                 double *bound)
{
    W = width;
    corner_scene(s);
    cast(s, g);
    double lookup_error = depth_bound(s);
    CHECK(lookup_error < bias);
    if (bound)
        *bound = lookup_error;
    return (bias + lookup_error) * max_ray_length();
}

#endif
