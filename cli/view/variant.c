/* variant.c - "save as variant" of `ssgraph view` (session.h: view_session_save): the
 * session as a graph file beside the graph, which `ssgraph run` then runs to the same
 * pixels without the server's command line: the graph included, the --scene, --lights,
 * --size, --guard and --seed the server was started with as the graph statements that say
 * the same, then the command line's and the page's parameter changes.
 *
 * What is written is text the graph lexer reads back as written: a file name is quoted
 * with the escapes it knows (core/lang/parse.c: \" \\ \n \t), and a name or a value that a
 * graph file cannot hold on its line (another control character) refuses the save, so no
 * line of the variant comes from a name or a value.
 *
 * The server calls this under the session's lock, so nothing here may wait on another
 * program: the name is looked at with lstat (a FIFO, a dangling link, a file nobody may
 * read all exist, and are refused, never replaced or opened), the text goes into a new
 * temporary file beside it (O_CREAT | O_EXCL: a regular file of our own), which is then
 * linked to the name (link(2) never replaces: whatever appeared there meanwhile wins, and
 * the save is refused). */
#define _GNU_SOURCE /* renameat2, RENAME_NOREPLACE */
#include "session.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

enum { NAME_MAX_CHARS = 64, TMP_TRIES = 100 };

/* 1 when name is 1 to 64 of [A-Za-z0-9_-], every character looked at. */
int view_valid_name(const char *name)
{
    size_t len = strlen(name);
    if (len == 0 || len > NAME_MAX_CHARS)
        return 0;
    return strspn(name, "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") ==
           len;
}

static int control(char c)
{
    return (unsigned char)c < 0x20 || c == 0x7f;
}

/* The first control character of s, or NULL. */
static const char *first_control(const char *s)
{
    for (; *s; s++)
        if (control(*s))
            return s;
    return NULL;
}

/* 1 when quote() can write s: its only control characters are a newline and a tab. */
int view_quotable(const char *s)
{
    for (; *s; s++)
        if (control(*s) && *s != '\n' && *s != '\t')
            return 0;
    return 1;
}

/* s as a graph string literal, with the lexer's escapes. */
void view_quote(FILE *f, const char *s)
{
    fputc('"', f);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            fprintf(f, "\\%c", *s);
        else if (*s == '\n')
            fputs("\\n", f);
        else if (*s == '\t')
            fputs("\\t", f);
        else
            fputc(*s, f);
    }
    fputc('"', f);
}

/* A file the server was given (relative to its working folder) as a path the variant can
 * name wherever it lies: absolute. NULL when the working folder cannot be read. */
char *view_absolute(const char *path)
{
    if (path[0] == '/')
        return strdup(path);
    char *cwd = getcwd(NULL, 0), *out = NULL;
    if (cwd && asprintf(&out, "%s/%s", cwd, path) < 0)
        out = NULL;
    free(cwd);
    return out;
}

/* A statement `word "path"` for a file given on the command line. */
static enum ssg_err path_line(FILE *f, const char *word, const char *path, struct ssg_diags *d)
{
    char *abs = view_absolute(path);
    if (!abs)
        return view_fail(d, SSG_E_IO, "cannot read the working folder to name %s", path);
    enum ssg_err e = SSG_OK;
    if (view_quotable(abs)) {
        fprintf(f, "%s ", word);
        view_quote(f, abs);
        fputc('\n', f);
    } else {
        e = view_fail(d, SSG_E_USAGE, "the %s file's name holds a control character a graph "
                      "file cannot quote: no variant can name it", word);
    }
    free(abs);
    return e;
}

/* The statements that stand for the server's --scene, --lights, --size, --guard, --seed. */
enum ssg_err view_command_line(FILE *f, const struct ssg_overrides *ov, struct ssg_diags *d)
{
    enum ssg_err e = SSG_OK;
    if (ov->scene)
        e = path_line(f, "scene", ov->scene, d);
    if (!e && ov->lights)
        e = path_line(f, "lights", ov->lights, d);
    if (ov->width)
        fprintf(f, "size %d %d\n", ov->width, ov->height);
    if (ov->guard_given)
        fprintf(f, "guard %d\n", ov->guard);
    if (ov->seed >= 0)
        fprintf(f, "seed %lld\n", (long long)ov->seed);
    if (ov->backend)
        fprintf(f, "# The server ran every node on %s (--backend %s): give it again.\n",
                ov->backend, ov->backend);
    return e;
}

/* `set key = value`; refused when either holds a control character (the core refuses
   such values; this keeps any that got by from becoming a line of its own). */
static enum ssg_err set_line(FILE *f, const char *key, int key_len, const char *value,
                             struct ssg_diags *d)
{
    const char *bad = first_control(value);
    for (int i = 0; i < key_len && !bad; i++)
        if (control(key[i]))
            bad = key + i;
    if (bad)
        return view_fail(d, SSG_E_USAGE, "the change of %.*s holds a control character "
                         "(0x%02x): it cannot be saved", key_len > 80 ? 80 : key_len, key,
                         (unsigned char)*bad);
    fprintf(f, "set %.*s = %s\n", key_len, key, value);
    return SSG_OK;
}

enum ssg_err view_set_lines(FILE *f, const struct view_session *s, struct ssg_diags *d)
{
    enum ssg_err e = SSG_OK;
    for (int i = 0; !e && i < s->args->ov.set_count; i++) {
        const char *a = s->args->ov.sets[i], *eq = strchr(a, '=');
        if (eq)
            e = set_line(f, a, (int)(eq - a), eq + 1, d);
    }
    for (int i = 0; !e && i < s->set_count; i++)
        e = set_line(f, s->sets[i].key, (int)strlen(s->sets[i].key), s->sets[i].value, d);
    return e;
}

