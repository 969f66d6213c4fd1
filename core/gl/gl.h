/* gl.h - what a node's GL side (nodes/<name>/<name>_gl.c) may use: compute passes over the
 * frame's images, written in GLSL files next to the node. A node never calls GL itself;
 * this header is its whole view of the GL backend.
 *
 * Images on the GL backend. Every image (1 to 4 channels) is one GL_TEXTURE_2D_ARRAY of
 * format R32F with one layer per channel, so its memory is the CPU's planar layout and a
 * transfer is one copy. Texel (x, y) is pixel (x, y): row 0 is the top, as on the CPU. The
 * runtime (core/gl/gl_runtime.c) uploads an input that was produced on the CPU before the node
 * runs and downloads an output when a CPU node reads it; a node sees only its images.
 *
 * A pass: one compute shader over a w x h grid of invocations (8 x 8 per work group, see
 * core/gl/common.glsl, which every shader gets first). Shaders are the files
 * nodes/<name>/<file>.glsl, compiled into the binary and found by file name ("ssao.glsl").
 * Compile and link errors are reported with node, file and line. Programs are compiled once
 * per process for each (file, defines) and cached.
 *
 *   struct ssg_gl_pass p;
 *   ssg_gl_pass_begin(&p, ctx, "gaussian.glsl", "#define HORIZONTAL 1\n");
 *   ssg_gl_input(&p, "src", io->in[0]);          // uniform sampler2DArray src;
 *   ssg_gl_output(&p, "dst", tmp);               // layout(r32f) uniform image2DArray dst;
 *   ssg_gl_int(&p, "radius", c->radius);         // uniform int radius;
 *   ssg_gl_floats(&p, "weight", 2 * r + 1, c->weight);
 *   ssg_gl_dispatch(&p, w, h);
 *   return ssg_gl_pass_end(&p);
 *
 * Binding by the tables. A node's shader that holds the line `#pragma ssg_params` gets its
 * parameters declared from the descriptor's table (`uniform float p_radius;`, enum choices
 * as `const int MODE_DISC = 2;`, rows marked host_only left out) and the pass binds their
 * values itself; `#pragma ssg_consts` does the same for the rows of the constants
 * prepare() made (the descriptor's `uniforms`, read under their own names); ssg_gl_ports
 * binds every port by its name (an input whose name is a GLSL keyword by its row's
 * gl_name; an on_demand output nobody reads that the shader still stores, to a scratch
 * image the pass frees at ssg_gl_pass_end). A node with one pass then names nothing by
 * hand:
 *
 *   struct ssg_gl_pass p;
 *   ssg_gl_pass_begin(&p, ctx, "ao.glsl", NULL);  // #pragma ssg_params in ao.glsl
 *   ssg_gl_ports(&p, io);                         // inputs as <port>, outputs dst_<port>
 *   ssg_gl_projection(&p, "proj", &c->proj);      // what prepare() made, by name
 *   ssg_gl_dispatch(&p, w, h);
 *   return ssg_gl_pass_end(&p);
 *
 * Variants. A shader compiled with a define that turns a feature off (NORMALS 0) does not
 * read that feature's uniforms, and the compiler drops them. A row or port marked
 * `.gl_if = "NORMALS"` says so: the pass requires it where the program was compiled with
 * NORMALS nonzero, and leaves it out where the program lacks it otherwise. Rows of kind
 * MAT3 are read as `float name[9]` (row-major), PROJECTION rows as `vec3 name`, a
 * parameter of kind INTS as `int p_name[SSG_INTS_MAX]` with its count `int p_name_count`
 * (read where the shader needs it).
 *
 * Nodes of several shaders. One table serves every shader of the node; a row or port
 * marked `.gl_in = "rsm_cells.glsl rsm.glsl"` is required only in the shaders named, and
 * left out in the others, so each pass may hold both pragmas and call ssg_gl_ports. Rows
 * of constants the consts already keep (a nested `g.cap`, a field the CPU names `cells`)
 * are made by SSG_UNIFORMS_AT_TABLE (lang/params.h) over the consts' own fields.
 *
 * What stays bound by hand (ssg_gl_int and the rest below) is what is neither a
 * parameter, a constant's row nor a port of the pass: a multi-pass node's scratch images
 * and loop values. tests/test_structure_gl.sh lists each such binding with its reason.
 * An array of structs (a light list) goes into a storage buffer as it is (ssg_gl_buffer).
 *
 * Errors are sticky: after the first failing call the pass does nothing and
 * ssg_gl_pass_end returns that error (already reported through ctx->diags), so a node can
 * chain calls and check once. A name the program lacks is such an error ("<node>
 * '<instance>': shader <file> has no active uniform '<name>'"), never a silent skip, and
 * so is a declared parameter the shader never reads: compilers drop unused uniforms, so a
 * node binds only what its shader (with these defines) reads. The optional names are
 * `<input>_bound` and ssg_grid. One thread (the executor's) uses GL at a time. */
#ifndef SSG_GL_H
#define SSG_GL_H

