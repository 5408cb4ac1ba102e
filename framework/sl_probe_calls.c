#include "sl_probe_calls.h"

#include <stdbool.h>

#include "sl_gl.h"
#include "sl_labs.h"
#include "sl_probe.h"

/* Each row runner calls this build's lab function (sl_build_lab_functions) on one input row and writes what
 * the probe reads back: the values it returns, or the GL state it set. */

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

/* Whether `framebuffer` is bound for drawing (1); 2 where it is bound for reading alone (GL_READ_FRAMEBUFFER:
 * a pass then draws elsewhere), 0 where not at all. Only 1 is right: the other two tell the message apart. */
static double _sl_bound_for_drawing(GLuint framebuffer) {
    GLint draw = 0, read = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
    return (GLuint)draw == framebuffer ? 1 : (GLuint)read == framebuffer ? 2 : 0;
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
    glViewport(0, 0, SL_PROBE_STALE_VIEWPORT_WIDTH, SL_PROBE_STALE_VIEWPORT_HEIGHT);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_FALSE);
    _sl_neutral_depth_state(); /* no culling: a pass that switches it on culls faces lab 1 draws */
    sl_status status = labs->lab1_begin_depth_pass(&map);
    GLint viewport[4] = {0}, func = 0;
    GLboolean writes = GL_FALSE;
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_DEPTH_FUNC, &func);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &writes);
    out[0] = _sl_bound_for_drawing(map.framebuffer);
    out[1] = viewport[2];
    out[2] = viewport[3];
    out[3] = glIsEnabled(GL_DEPTH_TEST);
    out[4] = func == GL_LEQUAL ? GL_LESS : func; /* both keep the nearest depth: equally right */
    out[5] = writes;
    float depth = -1;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, map.framebuffer);
    glReadPixels(size / 2, size / 2, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
    out[6] = depth;
    out[7] = glIsEnabled(GL_CULL_FACE);
    _sl_neutral_depth_state();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &map.framebuffer);
    glDeleteRenderbuffers(2, renderbuffers);
    glDeleteTextures(1, &map.depth_texture);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    return status;
}

/* glCheckFramebufferStatus as lab code calls it during a probe: which framebuffers it was asked about
 * (the one bound to the target's binding when asked). Lab code calls GL through the loader's pointers
 * (sl_gl.h), so the probe can stand in front of this one while the function runs. */
static PFNGLCHECKFRAMEBUFFERSTATUSPROC _sl_status_function;
static GLuint _sl_status_asked_of[8];
static int _sl_status_asked;

static GLenum APIENTRY _sl_check_status_watched(GLenum target) {
    GLint bound = 0;
    glGetIntegerv(target == GL_READ_FRAMEBUFFER ? GL_READ_FRAMEBUFFER_BINDING : GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    if (_sl_status_asked < (int)(sizeof _sl_status_asked_of / sizeof _sl_status_asked_of[0]))
        _sl_status_asked_of[_sl_status_asked] = (GLuint)bound;
    _sl_status_asked++;
    return _sl_status_function(target);
}

/* 1 when the status was asked of `framebuffer` (among other asks), 0 when asked of others only, -1 never. */
static double _sl_status_asked_of_map(GLuint framebuffer) {
    if (!_sl_status_asked) return -1;
    int recorded = _sl_status_asked < 8 ? _sl_status_asked : 8;
    for (int i = 0; i < recorded; i++)
        if (framebuffer && _sl_status_asked_of[i] == framebuffer) return 1;
    return 0;
}

/* The map's framebuffer as GL sees it after the function: its status while bound, and whether the depth
 * texture sits at the stencil attachment as well (GL_DEPTH_STENCIL_ATTACHMENT attaches at both). */
static void _sl_read_map_framebuffer(const sl_shadow_map *map, double *status, double *stencil) {
    *status = 0, *stencil = 0;
    if (!map->framebuffer || !glIsFramebuffer(map->framebuffer)) return;
    glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer);
    *status = _sl_status_function(GL_FRAMEBUFFER);
    GLint type = GL_NONE, name = 0;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE,
                                          &type);
    if (type == GL_TEXTURE)
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    *stencil = type == GL_TEXTURE && map->depth_texture && (GLuint)name == map->depth_texture;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    while (glGetError() != GL_NO_ERROR) {}
}

