/* oiio_host.h - inside the OpenImageIO module only (oiio_module.h): the library functions
 * the module calls, by their usual names, routed through the host table the library hands
 * over when it opens the module. Included last, after the headers that declare them. */
#ifndef SSG_OIIO_HOST_H
#define SSG_OIIO_HOST_H

#include "io/oiio_module.h"

extern "C" const struct ssg_oiio_host *ssg_oiio_host_fns;

#define ssg_diag_file ssg_oiio_host_fns->diag_file
#define ssg_image_create ssg_oiio_host_fns->image_create
#define ssg_image_destroy ssg_oiio_host_fns->image_destroy
#define ssg_image_size_ok ssg_oiio_host_fns->image_size_ok
#define ssg_input_open ssg_oiio_host_fns->input_open
#define ssg_tmp_create ssg_oiio_host_fns->tmp_create
#define ssg_tmp_discard ssg_oiio_host_fns->tmp_discard

/* The module's implementations of the api table (oiio_module_adapter.cc). */
extern "C" {
enum ssg_err ssg_oiio_image_read(const char *path, const char *layer, struct ssg_image **out,
                                 struct ssg_diags *diags);
enum ssg_err ssg_oiio_exr_stage(const char *path, const struct ssg_exr_layer *layers,
                                int count, enum ssg_exr_compression compression,
                                const struct ssg_exr_meta *meta, struct ssg_tmp *t,
                                struct ssg_diags *diags);
enum ssg_err ssg_oiio_exr_meta_read(const char *path, struct ssg_exr_meta *meta, int *found,
                                    struct ssg_diags *diags);
enum ssg_err ssg_oiio_views_stage(const char *path, const char *const *views,
                                  const char *const *files, int count, struct ssg_tmp *t,
                                  struct ssg_diags *diags);
enum ssg_err ssg_oiio_png_stage(const char *path, const struct ssg_image *image,
                                enum ssg_tonemap tonemap, float exposure, struct ssg_tmp *t,
                                struct ssg_diags *diags);
enum ssg_err ssg_oiio_text_draw(struct ssg_image *im, int x, int y, int size,
                                const char *text, struct ssg_diags *diags);
}

#endif
