#define _GNU_SOURCE
#include "sl_run.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "sl_backend.h"
#include "sl_protocol.h"
#include "sl_run_stream.h"
#include "sl_utf8.h"
#ifdef SL_STAFF_LIGHT_CAMERA
#include "sl_light_camera.h" /* staff builds: solutions/framework/ */
#endif

#define _SL_MAX_JOBS 64
#define _SL_OUTPUT_KEEP 2047

void sl_run_parse_stream(const sl_case *c, const void *data, size_t size, sl_case_result *r) {
    memset(r, 0, sizeof *r);
    _sl_stream s = {.c = c, .r = r, .wanted = _sl_wanted_captures(c)};
    _sl_stream_feed(&s, data, size);
    r->finished = s.done && !r->protocol_error[0];
    _sl_stream_end(&s);
}

/* ---- the runners ---- */

typedef struct _sl_job {
    int index;
    sl_sandbox_process proc; /* the runner */
    int job_fd;     /* the runner's fd 0: closed once DONE is checked */
    sl_job *job;    /* the job, until all of it went into job_fd */
    size_t job_sent;
    int channel_fd; /* its fd 3 */
    int output_fd;  /* its stdout and stderr */
    _sl_stream stream;
    char output[_SL_OUTPUT_KEEP + 1]; /* a ring of the last bytes */
    size_t output_len;
    long long output_total;
    double start, deadline, timeout;
    bool channel_open, output_open;
} _sl_job;

/* A runner's time limit counts the time it could run: the time its threads
 * waited for a CPU that other processes held is added (never more than the
 * wall time it spent off a CPU: turns its own threads take are its own),
 * up to _SL_STARVED_TIMEOUTS times the limit in all. Past that, a runner that
 * could run for less than _SL_STARVED_SHARE of its limit could not be graded. */
#define _SL_STARVED_TIMEOUTS 4
#define _SL_STARVED_SHARE 0.1

static double _sl_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static void _sl_close(int *fd) {
    if (*fd >= 0) close(*fd);
    *fd = -1;
}

/* The light camera a lab 1 case's frame draws its depth map with: the table's (sl_scene.c), else, in a
 * staff build, the staff computation (a hidden variant's light), else the overview the handout draws. */
static void _sl_lab1_light_camera(const sl_light *light, const sl_aabb *bounds, float view[16], float projection[16]) {
    mat4 v, p;
    bool known = sl_light_default_matrices(light, bounds, v, p);
#ifdef SL_STAFF_LIGHT_CAMERA
    if (!known) sl_light_camera_compute(light, bounds, v, p);
#endif
    (void)known;
    memcpy(view, v, sizeof v);
    memcpy(projection, p, sizeof p);
}

static void _sl_build_job(sl_job *job, const sl_case *c, const sl_run_options *o, const sl_sandbox_process *p) {
    memset(job, 0, sizeof *job);
    job->magic = SL_JOB_MAGIC;
    job->version = SL_PROTOCOL_VERSION;
    job->size = sizeof *job;
    job->lab = c->lab;
    job->width = c->width;
    job->height = c->height;
    job->backend = o->backend;
    job->scene = c->scene;
    job->frame_count = c->frame_count;
    memcpy(job->frame_lights, c->frame_lights, sizeof c->frame_lights[0] * (size_t)c->frame_count);
    job->light_cameras_given = sl_lab_given_light_camera(c->lab); /* lab 1's frames alone (sl_params.h) */
    for (int f = 0; job->light_cameras_given && f < c->frame_count; f++)
        _sl_lab1_light_camera(&c->frame_lights[f], &c->scene.bounds, job->frame_light_cameras[f][0],
                              job->frame_light_cameras[f][1]);
    job->camera_path = c->camera_path;
    if (c->camera_path) memcpy(job->frame_cameras, c->frame_cameras, sizeof c->frame_cameras[0] * (size_t)c->frame_count);
    job->params = c->params;
    job->captures = _sl_wanted_captures(c);
    for (int k = 0; k < SL_JOB_MAX_PROBES; k++) {
        sl_probe_table *t = &job->probes[k];
        if (k >= c->check_count || c->checks[k].kind != SL_CHECK_PROBE) continue;
        const sl_probe_function *f = sl_probe_at(c->checks[k].function);
        snprintf(t->function, sizeof t->function, "%s", f->name); /* by name: the runner's build resolves it */
        t->input_count = sl_probe_input_count(f);
        t->output_count = f->output_count;
        t->rows = c->checks[k].rows;
        memcpy(t->inputs, c->checks[k].inputs, sizeof t->inputs);
    }
    snprintf(job->labs_dir, sizeof job->labs_dir, "%s", p->labs_dir);
    snprintf(job->framework_dir, sizeof job->framework_dir, "%s", p->framework_dir);
}

