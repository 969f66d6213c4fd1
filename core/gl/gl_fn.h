/* gl_fn.h - the GL function table of the GL backend, for core/gl_*.c only (nodes use
 * core/gl/gl.h). GL's own headers give the types (glcorearb.h, no prototypes); the entry
 * points are loaded once at context creation, so the same code runs on OSMesa and on EGL,
 * and `glFoo(...)` below calls through the table. */
#ifndef SSG_GL_FN_H
#define SSG_GL_FN_H

#include <GL/glcorearb.h>

struct ssg_gl_fns {
#define X(type, name) type name;
#include "gl/gl_funcs.def"
#undef X
};
extern struct ssg_gl_fns ssg_gl_fn;

#define glGetError ssg_gl_fn.GetError
#define glGetString ssg_gl_fn.GetString
#define glGetStringi ssg_gl_fn.GetStringi
#define glGetIntegerv ssg_gl_fn.GetIntegerv
#define glFinish ssg_gl_fn.Finish
#define glFlush ssg_gl_fn.Flush
#define glEnable ssg_gl_fn.Enable
#define glDisable ssg_gl_fn.Disable
#define glDepthFunc ssg_gl_fn.DepthFunc
#define glViewport ssg_gl_fn.Viewport
#define glPixelStorei ssg_gl_fn.PixelStorei
#define glCreateShader ssg_gl_fn.CreateShader
#define glShaderSource ssg_gl_fn.ShaderSource
#define glCompileShader ssg_gl_fn.CompileShader
#define glGetShaderiv ssg_gl_fn.GetShaderiv
#define glGetShaderInfoLog ssg_gl_fn.GetShaderInfoLog
#define glDeleteShader ssg_gl_fn.DeleteShader
#define glCreateProgram ssg_gl_fn.CreateProgram
#define glAttachShader ssg_gl_fn.AttachShader
#define glLinkProgram ssg_gl_fn.LinkProgram
#define glGetProgramiv ssg_gl_fn.GetProgramiv
#define glGetProgramInfoLog ssg_gl_fn.GetProgramInfoLog
#define glDeleteProgram ssg_gl_fn.DeleteProgram
#define glUseProgram ssg_gl_fn.UseProgram
#define glGetUniformLocation ssg_gl_fn.GetUniformLocation
#define glProgramUniform1i ssg_gl_fn.ProgramUniform1i
#define glProgramUniform2i ssg_gl_fn.ProgramUniform2i
#define glProgramUniform1f ssg_gl_fn.ProgramUniform1f
#define glProgramUniform2f ssg_gl_fn.ProgramUniform2f
#define glProgramUniform3f ssg_gl_fn.ProgramUniform3f
#define glProgramUniform4f ssg_gl_fn.ProgramUniform4f
#define glProgramUniform1fv ssg_gl_fn.ProgramUniform1fv
#define glProgramUniform1iv ssg_gl_fn.ProgramUniform1iv
#define glProgramUniform3fv ssg_gl_fn.ProgramUniform3fv
#define glProgramUniformMatrix4fv ssg_gl_fn.ProgramUniformMatrix4fv
#define glCreateTextures ssg_gl_fn.CreateTextures
#define glTextureStorage2D ssg_gl_fn.TextureStorage2D
#define glTextureStorage3D ssg_gl_fn.TextureStorage3D
#define glTextureSubImage2D ssg_gl_fn.TextureSubImage2D
#define glTextureSubImage3D ssg_gl_fn.TextureSubImage3D
#define glGetTextureImage ssg_gl_fn.GetTextureImage
#define glTextureParameteri ssg_gl_fn.TextureParameteri
#define glDeleteTextures ssg_gl_fn.DeleteTextures
#define glBindTextureUnit ssg_gl_fn.BindTextureUnit
#define glBindImageTexture ssg_gl_fn.BindImageTexture
#define glClearTexImage ssg_gl_fn.ClearTexImage
#define glGenerateTextureMipmap ssg_gl_fn.GenerateTextureMipmap
#define glDispatchCompute ssg_gl_fn.DispatchCompute
#define glMemoryBarrier ssg_gl_fn.MemoryBarrier
#define glCreateBuffers ssg_gl_fn.CreateBuffers
#define glNamedBufferData ssg_gl_fn.NamedBufferData
#define glNamedBufferSubData ssg_gl_fn.NamedBufferSubData
#define glBindBufferBase ssg_gl_fn.BindBufferBase
#define glDeleteBuffers ssg_gl_fn.DeleteBuffers
#define glCreateQueries ssg_gl_fn.CreateQueries
#define glBeginQuery ssg_gl_fn.BeginQuery
#define glEndQuery ssg_gl_fn.EndQuery
#define glGetQueryObjectui64v ssg_gl_fn.GetQueryObjectui64v
#define glDeleteQueries ssg_gl_fn.DeleteQueries
#define glCreateFramebuffers ssg_gl_fn.CreateFramebuffers
#define glNamedFramebufferTexture ssg_gl_fn.NamedFramebufferTexture
#define glNamedFramebufferTextureLayer ssg_gl_fn.NamedFramebufferTextureLayer
#define glNamedFramebufferDrawBuffers ssg_gl_fn.NamedFramebufferDrawBuffers
#define glNamedFramebufferDrawBuffer ssg_gl_fn.NamedFramebufferDrawBuffer
#define glCheckNamedFramebufferStatus ssg_gl_fn.CheckNamedFramebufferStatus
#define glBindFramebuffer ssg_gl_fn.BindFramebuffer
#define glClearNamedFramebufferfv ssg_gl_fn.ClearNamedFramebufferfv
#define glDeleteFramebuffers ssg_gl_fn.DeleteFramebuffers
#define glCreateRenderbuffers ssg_gl_fn.CreateRenderbuffers
#define glNamedRenderbufferStorage ssg_gl_fn.NamedRenderbufferStorage
#define glNamedFramebufferRenderbuffer ssg_gl_fn.NamedFramebufferRenderbuffer
#define glDeleteRenderbuffers ssg_gl_fn.DeleteRenderbuffers
#define glCreateVertexArrays ssg_gl_fn.CreateVertexArrays
#define glBindVertexArray ssg_gl_fn.BindVertexArray
#define glVertexArrayVertexBuffer ssg_gl_fn.VertexArrayVertexBuffer
#define glVertexArrayElementBuffer ssg_gl_fn.VertexArrayElementBuffer
#define glVertexArrayAttribFormat ssg_gl_fn.VertexArrayAttribFormat
#define glVertexArrayAttribIFormat ssg_gl_fn.VertexArrayAttribIFormat
#define glVertexArrayAttribBinding ssg_gl_fn.VertexArrayAttribBinding
#define glEnableVertexArrayAttrib ssg_gl_fn.EnableVertexArrayAttrib
#define glDisableVertexArrayAttrib ssg_gl_fn.DisableVertexArrayAttrib
#define glDeleteVertexArrays ssg_gl_fn.DeleteVertexArrays
#define glDrawElements ssg_gl_fn.DrawElements
#define glDrawArrays ssg_gl_fn.DrawArrays
#define glQueryCounter ssg_gl_fn.QueryCounter

