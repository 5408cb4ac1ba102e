#include "sl_probe_pass.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_gl.h"
#include "sl_shader.h"
#include "sl_technique.h"

/* ---- GLSL functions ---- */

typedef struct _sl_text {
    char *data;
    size_t len, cap;
} _sl_text;

static void _sl_add(_sl_text *t, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void _sl_add(_sl_text *t, const char *fmt, ...) {
    va_list args;
    for (;;) {
        size_t room = t->cap - t->len;
        va_start(args, fmt);
        int n = vsnprintf(t->data ? t->data + t->len : NULL, t->data ? room : 0, fmt, args);
        va_end(args);
        if (n < 0) return;
        if (t->data && (size_t)n < room) {
            t->len += (size_t)n;
            return;
        }
        size_t cap = t->cap ? t->cap * 2 : 4096;
        while (cap < t->len + (size_t)n + 1) cap *= 2;
        char *data = realloc(t->data, cap);
        if (!data) return;
        t->data = data;
        t->cap = cap;
    }
}

static const char *_sl_glsl_type(sl_probe_type type) {
    switch (type) {
    case SL_PROBE_INT: return "int";
    case SL_PROBE_VEC2: return "vec2";
    case SL_PROBE_VEC3: return "vec3";
    case SL_PROBE_VEC4: return "vec4";
    case SL_PROBE_MAT4: return "mat4";
    default: return "float";
    }
}

/* The maps each map parameter uses over the table's rows. */
typedef struct _sl_maps {
    int param;                    /* index of the parameter */
    int offset;                   /* its float in a row */
    bool used[SL_PROBE_MAP_COUNT];
} _sl_maps;

/* The probe's fragment shader: the lab files' prelude (the framework functions a lab file may call, as
 * in every program that includes one), the lab's file, then a main() that reads row gl_FragCoord.y's
 * inputs from u_inputs and writes the function's result. */
static char *_sl_probe_source(const sl_probe_function *f, const _sl_maps *maps, int map_params) {
    _sl_text t = {0};
    static const char *const result_types[] = {"", "float", "vec2", "vec3", "vec4"};
    _sl_add(&t, "#version 330 core\n#include \"lab_prelude.glsl\"\n#include \"%s\"\n", f->file);
    _sl_add(&t, "uniform sampler2D u_inputs;\nout vec4 o_result;\n");
    for (int m = 0; m < map_params; m++)
        for (int k = 0; k < SL_PROBE_MAP_COUNT; k++)
            if (maps[m].used[k])
                _sl_add(&t, "uniform %s u_p%d_m%d;\n",
                        f->params[maps[m].param].type == SL_PROBE_SHADOW_MAP  ? "sampler2DShadow"
                        : f->params[maps[m].param].type == SL_PROBE_CUBE_MAP  ? "samplerCube"
                        : f->params[maps[m].param].type == SL_PROBE_ARRAY_MAP ? "sampler2DArray"
                        : f->params[maps[m].param].type == SL_PROBE_MOMENTS_MAP ? "sampler2D"
                                                                              : "sampler2D",
                        m, k);
    /* two pixels per row: a 2x2 quad holds one row only, so dFdx and dFdy of
     * anything computed from the inputs are 0 (a function is probed at a point,
     * not along a surface: compute_moments' derivative term adds nothing here) */
    _sl_add(&t, "float sl_in(int i) { return texelFetch(u_inputs, ivec2(i >> 2, int(gl_FragCoord.y) / 2), 0)[i & 3]; }\n");
    _sl_add(&t, "void main() {\n");
    int offset = 0;
    for (int i = 0; i < f->param_count; i++) {
        sl_probe_type type = f->params[i].type;
        int size = sl_probe_type_size(type);
        if (SL_PROBE_IS_MAP(type)) {
            _sl_add(&t, "    int a%d = int(sl_in(%d));\n", i, offset);
        } else if (type == SL_PROBE_INT || type == SL_PROBE_FLOAT) {
            _sl_add(&t, "    %s a%d = %s(sl_in(%d));\n", _sl_glsl_type(type), i, _sl_glsl_type(type), offset);
        } else {
            _sl_add(&t, "    %s a%d = %s(", _sl_glsl_type(type), i, _sl_glsl_type(type));
            for (int k = 0; k < size; k++) _sl_add(&t, "%ssl_in(%d)", k ? ", " : "", offset + k);
            _sl_add(&t, ");\n");
        }
        offset += size;
    }
    const char *result = result_types[f->output_count];
    _sl_add(&t, "    %s r = %s(0.0);\n", result, result);
    /* one branch per combination of maps: samplers cannot be chosen at run time */
    int choice[SL_PROBE_MAX_PARAMS] = {0};
    bool first = true;
    for (;;) {
        bool valid = true;
        for (int m = 0; m < map_params; m++) valid &= maps[m].used[choice[m]];
        if (valid) {
            _sl_add(&t, "    %sif (true", first ? "" : "else ");
            for (int m = 0; m < map_params; m++) _sl_add(&t, " && a%d == %d", maps[m].param, choice[m]);
            _sl_add(&t, ") r = %s(", f->name);
            for (int i = 0, m = 0; i < f->param_count; i++) {
                bool is_map = SL_PROBE_IS_MAP(f->params[i].type);
                if (is_map) {
                    _sl_add(&t, "%su_p%d_m%d", i ? ", " : "", m, choice[m]);
                    m++;
                } else {
                    _sl_add(&t, "%sa%d", i ? ", " : "", i);
                }
            }
            _sl_add(&t, ");\n");
            first = false;
        }
        int m = 0;
        while (m < map_params && ++choice[m] == SL_PROBE_MAP_COUNT) choice[m++] = 0;
        if (m == map_params) break;
    }
    static const char *const padding[] = {"", ", 0.0, 0.0, 0.0", ", 0.0, 0.0", ", 0.0", ""};
    _sl_add(&t, "    o_result = vec4(r%s);\n}\n", padding[f->output_count]);
    return t.data;
}

static GLuint _sl_cube_texture(sl_probe_map map) {
    static float texels[SL_PROBE_MAP_SIZE * SL_PROBE_MAP_SIZE];
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex);
    for (int face = 0; face < 6; face++) {
        for (int y = 0; y < SL_PROBE_MAP_SIZE; y++)
            for (int x = 0; x < SL_PROBE_MAP_SIZE; x++)
                texels[y * SL_PROBE_MAP_SIZE + x] = sl_probe_cube_depth(map, face, x, y);
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face, 0, GL_DEPTH_COMPONENT32F, SL_PROBE_MAP_SIZE,
                     SL_PROBE_MAP_SIZE, 0, GL_DEPTH_COMPONENT, GL_FLOAT, texels);
    }
    /* as lab 7's maps are set up: exact distances, no fetch across an edge */
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return tex;
}

