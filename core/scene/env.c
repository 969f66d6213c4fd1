/* env.c - the environment light's tables and lookups (conventions in env.h).
 *
 * Prefiltering: each coarse texel is the solid-angle-weighted mean of the probe pixels whose
 * centres fall in it (a probe coarser than the table is point-sampled 8 x 8 per texel), so
 * the coarse table keeps the probe's energy exactly. Irradiance is the cosine convolution of
 * the coarse table, summed over its texels (Ramamoorthi and Hanrahan 2001 show irradiance is
 * so smooth that 5.6 degree texels lose well under 1 % of it). Importance sampling inverts
 * the piecewise-constant 2D distribution of max(R, G, B) x solid angle, rows then columns
 * (Pharr, Jakob and Humphreys, "Physically Based Rendering", 3rd ed., sec. 13.6.7); inside a
 * pixel the direction is uniform in solid angle, so the pdf per steradian is the pixel's
 * weight over the total. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lang/diag.h"
#include "scene/env.h"
#include "scene/scene.h"

#ifndef M_PI /* C11's math.h need not define it */
#define M_PI 3.14159265358979323846
#endif
#define TWO_PI (2.0 * M_PI)

void ssg_env_direction(float u, float v, float d[3])
{
    float phi = (float)((u - 0.5) * TWO_PI), theta = (float)(v * M_PI);
    float st = sinf(theta);
    d[0] = st * sinf(phi);
    d[1] = cosf(theta);
    d[2] = -st * cosf(phi);
}

void ssg_env_latlong(const float d[3], float *u, float *v)
{
    float y = d[1] < -1.0f ? -1.0f : d[1] > 1.0f ? 1.0f : d[1];
    *u = 0.5f + atan2f(d[0], -d[2]) / (float)TWO_PI;
    *v = acosf(y) / (float)M_PI;
}

/* Row and column of the texel of a w x h lat-long image that d falls in. */
static void texel_of(const float d[3], int w, int h, int *x, int *y)
{
    float u, v;
    ssg_env_latlong(d, &u, &v);
    int ix = (int)(u * (float)w), iy = (int)(v * (float)h);
    *x = ix < 0 ? 0 : ix >= w ? w - 1 : ix;
    *y = iy < 0 ? 0 : iy >= h ? h - 1 : iy;
}

/* Solid angle of one texel in row y of a w x h lat-long image. */
static double texel_solid_angle(int y, int w, int h)
{
    return TWO_PI / w * (cos(M_PI * y / h) - cos(M_PI * (y + 1) / h));
}

static float sample_weight(const float *rgb)
{
    float m = rgb[0] > rgb[1] ? rgb[0] : rgb[1];
    return m > rgb[2] ? m : rgb[2];
}

void ssg_env_radiance(const struct ssg_env *env, const float d[3], float rgb[3])
{
    if (!env->has_image) {
        memcpy(rgb, env->constant, 3 * sizeof(float));
        return;
    }
    int x, y;
    texel_of(d, env->width, env->height, &x, &y);
    memcpy(rgb, &env->radiance[3 * ((size_t)y * (size_t)env->width + (size_t)x)],
           3 * sizeof(float));
}

/* Bilinear lookup in a coarse table: u wraps around; between the first (last) row's
   centres and the pole, the value blends towards the pole's own value (the row's mean), so
   a lookup at the pole does not depend on the azimuth it happens to carry. */
