/* graph_info.h - what the command line reads of a graph besides running it (graph_info.c):
 * `ssgraph dot`, the write node that -o names, the --set values it quotes, and what -v
 * prints of a loaded graph, all through the public interface (ssg_graph_parse, which only
 * parses: no scene is loaded; ssg_graph_inspect). Single-threaded, as the command line. */
#ifndef SSG_CLI_GRAPH_INFO_H
#define SSG_CLI_GRAPH_INFO_H

#include <stdio.h>

#include "options.h"
#include "ssgraph.h"

/* Writes the graph at path as Graphviz DOT: a node per instance labelled with its name and
 * type, an edge per connection labelled "output -> input" (the producer's port, the
 * consumer's input or layer). To out_path (its folders made) through a temporary file
 * (NULL: stdout). */
enum ssg_err ssg_cli_dot(const char *path, const char *out_path, struct ssg_diags *diags);

/* The instance name of the graph's first write node (in file order, includes first) into
 * name: 1; 0 when the graph has none; -1 when it does not parse (its load reports why). */
int ssg_cli_first_write(const char *path, char *name, size_t len);

/* Quotes every --set value written bare ("out.name=x") whose parameter is a string, so
 * that it reaches the graph as "out.name=\"x\"": for the graph commands the node is found
 * by instance name in a->files[0], for `node` the parameter in the node a->files[0]. A
 * value already quoted, or for another type, stays as written. Each bare value of a
 * --sweep of a string parameter is quoted the same way. 0, or a usage error's exit code
 * when the rewritten values do not fit. */
int ssg_cli_quote_sets(struct ssg_cli_args *a, enum ssg_cli_command command);

/* -v: the frame, seed, scene and backend a loaded graph resolved, and each node's
 * parameters as they will run, one node a line. */
/* The node lines of ssg_cli_print_resolved alone: each live node in run order with its
   backend and every parameter's value. */
void ssg_cli_print_node_params(const struct ssg_graph *g, FILE *f);
void ssg_cli_print_resolved(const struct ssg_graph *graph, FILE *stream);

#endif
