/* node.h - what a node is: one descriptor table (name, method, ports, parameters,
 * prepare and backend entries), exported from nodes/<name>/<name>.c and listed once in
 * nodes/nodes.def.
 *
 * A node never calls threads or GL directly: it sees image views, the constants its
 * prepare() made from the parameters, and ssg_parallel_rows(). Core never names a node.
 *
 * The contract, in the order things happen:
 *   1. check() sees the parameters and the input shapes (from the graph, or from images a
 *      caller binds) and gives the output shapes; every shape rule of the node lives here,
 *      reported with the graph's file:line:column before anything runs.
 *   2. prepare() sees the parameters and those shapes (ctx->in_shape, ctx->out_shape) and
 *      makes the constants both backends read, once.
 *   3. The executor verifies every bound image against the shapes (ssg_node_verify_io;
 *      one message naming node, port, actual and expected shape), then calls run_cpu or
 *      run_gl, which trust them.
 * Ports are arrays indexed by the node's enumerators, SSG_<NODE>_IN_<PORT> and
 * SSG_<NODE>_OUT_<PORT> (SSG_<NODE>_INPUTS and _OUTPUTS count them); parameters are
 * tables of SSG_FIELD_* entries (lang/params.h), type-checked at compile time.
 *
 * Frame conventions every node shares (view space, right-handed, OpenGL style):
 *   the camera looks down -z, x right, y up; `position` is the view-space point, `normal`
 *   the unit view-space normal, `depth` the linear distance along the view axis (-z).
 *   A pixel with no surface (background) has depth 0, position 0 and normal 0.
 *   Pixel (x, y) has its centre at (x + 0.5, y + 0.5); row 0 is the top.
 *   Projection: px = cx + f * x / -z, py = cy - f * y / -z with cx = width/2 + guard,
 *   cy = height/2 + guard (less the frame's jitter, 0 unless the graph has a `jitter`
 *   line), f = (height / 2) / tan(fov_y / 2) (ssg_frame_projection):
 *   frame-sized images hold the frame and its guard band (ssg_frame.guard pixels on
 *   every side, 0 by default), so the frame's own pixels start at (guard, guard). */
#ifndef SSG_NODE_H
#define SSG_NODE_H

#include <math.h>
#include <stddef.h>

#include "lang/params.h"
#include "ssgraph.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

struct ssg_scene;
struct ssg_metrics;
struct ssg_gl_shared;
struct ssg_behind;

#define SSG_FILE_NAME_MAX 256 /* bytes of an output file name, NUL included */

/* Port types. An input port accepts a mask of them; an output produces one (or copies the
 * type of an input, see same_as). */
enum ssg_type {
    SSG_T_SCALAR = 1u << 0,  /* 1 channel, frame sized: depth, occlusion */
    SSG_T_VECTOR = 1u << 1,  /* 3 channels, frame sized: view-space position or normal */
    SSG_T_COLOR = 1u << 2,   /* 3 channels, frame sized: linear RGB */
    SSG_T_KERNEL = 1u << 3,  /* count x 1, 3 channels: sample offsets in the unit hemisphere
                                around +z (tangent space), |s| <= 1 */
    SSG_T_PATTERN = 1u << 4, /* n x n tile, 2 channels: per-pixel rotation (cos, sin); or
                                4: and a per-pixel shift of the sample lengths (offset,
                                index shift; nodes/halton/README.md, "Lengths") */
    SSG_T_LIGHTS = 1u << 5,  /* count x 2, 3 channels: directional lights; row 0 the unit
                                world direction towards light i, row 1 its RGB irradiance on
                                a surface facing it (nodes/common/shadowmap.h) */
    SSG_T_SHADOWMAPS = 1u << 6, /* R x R, one channel per light of a light list: the depth
                                   of the nearest surface below each texel of light i's
                                   orthographic map (nodes/common/shadowmap.h) */
    SSG_T_LIGHTMAPS = 1u << 7, /* R x R, channels per face of the scene's own lights' maps
                                  (depth 1, normal 3, flux 3 a face; nodes/common/lightmap.h) */
};
#define SSG_T_IMAGE (SSG_T_SCALAR | SSG_T_VECTOR | SSG_T_COLOR)

