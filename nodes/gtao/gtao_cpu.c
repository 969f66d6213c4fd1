/* gtao_cpu.c - CPU kernel of the `gtao` node (method and geometry in gtao.c): one pixel at
 * a time, slices in order, per step the +D sample then the -D one, slices summed in
 * order. Rows go to ssg_parallel_rows in fixed bands and a pixel depends only on the
 * inputs, so the output does not depend on the thread count. gtao.glsl performs the same
 * IEEE operations in the same order (no fused multiply-adds: C11 mode does not contract
 * and x86-64-v2 has no FMA); only the transcendental functions (atan2, acos, cos, sin) may
 * round differently on GL. */
#include <math.h>
#include <stdint.h>

#include "common/sampling.h"
#include "gtao.h"

enum { ROWS_PER_BAND = 16 };

/* |proj N|^2 below this: the slice lies within asin(0.1) of the tangent plane (gtao.c). */
#define SLICE_MIN 0.01f
#define HALF_PI 1.57079632679489661923f

struct job {
    const struct ssg_gtao_consts *c;
    const float *nrm[3];
    const float *depth;  /* plane the depth is read from */
    float depth_sign;    /* depth = depth_sign * plane: 1 for depth, -1 for z */
    const float *rot;    /* the tile, cos plane then sin plane; NULL = none */
    int n;               /* tile side */
    float *out, *bent[3];
    int w, h;
};

/* What a pixel's slices share. */
struct pix {
    int x, y;
    float dp, au, av;      /* depth, a_u, a_v: P = dp (a_u, a_v, -1) */
    float v[3], n[3];      /* V, unit N */
    float e1x, e1z, e2[3]; /* e1 = (e1x, 0, e1z), e2 = V x e1 */
    float vn;              /* V.N, floored at 1e-6 */
    float step;            /* march length / steps */
    float u;               /* step jitter in (0, 1] */
    float co, si;          /* rotation of the tile */
};

/* The horizon of one side of a slice: its cosine, and the lowest one, cos(n -/+ pi/2). */
struct side {
    float hc, low;
};

static float depth_at(const struct job *j, int x, int y)
{
    float d = j->depth_sign * j->depth[(size_t)y * (size_t)j->w + (size_t)x];
    return (d > 0.0f) & (d <= 3.0e38f) ? d : -1.0f;
}

/* 1 - interleaved gradient noise (Jimenez 2014) at the pixel: in (0, 1]. */
static float step_jitter(int x, int y)
{
    float a = 0.06711056f * (float)x + 0.00583715f * (float)y;
    float b = 52.9829189f * (a - floorf(a));
    return 1.0f - (b - floorf(b));
}

/* Sets up pixel (x, y); returns 0 on background (depth 0, no normal, garbage). */
static int setup_pixel(const struct job *j, int x, int y, struct pix *p)
{
    const struct ssg_gtao_consts *c = j->c;
    size_t o = (size_t)y * (size_t)j->w + (size_t)x;
    float nx = j->nrm[0][o], ny = j->nrm[1][o], nz = j->nrm[2][o];
    float nn = nx * nx + ny * ny + nz * nz;
    p->dp = j->depth_sign * j->depth[o];
    if (!((p->dp > 0.0f) & (p->dp <= 3.0e38f) & (nn > 1e-12f)))
        return 0;
    if (fabsf(nn - 1.0f) > 1e-5f) {
        float inv = 1.0f / sqrtf(nn);
        nx *= inv, ny *= inv, nz *= inv;
    }
    p->n[0] = nx, p->n[1] = ny, p->n[2] = nz;
    const float invf = 1.0f / c->proj.f, radius = c->p.radius;
    p->x = x, p->y = y;
    p->au = ((float)x + 0.5f - c->proj.cx) * invf;
    p->av = -((float)y + 0.5f - c->proj.cy) * invf;
    float il = 1.0f / sqrtf(p->au * p->au + p->av * p->av + 1.0f);
    p->v[0] = -p->au * il, p->v[1] = -p->av * il, p->v[2] = il;
    p->e1x = c->e1[x], p->e1z = c->e1[j->w + x];
    p->e2[0] = p->v[1] * p->e1z;
    p->e2[1] = p->v[2] * p->e1x - p->v[0] * p->e1z;
    p->e2[2] = -p->v[1] * p->e1x;
    float vn = p->v[0] * nx + p->v[1] * ny + p->v[2] * nz;
    p->vn = vn > 1e-6f ? vn : 1e-6f;
    /* f R / den reaches every point of the slice within R (gtao.c). */
    float near = p->dp - radius, half = 0.5f * p->dp;
    float rp = c->proj.f * radius / (near > half ? near : half);
    float cap = c->p.max_screen_radius;
    rp = cap > 0.0f && rp > cap ? cap : rp;
    p->step = rp / (float)c->p.steps;
    p->u = step_jitter(x, y);
    p->co = 1.0f, p->si = 0.0f;
    if (j->rot) {
        size_t cell = (size_t)(y % j->n) * (size_t)j->n + (size_t)(x % j->n);
        p->co = j->rot[cell];
        p->si = j->rot[(size_t)j->n * (size_t)j->n + cell];
    }
    return 1;
}

