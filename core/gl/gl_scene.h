/* gl_scene.h - the scene on the GL backend, as a node's GL side sees it: its meshes,
 * materials and textures in storage buffers that compute passes read, and the one drawing
 * ssgraph does, rasterising the scene's triangles with a depth test into an image's
 * layers. Like gl.h, the whole of it a node may use (gbuffer, lightmaps, shadowmaps); a
 * node never calls GL itself.
 *
 * The usual use is a visibility buffer (Burns and Hunt, "The Visibility Buffer: A
 * Cache-Friendly Approach to Deferred Shading", JCGT 2(2), 2013): the rasteriser finds
 * the nearest triangle at each pixel centre and writes only its mesh and triangle index;
 * a compute pass then intersects the pixel's ray with that triangle and reads everything
 * else from the buffers below, so its attributes come from the same formulas the CPU's
 * ray caster uses.
 *
 * Storage buffers (std430), bound by ssg_gl_scene_bind at SSG_GL_SCENE_BINDING + i:
 *   +0 float vdata[]: every mesh's positions (xyz), normals (xyz), uvs (uv, only where
 *      its material has a texture or a normal map) and tangents (xyzw, only with a normal
 *      map) and colours (rgb, only where the mesh has them) as in the scene, at the offsets
 *      its Mesh record gives
 *   +1 uint index[]: every mesh's indices (3 per triangle, the mesh's own vertex numbers)
 *   +2 float texel[]: the textures materials use, linear RGB interleaved, row 0 at the top,
 *      each followed by its alpha plane when it has one (scene/coverage.h)
 *   +3 Mesh mesh[]: struct ssg_gl_mesh below, one per scene mesh, in scene order
 *   +4 Material material[]: struct ssg_gl_material below, in scene order
 * A shader declares them with the same fields, e.g.
 *   struct Mesh { int positions; int normals; int uvs; int indices; int material;
 *                 int tangents; int colors; };
 *   layout(std430, binding = 3) readonly buffer Meshes { Mesh scene_mesh[]; };
 * core/gl/gl.h's ssg_gl_buffer bindings from SSG_GL_SCENE_BINDING + SSG_GL_SCENE_BUFFERS on
 * stay free for the node's own data.
 *
 * Ownership: a node never holds the scene. It is ctx->scene uploaded once for a whole run,
 * on the first call below that needs it, and shared by every later node and frame of the
 * run (a live graph keeps it across runs); the run frees it (core/gl/gl_scene.c,
 * graph/gl_backend.h). So the calls below take a pass or ctx, never a scene, and an upload
 * that fails (the scene beyond GL's limits: SSG_E_NOMEM, SSG_E_VALUE or SSG_E_BACKEND,
 * reported as the node's error) is the pass's sticky error (gl.h). Call on the
 * executor's thread with the GL lock held, like all GL code. */
#ifndef SSG_GL_SCENE_H
#define SSG_GL_SCENE_H

#include <stdint.h>

#include "gl/gl.h"

enum { SSG_GL_SCENE_BINDING = 0, SSG_GL_SCENE_BUFFERS = 5 };

/* One mesh on GL: float offsets into vdata (uvs -1 = none, or no texture to look up), the
 * offset of its first index in index[], its material, and the offset of its tangents (xyzw,
 * -1 = none, or no normal map to bend by). */
struct ssg_gl_mesh {
    int32_t positions, normals, uvs, indices, material, tangents, colors; /* colors: rgb
                                                                   per vertex, -1 = none */
};

/* One material on GL (scene.h's fields); texels is the float offset of its texture in
 * texel[], -1 = none, width and height its size in texels; alpha_texels the offset of that
 * texture's alpha plane, -1 = none; masked 1 for alpha_mode mask or blend (coverage.h). */
struct ssg_gl_material {
    float albedo[3];
    float specular[3];
    float shininess;
    int32_t texels, width, height;
    float opacity, alpha_cutoff;
    int32_t alpha_texels, masked;
    int32_t normal_texels, normal_width, normal_height; /* the normal map, -1 = none */
    float normal_scale;
    float emission[3];
    int32_t emission_texels, emission_width, emission_height; /* its texture, -1 = none */
};

/* The camera the scene is drawn from: the pose of ssg_camera_frame (view = rot * (world -
 * eye), rot row-major), the frame's projection (node.h) and its visible depth range. */
struct ssg_gl_camera {
    const float *rot;            /* 9 floats */
    const float *eye;            /* 3 floats */
    struct ssg_projection proj;  /* f, cx, cy in pixels of the target */
    float near_z, far_z;         /* scene units; nearer and farther surfaces are clipped */
};

