/* show.h - `ssgraph run --show NODE.PORT[,...]` (show.c): the ports a run hands out
 * besides its own files (ssg_overrides.outputs with keep_sinks), each written as
 * <out>/NODE.PORT.exr and <out>/NODE.PORT.png, framed and previewed as a write node of the
 * port would write them. Uses only the public header. Not thread-safe (one run). */
#ifndef SSG_CLI_SHOW_H
#define SSG_CLI_SHOW_H

#include "ssgraph.h"

/* The parsed --show list and, after the run, its images. Zero-initialise it. */
struct ssg_cli_show {
    int count;                             /* ports */
    const char *ports[SSG_MAX_OUTPUTS];    /* "ao.out", pointing into text */
    char text[1024];                       /* the list, its commas made NULs */
    struct ssg_image *images[SSG_MAX_OUTPUTS]; /* the run's outputs (ssg_run_options) */
};

/* Parses "ao.out,g.normal" into *s: 0, or a usage error's exit code (printed): an empty
 * entry, one not NODE.PORT (names of letters, digits and '_'), one twice, more than
 * SSG_MAX_OUTPUTS. */
int ssg_cli_show_parse(const char *list, struct ssg_cli_show *s);

/* Asks the load for the ports (keeping the graph's sinks) and the run for their images. */
void ssg_cli_show_request(struct ssg_cli_show *s, struct ssg_overrides *ov,
                          struct ssg_run_options *ro);

/* Writes each image the run handed out into out_dir as NODE.PORT.exr and NODE.PORT.png
 * (tonemap, exposure: the PNG's, NULL/0 = the write node's defaults), naming each file on
 * a `wrote PATH` line unless quiet; the image without the graph's guard band. */
enum ssg_err ssg_cli_show_write(const struct ssg_cli_show *s, const struct ssg_graph *g,
                                const char *out_dir, const char *tonemap, float exposure,
                                int quiet, struct ssg_diags *diags);

/* Frees the images; *s may be parsed again. */
void ssg_cli_show_free(struct ssg_cli_show *s);

#endif
