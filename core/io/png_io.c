/* png_io.c - PNG through libpng (formats.h; contracts in imageio.h): the 8-bit preview,
 * tone-mapped and sRGB-encoded (io/tonemap.h), and reading any PNG to linear floats.
 *
 * Writing: the codes are made first, rows in parallel (each code depends on its value
 * alone, so the bytes never depend on the thread count), then libpng compresses them at
 * zlib level 1 with one filter for every row, into the staged temporary. The file carries an
 * sRGB chunk and nothing time- or host-dependent (no tIME, no text).
 * Reading: palette, gray under 8 bits and tRNS are expanded (to RGB, 8 bits, alpha); 8 and
 * 16 bits become floats in [0, 1], sRGB-decoded unless the file says otherwise (a gAMA chunk
 * without an sRGB chunk: then as stored, as OpenImageIO reads it); alpha is never decoded
 * and stays as stored (not premultiplied). Channels: Y, Y+A, R,G,B or R,G,B,A. */
#include <errno.h>
#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "graph/image.h"
#include "io/formats.h"
#include "io/tonemap.h"
#include "lang/diag.h"
#include "lang/files.h"

/* zlib level of the preview: a preview, not an archive. Level 1 and the Up filter on every
   row (no per-row filter search) write a 1280x720 frame several times faster than libpng's
   defaults, for a file about 1.3x larger (bench/io_latency.sh measures it). */
enum { PNG_LEVEL = 1 };

/* libpng's errors come here: the message is kept, then libpng's jump back. */
struct png_state {
    char why[256];
    int data;  /* reading: 1 = the stored values (a normal map), never sRGB-decoded */
    FILE *f; /* writing: where the bytes go */
};

static void on_png_error(png_structp png, png_const_charp msg)
{
    struct png_state *s = png_get_error_ptr(png);
    if (s && !s->why[0])
        snprintf(s->why, sizeof s->why, "%s", msg);
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp msg)
{
    (void)png, (void)msg; /* the library prints nothing; a warning changes no result */
}

/* ---- writing ------------------------------------------------------------------------- */

/* libpng's own writer would report a full disk as "Write Error": say why. */
static void write_bytes(png_structp png, png_bytep data, size_t length)
{
    struct png_state *s = png_get_io_ptr(png);
    if (fwrite(data, 1, length, s->f) != length) {
        snprintf(s->why, sizeof s->why, "%s", strerror(errno));
        png_error(png, "write error");
    }
}

static void flush_bytes(png_structp png)
{
    (void)png; /* the caller flushes and syncs once, at the end */
}

/* The 8-bit codes of the image, interleaved, a row at a time on OpenMP's threads. */
static unsigned char *preview_codes(const struct ssg_image *im, enum ssg_tonemap tonemap,
                                    float exposure)
{
    size_t w = (size_t)im->width, n = (size_t)im->channels;
    unsigned char *codes = malloc(w * n * (size_t)im->height);
    float scale = exp2f(exposure);
    if (!codes)
        return NULL;
    /* rows in parallel only for a frame worth it (see exr_core.c's chunk loop) */
    #pragma omp parallel for schedule(static) if (w * n * (size_t)im->height >= (1u << 20))
    for (int y = 0; y < im->height; y++) {
        unsigned char *line = codes + (size_t)y * w * n;
        for (size_t c = 0; c < n; c++) {
            const float *plane = ssg_image_plane(im, (int)c) + (size_t)y * w;
            for (size_t x = 0; x < w; x++)
                line[x * n + c] = ssg_srgb8_scaled(tonemap, scale, plane[x]);
        }
    }
    return codes;
}

