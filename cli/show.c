/* show.c - `ssgraph run --show` (show.h): the graph runs unchanged, its sinks writing
 * their files, while the library hands out the shown ports' last images; each is written
 * beside the run's files as the write node would write it as its main image: without the
 * guard band (ssg_image_framed), a 32-bit float EXR (Y or R,G,B) and the write node's PNG
 * preview (ssg_image_write_png). Only the public header. */
#include <stdio.h>
#include <string.h>

#include "options.h"
#include "show.h"

/* 1 when text is NAME.NAME with names of letters, digits and '_' (so that the file name
   made of it stays a plain one). */
static int is_port(const char *text)
{
    const char *dot = strchr(text, '.');
    if (!dot || dot == text || !dot[1])
        return 0;
    for (const char *c = text; *c; c++)
        if (c != dot && !(*c == '_' || (*c >= '0' && *c <= '9') || (*c >= 'a' && *c <= 'z') ||
                          (*c >= 'A' && *c <= 'Z')))
            return 0;
    return 1;
}

int ssg_cli_show_parse(const char *list, struct ssg_cli_show *s)
{
    memset(s, 0, sizeof *s);
    if (strlen(list) >= sizeof s->text)
        return ssg_cli_usage_error("--show: the list is too long, at '%.40s'", list);
    snprintf(s->text, sizeof s->text, "%s", list);
    for (char *p = s->text, *next; p; p = next) {
        next = strchr(p, ',');
        if (next)
            *next++ = '\0';
        if (!is_port(p))
            return ssg_cli_usage_error("--show expects NODE.PORT[,NODE.PORT...], got '%s'",
                                       p[0] ? p : list);
        for (int i = 0; i < s->count; i++)
            if (!strcmp(s->ports[i], p))
                return ssg_cli_usage_error("--show names '%s' twice", p);
        if (s->count == SSG_MAX_OUTPUTS)
            return ssg_cli_usage_error("--show: at most 8 ports, at '%s'", p);
        s->ports[s->count++] = p;
    }
    return 0;
}

void ssg_cli_show_request(struct ssg_cli_show *s, struct ssg_overrides *ov,
                          struct ssg_run_options *ro)
{
    ov->outputs = s->ports;
    ov->output_count = s->count;
    ov->keep_sinks = 1;
    ro->outputs = s->images;
}

/* One port's image as NAME.exr and NAME.png in out_dir. */
static enum ssg_err write_port(const char *name, const struct ssg_image *im,
                               const char *out_dir, const char *tonemap, float exposure,
                               int quiet, struct ssg_diags *d)
{
    char path[1200];
    const char *ext[2] = {"exr", "png"};
    for (int i = 0; i < 2; i++) {
        snprintf(path, sizeof path, "%s/%s.%s", out_dir, name, ext[i]);
        enum ssg_err e = i ? ssg_image_write_png(path, im, tonemap, exposure, d)
                           : ssg_image_write(path, im, d);
        if (e)
            return e;
        if (!quiet)
            printf("wrote %s\n", path);
    }
    return SSG_OK;
}

enum ssg_err ssg_cli_show_write(const struct ssg_cli_show *s, const struct ssg_graph *g,
                                const char *out_dir, const char *tonemap, float exposure,
                                int quiet, struct ssg_diags *d)
{
    struct ssg_frame frame;
    ssg_graph_frame(g, &frame);
    enum ssg_err e = ssg_make_dirs(out_dir, d);
    for (int i = 0; i < s->count && !e; i++) {
        struct ssg_image *copy = NULL;
        const struct ssg_image *im = ssg_image_framed(&frame, s->images[i], &copy);
        if (!im)
            return SSG_E_NOMEM;
        if (im->channels > 4)
            fprintf(stderr, "ssgraph: note: '%s' has %d channels: shown are the first 4\n",
                    s->ports[i], im->channels);
        struct ssg_image first = *im; /* planar: the first planes are a prefix */
        first.channels = im->channels > 4 ? 4 : im->channels;
        e = write_port(s->ports[i], &first, out_dir, tonemap, exposure, quiet, d);
        ssg_image_destroy(&copy);
    }
    return e;
}

void ssg_cli_show_free(struct ssg_cli_show *s)
{
    for (int i = 0; i < s->count; i++)
        ssg_image_destroy(&s->images[i]);
}