static void table_bilinear(const float (*t)[SSG_ENV_COARSE_W][3], const float (*pole)[3],
                           const float d[3], float rgb[3])
{
    float u, v;
    ssg_env_latlong(d, &u, &v);
    float fx = u * SSG_ENV_COARSE_W - 0.5f, fy = v * SSG_ENV_COARSE_H - 0.5f;
    float x0f = floorf(fx), ax = fx - x0f;
    int x0 = ((int)x0f % SSG_ENV_COARSE_W + SSG_ENV_COARSE_W) % SSG_ENV_COARSE_W;
    int x1 = (x0 + 1) % SSG_ENV_COARSE_W;
    int y = (int)floorf(fy), last = SSG_ENV_COARSE_H - 1;
    float ay = fy - floorf(fy);
    for (int c = 0; c < 3; c++) {
        float row[2];
        for (int k = 0; k < 2; k++) {
            int yk = y + k;
            row[k] = yk < 0 ? pole[0][c] : yk > last ? pole[1][c]
                   : (1 - ax) * t[yk][x0][c] + ax * t[yk][x1][c];
        }
        /* the poles sit half a texel beyond the outer row centres */
        float w = y < 0 ? 2 * ay - 1 : y >= last ? 2 * ay : ay;
        w = w < 0 ? 0 : w > 1 ? 1 : w;
        rgb[c] = (1 - w) * row[0] + w * row[1];
    }
}

/* The mean of a table's first and last rows: its values at the two poles. */
static void table_poles(const float (*t)[SSG_ENV_COARSE_W][3], float pole[2][3])
{
    for (int p = 0; p < 2; p++)
        for (int c = 0; c < 3; c++) {
            double sum = 0;
            for (int x = 0; x < SSG_ENV_COARSE_W; x++)
                sum += t[p ? SSG_ENV_COARSE_H - 1 : 0][x][c];
            pole[p][c] = (float)(sum / SSG_ENV_COARSE_W);
        }
}

void ssg_env_radiance_coarse(const struct ssg_env *env, const float d[3], float rgb[3])
{
    if (!env->has_image) {
        memcpy(rgb, env->constant, 3 * sizeof(float));
        return;
    }
    table_bilinear(env->coarse, (const float(*)[3])env->coarse_pole, d, rgb);
}

void ssg_env_irradiance(const struct ssg_env *env, const float n[3], float rgb[3])
{
    if (!env->has_image) {
        for (int c = 0; c < 3; c++)
            rgb[c] = (float)M_PI * env->constant[c];
        return;
    }
    table_bilinear(env->irradiance, (const float(*)[3])env->irradiance_pole, n, rgb);
}

/* Index of the interval of a cdf (count + 1 entries, 0 .. 1) that holds x. */
static int cdf_find(const float *cdf, int count, float x)
{
    int lo = 0, hi = count - 1;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (cdf[mid] <= x)
            lo = mid;
        else
            hi = mid - 1;
    }
    while (lo < count - 1 && cdf[lo + 1] <= cdf[lo]) /* skip empty intervals */
        lo++;
    return lo;
}

float ssg_env_sample(const struct ssg_env *env, float u1, float u2, float d[3], float rgb[3])
{
    if (!env->has_light || !(env->power > 0)) {
        d[0] = 0, d[1] = 1, d[2] = 0;
        rgb[0] = rgb[1] = rgb[2] = 0;
        return 0.0f;
    }
    if (!env->has_image) {
        float z = 1.0f - 2.0f * u1, r = sqrtf(fmaxf(0.0f, 1.0f - z * z));
        float phi = (float)TWO_PI * u2;
        d[0] = r * cosf(phi), d[1] = z, d[2] = r * sinf(phi);
        memcpy(rgb, env->constant, 3 * sizeof(float));
        return (float)(1.0 / (4.0 * M_PI));
    }
    const int w = env->width, h = env->height;
    int y = cdf_find(env->row_cdf, h, u2);
    const float *cc = &env->col_cdf[(size_t)y * (size_t)(w + 1)];
    int x = cdf_find(cc, w, u1);
    /* Re-use what is left of u1 and u2 inside the chosen intervals as uniform numbers. */
    float ry = env->row_cdf[y + 1] - env->row_cdf[y], rx = cc[x + 1] - cc[x];
    float fy = ry > 0 ? (u2 - env->row_cdf[y]) / ry : 0.5f;
    float fx = rx > 0 ? (u1 - cc[x]) / rx : 0.5f;
    fx = fx < 0 ? 0 : fx > 1 ? 1 : fx;
    fy = fy < 0 ? 0 : fy > 1 ? 1 : fy;
    double c0 = cos(M_PI * y / h), c1 = cos(M_PI * (y + 1) / h);
    float cos_t = (float)(c0 + (c1 - c0) * fy),
          sin_t = sqrtf(fmaxf(0.0f, 1.0f - cos_t * cos_t));
    float phi = (float)(((x + fx) / w - 0.5) * TWO_PI);
    d[0] = sin_t * sinf(phi), d[1] = cos_t, d[2] = -sin_t * cosf(phi);
    const float *px = &env->radiance[3 * ((size_t)y * (size_t)w + (size_t)x)];
    memcpy(rgb, px, 3 * sizeof(float));
    return (float)(sample_weight(px) / env->power);
}

