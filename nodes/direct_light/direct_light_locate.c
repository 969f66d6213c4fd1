/* direct_light_locate.c - where each of a chunk's lit pixels falls on a light's maps, in
 * lanes (direct_light_cpu.h, "Why lanes"): the normal offset, the cube face, the
 * projection and the receiver plane of every pixel as one straight loop (the face's frame
 * a gather from the light's few faces), then the turn of its tap disc. */
#include "common/vector_loops.h" /* first: see there */
#include <math.h>

#include "direct_light_cpu.h"

/* A light's faces (6 a cube, else 1; a tiled map's first) as the lanes gather them. */
struct frames {
    float origin[3][SSG_LIGHTMAP_CUBE_FACES], axis[3][SSG_LIGHTMAP_CUBE_FACES];
    float u[3][SSG_LIGHTMAP_CUBE_FACES], v[3][SSG_LIGHTMAP_CUBE_FACES];
    float half[SSG_LIGHTMAP_CUBE_FACES];
};

/* What the lanes read of the light and the parameters. */
struct light_in {
    float pos[3], texel, normal_offset, offset, res;
    int point, cube, first; /* first: its first face's first map element (int indices) */
    int face_elements;      /* R^2 */
};

/* The lit pixels' world points, normals and directions to the light, lane by lane. */
struct receivers {
    float p[3][DL_CHUNK], n[3][DL_CHUNK], l[3][DL_CHUNK];
};

/* The receiver p (normal n, unit direction l to the light) on the light's maps, moved
   along its normal first (the normal offset, normal_offset x sin(N, L) texels), as lane a
   of L: the face a point light's cube puts it on, its texel coordinates and distance
   (ssg_lightmap_project on that face), and its plane n . (X - q) = 0 for the taps' limits.
   point, cube: the light's kind, a constant where this is inlined. */
static inline __attribute__((always_inline)) void
locate_lanes(const struct receivers *restrict R, const struct light_in *in,
             const struct frames *F, int point, int cube, struct dl_lanes *restrict L)
{
    const float res = in->res; /* read once: a load under a condition does not vectorise */
    for (int a = 0; a < L->count; a++) {
        const float p[3] = {R->p[0][a], R->p[1][a], R->p[2][a]};
        const float n[3] = {R->n[0][a], R->n[1][a], R->n[2][a]};
        const float l[3] = {R->l[0][a], R->l[1][a], R->l[2][a]};
        float cosine = n[0] * l[0] + n[1] * l[1] + n[2] * l[2], c2 = 1.0f - cosine * cosine;
        float sine = sqrtf(c2 > 0.0f ? c2 : 0.0f);
        const float e[3] = {p[0] - in->pos[0], p[1] - in->pos[1], p[2] - in->pos[2]};
        float texel = point ? in->texel * sqrtf(e[0] * e[0] + e[1] * e[1] + e[2] * e[2])
                            : in->texel; /* a texel at the receiver: 2 d / R on a cube */
        float lift = in->normal_offset * texel * sine, q[3];
        for (int i = 0; i < 3; i++)
            q[i] = p[i] + lift * n[i];
        const float d[3] = {q[0] - in->pos[0], q[1] - in->pos[1], q[2] - in->pos[2]};
        int f = cube ? ssg_lightmap_cube_face(d) : 0;
        float r = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), dd[3], axis[3], u[3], v[3];
        for (int i = 0; i < 3; i++) {
            dd[i] = q[i] - F->origin[i][f];
            axis[i] = F->axis[i][f], u[i] = F->u[i][f], v[i] = F->v[i][f];
        }
        float depth = dd[0] * axis[0] + dd[1] * axis[1] + dd[2] * axis[2];
        float du = dd[0] * u[0] + dd[1] * u[1] + dd[2] * u[2];
        float dv = dd[0] * v[0] + dd[1] * v[1] + dd[2] * v[2];
        float half = F->half[f], scale = 1.0f / (point ? depth * half : half);
        int behind = point && depth <= 0.0f; /* not in front of the face: (0, 0) */
        L->x[a] = behind ? 0.0f : (du * scale + 1.0f) * 0.5f * res;
        L->y[a] = behind ? 0.0f : (dv * scale + 1.0f) * 0.5f * res;
        L->r[a] = point ? r : depth, L->z[a] = depth, L->texel[a] = texel;
        L->bias[a] = in->offset * texel;
        float nu = n[0] * u[0] + n[1] * u[1] + n[2] * u[2];
        float nv = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
        L->gx[a] = texel * nu / cosine, L->gy[a] = texel * nv / cosine;
        float nq = 0.0f;
        for (int i = 0; i < 3; i++) {
            L->n[i][a] = n[i];
            nq += n[i] * (q[i] - in->pos[i]);
            L->axis[i][a] = axis[i], L->u[i][a] = u[i], L->v[i][a] = v[i];
        }
        L->nq[a] = nq, L->half[a] = half, L->f[a] = f;
        L->base[a] = in->first + f * in->face_elements;
    }
}

