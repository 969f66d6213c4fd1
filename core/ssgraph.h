/* ssgraph.h - the public C interface of libssgraph.
 *
 * libssgraph loads a declarative graph of screen-space lighting passes (a `.graph` file),
 * validates it as a whole, and runs its nodes in dependency order on the CPU backend.
 * A user's own program can also run one node on in-memory images (ssg_node_run), which is
 * how nodes are unit-tested.
 *
 * Ownership: every object returned through a `T **` is owned by the caller and released
 * with the matching destroy function, which takes `T **` and sets it to NULL.
 * Images are planar float: channel c of pixel (x, y) is data[(c * height + y) * width + x];
 * row 0 is the top of the picture.
 * Thread safety: separate graphs may be used from separate threads; one graph is used by
 * one thread at a time (its run splits work over OpenMP threads internally).
 * Errors: functions return enum ssg_err and append diagnostics (with file:line:column)
 * to a struct ssg_diags the caller provides.
 * Output: the library prints nothing (bar the describe/docs/diagnostics functions that
 * write to a FILE * the caller gives): a graph run's timings, profile and metrics come back
 * in struct ssg_run_stats, its progress and notices through the callbacks of struct
 * ssg_run_options, and the caller (the ssgraph command line) prints them. */
#ifndef SSGRAPH_H
#define SSGRAPH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

#define SSG_VERSION "0.1.0"

/* Marks the functions of this interface: the only symbols libssgraph.so exports (the
 * library is compiled with -fvisibility=hidden; tests/test_public_api.sh holds the
 * exported set equal to the functions declared with SSG_API). */
#if defined(__GNUC__)
#define SSG_API __attribute__((visibility("default")))
#else
#define SSG_API
#endif

enum ssg_err {
#define X(code, text) code,
#include "errors.def"
#undef X
    SSG_ERR_COUNT
};

/* Short symbolic name ("SSG_E_CYCLE") and general description of an error code. */
SSG_API const char *ssg_err_name(enum ssg_err code);
SSG_API const char *ssg_err_text(enum ssg_err code);

/* One diagnostic. line/column are 1-based; 0 where the message has no location. */
struct ssg_diag {
    enum ssg_err code;
    char file[256];   /* file the problem is in, or "<command line>" */
    int line;         /* 1-based line, 0 if none */
    int column;       /* 1-based column, 0 if none */
    char message[512];/* full message, including what was expected */
};

#define SSG_DIAGS_MAX 32
#define SSG_WARNINGS_MAX 8
/* A list of diagnostics; zero-initialise it. Stores the first SSG_DIAGS_MAX errors, counts
 * all. Warnings (something probably unintended that still runs, such as a scene without
 * any light) are kept apart: they never make a call fail and never count as errors. */
struct ssg_diags {
    int count;                          /* errors stored */
    int total;                          /* errors reported, stored or not */
    struct ssg_diag items[SSG_DIAGS_MAX];
    int warning_count;                  /* warnings stored (the first SSG_WARNINGS_MAX) */
    struct ssg_diag warnings[SSG_WARNINGS_MAX]; /* code: the error it would be */
};

/* Prints every warning as `file:line:column: warning: message`, then every error as
 * `file:line:column: error: message`, one a line. */
SSG_API void ssg_diags_print(const struct ssg_diags *diags, FILE *stream);
/* First error code in the list, or SSG_OK. */
SSG_API enum ssg_err ssg_diags_first(const struct ssg_diags *diags);

/* A planar float image (see the header comment for the layout). */
struct ssg_image {
    int width;     /* pixels */
    int height;    /* pixels */
    int channels;  /* planes, 1..4 */
    float *data;   /* width * height * channels floats, planar */
    struct ssg_gl_image *gpu; /* private to the GL backend: its copy of the pixels, NULL =
                                 none (zero-initialise it) */
};

