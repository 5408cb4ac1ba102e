#define _POSIX_C_SOURCE 200809L
#include "sl_case_view.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_case.h"
#include "sl_compare.h"
#include "sl_context.h"
#include "sl_lab5_vsm.h"
#include "sl_lab7_cube.h"
#include "sl_renderer.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#ifndef SL_GRADER_DIR
#define SL_GRADER_DIR "grader"
#endif

enum { _SL_STUDENT, _SL_REFERENCE, _SL_DIFF, _SL_PANELS };

#define _SL_MAX_SHOWN 16

typedef struct _sl_case_view {
    sl_case c;
    const sl_check *check;        /* the check shown */
    const sl_check *shown[_SL_MAX_SHOWN]; /* every check with a picture, in the case's order (C cycles) */
    int shown_count, shown_index;
    const char *references_dir;
    sl_image reference;
    int panel_size[_SL_PANELS][2]; /* each panel's picture size, drawn with its aspect kept */
    double reference_flicker;      /* flicker: the share of the reference's pixels that change along the path */
    sl_context *ctx;
    sl_renderer renderer;
    sl_program panel_program;
    GLuint textures[_SL_PANELS], vao, target_fbo, target_texture, target_depth;
    bool side_by_side, show_reference, show_diff;
    int scale;
    char summary[256];
} _sl_case_view;

/* Checks whose capture is a picture the reference can be set beside (probes and
 * matrices are numbers). Flicker's capture is every frame of a camera path,
 * stacked: it is shown as its last frame with what changed along the path in red. */
static bool _sl_has_picture(sl_check_kind k) {
    switch (k) {
    case SL_CHECK_VISIBILITY: case SL_CHECK_PENUMBRA: case SL_CHECK_BLEEDING: case SL_CHECK_DEPTH_MAP:
    case SL_CHECK_IMAGE: case SL_CHECK_MOMENTS: case SL_CHECK_MOMENTS_BLURRED: case SL_CHECK_CASCADE_INDEX:
    case SL_CHECK_CUBE_FACE: case SL_CHECK_FLICKER:
        return true;
    default:
        return false;
    }
}

/* Maps and per-texel buffers are square and shown scaled; pictures at the camera's size. */
static bool _sl_is_map(sl_check_kind k) {
    return k == SL_CHECK_DEPTH_MAP || k == SL_CHECK_MOMENTS || k == SL_CHECK_MOMENTS_BLURRED || k == SL_CHECK_CUBE_FACE;
}

/* What the panels show, for the title and the terminal. */
static const char *_sl_legend(sl_check_kind k) {
    switch (k) {
    case SL_CHECK_DEPTH_MAP: return "depth (black near, white far)";
    case SL_CHECK_CUBE_FACE: return "distance / far (black near, white far)";
    case SL_CHECK_MOMENTS: case SL_CHECK_MOMENTS_BLURRED: return "moments (red: depth, green: depth squared)";
    case SL_CHECK_CASCADE_INDEX: return "cascade (red 0, green 1, blue 2, yellow 3, grey none)";
    case SL_CHECK_IMAGE: return "shaded image";
    case SL_CHECK_FLICKER: return "the last frame of the path, in red what changed from one frame to the next";
    default: return "visibility (white lit, black shadow)";
    }
}

/* Flicker: of a path's frames stacked top to bottom (each width x height), the
 * last frame in grey with every pixel that changed between two frames in red;
 * `changed` gets their fraction. */
static sl_image _sl_flicker_marks(const sl_image *stacked, int frames, double *changed) {
    int w = stacked->width, h = frames > 0 ? stacked->height / frames : 0;
    sl_image out = sl_image_alloc(w, h, 3);
    long count = 0;
    if (!out.data || !stacked->data || frames < 1) {
        *changed = 0;
        return out;
    }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            bool moved = false;
            for (int f = 1; f < frames && !moved; f++)
                moved = fabsf(sl_image_pixel(stacked, x, f * h + y)[0] - sl_image_pixel(stacked, x, (f - 1) * h + y)[0]) > 0.25f;
            float grey = sl_image_pixel(stacked, x, (frames - 1) * h + y)[0];
            float *q = sl_image_pixel(&out, x, y);
            q[0] = moved ? 1 : grey, q[1] = moved ? 0.05f : grey, q[2] = moved ? 0.05f : grey;
            count += moved;
        }
    *changed = (double)count / ((double)w * h);
    return out;
}

