/* lightmap_fit.c - a directional light's map fitted to what the camera sees (lightmap.h,
 * SSG_LIGHTMAP_FIT_VIEW): the square in the light's plane around the view frustum clipped
 * to the scene's box. The scene fit spreads the map's texels over the whole bounding
 * sphere, most of it off screen (the table scene's 8 x 8 floor: a 0.05 leg is two texels
 * at 512); the seen part is what the shadows' texels are spent on here (after the usual
 * fitting of an orthographic shadow map to the view frustum, as cascaded shadow maps do
 * per cascade: Engel, "Cascaded Shadow Maps", ShaderX5, 2006, sec. 4.1.1, and Zhang et al.,
 * "Parallel-Split Shadow Maps", 2006).
 *
 * The seen part is the intersection of two convex solids, the frustum and the box: its
 * vertices are the vertices of each solid's faces clipped by the other's planes
 * (Sutherland and Hodgman, "Reentrant Polygon Clipping", CACM 1974), so both sets of faces
 * are clipped and every vertex kept. */
#include <float.h>
#include <math.h>

#include "graph/node.h"
#include "common/lightmap.h"
#include "common/trace.h"

/* A clipped polygon has at most its own 4 vertices plus one a clipping plane. */
enum { POLY_MAX = 4 + 6, POINTS_MAX = 12 * POLY_MAX, TURNS = 64 };

/* A half space n . p + w >= 0. */
struct plane {
    float n[3], w;
};

static float dot3(const float a[3], const float b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Clips polygon p (count vertices) by half space h in place; the new count. */
static int clip_poly(float p[POLY_MAX][3], int count, const struct plane *h)
{
    float out[POLY_MAX][3];
    int n = 0;
    for (int i = 0; i < count; i++) { /* a convex polygon gains at most one vertex */
        const float *a = p[i], *b = p[(i + 1) % count];
        float da = dot3(h->n, a) + h->w, db = dot3(h->n, b) + h->w;
        if (da >= 0.0f)
            for (int k = 0; k < 3; k++)
                out[n][k] = a[k];
        n += da >= 0.0f;
        if ((da >= 0.0f) == (db >= 0.0f))
            continue;
        float t = da / (da - db);
        for (int k = 0; k < 3; k++)
            out[n][k] = a[k] + t * (b[k] - a[k]);
        n++;
    }
    for (int i = 0; i < n; i++)
        for (int k = 0; k < 3; k++)
            p[i][k] = out[i][k];
    return n;
}

/* A convex solid as 8 corners (bit 0: x, 1: y, 2: z of the corner's side), its 6 quads
   over them and its 6 inward half spaces. */
struct solid {
    float c[8][3];
    struct plane h[6];
};

/* Corner indices of face f (axis f / 2, side f % 2), in order around it. */
static void face_corners(int f, int idx[4])
{
    int a = f / 2, s = (f % 2) << a, b = 1 << ((a + 1) % 3), c = 1 << ((a + 2) % 3);
    idx[0] = s, idx[1] = s | b, idx[2] = s | b | c, idx[3] = s | c;
}

/* The half spaces from the corners: each face's plane, turned to hold the centroid. */
static void solid_planes(struct solid *s)
{
    float mid[3] = {0, 0, 0};
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 3; k++)
            mid[k] += s->c[i][k] / 8.0f;
    for (int f = 0; f < 6; f++) {
        int q[4];
        face_corners(f, q);
        const float *p0 = s->c[q[0]], *p1 = s->c[q[1]], *p3 = s->c[q[3]];
        float e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
        float e2[3] = {p3[0] - p0[0], p3[1] - p0[1], p3[2] - p0[2]};
        struct plane *h = &s->h[f];
        h->n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        h->n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        h->n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        h->w = -dot3(h->n, p0);
        if (dot3(h->n, mid) + h->w < 0.0f) {
            for (int k = 0; k < 3; k++)
                h->n[k] = -h->n[k];
            h->w = -h->w;
        }
    }
}

static void box_solid(const float lo[3], const float hi[3], struct solid *s)
{
    for (int i = 0; i < 8; i++)
        for (int k = 0; k < 3; k++)
            s->c[i][k] = (i >> k) & 1 ? hi[k] : lo[k];
    solid_planes(s);
}

/* The view frustum, near_z to far_z, over the whole image (guard band included). */
static void frustum_solid(const struct ssg_lightmap_view *view, struct solid *s)
{
    const struct ssg_frame *fr = view->frame;
    float rot[9], eye[3];
    ssg_camera_frame(view->camera, rot, eye);
    float t = tanf(0.5f * fr->fov_y * (float)M_PI / 180.0f);
    float ty = t * (float)ssg_frame_full_height(fr) / (float)fr->height;
    float tx = t * (float)ssg_frame_full_width(fr) / (float)fr->height;
    for (int i = 0; i < 8; i++) {
        float d = (i >> 2) & 1 ? fr->far_z : fr->near_z;
        float v[3] = {(i & 1 ? tx : -tx) * d, (i & 2 ? ty : -ty) * d, -d};
        for (int k = 0; k < 3; k++) /* world = eye + rot^T view */
            s->c[i][k] = eye[k] + rot[k] * v[0] + rot[3 + k] * v[1] + rot[6 + k] * v[2];
    }
    solid_planes(s);
}

