/* formats.h - private to core/io: the image formats built into the library, which
 * imageio_load.c hands a file to by its first bytes: OpenEXR through OpenEXRCore
 * (exr_read.c, exr_write.c, exr_views.c) and PNG through libpng (png_io.c). Every other
 * format goes to the OpenImageIO module (oiio_module.h). The contracts are imageio.h's.
 * Thread-safe: no state. */
#ifndef SSG_FORMATS_H
#define SSG_FORMATS_H

#include "io/imageio.h"

/* What a file's first bytes say it is. */
enum ssg_image_format { SSG_FORMAT_OTHER, SSG_FORMAT_EXR, SSG_FORMAT_PNG };
enum ssg_image_format ssg_image_format_of(int fd);

/* ssg_image_read of the EXR or PNG file open as fd (checked by ssg_input_open; the caller
   closes it): layer NULL or "" is the main image. An EXR whose compression OpenEXRCore
   cannot decode (DWAA, DWAB) is not read: *elsewhere = 1, SSG_OK, for OpenImageIO to read
   (after the checks of exr_guard.h, which such a file has passed then). */
enum ssg_err ssg_exr_read_fd(const char *path, int fd, const char *layer,
                             struct ssg_image **out, int *elsewhere, struct ssg_diags *diags);
/* data 1: the stored values scaled to [0, 1], never sRGB-decoded (a normal map). */
enum ssg_err ssg_png_read_fd(const char *path, int fd, int data, struct ssg_image **out,
                             struct ssg_diags *diags);

/* 1 when a file of file_bytes can hold w x h pixels of nch floats; else 0, reported
   against path: no format packs more than 65536 bytes of float pixels into a byte of file
   (zlib's limit is about 1032:1; a constant 8192^2 half EXR is 1800:1 of our floats), so a
   header that declares more (a 23-byte file claiming a gigabyte of pixels, found by
   fuzz_image) is refused before the image is allocated. */
int ssg_image_plausible(const char *path, int w, int h, int nch, long long file_bytes,
                        struct ssg_diags *diags);

/* ssg_image_layers of the EXR open as fd (exr_read.c). */
enum ssg_err ssg_exr_layers_fd(const char *path, int fd, struct ssg_layer_info *layers,
                               int max, int *count, struct ssg_diags *diags);

/* ssg_exr_meta_read of the EXR open as fd. */
enum ssg_err ssg_exr_meta_read_fd(const char *path, int fd, struct ssg_exr_meta *meta,
                                  int *found, struct ssg_diags *diags);

/* ssg_exr_views_join's file, staged in t (files.h) for the caller to commit. */
enum ssg_err ssg_exr_views_stage(const char *path, const char *const *views,
                                 const char *const *files, int count, struct ssg_tmp *t,
                                 struct ssg_diags *diags);

#endif