/* The last frame of a path's stack (a view into it: not to be freed). */
static sl_image _sl_last_frame(const sl_image *stacked, int frames) {
    int h = frames > 0 ? stacked->height / frames : stacked->height;
    sl_image last = *stacked;
    last.height = h;
    if (stacked->data && frames > 0) last.data = stacked->data + (size_t)(frames - 1) * (size_t)h * (size_t)stacked->width * (size_t)stacked->channels;
    return last;
}

/* An image as RGB texels for a panel, bottom row first (GL's order), in the
 * check's colours: cascade numbers as the viewer's K key colours them, the two
 * moments as red and green; the difference panel (kind < 0) as it is. */
static void _sl_upload(_sl_case_view *v, int panel, const sl_image *img, int kind) {
    static const float cascade_rgb[5][3] = {{0.3f, 0.3f, 0.3f}, {1, 0.3f, 0.25f}, {0.2f, 0.9f, 0.3f},
                                           {0.3f, 0.45f, 1}, {1, 0.85f, 0.2f}};
    GLuint texture = v->textures[panel];
    v->panel_size[panel][0] = img->width;
    v->panel_size[panel][1] = img->height;
    float *rgb = malloc(sizeof(float) * 3 * (size_t)img->width * (size_t)img->height);
    if (!rgb) return;
    for (int y = 0; y < img->height; y++)
        for (int x = 0; x < img->width; x++) {
            const float *p = sl_image_pixel(img, x, img->height - 1 - y);
            float *q = rgb + 3 * ((size_t)y * (size_t)img->width + (size_t)x);
            if (kind == SL_CHECK_CASCADE_INDEX) {
                int i = (int)floorf(p[0] + 0.5f) + 1; /* -1: no cascade */
                if (i < 0 || i > 4) i = 0;
                for (int c = 0; c < 3; c++) q[c] = cascade_rgb[i][c];
            } else if (img->channels == 2) {
                q[0] = p[0], q[1] = p[1], q[2] = 0;
            } else {
                for (int c = 0; c < 3; c++) q[c] = p[img->channels >= 3 ? c : 0];
            }
        }
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, img->width, img->height, 0, GL_RGB, GL_FLOAT, rgb);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    free(rgb);
}

