/* gl_parity.h - the CPU/GL parity check every node's GL test uses: one node run on both
 * backends (ssg_node_run with and without "backend=gl") on the same inputs, every output
 * compared over interior pixels (a border of `border` px left out, where clamped reads may
 * legitimately differ), the largest and the mean absolute difference against the node's
 * stated bound (its descriptor's `parity`, node.h: parity_tol_of). Prints one line per
 * output so a run shows the margins.
 * Also the inputs the node tests share (Halton kernels, count images, colour fields,
 * option-driven bindings) and, when planes.h is included before this header, the
 * helpers of the tests on its ray-cast G-buffers. Header-only, single-threaded. */
#ifndef SSG_TEST_GL_PARITY_H
#define SSG_TEST_GL_PARITY_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

struct parity_tol {
    int border;      /* px left out on each side */
    double max_abs;  /* largest |gl - cpu| allowed over the interior */
    double mean_abs; /* mean |gl - cpu| allowed */
};

/* The bound `node`'s descriptor states (node.h, struct ssg_parity_bound), no border: the
   one place a node's CPU/GL tolerance is written. An unknown node fails a CHECK. */
static inline struct parity_tol parity_tol_of(const char *node)
{
    const struct ssg_node_desc *d = ssg_node_find(node, strlen(node));
    CHECK(d != NULL);
    if (!d)
        return (struct parity_tol){0, 0.0, 0.0};
    return (struct parity_tol){.border = 0, .max_abs = d->parity.max,
                               .mean_abs = d->parity.mean};
}

struct parity_diff {
    double max_abs, mean_abs;
    int mismatched_nan; /* pixels finite on one backend and not on the other */
};

static inline struct parity_diff parity_compare(const struct ssg_image *cpu,
                                                const struct ssg_image *gl, int border)
{
    struct parity_diff d = {0, 0, 0};
    double sum = 0;
    long n = 0;
    for (int c = 0; c < cpu->channels; c++)
        for (int y = border; y < cpu->height - border; y++)
            for (int x = border; x < cpu->width - border; x++) {
                size_t o = ((size_t)c * cpu->height + y) * cpu->width + x;
                float a = cpu->data[o], b = gl->data[o];
                if (isfinite(a) != isfinite(b)) {
                    d.mismatched_nan++;
                    continue;
                }
                double e = isfinite(a) ? fabs((double)a - b) : 0.0;
                d.max_abs = e > d.max_abs ? e : d.max_abs;
                sum += e;
                n++;
            }
    d.mean_abs = n ? sum / (double)n : 0.0;
    return d;
}

/* Checks one output pair against tol and prints its line; on its own for tests that make
   the two runs themselves (a node run with a scene). Returns the largest difference. */
static inline double parity_check_output(const char *node, const char *label, const char *name,
                                         const struct ssg_image *cpu,
                                         const struct ssg_image *gl, struct parity_tol tol)
{
    struct parity_diff p = parity_compare(cpu, gl, tol.border);
    fprintf(stderr, "parity %-8s %-24s %-10s max %.3g (tol %.3g) mean %.3g (tol %.3g)\n", node,
            label, name, p.max_abs, tol.max_abs, p.mean_abs, tol.mean_abs);
    CHECK_EQ(p.mismatched_nan, 0);
    CHECK(p.max_abs <= tol.max_abs);
    CHECK(p.mean_abs <= tol.mean_abs);
    return p.max_abs;
}

/* Runs `node` on both backends and checks every output; `label` names the case. Returns
 * the largest max_abs seen (for tests that also want to see GL differ from something). */
static inline double parity_node(const char *label, const char *node,
                                 const struct ssg_binding *in, int in_count,
                                 const char *const *sets, int set_count,
                                 const struct ssg_frame *frame, struct parity_tol tol)
{
    const char *gl_sets[64];
    int n = set_count < 63 ? set_count : 63;
    memcpy(gl_sets, sets, (size_t)n * sizeof *gl_sets);
    gl_sets[n] = "backend=gl";
    struct ssg_outputs cpu = {0}, gl = {0};
    struct ssg_diags d = {0};
    enum ssg_err e1 = ssg_node_run(node, in, in_count, sets, set_count, frame, &cpu, &d);
    enum ssg_err e2 = ssg_node_run(node, in, in_count, gl_sets, n + 1, frame, &gl, &d);
    if (e1 || e2)
        ssg_diags_print(&d, stderr);
    CHECK_EQ(e1, SSG_OK);
    CHECK_EQ(e2, SSG_OK);
    double worst = 0;
    for (int i = 0; !e1 && !e2 && i < cpu.count; i++) {
        CHECK_EQ(cpu.images[i]->width, gl.images[i]->width);
        CHECK_EQ(cpu.images[i]->height, gl.images[i]->height);
        CHECK_EQ(cpu.images[i]->channels, gl.images[i]->channels);
        struct parity_tol t = tol;
        if (cpu.images[i]->height <= 2 * t.border || cpu.images[i]->width <= 2 * t.border)
            t.border = 0; /* kernels and patterns: every texel */
        double max_abs = parity_check_output(node, label, cpu.names[i], cpu.images[i],
                                             gl.images[i], t);
        worst = max_abs > worst ? max_abs : worst;
    }
    ssg_outputs_release(&cpu);
    ssg_outputs_release(&gl);
    return worst;
}

/* ---- Inputs the node tests share ---- */

/* One input a case may bind: bound when `opt` holds `flag` (always when flag is 0) and
   `image` is set, so each test states its node's ports once, in port order. */
struct parity_input {
    char flag;                     /* the letter of `opt` that asks for it, 0: always */
    const char *port;              /* the node's input port */
    const struct ssg_image *image; /* NULL: never bound */
};

