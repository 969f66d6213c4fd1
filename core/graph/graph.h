/* graph.h - the in-memory graph between loading and running. Internal to libssgraph.
 *
 * graph_build.c turns parsed statements (with includes, `set` lines and command-line
 * overrides) into nodes with parameters and connections; graph_check.c validates the whole
 * graph and orders it; graph.c loads the scene and runs the nodes. Everything a graph owns
 * lives in its arena, except the scene and the pool. */
#ifndef SSG_GRAPH_H
#define SSG_GRAPH_H

#include "lang/arena.h"
#include "graph/exec.h"
#include "graph/gl_backend.h"
#include "lang/parse.h"
#include "scene/scene.h"

/* An input connection: which node's output feeds it. */
struct gconn {
    int node;            /* producer index, -1 = unconnected */
    int port;            /* producer output port */
    const char *ref;     /* "g.position" as written, for messages */
    struct ssg_value value; /* the reference value (locations of node and port names;
                               value.prev = 1: prev(node.port), graph_history.h) */
};

/* Where a graph stands in time (graph_time.c, docs/time.md): the frame the next run starts
 * at and the last frame run, whose camera is the next frame's prev_camera when it follows
 * on. */
struct ssg_timeline {
    int next;          /* first frame of the next run (ssg_graph_set_frame), 0 */
    int last;          /* the last frame run, valid when has_last */
    int has_last;      /* 0 = nothing to follow on from: none run yet, or a cut since */
    int view_set;      /* 1 = ssg_graph_set_view's camera stands in for the path in
                          one-frame runs, until ssg_graph_set_frame */
    struct ssg_camera last_camera; /* the camera of frame `last` */
    struct ssg_camera prepared_prev; /* the previous camera the nodes last prepared with */
    int kept_frame;    /* the frame a live graph's kept outputs are of (set by every run) */
    int has_prepared_prev;
};

/* What one frame of a run sees of time (ssg_time_begin). */
struct ssg_time_step {
    double time_s;           /* frame / fps */
    struct ssg_camera prev;  /* the camera of the frame before, or this one's */
    int reset;               /* 1 = no earlier frame may be reused (node.h history_reset) */
};

struct gnode {
    const struct ssg_node_desc *desc;
    const char *name;          /* instance name ("ao"; "write_1" when anonymous) */
    struct ssg_loc loc;        /* the callee token, where node-level errors point */
    void *params;              /* desc->params_size bytes */
    unsigned char param_set[64]; /* 1 = given explicitly (required-parameter check) */
    struct gconn in[SSG_MAX_PORTS];
    int extra_count;
    const char *extra_names[SSG_MAX_EXTRA];
    struct gconn extra[SSG_MAX_EXTRA];
    unsigned extra_types[SSG_MAX_EXTRA];
    struct ssg_shape in_shape[SSG_MAX_PORTS];
    struct ssg_shape out_shape[SSG_MAX_PORTS];
    int live;                  /* 1 = contributes to a sink */
    int last_reader[SSG_MAX_PORTS]; /* run position of the last node reading each output */
    struct ssg_image *out_img[SSG_MAX_PORTS];
    const struct ssg_stmt *stmt; /* the statement that made it */
    enum ssg_backend backend;  /* backend= of the call; DEFAULT = the graph's */
    struct ssg_loc backend_loc; /* where backend= was written */
    enum ssg_backend runs_on;  /* resolved by validation: CPU or GL */
    struct ssg_image *supplied; /* a supplied node's image (ssg_graph_supply), the graph's
                                   own copy; NULL = none */
};