/* "scalar", "vector", "color|scalar", ... into buf. */
void ssg_type_names(unsigned mask, char *buf, size_t len);
/* Name and one-line description of the port type with bit number `bit` (enum ssg_type);
   NULL past the last. */
const char *ssg_type_name(int bit);
const char *ssg_type_doc(int bit);
/* Channels of a frame-sized type (1 or 3); 0 for kernel and pattern. */
int ssg_type_channels(unsigned type);

struct ssg_port_desc {
    const char *name;    /* as written in files: g.position */
    unsigned types;      /* input: accepted types; output: the produced type (one bit) */
    int optional;        /* input only: may stay unconnected */
    const char *same_as; /* output only: takes type and shape of this input port */
    const char *doc;     /* one line */
    int lit;             /* output only: 1 = light of the scene's lights or environment,
                            all black without them (reading it from a scene that has
                            neither is an error at load) */
    int on_demand;       /* output only: 1 = costs extra work that the node skips when
                            nobody reads it: a graph run then binds no image (io->out[i]
                            NULL), and the node must check before writing it */
    const char *gl_name; /* input only: the name ssg_gl_ports binds it as where its own
                            is a GLSL keyword (`in`: "src"); NULL = its name (gl.h) */
    const char *gl_if;   /* NULL, or a define of the node's shader: the shader reads the
                            port only when compiled with it nonzero (gl.h) */
    const char *gl_in;   /* NULL, or the node's shader files that read the port, space-
                            separated: ssg_gl_ports skips it in the others (gl.h) */
};

/* Shape of an image flowing along an edge. */
struct ssg_shape {
    int width, height, channels;
    unsigned type; /* one SSG_T_* bit */
};

/* Everything a node's functions may look at besides images and constants. */
struct ssg_node_ctx {
    const struct ssg_node_desc *desc; /* the node's type; messages name it (desc->name) */
    const char *instance;          /* node name in the graph ("ao") */
    const struct ssg_frame *frame; /* size, camera intrinsics, seed */
    const struct ssg_scene *scene; /* NULL when running without a scene */
    const char *out_dir;           /* where sink nodes write files */
    struct ssg_diags *diags;       /* for errors while running */
    struct ssg_metrics *metrics;   /* where ssg_metric_report goes; NULL = discarded */
    /* The shapes the graph was checked with (ssg_shapes_infer): inputs in port order
       (channels 0 = unconnected), outputs in port order, then the extra inputs. prepare()
       derives its per-resolution constants from them, once, for both backends. Before
       run_cpu or run_gl is called the executor has verified every bound image against
       them (ssg_node_verify_io), so a kernel reads its images without re-checking them. */
    const struct ssg_shape *in_shape;
    const struct ssg_shape *out_shape;
    const struct ssg_shape *extra_shape;
    const struct ssg_run_options *run; /* the graph run's options (its progress callback);
                                          NULL = a single-node run, nothing reported */
    struct ssg_scratch *scratch;   /* the node's working memory, kept between its runs
                                      (ssg_node_scratch); NULL = the thread's */
    const char *graph_path;        /* the graph file as given, for files that record what
                                      made them (write's EXR metadata); NULL = none */
    const char *const *sets;       /* the run's --set overrides as given (set_count) */
    int set_count;
    const void *params;            /* the node's parameters (its table's struct) while
                                      run_cpu or run_gl runs (set by the executor; a GL
                                      pass binds them by the table, gl.h); NULL in check
                                      and prepare, which get them as an argument */
    const void *consts;            /* what prepare() made, likewise while a backend runs
                                      (NULL for a node without consts) */
    const struct ssg_image *supplied; /* a `supplied` node's image from the caller, of
                                         output 0's shape; NULL = none supplied */
    /* Time (docs/time.md). A run of N frames is a sequence: frame_index 0 .. N-1 at
       time_s = frame_index / the scene's frame rate. prev_camera is the camera of the
       frame before (motion vectors reproject through it); it is the current camera in
       the first frame and after a cut. history_reset is 1 when no earlier frame may be
       reused (the first frame, a cut, a new size or a change that invalidates history);
       a node that keeps history then starts afresh. */
    int frame_index;
    double time_s;
    const struct ssg_camera *prev_camera; /* NULL without a scene */
    int history_reset;
    struct ssg_gl_shared *gl_shared; /* what the run's GL nodes share, the scene uploaded
                                        once (core/gl/gl_scene.h), owned by the run
                                        (graph/gl_backend.h); NULL = the executor lends
                                        the node one of its own for the call */
    /* Per input port, the serial of the run that made the image bound there: it changes
       whenever that producer runs again, so a node may keep in its scratch what it
       derives from an input (rsm's VPL list from the light maps) while the serial
       stands. 0 = unknown, derive it again: unconnected, a prev() input, a single-node
       run. NULL = all 0. */
    const unsigned long long *in_made;
    struct ssg_behind *behind; /* a sequence's queue of files written behind its frames
                                  (graph/behind.h): a sink that writes files may hand
                                  them to it with its own copies of what it writes, and
                                  return; NULL = write them now */
};