float ssg_env_pdf(const struct ssg_env *env, const float d[3])
{
    if (!env->has_light || !(env->power > 0))
        return 0.0f;
    if (!env->has_image)
        return (float)(1.0 / (4.0 * M_PI));
    int x, y;
    texel_of(d, env->width, env->height, &x, &y);
    return (float)(sample_weight(&env->radiance[3 * ((size_t)y * (size_t)env->width +
                                                      (size_t)x)]) / env->power);
}

/* Accumulates one probe direction of solid angle da into coarse texel (cy, cx): radiance
   sums in sum[..][0..2], the weight in sum[..][3], and the power-weighted direction in
   centroid (so the irradiance sees a small bright source where it is, not at the centre
   of its texel). */
static void accumulate(double (*sum)[SSG_ENV_COARSE_W][4], double (*centroid)[3], int cy,
                       int cx, const float d[3], const float *rgb, double da)
{
    for (int c = 0; c < 3; c++)
        sum[cy][cx][c] += da * rgb[c];
    sum[cy][cx][3] += da;
    double p = da * (rgb[0] + rgb[1] + rgb[2]) + 1e-30 * da;
    for (int k = 0; k < 3; k++)
        centroid[cy * SSG_ENV_COARSE_W + cx][k] += p * d[k];
}

/* The coarse table: solid-angle-weighted means of the probe (see the file comment), and
   each texel's power-weighted unit direction in dir (for build_irradiance). */
static enum ssg_err build_coarse(struct ssg_env *env, float (*dir)[3])
{
    const int w = env->width, h = env->height, cw = SSG_ENV_COARSE_W, ch = SSG_ENV_COARSE_H;
    double (*sum)[SSG_ENV_COARSE_W][4] = calloc(SSG_ENV_COARSE_H, sizeof *sum);
    double (*centroid)[3] = calloc((size_t)cw * ch, sizeof *centroid);
    if (!sum || !centroid) {
        free(sum);
        free(centroid);
        return SSG_E_NOMEM;
    }
    if (w >= cw && h >= ch) {
        for (int y = 0; y < h; y++) {
            double da = texel_solid_angle(y, w, h);
            int cy = (int)((y + 0.5) * ch / h);
            for (int x = 0; x < w; x++) {
                float d[3];
                ssg_env_direction((x + 0.5f) / (float)w, (y + 0.5f) / (float)h, d);
                accumulate(sum, centroid, cy, (int)((x + 0.5) * cw / w), d,
                           &env->radiance[3 * ((size_t)y * (size_t)w + (size_t)x)], da);
            }
        }
    } else {
        for (int cy = 0; cy < ch; cy++)
            for (int cx = 0; cx < cw; cx++)
                for (int j = 0; j < 8; j++)
                    for (int i = 0; i < 8; i++) {
                        float u = (cx + (i + 0.5f) / 8) / cw, v = (cy + (j + 0.5f) / 8) / ch;
                        float d[3], rgb[3];
                        ssg_env_direction(u, v, d);
                        ssg_env_radiance(env, d, rgb);
                        accumulate(sum, centroid, cy, cx, d, rgb, sin(M_PI * v));
                    }
    }
    for (int cy = 0; cy < ch; cy++)
        for (int cx = 0; cx < cw; cx++) {
            for (int c = 0; c < 3; c++)
                env->coarse[cy][cx][c] =
                    sum[cy][cx][3] > 0 ? (float)(sum[cy][cx][c] / sum[cy][cx][3]) : 0.0f;
            const double *m = centroid[cy * cw + cx];
            double len = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
            float *d = dir[cy * cw + cx];
            if (len > 0)
                d[0] = (float)(m[0] / len), d[1] = (float)(m[1] / len),
                d[2] = (float)(m[2] / len);
            else
                ssg_env_direction((cx + 0.5f) / cw, (cy + 0.5f) / ch, d);
        }
    free(sum);
    free(centroid);
    return SSG_OK;
}

