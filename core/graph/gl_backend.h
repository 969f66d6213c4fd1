/* gl_backend.h - the GL backend as the executor sees it (core/graph/exec.c, core/graph/graph.c,
 * core/graph/noderun.c): opening it, moving images between the CPU and GL, timer queries.
 * Internal to libssgraph. Declared here, in the graph layer, and implemented by core/gl
 * (gl_runtime.c), so that the layers include only downwards: lang, scene, graph, then gl and
 * io (tests/test_layers.sh).
 *
 * Residency: an image whose `gpu` field is NULL lives on the CPU only. Once a GL node reads
 * or writes it, it has a texture and two flags saying which copy is current; a transfer
 * makes the other copy current. The executor inserts them: before a GL node, every input
 * is uploaded unless its texture is current; before a CPU node, every input is downloaded
 * unless its pixels are current; after a node, its outputs are current where it ran.
 *
 * One GL context serves the process; ssg_gl_open takes a process-wide lock that
 * ssg_gl_close releases, so one graph run at a time uses GL (others wait). */
#ifndef SSG_GL_BACKEND_H
#define SSG_GL_BACKEND_H

#include "ssgraph.h"

/* Private per-image state (the `gpu` field of struct ssg_image). */
struct ssg_gl_image {
    unsigned texture; /* GL_TEXTURE_2D_ARRAY, R32F, one layer per channel */
    int cpu_valid;    /* 1 = image->data holds the current pixels */
    int gl_valid;     /* 1 = the texture holds the current pixels */
};

/* Takes the GL lock and makes the context current, creating it on first use. On failure
 * reports "GL backend unavailable: <cause>" with the hint to use --backend cpu, releases
 * the lock and returns SSG_E_BACKEND. */
enum ssg_err ssg_gl_open(struct ssg_diags *diags);
/* Waits for GL to finish and releases the lock. */
void ssg_gl_close(void);
/* "OSMesa: llvmpipe (LLVM 15.0.6, 256 bits)" or similar, for timing tables; "" before open. */
const char *ssg_gl_describe(void);

/* Makes the texture current (uploading the pixels if needed) / the pixels current
 * (downloading). Adds the milliseconds spent to *ms. SSG_E_NOMEM/SSG_E_BACKEND on failure
 * (reported). */
enum ssg_err ssg_gl_to_gpu(const struct ssg_image *image, double *ms, struct ssg_diags *diags);
enum ssg_err ssg_gl_to_cpu(const struct ssg_image *image, double *ms, struct ssg_diags *diags);
/* After a node wrote the image: its copy on GL (on_gl = 1) or on the CPU is current. */
void ssg_gl_mark_written(struct ssg_image *image, int on_gl);
/* Called by ssg_image_destroy: deletes the texture and the record. */
void ssg_gl_image_free(struct ssg_image *image);

/* A GPU timer query around one node: begin, then end returns its GPU milliseconds. */
void ssg_gl_timer_begin(void);
double ssg_gl_timer_end(void);

/* What the GL nodes of one run share (core/gl/gl_scene.c): the scene they draw and read,
 * uploaded on the first node that asks (core/gl/gl_scene.h) instead of once per node.
 * Owned by whoever owns the run: a fresh run (graph_run.c), a live graph across its runs
 * (graph.h, struct ssg_live), or the executor for a node run alone (exec.c). Zero = nothing
 * uploaded yet. ctx->gl_shared (node.h) points at it while a node runs. */
struct ssg_gl_scene;
struct ssg_scene;
enum { SSG_GL_VIEWS = 4 /* proxy levels kept on GL at once: a run uses one or two */ };
struct ssg_gl_shared {
    struct ssg_gl_scene *scene;       /* the scene on GL; NULL until a node asks */
    const struct ssg_scene *scene_of; /* the scene it was uploaded from (another one asked
                                         for replaces it) */
    int uploads;                      /* scenes uploaded into it so far (tests) */
    struct ssg_gl_scene *view[SSG_GL_VIEWS]; /* the scene's proxy views the map nodes drew
                                         (scene/proxy.h), newest first; NULL = free */
};
/* Deletes what the run's nodes shared and zeroes it but for the count: at the end of the
 * run, or when its scene changes. With GL open (ssg_gl_open) where anything was uploaded;
 * after a failed open only the memory is freed (the GL objects went with the context). */
void ssg_gl_shared_clear(struct ssg_gl_shared *shared);

#endif
