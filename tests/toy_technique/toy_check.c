/* The test technique's check (tests/CMakeLists.txt, technique.toy_lab0): a program built like the
 * course's, with the toy added in slot 0 of the technique table (sl_labs_program's TECHNIQUE). It
 * draws the toy's frame headless through the renderer, presses its key, finds that key in the viewer's
 * key listing, runs its probe through the probe pass and lists its benchmark row: each reaches the toy
 * only by walking the table.
 *   toy_check <scene.json> <expected visibility>
 * Prints "toy: ..." lines; exits 0 when every check holds. */
#define _POSIX_C_SOURCE 200809L /* fileno, dup */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "sl_bench.h"
#include "sl_capture.h"
#include "sl_context.h"
#include "sl_probe_pass.h"
#include "sl_renderer.h"
#include "sl_technique.h"
#include "sl_viewer.h"

enum { TOY_WIDTH = 160, TOY_HEIGHT = 120 };

static int _failures = 0;

static void _check(bool ok, const char *what) {
    printf("toy: %s: %s\n", ok ? "ok" : "FAIL", what);
    if (!ok) _failures++;
}

/* Every pixel is either black (no object) or the visibility's grey: the plane, drawn with it. After the
 * toy's key (pressed through its hook, as the viewer does), its debug view: the visibility in red. */
static void _check_frame(GLuint target, sl_scene *scene, float expected, bool press_key, char *err, size_t n) {
    sl_renderer r;
    if (!sl_renderer_init(&r, NULL, err, n) || !sl_renderer_set_scene(&r, scene, err, n)) {
        _check(false, err);
        return;
    }
    sl_render_params params;
    sl_render_params_defaults(&params);
    params.lab = 0;
    const sl_technique *toy = sl_technique_of(0);
    if (press_key) {
        bool pressed = toy && toy->keys && toy->keys[0].names && toy->key_pressed;
        _check(pressed, "the toy has a key and a hook for it");
        if (pressed) {
            sl_view_context c = {.params = &params, .scene = scene};
            toy->key_pressed(&c, &toy->keys[0], toy->keys[0].codes[0], false);
            char state[64] = "";
            if (toy->key_state) toy->key_state(&c, &toy->keys[0], state, sizeof state);
            printf("toy: key %s pressed: %s %s\n", toy->keys[0].names, toy->keys[0].label, state);
        }
    }
    sl_renderer_draw(&r, scene, &params, target, TOY_WIDTH, TOY_HEIGHT);
    sl_image image = {0};
    bool captured = sl_capture_framebuffer(target, TOY_WIDTH, TOY_HEIGHT, 3, &image);
    _check(captured, "the frame is read back");
    int plane = 0, background = 0, other = 0;
    for (int i = 0; captured && i < TOY_WIDTH * TOY_HEIGHT; i++) {
        const float *p = image.data + 3 * i;
        bool grey = fabsf(p[0] - p[1]) < 1e-3f && fabsf(p[1] - p[2]) < 1e-3f;
        bool red = p[1] <= 0.5f / 255 && p[2] <= 0.5f / 255;
        if ((press_key ? red : grey) && fabsf(p[0] - expected) <= 1.5f / 255) plane++;
        else if (grey && p[0] <= 0.5f / 255) background++;
        else other++;
    }
    printf("toy: frame %dx%d%s: %d pixels of the plane at visibility %.3f, %d of background, %d else\n", TOY_WIDTH,
           TOY_HEIGHT, press_key ? " (debug view)" : "", plane, expected, background, other);
    const sl_frame_info *info = sl_renderer_info(&r);
    _check(!info->shader_error, info->shader_error ? info->shader_error : "its shaders compile");
    _check(plane > TOY_WIDTH * TOY_HEIGHT / 5 && background > 0 && other == 0,
           press_key ? "after its key, the plane is drawn in its debug view's red, the expected visibility, on black"
                     : "the plane is drawn with one visibility, the expected one, on black");
    sl_image_free(&image);
    sl_renderer_destroy(&r);
}