/* Allocates a zeroed image; NULL for absurd sizes or when out of memory. */
SSG_API struct ssg_image *ssg_image_create(int width, int height, int channels);
SSG_API void ssg_image_destroy(struct ssg_image **image);
static inline float *ssg_image_plane(const struct ssg_image *im, int channel)
{
    return im->data + (size_t)channel * (size_t)im->width * (size_t)im->height;
}

/* Reads an image file (EXR, PNG, HDR, ... through OpenImageIO) into a planar float image.
 * `layer` selects an EXR layer by name ("ao" reads channels "ao.*"); NULL reads the
 * unnamed channels (or all channels when the file has no unnamed ones). */
SSG_API enum ssg_err ssg_image_read(const char *path, const char *layer, struct ssg_image **out,
                                    struct ssg_diags *diags);

/* Reads an image whose values are data, not colour (a normal map): a PNG's stored values
 * scaled to [0, 1], never sRGB-decoded (ssg_image_read decodes sRGB PNGs to linear); an EXR
 * as stored. Any other format is refused (SSG_E_IMAGE, naming the file). */
SSG_API enum ssg_err ssg_image_read_data(const char *path, struct ssg_image **out,
                                         struct ssg_diags *diags);

/* Writes an image as a 32-bit float EXR (1 channel: Y; 2: R,G; 3: R,G,B; 4: R,G,B,A),
 * through a temporary file renamed into place, so a failure leaves no partial file. */
SSG_API enum ssg_err ssg_image_write(const char *path, const struct ssg_image *image,
                                     struct ssg_diags *diags);

/* Creates `dir` and every missing parent (mkdir -p); an existing non-directory is an error. */
SSG_API enum ssg_err ssg_make_dirs(const char *dir, struct ssg_diags *diags);

/* What a screen-space node needs to know about the frame besides its images. */
struct ssg_frame {
    int width, height;  /* pixels of the full-resolution frame */
    float fov_y;        /* vertical field of view, degrees; default SSG_DEFAULT_FOV_Y */
    float near_z;       /* near plane distance, scene units; default SSG_DEFAULT_NEAR */
    float far_z;        /* far plane distance, scene units; default SSG_DEFAULT_FAR */
    uint64_t seed;      /* seed for every pseudo-random choice; default 1 */
    int guard;          /* pixels of guard band rendered beyond every side of the frame with
                           the same camera (graph line `guard G`; default 0): frame-sized
                           images are (width + 2 guard) x (height + 2 guard), so that
                           screen-space nodes see occluders just outside the frame; write
                           and compare crop it (docs/guard_band.md) */
    float jitter_x;     /* this frame's sub-pixel jitter in pixels (graph line `jitter N`, */
    float jitter_y;     /* 0 without one): pixel (x, y) samples the point (x + 0.5 +
                           jitter_x, y + 0.5 + jitter_y) of the unjittered image, on every
                           node (ssg_frame_projection); taau gathers the frames' samples
                           (docs/time.md) */
};

#define SSG_GUARD_MAX 1024 /* pixels of guard band, at most */
#define SSG_JITTER_MAX 1024 /* phases of a `jitter` line, at most */

/* The size of the frame's full-resolution images: the frame and its guard band. */
static inline int ssg_frame_full_width(const struct ssg_frame *f)
{
    return f->width + 2 * f->guard;
}
static inline int ssg_frame_full_height(const struct ssg_frame *f)
{
    return f->height + 2 * f->guard;
}

/* The camera's defaults, written once: a scene's camera() without them, a scene without a
 * camera, a graph without a scene and a single-node run all use these. */
#define SSG_DEFAULT_FOV_Y 45.0f /* degrees */
#define SSG_DEFAULT_NEAR 0.05f  /* scene units */
#define SSG_DEFAULT_FAR 100.0f  /* scene units */
#define SSG_FRAME_DEFAULTS                                                                 \
    ((struct ssg_frame){.fov_y = SSG_DEFAULT_FOV_Y, .near_z = SSG_DEFAULT_NEAR,           \
                        .far_z = SSG_DEFAULT_FAR, .seed = 1})

