#define _GNU_SOURCE
#include "sl_run.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "sl_context.h"
#include "sl_renderer.h"

/* ---- wire format: [u32 type][u32 name length][u64 payload length][name][payload] ---- */
enum { _SL_MSG_STAGE = 1, _SL_MSG_NOT_IMPLEMENTED, _SL_MSG_FAILED, _SL_MSG_ERROR, _SL_MSG_IMAGE, _SL_MSG_NUMBERS, _SL_MSG_DONE };

static int _sl_child_fd = -1;

static void _sl_write_all(int fd, const void *data, size_t n) {
    const char *p = data;
    while (n > 0) {
        ssize_t w = write(fd, p, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) _exit(3); /* parent gone */
        p += w;
        n -= (size_t)w;
    }
}

static void _sl_send(uint32_t type, const char *name, const void *payload, uint64_t payload_len) {
    uint32_t name_len = name ? (uint32_t)strlen(name) : 0;
    struct { uint32_t type, name_len; uint64_t payload_len; } header = {type, name_len, payload_len};
    _sl_write_all(_sl_child_fd, &header, sizeof header);
    if (name_len) _sl_write_all(_sl_child_fd, name, name_len);
    if (payload_len) _sl_write_all(_sl_child_fd, payload, (size_t)payload_len);
}

static void _sl_send_image(const char *name, const sl_image *img) {
    size_t n = (size_t)img->width * (size_t)img->height * (size_t)img->channels;
    size_t bytes = 3 * sizeof(int32_t) + n * sizeof(float);
    char *buf = malloc(bytes);
    if (!buf) return;
    int32_t dims[3] = {img->width, img->height, img->channels};
    memcpy(buf, dims, sizeof dims);
    memcpy(buf + sizeof dims, img->data, n * sizeof(float));
    _sl_send(_SL_MSG_IMAGE, name, buf, bytes);
    free(buf);
}

static void _sl_send_numbers(const char *name, const double *v, int count) {
    _sl_send(_SL_MSG_NUMBERS, name, v, (uint64_t)count * sizeof(double));
}

static void _sl_stage_hook(const char *function) { _sl_send(_SL_MSG_STAGE, function, NULL, 0); }

static bool _sl_case_has(const sl_case *c, sl_check_kind kind) {
    for (int i = 0; i < c->check_count; i++)
        if (c->checks[i].kind == kind) return true;
    return false;
}

/* What the FBO check needs to know about lab 1's framebuffer and texture. */
static void _sl_capture_fbo(const sl_shadow_map *map, int requested_size) {
    double v[10] = {0};
    while (glGetError() != GL_NO_ERROR) {}
    bool is_fbo = map->framebuffer && glIsFramebuffer(map->framebuffer);
    v[9] = requested_size;
    if (is_fbo) {
        GLint type = 0, name = 0, color_type = 0, draw = 0, read = 0;
        glBindFramebuffer(GL_FRAMEBUFFER, map->framebuffer);
        v[0] = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        if (type == GL_TEXTURE)
            glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &color_type);
        glGetIntegerv(GL_DRAW_BUFFER, &draw);
        glGetIntegerv(GL_READ_BUFFER, &read);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        v[1] = type;
        v[2] = (GLuint)name == map->depth_texture && name != 0;
        v[6] = draw;
        v[7] = read;
        v[8] = color_type;
    }
    if (map->depth_texture && glIsTexture(map->depth_texture)) {
        GLint w = 0, h = 0, bits = 0;
        glBindTexture(GL_TEXTURE_2D, map->depth_texture);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &bits);
        v[3] = bits;
        v[4] = w;
        v[5] = h;
    }
    while (glGetError() != GL_NO_ERROR) {}
    _sl_send_numbers("fbo", v, 10);
}

