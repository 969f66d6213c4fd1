/* image.c - planar float images and the pool that recycles them (image.h). */
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#include "graph/gl_backend.h"
#include "graph/image.h"

enum { HUGE_PAGE = 2 * 1024 * 1024 };

/* Zeroed pixel memory. Frame-sized planes are 2 MiB aligned and marked for transparent
 * huge pages: first-touch page faults of a 1080p G-buffer cost ~120 ms with 4 KiB pages
 * and ~20 ms with huge ones (this machine's THP setting is "madvise"). */
static float *pixels_alloc(size_t bytes)
{
    if (bytes < 2 * (size_t)HUGE_PAGE)
        return calloc(1, bytes);
    void *p = NULL;
    size_t rounded = (bytes + HUGE_PAGE - 1) / HUGE_PAGE * HUGE_PAGE;
    if (posix_memalign(&p, HUGE_PAGE, rounded) != 0)
        return NULL;
#ifdef MADV_HUGEPAGE
    madvise(p, rounded, MADV_HUGEPAGE);
#endif
    memset(p, 0, bytes);
    return p;
}

int ssg_image_size_ok(int width, int height, int channels)
{
    return width > 0 && height > 0 && width <= SSG_IMAGE_MAX_SIDE &&
           height <= SSG_IMAGE_MAX_SIDE && (long long)width * height <= SSG_IMAGE_MAX_PIXELS &&
           channels >= 1 && channels <= SSG_IMAGE_MAX_CHANNELS &&
           (long long)width * height * channels <= SSG_IMAGE_MAX_FLOATS;
}

struct ssg_image *ssg_image_create(int width, int height, int channels)
{
    if (!ssg_image_size_ok(width, height, channels))
        return NULL;
    struct ssg_image *im = malloc(sizeof *im);
    if (!im)
        return NULL;
    im->width = width;
    im->height = height;
    im->channels = channels;
    im->gpu = NULL;
    im->data = pixels_alloc((size_t)width * (size_t)height * (size_t)channels * sizeof(float));
    if (!im->data) {
        free(im);
        return NULL;
    }
    return im;
}

void ssg_image_destroy(struct ssg_image **image)
{
    if (!image || !*image)
        return;
    ssg_gl_image_free(*image);
    free((*image)->data);
    free(*image);
    *image = NULL;
}

static size_t image_bytes(const struct ssg_image *im)
{
    return (size_t)im->width * (size_t)im->height * (size_t)im->channels * sizeof(float);
}

enum { POOL_MAX = 256 };

struct ssg_pool {
    struct ssg_image *free_list[POOL_MAX];
    int free_count;
    size_t bytes, peak;
};

struct ssg_pool *ssg_pool_create(void)
{
    return calloc(1, sizeof(struct ssg_pool));
}

void ssg_pool_destroy(struct ssg_pool **pool)
{
    if (!pool || !*pool)
        return;
    for (int i = 0; i < (*pool)->free_count; i++)
        ssg_image_destroy(&(*pool)->free_list[i]);
    free(*pool);
    *pool = NULL;
}

struct ssg_image *ssg_pool_acquire(struct ssg_pool *pool, int width, int height, int channels)
{
    for (int i = 0; i < pool->free_count; i++) {
        struct ssg_image *im = pool->free_list[i];
        if (im->width == width && im->height == height && im->channels == channels) {
            pool->free_list[i] = pool->free_list[--pool->free_count];
            return im;
        }
    }
    struct ssg_image *im = ssg_image_create(width, height, channels);
    if (im) {
        pool->bytes += image_bytes(im);
        if (pool->bytes > pool->peak)
            pool->peak = pool->bytes;
    }
    return im;
}

void ssg_pool_release(struct ssg_pool *pool, struct ssg_image *image)
{
    if (!image)
        return;
    if (pool->free_count < POOL_MAX) {
        pool->free_list[pool->free_count++] = image;
        return;
    }
    pool->bytes -= image_bytes(image);
    ssg_image_destroy(&image);
}

size_t ssg_pool_bytes(const struct ssg_pool *pool)
{
    return pool->bytes;
}

size_t ssg_pool_peak_bytes(const struct ssg_pool *pool)
{
    return pool->peak;
}
