/* direct_light_contact.c - the contact shadows of the CPU kernel (README.md, "Contact
 * shadows"): each pixel the maps leave lit marches towards the light over the G-buffer.
 * A step for every lit pixel of a chunk is one straight loop (the cheap half of the test:
 * the step's point behind the plane of the pixel it projects to, with that pixel's
 * shading normal), which most steps fail; the few that pass finish per pixel
 * (step_shadow). A pixel's shadow is the largest of its steps', so the order in which
 * they are found does not matter. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>

#include "direct_light_cpu.h"

/* The chunk's lit pixels and their marches, lane a the a-th. */
struct marches {
    int n;
    int pixel[DL_CHUNK];
    float p[3][DL_CHUNK], v[3][DL_CHUNK]; /* view-space start, unit direction to the light */
    float step[DL_CHUNK], reach[DL_CHUNK], soft[DL_CHUNK];
    float shadow[DL_CHUNK]; /* the largest so far */
    int alive[DL_CHUNK];    /* 0 once a step passed behind the camera */
};

/* The G-buffer pixel that image point (u, w) falls in, into *b; 0 when off the image. */
static int pixel_at(const struct dl_job *j, float u, float w, size_t *b)
{
    if (!(u >= 0.0f && w >= 0.0f && u < (float)j->w && w < (float)j->h))
        return 0;
    *b = (size_t)(int)w * j->w + (size_t)(int)u;
    return 1;
}

/* Pixel (u, w) of the G-buffer as a plane: its view-space point and the geometric normal
   of its surface, unit, turned towards the camera, from its neighbours' points (along each
   axis the one-sided difference whose depth changes least, the lower side on a tie, which
   stays on the pixel's own surface beside an edge). Not the shading normal: a mesh's
   interpolated normals tilt away from its flat triangles, and a march just above a
   triangle would pass "behind" the plane they make. 0 when off the image, background,
   without a surface neighbour on either axis, or seen nearly edge-on (cosine to the view
   ray under SSG_DIRECT_LIGHT_CONTACT_GRAZING, a silhouette: no plane there).
   direct_light.glsl's pixel_plane makes the same operations. */
static int pixel_plane(const struct dl_job *j, float u, float w, float pt[3], float n[3])
{
    size_t b;
    if (!pixel_at(j, u, w, &b))
        return 0;
    const float *pos = j->io->in[SSG_DIRECT_LIGHT_IN_POSITION]->data;
    const float *nrm = j->io->in[SSG_DIRECT_LIGHT_IN_NORMAL]->data;
    const size_t plane = (size_t)j->w * j->h;
    const int x = (int)(b % (size_t)j->w), y = (int)(b / (size_t)j->w);
    for (int i = 0; i < 3; i++)
        pt[i] = pos[i * plane + b];
    if (!dl_is_surface(nrm, plane, b))
        return 0;
    float e[2][3];
    for (int axis = 0; axis < 2; axis++) {
        int best = 0;
        float best_dz = INFINITY;
        for (int side = -1; side <= 1; side += 2) {
            int nx = axis ? x : x + side, ny = axis ? y + side : y;
            if (nx < 0 || ny < 0 || nx >= j->w || ny >= j->h)
                continue;
            size_t o = (size_t)ny * j->w + (size_t)nx;
            if (!dl_is_surface(nrm, plane, o))
                continue;
            float dz = fabsf(pos[2 * plane + o] - pt[2]);
            if (dz < best_dz) {
                best_dz = dz, best = side;
                for (int i = 0; i < 3; i++)
                    e[axis][i] = (pos[i * plane + o] - pt[i]) * (float)side;
            }
        }
        if (!best)
            return 0;
    }
    float c[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                  e[0][0] * e[1][1] - e[0][1] * e[1][0]};
    float len2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
    float facing = -(c[0] * pt[0] + c[1] * pt[1] + c[2] * pt[2]);
    float dist2 = pt[0] * pt[0] + pt[1] * pt[1] + pt[2] * pt[2];
    const float g2 = SSG_DIRECT_LIGHT_CONTACT_GRAZING * SSG_DIRECT_LIGHT_CONTACT_GRAZING;
    if (!(facing * facing > g2 * len2 * dist2))
        return 0;
    float s = (facing < 0.0f ? -1.0f : 1.0f) / sqrtf(len2);
    for (int i = 0; i < 3; i++)
        n[i] = c[i] * s;
    return 1;
}

/* How far view-space point q lies behind the plane (pt, n), away from the camera. */
static inline float behind(const float q[3], const float pt[3], const float n[3])
{
    return -(n[0] * (q[0] - pt[0]) + n[1] * (q[1] - pt[1]) + n[2] * (q[2] - pt[2]));
}

/* The shadow of march a's step s, whose point lies behind the shading plane of the pixel
   at image point (u, w) (march_steps found that): that pixel's geometric plane is crossed
   (an occluder) only where the G-buffer shows a surface at the crossing (it lies within
   a step of the plane of the pixel it projects to): past a step's edge the march runs
   behind the tread's extension in open air, and is not shadowed. An occluder crossed d
   behind shadows by min(1, d / soft); none (0), once d exceeds the reach (a thin object
   in front). */
