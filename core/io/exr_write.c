/* exr_write.c - the multi-layer float EXR of imageio.h (ssg_exr_stage) through OpenEXRCore:
 * layer names and kinds into channel names, the run's metadata into header attributes, the
 * planes written straight from the images (exr_core.h: chunks compressed in parallel,
 * written in order), all into a staged temporary (files.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "graph/image.h"
#include "io/exr_core.h"
#include "io/exr_layers.h"
#include "io/imageio.h"
#include "lang/diag.h"
#include "lang/files.h"

enum { MAX_CHANNELS = 256, NAME_MAX_LEN = SSG_EXR_NAME_LEN };

/* The file's channels before OpenEXR sorts them: a name and the plane it comes from. */
struct channels {
    int count;
    char name[MAX_CHANNELS][NAME_MAX_LEN];
    const float *plane[MAX_CHANNELS];
};

/* Names every channel of every layer (main: R,G,B; ao.Y; depth: Z; normal.X,Y,Z). */
static enum ssg_err name_channels(const char *path, const struct ssg_exr_layer *layers,
                                  int count, struct channels *out, struct ssg_diags *diags)
{
    out->count = 0;
    for (int i = 0; i < count; i++) {
        const struct ssg_exr_layer *l = &layers[i];
        const char *const *suffixes = ssg_exr_layer_suffixes(l);
        int bare = ssg_exr_layer_is_main(l) || ssg_exr_layer_is_depth(l);
        for (int c = 0; c < l->image->channels; c++) {
            if (out->count == MAX_CHANNELS) {
                ssg_diag_file(diags, SSG_E_CHANNELS, path, "more than %d channels",
                              MAX_CHANNELS);
                return SSG_E_CHANNELS;
            }
            int n = snprintf(out->name[out->count], NAME_MAX_LEN, "%s%s%s",
                             bare ? "" : l->name, bare ? "" : ".", suffixes[c]);
            if (n < 0 || n >= NAME_MAX_LEN) {
                ssg_diag_file(diags, SSG_E_VALUE, path, "layer name '%.40s...' is too long",
                              l->name);
                return SSG_E_VALUE;
            }
            out->plane[out->count++] = ssg_image_plane(l->image, c);
        }
    }
    return SSG_OK;
}

static exr_compression_t compression_of(enum ssg_exr_compression c)
{
    switch (c) {
    case SSG_EXR_NONE: return EXR_COMPRESSION_NONE;
    case SSG_EXR_RLE: return EXR_COMPRESSION_RLE;
    case SSG_EXR_PIZ: return EXR_COMPRESSION_PIZ;
    case SSG_EXR_ZIP: break;
    }
    return EXR_COMPRESSION_ZIP; /* zlib level 1 (exr_core.c), 16-line chunks */
}

/* The scene's camera: ours as v3f, OpenEXR's two standard matrices. */
static exr_result_t add_camera(exr_context_t ctx, const struct ssg_exr_meta *m)
{
    exr_attr_v3f_t pos, target, up;
    exr_attr_m44f_t to_camera, to_ndc;
    memcpy(pos.arr, m->position, sizeof pos.arr);
    memcpy(target.arr, m->target, sizeof target.arr);
    memcpy(up.arr, m->up, sizeof up.arr);
    memcpy(to_camera.m, m->world_to_camera, sizeof to_camera.m);
    memcpy(to_ndc.m, m->world_to_ndc, sizeof to_ndc.m);
    exr_result_t rv = exr_attr_set_v3f(ctx, 0, "ssgraph:camera_position", &pos);
    if (!rv)
        rv = exr_attr_set_v3f(ctx, 0, "ssgraph:camera_target", &target);
    if (!rv)
        rv = exr_attr_set_v3f(ctx, 0, "ssgraph:camera_up", &up);
    if (!rv)
        rv = exr_attr_set_m44f(ctx, 0, "worldToCamera", &to_camera);
    if (!rv)
        rv = exr_attr_set_m44f(ctx, 0, "worldToNDC", &to_ndc);
    return rv;
}

/* The run's metadata (imageio.h, struct ssg_exr_meta) as header attributes; OpenEXR writes
   them sorted by name, so their order here does not matter. */