/* Lab 6's cascades: a depth texture array set up as the framework's (nearest, a border of 1.0 outside). */
static GLuint _sl_array_texture(sl_probe_map map) {
    static float texels[SL_PROBE_LAYERS * SL_PROBE_MAP_SIZE * SL_PROBE_MAP_SIZE];
    for (int layer = 0; layer < SL_PROBE_LAYERS; layer++)
        for (int y = 0; y < SL_PROBE_MAP_SIZE; y++)
            for (int x = 0; x < SL_PROBE_MAP_SIZE; x++)
                texels[(layer * SL_PROBE_MAP_SIZE + y) * SL_PROBE_MAP_SIZE + x] = sl_probe_layer_depth(map, layer, x, y);
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D_ARRAY, tex);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, SL_PROBE_MAP_SIZE, SL_PROBE_MAP_SIZE, SL_PROBE_LAYERS,
                 0, GL_DEPTH_COMPONENT, GL_FLOAT, texels);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[4] = {1, 1, 1, 1};
    glTexParameterfv(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BORDER_COLOR, border);
    glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return tex;
}

/* Lab 5's moments: (depth, depth^2), set up as lab 5's targets (GL_RG32F, linear, clamped to the edge). */
static GLuint _sl_moments_texture(sl_probe_map map) {
    static float texels[SL_PROBE_MAP_SIZE * SL_PROBE_MAP_SIZE * 2];
    for (int y = 0; y < SL_PROBE_MAP_SIZE; y++)
        for (int x = 0; x < SL_PROBE_MAP_SIZE; x++) {
            float d = sl_probe_moments_depth(map, x, y);
            texels[(y * SL_PROBE_MAP_SIZE + x) * 2] = d;
            texels[(y * SL_PROBE_MAP_SIZE + x) * 2 + 1] = d * d;
        }
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, SL_PROBE_MAP_SIZE, SL_PROBE_MAP_SIZE, 0, GL_RG, GL_FLOAT, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return tex;
}

