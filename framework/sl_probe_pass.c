#include "sl_probe_pass.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_gl.h"
#include "sl_labs.h"
#include "sl_shader.h"

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

/* The probe's fragment shader: the lab's file, then a main() that reads row
 * gl_FragCoord.y's inputs from u_inputs and writes the function's result. */
static char *_sl_probe_source(const sl_probe_function *f, const _sl_maps *maps, int map_params) {
    _sl_text t = {0};
    static const char *const result_types[] = {"", "float", "vec2", "vec3", "vec4"};
    _sl_add(&t, "#version 330 core\n#include \"%s\"\n", f->file);
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

/* ---- C functions ---- */

static void _sl_vec3(const float *in, vec3 out) { glm_vec3_copy((float *)in, out); }

static sl_light _sl_light(int type, const float *direction, const float *position) {
    sl_light light = {.type = (sl_light_type)type, .intensity = 1, .near = 0.5f, .far = 50, .spot_angle_deg = 30};
    _sl_vec3(direction, light.direction);
    _sl_vec3(position, light.position);
    glm_vec3_one(light.color);
    return light;
}

static void _sl_store_matrix(mat4 m, double *out) {
    for (int i = 0; i < 16; i++) out[i] = ((const float *)m)[i];
}

/* GL state the depth-pass functions set, from a neutral start as the renderer gives them. */
static void _sl_neutral_depth_state(void) {
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0, 0);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
}

/* lab1_begin_depth_pass on a framebuffer of `size` made here, from a state
 * that is wrong in every way the function must fix: another framebuffer
 * bound, a small viewport, the depth test off with GL_ALWAYS, depth writes
 * off, and the depths at 0.5, so a clear shows as 1.0. The framebuffer holds
 * renderbuffers (colour and depth), not lab 1's map: what the map is made of
 * is lab1_create_shadow_map's to get right, and this file ships to students.
 * map.depth_texture names a depth texture of that size too, for a function
 * that attaches it again; the depth read back is whichever is attached. */
static sl_status _sl_call_begin_depth_pass(const sl_lab_functions *labs, int size, double *out) {
    sl_shadow_map map = {.size = size};
    GLuint renderbuffers[2];
    glGenRenderbuffers(2, renderbuffers);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, size, size);
    glBindRenderbuffer(GL_RENDERBUFFER, renderbuffers[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glGenTextures(1, &map.depth_texture);
    glBindTexture(GL_TEXTURE_2D, map.depth_texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, size, size, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &map.framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffers[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, renderbuffers[1]);
    glDepthMask(GL_TRUE);
    glClearDepth(0.5);
    glClear(GL_DEPTH_BUFFER_BIT);
    glClearDepth(1.0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, 7, 5);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_FALSE);
    sl_status status = labs->lab1_begin_depth_pass(&map);
    GLint bound = 0, viewport[4] = {0}, func = 0;
    GLboolean writes = GL_FALSE;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_DEPTH_FUNC, &func);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &writes);
    out[0] = (GLuint)bound == map.framebuffer;
    out[1] = viewport[2];
    out[2] = viewport[3];
    out[3] = glIsEnabled(GL_DEPTH_TEST);
    out[4] = func == GL_LEQUAL ? GL_LESS : func; /* both keep the nearest depth: equally right */
    out[5] = writes;
    float depth = -1;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, map.framebuffer);
    glReadPixels(size / 2, size / 2, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
    out[6] = depth;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &map.framebuffer);
    glDeleteRenderbuffers(2, renderbuffers);
    glDeleteTextures(1, &map.depth_texture);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    return status;
}

/* lab1_create_shadow_map(size): the map's filtering and wrapping, as glGet*
 * reports them: what a lookup of a later lab reads between texels and past
 * the map's edge. */
