/* layers.h - `ssgraph layers FILE` and `ssgraph extract FILE LAYER -o OUT` (layers.c):
 * an image file's layers listed with their channels and value ranges, and one layer (or
 * one channel of it) written alone as EXR or PNG. Only the public header. */
#ifndef SSG_CLI_LAYERS_H
#define SSG_CLI_LAYERS_H

#include <stdio.h>

#include "ssgraph.h"

/* Prints `FILE: WxH, N layers` and a line per layer: name ("(unnamed)" for the unnamed
 * channels), channels, size, min, max, mean of its finite values (and how many are not
 * finite). Errors: the file's read errors. */
enum ssg_err ssg_cli_layers(const char *file, FILE *out, struct ssg_diags *diags);

/* Writes the layer (or the one channel) `spec` of file to output, an .exr or .png path
 * (checked by the caller), through a temporary file; tonemap and exposure are the PNG's.
 * An unknown layer is SSG_E_CHANNELS, its message listing the file's layers. */
enum ssg_err ssg_cli_extract(const char *file, const char *spec, const char *output,
                             const char *tonemap, float exposure, struct ssg_diags *diags);

#endif
