/* image_show.c - looking at images from outside a graph (ssgraph.h, "Looking at images"):
 * the write node's PNG preview of any image, and the list of an image file's layers.
 * The PNG goes through the writer the write node uses (png_io.c, tone curves in
 * tonemap.h), so a port shown by `ssgraph run --show` previews as a `write` of it would. */
#include <string.h>
#include <unistd.h>

#include "io/formats.h"
#include "lang/diag.h"

/* The tone curves by the names of the write node's `tonemap` choices, in enum order. */
static const char *const tonemap_names[] = {"clamp", "reinhard", "aces"};

static int tonemap_of(const char *name, enum ssg_tonemap *out)
{
    *out = SSG_TONEMAP_ACES; /* the write node's default */
    for (int i = 0; name && i < (int)(sizeof tonemap_names / sizeof *tonemap_names); i++)
        if (!strcmp(name, tonemap_names[i]))
            *out = (enum ssg_tonemap)i;
    return !name || !strcmp(name, tonemap_names[*out]);
}

/* The colour a PNG shows of a 2- or 4-channel image: red and green with blue 0, or the
   first three planes (planar: they come first, so a 4-channel image needs no copy). */
static const struct ssg_image *as_colour(const struct ssg_image *im, struct ssg_image *view,
                                         struct ssg_image **copy)
{
    *copy = NULL;
    if (im->channels == 1 || im->channels == 3)
        return im;
    if (im->channels == 4) {
        *view = (struct ssg_image){im->width, im->height, 3, im->data, NULL};
        return view;
    }
    if (!(*copy = ssg_image_create(im->width, im->height, 3)))
        return NULL;
    memcpy((*copy)->data, im->data,
           (size_t)im->width * (size_t)im->height * 2 * sizeof *im->data);
    return *copy;
}

enum ssg_err ssg_image_write_png(const char *path, const struct ssg_image *image,
                                 const char *tonemap, float exposure,
                                 struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_image_write_png", "path, image", 2, path, image))
        return SSG_E_USAGE;
    enum ssg_tonemap curve;
    if (!tonemap_of(tonemap, &curve)) {
        ssg_diag_file(diags, SSG_E_VALUE, path, "unknown tone curve '%s' (expected clamp, "
                      "reinhard or aces)", tonemap);
        return SSG_E_VALUE;
    }
    if (!image->data || image->channels < 1 || image->channels > 4) {
        ssg_diag_file(diags, SSG_E_CHANNELS, path, "a PNG preview shows 1 to 4 channels, "
                      "got %d", image->channels);
        return SSG_E_CHANNELS;
    }
    struct ssg_image view, *copy;
    const struct ssg_image *shown = as_colour(image, &view, &copy);
    if (!shown) {
        ssg_diag_file(diags, SSG_E_NOMEM, path, "out of memory for the preview");
        return SSG_E_NOMEM;
    }
    enum ssg_err e = ssg_png_write(path, shown, curve, exposure, diags);
    ssg_image_destroy(&copy);
    return e;
}

/* A file of one unnamed layer (PNG, HDR, ...): its channels Y; R,G; R,G,B; R,G,B,A. */
static enum ssg_err plain_layer(const char *path, struct ssg_layer_info *layers, int max,
                                int *count, struct ssg_diags *diags)
{
    static const char *const rgba[] = {"R", "G", "B", "A"};
    struct ssg_image *im = NULL;
    enum ssg_err e = ssg_image_read(path, NULL, &im, diags);
    if (e)
        return e;
    *count = 1;
    if (max > 0) {
        struct ssg_layer_info *l = &layers[0];
        memset(l, 0, sizeof *l);
        l->channel_count = im->channels;
        for (int k = 0; k < im->channels && k < 4; k++)
            snprintf(l->channels[k], sizeof l->channels[k], "%s",
                     im->channels == 1 ? "Y" : rgba[k]);
        l->width = im->width;
        l->height = im->height;
    }
    ssg_image_destroy(&im);
    return SSG_OK;
}

enum ssg_err ssg_image_layers(const char *path, struct ssg_layer_info *layers, int max,
                              int *count, struct ssg_diags *diags)
{
    if (count)
        *count = 0;
    if (ssg_api_null(diags, "ssg_image_layers", "path, count", 2, path, count) ||
        ssg_api_null(diags, "ssg_image_layers", "layers", max > 0, layers))
        return SSG_E_USAGE;
    char why[320];
    int fd = -1;
    enum ssg_err e = ssg_input_open(path, SSG_MAX_IMAGE_BYTES, &fd, why, sizeof why);
    if (e) {
        ssg_diag_file(diags, e, path, "cannot read image: %s", why);
        return e;
    }
    int exr = ssg_image_format_of(fd) == SSG_FORMAT_EXR;
    if (exr)
        e = ssg_exr_layers_fd(path, fd, layers, max, count, diags);
    close(fd);
    return exr ? e : plain_layer(path, layers, max, count, diags);
}
