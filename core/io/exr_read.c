/* exr_read.c - reading an EXR's layer and its metadata through OpenEXRCore (formats.h;
 * contracts in imageio.h and ssgraph.h's ssg_image_read). A layer is the channels
 * LAYER.suffix (the main image: the names without a dot), in the order R,G,B,A / X,Y,Z,W;
 * `depth` is also the bare Z the writer makes of it, `depth.VIEW` a view's VIEW.Z. Only the
 * first part is read, level 0 of a tiled one; every chunk's channels go straight into the
 * planes of the image. */
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "graph/image.h"
#include "io/exr_core.h"
#include "io/exr_guard.h"
#include "io/formats.h"
#include "lang/diag.h"

/* The file's channel names (sorted, as OpenEXR stores them). */
struct names {
    int count;
    const exr_attr_chlist_entry_t *e;
};

static const char *name_of(const struct names *n, int c)
{
    return n->e[c].name.str;
}

/* Position of a suffix in its layer's canonical order (R,G,B,A or X,Y,Z,W); 4 for any other,
   which keeps the file's order. */
static int suffix_rank(const char *suffix)
{
    static const char *const orders[2][4] = {{"R", "G", "B", "A"}, {"X", "Y", "Z", "W"}};
    for (int o = 0; o < 2; o++)
        for (int i = 0; i < 4; i++)
            if (strcmp(suffix, orders[o][i]) == 0)
                return i;
    return 4;
}

/* The part of a channel name after "layer.", or NULL when the channel is not in the layer.
   The main layer ("") holds the names without a dot. */
static const char *layer_suffix(const char *channel, const char *layer)
{
    size_t n = strlen(layer);
    if (!n)
        return strchr(channel, '.') ? NULL : channel;
    if (strlen(channel) <= n + 1 || strncmp(channel, layer, n) != 0 || channel[n] != '.')
        return NULL;
    return strchr(channel + n + 1, '.') ? NULL : channel + n + 1;
}

/* OpenEXR's depth channel: layer "depth" reads a bare Z, "depth.VIEW" reads VIEW.Z (the
   writers' depth, exr_layers.h); -1 when absent. */
static int depth_channel(const struct names *n, const char *layer)
{
    if (strcmp(layer, "depth") != 0 && strncmp(layer, "depth.", 6) != 0)
        return -1;
    char want[SSG_EXR_NAME_LEN];
    snprintf(want, sizeof want, "%s%s", layer[5] ? layer + 6 : "", layer[5] ? ".Z" : "Z");
    for (int c = 0; c < n->count; c++)
        if (strcmp(name_of(n, c), want) == 0)
            return c;
    return -1;
}

/* Sorts idx[0..count-1] by the rank of their suffixes, stably. */
static void sort_by_rank(const struct names *n, const char *layer, int *idx, int count)
{
    for (int i = 1; i < count; i++) {
        int v = idx[i], j = i;
        const char *s = layer_suffix(name_of(n, v), layer);
        int rank = s ? suffix_rank(s) : 4;
        while (j > 0) {
            const char *t = layer_suffix(name_of(n, idx[j - 1]), layer);
            if ((t ? suffix_rank(t) : 4) <= rank)
                break;
            idx[j] = idx[j - 1];
            j--;
        }
        idx[j] = v;
    }
}

/* The channels of a layer into idx (room for n->count), in canonical order; their count.
   In a layer with Z but no X (an image beside its depth: R,G,B,Z), Z is the depth. */
static int select_channels(const struct names *n, const char *layer, int *idx)
{
    int count = 0, z = -1, x = 0;
    for (int c = 0; c < n->count; c++) {
        const char *suffix = layer_suffix(name_of(n, c), layer);
        if (!suffix)
            continue;
        idx[count++] = c;
        z = strcmp(suffix, "Z") == 0 ? c : z;
        x = x || strcmp(suffix, "X") == 0;
    }
    if (z >= 0 && !x && count > 1) {
        int k = 0;
        for (int i = 0; i < count; i++)
            if (idx[i] != z)
                idx[k++] = idx[i];
        count = k;
    }
    int depth = count ? -1 : depth_channel(n, layer);
    if (depth >= 0)
        idx[count++] = depth;
    if (!count && !layer[0]) /* no unnamed channels: the whole file */
        for (int c = 0; c < n->count; c++)
            idx[count++] = c;
    sort_by_rank(n, layer, idx, count);
    return count;
}