/* What a run measured (ssg_run_options.stats): everything `ssgraph run` prints and
 * `ssgraph bench` tabulates; the library itself prints nothing.
 *
 * Ownership: ssg_graph_run zeroes *stats first and fills it once every frame has run (also
 * when writing metrics.json then fails, so that a caller can still show what ran); the
 * filled struct owns its arrays and strings until ssg_run_stats_free, which releases them
 * and zeroes it again (freeing a zeroed one is harmless). Strings documented as static
 * live as long as the program. */
struct ssg_run_metric {
    char node[64];  /* node instance that reported it ("cmp") */
    char name[32];  /* metric name ("rmse") */
    double value;   /* may be inf or NaN (the PSNR of identical images) */
};

/* One node of the run order. The last frame's columns are those of the one-frame table;
 * the rest is the profile over the frames. */
struct ssg_run_node {
    char *name;             /* instance name in the graph ("ao"); owned by the stats */
    const char *type;       /* node type ("ssao"); static */
    const char *backend;    /* where it ran, "cpu" or "gl"; static */
    double ms;              /* last frame: wall clock of its run, ms; includes its
                               prepare() when it prepared in that frame (every node of a
                               one-frame run, every sink) */
    double gpu_ms;          /* last frame: the GL timer query around its run, ms; 0 on cpu */
    double transfer_ms;     /* last frame: moving its inputs between CPU and GL, ms */
    int calls;              /* runs: one a frame, a sink's one in the last frame only
                               (one a frame with write sequence=true) */
    double avg_ms;          /* over its calls, prepare excluded */
    double min_ms, max_ms;  /* over its calls, prepare excluded; 0 without calls */
    double median_ms;       /* over its calls, prepare excluded: its steady time, without
                               the first call's one-off costs; 0 without calls */
    double share;           /* avg_ms / frame_avg_ms for a node that ran in every frame of
                               a frame with time, else 0 */
    double gpu_avg_ms;      /* over its calls; 0 on cpu */
    double transfer_avg_ms; /* over its calls */
    double prepare_ms;      /* its last prepare() (a camera path's new camera prepares
                               the nodes that read it again, docs/time.md) */
    double bytes;           /* a run's images: every connected input and output once (the
                               least traffic it can have) */
    double flops;           /* a run's floating-point operations as the node declares them
                               (flops_per_pixel, node.h); -1 = not declared */
    int kept;               /* frames in which it did not run: its outputs from before
                               stood (a live graph's earlier run, a sequence's first frame) */
    char *why;              /* why it ran or was kept, each reason with its count over the
                               frames, first the reasons it ran: "first run", "camera moved
                               x3", "parameter changed", "input g ran", "new frame x4",
                               "kept x3" (docs/development.md); owned by the stats */
};

struct ssg_run_stats {
    int frames;                 /* frames run (options.frames, at least 1) */
    double frame_avg_ms;        /* a frame: its passes' runs and transfers, without the
                                   prepares and the sinks (those run after the last) */
    double frame_min_ms, frame_max_ms;
    double frame_median_ms;     /* the median frame: the steady rate, without the first
                                   frame's one-off costs (fresh memory) that the average
                                   carries */
    double total_ms;            /* wall clock of every frame, prepares and sinks included */
    int width, height;          /* frame size, pixels */
    int threads;                /* OpenMP threads the run used */
    size_t peak_pool_bytes;     /* most bytes of images the run held at once */
    char *gl;                   /* the GL context, "OSMesa: llvmpipe (...)", when a node ran
                                   on GL, else NULL; owned by the stats */
    int node_count;             /* entries of nodes: the run order, every live node */
    struct ssg_run_node *nodes; /* owned by the stats */
    int metric_count;           /* entries of metrics */
    struct ssg_run_metric *metrics; /* as the nodes reported them (a node's together), in
                                       run order; owned by the stats */
};

