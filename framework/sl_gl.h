/* sl_gl: every OpenGL 3.3 core entry point, loaded at run time through the
 * current backend's get-proc function (OSMesaGetProcAddress, glfwGetProcAddress).
 *
 * Why not link libGL: libOSMesa exports only part of GL 3.3, and linking libGL
 * next to it binds calls to glvnd, which has no context. Code that includes this
 * header calls glClear() etc. as usual; the names resolve to loaded pointers. */
#ifndef SL_GL_H
#define SL_GL_H

#include <stdbool.h>
#include <stddef.h>

#ifdef __gl_h_
#error "include sl_gl.h instead of GL/gl.h"
#endif
/* On Windows glcorearb.h includes <windows.h> unless APIENTRY is defined, and
 * windows.h defines near and far (and min, max) as macros, which the scenes'
 * and lights' fields are named: give it the calling convention itself. */
#if defined(_WIN32) && !defined(APIENTRY)
#define APIENTRY __stdcall
#endif
#include <GL/glcorearb.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef void (*sl_gl_proc)(void);
typedef sl_gl_proc (*sl_gl_get_proc_fn)(const char *name);

#define SL_GL_FUNC(type, name) extern type _sl_##name;
#include "sl_gl_functions.h"
#undef SL_GL_FUNC

/* Loads every entry point; returns false and names the first missing one. */
bool sl_gl_load(sl_gl_get_proc_fn get_proc, char *err, size_t err_size);

/* Name of a GL error or framebuffer status enum, for messages. */
const char *sl_gl_enum_name(GLenum value);

#ifdef __cplusplus
}
#endif

#include "sl_gl_names.h"

#endif
