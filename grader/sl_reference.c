#define _POSIX_C_SOURCE 200809L
#include "sl_reference.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include <cjson/cJSON.h>

#include "sl_diagnose.h"
#include "sl_files.h"
#include "sl_json.h"
#include "sl_probe.h"
#include "sl_probe_generic.h"

/* A reference must fit its case: an image of the camera's size, a depth map of the map's. */
static bool _sl_reference_fits(sl_reference *ref, const sl_case *c, const sl_check *k) {
    const sl_image *img = &ref->image;
    int w = c->width, h = c->height, channels = k->kind == SL_CHECK_IMAGE ? 3 : 1;
    if (k->kind == SL_CHECK_DEPTH_MAP) w = h = c->params.shadow_map_size;
    if (k->kind == SL_CHECK_MOMENTS || k->kind == SL_CHECK_MOMENTS_BLURRED) {
        w = h = c->params.shadow_map_size;
        channels = 2;
    }
    if (k->kind == SL_CHECK_FLICKER) h = c->height * c->frame_count; /* lab 6: every frame, stacked */
    if (k->kind == SL_CHECK_CUBE_FACE) w = h = c->params.cube.map_size;
    if (img->width == w && img->height == h && img->channels == channels) return true;
    snprintf(ref->error, sizeof ref->error, "reference does not fit its case: %s is %dx%dx%d, the case makes %dx%dx%d",
             ref->path, img->width, img->height, img->channels, w, h, channels);
    sl_image_free(&ref->image);
    return false;
}

void sl_reference_load(sl_reference *ref, const char *dir, const sl_manifest *manifest, const char *manifest_error,
                       const sl_case *c, const sl_check *k) {
    sl_reference_load_cached(ref, dir, manifest, manifest_error, NULL, c, k);
}

/* A reference that does not read: where its bytes are not the manifest's either, say so too (staff
 * then know it was changed or damaged after it was made, not made broken). */
static void _sl_reference_corrupt(sl_reference *ref, const char *err, const sl_manifest *manifest, const sl_case *c,
                                  const char *file) {
    char why[1500];
    if (manifest && !sl_manifest_verify(manifest, c->name, file, ref->path, why, sizeof why))
        snprintf(ref->error, sizeof ref->error, "reference corrupt: %s; %s", err, why);
    else
        snprintf(ref->error, sizeof ref->error, "reference corrupt: %s", err);
}

static void _sl_reference_load_main(sl_reference *ref, const char *dir, const sl_manifest *manifest,
                                    const char *manifest_error, sl_reference_cache *cache, const sl_case *c,
                                    const sl_check *k);

bool sl_check_uses_lit_mask(const sl_case *c, const sl_check *k) {
    return (sl_check_captures(c, k) & (1u << SL_CAPTURE_LIT_MASK)) != 0;
}

/* The case's lit surfaces (one frame, camera size, one channel), verified as any reference is. */
static void _sl_reference_load_lit_mask(sl_reference *ref, const char *dir, const sl_manifest *manifest,
                                        sl_reference_cache *cache, const sl_case *c) {
    char path[1200], err[512], why[1500];
    snprintf(path, sizeof path, "%s/%s/%s", dir, c->name, SL_LIT_MASK_FILE);
    struct stat st;
    if (stat(path, &st) != 0) {
        snprintf(ref->error, sizeof ref->error,
                 "reference missing: %s (staff: run shadowlab-grade --update-references on a solutions build)", path);
        ref->loaded = false;
        return;
    }
    const char *recorded = cache ? sl_manifest_hash(manifest, c->name, SL_LIT_MASK_FILE) : NULL;
    bool read = recorded && sl_reference_cache_read(cache, path, recorded, &ref->lit_mask);
    if (!read) {
        if (!sl_image_read(path, &ref->lit_mask, err, sizeof err)) {
            if (!sl_manifest_verify(manifest, c->name, SL_LIT_MASK_FILE, path, why, sizeof why))
                snprintf(ref->error, sizeof ref->error, "reference corrupt: %s; %s", err, why);
            else
                snprintf(ref->error, sizeof ref->error, "reference corrupt: %s", err);
            ref->loaded = false;
            return;
        }
        if (!sl_manifest_verify(manifest, c->name, SL_LIT_MASK_FILE, path, why, sizeof why)) {
            snprintf(ref->error, sizeof ref->error, "%s", why);
            sl_image_free(&ref->lit_mask);
            ref->loaded = false;
            return;
        }
    }
    const sl_image *m = &ref->lit_mask;
    if (m->width != c->width || m->height != c->height || m->channels != 1) {
        snprintf(ref->error, sizeof ref->error, "reference does not fit its case: %s is %dx%dx%d, the case makes %dx%dx1",
                 path, m->width, m->height, m->channels, c->width, c->height);
        sl_image_free(&ref->lit_mask);
        ref->loaded = false;
    }
}