static GLuint _sl_map_texture(sl_probe_map map, bool shadow, bool linear) {
    static float texels[SL_PROBE_MAP_SIZE * SL_PROBE_MAP_SIZE];
    for (int y = 0; y < SL_PROBE_MAP_SIZE; y++)
        for (int x = 0; x < SL_PROBE_MAP_SIZE; x++) texels[y * SL_PROBE_MAP_SIZE + x] = sl_probe_map_depth(map, x, y);
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, SL_PROBE_MAP_SIZE, SL_PROBE_MAP_SIZE, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT, texels);
    GLint filter = linear ? GL_LINEAR : GL_NEAREST;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    /* outside the map: depth 1.0, nothing in front, as lab 1's maps are set up */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float border[4] = {1, 1, 1, 1};
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, shadow ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    return tex;
}

static bool _sl_run_glsl(const sl_probe_function *f, const sl_probe_table *t, const char *labs_dir,
                         const char *framework_dir, double *outputs, char *err, size_t n) {
    _sl_maps maps[SL_PROBE_MAX_PARAMS] = {0};
    int map_params = 0, offset = 0;
    for (int i = 0; i < f->param_count; i++) {
        sl_probe_type type = f->params[i].type;
        if (SL_PROBE_IS_MAP(type)) {
            maps[map_params] = (_sl_maps){.param = i, .offset = offset};
            for (int r = 0; r < t->rows; r++) {
                int m = (int)t->inputs[r][offset];
                if (m < 0 || m >= SL_PROBE_MAP_COUNT) m = 0;
                maps[map_params].used[m] = true;
            }
            map_params++;
        }
        offset += sl_probe_type_size(type);
    }
    char *source = _sl_probe_source(f, maps, map_params);
    if (!source) {
        snprintf(err, n, "out of memory");
        return false;
    }
    char shaders[SL_PATH_MAX], vs[SL_PATH_MAX + 32], fs[SL_PATH_MAX + 32];
    snprintf(shaders, sizeof shaders, "%s/shaders", framework_dir);
    snprintf(vs, sizeof vs, "%s/debug_quad.vert", shaders);
    snprintf(fs, sizeof fs, "%s/probe_%s.frag", shaders, f->name); /* names the generated text in messages */
    sl_program program;
    sl_shader_desc desc = {.vertex_path = vs, .fragment_path = fs, .fragment_source = source,
                           .search_dirs = {labs_dir, shaders}};
    bool ok = sl_program_build(&program, &desc, err, n);
    free(source);
    if (!ok) {
        sl_program_destroy(&program);
        return false;
    }
    int floats = sl_probe_input_count(f), width = (floats + 3) / 4;
    float *texels = calloc((size_t)width * 4 * (size_t)t->rows, sizeof(float));
    float *pixels = calloc((size_t)t->rows * 2 * 4, sizeof(float));
    if (!texels || !pixels) {
        free(texels);
        free(pixels);
        sl_program_destroy(&program);
        snprintf(err, n, "out of memory");
        return false;
    }
    for (int r = 0; r < t->rows; r++) memcpy(texels + (size_t)r * width * 4, t->inputs[r], sizeof(float) * (size_t)floats);
    GLuint inputs, target, framebuffer, vao, textures[SL_PROBE_MAX_PARAMS * SL_PROBE_MAP_COUNT];
    int texture_count = 0;
    glGenTextures(1, &inputs);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, inputs);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, t->rows, 0, GL_RGBA, GL_FLOAT, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenTextures(1, &target);
    glBindTexture(GL_TEXTURE_2D, target);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 2 * t->rows, 0, GL_RGBA, GL_FLOAT, NULL);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
    glUseProgram(program.id);
    glUniform1i(sl_program_uniform(&program, "u_inputs"), 0);
    int unit = 1;
    for (int m = 0; m < map_params; m++) {
        bool shadow = f->params[maps[m].param].type == SL_PROBE_SHADOW_MAP;
        for (int k = 0; k < SL_PROBE_MAP_COUNT; k++) {
            if (!maps[m].used[k]) continue;
            glActiveTexture(GL_TEXTURE0 + (GLenum)unit);
            sl_probe_type type = f->params[maps[m].param].type;
            textures[texture_count++] = type == SL_PROBE_CUBE_MAP    ? _sl_cube_texture((sl_probe_map)k)
                                        : type == SL_PROBE_ARRAY_MAP ? _sl_array_texture((sl_probe_map)k)
                                        : type == SL_PROBE_MOMENTS_MAP ? _sl_moments_texture((sl_probe_map)k)
                                                                     : _sl_map_texture((sl_probe_map)k, shadow,
                                                                                       shadow && f->linear_maps);
            char name[32];
            snprintf(name, sizeof name, "u_p%d_m%d", m, k);
            glUniform1i(sl_program_uniform(&program, name), unit++);
        }
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, inputs); /* unit 0 had the target bound while it was made */
    glViewport(0, 0, 1, 2 * t->rows);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, 1, 2 * t->rows, GL_RGBA, GL_FLOAT, pixels);
    for (int r = 0; r < t->rows; r++)
        for (int o = 0; o < f->output_count; o++) outputs[r * f->output_count + o] = pixels[2 * r * 4 + o];
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &target);
    glDeleteTextures(1, &inputs);
    glDeleteTextures(texture_count, textures);
    glUseProgram(0);
    sl_program_destroy(&program);
    free(texels);
    free(pixels);
    return true;
}

