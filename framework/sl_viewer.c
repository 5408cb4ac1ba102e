#define _POSIX_C_SOURCE 200809L
#include "sl_viewer.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#if !defined(_WIN32)
#include <fcntl.h>
#include <signal.h>
#if defined(__linux__)
#include <sys/prctl.h>
#endif
#include <sys/wait.h>
#include <unistd.h>
#endif

#include "sl_bench.h"
#include "sl_case_view.h"
#include "sl_log.h"
#include "sl_platform.h"
#include "sl_viewer_camera.h"
#include "sl_viewer_capture.h"
#include "sl_viewer_keys.h"
#include "sl_viewer_options.h"
#include "sl_viewer_overlay.h"
#include "sl_viewer_split.h"
#include "sl_viewer_state.h"
#include <cjson/cJSON.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

/* The second lab code (sl_viewer_set_second_labs), NULL in builds without one. */
static const sl_lab_functions *_sl_second_functions;
static const char *_sl_second_dir, *_sl_second_kind;

void sl_viewer_set_second_labs(const sl_lab_functions *functions, const char *labs_dir, const char *kind) {
    _sl_second_functions = functions;
    _sl_second_dir = labs_dir;
    _sl_second_kind = kind;
}

/* One viewer run: the options of one command line. `batch_line` > 0: line batch_line of --batch, which
 * must be a headless run that ends by itself (no window, no --serve). */
