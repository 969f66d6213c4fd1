/* test_counts.c - the per-pixel sample count input (`count`) of ssao, ssdo and hbao
 * (Szentandrasi section 4.3: a preprocessing pass decides each pixel's number of samples;
 * the `complexity` node makes it).
 *
 * The contract is exact, so the checks are bit for bit (memcmp of the float images):
 * - count = K (the kernel width; hbao: the directions) everywhere gives the bits of the
 *   run without the input: masked lanes add +0, which leaves every sum unchanged, and the
 *   divisions use the same float values (1 / K, 2 pi / K, strength / K).
 * - count = n everywhere gives the bits of a run with the kernel's first n samples as the
 *   whole kernel (ssao, ssdo). The halton node's own count=n kernel is not that prefix:
 *   with two bases its stratified lengths depend on count (halton.c), so the prefix is cut
 *   from the K kernel here.
 * - hbao: its directions are used in an order whose prefixes of 1, 2, 4, ... directions
 *   are exactly the sets of `directions` = 1, 2, 4, ... (angles 2 pi k / n in the same
 *   pair order), so count = n of 8 directions gives the bits of a directions=n run.
 * - mixed counts pick per pixel: each pixel equals the matching uniform run; rounding
 *   (19.6 -> 20, half up) and clamping (0 -> 1, 1e9 and NaN -> K) included.
 * The runs of different n differ on many pixels of the corner scene (checked), so a node
 * that ignored the counts, or applied a neighbour's, fails. */
#include <math.h>
#include <string.h>

#include "check.h"
#include "graph/node.h"
#include "ssgraph.h"

#include "planes.h"

enum { K = 50, PATTERN = 9 };

/* The count pattern: value and the sample count it means (for K = 50). */
static const float pattern_value[PATTERN] = {10, 20, 30, 40, 50, 0, 1e9f, NAN, 19.6f};
static const int pattern_n[PATTERN] = {10, 20, 30, 40, 50, 1, 50, 50, 20};

static int pattern_at(int x, int y)
{
    return (x + 2 * y) % PATTERN;
}

static struct ssg_image *fill(float v)
{
    struct ssg_image *im = ssg_image_create(W, H, 1);
    for (size_t i = 0; im && i < (size_t)W * H; i++)
        im->data[i] = v;
    return im;
}

/* count image of the pattern; scale maps the pattern's n to another kernel width (hbao:
   counts 1, 2, 4, 8 of 8 directions). */
static struct ssg_image *pattern_image(const float *values)
{
    struct ssg_image *im = ssg_image_create(W, H, 1);
    for (int y = 0; im && y < H; y++)
        for (int x = 0; x < W; x++)
            im->data[(size_t)y * W + x] = values[pattern_at(x, y)];
    return im;
}

/* The first n samples of a count x 1 x 3 kernel. */
static struct ssg_image *prefix(const struct ssg_image *k, int n)
{
    struct ssg_image *p = ssg_image_create(n, 1, 3);
    for (int c = 0; p && c < 3; c++)
        memcpy(p->data + (size_t)c * n, k->data + (size_t)c * k->width, sizeof(float) * n);
    return p;
}

/* Runs a node; returns output `which` (owned; the others are released) or NULL. */
static struct ssg_image *run(const char *node, const struct ssg_binding *b, int nb,
                             const char *const *sets, int ns, int which)
{
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run(node, b, nb, sets, ns, &f, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK) {
        ssg_diags_print(&diags, stderr);
        return NULL;
    }
    struct ssg_image *im = out.images[which];
    out.images[which] = NULL;
    ssg_outputs_release(&out);
    return im;
}

static int same_bits(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && a->width == b->width && a->height == b->height &&
           a->channels == b->channels &&
           memcmp(a->data, b->data, sizeof(float) * (size_t)a->width * a->height *
                                        (size_t)a->channels) == 0;
}

/* Pixels (any channel) where a and b differ. */
static int differing(const struct ssg_image *a, const struct ssg_image *b)
{
    int n = 0;
    size_t plane = (size_t)W * H;
    for (size_t i = 0; a && b && i < plane; i++)
        for (int c = 0; c < a->channels; c++)
            if (memcmp(&a->data[c * plane + i], &b->data[c * plane + i], sizeof(float))) {
                n++;
                break;
            }
    return n;
}