/* Renders the case as the grader's runner does, and takes the same capture. */
static bool _sl_render_student(_sl_case_view *v, sl_image *out) {
    const sl_case *c = &v->c;
    sl_scene scene = c->scene;
    sl_render_params p = c->params;
    sl_check_kind kind = v->check->kind;
    p.output = kind == SL_CHECK_IMAGE ? SL_OUTPUT_SHADED : kind == SL_CHECK_CASCADE_INDEX ? SL_OUTPUT_CASCADE_INDEX
                                                                                       : SL_OUTPUT_VISIBILITY;
    if (kind == SL_CHECK_MOMENTS) p.vsm.blur_radius = 0; /* the moments pass alone, as the runner takes it */
    for (int f = 0; f < c->frame_count; f++) {
        scene.light = c->frame_lights[f];
        if (c->camera_path) { /* lab 6: the cascades follow the path, the picture stays */
            p.cascades.use_camera = true;
            p.cascades.camera = c->frame_cameras[f];
        }
        sl_renderer_draw(&v->renderer, &scene, &p, v->target_fbo, c->width, c->height);
        if (kind == SL_CHECK_FLICKER) { /* every frame, stacked top to bottom, as the runner sends them */
            if (f == 0) *out = sl_image_alloc(c->width, c->height * c->frame_count, 1);
            sl_image frame;
            if (out->data && sl_capture_framebuffer(v->target_fbo, c->width, c->height, 1, &frame)) {
                memcpy(out->data + (size_t)f * (size_t)c->width * (size_t)c->height, frame.data,
                       sizeof(float) * (size_t)c->width * (size_t)c->height);
                sl_image_free(&frame);
            }
        }
    }
    if (kind == SL_CHECK_FLICKER) return out->data != NULL;
    const sl_frame_info *info = sl_renderer_info(&v->renderer);
    if (_sl_is_map(kind)) {
        char err[256];
        bool ok = false;
        if (kind == SL_CHECK_DEPTH_MAP)
            ok = info->shadow_map_ready && sl_capture_depth_texture(info->shadow_map.depth_texture, out, err, sizeof err);
        else if (kind == SL_CHECK_CUBE_FACE)
            ok = info->cube_map_ready && sl_capture_cube_face(info->cube_map.depth_cube, v->check->face, out, err, sizeof err);
        else
            ok = info->moments_ready && sl_vsm_capture_moments(info->moments_target.moments[0], out, err, sizeof err);
        if (!ok) { /* nothing drawn yet: black, the reference's size */
            *out = sl_image_alloc(v->reference.width, v->reference.height, v->reference.channels);
            return false;
        }
        return true;
    }
    return sl_capture_framebuffer(v->target_fbo, c->width, c->height, kind == SL_CHECK_IMAGE ? 3 : 1, out);
}

static void _sl_update(_sl_case_view *v) {
    sl_image student = {0}, diff = {0};
    _sl_render_student(v, &student);
    if (v->check->kind == SL_CHECK_FLICKER) {
        /* the path's frames: what changed along it, and the last frames side by side */
        const sl_frame_info *info = sl_renderer_info(&v->renderer);
        double yours = 0, reference = v->reference_flicker;
        sl_image marks = _sl_flicker_marks(&student, v->c.frame_count, &yours);
        sl_image last = _sl_last_frame(&student, v->c.frame_count), ref_last = _sl_last_frame(&v->reference, v->c.frame_count);
        sl_compare_images(&last, &ref_last, 0.05, &diff);
        snprintf(v->summary, sizeof v->summary,
                 "%s / %s: along the camera path %.3f%% of pixels change from one frame to the next in yours, %.3f%% in "
                 "the reference%s%s", v->c.name, v->check->name, 100 * yours, 100 * reference,
                 info->not_implemented_count ? "; not implemented: " : "",
                 info->not_implemented_count ? info->not_implemented[0] : "");
        if (marks.data) _sl_upload(v, _SL_STUDENT, &marks, -1);
        if (diff.data) _sl_upload(v, _SL_DIFF, &diff, -1);
        sl_image_free(&marks);
        sl_image_free(&student);
        sl_image_free(&diff);
        return;
    }
    sl_compare_stats st = sl_compare_images(&student, &v->reference, v->check->threshold, &diff);
    const sl_frame_info *info = sl_renderer_info(&v->renderer);
    if (st.size_mismatch)
        snprintf(v->summary, sizeof v->summary, "%s: yours is %dx%d, the reference %dx%d", v->c.name, student.width,
                 student.height, v->reference.width, v->reference.height);
    else
        snprintf(v->summary, sizeof v->summary, "%s / %s: %.2f%% of pixels differ (allowed %.2f%%)%s%s", v->c.name,
                 v->check->name, 100 * st.failing_fraction, 100 * v->check->fail_fraction,
                 info->not_implemented_count ? "; not implemented: " : "",
                 info->not_implemented_count ? info->not_implemented[0] : "");
    if (student.data) _sl_upload(v, _SL_STUDENT, &student, v->check->kind);
    if (diff.data) _sl_upload(v, _SL_DIFF, &diff, -1);
    sl_image_free(&student);
    sl_image_free(&diff);
}

