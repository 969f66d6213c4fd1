/* exr_views.c - single-view EXRs joined into one multi-view EXR (imageio.h,
 * ssg_exr_views_join; formats.h, ssg_exr_views_stage) through OpenEXRCore. Each view's file
 * is read whole into planes; the default view's channels keep their names, each other
 * view's become layer.VIEW.channel; the header is the default view's plus, for each other
 * view, every attribute whose value differs, as ssgraph:VIEW:NAME. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "graph/image.h"
#include "io/exr_core.h"
#include "io/exr_guard.h"
#include "io/formats.h"
#include "lang/diag.h"
#include "lang/files.h"

enum { MAX_VIEWS = 8, MAX_CHANNELS = 512 };

/* One view's file, open and read whole. */
struct view {
    int fd;
    struct ssg_exr_io io;
    exr_context_t ctx;
    struct ssg_image *pixels; /* every channel, in the file's (sorted) order */
};

/* Every channel of files[k] into v (which the caller closes with close_view either way). */
static enum ssg_err read_view(const char *file, struct view *v, struct ssg_diags *diags)
{
    char why[320];
    exr_attr_box2i_t dw;
    const exr_attr_chlist_t *list = NULL;
    enum ssg_err e = ssg_input_open(file, SSG_MAX_IMAGE_BYTES, &v->fd, why, sizeof why);
    if (e) {
        ssg_diag_file(diags, e, file, "cannot read a view: %s", why);
        return e;
    }
    if (!ssg_exr_guard(v->fd, why, sizeof why)) {
        ssg_diag_file(diags, SSG_E_IMAGE, file, "cannot read a view: %s", why);
        return SSG_E_IMAGE;
    }
    v->io.fd = v->fd;
    v->io.size = lseek(v->fd, 0, SEEK_END);
    if ((e = ssg_exr_open_read(file, &v->io, &v->ctx, diags)))
        return e;
    if (exr_get_data_window(v->ctx, 0, &dw) || exr_get_channels(v->ctx, 0, &list)) {
        ssg_diag_file(diags, SSG_E_IMAGE, file, "cannot read a view: no image part");
        return SSG_E_IMAGE;
    }
    int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1, n = list->num_channels;
    if (!(v->pixels = ssg_image_create(w, h, n))) {
        ssg_diag_file(diags, SSG_E_SIZE, file, "cannot read a view of %d x %d with %d "
                      "channels", w, h, n);
        return SSG_E_SIZE;
    }
    float *planes[MAX_CHANNELS];
    for (int c = 0; c < n && c < MAX_CHANNELS; c++)
        planes[c] = ssg_image_plane(v->pixels, c);
    exr_result_t rv = n <= MAX_CHANNELS ? ssg_exr_read_planes(v->ctx, planes, w, h)
                                        : EXR_ERR_INVALID_ARGUMENT;
    if (rv) {
        ssg_diag_file(diags, SSG_E_IMAGE, file, "cannot decode a view: %s",
                      ssg_exr_why(&v->io, rv));
        return SSG_E_IMAGE;
    }
    return SSG_OK;
}

static void close_view(struct view *v)
{
    ssg_exr_finish(&v->ctx, &v->io);
    if (v->fd >= 0)
        close(v->fd);
    ssg_image_destroy(&v->pixels);
}

/* OpenEXR's multi-view channel name: the view goes before the last component
   (layer.view.channel), so "R" -> "right.R" and "ao.Y" -> "ao.right.Y". */
static int view_channel(const char *channel, const char *view, char *out)
{
    const char *dot = strrchr(channel, '.');
    int n = dot ? snprintf(out, SSG_EXR_NAME_LEN, "%.*s.%s%s", (int)(dot - channel), channel,
                           view, dot)
                : snprintf(out, SSG_EXR_NAME_LEN, "%s.%s", view, channel);
    return n > 0 && n < SSG_EXR_NAME_LEN;
}

