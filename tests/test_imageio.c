/* test_imageio.c - image files (core/io/imageio.h, ssg_image_read): multi-layer EXR round
 * trip with exact floats, PNG codes of known inputs per tone curve (decoded with stb_image,
 * independently of our reader), byte determinism (over time and over thread counts, every
 * compression), error codes with file names for corrupt, missing and oversized files, and
 * no file left behind by a failed write.
 *
 * Fixtures: tests/fixtures/corrupt.exr is the first 4000 bytes of a real 64x64 float ZIP
 * EXR (`oiiotool --nosoftwareattrib --pattern fill:... 64x64 3 -d float -o x.exr`): its
 * header is intact, its pixels end early. tests/fixtures/garbage.png is a PNG signature
 * followed by text. Scratch files go to $SSG_TMP. */
#include <dirent.h>
#include <errno.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <math.h>
#include <png.h>

#include "check.h"
#include "scratch.h"
#include "io/imageio.h"

/* stb_image, static and PNG only, decodes our PNGs independently of our own reader. Its
   unused static functions are reported at the end of the file, so that warning stays off
   for the whole file. */
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
#pragma GCC diagnostic pop


/* Removes a file or an empty directory, ignoring "not there". */
static void remove_path(const char *path)
{
    if (remove(path) != 0 && errno != ENOENT)
        fprintf(stderr, "cannot remove %s: %s\n", path, strerror(errno));
}

/* Number of entries in dir (without . and ..), and whether any looks like a temp file. */
static int count_entries(const char *dir, int *temps)
{
    DIR *d = opendir(dir);
    int n = 0;
    *temps = 0;
    if (!d)
        return -1;
    for (struct dirent *e; (e = readdir(d));) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
            continue;
        n++;
        if (strstr(e->d_name, ".tmp-"))
            (*temps)++;
    }
    closedir(d);
    return n;
}

static long file_bytes(const char *path, unsigned char **data)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return -1;
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    *data = malloc((size_t)n + 1);
    if (fread(*data, 1, (size_t)n, f) != (size_t)n)
        n = -1;
    fclose(f);
    return n;
}

static int same_bytes(const char *a, const char *b)
{
    unsigned char *da = NULL, *db = NULL;
    long na = file_bytes(a, &da), nb = file_bytes(b, &db);
    int same = na > 0 && na == nb && memcmp(da, db, (size_t)na) == 0;
    free(da);
    free(db);
    return same;
}

/* Values that survive only an exact float path: fractions, negatives, huge, tiny. */
static struct ssg_image *pattern_image(int w, int h, int channels, float seed)
{
    struct ssg_image *im = ssg_image_create(w, h, channels);
    for (int i = 0; i < w * h * channels; i++)
        im->data[i] = seed + (float)i * 0.1234567f - (i % 3 == 0 ? 7.5f : 0.0f) +
                      (i % 5 == 0 ? 1e20f : 0.0f) + (i % 7 == 0 ? 1e-30f : 0.0f);
    return im;
}

static int images_equal(const struct ssg_image *a, const struct ssg_image *b)
{
    return a && b && a->width == b->width && a->height == b->height &&
           a->channels == b->channels &&
           memcmp(a->data, b->data, sizeof(float) * (size_t)a->width * (size_t)a->height *
                                        (size_t)a->channels) == 0;
}

/* Reads path's layer and compares it bit for bit with want. */
static void check_layer(const char *path, const char *layer, const struct ssg_image *want)
{
    struct ssg_diags d = {0};
    struct ssg_image *got = NULL;
    CHECK_EQ(ssg_image_read(path, layer, &got, &d), SSG_OK);
    CHECK_EQ(d.count, 0);
    CHECK(images_equal(got, want));
    ssg_image_destroy(&got);
}

