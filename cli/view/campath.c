/* campath.c - "save path" of `ssgraph view` (session.h: view_session_save_path): the camera
 * keys the page recorded, as a scene file beside the graph that includes the graph's scene
 * (core/scene/scene_include.c) and adds one camera_key line per key, so that
 * `ssgraph run GRAPH --scene NAME.scene --frames N` flies the path. The included scene's own
 * camera_key lines or orbit give way to these (a file's camera path replaces its
 * includes'); its camera line stays (near and far planes). The file is written as a
 * variant is (variant.c: name check, lstat, a temporary file of our own, link). */
#define _GNU_SOURCE /* open_memstream */
#include "session.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

enum { KEY_NUMBERS = 11 }; /* time, position, target, up, fov */

/* One key's 11 numbers from *p (advanced past them); 0 with the reason when they are not
   11 finite numbers apart by ',' and ended by ';' or the text's end. */
static int read_key(const char **p, double v[KEY_NUMBERS], const char **why)
{
    for (int i = 0; i < KEY_NUMBERS; i++) {
        char *end;
        v[i] = strtod(*p, &end);
        if (end == *p || !isfinite(v[i])) {
            *why = "expected 11 finite numbers a key (time, position, target, up, fov)";
            return 0;
        }
        *p = end;
        char sep = i + 1 < KEY_NUMBERS ? ',' : ';';
        if (**p == sep)
            (*p)++;
        else if (!(i + 1 == KEY_NUMBERS && **p == '\0')) {
            *why = "expected 11 numbers apart by ',' and keys apart by ';'";
            return 0;
        }
    }
    return 1;
}

/* What a camera_key line accepts (docs/scenes.md), so that the file written loads. */
static const char *key_fault(const double v[KEY_NUMBERS], double last_time)
{
    if (v[0] < 0 || v[0] > 1e9)
        return "a time is in [0, 1e9] seconds";
    if (v[0] <= last_time)
        return "the times must rise from key to key";
    for (int i = 1; i < 10; i++)
        if (fabs(v[i]) > 1e9)
            return "a coordinate is in [-1e9, 1e9]";
    if (!(v[10] >= 1 && v[10] <= 179))
        return "a fov is in [1, 179] degrees";
    return NULL;
}

/* The keys as camera_key lines to f; the number of keys, or 0 with the fault in diags. */
static int key_lines(FILE *f, const char *keys, struct ssg_diags *d)
{
    const char *p = keys, *why = NULL;
    double v[KEY_NUMBERS], last = -1;
    int n = 0;
    while (*p && n < VIEW_MAX_KEYS + 1) {
        if (!read_key(&p, v, &why) || (why = key_fault(v, last)))
            break;
        last = v[0];
        fprintf(f, "camera_key(time=%.9g, position=[%.9g, %.9g, %.9g], target=[%.9g, %.9g, "
                "%.9g], up=[%.9g, %.9g, %.9g], fov=%.9g)\n", v[0], v[1], v[2], v[3], v[4],
                v[5], v[6], v[7], v[8], v[9], v[10]);
        n++;
    }
    if (why)
        view_fail(d, SSG_E_USAGE, "key %d of the camera path: %s", n + 1, why);
    else if (n < 2 || n > VIEW_MAX_KEYS)
        view_fail(d, SSG_E_USAGE, "a camera path has 2 to %d keys, got %s%d", VIEW_MAX_KEYS,
                  n > VIEW_MAX_KEYS ? "more than " : "", n > VIEW_MAX_KEYS ? VIEW_MAX_KEYS : n);
    return why || n < 2 || n > VIEW_MAX_KEYS ? 0 : n;
}

/* The scene file's text (malloc'd) into *text. */
static enum ssg_err compose(const char *scene, const char *keys, char **text, size_t *len,
                            struct ssg_diags *d)
{
    char *abs = view_absolute(scene);
    if (!abs)
        return view_fail(d, SSG_E_IO, "cannot read the working folder to name %s", scene);
    int quotable = view_quotable(abs);
    FILE *f = quotable ? open_memstream(text, len) : NULL;
    if (!f) {
        free(abs);
        return quotable ? view_fail(d, SSG_E_NOMEM, "out of memory for the path")
                        : view_fail(d, SSG_E_USAGE, "the scene file's name holds a control "
                                    "character a scene cannot quote");
    }
    enum ssg_err e = SSG_OK;
    fputs("# A camera path recorded by `ssgraph view`: the scene included below, with these\n"
          "# keys as its camera path (they replace its own camera_key lines or orbit).\n"
          "include ", f);
    view_quote(f, abs);
    fputc('\n', f);
    if (!key_lines(f, keys, d))
        e = SSG_E_USAGE;
    free(abs);
    return view_text_close(f, text, e, "the path", d);
}

enum ssg_err view_session_save_path(const struct view_session *s, const char *name,
                                    const char *keys, char *path, size_t len,
                                    struct ssg_diags *d)
{
    struct ssg_graph_info info;
    ssg_graph_inspect(s->g, &info);
    if (!info.scene || !info.scene[0])
        return view_fail(d, SSG_E_USAGE, "the graph has no scene file: a camera path needs "
                         "one to include");
    enum ssg_err e = view_new_path(s, name, ".scene", path, len, d);
    if (e)
        return e;
    char *text = NULL;
    size_t text_len = 0;
    e = compose(info.scene, keys, &text, &text_len, d);
    if (!e)
        e = view_write_new(path, text, text_len, d);
    free(text);
    return e;
}
