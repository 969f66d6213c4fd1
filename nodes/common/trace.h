/* trace.h - what the nodes that trace rays from G-buffer points through the scene share:
 * the camera's view -> world transform and the scene check of their prepare(), the raised
 * ray origin of a G-buffer point, quasi-Monte Carlo sampling (the Hammersley set mapped to
 * the disk, per-pixel hashing for Cranley-Patterson rotation, a turned tangent frame,
 * Malley's cosine-weighted directions).
 *
 * Methods: Szentandrasi, "Modern Methods of Realistic Lighting in Real Time", sec. 4.2,
 * eq. 5-7 (Hammersley set, radical inverse); Cranley and Patterson 1976 (per-pixel shift
 * mod 1); Pharr, Jakob and Humphreys, "Physically Based Rendering", 3rd ed., sec. 13.6.3
 * (Malley's method); Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017,
 * listing 3); SplitMix64's finaliser (Steele, Lea and Flood 2014) as the hash. Each
 * function computes exactly what the nodes computed inline before, in the same order of
 * float operations, so moving them here left every output byte unchanged.
 *
 * Ownership: the functions write only through the pointers they are given; tables and
 * scratch belong to the caller. Thread safety: everything is pure and may run on any
 * thread. */
#ifndef SSG_TRACE_H
#define SSG_TRACE_H

#include <stddef.h>
#include <stdint.h>

#include "graph/node.h"

struct ssg_camera;
struct ssg_scene;

/* The view -> world transform: world = eye + rot^T view, rot the row-major world -> view
 * rotation of ssg_camera_view_matrix (view = rot * (world - eye)). */
void ssg_camera_frame(const struct ssg_camera *camera, float rot[9], float eye[3]);

/* The start of prepare() of a node that traces the scene: SSG_E_SCENE, reported as
 * "<node> '<instance>': needs a loaded scene ...", when ctx has no scene with built rays;
 * otherwise SSG_OK with rot and eye of its camera (ssg_camera_frame). */
enum ssg_err ssg_trace_camera(const struct ssg_node_ctx *ctx, float rot[9], float eye[3]);

/* The self-intersection offset at a point whose coordinates (or distance) reach `scale`:
 * max(offset, 1024 float ulps of scale), since float precision falls with the scene's
 * scale. */
float ssg_trace_offset(float offset, float scale);

/* A G-buffer point in world space and the origin of the rays traced from it. */
struct ssg_trace_point {
    float p[3]; /* the point, world: eye + rot^T view position */
    float n[3]; /* unit normal, world */
    float o[3]; /* ray origin p + e (n + v), v the unit vector from p to the camera,
                   e = ssg_trace_offset(offset, largest |coordinate| of p and depth) */
};

/* Fills *pt from pixel `at` of the view-space position and normal planes pos and nrm (the
 * normal not necessarily unit); returns 0, leaving *pt unspecified, for background (a zero
 * or NaN normal). The n term lifts o off its own surface, the v term moves it into the
 * free space the primary ray crossed, which keeps it off a neighbouring surface at a
 * concave edge too. */
int ssg_trace_point(const float rot[9], const float eye[3], float offset,
                    const float *const pos[3], const float *const nrm[3], size_t at,
                    struct ssg_trace_point *pt);

/* The geometric (face) normal, world, unit, on the camera's side, of the surface that the
 * G-buffer point pt lies on: the primary ray from the eye through pt->p is traced and the
 * hit triangle's own normal taken (surface.h). Interpolated normals may point below that
 * surface at grazing angles, and a ray that leaves below it enters the object, so the
 * hemisphere's horizon comes from this normal and the cosine from the shading one. When
 * the ray finds no surface within 0.1 % of the point's distance (a G-buffer from another
 * source), or a face whose normal is nearly perpendicular to pt->n (the neighbour at a
 * crease), ng is pt->n. */
void ssg_trace_face_normal(const struct ssg_scene *scene, const float eye[3],
                           const struct ssg_trace_point *pt, float ng[3]);

/* Radical inverse of i in the given base (Szentandrasi eq. 6): its digits mirrored about the
 * point. Exact in double for base 2 (32 bits). */
double ssg_radical_inverse(uint32_t i, uint32_t base);

/* The 2D Hammersley set (i / n, phi2(i)), i < n, mapped to the unit disk by Malley's method
 * in the form the kernels read: u[i] = i / n = r^2 (so cos^2 theta = 1 - u) and (c[i],
 * s[i]) the unit vector at angle 2 pi phi2(i). */
void ssg_hammersley_disk(int n, float *u, float *c, float *s);

/* SplitMix64's finaliser: a full-avalanche 64-bit mix. */
uint64_t ssg_mix64(uint64_t z);

/* The hash of pixel (x, y) under seed, from which its Cranley-Patterson shifts come. */
uint64_t ssg_pixel_hash(uint64_t seed, int x, int y);

/* Two shifts in [0, 1) from the 24-bit fields of a hash. */
void ssg_hash_shifts(uint64_t h, float out[2]);

/* The orthonormal tangent frame (t, b) of unit normal n (Duff et al.), turned about n by
 * the angle 2 pi turn: shifting Malley's v by `turn` is this turn of the frame, so the
 * table's cos and sin serve every pixel. */
void ssg_turned_basis(const float n[3], float turn, float t[3], float b[3]);

/* Unit directions of `count` disk points (u[i], c[i], s[i]) of ssg_hammersley_disk, u
 * shifted by `shift` mod 1, lifted to the cosine-weighted hemisphere about the frame
 * (t, b, n): two square roots each, no trigonometry. */
void ssg_malley_dirs(const float *u, const float *c, const float *s, int count, float shift,
                     const float t[3], const float b[3], const float n[3],
                     float *restrict dx, float *restrict dy, float *restrict dz);

#endif