/* Working memory a node keeps from one run to its next: a separable pass's intermediate
 * image, interleaved records. The runtime owns it: a graph run keeps one block a node for
 * all its frames and frees it at the end, so a frame touches no fresh pages (a fresh page
 * costs a page fault on first write, which on the development VM made a 59 MB scratch
 * buffer cost more than the pass it served). */
struct ssg_scratch {
    void *data;   /* 64-byte aligned */
    size_t bytes;
};
/* At least `bytes` of the node's scratch (contents undefined), valid until the node's next
 * call or the end of its run; NULL on out of memory. A ctx without a slot (a node run by
 * hand: tests, micro-benchmarks) gets the calling thread's, likewise kept for its next
 * run. Call from the node's thread, not inside row bands. */
void *ssg_node_scratch(const struct ssg_node_ctx *ctx, size_t bytes);
/* Frees a slot's block (a runtime that kept one for a node). */
void ssg_scratch_free(struct ssg_scratch *s);

/* Reports a named scalar result of this node (e.g. "rmse"); returned in the run's stats
 * and written to <out>/metrics.json. Call from the node's thread, not inside row bands. */
void ssg_metric_report(const struct ssg_node_ctx *ctx, const char *name, double value);

/* The images of one run: inputs in port order (NULL = unconnected optional), outputs in
 * port order (allocated by the executor to the shape check() gave; NULL for an on_demand
 * output nothing reads), then extra inputs. */
struct ssg_io {
    const struct ssg_image *const *in;
    struct ssg_image *const *out;
    int extra_count;                         /* extra named inputs (write's layers) */
    const char *const *extra_names;
    const struct ssg_image *const *extra_in;
    const unsigned *extra_types;             /* type of each extra input */
};

/* What a parameter change makes a kept graph's node redo (ssg_graph_set; the descriptor's
 * check_params, after vkdt's module check_params). Its readers run again in either case. */
enum ssg_recompute {
    SSG_RECOMPUTE_RUN = 1,     /* run again with the new value; prepare()'s constants stand */
    SSG_RECOMPUTE_PREPARE = 2, /* prepare() and run again: any change of a node without
                                  check_params, and any change that moves a shape */
    SSG_RECOMPUTE_HISTORY = 3, /* prepare, run, and forget the images of its outputs kept
                                  from the frame before (prev() readers start afresh): a
                                  new camera, a moved shape */
};

/* What a node reads besides its inputs and parameters (ssg_node_desc.reads). A change of
 * one of them makes the nodes that read it run again, and their readers after them. */
enum ssg_reads {
    SSG_READS_INPUTS = 1u << 0, /* its inputs and parameters: every declared mask says it */
    SSG_READS_SCENE = 1u << 1,  /* ctx->scene's geometry, materials or environment image: the
                                   graph must have a scene (gbuffer, the light maps) */
    SSG_READS_LIGHTS = 1u << 2, /* the scene's lights and environment, where there is a scene
                                   (ssg_graph_set_lights changes them) */
    SSG_READS_CAMERA = 1u << 3, /* the camera: ctx->frame's fov_y, near_z or far_z,
                                   ssg_frame_projection, ctx->scene->camera or prev_camera,
                                   directly, through a helper or through view-space data it
                                   makes itself (a new view, a camera path's next frame) */
    SSG_READS_FRAME = 1u << 4,  /* ctx->frame_index or time_s: samples that turn every frame
                                   (halton, gtao, ssilvb) */
};
#define SSG_READS_ALL (SSG_READS_INPUTS | SSG_READS_SCENE | SSG_READS_LIGHTS | \
                       SSG_READS_CAMERA | SSG_READS_FRAME)