/* 1 when every pixel of `mixed` has the bits of runs[index of its pattern's n]. */
static int picks_per_pixel(const struct ssg_image *mixed, struct ssg_image *const *runs,
                           const int *ns, int nruns, const int *pattern_ns)
{
    size_t plane = (size_t)W * H;
    for (int y = 0; mixed && y < H; y++)
        for (int x = 0; x < W; x++) {
            int n = pattern_ns[pattern_at(x, y)], r = 0;
            while (r < nruns && ns[r] != n)
                r++;
            size_t o = (size_t)y * W + x;
            for (int c = 0; r < nruns && runs[r] && c < mixed->channels; c++)
                if (memcmp(&mixed->data[c * plane + o], &runs[r]->data[c * plane + o],
                           sizeof(float)))
                    return 0;
        }
    return mixed != NULL;
}

struct inputs {
    struct gbuf g;
    struct ssg_image *kernel, *rot, *albedo, *light;
};

/* The node's bindings: G-buffer, the kernel (or none for hbao), rotation, and optionally
   albedo + light (ssdo's bounce) and a count image. */
static int bind(const struct inputs *in, const struct ssg_image *kernel, int colours,
                const struct ssg_image *count, struct ssg_binding *b)
{
    int n = 0;
    b[n++] = (struct ssg_binding){"position", in->g.pos};
    b[n++] = (struct ssg_binding){"normal", in->g.nrm};
    if (kernel)
        b[n++] = (struct ssg_binding){"kernel", kernel};
    b[n++] = (struct ssg_binding){"rotation", in->rot};
    if (colours) {
        b[n++] = (struct ssg_binding){"albedo", in->albedo};
        b[n++] = (struct ssg_binding){"light", in->light};
    }
    if (count)
        b[n++] = (struct ssg_binding){"count", count};
    return n;
}

/* ssao or ssdo with one parameter set: K everywhere, 10 everywhere, the mixed pattern. */
static void check_kernel_node(const struct inputs *in, const char *node,
                              const char *const *sets, int ns, int colours, int which)
{
    static const int levels[6] = {1, 10, 20, 30, 40, 50};
    struct ssg_binding b[8];
    struct ssg_image *runs[6] = {0}, *prefixes[6] = {0};
    for (int r = 0; r < 6; r++) {
        prefixes[r] = prefix(in->kernel, levels[r]);
        runs[r] = run(node, b, bind(in, prefixes[r], colours, NULL, b), sets, ns, which);
    }
    struct ssg_image *all = fill(K), *ten = fill(10), *mix = pattern_image(pattern_value);
    struct ssg_image *with_k =
        run(node, b, bind(in, in->kernel, colours, all, b), sets, ns, which);
    struct ssg_image *with_10 = run(node, b, bind(in, in->kernel, colours, ten, b), sets, ns,
                                    which);
    struct ssg_image *mixed = run(node, b, bind(in, in->kernel, colours, mix, b), sets, ns,
                                  which);
    CHECK(same_bits(with_k, runs[5]));
    CHECK(same_bits(with_10, runs[1]));
    CHECK(picks_per_pixel(mixed, runs, levels, 6, pattern_n));
    /* The runs must differ, or the checks above prove nothing. */
    CHECK(differing(runs[1], runs[5]) > W * H / 50);
    CHECK(differing(runs[0], runs[1]) > W * H / 50);
    for (int r = 0; r < 6; r++) {
        ssg_image_destroy(&runs[r]);
        ssg_image_destroy(&prefixes[r]);
    }
    ssg_image_destroy(&all);
    ssg_image_destroy(&ten);
    ssg_image_destroy(&mix);
    ssg_image_destroy(&with_k);
    ssg_image_destroy(&with_10);
    ssg_image_destroy(&mixed);
}

/* hbao: counts of directions. Pattern n in {1, 2, 4, 8} of 8 directions, the rest of the
   pattern clamps (0 -> 1, 1e9 and NaN -> 8, 1.6 -> 2). */