/* Expects exactly the error `code`, reported against a file whose name contains `file`. */
static void check_error(const struct ssg_diags *d, enum ssg_err got, enum ssg_err code,
                        const char *file)
{
    CHECK_EQ(got, code);
    CHECK(d->count >= 1);
    if (d->count >= 1) {
        CHECK_EQ(d->items[0].code, code);
        CHECK(strstr(d->items[0].file, file) != NULL);
    }
}

static void test_exr_round_trip(void)
{
    const char *path = tmp_path("multi.exr");
    struct ssg_image *main_im = pattern_image(5, 3, 3, 0.25f);
    struct ssg_image *ao = pattern_image(5, 3, 1, 0.5f);
    struct ssg_image *normal = pattern_image(5, 3, 3, -1.0f);
    struct ssg_image *albedo = pattern_image(5, 3, 3, 2.0f);
    struct ssg_exr_layer layers[] = {
        {.name = NULL, .image = main_im, .kind = SSG_LAYER_COLOR},
        {.name = "ao", .image = ao, .kind = SSG_LAYER_SCALAR},
        {.name = "normal", .image = normal, .kind = SSG_LAYER_VECTOR},
        {.name = "albedo", .image = albedo, .kind = SSG_LAYER_COLOR},
    };
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_exr_write(path, layers, 4, &d), SSG_OK);
    CHECK_EQ(d.count, 0);
    check_layer(path, NULL, main_im);
    check_layer(path, "", main_im);
    check_layer(path, "ao", ao);
    check_layer(path, "normal", normal);
    check_layer(path, "albedo", albedo);

    struct ssg_image *got = NULL;
    struct ssg_diags d2 = {0};
    check_error(&d2, ssg_image_read(path, "missing", &got, &d2), SSG_E_CHANNELS, "multi.exr");
    CHECK(got == NULL);
    /* "ao" must not match a layer that merely starts with it. */
    struct ssg_diags d3 = {0};
    check_error(&d3, ssg_image_read(path, "alb", &got, &d3), SSG_E_CHANNELS, "multi.exr");

    /* A scalar main image is channel Y and reads back as one channel; a file of layers
       only reads whole when no layer is asked for. */
    const char *gray = tmp_path("gray.exr");
    struct ssg_exr_layer one = {.name = "", .image = ao};
    struct ssg_diags d4 = {0};
    CHECK_EQ(ssg_exr_write(gray, &one, 1, &d4), SSG_OK);
    check_layer(gray, NULL, ao);
    const char *only = tmp_path("only_ao.exr");
    struct ssg_diags d5 = {0};
    CHECK_EQ(ssg_exr_write(only, &layers[1], 1, &d5), SSG_OK);
    check_layer(only, NULL, ao);
    check_layer(only, "ao", ao);

    ssg_image_destroy(&main_im);
    ssg_image_destroy(&ao);
    ssg_image_destroy(&normal);
    ssg_image_destroy(&albedo);
}

static void test_exr_bad_layers(void)
{
    struct ssg_image *a = ssg_image_create(4, 4, 3), *b = ssg_image_create(4, 5, 1);
    struct ssg_image *c = ssg_image_create(4, 4, 1);
    const char *path = tmp_path("bad_layers.exr");
    struct ssg_exr_layer size[] = {{.image = a}, {.name = "b", .image = b}};
    struct ssg_diags d = {0};
    check_error(&d, ssg_exr_write(path, size, 2, &d), SSG_E_SIZE, "bad_layers.exr");
    struct ssg_exr_layer kind[] = {{.image = a},
                                   {.name = "v", .image = c, .kind = SSG_LAYER_VECTOR}};
    struct ssg_diags d2 = {0};
    check_error(&d2, ssg_exr_write(path, kind, 2, &d2), SSG_E_CHANNELS, "bad_layers.exr");
    struct ssg_exr_layer dup[] = {{.name = "x", .image = c}, {.name = "x", .image = c}};
    struct ssg_diags d3 = {0};
    check_error(&d3, ssg_exr_write(path, dup, 2, &d3), SSG_E_DUPLICATE, "bad_layers.exr");
    struct ssg_exr_layer dot[] = {{.name = "a.b", .image = c}};
    struct ssg_diags d4 = {0};
    check_error(&d4, ssg_exr_write(path, dot, 1, &d4), SSG_E_VALUE, "bad_layers.exr");
    struct stat st;
    CHECK(stat(path, &st) != 0);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
    ssg_image_destroy(&c);
}

