/* write_cpu.c - what the `write` node does when it runs (method and layout in README.md):
 * create the output directory, gather the layers, hand them to core/io/imageio.h. */
#include <errno.h>
#include <string.h>
#include <sys/stat.h>

#include "io/imageio.h"
#include "write.h"

enum { PATH_MAX_LEN = 4096, MAX_LAYERS = 64 };

/* The images as written: each input, or a copy of its frame when it carries a guard band
   (ssg_image_framed, ssgraph.h: the band never reaches a file). */
struct framed {
    const struct ssg_image *image[MAX_LAYERS];
    struct ssg_image *owned[MAX_LAYERS]; /* the copies, freed by framed_free */
};

static void framed_free(struct framed *f, int n)
{
    for (int i = 0; i < n; i++)
        ssg_image_destroy(&f->owned[i]);
}

/* The main image (0) and every layer, framed; SSG_E_NOMEM when a copy fails. */
static enum ssg_err frame_all(const struct ssg_node_ctx *ctx, const struct ssg_io *io,
                              struct framed *f)
{
    int n = io->extra_count + 1;
    memset(f, 0, sizeof *f);
    if (n > MAX_LAYERS)
        return ssg_node_fail(ctx, SSG_E_VALUE, "%d layers, at most %d", n, MAX_LAYERS);
    for (int i = 0; i < n; i++) {
        const struct ssg_image *im = i ? io->extra_in[i - 1] : io->in[SSG_WRITE_IN_IMAGE];
        if (!(f->image[i] = ssg_image_framed(ctx->frame, im, &f->owned[i]))) {
            framed_free(f, i);
            return ssg_node_fail(ctx, SSG_E_NOMEM, "out of memory for the frame of a layer");
        }
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

static int layer_kind(unsigned type, enum ssg_layer_kind *kind)
{
    switch (type) {
    case SSG_T_SCALAR: *kind = SSG_LAYER_SCALAR; return 1;
    case SSG_T_VECTOR: *kind = SSG_LAYER_VECTOR; return 1;
    case SSG_T_COLOR: *kind = SSG_LAYER_COLOR; return 1;
    default: return 0;
    }
}

/* The EXR, staged: the main image, then each extra input as a layer named by its key. */
static enum ssg_err stage_exr(const struct ssg_node_ctx *ctx, const struct ssg_io *io,
                              const struct ssg_write_params *p, const struct framed *f,
                              const char *path, struct ssg_tmp *t)
{
    struct ssg_exr_layer layers[MAX_LAYERS];
    layers[0] = (struct ssg_exr_layer){.name = NULL, .image = f->image[0]};
    for (int i = 0; i < io->extra_count; i++) {
        layers[i + 1] = (struct ssg_exr_layer){.name = io->extra_names[i],
                                               .image = f->image[i + 1]};
        if (!layer_kind(io->extra_types[i], &layers[i + 1].kind)) {
            char types[64];
            ssg_type_names(io->extra_types[i], types, sizeof types);
            return ssg_node_fail(ctx, SSG_E_TYPE, "layer '%s' is a %s, expected scalar, "
                                 "vector or color", io->extra_names[i], types);
        }
    }
    struct ssg_exr_meta meta;
    ssg_write_meta(ctx, &meta);
    return ssg_exr_stage(path, layers, io->extra_count + 1,
                         (enum ssg_exr_compression)p->compression, &meta, t, ctx->diags);
}

enum ssg_err ssg_write_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                               const struct ssg_io *io)
{
    const struct ssg_write_params *p = consts;
    char why[512], path[PATH_MAX_LEN];
    if (!ssg_write_name_ok(p->name, why, sizeof why)) {
        return ssg_node_fail(ctx, SSG_E_VALUE, "%s", why);
    }
    if (!io->in[SSG_WRITE_IN_IMAGE]) {
        return ssg_node_fail(ctx, SSG_E_MISSING_INPUT, "input 'image' is not connected");
    }
    const char *dir = ctx->out_dir && ctx->out_dir[0] ? ctx->out_dir : "out";
    char stem[224];
    ssg_write_stem(p, ctx->frame_index, stem, sizeof stem);
    /* Both files are staged before either is renamed into place, so a failure (or a kill)
       while writing leaves the previous EXR and PNG together. The PNG goes first, staged
       and renamed, the EXR (the real output) last: a kill between the two renames leaves
       the new PNG beside the previous EXR, never a new EXR beside a stale PNG, and a pair
       whose EXR is older than its PNG is known to be incomplete (docs/exr.md). */
    struct ssg_tmp staged[2];
    struct framed f;
    int n = 0;
    enum ssg_err err = frame_all(ctx, io, &f);
    if (err)
        return err;
    err = ssg_make_dirs(dir, ctx->diags);
    if (!err && p->png &&
        !(err = make_path(path, sizeof path, dir, stem, "png", ctx->diags)))
        if (!(err = ssg_png_stage(path, f.image[0], (enum ssg_tonemap)p->tonemap, p->exposure,
                                  &staged[n], ctx->diags)))
            n++;
    if (!err && p->exr &&
        !(err = make_path(path, sizeof path, dir, stem, "exr", ctx->diags)))
        if (!(err = stage_exr(ctx, io, p, &f, path, &staged[n])))
            n++;
    framed_free(&f, io->extra_count + 1);
    if (err) {
        ssg_tmp_discard(staged, n);
        return err;
    }
    return ssg_tmp_commit(staged, n, ctx->diags);
}
