/* exr_core.h - private to the OpenEXR half of core/io (exr_core.c, exr_write.c, exr_read.c,
 * exr_views.c): OpenEXRCore contexts over descriptors of ours, their errors as one message,
 * and the pixels of a part moved to and from planar floats a chunk at a time on OpenMP's
 * threads.
 *
 * Why OpenEXRCore, the C library, and not OpenImageIO: OpenImageIO costs 0.3-0.7 s of
 * dynamic loading (oiio_module.h), OpenEXRCore needs only zlib. Why descriptors of ours:
 * a read checks the very file it then decodes (files.h: a regular file of a sane size,
 * exr_guard.h), and a write goes into the temporary ssg_tmp_create made.
 *
 * Determinism: chunks are compressed on any thread but written in chunk order, and a
 * chunk's bytes depend on its pixels alone, so the file never depends on the thread count.
 * Thread safety: a context belongs to one call; the chunk loops share it the way OpenEXRCore
 * allows (concurrent encoding and decoding, one writer at a time). */
#ifndef SSG_EXR_CORE_H
#define SSG_EXR_CORE_H

#include <OpenEXR/openexr.h>

#include "ssgraph.h"

/* What a context reads from or writes to, and what went wrong (the context's user data).
 * Zero-initialise it; from ssg_exr_open_* to ssg_exr_finish it is on a list of live ones
 * (its error handler's: exr_core.c), so it must outlive the context. */
struct ssg_exr_io {
    int fd;                    /* the file; the caller opens and closes it */
    long long size;            /* reading: the file's bytes */
    char why[400];             /* the first error reported, "" = none */
    exr_const_context_t ctx;   /* the context it serves, NULL = none (exr_core.c's) */
    struct ssg_exr_io *next;   /* the next live one (exr_core.c's) */
};

/* Starts reading the EXR open as io->fd (io->size set); SSG_OK, or SSG_E_IMAGE with the
 * reason in diags against path. *ctx is NULL on failure. */
enum ssg_err ssg_exr_open_read(const char *path, struct ssg_exr_io *io, exr_context_t *ctx,
                               struct ssg_diags *diags);

/* Starts writing into io->fd, the staged temporary t_path (files.h) of the output path
 * (named in messages); one scanline part is added by the caller. */
enum ssg_err ssg_exr_open_write(const char *path, const char *t_path, struct ssg_exr_io *io,
                                exr_context_t *ctx, struct ssg_diags *diags);

/* Finishes *ctx (NULL: nothing to finish; a write's chunk table is written here) and takes
 * io off the live list; *ctx is NULL after. Every context opened above ends here. */
exr_result_t ssg_exr_finish(exr_context_t *ctx, struct ssg_exr_io *io);

/* The message of a failed call: what the context reported, else OpenEXR's text of rv. */
const char *ssg_exr_why(const struct ssg_exr_io *io, exr_result_t rv);

/* Images of fewer bytes of floats are written and read on one thread (exr_core.c). */
#define SSG_EXR_PARALLEL_BYTES (4u << 20)

/* Longest channel name, with its NUL (OpenEXR's long names: 255 bytes). */
#define SSG_EXR_NAME_LEN 256

/* Adds the one scanline part of a file being written: width x height, 32-bit float
 * channels named names[0..channels-1] (each unique). */
exr_result_t ssg_exr_define_part(exr_context_t ctx, int width, int height,
                                 exr_compression_t compression, int channels,
                                 const char (*names)[SSG_EXR_NAME_LEN]);

/* sorted[s] = the plane of the s-th channel as OpenEXR stores them (sorted by name), from
 * planes[c] named names[c]. */
exr_result_t ssg_exr_sorted_planes(exr_context_t ctx, int count,
                                   const char (*names)[SSG_EXR_NAME_LEN],
                                   const float *const *planes, const float **sorted);

/* Writes every chunk of part 0 (its header already written: exr_write_header), channel c of
 * the part's channel list (sorted by name, as OpenEXR keeps it) from planes[c], rows of
 * width floats covering the data window. Chunks are compressed in parallel and written in order. */
exr_result_t ssg_exr_write_planes(exr_context_t ctx, const float *const *planes, int width);

/* One thread's ZIP chunk encoder (exr_zip.c): its scratch, reused from chunk to chunk;
 * zero-initialise it, free it with ssg_exr_zip_free. */
struct ssg_exr_zip {
    unsigned char *split, *pred, *out; /* split bytes, predicted bytes, the chunk to write */
    size_t split_cap, pred_cap, out_cap;
    void *compressor;                  /* libdeflate's, in a build with it */
};

/* The ZIP chunk of `lines` lines from line dy of the planes (channels of width floats, in
 * the file's channel order): its size, the bytes in z->out; 0 when out of memory. */
size_t ssg_exr_zip_chunk(struct ssg_exr_zip *z, const float *const *planes, int channels,
                         int width, int dy, int lines);
/* The same chunk uncompressed (compression NONE): the values in line, channel order. */
size_t ssg_exr_raw_chunk(struct ssg_exr_zip *z, const float *const *planes, int channels,
                         int width, int dy, int lines);
void ssg_exr_zip_free(struct ssg_exr_zip *z);

/* Reads part 0's data window, level 0, into planes: planes[c] receives channel c of the
 * part's channel list as floats (width x height of the data window), NULL = skip it. Every
 * chunk is decoded, in parallel; scanline or tiled. */
exr_result_t ssg_exr_read_planes(exr_context_t ctx, float *const *planes, int width,
                                 int height);

#endif