/* Inputs and their 8-bit codes, computed independently (double precision, IEC 61966-2-1):
   clamp min(x,1), reinhard x/(1+x), aces (x(2.51x+.03))/(x(2.43x+.59)+.14) clamped. */
static const float png_inputs[8] = {0, 0.001f, 0.18f, 0.5f, 1, 3, 16, 1000};
static const unsigned char png_codes[3][8] = {
    {0, 3, 118, 188, 255, 255, 255, 255}, /* clamp */
    {0, 3, 109, 156, 188, 225, 248, 255}, /* reinhard */
    {0, 1, 141, 206, 232, 250, 255, 255}, /* aces */
};

static void test_png_codes(void)
{
    struct ssg_image *im = ssg_image_create(8, 1, 1);
    memcpy(im->data, png_inputs, sizeof png_inputs);
    for (int t = 0; t < 3; t++) {
        const char *path = tmp_path("codes.png");
        struct ssg_diags d = {0};
        CHECK_EQ(ssg_png_write(path, im, (enum ssg_tonemap)t, 0.0f, &d), SSG_OK);
        int w = 0, h = 0, n = 0;
        unsigned char *px = stbi_load(path, &w, &h, &n, 0);
        CHECK(px != NULL);
        CHECK_EQ(w, 8);
        CHECK_EQ(h, 1);
        CHECK_EQ(n, 1); /* gray */
        for (int i = 0; px && i < 8; i++) {
            CHECK_EQ(px[i], png_codes[t][i]);
            CHECK_EQ(ssg_tonemap_to_srgb8((enum ssg_tonemap)t, 0.0f, png_inputs[i]),
                     png_codes[t][i]);
        }
        stbi_image_free(px);
    }
    ssg_image_destroy(&im);

    /* RGB order, exposure, and values no curve should pass on: negative, NaN, inf. */
    struct ssg_image *rgb = ssg_image_create(3, 2, 3);
    float r[6] = {1, 0.25f, -1, 0.5f, 0, 0}, g[6] = {0, 0.5f, NAN, 0, 0, 0},
          b[6] = {0.5f, 0, INFINITY, 0, 0, 0};
    memcpy(ssg_image_plane(rgb, 0), r, sizeof r);
    memcpy(ssg_image_plane(rgb, 1), g, sizeof g);
    memcpy(ssg_image_plane(rgb, 2), b, sizeof b);
    const char *path = tmp_path("rgb.png");
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_png_write(path, rgb, SSG_TONEMAP_CLAMP, 1.0f, &d), SSG_OK);
    int w = 0, h = 0, n = 0;
    unsigned char *px = stbi_load(path, &w, &h, &n, 0);
    CHECK(px != NULL && w == 3 && h == 2 && n == 3);
    if (px) {
        /* exposure +1: (1,0,.5) -> (2,0,1) -> (255,0,255); (.25,.5,0) -> (.5,1,0) */
        CHECK_EQ(px[0], 255);
        CHECK_EQ(px[1], 0);
        CHECK_EQ(px[2], 255);
        CHECK_EQ(px[3], 188);
        CHECK_EQ(px[4], 255);
        CHECK_EQ(px[5], 0);
        CHECK_EQ(px[6], 0);   /* negative */
        CHECK_EQ(px[7], 0);   /* NaN */
        CHECK_EQ(px[8], 255); /* inf */
        CHECK_EQ(px[9], 255); /* second row: 0.5 x 2 */
    }
    stbi_image_free(px);
    /* Reading an 8-bit PNG decodes sRGB to linear: code 188 is 0.50289 linear. */
    struct ssg_image *back = NULL;
    CHECK_EQ(ssg_image_read(path, NULL, &back, &d), SSG_OK);
    if (back) {
        CHECK_EQ(back->channels, 3);
        CHECK_NEAR(ssg_image_plane(back, 0)[1], 0.50289f, 1e-4);
        CHECK_NEAR(ssg_image_plane(back, 1)[1], 1.0f, 1e-6);
        CHECK_NEAR(ssg_image_plane(back, 2)[1], 0.0f, 1e-6);
    }
    ssg_image_destroy(&back);
    ssg_image_destroy(&rgb);
    /* Two channels are not a preview. */
    struct ssg_image *two = ssg_image_create(2, 2, 2);
    struct ssg_diags d2 = {0};
    check_error(&d2, ssg_png_write(tmp_path("two.png"), two, SSG_TONEMAP_CLAMP, 0, &d2),
                SSG_E_CHANNELS, "two.png");
    ssg_image_destroy(&two);
}