/* locate_lanes for each kind of light, each its own vector loop. */
SSG_VECTOR_CLONES
static void locate(const struct receivers *restrict R, const struct light_in *in,
                   const struct frames *F, struct dl_lanes *restrict L)
{
    if (in->cube)
        locate_lanes(R, in, F, 1, 1, L);
    else if (in->point)
        locate_lanes(R, in, F, 1, 0, L);
    else
        locate_lanes(R, in, F, 0, 0, L);
}

/* The turn of each lane's tap disc in turns [0, 1): the pixel's (direct_light.h) and
   the golden ratio's a light (the lights' discs differ at a pixel). */
SSG_VECTOR_CLONES
static void turns(struct dl_lanes *restrict L, int li, int y, int x0, float *restrict angle)
{
    for (int a = 0; a < L->count; a++) {
        float turn = ssg_direct_light_turn(x0 + L->pixel[a], y) + 0.618034f * (float)li;
        angle[a] = 2.0f * (float)M_PI * (turn - floorf(turn));
    }
}

/* Light li's faces and constants as the lanes read them. */
static void light_of(const struct dl_job *j, const struct ssg_direct_light_light *l,
                     struct light_in *in, struct frames *F)
{
    const int res = j->c->u.res, faces = l->cube ? SSG_LIGHTMAP_CUBE_FACES : 1;
    *in = (struct light_in){{l->pos[0], l->pos[1], l->pos[2]}, l->texel,
                            j->c->p.normal_offset, j->c->p.offset, (float)res, l->point,
                            l->cube, j->map_index ? l->face * res * res : 0,
                            j->map_index ? res * res : 0};
    for (int k = 0; k < faces; k++) {
        const struct ssg_lightmap_face *f = &j->c->faces[l->face + k];
        for (int i = 0; i < 3; i++) {
            F->origin[i][k] = f->origin[i], F->axis[i][k] = f->axis[i];
            F->u[i][k] = f->u[i], F->v[i][k] = f->v[i];
        }
        F->half[k] = f->half;
    }
}

void dl_lanes_fill(const struct dl_job *j, int li, int y, int x0, struct dl_pixels *px,
                   struct dl_lanes *L)
{
    const struct ssg_direct_light_light *l = &j->c->light[li];
    struct receivers R;
    L->count = 0;
    for (int i = 0; i < px->len; i++) {
        if (!(px->e[i] > 0.0f))
            continue;
        int a = L->count++;
        L->pixel[a] = i;
        for (int c = 0; c < 3; c++)
            R.p[c][a] = px->p[c][i], R.n[c][a] = px->n[c][i], R.l[c][a] = px->l[c][i];
    }
    struct light_in in;
    struct frames F;
    light_of(j, l, &in, &F);
    locate(&R, &in, &F, L);
    float angle[DL_CHUNK];
    turns(L, li, y, x0, angle);
    const float filter = j->c->p.filter;
    for (int a = 0; a < L->count; a++) {
        L->cs[a] = cosf(angle[a]), L->sn[a] = sinf(angle[a]);
        L->sum[a] = 0.0f;
        px->texel[L->pixel[a]] = L->texel[a];
        if (!(l->spread > 0.0f)) {
            L->radius[a] = filter; /* dl_filter_radius's without a blocker search */
            continue;
        }
        struct dl_lookup k;
        dl_lane_lookup(L, l, a, &k);
        L->radius[a] = dl_filter_radius(j, &k, L->cs[a], L->sn[a]);
    }
}