/* Irradiance at each coarse texel centre: the cosine-weighted sum over the coarse texels,
   each taken as arriving from its power-weighted direction. */
static void build_irradiance(struct ssg_env *env, const float (*src)[3])
{
    const int cw = SSG_ENV_COARSE_W, ch = SSG_ENV_COARSE_H;
    double row_da[SSG_ENV_COARSE_H], weight[3];
    for (int y = 0; y < ch; y++)
        row_da[y] = texel_solid_angle(y, cw, ch);
    for (int i = 0; i < cw * ch; i++) {
        float n[3];
        ssg_env_direction((i % cw + 0.5f) / cw, (i / cw + 0.5f) / ch, n);
        double e[3] = {0, 0, 0};
        for (int k = 0; k < cw * ch; k++) {
            double cosine = n[0] * src[k][0] + n[1] * src[k][1] + n[2] * src[k][2];
            if (cosine <= 0)
                continue;
            double da = row_da[k / cw];
            for (int c = 0; c < 3; c++) {
                weight[c] = da * env->coarse[k / cw][k % cw][c];
                e[c] += cosine * weight[c];
            }
        }
        for (int c = 0; c < 3; c++)
            env->irradiance[i / cw][i % cw][c] = (float)e[c];
    }
}

/* The row and column cdfs of the probe's sampling distribution; SSG_E_NOMEM on failure. */
static enum ssg_err build_sampling(struct ssg_env *env)
{
    const int w = env->width, h = env->height;
    env->row_cdf = malloc(sizeof(float) * (size_t)(h + 1));
    env->col_cdf = malloc(sizeof(float) * (size_t)h * (size_t)(w + 1));
    double *row = malloc(sizeof(double) * (size_t)h);
    if (!env->row_cdf || !env->col_cdf || !row) {
        free(row);
        return SSG_E_NOMEM;
    }
    double total = 0;
    for (int y = 0; y < h; y++) {
        float *cc = &env->col_cdf[(size_t)y * (size_t)(w + 1)];
        double s = 0;
        cc[0] = 0;
        for (int x = 0; x < w; x++) {
            s += sample_weight(&env->radiance[3 * ((size_t)y * (size_t)w + (size_t)x)]);
            cc[x + 1] = (float)s;
        }
        for (int x = 1; x <= w; x++)
            cc[x] = s > 0 ? (float)(cc[x] / s) : (float)x / (float)w;
        cc[w] = 1.0f;
        row[y] = s * texel_solid_angle(y, w, h);
        total += row[y];
    }
    double s = 0;
    env->row_cdf[0] = 0;
    for (int y = 0; y < h; y++) {
        s += row[y];
        env->row_cdf[y + 1] = total > 0 ? (float)(s / total) : (float)(y + 1) / (float)h;
    }
    env->row_cdf[h] = 1.0f;
    env->power = total;
    free(row);
    return SSG_OK;
}

/* Copies the probe, tinted and scaled, after checking it is a usable lat-long image. */
static enum ssg_err take_probe(struct ssg_env *env, const struct ssg_texture *t,
                               const char *path, struct ssg_diags *diags)
{
    if (t->width != 2 * t->height) {
        ssg_diag_file(diags, SSG_E_VALUE, path, "environment image is %d x %d: expected a "
                      "lat-long light probe twice as wide as it is high", t->width, t->height);
        return SSG_E_VALUE;
    }
    size_t n = (size_t)t->width * (size_t)t->height;
    for (size_t i = 0; i < 3 * n; i++)
        if (!(fabsf(t->rgb[i]) <= 3.0e38f)) {
            ssg_diag_file(diags, SSG_E_VALUE, path, "environment image has a non-finite "
                          "value (NaN or infinity) at pixel (%zu, %zu): expected finite "
                          "radiance", (i / 3) % (size_t)t->width, (i / 3) / (size_t)t->width);
            return SSG_E_VALUE;
        }
    env->radiance = malloc(sizeof(float) * 3 * n);
    if (!env->radiance)
        return SSG_E_NOMEM;
    /* Lossy EXR compression (the DWA of Blender's probes) rings slightly below 0 around
       bright spots: such values are noise, not negative light, and are taken as 0. */
    for (size_t i = 0; i < 3 * n; i++)
        env->radiance[i] = fmaxf(t->rgb[i], 0.0f) * env->constant[i % 3];
    env->width = t->width;
    env->height = t->height;
    return SSG_OK;
}

