/* flip.c - FLIP error maps (flip.h; method and departures in README.md).
 *
 * LDR-FLIP, HPG 2020 (the names below are the paper's; its equation numbers are not
 * cited, as they were not checked against the published text):
 *   colour: opponent space YyCxCz, each channel filtered with its contrast
 *   sensitivity function as a sum of Gaussians sized by pixels per degree,
 *   clamped to the linear sRGB cube, Hunt-adjusted L*a*b*, the HyAB distance,
 *   raised to qc = 0.7 and mapped to [0, 1] with pc = 0.4, pt = 0.95 against the largest
 *   such distance in the gamut, green against blue;
 *   features: edges and points of the achromatic channel by the first and second
 *   derivative of a Gaussian of deviation 0.5 * 0.082 degrees, their magnitude
 *   difference scaled by 1 / sqrt(2) and raised to qf = 0.5;
 *   the pixel's error dEc ^ (1 - dEf).
 * HDR-FLIP, EG 2021: the images exposure-compensated over the reference's range (start
 * exposure from its largest luminance, stop from its median, both through the tone
 * curve's inverse at 0.85), tone mapped with the ACES fit, LDR-FLIP at each of
 * max(2, ceil(stop - start)) exposures, the per-pixel maximum.
 *
 * Our inputs are linear. The paper's LDR input is sRGB-encoded and its first step decodes
 * it; encoding clamp(x, 0, 1) and decoding it again is the identity, so the linear values
 * enter directly (no rounding from the round trip).
 *
 * Layout: a pass is one function over row bands (ssg_parallel_rows). Per image: to the
 * opponent planes; seven horizontal 1D filters; the matching vertical ones, which end in
 * the pixel's Hunt-adjusted L*a*b* and feature magnitudes; then one pass combines the two
 * images into the map. Borders replicate the edge pixel (the paper's code filters so). */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "flip.h"
#include "graph/node.h"

enum {
    ROWS_PER_BAND = 16,
    MAX_R = 160, /* radii at SSG_FLIP_MAX_PPD: CSF 136, features 123 */
    MAX_TAPS = 2 * MAX_R + 1,
    /* The horizontal passes' outputs, in this order. */
    H_Y = 0, H_CX, H_CZ1, H_CZ2, H_G, H_D1, H_D2, HORIZONTAL,
    /* Per image after the vertical passes: Hunt-adjusted L, a, b; edge and point. */
    O_L = 0, O_A, O_B, O_EDGE, O_POINT, OUTS
};

static const float QC = 0.7f, QF = 0.5f, PC = 0.4f, PT = 0.95f;

/* Linear sRGB to CIE XYZ (D65), each row divided by its sum so that white is (1, 1, 1):
   the XYZ / (Xn, Yn, Zn) that YyCxCz and L*a*b* both start from. Rows from the exact
   fractions the paper's code uses (sRGB primaries, D65). */
