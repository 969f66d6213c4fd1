/* scratch.h - where a test writes its files: $SSG_TMP (ctest gives each test a folder of
 * its own), else CHECK_TMP_ROOT/ssg_TEST_PID. For the tests that write images. */
#ifndef SSG_TEST_SCRATCH_H
#define SSG_TEST_SCRATCH_H

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "check.h"

static char tmpdir[512];

/* Chooses and creates the folder; call first in main. */
static void setup_tmp(const char *test)
{
    const char *env = getenv("SSG_TMP");
    if (env && env[0])
        snprintf(tmpdir, sizeof tmpdir, "%s", env);
    else
        snprintf(tmpdir, sizeof tmpdir, CHECK_TMP_ROOT "/ssg_%s_%ld", test, (long)getpid());
    mkdir(tmpdir, 0777);
}

/* tmpdir/name, in one of 8 buffers used in turn (valid for the next 7 calls). */
static const char *tmp_path(const char *name)
{
    static char buf[8][1024];
    static int next;
    char *p = buf[next++ % 8];
    snprintf(p, 1024, "%s/%s", tmpdir, name);
    return p;
}

/* Writes text to tmpdir/name and returns its path (tmp_path's buffer); exits on failure.
   Inline: not every test that includes this writes text files. */
static inline const char *write_file(const char *name, const char *text)
{
    const char *path = tmp_path(name);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "cannot write %s: %s\n", path, strerror(errno));
        exit(1);
    }
    fputs(text, f);
    fclose(f);
    return path;
}

#endif
