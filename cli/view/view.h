/* view.h - `ssgraph view GRAPH`: the graph as a live graph behind a local web page
 * (server.c; the page: cli/view/page/, embedded; docs/viewer.md). */
#ifndef SSG_CLI_VIEW_H
#define SSG_CLI_VIEW_H

#include "../options.h"

/* Loads and runs the graph of args, serves the page on 127.0.0.1 (args->port; 0 = a free
 * port), prints its URL with a fresh token and serves until SIGINT or SIGTERM. Returns the
 * exit status: 0 after a signal, 1 when the graph does not load or the port cannot be
 * opened. */
int ssg_cli_view(const struct ssg_cli_args *args);

/* The page's files, embedded at build time (cmake/embed_files.cmake). */
struct ssg_view_file {
    const char *name; /* "index.html" */
    const char *text;
};
extern const struct ssg_view_file ssg_view_files[]; /* ends with {NULL, NULL} */

#endif
