/* graph_history.h - images kept from one frame to the next for the inputs written
 * prev(node.port) in a graph file (docs/time.md, "History across frames").
 *
 * A prev() edge reads the image its port had in the previous frame, so it does not order
 * the graph (graph_check.c leaves it out of the run order and the cycle check): a node may
 * read prev() of its own output or of a node that runs after it. Every port some node
 * reads through prev() gets a slot holding two images, double-buffered: when the port's
 * node is about to write a new frame, the image it wrote last becomes the slot's history
 * (no copy) and the history before goes back to the pool. A reader that runs before the
 * port's node in a frame reads the port's image itself, which is still the previous
 * frame's; one that runs after it reads the slot's history.
 *
 * Where no previous frame is valid (the first frame of a run, the first run of a kept
 * graph, a set of the port's node, its outputs evicted, a new camera, a cut), the reader
 * gets an all-zero image of the port's shape and ctx->history_reset = 1.
 *
 * The state belongs to the graph (ssg_graph.history): a run that is not kept creates and
 * frees it; a kept graph (ssg_graph_keep) keeps it from one run to the next, which is how
 * the viewer and a real-time loop accumulate, and frees it with its pool. One thread (the
 * executor) uses it. Internal to libssgraph. */
#ifndef SSG_GRAPH_HISTORY_H
#define SSG_GRAPH_HISTORY_H

#include "graph/graph.h"

struct ssg_image;
struct ssg_pool;

/* Before a run's first frame: makes the slots (none when nothing is read through prev());
   on a kept graph forgets the history of every port whose node will run afresh (a set, an
   eviction: live->kept cleared) or whose shape changed. SSG_E_NOMEM on out of memory. */
enum ssg_err ssg_history_begin(struct ssg_graph *g, struct ssg_pool *pool);
/* 1 when node n reads an input through prev(): its input is a new frame in every frame,
   so it runs in every one (graph_redo.c). */
int ssg_history_reads_prev(const struct gnode *n);
/* Forgets the frame before of every port of node `node` (index) read through prev(): its
   readers start afresh (SSG_RECOMPUTE_HISTORY). */
void ssg_history_forget_node(struct ssg_graph *g, struct ssg_pool *pool, int node);
/* At the start of each frame: a new frame for the double buffers, and a pending cut
   (ssg_history_cut) empties every slot. */
void ssg_history_frame(struct ssg_graph *g, struct ssg_pool *pool);
/* Node n is about to write output `port`: when a slot keeps that port, its current image
   becomes the history (the one before goes back to the pool) and n->out_img[port] is NULL;
   returns 1 then, 0 when no slot keeps it (the caller releases the image as before). */
int ssg_history_keep(struct ssg_graph *g, struct ssg_pool *pool, struct gnode *n, int port);
/* Node n's prev() inputs into in[] (ports) and extra[] (named inputs): the previous
   frame's image, or a zero image where there is none. *reset: -1 when n reads nothing
   through prev(), else 1 when one of them had no previous frame, 0 otherwise. */
enum ssg_err ssg_history_bind(struct ssg_graph *g, struct ssg_pool *pool, const struct gnode *n,
                              const struct ssg_image **in, const struct ssg_image **extra,
                              int *reset);
/* A discontinuity (a new camera, a cut in a camera path): the next frame starts without
   history. */
void ssg_history_cut(struct ssg_graph *g);
/* Gives every kept image back to the pool (before the pool is destroyed: it frees only
   the images given back) and frees the state. */
void ssg_history_free(struct ssg_graph *g, struct ssg_pool *pool);

#endif
