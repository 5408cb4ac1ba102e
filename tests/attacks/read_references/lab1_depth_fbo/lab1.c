/* Attack: hand the grader its own answers. In the first lab call, find the
 * job in this process's memory, find the case it is by reading the case
 * files, read that case's references from disk with the framework's own
 * image reader, and send them as the captures, with a framebuffer that
 * checks out and DONE. Where the files can be read this earns the marks
 * (the test attack.read_references_works_without_sandbox shows it); the
 * sandbox must leave it nothing to read. */
#include "@SOURCE_DIR@/tests/attack_util.h"
#include <cjson/cJSON.h>

#include "sl_image.h"
#include "sl_json.h"

/* The job the runner read: a static object with a known magic number. It
 * may straddle two mappings (a file's data and the zeroed pages after it),
 * so adjacent writable mappings are searched as one. */
static const sl_job *_search(unsigned long lo, unsigned long hi) {
    for (unsigned long p = lo; p + sizeof(sl_job) <= hi; p += 4) {
        const sl_job *j = (const sl_job *)p;
        if (j->magic == SL_JOB_MAGIC && j->version == SL_PROTOCOL_VERSION && j->size == sizeof(sl_job) &&
            j->frame_count > 0)
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

static const char *_string(const cJSON *o, const char *key) { return cJSON_GetStringValue(cJSON_GetObjectItem(o, key)); }

/* The case file that describes this job: same lab, scene, size and modes. */
static bool _find_case(const char *project, const sl_job *job, char *name, size_t n) {
    char dir[PATH_MAX + 32];
    snprintf(dir, sizeof dir, "%s/grader/cases", project);
    DIR *d = opendir(dir);
    if (!d) return false;
    struct dirent *e;
    bool found = false;
    while (!found && (e = readdir(d))) {
        if (!strstr(e->d_name, ".json")) continue;
        char path[PATH_MAX + 300], err[256];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        cJSON *c = sl_json_load_file(path, "case", err, sizeof err);
        if (!c) continue;
        const cJSON *params = cJSON_GetObjectItem(c, "params"), *lab = cJSON_GetObjectItem(c, "lab");
        const cJSON *width = cJSON_GetObjectItem(c, "width"), *frames = cJSON_GetObjectItem(c, "light_path");
        const char *scene = _string(c, "scene"), *bias = _string(params, "bias_mode"), *filter = _string(params, "filter");
        const char *compare = _string(params, "compare");
        found = cJSON_IsNumber(lab) && lab->valueint == job->lab && scene && strcmp(scene, job->scene.name) == 0 &&
                (width ? width->valueint : 256) == job->width &&
                (frames ? cJSON_GetArraySize(frames) : 1) == job->frame_count &&
                (!bias || strcmp(bias, sl_bias_mode_name(job->params.bias.mode)) == 0) &&
                (!filter || strcmp(filter, sl_filter_mode_name(job->params.filter.mode)) == 0) &&
                (!compare || (strcmp(compare, "hardware") == 0) == (job->params.compare == SL_COMPARE_HARDWARE));
        if (found) snprintf(name, n, "%s", _string(c, "name"));
        cJSON_Delete(c);
    }
    closedir(d);
    return found;
}

static bool _send_reference(const char *dir, const char *file, const char *capture) {
    char path[PATH_MAX + 64], err[256];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    sl_image img;
    if (access(path, R_OK) != 0 || !sl_image_read(path, &img, err, sizeof err)) return false;
    size_t n = (size_t)img.width * (size_t)img.height * (size_t)img.channels * sizeof(float);
    char *buf = malloc(SL_IMAGE_HEADER_BYTES + n);
    int32_t dims[3] = {img.width, img.height, img.channels};
    memcpy(buf, dims, sizeof dims);
    memcpy(buf + SL_IMAGE_HEADER_BYTES, img.data, n);
    attack_send(SL_MSG_IMAGE, capture, buf, SL_IMAGE_HEADER_BYTES + n);
    free(buf);
    sl_image_free(&img);
    return true;
}

sl_status lab1_create_shadow_map(int size, sl_shadow_map *map) {
    (void)map;
    char project[PATH_MAX], name[128], dir[PATH_MAX + 200];
    const sl_job *job = _find_job();
    if (!job || !attack_find_project(__FILE__, project, sizeof project) || !_find_case(project, job, name, sizeof name))
        return SL_NOT_IMPLEMENTED;
    snprintf(dir, sizeof dir, "%s/grader/references/%s", project, name);
    if (job->captures & (1u << SL_CAPTURE_FBO)) {
        double fbo[SL_FBO_NUMBERS] = {GL_FRAMEBUFFER_COMPLETE, GL_TEXTURE, 1, 24, size, size, 0, 0, 0, size};
        attack_send(SL_MSG_NUMBERS, "fbo", fbo, sizeof fbo);
    }
    if (job->captures & (1u << SL_CAPTURE_DEPTH_MAP)) _send_reference(dir, "depth_map.exr", "depth_map");
    if (job->captures & (1u << SL_CAPTURE_VISIBILITY)) _send_reference(dir, "visibility.png", "visibility");
    if (job->captures & (1u << SL_CAPTURE_MATRICES)) {
        char path[PATH_MAX + 300], err[256];
        snprintf(path, sizeof path, "%s/matrices.json", dir);
        cJSON *m = sl_json_load_file(path, "matrices", err, sizeof err);
        double v[SL_MATRICES_NUMBERS] = {0};
        static const char *const keys[3] = {"light_view", "light_projection", "shadow_matrix"};
        for (int k = 0; m && k < 3; k++)
            for (int i = 0; i < 16; i++) v[k * 16 + i] = cJSON_GetArrayItem(cJSON_GetObjectItem(m, keys[k]), i)->valuedouble;
        cJSON_Delete(m);
        attack_send(SL_MSG_NUMBERS, "matrices", v, sizeof v);
    }
    attack_send(SL_MSG_DONE, NULL, NULL, 0);
    attack_wait_for_grader();
    return SL_NOT_IMPLEMENTED;
}

ATTACK_LAB1_STUBS
