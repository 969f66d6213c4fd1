/* files.c - input checks, staged outputs and their registry (files.h), and ssg_make_dirs
 * (ssgraph.h): mkdir -p for output directories. */
#define _DEFAULT_SOURCE /* DT_* and O_NOFOLLOW/O_CLOEXEC names in glibc's headers */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "lang/files.h"
#include "lang/diag.h"

enum { PATH_MAX_LEN = 4096 };

/* mkdir -p: creates every missing directory of `dir`. */
enum ssg_err ssg_make_dirs(const char *dir, struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_make_dirs", "dir", 1, dir))
        return SSG_E_USAGE;
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

/* ---- inputs ---- */

static const char *file_kind(mode_t mode)
{
    return S_ISDIR(mode) ? "a directory" : S_ISFIFO(mode) ? "a FIFO" : S_ISCHR(mode) ?
           "a character device" : S_ISBLK(mode) ? "a block device" : S_ISSOCK(mode) ?
           "a socket" : "not a plain file";
}

enum ssg_err ssg_input_open(const char *path, long long max_bytes, int *fd, char *why,
                            size_t why_len)
{
    /* O_NONBLOCK: opening a FIFO with no writer must not wait; a regular file ignores it. */
    *fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (*fd < 0) {
        snprintf(why, why_len, "cannot open: %s", strerror(errno));
        return SSG_E_IO;
    }
    struct stat st;
    enum ssg_err e = SSG_E_IO;
    if (fstat(*fd, &st) != 0) {
        snprintf(why, why_len, "cannot read its status: %s", strerror(errno));
    } else if (!S_ISREG(st.st_mode)) {
        snprintf(why, why_len, "not a regular file (it is %s)", file_kind(st.st_mode));
    } else if ((long long)st.st_size > max_bytes) {
        snprintf(why, why_len, "file of %lld bytes is larger than the limit of %lld MiB",
                 (long long)st.st_size, max_bytes >> 20);
        e = SSG_E_SIZE;
    } else {
        fcntl(*fd, F_SETFL, fcntl(*fd, F_GETFL) & ~O_NONBLOCK);
        return SSG_OK;
    }
    close(*fd);
    *fd = -1;
    return e;
}

enum ssg_err ssg_input_check(const char *path, long long max_bytes, char *why,
                             size_t why_len)
{
    int fd;
    enum ssg_err e = ssg_input_open(path, max_bytes, &fd, why, why_len);
    if (!e)
        close(fd);
    return e;
}

enum ssg_err ssg_input_read(const char *path, long long max_bytes, char **data, size_t *len,
                            char *why, size_t why_len)
{
    *data = NULL;
    *len = 0;
    int fd;
    enum ssg_err opened = ssg_input_open(path, max_bytes, &fd, why, why_len);
    if (opened)
        return opened;
    struct stat st;
    fstat(fd, &st);
    /* Read at most the size fstat gave plus one byte: a file that grows while it is read
       is cut there, never read without end. */
    size_t cap = (size_t)st.st_size + 1, got = 0;
    char *buf = malloc(cap + 1);
    enum ssg_err e = buf ? SSG_OK : SSG_E_NOMEM;
    while (!e && got < cap) {
        ssize_t n = read(fd, buf + got, cap - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            snprintf(why, why_len, "cannot read: %s", strerror(errno));
            e = SSG_E_IO;
        }
        if (n <= 0)
            break;
        got += (size_t)n;
    }
    close(fd);
    if (e == SSG_E_NOMEM)
        snprintf(why, why_len, "out of memory for %lld bytes", (long long)st.st_size);
    if (!e && got > (size_t)max_bytes) {
        snprintf(why, why_len, "file grew past the limit of %lld MiB while read",
                 max_bytes >> 20);
        e = SSG_E_SIZE;
    }
    if (e) {
        free(buf);
        return e;
    }
    buf[got] = 0;
    *data = buf;
    *len = got;
    return SSG_OK;
}

/* ---- the registry of live temporaries ---- */

static char tmp_paths[SSG_TMP_MAX][4352];
static volatile sig_atomic_t tmp_live[SSG_TMP_MAX];
static atomic_flag tmp_lock = ATOMIC_FLAG_INIT;

static int registry_add(const char *path)
{
    while (atomic_flag_test_and_set(&tmp_lock))
        ;
    int slot = -1;
    for (int i = 0; i < SSG_TMP_MAX && slot < 0; i++) {
        if (!tmp_live[i]) {
            snprintf(tmp_paths[i], sizeof tmp_paths[i], "%s", path);
            tmp_live[i] = 1; /* after the path: a handler sees a whole one */
            slot = i;
        }
    }
    atomic_flag_clear(&tmp_lock);
    return slot;
}

static void registry_remove(int slot)
{
    if (slot >= 0)
        tmp_live[slot] = 0;
}

void ssg_tmp_remove_all(void)
{
    for (int i = 0; i < SSG_TMP_MAX; i++)
        if (tmp_live[i])
            unlink(tmp_paths[i]);
}

static void on_signal(int sig)
{
    ssg_tmp_remove_all();
    signal(sig, SIG_DFL);
    raise(sig);
}

void ssg_tmp_remove_on_signals(void)
{
    const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
    for (size_t i = 0; i < sizeof sigs / sizeof sigs[0]; i++) {
        struct sigaction sa, old;
        /* A signal the parent ignores stays ignored (nohup, background jobs, SIGPIPE for
           EPIPE): handling it would turn it into a death. */
        if (sigaction(sigs[i], NULL, &old) == 0 && old.sa_handler == SIG_IGN)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sigaction(sigs[i], &sa, NULL);
    }
}

/* ---- staged outputs ---- */

/* "<dir>/" of path ("" for a bare name) and its file name. */
static void split_path(const char *path, char *dir, size_t dir_len, const char **base)
{
    const char *slash = strrchr(path, '/');
    *base = slash ? slash + 1 : path;
    snprintf(dir, dir_len, "%.*s", slash ? (int)(slash - path + 1) : 0, path);
}

/* A temporary of ours is exactly ".<base>.tmp-<pid>-<n>[.exr|.png]": its pid, or 0 for any
   other name (a user's ".notes.tmp-42-draft.txt" is not ours). */
static long tmp_owner(const char *name)
{
    const char *tag = name[0] == '.' ? strstr(name, ".tmp-") : NULL;
    if (!tag || tag == name)
        return 0;
    const char *p = tag + 5;
    long pid = 0;
    for (; *p >= '0' && *p <= '9' && pid < 100000000; p++)
        pid = 10 * pid + (*p - '0');
    if (*p++ != '-' || *p < '0' || *p > '9')
        return 0;
    while (*p >= '0' && *p <= '9')
        p++;
    return *p == 0 || !strcmp(p, ".exr") || !strcmp(p, ".png") ? pid : 0;
}

int ssg_pid_gone(long pid)
{
    return pid > 0 && pid != (long)getpid() && kill((pid_t)pid, 0) != 0 && errno == ESRCH;
}

/* Removes temporaries in dir left by processes that were killed outright (their handler
   never ran). Stale means both: its pid is not a live process here, and nobody holds the
   lock its writer takes for as long as it lives (ssg_tmp_create), which also protects a
   live writer in another PID namespace (a container sharing the folder). */
static void remove_stale(const char *dir)
{
    DIR *d = opendir(dir[0] ? dir : ".");
    if (!d)
        return;
    for (struct dirent *e; (e = readdir(d));) {
        long pid = tmp_owner(e->d_name);
        if (!ssg_pid_gone(pid))
            continue;
        char path[PATH_MAX_LEN + 256];
        snprintf(path, sizeof path, "%s%s", dir, e->d_name);
        int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        struct stat st;
        if (fd < 0)
            continue;
        if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && flock(fd, LOCK_EX | LOCK_NB) == 0)
            unlink(path);
        close(fd);
    }
    closedir(d);
}

