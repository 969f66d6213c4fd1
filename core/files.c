/* files.c - ssg_make_dirs (ssgraph.h): mkdir -p for output directories; and
 * ssg_write_text_file (parse.h): a text file written whole or not at all. */
#include <errno.h>
#include <stdio.h>
#include <unistd.h>
#include <string.h>
#include <sys/stat.h>

#include "parse.h"

enum { PATH_MAX_LEN = 4096 };

/* mkdir -p: creates every missing directory of `dir`. */
enum ssg_err ssg_make_dirs(const char *dir, struct ssg_diags *diags)
{
    char buf[PATH_MAX_LEN];
    size_t len = strlen(dir);
    if (len >= sizeof buf) {
        ssg_diag_file(diags, SSG_E_IO, dir, "output directory path is too long");
        return SSG_E_IO;
    }
    memcpy(buf, dir, len + 1);
    for (size_t i = 1; i <= len; i++) {
        if (buf[i] != '/' && buf[i] != 0)
            continue;
        char saved = buf[i];
        buf[i] = 0;
        if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
            ssg_diag_file(diags, SSG_E_IO, buf, "cannot create output directory: %s",
                          strerror(errno));
            return SSG_E_IO;
        }
        buf[i] = saved;
    }
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        ssg_diag_file(diags, SSG_E_IO, dir, "output path exists and is not a directory");
        return SSG_E_IO;
    }
    return SSG_OK;
}

enum ssg_err ssg_write_text_file(const char *path, const char *what,
                                 void (*fill)(FILE *f, const void *user), const void *user,
                                 struct ssg_diags *diags)
{
    char tmp[PATH_MAX_LEN + 32];
    snprintf(tmp, sizeof tmp, "%s.tmp-%ld", path, (long)getpid());
    FILE *f = fopen(tmp, "w");
    if (!f) {
        ssg_diag_file(diags, SSG_E_IO, path, "cannot write %s: %s", what, strerror(errno));
        return SSG_E_IO;
    }
    fill(f, user);
    int failed = ferror(f);
    failed |= fclose(f) != 0;
    if (failed || rename(tmp, path) != 0) {
        ssg_diag_file(diags, SSG_E_IO, path, "cannot write %s: %s", what, strerror(errno));
        remove(tmp);
        return SSG_E_IO;
    }
    return SSG_OK;
}