static void _sl_draw_panel(_sl_case_view *v, int panel, int slot, int width, int height) {
    /* the picture's aspect kept: a square map in a wide panel is centred */
    int pw = v->panel_size[panel][0], ph = v->panel_size[panel][1], w = width, h = height;
    if (pw > 0 && ph > 0) {
        if ((long)width * ph > (long)height * pw) w = (int)((long)height * pw / ph);
        else h = (int)((long)width * ph / pw);
    }
    glViewport(slot * width + (width - w) / 2, (height - h) / 2, w, h);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, v->textures[panel]);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

static void _sl_draw(_sl_case_view *v, int width, int height) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_DEPTH_TEST);
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(v->panel_program.id);
    glUniform1i(sl_program_uniform(&v->panel_program, "u_texture"), 0);
    glBindVertexArray(v->vao);
    if (v->side_by_side) {
        for (int panel = 0; panel < _SL_PANELS; panel++) _sl_draw_panel(v, panel, panel, width / 3, height);
    } else {
        int panel = v->show_diff ? _SL_DIFF : v->show_reference ? _SL_REFERENCE : _SL_STUDENT;
        _sl_draw_panel(v, panel, 0, width, height);
    }
    glBindVertexArray(0);
    glUseProgram(0);
}

static void _sl_title(_sl_case_view *v) {
    GLFWwindow *w = sl_context_window(v->ctx);
    if (!w) return;
    char title[512];
    const char *layout = v->side_by_side ? "yours | reference | difference (red: shadow missing, blue: extra)"
                         : v->show_diff  ? "difference (red: shadow missing, blue: extra)"
                         : v->show_reference ? "reference" : "yours";
    snprintf(title, sizeof title, "shadowlab — %s — %s — %s%s", v->summary, layout, _sl_legend(v->check->kind),
             v->shown_count > 1 ? " — C: next check" : "");
    glfwSetWindowTitle(w, title);
}

/* The reference's panel: flicker's frames as what changed along the path. */
static void _sl_upload_reference(_sl_case_view *v) {
    if (v->check->kind != SL_CHECK_FLICKER) {
        _sl_upload(v, _SL_REFERENCE, &v->reference, v->check->kind);
        return;
    }
    sl_image marks = _sl_flicker_marks(&v->reference, v->c.frame_count, &v->reference_flicker);
    if (marks.data) _sl_upload(v, _SL_REFERENCE, &marks, -1);
    sl_image_free(&marks);
}

/* Shows check `index` of the shown ones: its reference, and a summary for it. */
static bool _sl_show_check(_sl_case_view *v, int index) {
    char err[1024], file[200], reference[1400];
    const sl_check *k = v->shown[index];
    sl_check_reference_file(k, file, sizeof file);
    snprintf(reference, sizeof reference, "%s/%s/%s", v->references_dir, v->c.name, file);
    sl_image img;
    if (!sl_image_read(reference, &img, err, sizeof err)) {
        fprintf(stderr, "shadowlab: --case: %s\n", err);
        return false;
    }
    sl_image_free(&v->reference);
    v->reference = img;
    v->check = k;
    v->shown_index = index;
    if (v->textures[_SL_REFERENCE]) _sl_upload_reference(v);
    printf("shadowlab: showing check %s (%d of %d): %s\n", k->name, index + 1, v->shown_count, _sl_legend(k->kind));
    return true;
}