static int _sl_viewer_run(int argc, char **argv, int batch_line) {
    _sl_viewer v = {0};
    sl_render_params_defaults(&v.params);
    v.second_functions = _sl_second_functions;
    v.second_dir = _sl_second_dir;
    v.second_kind = _sl_second_kind;
    _sl_viewer_options o;
    int parsed = _sl_viewer_options_parse(argc, argv, &v, &o);
    if (parsed >= 0) return parsed;
    if (batch_line && (!o.headless || o.serve_port)) {
        fprintf(stderr, "shadowlab: --batch: line %d %s: a batch runs headless runs only (--headless or "
                        "--backend, with --frames)\n", batch_line, o.serve_port ? "serves (--serve)" : "opens a window");
        return 2;
    }
    if (o.case_name) {
        sl_case_view_desc cv = {.case_name = o.case_name, .labs_dir = o.labs_dir, .headless = o.headless,
                                .backend = o.backend, .frames = o.frames, .screenshot = o.screenshot,
                                .check_name = o.check_name, .serve_port = o.serve_port, .serve_address = o.serve_address};
        return sl_case_view_main(&cv);
    }
    char err[16384];
    if (!sl_scene_load(&v.scene, o.scene_name, err, sizeof err)) {
        fprintf(stderr, "shadowlab: %s\n", err);
        return 1;
    }
    if (o.light_size > 0) v.scene.light.size = o.light_size;
    if (o.freeze) _sl_viewer_freeze(&v, true);
    if (!o.lab_given) {
        /* the lab whose technique the scene's light is for (sl_technique.default_for_lights: a point light's cube
         * maps, a sun's or a spot's filtering); if it is not in this build, a sun's, or the highest below it */
        v.params.lab = 0;
        for (int pass = 0; pass < 2 && !v.params.lab; pass++)
            for (int lab = SL_LAB_COUNT; lab >= 1 && !v.params.lab; lab--) {
                const sl_technique *t = sl_technique_of(lab);
                unsigned light = 1u << (pass == 0 ? v.scene.light.type : SL_LIGHT_DIRECTIONAL);
                if (t && (t->default_for_lights & light) && (pass == 1 || sl_lab_folder(lab))) v.params.lab = lab;
            }
        if (!v.params.lab) v.params.lab = 1;
        while (v.params.lab > 1 && !sl_lab_folder(v.params.lab)) v.params.lab--;
    }
    _sl_viewer_split_show(&v, v.split.given); /* the viewer's settings are the left half's */
    sl_context_desc cd = {
        .backend = o.headless ? o.backend : SL_BACKEND_GLFW,
        .width = o.width,
        .height = o.height,
        .title = "shadowlab",
        .resizable = true,
    };
    v.ctx = sl_context_create(&cd, err, sizeof err);
    if (!v.ctx) {
        fprintf(stderr, "shadowlab: %s\n", err);
        return 1;
    }
    sl_renderer_desc rd = {.labs_dir = o.labs_dir};
    if (!sl_renderer_init(&v.renderer, &rd, err, sizeof err) ||
        !sl_renderer_set_scene(&v.renderer, &v.scene, err, sizeof err)) {
        fprintf(stderr, "shadowlab: %s\n", err);
        sl_context_destroy(v.ctx);
        return 1;
    }
    printf("shadowlab: %s through %s, %s labs from %s\n", sl_context_renderer_name(), sl_backend_name(sl_context_backend(v.ctx)),
           sl_build_labs_kind, v.renderer.labs_dir);
    /* The overlay is on in an interactive window and off in unattended runs,
     * so screenshots and slide figures show the scene alone unless asked. */
    v.show_panels = !v.lecture; /* a hall sees one line; the panels come on key I */
    /* a lecture's line is what --lecture asks for, in a screenshot too */
    v.show_overlay = o.overlay_option >= 0 ? o.overlay_option == 1
                                           : (v.lecture || ((!o.headless || o.serve_port) && o.frames <= 0));
    v.overlay = sl_overlay_create(sl_framework_dir(), err, sizeof err);
    if (!v.overlay) fprintf(stderr, "shadowlab: no overlay: %s\n", err);
    else {
        sl_overlay_set_scale(v.overlay, v.text_scale);
        sl_overlay_set_lecture(v.overlay, v.lecture);
        if (v.font) sl_overlay_set_font(v.overlay, v.font);
    }
    /* GLFW's key codes for letters, digits and [ ] - = are their ASCII codes (upper case). */
    _sl_viewer_keys_attach(&v);
    for (const char *k = v.keys; k && *k; k++)
        _sl_viewer_key(NULL, *k >= 'a' && *k <= 'z' ? *k - 'a' + 'A' : *k, 0, GLFW_PRESS, 0);
    /* 0 would do too (the EGL backend binds its own for it); the name says what is meant. */
    GLuint target = sl_context_default_framebuffer(v.ctx);

    if (v.screenshot_dir && !_sl_viewer_screenshot_dir_make(v.screenshot_dir)) {
        sl_overlay_destroy(v.overlay);
        sl_renderer_destroy(&v.renderer);
        sl_context_destroy(v.ctx);
        return 1;
    }
    if (o.serve_port) {
        char *keys = _sl_viewer_keys_json(v.params.lab);
        sl_serve_desc sd = {.port = o.serve_port, .address = o.serve_address, .hello = keys};
        v.serve = sl_serve_start(&sd, err, sizeof err);
        cJSON_free(keys);
        if (!v.serve) {
            fprintf(stderr, "shadowlab: %s\n", err);
            sl_overlay_destroy(v.overlay);
            sl_renderer_destroy(&v.renderer);
            sl_context_destroy(v.ctx);
            return 1;
        }
        printf("shadowlab: serving the viewer at %s (open it in a browser; Ctrl-C stops)\n", sl_serve_url(v.serve));
        printf("shadowlab: X on the page saves screenshots into %s/\n", v.screenshot_dir);
        fflush(stdout);
    }
    GLFWwindow *window = sl_context_window(v.ctx);
    bool live = window || v.serve; /* someone watches: a window or a page */
    if (window) {
        glfwSetWindowUserPointer(window, &v);
        _sl_viewer_input_callbacks(window);
    }
    int rendered = 0;
    bool last_second = false; /* whose code the last frame drew with: said when it changes */
    double last_reload_check = 0, last_frame_time = 0;
    char reported_missing[512] = "-";
    const char *reported_shader_error = NULL;
    int status = 0;
    v.dirty_title = true;
    while (!sl_context_should_close(v.ctx)) {
        double now = window ? glfwGetTime() : v.serve ? sl_platform_seconds() : 0;
        if (v.serve) _sl_viewer_serve_events(&v);
        if (live && now - last_reload_check > 0.25) {
            last_reload_check = now;
            bool reloaded = false;
            if (!sl_renderer_reload_changed(v.show_second && v.second_ready ? &v.second : &v.renderer, &reloaded, err,
                                            sizeof err))
                fprintf(stderr, "shadowlab: shader reload failed, keeping the previous version:\n%s\n", err);
            else if (reloaded)
                printf("shadowlab: shaders reloaded\n");
            _sl_viewer_split_reload(&v);
        }
        if (live) _sl_viewer_fly(&v, window, now);
        int fw, fh;
        sl_context_framebuffer_size(v.ctx, &fw, &fh);
        if (v.show_second && !v.second_ready) {
            /* The second code draws with its own renderer: its own shaders, its own maps. */
            sl_renderer_desc sd = {.labs_dir = v.second_dir};
            if (!sl_renderer_init(&v.second, &sd, err, sizeof err) ||
                !sl_renderer_set_scene(&v.second, &v.scene, err, sizeof err)) {
                fprintf(stderr, "shadowlab: cannot draw with the %s: %s\n", v.second_kind, err);
                v.show_second = false;
            } else {
                for (int lab = 1; lab <= SL_LAB_COUNT; lab++) v.second.fns[lab] = v.second_functions;
                v.second_ready = true;
            }
        }
        sl_renderer *active = v.show_second ? &v.second : &v.renderer;
        if (last_second != v.show_second) {
            printf("shadowlab: drawing with the %s code\n", v.show_second ? v.second_kind : sl_build_labs_kind);
            last_second = v.show_second;
            v.dirty_title = true;
        }
        /* Per-pass GL timer queries only while the overlay shows them. */
        bool timing = v.overlay && v.show_overlay;
        if (active->timing != timing) sl_renderer_set_timing(active, timing);
        if (v.animate_light) {
            double dt = live ? now - last_frame_time : 1.0 / 30.0;
            _sl_viewer_animate_light(&v.scene.light, (float)(0.4 * (dt > 0.2 ? 0.2 : dt)));
        }
        double frame_seconds = live && last_frame_time > 0 ? now - last_frame_time : 0;
        last_frame_time = now;
        if (v.camera_path) _sl_viewer_camera_path(&v, o.frames > 0 ? (double)rendered / o.frames : now / _SL_PATH_SECONDS);
        /* --split: the right half's setting first, so the frame's depth is the left half's (the overlay's lines) */
        if (v.split.on) _sl_viewer_split_draw_right(&v, target, fw, fh);
        sl_renderer_draw(active, &v.scene, &v.params, target, fw, fh);
        if (v.split.on) _sl_viewer_split_compose(&v, target, fw, fh);
        const sl_frame_info *info = sl_renderer_info(active);
        /* --mark-changes compares the frames as drawn, before the overlay: its text (the pass times) changes
         * from frame to frame, the scene it is about may not */
        if (v.mark_changes && o.frames > 0 && !_sl_viewer_mark_changes(&v, target, fw, fh)) {
            fprintf(stderr, "shadowlab: --mark-changes: cannot read frame %d (or its size changed)\n", rendered + 1);
            status = 1;
            break;
        }
        bool labels = (v.show_overlay && v.show_panels) || v.labels;
        const sl_technique *asked = sl_technique_of(v.params.lab);
        bool overlay_drawn = v.overlay && (v.show_overlay || labels || v.show_frustum || v.caption || v.split.on ||
                                           (v.frozen && asked && asked->frozen_lines));
        mat4 camera;
        _sl_viewer_camera_view_projection(&v.scene, fw, fh, camera);
        if (overlay_drawn) {
            if (timing) _sl_viewer_update_timing(&v, active, frame_seconds, live);
            sl_overlay_clear(v.overlay);
            if (v.show_overlay) _sl_viewer_overlay_fill(&v, active, fw, fh, live);
            if (v.show_frustum) _sl_viewer_add_frustum(v.overlay, info);
            _sl_viewer_labels(&v, info, fw, fh, labels);
            if (v.split.on) _sl_viewer_split_labels(&v, info, fw, fh);
            if (v.caption) {
                sl_overlay_panel(v.overlay, SL_OVERLAY_BOTTOM_LEFT, NULL);
                sl_overlay_line(v.overlay, (const float[3]){1, 1, 1}, "%s", v.caption);
            }
            sl_overlay_draw(v.overlay, camera, target, fw, fh);
        }
        if (v.screenshot_requested) {
            v.screenshot_requested = false;
            _sl_viewer_screenshot_key(&v, target, fw, fh);
        }
        if (info->shader_error != reported_shader_error) {
            reported_shader_error = info->shader_error;
            if (info->shader_error)
                fprintf(stderr, "shadowlab: lab %d's shaders do not compile, so it is switched off until you fix "
                                "them (they reload when saved):\n%s\n", info->shader_error_lab, info->shader_error);
        }
        /* Say what is really drawing whenever that changes (a stub in the way, a setting, the scene). */
        char drawing_status[512];
        _sl_viewer_status(&v, info, drawing_status, sizeof drawing_status);
        if (strcmp(drawing_status, v.status) != 0) {
            snprintf(v.status, sizeof v.status, "%s", drawing_status);
            if (drawing_status[0]) printf("shadowlab: %s\n", drawing_status);
            v.dirty_title = true;
        }
        /* Say which stubs are in the way whenever that list changes (another lab, a mode). */
        char missing[512] = "";
        for (int i = 0; i < info->not_implemented_count; i++)
            snprintf(missing + strlen(missing), sizeof missing - strlen(missing), "%s ", info->not_implemented[i]);
        if (strcmp(missing, reported_missing) != 0) {
            snprintf(reported_missing, sizeof reported_missing, "%s", missing);
            for (int i = 0; i < info->not_implemented_count; i++)
                printf("shadowlab: not implemented yet: %s() (rendering without it)\n", info->not_implemented[i]);
            v.dirty_title = true;
        }
        if (v.dirty_title) {
            _sl_viewer_update_title(&v);
            v.dirty_title = false;
        }
        rendered++;
        if (o.gif && o.frames > 0 && !_sl_viewer_add_frame(&v, target, fw, fh, o.screenshot)) {
            status = 1;
            break;
        }
        if (v.frame_dir) {
            char path[SL_PATH_MAX + 16];
            snprintf(path, sizeof path, "%s/%03d.png", v.frame_dir, rendered);
            if (!_sl_viewer_save(target, fw, fh, path)) {
                status = 1;
                break;
            }
        }
        if (o.frames > 0 && rendered >= o.frames) {
            if (o.screenshot && !o.gif && v.mark_changes) {
                if (!_sl_viewer_save_changes(&v, o.screenshot, rendered, overlay_drawn, camera, target)) status = 1;
            } else if (o.screenshot && !o.gif && !_sl_viewer_save(target, fw, fh, o.screenshot)) {
                status = 1;
            }
            /* The last frame's overlay in words, for logs and tests. */
            if (v.overlay && overlay_drawn && (v.show_overlay || v.labels)) {
                char text[8192];
                sl_overlay_text(v.overlay, text, sizeof text);
                printf("shadowlab: overlay:\n%s", text);
            }
            break;
        }
        if (v.serve) {
            /* the overlay's words: its panels, labels and markers, whichever are drawn */
            static char text[16384];
            text[0] = '\0';
            if (overlay_drawn) sl_overlay_text(v.overlay, text, sizeof text);
            sl_serve_frame_desc fd = {.text = text, .lab = v.params.lab, .keys_acted = v.keys_acted};
            if (!sl_serve_frame(v.serve, target, fw, fh, &fd, err, sizeof err))
                fprintf(stderr, "shadowlab: --serve: %s\n", err);
            sl_serve_idle(v.serve);
        }
        sl_context_end_frame(v.ctx);
    }
    if (v.animation) {
        char aerr[1024] = "";
        if (sl_animation_close(v.animation, aerr, sizeof aerr))
            printf("shadowlab: saved %s (%d frames)\n", o.screenshot, rendered);
        else {
            fprintf(stderr, "shadowlab: cannot save the animation: %s\n", aerr);
            status = 1;
        }
    }
    sl_serve_stop(v.serve);
    sl_image_free(&v.first_frame);
    free(v.changed);
    sl_overlay_destroy(v.overlay);
    if (v.second_ready) sl_renderer_destroy(&v.second);
    _sl_viewer_split_destroy(&v);
    sl_renderer_destroy(&v.renderer);
    sl_context_destroy(v.ctx);
    return status;
}

