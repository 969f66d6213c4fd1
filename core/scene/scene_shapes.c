/* scene_shapes.c - tessellates the scene format's built-in primitives into world-space
 * triangle meshes (the same data the CPU ray tracer and a later GL rasteriser use), and
 * places loaded meshes with a translate / rotate / scale transform. See scene_shapes.h. */
#include "scene/scene_shapes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

void ssg_mesh_free(struct ssg_mesh *mesh)
{
    free(mesh->positions);
    free(mesh->normals);
    free(mesh->uvs);
    free(mesh->indices);
    free(mesh->tangents);
    free(mesh->colors);
    memset(mesh, 0, sizeof *mesh);
}

static enum ssg_err mesh_alloc(struct ssg_mesh *m, int vertices, int triangles)
{
    memset(m, 0, sizeof *m);
    m->vertex_count = vertices;
    m->triangle_count = triangles;
    m->positions = malloc(sizeof(float) * 3 * (size_t)vertices);
    m->normals = malloc(sizeof(float) * 3 * (size_t)vertices);
    m->uvs = malloc(sizeof(float) * 2 * (size_t)vertices);
    m->indices = malloc(sizeof(uint32_t) * 3 * (size_t)triangles);
    if (m->positions && m->normals && m->uvs && m->indices)
        return SSG_OK;
    ssg_mesh_free(m);
    return SSG_E_NOMEM;
}

static void mat_vec(const float r[9], const float v[3], float out[3])
{
    for (int i = 0; i < 3; i++)
        out[i] = r[3 * i] * v[0] + r[3 * i + 1] * v[1] + r[3 * i + 2] * v[2];
}

