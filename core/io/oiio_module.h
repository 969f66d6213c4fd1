/* oiio_module.h - the seam between the library and its OpenImageIO module.
 *
 * Everything that touches OpenImageIO (imageio_adapter.cc, text_adapter.cc) is built as a
 * module of its own, libssgraph_oiio.so, which imageio_load.c opens with dlopen the first
 * time it is needed: to read a format the library does not read itself (JPEG, HDR, TIFF,
 * ...: EXR and PNG are built in, formats.h) or to draw text. Why: linking OpenImageIO pulls
 * in some 250 shared libraries (codecs, OpenCV, OpenVDB, ...) whose dynamic linking costs
 * 0.3-0.7 s, which `ssgraph nodes`, `check`, every run that writes its EXR and PNG, every
 * test and every bench cell would pay for nothing.
 *
 * The module calls back into the library only through the host table below (the module
 * sees the library's functions under their usual names: oiio_host.h maps them), and the
 * library calls the module only through the api table; both are plain C. The ABI number
 * changes whenever either table does, so a stale module is refused, not misused. */
#ifndef SSG_OIIO_MODULE_H
#define SSG_OIIO_MODULE_H

#ifdef __cplusplus
extern "C" {
#endif

#include "graph/image.h"
#include "io/imageio.h"
#include "io/text.h"
#include "lang/diag.h"
#include "lang/files.h"

#define SSG_OIIO_MODULE_ABI 3
#define SSG_OIIO_MODULE_FILE "libssgraph_oiio.so"
#define SSG_OIIO_MODULE_ENTRY "ssg_oiio_module"

/* What the module uses of the library. */
struct ssg_oiio_host {
    void (*diag_file)(struct ssg_diags *diags, enum ssg_err code, const char *file,
                      const char *fmt, ...);
    struct ssg_image *(*image_create)(int width, int height, int channels);
    void (*image_destroy)(struct ssg_image **image);
    int (*image_size_ok)(int width, int height, int channels);
    enum ssg_err (*input_open)(const char *path, long long max_bytes, int *fd, char *why,
                               size_t why_len);
};

/* What the library uses of the module: ssg_image_read (ssgraph.h) for the formats other
   than EXR and PNG, and ssg_text_draw (text.h), with the same contracts. */
struct ssg_oiio_api {
    enum ssg_err (*image_read)(const char *path, const char *layer, struct ssg_image **out,
                               struct ssg_diags *diags);
    enum ssg_err (*text_draw)(struct ssg_image *im, int x, int y, int size, const char *text,
                              struct ssg_diags *diags);
};

/* The module's one exported symbol: its api for a host of this ABI, or NULL. */
typedef const struct ssg_oiio_api *(*ssg_oiio_module_fn)(int abi,
                                                         const struct ssg_oiio_host *host);

#ifdef __cplusplus
}
#endif

#endif