enum ssg_err ssg_env_build(const struct ssg_scene *scene, const char *image_path,
                           struct ssg_env **out, struct ssg_diags *diags)
{
    *out = NULL;
    struct ssg_env *env = calloc(1, sizeof *env);
    if (!env)
        return SSG_E_NOMEM;
    const struct ssg_environment *e = &scene->environment;
    for (int c = 0; c < 3; c++)
        env->constant[c] = e->color[c] * e->intensity;
    enum ssg_err err = SSG_OK;
    if (e->image >= 0 && e->image < scene->texture_count) {
        env->has_image = 1;
        float (*dir)[3] = malloc(sizeof *dir * SSG_ENV_COARSE_W * SSG_ENV_COARSE_H);
        if (!dir || (err = take_probe(env, &scene->textures[e->image], image_path, diags)) ||
            (err = build_sampling(env)) || (err = build_coarse(env, dir))) {
            free(dir);
            ssg_env_destroy(&env);
            return err ? err : SSG_E_NOMEM;
        }
        table_poles(env->coarse, env->coarse_pole);
        build_irradiance(env, (const float(*)[3])dir);
        table_poles(env->irradiance, env->irradiance_pole);
        free(dir);
        env->has_light = env->power > 0;
    } else {
        env->power = 4.0 * M_PI * sample_weight(env->constant);
        env->has_light = env->power > 0;
    }
    *out = env;
    return SSG_OK;
}

void ssg_env_destroy(struct ssg_env **env)
{
    if (!env || !*env)
        return;
    free((*env)->radiance);
    free((*env)->row_cdf);
    free((*env)->col_cdf);
    free(*env);
    *env = NULL;
}

/* Direction of texel (i, j) of a cube face, in the cube's frame (GL face conventions). */
static void cube_direction(int face, int i, int j, float d[3])
{
    float s = (i + 0.5f) / SSG_ENV_CUBE_SIZE * 2 - 1,
          t = (j + 0.5f) / SSG_ENV_CUBE_SIZE * 2 - 1;
    static const float basis[6][9] = {
        /* major axis, s axis, t axis */
        {1, 0, 0, 0, 0, -1, 0, -1, 0},  {-1, 0, 0, 0, 0, 1, 0, -1, 0},
        {0, 1, 0, 1, 0, 0, 0, 0, 1},    {0, -1, 0, 1, 0, 0, 0, 0, -1},
        {0, 0, 1, 1, 0, 0, 0, -1, 0},   {0, 0, -1, -1, 0, 0, 0, -1, 0},
    };
    const float *b = basis[face];
    for (int k = 0; k < 3; k++)
        d[k] = b[k] + s * b[3 + k] + t * b[6 + k];
}

void ssg_env_cube_build(const struct ssg_env *env, const float to_world[9],
                        struct ssg_env_cube *cube)
{
    const int n = SSG_ENV_CUBE_SIZE;
    for (int f = 0; f < 6; f++)
        for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                float d[3], w[3];
                cube_direction(f, i, j, d);
                float len = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                for (int r = 0; r < 3; r++)
                    w[r] = (to_world[3 * r] * d[0] + to_world[3 * r + 1] * d[1] +
                            to_world[3 * r + 2] * d[2]) / len;
                ssg_env_radiance_coarse(env, w, &cube->rgb[(size_t)((f * n + j) * n + i) * 3]);
            }
}