/* ---- whole shader stages ---- */

/* A stage's inputs of one row, set by name: a_* as the vertex's attribute (no array enabled: the generic
 * value), u_* as uniforms, the others (sl_v_*) as the probe's own uniforms that feed the varyings. */
static void _sl_stage_inputs(const sl_probe_function *f, const sl_program *program, const float *row) {
    int offset = 0;
    for (int i = 0; i < f->param_count; i++) {
        const char *name = f->params[i].name;
        const float *v = row + offset;
        offset += sl_probe_type_size(f->params[i].type);
        if (strncmp(name, "a_", 2) == 0) {
            GLint at = glGetAttribLocation(program->id, name);
            if (at >= 0) glVertexAttrib4f((GLuint)at, v[0], f->params[i].type >= SL_PROBE_VEC2 ? v[1] : 0,
                                          f->params[i].type >= SL_PROBE_VEC3 ? v[2] : 0,
                                          f->params[i].type >= SL_PROBE_VEC4 ? v[3] : 1);
            continue;
        }
        char uniform[96];
        snprintf(uniform, sizeof uniform, "%s%s", strncmp(name, "u_", 2) == 0 ? "" : "sl_v_", name);
        for (char *c = uniform; *c; c++)
            if (*c == '.') *c = '_';
        GLint at = sl_program_uniform(program, uniform);
        switch (f->params[i].type) {
        case SL_PROBE_INT: glUniform1i(at, (int)v[0]); break;
        case SL_PROBE_VEC2: glUniform2fv(at, 1, v); break;
        case SL_PROBE_VEC3: glUniform3fv(at, 1, v); break;
        case SL_PROBE_VEC4: glUniform4fv(at, 1, v); break;
        case SL_PROBE_MAT4: glUniformMatrix4fv(at, 1, GL_FALSE, v); break;
        default: glUniform1f(at, v[0]); break;
        }
    }
}

/* The fragment stage's vertex shader: one point, at the row's gl_FragCoord.z (the last parameter), with the
 * row's varyings in the block the stage reads (its name and members as the stage declares them). */
