/* text_out.h - the quoting every table and JSON file the CLI writes shares (text_out.c):
 * bench.csv and bench.json, tune.csv and tune.json. Each writes to the FILE it is given. */
#ifndef SSG_CLI_TEXT_OUT_H
#define SSG_CLI_TEXT_OUT_H

#include <stdio.h>

/* A CSV field, always quoted, inner quotes doubled (RFC 4180). */
void ssg_csv_field(FILE *f, const char *text);

/* A JSON string with quotes, backslashes and control characters escaped. */
void ssg_json_string(FILE *f, const char *s);

/* A JSON number at 9 significant digits; null where it is not finite (JSON has no inf:
   the PSNR of identical images, the error of a run that failed). */
void ssg_json_number(FILE *f, double v);

#endif
