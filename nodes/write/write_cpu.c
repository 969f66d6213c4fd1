/* write_cpu.c - what the `write` node does when it runs (method and layout in README.md):
 * gather the layers into a job, then create the output directory and hand the files to
 * core/io/imageio.h, in the frame or, in a sequence, behind it (graph/behind.h). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "graph/behind.h"
#include "io/imageio.h"
#include "write.h"

enum { PATH_MAX_LEN = 4096, MAX_LAYERS = 64 };

/* Everything the files need, read from the frame when the node runs: a job written
   behind the frames reads nothing the next frame changes. Layer names point into the
   graph, which outlives the run's jobs (the executor finishes them before it returns). */
struct write_job {
    char dir[PATH_MAX_LEN];
    char stem[224];
    struct ssg_write_params p;
    int count; /* layers: 0 is the main image */
    struct ssg_exr_layer layers[MAX_LAYERS];
    struct ssg_image *owned[MAX_LAYERS]; /* copies the job frees */
    struct ssg_exr_meta meta;
};

static void job_free_images(struct write_job *j)
{
    for (int i = 0; i < MAX_LAYERS; i++) /* a reused job may hold more than its count */
        ssg_image_destroy(&j->owned[i]);
}

static void job_free(void *job)
{
    job_free_images(job);
    free(job);
}

/* The frame of `im` (ssg_image_framed: a copy when it carries a guard band, which never
   reaches a file); with `own`, always a copy, for a job that outlives the frame, made in
   *owned when that has the shape already (a job handed back by the queue). */
static const struct ssg_image *frame_layer(const struct ssg_frame *frame,
                                           const struct ssg_image *im, int own,
                                           struct ssg_image **owned)
{
    struct ssg_image *band_cut = NULL;
    const struct ssg_image *f = ssg_image_framed(frame, im, &band_cut);
    if (!f || band_cut) {
        ssg_image_destroy(owned);
        return *owned = band_cut;
    }
    if (!own)
        return f;
    struct ssg_image *o = *owned;
    if (!o || o->width != im->width || o->height != im->height ||
        o->channels != im->channels) {
        ssg_image_destroy(owned);
        if (!(*owned = ssg_image_create(im->width, im->height, im->channels)))
            return NULL;
    }
    memcpy((*owned)->data, im->data,
           sizeof(float) * (size_t)im->width * (size_t)im->height * (size_t)im->channels);
    return *owned;
}

static int layer_kind(unsigned type, enum ssg_layer_kind *kind)
{
    switch (type) {
    case SSG_T_SCALAR: *kind = SSG_LAYER_SCALAR; return 1;
    case SSG_T_VECTOR: *kind = SSG_LAYER_VECTOR; return 1;
    case SSG_T_COLOR: *kind = SSG_LAYER_COLOR; return 1;
    default: return 0;
    }
}

/* The main image (0) and every extra input as a layer named by its key, framed (copied
   with `own`). */
static enum ssg_err gather_layers(const struct ssg_node_ctx *ctx, const struct ssg_io *io,
                                  int own, struct write_job *j)
{
    int n = io->extra_count + 1;
    if (n > MAX_LAYERS)
        return ssg_node_fail(ctx, SSG_E_VALUE, "%d layers, at most %d", n, MAX_LAYERS);
    for (j->count = 0; j->count < n; j->count++) {
        int i = j->count;
        struct ssg_exr_layer *l = &j->layers[i];
        const struct ssg_image *im = i ? io->extra_in[i - 1] : io->in[SSG_WRITE_IN_IMAGE];
        *l = (struct ssg_exr_layer){.name = i ? io->extra_names[i - 1] : NULL};
        if (i && !layer_kind(io->extra_types[i - 1], &l->kind)) {
            char types[64];
            ssg_type_names(io->extra_types[i - 1], types, sizeof types);
            return ssg_node_fail(ctx, SSG_E_TYPE, "layer '%s' is a %s, expected scalar, "
                                 "vector or color", io->extra_names[i - 1], types);
        }
        if (!(l->image = frame_layer(ctx->frame, im, own, &j->owned[i])))
            return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the frame of a layer");
    }
    return SSG_OK;
}