/* lab1_create_shadow_map(size): the map's filtering and wrapping, as glGet*
 * reports them: what a lookup of a later lab reads between texels and past
 * the map's edge; and the texture's size, which must be the argument's, as
 * must map->size. Then the framebuffer: complete or not, the depth texture
 * at the stencil attachment too or not, whether the function asked the
 * status of the map's framebuffer (bound) and what it returned. */
static sl_status _sl_call_create_shadow_map(const sl_lab_functions *labs, int size, double *out) {
    sl_shadow_map map = {0};
    _sl_status_function = _sl_glCheckFramebufferStatus;
    _sl_status_asked = 0;
    _sl_glCheckFramebufferStatus = _sl_check_status_watched;
    sl_status status = labs->lab1_create_shadow_map(size, &map);
    _sl_glCheckFramebufferStatus = _sl_status_function;
    while (glGetError() != GL_NO_ERROR) {}
    _sl_read_map_framebuffer(&map, &out[8], &out[9]);
    out[10] = _sl_status_asked_of_map(map.framebuffer);
    out[11] = status == SL_OK;
    if (map.depth_texture && glIsTexture(map.depth_texture)) {
        GLint min = 0, mag = 0, s = 0, t = 0, width = 0, height = 0;
        GLfloat border[4] = {0, 0, 0, 0};
        glBindTexture(GL_TEXTURE_2D, map.depth_texture);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &height);
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
        out[5] = width;
        out[6] = height;
    }
    out[7] = map.size; /* what lab1_begin_depth_pass sizes the viewport by */
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
    glViewport(0, 0, SL_PROBE_STALE_VIEWPORT_WIDTH, SL_PROBE_STALE_VIEWPORT_HEIGHT);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    /* the framework's depth function, GL_LESS: the README leaves it to the function, so only one it
     * changes to a function that does not keep the nearest depth is wrong */
    glDepthFunc(GL_LESS);
    sl_status status = labs->lab7_begin_cube_pass(&map, face);
    GLint viewport[4] = {0}, attached = 0, func = 0;
    GLboolean writes = GL_FALSE;
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &writes);
    out[0] = _sl_bound_for_drawing(map.framebuffer);
    out[2] = viewport[2];
    out[3] = viewport[3];
    out[4] = glIsEnabled(GL_DEPTH_TEST);
    out[5] = writes;
    out[1] = 0;
    out[6] = -1;
    /* the viewport's corner: each face is its own size x size attachment, so (0, 0) whatever the face */
    out[7] = viewport[0];
    out[8] = viewport[1];
    glGetIntegerv(GL_DEPTH_FUNC, &func);
    out[9] = func == GL_LEQUAL ? GL_LESS : func; /* both keep the nearest depth: equally right */
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

/* ---- one row of each function ---- */

static sl_status _sl_row_lab1_create_shadow_map(const float *in, double *out) {
    return _sl_call_create_shadow_map(&sl_build_lab_functions, (int)in[0], out);
}

static sl_status _sl_row_lab1_begin_depth_pass(const float *in, double *out) {
    return _sl_call_begin_depth_pass(&sl_build_lab_functions, (int)in[0], out);
}

static sl_status _sl_row_lab2_light_view(const float *in, double *out) {
    sl_status status = SL_FAILED;
    mat4 m;
    glm_mat4_identity(m);
    sl_light light = _sl_light((int)in[0], in + 1, in + 4);
    sl_aabb bounds;
    _sl_vec3(in + 7, bounds.min);
    _sl_vec3(in + 10, bounds.max);
    status = sl_build_lab_functions.lab2_light_view(&light, &bounds, m);
    _sl_store_matrix(m, out);
    return status;
}

