/* check_kind.h - what `ssgraph check FILE` takes a file for (check_kind.c): a model by its
 * extension, or a file that is none of what check takes (an image, a binary file), named for
 * what it is. Reads at most the first 4 KiB of a regular file; safe from any thread. */
#ifndef SSG_CLI_CHECK_KIND_H
#define SSG_CLI_CHECK_KIND_H

/* 1 when `check` should take path for a model file: an extension the model reader knows
   (ssg_model_supported), and not .scene or .graph. */
int ssg_cli_is_model(const char *path);

/* "a PNG image", "a binary file (it holds NUL bytes)": what path is when it is none of what
   check takes; NULL for text, or for what cannot be read (the graph's load says why). Only
   a regular file is read (a FIFO's open does not wait: O_NONBLOCK). */
const char *ssg_cli_not_checkable(const char *path);

#endif
