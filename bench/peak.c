/* peak.c - the machine's measured limits, for the profile's achieved fractions (`ssgraph
 * run --frames N` prints each node's GB/s and GFLOP/s against them). Measures, on every
 * thread OpenMP gives (or OMP_NUM_THREADS):
 *   - vector FMA throughput: independent chains of fused multiply-adds, AVX-512 (16 lanes)
 *     where the CPU has it, and AVX2 (8 lanes); a fused multiply-add counts 2 flops;
 *   - vector throughput without FMA (a multiply and an add a lane, what the kernels that
 *     keep exact bits issue): the widest vectors the CPU has;
 *   - memory bandwidth: the STREAM triad a = b + s c over arrays far larger than the caches,
 *     12 bytes moved an element as STREAM counts them.
 * Best of several runs each. Prints a line per result and writes them as JSON to the cache
 * the CLI reads: $SSGRAPH_PEAK, else $XDG_CACHE_HOME/ssgraph/peak.json, else
 * ~/.cache/ssgraph/peak.json. `peak --no-save` only prints; `peak --quick` measures with
 * small arrays and few rounds (a test's check that it works, not a measurement). */
#include <errno.h>
#include <immintrin.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "peak.h" /* cli/: the cache's path, shared with the profile */

enum { CHAINS = 12, ITERS = 20000000, RUNS = 5 };

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* One kernel: each thread runs CHAINS independent chains (enough to cover the latency of
   both vector ports) of acc = acc m + a for `iters` rounds, fused (FMA) or as a multiply
   and an add; the sum goes to `sink` so nothing is optimised away. LANES floats a vector;
   every round counts 2 flops a lane and chain. */
#define PEAK_KERNEL(name, isa, vec, LANES, set1, step, add, store)                          \
    __attribute__((target(isa))) static double name(long iters, float *sink)                \
    {                                                                                      \
        vec acc[CHAINS], m = set1(0.999999f), a = set1(1e-7f);                             \
        float lanes[LANES];                                                                \
        for (int c = 0; c < CHAINS; c++)                                                   \
            acc[c] = set1((float)c);                                                       \
        for (long i = 0; i < iters; i++)                                                   \
            for (int c = 0; c < CHAINS; c++)                                               \
                acc[c] = step(acc[c], m, a);                                               \
        for (int c = 1; c < CHAINS; c++)                                                   \
            acc[0] = add(acc[0], acc[c]);                                                  \
        store(lanes, acc[0]);                                                              \
        for (int l = 0; l < LANES; l++)                                                    \
            *sink += lanes[l];                                                             \
        return 2.0 * LANES * CHAINS * (double)iters;                                       \
    }

#define MULADD512(x, m, a) _mm512_add_ps(_mm512_mul_ps(x, m), a)
#define MULADD256(x, m, a) _mm256_add_ps(_mm256_mul_ps(x, m), a)
PEAK_KERNEL(fma512, "avx512f", __m512, 16, _mm512_set1_ps, _mm512_fmadd_ps, _mm512_add_ps,
            _mm512_storeu_ps)
PEAK_KERNEL(fma256, "avx2,fma", __m256, 8, _mm256_set1_ps, _mm256_fmadd_ps, _mm256_add_ps,
            _mm256_storeu_ps)
PEAK_KERNEL(muladd512, "avx512f", __m512, 16, _mm512_set1_ps, MULADD512, _mm512_add_ps,
            _mm512_storeu_ps)
PEAK_KERNEL(muladd256, "avx2", __m256, 8, _mm256_set1_ps, MULADD256, _mm256_add_ps,
            _mm256_storeu_ps)

typedef double (*kernel_fn)(long iters, float *sink);

/* GFLOP/s of fn on every thread at once, best of RUNS. */
static double gflops(kernel_fn fn, long iters)
{
    double best = 0.0;
    for (int r = 0; r < RUNS; r++) {
        double flops = 0.0, t0 = now();
        float sink = 0.0f;
#pragma omp parallel reduction(+ : flops, sink)
        flops += fn(iters, &sink);
        double rate = flops / (now() - t0) * 1e-9;
        if (sink == 12345.0f) /* never: keeps the result alive */
            puts("");
        best = rate > best ? rate : best;
    }
    return best;
}