/* A PNG written with libpng itself: one row of `w` pixels of the given type and depth (16-bit
   samples big-endian in `row`), optionally with only a gAMA chunk of 1.0 (linear), or a
   2-bit palette of two entries whose second is half transparent (tRNS). */
static void write_test_png(const char *path, int w, int color, int depth, const void *row,
                           int linear)
{
    FILE *f = fopen(path, "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    if (!f || !png || !info || setjmp(png_jmpbuf(png))) {
        CHECK(!"cannot write a test PNG");
        return;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, 1, depth, color, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (color == PNG_COLOR_TYPE_PALETTE) {
        png_color pal[2] = {{255, 0, 0}, {0, 0, 255}};
        png_byte trans[2] = {255, 128};
        png_set_PLTE(png, info, pal, 2);
        png_set_tRNS(png, info, trans, 2, NULL);
    }
    if (linear)
        png_set_gAMA(png, info, 1.0);
    png_write_info(png, info);
    png_write_row(png, (png_const_bytep)row);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
}

static float srgb_to_linear(float c)
{
    return c <= 0.04045f ? c / 12.92f : powf((c + 0.055f) / 1.055f, 2.4f);
}

/* Reads path and checks its channel count and its first pixel. */
static void check_png(const char *path, int channels, const float *want)
{
    struct ssg_diags d = {0};
    struct ssg_image *im = NULL;
    CHECK_EQ(ssg_image_read(path, NULL, &im, &d), SSG_OK);
    CHECK(im && im->channels == channels);
    for (int c = 0; im && c < channels && c < im->channels; c++)
        CHECK_NEAR(ssg_image_plane(im, c)[0], want[c], 1e-6);
    ssg_image_destroy(&im);
}

/* PNGs of every layout read as libpng expands them: colour sRGB-decoded to linear, alpha
   as stored, 16 bits kept, a gAMA of 1.0 without sRGB read as linear, a palette with tRNS
   as RGBA, 1-bit gray as 0 or 1; and a PNG has no named layers. */
static void test_png_reads(void)
{
    const unsigned char rgba[4] = {200, 100, 50, 128};
    write_test_png(tmp_path("rgba.png"), 1, PNG_COLOR_TYPE_RGB_ALPHA, 8, rgba, 0);
    float want_rgba[4] = {srgb_to_linear(200 / 255.0f), srgb_to_linear(100 / 255.0f),
                          srgb_to_linear(50 / 255.0f), 128 / 255.0f};
    check_png(tmp_path("rgba.png"), 4, want_rgba);
    const unsigned char ya16[4] = {0x75, 0x30, 0xff, 0xff}; /* 30000, 65535 */
    write_test_png(tmp_path("ya16.png"), 1, PNG_COLOR_TYPE_GRAY_ALPHA, 16, ya16, 0);
    float want_ya[2] = {srgb_to_linear(30000 / 65535.0f), 1.0f};
    check_png(tmp_path("ya16.png"), 2, want_ya);
    const unsigned char rgb[3] = {128, 0, 255};
    write_test_png(tmp_path("linear.png"), 1, PNG_COLOR_TYPE_RGB, 8, rgb, 1);
    float want_lin[3] = {128 / 255.0f, 0.0f, 1.0f};
    check_png(tmp_path("linear.png"), 3, want_lin);
    const unsigned char pal[1] = {0x40}; /* 2-bit indices 1, 0, 0, 0: the first pixel 1 */
    write_test_png(tmp_path("palette.png"), 4, PNG_COLOR_TYPE_PALETTE, 2, pal, 0);
    float want_pal[4] = {0.0f, 0.0f, 1.0f, 128 / 255.0f};
    check_png(tmp_path("palette.png"), 4, want_pal);
    const unsigned char bits[1] = {0x80};
    write_test_png(tmp_path("bits.png"), 8, PNG_COLOR_TYPE_GRAY, 1, bits, 0);
    float one = 1.0f;
    check_png(tmp_path("bits.png"), 1, &one);
    struct ssg_diags d = {0};
    struct ssg_image *im = NULL;
    check_error(&d, ssg_image_read(tmp_path("rgba.png"), "ao", &im, &d), SSG_E_CHANNELS,
                "rgba.png");
    CHECK(im == NULL);
}

static void test_determinism(void)
{
    struct ssg_image *im = pattern_image(17, 9, 3, 0.125f), *ao = pattern_image(17, 9, 1, 0.0f);
    struct ssg_exr_layer layers[] = {{.image = im}, {.name = "ao", .image = ao}};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_exr_write(tmp_path("det1.exr"), layers, 2, &d), SSG_OK);
    CHECK_EQ(ssg_png_write(tmp_path("det1.png"), im, SSG_TONEMAP_ACES, 0.5f, &d), SSG_OK);
    /* Over a second apart, so a time stamp in any header would differ. */
    struct timespec wait = {1, 100000000};
    nanosleep(&wait, NULL);
    CHECK_EQ(ssg_exr_write(tmp_path("det2.exr"), layers, 2, &d), SSG_OK);
    CHECK_EQ(ssg_png_write(tmp_path("det2.png"), im, SSG_TONEMAP_ACES, 0.5f, &d), SSG_OK);
    CHECK(same_bytes(tmp_path("det1.exr"), tmp_path("det2.exr")));
    CHECK(same_bytes(tmp_path("det1.png"), tmp_path("det2.png")));
    ssg_image_destroy(&im);
    ssg_image_destroy(&ao);
}