/* Releases what a run put into *stats and zeroes it; NULL or a zeroed struct: nothing. */
SSG_API void ssg_run_stats_free(struct ssg_run_stats *stats);

/* Progress of a long node (reference_ao and reference_gi report it), for a progress bar. */
struct ssg_progress_event {
    const char *instance; /* node instance ("ref"); valid during the call only */
    const char *type;     /* node type ("reference_ao"); static */
    double fraction;      /* of the node's work done, 0..1, rising within one node run */
    int done;             /* 1 = the node's work is finished: the last event of this node
                             run (fraction 1) */
};

/* Called by ssg_graph_run on the thread that called it (never from a worker thread, never
 * inside a band of rows), while the node runs, each time its whole percentage rises and
 * once with done; the node's other threads go on meanwhile, so keep it short. `event` is
 * valid during the call only. */
typedef void (*ssg_progress_fn)(void *user, const struct ssg_progress_event *event);

/* Called by ssg_graph_run on the thread that called it, for what the library has to say
 * that is neither a statistic nor progress: one line of text without a newline, valid
 * during the call only. Today: each file the run wrote ("wrote out/ssao.exr"), when it
 * was written. */
typedef void (*ssg_log_fn)(void *user, const char *line);

/* Options of a graph run; zero means default. */
struct ssg_run_options {
    const char *out_dir;   /* directory for written files; default "out" */
    int threads;           /* OpenMP threads; 0 = all cores */
    int frames;            /* run the graph this many times (0 = 1): frames of a sequence
                              (docs/time.md); every node prepares once (again when a
                              camera path moves the camera, if it reads the camera), then
                              runs every frame, but sinks (write, compare) only in the
                              last (write sequence=true: in every frame) */
    struct ssg_run_stats *stats; /* filled by the run when not NULL (see its ownership) */
    ssg_progress_fn progress;    /* progress of long nodes; NULL = not reported */
    ssg_log_fn log;              /* the library's notices; NULL = not reported */
    void *user;                  /* passed to progress and log as they are */
    struct ssg_image **outputs;  /* for a graph loaded with ssg_overrides.outputs: one
                                    entry per requested output, in that order, each set to
                                    a new CPU image of the last frame's pixels, owned by
                                    the caller (ssg_image_destroy); all NULL on failure;
                                    NULL = not wanted */
    int no_files;                /* 1 = the sinks that write files (write) do not run:
                                    a live view that looks at the images (ssgraph view)
                                    rather than writing them; metrics sinks (compare) still
                                    do */
};

/* Command-line style overrides applied after the graph file is read. */
struct ssg_overrides {
    const char *scene;       /* scene file path, NULL = the graph's own */
    const char *lights;      /* a scene file of lights only (point_light, directional_light,
                                environment) that replaces the scene's lights and
                                environment, NULL = the graph's `lights` line, else the
                                scene's own */
    int width, height;       /* 0 = the graph's own size */
    int guard_given;         /* 1 = guard replaces the graph's own `guard` line */
    int guard;               /* guard band, pixels (with guard_given) */
    const char *const *sets; /* "node.param=value" strings */
    int set_count;
    int64_t seed;            /* -1 = the graph's own seed */
    const char *backend;     /* "cpu" or "gl": every node runs there (a node without a GL
                                side stays on the CPU); NULL = the graph's and nodes' own */
    float eye_offset;        /* the camera (and its target) moved this far along its right
                                axis, scene units: one eye of a stereo pair; 0 = none */
    const char *const *outputs; /* "node.port" outputs the caller wants back: when given,
                                   only they and what they read are loaded and run, the
                                   graph's own sinks (write, compare) are not, and the run
                                   hands their images to ssg_run_options.outputs; a name
                                   the graph lacks is reported (file "<output>"); NULL =
                                   the sinks decide, as always */
    int output_count;        /* entries of outputs, at most SSG_MAX_OUTPUTS */
    int keep_sinks;          /* with outputs: 1 = the graph's sinks still load and run
                                (and write their files) beside the requested outputs,
                                which are handed out as well (`ssgraph run --show`);
                                0 = the outputs replace the sinks, as described above */
};