/* The node's reads, SSG_READS_ALL where the descriptor declares none. */
static inline unsigned ssg_node_reads(const struct ssg_node_desc *desc);
/* A node's reads under its parameters and scene: ssg_node_reads narrowed by the
   descriptor's reads_of, where it has one. */
static inline unsigned ssg_node_reads_with(const struct ssg_node_desc *desc,
                                           const void *params, const struct ssg_scene *scene);

/* 1 when the `size` bytes of two parameter structs differ at most in [offset, offset +
 * len): a check_params's test "only this field changed" (SSG_PARAMS_ONLY_CHANGED). Bytewise
 * is exact here: old_params is a copy of the node's block taken just before a set wrote
 * one field into it, so padding and untouched fields hold the same bytes in both. */
static inline int ssg_params_only_changed(const void *old_params, const void *new_params,
                                          size_t size, size_t offset, size_t len)
{
    const unsigned char *a = old_params, *b = new_params;
    for (size_t i = 0; i < size; i++)
        if ((i < offset || i >= offset + len) && a[i] != b[i])
            return 0;
    return 1;
}
#define SSG_PARAMS_ONLY_CHANGED(type, old_params, new_params, member) \
    ssg_params_only_changed(old_params, new_params, sizeof(type), offsetof(type, member), \
                            sizeof(((const type *)0)->member))

/* How far a node's GL outputs may be from its CPU outputs: |gl - cpu| of each value of
 * every output, on the parity scenes of tests/test_gl_<node>.c (tests/gl_parity.h reads
 * it from the descriptor, so the bound is stated once). Set to a small factor (about 4x)
 * over what those tests measure on llvmpipe, so a slip in one backend that moves the
 * answer by more than rounding fails them (a bound 1000x the measurement let a wrong acos
 * coefficient in gtao's shader pass). {0, 0}: bit-exact, as measured; a driver that rounds
 * otherwise (a GPU's division or sqrt) must then measure and state its own bound. Nodes
 * that rasterise (gbuffer, lightmaps, shadowmaps) state none here: where a texel centre
 * lies on an edge the rasteriser and the CPU may pick either surface, so their tests
 * bound the share of texels that differ and the difference of the rest. */
struct ssg_parity_bound {
    double max;  /* largest |gl - cpu| of one value, in the output's units; 0 = exact */
    double mean; /* mean |gl - cpu| over an output's values */
};