/* STREAM triad GB/s over n floats per array, best of RUNS. */
static double triad(size_t n)
{
    float *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b), *c = malloc(n * sizeof *c);
    if (!a || !b || !c) {
        free(a), free(b), free(c);
        return 0.0;
    }
#pragma omp parallel for schedule(static)
    for (size_t i = 0; i < n; i++)
        a[i] = 0.0f, b[i] = 1.0f, c[i] = 2.0f;
    double best = 0.0;
    for (int r = 0; r < RUNS; r++) {
        double t0 = now();
#pragma omp parallel for schedule(static)
        for (size_t i = 0; i < n; i++)
            a[i] = b[i] + 3.0f * c[i];
        double rate = 12.0 * (double)n / (now() - t0) * 1e-9;
        best = rate > best ? rate : best;
    }
    if (a[n / 2] != 7.0f)
        fprintf(stderr, "peak: triad gave %g, expected 7\n", a[n / 2]);
    free(a), free(b), free(c);
    return best;
}

/* mkdir -p of the directories above path. */
static void make_parents(const char *path)
{
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", path);
    for (char *p = dir + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            mkdir(dir, 0755);
            *p = '/';
        }
}

int main(int argc, char **argv)
{
    int save = 1, quick = 0;
    for (int a = 1; a < argc; a++) {
        if (!strcmp(argv[a], "--no-save")) {
            save = 0;
        } else if (!strcmp(argv[a], "--quick")) {
            quick = 1;
        } else {
            fprintf(stderr, "usage: peak [--no-save] [--quick]\n");
            return 2;
        }
    }
    int has512 = __builtin_cpu_supports("avx512f"), has256 = __builtin_cpu_supports("avx2") &&
                                                            __builtin_cpu_supports("fma");
    long iters = quick ? ITERS / 400 : ITERS / 4;
    double f512 = has512 ? gflops(fma512, iters) : 0.0;
    double f256 = has256 ? gflops(fma256, iters) : 0.0;
    double m512 = has512 ? gflops(muladd512, iters) : 0.0;
    double m256 = has256 ? gflops(muladd256, iters) : 0.0;
    double gbps = triad(quick ? (size_t)1 << 20 : (size_t)64 << 20); /* 3 x 256 MB */
    double fpeak = f512 > f256 ? f512 : f256, mpeak = m512 > m256 ? m512 : m256;
    int threads = omp_get_max_threads();
    printf("threads                 %d\n", threads);
    printf("AVX-512 FMA GFLOP/s     %.1f\n", f512);
    printf("AVX2 FMA GFLOP/s        %.1f\n", f256);
    printf("mul + add GFLOP/s       %.1f (AVX-512 %.1f, AVX2 %.1f)\n", mpeak, m512, m256);
    printf("memory GB/s (triad)     %.1f\n", gbps);
    char path[4096];
    if (!save || !ssg_peak_path(path, sizeof path))
        return 0;
    make_parents(path);
    /* a temporary next to it, renamed over it once complete: never a half-written cache */
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp-%d", path, (int)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) {
        fprintf(stderr, "peak: cannot write %s: %s\n", tmp, strerror(errno));
        return 1;
    }
    fprintf(f, "{\"threads\": %d, \"gflops\": %.3f, \"gflops_avx512_fma\": %.3f, "
               "\"gflops_avx2_fma\": %.3f, \"gflops_mul_add\": %.3f, \"gbps\": %.3f}\n",
            threads, fpeak, f512, f256, mpeak, gbps);
    if (fclose(f) != 0 || rename(tmp, path) != 0) {
        fprintf(stderr, "peak: cannot write %s: %s\n", path, strerror(errno));
        remove(tmp);
        return 1;
    }
    printf("saved to %s\n", path);
    return 0;
}