static float step_shadow(const struct dl_job *j, const struct marches *M, int a, int s,
                         float u, float w)
{
    const float f = j->c->u.proj.f, cx = j->c->u.proj.cx, cy = j->c->u.proj.cy;
    const float step = M->step[a], reach = M->reach[a];
    const float v[3] = {M->v[0][a], M->v[1][a], M->v[2][a]};
    float t = step * (float)s, q[3], pt[3], n[3], xp[3], pt2[3], n2[3];
    for (int i = 0; i < 3; i++)
        q[i] = M->p[i][a] + t * v[i];
    if (!pixel_plane(j, u, w, pt, n))
        return 0.0f;
    float d = behind(q, pt, n);
    if (!(d > 0.0f && d < reach))
        return 0.0f;
    /* the crossing: where the last step's segment meets the plane */
    float before = behind((float[3]){q[0] - step * v[0], q[1] - step * v[1],
                                     q[2] - step * v[2]}, pt, n);
    float c = before < 0.0f ? before / (before - d) : 0.0f;
    for (int i = 0; i < 3; i++)
        xp[i] = q[i] - step * v[i] + c * step * v[i];
    if (!(xp[2] < 0.0f) ||
        !pixel_plane(j, cx + f * xp[0] / -xp[2], cy - f * xp[1] / -xp[2], pt2, n2))
        return 0.0f;
    if (!(fabsf(behind(xp, pt2, n2)) < step))
        return 0.0f; /* the crossing is not on a surface the camera sees */
    float o = d / M->soft[a];
    return o < 1.0f ? o : 1.0f;
}

/* Step s of every march: a march whose step lies behind the camera stops (and its later
   steps with it); cand[a] = 1 where the step lies behind the shading plane of a surface
   pixel at image point (us[a], ws[a]). Whether any is. */
SSG_VECTOR_CLONES
static int march_steps(const struct dl_job *j, struct marches *restrict M, int s,
                        int *restrict cand, float *restrict us, float *restrict ws)
{
    const float f = j->c->u.proj.f, cx = j->c->u.proj.cx, cy = j->c->u.proj.cy;
    const float fw = (float)j->w, fh = (float)j->h, lw = (float)(j->w - 1);
    const float lh = (float)(j->h - 1);
    const int width = j->w, plane = j->w * j->h;
    const float *pos = j->io->in[SSG_DIRECT_LIGHT_IN_POSITION]->data;
    const float *nrm = j->io->in[SSG_DIRECT_LIGHT_IN_NORMAL]->data;
    const float *pos1 = pos + plane, *pos2 = pos1 + plane;
    const float *nrm1 = nrm + plane, *nrm2 = nrm1 + plane;
    int any = 0;
    for (int a = 0; a < M->n; a++) {
        float t = M->step[a] * (float)s, q[3];
        for (int i = 0; i < 3; i++)
            q[i] = M->p[i][a] + t * M->v[i][a];
        int alive = M->alive[a] & (q[2] < 0.0f);
        float u = cx + f * q[0] / -q[2], w = cy - f * q[1] / -q[2];
        int in = alive & (u >= 0.0f) & (w >= 0.0f) & (u < fw) & (w < fh);
        /* pixel_at's pixel where in, a pixel of the image anyway (the loads stay gathers) */
        float cu = u > 0.0f ? u : 0.0f, cw = w > 0.0f ? w : 0.0f;
        int b = (int)(cw < lh ? cw : lh) * width + (int)(cu < lw ? cu : lw);
        const float pt[3] = {pos[b], pos1[b], pos2[b]}, n[3] = {nrm[b], nrm1[b], nrm2[b]};
        M->alive[a] = alive;
        cand[a] = in & (behind(q, pt, n) > 0.0f);
        us[a] = u, ws[a] = w;
        any |= cand[a];
    }
    return any;
}

/* The lit pixels' marches (v > 0) towards the light from their view-space points, over
   reach = contact x the maps' texel at the receiver. */
SSG_VECTOR_CLONES
static void march_start(const struct dl_job *j, int y, int x0, const struct dl_pixels *restrict px,
                        struct marches *restrict M)
{
    const float *r = j->c->u.rot, contact = j->c->p.contact;
    const float rot[9] = {r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8]};
    const int plane = j->w * j->h;
    const float *pos = j->io->in[SSG_DIRECT_LIGHT_IN_POSITION]->data + (size_t)y * j->w + x0;
    int n = 0;
    for (int i = 0; i < px->len; i++)
        if (px->v[i] > 0.0f) /* else the maps shadow it already */
            M->pixel[n++] = i;
    M->n = n;
    for (int a = 0; a < n; a++) {
        const int i = M->pixel[a];
        const float l[3] = {px->l[0][i], px->l[1][i], px->l[2][i]};
        for (int c = 0; c < 3; c++) {
            M->p[c][a] = pos[c * plane + i];
            M->v[c][a] = rot[3 * c] * l[0] + rot[3 * c + 1] * l[1] + rot[3 * c + 2] * l[2];
        }
        float reach = contact * px->texel[i];
        M->reach[a] = reach, M->shadow[a] = 0.0f, M->alive[a] = 1;
        M->step[a] = reach / (float)SSG_DIRECT_LIGHT_CONTACT_STEPS;
        M->soft[a] = 0.125f * reach;
    }
}

void dl_contact(const struct dl_job *j, int y, int x0, struct dl_pixels *px)
{
    struct marches M;
    march_start(j, y, x0, px, &M);
    for (int s = 1; s <= SSG_DIRECT_LIGHT_CONTACT_STEPS; s++) {
        int cand[DL_CHUNK];
        float us[DL_CHUNK], ws[DL_CHUNK];
        if (!march_steps(j, &M, s, cand, us, ws))
            continue; /* most steps: in free space */
        for (int a = 0; a < M.n; a++) {
            if (!cand[a] || M.shadow[a] == 1.0f)
                continue; /* a march already wholly shadowed stays so */
            float o = step_shadow(j, &M, a, s, us[a], ws[a]);
            M.shadow[a] = o > M.shadow[a] ? o : M.shadow[a];
        }
    }
    for (int a = 0; a < M.n; a++)
        px->v[M.pixel[a]] *= 1.0f - M.shadow[a];
}