static int _sl_child_main(const sl_case *c, const sl_run_options *o) {
    char err[8192];
    sl_context_desc cd = {.backend = SL_BACKEND_OSMESA, .width = c->width, .height = c->height};
    sl_context *ctx = sl_context_create(&cd, err, sizeof err);
    if (!ctx) {
        _sl_send(_SL_MSG_ERROR, NULL, err, strlen(err));
        return 1;
    }
    sl_renderer r;
    sl_renderer_desc rd = {.labs_dir = o->labs_dir};
    if (o->isolate) {
        rd.labs_dir = o->isolation_dirs[c->lab];
        for (int lab = 1; lab <= SL_LAB_COUNT; lab++)
            if (lab != c->lab) rd.lab_functions[lab] = sl_isolation_lab_functions;
    }
    sl_scene scene = c->scene;
    if (!sl_renderer_init(&r, &rd, err, sizeof err) || !sl_renderer_set_scene(&r, &scene, err, sizeof err)) {
        _sl_send(_SL_MSG_ERROR, NULL, err, strlen(err));
        return 1;
    }
    sl_lab_call_hook = _sl_stage_hook;
    sl_render_params p = c->params;
    p.output = SL_OUTPUT_VISIBILITY;
    for (int f = 0; f < c->frame_count; f++) {
        scene.light = c->frame_lights[f];
        sl_renderer_draw(&r, &scene, &p, 0, c->width, c->height);
        glFinish();
    }
    const sl_frame_info *info = sl_renderer_info(&r);
    if (info->shader_error && info->shader_error_lab <= c->lab) {
        /* A lab's shaders this case needs do not compile: the case fails on that alone. */
        _sl_send(_SL_MSG_ERROR, NULL, info->shader_error, strlen(info->shader_error));
        return 1;
    }
    sl_image img;
    if ((_sl_case_has(c, SL_CHECK_VISIBILITY) || _sl_case_has(c, SL_CHECK_PENUMBRA)) &&
        sl_capture_framebuffer(0, c->width, c->height, 1, &img)) {
        _sl_send_image("visibility", &img);
        sl_image_free(&img);
    }
    if (_sl_case_has(c, SL_CHECK_VISIBILITY) && c->lab >= 3) {
        /* which pixels are surfaces facing the light: where acne can be told from shadow */
        p.output = SL_OUTPUT_LIT_MASK;
        sl_renderer_draw(&r, &scene, &p, 0, c->width, c->height);
        if (sl_capture_framebuffer(0, c->width, c->height, 1, &img)) {
            _sl_send_image("lit_mask", &img);
            sl_image_free(&img);
        }
    }
    if (_sl_case_has(c, SL_CHECK_IMAGE)) {
        p.output = SL_OUTPUT_SHADED;
        sl_renderer_draw(&r, &scene, &p, 0, c->width, c->height);
        if (sl_capture_framebuffer(0, c->width, c->height, 3, &img)) {
            _sl_send_image("image", &img);
            sl_image_free(&img);
        }
    }
    for (int i = 0; i < info->not_implemented_count; i++)
        _sl_send(_SL_MSG_NOT_IMPLEMENTED, info->not_implemented[i], NULL, 0);
    if (info->failed) _sl_send(_SL_MSG_FAILED, info->failed, NULL, 0);
    if (_sl_case_has(c, SL_CHECK_FBO) && info->shadow_map.framebuffer + info->shadow_map.depth_texture > 0)
        _sl_capture_fbo(&info->shadow_map, p.shadow_map_size);
    if (_sl_case_has(c, SL_CHECK_DEPTH_MAP) && info->shadow_map_ready) {
        if (sl_capture_depth_texture(info->shadow_map.depth_texture, &img, err, sizeof err)) {
            _sl_send_image("depth_map", &img);
            sl_image_free(&img);
        } else {
            _sl_send(_SL_MSG_ERROR, "depth_map", err, strlen(err));
        }
    }
    if (_sl_case_has(c, SL_CHECK_MATRICES) && info->lab2_ready) {
        double m[48];
        for (int i = 0; i < 16; i++) {
            m[i] = ((const float *)info->light_view)[i];
            m[16 + i] = ((const float *)info->light_projection)[i];
            m[32 + i] = ((const float *)info->shadow_matrix)[i];
        }
        _sl_send_numbers("matrices", m, 48);
    }
    sl_lab_call_hook = NULL;
    sl_renderer_destroy(&r);
    sl_context_destroy(ctx);
    _sl_send(_SL_MSG_DONE, NULL, NULL, 0);
    return 0;
}

/* ---- parent side ---- */

typedef struct _sl_job {
    pid_t pid;
    int fd;
    int index;
    char *buf;
    size_t len, cap;
    double start, deadline;
    char log_path[64];
} _sl_job;