/* libpng compresses the codes into s->f; 0 with the reason in s->why on failure. */
static int encode_png(const unsigned char *codes, int w, int h, int channels,
                      struct png_state *s)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, s, on_png_error,
                                              on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    png_bytep *volatile rows = NULL;
    int ok = 0;
    if (info && !setjmp(png_jmpbuf(png))) {
        rows = malloc(sizeof *rows * (size_t)h);
        if (!rows)
            png_error(png, "out of memory");
        for (int y = 0; y < h; y++)
            rows[y] = (png_bytep)codes + (size_t)y * (size_t)w * (size_t)channels;
        png_set_write_fn(png, s, write_bytes, flush_bytes);
        png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8,
                     channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB,
                     PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
        png_set_compression_level(png, PNG_LEVEL);
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
        png_set_rows(png, info, rows);
        png_write_png(png, info, PNG_TRANSFORM_IDENTITY, NULL);
        ok = 1;
    } else if (!s->why[0]) {
        snprintf(s->why, sizeof s->why, "cannot start libpng");
    }
    free(rows);
    png_destroy_write_struct(png ? &png : NULL, info ? &info : NULL);
    return ok;
}

/* Writes the codes into the open temporary t, synced and closed; the reason of a failure
   in s->why. */
static int write_png_file(struct ssg_tmp *t, const unsigned char *codes,
                          const struct ssg_image *im, struct png_state *s)
{
    FILE *f = fdopen(t->fd, "wb");
    if (!f) {
        snprintf(s->why, sizeof s->why, "%s", strerror(errno));
        return 0;
    }
    t->fd = -1; /* f owns the descriptor now */
    s->f = f;
    int ok = encode_png(codes, im->width, im->height, im->channels, s);
    int flushed = fflush(f) == 0 && !ferror(f) && fsync(fileno(f)) == 0;
    int saved = errno;
    flushed = fclose(f) == 0 && flushed;
    if (ok && !flushed)
        snprintf(s->why, sizeof s->why, "%s", strerror(saved ? saved : errno));
    return ok && flushed;
}

enum ssg_err ssg_png_stage(const char *path, const struct ssg_image *image,
                           enum ssg_tonemap tonemap, float exposure, struct ssg_tmp *t,
                           struct ssg_diags *diags)
{
    t->fd = t->lock_fd = -1;
    t->slot = -1;
    if (!image || !image->data || (image->channels != 1 && image->channels != 3)) {
        ssg_diag_file(diags, SSG_E_CHANNELS, path,
                      "a PNG preview needs a 1- or 3-channel image, got %d channels",
                      image ? image->channels : 0);
        return SSG_E_CHANNELS;
    }
    unsigned char *codes = preview_codes(image, tonemap, exposure);
    if (!codes) {
        ssg_diag_file(diags, SSG_E_NOMEM, path, "out of memory while writing");
        return SSG_E_NOMEM;
    }
    struct png_state s = {.why = ""};
    enum ssg_err e = ssg_tmp_create(path, ".png", "image", t, diags);
    if (!e && !write_png_file(t, codes, image, &s)) {
        ssg_diag_file(diags, SSG_E_IO, path, "cannot write image: %s", s.why);
        ssg_tmp_discard(t, 1);
        e = SSG_E_IO;
    }
    free(codes);
    return e;
}

/* ---- reading ------------------------------------------------------------------------- */

/* IEC 61966-2-1 decoding to linear (the encoding is tonemap.h's). */
static float srgb_decode(float c)
{
    return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}

/* What the header says, after the expansions asked for. */
struct png_shape {
    png_uint_32 w, h;
    int channels, bits, srgb, alpha; /* alpha: index of the alpha channel, -1 = none */
};

static void read_header(png_structp png, png_infop info, struct png_shape *p)
{
    int srgb_intent = 0;
    double gamma = 0;
    png_read_info(png, info);
    /* As OpenImageIO: sRGB unless a gAMA chunk without an sRGB chunk says otherwise. */
    p->srgb = png_get_sRGB(png, info, &srgb_intent) || !png_get_gAMA(png, info, &gamma);
    const struct png_state *s = png_get_error_ptr(png);
    p->srgb = s && s->data ? 0 : p->srgb; /* data: values as stored, scaled to [0, 1] */
    png_set_expand(png);
    if (png_get_bit_depth(png, info) == 16)
        png_set_swap(png); /* PNG is big-endian */
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    p->w = png_get_image_width(png, info);
    p->h = png_get_image_height(png, info);
    p->channels = png_get_channels(png, info);
    p->bits = png_get_bit_depth(png, info);
    p->alpha = p->channels == 2 || p->channels == 4 ? p->channels - 1 : -1;
}

