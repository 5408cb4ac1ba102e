/* sl_lab1_4_programs: the programs of labs 1-4's shadow-map frame (sl_lab1_4_shadow_map.c draws with
 * them): lab 1's depth program, the debug view's, and the camera pass's per lab and setting. */
#define _POSIX_C_SOURCE 200809L
#include "sl_lab1_4_programs.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef struct _sl_variant {
    sl_lab1_4_variant_key key;
    sl_lab1_4_slot slot;
    bool stale;              /* its files changed while another program was in use: rebuild when used */
    unsigned long last_used; /* frame number */
} _sl_variant;

/* Enough for every setting an instructor cycles through in a lecture; the
 * least recently used program makes room beyond that. */
#define _SL_MAX_VARIANTS 32

struct _sl_programs {
    sl_lab1_4_slot depth, debug;
    _sl_variant variants[_SL_MAX_VARIANTS];
    int variant_count;
    int builds;
    double build_ms;
};

/* The programs, made by the first frame (the renderer's technique_state[1]); NULL when out of memory. */
static struct _sl_programs *_sl_programs_of(sl_renderer *r) {
    if (!r->technique_state[1]) r->technique_state[1] = calloc(1, sizeof(struct _sl_programs));
    return r->technique_state[1];
}

bool sl_lab1_4_programs_ready(sl_renderer *r) { return _sl_programs_of(r) != NULL; }