static const double RGB2XYZN[3][3] = {
    {10135552.0 / 23359437.0, 8788810.0 / 23359437.0, 4435075.0 / 23359437.0},
    {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
    {1425312.0 / 80288307.0, 8788810.0 / 80288307.0, 70074185.0 / 80288307.0}};

/* The filters, made once per call from ppd. */
struct kernels {
    int rc, rf;             /* CSF and feature radii, px */
    float y[MAX_TAPS];      /* achromatic CSF, 1D, sums to 1 (the 2D one is y (x) y) */
    float cx[MAX_TAPS];     /* red-green CSF, 1D, sums to 1 */
    float cz1[MAX_TAPS];    /* blue-yellow CSF: 2D = wz1 cz1 (x) cz1 + wz2 cz2 (x) cz2 */
    float cz2[MAX_TAPS];
    float wz1, wz2;         /* their shares, summing to 1 */
    float g[MAX_TAPS];      /* feature Gaussian, sums to 1 */
    float d1[MAX_TAPS];     /* its first derivative: positive taps sum to 1, negative -1 */
    float d2[MAX_TAPS];     /* its second derivative, normalised the same way */
    float cmax;             /* HyAB(green, blue) ^ qc in Hunt-adjusted L*a*b* */
};

/* A 1D Gaussian exp(-pi^2 (x / ppd)^2 / b) over [-r, r] (one term of the CSF); returns its
   sum and leaves it normalised. */
static double csf_gauss(float *k, int r, double ppd, double b)
{
    double e[MAX_TAPS], s = 0;
    for (int i = -r; i <= r; i++) {
        double x = i / ppd;
        e[i + r] = exp(-M_PI * M_PI * x * x / b);
        s += e[i + r];
    }
    for (int i = 0; i <= 2 * r; i++)
        k[i] = (float)(e[i] / s);
    return s;
}

/* The CSF: S(x) = a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi / b2) exp(...), in 2D
   normalised to unit sum. Each term is separable: term i sums to ai sqrt(pi / bi) Si^2
   over the square (Si its 1D sum), which gives the two terms' shares. The radius covers
   three deviations of the widest term of all three channels (b = 0.04), as in the paper. */
static void csf_kernels(struct kernels *k, double ppd)
{
    k->rc = (int)ceil(3.0 * sqrt(0.04 / (2.0 * M_PI * M_PI)) * ppd);
    csf_gauss(k->y, k->rc, ppd, 0.0047);
    csf_gauss(k->cx, k->rc, ppd, 0.0053);
    double s1 = csf_gauss(k->cz1, k->rc, ppd, 0.04);
    double s2 = csf_gauss(k->cz2, k->rc, ppd, 0.025);
    double t1 = 34.1 * sqrt(M_PI / 0.04) * s1 * s1, t2 = 13.5 * sqrt(M_PI / 0.025) * s2 * s2;
    k->wz1 = (float)(t1 / (t1 + t2));
    k->wz2 = (float)(t2 / (t1 + t2));
}

/* Scales positive taps to sum 1 and negative to -1 (the paper's
   normalisation: a uniform area gives 0). */
static void normalise_signed(const double *v, float *k, int n)
{
    double pos = 0, neg = 0;
    for (int i = 0; i < n; i++)
        v[i] > 0 ? (pos += v[i]) : (neg -= v[i]);
    for (int i = 0; i < n; i++)
        k[i] = (float)(v[i] > 0 ? v[i] / pos : v[i] < 0 ? v[i] / neg : 0.0);
}

/* The feature detectors: the 2D kernels are G'(x) g(y) and G''(x) g(y) (and
   transposed). Their sign depends on x alone, so normalising the 2D kernel's positive
   and negative parts is normalising the 1D derivative's and the 1D Gaussian separately. */
static void feature_kernels(struct kernels *k, double ppd)
{
    double sd = 0.5 * 0.082 * ppd, e[MAX_TAPS], d1[MAX_TAPS], d2[MAX_TAPS], s = 0;
    int r = k->rf = (int)ceil(3.0 * sd);
    for (int i = -r; i <= r; i++) {
        e[i + r] = exp(-(double)i * i / (2.0 * sd * sd));
        d1[i + r] = -i * e[i + r];
        d2[i + r] = ((double)i * i / (sd * sd) - 1.0) * e[i + r];
        s += e[i + r];
    }
    for (int i = 0; i <= 2 * r; i++)
        k->g[i] = (float)(e[i] / s);
    normalise_signed(d1, k->d1, 2 * r + 1);
    normalise_signed(d2, k->d2, 2 * r + 1);
}

/* t^(1/3) for t in (0.008, 2]: a guess from the exponent bits (within 4 %), then two
   Halley steps y (y^3 + 2t) / (2y^3 + t), each cubing the relative error: ~1e-7, float's
   own precision. libm's cbrtf is a call per value and was a third of FLIP's time; this
   vectorises. Plain IEEE operations: the same bits on every CPU and thread. */
static inline float cube_root(float t)
{
    union { float f; uint32_t u; } v = {.f = t};
    v.u = v.u / 3u + 709921077u; /* 709921077 = (127 - 127 / 3) << 23, tuned (Kahan) */
    float y = v.f;
    for (int i = 0; i < 2; i++) {
        float y3 = y * y * y;
        y = y * (y3 + 2.0f * t) / (2.0f * y3 + t);
    }
    return y;
}

static inline float lab_f(float t)
{
    const float d = 6.0f / 29.0f;
    return t > d * d * d ? cube_root(t) : t / (3.0f * d * d) + 4.0f / 29.0f;
}

/* Linear RGB in [0, 1] to Hunt-adjusted L*a*b* (Hunt: a and b scaled by 0.01 L). */
static inline void hunt_lab(float r, float g, float b, float lab[3])
{
    float x = lab_f((float)RGB2XYZN[0][0] * r + (float)RGB2XYZN[0][1] * g +
                    (float)RGB2XYZN[0][2] * b);
    float y = lab_f((float)RGB2XYZN[1][0] * r + (float)RGB2XYZN[1][1] * g +
                    (float)RGB2XYZN[1][2] * b);
    float z = lab_f((float)RGB2XYZN[2][0] * r + (float)RGB2XYZN[2][1] * g +
                    (float)RGB2XYZN[2][2] * b);
    float l = 116.0f * y - 16.0f;
    lab[0] = l;
    lab[1] = 0.01f * l * 500.0f * (x - y);
    lab[2] = 0.01f * l * 200.0f * (y - z);
}

/* HyAB: |dL| + ||(da, db)||. Symmetric in its arguments bit for bit. */
static inline float hyab(const float p[3], const float q[3])
{
    float dl = p[0] - q[0], da = p[1] - q[1], db = p[2] - q[2];
    return fabsf(dl) + sqrtf(da * da + db * db);
}

static void make_kernels(struct kernels *k, double ppd)
{
    csf_kernels(k, ppd);
    feature_kernels(k, ppd);
    float green[3], blue[3];
    hunt_lab(0, 1, 0, green);
    hunt_lab(0, 0, 1, blue);
    k->cmax = powf(hyab(green, blue), QC);
}

/* What every pass reads; planes are w * h floats. */
struct work {
    const struct ssg_flip_input *in;
    const struct kernels *k;
    int hdr;              /* tone map (HDR-FLIP) or clamp (LDR-FLIP) */
    float exposure;       /* HDR: 2^exposure, the compensation factor */
    int test;             /* which image the per-image passes read: 1 = test, 0 = ref */
    float *opp[3];        /* normalised luminance Y / Yn, Cx, Cz of the current image */
    float *hor[HORIZONTAL];
    float *out[2][OUTS];  /* per image (0 ref, 1 test) */
    float *map;
    int first;            /* 1 = the map's first exposure: store, else keep the maximum */
    float *scratch;       /* per band: SCRATCH(w, r) floats, for its padded row and its
                             eight vertical sums (allocated once: a band cannot fail) */
    size_t scratch_len;   /* floats per band */
};

/* The ACES fit (Narkowicz 2016) with the paper's 0.6 pre-exposure folded in. */
static const double ACES[6] = {0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.0, 0.6 * 0.6 * 2.43,
                               0.6 * 0.59, 0.14};

static inline float tone(float x)
{
    float n = ((float)ACES[0] * x + (float)ACES[1]) * x + (float)ACES[2];
    float d = ((float)ACES[3] * x + (float)ACES[4]) * x + (float)ACES[5];
    float y = n / d; /* x huge: inf / inf = NaN, taken as white below */
    return y >= 0.0f && y < 1.0f ? y : y >= 1.0f || y != y ? 1.0f : 0.0f;
}

/* A source value as LDR-FLIP sees it: non-finite as 0, negative as 0, then clamped (LDR)
   or exposed and tone mapped (HDR). */
static inline float ldr_value(const struct work *wk, float v)
{
    v = isfinite(v) && v > 0.0f ? v : 0.0f;
    if (wk->hdr)
        return tone(v * wk->exposure);
    return v < 1.0f ? v : 1.0f;
}

/* Pass 1: the current image to YyCxCz. Y is kept as Y / Yn, which is what the
   feature pass needs ((Y + 16) / 116) and which the CSF filters like Y itself (they sum to
   1, so the affine 116 t - 16 commutes with them). */
static SSG_VECTOR_CLONES void opponent_rows(void *user, int y0, int y1)
{
    const struct work *wk = user;
    const struct ssg_flip_input *in = wk->in;
    size_t w = (size_t)in->w;
    for (size_t i = (size_t)y0 * w; i < (size_t)y1 * w; i++) {
        float c[3];
        for (int ch = 0; ch < 3; ch++) {
            float v = wk->test && in->on[i] ? in->test[ch][i] : in->ref[ch][i];
            c[ch] = ldr_value(wk, v);
        }
        float xyz[3];
        for (int r = 0; r < 3; r++)
            xyz[r] = (float)RGB2XYZN[r][0] * c[0] + (float)RGB2XYZN[r][1] * c[1] +
                     (float)RGB2XYZN[r][2] * c[2];
        wk->opp[0][i] = xyz[1];
        wk->opp[1][i] = 500.0f * (xyz[0] - xyz[1]);
        wk->opp[2][i] = 200.0f * (xyz[1] - xyz[2]);
    }
}

/* out[x] = sum_t k[t] row[x + t] over a row padded by r replicated pixels. */
static inline void filter_row(const float *k, int r, const float *row, float *restrict out,
                              int w)
{
    /* Taps outermost: the x loop vectorises, and each pixel still adds its taps in t
       order (the same bits whatever the band). */
    for (int x = 0; x < w; x++)
        out[x] = k[0] * row[x];
    for (int t = 1; t <= 2 * r; t++)
        for (int x = 0; x < w; x++)
            out[x] += k[t] * row[x + t];
}

/* Copies row y of plane p into pad with r replicated pixels on either side. */
static void pad_row(const float *p, int w, int y, int r, float *pad)
{
    const float *row = p + (size_t)y * (size_t)w;
    for (int i = 0; i < r; i++)
        pad[i] = row[0], pad[r + w + i] = row[w - 1];
    memcpy(pad + r, row, (size_t)w * sizeof(float));
}

/* Pass 2: the seven horizontal 1D filters (CSF per channel, two for Cz; Gaussian, first
   and second derivative of the luminance). */
static SSG_VECTOR_CLONES void horizontal_rows(void *user, int y0, int y1)
{
    const struct work *wk = user;
    const struct kernels *k = wk->k;
    int w = wk->in->w, r = k->rc > k->rf ? k->rc : k->rf;
    float *pad = wk->scratch + (size_t)(y0 / ROWS_PER_BAND) * wk->scratch_len;
    for (int y = y0; y < y1; y++) {
        size_t o = (size_t)y * (size_t)w;
        pad_row(wk->opp[0], w, y, r, pad);
        filter_row(k->y, k->rc, pad + r - k->rc, wk->hor[H_Y] + o, w);
        filter_row(k->g, k->rf, pad + r - k->rf, wk->hor[H_G] + o, w);
        filter_row(k->d1, k->rf, pad + r - k->rf, wk->hor[H_D1] + o, w);
        filter_row(k->d2, k->rf, pad + r - k->rf, wk->hor[H_D2] + o, w);
        pad_row(wk->opp[1], w, y, r, pad);
        filter_row(k->cx, k->rc, pad + r - k->rc, wk->hor[H_CX] + o, w);
        pad_row(wk->opp[2], w, y, r, pad);
        filter_row(k->cz1, k->rc, pad + r - k->rc, wk->hor[H_CZ1] + o, w);
        filter_row(k->cz2, k->rc, pad + r - k->rc, wk->hor[H_CZ2] + o, w);
    }
}

/* out[x] = sum_t k[t] plane[row y + t - r, replicated at the ends][x]. */
static inline void filter_column(const float *k, int r, const float *p, int w, int h, int y,
                                 float *restrict out)
{
    for (int x = 0; x < w; x++)
        out[x] = 0.0f;
    for (int t = 0; t <= 2 * r; t++) {
        int ry = y + t - r;
        ry = ry < 0 ? 0 : ry >= h ? h - 1 : ry;
        const float *row = p + (size_t)ry * (size_t)w;
        for (int x = 0; x < w; x++)
            out[x] += k[t] * row[x];
    }
}

/* The filtered opponent colour back to linear RGB, clamped to the cube, then
   Hunt-adjusted L*a*b*. yn is the filtered Y / Yn. */
static inline void filtered_lab(float yn, float cx, float cz, float lab[3])
{
    /* XYZ / white, then the inverse of RGB2XYZN (the sRGB matrix with white folded in). */
    float xn = yn + cx / 500.0f, zn = yn - cz / 200.0f;
    float X = 0.950428545f * xn, Y = yn, Z = 1.088900371f * zn;
    float r = 3.241003232976358f * X - 1.537398969488785f * Y - 0.498615881996363f * Z;
    float g = -0.969224252202516f * X + 1.875929983695176f * Y + 0.041554226340085f * Z;
    float b = 0.055639419851975f * X - 0.204011206123910f * Y + 1.057148977187533f * Z;
    r = r > 0.0f ? (r < 1.0f ? r : 1.0f) : 0.0f;
    g = g > 0.0f ? (g < 1.0f ? g : 1.0f) : 0.0f;
    b = b > 0.0f ? (b < 1.0f ? b : 1.0f) : 0.0f;
    hunt_lab(r, g, b, lab);
}

/* Pass 3: the vertical filters, then per pixel its L*a*b* and feature magnitudes. */
static SSG_VECTOR_CLONES void vertical_rows(void *user, int y0, int y1)
{
    const struct work *wk = user;
    const struct kernels *k = wk->k;
    int w = wk->in->w, h = wk->in->h;
    float *acc = wk->scratch + (size_t)(y0 / ROWS_PER_BAND) * wk->scratch_len, *f[8];
    for (int i = 0; i < 8; i++)
        f[i] = acc + (size_t)i * (size_t)w;
    float *const *out = wk->out[wk->test];
    for (int y = y0; y < y1; y++) {
        filter_column(k->y, k->rc, wk->hor[H_Y], w, h, y, f[0]);
        filter_column(k->cx, k->rc, wk->hor[H_CX], w, h, y, f[1]);
        filter_column(k->cz1, k->rc, wk->hor[H_CZ1], w, h, y, f[2]);
        filter_column(k->cz2, k->rc, wk->hor[H_CZ2], w, h, y, f[3]);
        filter_column(k->g, k->rf, wk->hor[H_D1], w, h, y, f[4]);  /* edge, x */
        filter_column(k->d1, k->rf, wk->hor[H_G], w, h, y, f[5]);  /* edge, y */
        filter_column(k->g, k->rf, wk->hor[H_D2], w, h, y, f[6]);  /* point, x */
        filter_column(k->d2, k->rf, wk->hor[H_G], w, h, y, f[7]);  /* point, y */
        size_t o = (size_t)y * (size_t)w;
        for (int x = 0; x < w; x++) {
            float lab[3];
            filtered_lab(f[0][x], f[1][x], k->wz1 * f[2][x] + k->wz2 * f[3][x], lab);
            out[O_L][o + x] = lab[0];
            out[O_A][o + x] = lab[1];
            out[O_B][o + x] = lab[2];
            out[O_EDGE][o + x] = sqrtf(f[4][x] * f[4][x] + f[5][x] * f[5][x]);
            out[O_POINT][o + x] = sqrtf(f[6][x] * f[6][x] + f[7][x] * f[7][x]);
        }
    }
}

/* HyAB^qc mapped to [0, pt] below pc * cmax and to (pt, 1] above; clamped to 1
   for the few pairs (if any) farther apart than green and blue. */
static inline float colour_error(float d, float cmax)
{
    float p = powf(d, QC), knee = PC * cmax;
    float e = p < knee ? PT / knee * p : PT + (p - knee) / (cmax - knee) * (1.0f - PT);
    return e < 1.0f ? e : 1.0f;
}

/* Pass 4: colour ^ (1 - feature) per pixel, kept as the maximum over exposures. */
static SSG_VECTOR_CLONES void combine_rows(void *user, int y0, int y1)
{
    const struct work *wk = user;
    size_t w = (size_t)wk->in->w;
    float *const *r = wk->out[0], *const *t = wk->out[1];
    const float inv_sqrt2 = 0.70710678118654752f;
    for (size_t i = (size_t)y0 * w; i < (size_t)y1 * w; i++) {
        float pr[3] = {r[O_L][i], r[O_A][i], r[O_B][i]};
        float pt[3] = {t[O_L][i], t[O_A][i], t[O_B][i]};
        float ec = colour_error(hyab(pr, pt), wk->k->cmax);
        float de = fabsf(r[O_EDGE][i] - t[O_EDGE][i]);
        float dp = fabsf(r[O_POINT][i] - t[O_POINT][i]);
        float ef = powf(inv_sqrt2 * (de > dp ? de : dp), QF);
        float v = powf(ec, 1.0f - ef);
        wk->map[i] = wk->first || v > wk->map[i] ? v : wk->map[i];
    }
}

/* One LDR-FLIP evaluation at the work's exposure, folded into the map. */
static void ldr_flip(struct work *wk)
{
    int h = wk->in->h;
    for (int img = 0; img < 2; img++) {
        wk->test = img;
        ssg_parallel_rows(h, ROWS_PER_BAND, opponent_rows, wk);
        ssg_parallel_rows(h, ROWS_PER_BAND, horizontal_rows, wk);
        ssg_parallel_rows(h, ROWS_PER_BAND, vertical_rows, wk);
    }
    ssg_parallel_rows(h, ROWS_PER_BAND, combine_rows, wk);
    wk->first = 0;
}

static int cmp_float(const void *a, const void *b)
{
    float x = *(const float *)a, y = *(const float *)b;
    return (x > y) - (x < y);
}

/* np.percentile(v, 50) of n > 0 sorted values: the middle one, or the middle two's mean. */
static double median(const float *v, size_t n)
{
    return n % 2 ? v[n / 2] : 0.5 * ((double)v[n / 2 - 1] + (double)v[n / 2]);
}

/* HDR-FLIP's exposure range from the reference's luminance over the compared pixels:
   start = log2(x85 / max Y), stop = log2(x85 / median Y), x85 the tone curve's input for
   0.85. A median of 0 (half the pixels black) has no stop: the median of the positive
   values stands in. All black: start = stop = 0, as in the paper's code. */
static int exposure_range(const struct ssg_flip_input *in, double *start, double *stop)
{
    size_t n = (size_t)in->w * (size_t)in->h, m = 0;
    float *lum = malloc((n ? n : 1) * sizeof(float));
    if (!lum)
        return -1;
    for (size_t i = 0; i < n; i++) {
        if (!in->on[i])
            continue;
        float c[3];
        for (int ch = 0; ch < 3; ch++)
            c[ch] = isfinite(in->ref[ch][i]) && in->ref[ch][i] > 0 ? in->ref[ch][i] : 0.0f;
        lum[m++] = 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2];
    }
    qsort(lum, m, sizeof(float), cmp_float);
    size_t zeros = 0;
    while (zeros < m && lum[zeros] <= 0.0f)
        zeros++;
    *start = *stop = 0.0;
    if (zeros < m) {
        double med = median(lum, m);
        med = med > 0 ? med : median(lum + zeros, m - zeros);
        double t = 0.85, a = ACES[0] - ACES[3] * t;
        double c0 = (ACES[1] - ACES[4] * t) / a, c1 = (ACES[2] - ACES[5] * t) / a;
        double x85 = -0.5 * c0 + sqrt(0.25 * c0 * c0 - c1);
        *start = log2(x85 / lum[m - 1]);
        *stop = log2(x85 / med);
    }
    free(lum);
    return 0;
}