/* A pipe whose ends close on exec (pipe2 is not everywhere). */
static int _sl_pipe(int fds[2]) {
    if (pipe(fds) != 0) return -1;
    if (fcntl(fds[0], F_SETFD, FD_CLOEXEC) != 0 || fcntl(fds[1], F_SETFD, FD_CLOEXEC) != 0) {
        int error = errno;
        close(fds[0]);
        close(fds[1]);
        errno = error;
        return -1;
    }
    return 0;
}

/* Writes what the runner's pipe takes now, never waiting (lab code runs
 * before the runner's main, and may never read): the rest when it reads,
 * from the poll loop. False when the pipe broke. */
static bool _sl_send_job(_sl_job *job) {
    const char *data = (const char *)job->job;
    while (job->job_sent < sizeof *job->job) {
        ssize_t w = write(job->job_fd, data + job->job_sent, sizeof *job->job - job->job_sent);
        if (w < 0 && errno == EINTR) continue;
        if (w < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
        if (w <= 0) return false;
        job->job_sent += (size_t)w;
    }
    free(job->job);
    job->job = NULL;
    return true;
}

static bool _sl_start(_sl_job *job, const sl_case *c, int index, const sl_run_options *o, sl_case_result *r) {
    memset(job, 0, sizeof *job);
    job->index = index;
    job->job_fd = job->channel_fd = job->output_fd = -1;
    const sl_runner_setup *setup = o->setups[c->lab].runner ? &o->setups[c->lab] : &o->setups[0];
    if (!setup->runner) {
        snprintf(r->error, sizeof r->error, "no runner for lab %d in this build", c->lab);
        return false;
    }
    int in[2], channel[2], output[2];
    if (_sl_pipe(in) != 0) goto fail_errno;
    if (_sl_pipe(channel) != 0) goto fail_in;
    if (_sl_pipe(output) != 0) goto fail_channel;
    double timeout = o->timeout > 0 ? o->timeout : c->timeout_seconds;
    sl_sandbox_spawn_desc d = {
        .runner = setup->runner,
        .labs_tree = setup->labs_tree,
        .framework_dir = o->framework_dir,
        .environment = o->environment,
        .display = o->backend == SL_BACKEND_WINDOW,
        .stdin_fd = in[0],
        .channel_fd = channel[1],
        .output_fd = output[1],
        .cpu_seconds = timeout * 2 + 5, /* wall clock is the grader's deadline; this stops a runaway for good */
        .memory_bytes = o->memory_bytes ? o->memory_bytes : (unsigned long long)(c->memory_mb * 1048576.0),
    };
    memcpy(d.lab_dirs, setup->lab_dirs, sizeof d.lab_dirs);
    char err[600];
    bool spawned = sl_sandbox_spawn(o->sandbox, &d, &job->proc, err, sizeof err);
    close(in[0]);
    close(channel[1]);
    close(output[1]);
    if (!spawned) {
        close(in[1]);
        close(channel[0]);
        close(output[0]);
        /* no lab code ran yet: the machine's fault, never the submission's */
        snprintf(r->staff_error, sizeof r->staff_error, "could not start the runner: %s", err);
        return false;
    }
    job->job_fd = in[1];
    job->channel_fd = channel[0];
    job->output_fd = output[0];
    job->channel_open = job->output_open = true;
    fcntl(job->channel_fd, F_SETFL, O_NONBLOCK);
    fcntl(job->output_fd, F_SETFL, O_NONBLOCK);
    job->stream = (_sl_stream){.c = c, .r = r, .wanted = _sl_wanted_captures(c)};
    job->start = _sl_now();
    job->timeout = timeout;
    job->deadline = job->start + timeout;
    r->started = true;
    /* The job goes as the runner reads it (_sl_send_job). No memory for it
     * is the machine's fault; a runner that left before reading it is the
     * case's (lab code's constructors ran by then). */
    job->job = malloc(sizeof *job->job);
    if (job->job) _sl_build_job(job->job, c, o, &job->proc);
    if (!job->job || fcntl(job->job_fd, F_SETFL, O_NONBLOCK) != 0) {
        snprintf(r->staff_error, sizeof r->staff_error, "could not send the case to the runner: %s",
                 job->job ? strerror(errno) : "out of memory");
        _sl_close(&job->job_fd);
    } else if (!_sl_send_job(job)) {
        /* lab code's constructors ran and the runner left already: what it said, or not, is the case's */
        _sl_close(&job->job_fd);
    }
    return true;
fail_channel:
    close(channel[0]);
    close(channel[1]);
fail_in:
    close(in[0]);
    close(in[1]);
fail_errno:
    snprintf(r->staff_error, sizeof r->staff_error, "could not start the runner: %s", strerror(errno));
    return false;
}

static void _sl_keep_output(_sl_job *job, const char *data, size_t n) {
    job->output_total += (long long)n;
    if (n >= _SL_OUTPUT_KEEP) {
        memcpy(job->output, data + n - _SL_OUTPUT_KEEP, _SL_OUTPUT_KEEP);
        job->output_len = _SL_OUTPUT_KEEP;
        return;
    }
    if (job->output_len + n > _SL_OUTPUT_KEEP) {
        size_t drop = job->output_len + n - _SL_OUTPUT_KEEP;
        memmove(job->output, job->output + drop, job->output_len - drop);
        job->output_len -= drop;
    }
    memcpy(job->output + job->output_len, data, n);
    job->output_len += n;
}

/* Reads what is there; false when the fd reached its end. */
static bool _sl_drain(_sl_job *job, bool channel) {
    static char buf[1 << 16];
    for (;;) {
        ssize_t got = read(channel ? job->channel_fd : job->output_fd, buf, sizeof buf);
        if (got > 0) {
            if (!channel) _sl_keep_output(job, buf, (size_t)got);
            else if (!_sl_stream_feed(&job->stream, buf, (size_t)got)) return false;
            continue;
        }
        if (got < 0 && errno == EINTR) continue;
        if (got < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return true;
        return false;
    }
}

/* After DONE: the process must still be the runner (lab code could have
 * exec'ed another program to speak for it). Then it may exit. */
static void _sl_acknowledge(_sl_job *job, const sl_run_options *o) {
    if (job->job_fd < 0) return;
    if (!sl_sandbox_runs_runner(o->sandbox, &job->proc)) {
        _sl_protocol_error(&job->stream, "DONE came from a process that is no longer the runner");
        sl_sandbox_kill(o->sandbox, job->proc.pid);
    }
    _sl_close(&job->job_fd);
}

/* Where `text` names a file under `seen` (the folder as the runner saw it: "/labs" in the namespaces
 * sandbox, a real path below it), the name the student knows: `as` ("labs") and the rest. Only at a
 * name's start (the text's, or after a space, a bracket or a quote), so a longer path is left alone. */
static void _sl_rename_folder(char *text, size_t size, const char *seen, const char *as) {
    size_t n = strlen(seen);
    if (n < 2 || seen[0] != '/') return;
    char out[8192];
    size_t used = 0;
    for (const char *p = text; *p && used + 1 < sizeof out;) {
        bool start = p == text || strchr(" \t\n(\"'`", p[-1]) != NULL;
        if (start && strncmp(p, seen, n) == 0 && p[n] == '/') {
            used += (size_t)snprintf(out + used, sizeof out - used, "%s", as);
            p += n;
            if (used >= sizeof out) used = sizeof out - 1;
            continue;
        }
        out[used++] = *p++;
    }
    out[used] = '\0';
    sl_utf8_copy(text, size, out);
}

/* A runner's errors name files as it saw them, in the sandbox's view (/labs/lab3_bias/shaders/bias.glsl)
 * or, below that level, by their real paths on this machine: a student knows them as the handout names
 * them (labs/lab3_bias/shaders/bias.glsl). */
static void _sl_student_paths(sl_case_result *r, const char *labs_dir, const char *framework_dir) {
    const char *seen[2] = {labs_dir, framework_dir}, *as[2] = {"labs", "framework"};
    for (int i = 0; i < 2; i++) {
        char real[4096];
        const char *forms[2] = {seen[i], realpath(seen[i], real) ? real : NULL};
        for (int f = 0; f < 2; f++) {
            if (!forms[f] || (f == 1 && strcmp(forms[1], forms[0]) == 0)) continue;
            _sl_rename_folder(r->error, sizeof r->error, forms[f], as[i]);
            _sl_rename_folder(r->capture_error, sizeof r->capture_error, forms[f], as[i]);
            for (int k = 0; k < SL_JOB_MAX_PROBES; k++)
                _sl_rename_folder(r->probe_errors[k], sizeof r->probe_errors[k], forms[f], as[i]);
        }
    }
}

static void _sl_finish(_sl_job *job, const sl_run_options *o, bool kill_it) {
    sl_case_result *r = job->stream.r;
    char labs_dir[sizeof job->proc.labs_dir], framework_dir[sizeof job->proc.framework_dir];
    snprintf(labs_dir, sizeof labs_dir, "%s", job->proc.labs_dir); /* as the runner saw them */
    snprintf(framework_dir, sizeof framework_dir, "%s", job->proc.framework_dir);
    if (kill_it) sl_sandbox_kill(o->sandbox, job->proc.pid);
    _sl_close(&job->job_fd);
    free(job->job);
    job->job = NULL;
    int status = 0;
    struct rusage usage = {0};
    while (wait4(job->proc.pid, &status, 0, &usage) < 0 && errno == EINTR) {}
    /* In case it was not PID 1 of a namespace: nothing of its session may
     * stay, nor of its uid or cgroup, which are then free for another. */
    sl_sandbox_kill(o->sandbox, job->proc.pid);
    sl_sandbox_end(o->sandbox, &job->proc);
    if (job->channel_open) _sl_drain(job, true);
    if (job->output_open) _sl_drain(job, false);
    _sl_close(&job->channel_fd);
    _sl_close(&job->output_fd);
    r->seconds = _sl_now() - job->start;
    r->cpu_seconds = (double)usage.ru_utime.tv_sec + (double)usage.ru_utime.tv_usec * 1e-6 +
                     (double)usage.ru_stime.tv_sec + (double)usage.ru_stime.tv_usec * 1e-6;
    if (WIFSIGNALED(status) && !r->timed_out && !r->interrupted) r->signal = WTERMSIG(status);
    if (WIFEXITED(status)) r->exit_code = WEXITSTATUS(status);
    bool done = job->stream.done;
    _sl_stream_end(&job->stream);
    _sl_student_paths(r, labs_dir, framework_dir);
    r->finished = done && !r->protocol_error[0] && !r->staff_error[0] && !r->timed_out && !r->interrupted &&
                  WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (r->protocol_error[0]) {
        /* whatever arrived is not to be trusted */
        sl_case_result_free(r);
        r->not_implemented_count = 0;
    }
    /* The tail kept: where output was dropped its first character may be cut (not lab code's doing), and
     * cleaning may lengthen the text (U+FFFD for a byte): the end is what it printed last, so the end is kept. */
    size_t skip = 0;
    while (job->output_total > (long long)job->output_len && skip < 3 && skip < job->output_len &&
           ((unsigned char)job->output[skip] & 0xC0) == 0x80) /* a continuation byte */
        skip++;
    char clean[3 * _SL_OUTPUT_KEEP + 1];
    size_t len = sl_utf8_clean(clean, sizeof clean, job->output + skip, job->output_len - skip,
                               SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB);
    size_t start = sl_utf8_tail(clean, len, sizeof r->output_tail - 1);
    memcpy(r->output_tail, clean + start, len - start + 1);
    r->output_dropped = job->output_total - (long long)(job->output_len - skip);
    job->proc.pid = 0;
}

/* At the deadline: true when the runner had its time; else the deadline
 * moves by the time others' processes took from it (see _SL_STARVED_TIMEOUTS). */
static bool _sl_out_of_time(_sl_job *job, double now) {
    if (now <= job->deadline) return false;
    double elapsed = now - job->start, cpu = 0, waited = 0, starved = 0;
    if (sl_sandbox_usage(job->proc.pid, &cpu, &waited) && waited > 0) {
        double off_cpu = elapsed - cpu;
        starved = waited < off_cpu ? waited : off_cpu > 0 ? off_cpu : 0;
    }
    double could_run = elapsed - starved;
    if (could_run < job->timeout && elapsed < _SL_STARVED_TIMEOUTS * job->timeout) {
        double wait = job->timeout - could_run;
        job->deadline = now + (wait > 0.25 ? wait : 0.25);
        return false;
    }
    if (could_run < _SL_STARVED_SHARE * job->timeout)
        snprintf(job->stream.r->staff_error, sizeof job->stream.r->staff_error,
                 "the runner was starved of CPU by other processes: in %.0f s it could run for %.1f s (%.1f s on a "
                 "CPU), its limit is %.0f s (the machine is overloaded: grade again when it is not)",
                 elapsed, could_run, cpu, job->timeout);
    return true;
}

bool sl_run_cases(const sl_case *cases, int count, const sl_run_options *o, sl_case_result *results,
                  volatile int *stop) {
    int jobs = o->jobs > 0 ? o->jobs : 2;
    if (jobs > _SL_MAX_JOBS) jobs = _SL_MAX_JOBS;
    static _sl_job running[_SL_MAX_JOBS];
    int active = 0, next = 0, ended = 0;
    memset(results, 0, sizeof *results * (size_t)count);
    signal(SIGPIPE, SIG_IGN);
    while (next < count || active > 0) {
        if (stop && *stop) break;
        while (active < jobs && next < count) {
            if (_sl_start(&running[active], &cases[next], next, o, &results[next])) active++;
            else if (o->case_ended) o->case_ended(&cases[next], &results[next], ++ended, count, o->case_ended_context);
            next++;
        }
        if (active == 0) continue;
        struct pollfd pfd[3 * _SL_MAX_JOBS];
        double now = _sl_now(), wait = 1e9;
        for (int i = 0; i < active; i++) {
            pfd[3 * i] = (struct pollfd){.fd = running[i].channel_open ? running[i].channel_fd : -1, .events = POLLIN};
            pfd[3 * i + 1] = (struct pollfd){.fd = running[i].output_open ? running[i].output_fd : -1, .events = POLLIN};
            pfd[3 * i + 2] = (struct pollfd){.fd = running[i].job ? running[i].job_fd : -1, .events = POLLOUT};
            if (running[i].deadline - now < wait) wait = running[i].deadline - now;
        }
        int ms = wait <= 0 ? 0 : wait > 1 ? 1000 : (int)(wait * 1000) + 1;
        nfds_t watched = (nfds_t)(3 * active);
        if (watched > sizeof pfd / sizeof pfd[0]) watched = sizeof pfd / sizeof pfd[0];
        int n = poll(pfd, watched, ms);
        if (n < 0 && errno != EINTR) break;
        now = _sl_now();
        for (int i = active - 1; i >= 0; i--) {
            _sl_job *job = &running[i];
            bool broken = false;
            if (n > 0 && job->job && job->job_fd >= 0 && (pfd[3 * i + 2].revents & (POLLOUT | POLLHUP | POLLERR)) &&
                !_sl_send_job(job)) {
                /* the runner's end is closed: it left before reading its case, which the end of its output says */
                free(job->job);
                job->job = NULL;
                _sl_close(&job->job_fd);
            }
            if (n > 0 && job->channel_open && (pfd[3 * i].revents & (POLLIN | POLLHUP | POLLERR))) {
                if (!_sl_drain(job, true)) {
                    job->channel_open = false;
                    broken = job->stream.r->protocol_error[0] != '\0';
                }
                if (job->stream.done) _sl_acknowledge(job, o);
            }
            if (n > 0 && job->output_open && (pfd[3 * i + 1].revents & (POLLIN | POLLHUP | POLLERR)))
                job->output_open = _sl_drain(job, false);
            /* The runner's set-up failed: it said why and stops. */
            if (job->stream.r->error[0] && !job->stream.done) _sl_close(&job->job_fd);
            bool timed_out = _sl_out_of_time(job, now);
            if (timed_out && !job->stream.r->staff_error[0]) job->stream.r->timed_out = true;
            if (broken || timed_out || (!job->channel_open && !job->output_open)) {
                _sl_finish(job, o, broken || timed_out || !job->stream.done);
                if (o->case_ended)
                    o->case_ended(job->stream.c, job->stream.r, ++ended, count, o->case_ended_context);
                running[i] = running[--active];
            }
        }
    }
    if (active > 0 || next < count) {
        for (int i = 0; i < active; i++) {
            running[i].stream.r->interrupted = true;
            _sl_finish(&running[i], o, true);
        }
        for (int i = next; i < count; i++) results[i].interrupted = true;
        return false;
    }
    return true;
}
