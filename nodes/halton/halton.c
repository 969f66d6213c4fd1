/* halton.c - the `halton` node's descriptor, check and prepare: a Halton hemisphere kernel
 * and a tiled rotation pattern, made once in prepare(). Method: README.md in this folder. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "halton.h"
#include "graph/node.h"
#include "common/random.h"
#include "common/sampling.h"

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
    ssg_halton_point_at(p, 0, sample, u);
}

void ssg_halton_point_at(const struct ssg_halton_params *p, int frame, int sample,
                         double u[3])
{
    uint64_t index = (uint64_t)p->offset + (uint64_t)frame * (uint64_t)p->count +
                     (uint64_t)sample;
    /* The stratified length's place in its stratum: the midpoint in frame 0, then the
       golden-ratio sequence from it, so frames fill the strata evenly too. */
    double t = 0.5 + ssg_sampling_frame_turn(frame);
    double mid = t - floor(t);
    u[0] = ssg_halton_radical_inverse(index, p->bases.v[0]);
    u[1] = ssg_halton_radical_inverse(index, p->bases.v[1]);
    if (p->bases.count >= 3) {
        u[2] = ssg_halton_radical_inverse(index, p->bases.v[2]);
    } else if (p->period > 0) {
        int blocks = p->count / p->period;
        int r = sample % p->period, j = sample / p->period;
        u[2] = ((double)r + ((double)j + mid) / blocks) / p->period;
    } else {
        u[2] = ((double)sample + mid) / p->count;
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

/* lengths=shifted moves every length of a pixel by one offset, which keeps each sample in
   its stratum only where the length is linear in a stratified t (README.md, "Lengths"). */
static enum ssg_err check_lengths(const struct ssg_halton_params *p, char *why,
                                  size_t why_len)
{
    if (p->lengths != SSG_HALTON_SHIFTED)
        return SSG_OK;
    if (p->falloff != 1.0f || p->bases.count != 2) {
        snprintf(why, why_len, "lengths=shifted needs falloff=1 and two bases (a length "
                 "linear in a stratified coordinate, so one offset per pixel keeps every "
                 "sample in its stratum); got falloff %g and %d bases", (double)p->falloff,
                 p->bases.count);
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
    if (e == SSG_OK)
        e = check_lengths(p, why, why_len);
    if (e != SSG_OK)
        return e;
    int planes = p->lengths == SSG_HALTON_SHIFTED ? 4 : 2;
    out[0] = (struct ssg_shape){p->count, 1, 3, SSG_T_KERNEL};
    out[1] = (struct ssg_shape){p->pattern, p->pattern, planes, SSG_T_PATTERN};
    return SSG_OK;
}

/* The kernel of frame `frame`: count samples, planar (x plane, y, z). */
static void make_kernel(const struct ssg_halton_params *p, int frame, float *kernel)
{
    for (int i = 0; i < p->count; i++) {
        double u[3], s[3];
        ssg_halton_point_at(p, frame, i, u);
        map_sample(p, u, s);
        for (int ch = 0; ch < 3; ch++)
            kernel[ch * p->count + i] = (float)s[ch];
    }
}

double ssg_halton_length_offset(const struct ssg_halton_params *p, int frame, double place)
{
    double turn = ssg_sampling_frame_turn(frame);
    double to = place + turn, mid = 0.5 + turn; /* mid: ssg_halton_point_at's place */
    to -= floor(to);
    mid -= floor(mid);
    return (1.0 - (double)p->min_scale) * (to - mid) / (double)p->count;
}

/* The third plane of lengths=shifted in frame `frame`: every cell's length offset (the
   fourth, the index shift, is the same in every frame). */
static void make_offsets(const struct ssg_halton_consts *c, int frame, float *offset)
{
    for (int i = 0; i < c->n * c->n; i++)
        offset[i] = (float)ssg_halton_length_offset(&c->p, frame, c->place[i]);
}

void ssg_halton_frame(const struct ssg_halton_consts *c, int frame, float *kernel,
                      float *pattern)
{
    size_t cells = (size_t)c->n * (size_t)c->n;
    if (frame == 0) { /* the single-frame bytes, -0 included */
        memcpy(kernel, c->kernel, sizeof(float) * 3 * (size_t)c->count);
        memcpy(pattern, c->pattern, sizeof(float) * (size_t)c->planes * cells);
        return;
    }
    if (c->planes == 4) {
        make_offsets(c, frame, pattern + 2 * cells);
        memcpy(pattern + 3 * cells, c->pattern + 3 * cells, sizeof(float) * cells);
    }
    make_kernel(&c->p, frame, kernel);
    /* Every pixel's angle advances by the same golden-ratio turn: each pixel's angles
       over frames are then a Kronecker sequence, and the tile keeps its layout. */
    double a = 2.0 * M_PI * ssg_sampling_frame_turn(frame), ca = cos(a), sa = sin(a);
    for (size_t i = 0; i < cells; i++) {
        double co = c->pattern[i], si = c->pattern[cells + i];
        pattern[i] = (float)(co * ca - si * sa);
        pattern[cells + i] = (float)(si * ca + co * sa);
    }
}

static enum ssg_err prepare(const struct ssg_node_ctx *ctx, const void *params, void *consts)
{
    const struct ssg_halton_params *p = params;
    struct ssg_halton_consts *c = consts;
    c->p = *p;
    c->count = p->count;
    c->n = p->pattern;
    c->planes = p->lengths == SSG_HALTON_SHIFTED ? 4 : 2;
    make_kernel(p, 0, c->kernel);
    uint64_t seed = ctx->frame ? ctx->frame->seed : 1;
    if (!ssg_halton_make_pattern(p->rotations, p->pattern, seed, c->pattern))
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the blue-noise tile");
    if (c->planes == 4) {
        size_t cells = (size_t)c->n * (size_t)c->n;
        ssg_halton_make_places(p->pattern, p->count, seed, c->place, c->pattern + 3 * cells);
        make_offsets(c, 0, c->pattern + 2 * cells);
    }
    return SSG_OK;
}

static const char *const ssg_halton_mapping_choices[] = {"cosine", "uniform", NULL};
static const char *const ssg_halton_rotations_choices[] = {"tile", "interleaved", "blue_noise",
                                                           NULL};
static const char *const ssg_halton_lengths_choices[] = {"shared", "shifted", NULL};
SSG_PARAMS_TABLE(params, ssg_halton_params, SSG_HALTON_PARAMS);

SSG_PORT_TABLE(outputs, SSG_HALTON_OUT);

const struct ssg_node_desc ssg_node_halton = {
    .name = "halton",
    .summary = "Halton hemisphere sample kernel and per-pixel rotation tile",
    .method = "Szentandrasi, Modern Methods of Realistic Lighting in Real Time, sec. 4.2, "
              "eq. 5-8 (Halton sequence, period property)",
    SSG_NODE_OUTPUTS(outputs),
    SSG_NODE_PARAMS(params, struct ssg_halton_params),
    .consts_size = sizeof(struct ssg_halton_consts),
    .check = check,
    /* kernels and rotations from the parameters and the seed, turned every frame
       (docs/time.md) */
    .reads = SSG_READS_INPUTS | SSG_READS_FRAME,
    .prepare = prepare,
    .run_cpu = ssg_halton_run_cpu,
    .run_gl = ssg_halton_run_gl,
    .parity = {.max = 0, .mean = 0}, /* GL copies prepare()'s bytes: exact (test_gl_misc.c) */
};