static void hdr_flip(struct work *wk, int *count)
{
    double start, stop;
    if (exposure_range(wk->in, &start, &stop))
        return;
    int n = (int)fmax(2.0, ceil(stop - start));
    /* start == stop: every exposure is the same one; evaluating it once gives the map. */
    if (stop == start)
        n = 1;
    for (int i = 0; i < n; i++) {
        double e = n > 1 ? start + i * (stop - start) / (n - 1) : start;
        wk->exposure = (float)exp2(e);
        ldr_flip(wk);
    }
    *count = n;
}

int ssg_flip_map(const struct ssg_flip_input *in, float *map, int *exposures)
{
    struct kernels *k = malloc(sizeof *k);
    size_t n = (size_t)in->w * (size_t)in->h, planes = 3 + HORIZONTAL + 2 * OUTS;
    size_t bands = (size_t)(in->h + ROWS_PER_BAND - 1) / ROWS_PER_BAND;
    /* a band's scratch: the padded row (w + 2 MAX_R) or the eight vertical sums (8 w) */
    size_t per_band = (size_t)in->w * 8 + 2 * MAX_R + 1;
    float *mem = malloc((n * planes + bands * per_band + 1) * sizeof(float));
    int count = 0;
    if (!k || !mem) {
        free(k), free(mem);
        return -1;
    }
    make_kernels(k, in->ppd);
    struct work wk = {.in = in, .k = k, .hdr = in->hdr, .exposure = 1.0f, .map = map,
                      .first = 1, .scratch = mem + n * planes, .scratch_len = per_band};
    float *p = mem;
    for (int i = 0; i < 3; i++, p += n)
        wk.opp[i] = p;
    for (int i = 0; i < HORIZONTAL; i++, p += n)
        wk.hor[i] = p;
    for (int img = 0; img < 2; img++)
        for (int i = 0; i < OUTS; i++, p += n)
            wk.out[img][i] = p;
    if (in->hdr) {
        hdr_flip(&wk, &count);
    } else {
        ldr_flip(&wk);
        count = 1;
    }
    free(mem);
    free(k);
    if (exposures)
        *exposures = count;
    return count > 0 ? 0 : -1;
}
