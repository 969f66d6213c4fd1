/* test_halton_rotations.c - the `halton` node's rotation tiles (halton_pattern.c):
 * rotations=blue_noise puts every one of its n*n equally spaced angles on the tile once
 * (each angle equally likely) and its periodogram is low at low frequencies where the
 * white tile's is not; rotations=interleaved puts each of its n equally spaced angles once
 * in every row and every column; the tiles are the same bytes for a seed and change with
 * it; the default is still the white tile of old. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "halton/halton.h"
#include "graph/node.h"
#include "ssgraph.h"

enum { N = 64, CELLS = N * N };

static int run_tile(const char *rotations, int n, uint64_t seed, float *pattern)
{
    char kind[64], side[32];
    snprintf(kind, sizeof kind, "rotations=%s", rotations);
    snprintf(side, sizeof side, "pattern=%d", n);
    const char *sets[] = {kind, side};
    struct ssg_frame frame = {64, 64, 45.0f, 0.05f, 100.0f, seed, 0, 0, 0};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    enum ssg_err e = ssg_node_run("halton", NULL, 0, sets, 2, &frame, &out, &diags);
    CHECK_EQ(e, SSG_OK);
    if (e != SSG_OK || out.count != 2)
        return 0;
    memcpy(pattern, out.images[1]->data, sizeof(float) * 2 * (size_t)n * (size_t)n);
    ssg_outputs_release(&out);
    return 1;
}

/* Angle of cell i in turns, [0, 1). */
static double turns(const float *pattern, int cells, int i)
{
    double t = atan2(pattern[cells + i], pattern[i]) / (2.0 * M_PI);
    return t < 0 ? t + 1.0 : t;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The sorted angles, in turns, are `count` steps of 1/count apart (the first anywhere). */
static void check_equally_spaced(double *t, int count)
{
    qsort(t, (size_t)count, sizeof *t, by_value);
    double worst = 0;
    for (int i = 1; i < count; i++)
        worst = fmax(worst, fabs(t[i] - t[i - 1] - 1.0 / count));
    worst = fmax(worst, fabs(t[0] + 1.0 - t[count - 1] - 1.0 / count));
    CHECK(worst < 1e-5);
}

static void test_blue_noise_angles(void)
{
    static float p[2 * CELLS];
    static double t[CELLS];
    if (!run_tile("blue_noise", N, 3, p))
        return;
    for (int i = 0; i < CELLS; i++)
        t[i] = turns(p, CELLS, i);
    check_equally_spaced(t, CELLS);
    /* The rank map itself: a permutation of 0..n*n-1. */
    static int rank[CELLS], seen[CELLS];
    CHECK(ssg_halton_blue_noise_ranks(N, 3, rank));
    int bad = 0;
    for (int i = 0; i < CELLS; i++)
        bad += rank[i] < 0 || rank[i] >= CELLS || seen[rank[i]]++;
    CHECK_EQ(bad, 0);
}

/* Mean periodogram of the cos plane over the frequencies 0 < |k| <= 8 (cycles a tile),
   relative to the white-noise expectation (its variance times the cells). */
static double low_power(const float *p)
{
    double mean = 0, var = 0;
    for (int i = 0; i < CELLS; i++)
        mean += p[i] / CELLS;
    for (int i = 0; i < CELLS; i++)
        var += (p[i] - mean) * (p[i] - mean) / CELLS;
    double sum = 0;
    int count = 0;
    for (int ky = -8; ky <= 8; ky++)
        for (int kx = 0; kx <= 8; kx++) {
            if (kx * kx + ky * ky > 64 || (kx == 0 && ky <= 0))
                continue;
            double re = 0, im = 0;
            for (int y = 0; y < N; y++)
                for (int x = 0; x < N; x++) {
                    double a = 2.0 * M_PI * (kx * x + ky * y) / N;
                    re += (p[y * N + x] - mean) * cos(a);
                    im -= (p[y * N + x] - mean) * sin(a);
                }
            sum += (re * re + im * im) / CELLS;
            count++;
        }
    return sum / count / var;
}

static void test_blue_noise_spectrum(void)
{
    static float blue[2 * CELLS], white[2 * CELLS];
    if (!run_tile("blue_noise", N, 5, blue) || !run_tile("tile", N, 5, white))
        return;
    double b = low_power(blue), w = low_power(white);
    fprintf(stderr, "low-frequency power / white expectation: blue %.3f, white %.3f\n", b, w);
    CHECK(w > 0.6 && w < 1.6); /* white: flat, about 1 */
    CHECK(b < 0.1);
    CHECK(b < 0.1 * w);
}

static void test_interleaved(void)
{
    enum { n = 6 };
    float p[2 * n * n];
    if (!run_tile("interleaved", n, 9, p))
        return;
    for (int line = 0; line < n; line++) {
        double row[n], col[n];
        for (int k = 0; k < n; k++) {
            row[k] = turns(p, n * n, line * n + k);
            col[k] = turns(p, n * n, k * n + line);
        }
        check_equally_spaced(row, n);
        check_equally_spaced(col, n);
    }
}

static void test_determinism(void)
{
    const char *kinds[] = {"tile", "interleaved", "blue_noise"};
    static float a[2 * CELLS], b[2 * CELLS], c[2 * CELLS];
    for (int k = 0; k < 3; k++) {
        int n = k == 1 ? 8 : N;
        size_t bytes = sizeof(float) * 2 * (size_t)n * (size_t)n;
        if (!run_tile(kinds[k], n, 11, a) || !run_tile(kinds[k], n, 11, b) ||
            !run_tile(kinds[k], n, 12, c))
            return;
        CHECK(memcmp(a, b, bytes) == 0);
        CHECK(memcmp(a, c, bytes) != 0);
    }
    /* No rotations parameter: the white tile, as before the parameter existed. */
    const char *sets[] = {"pattern=8"};
    struct ssg_frame frame = {64, 64, 45.0f, 0.05f, 100.0f, 11, 0, 0, 0};
    struct ssg_diags diags = {0};
    struct ssg_outputs out;
    CHECK_EQ(ssg_node_run("halton", NULL, 0, sets, 1, &frame, &out, &diags), SSG_OK);
    if (run_tile("tile", 8, 11, a) && out.count == 2)
        CHECK(memcmp(a, out.images[1]->data, sizeof(float) * 2 * 64) == 0);
    ssg_outputs_release(&out);
}

int main(void)
{
    test_blue_noise_angles();
    test_blue_noise_spectrum();
    test_interleaved();
    test_determinism();
    return check_report();
}