static char *_sl_fragment_stage_vertex(const sl_probe_function *f) {
    _sl_text t = {0};
    _sl_add(&t, "#version 330 core\nout %s sl_out;\nuniform float sl_v_gl_FragCoord_z;\n", f->stage_inputs);
    for (int i = 0; i + 1 < f->param_count; i++)
        if (strncmp(f->params[i].name, "u_", 2) != 0)
            _sl_add(&t, "uniform %s sl_v_%s;\n", _sl_glsl_type(f->params[i].type), f->params[i].name);
    _sl_add(&t, "void main() {\n");
    for (int i = 0; i + 1 < f->param_count; i++)
        if (strncmp(f->params[i].name, "u_", 2) != 0)
            _sl_add(&t, "    sl_out.%s = sl_v_%s;\n", f->params[i].name, f->params[i].name);
    _sl_add(&t, "    gl_Position = vec4(0.0, 0.0, 2.0 * sl_v_gl_FragCoord_z - 1.0, 1.0);\n    gl_PointSize = 1.0;\n}\n");
    return t.data;
}

static const char _sl_no_colour_fragment[] = "#version 330 core\nvoid main() {\n}\n";

static bool _sl_run_stage(const sl_probe_function *f, const sl_probe_table *t, const char *labs_dir,
                          const char *framework_dir, double *outputs, char *err, size_t n) {
    bool vertex = f->stage == SL_PROBE_VERTEX_MAIN;
    char shaders[SL_PATH_MAX], student[SL_PATH_MAX + 64], ours[SL_PATH_MAX + 64];
    snprintf(shaders, sizeof shaders, "%s/shaders", framework_dir);
    snprintf(student, sizeof student, "%s/%s", labs_dir, f->file);
    snprintf(ours, sizeof ours, "%s/probe_%s_%s", shaders, vertex ? "fragment_for" : "vertex_for", f->name);
    char *vertex_source = vertex ? NULL : _sl_fragment_stage_vertex(f);
    if (!vertex && !vertex_source) {
        snprintf(err, n, "out of memory");
        return false;
    }
    sl_program program;
    sl_shader_desc desc = {.vertex_path = vertex ? student : ours, .fragment_path = vertex ? ours : student,
                           .vertex_source = vertex_source, .fragment_source = vertex ? _sl_no_colour_fragment : NULL,
                           .search_dirs = {labs_dir, shaders}};
    bool ok = sl_program_build(&program, &desc, err, n);
    free(vertex_source);
    if (ok && vertex) { /* gl_Position itself, captured before clipping */
        const char *varyings[] = {"gl_Position"};
        glTransformFeedbackVaryings(program.id, 1, varyings, GL_INTERLEAVED_ATTRIBS);
        glLinkProgram(program.id);
        GLint linked = 0;
        glGetProgramiv(program.id, GL_LINK_STATUS, &linked);
        if (!linked) {
            char log[2048] = {0};
            glGetProgramInfoLog(program.id, sizeof log, NULL, log);
            snprintf(err, n, "GLSL link error (%s, capturing gl_Position):\n%s", student, log);
            ok = false;
        }
    }
    if (!ok) {
        sl_program_destroy(&program);
        return false;
    }
    GLuint vao, buffer = 0, depth = 0, framebuffer = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glUseProgram(program.id);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    if (vertex) {
        glGenBuffers(1, &buffer);
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffer);
        glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, 4 * sizeof(float), NULL, GL_STREAM_READ);
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
        glEnable(GL_RASTERIZER_DISCARD);
    } else {
        /* a renderbuffer: what lab 1 makes (a depth texture attached) stays lab 1's to write */
        glGenRenderbuffers(1, &depth);
        glBindRenderbuffer(GL_RENDERBUFFER, depth);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, 1, 1);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glGenFramebuffers(1, &framebuffer);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
        glDrawBuffer(GL_NONE);
        glReadBuffer(GL_NONE);
        glViewport(0, 0, 1, 1);
        glDepthRange(0.0, 1.0);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS); /* whatever it writes is kept */
        glDepthMask(GL_TRUE);
    }
    for (int r = 0; r < t->rows; r++) {
        double *out = outputs + r * f->output_count;
        _sl_stage_inputs(f, &program, t->inputs[r]);
        float got[4] = {NAN, NAN, NAN, NAN};
        if (vertex) {
            glBeginTransformFeedback(GL_POINTS);
            glDrawArrays(GL_POINTS, 0, 1);
            glEndTransformFeedback();
            glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, sizeof got, got);
        } else {
            glClearDepth(1.0);
            glClear(GL_DEPTH_BUFFER_BIT);
            glDrawArrays(GL_POINTS, 0, 1);
            glPixelStorei(GL_PACK_ALIGNMENT, 4);
            glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, got);
        }
        for (int o = 0; o < f->output_count; o++) out[o] = got[o];
    }
    if (vertex) {
        glDisable(GL_RASTERIZER_DISCARD);
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
        glDeleteBuffers(1, &buffer);
    } else {
        glDepthFunc(GL_LESS);
        glDisable(GL_DEPTH_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &framebuffer);
        glDeleteRenderbuffers(1, &depth);
    }
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    glUseProgram(0);
    sl_program_destroy(&program);
    return true;
}