static sl_status _sl_row_lab2_light_projection(const float *in, double *out) {
    sl_status status = SL_FAILED;
    mat4 m;
    glm_mat4_identity(m);
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
    status = sl_build_lab_functions.lab2_light_projection(&light, &bounds, view, m);
    _sl_store_matrix(m, out);
    return status;
}

static sl_status _sl_row_lab2_shadow_matrix(const float *in, double *out) {
    sl_status status = SL_FAILED;
    mat4 m;
    glm_mat4_identity(m);
    mat4 projection, view;
    glm_ortho(in[0], in[1], in[2], in[3], in[4], in[5], projection);
    vec3 eye, target, up;
    _sl_vec3(in + 6, eye);
    _sl_vec3(in + 9, target);
    _sl_vec3(in + 12, up);
    glm_lookat(eye, target, up, view);
    status = sl_build_lab_functions.lab2_shadow_matrix(projection, view, m);
    _sl_store_matrix(m, out);
    return status;
}

static sl_status _sl_row_lab3_depth_pass_state(const float *in, double *out) {
    sl_status status = SL_FAILED;
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
        status = sl_build_lab_functions.lab3_depth_pass_state(&before);
    }
    if (status == SL_OK || previous < 0) status = sl_build_lab_functions.lab3_depth_pass_state(&bias);
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
    return status;
}

/* Which faces the current state culls, as front or back for the current winding: 1 front, 2 back, 3 both,
 * 0 none (with culling off, the faces glCullFace chose, the same way, in *chosen). */
static int _sl_faces_culled(int *chosen) {
    GLint mode = GL_BACK, winding = GL_CCW;
    glGetIntegerv(GL_CULL_FACE_MODE, &mode);
    glGetIntegerv(GL_FRONT_FACE, &winding);
    int faces = mode == GL_FRONT_AND_BACK ? 3 : (mode == GL_FRONT) == (winding == GL_CCW) ? 1 : 2;
    *chosen = faces;
    return glIsEnabled(GL_CULL_FACE) ? faces : 0;
}

static sl_status _sl_row_lab3_second_depth_state(const float *in, double *out) {
    /* the state lab 1's pass leaves (depth test on, nearest kept, writes on), culling as the row says */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glFrontFace(GL_CCW);
    _sl_neutral_depth_state();
    if ((int)in[0] == 1) glEnable(GL_CULL_FACE); /* glCullFace(GL_BACK) from the neutral state */
    sl_status status = sl_build_lab_functions.lab3_second_depth_state();
    int chosen = 0, culled = _sl_faces_culled(&chosen);
    GLint func = 0;
    GLboolean writes = GL_FALSE;
    glGetIntegerv(GL_DEPTH_FUNC, &func);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &writes);
    out[0] = (culled & 1) != 0;
    out[1] = (culled & 2) != 0;
    out[2] = culled ? 0 : chosen; /* what glCullFace chose, where GL_CULL_FACE never switched it on */
    out[3] = glIsEnabled(GL_DEPTH_TEST);
    out[4] = func == GL_LEQUAL ? GL_LESS : func; /* both keep the nearest of the faces drawn */
    out[5] = writes;
    glFrontFace(GL_CCW);
    _sl_neutral_depth_state();
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    return status;
}

static sl_status _sl_row_lab6_split_distances(const float *in, double *out) {
    sl_status status = SL_FAILED;
    float splits[SL_MAX_CASCADES + 1] = {0};
    int count = (int)in[2];
    status = sl_build_lab_functions.lab6_split_distances(in[0], in[1], count, in[3], splits);
    for (int i = 0; i <= SL_MAX_CASCADES; i++) out[i] = i <= count ? splits[i] : 0;
    return status;
}

static sl_status _sl_row_lab6_slice_sphere(const float *in, double *out) {
    sl_status status = SL_FAILED;
    sl_camera cam = {.fov_deg = in[6], .near = in[8], .far = in[9]};
    _sl_vec3(in + 0, cam.position);
    _sl_vec3(in + 3, cam.target);
    mat4 view, proj, vp, inv;
    sl_camera_view(&cam, view);
    sl_camera_projection(&cam, in[7], proj);
    glm_mat4_mul(proj, view, vp);
    glm_mat4_inv(vp, inv);
    vec4 sphere = {0, 0, 0, 0};
    status = sl_build_lab_functions.lab6_slice_sphere(inv, cam.near, cam.far, in[10], in[11], sphere);
    for (int i = 0; i < 4; i++) out[i] = sphere[i];
    return status;
}

