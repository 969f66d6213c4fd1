/* halton_pattern.c - the three rotation tiles of the `halton` node (rotations = tile,
 * interleaved, blue_noise), made once in prepare() from the frame seed, so both backends
 * copy the same floats and a seed gives the same tile whatever the machine.
 *
 * Why more than one: a filter after the sampling pass (bilateral, 9 taps) removes the
 * tile's noise only where its response is small. The 9-tap Gaussian (sigma 3, cut at 4)
 * passes about 3% at 1/4 cycle per pixel, and a separable filter's response to a
 * structure constant along y is its x response alone, so whatever the 4 x 4 tile leaves
 * in its column means survives as vertical streaks, and where the error also depends on
 * the geometry (self-occlusion against the rounded depth of a receding wall) the same
 * rotation every 4 pixels beats with it into wide streaks. The choices:
 *
 *   tile         n*n angles 2 pi frac(Phi_2(k) + u) (a van der Corput set, Cranley-
 *                Patterson shifted by u), placed by a seeded permutation: white noise on
 *                the tile, repeated every n pixels. The original behaviour, the default.
 *   interleaved  n angles 2 pi (j + u) / n on a Latin square (Keller and Heidrich,
 *                "Interleaved Sampling", EGWR 2001: n sample sets interleaved on the
 *                screen and recombined by a filter covering them): cell (x, y) holds set
 *                (s(x) + t(y)) mod n, s and t seeded permutations, so every row and every
 *                column of the tile holds every angle once. The tile's row and column means
 *                are then equal, whatever the error is as a function of the angle: nothing
 *                of it is constant along a row or a column, and a separable filter damps
 *                what is left by the product of its x and y responses.
 *   blue_noise   n*n angles 2 pi frac((rank + 1/2) / n^2 + u), placed by a void-and-
 *                cluster rank map of the n x n torus (Ulichney, "The void-and-cluster
 *                method for dither array generation", SPIE 1913, 1993): neighbouring
 *                pixels get far-apart ranks, the map's periodogram is low at low
 *                frequencies, and every one of the n^2 angles occurs once. The filter
 *                removes high-frequency noise and little low-frequency noise is there. */
#include <math.h>
#include <stdlib.h>

#include "halton.h"
#include "common/random.h"
#include "graph/node.h" /* M_PI */

/* Ulichney's energy filter: a Gaussian of sigma 1.5 px in toroidal distance (sec. 3). */
#define VC_SIGMA 1.5

/* Writes angle a (radians) of cell i of an n*n tile as (cos, sin) in the planar layout. */
static void put_angle(float *pattern, int cells, int i, double a)
{
    pattern[i] = (float)cos(a);
    pattern[cells + i] = (float)sin(a);
}

static void tile_pattern(int n, uint64_t *state, float *pattern)
{
    int cells = n * n;
    int perm[SSG_HALTON_MAX_PATTERN * SSG_HALTON_MAX_PATTERN];
    double shift = ssg_random_unit(state);
    ssg_random_permutation(state, perm, cells);
    for (int k = 0; k < cells; k++) {
        double a = ssg_halton_radical_inverse((uint64_t)k, 2) + shift;
        put_angle(pattern, cells, perm[k], 2.0 * M_PI * (a - floor(a)));
    }
}

static void interleaved_pattern(int n, uint64_t *state, float *pattern)
{
    int s[SSG_HALTON_MAX_PATTERN], t[SSG_HALTON_MAX_PATTERN];
    double shift = ssg_random_unit(state);
    ssg_random_permutation(state, s, n);
    ssg_random_permutation(state, t, n);
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            int set = (s[x] + t[y]) % n;
            put_angle(pattern, n * n, y * n + x, 2.0 * M_PI * ((set + shift) / n));
        }
}

/* The void-and-cluster state: the binary pattern, each cell's energy (the Gaussian sum
   over the cells that are 1), and the filter by toroidal offset. */
struct vc {
    int n, cells;
    unsigned char *on;
    double *energy;
    double *gauss; /* cells: exp(-d^2 / (2 sigma^2)), d the toroidal length of offset i */
};

/* Sets cell i to v (0 or 1) and adds or removes its Gaussian from every cell's energy.
   The sums run in a fixed order, so the energies are the same bits on every machine. */
static void vc_set(struct vc *vc, int i, int v)
{
    int n = vc->n, ix = i % n, iy = i / n;
    double sign = v ? 1.0 : -1.0;
    vc->on[i] = (unsigned char)v;
    for (int y = 0; y < n; y++) {
        const double *g = vc->gauss + (size_t)((y - iy + n) % n) * (size_t)n;
        double *e = vc->energy + (size_t)y * (size_t)n;
        /* Offsets x - ix, wrapped: the row in two runs, no modulo per cell. */
        for (int x = ix; x < n; x++)
            e[x] += sign * g[x - ix];
        for (int x = 0; x < ix; x++)
            e[x] += sign * g[x - ix + n];
    }
}

/* The tightest cluster (want = 1: the 1 of highest energy) or the largest void (want = 0:
   the 0 of lowest energy); ties go to the lowest index. */
static int vc_find(const struct vc *vc, int want)
{
    int best = -1;
    for (int i = 0; i < vc->cells; i++) {
        if (vc->on[i] != want)
            continue;
        if (best < 0 || (want ? vc->energy[i] > vc->energy[best]
                              : vc->energy[i] < vc->energy[best]))
            best = i;
    }
    return best;
}

