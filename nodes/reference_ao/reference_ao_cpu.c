/* reference_ao_cpu.c - CPU kernel of the `reference_ao` node (method in reference_ao.c).
 *
 * Bands of ROWS_PER_BAND rows go to ssg_parallel_rows. Per pixel, a short scalar setup
 * (world point and normal, raised origin, rotated tangent frame, the hashed shift of u)
 * is followed by the rays in batches of BATCH: one loop builds the directions from the
 * prepared table (two square roots, no trigonometry; the compiler vectorises it) into
 * structure-of-arrays scratch, and the batch goes to Embree as one occlusion query
 * (ssg_rt_occluded_rays, which says why it uses the query style it does). A pixel
 * depends only on its inputs, (x, y), the seed and the table, and its count of occluded
 * rays is an integer sum, so the output does not depend on the threads. The progress bar
 * (stderr, only when it is a terminal) is advanced by whichever thread finishes a band,
 * through C11 atomics; nothing in the output depends on it. */
#include <float.h>
#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <unistd.h>

#include "reference_ao.h"
#include "rt.h"
#include "scene.h"

enum { ROWS_PER_BAND = 2, BATCH = 256, BAR = 30 };

struct job {
    const struct ssg_reference_ao_consts *c;
    const struct ssg_rt *rt;
    const float *pos[3], *nrm[3]; /* input planes */
    float *out;
    int w, h;
    const char *name;     /* instance, for the progress bar */
    int progress;         /* 1 = stderr is a terminal: show the bar */
    int bands;            /* bands in the frame */
    atomic_int done;      /* bands finished */
    atomic_int shown;     /* last percentage printed */
};

/* What the rays of one pixel share. */
struct pixel {
    float o[3];       /* ray origin, world */
    float t[3], b[3]; /* tangent frame, turned by the pixel's angle */
    float n[3];       /* unit normal, world */
    float shift;      /* Cranley-Patterson shift of u, [0, 1) */
};

/* Rays of one batch, structure of arrays. */
struct batch {
    float ox[BATCH], oy[BATCH], oz[BATCH];
    float dx[BATCH], dy[BATCH], dz[BATCH];
};

/* SplitMix64's finaliser (Steele, Lea and Flood 2014): a full-avalanche 64-bit mix. */
static uint64_t mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
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

/* Per-pixel setup; 0 for background (a zero normal). */
static int setup_pixel(const struct job *j, int x, int y, struct pixel *px)
{
    const struct ssg_reference_ao_consts *c = j->c;
    const float *r = c->rot;
    size_t o = (size_t)y * (size_t)j->w + (size_t)x;
    float nv[3] = {j->nrm[0][o], j->nrm[1][o], j->nrm[2][o]};
    float pv[3] = {j->pos[0][o], j->pos[1][o], j->pos[2][o]};
    float nn = nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2];
    if (!(nn > 1e-12f)) /* also catches NaN */
        return 0;
    float dist = sqrtf(pv[0] * pv[0] + pv[1] * pv[1] + pv[2] * pv[2]);
    float inv = 1.0f / sqrtf(nn), to_eye = dist > 0.0f ? -1.0f / dist : 0.0f;
    float scale = fabsf(pv[2]), v[3];
    for (int i = 0; i < 3; i++) { /* world = eye + R^T view */
        px->n[i] = (r[i] * nv[0] + r[3 + i] * nv[1] + r[6 + i] * nv[2]) * inv;
        px->o[i] = c->eye[i] + r[i] * pv[0] + r[3 + i] * pv[1] + r[6 + i] * pv[2];
        v[i] = (r[i] * pv[0] + r[3 + i] * pv[1] + r[6 + i] * pv[2]) * to_eye;
        scale = fmaxf(scale, fabsf(px->o[i]));
    }
    float e = fmaxf(c->p.offset, 1024.0f * FLT_EPSILON * scale);
    for (int i = 0; i < 3; i++) /* off the own surface (n) and any adjacent one (v) */
        px->o[i] += e * (px->n[i] + v[i]);
    uint64_t h = mix64(c->seed ^ mix64(((uint64_t)(uint32_t)y << 32) | (uint32_t)x));
    px->shift = (float)(h >> 40) * (1.0f / 16777216.0f);
    float angle = (float)((h >> 16) & 0xffffffu) * (float)(2.0 * M_PI / 16777216.0);
    float ca = cosf(angle), sa = sinf(angle), t[3], b[3];
    basis(px->n, t, b);
    for (int i = 0; i < 3; i++) {
        px->t[i] = ca * t[i] + sa * b[i];
        px->b[i] = ca * b[i] - sa * t[i];
    }
    return 1;
}

