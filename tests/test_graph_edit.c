/* test_graph_edit.c - ssg_graph_text_edit and ssg_graph_load_text (ssgraph_tools.h): the
 * edits change only their spans, the way a person edits a graph file:
 * - a keyed argument and a positional one are replaced where they stand (a prev(node.port)
 *   whole, both ways); an argument the call lacks is added to it, on a line of its own past
 *   column 96; a set line of the key is changed instead of the call; a node of an included
 *   file gets a set line;
 * - a new node is appended; remove deletes the call's whole lines with the comment above
 *   and on its line, and the node's set lines; several edits apply in order;
 * - refused: a node others read (each reader at its file:line:column), a node the text
 *   does not define, an anonymous new node, an unknown edit, a syntax error in the edits
 *   (at <edit>:line:column);
 * - the edited text loads in the file's place, its messages at the file's name and the
 *   edited text's line, its includes resolved beside the file. */
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scratch.h"
#include "ssgraph.h"

static const char *BASE =
    "# base\n"
    "g   = gbuffer()\n"
    "k   = halton(count=8, bases=[2, 3])\n"
    "ao  = ssao(g.position, g.normal, kernel=k.samples, rotation=k.rotation, radius=0.5)\n"
    "# smooths the AO\n"
    "b   = bilateral(ao.out, depth=g.depth, size=5)   # five taps\n"
    "set b.size = 7\n"
    "out = write(b.out, \"x\")\n";

static struct ssg_diags diags;

/* The text after edits (static; "" when refused, the code in *code). */
static const char *edit(const char *text, const char *edits, enum ssg_err *code)
{
    static char result[4096];
    char *out = NULL;
    diags = (struct ssg_diags){0};
    enum ssg_err e = ssg_graph_text_edit("t.graph", text, edits, &out, &diags);
    if (code)
        *code = e;
    snprintf(result, sizeof result, "%s", out ? out : "");
    free(out);
    return result;
}

/* 1 when `text` is BASE with line `from` replaced by `to` (NULL: deleted). */
static int base_with(const char *text, const char *from, const char *to)
{
    char want[4096];
    const char *at = strstr(BASE, from);
    if (!at)
        return 0;
    snprintf(want, sizeof want, "%.*s%s%s", (int)(at - BASE), BASE, to ? to : "",
             at + strlen(from));
    if (strcmp(text, want))
        fprintf(stderr, "got:\n%s\nwanted:\n%s\n", text, want);
    return !strcmp(text, want);
}

static int has_message(const char *part)
{
    for (int i = 0; i < diags.count; i++) {
        char line[1200];
        snprintf(line, sizeof line, "%s:%d:%d: %s", diags.items[i].file, diags.items[i].line,
                 diags.items[i].column, diags.items[i].message);
        if (strstr(line, part))
            return 1;
    }
    fprintf(stderr, "no message has '%s' (%d messages)\n", part, diags.count);
    return 0;
}

static void test_changes(void)
{
    CHECK(base_with(edit(BASE, "set ao.radius = 0.25", NULL), "radius=0.5", "radius=0.25"));
    CHECK(base_with(edit(BASE, "set ao.normal = g.position", NULL), "g.normal,",
                    "g.position,"));                       /* positional: the second input */
    CHECK(base_with(edit(BASE, "set b.size = 3", NULL), "set b.size = 7", "set b.size = 3"));
    CHECK(base_with(edit(BASE, "set b.normal = g.normal", NULL), "size=5)",
                    "size=5, normal=g.normal)"));
    /* past column 96: on a line of its own, under the first argument */
    CHECK(base_with(edit(BASE, "set ao.max_screen_radius = 0.25", NULL), "radius=0.5)",
                    "radius=0.5,\n           max_screen_radius=0.25)"));
    /* prev(node.port) is one value, written whole both ways */
    const char *prev = edit(BASE, "set b.depth = prev(g.depth)", NULL);
    CHECK(base_with(prev, "depth=g.depth, size", "depth=prev(g.depth), size"));
    char back[4096];
    snprintf(back, sizeof back, "%s", prev);
    CHECK(!strcmp(edit(back, "set b.depth = g.depth", NULL), BASE));
    const char *empty = "scene \"a.scene\"\ng = gbuffer()\n";
    CHECK(!strcmp(edit(empty, "set g.backend = cpu", NULL),
                  "scene \"a.scene\"\ng = gbuffer(backend=cpu)\n"));
    /* a node the text does not define (an include's): a set line */
    CHECK(!strcmp(edit("include \"b.graph\"", "set ao.radius = 1", NULL),
                  "include \"b.graph\"\nset ao.radius = 1\n"));
}