/* Ulichney sec. 3: a seeded random 1 in 10 cells, then the tightest cluster moved to the
   largest void until that move would put it back: the initial binary pattern. */
static void vc_initial(struct vc *vc, uint64_t *state, int ones)
{
    int perm[SSG_HALTON_MAX_PATTERN * SSG_HALTON_MAX_PATTERN];
    ssg_random_permutation(state, perm, vc->cells);
    for (int k = 0; k < ones; k++)
        vc_set(vc, perm[k], 1);
    for (int guard = 0; guard < 4 * vc->cells; guard++) {
        int cluster = vc_find(vc, 1);
        vc_set(vc, cluster, 0);
        int hole = vc_find(vc, 0);
        vc_set(vc, hole, 1);
        if (hole == cluster)
            break;
    }
}

static void vc_state(struct vc *vc, const unsigned char *on)
{
    for (int i = 0; i < vc->cells; i++)
        vc->energy[i] = 0, vc->on[i] = 0;
    for (int i = 0; i < vc->cells; i++)
        if (on[i])
            vc_set(vc, i, 1);
}

/* The rank map: phase 1 removes the initial pattern's tightest clusters (ranks ones-1 ..
   0), phase 2 fills the largest voids up to half the cells, phase 3 the rest, where the
   tightest cluster of 0s is the 0 of lowest energy of the 1s, the same search. */
static void vc_ranks(struct vc *vc, uint64_t *state, int *rank, unsigned char *initial)
{
    int ones = vc->cells / 10 > 0 ? vc->cells / 10 : 1;
    vc_initial(vc, state, ones);
    for (int i = 0; i < vc->cells; i++)
        initial[i] = vc->on[i];
    for (int r = ones - 1; r >= 0; r--) {
        int i = vc_find(vc, 1);
        vc_set(vc, i, 0);
        rank[i] = r;
    }
    vc_state(vc, initial);
    for (int r = ones; r < vc->cells; r++) {
        int i = vc_find(vc, 0);
        vc_set(vc, i, 1);
        rank[i] = r;
    }
}

int ssg_halton_blue_noise_ranks(int n, uint64_t seed, int *rank)
{
    struct vc vc = {.n = n, .cells = n * n};
    unsigned char *initial = malloc((size_t)vc.cells);
    vc.on = calloc((size_t)vc.cells, 1);
    vc.energy = calloc((size_t)vc.cells, sizeof(double));
    vc.gauss = malloc((size_t)vc.cells * sizeof(double));
    int ok = initial && vc.on && vc.energy && vc.gauss;
    if (ok) {
        for (int dy = 0; dy < n; dy++)
            for (int dx = 0; dx < n; dx++) {
                int tx = dx < n - dx ? dx : n - dx, ty = dy < n - dy ? dy : n - dy;
                vc.gauss[dy * n + dx] =
                    exp(-(double)(tx * tx + ty * ty) / (2.0 * VC_SIGMA * VC_SIGMA));
            }
        uint64_t state = seed ^ 0xBB67AE8584CAA73Bull;
        vc_ranks(&vc, &state, rank, initial);
    }
    free(initial), free(vc.on), free(vc.energy), free(vc.gauss);
    return ok;
}

static int blue_noise_pattern(int n, uint64_t seed, uint64_t *state, float *pattern)
{
    int rank[SSG_HALTON_MAX_PATTERN * SSG_HALTON_MAX_PATTERN];
    double shift = ssg_random_unit(state);
    if (!ssg_halton_blue_noise_ranks(n, seed, rank))
        return 0;
    for (int i = 0; i < n * n; i++) {
        double a = ((double)rank[i] + 0.5) / (double)(n * n) + shift;
        put_angle(pattern, n * n, i, 2.0 * M_PI * (a - floor(a)));
    }
    return 1;
}

void ssg_halton_make_places(int n, int count, uint64_t seed, double *place, float *shift)
{
    /* A stream of its own (the next SHA-512 initial word), so the rotation tiles of a
       seed stay as they were; permutations of their own decorrelate the places, the
       shifts and the rotation. */
    uint64_t state = seed ^ 0x3C6EF372FE94F82Bull;
    int s[3][SSG_HALTON_MAX_PATTERN], t[3][SSG_HALTON_MAX_PATTERN];
    for (int m = 0; m < 3; m++) {
        ssg_random_permutation(&state, s[m], n);
        ssg_random_permutation(&state, t[m], n);
    }
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            int q = (s[0][x] + t[0][y]) % n, a = (s[1][x] + t[1][y]) % n;
            int b = (s[2][x] + t[2][y]) % n;
            place[y * n + x] = ((double)q + 0.5) / (double)n;
            shift[y * n + x] = (float)(((int64_t)count * (a * n + b)) / ((int64_t)n * n));
        }
}

int ssg_halton_make_pattern(int kind, int n, uint64_t seed, float *pattern)
{
    /* The tile's stream starts as it always has, so seeds keep their tiles. */
    uint64_t state = seed ^ 0x6A09E667F3BCC909ull;
    switch (kind) {
    case SSG_HALTON_INTERLEAVED: interleaved_pattern(n, &state, pattern); return 1;
    case SSG_HALTON_BLUE_NOISE: return blue_noise_pattern(n, seed, &state, pattern);
    default: tile_pattern(n, &state, pattern); return 1;
    }
}