void sl_reference_load_cached(sl_reference *ref, const char *dir, const sl_manifest *manifest,
                              const char *manifest_error, sl_reference_cache *cache, const sl_case *c,
                              const sl_check *k) {
    _sl_reference_load_main(ref, dir, manifest, manifest_error, cache, c, k);
    if (ref->loaded && sl_check_uses_lit_mask(c, k)) {
        _sl_reference_load_lit_mask(ref, dir, manifest, cache, c);
        if (!ref->loaded) sl_image_free(&ref->image);
    }
}

static void _sl_reference_load_main(sl_reference *ref, const char *dir, const sl_manifest *manifest,
                                    const char *manifest_error, sl_reference_cache *cache, const sl_case *c,
                                    const sl_check *k) {
    memset(ref, 0, sizeof *ref);
    char file[200];
    if (!sl_check_reference_file(k, file, sizeof file)) return;
    ref->needed = true;
    snprintf(ref->path, sizeof ref->path, "%s/%s/%s", dir, c->name, file);
    struct stat st;
    if (stat(ref->path, &st) != 0) {
        snprintf(ref->error, sizeof ref->error, "reference missing: %s (staff: run shadowlab-grade --update-references on a solutions build)", ref->path);
        return;
    }
    if (k->kind == SL_CHECK_PROBE) {
        if (!sl_probe_reference_read(ref->path, k, ref->numbers, ref->error, sizeof ref->error)) return;
        int outputs = sl_probe_at(k->function)->output_count;
        /* the generic rows' expected outputs: the contract's formula (sl_probe_generic.h), never a file's */
        for (int row = k->rows - k->generic_rows; row < k->rows; row++)
            sl_probe_generic_expected(k, row, &ref->numbers[row * outputs]);
        ref->number_count = k->rows * outputs;
    } else if (k->kind == SL_CHECK_MATRICES) {
        char json_err[600] = "";
        cJSON *json = sl_json_load_file(ref->path, "reference", json_err, sizeof json_err);
        static const char *keys[3] = {"light_view", "light_projection", "shadow_matrix"};
        bool ok = json != NULL;
        for (int m = 0; ok && m < 3; m++) {
            const cJSON *a = cJSON_GetObjectItemCaseSensitive(json, keys[m]);
            ok = cJSON_IsArray(a) && cJSON_GetArraySize(a) == 16;
            for (int i = 0; ok && i < 16; i++) {
                const cJSON *v = cJSON_GetArrayItem(a, i);
                ok = cJSON_IsNumber(v);
                if (ok) ref->numbers[m * 16 + i] = v->valuedouble;
            }
        }
        cJSON_Delete(json);
        if (!ok && !json_err[0])
            snprintf(json_err, sizeof json_err, "%s: expected light_view, light_projection, shadow_matrix: 16 numbers each", ref->path);
        if (!ok) {
            _sl_reference_corrupt(ref, json_err, manifest, c, file);
            return;
        }
        ref->number_count = 48;
    } else {
        /* From the cache only a file whose bytes hash to the manifest's: it
         * then passes every check below but the size, so a reference that is
         * missing from the manifest, changed or corrupt takes the usual way,
         * and its message is the same. */
        const char *recorded = manifest && cache ? sl_manifest_hash(manifest, c->name, file) : NULL;
        if (recorded && sl_reference_cache_read(cache, ref->path, recorded, &ref->image)) {
            ref->loaded = _sl_reference_fits(ref, c, k);
            return;
        }
        char err[512];
        if (!sl_image_read(ref->path, &ref->image, err, sizeof err)) {
            _sl_reference_corrupt(ref, err, manifest, c, file);
            return;
        }
        if (!_sl_reference_fits(ref, c, k)) return;
    }
    char why[1500];
    if (!manifest) {
        snprintf(ref->error, sizeof ref->error, "references cannot be verified: %s", manifest_error);
        sl_image_free(&ref->image);
        return;
    }
    if (!sl_manifest_verify(manifest, c->name, file, ref->path, why, sizeof why)) {
        snprintf(ref->error, sizeof ref->error, "%s", why);
        sl_image_free(&ref->image);
        return;
    }
    ref->loaded = true;
}

