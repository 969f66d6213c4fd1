/* api.h - the bodies of the viewer's answers (api.c): the state as JSON, a port's image as
 * the binary the page draws, the metrics of two ports against a reference, and the graph's
 * diagram as SVG (Graphviz's dot). The HTTP side (server.c) sends them; the format of each
 * is in docs/viewer-api.md. Each returns a malloc'd buffer and its length,
 * or NULL with the reason in diags. */
#ifndef SSG_CLI_VIEW_API_H
#define SSG_CLI_VIEW_API_H

#include <stddef.h>

#include "session.h"

/* GET /api/state: the graph, its nodes with parameters (value and descriptor), ports,
 * what ran and how long, the camera, the last error. */
char *view_state_json(const struct view_session *s, size_t *len);

/* GET /api/image: "SSGI", then width, height, channels and the generation as little-endian
 * uint32, then the pixels as float32, rows top to bottom, channels interleaved. */
char *view_image_bytes(struct view_session *s, const char *port, int preview, size_t *len,
                       struct ssg_diags *diags);

/* GET /api/metrics: {"a": {"rmse", "ssim"}, "b": ... | null} of ports a and b (b may be
 * NULL) against ref, through the compare node. */
char *view_metrics_json(struct view_session *s, const char *ref, const char *a, const char *b,
                        size_t *len, struct ssg_diags *diags);

/* GET /api/flip: the FLIP map (nodes/compare/README.md) of port a against port b, the
 * reference, both at full size, as GET /api/image's bytes of one channel in [0, 1]. */
char *view_flip_bytes(struct view_session *s, const char *a, const char *b, size_t *len,
                      struct ssg_diags *diags);

/* GET /api/graph.svg: `dot -Tsvg` of the graph's DOT (ssg_graph_dot). */
char *view_graph_svg(const struct view_session *s, size_t *len, struct ssg_diags *diags);

/* GET /api/types: every node type a page may add, with its input ports (the types each
 * takes, optional or not) and output ports (edit.c). */
char *view_types_json(size_t *len);

#endif