/* Keys, read by polling: Tab layout, Space yours/reference, D difference, C next check, Esc quit. */
static bool _sl_keys(_sl_case_view *v) {
    GLFWwindow *w = sl_context_window(v->ctx);
    static int previous[GLFW_KEY_LAST + 1];
    static const int keys[] = {GLFW_KEY_TAB, GLFW_KEY_SPACE, GLFW_KEY_D, GLFW_KEY_A, GLFW_KEY_C};
    bool changed = false;
    for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
        int now = glfwGetKey(w, keys[i]);
        if (now == GLFW_PRESS && previous[keys[i]] != GLFW_PRESS) {
            changed = true;
            if (keys[i] == GLFW_KEY_C) {
                _sl_show_check(v, (v->shown_index + 1) % v->shown_count);
                continue;
            }
            if (keys[i] == GLFW_KEY_TAB) v->side_by_side = !v->side_by_side;
            else if (keys[i] == GLFW_KEY_SPACE || keys[i] == GLFW_KEY_A) {
                v->show_reference = !v->show_reference;
                v->show_diff = false;
            } else if (keys[i] == GLFW_KEY_D) v->show_diff = !v->show_diff;
            if (keys[i] != GLFW_KEY_TAB) v->side_by_side = false;
        }
        previous[keys[i]] = now;
    }
    if (glfwGetKey(w, GLFW_KEY_ESCAPE) == GLFW_PRESS) glfwSetWindowShouldClose(w, GLFW_TRUE);
    return changed;
}

static bool _sl_setup(_sl_case_view *v, const sl_case_view_desc *d, char *err, size_t n) {
    static char path[1200];
    const char *cases = d->cases_dir ? d->cases_dir : SL_GRADER_DIR "/cases";
    const char *refs = d->references_dir ? d->references_dir : SL_GRADER_DIR "/references";
    bool is_path = strchr(d->case_name, '/') || strstr(d->case_name, ".json");
    if (is_path) snprintf(path, sizeof path, "%s", d->case_name);
    else snprintf(path, sizeof path, "%s/%s.json", cases, d->case_name);
    if (!sl_case_load(&v->c, path, err, n)) return false;
    v->references_dir = refs;
    int first = -1;
    bool maps_only = true;
    for (int i = 0; i < v->c.check_count && v->shown_count < _SL_MAX_SHOWN; i++) {
        const sl_check *k = &v->c.checks[i];
        if (!_sl_has_picture(k->kind)) continue;
        if (d->check_name && strcmp(k->name, d->check_name) == 0) first = v->shown_count;
        maps_only &= _sl_is_map(k->kind);
        v->shown[v->shown_count++] = k;
    }
    if (v->shown_count == 0) {
        snprintf(err, n, "%s has no picture to show (its checks are probes or numbers): "
                 "run shadowlab-grade --case %s", v->c.name, v->c.name);
        return false;
    }
    if (d->check_name && first < 0) {
        char names[600] = "";
        for (int i = 0; i < v->shown_count; i++)
            snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", i ? ", " : "", v->shown[i]->name);
        snprintf(err, n, "%s has no check with a picture named %s (it has: %s)", v->c.name, d->check_name, names);
        return false;
    }
    for (int i = 0; first < 0 && i < v->shown_count; i++) /* what the camera sees first, then the maps */
        if (v->shown[i]->kind == SL_CHECK_VISIBILITY || v->shown[i]->kind == SL_CHECK_PENUMBRA) first = i;
    if (first < 0) first = 0;
    if (!_sl_show_check(v, first)) {
        snprintf(err, n, "the reference of %s / %s does not load (said above)", v->c.name, v->shown[first]->name);
        return false;
    }
    int panel_w = v->c.width, panel_h = v->c.height;
    if (maps_only) panel_w = panel_h = 384; /* maps alone: square panels, shown scaled */
    v->scale = panel_w * 3 * 2 <= 1800 ? 2 : 1;
    sl_context_desc cd = {
        .backend = d->headless ? (sl_backend)d->backend : SL_BACKEND_GLFW,
        .width = panel_w * v->scale * 3,
        .height = panel_h * v->scale,
        .title = "shadowlab",
    };
    v->ctx = sl_context_create(&cd, err, n);
    if (!v->ctx) return false;
    sl_renderer_desc rd = {.labs_dir = d->labs_dir};
    if (!sl_renderer_init(&v->renderer, &rd, err, n) || !sl_renderer_set_scene(&v->renderer, &v->c.scene, err, n))
        return false;
    /* the grader's image size, off screen, in floats as the runner reads it */
    glGenTextures(1, &v->target_texture);
    glBindTexture(GL_TEXTURE_2D, v->target_texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, v->c.width, v->c.height, 0, GL_RGBA, GL_FLOAT, NULL);
    glGenRenderbuffers(1, &v->target_depth);
    glBindRenderbuffer(GL_RENDERBUFFER, v->target_depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, v->c.width, v->c.height);
    glGenFramebuffers(1, &v->target_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, v->target_fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, v->target_texture, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, v->target_depth);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    char vs[SL_PATH_MAX + 32], fs[SL_PATH_MAX + 32];
    snprintf(vs, sizeof vs, "%s/debug_quad.vert", v->renderer.shaders_dir);
    snprintf(fs, sizeof fs, "%s/case_panel.frag", v->renderer.shaders_dir);
    sl_shader_desc sd = {.vertex_path = vs, .fragment_path = fs, .search_dirs = {v->renderer.shaders_dir}};
    if (!sl_program_build(&v->panel_program, &sd, err, n)) return false;
    glGenTextures(_SL_PANELS, v->textures);
    glGenVertexArrays(1, &v->vao);
    _sl_upload_reference(v);
    return true;
}

