/* edit.c - the graph editor's side of `ssgraph view` that is not the session's state:
 * "save as" of the edited text (session.h: view_session_save_edited) and the node types a
 * page may add (api.h: view_types_json). The edits themselves are the core's
 * (ssg_graph_text_edit) and the session's (view_session_edit).
 *
 * The saved file is the graph file as the page left it: the parameter changes of the
 * command line and of the page are written into the statements the way the edits are
 * (a call's argument changed or added, not a set line on top), and the server's --scene,
 * --lights, --size, --guard and --seed follow as statements at the end (later lines win,
 * docs/graphs.md), so `ssgraph check NAME.graph` loads the graph the page shows. */
#define _DEFAULT_SOURCE /* open_memstream */
#include "api.h"

#include <stdlib.h>
#include <string.h>

#include "../text_out.h"

/* The parameter changes of the command line and of this session as set lines (variant.c's,
   with its refusal of control characters), malloc'd into *text. */
static enum ssg_err set_lines(const struct view_session *s, char **text, struct ssg_diags *d)
{
    size_t len = 0;
    FILE *f = open_memstream(text, &len);
    if (!f)
        return view_fail(d, SSG_E_NOMEM, "out of memory for the saved graph");
    enum ssg_err e = view_set_lines(f, s, d);
    return view_text_close(f, text, e, "the saved graph", d);
}

/* The server's command line as statements, after a comment; "" when it gave none. */
static enum ssg_err command_tail(const struct view_session *s, FILE *out, struct ssg_diags *d)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f)
        return view_fail(d, SSG_E_NOMEM, "out of memory for the saved graph");
    enum ssg_err e = view_command_line(f, &s->args->ov, d);
    fclose(f);
    if (!e && text && len)
        fprintf(out, "\n# The command line `ssgraph view` was started with:\n%s", text);
    free(text);
    return e;
}

/* The edited text with the parameter changes written in, then the command line. */
static enum ssg_err compose(const struct view_session *s, char **text, size_t *len,
                            struct ssg_diags *d)
{
    char *sets = NULL, *folded = NULL;
    enum ssg_err e = set_lines(s, &sets, d);
    if (!e && sets && *sets)
        e = ssg_graph_text_edit(s->args->files[0], s->text, sets, &folded, d);
    free(sets);
    if (e)
        return e;
    FILE *f = open_memstream(text, len);
    if (!f) {
        free(folded);
        return view_fail(d, SSG_E_NOMEM, "out of memory for the saved graph");
    }
    const char *body = folded ? folded : s->text;
    fputs(body, f);
    if (*body && body[strlen(body) - 1] != '\n')
        fputc('\n', f);
    free(folded);
    e = command_tail(s, f, d);
    view_camera_comment(f, s);
    return view_text_close(f, text, e, "the saved graph", d);
}

enum ssg_err view_session_save_edited(struct view_session *s, const char *name, char *path,
                                      size_t len, struct ssg_diags *d)
{
    if (!s->text)
        return view_fail(d, SSG_E_USAGE, "the graph has no edits to save (save as variant "
                         "keeps the page's parameter changes)");
    enum ssg_err e = view_new_path(s, name, ".graph", path, len, d);
    char *text = NULL;
    size_t text_len = 0;
    if (!e)
        e = compose(s, &text, &text_len, d);
    if (!e)
        e = view_write_new(path, text, text_len, d);
    free(text);
    if (!e)
        s->edits = 0;
    return e;
}

/* "color|scalar" as ["color","scalar"]. */
static void json_types(FILE *f, const char *types)
{
    fputs("[", f);
    for (const char *p = types; *p;) {
        size_t n = strcspn(p, "|");
        char one[32];
        snprintf(one, sizeof one, "%.*s", (int)n, p);
        if (p != types)
            fputs(",", f);
        ssg_json_string(f, one);
        p += n + (p[n] == '|');
    }
    fputs("]", f);
}

static void json_type(FILE *f, int index)
{
    const char *type = ssg_node_name(index);
    fputs("{\"name\":", f);
    ssg_json_string(f, type);
    fputs(",\"doc\":", f);
    ssg_json_string(f, ssg_node_summary(index));
    for (int output = 0; output < 2; output++) {
        fputs(output ? "],\"outputs\":[" : ",\"inputs\":[", f);
        int first = 1;
        for (int k = 0; k < ssg_node_port_count(type); k++) {
            struct ssg_type_port p;
            if (ssg_node_port_info(type, k, &p) || p.output != output)
                continue;
            fputs(first ? "{\"port\":" : ",{\"port\":", f);
            first = 0;
            ssg_json_string(f, p.name);
            fputs(",\"types\":", f);
            json_types(f, p.types);
            fprintf(f, ",\"optional\":%s}", p.optional ? "true" : "false");
        }
    }
    fputs("]}", f);
}

char *view_types_json(size_t *len)
{
    char *text = NULL;
    FILE *f = open_memstream(&text, len);
    if (!f)
        return NULL;
    fputs("{\"types\":[", f);
    for (int i = 0; i < ssg_node_count(); i++) {
        if (i)
            fputs(",", f);
        json_type(f, i);
    }
    fputs("]}\n", f);
    if (fclose(f)) {
        free(text);
        return NULL;
    }
    return text;
}