const sl_probe_function *sl_probe_pass_function(const char *name) {
    const sl_probe_function *f = sl_probe_find(name);
    for (int lab = 0; !f && lab <= SL_LAB_COUNT; lab++) {
        const sl_technique *t = sl_technique_of(lab);
        for (const sl_technique_probe *p = t ? t->probes : NULL; !f && p && p->function; p++)
            if (p->described && strcmp(p->function, name) == 0) f = p->described;
    }
    return f;
}

bool sl_probe_pass_run(const sl_probe_table *t, const char *labs_dir, const char *framework_dir, double *outputs,
                       bool *not_implemented, char *err, size_t n) {
    *not_implemented = false;
    char name[SL_PROBE_NAME_MAX];
    snprintf(name, sizeof name, "%s", t->function);
    const sl_probe_function *f = sl_probe_pass_function(name);
    if (!f) {
        snprintf(err, n, "this build has no function %s() to probe", name);
        return false;
    }
    if (sl_probe_input_count(f) != t->input_count || f->output_count != t->output_count) {
        snprintf(err, n, "the case describes %s() with %d inputs and %d outputs a row; this build's has %d and %d",
                 name, t->input_count, t->output_count, sl_probe_input_count(f), f->output_count);
        return false;
    }
    return sl_probe_pass_run_function(f, t, labs_dir, framework_dir, outputs, not_implemented, err, n);
}

bool sl_probe_pass_run_function(const sl_probe_function *f, const sl_probe_table *t, const char *labs_dir,
                                const char *framework_dir, double *outputs, bool *not_implemented, char *err,
                                size_t n) {
    *not_implemented = false;
    if (!f || t->rows < 1 || t->rows > SL_PROBE_MAX_ROWS) {
        snprintf(err, n, "a malformed probe table");
        return false;
    }
    if (f->glsl && f->stage != SL_PROBE_FUNCTION) return _sl_run_stage(f, t, labs_dir, framework_dir, outputs, err, n);
    if (f->glsl) return _sl_run_glsl(f, t, labs_dir, framework_dir, outputs, err, n);
    /* C functions: the row runner of the technique of the function's lab (sl_technique.h) */
    const sl_technique_probe *probe = sl_technique_probe_of(f->lab, f->name);
    for (int r = 0; r < t->rows; r++) {
        double *out = outputs + r * f->output_count;
        for (int o = 0; o < f->output_count; o++) out[o] = NAN;
        sl_status status = probe ? probe->run_row(t->inputs[r], out) : SL_FAILED;
        while (glGetError() != GL_NO_ERROR) {}
        if (status == SL_NOT_IMPLEMENTED) *not_implemented = true;
        if (status == SL_NOT_IMPLEMENTED || (status != SL_OK && !f->reports_status))
            for (int o = 0; o < f->output_count; o++) out[o] = NAN;
    }
    return true;
}
