/* gbuffer.h - parameters and prepared constants of the `gbuffer` node, shared by
 * gbuffer.c (descriptor, prepare), gbuffer_cpu.c (the CPU kernel) and gbuffer_gl.c (the
 * GL side). Method and conventions: README.md in this folder. */
#ifndef SSG_GBUFFER_H
#define SSG_GBUFFER_H

#include "graph/node.h"

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields. */
#define SSG_GBUFFER_OUT(X)                                                                 \
    X(SSG_GBUFFER_OUT_POSITION, "position", SSG_T_VECTOR,                                  \
      "view-space position, 0 = background")                                               \
    X(SSG_GBUFFER_OUT_NORMAL, "normal", SSG_T_VECTOR,                                      \
      "unit view-space normal facing the camera")                                          \
    X(SSG_GBUFFER_OUT_DEPTH, "depth", SSG_T_SCALAR,                                        \
      "linear depth along -z, 0 = background")                                             \
    X(SSG_GBUFFER_OUT_ALBEDO, "albedo", SSG_T_COLOR,                                       \
      "material albedo times texture, linear RGB")                                         \
    X(SSG_GBUFFER_OUT_DIRECT, "direct", SSG_T_COLOR,                                       \
      "diffuse + Blinn-Phong light of the scene's lights, no shadows, linear RGB",         \
      .lit = 1)                                                                            \
    X(SSG_GBUFFER_OUT_ENVIRONMENT, "environment", SSG_T_COLOR,                             \
      "diffuse light of the scene's environment, no occlusion: albedo / pi * "             \
      "irradiance, linear RGB", .lit = 1)                                                  \
    X(SSG_GBUFFER_OUT_BACK, "back", SSG_T_SCALAR,                                          \
      "linear depth along -z of the next surface behind the first on the pixel's "        \
      "ray (depth * (1 + 1e-4) < back <= far); +inf where there is none, 0 = "             \
      "background", .on_demand = 1) /* only computed when something reads it */        \
    X(SSG_GBUFFER_OUT_MOTION, "motion", SSG_T_VECTOR,                                      \
      "screen motion to the previous frame (ctx->prev_camera): x, y = the surface "       \
      "point's previous pixel position minus this one, in pixels (+x right, +y down); "   \
      "z = its view depth in the previous camera; 0 = background",                        \
      .on_demand = 1)
SSG_PORT_ENUM(ssg_gbuffer_output, SSG_GBUFFER_OUT, SSG_GBUFFER_OUTPUTS);

/* The second layer (`back`) is the nearest surface whose depth exceeds depth + depth *
   SSG_GBUFFER_BACK_GAP (float operations in that order, on both backends): the first
   surface, and a coplanar or edge-adjacent triangle at its depth, is never found again.
   1e-4 is 1000 times the float rounding of a depth and of the GL rasteriser's
   interpolated depth, and thinner than any modelled wall (0.1 mm at 1 m). */
#define SSG_GBUFFER_BACK_GAP 1e-4f

enum ssg_gbuffer_normals {
    SSG_GBUFFER_NORMALS_SMOOTH, /* interpolated vertex normals */
    SSG_GBUFFER_NORMALS_FACE,   /* the triangle's geometric normal */
};

/* The parameters, one row each (lang/params.h); gbuffer.glsl reads them as p_<field>
   (#pragma ssg_params). */
#define SSG_GBUFFER_PARAMS(P)                                                              \
    P(ENUM, normals,                                                                       \
      "smooth: interpolated vertex normals; face: the triangle's own normal (no "         \
      "self-occlusion of flat-shaded meshes in SSAO)",                                     \
      .def = SSG_GBUFFER_NORMALS_SMOOTH, .choices = ssg_gbuffer_normals_choices)
SSG_PARAMS_STRUCT(ssg_gbuffer_params, SSG_GBUFFER_PARAMS);

struct ssg_gbuffer_consts {
    struct ssg_gbuffer_params p;
    struct ssg_projection proj; /* ssg_frame_projection of the frame */
    float inv_f;                /* 1 / proj.f: pixel (x, y)'s ray has view direction
                                   ((x + 0.5 - cx) inv_f, -(y + 0.5 - cy) inv_f, -1) on
                                   both backends */
    float rot[9];               /* world -> view rotation, row-major */
    float eye[3];               /* camera position, world */
    float near_z, far_z;        /* visible depth range, scene units */
    /* Motion (README.md, `motion`): the point at view position q of this camera is at
       m_rot q + m_move in the previous camera's view (prepare_motion, gbuffer.c). */
    float m_rot[9];             /* this view -> the previous view, row-major */
    float m_move[3];            /* this camera's position in the previous view */
    float prev_f;               /* the previous frame's focal length, pixels (its
                                   principal point is proj's: the same image size) */
};

enum ssg_err ssg_gbuffer_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);
/* The GL side (gbuffer_gl.c): rasterised visibility, then the same formulas per pixel. */
enum ssg_err ssg_gbuffer_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);

#endif
