/* image.h - the image pool of a graph run. Every intermediate image is taken from the pool
 * and given back after its last reader has run; the pool reuses images of the same shape,
 * so a graph's peak memory is its widest cut, not the sum of its images. One pool per run,
 * used by one thread (the executor). */
#ifndef SSG_IMAGE_H
#define SSG_IMAGE_H

#include <stddef.h>

#include "ssgraph.h"

/* Largest side and pixel count an image may have; larger requests are errors. */
#define SSG_IMAGE_MAX_SIDE 16384
#define SSG_IMAGE_MAX_PIXELS (64 * 1024 * 1024)
/* Most channels an image may have: a stack of shadow maps has one per light (2048 is also
 * the GL 4.5 minimum of GL_MAX_ARRAY_TEXTURE_LAYERS, each channel being one layer). */
#define SSG_IMAGE_MAX_CHANNELS 2048
/* Most floats (width x height x channels) one image may hold: 2 GiB, 512 shadow maps of
 * 1024 x 1024. */
#define SSG_IMAGE_MAX_FLOATS (512ll * 1024 * 1024)

/* 1 when width x height x channels is a size ssg_image_create accepts. */
int ssg_image_size_ok(int width, int height, int channels);

struct ssg_pool;
struct ssg_pool *ssg_pool_create(void);
void ssg_pool_destroy(struct ssg_pool **pool);
/* An image of that shape: a free one of the same shape, else a new zeroed one. Its
 * contents are undefined (nodes write every pixel of their outputs). NULL when out of
 * memory. */
struct ssg_image *ssg_pool_acquire(struct ssg_pool *pool, int width, int height, int channels);
/* Gives an image back for reuse. */
void ssg_pool_release(struct ssg_pool *pool, struct ssg_image *image);
/* Bytes of pixel data held now (in use + free) and the most ever held. */
size_t ssg_pool_bytes(const struct ssg_pool *pool);
size_t ssg_pool_peak_bytes(const struct ssg_pool *pool);

#endif
