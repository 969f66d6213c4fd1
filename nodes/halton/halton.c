/* halton.c - the `halton` node: a hemisphere sample kernel from the Halton sequence and a
 * tiled per-pixel rotation pattern, made once in prepare() so every backend reads the
 * same bytes.
 *
 * Method: Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", section 4.2.
 * Sample i uses the Halton point x_{offset+i} (eq. 7) built from radical inverses (eq. 5,
 * 6) in pairwise-coprime bases: the first coordinate picks the elevation, the second the
 * azimuth, an optional third the length. Quasi-Monte Carlo points avoid the clumping of
 * random ones, which section 4.2 names as the reason for using them. Lengths follow
 * lerp(min_scale, 1, t^falloff), packing samples near the pixel so that close occluders
 * weigh more (Belonogov section 4.6 / figure 4.11, after Chapman's SSAO tutorial).
 *
 * Period (eq. 8): Phi_b(i) and Phi_b(i + m N_g) differ by less than b^-k when
 * N_g = l b^k, because i and i + m N_g share their k lowest base-b digits, which become
 * the k leading digits of Phi_b. With period = N_g > 0 the kernel is count / N_g blocks of
 * N_g consecutive indices; sample r of every block lies in the same cell of side b^-k_b
 * (k_b = ssg_halton_period_digits(N_g, b)) as sample r of the first block, and every block
 * on its own meets each cell of that grid equally often (N_g consecutive integers cover
 * every residue modulo b^k_b, jointly over the bases since they are coprime). So any
 * prefix of whole blocks is itself a quasi-uniform kernel: the paper's "10, 20, ..., k*10
 * sampling points" with period 10 and bases 2, 5. check() therefore requires N_g to be a
 * multiple of every base (else eq. 8 bounds nothing) and count to be a multiple of N_g.
 * Without a third base the length coordinate is stratified: (i + 0.5) / count, or, with a
 * period, (r + (j + 0.5) / K) / N_g for sample r of block j of K, which keeps the blocks
 * alike and still gives the same set of values as (i + 0.5) / count overall.
 *
 * The rotation tile (rotations = tile, the default) holds n*n angles 2*pi*frac(Phi_2(k) + u),
 * k = 0..n*n-1, a van der Corput set shifted by u (Cranley-Patterson rotation) and placed
 * on the tile by a permutation; u and the permutation come from the frame seed, so the
 * pattern is deterministic per seed and changes with it. rotations = interleaved (a Latin
 * square of n angles) and blue_noise (a void-and-cluster rank map) leave less structure
 * after the filter: halton_pattern.c says why and how. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "halton.h"
#include "graph/node.h"
#include "common/random.h"

double ssg_halton_radical_inverse(uint64_t i, int base)
{
    /* Mirror the digits into an integer numerator over base^digits and divide once, so
       the result is the correctly rounded value of eq. 6 rather than a sum of rounded
       powers. */
    uint64_t b = (uint64_t)base, num = 0, den = 1;
    while (i > 0) {
        num = num * b + i % b;
        den *= b;
        i /= b;
    }
    return (double)num / (double)den;
}

int ssg_halton_period_digits(int period, int base)
{
    int k = 0;
    if (period <= 0 || base < 2)
        return 0;
    while (period % base == 0) {
        period /= base;
        k++;
    }
    return k;
}

void ssg_halton_point(const struct ssg_halton_params *p, int sample, double u[3])
{
    uint64_t index = (uint64_t)p->offset + (uint64_t)sample;
    u[0] = ssg_halton_radical_inverse(index, p->bases.v[0]);
    u[1] = ssg_halton_radical_inverse(index, p->bases.v[1]);
    if (p->bases.count >= 3) {
        u[2] = ssg_halton_radical_inverse(index, p->bases.v[2]);
    } else if (p->period > 0) {
        int blocks = p->count / p->period;
        int r = sample % p->period, j = sample / p->period;
        u[2] = ((double)r + ((double)j + 0.5) / blocks) / p->period;
    } else {
        u[2] = ((double)sample + 0.5) / p->count;
    }
}

