/* stereo.c - a stereo run's eye folders into multi-view EXRs and per-eye previews
 * (ssgraph.h, the stereo section). */
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io/imageio.h"
#include "ssgraph.h" /* ssg_stereo_join, _discard, _sweep */
#include "lang/diag.h"
#include "lang/files.h"

enum { PATH_LEN = 4096, MAX_FILES = 256, MAX_VIEWS = 8 };

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The visible entries of dir, sorted (the order files are joined in never depends on the
   file system's); the caller frees names[0..*count-1]. */
static enum ssg_err list_dir(const char *dir, char **names, int *count,
                             struct ssg_diags *diags)
{
    DIR *d = opendir(dir);
    *count = 0;
    if (!d) {
        ssg_diag_file(diags, SSG_E_IO, dir, "cannot list a stereo eye's files: %s",
                      strerror(errno));
        return SSG_E_IO;
    }
    struct dirent *e;
    while ((e = readdir(d)) && *count < MAX_FILES)
        if (e->d_name[0] != '.' && (names[*count] = strdup(e->d_name)))
            (*count)++;
    closedir(d);
    qsort(names, (size_t)*count, sizeof *names, by_name);
    return SSG_OK;
}

static int ends_with(const char *s, const char *tail)
{
    size_t n = strlen(s), t = strlen(tail);
    return n >= t && strcmp(s + n - t, tail) == 0;
}

/* Where the results are announced (ssg_stereo_join's log). */
struct announce {
    ssg_log_fn log;
    void *user;
};

static void wrote(const struct announce *a, const char *path)
{
    char line[PATH_LEN + 8];
    snprintf(line, sizeof line, "wrote %s", path);
    if (a->log)
        a->log(a->user, line);
}

/* "ssao.png" of view "left" -> out/ssao_left.png (a name without a dot: out/NAME_left). */
static enum ssg_err move_view_file(const char *out_dir, const char *dir, const char *name,
                                   const char *view, const struct announce *a,
                                   struct ssg_diags *diags)
{
    char from[PATH_LEN], to[PATH_LEN];
    const char *dot = strrchr(name, '.');
    int stem = dot ? (int)(dot - name) : (int)strlen(name);
    snprintf(from, sizeof from, "%s/%s", dir, name);
    int n = snprintf(to, sizeof to, "%s/%.*s_%s%s", out_dir, stem, name, view, dot ? dot : "");
    if (n < 0 || (size_t)n >= sizeof to || rename(from, to) != 0) {
        ssg_diag_file(diags, SSG_E_IO, to, "cannot move %s into place: %s", from,
                      n < 0 || (size_t)n >= sizeof to ? "path too long" : strerror(errno));
        return SSG_E_IO;
    }
    wrote(a, to);
    return SSG_OK;
}

/* One file the eyes share: an EXR joined into out/NAME, anything else moved per view. */
static enum ssg_err join_one(const char *out_dir, const char *const *dirs,
                             const char *const *views, int count, const char *name,
                             const struct announce *a, struct ssg_diags *diags)
{
    if (!ends_with(name, ".exr")) {
        enum ssg_err e = SSG_OK;
        for (int k = 0; k < count && !e; k++)
            e = move_view_file(out_dir, dirs[k], name, views[k], a, diags);
        return e;
    }
    char files[MAX_VIEWS][PATH_LEN], target[PATH_LEN];
    const char *file_ptrs[MAX_VIEWS];
    for (int k = 0; k < count; k++) {
        snprintf(files[k], sizeof files[k], "%s/%s", dirs[k], name);
        file_ptrs[k] = files[k];
    }
    snprintf(target, sizeof target, "%s/%s", out_dir, name);
    enum ssg_err e = ssg_exr_views_join(target, views, file_ptrs, count, diags);
    if (!e)
        wrote(a, target);
    return e;
}

enum ssg_err ssg_stereo_join(const char *out_dir, const char *const *dirs,
                             const char *const *views, int count, ssg_log_fn log,
                             void *user, struct ssg_diags *diags)
{
    const struct announce a = {log, user};
    char *names[MAX_FILES];
    int n = 0;
    if (count < 2 || count > MAX_VIEWS) {
        ssg_diag_file(diags, SSG_E_VALUE, out_dir, "%d views, expected 2 to %d", count,
                      MAX_VIEWS);
        return SSG_E_VALUE;
    }
    enum ssg_err e = ssg_make_dirs(out_dir, diags);
    if (!e)
        e = list_dir(dirs[0], names, &n, diags);
    for (int i = 0; i < n; i++) {
        if (!e)
            e = join_one(out_dir, dirs, views, count, names[i], &a, diags);
        free(names[i]);
    }
    ssg_stereo_discard(dirs, count);
    return e;
}

void ssg_stereo_discard(const char *const *dirs, int count)
{
    for (int k = 0; k < count; k++) {
        DIR *d = opendir(dirs[k]);
        struct dirent *e;
        char path[PATH_LEN];
        while (d && (e = readdir(d)))
            if (strcmp(e->d_name, ".") && strcmp(e->d_name, "..") &&
                snprintf(path, sizeof path, "%s/%s", dirs[k], e->d_name) < (int)sizeof path)
                unlink(path);
        if (d)
            closedir(d);
        rmdir(dirs[k]);
    }
}

/* The pid of an eye folder's name ".stereo-VIEW-PID", or 0 when the name is not one. */
static long eye_folder_owner(const char *name)
{
    if (strncmp(name, ".stereo-", 8) != 0)
        return 0;
    const char *dash = strrchr(name + 8, '-');
    if (!dash || dash == name + 8 || !dash[1])
        return 0;
    long pid = 0;
    for (const char *p = dash + 1; *p; p++) {
        if (*p < '0' || *p > '9' || pid > 100000000)
            return 0;
        pid = 10 * pid + (*p - '0');
    }
    return pid;
}

void ssg_stereo_sweep(const char *out_dir)
{
    DIR *d = opendir(out_dir);
    if (!d)
        return;
    for (struct dirent *e; (e = readdir(d));) {
        long pid = eye_folder_owner(e->d_name);
        /* a live process's folder (its run still going) is left alone */
        if (!ssg_pid_gone(pid))
            continue;
        char path[PATH_LEN];
        if (snprintf(path, sizeof path, "%s/%s", out_dir, e->d_name) < (int)sizeof path) {
            const char *one = path;
            ssg_stereo_discard(&one, 1);
        }
    }
    closedir(d);
}
