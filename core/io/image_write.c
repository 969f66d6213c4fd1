/* image_write.c - ssg_image_write (ssgraph.h): one image as the main layer of an EXR. */
#include "io/imageio.h"
#include "lang/diag.h"

enum ssg_err ssg_image_write(const char *path, const struct ssg_image *image,
                             struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_image_write", "path, image", 2, path, image))
        return SSG_E_USAGE;
    enum ssg_layer_kind kind = image->channels == 1 ? SSG_LAYER_SCALAR : SSG_LAYER_COLOR;
    struct ssg_exr_layer layer = {NULL, image, kind};
    return ssg_exr_write(path, &layer, 1, diags);
}