static sl_status _sl_row_lab6_cascade_matrices(const float *in, double *out) {
    sl_status status = SL_FAILED;
    sl_light light = _sl_light(SL_LIGHT_DIRECTIONAL, in + 0, in + 0);
    vec4 sphere = {in[3], in[4], in[5], in[6]};
    mat4 view, proj, vp;
    glm_mat4_identity(view);
    glm_mat4_identity(proj);
    status = sl_build_lab_functions.lab6_cascade_matrices(&light, sphere, in[7], (int)in[8], view, proj);
    glm_mat4_mul(proj, view, vp);
    _sl_store_matrix(vp, out);
    return status;
}

static sl_status _sl_row_lab7_create_cube_map(const float *in, double *out) {
    return _sl_call_create_cube_map(&sl_build_lab_functions, (int)in[0], out);
}

static sl_status _sl_row_lab7_begin_cube_pass(const float *in, double *out) {
    return _sl_call_begin_cube_pass(&sl_build_lab_functions, (int)in[0], (int)in[1], out);
}

static sl_status _sl_row_lab7_face_view(const float *in, double *out) {
    sl_status status = SL_FAILED;
    mat4 m;
    glm_mat4_identity(m);
    vec3 position;
    _sl_vec3(in + 1, position);
    status = sl_build_lab_functions.lab7_face_view(position, (int)in[0], m);
    _sl_store_matrix(m, out);
    return status;
}

static sl_status _sl_row_lab7_face_projection(const float *in, double *out) {
    mat4 m;
    glm_mat4_identity(m);
    sl_status status = sl_build_lab_functions.lab7_face_projection(in[0], in[1], m);
    _sl_store_matrix(m, out);
    return status;
}

static sl_status _sl_row_lab4_configure_shadow_texture(const float *in, double *out) {
    sl_status status = SL_FAILED;
    GLuint tex;
    glGenTextures(1, &tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 16, 16, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
    /* neither value any mode asks for: what the function sets shows */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    status = sl_build_lab_functions.lab4_configure_shadow_texture(tex, (sl_filter_mode)(int)in[0]);
    GLint min = 0, mag = 0;
    glBindTexture(GL_TEXTURE_2D, tex);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &min);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &mag);
    out[0] = min;
    out[1] = mag;
    glDeleteTextures(1, &tex);
    return status;
}

/* lab5_create_moments_target(size): each moments texture's format, size, filters and wrap modes, whether
 * each framebuffer holds its own texture at GL_COLOR_ATTACHMENT0, framebuffer[0]'s depth, as glGet* reports
 * them. */
static void _sl_moments_texture_state(GLuint texture, double *format, double *width, double *params) {
    *format = 0;
    for (int i = 0; i < 4; i++) params[i] = 0;
    if (!texture || !glIsTexture(texture)) return;
    glBindTexture(GL_TEXTURE_2D, texture);
    if (glGetError() != GL_NO_ERROR) return; /* not a 2D texture */
    GLint f = 0, w = 0, v[4] = {0};
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, &v[0]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, &v[1]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, &v[2]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, &v[3]);
    *format = f;
    if (width) *width = w;
    for (int i = 0; i < 4; i++) params[i] = v[i];
    glBindTexture(GL_TEXTURE_2D, 0);
}