/* Unit-cube point -> tangent-space offset inside the unit hemisphere around +z. */
static void map_sample(const struct ssg_halton_params *p, const double u[3], double s[3])
{
    double z, rad, phi = 2.0 * M_PI * u[1];
    if (p->mapping == SSG_HALTON_COSINE) {
        /* Malley: uniform on the disk, lifted to the hemisphere -> pdf cos(theta)/pi. */
        rad = sqrt(u[0]);
        z = sqrt(fmax(0.0, 1.0 - u[0]));
    } else {
        /* z uniform on (0, 1] -> uniform in solid angle (Archimedes). */
        z = 1.0 - u[0];
        rad = sqrt(fmax(0.0, 1.0 - z * z));
    }
    double t = pow(u[2], p->falloff);
    double len = p->min_scale + (1.0 - p->min_scale) * t;
    s[0] = len * rad * cos(phi);
    s[1] = len * rad * sin(phi);
    s[2] = len * z;
}

static int is_prime(int v)
{
    if (v < 2)
        return 0;
    for (int d = 2; d * d <= v; d++)
        if (v % d == 0)
            return 0;
    return 1;
}

static enum ssg_err check_bases(const struct ssg_halton_params *p, char *why, size_t why_len)
{
    for (int i = 0; i < p->bases.count; i++) {
        if (!is_prime(p->bases.v[i])) {
            snprintf(why, why_len, "bases must be primes (eq. 7 needs pairwise coprime "
                     "bases); %d is not prime", p->bases.v[i]);
            return SSG_E_VALUE;
        }
        for (int j = 0; j < i; j++)
            if (p->bases.v[j] == p->bases.v[i]) {
                snprintf(why, why_len, "bases must be pairwise coprime; %d appears twice",
                         p->bases.v[i]);
                return SSG_E_VALUE;
            }
    }
    return SSG_OK;
}

static enum ssg_err check_period(const struct ssg_halton_params *p, char *why, size_t why_len)
{
    if (p->period <= 0)
        return SSG_OK;
    for (int i = 0; i < p->bases.count; i++)
        if (p->period % p->bases.v[i] != 0) {
            snprintf(why, why_len, "period %d must be a multiple of every base (eq. 8: "
                     "N_g = l*b^k with k >= 1); base %d does not divide it", p->period,
                     p->bases.v[i]);
            return SSG_E_VALUE;
        }
    if (p->count % p->period != 0) {
        snprintf(why, why_len, "count %d must be a multiple of period %d (the kernel is "
                 "whole periods)", p->count, p->period);
        return SSG_E_VALUE;
    }
    return SSG_OK;
}

static enum ssg_err check(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len)
{
    const struct ssg_halton_params *p = params;
    enum ssg_err e = check_bases(p, why, why_len);
    if (e == SSG_OK)
        e = check_period(p, why, why_len);
    if (e != SSG_OK)
        return e;
    out[0] = (struct ssg_shape){p->count, 1, 3, SSG_T_KERNEL};
    out[1] = (struct ssg_shape){p->pattern, p->pattern, 2, SSG_T_PATTERN};
    return SSG_OK;
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_halton_params *p = params;
    struct ssg_halton_consts *c = consts;
    char why[256];
    struct ssg_shape shapes[2];
    /* prepare() may be reached without check() (a hand-built run): never index out of
       the fixed arrays. */
    if (p->count < 1 || p->count > SSG_HALTON_MAX_COUNT || p->pattern < 1 ||
        p->pattern > SSG_HALTON_MAX_PATTERN || p->bases.count < 2 || p->bases.count > 3 ||
        check(params, ctx->frame, NULL, shapes, why, sizeof why) != SSG_OK) {
        return ssg_node_fail(ctx, SSG_E_VALUE, "invalid parameters");
    }
    c->count = p->count;
    c->n = p->pattern;
    for (int i = 0; i < p->count; i++) {
        double u[3], s[3];
        ssg_halton_point(p, i, u);
        map_sample(p, u, s);
        for (int ch = 0; ch < 3; ch++)
            c->kernel[ch * p->count + i] = (float)s[ch];
    }
    if (!ssg_halton_make_pattern(p->rotations, p->pattern, ctx->frame ? ctx->frame->seed : 1,
                                 c->pattern))
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the blue-noise tile");
    return SSG_OK;
}

static const char *const mapping_choices[] = {"cosine", "uniform", NULL};
static const char *const rotations_choices[] = {"tile", "interleaved", "blue_noise", NULL};