/* Directions of samples [first, first + n): Malley's method on the shifted table point. */
static void make_dirs(const struct ssg_reference_ao_consts *c, const struct pixel *px,
                      int first, int n, struct batch *restrict k)
{
    const float *restrict tu = c->u + first, *restrict tc = c->c + first;
    const float *restrict ts = c->s + first;
    const float a = px->shift;
    for (int i = 0; i < n; i++) {
        float u = tu[i] + a;
        u = u >= 1.0f ? u - 1.0f : u;
        float rr = sqrtf(u), z = sqrtf(1.0f - u);
        float dx = rr * tc[i], dy = rr * ts[i];
        k->dx[i] = dx * px->t[0] + dy * px->b[0] + z * px->n[0];
        k->dy[i] = dx * px->t[1] + dy * px->b[1] + z * px->n[1];
        k->dz[i] = dx * px->t[2] + dy * px->b[2] + z * px->n[2];
    }
}

/* Visibility of one foreground pixel. */
static float trace_pixel(const struct job *j, const struct pixel *px, struct batch *k)
{
    const int n = j->c->p.rays;
    for (int i = 0; i < BATCH; i++)
        k->ox[i] = px->o[0], k->oy[i] = px->o[1], k->oz[i] = px->o[2];
    int occluded = 0;
    for (int first = 0; first < n; first += BATCH) {
        int count = n - first < BATCH ? n - first : BATCH;
        make_dirs(j->c, px, first, count, k);
        struct ssg_rays rays = {count, k->ox, k->oy, k->oz, k->dx, k->dy, k->dz, 0.0f,
                                j->c->p.max_distance};
        occluded += ssg_rt_occluded_rays(j->rt, &rays, NULL);
    }
    return (float)(n - occluded) / (float)n;
}

/* Advances the bar to the finished fraction. Only the thread that raises the shown
   percentage prints, and only while it is still the latest under the stream's lock, so
   the bar never steps back when two threads finish bands at once. */
static void progress(struct job *j)
{
    int done = atomic_fetch_add(&j->done, 1) + 1;
    int pct = (int)((long long)done * 100 / j->bands);
    int prev = atomic_load(&j->shown);
    while (pct > prev) {
        if (!atomic_compare_exchange_weak(&j->shown, &prev, pct))
            continue; /* prev now holds the newer value */
        char bar[BAR + 1];
        for (int i = 0; i < BAR; i++)
            bar[i] = i < pct * BAR / 100 ? '#' : '.';
        bar[BAR] = '\0';
        flockfile(stderr);
        if (atomic_load(&j->shown) == pct)
            fprintf(stderr, "\rreference_ao '%s' [%s] %3d%%", j->name, bar, pct);
        fflush(stderr);
        funlockfile(stderr);
        break;
    }
}

static void rows(void *user, int y0, int y1)
{
    struct job *j = user;
    struct batch k;
    struct pixel px;
    for (int y = y0; y < y1; y++)
        for (int x = 0; x < j->w; x++)
            j->out[(size_t)y * (size_t)j->w + (size_t)x] =
                setup_pixel(j, x, y, &px) ? trace_pixel(j, &px, &k) : 1.0f;
    if (j->progress)
        progress(j);
}

enum ssg_err ssg_reference_ao_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                      const struct ssg_io *io)
{
    const struct ssg_image *pos = io->in[SSG_REFERENCE_AO_IN_POSITION];
    const struct ssg_image *nrm = io->in[SSG_REFERENCE_AO_IN_NORMAL];
    struct ssg_image *out = io->out[0];
    if (nrm->width != pos->width || nrm->height != pos->height || out->width != pos->width ||
        out->height != pos->height) {
        ssg_diag_at(ctx->diags, SSG_E_SIZE, (struct ssg_loc){0}, "reference_ao '%s': "
                    "position, normal and out must have one size",
                    ctx->instance ? ctx->instance : "");
        return SSG_E_SIZE;
    }
    struct job j = {.c = consts, .rt = ctx->scene->rt, .out = out->data, .w = pos->width,
                    .h = pos->height, .name = ctx->instance ? ctx->instance : ""};
    for (int i = 0; i < 3; i++) {
        j.pos[i] = ssg_image_plane(pos, i);
        j.nrm[i] = ssg_image_plane(nrm, i);
    }
    j.bands = (j.h + ROWS_PER_BAND - 1) / ROWS_PER_BAND;
    j.progress = j.bands > 0 && isatty(fileno(stderr));
    atomic_init(&j.done, 0);
    atomic_init(&j.shown, -1);
    ssg_parallel_rows(j.h, ROWS_PER_BAND, rows, &j);
    if (j.progress)
        fputc('\n', stderr);
    return SSG_OK;
}
