/* graph_files.h - the graph files a build read, kept for file watchers (ssg_graph_files,
 * api_graph_files.c). Internal to libssgraph. The list lives in the graph's arena and is
 * filled by graph_build.c as it reads each file (the top one and every include). */
#ifndef SSG_GRAPH_FILES_H
#define SSG_GRAPH_FILES_H

#include "graph/graph.h"

/* The graph files read, each once, in the order first read. */
struct ssg_file_list {
    const char **paths; /* count entries, strings in the graph's arena */
    int count, cap;
};

/* Records that the builder opens path (before it is read, so a missing include is listed
 * too and a watcher sees it appear); a path already listed is not added again. SSG_OK, or
 * SSG_E_NOMEM. */
enum ssg_err ssg_graph_file_note(struct ssg_graph *g, const char *path);

#endif