static sl_status _sl_row_lab5_create_moments_target(const float *in, double *out) {
    int size = (int)in[0];
    sl_moments_target target = {0};
    sl_status status = sl_build_lab_functions.lab5_create_moments_target(size, &target);
    while (glGetError() != GL_NO_ERROR) {}
    for (int o = 0; o < 16; o++) out[o] = 0;
    _sl_moments_texture_state(target.moments[0], &out[0], &out[2], &out[3]);
    _sl_moments_texture_state(target.moments[1], &out[1], NULL, &out[7]);
    bool own[2] = {false, false};
    for (int i = 0; i < 2; i++) {
        if (!target.framebuffer[i] || !glIsFramebuffer(target.framebuffer[i])) continue;
        glBindFramebuffer(GL_FRAMEBUFFER, target.framebuffer[i]);
        GLint type = 0, name = 0;
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        if (type == GL_TEXTURE)
            glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                                  GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
        own[i] = type == GL_TEXTURE && (GLuint)name == target.moments[i] && target.moments[i] != 0;
        if (i == 0) {
            GLint depth_type = 0, bits = 0;
            glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                                  GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &depth_type);
            if (depth_type != GL_NONE)
                glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                                      GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &bits);
            out[12] = bits >= 16; /* any depth the moments pass can test with: 16, 24 or 32 bits */
        }
        out[13] += glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
    out[11] = own[0] && own[1];
    out[14] = target.size;
    out[15] = own[0]; /* which framebuffer lost its texture, when one did */
    while (glGetError() != GL_NO_ERROR) {}
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(2, target.framebuffer);
    glDeleteTextures(2, target.moments);
    if (target.depth) glDeleteRenderbuffers(1, &target.depth);
    return status;
}

/* A moments target of `size` made here as lab 5's contract describes it (two GL_RG32F textures, each at
 * its framebuffer's GL_COLOR_ATTACHMENT0, a depth renderbuffer on framebuffer[0]): what the target is made
 * of is lab5_create_moments_target's to get right, and this file ships to students. Every texel holds
 * (0.3, 0.3) and framebuffer[0]'s depths 0.5, so a clear shows. */
static void _sl_probe_moments_target(int size, sl_moments_target *target) {
    target->size = size;
    glGenRenderbuffers(1, &target->depth);
    glBindRenderbuffer(GL_RENDERBUFFER, target->depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, size, size);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glGenTextures(2, target->moments);
    glGenFramebuffers(2, target->framebuffer);
    for (int i = 0; i < 2; i++) {
        glBindTexture(GL_TEXTURE_2D, target->moments[i]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, size, size, 0, GL_RG, GL_FLOAT, NULL);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glBindFramebuffer(GL_FRAMEBUFFER, target->framebuffer[i]);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target->moments[i], 0);
        if (i == 0) glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, target->depth);
        glViewport(0, 0, size, size);
        glClearColor(0.3f, 0.3f, 0.3f, 0.3f);
        glClearDepth(0.5);
        glDepthMask(GL_TRUE);
        glClear(GL_COLOR_BUFFER_BIT | (i == 0 ? GL_DEPTH_BUFFER_BIT : 0));
    }
    glBindTexture(GL_TEXTURE_2D, 0);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
}

static void _sl_free_probe_moments_target(sl_moments_target *target) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(2, target->framebuffer);
    glDeleteTextures(2, target->moments);
    glDeleteRenderbuffers(1, &target->depth);
    glActiveTexture(GL_TEXTURE0);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

/* 0 or 1: which of the target's framebuffers is bound for drawing; -1 another (or none). */
static double _sl_target_framebuffer_bound(const sl_moments_target *target) {
    GLint bound = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    return (GLuint)bound == target->framebuffer[0] ? 0 : (GLuint)bound == target->framebuffer[1] ? 1 : -1;
}

/* lab5_begin_moments_pass on a probe's target, from a state wrong in every way the function must fix (no
 * framebuffer bound, a 7x5 viewport, the depth test off with GL_ALWAYS, depth writes off, a clear colour
 * of its own): which framebuffer it binds, the viewport, the depth state, and what framebuffer[0] holds
 * afterwards (its depth and its moments at the centre: a clear to "nothing in front" shows as 1, (1, 1)). */
