/* vector_loops.h - included first by the CPU kernels whose hot loops must vectorise.
 *
 * SSG_VECTOR_CLONES marks a kernel's hot function: GCC compiles it three times, for
 * x86-64-v4 (AVX-512), x86-64-v3 (AVX2) and the baseline (SSE4), and the loader picks the
 * best one the CPU has. The clones perform the same IEEE operations lane by lane (C11 mode
 * does not contract a * b + c), so every instruction set gives the same bits, as does
 * every thread count. On the development machine the AVX-512 clone takes 0.5x the time of
 * the AVX2 one for bilateral, 0.7x for upsample, 0.8x for ssao, hbao and gtao.
 *
 * A file that defines SSG_VECTOR_FMA before the include lets the clones contract into
 * fused multiply-adds (one rounding instead of two; 0.8x the time again for bilateral and
 * upsample). Only the filters do: their weights feed one normalised sum, where an ulp
 * changes nothing a test or a user can see, while the sampling kernels keep exact
 * identities (an open plane's modulation exactly 1) that fusing one side of a quotient
 * and not the other would break. With it, a filter's bits differ between a CPU with FMA
 * (x86-64-v3 and up) and one without, never between thread counts: every thread runs the
 * same clone and every per-pixel sum keeps its order. The sanitizer builds use the
 * baseline only.
 *
 * The kernels never unmask floating-point exceptions, so float operations cannot trap.
 * Telling GCC so (no-trapping-math) lets it vectorise loops whose comparisons and selects
 * it would otherwise turn into branches; no result changes (no reassociation). It must
 * come before every other include: the shared inline code of nodes/common/sampling.h and
 * nodes/ssdo/ssdo_sampling.h is inlined into the kernels (and their clones) and must be
 * compiled with the same options, or its selects stay branches. The pragma applies to the rest of the including file; fp-contract=fast changes
 * nothing where the target has no FMA (the baseline). */
#ifndef SSG_VECTOR_LOOPS_H
#define SSG_VECTOR_LOOPS_H

#if defined(__GNUC__) && !defined(__clang__) && defined(SSG_VECTOR_FMA)
#pragma GCC optimize("no-trapping-math", "fp-contract=fast")
#elif defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("no-trapping-math")
#endif

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) &&                      \
    !defined(__SANITIZE_ADDRESS__)
#define SSG_VECTOR_CLONES                                                                  \
    __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define SSG_VECTOR_CLONES
#endif

#endif
