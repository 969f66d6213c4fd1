/* graph_skip.h - skipping the passes of a frame whose work nothing uses (graph_skip.c).
 * Internal to libssgraph: the executor (graph_run.c) asks before each node it would run.
 *
 * A graph made for every scene computes terms some scenes do not have: gi.graph's far
 * field lights a scene from its environment through 768 shadow-mapped lights, and on a
 * scene without one (lightprobe missing=dark) every one of them carries nothing, so the
 * half-resolution G-buffer, the probe's light, its filter and its upsampling (a tenth of
 * the frame at 1280x720) made zeros and a visibility that combine then multiplied by those
 * zeros. Three declarations in the node descriptors (node.h) let the executor see it:
 * which outputs are zero for the inputs at hand (zero_outputs), which output stays zero
 * with which input (zero_with), and which inputs cannot change any output byte while
 * others are zero (ignored_inputs). A node is skipped when each of its outputs is known to
 * be all zero or is used by nothing that will run and use it; its outputs are then filled
 * with +0 where anything reads them, the bytes its run would have made where they are
 * used. */
#ifndef SSG_GRAPH_SKIP_H
#define SSG_GRAPH_SKIP_H

#include "graph/graph.h"

struct ssg_skip;
/* The state of one run of g (positions, the zero outputs known so far); NULL on out of
   memory. */
struct ssg_skip *ssg_skip_create(const struct ssg_graph *g);
void ssg_skip_free(struct ssg_skip **s);
/* Whether the node at run position p, about to run, may be skipped; the nodes before p
   have run, been skipped or been kept in this frame. *fill gets the outputs to fill with
   +0 (read by something that runs) when it may. Records what p's outputs will be: call it
   for every node that runs. */
int ssg_skip_decide(struct ssg_skip *s, const struct ssg_graph *g, int p, unsigned *fill);

#endif