/* The faces of a clipped by b's half spaces, their vertices appended to pts[*n ..]. */
static void clipped_faces(const struct solid *a, const struct solid *b, float (*pts)[3],
                          int *n)
{
    for (int f = 0; f < 6; f++) {
        int q[4];
        float poly[POLY_MAX][3];
        face_corners(f, q);
        for (int i = 0; i < 4; i++)
            for (int k = 0; k < 3; k++)
                poly[i][k] = a->c[q[i]][k];
        int count = 4;
        for (int h = 0; h < 6 && count > 0; h++)
            count = clip_poly(poly, count, &b->h[h]);
        for (int i = 0; i < count && *n < POINTS_MAX; i++, (*n)++)
            for (int k = 0; k < 3; k++)
                pts[*n][k] = poly[i][k];
    }
}

/* The square over the points (a, b in the face's plane) turned by the angle of turn t in
   the plane: its side, and its centre in (a, b). */
static float square_at(const float (*ab)[2], int n, int t, float centre[2])
{
    double ang = 0.5 * M_PI * t / TURNS;
    float c = (float)cos(ang), s = (float)sin(ang);
    float lo[2] = {FLT_MAX, FLT_MAX}, hi[2] = {-FLT_MAX, -FLT_MAX};
    for (int i = 0; i < n; i++) {
        float r[2] = {c * ab[i][0] + s * ab[i][1], -s * ab[i][0] + c * ab[i][1]};
        for (int k = 0; k < 2; k++) {
            lo[k] = fminf(lo[k], r[k]);
            hi[k] = fmaxf(hi[k], r[k]);
        }
    }
    float mr[2] = {0.5f * (lo[0] + hi[0]), 0.5f * (lo[1] + hi[1])};
    centre[0] = c * mr[0] - s * mr[1], centre[1] = s * mr[0] + c * mr[1];
    return fmaxf(hi[0] - lo[0], hi[1] - lo[1]);
}

/* Moves f to the square of side `side` turned by turn t, centred at (a, b) of its plane. */
static void place(struct ssg_lightmap_face *f, int t, const float centre[2], float side,
                  int res)
{
    double ang = 0.5 * M_PI * t / TURNS;
    float c = (float)cos(ang), s = (float)sin(ang), u[3], v[3];
    for (int k = 0; k < 3; k++) {
        u[k] = c * f->u[k] + s * f->v[k];
        v[k] = -s * f->u[k] + c * f->v[k];
        f->origin[k] += centre[0] * f->u[k] + centre[1] * f->v[k];
    }
    for (int k = 0; k < 3; k++)
        f->u[k] = u[k], f->v[k] = v[k];
    f->half = 0.5f * side * (float)res / (float)(res - 2 * SSG_LIGHTMAP_FIT_PAD);
}

int ssg_lightmap_fit_view(const struct ssg_lightmap_view *view, const float lo[3],
                          const float hi[3], struct ssg_lightmap_face *f)
{
    if (!(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2]) ||
        view->res <= 4 * SSG_LIGHTMAP_FIT_PAD)
        return 0;
    struct solid box, frustum;
    box_solid(lo, hi, &box);
    frustum_solid(view, &frustum);
    float pts[POINTS_MAX][3], ab[POINTS_MAX][2];
    int n = 0;
    clipped_faces(&box, &frustum, pts, &n);
    clipped_faces(&frustum, &box, pts, &n);
    for (int i = 0; i < n; i++) {
        float d[3] = {pts[i][0] - f->origin[0], pts[i][1] - f->origin[1],
                      pts[i][2] - f->origin[2]};
        ab[i][0] = dot3(d, f->u), ab[i][1] = dot3(d, f->v);
    }
    int best = -1;
    float best_side = FLT_MAX, best_centre[2] = {0, 0};
    for (int t = 0; t < TURNS && n > 0; t++) {
        float centre[2], side = square_at((const float(*)[2])ab, n, t, centre);
        if (side < best_side)
            best = t, best_side = side, best_centre[0] = centre[0], best_centre[1] = centre[1];
    }
    float pad = (float)view->res / (float)(view->res - 2 * SSG_LIGHTMAP_FIT_PAD);
    if (best < 0 || !(0.5f * best_side * pad < f->half))
        return 0;
    place(f, best, best_centre, best_side, view->res);
    return 1;
}