static double _sl_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static void _sl_parse(const _sl_job *job, sl_case_result *r) {
    size_t pos = 0;
    char stage[64] = "";
    while (pos + 16 <= job->len) {
        uint32_t type, name_len;
        uint64_t payload_len;
        memcpy(&type, job->buf + pos, 4);
        memcpy(&name_len, job->buf + pos + 4, 4);
        memcpy(&payload_len, job->buf + pos + 8, 8);
        if (pos + 16 + name_len + payload_len > job->len) break; /* cut off by a crash */
        char name[64];
        snprintf(name, sizeof name, "%.*s", (int)(name_len < 63 ? name_len : 63), job->buf + pos + 16);
        const char *payload = job->buf + pos + 16 + name_len;
        switch (type) {
        case _SL_MSG_STAGE: snprintf(stage, sizeof stage, "%s", name); break;
        case _SL_MSG_NOT_IMPLEMENTED:
            if (r->not_implemented_count < 16) snprintf(r->not_implemented[r->not_implemented_count++], 64, "%s", name);
            break;
        case _SL_MSG_FAILED: snprintf(r->failed, sizeof r->failed, "%s", name); break;
        case _SL_MSG_ERROR:
            if (name[0])
                snprintf(r->capture_error, sizeof r->capture_error, "%s: %.*s", name, (int)payload_len, payload);
            else
                snprintf(r->error, sizeof r->error, "%.*s", (int)payload_len, payload);
            break;
        case _SL_MSG_IMAGE:
            if (r->capture_count < SL_RUN_MAX_CAPTURES && payload_len >= 12) {
                int32_t dims[3];
                memcpy(dims, payload, sizeof dims);
                uint64_t expect = 12 + (uint64_t)dims[0] * (uint64_t)dims[1] * (uint64_t)dims[2] * sizeof(float);
                if (dims[0] > 0 && dims[1] > 0 && dims[2] > 0 && expect == payload_len) {
                    sl_capture *cap = &r->captures[r->capture_count++];
                    snprintf(cap->name, sizeof cap->name, "%s", name);
                    cap->is_image = true;
                    cap->image = sl_image_alloc(dims[0], dims[1], dims[2]);
                    if (cap->image.data) memcpy(cap->image.data, payload + 12, payload_len - 12);
                }
            }
            break;
        case _SL_MSG_NUMBERS:
            if (r->capture_count < SL_RUN_MAX_CAPTURES) {
                sl_capture *cap = &r->captures[r->capture_count++];
                snprintf(cap->name, sizeof cap->name, "%s", name);
                cap->number_count = (int)(payload_len / sizeof(double));
                if (cap->number_count > SL_RUN_MAX_NUMBERS) cap->number_count = SL_RUN_MAX_NUMBERS;
                memcpy(cap->numbers, payload, (size_t)cap->number_count * sizeof(double));
            }
            break;
        case _SL_MSG_DONE: r->finished = true; break;
        default: break;
        }
        pos += 16 + name_len + payload_len;
    }
    if (!r->finished && stage[0]) snprintf(r->crashed_in, sizeof r->crashed_in, "%s", stage);
}

static void _sl_read_tail(const char *path, char *out, size_t n) {
    out[0] = '\0';
    FILE *f = fopen(path, "rb");
    if (!f) return;
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    long start = size > (long)n - 1 ? size - ((long)n - 1) : 0;
    fseek(f, start, SEEK_SET);
    size_t got = fread(out, 1, n - 1, f);
    out[got] = '\0';
    fclose(f);
}

static bool _sl_start(_sl_job *job, const sl_case *c, int index, const sl_run_options *o) {
    int fds[2];
    memset(job, 0, sizeof *job);
    job->index = index;
    snprintf(job->log_path, sizeof job->log_path, "/tmp/shadowlab-case-XXXXXX");
    int log_fd = mkstemp(job->log_path);
    if (pipe(fds) != 0) return false;
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0) {
        close(fds[0]);
        close(fds[1]);
        return false;
    }
    if (pid == 0) {
        /* Child: keep only our pipe; what lab code prints goes to the log. */
        for (int fd = 3; fd < 1024; fd++)
            if (fd != fds[1] && fd != log_fd) close(fd);
        if (log_fd >= 0) {
            dup2(log_fd, 1);
            dup2(log_fd, 2);
            close(log_fd);
        }
        int null_fd = open("/dev/null", O_RDONLY);
        if (null_fd >= 0) dup2(null_fd, 0);
        struct rlimit core = {0, 0};
        setrlimit(RLIMIT_CORE, &core);
        double limit = o->timeout > 0 ? o->timeout : c->timeout_seconds;
        struct rlimit cpu = {(rlim_t)limit * 2 + 5, (rlim_t)limit * 2 + 6};
        setrlimit(RLIMIT_CPU, &cpu);
        struct rlimit fsize = {64 << 20, 64 << 20};
        setrlimit(RLIMIT_FSIZE, &fsize);
        /* Runaway allocations fail in the case, not on the grading machine
         * (llvmpipe needs well under 1 GiB of address space here). */
        struct rlimit memory = {(rlim_t)4 << 30, (rlim_t)4 << 30};
        setrlimit(RLIMIT_AS, &memory);
        signal(SIGPIPE, SIG_DFL);
        _sl_child_fd = fds[1];
        _exit(_sl_child_main(c, o));
    }
    if (log_fd >= 0) close(log_fd);
    close(fds[1]);
    job->pid = pid;
    job->fd = fds[0];
    job->start = _sl_now();
    job->deadline = job->start + (o->timeout > 0 ? o->timeout : c->timeout_seconds);
    return true;
}

