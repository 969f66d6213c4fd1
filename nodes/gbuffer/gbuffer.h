/* gbuffer.h - parameters and prepared constants of the `gbuffer` node, shared by
 * gbuffer.c (descriptor, prepare), gbuffer_cpu.c (the CPU kernel) and gbuffer_gl.c (the
 * GL side). Method and conventions: README.md in this folder. */
#ifndef SSG_GBUFFER_H
#define SSG_GBUFFER_H

#include "graph/node.h"

/* The shaders of the GL side (gbuffer_gl.c) that read a port or a row (.gl_in): the
   shading pass, the second layer's cast, the motion pass, the depth peel. */
#define SSG_GBUFFER_GL_SHADE "gbuffer.glsl"
#define SSG_GBUFFER_GL_RAYS "gbuffer.glsl gbuffer_back.glsl"
#define SSG_GBUFFER_GL_PIXELS "gbuffer.glsl gbuffer_back.glsl gbuffer_motion.glsl"
#define SSG_GBUFFER_GL_MOTION "gbuffer_motion.glsl"
#define SSG_GBUFFER_GL_PEEL "gbuffer_peel.glsl"
#define SSG_GBUFFER_GL_EMISSION "gbuffer_emission.glsl"

/* Ports, one row each (node.h): enumerator, name, types, doc, further fields; on GL each
   output is written by one pass (.gl_in), as dst_<name>. */
#define SSG_GBUFFER_OUT(X)                                                                 \
    X(SSG_GBUFFER_OUT_POSITION, "position", SSG_T_VECTOR,                                  \
      "view-space position, 0 = background", .gl_in = SSG_GBUFFER_GL_SHADE)                \
    X(SSG_GBUFFER_OUT_NORMAL, "normal", SSG_T_VECTOR,                                      \
      "unit view-space normal facing the camera", .gl_in = SSG_GBUFFER_GL_SHADE)           \
    X(SSG_GBUFFER_OUT_DEPTH, "depth", SSG_T_SCALAR,                                        \
      "linear depth along -z, 0 = background", .gl_in = SSG_GBUFFER_GL_SHADE)              \
    X(SSG_GBUFFER_OUT_ALBEDO, "albedo", SSG_T_COLOR,                                       \
      "material albedo times texture, linear RGB", .gl_in = SSG_GBUFFER_GL_SHADE)          \
    X(SSG_GBUFFER_OUT_DIRECT, "direct", SSG_T_COLOR,                                       \
      "diffuse + Blinn-Phong light of the scene's lights, no shadows, linear RGB",         \
      .lit = 1, .on_demand = 1, .gl_in = SSG_GBUFFER_GL_SHADE)                             \
    X(SSG_GBUFFER_OUT_ENVIRONMENT, "environment", SSG_T_COLOR,                             \
      "diffuse light of the scene's environment, no occlusion: albedo / pi * "             \
      "irradiance, linear RGB", .lit = 1, .on_demand = 1, .gl_in = SSG_GBUFFER_GL_SHADE)   \
    X(SSG_GBUFFER_OUT_BACK, "back", SSG_T_SCALAR,                                          \
      "linear depth along -z of the next surface behind the first on the pixel's "        \
      "ray (depth * (1 + 1e-4) < back <= far); +inf where there is none, 0 = "             \
      "background", .on_demand = 1, /* only computed when something reads it */           \
      .gl_in = "gbuffer_back.glsl")                                                        \
    X(SSG_GBUFFER_OUT_MOTION, "motion", SSG_T_VECTOR,                                      \
      "screen motion to the previous frame (ctx->prev_camera): x, y = the surface "       \
      "point's previous pixel position minus this one, in pixels (+x right, +y down); "   \
      "z = its view depth in the previous camera; 0 = background",                        \
      .on_demand = 1, .gl_in = SSG_GBUFFER_GL_MOTION)                                     \
    X(SSG_GBUFFER_OUT_EMISSION, "emission", SSG_T_COLOR,                                   \
      "radiance the visible surface emits (its material's emission x emission texture), " \
      "linear RGB: what the camera sees of it directly; combine adds it",                  \
      .on_demand = 1, .gl_in = SSG_GBUFFER_GL_EMISSION)
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
    /* The scene's lights and environment as the GL shading pass reads them (prepare_gl,
       gbuffer.c); the CPU kernel reads the scene itself. */
    int light_count;
    int env_mode;               /* 0 black, 1 constant, 2 the irradiance table */
    float env_constant[3];      /* mode 1: pi * the constant radiance (ssg_env_irradiance) */
    float env_pole[2][3];       /* mode 2: the table's north and south pole values */
    float gap;                  /* SSG_GBUFFER_BACK_GAP, for the depth peel */
};

/* The constants the GL shaders read (#pragma ssg_consts), rows over the consts' own
   fields (lang/params.h): kind, GLSL name, field, doc, the shaders that read it. */
#define SSG_GBUFFER_UNIFORMS(U)                                                            \
    U(PROJECTION, proj, proj, "the frame's projection f, cx, cy",                         \
      .gl_in = SSG_GBUFFER_GL_PIXELS)                                                      \
    U(FLOAT, inv_f, inv_f, "1 / f rounded on the CPU", .gl_in = SSG_GBUFFER_GL_PIXELS)    \
    U(MAT3, rot, rot, "world -> view rotation", .gl_in = SSG_GBUFFER_GL_RAYS)             \
    U(VEC3, eye, eye, "the camera's world position", .gl_in = SSG_GBUFFER_GL_RAYS)        \
    U(INT, light_count, light_count, "the scene's lights", .gl_in = SSG_GBUFFER_GL_SHADE) \
    U(INT, env_mode, env_mode, "the environment: 0 black, 1 constant, 2 the table",      \
      .gl_in = SSG_GBUFFER_GL_SHADE)                                                       \
    U(VEC3, env_constant, env_constant, "pi * the constant radiance",                    \
      .gl_in = SSG_GBUFFER_GL_SHADE)                                                       \
    U(VEC3, env_north, env_pole[0], "the irradiance table's north pole value",            \
      .gl_in = SSG_GBUFFER_GL_SHADE)                                                       \
    U(VEC3, env_south, env_pole[1], "the irradiance table's south pole value",            \
      .gl_in = SSG_GBUFFER_GL_SHADE)                                                       \
    U(FLOAT, gap, gap, "SSG_GBUFFER_BACK_GAP", .gl_in = SSG_GBUFFER_GL_PEEL)              \
    U(FLOAT, prev_f, prev_f, "the previous frame's focal length",                         \
      .gl_in = SSG_GBUFFER_GL_MOTION)                                                      \
    U(MAT3, m_rot, m_rot, "this view -> the previous view", .gl_in = SSG_GBUFFER_GL_MOTION) \
    U(VEC3, m_move, m_move, "this camera's position in the previous view",                \
      .gl_in = SSG_GBUFFER_GL_MOTION)                                                      \
    U(FLOAT, near_z, near_z, "the visible depth's near end", .gl_in = SSG_GBUFFER_GL_MOTION)

enum ssg_err ssg_gbuffer_run_cpu(const struct ssg_node_ctx *ctx, const void *consts,
                                 const struct ssg_io *io);
/* The GL side (gbuffer_gl.c): rasterised visibility, then the same formulas per pixel. */
enum ssg_err ssg_gbuffer_run_gl(const struct ssg_node_ctx *ctx, const void *consts,
                                const struct ssg_io *io);

#endif
