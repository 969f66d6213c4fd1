/* exr_zip.c - one chunk of a ZIP-compressed EXR made from planar floats (exr_core.h), the
 * write node's default and the bulk of its time.
 *
 * OpenEXR's ZIP chunk (the file layout's "ZIP compression"): the chunk's lines, each line
 * its channels in the file's (sorted) order, each value 4 little-endian bytes; the bytes
 * split into the even-indexed ones then the odd ones; each byte replaced by its difference
 * from the one before plus 128; then one zlib stream. OpenEXRCore makes the same bytes
 * through three passes over a packed copy (pack under its context lock, split, predict);
 * here the split comes straight from the planes and the prediction is a separate
 * vectorisable pass, and the deflate is libdeflate's when the build has it (about twice
 * zlib's speed on these bytes, at the same level and a slightly smaller stream), else
 * zlib's. Either way the stream is standard zlib that every EXR reader inflates, and the
 * same pixels give the same bytes. A chunk that does not shrink is stored raw, as OpenEXR
 * does. Thread safety: one struct ssg_exr_zip per thread. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#ifdef SSG_HAVE_LIBDEFLATE
#include <libdeflate.h>
#else
#include <zlib.h>
#endif

#include "io/exr_core.h"

/* Deflate level: the fastest. On a frame's float layers higher levels gain a few percent
   of size for twice the time or more (imageio.h has the measurements). */
enum { LEVEL = 1 };

/* Grows *buf to n bytes; 0 when out of memory. */
static int reserve(unsigned char **buf, size_t *cap, size_t n)
{
    if (*cap >= n)
        return 1;
    unsigned char *grown = realloc(*buf, n);
    if (!grown)
        return 0;
    *buf = grown, *cap = n;
    return 1;
}

/* Bytes 0 and 2 of each value into lo, bytes 1 and 3 into hi: OpenEXR's even/odd split of
   the packed chunk, whose values lie on 4-byte boundaries. */
static void split_line(const float *src, int width, uint16_t *lo, uint16_t *hi)
{
    for (int x = 0; x < width; x++) {
        uint32_t v;
        memcpy(&v, &src[x], sizeof v);
        lo[x] = (uint16_t)((v & 0xffu) | ((v >> 8) & 0xff00u));
        hi[x] = (uint16_t)(((v >> 8) & 0xffu) | ((v >> 16) & 0xff00u));
    }
}

/* The split chunk into z->split (raw bytes: lines x channels x width x 4). */
static void split_chunk(struct ssg_exr_zip *z, const float *const *planes, int channels,
                        int width, int dy, int lines, size_t raw)
{
    uint16_t *lo = (uint16_t *)z->split, *hi = (uint16_t *)(z->split + raw / 2);
    size_t at = 0;
    for (int l = 0; l < lines; l++)
        for (int c = 0; c < channels; c++, at += (size_t)width)
            split_line(planes[c] + (size_t)(dy + l) * (size_t)width, width, lo + at, hi + at);
}

/* OpenEXR's predictor: each byte as its difference from the one before, plus 128. */
static void predict(const unsigned char *in, unsigned char *out, size_t n)
{
    if (!n)
        return;
    out[0] = in[0];
    for (size_t i = 1; i < n; i++)
        out[i] = (unsigned char)(in[i] - in[i - 1] + 128u);
}

/* The chunk as stored without compression: values in line, channel order. */
static void pack_raw(unsigned char *out, const float *const *planes, int channels, int width,
                     int dy, int lines)
{
    size_t line = (size_t)width * sizeof(float);
    for (int l = 0; l < lines; l++)
        for (int c = 0; c < channels; c++, out += line)
            memcpy(out, planes[c] + (size_t)(dy + l) * (size_t)width, line);
}

/* Deflates n bytes of in into z->out as a zlib stream; its size, or 0 when it would not be
   smaller than n. */
static size_t deflate_chunk(struct ssg_exr_zip *z, const unsigned char *in, size_t n)
{
#ifdef SSG_HAVE_LIBDEFLATE
    if (!z->compressor && !(z->compressor = libdeflate_alloc_compressor(LEVEL)))
        return 0;
    return libdeflate_zlib_compress(z->compressor, in, n, z->out, n - 1);
#else
    uLongf size = (uLongf)z->out_cap;
    if (compress2(z->out, &size, in, (uLong)n, LEVEL) != Z_OK || size >= n)
        return 0;
    return size;
#endif
}

size_t ssg_exr_zip_chunk(struct ssg_exr_zip *z, const float *const *planes, int channels,
                         int width, int dy, int lines)
{
    size_t raw = (size_t)lines * (size_t)channels * (size_t)width * sizeof(float);
#ifdef SSG_HAVE_LIBDEFLATE
    size_t bound = raw;
#else
    size_t bound = compressBound((uLong)raw) > raw ? compressBound((uLong)raw) : raw;
#endif
    if (!reserve(&z->split, &z->split_cap, raw) || !reserve(&z->pred, &z->pred_cap, raw) ||
        !reserve(&z->out, &z->out_cap, bound))
        return 0;
    split_chunk(z, planes, channels, width, dy, lines, raw);
    predict(z->split, z->pred, raw);
    size_t size = deflate_chunk(z, z->pred, raw);
    if (size)
        return size;
    pack_raw(z->out, planes, channels, width, dy, lines); /* incompressible: stored raw */
    return raw;
}

size_t ssg_exr_raw_chunk(struct ssg_exr_zip *z, const float *const *planes, int channels,
                         int width, int dy, int lines)
{
    size_t raw = (size_t)lines * (size_t)channels * (size_t)width * sizeof(float);
    if (!reserve(&z->out, &z->out_cap, raw))
        return 0;
    pack_raw(z->out, planes, channels, width, dy, lines);
    return raw;
}

void ssg_exr_zip_free(struct ssg_exr_zip *z)
{
#ifdef SSG_HAVE_LIBDEFLATE
    libdeflate_free_compressor(z->compressor);
#endif
    free(z->split);
    free(z->pred);
    free(z->out);
    *z = (struct ssg_exr_zip){0};
}