static void test_add_remove(void)
{
    char want[4096];
    snprintf(want, sizeof want, "%sb2 = bilateral(ao.out, depth=g.depth)\n", BASE);
    CHECK(!strcmp(edit(BASE, "b2 = bilateral(ao.out, depth=g.depth)", NULL), want));
    const char *two = edit(BASE, "set out.image = ao.out\nremove b", NULL);
    CHECK(!strcmp(two, "# base\n"
                       "g   = gbuffer()\n"
                       "k   = halton(count=8, bases=[2, 3])\n"
                       "ao  = ssao(g.position, g.normal, kernel=k.samples, rotation=k.rotation, "
                       "radius=0.5)\n"
                       "out = write(ao.out, \"x\")\n"));
}

static void test_refused(void)
{
    enum ssg_err e;
    CHECK(!*edit(BASE, "remove g", &e));
    CHECK_EQ(e, SSG_E_UNKNOWN_NAME);
    CHECK(has_message("t.graph:4:12: cannot remove node 'g': node 'ao' reads it"));
    CHECK(has_message("t.graph:6:31: cannot remove node 'g': node 'b' reads it"));
    CHECK(!*edit(BASE, "remove nobody", &e) && e == SSG_E_UNKNOWN_NAME);
    CHECK(has_message("<edit>:1:8: no node 'nobody' is defined in t.graph"));
    CHECK(!*edit(BASE, "bilateral(ao.out)", &e) && e == SSG_E_SYNTAX);
    CHECK(has_message("<edit>:1:1: a new node needs a name"));
    CHECK(!*edit(BASE, "scene \"x\"", &e) && e == SSG_E_SYNTAX);
    CHECK(has_message("<edit>:1:1: unknown edit 'scene'"));
    CHECK(!*edit(BASE, "set b.size = (", &e) && e == SSG_E_SYNTAX);
    CHECK(has_message("<edit>:1:14: expected a value"));
    CHECK(!*edit(BASE, "", &e) && e == SSG_E_SYNTAX);
}

static void test_load_text(void)
{
    write_file("inc.graph", "size 32 18\ng = gbuffer()\nk = halton(count=4)\n");
    const char *path = tmp_path("top.graph"); /* never written: the text stands for it */
    char text[1024];
    snprintf(text, sizeof text, "include \"inc.graph\"\nscene \"%s/examples/cornell.scene\"\n"
             "ao = ssao(g.position, g.normal, kernel=k.samples, rotation=k.rotation)\n"
             "out = write(ao.out, \"x\")\n",
             SSG_SOURCE_DIR);
    struct ssg_graph *g = NULL;
    diags = (struct ssg_diags){0};
    CHECK_EQ(ssg_graph_load_text(path, text, NULL, &g, &diags), SSG_OK);
    CHECK(g && ssg_graph_node_index(g, "ao") >= 0);
    ssg_graph_destroy(&g);
    char *bad = NULL;
    CHECK_EQ(ssg_graph_text_edit(path, text, "set ao.normal = g.depth", &bad, &diags), SSG_OK);
    diags = (struct ssg_diags){0};
    CHECK(ssg_graph_load_text(path, bad, NULL, &g, &diags) != SSG_OK && !g);
    char where[1100];
    snprintf(where, sizeof where, "%s:3:23: input 'normal'", path);
    CHECK(has_message(where));
    free(bad);
}

int main(void)
{
    setup_tmp("graph_edit");
    test_changes();
    test_add_remove();
    test_refused();
    test_load_text();
    return check_report();
}