struct ssg_graph {
    struct ssg_arena arena;
    const char *path;          /* the top graph file */
    const char *text;          /* its text when it comes from memory (ssg_graph_load_text),
                                  the caller's, during the build only; NULL = read path */
    char scene_path[512];      /* resolved scene file, "" = none */
    struct ssg_loc scene_loc;  /* where it was named */
    char lights_path[512];     /* resolved lights file replacing the scene's lights, "" =
                                  the scene's own */
    int width, height;
    struct ssg_loc size_loc;
    int guard;                 /* the `guard` line's pixels, 0 = none */
    struct ssg_loc guard_loc;
    int jitter;                /* the `jitter` line's phases, 0 = none (graph_time.c) */
    int64_t seed;
    struct gnode *nodes;
    int count, cap;
    int *name_slots;           /* open-addressing table of node index + 1 by name (0 =
                                  empty), name_cap slots, at most half full: a lookup is
                                  O(1), so building and checking stay linear */
    int name_cap;
    int *order;                /* run order: node indices, live nodes only */
    int order_count;
    struct ssg_scene *scene;
    struct ssg_frame frame;
    enum ssg_backend backend;  /* `backend` directive; DEFAULT = cpu */
    enum ssg_backend forced;   /* --backend: every node runs there (DEFAULT = not given) */
    struct gconn wanted[SSG_MAX_OUTPUTS]; /* ssg_overrides.outputs, resolved by validation:
                                  only they and what they read are live, and each keeps
                                  its image until the run hands it out */
    int wanted_count;          /* 0 = the sinks decide what is live */
    int keep_sinks;            /* ssg_overrides.keep_sinks: with wanted outputs, the sinks
                                  are live and run too */
    const char **sets;         /* ssg_overrides.sets, copied: what the run's files record */
    int set_count;
    struct ssg_live *live;     /* the run state kept between runs (ssg_graph_keep), NULL =
                                  every run starts afresh */
    struct ssg_file_list *files; /* graph files read (graph_files.h), NULL = none yet */
    struct ssg_history *history; /* the previous frame's images of the ports read through
                                  prev() (graph_history.h), NULL = none kept */
    float eye_offset;          /* ssg_overrides.eye_offset: every camera moved sideways */
    struct ssg_timeline time;  /* graph_time.c */
};

/* Node n's connections, its ports' then its extra inputs': k from 0 to
   ssg_gnode_conn_count(n) - 1; an unconnected one has node < 0. */
static inline int ssg_gnode_conn_count(const struct gnode *n)
{
    return SSG_MAX_PORTS + n->extra_count;
}
static inline const struct gconn *ssg_gnode_conn(const struct gnode *n, int k)
{
    return k < SSG_MAX_PORTS ? &n->in[k] : &n->extra[k - SSG_MAX_PORTS];
}

/* What node n of g reads under its parameters and g's scene (node.h,
   ssg_node_reads_with): the one mask the redo rule, a sequence's held nodes and
   tests/test_camera_deps.c use. */
static inline unsigned ssg_gnode_reads(const struct ssg_graph *g, const struct gnode *n)
{
    return ssg_node_reads_with(n->desc, n->params, g->scene);
}

/* Before frame `frame` of a run (first: the run's first frame; frames: the run's count;
 * live: the graph keeps its run state): puts the frame's camera (from the scene's path)
 * into the scene and the frame, and fills *step. Returns 1 when the camera changed, so
 * the nodes that read it must prepare again (graph_time.c). */
int ssg_time_begin(struct ssg_graph *g, int frame, int first, int frames, int live,
                   struct ssg_time_step *step);
/* After frame `frame` ran: it is the one the next frame follows on from. */
void ssg_time_end(struct ssg_graph *g, int frame);

/* What a graph knows of its nodes between runs (a live graph: ssg_graph_keep) or between
 * the frames of one run (every run has one; a live graph's is kept): per run position,
 * what prepare() made, its scratch, whether it is prepared, whether its outputs are kept
 * and still current, and why not (the reason of the event that cleared them); the pool
 * the images live in. Only graph_redo.c's functions clear `kept`, `prepared` and `consts`
 * for a reason; a run re-runs a node whose outputs are not kept or one of whose producers
 * ran in the frame (ssg_redo_decide). */