static sl_status _sl_row_lab5_begin_moments_pass(const float *in, double *out) {
    int size = (int)in[0];
    sl_moments_target target = {0};
    _sl_probe_moments_target(size, &target);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, SL_PROBE_STALE_VIEWPORT_WIDTH, SL_PROBE_STALE_VIEWPORT_HEIGHT);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_FALSE);
    glClearColor(0.6f, 0.1f, 0.2f, 0.4f);
    _sl_neutral_depth_state();
    sl_status status = sl_build_lab_functions.lab5_begin_moments_pass(&target);
    GLint viewport[4] = {0}, func = 0;
    GLboolean writes = GL_FALSE;
    out[0] = _sl_target_framebuffer_bound(&target);
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_DEPTH_FUNC, &func);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &writes);
    out[1] = viewport[2];
    out[2] = viewport[3];
    out[3] = glIsEnabled(GL_DEPTH_TEST);
    out[4] = func == GL_LEQUAL ? GL_LESS : func; /* both keep the nearest depth: equally right */
    out[5] = writes;
    float depth = -1, moments[2] = {-1, -1};
    glBindFramebuffer(GL_READ_FRAMEBUFFER, target.framebuffer[0]);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(size / 2, size / 2, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
    glReadPixels(size / 2, size / 2, 1, 1, GL_RG, GL_FLOAT, moments);
    out[6] = depth;
    out[7] = moments[0];
    out[8] = moments[1];
    while (glGetError() != GL_NO_ERROR) {}
    glClearColor(0, 0, 0, 0);
    _sl_neutral_depth_state();
    _sl_free_probe_moments_target(&target);
    return status;
}

/* lab5_begin_blur_pass(direction) on a probe's target, from a wrong state (no framebuffer bound, a 7x5
 * viewport, the depth test on, texture unit 2 active with nothing on unit 0): which framebuffer it draws
 * into, which moments texture unit 0 holds for the blur to read, the viewport, the depth test. */
static sl_status _sl_row_lab5_begin_blur_pass(const float *in, double *out) {
    int direction = (int)in[0], size = (int)in[1];
    sl_moments_target target = {0};
    _sl_probe_moments_target(size, &target);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, SL_PROBE_STALE_VIEWPORT_WIDTH, SL_PROBE_STALE_VIEWPORT_HEIGHT);
    glEnable(GL_DEPTH_TEST);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE2);
    sl_status status = sl_build_lab_functions.lab5_begin_blur_pass(&target, direction);
    GLint viewport[4] = {0}, texture = 0;
    out[0] = _sl_target_framebuffer_bound(&target);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
    out[1] = (GLuint)texture == target.moments[0] ? 0 : (GLuint)texture == target.moments[1] ? 1 : -1;
    glGetIntegerv(GL_VIEWPORT, viewport);
    out[2] = viewport[2];
    out[3] = viewport[3];
    out[4] = glIsEnabled(GL_DEPTH_TEST);
    while (glGetError() != GL_NO_ERROR) {}
    glBindTexture(GL_TEXTURE_2D, 0);
    glDisable(GL_DEPTH_TEST);
    _sl_free_probe_moments_target(&target);
    return status;
}

/* lab1_destroy_shadow_map and lab7_destroy_cube_map on objects the probe makes (a framebuffer and a texture
 * of the map's kind, made by binding them: how a map is made is the create steps' to write, and this file
 * ships to students), with a texture and a framebuffer of the probe's own beside them: whether the map's
 * objects are gone, whether its fields are 0, and whether the others are untouched. */