enum ssg_err view_text_close(FILE *f, char **text, enum ssg_err e, const char *what,
                             struct ssg_diags *d)
{
    if (fclose(f) && !e)
        e = view_fail(d, SSG_E_NOMEM, "out of memory for %s", what);
    if (e) {
        free(*text);
        *text = NULL;
    }
    return e;
}

void view_camera_comment(FILE *f, const struct view_session *s)
{
    if (!s->camera_changed)
        return;
    const struct ssg_view *c = &s->camera;
    fprintf(f, "# The page's camera (a scene file's camera line takes it):\n"
               "# camera(position=[%g, %g, %g], target=[%g, %g, %g], up=[%g, %g, %g], "
               "fov=%g)\n", c->position[0], c->position[1], c->position[2],
            c->target[0], c->target[1], c->target[2], c->up[0], c->up[1], c->up[2],
            c->fov_y);
}

/* The variant's text (malloc'd) into *text; include is the graph's file name. */
static enum ssg_err compose(const struct view_session *s, const char *include, char **text,
                            size_t *len, struct ssg_diags *d)
{
    if (!view_quotable(include))
        return view_fail(d, SSG_E_USAGE, "the graph's file name holds a control character a "
                         "graph file cannot quote: no variant can include it");
    FILE *f = open_memstream(text, len);
    if (!f)
        return view_fail(d, SSG_E_NOMEM, "out of memory for the variant");
    fputs("# A variant saved by `ssgraph view`: the graph, the server's --scene, --size and\n"
          "# --seed, then the parameters changed on the command line and in the page.\n"
          "include ", f);
    view_quote(f, include);
    fputc('\n', f);
    enum ssg_err e = view_command_line(f, &s->args->ov, d);
    if (!e)
        e = view_set_lines(f, s, d);
    view_camera_comment(f, s);
    return view_text_close(f, text, e, "the variant", d);
}

/* A new regular file beside path, named path.tmp-PID-N, opened for writing; -1 with errno. */
static int create_temporary(const char *path, char *tmp, size_t len)
{
    for (int n = 0; n < TMP_TRIES; n++) {
        if ((size_t)snprintf(tmp, len, "%s.tmp-%ld-%d", path, (long)getpid(), n) >= len) {
            errno = ENAMETOOLONG;
            return -1;
        }
        int fd = open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC,
                      0666);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    return -1;
}

static int write_all(int fd, const char *text, size_t len)
{
    while (len) {
        ssize_t n = write(fd, text, len);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return -1;
        text += n;
        len -= (size_t)n;
    }
    return 0;
}

/* Gives tmp the name path unless something has it: link(2), or on a file system without
 * hard links renameat2(RENAME_NOREPLACE); neither replaces. 0, or -1 with errno. */
static int name_new(const char *tmp, const char *path)
{
    if (!link(tmp, path))
        return unlink(tmp), 0;
    if (errno != EPERM && errno != EOPNOTSUPP && errno != ENOSYS)
        return -1;
    return renameat2(AT_FDCWD, tmp, AT_FDCWD, path, RENAME_NOREPLACE);
}

/* Writes text as a new file path, never replacing nor opening what is there. */
enum ssg_err view_write_new(const char *path, const char *text, size_t len,
                            struct ssg_diags *d)
{
    char tmp[1100];
    int fd = create_temporary(path, tmp, sizeof tmp);
    if (fd < 0)
        return view_fail(d, SSG_E_IO, "cannot create a file beside %s: %s", path,
                         strerror(errno));
    int failed = write_all(fd, text, len);
    int err = errno;
    if (close(fd) && !failed)
        failed = -1, err = errno;
    if (!failed && name_new(tmp, path))
        failed = -1, err = errno;
    if (!failed)
        return SSG_OK;
    unlink(tmp);
    if (err == EEXIST)
        return view_fail(d, SSG_E_IO, "%s exists already: choose another name", path);
    return view_fail(d, SSG_E_IO, "cannot write %s: %s", path, strerror(err));
}

enum ssg_err view_new_path(const struct view_session *s, const char *name, const char *ext,
                          char *path, size_t len, struct ssg_diags *d)
{
    if (!view_valid_name(name))
        return view_fail(d, SSG_E_USAGE, "a name to save as is 1 to 64 letters, digits, '_' "
                         "or '-', got '%.80s'", name);
    const char *graph = s->args->files[0], *slash = strrchr(graph, '/');
    int dir = slash ? (int)(slash - graph + 1) : 0;
    if ((size_t)snprintf(path, len, "%.*s%s%s", dir, graph, name, ext) >= len)
        return view_fail(d, SSG_E_USAGE, "the path to save as is too long");
    struct stat st;
    if (!lstat(path, &st)) /* a FIFO, a link, a directory, an unreadable file: all exist */
        return view_fail(d, SSG_E_IO, "%s exists already: choose another name", path);
    if (errno != ENOENT)
        return view_fail(d, SSG_E_IO, "cannot save as %s: %s", path, strerror(errno));
    return SSG_OK;
}

enum ssg_err view_session_save(struct view_session *s, const char *name, char *path,
                               size_t len, struct ssg_diags *d)
{
    enum ssg_err e = view_new_path(s, name, ".graph", path, len, d);
    if (e)
        return e;
    const char *graph = s->args->files[0], *slash = strrchr(graph, '/');
    char *text = NULL;
    size_t text_len = 0;
    e = compose(s, slash ? slash + 1 : graph, &text, &text_len, d);
    if (!e)
        e = view_write_new(path, text, text_len, d);
    free(text);
    return e;
}
