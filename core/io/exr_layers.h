/* exr_layers.h - private to core/io: the rules that turn the layers of an EXR to write
 * (imageio.h, struct ssg_exr_layer) into channel names, in one place for the writers
 * (exr_write.c) and the reader's depth rule (exr_read.c). Stateless, thread-safe. */
#ifndef SSG_EXR_LAYERS_H
#define SSG_EXR_LAYERS_H

#include "io/imageio.h"

/* 1 for the main image (no name or ""): plain channels R,G,B / Y. */
int ssg_exr_layer_is_main(const struct ssg_exr_layer *l);

/* 1 for the scalar layer `depth`: OpenEXR's depth channel, a bare Z, as Blender and Nuke
   read depth (the reader reads Z back under the layer name). */
int ssg_exr_layer_is_depth(const struct ssg_exr_layer *l);

/* The channel suffixes of a layer in its channel order (Y; R,G,B,A; X,Y,Z; Z), or NULL
   when its channel count does not fit its kind. */
const char *const *ssg_exr_layer_suffixes(const struct ssg_exr_layer *l);

/* Checks the layers against each other (images present, one size, channel counts, no '.'
   in a name, no name twice); reports every problem against path, returns the first. */
enum ssg_err ssg_exr_layers_check(const char *path, const struct ssg_exr_layer *layers,
                                  int count, struct ssg_diags *diags);

#endif