/* The chunks are compressed on any thread and written in order: one thread or several, the
   same bytes, for every compression; and they read back exactly. 61 rows: four 16-row ZIP
   chunks, the last one short; one 32-row PIZ chunk and a short one. */
static void test_thread_determinism(void)
{
    struct ssg_image *im = pattern_image(37, 61, 3, 0.375f), *ao = pattern_image(37, 61, 1, 2.0f);
    struct ssg_exr_layer layers[] = {{.image = im}, {.name = "ao", .image = ao}};
    int threads = omp_get_max_threads();
    for (int c = SSG_EXR_ZIP; c <= SSG_EXR_PIZ; c++) {
        struct ssg_diags d = {0};
        omp_set_num_threads(1);
        CHECK_EQ(ssg_exr_write_compressed(tmp_path("t1.exr"), layers, 2, c, &d), SSG_OK);
        CHECK_EQ(ssg_png_write(tmp_path("t1.png"), im, SSG_TONEMAP_ACES, 0.0f, &d), SSG_OK);
        omp_set_num_threads(4);
        CHECK_EQ(ssg_exr_write_compressed(tmp_path("t4.exr"), layers, 2, c, &d), SSG_OK);
        CHECK_EQ(ssg_png_write(tmp_path("t4.png"), im, SSG_TONEMAP_ACES, 0.0f, &d), SSG_OK);
        CHECK(same_bytes(tmp_path("t1.exr"), tmp_path("t4.exr")));
        CHECK(same_bytes(tmp_path("t1.png"), tmp_path("t4.png")));
        check_layer(tmp_path("t4.exr"), NULL, im);
        check_layer(tmp_path("t4.exr"), "ao", ao);
    }
    omp_set_num_threads(threads);
    ssg_image_destroy(&im);
    ssg_image_destroy(&ao);
}

