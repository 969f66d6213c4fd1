/* shaders.h - the GLSL files compiled into the binary (core/gl/common.glsl and every
 * nodes/<name>/<file>.glsl), generated at build time by cmake/embed_files.cmake. */
#ifndef SSG_SHADERS_H
#define SSG_SHADERS_H

struct ssg_shader_file {
    const char *name;   /* file name, "ssao.glsl" */
    const char *source; /* its text, NUL-terminated */
};

/* Terminated by {NULL, NULL}. */
extern const struct ssg_shader_file ssg_shader_files[];

/* The text of a shader file by name, or NULL. */
const char *ssg_shader_source(const char *name);

#endif
