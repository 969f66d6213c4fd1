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

/* The module's implementations of the api table (oiio_module_adapter.cc). */
extern "C" {
enum ssg_err ssg_oiio_image_read(const char *path, const char *layer, struct ssg_image **out,
                                 struct ssg_diags *diags);
enum ssg_err ssg_oiio_text_draw(struct ssg_image *im, int x, int y, int size,
                                const char *text, struct ssg_diags *diags);
}

#endif