/* Most outputs one load may request (ssg_overrides.outputs). */
#define SSG_MAX_OUTPUTS 8

struct ssg_graph;

/* Parses, includes, applies overrides, loads the scene and validates the whole graph.
 * Every problem found goes into diags; on any error *out is NULL. */
SSG_API enum ssg_err ssg_graph_load(const char *path, const struct ssg_overrides *overrides,
                                    struct ssg_graph **out, struct ssg_diags *diags);
/* Same, validating only: does not load the scene's meshes or images. */
SSG_API enum ssg_err ssg_graph_check(const char *path, const struct ssg_overrides *overrides,
                                     struct ssg_diags *diags);
/* Runs every node in dependency order; writes files into options->out_dir. Prints
 * nothing: what it measured goes to options->stats, progress and notices to the
 * callbacks. Metrics that nodes report (compare) are written to <out_dir>/metrics.json. */
SSG_API enum ssg_err ssg_graph_run(struct ssg_graph *graph, const struct ssg_run_options *options,
                                   struct ssg_diags *diags);
SSG_API void ssg_graph_destroy(struct ssg_graph **graph);

/* The value of a number parameter of a loaded graph's node, key "node.param" ("h.bias"),
 * as the graph, its set lines and the overrides left it; *integer (if not NULL) is 1 for an
 * integer parameter, 0 for a decimal. For a caller that searches over parameters (ssgraph
 * tune). Reports, with what was expected: a key without a dot (SSG_E_USAGE), no such node
 * (SSG_E_UNKNOWN_NAME, at the graph file), no such parameter (SSG_E_UNKNOWN_PARAM) or one
 * that is not a number (a bool, a choice, a string, a list: SSG_E_TYPE), both at the node's
 * definition. */
SSG_API enum ssg_err ssg_graph_param(const struct ssg_graph *graph, const char *key, double *value,
                                     int *integer, struct ssg_diags *diags);

/* Live graphs: change a loaded graph and re-run only what the change affects.
 *
 * ssg_graph_keep makes the graph keep its run state from one ssg_graph_run to the next:
 * every node's prepared constants and working memory, and every live node's output images
 * (not only those a sink reads), at most max_bytes of images (0 = no limit; past it the
 * largest node outputs are given back after the run, and those nodes run again next time).
 * A kept graph's one-frame run then skips a node whose outputs are kept and none of whose
 * producers ran; write always runs, and a compare (a sink that only reports metrics) is
 * kept like any node, its metrics reported again in the run's. The run's stats show what
 * ran: a skipped node has calls 0. A run of several frames runs everything.
 *
 * ssg_graph_set changes one parameter, key "node.param", value as written in a graph file
 * ("0.25", "smooth", "true"), with the parsing and checks of --set; it reports errors (an
 * unknown node or parameter, a value out of range, a shape the new value makes impossible)
 * at the node's definition in its graph file ("graphs/x.graph:21:7: error: do.radius=-3:
 * parameter 'radius' ... (node 'do' is defined here)"), and then leaves the graph as it
 * was. It marks the node, and every node whose shapes it changed, to run again, and to
 * prepare again unless the node declares the change needs none (check_params,
 * docs/adding-a-node.md); their readers run again because their producers ran. Whatever the sequence of sets and runs, a run gives
 * the bytes of a fresh load with the final settings (tests/test_live.c).
 *
 * ssg_graph_output hands out a copy of an output's latest image, port "node.port", as a new
 * CPU image the caller destroys; the graph must be kept and have run, and the node be
 * live. The graph is not thread-safe: one call on a graph at a time. */
SSG_API enum ssg_err ssg_graph_keep(struct ssg_graph *graph, size_t max_bytes,
                                    struct ssg_diags *diags);