static const struct ssg_param_desc params[] = {
    {.name = "count", SSG_FIELD_INT(struct ssg_halton_params, count), .def = 16, .min = 1,
     .max = SSG_HALTON_MAX_COUNT, .unit = "samples", .help = "kernel samples"},
    {.name = "bases", SSG_FIELD_INTS(struct ssg_halton_params, bases), .def_ints = {2, 3},
     .def_ints_count = 2,
     .min_count = 2,
     .max_count = 3,
     .min = 2,
     .max = 997,
     .help = "distinct primes: elevation, azimuth, optional length (eq. 7)"},
    {.name = "offset", SSG_FIELD_INT(struct ssg_halton_params, offset), .def = 1, .min = 0,
     .max = 1000000000, .help = "first sequence index (0 is the point 0,0,0)"},
    {.name = "period", SSG_FIELD_INT(struct ssg_halton_params, period), .def = 0, .min = 0,
     .max = SSG_HALTON_MAX_COUNT, .unit = "samples",
     .help = "eq. 8 period N_g: blocks of N_g samples alike, prefixes quasi-uniform; 0 = off"},
    {.name = "mapping", SSG_FIELD_ENUM(struct ssg_halton_params, mapping),
     .def = SSG_HALTON_COSINE, .choices = mapping_choices,
     .help = "direction density over the hemisphere"},
    {.name = "falloff", SSG_FIELD_FLOAT(struct ssg_halton_params, falloff), .def = 2,
     .min = 0.01, .max = 16,
     .help = "length = lerp(min_scale, 1, t^falloff): > 1 packs samples near the centre"},
    {.name = "min_scale", SSG_FIELD_FLOAT(struct ssg_halton_params, min_scale), .def = 0.1,
     .min = 0, .max = 1, .help = "shortest sample length as a fraction of the radius"},
    {.name = "pattern", SSG_FIELD_INT(struct ssg_halton_params, pattern), .def = 4, .min = 1,
     .max = SSG_HALTON_MAX_PATTERN, .unit = "px", .help = "side of the tiled rotation pattern"},
    {.name = "rotations", SSG_FIELD_ENUM(struct ssg_halton_params, rotations),
     .def = SSG_HALTON_TILE, .choices = rotations_choices,
     .help = "tile layout: tile = n*n angles, white; interleaved = n angles, every row and "
             "column holds each once; blue_noise = n*n angles, void-and-cluster (n = 64)"},
};

static const struct ssg_port_desc outputs[] = {
    [SSG_HALTON_OUT_SAMPLES] = {.name = "samples", .types = SSG_T_KERNEL,
     .doc = "count x 1 tangent-space offsets in the unit hemisphere around +z"},
    [SSG_HALTON_OUT_ROTATION] = {.name = "rotation", .types = SSG_T_PATTERN,
     .doc = "n x n tile of (cos, sin) of a rotation about the normal"},
};
_Static_assert(SSG_COUNT(outputs) == SSG_HALTON_OUTPUTS, "one entry a port enumerator");

const struct ssg_node_desc ssg_node_halton = {
    .name = "halton",
    .summary = "Halton hemisphere sample kernel and per-pixel rotation tile",
    .method = "Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 4.2, "
              "eq. 5-8 (Halton sequence, period property)",
    .doc = "Makes the sample kernel for ssao: sample i is the Halton point of index "
           "offset+i (eq. 7) mapped to the hemisphere (cosine or uniform) and scaled to "
           "length lerp(min_scale, 1, t^falloff). With period > 0 (eq. 8) the kernel is "
           "count/period alike blocks and every prefix of whole blocks is quasi-uniform. "
           "The rotation tile (rotations=tile) holds a seed-shifted van der Corput set of "
           "angles, placed by a seeded permutation; it changes with the frame seed. "
           "rotations=interleaved: n angles 2 pi (j + u) / n on a seeded Latin square "
           "(Keller and Heidrich 2001), every row and column of the tile holds each once, "
           "so its row and column means are equal and a separable filter leaves no streaks "
           "from it. rotations=blue_noise: the n*n angles placed by a void-and-cluster rank "
           "map of the n x n torus (Ulichney 1993, Gaussian sigma 1.5, seeded initial "
           "pattern, made in prepare), low in energy at low frequencies, so that the filter "
           "removes what noise there is; use pattern=64.",
    SSG_NODE_OUTPUTS(outputs),
    SSG_NODE_PARAMS(params, struct ssg_halton_params),
    .consts_size = sizeof(struct ssg_halton_consts),
    .check = check,
    .prepare = prepare,
    .run_cpu = ssg_halton_run_cpu,
    .run_gl = ssg_halton_run_gl,
};
