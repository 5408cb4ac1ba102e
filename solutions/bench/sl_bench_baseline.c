#include "sl_bench_baseline.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The shaders a tutorial would write: no includes, no defines but the kernel
 * radius, every tap compared in the loop. */
static const char _sl_depth_vs[] = "#version 330 core\n"
                                   "layout(location = 0) in vec3 a_position;\n"
                                   "uniform mat4 u_light_view_projection, u_model;\n"
                                   "void main() { gl_Position = u_light_view_projection * u_model * vec4(a_position, 1.0); }\n";
static const char _sl_depth_fs[] = "#version 330 core\n"
                                   "void main() {}\n";
static const char _sl_camera_vs[] =
    "#version 330 core\n"
    "layout(location = 0) in vec3 a_position;\n"
    "layout(location = 1) in vec3 a_normal;\n"
    "uniform mat4 u_model, u_view, u_projection, u_light_view_projection;\n"
    "out vec3 v_position;\n"
    "out vec3 v_normal;\n"
    "out vec4 v_light_position;\n"
    "void main() {\n"
    "    vec4 world = u_model * vec4(a_position, 1.0);\n"
    "    v_position = world.xyz;\n"
    "    v_normal = transpose(inverse(mat3(u_model))) * a_normal;\n"
    "    v_light_position = u_light_view_projection * world;\n"
    "    gl_Position = u_projection * u_view * world;\n"
    "}\n";
static const char _sl_camera_fs[] =
    "#version 330 core\n"
    "in vec3 v_position;\n"
    "in vec3 v_normal;\n"
    "in vec4 v_light_position;\n"
    "uniform sampler2D u_shadow_map;\n"
    "uniform vec3 u_color, u_light_direction, u_light_color, u_eye;\n"
    "out vec4 frag_color;\n"
    "float shadow(vec4 light_position, vec3 n, vec3 l) {\n"
    "    vec3 p = light_position.xyz / light_position.w * 0.5 + 0.5;\n"
    "    if (p.z > 1.0) return 0.0;\n"
    "    float bias = max(0.005 * (1.0 - dot(n, l)), 0.0005);\n"
    "    vec2 texel = 1.0 / vec2(textureSize(u_shadow_map, 0));\n"
    "    float sum = 0.0;\n"
    "    for (int x = -RADIUS; x <= RADIUS; ++x)\n"
    "        for (int y = -RADIUS; y <= RADIUS; ++y) {\n"
    "            float closest = texture(u_shadow_map, p.xy + vec2(x, y) * texel).r;\n"
    "            sum += p.z - bias > closest ? 1.0 : 0.0;\n"
    "        }\n"
    "    return sum / float((2 * RADIUS + 1) * (2 * RADIUS + 1));\n"
    "}\n"
    "void main() {\n"
    "    vec3 n = normalize(v_normal), l = normalize(-u_light_direction);\n"
    "    vec3 h = normalize(l + normalize(u_eye - v_position));\n"
    "    float diffuse = max(dot(n, l), 0.0), specular = pow(max(dot(n, h), 0.0), 32.0);\n"
    "    float lit = 1.0 - shadow(v_light_position, n, l);\n"
    "    vec3 c = u_color * (0.15 + lit * diffuse * u_light_color) + lit * specular * 0.2 * u_light_color;\n"
    "    frag_color = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);\n"
    "}\n";

static GLuint _sl_compile(GLenum type, const char *const *sources, int count, char *err, size_t err_size) {
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, count, sources, NULL);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetShaderInfoLog(shader, sizeof log, NULL, log);
        snprintf(err, err_size, "baseline shader: %s", log);
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

static GLuint _sl_link(const char *vs, const char *fs, const char *defines, char *err, size_t err_size) {
    /* #version must come first: split it off and put the defines after it */
    const char *vs_rest = strchr(vs, '\n') + 1, *fs_rest = strchr(fs, '\n') + 1;
    const char *v[] = {"#version 330 core\n", defines, vs_rest};
    const char *f[] = {"#version 330 core\n", defines, fs_rest};
    GLuint vsh = _sl_compile(GL_VERTEX_SHADER, v, 3, err, err_size);
    GLuint fsh = vsh ? _sl_compile(GL_FRAGMENT_SHADER, f, 3, err, err_size) : 0;
    if (!fsh) {
        if (vsh) glDeleteShader(vsh);
        return 0;
    }
    GLuint program = glCreateProgram();
    glAttachShader(program, vsh);
    glAttachShader(program, fsh);
    glLinkProgram(program);
    glDeleteShader(vsh);
    glDeleteShader(fsh);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048];
        glGetProgramInfoLog(program, sizeof log, NULL, log);
        snprintf(err, err_size, "baseline program: %s", log);
        glDeleteProgram(program);
        return 0;
    }
    return program;
}

