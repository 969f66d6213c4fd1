/* test_param_format.c - a parameter's value as text (ssg_param_format: `describe`, the
 * viewer's parameter list, Python's Node.params, values written back into files) reads back
 * as the same value: a string holding a quote, a backslash, a newline or a tab (each spelled
 * by its escape in a file) is written with those escapes, on one line, never raw (a raw
 * newline there would start a second line in whatever file the text is pasted into). */
#include <string.h>

#include "check.h"
#include "lang/params.h"

struct labelled {
    char label[SSG_STR_MAX];
};

static const struct ssg_param_desc rows[] = {
    {.name = "label", SSG_FIELD_STRING(struct labelled, label), .help = "a label"},
};

/* Parses `set` ("label=...") and returns the value formatted into buf. */
static const char *round_trip(const char *set, char *buf, size_t len)
{
    struct ssg_param_table table = SSG_TABLE(rows);
    struct labelled v;
    struct ssg_diags d = {0};
    ssg_params_defaults(table, &v);
    CHECK_EQ(ssg_param_set_text(table, &v, set, "<test>", "demo", &d), SSG_OK);
    ssg_param_format(&rows[0], &v, buf, len);
    return buf;
}

static void test_escapes_written_back(void)
{
    char buf[64], again[80], twice[64];
    round_trip("label=\"a\\\"b\\\\c\\nd\\te\"", buf, sizeof buf);
    CHECK(strcmp(buf, "\"a\\\"b\\\\c\\nd\\te\"") == 0);
    CHECK(strpbrk(buf, "\n\t") == NULL);
    /* what was written parses back to the same value, and so formats the same */
    snprintf(again, sizeof again, "label=%s", buf);
    round_trip(again, twice, sizeof twice);
    CHECK(strcmp(twice, buf) == 0);
}

static void test_cut_before_an_escape(void)
{
    /* 6 bytes: '"', 'a', then '\n' needs 2 and the closing quote 1 with the NUL: cut there */
    char buf[6];
    round_trip("label=\"ab\\ncd\"", buf, sizeof buf);
    CHECK(strcmp(buf, "\"ab\"") == 0);
    char tiny[2] = "x";
    round_trip("label=\"ab\"", tiny, sizeof tiny);
    CHECK(tiny[0] == '\0');
}

int main(void)
{
    test_escapes_written_back();
    test_cut_before_an_escape();
    return check_report();
}