/* The viewer's key listing (--list-keys, what --help, the key panel and the slides' key test read) holds
 * the toy's key as lab 0's, beside the common keys. */
static void _check_key_listed(void) {
    const sl_technique *toy = sl_technique_of(0);
    if (!toy || !toy->keys || !toy->keys[0].names) return;
    FILE *listing = tmpfile();
    int saved = dup(STDOUT_FILENO);
    if (!listing || saved < 0) {
        _check(false, "a temporary file for the viewer's key listing");
        return;
    }
    fflush(stdout);
    dup2(fileno(listing), STDOUT_FILENO);
    char *args[] = {"toy_check", "--list-keys", NULL};
    int status = sl_viewer_main(2, args);
    fflush(stdout);
    dup2(saved, STDOUT_FILENO);
    close(saved);
    char line[512], want[128];
    snprintf(want, sizeof want, "0\t%s\t%s\n", toy->keys[0].names, toy->keys[0].help);
    bool toy_key = false, common_key = false;
    rewind(listing);
    while (fgets(line, sizeof line, listing)) {
        toy_key |= strcmp(line, want) == 0;
        common_key |= strncmp(line, "all\tV\t", 6) == 0;
    }
    fclose(listing);
    printf("toy: the viewer's --list-keys %s \"0<tab>%s<tab>...\"\n", toy_key ? "lists" : "does not list",
           toy->keys[0].names);
    _check(status == 0 && toy_key && common_key, "the viewer lists its key as lab 0's, beside the common keys");
}

/* The probe pass runs the toy's probe, found by its name through the table, as the runner finds a
 * case's probe (sl_probe_pass_run). */
static void _check_probe(float expected, char *err, size_t n) {
    const sl_technique_probe *probe = sl_technique_probe_of(0, "toy_visibility");
    _check(probe && probe->described, "the table holds the toy's probe");
    if (!probe || !probe->described) return;
    sl_probe_table table = {.function = "toy_visibility", .output_count = 1, .rows = 1};
    double outputs[SL_PROBE_MAX_OUTPUTS] = {0};
    bool not_implemented = false;
    bool ran = sl_probe_pass_run(&table, sl_build_labs_dir, sl_framework_dir(), outputs, &not_implemented, err, n);
    printf("toy: probe toy_visibility() = %.3f\n", outputs[0]);
    _check(ran && !not_implemented && fabs(outputs[0] - expected) < 1e-6, "its probe returns the expected visibility");
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: toy_check <scene.json> <expected visibility>\n");
        return 2;
    }
    float expected = strtof(argv[2], NULL);
    static char err[16384];
    const sl_technique *toy = sl_technique_of(0);
    _check(toy && toy->lab == 0, "slot 0 of the table holds the technique this build adds");
    if (toy) printf("toy: slot 0: \"%s\"\n", toy->name);
    sl_context *ctx = sl_context_create(&(sl_context_desc){.width = TOY_WIDTH, .height = TOY_HEIGHT}, err, sizeof err);
    if (!ctx) {
        printf("toy: FAIL: no headless context: %s\n", err);
        return 1;
    }
    sl_scene scene;
    if (!sl_scene_load(&scene, argv[1], err, sizeof err)) {
        printf("toy: FAIL: %s\n", err);
        return 1;
    }
    _check_frame(sl_context_default_framebuffer(ctx), &scene, expected, false, err, sizeof err);
    _check_frame(sl_context_default_framebuffer(ctx), &scene, expected, true, err, sizeof err);
    _check_key_listed();
    _check_probe(expected, err, sizeof err);
    sl_context_destroy(ctx);
    /* the benchmark's list: the toy has no row of its own, so it gets its lab's defaults */
    fflush(stdout);
    char *bench[] = {"toy_check", "--bench", "--list", "--only", "lab0", NULL};
    _check(sl_bench_main(5, bench) == 0, "the benchmark lists it");
    return _failures ? 1 : 0;
}
