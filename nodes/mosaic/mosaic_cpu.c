/* mosaic_cpu.c - the `mosaic` node's layout and resampling (method in README.md). */
#include <math.h>
#include <string.h>

#include "mosaic.h"
#include "io/text.h"

struct cell {
    int x, y, w, h; /* where the image lands (aspect kept, centred in its cell) */
};

/* The value shown for channel c of image pixel i: grey for scalars, 0.5 + 0.5 v for
   vectors. */
static float shown(const struct ssg_image *im, unsigned type, int c, size_t i)
{
    size_t plane = (size_t)im->width * im->height;
    float v = im->data[(im->channels == 1 ? 0 : (size_t)c) * plane + i];
    return type == SSG_T_VECTOR ? 0.5f + 0.5f * v : v;
}

/* Box-filtered resampling of im into the cell: each output pixel averages the source
   pixels its footprint covers (at least the nearest one). */
static void paint(struct ssg_image *out, const struct ssg_image *im, unsigned type,
                  const struct cell *k)
{
    size_t plane = (size_t)out->width * out->height;
    double sx = (double)im->width / k->w, sy = (double)im->height / k->h;
    for (int y = 0; y < k->h; y++) {
        int y0 = (int)(y * sy), y1 = (int)fmax(y0 + 1, (y + 1) * sy);
        for (int x = 0; x < k->w; x++) {
            int x0 = (int)(x * sx), x1 = (int)fmax(x0 + 1, (x + 1) * sx);
            double sum[3] = {0, 0, 0};
            for (int v = y0; v < y1 && v < im->height; v++)
                for (int u = x0; u < x1 && u < im->width; u++)
                    for (int c = 0; c < 3; c++)
                        sum[c] += shown(im, type, c, (size_t)v * im->width + u);
            double n = (double)(y1 - y0) * (x1 - x0);
            size_t at = (size_t)(k->y + y) * out->width + (size_t)(k->x + x);
            for (int c = 0; c < 3; c++)
                out->data[c * plane + at] = (float)(sum[c] / n);
        }
    }
}

/* Cell i of a grid of cols x rows over the image, the image's aspect kept. */
static struct cell place(const struct ssg_image *out, const struct ssg_image *im, int i,
                         int cols, int rows, int gap)
{
    int cw = (out->width - gap * (cols - 1)) / cols,
        ch = (out->height - gap * (rows - 1)) / rows;
    double scale = fmin((double)cw / im->width, (double)ch / im->height);
    struct cell k = {0, 0, (int)(im->width * scale), (int)(im->height * scale)};
    k.w = k.w < 1 ? 1 : k.w, k.h = k.h < 1 ? 1 : k.h;
    k.x = (i % cols) * (cw + gap) + (cw - k.w) / 2;
    k.y = (i / cols) * (ch + gap) + (ch - k.h) / 2;
    return k;
}

enum ssg_err ssg_mosaic_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io)
{
    const struct ssg_mosaic_params *p = consts;
    struct ssg_image *out = io->out[SSG_MOSAIC_OUT_OUT];
    int n = io->extra_count;
    if (n < 1)
        return ssg_node_fail(ctx, SSG_E_MISSING_INPUT, "needs at least one "
                             "name=node.port argument to show");
    int cols = p->columns > 0 ? p->columns : (int)ceil(sqrt((double)n));
    cols = cols > n ? n : cols;
    int rows = (n + cols - 1) / cols;
    if ((out->width - p->gap * (cols - 1)) / cols < 1 ||
        (out->height - p->gap * (rows - 1)) / rows < 1)
        return ssg_node_fail(ctx, SSG_E_VALUE, "the frame (%dx%d) is too small for %d "
                             "cells with gap %d (fewer columns or a smaller gap)",
                             out->width, out->height, n, p->gap);
    memset(out->data, 0, sizeof(float) * 3 * (size_t)out->width * out->height);
    for (int i = 0; i < n; i++) {
        struct cell k = place(out, io->extra_in[i], i, cols, rows, p->gap);
        paint(out, io->extra_in[i], io->extra_types[i], &k);
        int size = p->font_size ? p->font_size : (k.h / 16 > 10 ? k.h / 16 : 10);
        enum ssg_err e = p->labels ? ssg_text_draw(out, k.x + size / 3, k.y + size / 4, size,
                                                   io->extra_names[i], ctx->diags)
                                   : SSG_OK;
        if (e)
            return e;
    }
    return SSG_OK;
}