static void _sl_finish(_sl_job *job, sl_case_result *r, bool timed_out) {
    int status = 0;
    if (timed_out) kill(job->pid, SIGKILL);
    while (waitpid(job->pid, &status, 0) < 0 && errno == EINTR) {}
    close(job->fd);
    r->seconds = _sl_now() - job->start;
    r->timed_out = timed_out;
    if (WIFSIGNALED(status)) r->signal = timed_out ? 0 : WTERMSIG(status);
    if (WIFEXITED(status)) r->exit_code = WEXITSTATUS(status);
    _sl_parse(job, r);
    if (r->finished && (r->signal || r->exit_code)) r->finished = false;
    _sl_read_tail(job->log_path, r->output_tail, sizeof r->output_tail);
    unlink(job->log_path);
    free(job->buf);
    job->buf = NULL;
    job->pid = 0;
}

void sl_run_cases(const sl_case *cases, int count, const sl_run_options *o, sl_case_result *results) {
    int jobs = o->jobs > 0 ? o->jobs : 2;
    if (jobs > 64) jobs = 64;
    _sl_job running[64];
    int active = 0, next = 0, done = 0;
    memset(results, 0, sizeof *results * (size_t)count);
    signal(SIGPIPE, SIG_IGN);
    while (done < count) {
        while (active < jobs && next < count) {
            if (_sl_start(&running[active], &cases[next], next, o)) {
                active++;
            } else {
                snprintf(results[next].error, sizeof results[next].error, "could not start a process for this case: %s",
                         strerror(errno));
                done++;
            }
            next++;
        }
        if (active == 0) continue;
        struct pollfd pfd[64];
        double now = _sl_now(), wait = 1e9;
        for (int i = 0; i < active; i++) {
            pfd[i] = (struct pollfd){.fd = running[i].fd, .events = POLLIN};
            if (running[i].deadline - now < wait) wait = running[i].deadline - now;
        }
        int ms = wait <= 0 ? 0 : (int)(wait * 1000) + 1;
        int n = poll(pfd, (nfds_t)active, ms);
        if (n < 0 && errno != EINTR) break;
        now = _sl_now();
        for (int i = active - 1; i >= 0; i--) {
            _sl_job *job = &running[i];
            bool finished = false, timed_out = false;
            if (n > 0 && (pfd[i].revents & (POLLIN | POLLHUP | POLLERR))) {
                if (job->cap - job->len < 65536) {
                    size_t cap = job->cap ? job->cap * 2 : 1 << 20;
                    char *buf = realloc(job->buf, cap);
                    if (buf) {
                        job->buf = buf;
                        job->cap = cap;
                    }
                }
                ssize_t got = job->cap > job->len ? read(job->fd, job->buf + job->len, job->cap - job->len) : -1;
                if (got > 0) job->len += (size_t)got;
                else if (got == 0 || (errno != EINTR && errno != EAGAIN)) finished = true;
            }
            if (!finished && now > job->deadline) finished = timed_out = true;
            if (finished) {
                _sl_finish(job, &results[job->index], timed_out);
                running[i] = running[--active];
                done++;
            }
        }
    }
}

const sl_capture *sl_result_capture(const sl_case_result *r, const char *name) {
    for (int i = 0; i < r->capture_count; i++)
        if (strcmp(r->captures[i].name, name) == 0) return &r->captures[i];
    return NULL;
}

void sl_case_result_free(sl_case_result *r) {
    for (int i = 0; i < r->capture_count; i++) sl_image_free(&r->captures[i].image);
    r->capture_count = 0;
}