/* The layer channel c is in: the name before its last dot; "" (the unnamed channels) for
   a name without one, but "depth" for OpenEXR's bare Z (exr_layers.h). */
static void layer_of(const struct names *n, int c, char *layer, size_t len)
{
    const char *ch = name_of(n, c), *dot = strrchr(ch, '.');
    snprintf(layer, len, "%.*s", dot ? (int)(dot - ch) : 0, dot ? ch : "");
    if (!dot && !strcmp(ch, "Z"))
        snprintf(layer, len, "depth");
}

/* 1 when an earlier channel than c is in the same layer (it was met already). */
static int layer_seen(const struct names *n, int c, const char *layer)
{
    char other[SSG_EXR_NAME_LEN];
    for (int k = 0; k < c; k++) {
        layer_of(n, k, other, sizeof other);
        if (!strcmp(other, layer))
            return 1;
    }
    return 0;
}

/* "(unnamed), ao, depth": the layers of a file, for the message about a missing one. */
static void layer_list(const struct names *n, char *out, size_t len)
{
    size_t used = 0;
    out[0] = '\0';
    for (int c = 0; c < n->count && used + 1 < len; c++) {
        char layer[SSG_EXR_NAME_LEN];
        layer_of(n, c, layer, sizeof layer);
        if (!layer_seen(n, c, layer))
            used += (size_t)snprintf(out + used, len - used, "%s%s", used ? ", " : "",
                                     layer[0] ? layer : "(unnamed)");
    }
}

/* Opens the EXR at fd for reading, after the size checks of exr_guard.h. */
static enum ssg_err open_checked(const char *path, int fd, struct ssg_exr_io *io,
                                 exr_context_t *ctx, struct ssg_diags *diags)
{
    char why[320];
    struct stat st;
    if (!ssg_exr_guard(fd, why, sizeof why)) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "not a readable image: %s", why);
        return SSG_E_IMAGE;
    }
    io->fd = fd;
    io->size = fstat(fd, &st) == 0 ? (long long)st.st_size : 0;
    return ssg_exr_open_read(path, io, ctx, diags);
}

/* The part's shape and channels, refusing what ssgraph does not read (deep data). */
static enum ssg_err read_shape(const char *path, exr_context_t ctx, int *w, int *h,
                              struct names *n, struct ssg_diags *diags)
{
    exr_storage_t storage;
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *list = NULL;
    if (exr_get_storage(ctx, 0, &storage) || exr_get_data_window(ctx, 0, &dw) ||
        exr_get_channels(ctx, 0, &list) || !list) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "not a readable image: no image part");
        return SSG_E_IMAGE;
    }
    if (storage != EXR_STORAGE_SCANLINE && storage != EXR_STORAGE_TILED) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "deep and volume images are not supported");
        return SSG_E_IMAGE;
    }
    *w = (int)((long long)dw.max.x - dw.min.x + 1);
    *h = (int)((long long)dw.max.y - dw.min.y + 1);
    n->count = list->num_channels;
    n->e = list->entries;
    return SSG_OK;
}

/* The selected channels' planes, in a new image; the others' NULL. */
static enum ssg_err decode(const char *path, exr_context_t ctx, const struct ssg_exr_io *io,
                           const int *idx, int nch, int w, int h, const struct names *n,
                           struct ssg_image **out, struct ssg_diags *diags)
{
    for (int k = 0; k < nch; k++)
        if (n->e[idx[k]].x_sampling != 1 || n->e[idx[k]].y_sampling != 1) {
            ssg_diag_file(diags, SSG_E_IMAGE, path, "channel '%s' is subsampled: not "
                          "supported", name_of(n, idx[k]));
            return SSG_E_IMAGE;
        }
    float **planes = calloc((size_t)n->count, sizeof *planes);
    struct ssg_image *im = planes ? ssg_image_create(w, h, nch) : NULL;
    if (!im) {
        free(planes);
        ssg_diag_file(diags, SSG_E_NOMEM, path, "out of memory for a %d x %d image", w, h);
        return SSG_E_NOMEM;
    }
    for (int k = 0; k < nch; k++)
        planes[idx[k]] = ssg_image_plane(im, k);
    exr_result_t rv = ssg_exr_read_planes(ctx, planes, w, h);
    free(planes);
    if (rv) {
        ssg_diag_file(diags, SSG_E_IMAGE, path, "cannot decode image: %s", ssg_exr_why(io, rv));
        ssg_image_destroy(&im);
        return SSG_E_IMAGE;
    }
    *out = im;
    return SSG_OK;
}

