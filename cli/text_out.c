/* text_out.c - CSV and JSON quoting for the CLI's result files (text_out.h). */
#include <math.h>
#include <string.h>

#include "text_out.h"

void ssg_csv_field(FILE *f, const char *text)
{
    fputc('"', f);
    for (; *text; text++) {
        if (*text == '"')
            fputc('"', f);
        fputc(*text, f);
    }
    fputc('"', f);
}

void ssg_json_string(FILE *f, const char *s)
{
    /* runs of plain characters in one fwrite: a character at a time took the stream's lock
       for each, a fifth of the viewer's state answer (37 KB of names and docs) */
    static const char special[] = "\"\\\x01\x02\x03\x04\x05\x06\x07\x08\x09\x0a\x0b\x0c\x0d"
                                  "\x0e\x0f\x10\x11\x12\x13\x14\x15\x16\x17\x18\x19\x1a\x1b"
                                  "\x1c\x1d\x1e\x1f";
    fputc('"', f);
    for (;;) {
        size_t plain = strcspn(s, special);
        fwrite(s, 1, plain, f);
        s += plain;
        if (!*s)
            break;
        if (*s == '"' || *s == '\\')
            fprintf(f, "\\%c", *s);
        else
            fprintf(f, "\\u%04x", *s);
        s++;
    }
    fputc('"', f);
}

void ssg_json_number(FILE *f, double v)
{
    if (isfinite(v))
        fprintf(f, "%.9g", v);
    else
        fputs("null", f);
}
