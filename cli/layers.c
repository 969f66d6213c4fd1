/* layers.c - `ssgraph layers` and `ssgraph extract` (layers.h). A layer is read with
 * ssg_image_read under the name ssg_image_layers gives it, so what is listed is what
 * `extract`, `node --in PORT=FILE:LAYER` and `compare FILE:LAYER` read. Only the public
 * header. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "layers.h"

/* A file's layers: the first SSG_LAYERS_MAX of them, on the heap (some 40 KB). */
struct layer_list {
    int count;  /* in the file */
    int listed; /* in items */
    struct ssg_layer_info items[SSG_LAYERS_MAX];
};

static enum ssg_err list_layers(const char *file, struct layer_list **out,
                                struct ssg_diags *d)
{
    struct layer_list *l = calloc(1, sizeof *l);
    if (!(*out = l))
        return SSG_E_NOMEM;
    enum ssg_err e = ssg_image_layers(file, l->items, SSG_LAYERS_MAX, &l->count, d);
    l->listed = l->count < SSG_LAYERS_MAX ? l->count : SSG_LAYERS_MAX;
    return e;
}

static const char *shown_name(const struct ssg_layer_info *info)
{
    return info->name[0] ? info->name : "(unnamed)";
}

/* "ao.Y" or "R,G,B": the channels as the file names them. */
static void channel_list(const struct ssg_layer_info *info, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int k = 0; k < info->channel_count && k < 4 && used < len; k++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", k ? "," : "",
                                 info->channels[k]);
    if (info->channel_count > 4 && used < len)
        snprintf(buf + used, len - used, ",... (%d)", info->channel_count);
}

/* min, max, mean of the finite values of an image; *nonfinite counts the others. */
static void value_range(const struct ssg_image *im, double *lo, double *hi, double *mean,
                        size_t *nonfinite)
{
    size_t n = (size_t)im->width * (size_t)im->height * (size_t)im->channels, finite = 0;
    double sum = 0;
    *lo = INFINITY, *hi = -INFINITY, *nonfinite = 0;
    for (size_t i = 0; i < n; i++) {
        double v = im->data[i];
        if (!isfinite(v)) {
            ++*nonfinite;
            continue;
        }
        finite++;
        sum += v;
        *lo = v < *lo ? v : *lo;
        *hi = v > *hi ? v : *hi;
    }
    *mean = finite ? sum / (double)finite : NAN;
    if (!finite)
        *lo = *hi = NAN;
}

/* One layer's line; its read errors go to d. */
static enum ssg_err print_layer(const char *file, const struct ssg_layer_info *info,
                                int name_width, int channel_width, FILE *out,
                                struct ssg_diags *d)
{
    char channels[600];
    channel_list(info, channels, sizeof channels);
    fprintf(out, "%-*s  %-*s  %dx%d", name_width, shown_name(info), channel_width, channels,
            info->width, info->height);
    if (info->channel_count > 4) {
        fputs("  (too many channels to read as one image)\n", out);
        return SSG_OK;
    }
    struct ssg_image *im = NULL;
    enum ssg_err e = ssg_image_read(file, info->name[0] ? info->name : NULL, &im, d);
    if (e) {
        fputc('\n', out);
        return e;
    }
    double lo, hi, mean;
    size_t nonfinite;
    value_range(im, &lo, &hi, &mean, &nonfinite);
    fprintf(out, "  min %-10.6g max %-10.6g mean %.6g", lo, hi, mean);
    if (nonfinite)
        fprintf(out, "  not finite %zu", nonfinite);
    fputc('\n', out);
    ssg_image_destroy(&im);
    return SSG_OK;
}

enum ssg_err ssg_cli_layers(const char *file, FILE *out, struct ssg_diags *d)
{
    struct layer_list *l = NULL;
    enum ssg_err e = list_layers(file, &l, d);
    int name_width = 4, channel_width = 8;
    for (int i = 0; !e && i < l->listed; i++) {
        char channels[600];
        channel_list(&l->items[i], channels, sizeof channels);
        int nw = (int)strlen(shown_name(&l->items[i])), cw = (int)strlen(channels);
        name_width = nw > name_width ? nw : name_width;
        channel_width = cw > channel_width ? cw : channel_width;
    }
    if (!e)
        fprintf(out, "%s: %d layer%s\n", file, l->count, l->count == 1 ? "" : "s");
    for (int i = 0; !e && i < l->listed; i++)
        e = print_layer(file, &l->items[i], name_width, channel_width, out, d);
    if (!e && l->count > l->listed)
        fprintf(out, "... and %d more\n", l->count - l->listed);
    free(l);
    return e;
}

/* The layer spec names: a layer's name ("(unnamed)" too), else one channel of a layer
   (*channel its index when the layer has more, else -1); NULL when none. */
static const struct ssg_layer_info *find_layer(const struct layer_list *l, const char *spec,
                                               int *channel)
{
    *channel = -1;
    for (int i = 0; i < l->listed; i++)
        if (!strcmp(spec, l->items[i].name) || !strcmp(spec, shown_name(&l->items[i])))
            return &l->items[i];
    for (int i = 0; i < l->listed; i++)
        for (int k = 0; k < l->items[i].channel_count && k < 4; k++)
            if (!strcmp(spec, l->items[i].channels[k])) {
                *channel = l->items[i].channel_count > 1 ? k : -1;
                return &l->items[i];
            }
    return NULL;
}

/* Channel k of im alone, in place (planar: its plane moves to the front). */
static void keep_channel(struct ssg_image *im, int k)
{
    size_t plane = (size_t)im->width * (size_t)im->height;
    memmove(im->data, im->data + (size_t)k * plane, plane * sizeof *im->data);
    im->channels = 1;
}

static int ends_with(const char *s, const char *tail)
{
    size_t n = strlen(s), t = strlen(tail);
    return n > t && !strcmp(s + n - t, tail);
}

enum ssg_err ssg_cli_extract(const char *file, const char *spec, const char *output,
                             const char *tonemap, float exposure, struct ssg_diags *d)
{
    struct layer_list *l = NULL;
    struct ssg_image *im = NULL;
    int channel = -1;
    enum ssg_err e = list_layers(file, &l, d);
    const struct ssg_layer_info *info = e ? NULL : find_layer(l, spec, &channel);
    /* a spec that is neither goes to the reader as it is: it reads what it can (a view's
       depth.right) and names the file's layers when it cannot */
    const char *layer = !info ? spec : info->name[0] ? info->name : NULL;
    if (!e)
        e = ssg_image_read(file, layer, &im, d);
    if (!e && channel >= 0)
        keep_channel(im, channel);
    if (!e)
        e = ends_with(output, ".png") ? ssg_image_write_png(output, im, tonemap, exposure, d)
                                      : ssg_image_write(output, im, d);
    ssg_image_destroy(&im);
    free(l);
    return e;
}