/* Why target cannot be replaced by an output, checked without opening it (stat never
   blocks; open on a FIFO waits for a reader): "" when it can. A rename would replace a
   device, a FIFO or a socket at the target with a regular file (`--profile-json
   /dev/null` used to turn /dev/null into a file), and cannot replace a directory; with
   `streams`, a character device or FIFO is taken (ssg_write_text_stream writes into it). */
static void kind_refusal(const char *target, int streams, char *why, size_t len)
{
    struct stat st;
    why[0] = '\0';
    if (stat(target, &st) != 0 || S_ISREG(st.st_mode) ||
        (streams && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))))
        return;
    snprintf(why, len, "cannot write an output here: it is %s, not a regular file (outputs "
             "are written to a temporary and renamed into place, which would replace it); "
             "expected a regular file or a new name", file_kind(st.st_mode));
}

/* Why no temporary can be made beside target: its folder is missing, not a folder, or
   not one this process may create files in; "" when it can. `what` names the content. */
static void folder_refusal(const char *target, const char *what, char *why, size_t len)
{
    struct stat st;
    char dir[PATH_MAX_LEN];
    const char *base;
    split_path(target, dir, sizeof dir, &base);
    const char *folder = dir[0] ? dir : ".";
    why[0] = '\0';
    if (!base[0])
        snprintf(why, len, "cannot write %s: the path names a folder", what);
    else if (stat(folder, &st) != 0)
        snprintf(why, len, "cannot write %s: its folder '%s': %s", what, folder,
                 strerror(errno));
    else if (!S_ISDIR(st.st_mode))
        snprintf(why, len, "cannot write %s: '%s' is not a folder", what, folder);
    else if (access(folder, W_OK | X_OK) != 0)
        snprintf(why, len, "cannot write %s: cannot create a file in '%s': %s", what, folder,
                 strerror(errno));
}

