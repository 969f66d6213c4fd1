/* test_halton_lengths.c - the `halton` node's lengths=shifted (README.md, "Lengths"): the
 * rotation tile's planes 3 and 4 give each pixel a length offset dl and an index shift k,
 * its sample i taking the length of kernel sample (i + k) mod count plus dl; over the
 * tile the kernel's lengths become the stratified lengths of a kernel n times larger: the
 * tile's distribution of lengths is the kernel's (uniform in the length coordinate t),
 * only finer, whatever the shifts k (they only pair lengths with other directions).
 * Worked out by hand on tiny kernels:
 *
 * - count 2, pattern 2, min_scale 0, falloff 1: lengths t = 1/4 and 3/4; the places of the
 *   2 x 2 Latin square are 1/4 and 3/4, offsets (place - 1/2) / 2 = -1/8 and +1/8; the
 *   tile's 8 lengths are 1/8, 3/8, 5/8, 7/8, each twice (each offset holds two cells).
 * - count 4, pattern 4, min_scale 0.5: lengths 0.5 + 0.5 (i + 1/2) / 4; offsets
 *   0.5 (j + 1/2 - 2) / 16 = (2 j - 3) / 64 for j = 0..3, so pixel length i, level j is
 *   0.5 + (4 i + j + 1/2) / 32: the 16 lengths 0.5 + (k + 1/2) / 32, each 4 times.
 * - every row and every column of the offsets holds each of the n offsets once, and each
 *   of the n blocks of shifts floor(k n / count) once (here count = n: each shift).
 * - in a later frame the places turn by the golden-ratio step with the stratified length,
 *   so every sample stays in its stratum and each of the n sub-strata holds one place.
 * - check(): shifted needs falloff 1 and two bases; shared keeps two planes. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "halton/halton.h"
#include "graph/node.h"
#include "ssgraph.h"

/* Runs halton with sets; the kernel and the tile (owned by *out), or 0 on error. */
static int run(const char *const *sets, int count, struct ssg_outputs *out)
{
    struct ssg_frame frame = {64, 64, 45.0f, 0.05f, 100.0f, 5, 0, 0, 0};
    struct ssg_diags diags = {0};
    enum ssg_err e = ssg_node_run("halton", NULL, 0, sets, count, &frame, out, &diags);
    CHECK_EQ(e, SSG_OK);
    return e == SSG_OK && out->count == 2;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The tile's lengths |s_(i + k) mod count| + dl of every cell, sorted, against
   want[m / copies]. */
static void check_tile_lengths(const struct ssg_outputs *out, const double *want,
                               int copies)
{
    const struct ssg_image *k = out->images[0], *t = out->images[1];
    int count = k->width, cells = t->width * t->height;
    CHECK_EQ(t->channels, 4);
    if (t->channels != 4)
        return;
    double *len = malloc(sizeof(double) * (size_t)(count * cells));
    for (int c = 0; c < cells; c++)
        for (int i = 0; i < count; i++) {
            int j = (i + (int)t->data[3 * cells + c]) % count;
            double x = k->data[j], y = k->data[count + j], z = k->data[2 * count + j];
            len[c * count + i] = sqrt(x * x + y * y + z * z) + t->data[2 * cells + c];
        }
    qsort(len, (size_t)(count * cells), sizeof *len, by_value);
    for (int m = 0; m < count * cells; m++)
        CHECK_NEAR(len[m], want[m / copies], 1e-6);
    free(len);
}

/* Every row and every column of the n x n index shifts holds each of 0..n-1 once. */
static void check_shifts(const float *k, int n)
{
    for (int a = 0; a < n; a++)
        for (int v = 0; v < n; v++) {
            int in_row = 0, in_col = 0;
            for (int b = 0; b < n; b++) {
                in_row += k[a * n + b] == (float)v;
                in_col += k[b * n + a] == (float)v;
            }
            CHECK_EQ(in_row, 1);
            CHECK_EQ(in_col, 1);
        }
}

static void test_two_by_two(void)
{
    const char *sets[] = {"count=2", "min_scale=0", "falloff=1", "pattern=2",
                          "lengths=shifted"};
    struct ssg_outputs out;
    if (!run(sets, 5, &out))
        return;
    static const double want[] = {0.125, 0.375, 0.625, 0.875};
    check_tile_lengths(&out, want, 2);
    check_shifts(out.images[1]->data + 3 * 4, 2);
    ssg_outputs_release(&out);
}

/* Every row and every column of the n x n offsets holds each of `levels` once. */
static void check_latin(const float *off, int n, const double *levels)
{
    for (int a = 0; a < n; a++)
        for (int j = 0; j < n; j++) {
            int in_row = 0, in_col = 0;
            for (int b = 0; b < n; b++) {
                in_row += fabs(off[a * n + b] - levels[j]) < 1e-7;
                in_col += fabs(off[b * n + a] - levels[j]) < 1e-7;
            }
            CHECK_EQ(in_row, 1);
            CHECK_EQ(in_col, 1);
        }
}

static void test_four_by_four(void)
{
    const char *sets[] = {"count=4", "min_scale=0.5", "falloff=1", "pattern=4",
                          "mapping=uniform", "lengths=shifted"};
    struct ssg_outputs out;
    if (!run(sets, 6, &out))
        return;
    double want[16];
    for (int k = 0; k < 16; k++)
        want[k] = 0.5 + (k + 0.5) / 32.0;
    check_tile_lengths(&out, want, 4);
    static const double levels[] = {-3.0 / 64, -1.0 / 64, 1.0 / 64, 3.0 / 64};
    check_latin(out.images[1]->data + 2 * 16, 4, levels);
    check_shifts(out.images[1]->data + 3 * 16, 4);
    ssg_outputs_release(&out);
}

/* Frame 3: sample i's shifted coordinate t + offset / (1 - min_scale) lies in its
   stratum [i, i + 1) / count, and the n places of a sample fall one in each sub-stratum
   [i + m / n, i + (m + 1) / n) / count. */
static void test_frames(void)
{
    struct ssg_halton_params p = {.count = 4, .bases = {.v = {2, 3}, .count = 2},
                                  .offset = 1, .falloff = 1, .min_scale = 0.5f,
                                  .lengths = SSG_HALTON_SHIFTED};
    enum { N = 4 };
    for (int i = 0; i < p.count; i++) {
        double u[3];
        ssg_halton_point_at(&p, 3, i, u);
        int seen[N] = {0};
        for (int j = 0; j < N; j++) {
            double dl = ssg_halton_length_offset(&p, 3, (j + 0.5) / N);
            double t = u[2] + dl / (1.0 - p.min_scale);
            int m = (int)floor((t * p.count - i) * N + 1e-9);
            CHECK(m >= 0 && m < N);
            if (m >= 0 && m < N)
                seen[m]++;
        }
        for (int m = 0; m < N; m++)
            CHECK_EQ(seen[m], 1);
    }
    /* Frame 0 is the stratum's middle: the offset is (place - 1/2) (1 - m) / count. */
    CHECK_NEAR(ssg_halton_length_offset(&p, 0, 0.875), 0.375 * 0.5 / 4, 1e-15);
}

static void test_check(void)
{
    struct ssg_frame frame = {64, 64, 45.0f, 0.05f, 100.0f, 5, 0, 0, 0};
    struct ssg_outputs out;
    struct ssg_diags diags = {0};
    const char *curved[] = {"lengths=shifted", "falloff=2"};
    CHECK_EQ(ssg_node_run("halton", NULL, 0, curved, 2, &frame, &out, &diags), SSG_E_VALUE);
    const char *three[] = {"lengths=shifted", "falloff=1", "bases=[2, 3, 5]"};
    CHECK_EQ(ssg_node_run("halton", NULL, 0, three, 3, &frame, &out, &diags), SSG_E_VALUE);
    const char *shared[] = {"falloff=1"};
    if (run(shared, 1, &out)) {
        CHECK_EQ(out.images[1]->channels, 2);
        ssg_outputs_release(&out);
    }
}

int main(void)
{
    test_two_by_two();
    test_four_by_four();
    test_frames();
    test_check();
    return check_report();
}