/* Splits `line` into words as a POSIX shell quotes them, without expanding anything: blanks separate
 * words; '...' keeps everything; "..." keeps everything but a backslash before " $ ` or a backslash;
 * a backslash elsewhere keeps the next character; # at a word's start comments out the rest. The words
 * go to `text` (2x the line's length + 2) and `words` (the line's length + 2 entries). Returns the count, or -1 with `why`. */
static int _sl_batch_split(const char *line, char *text, char **words, const char **why) {
    int n = 0;
    const char *p = line;
    char *out = text;
    for (;;) {
        while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') p++;
        if (!*p || *p == '#') return n;
        words[n++] = out;
        while (*p && *p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') {
            if (*p == '\'') {
                const char *close = strchr(p + 1, '\'');
                if (!close) return *why = "a ' is not closed", -1;
                memcpy(out, p + 1, (size_t)(close - p - 1));
                out += close - p - 1;
                p = close + 1;
            } else if (*p == '"') {
                for (p++; *p && *p != '"'; p++) {
                    if (*p == '\\' && p[1] && strchr("\"\\$`", p[1])) p++;
                    *out++ = *p;
                }
                if (!*p) return *why = "a \" is not closed", -1;
                p++;
            } else if (*p == '\\') {
                if (!p[1] || p[1] == '\n' || p[1] == '\r') return *why = "the line ends in a \\", -1;
                *out++ = p[1];
                p += 2;
            } else {
                *out++ = *p++;
            }
        }
        *out++ = '\0';
    }
}

