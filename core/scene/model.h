/* model.h - mesh files of any supported format, behind one call. glTF 2.0 (.gltf, .glb)
 * goes through tinygltf (gltf.h); OBJ, PLY, FBX, 3DS, STL, DAE, glTF 1.0 and whatever
 * else the installed Assimp reads go through the Assimp adapter (assimp_adapter.cc). Both
 * fill the same struct ssg_gltf: world-space triangle meshes, materials (a diffuse colour
 * becomes base_color, as glTF's baseColorFactor does), textures and an optional camera.
 *
 * Assimp is a large library fed untrusted files, and some of them crash it (deep XML
 * overflows its stack), hang it (a PLY header without end_header) or make it allocate
 * gigabytes (a count in a header). So every file is first pre-checked here (model_check.c:
 * nesting depth, header counts against the file's size), and the import itself runs in a
 * child process (model_sandbox.c) under a time and a memory limit: whatever still goes
 * wrong becomes an error naming the file, never a crash, a hang or a swapping machine.
 *
 * Ownership as in gltf.h: the caller frees the result with ssg_gltf_destroy. Every message
 * names the file; the scene loader puts it at the mesh line. Thread-safe: no shared state
 * (each call makes its own Assimp importer, in its own child process). */
#ifndef SSG_MODEL_H
#define SSG_MODEL_H

#include <stddef.h>

#include "scene/gltf.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The formats a message lists when a file's extension is not one of them. */
#define SSG_MODEL_FORMATS                                                                  \
    ".gltf/.glb (glTF 2.0 through tinygltf; glTF 1.0 through Assimp), and through Assimp "  \
    ".obj, .ply, .fbx, .3ds, .stl, .dae (and the other formats of the installed Assimp)"

/* Deepest nesting of XML elements (DAE, X3D, AMF...) or of braces and brackets (glTF 1.0,
   ASCII FBX, .x, .ase) a model file may have: Assimp's readers recurse once per level, and
   100,000 levels overflow the stack. No real model comes near it. */
#define SSG_MODEL_MAX_NESTING 256

/* The up axis of a loaded model, and what that rests on (for `ssgraph check`). */
struct ssg_model_up {
    int axis;        /* 0, 1, 2: x, y, z of the loaded model; -1: the file does not say */
    int sign;        /* +1 or -1 (the up direction along axis) */
    char basis[200]; /* what the axis rests on, "the glTF 2.0 specification (+Y up)" */
    int alt_axis;    /* with alt_sign: where up comes out for a file that did not follow
                        the format's custom the axis rests on (a 3DS made Y-up: -Z), which
                        the file does not record */
    int alt_sign;    /* +1 or -1; 0: no other way (zero-initialised: none) */
};

/* ssg_model_supported: in ssgraph.h (public). */

/* Loads path by its extension (and, for glTF, by the version it declares). Returns
 * SSG_E_IO (unreadable), SSG_E_GLTF (malformed, unsupported content or format, or an
 * importer that crashed or ran out of time) or SSG_E_NOMEM with a message naming the file
 * in why, and *out NULL. */
enum ssg_err ssg_model_load(const char *path, struct ssg_gltf **out, char *why,
                            size_t why_len);

/* ssg_model_load, also telling the model's up axis in *up. With out NULL only *up is
   found (a glTF is not even read then). */
enum ssg_err ssg_model_load_up(const char *path, struct ssg_gltf **out,
                               struct ssg_model_up *up, char *why, size_t why_len);

/* The same reading in this process, without a child and its limits: for the fuzz target
   (fuzz/fuzz_model.c), where a crash or hang is what is being looked for. */
enum ssg_err ssg_model_load_here(const char *path, struct ssg_gltf **out,
                                 struct ssg_model_up *up, char *why, size_t why_len);

/* The cheap checks of model_check.c on path's bytes, by its extension and content: XML
 * and brace nesting (at most SSG_MODEL_MAX_NESTING), a PLY's header and element counts,
 * a binary STL's triangle count, a 3DS's chunk sizes. SSG_OK, or SSG_E_GLTF with
 * "PATH:LINE:COLUMN: problem" (or "PATH: problem") in why; SSG_E_IO when unreadable. */
enum ssg_err ssg_model_precheck(const char *path, char *why, size_t why_len);

/* The same on bytes in memory, named path in messages; ext is the lower-case extension
   with its dot (".ply"). */
enum ssg_err ssg_model_precheck_bytes(const char *path, const char *ext, const char *data,
                                      size_t len, char *why, size_t why_len);

/* The child process's limits (model_sandbox.c); 0 means none. */
struct ssg_model_limits {
    double seconds;       /* wall-clock time of the whole import */
    long long bytes;      /* address space the import may add (not under AddressSanitizer,
                             which reserves terabytes of it: the pre-checks stand alone) */
};

/* The defaults: $SSGRAPH_MODEL_TIMEOUT seconds (default 60, plus 1 per 4 MiB of a file of
   file_bytes) and $SSGRAPH_MODEL_MEMORY MiB (default half the physical memory). */
void ssg_model_limits_default(long long file_bytes, struct ssg_model_limits *limits);

/* An import run in the child: ssg_assimp_load's shape. */
typedef enum ssg_err (*ssg_model_import_fn)(const char *path, struct ssg_gltf **out,
                                            struct ssg_model_up *up, char *why,
                                            size_t why_len);

/* Runs import(path, ...) in a child process under limits and brings its result back
 * through a pipe. A child that runs out of time is killed: SSG_E_GLTF "PATH: the model
 * importer ran out of time (N s ...)"; out of memory: SSG_E_NOMEM "... ran out of memory
 * (limit N MiB ...)"; killed by a signal: SSG_E_GLTF "... crashed (signal N, NAME)".
 * Otherwise what import returned. out NULL: only *up comes back. */
enum ssg_err ssg_model_sandbox(const char *path, ssg_model_import_fn import,
                               const struct ssg_model_limits *limits, struct ssg_gltf **out,
                               struct ssg_model_up *up, char *why, size_t why_len);

/* The Assimp side: 1 when the installed Assimp reads files ending in ext (".obj"). */
int ssg_assimp_supports(const char *ext);
/* Reads path through Assimp in this process (no pre-checks, no limits), triangulated, its
 * node transforms applied; materials carry a diffuse texture as texture_file (relative to
 * the model file), decoded by the caller. *up: the up axis (up may be NULL); out NULL:
 * only the up axis is wanted, and the meshes are not flattened. */
enum ssg_err ssg_assimp_load(const char *path, struct ssg_gltf **out, struct ssg_model_up *up,
                             char *why, size_t why_len);

#ifdef __cplusplus
}
#endif
#endif