static void test_read_errors(void)
{
    struct ssg_image *im = NULL;
    struct ssg_diags d = {0};
    check_error(&d, ssg_image_read("tests/fixtures/corrupt.exr", NULL, &im, &d), SSG_E_IMAGE,
                "tests/fixtures/corrupt.exr");
    CHECK(im == NULL);
    struct ssg_diags d2 = {0};
    check_error(&d2, ssg_image_read("tests/fixtures/garbage.png", NULL, &im, &d2), SSG_E_IMAGE,
                "tests/fixtures/garbage.png");
    CHECK(im == NULL);
    struct ssg_diags d3 = {0};
    check_error(&d3, ssg_image_read(tmp_path("no_such_file.exr"), NULL, &im, &d3), SSG_E_IO,
                "no_such_file.exr");
    struct ssg_diags d4 = {0};
    check_error(&d4, ssg_image_read(tmpdir, NULL, &im, &d4), SSG_E_IO, tmpdir);
    CHECK(im == NULL);
}

/* OpenEXR files may be tiled as well as scanline: both read to the same pixels (the
   fixtures are one gradient written both ways by oiiotool, 16 x 16 tiles over 40 x 24, so
   the last tiles are partial), a named layer too. */
static void test_tiled_reads(void)
{
    struct ssg_image *scan = NULL, *tiled = NULL, *layer = NULL, *red = NULL;
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_image_read("tests/fixtures/images/scanline.exr", NULL, &scan, &d), SSG_OK);
    CHECK_EQ(ssg_image_read("tests/fixtures/images/tiled.exr", NULL, &tiled, &d), SSG_OK);
    CHECK_EQ(ssg_image_read("tests/fixtures/images/tiled_layer.exr", "depth", &layer, &d),
             SSG_OK);
    CHECK_EQ(ssg_image_read("tests/fixtures/images/scanline_layer.exr", "depth", &red, &d),
             SSG_OK);
    CHECK(scan && tiled && images_equal(scan, tiled));
    CHECK(layer && red && images_equal(layer, red));
    CHECK(scan && ssg_image_plane(scan, 0)[39] > 0.9f); /* a gradient, not zeros */
    ssg_image_destroy(&scan);
    ssg_image_destroy(&tiled);
    ssg_image_destroy(&layer);
    ssg_image_destroy(&red);
}

/* Endless streams and special files are refused before anything reads them: a FIFO with
   no writer would block open(), /dev/zero would never end. */
static void test_special_files(void)
{
    struct ssg_image *im = NULL;
    struct ssg_diags d = {0};
    check_error(&d, ssg_image_read("/dev/zero", NULL, &im, &d), SSG_E_IO, "/dev/zero");
    CHECK(d.count && strstr(d.items[0].message, "not a regular file") != NULL);
    CHECK(im == NULL);
    const char *fifo = tmp_path("fifo.exr");
    unlink(fifo);
    CHECK(mkfifo(fifo, 0600) == 0);
    struct ssg_diags d2 = {0};
    check_error(&d2, ssg_image_read(fifo, NULL, &im, &d2), SSG_E_IO, "fifo.exr");
    CHECK(im == NULL);
    unlink(fifo);
}