SSG_API enum ssg_err ssg_graph_set(struct ssg_graph *graph, const char *key, const char *value,
                                   struct ssg_diags *diags);
SSG_API enum ssg_err ssg_graph_output(struct ssg_graph *graph, const char *port,
                                      struct ssg_image **out, struct ssg_diags *diags);

/* Supplies the image of an `input` node (docs/nodes.md): the graph keeps a copy, used by
 * every run until the next supply. The image must have the node's output shape (its type's
 * channels; the frame's size with its guard band unless the node's width and height say
 * otherwise), else SSG_E_SIZE naming both; a node that is not an input is refused. On a
 * kept graph the node and what reads it run again. */
SSG_API enum ssg_err ssg_graph_supply(struct ssg_graph *graph, const char *node,
                              const struct ssg_image *image, struct ssg_diags *diags);

/* The camera of a loaded graph's scene, and a new one for the whole graph (every node that
 * reads the camera sees it: the G-buffer, projections, ray tracers). A camera that cannot
 * be is refused with why (SSG_E_VALUE), as a scene file's would be: a coordinate not
 * finite or past +-1e9 (the scene format's limit: then target - position is a finite
 * float), target = position in float, up parallel to the view or zero, fov_y outside
 * [0.001, 179.999]; a graph without a scene has no camera
 * (SSG_E_SCENE). On a kept graph a new camera makes every node prepare and run again
 * except those that never read it (lightprobe, shadow maps, halton: their descriptor's
 * `reads` leaves out the camera, docs/development.md) whose producers are kept as well. */
struct ssg_view {
    float position[3]; /* world, scene units */
    float target[3];   /* the world point looked at */
    float up[3];       /* world up hint */
    float fov_y;       /* vertical field of view, degrees */
};
SSG_API enum ssg_err ssg_graph_view(const struct ssg_graph *graph, struct ssg_view *out,
                                    struct ssg_diags *diags);
SSG_API enum ssg_err ssg_graph_set_view(struct ssg_graph *graph, const struct ssg_view *view,
                                        struct ssg_diags *diags);

/* Replaces the lights and environment of the graph's scene with those of the scene file
 * `lights` (point_light, directional_light and environment lines only, as --lights and
 * ssg_overrides.lights take), or with the scene file's own where lights is NULL; the
 * geometry and camera stay. Refused, with the graph as it was, when the file does not
 * load (its file:line:column), when the graph reads a light the new set leaves black, or
 * when a node refuses the new lights' shapes; SSG_E_SCENE for a graph without a scene. On
 * a kept graph the nodes that read the lights prepare and run again (direct light, the
 * light and shadow maps, the probe's lights, the G-buffer's lit ports), and their readers
 * after them; the rest are kept. */
SSG_API enum ssg_err ssg_graph_set_lights(struct ssg_graph *graph, const char *lights,
                                          struct ssg_diags *diags);

/* Time (docs/time.md). Frame f of a sequence is at time f / fps (the scene's frame_rate,
 * 30 without one); a scene with a camera path (camera_key lines or an orbit) gives each
 * frame its camera, a scene without one keeps its camera in every frame. A run of N frames
 * (ssg_run_options.frames) runs frames first .. first + N - 1, first = 0 unless
 * ssg_graph_set_frame chose another (a run whose last frame would pass INT_MAX is refused,
 * SSG_E_VALUE, before it runs); nodes see the frame's index, time, the camera of the
 * frame before (prev_camera) and whether history may be reused (history_reset: 0 only
 * when the frame follows on from the frame before without a cut of the path).
 *
 * ssg_graph_camera_at gives frame `frame_index`'s camera (the scene's camera for a scene
 * without a path); SSG_E_SCENE without a scene, SSG_E_VALUE for a negative frame.
 *
 * ssg_graph_set_frame chooses the frame the next run starts at. On a kept graph
 * (ssg_graph_keep) a one-frame run of frame last + 1 follows on from the last frame run
 * (prev_camera its camera, history kept); any other frame is a cut. When the frame's
 * camera differs from the last one, the nodes that read the camera prepare and run again,
 * as after ssg_graph_set_view. A new camera from ssg_graph_set_view is a cut, and
 * one-frame runs keep it (rather than the path's) until the next ssg_graph_set_frame. */