struct ssg_live {
    size_t max_bytes;          /* kept images beyond this are evicted, largest first */
    struct ssg_pool *pool;
    void **consts;
    struct ssg_scratch *scratch;
    unsigned char *prepared;
    unsigned char *kept;
    unsigned char *why;        /* enum ssg_why of the first event since the node last ran */
    struct ssg_metric **reported; /* a kept sink's metrics from its last run (count beside):
                                     a compare whose inputs did not change is not run again,
                                     and a run reports them again as this run's */
    int *reported_count;
    unsigned long long *made;  /* per position: the serial of its last run (0 = none yet);
                                  what a reader's ctx->in_made tells (ssg_redo_made) */
    unsigned long long serial; /* the last serial handed out, one a run */
    int count;                 /* run positions */
    int used_gl;               /* a run used GL: images may hold textures */
    struct ssg_gl_shared gl;   /* the scene on GL, uploaded by the first run's first node
                                  that asks and kept while the graph lives: its scene never
                                  changes (whatever replaced it would clear this) */
};
/* The arrays and pool of a state for `count` run positions; 0 on out of memory (what was
   made is then freed by ssg_live_release). */
int ssg_live_init(struct ssg_live *l, int count);
/* Gives back every image the state holds (its nodes' outputs, the history) and frees its
   arrays and pool; GL must be open where a run used it (textures). */
void ssg_live_release(struct ssg_graph *g, struct ssg_live *l);
/* After a live run: evicts the largest kept outputs while they exceed max_bytes
   (graph_live.c). */
void ssg_live_after_run(struct ssg_graph *g, int used_gl);

/* Every node's shapes before a change (ssg_graph_set, ssg_graph_set_lights), malloc'd;
   NULL on out of memory. ssg_redo_moved then makes every node whose shapes the change
   moved redo its history (graph_live.c). */
struct ssg_shapes_saved;
struct ssg_shapes_saved *ssg_shapes_save(const struct ssg_graph *g);
void ssg_redo_moved(struct ssg_graph *g, const struct ssg_shapes_saved *saved);

/* Why a node ran in a frame, or that it was kept (graph_redo.c). When several hold, the
 * first in this order is the one told. */
enum ssg_why {
    SSG_WHY_KEPT,     /* its outputs from before stand */
    SSG_WHY_FIRST,    /* nothing from before: the first run */
    SSG_WHY_SHAPE,    /* its input or output shapes changed */
    SSG_WHY_PARAM,    /* one of its parameters changed */
    SSG_WHY_SUPPLIED, /* the caller supplied a new image */
    SSG_WHY_LIGHTS,   /* the scene's lights changed, and it reads them */
    SSG_WHY_CAMERA,   /* the camera changed, and it reads it */
    SSG_WHY_FRAME,    /* another frame, and it reads the frame index */
    SSG_WHY_HISTORY,  /* it reads prev(): every frame is new to it */
    SSG_WHY_EVICTED,  /* its kept outputs were given back (the live graph's memory bound) */
    SSG_WHY_FAILED,   /* its last run failed */
    SSG_WHY_SEQUENCE, /* a sequence keeps only what no frame of it can change */
    SSG_WHY_INPUT,    /* a producer ran in this frame */
    SSG_WHY_SINK,     /* a sink: its files and metrics are this run's */
    SSG_WHY_NO_FILES, /* a sink that writes files, not run: the run writes none (Python) */
    SSG_WHY_SKIPPED,  /* not run: its outputs are all 0 or unused (graph_skip.h) */
    SSG_WHY_COUNT
};
/* Node p (run position) must redo `level` (enum ssg_recompute: run, prepare, history) of
   its work because of `why`: the one place a node's state is cleared. */
void ssg_redo(struct ssg_graph *g, struct ssg_live *l, int p, unsigned level,
              enum ssg_why why);
/* The same for every node whose reads (node.h, ssg_node_reads) include one of `changed`. */
void ssg_redo_reading(struct ssg_graph *g, struct ssg_live *l, unsigned changed,
                      unsigned level, enum ssg_why why);
