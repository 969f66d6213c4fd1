/* check.h - the whole test library: CHECK, CHECK_EQ, CHECK_NEAR print the expression, the
 * values and file:line and count failures; main returns check_report(). */
#ifndef SSG_CHECK_H
#define SSG_CHECK_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Where a test writes scratch files when ctest gave it no SSG_TMP folder. */
#define CHECK_TMP_ROOT "/tmp"

static int check_failures;
static int check_count;

#define CHECK(cond)                                                                    \
    do {                                                                               \
        check_count++;                                                                 \
        if (!(cond)) {                                                                 \
            check_failures++;                                                          \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);   \
        }                                                                              \
    } while (0)

#define CHECK_EQ(a, b)                                                                 \
    do {                                                                               \
        long long va_ = (long long)(a), vb_ = (long long)(b);                          \
        check_count++;                                                                 \
        if (va_ != vb_) {                                                              \
            check_failures++;                                                          \
            fprintf(stderr, "%s:%d: CHECK_EQ failed: %s == %s (%lld vs %lld)\n",       \
                    __FILE__, __LINE__, #a, #b, va_, vb_);                             \
        }                                                                              \
    } while (0)

#define CHECK_NEAR(a, b, tol)                                                          \
    do {                                                                               \
        double va_ = (double)(a), vb_ = (double)(b), vt_ = (double)(tol);              \
        check_count++;                                                                 \
        if (!(fabs(va_ - vb_) <= vt_)) {                                               \
            check_failures++;                                                          \
            fprintf(stderr, "%s:%d: CHECK_NEAR failed: %s ~ %s (%.6g vs %.6g, tol %.3g)\n", \
                    __FILE__, __LINE__, #a, #b, va_, vb_, vt_);                        \
        }                                                                              \
    } while (0)

static inline int check_report(void)
{
    fprintf(stderr, "%d checks, %d failed\n", check_count, check_failures);
    return check_failures ? 1 : 0;
}

#endif