/* How far a batch's runs got: the line being run (0 between lines) and the index of the next line to run.
 * Written to the parent that started the process running them (_sl_viewer_batch) as each line starts and
 * ends, on a pipe (`fd`, -1: none). */
typedef struct _sl_batch_progress {
    int running;
    int next;
} _sl_batch_progress;

static void _sl_batch_note(int fd, int running, int next) {
#if !defined(_WIN32)
    _sl_batch_progress p = {running, next};
    if (fd >= 0 && write(fd, &p, sizeof p) != (ssize_t)sizeof p) {} /* the parent is gone: nothing to tell */
#else
    (void)fd, (void)running, (void)next;
#endif
}

/* Lines[from..] of a batch, run here one after another (the image module and the GL drivers load once).
 * Every run starts from the same state as a process of its own. Returns 1 if a line failed. */
static int _sl_batch_run_lines(const char *program, char **lines, int count, int from, int progress) {
    int failed = 0;
    for (int i = from; i < count; i++) {
        int line_number = i + 1;
        size_t length = strlen(lines[i]);
        char *text = malloc(2 * length + 2);
        char **argv = malloc((length + 3) * sizeof *argv);
        if (!text || !argv) {
            free(text);
            free(argv);
            fprintf(stderr, "shadowlab: --batch: out of memory at line %d\n", line_number);
            return 1;
        }
        const char *why = NULL;
        int words = _sl_batch_split(lines[i], text, argv + 1, &why);
        if (words != 0) {
            printf("shadowlab: batch line %d\n", line_number);
            fflush(stdout);
            fprintf(stderr, "shadowlab: batch line %d\n", line_number);
            _sl_batch_note(progress, line_number, i);
            int status = 2;
            if (words < 0) fprintf(stderr, "shadowlab: --batch: line %d: %s\n", line_number, why);
            else {
                argv[0] = (char *)program;
                argv[words + 1] = NULL;
                const char *refused = NULL;
                for (int k = 1; k <= words && !refused; k++)
                    if (strcmp(argv[k], "--batch") == 0 || strcmp(argv[k], "--bench") == 0) refused = argv[k];
                if (refused)
                    fprintf(stderr, "shadowlab: --batch: line %d has %s: a batch's lines are viewer runs\n",
                            line_number, refused);
                else
                    status = _sl_viewer_run(words + 1, argv, line_number);
            }
            fflush(stdout);
            fflush(stderr);
            printf("shadowlab: batch line %d: exit %d\n", line_number, status);
            fflush(stdout);
            if (status != 0) failed = 1;
        }
        _sl_batch_note(progress, 0, i + 1);
        free(text);
        free(argv);
    }
    return failed;
}