/* Why node p runs in this frame, SSG_WHY_KEPT when it does not; ran[] marks the nodes
   (by index) that ran in this frame; *producer the producer that ran (SSG_WHY_INPUT),
   else -1. */
enum ssg_why ssg_redo_decide(const struct ssg_graph *g, const struct ssg_live *l, int p,
                             const unsigned char *ran, int *producer);
/* After node p ran with result e: its outputs are kept when `keep` and it succeeded; they
   get a new serial either way (ssg_redo_made). */
void ssg_redo_after(struct ssg_live *l, int p, int keep, enum ssg_err e);
/* The serial of the run that made the image connection c brings (node.h, ctx.in_made):
   it changes whenever that producer runs again; 0 when c is unconnected, a prev() input
   or its producer has not run. */
unsigned long long ssg_redo_made(const struct ssg_graph *g, const struct ssg_live *l,
                                 const struct gconn *c);
/* "first run", "camera moved"... */
const char *ssg_why_text(enum ssg_why why);
/* One line from the counts of each reason over a run's frames ("first run, kept x3");
   producer names the producer of SSG_WHY_INPUT, NULL = none named. */
void ssg_why_summary(const int *counts, const char *producer, char *buf, size_t len);
/* Frees a live graph's state (opening GL to delete textures where a run used it). */
void ssg_live_free(struct ssg_graph *g);

/* Reads path (and what it includes), builds nodes, applies `set` lines and overrides.
 * Reports every problem; returns the first error code. */
enum ssg_err ssg_graph_build(struct ssg_graph *g, const char *path,
                             const struct ssg_overrides *ov, struct ssg_diags *diags);
/* Parses one file the build reads (graph.c): the top one (top = 1) from g->text when the
 * graph is loaded from text, else from disk (a failure to read it reported at `from`). */
enum ssg_err ssg_graph_read(struct ssg_graph *g, const char *path, struct ssg_loc from, int top,
                            struct ssg_file *file, struct ssg_diags *diags);
/* Checks connections, types, required inputs, cycles and shapes; fills the run order and
 * each output's last reader. Needs g->frame. */
enum ssg_err ssg_graph_validate(struct ssg_graph *g, struct ssg_diags *diags);
/* Shapes again, after a parameter changed (ssg_graph_set): every live node's check() in
 * run order, as validation does. */
enum ssg_err ssg_graph_reinfer(struct ssg_graph *g, struct ssg_diags *diags);
/* Applies "node.param=value" as --set does (messages from source "<ssg_graph_set>"). */
enum ssg_err ssg_graph_apply_set(struct ssg_graph *g, const char *text,
                                 struct ssg_diags *diags);
/* Index of the node with that name, or -1. */
int ssg_graph_find(const struct ssg_graph *g, const char *name, size_t len);
/* Whether output k of node `node` has a current image a kept graph hands out
   (ssg_graph_output): the node live and run, its image kept. */
int ssg_graph_output_kept(const struct ssg_graph *g, int node, int k);
/* Adds node `index` (named) to the name table, growing it to keep it at most half full;
 * 0 when out of memory. */
int ssg_graph_name_add(struct ssg_graph *g, int index);

/* "ssao, hbao, ...": every node type, for a message (graph_names.c). */
void ssg_node_names(char *buf, size_t len);
/* Reports a key that is neither an input nor a parameter of n, listing both; returns the
 * code (SSG_E_UNKNOWN_PARAM). */
enum ssg_err ssg_graph_unknown_key(struct ssg_diags *diags, const struct gnode *n,
                                   const char *key, size_t len, struct ssg_loc loc);
/* Reports a `set` that would add a named input to n (set only changes; `add` adds),
 * listing its inputs and named inputs; returns the code (SSG_E_UNKNOWN_PARAM). */
enum ssg_err ssg_graph_set_adds(struct ssg_diags *diags, const struct gnode *n,
                                const char *key, size_t len, struct ssg_loc loc);

#endif
