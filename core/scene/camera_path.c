/* camera_path.c - a scene's camera path evaluated at a time (camera_path.h): centripetal
 * Catmull-Rom through camera keys, or an orbit. Everything in double, rounded to the
 * camera's floats at the end, so a frame's camera is the same on every machine and run. */
#include <math.h>
#include <string.h>

#include "scene/camera_path.h"

int ssg_camera_path_active(const struct ssg_camera_path *path)
{
    return path->key_count >= 2 || path->has_orbit;
}

int ssg_camera_path_piece(const struct ssg_camera_path *path, double t)
{
    int piece = 0;
    for (int i = 1; i < path->key_count && path->keys[i].time <= t; i++)
        piece += path->keys[i].cut;
    return piece;
}

static double distance3(const float a[3], const float b[3])
{
    double d[3] = {(double)b[0] - a[0], (double)b[1] - a[1], (double)b[2] - a[2]};
    return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

/* The centripetal Catmull-Rom segment from p1 (u = 0) to p2 (u = 1) with neighbours p0
   and p3, in the Barry-Goldman pyramid form: knots spaced by the square root of the
   distance between points, which never cusps or self-intersects within a segment (Yuksel,
   Schaefer and Keyser 2011). A neighbour that coincides with its end point (a duplicated
   end key) has a zero knot interval; its first-level lerp is that point. */
static void catmull_rom(const float p0[3], const float p1[3], const float p2[3],
                        const float p3[3], double u, float out[3])
{
    double d01 = sqrt(distance3(p0, p1)), d12 = sqrt(distance3(p1, p2)),
           d23 = sqrt(distance3(p2, p3));
    if (d12 == 0.0) {
        memcpy(out, p1, 3 * sizeof *out);
        return;
    }
    double t1 = d01, t2 = t1 + d12, t3 = t2 + d23, t = t1 + u * d12;
    for (int k = 0; k < 3; k++) {
        double a1 = d01 > 0 ? ((t1 - t) * p0[k] + t * p1[k]) / d01 : p1[k];
        double a2 = ((t2 - t) * p1[k] + (t - t1) * p2[k]) / d12;
        double a3 = d23 > 0 ? ((t3 - t) * p2[k] + (t - t2) * p3[k]) / d23 : p2[k];
        double b1 = ((t2 - t) * a1 + t * a2) / t2;
        double b2 = ((t3 - t) * a2 + (t - t1) * a3) / (t3 - t1);
        out[k] = (float)(((t2 - t) * b1 + (t - t1) * b2) / d12);
    }
}

/* The first and last key of the piece time t falls in. */
static void piece_bounds(const struct ssg_camera_path *path, double t, int *first, int *last)
{
    int a = 0;
    for (int i = 1; i < path->key_count && path->keys[i].time <= t; i++)
        if (path->keys[i].cut)
            a = i;
    int b = a + 1;
    while (b < path->key_count && !path->keys[b].cut)
        b++;
    *first = a;
    *last = b - 1;
}

static void key_camera(const struct ssg_camera_path *path, const struct ssg_camera_key *k,
                       struct ssg_camera *out)
{
    memcpy(out->position, k->position, sizeof out->position);
    memcpy(out->target, k->target, sizeof out->target);
    memcpy(out->up, k->up, sizeof out->up);
    out->fov_y = k->fov_y;
    out->near_z = path->near_z;
    out->far_z = path->far_z;
}

static void eval_keys(const struct ssg_camera_path *path, double t, struct ssg_camera *out)
{
    int a, b;
    piece_bounds(path, t, &a, &b);
    const struct ssg_camera_key *keys = path->keys;
    if (t <= keys[a].time || t >= keys[b].time) { /* clamped: before, after, or held */
        key_camera(path, &keys[t <= keys[a].time ? a : b], out);
        return;
    }
    int k = a;
    while (k + 1 < b && keys[k + 1].time <= t)
        k++;
    double u = (t - keys[k].time) / (keys[k + 1].time - keys[k].time);
    if (u <= 0.0) { /* exactly on a key: its own values, no rounding */
        key_camera(path, &keys[k], out);
        return;
    }
    const struct ssg_camera_key *k0 = &keys[k > a ? k - 1 : k], *k1 = &keys[k],
                                *k2 = &keys[k + 1], *k3 = &keys[k + 2 <= b ? k + 2 : k + 1];
    catmull_rom(k0->position, k1->position, k2->position, k3->position, u, out->position);
    catmull_rom(k0->target, k1->target, k2->target, k3->target, u, out->target);
    double up[3], len = 0;
    for (int i = 0; i < 3; i++) {
        up[i] = (1.0 - u) * k1->up[i] + u * k2->up[i];
        len += up[i] * up[i];
    }
    len = sqrt(len);
    for (int i = 0; i < 3; i++) /* opposite ups cancel: keep the earlier key's */
        out->up[i] = len > 0 ? (float)(up[i] / len) : k1->up[i];
    out->fov_y = (float)((1.0 - u) * k1->fov_y + u * k2->fov_y);
    out->near_z = path->near_z;
    out->far_z = path->far_z;
}

/* The orbit's horizontal axes: e1 is +z made perpendicular to up (+x when up is along z),
   e2 = up x e1, so start = 0 puts the camera on the +z side and 90 on the +x side for
   up = +y. */
static void orbit_axes(const float up[3], double e1[3], double e2[3])
{
    double axis[3] = {0, 0, 1};
    if (fabs(up[2]) > 0.999)
        axis[0] = 1, axis[2] = 0;
    double d = axis[0] * up[0] + axis[1] * up[1] + axis[2] * up[2], len = 0;
    for (int i = 0; i < 3; i++) {
        e1[i] = axis[i] - d * up[i];
        len += e1[i] * e1[i];
    }
    for (int i = 0; i < 3; i++)
        e1[i] /= sqrt(len);
    e2[0] = up[1] * e1[2] - up[2] * e1[1];
    e2[1] = up[2] * e1[0] - up[0] * e1[2];
    e2[2] = up[0] * e1[1] - up[1] * e1[0];
}

static void eval_orbit(const struct ssg_camera_path *path, double t, struct ssg_camera *out)
{
    const struct ssg_orbit *o = &path->orbit;
    double e1[3], e2[3];
    orbit_axes(o->up, e1, e2);
    double turns = t / o->period;
    double angle = (o->start / 360.0 + (turns - floor(turns))) * 2.0 * 3.14159265358979323846;
    for (int i = 0; i < 3; i++) {
        out->position[i] = (float)(o->target[i] + o->radius * (cos(angle) * e1[i] +
                                                                sin(angle) * e2[i]) +
                                   o->height * o->up[i]);
        out->target[i] = o->target[i];
        out->up[i] = o->up[i];
    }
    out->fov_y = o->fov_y;
    out->near_z = path->near_z;
    out->far_z = path->far_z;
}

void ssg_camera_path_eval(const struct ssg_camera_path *path, double t, struct ssg_camera *out)
{
    if (path->has_orbit)
        eval_orbit(path, t, out);
    else if (path->key_count >= 2)
        eval_keys(path, t, out);
}

void ssg_camera_path_frame(const struct ssg_camera_path *path, int frame,
                           struct ssg_camera *out, int *cut)
{
    /* key times are the scene file's floats: a frame time rounded to float meets a key
       written at that time (frame 3 at 30 fps is the key at time=0.1) */
    double t = (float)(frame / path->fps), before = (float)((frame - 1) / path->fps);
    ssg_camera_path_eval(path, t, out);
    *cut = frame > 0 && ssg_camera_path_piece(path, t) != ssg_camera_path_piece(path, before);
}

int ssg_camera_differs(const struct ssg_camera *a, const struct ssg_camera *b)
{
    return memcmp(a->position, b->position, sizeof a->position) ||
           memcmp(a->target, b->target, sizeof a->target) ||
           memcmp(a->up, b->up, sizeof a->up) || a->fov_y != b->fov_y ||
           a->near_z != b->near_z || a->far_z != b->far_z;
}

void ssg_camera_shift(struct ssg_camera *c, float offset)
{
    float f[3], r[3];
    for (int k = 0; k < 3; k++)
        f[k] = c->target[k] - c->position[k];
    r[0] = f[1] * c->up[2] - f[2] * c->up[1];
    r[1] = f[2] * c->up[0] - f[0] * c->up[2];
    r[2] = f[0] * c->up[1] - f[1] * c->up[0];
    float len = sqrtf(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    for (int k = 0; k < 3 && len > 0; k++) {
        c->position[k] += offset * r[k] / len;
        c->target[k] += offset * r[k] / len;
    }
}
