/* combine_cpu.c - CPU kernel of the `combine` node (method in README.md):
 * one pass over fixed bands of rows, one plane at a time, so the inner loops are plain
 * contiguous multiply-adds the compiler vectorises. */
#include "combine.h"

/* Rows per band of ssg_parallel_rows: the bands, not the threads, fix the work split. */
enum { BAND_ROWS = 16 };

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
};

/* One channel of one band. The optional inputs are loop-invariant NULL tests, which the
   compiler hoists out of the loop (unswitching), so each variant is a plain vector loop. */
static void combine_channel(const struct combine_job *j, int c, size_t begin, size_t end)
{
    const float *d = j->direct[c], *a = j->albedo[c], *ao = j->ao, *ind = j->indirect[c];
    const float *env = j->environment[c], *m = j->modulation[c], *irr = j->irradiance[c];
    const int darken = j->darken_indirect, dd = j->darken_direct, ea = j->environment_albedo;
    float *o = j->out[c], k = j->k[c];
    for (size_t i = begin; i < end; i++) {
        float mi = m ? m[i] : 1.0f, occ = ao ? ao[i] : 1.0f;
        float ambient = (env ? env[i] * (ea ? a[i] : 1.0f) : 0.0f) + k * a[i];
        float bounce = ind ? ind[i] : 0.0f;
        float far_light = irr ? irr[i] * a[i] : 0.0f;
        o[i] = (dd ? mi : 1.0f) * d[i] + mi * occ * ambient + (darken ? mi : 1.0f) * bounce
               + mi * occ * far_light;
    }
}

/* The same with a far field (combine.c): the environment darkened by q = min(1, M / V),
   and the far bounce albedo max(0, M - V) own. */
static void combine_channel_far(const struct combine_job *j, int c, size_t begin, size_t end)
{
    const float *d = j->direct[c], *a = j->albedo[c], *ao = j->ao, *ind = j->indirect[c];
    const float *env = j->environment[c], *m = j->modulation[c], *far = j->far;
    const float *irr = j->irradiance[c];
    const int darken = j->darken_indirect, dd = j->darken_direct;
    const float fb = j->far_bounce ? 1.0f : 0.0f;
    const int ea = j->environment_albedo;
    float *o = j->out[c], k = j->k[c];
    for (size_t i = begin; i < end; i++) {
        float mi = m ? m[i] : 1.0f, occ = ao ? ao[i] : 1.0f, v = far[i];
        float q = v > 0.0f ? mi / v : 1.0f;
        q = q < 1.0f ? q : 1.0f;
        float ambient = (env ? env[i] * (ea ? a[i] : 1.0f) : 0.0f) + k * a[i];
        float bounce = ind ? ind[i] : 0.0f;
        float lit_env = q * occ * ambient;
        float own = (dd ? mi : 1.0f) * d[i] + lit_env;
        float gap = mi - v;
        gap = gap > 0.0f ? gap : 0.0f;
        float far_light = irr ? irr[i] * a[i] : 0.0f;
        float sent = irr ? lit_env : own; /* what the far surfaces' bounce stands for */
        o[i] = own + (darken ? mi : 1.0f) * bounce + fb * a[i] * gap * sent
               + mi * occ * far_light;
    }
}

static void combine_rows(void *user, int y0, int y1)
{
    const struct combine_job *j = user;
    size_t w = (size_t)j->width;
    for (int c = 0; c < 3; c++) {
        (j->far ? combine_channel_far : combine_channel)(j, c, (size_t)y0 * w,
                                                         (size_t)y1 * w);
        const float *em = j->emission[c]; /* added last, as it is (never darkened) */
        for (size_t i = (size_t)y0 * w; em && i < (size_t)y1 * w; i++)
            j->out[c][i] += em[i];
    }
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