static void test_size_errors(void)
{
    /* Wider than ssg_image_create allows: built by hand, since only the reader refuses. */
    struct ssg_image wide = {.width = 16385, .height = 1, .channels = 1};
    wide.data = calloc(16385, sizeof(float));
    struct ssg_exr_layer l = {.image = &wide};
    struct ssg_diags d = {0};
    CHECK_EQ(ssg_exr_write(tmp_path("wide.exr"), &l, 1, &d), SSG_OK);
    free(wide.data);
    struct ssg_image *im = NULL;
    struct ssg_diags d2 = {0};
    check_error(&d2, ssg_image_read(tmp_path("wide.exr"), NULL, &im, &d2), SSG_E_SIZE,
                "wide.exr");
    CHECK(im == NULL);
    /* Six channels, none unnamed: reading "everything" is more than 4 channels. */
    struct ssg_image *a = ssg_image_create(2, 2, 3), *b = ssg_image_create(2, 2, 3);
    struct ssg_exr_layer six[] = {{.name = "a", .image = a, .kind = SSG_LAYER_COLOR},
                                  {.name = "b", .image = b, .kind = SSG_LAYER_VECTOR}};
    struct ssg_diags d3 = {0};
    CHECK_EQ(ssg_exr_write(tmp_path("six.exr"), six, 2, &d3), SSG_OK);
    check_error(&d3, ssg_image_read(tmp_path("six.exr"), NULL, &im, &d3), SSG_E_SIZE,
                "six.exr");
    check_layer(tmp_path("six.exr"), "b", b);
    ssg_image_destroy(&a);
    ssg_image_destroy(&b);
}

/* A write that fails must leave the directory as it was: no target, no temporary file. */
static void check_failed_write(const char *dir, const char *target, int entries_before)
{
    struct ssg_image *im = pattern_image(4, 4, 3, 1.0f);
    struct ssg_exr_layer l = {.image = im};
    struct ssg_diags d = {0};
    check_error(&d, ssg_exr_write(target, &l, 1, &d), SSG_E_IO, target);
    struct ssg_diags d2 = {0};
    check_error(&d2, ssg_png_write(target, im, SSG_TONEMAP_ACES, 0, &d2), SSG_E_IO, target);
    int temps = 0;
    CHECK_EQ(count_entries(dir, &temps), entries_before);
    CHECK_EQ(temps, 0);
    ssg_image_destroy(&im);
}

static void test_failed_writes(void)
{
    const char *dir = tmp_path("fail");
    mkdir(dir, 0777);
    /* The target is a directory: the temporary file is complete, the rename fails. */
    const char *target_dir = tmp_path("fail/target.exr");
    mkdir(target_dir, 0777);
    check_failed_write(dir, target_dir, 1);
    /* The parent is a regular file: not even the temporary file can be made. */
    const char *file = tmp_path("fail/plain");
    FILE *f = fopen(file, "w");
    if (f)
        fclose(f);
    check_failed_write(dir, tmp_path("fail/plain/x.exr"), 2);
    /* The parent does not exist. */
    check_failed_write(dir, tmp_path("fail/missing/x.exr"), 2);
    /* A directory without write permission (root ignores permissions: skipped there). */
    if (geteuid() != 0) {
        const char *ro = tmp_path("fail/readonly");
        mkdir(ro, 0555);
        chmod(ro, 0555);
        check_failed_write(ro, tmp_path("fail/readonly/x.exr"), 0);
        remove_path(ro);
    }
    remove_path(target_dir);
    remove_path(file);
    remove_path(dir);
}

int main(void)
{
    setup_tmp("test_imageio");
    test_exr_round_trip();
    test_exr_bad_layers();
    test_png_codes();
    test_png_reads();
    test_determinism();
    test_thread_determinism();
    test_read_errors();
    test_tiled_reads();
    test_special_files();
    test_size_errors();
    test_failed_writes();
    return check_report();
}
