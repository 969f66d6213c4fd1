/* scene_shapes.h - private to the scene loader: tessellation of the built-in primitives
 * (plane, box, sphere) into struct ssg_mesh, and rigid placement of loaded meshes.
 *
 * Every mesh made here owns malloc'd arrays (positions, normals, uvs, indices) freed by
 * ssg_mesh_free. Winding is counter-clockwise seen from outside, so the geometric normal
 * cross(p1 - p0, p2 - p0) points the way the vertex normals do. No shared state. */
#ifndef SSG_SCENE_SHAPES_H
#define SSG_SCENE_SHAPES_H

#include "scene/scene.h"

/* Rotation matrix (row-major 3x3) of Euler angles in degrees: about x first, then y, then
 * z, all about the fixed world axes, i.e. R = Rz * Ry * Rx. */
void ssg_euler_matrix(const float degrees[3], float r[9]);

/* A rectangle through `center` facing `normal` (need not be unit, must not be 0). Its
 * frame is the shortest rotation taking +y to the normal; size[0] is its extent along the
 * rotated x axis, size[2] along the rotated z axis (size[1] is unused). 2 triangles. */
enum ssg_err ssg_shape_plane(const float center[3], const float size[3], const float normal[3],
                             struct ssg_mesh *out);
/* A box of extents `size` rotated by `rotate` (degrees, see ssg_euler_matrix) about its
 * centre; faceted normals, each face uv-mapped to [0,1]^2. 12 triangles. */
enum ssg_err ssg_shape_box(const float center[3], const float size[3], const float rotate[3],
                           struct ssg_mesh *out);
/* A latitude-longitude sphere with `rings` bands of latitude and 2 * rings segments of
 * longitude; smooth normals; uv = (longitude, latitude) in [0,1]^2, v = 0 at the top. */
enum ssg_err ssg_shape_sphere(const float center[3], float radius, int rings,
                              struct ssg_mesh *out);

/* p' = R * (scale * p) + translate, normals by the inverse transpose (and the winding
 * flipped when the scale mirrors). */
void ssg_mesh_place(struct ssg_mesh *mesh, const float translate[3], const float rotate[3],
                    const float scale[3]);

/* Grows the axis-aligned box [lo, hi] to hold every vertex of the mesh. */
void ssg_mesh_bounds(const struct ssg_mesh *mesh, float lo[3], float hi[3]);

void ssg_mesh_free(struct ssg_mesh *mesh);

/* Gives a mesh with uvs its per-vertex tangents (mesh->tangents, xyzw, world) in the way of
   Lengyel, "Computing Tangent Space Basis Vectors for an Arbitrary Mesh" (2001): each
   triangle's direction of +u and +v from its edges and uv differences, summed at its
   vertices (weighted by its area, as the unnormalised sums are), the tangent made
   orthogonal to the vertex normal (Gram-Schmidt) and w the sign that turns cross(n, t) into
   +v. A vertex whose sum vanishes (degenerate uvs) gets any unit vector orthogonal to n.
   Without uvs, or when it has tangents already, nothing changes. SSG_E_NOMEM or SSG_OK. */
enum ssg_err ssg_mesh_tangents(struct ssg_mesh *mesh);

#endif