struct ssg_node_desc {
    const char *name;    /* "ssao" */
    const char *summary; /* one line for `ssgraph nodes` */
    const char *method;  /* paper, section and equation implemented */
    const char *doc;     /* a paragraph for `describe` and docs; NULL when the node's folder
                            has a README.md, which then is its doc (ssg_node_doc): the
                            method text lives in one place */
    const struct ssg_port_desc *inputs;
    int input_count;
    const struct ssg_port_desc *outputs;
    int output_count;
    int extra_inputs;    /* 1 = accepts further key=port arguments as named inputs */
    int extra_same_size; /* 1 = every extra input must have input 0's width and height
                            (checked with the graph, before anything runs) */
    struct ssg_param_table params;
    size_t params_size;  /* sizeof the params struct */
    size_t consts_size;  /* sizeof what prepare() writes; 0 = none */
    /* Optional, instead of consts_size: the bytes prepare() writes for these parameters
       and input shapes, for constants whose tables grow with a parameter (hbao's per-
       direction steps): a struct ending in a flexible array, sized to what is used. */
    size_t (*consts_size_of)(const void *params, const struct ssg_shape *in);
    /* Optional: the rows of the constants both backends read by name (made in prepare()
       into a struct generated from the rows, a member of the consts at uniforms_offset;
       a shader with `#pragma ssg_consts` gets them as uniforms, bound by the pass).
       SSG_NODE_UNIFORMS fills both. */
    struct ssg_param_table uniforms;
    size_t uniforms_offset;
    /* What the node reads besides its inputs and parameters (enum ssg_reads): the one
       rule for what runs again (core/graph/graph_redo.c). A live graph's node, or one in
       a sequence of frames, runs again when something it reads changed or one of its
       producers ran; else its outputs from before stand. 0 = not declared: everything
       (SSG_READS_ALL), the safe set, since the two mistakes differ: a node that reads
       less than it says only runs more often (slower), one that reads more than it says
       shows a stale image, which no ordinary run or parity test sees.
       tests/test_camera_deps.c runs every node that leaves out SSG_READS_CAMERA at two
       cameras, and every one that leaves out SSG_READS_LIGHTS under two light sets, and
       requires the same bytes. */
    unsigned reads;
    /* Optional: the reads of a node under these parameters and scene (NULL: none loaded),
       a subset of .reads, where they decide whether it reads something (lightmaps reads
       the camera only with fit=view and a directional light); NULL = .reads. What runs
       again and what a sequence holds follow it (ssg_node_reads_with). */
    unsigned (*reads_of)(const void *params, const struct ssg_scene *scene);
    /* The names of every metric the node may report (ssg_metric_report), NULL-terminated;
       NULL = none. What `bench --error NODE.METRIC` is checked against before any run. */
    const char *const *metrics;
    /* Optional, skipping work nothing uses (core/graph/graph_skip.c): per output, the input
       it is zero with: the output is all +0 wherever that input is all +0 or unconnected
       (a filter's out from in, out2 from in2), whatever the other inputs; that input feeds
       no other output. A negative entry (or NULL) = no such input. The array has
       output_count entries. */
    const signed char *zero_with;
    /* Optional: the outputs (bit k = output k) that are all +0 for these inputs, asked
       before a run; bit i of `connected` says input i is connected, and in[i] is its
       image where it is already made on the CPU, else NULL: the answer may use only what
       is there (probe_light: every light carries nothing). */
    unsigned (*zero_outputs)(const void *params, const struct ssg_image *const *in,
                             unsigned connected);
    /* Optional: the inputs (bit i = input i) whose pixels cannot change any output byte
       while the inputs in `zero_in` are all +0 (combine: far_visibility, while the
       environment is 0 and nothing else reads V). */
    unsigned (*ignored_inputs)(const void *params, unsigned zero_in);
    int is_sink;         /* 1 = always runs (writes files or reports metrics); the
                            runtime keeps what it reads and prunes what no sink reads */
    int supplied;        /* 1 = a source whose image the caller supplies
                            (ssg_graph_supply): the executor hands it to the node as
                            ctx->supplied, which must match output 0's shape */