/* Picks the layer's channels and checks what they would make. */
static enum ssg_err read_layer(const char *path, exr_context_t ctx, const struct ssg_exr_io *io,
                               const char *layer, struct ssg_image **out,
                               struct ssg_diags *diags)
{
    int w, h;
    struct names n;
    enum ssg_err e = read_shape(path, ctx, &w, &h, &n, diags);
    int *idx = e ? NULL : malloc(sizeof *idx * (size_t)(n.count ? n.count : 1));
    if (e || !idx) {
        if (!e)
            ssg_diag_file(diags, SSG_E_NOMEM, path, "out of memory while reading");
        return e ? e : SSG_E_NOMEM;
    }
    int nch = select_channels(&n, layer, idx);
    char layers[1024];
    if (!nch) {
        layer_list(&n, layers, sizeof layers);
        ssg_diag_file(diags, SSG_E_CHANNELS, path, "no layer '%s' (layers in the file: %s)",
                      layer[0] ? layer : "(unnamed)", layers);
        e = SSG_E_CHANNELS;
    } else if (nch > 4 || !ssg_image_size_ok(w, h, nch)) {
        /* Files hold what ports read (1 to 4 channels): a multi-layer EXR read whole is a
           mistake to report, not a many-channel image to load. */
        ssg_diag_file(diags, SSG_E_SIZE, path, "unsupported image size %d x %d with %d "
                      "channels (expected at most %d pixels a side, %d pixels and 1..4 "
                      "channels)", w, h, nch, SSG_IMAGE_MAX_SIDE, SSG_IMAGE_MAX_PIXELS);
        e = SSG_E_SIZE;
    } else if (!ssg_image_plausible(path, w, h, nch, io->size, diags)) {
        e = SSG_E_IMAGE;
    } else {
        e = decode(path, ctx, io, idx, nch, w, h, &n, out, diags);
    }
    free(idx);
    return e;
}

/* OpenEXRCore 3.1 cannot decode DWAA and DWAB ("not yet implemented in C"): such a file,
   a light probe saved by Blender's tools for one, is OpenImageIO's to read. */
static int core_decodes(exr_context_t ctx)
{
    exr_compression_t c = EXR_COMPRESSION_NONE;
    exr_get_compression(ctx, 0, &c);
    return c != EXR_COMPRESSION_DWAA && c != EXR_COMPRESSION_DWAB;
}

enum ssg_err ssg_exr_read_fd(const char *path, int fd, const char *layer,
                             struct ssg_image **out, int *elsewhere, struct ssg_diags *diags)
{
    struct ssg_exr_io io = {0};
    exr_context_t ctx;
    *elsewhere = 0;
    enum ssg_err e = open_checked(path, fd, &io, &ctx, diags);
    if (e)
        return e;
    if (core_decodes(ctx))
        e = read_layer(path, ctx, &io, layer ? layer : "", out, diags);
    else
        *elsewhere = 1;
    ssg_exr_finish(&ctx, &io);
    return e;
}

/* n floats of attribute `name` (a float, a V3f, an M44f) into out; 0 when the file lacks
   it or it holds another type. */
static int float_attr(exr_context_t ctx, const char *name, float *out, int n)
{
    const exr_attribute_t *a = NULL;
    if (exr_get_attribute_by_name(ctx, 0, name, &a) || !a)
        return 0;
    if (n == 1 && a->type == EXR_ATTR_FLOAT)
        *out = a->f;
    else if (n == 3 && a->type == EXR_ATTR_V3F)
        memcpy(out, a->v3f->arr, sizeof a->v3f->arr);
    else if (n == 16 && a->type == EXR_ATTR_M44F)
        memcpy(out, a->m44f->m, sizeof a->m44f->m);
    else
        return 0;
    return 1;
}

