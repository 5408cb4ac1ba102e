#include "sl_gl.h"

#include <stdio.h>

#define SL_GL_FUNC(type, name) type _sl_##name;
#include "sl_gl_functions.h"
#undef SL_GL_FUNC

bool sl_gl_load(sl_gl_get_proc_fn get_proc, char *err, size_t err_size) {
    /* Function pointers and data pointers differ in ISO C; the get-proc APIs
     * return function pointers already, so only a same-kind cast is needed. */
#define SL_GL_FUNC(type, name)                                                     \
    _sl_##name = (type)get_proc(#name);                                            \
    if (!_sl_##name) {                                                             \
        if (err && err_size) snprintf(err, err_size, "OpenGL function %s is not available", #name); \
        return false;                                                              \
    }
#include "sl_gl_functions.h"
#undef SL_GL_FUNC
    return true;
}

const char *sl_gl_enum_name(GLenum value) {
    switch (value) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_FRAMEBUFFER_COMPLETE: return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER: return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_DEPTH_COMPONENT: return "GL_DEPTH_COMPONENT";
    case GL_DEPTH_COMPONENT16: return "GL_DEPTH_COMPONENT16";
    case GL_DEPTH_COMPONENT24: return "GL_DEPTH_COMPONENT24";
    case GL_DEPTH_COMPONENT32: return "GL_DEPTH_COMPONENT32";
    case GL_DEPTH_COMPONENT32F: return "GL_DEPTH_COMPONENT32F";
    case GL_DEPTH24_STENCIL8: return "GL_DEPTH24_STENCIL8";
    case GL_DEPTH32F_STENCIL8: return "GL_DEPTH32F_STENCIL8";
    case GL_RGBA8: return "GL_RGBA8";
    case GL_RGBA: return "GL_RGBA";
    /* lab 5's moments */
    case GL_RG: return "GL_RG";
    case GL_RG8: return "GL_RG8";
    case GL_RG16: return "GL_RG16";
    case GL_RG16F: return "GL_RG16F";
    case GL_RG32F: return "GL_RG32F";
    case GL_RGBA16F: return "GL_RGBA16F";
    case GL_RGBA32F: return "GL_RGBA32F";
    case GL_R32F: return "GL_R32F";
    case GL_R16F: return "GL_R16F";
    case GL_R16: return "GL_R16";
    case GL_R8: return "GL_R8";
    case GL_NEAREST: return "GL_NEAREST";
    case GL_LINEAR: return "GL_LINEAR";
    case GL_NEAREST_MIPMAP_NEAREST: return "GL_NEAREST_MIPMAP_NEAREST";
    case GL_LINEAR_MIPMAP_NEAREST: return "GL_LINEAR_MIPMAP_NEAREST";
    case GL_NEAREST_MIPMAP_LINEAR: return "GL_NEAREST_MIPMAP_LINEAR";
    case GL_LINEAR_MIPMAP_LINEAR: return "GL_LINEAR_MIPMAP_LINEAR";
    case GL_NEVER: return "GL_NEVER";
    case GL_LESS: return "GL_LESS";
    case GL_EQUAL: return "GL_EQUAL";
    case GL_LEQUAL: return "GL_LEQUAL";
    case GL_GREATER: return "GL_GREATER";
    case GL_NOTEQUAL: return "GL_NOTEQUAL";
    case GL_GEQUAL: return "GL_GEQUAL";
    case GL_ALWAYS: return "GL_ALWAYS";
    case GL_FRONT: return "GL_FRONT";
    case GL_BACK: return "GL_BACK";
    case GL_FRONT_AND_BACK: return "GL_FRONT_AND_BACK";
    default: return "unknown GL enum";
    }
}
