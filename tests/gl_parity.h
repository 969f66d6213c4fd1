/* gl_parity.h - the CPU/GL parity check every node's GL test uses: one node run on both
 * backends (ssg_node_run with and without "backend=gl") on the same inputs, every output
 * compared over interior pixels (a border of `border` px left out, where clamped reads may
 * legitimately differ), the largest and the mean absolute difference against the
 * tolerances the test states. Prints one line per output so a run shows the margins. */
#ifndef SSG_TEST_GL_PARITY_H
#define SSG_TEST_GL_PARITY_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "ssgraph.h"

struct parity_tol {
    int border;      /* px left out on each side */
    double max_abs;  /* largest |gl - cpu| allowed over the interior */
    double mean_abs; /* mean |gl - cpu| allowed */
};

struct parity_diff {
    double max_abs, mean_abs;
    int mismatched_nan; /* pixels finite on one backend and not on the other */
};

static inline struct parity_diff parity_compare(const struct ssg_image *cpu, const struct ssg_image *gl,
                                         int border)
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
        int border = tol.border;
        if (cpu.images[i]->height <= 2 * border || cpu.images[i]->width <= 2 * border)
            border = 0; /* kernels and patterns: every texel */
        struct parity_diff p = parity_compare(cpu.images[i], gl.images[i], border);
        fprintf(stderr, "parity %-8s %-24s %-10s max %.3g (tol %.3g) mean %.3g (tol %.3g)\n",
                node, label, cpu.names[i], p.max_abs, tol.max_abs, p.mean_abs, tol.mean_abs);
        CHECK_EQ(p.mismatched_nan, 0);
        CHECK(p.max_abs <= tol.max_abs);
        CHECK(p.mean_abs <= tol.mean_abs);
        worst = p.max_abs > worst ? p.max_abs : worst;
    }
    ssg_outputs_release(&cpu);
    ssg_outputs_release(&gl);
    return worst;
}

#endif