/* One sample at pixel offset sg (ou, ov): its horizon cosine, faded by distance, raises
   (or with thickness lowers) the side's horizon. d, m are D and M = V x D; al, be fold
   the projection along the tangent plane (hbao_cpu.c place_step). */
static void sample(const struct job *j, const struct pix *p, const float d[3],
                   const float m[3], float al, float be, float sg, float ou, float ov,
                   struct side *s)
{
    const struct ssg_gtao_consts *c = j->c;
    float qx = (float)p->x + sg * ou, qy = (float)p->y + sg * ov;
    if (!(qx >= 0.0f && qx < (float)j->w && qy >= 0.0f && qy < (float)j->h))
        return;
    float dq = depth_at(j, (int)qx, (int)qy);
    if (dq < 0.0f)
        return;
    const float invf = 1.0f / c->proj.f;
    float aqu = (qx + 0.5f - c->proj.cx) * invf, aqv = -(qy + 0.5f - c->proj.cy) * invf;
    float hx = dq * aqu - p->dp * p->au, hy = dq * aqv - p->dp * p->av, hz = p->dp - dq;
    float hv = hx * p->v[0] + hy * p->v[1] + hz * p->v[2];
    float hd = hx * d[0] + hy * d[1] + hz * d[2];
    float hm = hx * m[0] + hy * m[1] + hz * m[2];
    float pv = hv + hm * al, pd = sg * (hd + hm * be);
    if (!(pd > fabsf(hm)))
        return; /* more off the slice than along it, or P's own pixel */
    float r = sqrtf(hx * hx + hy * hy + hz * hz);
    float w = c->p.falloff > 0.0f ? r * c->fall_mul + c->fall_add : (r <= c->p.radius);
    w = w < 0.0f ? 0.0f : w;
    w = w < 1.0f ? w : 1.0f;
    float shc = pv / sqrtf(pv * pv + pd * pd);
    shc = s->low + w * (shc - s->low);
    if (shc > s->hc)
        s->hc = shc;
    else if (w > 0.0f && c->p.thickness > 0.0f)
        s->hc = s->hc + c->p.thickness * (shc - s->hc);
}

/* A side's horizon cosine within this of its lowest counts as no horizon: samples of P's
   own plane land on the tangent only up to float rounding (gtao.c). */
#define OPEN_EPS 1e-5f

/* One side of a slice: its horizon angle h from V (sg = 1: +D, h2; sg = -1: -D, h1), half
   the inner integral, 1/4 (cos n + 2 h sin n - cos(2 h - n)), and its share of the bent
   normal's t0 and t1 (gtao.c). A side without a horizon lies at the hemisphere's limit
   h = n + sg pi/2, where every term is algebraic in cos n, sin n (cos(2 h - n) = -cos n,
   sin(h - n) = sg, sin(3 h - n) = -sg cos 2n, sin(h + n) = sg cos 2n, cos(3 h - n) =
   sg sin 2n, cos(h + n) = -sg sin 2n): no trigonometry, and exactly the open value. */
struct arc {
    float a, t0, t1;
};

static struct arc side_arc(const struct side *s, float sg, float n, float cn, float sn)
{
    float lim = n + sg * HALF_PI;
    if (!(s->hc > s->low + OPEN_EPS)) {
        float c2 = cn * cn - sn * sn, s2 = 2.0f * sn * cn;
        return (struct arc){0.25f * (cn + 2.0f * lim * sn + cn), sg * (6.0f - 2.0f * c2),
                            2.0f * sg * s2};
    }
    float h = sg * acosf(s->hc);
    /* Clamped to the normal's hemisphere (sec. 4.1). */
    h = sg > 0.0f ? (h < lim ? h : lim) : (h > lim ? h : lim);
    return (struct arc){0.25f * (cn + 2.0f * h * sn - cosf(2.0f * h - n)),
                        6.0f * sinf(h - n) - sinf(3.0f * h - n) - 3.0f * sinf(h + n),
                        -cosf(3.0f * h - n) - 3.0f * cosf(h + n)};
}

/* Slice k: adds |proj N| a(h1, h2, n) to *vis, the open value to *open, and the slice's
   bent-normal term to bent. */
