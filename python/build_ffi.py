"""build_ffi.py - the cffi description of ssgraph's public C interface (core/ssgraph.h and
ssgraph_tools.h), compiled at install time into ssgraph._ssgraph.

cffi's API mode: the declarations below are checked by the C compiler against the real
header, and the structs end in `...;`, so their layout is the compiler's, never a guess (a
field renamed or retyped in the header fails the install instead of reading wrong memory).
The error codes come from errors.def, the header's own single list.

Where the library is (first that holds):
  SSGRAPH_BUILD_DIR   a CMake build folder with libssgraph.so (headers: its source tree)
  SSGRAPH_PREFIX      an install prefix (include/ssgraph/ssgraph.h, lib*/libssgraph.so)
  the repository      ../build, then ../build-test, beside this file
  pkg-config ssgraph  an installed ssgraph on pkg-config's path
The module is linked with an RPATH to that folder, so `import ssgraph` needs no
LD_LIBRARY_PATH; the library finds its OpenImageIO module from its own place.
"""
import os
import re
import subprocess
import sys

from cffi import FFI

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)


def _cmake_source_dir(build):
    """The source tree a CMake build folder was configured from (CMakeCache.txt)."""
    try:
        with open(os.path.join(build, "CMakeCache.txt")) as f:
            for line in f:
                if line.startswith("CMAKE_HOME_DIRECTORY:"):
                    return line.split("=", 1)[1].strip()
    except OSError:
        pass
    return REPO


def _has_library(folder):
    return os.path.exists(os.path.join(folder, "libssgraph.so"))


def _pkg_config(variable):
    try:
        out = subprocess.run(["pkg-config", "--variable=" + variable, "ssgraph"],
                             capture_output=True, text=True, check=True)
        return out.stdout.strip() or None
    except (OSError, subprocess.CalledProcessError):
        return None


def find_ssgraph():
    """(include_dir, library_dir): where ssgraph.h and libssgraph.so are."""
    build = os.environ.get("SSGRAPH_BUILD_DIR")
    if build:
        # pip builds in the package's folder: a relative path is the caller's, whose
        # folder the shell still names in PWD
        build = os.path.join(os.environ.get("PWD", os.getcwd()), build)
        if not _has_library(build):
            sys.exit("ssgraph: SSGRAPH_BUILD_DIR=%s holds no libssgraph.so (build it: cmake "
                     "--build %s)" % (build, build))
        return os.path.join(_cmake_source_dir(build), "core"), build
    prefix = os.environ.get("SSGRAPH_PREFIX")
    if prefix:
        for lib in ("lib", "lib64", "lib/x86_64-linux-gnu", "lib/aarch64-linux-gnu"):
            if _has_library(os.path.join(prefix, lib)):
                return os.path.join(prefix, "include", "ssgraph"), os.path.join(prefix, lib)
        sys.exit("ssgraph: SSGRAPH_PREFIX=%s holds no lib*/libssgraph.so" % prefix)
    for name in ("build", "build-test"):
        build = os.path.join(REPO, name)
        if _has_library(build) and os.path.exists(os.path.join(REPO, "core", "ssgraph.h")):
            return os.path.join(REPO, "core"), build
    include, lib = _pkg_config("includedir"), _pkg_config("libdir")
    if include and lib and _has_library(lib):
        return os.path.join(include, "ssgraph"), lib
    sys.exit("ssgraph: no libssgraph.so found. Build the library first (README.md: cmake -S . "
             "-B build && cmake --build build), or name it: SSGRAPH_BUILD_DIR=<cmake build "
             "folder> or SSGRAPH_PREFIX=<install prefix>")


def error_codes(include):
    """The codes of errors.def, in order (they are the enum's values 0, 1, ...)."""
    with open(os.path.join(include, "errors.def")) as f:
        return re.findall(r"^X\((SSG_\w+)\s*,", f.read(), re.M)


