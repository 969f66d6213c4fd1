/* combine_cpu.c - CPU kernel of the `combine` node (method in README.md):
 * one pass over fixed bands of rows, cut into segments of SEGMENT pixels; per segment one
 * straight loop per colour channel into L1 scratch, then streaming stores into the output
 * plane (nodes/common/stream_store.h: the output is written, never read, and the planes
 * are far larger than the caches).
 *
 * The loops vectorise (compiled per instruction set, SSG_VECTOR_CLONES): an input that is
 * not connected reads a row of ones or zeros in its place, so no load depends on a
 * condition, and where a missing input's term is not a plain 1 or 0 (a product, the
 * emission's add) a loop-invariant select takes the value the term had before. Every
 * result is the same float operations in the same order as the scalar formulas: the bytes
 * do not change. A 1-channel modulation, far visibility or AO is reused from L1 by the
 * three channels of a segment. */
#include "common/vector_loops.h" /* first: see there */

#include "combine.h"
#include "common/stream_store.h"

/* Rows per band of ssg_parallel_rows: the bands, not the threads, fix the work split. */
enum { BAND_ROWS = 16, SEGMENT = 256 };

struct combine_job {
    const float *direct[3], *albedo[3]; /* required */
    const float *indirect[3];           /* NULL = none */
    const float *irradiance[3];         /* NULL = none */
    const float *environment[3];        /* NULL = none */
    const float *modulation[3];         /* NULL = 1; a 1-channel factor repeats plane 0 */
    const float *ao;                    /* NULL = unoccluded */
    const float *far;                   /* far_visibility, NULL = none */
    const float *emission[3];           /* NULL = none */
    int darken_indirect, far_bounce, darken_direct, environment_albedo;
    float *out[3];
    float k[3];                         /* ambient * ambient_color (prepare) */
    int width;
    float ones[SEGMENT], zeros[SEGMENT]; /* what a missing input reads */
};

/* One segment of one channel's inputs: each a row of the input's plane, or of ones or
   zeros when it is missing (has_* says which, for the terms a plain 1 or 0 would change). */
struct segment {
    const float *d, *a, *env, *m, *ao, *far, *ind, *irr, *em;
    const float *env_factor; /* what the environment is multiplied by: albedo or ones */
    int has_env, has_irr, has_em;
    int n;
};

/* One channel of a segment into o: out = (darken_direct ? M : 1) direct + M ao ambient +
   (darken_indirect ? M : 1) bounce + M ao far_light, or with a far field (combine.c) the
   environment darkened by q = min(1, M / V) and the far bounce albedo max(0, M - V) own
   added. Both are computed and has_far selects one (a far field costs no branch, and an
   absent one reads ones): each is the same operations in the same order as the two loops
   it replaces. darken_indirect and darken_direct: loop-invariant selects;
   environment_albedo picks env_factor (a select nested in another kept GCC 12 from
   vectorising the loop). */
SSG_VECTOR_CLONES static void combine_channel(const struct combine_job *j,
                                              const struct segment *s, float k,
                                              float *restrict o)
{
    const float *restrict d = s->d, *restrict a = s->a, *restrict ao = s->ao;
    const float *restrict ind = s->ind, *restrict env = s->env, *restrict m = s->m;
    const float *restrict irr = s->irr, *restrict em = s->em, *restrict far = s->far;
    const float *restrict ef = s->env_factor;
    const int darken = j->darken_indirect, dd = j->darken_direct, has_far = j->far != NULL;
    const float fb = j->far_bounce ? 1.0f : 0.0f;
    const int has_env = s->has_env, has_irr = s->has_irr, has_em = s->has_em, n = s->n;
    for (int i = 0; i < n; i++) {
        float mi = m[i], occ = ao[i], v = far[i];
        float ambient = (has_env ? env[i] * ef[i] : 0.0f) + k * a[i];
        float bounce = ind[i];
        float far_light = has_irr ? irr[i] * a[i] : 0.0f;
        float near = (dd ? mi : 1.0f) * d[i] + mi * occ * ambient + (darken ? mi : 1.0f) * bounce
                     + mi * occ * far_light;
        float q = v > 0.0f ? mi / v : 1.0f;
        q = q < 1.0f ? q : 1.0f;
        float lit_env = q * occ * ambient;
        float own = (dd ? mi : 1.0f) * d[i] + lit_env;
        float gap = mi - v;
        gap = gap > 0.0f ? gap : 0.0f;
        float sent = has_irr ? lit_env : own; /* what the far surfaces' bounce stands for */
        float with_far = own + (darken ? mi : 1.0f) * bounce + fb * a[i] * gap * sent
                         + mi * occ * far_light;
        float out = has_far ? with_far : near;
        o[i] = has_em ? out + em[i] : out; /* emission added last, as it is (never darkened) */
    }
}