static exr_result_t add_meta(exr_context_t ctx, const struct ssg_exr_meta *m)
{
    char seed[32];
    snprintf(seed, sizeof seed, "%llu", (unsigned long long)m->seed);
    exr_attr_v2i_t size = {.x = m->width, .y = m->height};
    exr_result_t rv = exr_attr_set_string(ctx, 0, "software", "ssgraph " SSG_VERSION);
    if (!rv && m->graph)
        rv = exr_attr_set_string(ctx, 0, "ssgraph:graph", m->graph);
    if (!rv && m->scene && m->scene[0])
        rv = exr_attr_set_string(ctx, 0, "ssgraph:scene", m->scene);
    if (!rv && m->lights && m->lights[0])
        rv = exr_attr_set_string(ctx, 0, "ssgraph:lights", m->lights);
    if (!rv && m->set_count > 0)
        rv = exr_attr_set_string_vector(ctx, 0, "ssgraph:overrides", m->set_count,
                                        (const char **)m->sets);
    if (!rv)
        rv = exr_attr_set_string(ctx, 0, "ssgraph:seed", seed);
    if (!rv)
        rv = exr_attr_set_v2i(ctx, 0, "ssgraph:frame_size", &size);
    if (!rv)
        rv = exr_attr_set_int(ctx, 0, "ssgraph:guard", m->guard);
    if (!rv)
        rv = exr_attr_set_float(ctx, 0, "ssgraph:fov", m->fov_y);
    if (!rv)
        rv = exr_attr_set_float(ctx, 0, "ssgraph:near", m->near_z);
    if (!rv)
        rv = exr_attr_set_float(ctx, 0, "ssgraph:far", m->far_z);
    return rv || !m->has_camera ? rv : add_camera(ctx, m);
}

/* Header, then pixels, into the open temporary t; the message of a failure goes to why. */
static exr_result_t write_file(const char *path, const struct channels *ch, int width,
                               int height, enum ssg_exr_compression compression,
                               const struct ssg_exr_meta *meta, struct ssg_tmp *t,
                               struct ssg_diags *diags)
{
    struct ssg_exr_io io = {.fd = t->fd};
    exr_context_t ctx;
    if (ssg_exr_open_write(path, t->path, &io, &ctx, diags))
        return EXR_ERR_FILE_ACCESS;
    const float *sorted[MAX_CHANNELS];
    exr_result_t rv = ssg_exr_define_part(ctx, width, height, compression_of(compression),
                                          ch->count, ch->name);
    if (!rv && meta)
        rv = add_meta(ctx, meta);
    if (!rv)
        rv = ssg_exr_sorted_planes(ctx, ch->count, ch->name, ch->plane, sorted);
    if (!rv)
        rv = exr_write_header(ctx);
    if (!rv)
        rv = ssg_exr_write_planes(ctx, sorted, width);
    exr_result_t done = ssg_exr_finish(&ctx, &io);
    rv = rv ? rv : done;
    if (rv)
        ssg_diag_file(diags, SSG_E_IO, path, "cannot write image: %s", ssg_exr_why(&io, rv));
    return rv;
}

enum ssg_err ssg_exr_stage(const char *path, const struct ssg_exr_layer *layers, int count,
                           enum ssg_exr_compression compression,
                           const struct ssg_exr_meta *meta, struct ssg_tmp *t,
                           struct ssg_diags *diags)
{
    t->fd = t->lock_fd = -1;
    t->slot = -1;
    enum ssg_err err = ssg_exr_layers_check(path, layers, count, diags);
    if (err)
        return err;
    struct channels *ch = malloc(sizeof *ch);
    if (!ch) {
        ssg_diag_file(diags, SSG_E_NOMEM, path, "out of memory while writing");
        return SSG_E_NOMEM;
    }
    err = name_channels(path, layers, count, ch, diags);
    int created = !err && !(err = ssg_tmp_create(path, ".exr", "image", t, diags));
    if (!err && write_file(path, ch, layers[0].image->width, layers[0].image->height,
                           compression, meta, t, diags))
        err = SSG_E_IO;
    if (!err)
        err = ssg_tmp_close(t, diags); /* synced now: a full disk fails here, not at commit */
    free(ch);
    if (err && created)
        ssg_tmp_discard(t, 1);
    return err;
}
