/* exr_core.c - OpenEXRCore contexts over our descriptors and the chunk loops (exr_core.h). */
#define _GNU_SOURCE /* pread, pwrite */
#include <errno.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "io/exr_core.h"
#include "lang/diag.h"

/* ---- contexts ----------------------------------------------------------------------- */

/* The io of every live context, found by the context's address. OpenEXR reports errors
   through on_error, sometimes with the context's lock held (a write_fn that fails inside
   exr_write_scanline_chunk or exr_write_header), and that lock is not recursive: asking
   OpenEXR for the user data there (exr_get_user_data takes the lock) waited for ever, so a
   write on a full disk never returned. This list is ours, under a lock of ours that is
   never held while OpenEXR is called. */
static pthread_mutex_t live_lock = PTHREAD_MUTEX_INITIALIZER;
static struct ssg_exr_io *live;

/* Ties io to ctxt (once): from the calls that receive both, so that even the errors
   exr_start_read reports, before it returns the context, find their io. */
static void adopt(struct ssg_exr_io *io, exr_const_context_t ctxt)
{
    pthread_mutex_lock(&live_lock);
    if (!io->ctx) {
        io->ctx = ctxt;
        io->next = live;
        live = io;
    }
    pthread_mutex_unlock(&live_lock);
}

static void release(struct ssg_exr_io *io)
{
    pthread_mutex_lock(&live_lock);
    for (struct ssg_exr_io **at = &live; *at; at = &(*at)->next)
        if (*at == io) {
            *at = io->next;
            break;
        }
    io->ctx = NULL;
    io->next = NULL;
    pthread_mutex_unlock(&live_lock);
}

/* Keeps text as io's reason unless it has one (several chunk threads may fail at once:
   the first is kept). Under live_lock, as on_error reads the list. */
static void keep_why(struct ssg_exr_io *io, const char *text)
{
    pthread_mutex_lock(&live_lock);
    if (!io->why[0])
        snprintf(io->why, sizeof io->why, "%s", text);
    pthread_mutex_unlock(&live_lock);
}

/* OpenEXR reports errors through this (by default it prints them: the library prints
   nothing). It calls nothing of OpenEXR's (see live). */
static void on_error(exr_const_context_t ctxt, exr_result_t code, const char *msg)
{
    pthread_mutex_lock(&live_lock);
    struct ssg_exr_io *io = live;
    while (io && io->ctx != ctxt)
        io = io->next;
    pthread_mutex_unlock(&live_lock);
    /* io lives on: its owner is in the OpenEXR call that reports this */
    if (io)
        keep_why(io, msg && msg[0] ? msg : exr_get_error_code_as_string(code));
}

