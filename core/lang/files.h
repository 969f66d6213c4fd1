/* files.h - the rules every file ssgraph reads or writes follows, in one place.
 *
 * Reading: an input must be a regular file (a FIFO would block, /dev/zero never ends, a
 * directory is no image) and no larger than the limit of its kind; the check happens on
 * the open descriptor. Text files and glTF files are read from that descriptor; images
 * are then opened again by name by OpenImageIO, so swapping a file in between is not
 * guarded against there (a race with someone who can write the folder anyway).
 *
 * Writing: an output appears whole or not at all. It is written under a hidden temporary
 * name in its own folder, created with O_EXCL | O_NOFOLLOW (a symbolic link planted there
 * is never followed, a name never shared), flushed and synced with every error checked
 * (a full disk is an error, not a short file), and renamed over the target only then; a
 * rename replaces a link at the target rather than writing through it. Several outputs of
 * one node are all staged before any is renamed. Temporaries are registered: the CLI's
 * signal handler removes them (ssg_tmp_remove_all), and a temporary left by a process that
 * was killed outright (SIGKILL) is removed by the next write into that folder: one whose
 * pid is gone and whose lock (flock, held by its writer until the rename) is free.
 *
 * Thread safety: staging and committing may run on any thread; the registry holds at most
 * SSG_TMP_MAX live temporaries at once (more is an error, not a leak). */
#ifndef SSG_FILES_H
#define SSG_FILES_H

#include <stddef.h>
#include <stdio.h>

#include "ssgraph.h"

/* Largest files read, bytes: each kind is refused past its limit before it is read. */
#define SSG_MAX_TEXT_BYTES (16LL << 20)   /* graph and scene files */
#define SSG_MAX_MODEL_BYTES (1LL << 30)   /* a glTF, .glb or one of its buffers/images */
#define SSG_MAX_IMAGE_BYTES (2LL << 30)   /* an image: EXR, PNG, HDR, ... */

/* Opens path for reading into *fd when it is a regular file of at most max_bytes: SSG_OK
 * (the caller closes *fd), else SSG_E_IO (cannot open, not a regular file) or SSG_E_SIZE
 * (too large) with the reason in why, e.g. "not a regular file (it is a FIFO)". */
enum ssg_err ssg_input_open(const char *path, long long max_bytes, int *fd, char *why,
                            size_t why_len);

/* ssg_input_open and close: SSG_OK, or SSG_E_IO (cannot open, not regular) or SSG_E_SIZE
 * (too large) with the reason in why. */
enum ssg_err ssg_input_check(const char *path, long long max_bytes, char *why,
                             size_t why_len);

/* ssg_input_read: in ssgraph.h (public). */

/* 1 when no process with this pid exists here (kill(pid, 0) fails with ESRCH): whatever it
 * left behind in an output folder (a temporary, a stereo eye's folder) is stale. 0 for
 * this process, a live one, or pid <= 0. */
int ssg_pid_gone(long pid);

/* struct ssg_tmp, ssg_tmp_create, _close, _commit, _discard, _remove_all and
 * _remove_on_signals: in ssgraph.h (public). */

/* ssg_write_text_file: in ssgraph.h (public). */

#endif