/* Fills b from table (count entries, b as large) for the letters of opt; returns how
   many it bound. */
static inline int parity_bind(const struct parity_input *table, int count, const char *opt,
                              struct ssg_binding *b)
{
    int n = 0;
    for (int i = 0; i < count; i++)
        if (table[i].image && (!table[i].flag || strchr(opt, table[i].flag)))
            b[n++] = (struct ssg_binding){table[i].port, table[i].image};
    return n;
}

/* The `halton` node's kernel and rotation tile for frame f, so every test samples with the
   node's own kernels; kernel may be NULL (the tile alone), and a failed run fails a CHECK. */
static inline void parity_halton(const struct ssg_frame *f, const char *const *sets,
                                 int set_count, struct ssg_image **kernel,
                                 struct ssg_image **rot)
{
    struct ssg_diags d = {0};
    struct ssg_outputs out = {0};
    CHECK_EQ(ssg_node_run("halton", NULL, 0, sets, set_count, f, &out, &d), SSG_OK);
    if (kernel)
        *kernel = out.images[0];
    else
        ssg_image_destroy(&out.images[0]);
    *rot = out.images[1];
}

/* A w x h count input over the whole range the sampling nodes accept for a kernel of k:
   below 1, fractions (half up), above k, and NaN. */
static inline struct ssg_image *parity_count_image(int w, int h, int k)
{
    struct ssg_image *c = ssg_image_create(w, h, 1);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            float v = (float)((x * 7 + y * 3) % (k + 4)) - 1.5f;
            c->data[y * w + x] = (x + y) % 23 == 0 ? NAN : v;
        }
    return c;
}

/* A w x h x 3 smooth colour field, base + gain * [0, 1), so that each sender's light and
   each receiver differ. */
static inline struct ssg_image *parity_colour_field(int w, int h, float base, float gain)
{
    struct ssg_image *im = ssg_image_create(w, h, 3);
    for (int c = 0; c < 3; c++)
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++)
                im->data[((size_t)c * h + y) * w + x] =
                    base + gain * (float)((x * (c + 1) + y * (3 - c)) % 17) / 17.0f;
    return im;
}

/* A copy of im with every value times s (non-unit normals from unit ones). */
static inline struct ssg_image *parity_scaled(const struct ssg_image *im, float s)
{
    struct ssg_image *out = ssg_image_create(im->width, im->height, im->channels);
    for (size_t i = 0; i < (size_t)im->width * im->height * im->channels; i++)
        out->data[i] = s * im->data[i];
    return out;
}

#endif

/* ---- Tests on planes.h's G-buffers (planes.h included before this header) ---- */
#if defined(SSG_TEST_PLANES_H) && !defined(SSG_TEST_GL_PARITY_PLANES)
#define SSG_TEST_GL_PARITY_PLANES

/* For background pixels: a floor with a wall on its left under an open sky. */
static inline void parity_sky_scene(struct scene *s)
{
    *s = (struct scene){.count = 2};
    plane_at(&s->pl[0], 0, 1, 0.2, 0, -1, -5);   /* floor */
    plane_at(&s->pl[1], 1, 0, 0.3, -1.5, 0, -5); /* wall on the left, facing right */
}

/* Ray-casts the scene that scene_fn makes into g (W x H; release() it). */
static inline void parity_cast(void (*scene_fn)(struct scene *), struct gbuf *g)
{
    struct scene s;
    scene_fn(&s);
    cast(&s, g);
}

/* The frame of a G-buffer cast at W x H read as a 2x subsampled one: the projection
   scaled by 2 is the one it was cast with. */
static inline struct ssg_frame parity_subsampled_frame(void)
{
    struct ssg_frame big = frame();
    big.width *= 2, big.height *= 2;
    return big;
}

/* The inputs of a sampling node's cases on one G-buffer: a test fills those its node
   reads and leaves the rest NULL; parity_inputs_free() frees them all. */
struct parity_inputs {
    struct gbuf g;                          /* the ray-cast G-buffer, W x H */
    struct ssg_image *kernel, *rot, *count; /* halton's kernel and tile; per-pixel counts */
    struct ssg_image *nrm2;                 /* g's normals scaled by 2 (non-unit) */
    struct ssg_image *albedo, *light;       /* W x H x 3 colour fields */
};

static inline void parity_inputs_free(struct parity_inputs *in)
{
    release(&in->g);
    ssg_image_destroy(&in->kernel);
    ssg_image_destroy(&in->rot);
    ssg_image_destroy(&in->count);
    ssg_image_destroy(&in->nrm2);
    ssg_image_destroy(&in->albedo);
    ssg_image_destroy(&in->light);
}

/* Parity of images of ones would prove nothing: runs `node` on the CPU and checks that
   its first output darkens more than 1 in 200 of g's pixels (printing how many). */
static inline void parity_check_darkens(const char *node, const struct gbuf *g,
                                        const struct ssg_binding *b, int n,
                                        const char *const *sets, int set_count,
                                        const struct ssg_frame *f)
{
    struct ssg_outputs cpu = {0};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_node_run(node, b, n, sets, set_count, f, &cpu, &d), SSG_OK);
    if (cpu.count < 1)
        return;
    int lit, dark = count_not_one(g, cpu.images[0]);
    double mean = mean_over(cpu.images[0], g->which, 0, 0, W, H, 0, &lit);
    fprintf(stderr, "    %d of %d not 1, mean %.3f\n", dark, W * H, mean);
    CHECK(dark > W * H / 200);
    ssg_outputs_release(&cpu);
}

#endif
