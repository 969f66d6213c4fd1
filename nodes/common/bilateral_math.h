/* bilateral_math.h - the small vectorisable e^x and ln(x) that the geometry-aware filters
 * (bilateral_cpu.c, upsample_cpu.c) use to turn a sum of log-weights into one weight. libm's
 * versions do not vectorise without -ffast-math; these are plain float polynomials, the
 * same IEEE operations in every lane, so results do not depend on the vector width.
 * Header-only (static inline); include it after any file-wide optimisation pragma. */
#ifndef SSG_BILATERAL_MATH_H
#define SSG_BILATERAL_MATH_H

#include <math.h>
#include <stdint.h>
#include <string.h>

/* e^x for x <= 0, clamped at -80 (weights below 1.8e-35 are 0 for every purpose and stay
   normal floats). x = k ln2 + g with |g| <= ln2 / 2; e^g by its Taylor series to g^6
   (error below 1.3e-7 relative), 2^k by building the float's exponent bits. */
static inline float exp_neg(float x)
{
    x = x < -80.0f ? -80.0f : x;
    float t = x * 1.44269504088896341f;
    float k = floorf(t + 0.5f);
    float g = (t - k) * 0.693147180559945309f;
    float p = 1.0f + g * (1.0f + g * (0.5f + g * (1.0f / 6.0f + g * (1.0f / 24.0f +
              g * (1.0f / 120.0f + g * (1.0f / 720.0f))))));
    int32_t bits = ((int32_t)k + 127) << 23;
    float scale;
    memcpy(&scale, &bits, sizeof scale);
    return p * scale;
}

/* ln(c) for a positive normal float: c = 2^e m with m in [sqrt(1/2), sqrt(2)), and
   ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.172, by its series to s^9. */
static inline float log_pos(float c)
{
    int32_t bits;
    memcpy(&bits, &c, sizeof bits);
    int32_t e = (bits >> 23) - 127;
    int32_t mbits = (bits & 0x007FFFFF) | 0x3F800000;
    float m;
    memcpy(&m, &mbits, sizeof m);
    int big = m > 1.41421356f;
    m = big ? 0.5f * m : m;
    e = big ? e + 1 : e;
    float s = (m - 1.0f) / (m + 1.0f), s2 = s * s;
    float lm = 2.0f * s * (1.0f + s2 * (1.0f / 3.0f + s2 * (1.0f / 5.0f + s2 * (1.0f / 7.0f +
               s2 * (1.0f / 9.0f)))));
    return (float)e * 0.693147180559945309f + lm;
}

/* How the joint filters compute the normal weight c^p, picked once per run: 0..6 =
   p = 2^mode, by mode squarings of c (the default 16 is 4); SSG_NORMAL_GENERAL = any other
   power, p ln(c) added to the log-weight; SSG_NORMAL_OFF = no normal term (no normals, or
   p = 0). `squarings` is prepare()'s (struct ssg_joint_weights), which the GL side reads
   too. */
enum ssg_normal_mode { SSG_NORMAL_OFF = -1, SSG_NORMAL_GENERAL = 7 };

static inline int ssg_normal_mode(int normal_term, int squarings)
{
    if (!normal_term)
        return SSG_NORMAL_OFF;
    return squarings >= 0 ? squarings : SSG_NORMAL_GENERAL;
}

/* The normal term of one tap with clamped cosine c: the factor c^p by squarings, or 1
   with p ln(c) added to the log-weight *e (mode a constant at each call site). */
static inline __attribute__((always_inline)) float ssg_normal_factor(float c, float p,
                                                                    int mode, float *e)
{
    float wn = 1.0f;
    if (mode == SSG_NORMAL_GENERAL) {
        *e += p * log_pos(c);
    } else {
        wn = c;
        for (int s = 0; s < mode; s++)
            wn *= wn;
    }
    return wn;
}

/* CALL(m) with m the constant of each normal mode: one straight loop a mode. */
#define SSG_NORMAL_MODE_SWITCH(mode, CALL)                                                 \
    switch (mode) {                                                                        \
    case SSG_NORMAL_OFF: CALL(SSG_NORMAL_OFF); break;                                      \
    case 0: CALL(0); break;                                                                \
    case 1: CALL(1); break;                                                                \
    case 2: CALL(2); break;                                                                \
    case 3: CALL(3); break;                                                                \
    case 4: CALL(4); break;                                                                \
    case 5: CALL(5); break;                                                                \
    case 6: CALL(6); break;                                                                \
    default: CALL(SSG_NORMAL_GENERAL); break;                                              \
    }

#endif