    /* Optional. Cross-parameter checks and output shapes. `out` arrives filled with the
       default shapes (frame size, type channels, or same_as); a node with kernel or pattern
       outputs sets them here. Return SSG_OK or an error code with a message in why. */
    enum ssg_err (*check)(const void *params, const struct ssg_frame *frame,
                          const struct ssg_shape *in, struct ssg_shape *out, char *why,
                          size_t why_len);
    /* Optional, a node reading the scene whose output shapes depend on the scene (lightmaps:
       one face a directional light, six a point light): called after check() with the
       loaded scene when the graph is checked, with the input shapes: may change the
       channels of `out`, refuses what the scene makes too large and inputs that do not
       fit the scene (direct_light: maps of another scene's lights). Runs without a graph
       (tests) bind images of the right shape themselves. Return SSG_OK or an error code
       with why; SSG_OK with a why is a warning, shown at the node's definition (combine:
       an ambient_occlusion that darkens nothing). */
    enum ssg_err (*check_scene)(const void *params, const struct ssg_scene *scene,
                                const struct ssg_shape *in, struct ssg_shape *out,
                                char *why, size_t why_len);
    /* Optional, sinks that write files: the names of the files the node writes into the
       output folder under these parameters in frame `frame_index` (write: <name>.exr,
       <name>.png; with sequence=true <name>_0003.exr...), at most `max` names of
       SSG_FILE_NAME_MAX bytes; returns how many. Two live nodes that would write one file
       (in frame 0) are refused when the graph is checked: the second would silently
       replace the first's. */
    int (*output_files)(const void *params, int frame_index, char (*files)[SSG_FILE_NAME_MAX],
                        int max);
    /* Optional, sinks: 1 when under these parameters the sink runs in every frame of a run
       (write sequence=true: one set of files a frame); NULL or 0 = in the last frame
       only, as every sink does by default. */
    int (*every_frame)(const void *params);
    /* Optional. Turns parameters and the checked shapes (ctx->in_shape, ctx->out_shape)
       into the constants both backends read: sample kernels, the projection of the
       inputs' resolution, per-column or per-count tables. Called once before the first
       run; both backends read these same bytes, so what depends only on parameters and
       shapes is computed here and never twice. Returns SSG_OK or ssg_node_fail(...). */
    enum ssg_err (*prepare)(const struct ssg_node_ctx *ctx, const void *params, void *consts);
    /* Optional (vkdt's check_params): what a change of the parameters from old_params to
       new_params (one ssg_graph_set on a kept graph) requires of this node, an enum
       ssg_recompute. SSG_RECOMPUTE_RUN only when every changed parameter is read by
       run_cpu and run_gl from ctx->params alone (on GL: a row bound as p_<field>, not
       host_only), never by check, prepare or from a copy in the consts: the run then
       sees the new value with the old constants. NULL = any change prepares again, the
       safe default; worth declaring where prepare() is costly. */
    unsigned (*check_params)(const void *old_params, const void *new_params);
    /* Optional. Floating-point operations one run does per pixel of output 0 (a multiply,
       an add, a compare-and-select each count 1; a division or square root 1; the
       polynomial exp and log as their operations), from the parameters and the input
       shapes (the kernel's width): the profile divides by the run's time for GFLOP/s and
       sets it against the machine's peak (bench/peak). An estimate by reading the
       kernel's inner loop, stated where it is defined; NULL = not declared. */
    double (*flops_per_pixel)(const void *consts, const struct ssg_shape *in);
    /* The CPU backend. `consts` is what prepare wrote, or the params when consts_size is 0.
       Every bound image has the shape check() gave (the executor verified it), so the
       kernel neither checks shapes nor fails on them; its errors are run-time ones (out
       of memory, a file it cannot write). */
    enum ssg_err (*run_cpu)(const struct ssg_node_ctx *ctx, const void *consts,
                            const struct ssg_io *io);
    /* The GL backend (nodes/<name>/<name>_gl.c, through core/gl/gl.h only), NULL = CPU only.
       Same contract as run_cpu: the runtime has made every input and output image a GL
       texture (io->in[i]->data must not be read), the same consts; it must write every
       output pixel. The CPU result is the reference; `parity` below states how far
       this one may be from it. */
    enum ssg_err (*run_gl)(const struct ssg_node_ctx *ctx, const void *consts,
                           const struct ssg_io *io);
    /* How far run_gl's outputs may be from run_cpu's (struct ssg_parity_bound; the tests
       read it). Zero = bit-exact; no effect on any output. */
    struct ssg_parity_bound parity;
};

/* The registry, built from nodes/nodes.def. NULL when unknown. */
const struct ssg_node_desc *ssg_node_find(const char *name, size_t len);
/* The registry's index-th node (0 .. ssg_node_count() - 1), else NULL. */
const struct ssg_node_desc *ssg_node_at(int index);
/* A node's method text in one place: nodes/<name>/README.md (a second node in a folder:
 * nodes/<folder>/<name>.md), embedded by the build (cmake/embed_files.cmake) into
 * ssg_node_readmes[] (terminated by {NULL, NULL}), else the descriptor's doc. */
struct ssg_node_readme {
    const char *node; /* the folder's name, "ssao" */
    const char *text; /* README.md */
};
extern const struct ssg_node_readme ssg_node_readmes[];
/* The README.md of the node's folder (its first line, the `# title`, left out), or doc;
 * *len is its length without trailing newlines (print it with "%.*s"). */
const char *ssg_node_doc(const struct ssg_node_desc *d, int *len);
/* The README.md of a node folder by name (whole text), or NULL. */
const char *ssg_node_readme(const char *node);