/* The decoded rows into planar linear floats. */
static void to_planes(const unsigned char *rows, const struct png_shape *p,
                      struct ssg_image *im)
{
    size_t w = p->w, n = (size_t)p->channels;
    float max = p->bits == 16 ? 65535.0f : 255.0f;
    #pragma omp parallel for schedule(static) if (w * n * p->h >= (1u << 20))
    for (int y = 0; y < (int)p->h; y++)
        for (size_t c = 0; c < n; c++) {
            float *dst = ssg_image_plane(im, (int)c) + (size_t)y * w;
            int decode = p->srgb && (int)c != p->alpha;
            for (size_t x = 0; x < w; x++) {
                size_t i = ((size_t)y * w + x) * n + c;
                float v = p->bits == 16 ? (float)((const uint16_t *)rows)[i] / max
                                        : (float)rows[i] / max;
                dst[x] = decode ? srgb_decode(v) : v;
            }
        }
}

/* Decodes the whole file; *out on success, else the reason in s->why (or a diagnostic for
   a size ssgraph refuses, then *code). */
static int decode_png(const char *path, FILE *f, long long file_bytes, struct ssg_image **out,
                      struct png_state *s, enum ssg_err *code, struct ssg_diags *diags)
{
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, s, on_png_error,
                                             on_png_warning);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    unsigned char *volatile pixels = NULL;
    png_bytep *volatile rows = NULL;
    struct ssg_image *volatile im = NULL;
    int ok = 0;
    if (info && !setjmp(png_jmpbuf(png))) {
        struct png_shape p;
        png_init_io(png, f);
        read_header(png, info, &p);
        if (!ssg_image_size_ok((int)(p.w > 1u << 30 ? 0 : p.w), (int)(p.h > 1u << 30 ? 0 : p.h),
                               p.channels)) {
            ssg_diag_file(diags, SSG_E_SIZE, path, "unsupported image size %lu x %lu with %d "
                          "channels", (unsigned long)p.w, (unsigned long)p.h, p.channels);
            *code = SSG_E_SIZE;
        } else if (!ssg_image_plausible(path, (int)p.w, (int)p.h, p.channels, file_bytes,
                                        diags)) {
            *code = SSG_E_IMAGE;
        } else {
            size_t row_bytes = png_get_rowbytes(png, info);
            pixels = malloc(row_bytes * p.h);
            rows = malloc(sizeof *rows * p.h);
            im = ssg_image_create((int)p.w, (int)p.h, p.channels);
            if (!pixels || !rows || !im)
                png_error(png, "out of memory");
            for (png_uint_32 y = 0; y < p.h; y++)
                rows[y] = pixels + (size_t)y * row_bytes;
            png_read_image(png, rows);
            png_read_end(png, NULL);
            to_planes(pixels, &p, im);
            *out = im;
            im = NULL;
            ok = 1;
        }
    } else if (!s->why[0]) {
        snprintf(s->why, sizeof s->why, "cannot start libpng");
    }
    struct ssg_image *left = im;
    ssg_image_destroy(&left);
    free(pixels);
    free(rows);
    png_destroy_read_struct(png ? &png : NULL, info ? &info : NULL, NULL);
    return ok;
}

enum ssg_err ssg_png_read_fd(const char *path, int fd, int data, struct ssg_image **out,
                             struct ssg_diags *diags)
{
    int own = dup(fd); /* fclose closes its own descriptor; the caller closes fd */
    FILE *f = own >= 0 ? fdopen(own, "rb") : NULL;
    if (!f) {
        ssg_diag_file(diags, SSG_E_IO, path, "cannot read image: %s", strerror(errno));
        if (own >= 0)
            close(own);
        return SSG_E_IO;
    }
    struct png_state s = {.why = "", .data = data};
    struct stat st;
    enum ssg_err code = SSG_OK;
    long long bytes = fstat(fd, &st) == 0 ? (long long)st.st_size : 0;
    int ok = decode_png(path, f, bytes, out, &s, &code, diags);
    fclose(f);
    if (ok)
        return SSG_OK;
    if (code)
        return code;
    ssg_diag_file(diags, SSG_E_IMAGE, path, "not a readable image: %s", s.why);
    return SSG_E_IMAGE;
}
