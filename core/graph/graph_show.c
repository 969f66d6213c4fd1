/* graph_show.c - what a caller needs to look at a loaded graph's ports as the write node
 * writes them (ssgraph.h, "Looking at images"): the graph's frame, and an image without
 * its guard band. The write node (nodes/write/write_cpu.c) frames its layers with the same
 * function, so `ssgraph run --show` writes the very pixels a `write` of that port would. */
#include <string.h>

#include "graph/graph.h"

void ssg_graph_frame(const struct ssg_graph *graph, struct ssg_frame *frame)
{
    if (frame)
        *frame = graph ? graph->frame : SSG_FRAME_DEFAULTS;
}

const struct ssg_image *ssg_image_framed(const struct ssg_frame *frame,
                                         const struct ssg_image *image,
                                         struct ssg_image **copy)
{
    if (!copy || !image)
        return NULL;
    *copy = NULL;
    if (!frame)
        return image;
    struct ssg_shape shape = {image->width, image->height, image->channels, 0};
    int x0, y0, x1, y1;
    ssg_frame_region(frame, &shape, &x0, &y0, &x1, &y1);
    if (x0 == 0 && y0 == 0 && x1 == image->width && y1 == image->height)
        return image;
    if (!(*copy = ssg_image_create(x1 - x0, y1 - y0, image->channels)))
        return NULL;
    for (int ch = 0; ch < image->channels; ch++) {
        const float *src = ssg_image_plane(image, ch);
        float *dst = ssg_image_plane(*copy, ch);
        for (int y = y0; y < y1; y++)
            memcpy(dst + (size_t)(y - y0) * (size_t)(x1 - x0),
                   src + (size_t)y * (size_t)image->width + (size_t)x0,
                   (size_t)(x1 - x0) * sizeof(float));
    }
    return *copy;
}