static void check_hbao(const struct inputs *in, const char *falloff)
{
    static const float values[PATTERN] = {1, 2, 4, 8, 8, 0, 1e9f, NAN, 1.6f};
    static const int ns[PATTERN] = {1, 2, 4, 8, 8, 1, 8, 8, 2};
    static const int levels[4] = {1, 2, 4, 8};
    static const char *dirs[4] = {"directions=1", "directions=2", "directions=4",
                                  "directions=8"};
    struct ssg_binding b[8];
    struct ssg_image *runs[4] = {0};
    for (int r = 0; r < 4; r++) {
        const char *sets[] = {dirs[r], falloff, "radius=1"};
        runs[r] = run("hbao", b, bind(in, NULL, 0, NULL, b), sets, 3, 0);
    }
    const char *sets[] = {"directions=8", falloff, "radius=1"};
    struct ssg_image *all = fill(8), *four = fill(4), *mix = pattern_image(values);
    struct ssg_image *with_8 = run("hbao", b, bind(in, NULL, 0, all, b), sets, 3, 0);
    struct ssg_image *with_4 = run("hbao", b, bind(in, NULL, 0, four, b), sets, 3, 0);
    struct ssg_image *mixed = run("hbao", b, bind(in, NULL, 0, mix, b), sets, 3, 0);
    CHECK(same_bits(with_8, runs[3]));
    CHECK(same_bits(with_4, runs[2]));
    CHECK(picks_per_pixel(mixed, runs, levels, 4, ns));
    CHECK(differing(runs[0], runs[3]) > W * H / 50);
    CHECK(differing(runs[2], runs[3]) > W * H / 50);
    for (int r = 0; r < 4; r++)
        ssg_image_destroy(&runs[r]);
    ssg_image_destroy(&all);
    ssg_image_destroy(&four);
    ssg_image_destroy(&mix);
    ssg_image_destroy(&with_8);
    ssg_image_destroy(&with_4);
    ssg_image_destroy(&mixed);
}

/* A count image of the wrong size is refused at check time. */
static void check_rejects(const struct inputs *in)
{
    struct ssg_image *small = ssg_image_create(W / 2, H, 1);
    struct ssg_binding b[8];
    const char *nodes[2] = {"ssao", "ssdo"};
    for (int k = 0; k < 2; k++) {
        struct ssg_diags diags = {0};
        struct ssg_frame f = frame();
        struct ssg_outputs out;
        CHECK_EQ(ssg_node_run(nodes[k], b, bind(in, in->kernel, 0, small, b), NULL, 0, &f,
                              &out, &diags), SSG_E_SIZE);
        ssg_outputs_release(&out);
    }
    struct ssg_diags diags = {0};
    struct ssg_frame f = frame();
    struct ssg_outputs out;
    CHECK_EQ(ssg_node_run("hbao", b, bind(in, NULL, 0, small, b), NULL, 0, &f, &out, &diags),
             SSG_E_SIZE);
    ssg_outputs_release(&out);
    ssg_image_destroy(&small);
}

int main(void)
{
    W = 96, H = 128;
    (void)count_not_one; /* planes.h helpers this test does not need */
    (void)mean_over;
    struct inputs in = {0};
    struct scene s;
    corner_scene(&s);
    cast(&s, &in.g);
    in.albedo = ssg_image_create(W, H, 3);
    in.light = ssg_image_create(W, H, 3);
    for (size_t i = 0; i < (size_t)W * H * 3; i++) {
        in.albedo->data[i] = 0.6f;
        in.light->data[i] = 0.25f + 0.5f * (float)(i % W) / W; /* a ramp: bounce varies */
    }
    /* A kernel of five Halton periods of 10 (bases 2, 5: eq. 8), uniform for ssdo. */
    struct ssg_frame f = frame();
    struct ssg_diags diags = {0};
    struct ssg_outputs hal;
    const char *hsets[] = {"count=50", "bases=[2, 5]", "period=10", "mapping=uniform"};
    CHECK_EQ(ssg_node_run("halton", NULL, 0, hsets, 4, &f, &hal, &diags), SSG_OK);
    in.kernel = hal.images[0];
    in.rot = hal.images[1];
    static const char *modes[3] = {"mode=hemisphere", "mode=sphere", "mode=disc"};
    for (int m = 0; in.kernel && m < 3; m++) {
        const char *sets[] = {modes[m], "radius=1", "range_check=smooth"};
        check_kernel_node(&in, "ssao", sets, 3, 0, 0);
    }
    if (in.kernel) {
        const char *plain[] = {"radius=1"};
        check_kernel_node(&in, "ssdo", plain, 1, 0, 0);
        const char *radiance[] = {"radius=1", "mode=radiance", "bounce=true"};
        check_kernel_node(&in, "ssdo", radiance, 3, 1, 0);
        check_kernel_node(&in, "ssdo", radiance, 3, 1, 1); /* the bounce output */
        check_hbao(&in, "falloff=linear");
        check_hbao(&in, "falloff=none");
        check_rejects(&in);
    }
    ssg_outputs_release(&hal);
    ssg_image_destroy(&in.albedo);
    ssg_image_destroy(&in.light);
    release(&in.g);
    return check_report();
}