/* Row i0 of an input plane, or the row a missing one reads instead. */
static const float *row_of(const float *plane, size_t i0, const float *instead)
{
    return plane ? plane + i0 : instead;
}

/* Pixels [i0, i0 + n) of channel c. */
static struct segment segment_of(const struct combine_job *j, int c, size_t i0, int n)
{
    return (struct segment){
        .d = j->direct[c] + i0, .a = j->albedo[c] + i0,
        .env = row_of(j->environment[c], i0, j->zeros), .m = row_of(j->modulation[c], i0, j->ones),
        .ao = row_of(j->ao, i0, j->ones), .far = row_of(j->far, i0, j->ones),
        .ind = row_of(j->indirect[c], i0, j->zeros), .irr = row_of(j->irradiance[c], i0, j->zeros),
        .em = row_of(j->emission[c], i0, j->zeros),
        .env_factor = j->environment_albedo ? j->albedo[c] + i0 : j->ones, .has_env = j->environment[c] != NULL,
        .has_irr = j->irradiance[c] != NULL, .has_em = j->emission[c] != NULL, .n = n};
}

static void combine_rows(void *user, int y0, int y1)
{
    const struct combine_job *j = user;
    const size_t w = (size_t)j->width, end = (size_t)y1 * w;
    float o[SEGMENT];
    for (size_t i0 = (size_t)y0 * w; i0 < end; i0 += SEGMENT) {
        int n = end - i0 < SEGMENT ? (int)(end - i0) : SEGMENT;
        for (int c = 0; c < 3; c++) {
            struct segment s = segment_of(j, c, i0, n);
            combine_channel(j, &s, j->k[c], o);
            ssg_stream_store(j->out[c] + i0, o, n);
        }
    }
    ssg_stream_fence();
}

enum ssg_err ssg_combine_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io)
{
    const struct ssg_combine_consts *k = consts;
    const struct ssg_combine_params *p = &k->p;
    const struct ssg_image *direct = io->in[SSG_COMBINE_IN_DIRECT];
    const struct ssg_image *albedo = io->in[SSG_COMBINE_IN_ALBEDO];
    const struct ssg_image *ao = io->in[SSG_COMBINE_IN_AMBIENT_OCCLUSION];
    const struct ssg_image *indirect = io->in[SSG_COMBINE_IN_INDIRECT];
    const struct ssg_image *irradiance = io->in[SSG_COMBINE_IN_IRRADIANCE];
    const struct ssg_image *modulation = io->in[SSG_COMBINE_IN_MODULATION];
    const struct ssg_image *environment = io->in[SSG_COMBINE_IN_ENVIRONMENT];
    struct ssg_image *out = io->out[SSG_COMBINE_OUT_OUT];
    const struct ssg_image *far = io->in[SSG_COMBINE_IN_FAR_VISIBILITY];
    struct combine_job job = {.ao = ao ? ao->data : NULL, .far = far ? far->data : NULL,
                              .width = out->width, .darken_indirect = p->darken_indirect,
                              .far_bounce = p->far_bounce, .darken_direct = p->darken_direct,
                              .environment_albedo = p->environment_albedo};
    for (int i = 0; i < SEGMENT; i++)
        job.ones[i] = 1.0f, job.zeros[i] = 0.0f;
    for (int c = 0; c < 3; c++) {
        job.direct[c] = ssg_image_plane(direct, c);
        job.albedo[c] = ssg_image_plane(albedo, c);
        job.indirect[c] = indirect ? ssg_image_plane(indirect, c) : NULL;
        job.irradiance[c] = irradiance ? ssg_image_plane(irradiance, c) : NULL;
        job.environment[c] = environment ? ssg_image_plane(environment, c) : NULL;
        job.emission[c] = io->in[SSG_COMBINE_IN_EMISSION]
                              ? ssg_image_plane(io->in[SSG_COMBINE_IN_EMISSION], c)
                              : NULL;
        int plane = c < k->u.modulation_last ? c : k->u.modulation_last;
        job.modulation[c] = modulation ? ssg_image_plane(modulation, plane) : NULL;
        job.out[c] = ssg_image_plane(out, c);
        job.k[c] = k->u.k[c];
    }
    ssg_parallel_rows(out->height, BAND_ROWS, combine_rows, &job);
    return SSG_OK;
}