/* The numbers of an ssgraph EXR's metadata; 0 (m untouched) without ssgraph:fov. */
static int read_meta(exr_context_t ctx, struct ssg_exr_meta *m)
{
    const exr_attribute_t *a = NULL;
    exr_attr_box2i_t dw = {.min = {.x = 0, .y = 0}, .max = {.x = -1, .y = -1}};
    if (!float_attr(ctx, "ssgraph:fov", &m->fov_y, 1))
        return 0;
    if (!float_attr(ctx, "ssgraph:near", &m->near_z, 1))
        m->near_z = SSG_DEFAULT_NEAR;
    if (!float_attr(ctx, "ssgraph:far", &m->far_z, 1))
        m->far_z = SSG_DEFAULT_FAR;
    m->guard = exr_attr_get_int(ctx, 0, "ssgraph:guard", &m->guard) ? 0 : m->guard;
    m->seed = 1;
    if (!exr_get_attribute_by_name(ctx, 0, "ssgraph:seed", &a) && a->type == EXR_ATTR_STRING)
        m->seed = strtoull(a->string->str, NULL, 10);
    exr_get_data_window(ctx, 0, &dw);
    m->width = dw.max.x - dw.min.x + 1;
    m->height = dw.max.y - dw.min.y + 1;
    if (!exr_get_attribute_by_name(ctx, 0, "ssgraph:frame_size", &a) && a->type == EXR_ATTR_V2I)
        m->width = a->v2i->x, m->height = a->v2i->y;
    m->has_camera = float_attr(ctx, "ssgraph:camera_position", m->position, 3) &&
                    float_attr(ctx, "ssgraph:camera_target", m->target, 3) &&
                    float_attr(ctx, "ssgraph:camera_up", m->up, 3) &&
                    float_attr(ctx, "worldToCamera", m->world_to_camera, 16) &&
                    float_attr(ctx, "worldToNDC", m->world_to_ndc, 16);
    return 1;
}

enum ssg_err ssg_exr_meta_read_fd(const char *path, int fd, struct ssg_exr_meta *meta,
                                  int *found, struct ssg_diags *diags)
{
    struct ssg_exr_io io = {0};
    exr_context_t ctx;
    *found = 0;
    enum ssg_err e = open_checked(path, fd, &io, &ctx, diags);
    if (e)
        return e;
    struct ssg_exr_meta m = {0};
    if (read_meta(ctx, &m)) {
        *meta = m;
        *found = 1;
    }
    ssg_exr_finish(&ctx, &io);
    return SSG_OK;
}

/* The layer `name` (channels picked as a read picks them) into info. */
static void layer_info(const struct names *n, const char *name, int w, int h, int *idx,
                       struct ssg_layer_info *info)
{
    memset(info, 0, sizeof *info);
    snprintf(info->name, sizeof info->name, "%.*s", SSG_LAYER_NAME_MAX - 1, name);
    info->channel_count = select_channels(n, name, idx);
    for (int k = 0; k < info->channel_count && k < 4; k++)
        snprintf(info->channels[k], sizeof info->channels[k], "%.*s",
                 SSG_LAYER_NAME_MAX - 1, name_of(n, idx[k]));
    info->width = w;
    info->height = h;
}

enum ssg_err ssg_exr_layers_fd(const char *path, int fd, struct ssg_layer_info *layers,
                               int max, int *count, struct ssg_diags *diags)
{
    struct ssg_exr_io io = {0};
    exr_context_t ctx;
    int w, h;
    struct names n;
    *count = 0;
    enum ssg_err e = open_checked(path, fd, &io, &ctx, diags);
    if (e)
        return e;
    e = read_shape(path, ctx, &w, &h, &n, diags);
    int *idx = e ? NULL : malloc(sizeof *idx * (size_t)(n.count ? n.count : 1));
    if (!e && !idx) {
        ssg_diag_file(diags, SSG_E_NOMEM, path, "out of memory while reading");
        e = SSG_E_NOMEM;
    }
    for (int c = 0; !e && c < n.count; c++) {
        char layer[SSG_EXR_NAME_LEN];
        layer_of(&n, c, layer, sizeof layer);
        if (layer_seen(&n, c, layer))
            continue;
        if (*count < max)
            layer_info(&n, layer, w, h, idx, &layers[*count]);
        ++*count;
    }
    free(idx);
    ssg_exr_finish(&ctx, &io);
    return e;
}