/* One line of `f` (with its newline), however long, in memory of its own; NULL at the end. fgets,
 * not getline: Windows' C library has no getline. */
static char *_sl_batch_read_line(FILE *f) {
    size_t size = 256, used = 0;
    char *line = malloc(size);
    while (line && fgets(line + used, (int)(size - used), f)) {
        used += strlen(line + used);
        if (used > 0 && line[used - 1] == '\n') return line;
        if (size - used > 1) break; /* the last line, without a newline */
        char *bigger = realloc(line, size * 2);
        if (!bigger) break;
        line = bigger;
        size *= 2;
    }
    if (line && used > 0 && !ferror(f)) return line;
    free(line);
    return NULL;
}

/* --batch FILE ("-": stdin): each line a viewer command line. The lines run one after another in one
 * process; where a system has fork, that process is a child of this one, and when a line kills it (a
 * crash, a signal, an exit in the middle of a run), that line alone fails (its end marked with 128 + the
 * signal, or its exit status) and the lines after it run on in a new process. */
static int _sl_viewer_batch(const char *program, const char *path) {
    FILE *f = strcmp(path, "-") == 0 ? stdin : fopen(path, "r");
    if (!f) {
        fprintf(stderr, "shadowlab: --batch: cannot read %s: %s\n", path, strerror(errno));
        return 2;
    }
    /* read whole: a process that starts after a line that died reads from there, stdin or not */
    char **lines = NULL, *line = NULL;
    int count = 0, failed = 0;
    while (!failed && (line = _sl_batch_read_line(f)) != NULL) {
        char **more = realloc(lines, (size_t)(count + 1) * sizeof *lines);
        if (!more) {
            free(line);
            fprintf(stderr, "shadowlab: --batch: out of memory at line %d\n", count + 1);
            failed = 2;
            break;
        }
        lines = more;
        lines[count++] = line;
    }
    if (!failed && ferror(f)) {
        fprintf(stderr, "shadowlab: --batch: cannot read %s: %s\n", path, strerror(errno));
        failed = 2;
    }
    if (f != stdin) fclose(f);
    if (failed) {
        for (int i = 0; i < count; i++) free(lines[i]);
        free(lines);
        return failed;
    }
#if defined(_WIN32)
    failed = _sl_batch_run_lines(program, lines, count, 0, -1);
#else
    int from = 0;
    pid_t parent = getpid();
    while (from < count) {
        int fds[2] = {-1, -1};
        pid_t pid = -1;
        fflush(stdout);
        fflush(stderr);
        if (pipe(fds) == 0) {
            fcntl(fds[0], F_SETFD, FD_CLOEXEC);
            fcntl(fds[1], F_SETFD, FD_CLOEXEC);
            pid = fork();
        }
        if (pid < 0) { /* no process of its own: the lines run here */
            if (fds[0] >= 0) close(fds[0]), close(fds[1]);
            failed |= _sl_batch_run_lines(program, lines, count, from, -1);
            break;
        }
        if (pid == 0) {
            close(fds[0]);
            setvbuf(stdout, NULL, _IOLBF, 0); /* what a line says before it dies is kept */
#if defined(__linux__)
            prctl(PR_SET_PDEATHSIG, SIGKILL); /* a batch killed (a timeout, a kill) takes its lines with it */
#endif
            if (getppid() != parent) _exit(1);
            exit(_sl_batch_run_lines(program, lines, count, from, fds[1]));
        }
        close(fds[1]);
        _sl_batch_progress got = {0, from}, p;
        ssize_t n;
        while ((n = read(fds[0], &p, sizeof p)) == (ssize_t)sizeof p || (n < 0 && errno == EINTR))
            if (n > 0) got = p;
        close(fds[0]);
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
        int running = got.running, next = got.next;
        if (WIFEXITED(status) && running == 0 && next >= count) {
            failed |= WEXITSTATUS(status) != 0;
            break;
        }
        failed = 1;
        char how[96];
        int code;
        if (WIFSIGNALED(status)) {
            code = 128 + WTERMSIG(status);
            snprintf(how, sizeof how, "was killed by signal %d (%s)", WTERMSIG(status), strsignal(WTERMSIG(status)));
        } else {
            code = WIFEXITED(status) && WEXITSTATUS(status) ? WEXITSTATUS(status) : 1;
            snprintf(how, sizeof how, "exited with status %d", WIFEXITED(status) ? WEXITSTATUS(status) : -1);
        }
        if (running == 0) { /* between two lines: none to blame */
            fprintf(stderr, "shadowlab: --batch: the viewer %s after line %d\n", how, next);
            if (next == from) break; /* not one line further: it would again */
            from = next;
            continue;
        }
        fprintf(stderr, "shadowlab: --batch: line %d: the viewer %s%s\n", running, how,
                running < count ? "; the lines after it run in a new process" : "");
        printf("shadowlab: batch line %d: exit %d\n", running, code);
        fflush(stdout);
        from = running;
    }
#endif
    for (int i = 0; i < count; i++) free(lines[i]);
    free(lines);
    return failed;
}

int sl_viewer_main(int argc, char **argv) {
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--batch") == 0) {
            if (i != 1 || argc != 3) {
                fprintf(stderr, "shadowlab: --batch FILE takes no other options: each line of FILE has its own\n");
                return 2;
            }
            return _sl_viewer_batch(argv[0], argv[2]);
        }
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--bench") == 0) return sl_bench_main(argc, argv);
    return _sl_viewer_run(argc, argv, 0);
}
