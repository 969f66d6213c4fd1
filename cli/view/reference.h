/* reference.h - an EXR file as the viewer's reference (reference.c): POST /api/reference
 * and `ssgraph view --reference FILE` read one, which the page then names "file:PATH" in
 * its port lists beside the graph's ports (as B, or as the metrics' reference). One file
 * at a time: opening another replaces it. Read-only: regular files named *.exr, at the
 * graph's frame size, read through ssg_image_read. Not thread-safe (the session's lock). */
#ifndef SSG_CLI_VIEW_REFERENCE_H
#define SSG_CLI_VIEW_REFERENCE_H

#include "session.h"

enum { VIEW_REFERENCE_PATH_MAX = 1024 };
/* The largest file read: 1 GiB, a 16k x 16k four-channel half-float image. */
#define VIEW_REFERENCE_BYTES_MAX (1ll << 30)

/* Reads path as the session's reference file (replacing the one before); on failure the
 * one before stays and diags say why: SSG_E_USAGE for a name that is not *.exr, SSG_E_IO
 * for a missing or unreadable file or one that is not a regular file, SSG_E_IMAGE for a
 * broken one, SSG_E_SIZE when its size is not the graph's frame size. */
enum ssg_err view_reference_open(struct view_session *s, const char *path,
                                 struct ssg_diags *diags);
void view_reference_close(struct view_session *s);

/* 0 when port does not name a file ("file:..."): the caller looks among the graph's
 * ports. Else 1, with *e the outcome and *out a copy of the file's image the caller
 * destroys (SSG_E_UNKNOWN_PORT when that file is not the one open). */
int view_reference_image(const struct view_session *s, const char *port,
                         struct ssg_image **out, enum ssg_err *e, struct ssg_diags *diags);

#endif