/* Binds the run's scene's buffers above for the pass's compute shader (uploading it first
 * when no node of the run has). */
void ssg_gl_scene_bind(struct ssg_gl_pass *pass);

/* Binds the scene's distance field (scene/distance.h; uploaded with the scene, once a run)
 * for the pass's compute shader as
 *   layout(std430, binding = B) readonly buffer Distance { float distance_field[]; };
 * its voxels in the field's order (x fastest); a scene without triangles binds one 0. The
 * grid's shape (n, lo, voxel) is the CPU's struct, which the node passes as constants.
 * `binding` is one of the node's own (SSG_GL_SCENE_BINDING + SSG_GL_SCENE_BUFFERS on). */
void ssg_gl_scene_bind_distance(struct ssg_gl_pass *pass, int binding);

/* Clears `target` (a frame-sized image, one colour attachment per layer, at most 8) to 0
 * and draws every mesh with the raster program of `shader` (its SSG_VERTEX and
 * SSG_FRAGMENT halves, gl_fn.h) and a depth test, nearest surface wins, no culling: the
 * rasteriser samples at pixel centres (x + 0.5, y + 0.5) and the projection is flipped so
 * row 0 is the top, as everywhere in ssgraph. The program gets
 *   layout(location = 0) in vec3 ssg_position;   world position
 *   layout(location = 1) in vec2 ssg_uv;         texture coordinates (0 without)
 *   uniform mat4 ssg_world_to_clip;              the camera's projection
 *   uniform int ssg_mesh;                        index of the mesh being drawn
 * and the scene's buffers above bound, and writes `layout(location = i) out float` for
 * layer i. Every raster program discards the fragments an alpha-masked mesh does not
 * cover (nodes/common/surface.glsl's mesh_covers at the interpolated ssg_uv), so a mask
 * is the same to every map and layer. */
enum ssg_err ssg_gl_scene_draw(const struct ssg_node_ctx *ctx, const char *shader,
                               const struct ssg_gl_camera *camera, struct ssg_image *target);

/* A raster pass whose uniforms the node sets with core/gl/gl.h's calls (ssg_gl_input,
 * ssg_gl_float, ...) before ssg_gl_scene_draw_layers: compiles (or finds) the program of
 * `shader`'s SSG_VERTEX and SSG_FRAGMENT halves. Errors are sticky as in gl.h. */
enum ssg_err ssg_gl_raster_begin(struct ssg_gl_pass *pass, const struct ssg_node_ctx *ctx,
                                 const char *shader);

/* Draws every mesh once per layer of `target` (any number of layers, each its own draw):
 * layer i is cleared to `clear` and a depth buffer of the target's size to 1, the program
 * gets `uniform int ssg_layer` = i and `layout(location = 0) in vec3 ssg_position` (world)
 * and makes gl_Position itself (the layer's own projection; NDC x, y in [-1, 1] cover the
 * image with texel row 0 at y = -1); the nearest fragment's `layout(location = 0) out
 * float` is kept (depth test LESS, no culling). Shadow maps are drawn this way. */
enum ssg_err ssg_gl_scene_draw_layers(struct ssg_gl_pass *pass, struct ssg_image *target,
                                      float clear);

/* One image of a stacked draw: draw i writes its layers [i layers, (i + 1) layers). */
struct ssg_gl_stack {
    struct ssg_image *image;
    int layers;  /* layers a draw writes */
    float clear; /* their value where no fragment lands */
};

/* ssg_gl_scene_draw_layers for several images at once (lightmaps: depth, normal and flux
 * of each face): `draws` draws, draw i with `uniform int ssg_layer` = i writing layers
 * [i layers_k, (i + 1) layers_k) of stacks[k] to the fragment outputs in order (the first
 * stack's at location 0, ...), at most 8 outputs; every image has the first one's width
 * and height. A stack whose image is NULL (an unread on_demand output; not the first)
 * keeps its outputs' locations, which go nowhere. Depth test LESS, no culling, as
 * ssg_gl_scene_draw_layers. */
enum ssg_err ssg_gl_scene_draw_stacks(struct ssg_gl_pass *pass,
                                      const struct ssg_gl_stack *stacks, int count, int draws);

/* ssg_gl_scene_draw with a raster pass of ssg_gl_raster_begin whose inputs and uniforms
 * the node has set (a depth peel reads the first layer's depth): the same drawing, the
 * same program interface. Returns the pass's (sticky) error. */
enum ssg_err ssg_gl_scene_draw_pass(struct ssg_gl_pass *pass,
                                    const struct ssg_gl_camera *camera,
                                    struct ssg_image *target);

#endif