enum ssg_err ssg_output_check(const char *path, const char *what, int streams,
                              struct ssg_diags *diags)
{
    if (ssg_api_null(diags, "ssg_output_check", "path, what", 2, path, what))
        return SSG_E_USAGE;
    char why[PATH_MAX_LEN + 200];
    struct stat st;
    kind_refusal(path, streams, why, sizeof why);
    if (!why[0] && (stat(path, &st) != 0 || S_ISREG(st.st_mode)))
        folder_refusal(path, what, why, sizeof why); /* a stream needs no temporary */
    if (!why[0])
        return SSG_OK;
    ssg_diag_file(diags, SSG_E_IO, path, "%s", why);
    return SSG_E_IO;
}

enum ssg_err ssg_tmp_create(const char *target, const char *ext, const char *what,
                            struct ssg_tmp *t, struct ssg_diags *diags)
{
    static atomic_uint counter;
    char dir[PATH_MAX_LEN];
    const char *base;
    t->fd = t->lock_fd = -1;
    t->slot = -1;
    if (strlen(target) >= sizeof t->target) {
        ssg_diag_file(diags, SSG_E_IO, target, "output path is too long");
        return SSG_E_IO;
    }
    snprintf(t->target, sizeof t->target, "%s", target);
    char why[300];
    kind_refusal(target, 0, why, sizeof why);
    if (why[0]) {
        ssg_diag_file(diags, SSG_E_IO, target, "%s", why);
        return SSG_E_IO;
    }
    split_path(target, dir, sizeof dir, &base);
    remove_stale(dir);
    /* A name that exists already (planted, or left by a process with a reused pid) is
       skipped, never opened: O_EXCL | O_NOFOLLOW. */
    for (int tries = 0; tries < 100 && t->fd < 0; tries++) {
        /* at most 100 bytes of the target's name: the temporary's stays under NAME_MAX */
        snprintf(t->path, sizeof t->path, "%s.%.100s.tmp-%ld-%u%s", dir, base,
                 (long)getpid(), atomic_fetch_add(&counter, 1u), ext);
        t->fd = open(t->path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (t->fd < 0 && errno != EEXIST)
            break;
    }
    /* Locked while this process lives (the lock belongs to the open file, kept open by
       lock_fd until commit or discard), and registered for the signal handler. */
    t->lock_fd = t->fd >= 0 ? dup(t->fd) : -1;
    if (t->lock_fd >= 0)
        flock(t->lock_fd, LOCK_EX | LOCK_NB);
    if (t->fd >= 0 && (t->lock_fd < 0 || (t->slot = registry_add(t->path)) < 0)) {
        unlink(t->path);
        close(t->fd);
        if (t->lock_fd >= 0)
            close(t->lock_fd);
        t->fd = t->lock_fd = -1;
        ssg_diag_file(diags, SSG_E_IO, target, "more than %d outputs written at once",
                      SSG_TMP_MAX);
        return SSG_E_IO;
    }
    if (t->fd < 0) {
        ssg_diag_file(diags, SSG_E_IO, target, "cannot write %s: cannot create a file in "
                      "'%s': %s", what, dir[0] ? dir : ".", strerror(errno));
        return SSG_E_IO;
    }
    return SSG_OK;
}

enum ssg_err ssg_tmp_close(struct ssg_tmp *t, struct ssg_diags *diags)
{
    if (t->fd < 0)
        return SSG_OK;
    int failed = fsync(t->fd) != 0;
    int saved = errno;
    failed |= close(t->fd) != 0;
    if (!failed)
        saved = 0;
    else if (!saved)
        saved = errno;
    t->fd = -1;
    if (failed) {
        ssg_diag_file(diags, SSG_E_IO, t->target, "cannot write: %s", strerror(saved));
        return SSG_E_IO;
    }
    return SSG_OK;
}

static void release_lock(struct ssg_tmp *t)
{
    if (t->lock_fd >= 0)
        close(t->lock_fd);
    t->lock_fd = -1;
}

void ssg_tmp_discard(struct ssg_tmp *t, int count)
{
    for (int i = 0; i < count; i++) {
        if (t[i].fd >= 0)
            close(t[i].fd);
        t[i].fd = -1;
        if (t[i].slot >= 0) {
            unlink(t[i].path);
            registry_remove(t[i].slot);
            t[i].slot = -1;
        }
        release_lock(&t[i]);
    }
}

enum ssg_err ssg_tmp_commit(struct ssg_tmp *t, int count, struct ssg_diags *diags)
{
    /* Every file complete on disk before the first rename, so a failure or a kill leaves
       as few mixed outputs as it can. */
    for (int i = 0; i < count; i++) {
        if (ssg_tmp_close(&t[i], diags) != SSG_OK) {
            ssg_tmp_discard(t, count);
            return SSG_E_IO;
        }
    }
    for (int i = 0; i < count; i++) {
        if (rename(t[i].path, t[i].target) != 0) {
            ssg_diag_file(diags, SSG_E_IO, t[i].target, "cannot rename the finished file "
                          "into place: %s", strerror(errno));
            ssg_tmp_discard(t + i, count - i);
            return SSG_E_IO;
        }
        registry_remove(t[i].slot);
        t[i].slot = -1;
        release_lock(&t[i]);
    }
    return SSG_OK;
}

/* 1 when path names an existing character device or FIFO (/dev/stdout, a pipe made by
   mkfifo): a stream to write into, never to replace. */
static int is_stream(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode));
}