static sl_status _sl_call_create_shadow_map(const sl_lab_functions *labs, int size, double *out) {
    sl_shadow_map map = {0};
    sl_status status = labs->lab1_create_shadow_map(size, &map);
    while (glGetError() != GL_NO_ERROR) {}
    if (map.depth_texture && glIsTexture(map.depth_texture)) {
        GLint min = 0, mag = 0, s = 0, t = 0;
        GLfloat border[4] = {0, 0, 0, 0};
        glBindTexture(GL_TEXTURE_2D, map.depth_texture);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &min);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &mag);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &s);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &t);
        glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
        glBindTexture(GL_TEXTURE_2D, 0);
        out[0] = min;
        out[1] = mag;
        out[2] = s;
        out[3] = t;
        /* a depth texture reads its border's first component: only past the edge does it count */
        out[4] = s == GL_CLAMP_TO_BORDER || t == GL_CLAMP_TO_BORDER ? border[0] : -1;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (map.framebuffer) glDeleteFramebuffers(1, &map.framebuffer);
    if (map.depth_texture) glDeleteTextures(1, &map.depth_texture);
    return status;
}

/* lab7_create_cube_map(size): what it made, as glGet* reports it. */
static sl_status _sl_call_create_cube_map(const sl_lab_functions *labs, int size, double *out) {
    sl_cube_map map = {0};
    sl_status status = labs->lab7_create_cube_map(size, &map);
    while (glGetError() != GL_NO_ERROR) {}
    bool cube = map.depth_cube && glIsTexture(map.depth_cube);
    if (cube) {
        glBindTexture(GL_TEXTURE_CUBE_MAP, map.depth_cube);
        cube = glGetError() == GL_NO_ERROR; /* a texture first bound as 2D cannot become a cube map */
    }
    out[0] = cube;
    for (int o = 1; o < 9; o++) out[o] = 0;
    if (cube) {
        GLint w = 0, h = 0, bits = 0, faces = 0, min = 0, mag = 0, s = 0, t = 0, r = 0;
        glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_TEXTURE_HEIGHT, &h);
        glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_TEXTURE_DEPTH_SIZE, &bits);
        for (int face = 0; face < 6; face++) {
            GLint fw = 0, fb = 0;
            glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face, 0, GL_TEXTURE_WIDTH, &fw);
            glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)face, 0, GL_TEXTURE_DEPTH_SIZE, &fb);
            faces += fw == size && fb > 0;
        }
        glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, &min);
        glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, &mag);
        glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, &s);
        glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, &t);
        glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, &r);
        out[1] = w;
        out[2] = h;
        out[3] = bits > 0; /* 16, 24 or 32 bits, integer or float: distance / far fits any */
        out[4] = faces;
        out[5] = min == GL_NEAREST && mag == GL_NEAREST;
        out[6] = s == GL_CLAMP_TO_EDGE && t == GL_CLAMP_TO_EDGE && r == GL_CLAMP_TO_EDGE;
        glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    }
    if (map.framebuffer && glIsFramebuffer(map.framebuffer)) {
        GLint draw = -1, read = -1;
        glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer);
        out[7] = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        glGetIntegerv(GL_DRAW_BUFFER, &draw);
        glGetIntegerv(GL_READ_BUFFER, &read);
        out[8] = draw == GL_NONE && read == GL_NONE;
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    if (map.framebuffer) glDeleteFramebuffers(1, &map.framebuffer);
    if (map.depth_cube) glDeleteTextures(1, &map.depth_cube);
    return status;
}

/* lab7_begin_cube_pass(face) on a cube map of `size` made here, from a state
 * wrong in every way the function must fix (as lab 1's probe), every face's
 * depths at 0.5 so a clear shows as 1.0. */
static sl_status _sl_call_begin_cube_pass(const sl_lab_functions *labs, int face, int size, double *out) {
    sl_cube_map map = {.size = size};
    glGenTextures(1, &map.depth_cube);
    glBindTexture(GL_TEXTURE_CUBE_MAP, map.depth_cube);
    for (int f = 0; f < 6; f++)
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_DEPTH_COMPONENT24, size, size, 0,
                     GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
    glGenFramebuffers(1, &map.framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, map.framebuffer);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    glDepthMask(GL_TRUE);
    glClearDepth(0.5);
    for (int f = 0; f < 6; f++) {
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f,
                               map.depth_cube, 0);
        glClear(GL_DEPTH_BUFFER_BIT);
    }
    glClearDepth(1.0);
    /* the wrong face attached: the function must attach its own */
    int other = face >= 0 && face < 6 ? (face + 3) % 6 : 0;
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)other,
                           map.depth_cube, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, 7, 5);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    sl_status status = labs->lab7_begin_cube_pass(&map, face);
    GLint bound = 0, viewport[4] = {0}, attached = 0;
    GLboolean writes = GL_FALSE;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &writes);
    out[0] = (GLuint)bound == map.framebuffer;
    out[2] = viewport[2];
    out[3] = viewport[3];
    out[4] = glIsEnabled(GL_DEPTH_TEST);
    out[5] = writes;
    out[1] = 0;
    out[6] = -1;
    if (out[0]) {
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                              GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE, &attached);
        out[1] = attached;
        float depth = -1;
        glBindFramebuffer(GL_READ_FRAMEBUFFER, map.framebuffer);
        glReadPixels(size / 2, size / 2, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
        out[6] = depth;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &map.framebuffer);
    glDeleteTextures(1, &map.depth_cube);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    return status;
}

