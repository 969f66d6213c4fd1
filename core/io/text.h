/* text.h - labels drawn into images (text_adapter.cc, OpenImageIO's render_text with the
 * DejaVu Sans TrueType font; Debian: fonts-dejavu-core), for contact sheets. */
#ifndef SSG_TEXT_H
#define SSG_TEXT_H

#include "ssgraph.h"

/* Draws white text on a darkened box into the 3-channel image im, its top-left corner at
 * (x, y), `size` pixels high; clipped to the image. SSG_E_BACKEND with a message in diags
 * when no font can be found. */
enum ssg_err ssg_text_draw(struct ssg_image *im, int x, int y, int size, const char *text,
                           struct ssg_diags *diags);

#endif