static enum ssg_err make_path(char *buf, size_t len, const char *dir, const char *name,
                              const char *ext, struct ssg_diags *diags)
{
    int n = snprintf(buf, len, "%s/%s.%s", dir, name, ext);
    if (n < 0 || (size_t)n >= len) {
        ssg_diag_file(diags, SSG_E_IO, dir, "output file path for '%s' is too long", name);
        return SSG_E_IO;
    }
    return SSG_OK;
}

/* The job's files. Both are staged before either is renamed into place, so a failure (or
   a kill) while writing leaves the previous EXR and PNG together. The PNG goes first,
   staged and renamed, the EXR (the real output) last: a kill between the two renames
   leaves the new PNG beside the previous EXR, never a new EXR beside a stale PNG, and a
   pair whose EXR is older than its PNG is known to be incomplete (docs/exr.md). */
static enum ssg_err write_files(void *job, struct ssg_diags *diags)
{
    const struct write_job *j = job;
    char path[PATH_MAX_LEN];
    struct ssg_tmp staged[2];
    int n = 0;
    enum ssg_err err = ssg_make_dirs(j->dir, diags);
    if (!err && j->p.png && !(err = make_path(path, sizeof path, j->dir, j->stem, "png", diags)))
        if (!(err = ssg_png_stage(path, j->layers[0].image, (enum ssg_tonemap)j->p.tonemap,
                                  j->p.exposure, &staged[n], diags)))
            n++;
    if (!err && j->p.exr && !(err = make_path(path, sizeof path, j->dir, j->stem, "exr", diags)))
        if (!(err = ssg_exr_stage(path, j->layers, j->count,
                                  (enum ssg_exr_compression)j->p.compression, &j->meta,
                                  &staged[n], diags)))
            n++;
    if (err) {
        ssg_tmp_discard(staged, n);
        return err;
    }
    return ssg_tmp_commit(staged, n, diags);
}

/* The job of this run: paths, parameters, metadata and layers (copied with `own`). */
static enum ssg_err make_job(const struct ssg_node_ctx *ctx,
                             const struct ssg_write_params *p, const struct ssg_io *io,
                             int own, struct write_job *j)
{
    const char *dir = ctx->out_dir && ctx->out_dir[0] ? ctx->out_dir : "out";
    if (snprintf(j->dir, sizeof j->dir, "%s", dir) >= (int)sizeof j->dir) {
        ssg_diag_file(ctx->diags, SSG_E_IO, dir, "output directory path is too long");
        return SSG_E_IO;
    }
    j->p = *p;
    ssg_write_stem(p, ctx->frame_index, j->stem, sizeof j->stem);
    ssg_write_meta(ctx, &j->meta);
    return gather_layers(ctx, io, own, j);
}

enum ssg_err ssg_write_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    const struct ssg_write_params *p = consts;
    char why[512];
    if (!ssg_write_name_ok(p->name, why, sizeof why))
        return ssg_node_fail(ctx, SSG_E_VALUE, "%s", why);
    if (!io->in[SSG_WRITE_IN_IMAGE])
        return ssg_node_fail(ctx, SSG_E_MISSING_INPUT, "input 'image' is not connected");
    int behind = ctx->behind != NULL;
    struct write_job *j = behind ? ssg_behind_spare(ctx->behind, job_free) : NULL;
    if (!j)
        j = calloc(1, sizeof *j);
    if (!j)
        return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the files' job");
    enum ssg_err err = make_job(ctx, p, io, behind, j);
    if (err) {
        job_free(j);
        return err;
    }
    if (behind) /* the queue owns the job from here */
        return ssg_behind_submit(ctx->behind, write_files, job_free, j, ctx->diags);
    err = write_files(j, ctx->diags);
    job_free(j);
    return err;
}