void sl_reference_free(sl_reference *ref) {
    sl_image_free(&ref->image);
    sl_image_free(&ref->lit_mask);
}

bool sl_reference_write(const char *dir, sl_manifest *manifest, const sl_case *c, const sl_check *k,
                        const sl_case_result *r, char *err, size_t err_size) {
    char file[200];
    if (!sl_check_reference_file(k, file, sizeof file)) return true;
    char folder[1100], path[1200];
    snprintf(folder, sizeof folder, "%s/%s", dir, c->name);
    if (!sl_mkdirs(folder)) {
        snprintf(err, err_size, "%s: cannot create the folder", folder);
        return false;
    }
    snprintf(path, sizeof path, "%s/%s", folder, file);
    const char *capture = sl_check_capture_name(c, k);
    const sl_capture *cap = sl_result_capture(r, capture);
    if (!cap) {
        snprintf(err, err_size, "%s: the solutions captured no %s (%s)", c->name, capture,
                 r->not_implemented_count ? "a stub is not implemented"
                 : r->capture_error[0]    ? r->capture_error
                 : r->error[0]            ? r->error
                                          : "see the case");
        return false;
    }
    bool ok;
    if (k->kind == SL_CHECK_PROBE) {
        ok = sl_probe_reference_write(path, k, cap->numbers, err, err_size);
    } else if (k->kind == SL_CHECK_MATRICES) {
        static const char *keys[3] = {"light_view", "light_projection", "shadow_matrix"};
        sl_atomic_file f;
        if (!sl_atomic_open(&f, path, err, err_size)) return false;
        fprintf(f.f, "{\n");
        for (int m = 0; m < 3; m++) {
            fprintf(f.f, "  \"%s\": [", keys[m]);
            for (int i = 0; i < 16; i++) fprintf(f.f, "%s%.9g", i ? ", " : "", cap->numbers[m * 16 + i]);
            fprintf(f.f, "]%s\n", m < 2 ? "," : "");
        }
        fprintf(f.f, "}\n");
        ok = sl_atomic_commit(&f, err, err_size);
    } else {
        ok = sl_atomic_write_image(path, &cap->image, err, err_size);
    }
    if (!ok || !sl_manifest_record(manifest, c->name, file, path, r->cpu_seconds, err, err_size)) return false;
    if (!sl_check_uses_lit_mask(c, k)) return true;
    /* the lit surfaces this check measures on: the grader's own, never the runner's */
    const sl_capture *mask = sl_result_capture(r, "lit_mask");
    if (!mask || !mask->is_image) {
        snprintf(err, err_size, "%s: the solutions captured no lit_mask (%s)", c->name,
                 r->capture_error[0] ? r->capture_error : r->error[0] ? r->error : "see the case");
        return false;
    }
    snprintf(path, sizeof path, "%s/%s", folder, SL_LIT_MASK_FILE);
    return sl_atomic_write_image(path, &mask->image, err, err_size) &&
           sl_manifest_record(manifest, c->name, SL_LIT_MASK_FILE, path, r->cpu_seconds, err, err_size);
}