/* ---- the context (core/gl/gl_context.c) ---- */

/* Creates the process's GL 4.5 core context and loads the table. The platform comes from
 * SSG_GL_PLATFORM: "osmesa" (software, llvmpipe), "egl" (the first EGL device, a GPU where
 * there is one), or "auto"/unset (an EGL device backed by a GPU driver when one exists,
 * else OSMesa). On failure writes the cause into why and returns 0. */
int ssg_gl_context_create(char *why, size_t why_len);
/* Makes it current on the calling thread (the executor may differ between runs). */
int ssg_gl_context_bind(void);
/* "OSMesa" or "EGL", and the GL renderer string, for timing tables. */
const char *ssg_gl_context_platform(void);
const char *ssg_gl_context_renderer(void);
void ssg_gl_context_destroy(void);

/* ---- compiling (core/gl/gl_program.c) ---- */

/* A program from shader file `shader` with `defines`, cached for the process. `stages`:
 * SSG_GL_COMPUTE, or SSG_GL_RASTER (the file's SSG_VERTEX and SSG_FRAGMENT halves).
 * On failure reports "<node> '<instance>': shader <file>:<line>: <message>" (every
 * compiler line) and returns 0. */
enum { SSG_GL_COMPUTE = 1, SSG_GL_RASTER = 2 };
/* *binds: which of the node's tables the file declares (#pragma ssg_params, ssg_consts;
 * gl_program.c), for the pass to bind. */
enum { SSG_GL_BINDS_PARAMS = 1, SSG_GL_BINDS_CONSTS = 2 };
struct ssg_node_ctx;
GLuint ssg_gl_program_get(const struct ssg_node_ctx *ctx, const char *shader,
                          const char *defines, int stages, int *binds);
void ssg_gl_programs_free(void);

#endif