static double _sl_now_ms(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static void _sl_path(char *out, size_t n, const char *dir, const char *file) { snprintf(out, n, "%s/%s", dir, file); }

/* Builds s from vertex and fragment files (each under its own folder); the error goes to shader_errors[lab]. */
static bool _sl_slot_build(sl_renderer *r, sl_lab1_4_slot *s, const char *vs_dir, const char *vs_file, const char *fs_dir,
                           const char *fs_file, const char *defines, int lab) {
    char vs[SL_PATH_MAX * 2], fs[SL_PATH_MAX * 2];
    _sl_path(vs, sizeof vs, vs_dir, vs_file);
    _sl_path(fs, sizeof fs, fs_dir, fs_file);
    sl_shader_desc desc = {
        .vertex_path = vs,
        .fragment_path = fs,
        .search_dirs = {r->labs_dir, r->shaders_dir},
        .defines = defines,
    };
    double start = _sl_now_ms();
    s->attempted = true;
    bool ok = sl_program_build(&s->program, &desc, r->shader_errors[lab], sizeof r->shader_errors[lab]);
    s->compiles = ok;
    _sl_programs_of(r)->builds++;
    _sl_programs_of(r)->build_ms += _sl_now_ms() - start;
    return ok;
}

/* Rebuilds s if its files changed; false (old program kept) with the error in shader_errors[lab]. */
static bool _sl_slot_reload(sl_renderer *r, sl_lab1_4_slot *s, int lab, bool *reloaded) {
    char e[sizeof r->shader_errors[0]];
    double start = _sl_now_ms();
    bool rebuilt = sl_program_reload_if_changed(&s->program, e, sizeof e);
    if (rebuilt || e[0]) {
        _sl_programs_of(r)->builds++;
        _sl_programs_of(r)->build_ms += _sl_now_ms() - start;
    }
    if (rebuilt) {
        r->shader_errors[lab][0] = '\0';
        s->compiles = true;
        if (reloaded) *reloaded = true;
    } else if (e[0]) {
        snprintf(r->shader_errors[lab], sizeof r->shader_errors[lab], "%s", e);
        s->compiles = false;
        return false;
    }
    return true;
}

const sl_lab1_4_uniforms *sl_lab1_4_uniforms_of(sl_lab1_4_slot *s) {
    if (s->located != s->program.id) {
#define _SL_UNIFORM_LOOKUP(name) s->u.name = glGetUniformLocation(s->program.id, "u_" #name);
        SL_LAB1_4_UNIFORMS(_SL_UNIFORM_LOOKUP)
#undef _SL_UNIFORM_LOOKUP
        s->located = s->program.id;
    }
    return &s->u;
}

/* A framework program (or lab 1's depth program), built on first use; NULL if it does not compile. */
static sl_lab1_4_slot *_sl_fixed_program(sl_renderer *r, sl_lab1_4_slot *s, const char *dir, const char *vs, const char *fs,
                                   int lab) {
    if (!s->attempted) _sl_slot_build(r, s, dir, vs, dir, fs, NULL, lab);
    return s->program.id ? s : NULL;
}

sl_lab1_4_slot *sl_lab1_4_depth_program(sl_renderer *r) {
    return _sl_fixed_program(r, &_sl_programs_of(r)->depth, r->labs_dir, "lab1_depth_fbo/shaders/depth.vert",
                             "lab1_depth_fbo/shaders/depth.frag", 1);
}

sl_lab1_4_slot *sl_lab1_4_debug_program(sl_renderer *r) {
    return _sl_fixed_program(r, &_sl_programs_of(r)->debug, r->shaders_dir, "debug_quad.vert", "debug_quad.frag", 0);
}

/* The camera-pass shaders of each lab: a lab's fragment shader includes its GLSL and the labs' before it. */
static const char *const _sl_scene_vertex[SL_RENDERER_MAX_LAB + 1] = {
    [0] = "plain.vert", [2] = "scene.vert", [3] = "scene.vert", [4] = "scene.vert", [5] = "scene.vert",
};
static const char *const _sl_scene_fragment[SL_RENDERER_MAX_LAB + 1] = {
    [0] = "plain.frag", [2] = "scene.frag", [3] = "scene_bias.frag", [4] = "scene_filter.frag",
    [5] = "scene_vsm.frag",
};

bool sl_lab1_4_has_camera_pass(int lab) { return _sl_scene_fragment[lab] != NULL; }

static void _sl_variant_defines(const sl_lab1_4_variant_key *k, char *out, size_t n) {
    int len = snprintf(out, n, "#define SL_LAB %d\n#define SL_LIGHT_TYPE %d\n", k->lab, k->light_type);
    if (k->hardware) len += snprintf(out + len, n - (size_t)len, "#define SL_HARDWARE_COMPARE 1\n");
    if (k->lab >= 3) len += snprintf(out + len, n - (size_t)len, "#define SL_BIAS_MODE %d\n", k->bias_mode);
    if (k->lab == 4)
        snprintf(out + len, n - (size_t)len, "#define SL_FILTER_MODE %d\n#define SL_GRID_RADIUS %d\n", k->filter_mode,
                 k->grid_radius);
}

/* Field by field: the padding of two equal keys may differ. */
static bool _sl_same_variant(const sl_lab1_4_variant_key *a, const sl_lab1_4_variant_key *b) {
    return a->lab == b->lab && a->light_type == b->light_type && a->hardware == b->hardware &&
           a->bias_mode == b->bias_mode && a->filter_mode == b->filter_mode && a->grid_radius == b->grid_radius;
}

/* The camera-pass program for key, built on first use; NULL if it does not compile. */
sl_lab1_4_slot *sl_lab1_4_variant_program(sl_renderer *r, const sl_lab1_4_variant_key *key) {
    struct _sl_programs *ps = _sl_programs_of(r);
    _sl_variant *v = NULL;
    for (int i = 0; i < ps->variant_count && !v; i++)
        if (_sl_same_variant(&ps->variants[i].key, key)) v = &ps->variants[i];
    if (v) {
        v->last_used = r->frame_count;
        if (v->stale) {
            v->stale = false;
            _sl_slot_reload(r, &v->slot, key->lab, NULL);
        }
        return v->slot.program.id ? &v->slot : NULL;
    }
    if (ps->variant_count < _SL_MAX_VARIANTS) {
        v = &ps->variants[ps->variant_count++];
    } else {
        v = &ps->variants[0];
        for (int i = 1; i < ps->variant_count; i++)
            if (ps->variants[i].last_used < v->last_used) v = &ps->variants[i];
        sl_program_destroy(&v->slot.program);
    }
    *v = (_sl_variant){.key = *key, .last_used = r->frame_count};
    char defines[256];
    _sl_variant_defines(key, defines, sizeof defines);
    _sl_slot_build(r, &v->slot, r->shaders_dir, _sl_scene_vertex[key->lab], r->shaders_dir,
                   _sl_scene_fragment[key->lab], defines, key->lab);
    return v->slot.program.id ? &v->slot : NULL;
}

void sl_lab1_4_program_stats(const sl_renderer *r, sl_program_stats *out) {
    const struct _sl_programs *ps = r->technique_state[1];
    if (!ps) return;
    out->builds += ps->builds;
    out->build_ms += ps->build_ms;
    out->cached += (ps->depth.program.id != 0) + (ps->debug.program.id != 0);
    for (int i = 0; i < ps->variant_count; i++) out->cached += ps->variants[i].slot.program.id != 0;
}

bool sl_lab1_4_reload_changed(sl_renderer *r, bool *reloaded, char *err, size_t err_size) {
    struct _sl_programs *ps = r->technique_state[1];
    if (!ps) return true;
    bool ok = true;
    /* Rebuilt now: what the last frame drew with (so a save shows at once and its errors are
     * reported), and any program that never compiled (so a fix switches its lab back on). */
    typedef struct { sl_lab1_4_slot *slot; int lab; } watched;
    watched now[2 + _SL_MAX_VARIANTS] = {{&ps->depth, 1}, {&ps->debug, 0}};
    int n = 2;
    for (int i = 0; i < ps->variant_count; i++) {
        _sl_variant *v = &ps->variants[i];
        if (v->last_used == r->frame_count || !v->slot.program.id) now[n++] = (watched){&v->slot, v->key.lab};
        else if (!v->stale && sl_program_files_changed(&v->slot.program)) v->stale = true;
    }
    for (int i = 0; i < n; i++) {
        if (!now[i].slot->attempted || _sl_slot_reload(r, now[i].slot, now[i].lab, reloaded)) continue;
        if (ok) snprintf(err, err_size, "%s", r->shader_errors[now[i].lab]);
        ok = false;
    }
    return ok;
}

void sl_lab1_4_programs_destroy(sl_renderer *r) {
    struct _sl_programs *ps = r->technique_state[1];
    if (!ps) return;
    sl_program_destroy(&ps->depth.program);
    sl_program_destroy(&ps->debug.program);
    for (int i = 0; i < ps->variant_count; i++) sl_program_destroy(&ps->variants[i].slot.program);
    free(ps);
    r->technique_state[1] = NULL;
}
