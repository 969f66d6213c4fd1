/* reference.c - an EXR file as the viewer's reference image (reference.h). */
#define _DEFAULT_SOURCE /* strdup, strncasecmp */
#include "reference.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* What a page names the file by: "file:" and its path as given. */
static const char PREFIX[] = "file:";
enum { PREFIX_LEN = sizeof PREFIX - 1 };

/* EXR files only: the viewer reads what a renderer writes, never any file a path names
   (ssg_image_read would take PNG, HDR, TIFF, ... through OpenImageIO). */
static int is_exr(const char *path)
{
    size_t n = strlen(path);
    return n > 4 && !strncasecmp(path + n - 4, ".exr", 4);
}

/* The checks before the file is opened: an EXR name, a regular file (a FIFO or a device
   would keep the server waiting on another program), of a sane size. */
static enum ssg_err check_path(const char *path, struct ssg_diags *d)
{
    if (!*path || strlen(path) > VIEW_REFERENCE_PATH_MAX)
        return view_fail(d, SSG_E_USAGE, "expected path=FILE.exr (1 to %d bytes)",
                         VIEW_REFERENCE_PATH_MAX);
    if (!is_exr(path))
        return view_fail(d, SSG_E_USAGE, "%s: the reference must be an OpenEXR file (.exr)",
                         path);
    struct stat st;
    if (stat(path, &st))
        return view_fail(d, SSG_E_IO, "%s: %s (a relative path is read from the folder "
                         "`ssgraph view` started in)", path, strerror(errno));
    if (!S_ISREG(st.st_mode))
        return view_fail(d, SSG_E_IO, "%s: not a regular file", path);
    if (st.st_size > (off_t)VIEW_REFERENCE_BYTES_MAX)
        return view_fail(d, SSG_E_SIZE, "%s: %lld bytes, more than the viewer reads (%lld)",
                         path, (long long)st.st_size, (long long)VIEW_REFERENCE_BYTES_MAX);
    return SSG_OK;
}

enum ssg_err view_reference_open(struct view_session *s, const char *path,
                                 struct ssg_diags *d)
{
    enum ssg_err e = check_path(path, d);
    struct ssg_image *img = NULL;
    if (!e)
        e = ssg_image_read(path, NULL, &img, d);
    if (e)
        return e;
    if (img->width != s->width || img->height != s->height) {
        view_fail(d, SSG_E_SIZE, "%s is %dx%d, the graph's frame is %dx%d (start the viewer "
                  "with --size %dx%d to compare with it)", path, img->width, img->height,
                  s->width, s->height, img->width, img->height);
        ssg_image_destroy(&img);
        return SSG_E_SIZE;
    }
    char *port = malloc(PREFIX_LEN + strlen(path) + 1);
    if (!port) {
        ssg_image_destroy(&img);
        return view_fail(d, SSG_E_NOMEM, "out of memory");
    }
    memcpy(port, PREFIX, PREFIX_LEN);
    strcpy(port + PREFIX_LEN, path);
    view_reference_close(s);
    s->ref_file = img;
    s->ref_port = port;
    return SSG_OK;
}

void view_reference_close(struct view_session *s)
{
    ssg_image_destroy(&s->ref_file);
    free(s->ref_port);
    s->ref_port = NULL;
}

int view_reference_image(const struct view_session *s, const char *port,
                         struct ssg_image **out, enum ssg_err *e, struct ssg_diags *d)
{
    if (strncmp(port, PREFIX, PREFIX_LEN))
        return 0;
    *out = NULL;
    if (!s->ref_port || strcmp(port, s->ref_port)) {
        *e = view_fail(d, SSG_E_UNKNOWN_PORT, "%s: no such reference file is open (open it "
                       "with POST /api/reference or --reference)", port + PREFIX_LEN);
        return 1;
    }
    const struct ssg_image *r = s->ref_file;
    *out = ssg_image_create(r->width, r->height, r->channels);
    if (!*out) {
        *e = view_fail(d, SSG_E_NOMEM, "out of memory for %dx%d pixels", r->width, r->height);
        return 1;
    }
    memcpy((*out)->data, r->data,
           (size_t)r->width * (size_t)r->height * (size_t)r->channels * sizeof(float));
    *e = SSG_OK;
    return 1;
}
