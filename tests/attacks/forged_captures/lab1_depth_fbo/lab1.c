/* Attack: send exactly what the case asks for, and nothing it could refuse.
 * In the first lab call (every case of labs 1-6 draws lab 1's map, and lab
 * 1's probes call these functions), find the job in this process's memory
 * and answer every capture it asks for: the framebuffer "complete" as
 * glGet* would say it, identity matrices, each picture at its exact size
 * and full of zeros, each probe's outputs as zeros; then DONE, and wait for
 * the grader as the runner does. The runner's own HELLO went first; nothing
 * here breaks a rule of the channel, so only the grading can refuse it:
 * state numbers alone must earn nothing, and empty pictures match no
 * reference. No framebuffer is ever made. */
#include "@SOURCE_DIR@/tests/attack_util.h"

/* The job the runner read: a static object with a known magic number (a
 * probe case draws no frame: frame_count may be 0). Adjacent writable
 * mappings are searched as one: it may straddle two. */
static const sl_job *_search(unsigned long lo, unsigned long hi) {
    for (unsigned long p = lo; p + sizeof(sl_job) <= hi; p += 4) {
        const sl_job *j = (const sl_job *)p;
        if (j->magic == SL_JOB_MAGIC && j->version == SL_PROTOCOL_VERSION && j->size == sizeof(sl_job) &&
            j->width > 0 && j->height > 0 && j->frame_count >= 0)
            return j;
    }
    return NULL;
}

static const sl_job *_find_job(void) {
    FILE *maps = fopen("/proc/self/maps", "r");
    if (!maps) return NULL;
    char line[512];
    const sl_job *found = NULL;
    unsigned long start = 0, end = 0;
    while (!found && fgets(line, sizeof line, maps)) {
        unsigned long lo, hi;
        char perms[8];
        if (sscanf(line, "%lx-%lx %7s", &lo, &hi, perms) != 3 || perms[0] != 'r' || perms[1] != 'w') continue;
        if (lo != end) {
            if (end > start) found = _search(start, end);
            start = lo;
        }
        end = hi;
    }
    if (!found && end > start) found = _search(start, end);
    fclose(maps);
    return found;
}

static void _fill(int capture, int w, int h, int channels, float value) {
    size_t n = (size_t)w * (size_t)h * (size_t)channels, bytes = SL_IMAGE_HEADER_BYTES + n * sizeof(float);
    char *buf = calloc(1, bytes);
    if (!buf) return;
    int32_t dims[3] = {w, h, channels};
    memcpy(buf, dims, sizeof dims);
    float *pixels = (float *)(buf + SL_IMAGE_HEADER_BYTES);
    for (size_t i = 0; i < n; i++) pixels[i] = value;
    attack_send(SL_MSG_IMAGE, sl_capture_name(capture), buf, bytes);
    free(buf);
}

static void _numbers(int capture, const double *v, int count) {
    attack_send(SL_MSG_NUMBERS, sl_capture_name(capture), v, (uint64_t)count * sizeof(double));
}

static void _forge(void) {
    const sl_job *job = _find_job();
    if (!job) return;
    int size = job->params.shadow_map_size, w = job->width, h = job->height;
    static double v[SL_PROBE_MAX_ROWS * SL_PROBE_MAX_OUTPUTS]; /* zeros */
    for (int capture = 0; capture < SL_CAPTURE_END; capture++) {
        if (!((job->captures >> capture) & 1u)) continue;
        if (capture >= SL_CAPTURE_PROBE) {
            const sl_probe_table *t = &job->probes[capture - SL_CAPTURE_PROBE];
            _numbers(capture, v, t->rows * t->output_count);
        } else if (capture >= SL_CAPTURE_CUBE_FACE && capture <= SL_CAPTURE_CUBE_FACE_LAST) {
            _fill(capture, job->params.cube.map_size, job->params.cube.map_size, 1, 0);
        } else if (capture == SL_CAPTURE_FBO) {
            double fbo[SL_FBO_NUMBERS] = {GL_FRAMEBUFFER_COMPLETE, GL_TEXTURE, 1, 24, size, size, GL_NONE, GL_NONE,
                                          GL_NONE, size};
            _numbers(capture, fbo, SL_FBO_NUMBERS);
        } else if (capture == SL_CAPTURE_MATRICES) {
            double m[SL_MATRICES_NUMBERS] = {0};
            for (int k = 0; k < 3; k++)
                for (int i = 0; i < 4; i++) m[k * 16 + i * 5] = 1;
            _numbers(capture, m, SL_MATRICES_NUMBERS);
        } else if (capture == SL_CAPTURE_MOMENTS_TARGET) {
            _numbers(capture, v, SL_MOMENTS_TARGET_NUMBERS);
        } else if (capture == SL_CAPTURE_PATH) {
            double path[SL_PATH_NUMBERS] = {job->lab, 0};
            _numbers(capture, path, SL_PATH_NUMBERS);
        } else if (capture == SL_CAPTURE_DEPTH_MAP) {
            _fill(capture, size, size, 1, 0);
        } else if (capture == SL_CAPTURE_MOMENTS || capture == SL_CAPTURE_MOMENTS_BLURRED) {
            _fill(capture, size, size, 2, 0);
        } else if (capture == SL_CAPTURE_IMAGE) {
            _fill(capture, w, h, 3, 0);
        } else if (capture == SL_CAPTURE_FLICKER) {
            _fill(capture, w, h * (job->frame_count > 0 ? job->frame_count : 1), 1, 1);
        } else if (capture == SL_CAPTURE_VISIBILITY || capture == SL_CAPTURE_VISIBILITY_UNREDUCED) {
            _fill(capture, w, h, 1, 1);
        } else {
            _fill(capture, w, h, 1, 0); /* the lit mask, the cascade index */
        }
    }
    attack_send(SL_MSG_DONE, NULL, NULL, 0);
    attack_wait_for_grader();
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)size;
    (void)map;
    _forge();
    return SL_NOT_IMPLEMENTED;
}

sl_status lab1_begin_depth_pass(const sl_shadow_map *map) {
    (void)map;
    _forge();
    return SL_NOT_IMPLEMENTED;
}

void lab1_destroy_shadow_map(sl_shadow_map *map) { (void)map; }