/* "cpu, gl" or "cpu only". */
const char *ssg_node_backends(const struct ssg_node_desc *d);
int ssg_port_find(const struct ssg_port_desc *ports, int count, const char *name, size_t len);

/* Runs fn over fixed bands of `rows_per_band` rows, in parallel (OpenMP). The bands do not
 * depend on the thread count, so a node whose pixels depend only on its band is
 * deterministic whatever the threads. fn(user, y0, y1) covers rows [y0, y1). */
typedef void (*ssg_rows_fn)(void *user, int y0, int y1);
void ssg_parallel_rows(int height, int rows_per_band, ssg_rows_fn fn, void *user);

/* ssg_parallel_rows for a node long enough to show its progress (reference_ao): the same
 * bands, counted as they finish by whichever thread ran them; only the node's own thread
 * (the caller) reports, between its bands, through the run's progress callback
 * (ssgraph.h), then once with done after the last band. Without a callback (ctx->run NULL
 * or its progress NULL) it is ssg_parallel_rows. Nothing a node computes depends on it. */
void ssg_parallel_rows_progress(const struct ssg_node_ctx *ctx, int height, int rows_per_band,
                                ssg_rows_fn fn, void *user);

/* Camera intrinsics of the frame in the form the projection above uses. */
struct ssg_projection {
    float f;       /* focal length in pixels */
    float cx, cy;  /* principal point in pixels */
};
/* A projection as a row of constants (lang/params.h): kind PROJECTION, stored as the struct
   and read by a shader as `vec3 name` = (f, cx, cy), the three floats in their order. */
#define SSG_PARAM_DECL_PROJECTION(f) struct ssg_projection f
#define SSG_FIELD_PROJECTION(owner, field) \
    .type = SSG_P_VEC3, .offset = SSG_FIELD_OFFSET(owner, field, struct ssg_projection *)
_Static_assert(sizeof(struct ssg_projection) == 3 * sizeof(float) &&
                   offsetof(struct ssg_projection, cy) == 2 * sizeof(float),
               "a projection row is bound as three consecutive floats");
static inline struct ssg_projection ssg_frame_projection(const struct ssg_frame *frame)
{
    struct ssg_projection p;
    p.f = 0.5f * (float)frame->height / tanf(0.5f * frame->fov_y * (float)M_PI / 180.0f);
    /* jitter: the image moves by -jitter, so that pixel x's centre x + 0.5 looks through
       x + 0.5 + jitter of the unjittered image (0 without a `jitter` line: the same floats) */
    p.cx = 0.5f * (float)frame->width + (float)frame->guard - frame->jitter_x;
    p.cy = 0.5f * (float)frame->height + (float)frame->guard - frame->jitter_y;
    return p;
}

/* The projection `p` of a frame_w x frame_h frame as seen by an image of w x h pixels.
 * An image subsampled by an integer k the way `downsample` does it (ceil(frame / k) on
 * both axes) gets the frame's projection divided by k, so that its pixel X covers the
 * frame's pixels [kX, kX + k) exactly, odd frame sizes included; any other size scales
 * each axis by its size ratio. */
static inline struct ssg_projection ssg_projection_scaled(const struct ssg_projection *p,
                                                          int frame_w, int frame_h, int w,
                                                          int h)
{
    struct ssg_projection q = *p;
    if (w == frame_w && h == frame_h)
        return q;
    int k = w > 0 ? (frame_w + w - 1) / w : 1;
    if (k > 1 && (frame_w + k - 1) / k == w && (frame_h + k - 1) / k == h) {
        q.f = p->f / (float)k;
        q.cx = p->cx / (float)k;
        q.cy = p->cy / (float)k;
        return q;
    }
    q.f = p->f * (float)h / (float)frame_h;
    q.cx = p->cx * (float)w / (float)frame_w;
    q.cy = p->cy * (float)h / (float)frame_h;
    return q;
}

/* The frame's own pixels within an image of `shape`: [x0, x1) x [y0, y1). An image of
 * the full size (ssg_frame_full_width) has the guard band cut off; any other image
 * (subsampled, a kernel, a hand-bound input) is all frame. Sinks (write, compare) use it
 * so that a guard band never reaches a file or a metric. */
