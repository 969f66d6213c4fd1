/* env.h - the scene's environment light as the nodes need it: radiance in a direction, a
 * coarse prefiltered radiance and a view-space cube of it for screen-space samples, the
 * diffuse irradiance about a normal, and importance sampling for the reference nodes.
 *
 * The environment is a constant colour, or an HDR lat-long light probe (`environment(
 * image="probe.exr")` in the scene) tinted by the colour; both times the intensity.
 * Lat-long convention (world space, y up): a unit direction d maps to
 *   u = 0.5 + atan2(d.x, -d.z) / (2 pi),  v = acos(d.y) / pi,
 * column u * width and row v * height, row 0 straight up, the image centre looking down -z
 * (the default view direction). The probe is piecewise constant over its pixels: radiance
 * lookups, the sampling pdf and the prefiltered tables all use that one reading, so the
 * reference estimators are unbiased for exactly the image given.
 *
 * ssg_env_build makes the derived tables once, at scene load; afterwards a struct ssg_env
 * is read-only and may be shared by threads. Its memory is its own (ssg_env_destroy). */
#ifndef SSG_ENV_H
#define SSG_ENV_H

#include "ssgraph.h"

struct ssg_scene;

/* Size of the coarse radiance and irradiance tables (lat-long, 5.6 degree texels). */
enum { SSG_ENV_COARSE_W = 64, SSG_ENV_COARSE_H = 32 };

struct ssg_env {
    int has_light;             /* 0 = black everywhere (no environment line, or intensity 0) */
    int has_image;             /* 0 = constant radiance `constant` in every direction */
    float constant[3];         /* colour * intensity, linear RGB */
    int width, height;         /* the probe, px; 0 without an image */
    float *radiance;           /* width x height x 3 interleaved, already times colour and
                                  intensity; NULL without an image */
    float coarse[SSG_ENV_COARSE_H][SSG_ENV_COARSE_W][3];     /* solid-angle average of
                                                                radiance over each texel */
    float irradiance[SSG_ENV_COARSE_H][SSG_ENV_COARSE_W][3]; /* E(n) = integral of L(w)
                                                                max(0, n.w) dw at the texel
                                                                centre's direction n */
    float coarse_pole[2][3];     /* the coarse table's value at the north and south pole
                                    (mean of its first and last row) */
    float irradiance_pole[2][3]; /* likewise for the irradiance table */
    /* Importance sampling of the probe by luminance x solid angle (piecewise constant):
       row_cdf[height + 1] over rows, col_cdf[height][width + 1] within each row. */
    float *row_cdf, *col_cdf;
    double power;              /* integral of luminance over the sphere (the sampling
                                  normaliser); 4 pi luminance of `constant` without image */
};

/* Builds the environment of a loaded scene (scene->environment and its image in
 * scene->textures). A probe that is not 2:1, or that holds a NaN or infinity, is an error
 * (SSG_E_VALUE, naming the pixel) in diags; negative values (the ringing of lossy EXR
 * compression) are taken as 0. */
enum ssg_err ssg_env_build(const struct ssg_scene *scene, const char *image_path,
                           struct ssg_env **out, struct ssg_diags *diags);
void ssg_env_destroy(struct ssg_env **env);

/* Radiance arriving from unit world direction d (the probe texel d falls in). */
void ssg_env_radiance(const struct ssg_env *env, const float d[3], float rgb[3]);

/* The coarse table's radiance for unit world direction d, bilinear: the environment as a
 * sample covering several degrees sees it. */
void ssg_env_radiance_coarse(const struct ssg_env *env, const float d[3], float rgb[3]);

/* Irradiance E(n) = integral over the sphere of L(w) max(0, n.w) dw for unit world normal n
 * (bilinear in the table; pi * L for a constant environment). A diffuse surface of albedo
 * rho reflects rho / pi * E. */
void ssg_env_irradiance(const struct ssg_env *env, const float n[3], float rgb[3]);

/* Draws a world direction from (u1, u2) in [0, 1)^2 with probability proportional to the
 * probe's luminance x solid angle (uniform over the sphere for a constant environment) and
 * returns its pdf per steradian (0 when the environment is black); rgb gets the radiance. */
float ssg_env_sample(const struct ssg_env *env, float u1, float u2, float d[3], float rgb[3]);

/* The pdf per steradian with which ssg_env_sample draws unit direction d. */
float ssg_env_pdf(const struct ssg_env *env, const float d[3]);

/* Unit world direction of lat-long coordinates (u, v) in [0, 1]^2, and back. */
void ssg_env_direction(float u, float v, float d[3]);
void ssg_env_latlong(const float d[3], float *u, float *v);

/* A cube map of the coarse radiance in a node's own frame (view space, say), for lookups
 * that cost no trigonometry: `to_world` is the 3x3 row-major rotation from that frame to
 * world. Faces +x, -x, +y, -y, +z, -z; texel (i, j) of face f at rgb[((f * size + j) *
 * size + i) * 3]. */
enum { SSG_ENV_CUBE_SIZE = 16 };
struct ssg_env_cube {
    float rgb[6 * SSG_ENV_CUBE_SIZE * SSG_ENV_CUBE_SIZE * 3];
};
void ssg_env_cube_build(const struct ssg_env *env, const float to_world[9],
                        struct ssg_env_cube *cube);

/* Index (in texels, times 3 for the float offset) of the nearest cube texel for direction
 * (x, y, z) in the cube's frame (need not be unit, must not be 0). Written with selects
 * only, no branches, so a loop over many directions vectorises. */
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
static inline int ssg_env_cube_index(float x, float y, float z)
{
    const int n = SSG_ENV_CUBE_SIZE;
    float ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, az = z < 0 ? -z : z;
    int xm = (ax >= ay) & (ax >= az), ym = !xm & (ay >= az);
    float ma = xm ? ax : ym ? ay : az;
    int face = xm ? (x >= 0 ? 0 : 1) : ym ? (y >= 0 ? 2 : 3) : (z >= 0 ? 4 : 5);
    float sc = xm ? (x >= 0 ? -z : z) : ym ? x : (z >= 0 ? x : -x);
    float tc = xm ? -y : ym ? (y >= 0 ? z : -z) : -y;
    float inv = 0.5f * (float)n / ma;
    int i = (int)(sc * inv + 0.5f * (float)n), j = (int)(tc * inv + 0.5f * (float)n);
    i = i < 0 ? 0 : i >= n ? n - 1 : i;
    j = j < 0 ? 0 : j >= n ? n - 1 : j;
    return (face * n + j) * n + i;
}

/* The nearest texel's RGB for direction (x, y, z) (see ssg_env_cube_index). */
static inline const float *ssg_env_cube_texel(const struct ssg_env_cube *cube, float x,
                                              float y, float z)
{
    return &cube->rgb[(size_t)ssg_env_cube_index(x, y, z) * 3];
}

#endif