SSG_API enum ssg_err ssg_graph_camera_at(const struct ssg_graph *graph, int frame_index,
                                         struct ssg_view *out, struct ssg_diags *diags);
/* Frame `frame_index`'s sub-pixel jitter (ssg_frame.jitter_x, _y) under the graph's
 * `jitter N` line, 0, 0 without one: what an engine that rasterises its own G-buffer into
 * an `input` graph must offset that frame's projection by (docs/time.md). SSG_E_VALUE for a
 * negative frame. */
SSG_API enum ssg_err ssg_graph_jitter_at(const struct ssg_graph *graph, int frame_index,
                                         float jitter[2], struct ssg_diags *diags);
SSG_API enum ssg_err ssg_graph_set_frame(struct ssg_graph *graph, int frame_index,
                                         struct ssg_diags *diags);

/* Parses and validates a scene file and every file it names (meshes included, so a broken
 * glTF is found), without building the ray-tracing scene. */
SSG_API enum ssg_err ssg_scene_check(const char *path, struct ssg_diags *diags);

/* Writes the Markdown reference of every scene entity and its parameters (docs/scenes.md),
 * from the same tables that parse and validate scene files. */
SSG_API void ssg_scenes_markdown(FILE *stream);

/* One input of a single-node run: an image bound to a named input port. */
struct ssg_binding {
    const char *port;
    const struct ssg_image *image;
};

/* The outputs of a single-node run, in the node's port order, and the metrics it reported
 * (compare's rmse, psnr, ...). */
struct ssg_outputs {
    int count;
    const char *names[8];
    struct ssg_image *images[8];  /* owned; released by ssg_outputs_release */
    int metric_count;
    char metric_names[16][32];
    double metric_values[16];
};
SSG_API void ssg_outputs_release(struct ssg_outputs *outputs);

/* Runs one node alone on in-memory images. `sets` are "param=value" strings, and
 * "backend=gl" runs the node on the GL backend (outputs come back as CPU images), and
 * "frame=N" runs it as frame N of a sequence (default 0; per-frame samples, docs/time.md).
 * The frame gives size and camera; its width/height default to the first input's size.
 * Its fov must lie in [0.001, 179.999] degrees and its planes be finite with near < far
 * (a camera's bounds), else SSG_E_VALUE; zero (or less) means the default. */
SSG_API enum ssg_err ssg_node_run(const char *node, const struct ssg_binding *inputs,
                                  int input_count, const char *const *sets, int set_count,
                                  const struct ssg_frame *frame, struct ssg_outputs *outputs,
                                  struct ssg_diags *diags);

/* The node registry: names, and a full description (ports, parameters, defaults, ranges,
 * units, doc) printed from the node's descriptor table. */
SSG_API int ssg_node_count(void);
SSG_API const char *ssg_node_name(int index);
SSG_API const char *ssg_node_summary(int index);
/* Returns SSG_E_UNKNOWN_NODE when no node has that name. */
SSG_API enum ssg_err ssg_node_describe(const char *node, FILE *stream);
/* Writes the Markdown reference of every node (docs/nodes.md): a glossary of the port
 * types, then each node's ports and parameters. With graphs_dir (NULL: left out), each
 * node also lists the .graph files of that folder and its sub-folders that use it. */
SSG_API void ssg_nodes_markdown(FILE *stream, const char *graphs_dir);

/* The rest of the interface: looking into a graph, files, what the command line needs. */
#include "ssgraph_tools.h"

#ifdef __cplusplus
}
#endif
#endif
