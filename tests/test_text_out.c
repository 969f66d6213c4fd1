/* test_text_out.c - the CLI's JSON string quoting (cli/text_out.h), which every answer of the
 * viewer's API and `run --stats` goes through: quotes and backslashes escaped, every control
 * character (a newline in a value, issue 45's kind) as \u00XX, everything else, UTF-8
 * included, copied whole, whatever the run lengths between them. */
#define _DEFAULT_SOURCE /* open_memstream */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "text_out.h"

/* ssg_json_string of s, as a new string. */
static char *quoted(const char *s)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    ssg_json_string(f, s);
    fclose(f);
    return text;
}

static void expect(const char *in, const char *want)
{
    char *got = quoted(in);
    if (strcmp(got, want))
        fprintf(stderr, "ssg_json_string(%s): got %s, expected %s\n", in, got, want);
    CHECK(!strcmp(got, want));
    free(got);
}

int main(void)
{
    expect("", "\"\"");
    expect("plain text", "\"plain text\"");
    expect("a\"b\\c", "\"a\\\"b\\\\c\"");
    expect("line\nnext\ttab\r", "\"line\\u000anext\\u0009tab\\u000d\"");
    expect("\x01\x1f", "\"\\u0001\\u001f\"");
    expect("\"", "\"\\\"\"");
    expect("caf\xc3\xa9 \x7f", "\"caf\xc3\xa9 \x7f\""); /* UTF-8 and DEL pass through */
    /* every control character, each between plain runs */
    for (int c = 1; c < 0x20; c++) {
        char in[8], want[16];
        snprintf(in, sizeof in, "x%cy", c);
        snprintf(want, sizeof want, "\"x\\u%04xy\"", c);
        expect(in, want);
    }
    return check_report();
}
