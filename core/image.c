/* image.c - planar float images and the pool that recycles them (image.h). */
#include <stdlib.h>

#include "image.h"

int ssg_image_size_ok(int width, int height, int channels)
{
    return width > 0 && height > 0 && width <= SSG_IMAGE_MAX_SIDE &&
           height <= SSG_IMAGE_MAX_SIDE && (long long)width * height <= SSG_IMAGE_MAX_PIXELS &&
           channels >= 1 && channels <= 4;
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
    im->data = calloc((size_t)width * (size_t)height * (size_t)channels, sizeof(float));
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