#include <stddef.h>

#include "graph/node.h"

/* Invocations per work group on each axis (core/gl/common.glsl's local_size). */
#define SSG_GL_GROUP 8

struct ssg_gl_pass {
    const struct ssg_node_ctx *ctx; /* the node running the pass (for messages) */
    const char *shader;             /* file name, for messages */
    const char *defines;            /* as given to ssg_gl_pass_begin (kept: it must outlive
                                       the pass), for the rows and ports marked gl_if */
    unsigned program;               /* GL program, 0 after an error */
    int next_unit;                  /* next free texture unit */
    int next_image;                 /* next free image unit */
    enum ssg_err err;               /* first error, SSG_OK while all went well */
    struct ssg_image *unread[8];    /* scratch images ssg_gl_ports bound for on_demand
                                       outputs nobody reads (freed by ssg_gl_pass_end) */
    int unread_count;
};

/* Compiles (or finds in the cache) the shader file with `defines` (GLSL lines inserted
 * after #version, NULL = none) and makes it current. */
enum ssg_err ssg_gl_pass_begin(struct ssg_gl_pass *pass, const struct ssg_node_ctx *ctx,
                               const char *shader, const char *defines);

/* A whole pass of its own: copies prepared planar floats (width x height x channels of each
 * dst, as in ssgraph.h) into `count` output images, for nodes whose output is a table made
 * in prepare() (the same bytes as the CPU backend writes). */
enum ssg_err ssg_gl_fill(const struct ssg_node_ctx *ctx, const float *const *planes,
                         struct ssg_image *const *dst, int count);

/* Binds an image for reading as `uniform sampler2DArray <name>` (texelFetch, or texture()
 * with linear filtering and clamp-to-edge). NULL (an unconnected optional input) binds a
 * 1x1 image of zeros. Also sets `uniform bool <name>_bound` when the shader declares it. */
void ssg_gl_input(struct ssg_gl_pass *pass, const char *name, const struct ssg_image *image);
/* Binds an image for writing as `layout(r32f) uniform image2DArray <name>` (imageStore;
 * also readable with imageLoad when declared without writeonly). */
void ssg_gl_output(struct ssg_gl_pass *pass, const char *name, struct ssg_image *image);

/* Binds every port by the descriptor's names: input i as ssg_gl_input(desc->inputs[i].name)
 * and output i as `dst_<name>` (out is a GLSL keyword); an on_demand output nobody reads
 * is left unbound. For a pass whose shader reads every port. */
void ssg_gl_ports(struct ssg_gl_pass *pass, const struct ssg_io *io);

/* Uniforms. Arrays: `count` values into `uniform float name[N]` (count <= N). */
void ssg_gl_int(struct ssg_gl_pass *pass, const char *name, int value);
void ssg_gl_ivec2(struct ssg_gl_pass *pass, const char *name, int x, int y);
void ssg_gl_float(struct ssg_gl_pass *pass, const char *name, float value);
void ssg_gl_vec2(struct ssg_gl_pass *pass, const char *name, float x, float y);
void ssg_gl_vec3(struct ssg_gl_pass *pass, const char *name, const float v[3]);
void ssg_gl_vec4(struct ssg_gl_pass *pass, const char *name, const float v[4]);
void ssg_gl_floats(struct ssg_gl_pass *pass, const char *name, int count, const float *v);
void ssg_gl_ints(struct ssg_gl_pass *pass, const char *name, int count, const int *v);
/* The projection of node.h as `uniform vec3 <name>` = (f, cx, cy). */
void ssg_gl_projection(struct ssg_gl_pass *pass, const char *name,
                       const struct ssg_projection *p);

/* Read-only data too large or too irregular for uniforms (tables, light lists, a cube map
 * of the environment): `bytes` copied into a shader storage buffer at `binding`, i.e.
 * `layout(std430, binding = B) readonly buffer Name { float v[]; };`. Lay the C data out as
 * std430 does: scalars and float arrays match C; a vec3 does not (use float triples). */
void ssg_gl_buffer(struct ssg_gl_pass *pass, int binding, const void *data, size_t bytes);

/* Runs the shader over a width x height grid (ceil(width / 8) x ceil(height / 8) work
 * groups; the shader returns early outside the grid) and makes its image writes visible to
 * the next pass. May be called several times in one pass with different uniforms. */
void ssg_gl_dispatch(struct ssg_gl_pass *pass, int width, int height);

/* Checks for GL errors and returns the pass's first error. */
enum ssg_err ssg_gl_pass_end(struct ssg_gl_pass *pass);

/* A GL-only image for a node's intermediate results (a separable filter's middle): it has
 * no CPU pixels (data is NULL) and lives until ssg_gl_scratch_release. NULL when out of
 * memory (reported). Scratch images of the same shape are reused across nodes. */
struct ssg_image *ssg_gl_scratch(const struct ssg_node_ctx *ctx, int width, int height,
                                 int channels);
void ssg_gl_scratch_release(struct ssg_image **image);

#endif