/* What each attribute holds, compared byte for byte (a string by its characters). */
static int same_attr(const exr_attribute_t *a, const exr_attribute_t *b)
{
    if (a->type != b->type)
        return 0;
    switch (a->type) {
    case EXR_ATTR_INT: return a->i == b->i;
    case EXR_ATTR_FLOAT: return memcmp(&a->f, &b->f, sizeof a->f) == 0;
    case EXR_ATTR_DOUBLE: return memcmp(&a->d, &b->d, sizeof a->d) == 0;
    case EXR_ATTR_STRING:
        return a->string->length == b->string->length &&
               memcmp(a->string->str, b->string->str, (size_t)a->string->length) == 0;
    case EXR_ATTR_STRING_VECTOR:
        if (a->stringvector->n_strings != b->stringvector->n_strings)
            return 0;
        for (int i = 0; i < a->stringvector->n_strings; i++) {
            const exr_attr_string_t *x = &a->stringvector->strings[i],
                                    *y = &b->stringvector->strings[i];
            if (x->length != y->length || memcmp(x->str, y->str, (size_t)x->length))
                return 0;
        }
        return 1;
    case EXR_ATTR_V2I: return memcmp(a->v2i, b->v2i, sizeof *a->v2i) == 0;
    case EXR_ATTR_V2F: return memcmp(a->v2f, b->v2f, sizeof *a->v2f) == 0;
    case EXR_ATTR_V3I: return memcmp(a->v3i, b->v3i, sizeof *a->v3i) == 0;
    case EXR_ATTR_V3F: return memcmp(a->v3f, b->v3f, sizeof *a->v3f) == 0;
    case EXR_ATTR_M33F: return memcmp(a->m33f, b->m33f, sizeof *a->m33f) == 0;
    case EXR_ATTR_M44F: return memcmp(a->m44f, b->m44f, sizeof *a->m44f) == 0;
    case EXR_ATTR_BOX2I: return memcmp(a->box2i, b->box2i, sizeof *a->box2i) == 0;
    default: return 1; /* a type ssgraph never writes: the default view's stands */
    }
}

/* Sets attribute `name` of ctx to a's value. */
static exr_result_t set_attr(exr_context_t ctx, const char *name, const exr_attribute_t *a)
{
    switch (a->type) {
    case EXR_ATTR_INT: return exr_attr_set_int(ctx, 0, name, a->i);
    case EXR_ATTR_FLOAT: return exr_attr_set_float(ctx, 0, name, a->f);
    case EXR_ATTR_DOUBLE: return exr_attr_set_double(ctx, 0, name, a->d);
    case EXR_ATTR_STRING: return exr_attr_set_string(ctx, 0, name, a->string->str);
    case EXR_ATTR_STRING_VECTOR: {
        const char *s[64];
        int n = a->stringvector->n_strings < 64 ? a->stringvector->n_strings : 64;
        for (int i = 0; i < n; i++)
            s[i] = a->stringvector->strings[i].str;
        return exr_attr_set_string_vector(ctx, 0, name, n, s);
    }
    case EXR_ATTR_V2I: return exr_attr_set_v2i(ctx, 0, name, a->v2i);
    case EXR_ATTR_V2F: return exr_attr_set_v2f(ctx, 0, name, a->v2f);
    case EXR_ATTR_V3I: return exr_attr_set_v3i(ctx, 0, name, a->v3i);
    case EXR_ATTR_V3F: return exr_attr_set_v3f(ctx, 0, name, a->v3f);
    case EXR_ATTR_M33F: return exr_attr_set_m33f(ctx, 0, name, a->m33f);
    case EXR_ATTR_M44F: return exr_attr_set_m44f(ctx, 0, name, a->m44f);
    case EXR_ATTR_BOX2I: return exr_attr_set_box2i(ctx, 0, name, a->box2i);
    default: return EXR_ERR_SUCCESS;
    }
}

/* What the file itself says about its image: rewritten for the joined file, never copied
   between views. */
static int header_own(const char *name)
{
    static const char *const own[] = {
        "channels",          "compression",        "dataWindow", "displayWindow",
        "lineOrder",         "pixelAspectRatio",   "screenWindowCenter",
        "screenWindowWidth", "multiView",          "type",       "name",
        "chunkCount",        "tiles",              "version"};
    for (size_t i = 0; i < sizeof own / sizeof own[0]; i++)
        if (strcmp(name, own[i]) == 0)
            return 1;
    return 0;
}

/* The default view's attributes, then each other view's that differ, as ssgraph:VIEW:NAME
   (the `ssgraph:` of NAME dropped: ssgraph:right:camera_position). */
static exr_result_t join_attributes(exr_context_t out, const struct view *v, int count,
                                    const char *const *views)
{
    exr_result_t rv = exr_copy_unset_attributes(out, 0, v[0].ctx, 0);
    for (int k = 1; !rv && k < count; k++) {
        int n = 0;
        exr_get_attribute_count(v[k].ctx, 0, &n);
        for (int i = 0; !rv && i < n; i++) {
            const exr_attribute_t *a = NULL, *base = NULL;
            if (exr_get_attribute_by_index(v[k].ctx, 0, EXR_ATTR_LIST_SORTED_ORDER, i, &a) ||
                header_own(a->name))
                continue;
            if (!exr_get_attribute_by_name(v[0].ctx, 0, a->name, &base) && same_attr(base, a))
                continue;
            const char *bare = strncmp(a->name, "ssgraph:", 8) ? a->name : a->name + 8;
            char name[SSG_EXR_NAME_LEN];
            if (snprintf(name, sizeof name, "ssgraph:%s:%s", views[k], bare) < (int)sizeof name)
                rv = set_attr(out, name, a);
        }
    }
    return rv;
}