static sl_status _sl_call_c(const sl_probe_function *f, const float *in, double *out) {
    const sl_lab_functions *labs = &sl_build_lab_functions;
    mat4 m;
    glm_mat4_identity(m);
    sl_status status = SL_FAILED;
    if (strcmp(f->name, "lab1_create_shadow_map") == 0) {
        status = _sl_call_create_shadow_map(labs, (int)in[0], out);
    } else if (strcmp(f->name, "lab1_begin_depth_pass") == 0) {
        status = _sl_call_begin_depth_pass(labs, (int)in[0], out);
    } else if (strcmp(f->name, "lab2_light_view") == 0) {
        sl_light light = _sl_light((int)in[0], in + 1, in + 4);
        sl_aabb bounds;
        _sl_vec3(in + 7, bounds.min);
        _sl_vec3(in + 10, bounds.max);
        status = labs->lab2_light_view(&light, &bounds, m);
        _sl_store_matrix(m, out);
    } else if (strcmp(f->name, "lab2_light_projection") == 0) {
        sl_light light = _sl_light((int)in[0], in + 1, in + 4);
        light.spot_angle_deg = in[7];
        light.near = in[8];
        light.far = in[9];
        sl_aabb bounds;
        _sl_vec3(in + 10, bounds.min);
        _sl_vec3(in + 13, bounds.max);
        vec3 eye, target, up;
        _sl_vec3(in + 16, eye);
        _sl_vec3(in + 19, target);
        _sl_vec3(in + 22, up);
        mat4 view;
        glm_lookat(eye, target, up, view);
        status = labs->lab2_light_projection(&light, &bounds, view, m);
        _sl_store_matrix(m, out);
    } else if (strcmp(f->name, "lab2_shadow_matrix") == 0) {
        mat4 projection, view;
        glm_ortho(in[0], in[1], in[2], in[3], in[4], in[5], projection);
        vec3 eye, target, up;
        _sl_vec3(in + 6, eye);
        _sl_vec3(in + 9, target);
        _sl_vec3(in + 12, up);
        glm_lookat(eye, target, up, view);
        status = labs->lab2_shadow_matrix(projection, view, m);
        _sl_store_matrix(m, out);
    } else if (strcmp(f->name, "lab3_depth_pass_state") == 0) {
        sl_render_params defaults;
        sl_render_params_defaults(&defaults);
        sl_bias_settings bias = defaults.bias;
        bias.mode = (sl_bias_mode)(int)in[0];
        bias.polygon_offset_factor = in[1];
        bias.polygon_offset_units = in[2];
        _sl_neutral_depth_state();
        int previous = (int)in[3];
        if (previous >= 0 && previous < SL_BIAS_MODE_COUNT) {
            /* the mode before: whatever it switched on must not outlive it */
            sl_bias_settings before = bias;
            before.mode = (sl_bias_mode)previous;
            status = labs->lab3_depth_pass_state(&before);
        }
        if (status == SL_OK || previous < 0) status = labs->lab3_depth_pass_state(&bias);
        GLfloat factor = 0, units = 0;
        GLint face = 0;
        glGetFloatv(GL_POLYGON_OFFSET_FACTOR, &factor);
        glGetFloatv(GL_POLYGON_OFFSET_UNITS, &units);
        glGetIntegerv(GL_CULL_FACE_MODE, &face);
        /* factor, units and face only count where their switch is on: left
         * set but disabled, they change nothing */
        out[0] = glIsEnabled(GL_POLYGON_OFFSET_FILL);
        out[1] = out[0] ? factor : 0;
        out[2] = out[0] ? units : 0;
        out[3] = glIsEnabled(GL_CULL_FACE);
        out[4] = out[3] ? face : 0;
        _sl_neutral_depth_state();
    } else if (strcmp(f->name, "lab6_split_distances") == 0) {
        float splits[SL_MAX_CASCADES + 1] = {0};
        int count = (int)in[2];
        status = labs->lab6_split_distances(in[0], in[1], count, in[3], splits);
        for (int i = 0; i <= SL_MAX_CASCADES; i++) out[i] = i <= count ? splits[i] : 0;
    } else if (strcmp(f->name, "lab6_slice_sphere") == 0) {
        sl_camera cam = {.fov_deg = in[6], .near = in[8], .far = in[9]};
        _sl_vec3(in + 0, cam.position);
        _sl_vec3(in + 3, cam.target);
        mat4 view, proj, vp, inv;
        sl_camera_view(&cam, view);
        sl_camera_projection(&cam, in[7], proj);
        glm_mat4_mul(proj, view, vp);
        glm_mat4_inv(vp, inv);
        vec4 sphere = {0, 0, 0, 0};
        status = labs->lab6_slice_sphere(inv, cam.near, cam.far, in[10], in[11], sphere);
        for (int i = 0; i < 4; i++) out[i] = sphere[i];
    } else if (strcmp(f->name, "lab6_cascade_matrices") == 0) {
        sl_light light = _sl_light(SL_LIGHT_DIRECTIONAL, in + 0, in + 0);
        vec4 sphere = {in[3], in[4], in[5], in[6]};
        mat4 view, proj, vp;
        glm_mat4_identity(view);
        glm_mat4_identity(proj);
        status = labs->lab6_cascade_matrices(&light, sphere, in[7], (int)in[8], view, proj);
        glm_mat4_mul(proj, view, vp);
        _sl_store_matrix(vp, out);
    } else if (strcmp(f->name, "lab7_create_cube_map") == 0) {
        status = _sl_call_create_cube_map(labs, (int)in[0], out);
    } else if (strcmp(f->name, "lab7_begin_cube_pass") == 0) {
        status = _sl_call_begin_cube_pass(labs, (int)in[0], (int)in[1], out);
    } else if (strcmp(f->name, "lab7_face_view") == 0) {
        vec3 position;
        _sl_vec3(in + 1, position);
        status = labs->lab7_face_view(position, (int)in[0], m);
        _sl_store_matrix(m, out);
    } else if (strcmp(f->name, "lab7_face_projection") == 0) {
        status = labs->lab7_face_projection(in[0], in[1], m);
        _sl_store_matrix(m, out);
    } else if (strcmp(f->name, "lab4_configure_shadow_texture") == 0) {
        GLuint tex;
        glGenTextures(1, &tex);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 16, 16, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
        /* neither value any mode asks for: what the function sets shows */
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        status = labs->lab4_configure_shadow_texture(tex, (sl_filter_mode)(int)in[0]);
        GLint min = 0, mag = 0;
        glBindTexture(GL_TEXTURE_2D, tex);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &min);
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &mag);
        out[0] = min;
        out[1] = mag;
        glDeleteTextures(1, &tex);
    }
    while (glGetError() != GL_NO_ERROR) {}
    return status;
}

bool sl_probe_pass_run(const sl_probe_table *t, const char *labs_dir, const char *framework_dir, double *outputs,
                       bool *not_implemented, char *err, size_t n) {
    *not_implemented = false;
    const sl_probe_function *f = sl_probe_at(t->function);
    if (!f || t->rows < 1 || t->rows > SL_PROBE_MAX_ROWS) {
        snprintf(err, n, "a malformed probe table");
        return false;
    }
    if (f->glsl) return _sl_run_glsl(f, t, labs_dir, framework_dir, outputs, err, n);
    for (int r = 0; r < t->rows; r++) {
        double *out = outputs + r * f->output_count;
        for (int o = 0; o < f->output_count; o++) out[o] = NAN;
        sl_status status = _sl_call_c(f, t->inputs[r], out);
        if (status == SL_NOT_IMPLEMENTED) *not_implemented = true;
        if (status != SL_OK)
            for (int o = 0; o < f->output_count; o++) out[o] = NAN;
    }
    return true;
}