/* Writes a text output straight into a stream (no temporary: a stream cannot be renamed
   over, and a reader sees it as it comes). Opening a FIFO waits for its reader: only for
   a file the user named, who then reads it. */
static enum ssg_err write_text_stream(const char *path, const char *what,
                                      void (*fill)(FILE *f, const void *user),
                                      const void *user, struct ssg_diags *diags)
{
    int fd = open(path, O_WRONLY | O_NOCTTY | O_CLOEXEC);
    FILE *f = fd >= 0 ? fdopen(fd, "w") : NULL;
    if (!f) {
        ssg_diag_file(diags, SSG_E_IO, path, "cannot write %s: %s", what, strerror(errno));
        if (fd >= 0)
            close(fd);
        return SSG_E_IO;
    }
    fill(f, user);
    int failed = fflush(f) != 0 || ferror(f);
    int saved = errno;
    failed |= fclose(f) != 0;
    if (failed) {
        ssg_diag_file(diags, SSG_E_IO, path, "cannot write %s: %s", what,
                      strerror(saved ? saved : errno));
        return SSG_E_IO;
    }
    return SSG_OK;
}

enum ssg_err ssg_write_text_file(const char *path, const char *what,
                                 void (*fill)(FILE *f, const void *user), const void *user,
                                 struct ssg_diags *diags)
{
    struct ssg_tmp t;
    if (ssg_tmp_create(path, "", what, &t, diags))
        return SSG_E_IO;
    FILE *f = fdopen(t.fd, "w");
    if (!f) {
        ssg_diag_file(diags, SSG_E_IO, path, "cannot write %s: %s", what, strerror(errno));
        ssg_tmp_discard(&t, 1);
        return SSG_E_IO;
    }
    fill(f, user);
    int failed = fflush(f) != 0 || ferror(f) || fsync(t.fd) != 0;
    int saved = errno;
    failed |= fclose(f) != 0; /* closes t.fd too */
    t.fd = -1;
    if (failed) {
        ssg_diag_file(diags, SSG_E_IO, path, "cannot write %s: %s", what,
                      strerror(saved ? saved : errno));
        ssg_tmp_discard(&t, 1);
        return SSG_E_IO;
    }
    return ssg_tmp_commit(&t, 1, diags);
}

enum ssg_err ssg_write_text_stream(const char *path, const char *what,
                                   void (*fill)(FILE *f, const void *user), const void *user,
                                   struct ssg_diags *diags)
{
    if (is_stream(path))
        return write_text_stream(path, what, fill, user, diags);
    return ssg_write_text_file(path, what, fill, user, diags);
}