bool sl_bench_baseline_init(sl_bench_baseline *b, const sl_scene *scene, int map_size, int radius, char *err,
                            size_t err_size) {
    memset(b, 0, sizeof *b);
    b->map_size = map_size;
    char defines[64];
    snprintf(defines, sizeof defines, "#define RADIUS %d\n", radius);
    b->depth_program = _sl_link(_sl_depth_vs, _sl_depth_fs, "", err, err_size);
    b->camera_program = b->depth_program ? _sl_link(_sl_camera_vs, _sl_camera_fs, defines, err, err_size) : 0;
    if (!b->camera_program) {
        sl_bench_baseline_destroy(b);
        return false;
    }
    glGenTextures(1, &b->depth_texture);
    glBindTexture(GL_TEXTURE_2D, b->depth_texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, map_size, map_size, 0, GL_DEPTH_COMPONENT, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glGenFramebuffers(1, &b->framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, b->framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, b->depth_texture, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!complete) {
        snprintf(err, err_size, "baseline: the depth framebuffer is not complete");
        sl_bench_baseline_destroy(b);
        return false;
    }
    for (int i = 0; i < scene->object_count; i++) {
        sl_mesh_data data = sl_mesh_for_object(&scene->objects[i]);
        bool ok = sl_mesh_upload(&b->meshes[i], &data);
        sl_mesh_data_free(&data);
        if (!ok) {
            snprintf(err, err_size, "baseline: could not build the mesh of object %d", i);
            sl_bench_baseline_destroy(b);
            return false;
        }
        b->mesh_count = i + 1;
    }
    mat4 view, projection;
    sl_light_default_matrices(&scene->light, &scene->bounds, view, projection);
    glm_mat4_mul(projection, view, b->light_view_projection);
    glGenQueries(3, b->queries);
    return true;
}

static void _sl_draw_meshes(const sl_bench_baseline *b, const sl_scene *scene, GLint model, GLint color) {
    for (int i = 0; i < b->mesh_count; i++) {
        glUniformMatrix4fv(model, 1, GL_FALSE, (const float *)scene->objects[i].model);
        if (color >= 0) glUniform3fv(color, 1, scene->objects[i].color);
        sl_mesh_draw(&b->meshes[i]);
    }
}

void sl_bench_baseline_draw(sl_bench_baseline *b, const sl_scene *scene, int width, int height, double pass_ms[2]) {
    pass_ms[0] = pass_ms[1] = 0;
    GLint available = 0;
    glGetQueryObjectiv(b->queries[2], GL_QUERY_RESULT_AVAILABLE, &available);
    if (available) {
        GLuint64 t[3];
        for (int i = 0; i < 3; i++) glGetQueryObjectui64v(b->queries[i], GL_QUERY_RESULT, &t[i]);
        pass_ms[0] = (double)(t[1] - t[0]) * 1e-6;
        pass_ms[1] = (double)(t[2] - t[1]) * 1e-6;
    }
    glQueryCounter(b->queries[0], GL_TIMESTAMP);
    /* 1. depth from the light */
    glBindFramebuffer(GL_FRAMEBUFFER, b->framebuffer);
    glViewport(0, 0, b->map_size, b->map_size);
    glEnable(GL_DEPTH_TEST);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(b->depth_program);
    glUniformMatrix4fv(glGetUniformLocation(b->depth_program, "u_light_view_projection"), 1, GL_FALSE,
                       (const float *)b->light_view_projection);
    _sl_draw_meshes(b, scene, glGetUniformLocation(b->depth_program, "u_model"), -1);
    glQueryCounter(b->queries[1], GL_TIMESTAMP);
    /* 2. the camera's picture */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    glClearColor(0.05f, 0.05f, 0.08f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    GLuint p = b->camera_program;
    glUseProgram(p);
    mat4 view, projection;
    sl_camera_view(&scene->camera, view);
    sl_camera_projection(&scene->camera, (float)width / (float)height, projection);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_view"), 1, GL_FALSE, (const float *)view);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_projection"), 1, GL_FALSE, (const float *)projection);
    glUniformMatrix4fv(glGetUniformLocation(p, "u_light_view_projection"), 1, GL_FALSE,
                       (const float *)b->light_view_projection);
    glUniform3fv(glGetUniformLocation(p, "u_light_direction"), 1, scene->light.direction);
    glUniform3fv(glGetUniformLocation(p, "u_light_color"), 1, scene->light.color);
    glUniform3fv(glGetUniformLocation(p, "u_eye"), 1, scene->camera.position);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, b->depth_texture);
    glUniform1i(glGetUniformLocation(p, "u_shadow_map"), 0);
    _sl_draw_meshes(b, scene, glGetUniformLocation(p, "u_model"), glGetUniformLocation(p, "u_color"));
    glQueryCounter(b->queries[2], GL_TIMESTAMP);
}

void sl_bench_baseline_destroy(sl_bench_baseline *b) {
    for (int i = 0; i < b->mesh_count; i++) sl_mesh_destroy(&b->meshes[i]);
    if (b->queries[0]) glDeleteQueries(3, b->queries);
    if (b->framebuffer) glDeleteFramebuffers(1, &b->framebuffer);
    if (b->depth_texture) glDeleteTextures(1, &b->depth_texture);
    if (b->depth_program) glDeleteProgram(b->depth_program);
    if (b->camera_program) glDeleteProgram(b->camera_program);
    memset(b, 0, sizeof *b);
}

static void *_sl_create(const sl_scene *scene, int map_size, int pcf_radius, char *err, size_t err_size) {
    sl_bench_baseline *b = calloc(1, sizeof *b);
    if (!b) {
        snprintf(err, err_size, "out of memory");
        return NULL;
    }
    if (sl_bench_baseline_init(b, scene, map_size, pcf_radius, err, err_size)) return b;
    free(b);
    return NULL;
}

static void _sl_draw(void *b, const sl_scene *scene, int width, int height, double pass_ms[2]) {
    sl_bench_baseline_draw(b, scene, width, height, pass_ms);
}

static void _sl_destroy(void *b) {
    sl_bench_baseline_destroy(b);
    free(b);
}

const sl_bench_plain_gl sl_bench_baseline_program = {_sl_create, _sl_draw, _sl_destroy};
