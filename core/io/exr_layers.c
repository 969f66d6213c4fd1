/* exr_layers.c - layer names and kinds into EXR channel names (exr_layers.h). */
#include <string.h>

#include "io/exr_layers.h"
#include "lang/diag.h"

int ssg_exr_layer_is_main(const struct ssg_exr_layer *l)
{
    return !l->name || !l->name[0];
}

int ssg_exr_layer_is_depth(const struct ssg_exr_layer *l)
{
    return !ssg_exr_layer_is_main(l) && l->kind == SSG_LAYER_SCALAR &&
           strcmp(l->name, "depth") == 0;
}

const char *const *ssg_exr_layer_suffixes(const struct ssg_exr_layer *l)
{
    static const char *const gray[] = {"Y"}, *const rgba[] = {"R", "G", "B", "A"},
                             *const xyz[] = {"X", "Y", "Z"}, *const z[] = {"Z"};
    int ch = l->image->channels;
    if (ssg_exr_layer_is_main(l))
        return ch == 1 ? gray : ch >= 2 && ch <= 4 ? rgba : NULL;
    switch (l->kind) {
    case SSG_LAYER_SCALAR: return ch == 1 ? (ssg_exr_layer_is_depth(l) ? z : gray) : NULL;
    case SSG_LAYER_VECTOR: return ch == 3 ? xyz : NULL;
    case SSG_LAYER_COLOR: return ch == 3 ? rgba : NULL;
    }
    return NULL;
}

/* Whether layer i repeats an earlier one's name (the main image counts as one name). */
static int repeated(const struct ssg_exr_layer *layers, int i)
{
    const struct ssg_exr_layer *l = &layers[i];
    for (int j = 0; j < i; j++)
        if (ssg_exr_layer_is_main(l) == ssg_exr_layer_is_main(&layers[j]) &&
            (ssg_exr_layer_is_main(l) || strcmp(l->name, layers[j].name) == 0))
            return 1;
    return 0;
}

/* The problems of layer i against layer 0; the first one's code, SSG_OK for none. */
static enum ssg_err check_one(const char *path, const struct ssg_exr_layer *layers, int i,
                              struct ssg_diags *diags)
{
    const struct ssg_exr_layer *l = &layers[i], *first = &layers[0];
    const char *name = ssg_exr_layer_is_main(l) ? "(main)" : l->name;
    enum ssg_err e = SSG_OK;
    if (!l->image || !l->image->data) {
        ssg_diag_file(diags, SSG_E_VALUE, path, "layer '%s' has no image", name);
        return SSG_E_VALUE;
    }
    if (l->image->width != first->image->width || l->image->height != first->image->height) {
        ssg_diag_file(diags, SSG_E_SIZE, path, "layer '%s' is %d x %d, expected %d x %d", name,
                      l->image->width, l->image->height, first->image->width,
                      first->image->height);
        e = SSG_E_SIZE;
    }
    if (!ssg_exr_layer_suffixes(l)) {
        ssg_diag_file(diags, SSG_E_CHANNELS, path, "layer '%s' has %d channels, expected %s",
                      name, l->image->channels, ssg_exr_layer_is_main(l) ? "1 to 4"
                                                : l->kind == SSG_LAYER_SCALAR ? "1" : "3");
        e = e ? e : SSG_E_CHANNELS;
    }
    if (!ssg_exr_layer_is_main(l) && strchr(l->name, '.')) {
        ssg_diag_file(diags, SSG_E_VALUE, path, "layer name '%s' contains a '.'", name);
        e = e ? e : SSG_E_VALUE;
    }
    if (repeated(layers, i)) {
        ssg_diag_file(diags, SSG_E_DUPLICATE, path, "layer '%s' is given twice", name);
        e = e ? e : SSG_E_DUPLICATE;
    }
    return e;
}

enum ssg_err ssg_exr_layers_check(const char *path, const struct ssg_exr_layer *layers,
                                  int count, struct ssg_diags *diags)
{
    if (count < 1) {
        ssg_diag_file(diags, SSG_E_VALUE, path, "no layers to write");
        return SSG_E_VALUE;
    }
    if (!layers[0].image || !layers[0].image->data) {
        ssg_diag_file(diags, SSG_E_VALUE, path, "layer '%s' has no image",
                      ssg_exr_layer_is_main(&layers[0]) ? "(main)" : layers[0].name);
        return SSG_E_VALUE;
    }
    enum ssg_err first = SSG_OK;
    for (int i = 0; i < count; i++) {
        enum ssg_err e = check_one(path, layers, i, diags);
        first = first ? first : e;
    }
    return first;
}