/* The joined channels: names and planes, view by view. */
struct joined {
    int count;
    char name[MAX_CHANNELS][SSG_EXR_NAME_LEN];
    const float *plane[MAX_CHANNELS];
};

static enum ssg_err join_channels(const char *path, const struct view *v, int count,
                                  const char *const *views, struct joined *j,
                                  struct ssg_diags *diags)
{
    j->count = 0;
    for (int k = 0; k < count; k++) {
        const exr_attr_chlist_t *list = NULL;
        exr_get_channels(v[k].ctx, 0, &list);
        for (int c = 0; c < list->num_channels; c++) {
            const char *ch = list->entries[c].name.str;
            int ok = j->count < MAX_CHANNELS &&
                     (k ? view_channel(ch, views[k], j->name[j->count])
                        : snprintf(j->name[j->count], SSG_EXR_NAME_LEN, "%s", ch) > 0);
            if (!ok) {
                ssg_diag_file(diags, SSG_E_CHANNELS, path, "too many channels or too long a "
                              "name to join (view '%s', channel '%s')", views[k], ch);
                return SSG_E_CHANNELS;
            }
            j->plane[j->count++] = ssg_image_plane(v[k].pixels, c);
        }
    }
    return SSG_OK;
}

/* The joined file into the open temporary t. */
static enum ssg_err write_joined(const char *path, const struct view *v, int count,
                                 const char *const *views, const struct joined *j,
                                 struct ssg_tmp *t, struct ssg_diags *diags)
{
    struct ssg_exr_io io = {.fd = t->fd};
    exr_context_t ctx;
    exr_compression_t compression = EXR_COMPRESSION_ZIP;
    const float *sorted[MAX_CHANNELS];
    if (ssg_exr_open_write(path, t->path, &io, &ctx, diags))
        return SSG_E_IO;
    exr_get_compression(v[0].ctx, 0, &compression);
    exr_result_t rv = ssg_exr_define_part(ctx, v[0].pixels->width, v[0].pixels->height,
                                          compression, j->count, j->name);
    if (!rv)
        rv = exr_attr_set_string_vector(ctx, 0, "multiView", count, (const char **)views);
    if (!rv)
        rv = join_attributes(ctx, v, count, views);
    if (!rv)
        rv = ssg_exr_sorted_planes(ctx, j->count, j->name, j->plane, sorted);
    if (!rv)
        rv = exr_write_header(ctx);
    if (!rv)
        rv = ssg_exr_write_planes(ctx, sorted, v[0].pixels->width);
    exr_result_t done = ssg_exr_finish(&ctx, &io);
    rv = rv ? rv : done;
    if (rv)
        ssg_diag_file(diags, SSG_E_IO, path, "cannot write image: %s", ssg_exr_why(&io, rv));
    return rv ? SSG_E_IO : SSG_OK;
}

/* Reads the views and checks they share one size. */
static enum ssg_err read_views(const char *const *views, const char *const *files, int count,
                               struct view *v, struct ssg_diags *diags)
{
    for (int k = 0; k < count; k++) {
        enum ssg_err e = read_view(files[k], &v[k], diags);
        if (e)
            return e;
        const struct ssg_image *a = v[k].pixels, *b = v[0].pixels;
        if (a->width != b->width || a->height != b->height) {
            ssg_diag_file(diags, SSG_E_SIZE, files[k], "view '%s' is %d x %d, the default "
                          "view %d x %d", views[k], a->width, a->height, b->width, b->height);
            return SSG_E_SIZE;
        }
    }
    return SSG_OK;
}

enum ssg_err ssg_exr_views_stage(const char *path, const char *const *views,
                                 const char *const *files, int count, struct ssg_tmp *t,
                                 struct ssg_diags *diags)
{
    t->fd = t->lock_fd = -1;
    t->slot = -1;
    if (count < 2 || count > MAX_VIEWS) {
        ssg_diag_file(diags, SSG_E_VALUE, path, "a multi-view EXR needs 2 to %d views",
                      MAX_VIEWS);
        return SSG_E_VALUE;
    }
    struct view v[MAX_VIEWS];
    for (int k = 0; k < count; k++)
        v[k] = (struct view){.fd = -1};
    struct joined *j = malloc(sizeof *j);
    enum ssg_err e = j ? read_views(views, files, count, v, diags) : SSG_E_NOMEM;
    if (!j)
        ssg_diag_file(diags, e, path, "out of memory while joining views");
    if (!e)
        e = join_channels(path, v, count, views, j, diags);
    int created = !e && !(e = ssg_tmp_create(path, ".exr", "image", t, diags));
    if (!e)
        e = write_joined(path, v, count, views, j, t, diags);
    if (!e)
        e = ssg_tmp_close(t, diags);
    if (e && created)
        ssg_tmp_discard(t, 1);
    for (int k = 0; k < count; k++)
        close_view(&v[k]);
    free(j);
    return e;
}
