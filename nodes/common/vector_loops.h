/* vector_loops.h - included first by the CPU kernels whose hot loops must vectorise.
 *
 * The kernels never unmask floating-point exceptions, so float operations cannot trap.
 * Telling GCC so (no-trapping-math) lets it vectorise loops whose comparisons and selects
 * it would otherwise turn into branches; no result changes (no reassociation, no
 * contraction). It must come before every other include: the shared inline code of
 * nodes/common/sampling.h and nodes/ssdo/ssdo_sampling.h is inlined into the kernels (and
 * their AVX2 clones) and must be compiled with the same options, or its selects stay
 * branches. The pragma applies to the rest of the including file. */
#ifndef SSG_VECTOR_LOOPS_H
#define SSG_VECTOR_LOOPS_H

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC optimize("no-trapping-math")
#endif

#endif