int sl_case_view_main(const sl_case_view_desc *d) {
    static _sl_case_view v;
    memset(&v, 0, sizeof v);
    v.side_by_side = true;
    char err[8192];
    int status = 0;
    if (!_sl_setup(&v, d, err, sizeof err)) {
        fprintf(stderr, "shadowlab: --case: %s\n", err);
        status = 1;
    } else {
        printf("shadowlab: case %s (%s), lab %d: %s\n", v.c.name, v.c.title, v.c.lab, sl_context_renderer_name());
        GLFWwindow *window = sl_context_window(v.ctx);
        if (window) printf("shadowlab: keys: Tab yours | reference | difference, or one at a time; Space yours or the "
                           "reference; D the difference;%s Esc quit\n", v.shown_count > 1 ? " C the next check;" : "");
        int rendered = 0;
        double last_reload = 0;
        const char *reported_error = NULL;
        char last_summary[256] = "";
        while (!sl_context_should_close(v.ctx)) {
            if (window && glfwGetTime() - last_reload > 0.25) {
                last_reload = glfwGetTime();
                bool reloaded = false;
                if (!sl_renderer_reload_changed(&v.renderer, &reloaded, err, sizeof err))
                    fprintf(stderr, "shadowlab: shader reload failed, keeping the previous version:\n%s\n", err);
            }
            _sl_update(&v);
            const sl_frame_info *info = sl_renderer_info(&v.renderer);
            if (info->shader_error != reported_error) {
                reported_error = info->shader_error;
                if (reported_error) fprintf(stderr, "shadowlab: %s\n", reported_error);
            }
            if (strcmp(last_summary, v.summary) != 0) {
                snprintf(last_summary, sizeof last_summary, "%s", v.summary);
                printf("shadowlab: %s\n", v.summary);
            }
            if (window && _sl_keys(&v)) {}
            _sl_title(&v);
            int fw, fh;
            sl_context_framebuffer_size(v.ctx, &fw, &fh);
            _sl_draw(&v, fw, fh);
            rendered++;
            if (d->frames > 0 && rendered >= d->frames) {
                if (d->screenshot) {
                    sl_image shot;
                    glFinish();
                    if (!sl_capture_framebuffer(0, fw, fh, 3, &shot) || !sl_image_write(d->screenshot, &shot, err, sizeof err)) {
                        fprintf(stderr, "shadowlab: cannot save the screenshot: %s\n", err);
                        status = 1;
                    } else {
                        printf("shadowlab: saved %s (%dx%d)\n", d->screenshot, fw, fh);
                    }
                    sl_image_free(&shot);
                }
                break;
            }
            sl_context_end_frame(v.ctx);
        }
    }
    if (v.ctx) {
        sl_program_destroy(&v.panel_program);
        sl_renderer_destroy(&v.renderer);
        sl_context_destroy(v.ctx);
    }
    sl_image_free(&v.reference);
    return status;
}