static void mat_mul(const float a[9], const float b[9], float out[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            out[3 * i + j] =
                a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
}

static void normalize3(float v[3])
{
    float len = sqrtf(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (len > 0.0f)
        v[0] /= len, v[1] /= len, v[2] /= len;
}

void ssg_euler_matrix(const float degrees[3], float r[9])
{
    float c[3], s[3];
    for (int i = 0; i < 3; i++) {
        float a = degrees[i] * (float)M_PI / 180.0f;
        c[i] = cosf(a);
        s[i] = sinf(a);
    }
    const float rx[9] = {1, 0, 0, 0, c[0], -s[0], 0, s[0], c[0]};
    const float ry[9] = {c[1], 0, s[1], 0, 1, 0, -s[1], 0, c[1]};
    const float rz[9] = {c[2], -s[2], 0, s[2], c[2], 0, 0, 0, 1};
    float zy[9];
    mat_mul(rz, ry, zy);
    mat_mul(zy, rx, r);
}

/* The shortest rotation taking +y onto unit n (Rodrigues' formula); half a turn about x
 * when n is -y, where the shortest rotation is not unique. */
static void rotation_from_y(const float n[3], float r[9])
{
    float c = n[1];
    if (c < -0.999999f) {
        const float flip[9] = {1, 0, 0, 0, -1, 0, 0, 0, -1};
        memcpy(r, flip, sizeof flip);
        return;
    }
    /* axis y x n = (n.z, 0, -n.x), |axis| = sin; R = I + [k]x + [k]x^2 / (1 + c) */
    float kx = n[2], kz = -n[0], f = 1.0f / (1.0f + c);
    const float rot[9] = {1 - kz * kz * f, -kz, kx * kz * f,
                          kz, c, -kx,
                          kx * kz * f, kx, 1 - kx * kx * f};
    memcpy(r, rot, sizeof rot);
}

static void put3(float *dst, float x, float y, float z)
{
    dst[0] = x, dst[1] = y, dst[2] = z;
}

static void put_tri(uint32_t *dst, uint32_t a, uint32_t b, uint32_t c)
{
    dst[0] = a, dst[1] = b, dst[2] = c;
}

/* Writes quad q (4 vertices from index 4q) of a mesh: corners in local space, transformed
 * by r and moved to center; a shared faceted normal; uvs over [0,1]^2. */
static void put_quad(struct ssg_mesh *m, int q, const float corners[4][3],
                     const float normal[3], const float r[9], const float center[3])
{
    static const float uv[4][2] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    float n[3];
    mat_vec(r, normal, n);
    normalize3(n);
    for (int k = 0; k < 4; k++) {
        float p[3];
        int v = 4 * q + k;
        mat_vec(r, corners[k], p);
        put3(&m->positions[3 * v], p[0] + center[0], p[1] + center[1], p[2] + center[2]);
        put3(&m->normals[3 * v], n[0], n[1], n[2]);
        m->uvs[2 * v] = uv[k][0];
        m->uvs[2 * v + 1] = uv[k][1];
    }
    uint32_t b = (uint32_t)(4 * q);
    put_tri(&m->indices[6 * q], b, b + 1, b + 2);
    put_tri(&m->indices[6 * q + 3], b, b + 2, b + 3);
}

enum ssg_err ssg_shape_plane(const float center[3], const float size[3], const float normal[3],
                             struct ssg_mesh *out)
{
    enum ssg_err e = mesh_alloc(out, 4, 2);
    if (e)
        return e;
    float n[3] = {normal[0], normal[1], normal[2]}, r[9];
    normalize3(n);
    rotation_from_y(n, r);
    float w = 0.5f * size[0], d = 0.5f * size[2];
    /* counter-clockwise seen from +y */
    const float corners[4][3] = {{-w, 0, -d}, {-w, 0, d}, {w, 0, d}, {w, 0, -d}};
    const float up[3] = {0, 1, 0};
    put_quad(out, 0, corners, up, r, center);
    return SSG_OK;
}

enum ssg_err ssg_shape_box(const float center[3], const float size[3], const float rotate[3],
                           struct ssg_mesh *out)
{
    enum ssg_err e = mesh_alloc(out, 24, 12);
    if (e)
        return e;
    float r[9];
    ssg_euler_matrix(rotate, r);
    /* each face is the +y face of a unit cube turned to face axis `a` with sign `s` */
    for (int f = 0; f < 6; f++) {
        int a = f / 2;
        float s = f % 2 ? -1.0f : 1.0f, h[3] = {0.5f * size[0], 0.5f * size[1], 0.5f * size[2]};
        float face_r[9], corners[4][3], n[3] = {0, 0, 0};
        n[a] = s;
        rotation_from_y(n, face_r);
        static const float unit[4][3] = {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}};
        for (int k = 0; k < 4; k++) {
            mat_vec(face_r, unit[k], corners[k]);
            for (int i = 0; i < 3; i++)
                corners[k][i] = roundf(corners[k][i]) * h[i];
        }
        put_quad(out, f, corners, n, r, center);
    }
    return SSG_OK;
}

static void sphere_vertex(struct ssg_mesh *m, int v, const float center[3], float radius,
                          float u, float t)
{
    float theta = t * (float)M_PI, phi = u * 2.0f * (float)M_PI;
    float n[3] = {sinf(theta) * sinf(phi), cosf(theta), sinf(theta) * cosf(phi)};
    put3(&m->normals[3 * v], n[0], n[1], n[2]);
    put3(&m->positions[3 * v], center[0] + radius * n[0], center[1] + radius * n[1],
         center[2] + radius * n[2]);
    m->uvs[2 * v] = u;
    m->uvs[2 * v + 1] = t;
}

enum ssg_err ssg_shape_sphere(const float center[3], float radius, int rings,
                              struct ssg_mesh *out)
{
    int segs = 2 * rings, cols = segs + 1;
    /* the first and last bands are fans: one triangle per segment, not two */
    enum ssg_err e = mesh_alloc(out, (rings + 1) * cols, 2 * segs * (rings - 1));
    if (e)
        return e;
    for (int i = 0; i <= rings; i++)
        for (int j = 0; j <= segs; j++)
            sphere_vertex(out, i * cols + j, center, radius, (float)j / (float)segs,
                          (float)i / (float)rings);
    uint32_t *t = out->indices;
    for (int i = 0; i < rings; i++) {
        for (int j = 0; j < segs; j++) {
            uint32_t a = (uint32_t)(i * cols + j), b = a + (uint32_t)cols;
            if (i > 0)
                put_tri(t, a, b, a + 1), t += 3;
            if (i < rings - 1)
                put_tri(t, a + 1, b, b + 1), t += 3;
        }
    }
    return SSG_OK;
}

void ssg_mesh_place(struct ssg_mesh *mesh, const float translate[3], const float rotate[3],
                    const float scale[3])
{
    float r[9];
    ssg_euler_matrix(rotate, r);
    for (int v = 0; v < mesh->vertex_count; v++) {
        float *p = &mesh->positions[3 * v], *n = &mesh->normals[3 * v];
        float sp[3] = {p[0] * scale[0], p[1] * scale[1], p[2] * scale[2]};
        float sn[3] = {n[0] / scale[0], n[1] / scale[1], n[2] / scale[2]};
        mat_vec(r, sp, p);
        mat_vec(r, sn, n);
        normalize3(n);
        for (int i = 0; i < 3; i++)
            p[i] += translate[i];
    }
    for (int v = 0; mesh->tangents && v < mesh->vertex_count; v++) { /* a direction */
        float *t = &mesh->tangents[4 * v];
        float st[3] = {t[0] * scale[0], t[1] * scale[1], t[2] * scale[2]};
        mat_vec(r, st, t);
        normalize3(t);
        t[3] = scale[0] * scale[1] * scale[2] < 0.0f ? -t[3] : t[3]; /* a mirror flips b */
    }
    if (scale[0] * scale[1] * scale[2] < 0.0f)
        for (int t = 0; t < mesh->triangle_count; t++) {
            uint32_t *i = &mesh->indices[3 * t], tmp = i[1];
            i[1] = i[2];
            i[2] = tmp;
        }
}

void ssg_mesh_bounds(const struct ssg_mesh *mesh, float lo[3], float hi[3])
{
    for (int v = 0; v < mesh->vertex_count; v++)
        for (int i = 0; i < 3; i++) {
            float p = mesh->positions[3 * v + i];
            lo[i] = p < lo[i] ? p : lo[i];
            hi[i] = p > hi[i] ? p : hi[i];
        }
}

/* Any unit vector orthogonal to unit n (Duff et al. 2017, as trace.h's frames). */
static void any_tangent(const float n[3], float t[3])
{
    float sign = n[2] >= 0.0f ? 1.0f : -1.0f, a = -1.0f / (sign + n[2]), b = n[0] * n[1] * a;
    put3(t, 1.0f + sign * n[0] * n[0] * a, sign * b, -sign * n[0]);
}

enum ssg_err ssg_mesh_tangents(struct ssg_mesh *m)
{
    if (!m->uvs || m->tangents || m->vertex_count < 1)
        return SSG_OK;
    size_t n = (size_t)m->vertex_count;
    double *sum = calloc(6 * n, sizeof *sum); /* per vertex: +u direction, then +v */
    m->tangents = malloc(4 * n * sizeof(float));
    if (!sum || !m->tangents) {
        free(sum);
        free(m->tangents);
        m->tangents = NULL;
        return SSG_E_NOMEM;
    }
    for (int t = 0; t < m->triangle_count; t++) {
        const uint32_t *k = &m->indices[3 * t];
        const float *p0 = &m->positions[3 * k[0]], *p1 = &m->positions[3 * k[1]];
        const float *p2 = &m->positions[3 * k[2]];
        double e1[3], e2[3], du1 = (double)m->uvs[2 * k[1]] - m->uvs[2 * k[0]];
        double dv1 = (double)m->uvs[2 * k[1] + 1] - m->uvs[2 * k[0] + 1];
        double du2 = (double)m->uvs[2 * k[2]] - m->uvs[2 * k[0]];
        double dv2 = (double)m->uvs[2 * k[2] + 1] - m->uvs[2 * k[0] + 1];
        double det = du1 * dv2 - du2 * dv1;
        if (det == 0.0)
            continue; /* no uv area: no direction of +u */
        for (int i = 0; i < 3; i++)
            e1[i] = (double)p1[i] - p0[i], e2[i] = (double)p2[i] - p0[i];
        for (int c = 0; c < 3; c++)
            for (int i = 0; i < 3; i++) {
                sum[6 * k[c] + i] += (dv2 * e1[i] - dv1 * e2[i]) / det;
                sum[6 * k[c] + 3 + i] += (du1 * e2[i] - du2 * e1[i]) / det;
            }
    }
    for (size_t v = 0; v < n; v++) {
        const float *nv = &m->normals[3 * v];
        const double *su = &sum[6 * v], *sv = &sum[6 * v + 3];
        double d = su[0] * nv[0] + su[1] * nv[1] + su[2] * nv[2], t[3];
        for (int i = 0; i < 3; i++)
            t[i] = su[i] - nv[i] * d;
        double len = sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        float *out = &m->tangents[4 * v];
        if (len > 0.0) {
            put3(out, (float)(t[0] / len), (float)(t[1] / len), (float)(t[2] / len));
        } else {
            any_tangent(nv, out);
        }
        double c[3] = {nv[1] * out[2] - nv[2] * out[1], nv[2] * out[0] - nv[0] * out[2],
                       nv[0] * out[1] - nv[1] * out[0]};
        out[3] = c[0] * sv[0] + c[1] * sv[1] + c[2] * sv[2] < 0.0 ? -1.0f : 1.0f;
    }
    free(sum);
    return SSG_OK;
}