static sl_status _sl_call_destroy(int lab, int size, double *out) {
    GLuint bystanders[2] = {0}, framebuffer = 0, texture = 0;
    GLenum target = lab == 7 ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
    glGenTextures(1, &bystanders[0]);
    glBindTexture(GL_TEXTURE_2D, bystanders[0]);
    glGenFramebuffers(1, &bystanders[1]);
    glBindFramebuffer(GL_FRAMEBUFFER, bystanders[1]);
    glGenTextures(1, &texture);
    glBindTexture(target, texture);
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindTexture(target, 0);
    /* each field on its own, so a message can say which one is left */
    bool zeroed[3];
    if (lab == 7) {
        sl_cube_map map = {.framebuffer = framebuffer, .depth_cube = texture, .size = size};
        sl_build_lab_functions.lab7_destroy_cube_map(&map);
        zeroed[0] = map.framebuffer == 0, zeroed[1] = map.depth_cube == 0, zeroed[2] = map.size == 0;
    } else {
        sl_shadow_map map = {.framebuffer = framebuffer, .depth_texture = texture, .size = size};
        sl_build_lab_functions.lab1_destroy_shadow_map(&map);
        zeroed[0] = map.framebuffer == 0, zeroed[1] = map.depth_texture == 0, zeroed[2] = map.size == 0;
    }
    while (glGetError() != GL_NO_ERROR) {}
    out[0] = !glIsFramebuffer(framebuffer);
    out[1] = !glIsTexture(texture);
    for (int i = 0; i < 3; i++) out[2 + i] = zeroed[i];
    out[5] = glIsTexture(bystanders[0]) && glIsFramebuffer(bystanders[1]);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &texture);
    glDeleteFramebuffers(1, &bystanders[1]);
    glDeleteTextures(1, &bystanders[0]);
    return SL_OK; /* a void function: what it did is all there is to read */
}

static sl_status _sl_row_lab1_destroy_shadow_map(const float *in, double *out) {
    return _sl_call_destroy(1, (int)in[0], out);
}

static sl_status _sl_row_lab7_destroy_cube_map(const float *in, double *out) {
    return _sl_call_destroy(7, (int)in[0], out);
}

/* ---- each lab's list, for its technique's descriptor ---- */

const sl_technique_probe sl_lab1_probes[] = {
    {.function = "lab1_create_shadow_map", .run_row = _sl_row_lab1_create_shadow_map},
    {.function = "lab1_begin_depth_pass", .run_row = _sl_row_lab1_begin_depth_pass},
    {.function = "lab1_destroy_shadow_map", .run_row = _sl_row_lab1_destroy_shadow_map},
    {0},
};
const sl_technique_probe sl_lab2_probes[] = {
    {.function = "lab2_light_view", .run_row = _sl_row_lab2_light_view},
    {.function = "lab2_light_projection", .run_row = _sl_row_lab2_light_projection},
    {.function = "lab2_shadow_matrix", .run_row = _sl_row_lab2_shadow_matrix},
    {0},
};
const sl_technique_probe sl_lab3_probes[] = {
    {.function = "lab3_depth_pass_state", .run_row = _sl_row_lab3_depth_pass_state},
    {.function = "lab3_second_depth_state", .run_row = _sl_row_lab3_second_depth_state},
    {0},
};
const sl_technique_probe sl_lab4_probes[] = {
    {.function = "lab4_configure_shadow_texture", .run_row = _sl_row_lab4_configure_shadow_texture},
    {0},
};
const sl_technique_probe sl_lab5_probes[] = {
    {.function = "lab5_create_moments_target", .run_row = _sl_row_lab5_create_moments_target},
    {.function = "lab5_begin_moments_pass", .run_row = _sl_row_lab5_begin_moments_pass},
    {.function = "lab5_begin_blur_pass", .run_row = _sl_row_lab5_begin_blur_pass},
    {0},
};
const sl_technique_probe sl_lab6_probes[] = {
    {.function = "lab6_split_distances", .run_row = _sl_row_lab6_split_distances},
    {.function = "lab6_slice_sphere", .run_row = _sl_row_lab6_slice_sphere},
    {.function = "lab6_cascade_matrices", .run_row = _sl_row_lab6_cascade_matrices},
    {0},
};
const sl_technique_probe sl_lab7_probes[] = {
    {.function = "lab7_create_cube_map", .run_row = _sl_row_lab7_create_cube_map},
    {.function = "lab7_begin_cube_pass", .run_row = _sl_row_lab7_begin_cube_pass},
    {.function = "lab7_face_view", .run_row = _sl_row_lab7_face_view},
    {.function = "lab7_face_projection", .run_row = _sl_row_lab7_face_projection},
    {.function = "lab7_destroy_cube_map", .run_row = _sl_row_lab7_destroy_cube_map},
    {0},
};