CDEF = """
enum ssg_err { %(codes)s, SSG_ERR_COUNT };
const char *ssg_err_name(enum ssg_err code);
const char *ssg_err_text(enum ssg_err code);

struct ssg_diag {
    enum ssg_err code; char file[256]; int line; int column; char message[512]; ...;
};
#define SSG_DIAGS_MAX ...
#define SSG_WARNINGS_MAX ...
#define SSG_MAX_OUTPUTS ...
#define SSG_GUARD_MAX ...
struct ssg_diags {
    int count; int total; struct ssg_diag items[...]; int warning_count;
    struct ssg_diag warnings[...]; ...;
};

struct ssg_image { int width; int height; int channels; float *data; ...; };
struct ssg_image *ssg_image_create(int width, int height, int channels);
void ssg_image_destroy(struct ssg_image **image);
enum ssg_err ssg_image_read(const char *path, const char *layer, struct ssg_image **out,
                            struct ssg_diags *diags);
enum ssg_err ssg_image_write(const char *path, const struct ssg_image *image,
                             struct ssg_diags *diags);

struct ssg_frame {
    int width; int height; float fov_y; float near_z; float far_z; uint64_t seed; int guard;
    ...;
};

struct ssg_run_metric { char node[64]; char name[32]; double value; ...; };
struct ssg_run_node {
    char *name; const char *type; const char *backend; double ms; double gpu_ms;
    double transfer_ms; int calls; double avg_ms; double min_ms; double max_ms;
    double median_ms; double share; double prepare_ms; int kept; char *why; ...;
};
struct ssg_run_stats {
    int frames; double frame_avg_ms; double frame_min_ms; double frame_max_ms;
    double frame_median_ms; double total_ms; int width; int height; int threads;
    size_t peak_pool_bytes; char *gl; int node_count; struct ssg_run_node *nodes;
    int metric_count; struct ssg_run_metric *metrics; ...;
};
void ssg_run_stats_free(struct ssg_run_stats *stats);

struct ssg_run_options {
    const char *out_dir; int threads; int frames; struct ssg_run_stats *stats;
    struct ssg_image **outputs; int no_files; ...;
};
struct ssg_overrides {
    const char *scene; const char *lights; int width; int height; int guard_given;
    int guard; const char *const *sets; int set_count; int64_t seed; const char *backend;
    ...;
};

struct ssg_graph;
enum ssg_err ssg_graph_load(const char *path, const struct ssg_overrides *overrides,
                            struct ssg_graph **out, struct ssg_diags *diags);
enum ssg_err ssg_graph_run(struct ssg_graph *graph, const struct ssg_run_options *options,
                           struct ssg_diags *diags);
void ssg_graph_destroy(struct ssg_graph **graph);
enum ssg_err ssg_graph_param(const struct ssg_graph *graph, const char *key, double *value,
                             int *integer, struct ssg_diags *diags);
enum ssg_err ssg_graph_keep(struct ssg_graph *graph, size_t max_bytes, struct ssg_diags *diags);
enum ssg_err ssg_graph_set(struct ssg_graph *graph, const char *key, const char *value,
                           struct ssg_diags *diags);
enum ssg_err ssg_graph_output(struct ssg_graph *graph, const char *port,
                              struct ssg_image **out, struct ssg_diags *diags);
enum ssg_err ssg_graph_supply(struct ssg_graph *graph, const char *node,
                              const struct ssg_image *image, struct ssg_diags *diags);

struct ssg_view { float position[3]; float target[3]; float up[3]; float fov_y; ...; };
enum ssg_err ssg_graph_view(const struct ssg_graph *graph, struct ssg_view *out,
                            struct ssg_diags *diags);
enum ssg_err ssg_graph_set_view(struct ssg_graph *graph, const struct ssg_view *view,
                                struct ssg_diags *diags);
enum ssg_err ssg_graph_set_lights(struct ssg_graph *graph, const char *lights,
                                  struct ssg_diags *diags);
enum ssg_err ssg_graph_camera_at(const struct ssg_graph *graph, int frame_index,
                                 struct ssg_view *out, struct ssg_diags *diags);
enum ssg_err ssg_graph_jitter_at(const struct ssg_graph *graph, int frame_index,
                                 float jitter[2], struct ssg_diags *diags);
enum ssg_err ssg_graph_set_frame(struct ssg_graph *graph, int frame_index,
                                 struct ssg_diags *diags);

struct ssg_graph_info {
    const char *path; const char *scene; const char *lights; struct ssg_frame frame;
    int node_count; int run_count; ...;
};
void ssg_graph_inspect(const struct ssg_graph *graph, struct ssg_graph_info *info);
struct ssg_node_info { const char *name; const char *type; const char *backend;
                       int param_count; ...; };
enum ssg_err ssg_graph_node_inspect(const struct ssg_graph *graph, int index,
                                    struct ssg_node_info *info);
int ssg_graph_run_node(const struct ssg_graph *graph, int position);
const char *ssg_graph_node_param(const struct ssg_graph *graph, int index, int k,
                                 char *value, size_t len);
struct ssg_param_info {
    const char *name; const char *type; const char *unit; const char *doc; int bounded;
    double min; double max; const char *const *choices; double soft_min; double soft_max;
    ...;
};
enum ssg_err ssg_node_param_info(const char *node, int k, struct ssg_param_info *info);
struct ssg_port_info {
    const char *name; const char *type; const char *doc; int output; int optional;
    int channels; int width; int height; char from[128]; ...;
};
int ssg_graph_port_count(const struct ssg_graph *graph, int index);
enum ssg_err ssg_graph_port_inspect(const struct ssg_graph *graph, int index, int k,
                                    struct ssg_port_info *info);

struct ssg_binding { const char *port; const struct ssg_image *image; ...; };
struct ssg_outputs {
    int count; const char *names[8]; struct ssg_image *images[8]; int metric_count;
    char metric_names[16][32]; double metric_values[16]; ...;
};
void ssg_outputs_release(struct ssg_outputs *outputs);
enum ssg_err ssg_node_run(const char *node, const struct ssg_binding *inputs, int input_count,
                          const char *const *sets, int set_count,
                          const struct ssg_frame *frame, struct ssg_outputs *outputs,
                          struct ssg_diags *diags);
int ssg_node_count(void);
const char *ssg_node_name(int index);
const char *ssg_node_summary(int index);
"""

INCLUDE, LIBDIR = find_ssgraph()
ffibuilder = FFI()
ffibuilder.cdef(CDEF % {"codes": ", ".join(error_codes(INCLUDE))})
ffibuilder.set_source(
    "ssgraph._ssgraph", '#include "ssgraph.h"\n', include_dirs=[INCLUDE],
    library_dirs=[LIBDIR], libraries=["ssgraph"], runtime_library_dirs=[LIBDIR])

if __name__ == "__main__":
    ffibuilder.compile(verbose=True)
