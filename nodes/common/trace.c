/* trace.c - camera frame, ray origins and quasi-Monte Carlo sampling of the nodes that
 * trace the scene (trace.h, which cites the methods). */
#include <float.h>
#include <math.h>

#include "scene/rt.h"
#include "scene/scene.h"
#include "common/surface.h"
#include "common/trace.h"

void ssg_camera_frame(const struct ssg_camera *camera, float rot[9], float eye[3])
{
    float m[16];
    ssg_camera_view_matrix(camera, m);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++)
            rot[3 * r + k] = m[4 * k + r];
    for (int i = 0; i < 3; i++)
        eye[i] = camera->position[i];
}

enum ssg_err ssg_trace_camera(const struct ssg_node_ctx *ctx, float rot[9], float eye[3])
{
    const struct ssg_scene *s = ctx->scene;
    if (!s || !s->rt)
        return ssg_node_fail(ctx, SSG_E_SCENE,
                             "needs a loaded scene (a `scene` line in the graph, or --scene)");
    ssg_camera_frame(&s->camera, rot, eye);
    return SSG_OK;
}

float ssg_trace_offset(float offset, float scale)
{
    return fmaxf(offset, 1024.0f * FLT_EPSILON * scale);
}

int ssg_trace_point(const float rot[9], const float eye[3], float offset,
                    const float *const pos[3], const float *const nrm[3], size_t at,
                    struct ssg_trace_point *pt)
{
    const float *r = rot;
    float nv[3] = {nrm[0][at], nrm[1][at], nrm[2][at]};
    float pv[3] = {pos[0][at], pos[1][at], pos[2][at]};
    float nn = nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2];
    if (!(nn > 1e-12f)) /* also catches NaN */
        return 0;
    float dist = sqrtf(pv[0] * pv[0] + pv[1] * pv[1] + pv[2] * pv[2]);
    float inv = 1.0f / sqrtf(nn), to_eye = dist > 0.0f ? -1.0f / dist : 0.0f;
    float scale = fabsf(pv[2]), v[3];
    for (int i = 0; i < 3; i++) { /* world = eye + R^T view */
        pt->n[i] = (r[i] * nv[0] + r[3 + i] * nv[1] + r[6 + i] * nv[2]) * inv;
        pt->p[i] = eye[i] + r[i] * pv[0] + r[3 + i] * pv[1] + r[6 + i] * pv[2];
        v[i] = (r[i] * pv[0] + r[3 + i] * pv[1] + r[6 + i] * pv[2]) * to_eye;
        scale = fmaxf(scale, fabsf(pt->p[i]));
    }
    float e = ssg_trace_offset(offset, scale);
    for (int i = 0; i < 3; i++) /* off the own surface (n) and any adjacent one (v) */
        pt->o[i] = pt->p[i] + e * (pt->n[i] + v[i]);
    return 1;
}

void ssg_trace_face_normal(const struct ssg_scene *scene, const float eye[3],
                           const struct ssg_trace_point *pt, float ng[3])
{
    float dir[3] = {pt->p[0] - eye[0], pt->p[1] - eye[1], pt->p[2] - eye[2]};
    struct ssg_hit hit;
    ssg_rt_intersect(scene->rt, eye, dir, 0.0f, 1.001f, &hit);
    float len = 0.0f;
    if (hit.mesh >= 0 && hit.t > 0.999f) {
        ssg_hit_normal(scene, &hit, 1, ng);
        len = sqrtf(ng[0] * ng[0] + ng[1] * ng[1] + ng[2] * ng[2]);
    }
    if (!(len > 0.0f)) {
        for (int i = 0; i < 3; i++)
            ng[i] = pt->n[i];
        return;
    }
    /* On the camera's side: dir points away from the eye. */
    float side = ng[0] * dir[0] + ng[1] * dir[1] + ng[2] * dir[2] > 0.0f ? -1.0f : 1.0f;
    for (int i = 0; i < 3; i++)
        ng[i] *= side / len;
    /* At a crease the re-traced ray (p rebuilt from float view space) may hit the
       neighbouring face: a face normal far from the shading one is that, not a lean. */
    if (ng[0] * pt->n[0] + ng[1] * pt->n[1] + ng[2] * pt->n[2] < 0.1f)
        for (int i = 0; i < 3; i++)
            ng[i] = pt->n[i];
}

double ssg_radical_inverse(uint32_t i, uint32_t base)
{
    double inv = 1.0 / base, scale = inv, r = 0.0;
    for (; i; i /= base, scale *= inv)
        r += (double)(i % base) * scale;
    return r;
}

void ssg_hammersley_disk(int n, float *u, float *c, float *s)
{
    for (int i = 0; i < n; i++) {
        double phi = 2.0 * M_PI * ssg_radical_inverse((uint32_t)i, 2);
        u[i] = (float)((double)i / (double)n);
        c[i] = (float)cos(phi);
        s[i] = (float)sin(phi);
    }
}

uint64_t ssg_mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

uint64_t ssg_pixel_hash(uint64_t seed, int x, int y)
{
    return ssg_mix64(seed ^ ssg_mix64(((uint64_t)(uint32_t)y << 32) | (uint32_t)x));
}

void ssg_hash_shifts(uint64_t h, float out[2])
{
    out[0] = (float)(h >> 40) * (1.0f / 16777216.0f);
    out[1] = (float)((h >> 16) & 0xffffffu) * (1.0f / 16777216.0f);
}

/* Duff et al. 2017, listing 3: a branch-free orthonormal basis (t, b, n). */
static void basis(const float n[3], float t[3], float b[3])
{
    float sign = copysignf(1.0f, n[2]);
    float a = -1.0f / (sign + n[2]);
    float k = n[0] * n[1] * a;
    t[0] = 1.0f + sign * n[0] * n[0] * a, t[1] = sign * k, t[2] = -sign * n[0];
    b[0] = k, b[1] = sign + n[1] * n[1] * a, b[2] = -n[1];
}

void ssg_turned_basis(const float n[3], float turn, float t[3], float b[3])
{
    float angle = turn * (float)(2.0 * M_PI), ca = cosf(angle), sa = sinf(angle);
    float t0[3], b0[3];
    basis(n, t0, b0);
    for (int i = 0; i < 3; i++) {
        t[i] = ca * t0[i] + sa * b0[i];
        b[i] = ca * b0[i] - sa * t0[i];
    }
}

void ssg_malley_dirs(const float *u, const float *c, const float *s, int count, float shift,
                     const float t[3], const float b[3], const float n[3],
                     float *restrict dx, float *restrict dy, float *restrict dz)
{
    const float *restrict tu = u, *restrict tc = c, *restrict ts = s;
    /* the frame in locals: the stores through dx, dy, dz cannot change it */
    const float t0 = t[0], t1 = t[1], t2 = t[2], b0 = b[0], b1 = b[1], b2 = b[2];
    const float n0 = n[0], n1 = n[1], n2 = n[2];
    for (int i = 0; i < count; i++) {
        float v = tu[i] + shift;
        v = v >= 1.0f ? v - 1.0f : v;
        float rr = sqrtf(v), z = sqrtf(1.0f - v);
        float x = rr * tc[i], y = rr * ts[i];
        dx[i] = x * t0 + y * b0 + z * n0;
        dy[i] = x * t1 + y * b1 + z * n1;
        dz[i] = x * t2 + y * b2 + z * n2;
    }
}
