/* ssgraph_tools.h - the second half of the public interface, included by ssgraph.h (include
 * that, never this alone): looking into a graph, files, stereo runs, the machine, scene and
 * model summaries, and looking at images. Split from ssgraph.h only to keep each file
 * readable; every function here is SSG_API too (tests/test_public_api.sh reads both). */
#ifndef SSG_SSGRAPH_TOOLS_H
#define SSG_SSGRAPH_TOOLS_H

#include "ssgraph.h"

#ifdef __cplusplus
extern "C" {
#endif
/* ======== Looking into a graph; files; what the command line needs ========
 * Everything the ssgraph command line uses of the library is declared in this header: no
 * file of cli/ includes another header of core/ (tests/test_public_api.sh holds it). */

/* ---- A graph's structure and current values (ssgraph dot, -v, bench's reference key) */

/* Reads a graph file (its includes and set lines) and builds its nodes without checking
 * the graph as a whole or loading its scene: for looking at its structure. Unlike
 * ssg_graph_load, *out is the graph as far as it could be built even when diags has errors
 * (a node of an unknown type then has type NULL): NULL only when out of memory. Returns
 * the first error. Release it with ssg_graph_destroy; do not run it. */
SSG_API enum ssg_err ssg_graph_parse(const char *path, struct ssg_graph **out,
                                     struct ssg_diags *diags);

/* What a graph resolved; the strings belong to the graph. */
struct ssg_graph_info {
    const char *path;       /* the graph file as given */
    const char *scene;      /* the scene file it uses, resolved; "" = none */
    const char *lights;     /* the lights file replacing the scene's lights; "" = none */
    struct ssg_frame frame; /* size, lens, seed and guard as the graph and overrides left
                               them (a loaded graph's; only partly set by ssg_graph_parse) */
    int node_count;         /* nodes, in file order (an include's where it stands) */
    int run_count;          /* live nodes in run order (ssg_graph_run_node); 0 for a graph
                               that was only parsed */
};
SSG_API void ssg_graph_inspect(const struct ssg_graph *graph, struct ssg_graph_info *info);

/* One node of a graph; the strings belong to the graph (type and backend are static). */
struct ssg_node_info {
    const char *name;    /* instance name ("ao"; "write_1" when anonymous) */
    const char *type;    /* node type ("ssao"); NULL when the file names an unknown one */
    const char *backend; /* where it runs, "cpu" or "gl" once loaded ("default" before) */
    int param_count;     /* parameters of its type (ssg_graph_node_param) */
};
/* Node `index` in file order (0 .. node_count - 1): SSG_OK, or SSG_E_USAGE out of range. */
SSG_API enum ssg_err ssg_graph_node_inspect(const struct ssg_graph *graph, int index,
                                            struct ssg_node_info *info);
/* The file-order index of the node at run position `position` (0 .. run_count - 1), or
 * -1 out of range. */
SSG_API int ssg_graph_run_node(const struct ssg_graph *graph, int position);
/* The file-order index of the node with that instance name, or -1. */
SSG_API int ssg_graph_node_index(const struct ssg_graph *graph, const char *name);
/* Parameter k (0 .. param_count - 1) of node `index`: returns its name (static) and writes
 * its current value into value as -v prints it ("0.5", "true", "smooth"); NULL (value
 * "") out of range. */
SSG_API const char *ssg_graph_node_param(const struct ssg_graph *graph, int index, int k,
                                         char *value, size_t len);
/* Writes the graph as Graphviz DOT: a node per instance labelled with its name and type,
 * an edge per connection labelled "output -> input" (the producer's port, the consumer's
 * input or layer). */
SSG_API void ssg_graph_dot(const struct ssg_graph *graph, FILE *stream);

/* The type of parameter `param` of node type `node` as `ssgraph describe` names it
 * ("float", "int", "bool", "enum", "string", "vec3", "int list", "name"); NULL when there
 * is no such node or parameter. */
SSG_API const char *ssg_node_param_type(const char *node, const char *param);
/* Metric k (0, 1, ...) that node type `node` may report (compare: "rmse", "mae", ...), from
 * its descriptor; NULL past the last, or for a node that reports none or is unknown. */
SSG_API const char *ssg_node_metric(const char *node, int k);

/* ---- Descriptors of parameters and ports, for a generated interface (ssgraph view) */

/* Parameter k (0 .. param count - 1) of node type `node`, from the table that parses it;
 * strings are static. */
struct ssg_param_info {
    const char *name;           /* "radius" */
    const char *type;           /* as ssg_node_param_type names it */
    const char *unit;           /* "scene units", "px", ...; NULL = none */
    const char *doc;            /* one line */
    int bounded;                /* 1 = min and max hold (number, vec3 or int-list values) */
    double min, max;            /* inclusive */
    const char *const *choices; /* an enum's names, NULL-terminated; NULL otherwise */
    double soft_min, soft_max;  /* a number's useful range, what a slider spans (inside min
                                   .. max, around the default); min, max where the row
                                   gives none; both 0 for an unbounded one without */
};
/* SSG_E_UNKNOWN_NODE without such a node type, SSG_E_USAGE with k out of range. */
SSG_API enum ssg_err ssg_node_param_info(const char *node, int k, struct ssg_param_info *info);

/* Port k of a graph's node `index`: its inputs (declared ports, then extra named inputs),
 * then its outputs. Strings are static or the graph's, except from. */
struct ssg_port_info {
    const char *name;   /* "position" */
    const char *type;   /* port type ("scalar"; docs/nodes.md); "" when not one type yet
                           (an input's accepted set, or an output shaped like an input of a
                           graph that was only parsed) */
    const char *doc;    /* one line */
    int output;         /* 1 = an output */
    int optional;       /* input: may stay unconnected */
    int channels;       /* an output's channels (0 when not known yet) */
    int width, height;  /* an output's size on a loaded graph (0 before) */
    char from[128];     /* input: the producer's "node.port" as written; "" = unconnected */
    int has_image;      /* output: a kept graph (ssg_graph_keep) holds its latest image, so
                           ssg_graph_output hands it out; 0 before a run, for a node that is
                           not live, and for an on-demand output nothing read */
};
/* How many ports node `index` has (0 out of range or for an unknown type). */
SSG_API int ssg_graph_port_count(const struct ssg_graph *graph, int index);
/* SSG_E_USAGE with index or k out of range. */
SSG_API enum ssg_err ssg_graph_port_inspect(const struct ssg_graph *graph, int index, int k,
                                            struct ssg_port_info *info);

/* Port k of node type `node` (no graph needed: a menu of types to add): its inputs, then
 * its outputs. Strings are static. */
struct ssg_type_port {
    const char *name; /* "position" */
    const char *doc;  /* one line */
    int output;       /* 1 = an output */
    int optional;     /* input: may stay unconnected */
    char types[96];   /* the port types it takes (an input) or makes, "color|scalar" */
};
/* How many ports node type `node` has (0 for an unknown type). */
SSG_API int ssg_node_port_count(const char *node);
/* SSG_E_UNKNOWN_NODE without such a type, SSG_E_USAGE with k out of range or info NULL. */
SSG_API enum ssg_err ssg_node_port_info(const char *node, int k, struct ssg_type_port *info);

/* ---- Editing a graph file's text (`ssgraph view`'s editor, graph_edit.c) */

/* The largest graph file the parser reads, in bytes (a text to edit is read with it). */
#define SSG_GRAPH_FILE_MAX_BYTES (16 * 1024 * 1024)

/* ssg_graph_load with the top file's text given: `text` stands for the file at `path`
 * (messages name path and the line of text; includes and the scene resolve against
 * path's folder, and included files are read from disk). */
SSG_API enum ssg_err ssg_graph_load_text(const char *path, const char *text,
                                         const struct ssg_overrides *overrides,
                                         struct ssg_graph **out, struct ssg_diags *diags);
/* Applies `edits`, graph statements one a line, to the graph file text `text` (of the file
 * `path`, for messages) the way a person would edit it, into *out (malloc'd; NULL on an
 * error): `NAME = TYPE(args)` appends a node; `set NAME.KEY = VALUE` changes the argument
 * where it is written (the file's last set line of it, else the call's argument, keyed or
 * positional, else adds KEY=VALUE to the call; a node the file does not define gets the
 * set line); `add NAME.LAYER = NODE.PORT` appends that line; `remove NAME` deletes the
 * node's call and set lines (whole lines, with their comments), refused with each reader's
 * file:line:column when another statement reads it. Every other byte stays as it was. The
 * result is not checked: load it (ssg_graph_load_text) for that. Errors: a syntax error in
 * the edits (file "<edit>") or in the text, an unknown edit, a node to remove that the
 * text does not define, readers. */
SSG_API enum ssg_err ssg_graph_text_edit(const char *path, const char *text, const char *edits,
                                         char **out, struct ssg_diags *diags);

/* ---- Files: read within limits, written whole or not at all (the rules: lang/files.h) */

/* Reads a whole regular file of at most max_bytes into malloc'd memory with a NUL after
 * the last byte; *len excludes it. SSG_E_IO (cannot open, not a regular file) or SSG_E_SIZE
 * (too large) with the reason in why, e.g. "not a regular file (it is a FIFO)". */
SSG_API enum ssg_err ssg_input_read(const char *path, long long max_bytes, char **data,
                                    size_t *len, char *why, size_t why_len);

#define SSG_TMP_MAX 64 /* temporaries registered at once, at most (more is an error) */

/* One output being written: the temporary (open as fd until ssg_tmp_close) and its
 * target. */
struct ssg_tmp {
    char path[4352];  /* the temporary: <dir>/.<stem>.tmp-<pid>-<n><ext> */
    char target[4096];
    int fd;           /* -1 once closed */
    int lock_fd;      /* holds the temporary's lock until commit or discard, -1 = none */
    int slot;         /* registry slot, -1 = none */
};

/* Creates the temporary of `target` (ext: its extension with the dot, which OpenImageIO
 * reads to pick the format; "" for none; `what` names the content in messages, "image"),
 * registered for removal on a signal. Also removes temporaries of dead processes in that
 * folder. An existing target that is not a regular file (a device, FIFO, socket or
 * directory) is refused with SSG_E_IO: the rename would replace it. */
SSG_API enum ssg_err ssg_tmp_create(const char *target, const char *ext, const char *what,
                                    struct ssg_tmp *t, struct ssg_diags *diags);
/* Flushes, syncs and closes t's descriptor: SSG_OK only if every byte reached the disk. */
SSG_API enum ssg_err ssg_tmp_close(struct ssg_tmp *t, struct ssg_diags *diags);
/* Renames every closed temporary over its target, in order; on any failure the rest are
 * discarded. */
SSG_API enum ssg_err ssg_tmp_commit(struct ssg_tmp *t, int count, struct ssg_diags *diags);
/* Removes the temporaries (closing them first) and unregisters them. */
SSG_API void ssg_tmp_discard(struct ssg_tmp *t, int count);
/* Async-signal-safe: unlinks every registered temporary. For a signal handler. */
SSG_API void ssg_tmp_remove_all(void);
/* Installs handlers for SIGINT, SIGTERM, SIGHUP and SIGPIPE that remove the temporaries,
 * then die of the same signal. For programs (the CLI); a library user keeps its own. */
SSG_API void ssg_tmp_remove_on_signals(void);

/* Whether path can take an output, checked without opening it (nothing blocks): SSG_OK
 * when it is a new name or a regular file in a folder this process can create files in,
 * and with `streams` also when it is a character device or a FIFO (what
 * ssg_write_text_stream writes into); else SSG_E_IO naming what it is (a directory, a
 * FIFO, ...) or what is wrong with its folder (`what` names the content: "profile"). For
 * checking an output before any work; every writer above checks again. */
SSG_API enum ssg_err ssg_output_check(const char *path, const char *what, int streams,
                                      struct ssg_diags *diags);

/* Writes a text file whole or not at all through a temporary (above): fill() writes into
 * it. `what` names the content in error messages ("metrics", "bench table"). For the files
 * the program names (in an output folder, a cache): an existing target that is not a
 * regular file (a FIFO, a device, a directory, a socket) is refused without being opened,
 * as by ssg_tmp_create for every output, so a FIFO planted there never blocks a run. */
SSG_API enum ssg_err ssg_write_text_file(const char *path, const char *what,
                                         void (*fill)(FILE *f, const void *user),
                                         const void *user, struct ssg_diags *diags);
/* ssg_write_text_file for a file the user names (--profile-json, dot -o): a path naming a
 * character device or a FIFO (/dev/stdout, a named pipe a script reads) is written into
 * as a stream, never replaced (opening a FIFO waits for its reader). */
SSG_API enum ssg_err ssg_write_text_stream(const char *path, const char *what,
                                           void (*fill)(FILE *f, const void *user),
                                           const void *user, struct ssg_diags *diags);

/* ---- Stereo runs (`ssgraph run --stereo`): each eye's graph run writes into a folder of
 * its own, then ssg_stereo_join makes one multi-view EXR of each EXR the eyes share (the
 * first view the default one, the others' channels named layer.VIEW.channel) and moves
 * every other file, the PNG previews among them, next to it as STEM_VIEW.EXT
 * (ssao_left.png, ssao_right.png). The eye folders are removed at the end either way
 * (ssg_stereo_discard), and a killed run's by the next stereo run into the same folder
 * (ssg_stereo_sweep). Touches only the folders it is given. */

/* dirs[k] holds view views[k]'s files (count views, the first the default); the results go
 * to out_dir, which is created if missing, each announced to log ("wrote out/ssao.exr";
 * NULL = not). Every problem goes to diags. */
SSG_API enum ssg_err ssg_stereo_join(const char *out_dir, const char *const *dirs,
                                     const char *const *views, int count, ssg_log_fn log,
                                     void *user, struct ssg_diags *diags);
/* Removes the plain files in each of the count folders, then the folders (a failed run's
 * leftovers); a missing folder is no error. */
SSG_API void ssg_stereo_discard(const char *const *dirs, int count);
/* Removes the eye folders (".stereo-VIEW-PID") in out_dir that a killed stereo run left:
 * those whose process is gone. Called by each stereo run before it starts. */
SSG_API void ssg_stereo_sweep(const char *out_dir);

/* The camera a file records, for a node run on it (`ssgraph node`): the fov, near and far
 * of an ssgraph EXR into frame->fov_y, near_z, far_z. spec is FILE or FILE:LAYER (the
 * `--in` form; the layer does not matter: every view has the same lens). 1 when the file
 * carries them; 0, frame untouched, for a foreign file or one that cannot be read (its
 * image read reports why). */
SSG_API int ssg_exr_frame_read(const char *spec, struct ssg_frame *frame);

/* ---- The process and the machine (ssgraph --version, the profile) */

#define SSG_LOADS_MAX 8 /* one-off loads kept (later ones are still taken out of nodes) */

/* A library the process loaded once, at run time (the OpenImageIO module, the GL
 * library): a node run that contained it is not charged for it. */
struct ssg_load {
    const char *what; /* "OpenImageIO module"; static */
    double start_ms;  /* when it began, on the clock of the stats' times */
    double ms;        /* how long it took */
};
/* Copies the process's loads so far, in order, into out (room for max); their count.
 * Thread-safe. */
SSG_API int ssg_loads(struct ssg_load *out, int max);

/* Opens the GL backend as a graph run would (EGL on a GPU device, else OSMesa; the
 * SSG_GL_PLATFORM variable chooses), writes what it opened into text ("OSMesa: llvmpipe
 * (LLVM 15.0.6, 256 bits)") and closes it again. On failure reports "GL backend
 * unavailable: <cause>" (SSG_E_BACKEND) and leaves text "". Waits while another thread's
 * run holds GL. */
SSG_API enum ssg_err ssg_gl_info(char *text, size_t len, struct ssg_diags *diags);

/* ---- Scenes and models as a newcomer needs to see them (ssgraph check) */

/* Loads and validates the scene at path with its meshes (problems go to diags) and, when
 * it loads, writes "PATH: ok" and its summary to out: the bounds, the triangles of each
 * mesh line with each mesh's box after the line's transform and an up-axis hint, the
 * camera, the lights, and a scale hint when the scene's size does not suit the AO radius
 * of the default graph. */
SSG_API enum ssg_err ssg_scene_summary(const char *path, FILE *out, struct ssg_diags *diags);
/* 1 when path's extension names a model format the scene's mesh() line reads; otherwise 0
 * with the reason (the extension, or that there is none) in why. */
SSG_API int ssg_model_supported(const char *path, char *why, size_t why_len);
/* Loads the model at path (a problem goes to diags, at its line and column where the file
 * has them) and writes "PATH: ok", its meshes with their boxes, its bounds, its up axis
 * and on what that rests, a scale hint, and a scene file to paste around it to out. */
SSG_API enum ssg_err ssg_model_summary(const char *path, FILE *out, struct ssg_diags *diags);

/* ---- Looking at images: a run's ports and an EXR's layers (`ssgraph run --show`,
 * `ssgraph layers`, `ssgraph extract`). Added for issue 31; core/graph/graph_show.c and
 * core/io/image_show.c. ---- */

/* The frame a loaded graph runs at, as its nodes see it: size, guard band, lens, seed. */
SSG_API void ssg_graph_frame(const struct ssg_graph *graph, struct ssg_frame *frame);

/* The frame's part of an image, as the write node writes it: an image of the frame's full
 * size with a guard band (ssg_frame_full_width x ssg_frame_full_height, guard > 0) loses
 * its band into a new image, which *copy owns (the caller frees it) and which is returned;
 * any other image (or any with frame NULL) is returned as it is, *copy NULL. NULL when
 * out of memory, or when image or copy is NULL. */
SSG_API const struct ssg_image *ssg_image_framed(const struct ssg_frame *frame,
                                         const struct ssg_image *image,
                                         struct ssg_image **copy);

/* Writes the 8-bit sRGB PNG preview the write node writes of its main image, through a
 * temporary file renamed into place: every value times 2^exposure (stops), tone mapped by
 * `tonemap` ("aces", the write node's default, when NULL; "reinhard"; "clamp"), sRGB
 * encoded. 1 channel: grey; 3: colour; 2: red and green, blue 0; 4: the colour without
 * alpha. Errors: SSG_E_VALUE for an unknown tone curve, SSG_E_CHANNELS for more than 4
 * channels, SSG_E_IO, SSG_E_NOMEM. */
SSG_API enum ssg_err ssg_image_write_png(const char *path, const struct ssg_image *image,
                                 const char *tonemap, float exposure,
                                 struct ssg_diags *diags);

#define SSG_LAYER_NAME_MAX 128 /* bytes of a layer or channel name, with its NUL */
#define SSG_LAYERS_MAX 64      /* layers ssg_image_layers lists, at most */

/* One layer of an image file: what ssg_image_read(path, name, ...) reads. */
struct ssg_layer_info {
    char name[SSG_LAYER_NAME_MAX]; /* as ssg_image_read's `layer` takes it ("ao",
                                      "depth"); "" = the unnamed channels (R,G,B or Y) */
    int channel_count;             /* channels it reads as (1..4; more: too many to read) */
    char channels[4][SSG_LAYER_NAME_MAX]; /* the file's names of its first channels, in the
                                             order read ("ao.Y"; "R", "G", "B"; depth's
                                             "Z") */
    int width, height;             /* pixels */
};

/* The layers of an image file: an EXR's unnamed channels (when it has some), each LAYER
 * of its LAYER.suffix channels and `depth` for OpenEXR's bare Z, in the order of their
 * first channel in the file (OpenEXR sorts channel names); any other file is one unnamed
 * layer. Fills at most max
 * entries, *count = how many the file has. Errors as ssg_image_read's. */
SSG_API enum ssg_err ssg_image_layers(const char *path, struct ssg_layer_info *layers, int max,
                              int *count, struct ssg_diags *diags);

/* ---- The files a graph depends on, for file watchers (`ssgraph run --watch`, the
 * viewer's reload). Added for issue 31; core/graph/api_graph_files.c. ----
 *
 * A watcher lists them after each load and reloads when one changes on disk. Listing a
 * graph that failed to load works too: ssg_graph_parse's graph (even one with errors)
 * lists the files read so far, so a watcher whose reload failed still knows what to
 * watch. Thread safety: as reading the graph; the scene and lights files are read again. */

#define SSG_GRAPH_FILE_PATH_MAX 1024 /* bytes of a listed path, with its NUL */

enum ssg_graph_file_kind {
    SSG_GRAPH_FILE_GRAPH,       /* the top graph file or an included one */
    SSG_GRAPH_FILE_SCENE,       /* the scene file */
    SSG_GRAPH_FILE_LIGHTS,      /* the lights file that replaces the scene's lights */
    SSG_GRAPH_FILE_MODEL,       /* a mesh(...) line's model file */
    SSG_GRAPH_FILE_TEXTURE,     /* a material's texture */
    SSG_GRAPH_FILE_ENVIRONMENT, /* the environment's image */
};

/* One file a graph depends on. */
struct ssg_graph_file {
    char path[SSG_GRAPH_FILE_PATH_MAX]; /* as it is opened: relative paths resolved against
                                           the file that names them ("graphs/../x.scene") */
    enum ssg_graph_file_kind kind;
};

/* Fills files[0 .. max-1] with the files graph depends on, each once, in this order: the
 * graph files (the top one, then each include as it was first read; one that could not be
 * opened is listed too, so its appearing can be seen), the scene file, the lights file,
 * then the files the scene and lights files name (models, textures, the environment image;
 * not those a model file names itself, such as a glTF's buffers). The scene and lights
 * files are read again for that, whether or not the scene was loaded (a scene that does
 * not parse adds what its readable statements name). Returns how many there are, which may
 * exceed max (then only max were written); 0 for a NULL graph. files may be NULL when max
 * is 0 (to count them). */
SSG_API int ssg_graph_files(const struct ssg_graph *graph, struct ssg_graph_file *files,
                            int max);
/* The same for a scene file and a lights file (NULL or "" = none) without a graph: the
 * files themselves, then what they name, as above. For a watcher whose graph did not load
 * but whose scene was given on the command line (ssg_graph_parse knows only the graph's
 * own). */
SSG_API int ssg_scene_files(const char *scene, const char *lights,
                            struct ssg_graph_file *files, int max);

#ifdef __cplusplus
}
#endif
#endif