static void slice(const struct job *j, const struct pix *p, int k, float *vis, float *open,
                  float bent[3])
{
    const struct ssg_gtao_consts *c = j->c;
    float dc = c->slice_cos[k], ds = c->slice_sin[k];
    float cs = dc * p->co - ds * p->si, sn = ds * p->co + dc * p->si;
    float d[3] = {cs * p->e1x + sn * p->e2[0], sn * p->e2[1], cs * p->e1z + sn * p->e2[2]};
    float m[3] = {cs * p->e2[0] - sn * p->e1x, cs * p->e2[1], cs * p->e2[2] - sn * p->e1z};
    float dn = d[0] * p->n[0] + d[1] * p->n[1] + d[2] * p->n[2];
    float mn = m[0] * p->n[0] + m[1] * p->n[1] + m[2] * p->n[2];
    float vn = p->vn, sl = vn * vn + dn * dn;
    if (!(sl >= SLICE_MIN))
        return;
    float pl = sqrtf(sl), n = atan2f(dn, vn), cn = vn / pl, snn = dn / pl;
    float isl = mn / sl, al = isl * vn, be = isl * dn;
    struct side pos = {-snn, -snn}, neg = {snn, snn};
    float su = (d[0] + p->au * d[2]) * p->step, sv = -(d[1] + p->av * d[2]) * p->step;
    for (int s = 0; s < c->p.steps; s++) {
        float t = (float)s + p->u;
        float ou = nearbyintf(su * t), ov = nearbyintf(sv * t);
        sample(j, p, d, m, al, be, 1.0f, ou, ov, &pos);
        sample(j, p, d, m, al, be, -1.0f, ou, ov, &neg);
    }
    struct arc a1 = side_arc(&neg, -1.0f, n, cn, snn), a2 = side_arc(&pos, 1.0f, n, cn, snn);
    float lim1 = n - HALF_PI, lim2 = n + HALF_PI;
    *vis += pl * (a1.a + a2.a);
    *open += pl * (0.25f * (cn + 2.0f * lim1 * snn + cn) + 0.25f * (cn + 2.0f * lim2 * snn + cn));
    /* Bent normal: the slice's mean direction t0 D + t1 V (XeGTAO's closed form). */
    float t0 = (a1.t0 + a2.t0 + 16.0f * snn) / 12.0f;
    float t1 = (a1.t1 + a2.t1 + 8.0f * cn) / 12.0f;
    for (int i = 0; i < 3; i++)
        bent[i] += pl * (t0 * d[i] + t1 * p->v[i]);
}

static void pixel(const struct job *j, int x, int y)
{
    size_t o = (size_t)y * (size_t)j->w + (size_t)x, plane = (size_t)j->w * (size_t)j->h;
    float *bent = j->bent[0];
    struct pix p;
    if (!setup_pixel(j, x, y, &p)) {
        j->out[o] = 1.0f;
        bent[o] = bent[plane + o] = bent[2 * plane + o] = 0.0f;
        return;
    }
    float vis = 0.0f, open = 0.0f, b[3] = {0.0f, 0.0f, 0.0f};
    for (int k = 0; k < j->c->p.slices; k++)
        slice(j, &p, k, &vis, &open, b);
    float v = open > 0.0f ? vis / open : 1.0f;
    v = v > 0.0f ? v : 0.0f;
    v = v < 1.0f ? v : 1.0f;
    j->out[o] = j->c->p.power == 1.0f ? v : powf(v, j->c->p.power);
    float bl = sqrtf(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    /* No slice (all grazing): the normal itself. */
    float ib = bl > 0.0f ? 1.0f / bl : 0.0f;
    for (int i = 0; i < 3; i++)
        bent[(size_t)i * plane + o] = bl > 0.0f ? b[i] * ib : p.n[i];
}

static void band(void *user, int y0, int y1)
{
    const struct job *j = user;
    for (int y = y0; y < y1; y++)
        for (int x = 0; x < j->w; x++)
            pixel(j, x, y);
}

enum ssg_err ssg_gtao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                              const struct ssg_io *io)
{
    const struct ssg_gtao_consts *c = consts;
    const struct ssg_image *pos = io->in[SSG_GTAO_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_GTAO_IN_NORMAL];
    const struct ssg_image *rot = io->in[SSG_GTAO_IN_ROTATION];
    const struct ssg_image *dep = io->in[SSG_GTAO_IN_DEPTH];
    struct job j = {.c = c, .w = pos->width, .h = pos->height};
    j.out = io->out[SSG_GTAO_OUT_OUT]->data;
    j.bent[0] = io->out[SSG_GTAO_OUT_BENT_NORMAL]->data;
    for (int ch = 0; ch < 3; ch++)
        j.nrm[ch] = ssg_image_plane(nrm, ch);
    j.depth = dep ? dep->data : ssg_image_plane(pos, 2);
    j.depth_sign = dep ? 1.0f : -1.0f;
    j.rot = rot ? rot->data : NULL;
    j.n = rot ? rot->width : 1;
    ssg_parallel_rows(j.h, ROWS_PER_BAND, band, &j);
    return SSG_OK;
}