/* pread until sz bytes or the end; a short count is OpenEXR's to report. */
static int64_t read_at(exr_const_context_t ctxt, void *user, void *buffer, uint64_t sz,
                       uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    struct ssg_exr_io *io = user;
    uint64_t done = 0;
    adopt(io, ctxt);
    while (done < sz) {
        ssize_t n = pread(io->fd, (char *)buffer + done, sz - done, (off_t)(offset + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            char why[300];
            snprintf(why, sizeof why, "cannot read: %s", strerror(errno));
            keep_why(io, why);
            error_cb(ctxt, EXR_ERR_READ_IO, "%s", why);
            return -1;
        }
        if (n == 0)
            break;
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

static int64_t size_of(exr_const_context_t ctxt, void *user)
{
    (void)ctxt;
    return ((const struct ssg_exr_io *)user)->size;
}

/* pwrite all of it: a full disk or a file size limit is an error here, never a short file;
   its reason (the OS's: "No space left on device") is kept before OpenEXR hears of it. */
static int64_t write_at(exr_const_context_t ctxt, void *user, const void *buffer, uint64_t sz,
                        uint64_t offset, exr_stream_error_func_ptr_t error_cb)
{
    struct ssg_exr_io *io = user;
    uint64_t done = 0;
    adopt(io, ctxt);
    while (done < sz) {
        ssize_t n = pwrite(io->fd, (const char *)buffer + done, sz - done,
                           (off_t)(offset + done));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0) {
            const char *why = n < 0 ? strerror(errno) : "wrote nothing";
            keep_why(io, why);
            error_cb(ctxt, EXR_ERR_WRITE_IO, "%s", why);
            return -1;
        }
        done += (uint64_t)n;
    }
    return (int64_t)done;
}

const char *ssg_exr_why(const struct ssg_exr_io *io, exr_result_t rv)
{
    return io->why[0] ? io->why : exr_get_error_code_as_string(rv);
}

enum ssg_err ssg_exr_open_read(const char *path, struct ssg_exr_io *io, exr_context_t *ctx,
                               struct ssg_diags *diags)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = io;
    init.read_fn = read_at;
    init.size_fn = size_of;
    io->why[0] = '\0';
    io->ctx = NULL;
    *ctx = NULL;
    exr_result_t rv = exr_start_read(ctx, path, &init);
    if (rv == EXR_ERR_SUCCESS) {
        adopt(io, *ctx);
        return SSG_OK;
    }
    ssg_diag_file(diags, SSG_E_IMAGE, path, "not a readable image: %s", ssg_exr_why(io, rv));
    ssg_exr_finish(ctx, io);
    return SSG_E_IMAGE;
}

enum ssg_err ssg_exr_open_write(const char *path, const char *t_path, struct ssg_exr_io *io,
                                exr_context_t *ctx, struct ssg_diags *diags)
{
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    init.error_handler_fn = on_error;
    init.user_data = io;
    init.write_fn = write_at;
    /* zlib level 1: on a frame's float layers about a third faster than the default level
       for files about 1.5% larger (imageio.h has the measurements) */
    init.zip_level = 1;
    io->why[0] = '\0';
    io->ctx = NULL;
    *ctx = NULL;
    /* Our write_fn: OpenEXR neither opens nor, on failure, removes the file it is told
       of; it is told of the temporary anyway, never the output it will replace. */
    exr_result_t rv = exr_start_write(ctx, t_path, EXR_WRITE_FILE_DIRECTLY, &init);
    if (rv == EXR_ERR_SUCCESS) {
        adopt(io, *ctx);
        return SSG_OK;
    }
    ssg_diag_file(diags, SSG_E_IO, path, "cannot write image: %s", ssg_exr_why(io, rv));
    *ctx = NULL; /* OpenEXR frees a context it failed to start writing */
    release(io);
    return SSG_E_IO;
}

exr_result_t ssg_exr_finish(exr_context_t *ctx, struct ssg_exr_io *io)
{
    /* finishing a write writes the chunk table: its errors still find io */
    exr_result_t rv = *ctx ? exr_finish(ctx) : EXR_ERR_SUCCESS;
    *ctx = NULL;
    release(io);
    return rv;
}

exr_result_t ssg_exr_define_part(exr_context_t ctx, int width, int height,
                                 exr_compression_t compression, int channels,
                                 const char (*names)[SSG_EXR_NAME_LEN])
{
    int part = 0;
    exr_result_t rv = exr_add_part(ctx, NULL, EXR_STORAGE_SCANLINE, &part);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_initialize_required_attr_simple(ctx, part, width, height, compression);
    for (int c = 0; rv == EXR_ERR_SUCCESS && c < channels; c++)
        rv = exr_add_channel(ctx, part, names[c], EXR_PIXEL_FLOAT,
                             EXR_PERCEPTUALLY_LOGARITHMIC, 1, 1);
    return rv;
}

exr_result_t ssg_exr_sorted_planes(exr_context_t ctx, int count,
                                   const char (*names)[SSG_EXR_NAME_LEN],
                                   const float *const *planes, const float **sorted)
{
    const exr_attr_chlist_t *list = NULL;
    exr_result_t rv = exr_get_channels(ctx, 0, &list);
    if (rv != EXR_ERR_SUCCESS || list->num_channels != count)
        return rv ? rv : EXR_ERR_INVALID_ARGUMENT;
    for (int s = 0; s < count; s++) {
        sorted[s] = NULL;
        for (int c = 0; c < count && !sorted[s]; c++)
            if (strcmp(list->entries[s].name.str, names[c]) == 0)
                sorted[s] = planes[c];
        if (!sorted[s])
            return EXR_ERR_INVALID_ARGUMENT;
    }
    return EXR_ERR_SUCCESS;
}

/* ---- writing chunks ----------------------------------------------------------------- */

/* One thread's encoder: ZIP and uncompressed chunks made by exr_zip.c straight from the
   planes, the other compressions by an OpenEXRCore pipeline made for its first chunk and
   updated for the next. */
struct encoder {
    exr_compression_t compression;
    struct ssg_exr_zip z;
    exr_encode_pipeline_t pipe;
    int ready;                  /* pipe initialised (to be destroyed) */
    const void *bytes;          /* the chunk to write */
    size_t size;
};

/* Packs and compresses the chunk starting at line y (dy lines into the planes) through
   OpenEXRCore; no write and no order check here (write_fn and the yield are unset): the
   caller writes the chunks in order. */
static exr_result_t pipe_chunk(exr_context_t ctx, struct encoder *e, const float *const *planes,
                               int width, int y, int dy)
{
    exr_chunk_info_t ci;
    exr_result_t rv = exr_write_scanline_chunk_info(ctx, 0, y, &ci);
    if (rv == EXR_ERR_SUCCESS)
        rv = e->ready ? exr_encoding_update(ctx, 0, &ci, &e->pipe)
                      : exr_encoding_initialize(ctx, 0, &ci, &e->pipe);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    int first = !e->ready;
    e->ready = 1;
    for (int c = 0; c < e->pipe.channel_count; c++) {
        exr_coding_channel_info_t *ch = &e->pipe.channels[c];
        ch->encode_from_ptr = (const uint8_t *)(planes[c] + (size_t)dy * (size_t)width);
        ch->user_pixel_stride = (int32_t)sizeof(float);
        ch->user_line_stride = (int32_t)sizeof(float) * width;
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = (int16_t)sizeof(float);
    }
    if (first && (rv = exr_encoding_choose_default_routines(ctx, 0, &e->pipe)))
        return rv;
    e->pipe.yield_until_ready_fn = NULL;
    e->pipe.write_fn = NULL;
    rv = exr_encoding_run(ctx, 0, &e->pipe);
    e->bytes = e->pipe.compressed_buffer;
    e->size = e->pipe.compressed_bytes;
    return rv;
}

/* The chunk of line y (dy lines into the planes, `lines` of them) into e->bytes/size. */
static exr_result_t encode_chunk(exr_context_t ctx, struct encoder *e, const float *const *planes,
                                 int channels, int width, int y, int dy, int lines)
{
    if (e->compression == EXR_COMPRESSION_ZIP)
        e->size = ssg_exr_zip_chunk(&e->z, planes, channels, width, dy, lines);
    else if (e->compression == EXR_COMPRESSION_NONE)
        e->size = ssg_exr_raw_chunk(&e->z, planes, channels, width, dy, lines);
    else
        return pipe_chunk(ctx, e, planes, width, y, dy);
    e->bytes = e->z.out;
    return e->size ? EXR_ERR_SUCCESS : EXR_ERR_OUT_OF_MEMORY;
}

/* Keeps the first error of the chunk loop. */
static void keep_error(atomic_int *failed, exr_result_t rv)
{
    int none = EXR_ERR_SUCCESS;
    if (rv != EXR_ERR_SUCCESS)
        atomic_compare_exchange_strong(failed, &none, (int)rv);
}

/* What the chunk loop needs to know of the part. */
struct part_shape {
    int chunks, lines, channels, height;
    exr_attr_box2i_t dw;
    exr_compression_t compression;
};

static exr_result_t shape_of(exr_context_t ctx, struct part_shape *p)
{
    const exr_attr_chlist_t *list = NULL;
    exr_result_t rv = exr_get_chunk_count(ctx, 0, &p->chunks);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_scanlines_per_chunk(ctx, 0, &p->lines);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_data_window(ctx, 0, &p->dw);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_compression(ctx, 0, &p->compression);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_channels(ctx, 0, &list);
    p->channels = list ? list->num_channels : 0;
    p->height = p->dw.max.y - p->dw.min.y + 1;
    return rv;
}

exr_result_t ssg_exr_write_planes(exr_context_t ctx, const float *const *planes, int width)
{
    struct part_shape p;
    exr_result_t rv = shape_of(ctx, &p);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    atomic_int failed = EXR_ERR_SUCCESS;
    /* Each thread compresses the next chunk (deflate is most of the time), then waits its
       turn to append it: OpenEXR writes a scanline file's chunks in order. A small image is
       one thread's: on a machine whose other cores are busy, a waiting thread that has to
       be scheduled again costs more than its share of a few chunks saves. */
    size_t bytes = (size_t)width * (size_t)p.height * (size_t)p.channels * sizeof(float);
    #pragma omp parallel if (bytes >= SSG_EXR_PARALLEL_BYTES)
    {
        struct encoder e = {.compression = p.compression};
        #pragma omp for ordered schedule(dynamic, 1)
        for (int c = 0; c < p.chunks; c++) {
            int dy = c * p.lines, y = p.dw.min.y + dy;
            int lines = p.height - dy < p.lines ? p.height - dy : p.lines;
            exr_result_t r = EXR_ERR_SUCCESS;
            if (!atomic_load(&failed))
                r = encode_chunk(ctx, &e, planes, p.channels, width, y, dy, lines);
            keep_error(&failed, r);
            #pragma omp ordered
            if (!atomic_load(&failed))
                keep_error(&failed, exr_write_scanline_chunk(ctx, 0, y, e.bytes, e.size));
        }
        if (e.ready)
            exr_encoding_destroy(ctx, &e.pipe);
        ssg_exr_zip_free(&e.z);
    }
    return (exr_result_t)atomic_load(&failed);
}

/* ---- reading chunks ----------------------------------------------------------------- */

/* Where a part's chunks lie: scanline bands of `lines`, or tiles of tw x th at level 0. */
struct layout {
    int tiled, lines, tw, th, tiles_x, count;
    exr_attr_box2i_t dw;
};

static exr_result_t layout_of(exr_context_t ctx, int width, int height, struct layout *l)
{
    exr_storage_t storage;
    exr_result_t rv = exr_get_storage(ctx, 0, &storage);
    if (rv == EXR_ERR_SUCCESS)
        rv = exr_get_data_window(ctx, 0, &l->dw);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    l->tiled = storage == EXR_STORAGE_TILED;
    if (!l->tiled && storage != EXR_STORAGE_SCANLINE)
        return EXR_ERR_INVALID_ARGUMENT; /* deep: the caller refuses it before */
    if (!l->tiled) {
        rv = exr_get_scanlines_per_chunk(ctx, 0, &l->lines);
        l->count = l->lines > 0 ? (height + l->lines - 1) / l->lines : 0;
        return rv;
    }
    rv = exr_get_tile_sizes(ctx, 0, 0, 0, &l->tw, &l->th);
    if (rv != EXR_ERR_SUCCESS || l->tw <= 0 || l->th <= 0)
        return rv ? rv : EXR_ERR_INVALID_ATTR;
    l->tiles_x = (width + l->tw - 1) / l->tw;
    l->count = l->tiles_x * ((height + l->th - 1) / l->th);
    return EXR_ERR_SUCCESS;
}

struct decoder {
    exr_decode_pipeline_t pipe;
    int ready;
};

/* Decodes chunk k of the layout straight into the planes. */
static exr_result_t decode_chunk(exr_context_t ctx, struct decoder *d, const struct layout *l,
                                 float *const *planes, int width, int k)
{
    exr_chunk_info_t ci;
    int x0 = 0, y0 = k * l->lines;
    exr_result_t rv;
    if (l->tiled) {
        x0 = (k % l->tiles_x) * l->tw, y0 = (k / l->tiles_x) * l->th;
        rv = exr_read_tile_chunk_info(ctx, 0, k % l->tiles_x, k / l->tiles_x, 0, 0, &ci);
    } else {
        rv = exr_read_scanline_chunk_info(ctx, 0, l->dw.min.y + y0, &ci);
    }
    if (rv == EXR_ERR_SUCCESS)
        rv = d->ready ? exr_decoding_update(ctx, 0, &ci, &d->pipe)
                      : exr_decoding_initialize(ctx, 0, &ci, &d->pipe);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    d->ready = 1;
    for (int c = 0; c < d->pipe.channel_count; c++) {
        exr_coding_channel_info_t *ch = &d->pipe.channels[c];
        ch->decode_to_ptr = planes[c] ? (uint8_t *)(planes[c] + (size_t)y0 * (size_t)width +
                                                    (size_t)x0)
                                      : NULL;
        ch->user_pixel_stride = (int32_t)sizeof(float);
        ch->user_line_stride = (int32_t)sizeof(float) * width;
        ch->user_data_type = EXR_PIXEL_FLOAT;
        ch->user_bytes_per_element = (int16_t)sizeof(float);
    }
    rv = exr_decoding_choose_default_routines(ctx, 0, &d->pipe);
    return rv ? rv : exr_decoding_run(ctx, 0, &d->pipe);
}

exr_result_t ssg_exr_read_planes(exr_context_t ctx, float *const *planes, int width,
                                 int height)
{
    struct layout l = {0};
    exr_result_t rv = layout_of(ctx, width, height, &l);
    if (rv != EXR_ERR_SUCCESS)
        return rv;
    atomic_int failed = EXR_ERR_SUCCESS;
    size_t bytes = (size_t)width * (size_t)height * sizeof(float) * 4;
    #pragma omp parallel if (bytes >= SSG_EXR_PARALLEL_BYTES)
    {
        struct decoder d = {.ready = 0};
        #pragma omp for schedule(dynamic, 1)
        for (int k = 0; k < l.count; k++)
            if (!atomic_load(&failed))
                keep_error(&failed, decode_chunk(ctx, &d, &l, planes, width, k));
        if (d.ready)
            exr_decoding_destroy(ctx, &d.pipe);
    }
    return (exr_result_t)atomic_load(&failed);
}