static inline void ssg_frame_region(const struct ssg_frame *frame,
                                    const struct ssg_shape *shape, int *x0, int *y0, int *x1,
                                    int *y1)
{
    int g = frame->guard;
    if (g > 0 && shape->width == ssg_frame_full_width(frame) &&
        shape->height == ssg_frame_full_height(frame)) {
        *x0 = g, *y0 = g, *x1 = g + frame->width, *y1 = g + frame->height;
    } else {
        *x0 = 0, *y0 = 0, *x1 = shape->width, *y1 = shape->height;
    }
}

/* Reports a node's run-time error (out of memory, a file it cannot write, a scene it
 * needs) as "<node> '<instance>': <what>", what formatted like printf, and returns code.
 * No file location: graph-level problems were reported with one before the run. Shapes
 * are never a run-time error of a node: check() refuses them before anything runs and
 * the executor verifies the images against them. */
enum ssg_err ssg_node_fail(const struct ssg_node_ctx *ctx, enum ssg_err code, const char *fmt,
                           ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* 1 when two shapes have the same width and height. */
static inline int ssg_shape_same_size(const struct ssg_shape *a, const struct ssg_shape *b)
{
    return a->width == b->width && a->height == b->height;
}

/* Convenience for node files. */
#define SSG_COUNT(arr) ((int)(sizeof(arr) / sizeof((arr)[0])))
/* Descriptor fields from a node's port arrays and parameter table (each array with its
   length, so a count cannot drift from its array). */
#define SSG_NODE_INPUTS(in) .inputs = (in), .input_count = SSG_COUNT(in)
#define SSG_NODE_OUTPUTS(out) .outputs = (out), .output_count = SSG_COUNT(out)
#define SSG_NODE_PORTS(in, out) SSG_NODE_INPUTS(in), SSG_NODE_OUTPUTS(out)
#define SSG_NODE_PARAMS(table, params_type) \
    .params = SSG_TABLE(table), .params_size = sizeof(params_type)

/* The constants' rows (lang/params.h, SSG_UNIFORMS_TABLE) and where their struct sits in
   the consts. */
#define SSG_NODE_UNIFORMS(table, consts_type, member) \
    .uniforms = SSG_TABLE(table), .uniforms_offset = offsetof(consts_type, member)

/* One-line port rows, as parameters have (lang/params.h): a node lists each port once,
 * with its enumerator, name, types, one-line doc and any further fields,
 *   #define SSG_SSAO_IN(X)                                                          \
 *       X(SSG_SSAO_IN_POSITION, "position", SSG_T_VECTOR, "view-space position")     \
 *       X(SSG_SSAO_IN_NORMAL, "normal", SSG_T_VECTOR, "unit normal", .optional = 1)
 *   SSG_PORT_ENUM(ssg_ssao_input, SSG_SSAO_IN, SSG_SSAO_INPUTS);   (in the header)
 *   SSG_PORT_TABLE(inputs, SSG_SSAO_IN);                           (in the .c file)
 * The enum gets the enumerators in order and the count last; the table one entry each,
 * indexed by its enumerator, so the two cannot drift apart. */
#define SSG_PORT_AS_ENUMERATOR(id, ...) id,
#define SSG_PORT_AS_ROW(id, port, type_mask, text, ...) \
    [id] = {.name = port, .types = type_mask, .doc = text, __VA_ARGS__},
#define SSG_PORT_ENUM(tag, LIST, count) enum tag { LIST(SSG_PORT_AS_ENUMERATOR) count }
#define SSG_PORT_TABLE(var, LIST) static const struct ssg_port_desc var[] = {LIST(SSG_PORT_AS_ROW)}

static inline unsigned ssg_node_reads(const struct ssg_node_desc *desc)
{
    return desc->reads ? desc->reads : SSG_READS_ALL;
}

static inline unsigned ssg_node_reads_with(const struct ssg_node_desc *desc,
                                           const void *params, const struct ssg_scene *scene)
{
    unsigned all = ssg_node_reads(desc);
    return desc->reads_of && params ? all & desc->reads_of(params, scene) : all;
}

#endif
