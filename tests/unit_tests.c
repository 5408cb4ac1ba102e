/* Unit tests of the parts that need no GL: comparison, shader preprocessing
 * and error mapping, case and scene files, meshes. Run one with its name:
 *   sl_unit_tests compare_neighbourhood */
#define _GNU_SOURCE
#include <stdint.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <time.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <signal.h>

#include "sl_build_failure.h"
#include "sl_case.h"
#include "sl_compare.h"
#include "sl_diag_words.h"
#include "sl_gl.h"
#include "sl_glsl_functions.h"
#include "sl_grade.h"
#include "sl_hidden.h"
#include "sl_probe_generic.h"
#include "diagnose/camera.h"
#include <cglm/cglm.h>
#include "sl_mesh.h"
#include "sl_scene.h"
#include "sl_protocol.h"
#include "sl_reference_cache.h"
#include "sl_report.h"
#include "sl_run.h"
#include "sl_sha256.h"
#include "sl_shader.h"
#include "sl_text.h"
#include "sl_utf8.h"

static int failures;
#define CHECK(cond)                                                                \
    do {                                                                           \
        if (!(cond)) {                                                             \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
            failures++;                                                            \
        }                                                                          \
    } while (0)

static char tmp_dir[256];

static void write_file(const char *name, const char *text) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s", tmp_dir, name);
    FILE *f = fopen(path, "w");
    fputs(text, f);
    fclose(f);
}

static sl_image square(int w, int h, float inside, float outside, int x0, int y0, int x1, int y1) {
    sl_image img = sl_image_alloc(w, h, 1);
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) sl_image_pixel(&img, x, y)[0] = (x >= x0 && x < x1 && y >= y0 && y < y1) ? inside : outside;
    return img;
}

static void test_compare_neighbourhood(void) {
    sl_image ref = square(64, 64, 0, 1, 16, 16, 40, 40);
    sl_image moved = square(64, 64, 0, 1, 17, 16, 41, 40);   /* edge one pixel over: renderer noise */
    sl_image missing = square(64, 64, 1, 1, 0, 0, 0, 0);      /* no shadow at all: a mistake */
    sl_image shifted = square(64, 64, 0, 1, 24, 16, 48, 40);  /* 8 pixels over: a mistake */
    sl_image diff;
    sl_compare_stats s = sl_compare_images(&ref, &ref, 0.1, NULL);
    CHECK(s.failing == 0);
    s = sl_compare_images(&moved, &ref, 0.1, &diff);
    CHECK(s.failing == 0);
    CHECK(diff.width == 64 && diff.channels == 3);
    sl_image_free(&diff);
    s = sl_compare_images(&missing, &ref, 0.1, NULL);
    CHECK(s.failing == 24 * 24);
    CHECK(fabs(s.failing_fraction - 576.0 / 4096) < 1e-9);
    s = sl_compare_images(&shifted, &ref, 0.1, NULL);
    CHECK(s.failing_fraction > 0.05);
    sl_visibility_stats v = sl_visibility_compare(&missing, &ref);
    CHECK(v.missing_shadow == 1.0 && v.extra_shadow == 0.0);
    /* NaN never passes */
    sl_image nan_img = square(64, 64, 0, 1, 16, 16, 40, 40);
    nan_img.data[100] = NAN;
    s = sl_compare_images(&nan_img, &ref, 0.1, NULL);
    CHECK(s.nan_pixels == 1 && s.failing >= 1);
    /* size mismatch */
    sl_image small = sl_image_alloc(32, 32, 1);
    s = sl_compare_images(&small, &ref, 0.1, NULL);
    CHECK(s.size_mismatch);
    sl_image_free(&ref);
    sl_image_free(&moved);
    sl_image_free(&missing);
    sl_image_free(&shifted);
    sl_image_free(&nan_img);
    sl_image_free(&small);
}

/* The failing pixels by kind add up to the failing count: shadows lost, shadows gained, brightness only. */
static void test_compare_failing_by_kind(void) {
    sl_image ref = square(64, 64, 0, 1, 16, 16, 40, 40);        /* a 24x24 shadow */
    sl_image stu = square(64, 64, 0, 1, 16, 16, 40, 40);
    for (int y = 16; y < 40; y++)
        for (int x = 16; x < 28; x++) sl_image_pixel(&stu, x, y)[0] = 1;   /* half the shadow lost: 12x24 */
    for (int y = 50; y < 54; y++)
        for (int x = 50; x < 60; x++) sl_image_pixel(&stu, x, y)[0] = 0;   /* a shadow gained: 10x4 */
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 64; x++) sl_image_pixel(&stu, x, y)[0] = 0.7f; /* lit but dimmer: 64x8 */
    sl_compare_stats s = sl_compare_images(&stu, &ref, 0.1, NULL);
    /* a pixel passes where a neighbour matches it: a few at the lost half's corners do */
    CHECK(s.failing_shadow_lost > 11 * 24 && s.failing_shadow_lost <= 12 * 24);
    CHECK(s.failing_shadow_gained == 10 * 4);
    CHECK(s.nan_pixels == 0);
    CHECK(s.failing - s.failing_shadow_lost - s.failing_shadow_gained == 64 * 8);
    sl_image_free(&ref);
    sl_image_free(&stu);
}

/* A slip of units is named from the matrix's m11 alone; a right or unrelated angle is no slip. */
static void test_diag_angle_slips_and_words(void) {
    char text[200] = "";
    const double pi = acos(-1.0);
    double m11_of_90_radians = 1.0 / tan(90.0 / 2), m11_of_90_degrees = 1.0 / tan(pi / 4);
    CHECK(sl_diag_angle_slip(m11_of_90_radians, 90, "90.0f", text, sizeof text));
    CHECK(strcmp(text, "90 was passed as radians: use glm_rad(90.0f)") == 0);
    CHECK(fabs(sl_diag_perspective_fov_deg(m11_of_90_radians) - 116.6) < 0.1); /* what the matrix shows */
    CHECK(!sl_diag_angle_slip(m11_of_90_degrees, 90, "90.0f", text, sizeof text));
    CHECK(!sl_diag_angle_slip(1.0 / tan(pi / 8), 90, "90.0f", text, sizeof text)); /* 45 degrees: no slip */
    /* 60 radians folds past 180 degrees: m11 is negative, and still read */
    double m11_of_60_radians = 1.0 / tan(60.0 / 2);
    CHECK(m11_of_60_radians < 0);
    CHECK(sl_diag_angle_slip(m11_of_60_radians, 60, "2 * spot_angle_deg", text, sizeof text));
    CHECK(strcmp(text, "2 * spot_angle_deg = 60 was passed as radians: use glm_rad(2 * spot_angle_deg)") == 0);
    double twice = 90 * pi / 180 * pi / 180;
    CHECK(sl_diag_angle_slip(1.0 / tan(twice / 2), 90, "90.0f", text, sizeof text));
    CHECK(strncmp(text, "glm_rad was applied twice", 25) == 0);
    CHECK(strcmp(sl_diag_darkening_word(0.95), "slightly") == 0);
    CHECK(strcmp(sl_diag_darkening_word(0.8), "noticeably") == 0);
    CHECK(strcmp(sl_diag_darkening_word(0.6), "strongly") == 0);
    CHECK(strcmp(sl_diag_shadowed_share_words(0.56), "most of the lit area") == 0);
    CHECK(strcmp(sl_diag_shadowed_share_words(0.95), "almost everything") == 0);
}

/* Flicker as the grader and the viewer's --case count it: of the receivers only, per frame pair;
 * and a criterion's percentage printed as the case states it (0.25, not 0.2). */
static void test_compare_flicker_and_percent(void) {
    sl_image mask = sl_image_alloc(4, 2, 1), stack = sl_image_alloc(4, 2 * 3, 1);
    for (int i = 0; i < 4; i++) mask.data[i] = 1; /* the top row faces the light, the bottom row does not */
    for (int i = 0; i < 4 * 6; i++) stack.data[i] = 1;
    sl_image_pixel(&stack, 0, 2)[0] = 0; /* frame 1: one receiver in shadow, then lit again in frame 2 */
    sl_image_pixel(&stack, 1, 3)[0] = 0; /* a pixel facing away changes: not a receiver, not counted */
    sl_flicker f = sl_flicker_measure(&stack, &mask, 3);
    CHECK(f.receivers == 4);
    CHECK(fabs(f.score - 2.0 / (4 * 2)) < 1e-12); /* two changes over 4 receivers and 2 frame pairs */
    CHECK(fabs(f.shadowed - 1.0 / (4 * 3)) < 1e-12);
    sl_flicker none = {4, 0, 0}, reference = {4, 0, 0.1};
    CHECK(!sl_flicker_shadows_kept(&none, &reference));
    CHECK(sl_flicker_shadows_kept(&reference, &reference));
    char text[16];
    CHECK(strcmp(sl_criterion_percent(0.0025, text, sizeof text), "0.25") == 0);
    CHECK(strcmp(sl_criterion_percent(0.001, text, sizeof text), "0.1") == 0);
    CHECK(strcmp(sl_criterion_percent(0.01, text, sizeof text), "1") == 0);
    sl_image_free(&mask);
    sl_image_free(&stack);
}

static void test_compare_depth_patterns(void) {
    /* depths only in the lower-left 16x16 of a 64x64 map (rows stored top first) */
    sl_image img = square(64, 64, 0.5f, 1.0f, 0, 48, 16, 64);
    CHECK(sl_content_only_in_lower_left(&img, 1.0f, 16, 16));
    CHECK(!sl_content_only_in_lower_left(&img, 1.0f, 8, 8));
    sl_image full = square(64, 64, 0.5f, 1.0f, 0, 0, 64, 64);
    CHECK(!sl_content_only_in_lower_left(&full, 1.0f, 16, 16));
    CHECK(sl_fraction_equal(&full, 0.5f, 1e-6f) == 1.0);
    sl_image_free(&img);
    sl_image_free(&full);
}

static void test_shader_includes_and_lines(void) {
    write_file("main.frag", "#version 330 core\n#include \"lib.glsl\"\n#include \"lib.glsl\"\nvoid main() {\n  oops;\n}\n");
    write_file("lib.glsl", "// shared\nfloat f() { return 1.0; }\n");
    char path[512], files[SL_SHADER_MAX_FILES][SL_PATH_MAX], err[1024];
    int count = 0;
    snprintf(path, sizeof path, "%s/main.frag", tmp_dir);
    const char *dirs[] = {NULL};
    char *src = sl_shader_preprocess(path, dirs, "#define X 1", files, &count, err, sizeof err);
    CHECK(src != NULL);
    if (!src) return;
    CHECK(count == 2);
    CHECK(strncmp(src, "#version 330 core\n#define X 1\n", 30) == 0);
    CHECK(strstr(src, "float f()") != NULL);
    CHECK(strstr(strstr(src, "float f()") + 1, "float f()") == NULL); /* included once */
    CHECK(strstr(src, "#line 4 0") != NULL); /* back in main.frag after the includes */
    free(src);
    /* A driver log in Mesa's format maps to file:line:column */
    char out[2048];
    sl_shader_map_log("0:5(3): error: `oops' undeclared\n1:2(1): warning: x\n", files, count, out, sizeof out);
    char expect[1024];
    snprintf(expect, sizeof expect, "%s/main.frag:5:3: error: `oops' undeclared", tmp_dir);
    CHECK(strstr(out, expect) != NULL);
    snprintf(expect, sizeof expect, "%s/lib.glsl:2:1: warning: x", tmp_dir);
    CHECK(strstr(out, expect) != NULL);
    /* NVIDIA's format too */
    sl_shader_map_log("1(7) : error C0000: syntax error\n", files, count, out, sizeof out);
    snprintf(expect, sizeof expect, "%s/lib.glsl:7: error C0000", tmp_dir);
    CHECK(strstr(out, expect) != NULL);
}

static void test_shader_missing_include(void) {
    write_file("bad.frag", "#version 330 core\n\n#include \"nowhere.glsl\"\n");
    char path[512], files[SL_SHADER_MAX_FILES][SL_PATH_MAX], err[1024] = "";
    int count = 0;
    snprintf(path, sizeof path, "%s/bad.frag", tmp_dir);
    const char *dirs[] = {NULL};
    char *src = sl_shader_preprocess(path, dirs, NULL, files, &count, err, sizeof err);
    CHECK(src == NULL);
    CHECK(strstr(err, "bad.frag:3: error: cannot find included file \"nowhere.glsl\"") != NULL);
    free(src);
}

/* An #include that resolves outside the shader folders is refused, whether
 * by a relative path climbing out or by an absolute one. */
static void test_shader_include_stays_inside(void) {
    char dir[300], outside[300], path[512], files[SL_SHADER_MAX_FILES][SL_PATH_MAX], err[1024] = "";
    snprintf(dir, sizeof dir, "%s/inside", tmp_dir);
    snprintf(outside, sizeof outside, "%s/secret.glsl", tmp_dir);
    CHECK(mkdir(dir, 0755) == 0);
    write_file("secret.glsl", "float answer() { return 42.0; }\n");
    write_file("inside/ok.glsl", "float ok() { return 1.0; }\n");
    write_file("inside/climb.frag", "#version 330 core\n#include \"ok.glsl\"\n#include \"../secret.glsl\"\n");
    char absolute[700];
    snprintf(absolute, sizeof absolute, "#version 330 core\n#include \"%s\"\n", outside);
    write_file("inside/absolute.frag", absolute);
    const char *dirs[] = {dir, NULL};
    int count = 0;
    snprintf(path, sizeof path, "%s/climb.frag", dir);
    char *src = sl_shader_preprocess(path, dirs, NULL, files, &count, err, sizeof err);
    CHECK(src == NULL);
    CHECK(strstr(err, "climb.frag:3: error: #include \"../secret.glsl\" reaches outside the shader folders") != NULL);
    free(src);
    snprintf(path, sizeof path, "%s/absolute.frag", dir);
    src = sl_shader_preprocess(path, dirs, NULL, files, &count, err, sizeof err);
    CHECK(src == NULL && strstr(err, "absolute.frag:2: error: #include") && strstr(err, "reaches outside"));
    free(src);
    /* a link inside that points outside is outside too */
    char link_path[400];
    snprintf(link_path, sizeof link_path, "%s/link.glsl", dir);
    CHECK(symlink(outside, link_path) == 0);
    write_file("inside/via_link.frag", "#version 330 core\n#include \"link.glsl\"\n");
    snprintf(path, sizeof path, "%s/via_link.frag", dir);
    src = sl_shader_preprocess(path, dirs, NULL, files, &count, err, sizeof err);
    CHECK(src == NULL && strstr(err, "reaches outside"));
    free(src);
}

static void write_bytes(const char *name, const char *bytes, size_t n) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s", tmp_dir, name);
    FILE *f = fopen(path, "wb");
    fwrite(bytes, 1, n, f);
    fclose(f);
}

/* Shader files as Windows and old Mac editors save them: a UTF-8 byte-order
 * mark and CRLF or lone CR line ends are made plain before compiling; a NUL
 * byte, Latin-1 or UTF-16 is named with the file and the byte's offset. */
static void test_shader_text_as_editors_write_it(void) {
    static const char crlf[] = "\xef\xbb\xbf#version 330 core\r\n#include \"cr.glsl\"\r\nvoid main() {\r\n}\r\n";
    static const char cr[] = "// old Mac\rfloat g() { return 2.0; }\r";
    write_bytes("crlf.frag", crlf, sizeof crlf - 1);
    write_bytes("cr.glsl", cr, sizeof cr - 1);
    char path[512], files[SL_SHADER_MAX_FILES][SL_PATH_MAX], err[1024] = "";
    int count = 0;
    const char *dirs[] = {NULL};
    snprintf(path, sizeof path, "%s/crlf.frag", tmp_dir);
    char *src = sl_shader_preprocess(path, dirs, NULL, files, &count, err, sizeof err);
    CHECK(src != NULL);
    if (src) {
        CHECK(strncmp(src, "#version 330 core\n", 18) == 0);
        CHECK(strchr(src, '\r') == NULL);
        CHECK(strstr(src, "#line 100001 1\n// old Mac\nfloat g()") != NULL); /* lines counted at each CR */
        CHECK(strstr(src, "void main() {\n}\n") != NULL);
    }
    free(src);
    /* not text: named with the file and the byte's offset and line */
    static const char nul[] = "#version 330 core\nvoid main() {\n  x\0;\n}\n";
    static const char latin1[] = "#version 330 core\n// caf\xe9\n";
    static const char utf16[] = "\xff\xfe#\0v\0";
    static const struct { const char *name, *bytes; size_t n; const char *expect; } bad[] = {
        {"nul.frag", nul, sizeof nul - 1, "nul.frag: a NUL byte at byte offset 35 (line 3)"},
        {"latin1.frag", latin1, sizeof latin1 - 1, "latin1.frag: invalid UTF-8 at byte offset 24 (line 2)"},
        {"utf16.frag", utf16, sizeof utf16 - 1, "utf16.frag: saved as UTF-16"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        write_bytes(bad[i].name, bad[i].bytes, bad[i].n);
        snprintf(path, sizeof path, "%s/%s", tmp_dir, bad[i].name);
        err[0] = '\0';
        src = sl_shader_preprocess(path, dirs, NULL, files, &count, err, sizeof err);
        CHECK(src == NULL);
        CHECK(strstr(err, bad[i].expect) != NULL);
        if (!strstr(err, bad[i].expect)) fprintf(stderr, "  got: %s\n", err);
        free(src);
    }
}

static void test_case_files(void) {
    char path[512], err[2048];
    sl_case c;
    write_file("ok.json", "{\"name\": \"t\", \"lab\": 2, \"scene\": \"boxes_on_floor\", \"params\": {\"compare\": \"hardware\"},"
                          "\"checks\": [{\"kind\": \"visibility\", \"points\": 3, \"fail_percent\": 1}]}");
    snprintf(path, sizeof path, "%s/ok.json", tmp_dir);
    CHECK(sl_case_load(&c, path, err, sizeof err));
    CHECK(c.lab == 2 && c.check_count == 1 && c.checks[0].points == 3);
    CHECK(fabs(c.checks[0].fail_fraction - 0.01) < 1e-12 && c.checks[0].threshold == 0.05); /* the visibility default */
    CHECK(c.params.compare == SL_COMPARE_HARDWARE && c.scene.object_count > 0);

    write_file("broken.json", "{\"name\": \"t\",\n \"lab\": 2,\n oops}");
    snprintf(path, sizeof path, "%s/broken.json", tmp_dir);
    CHECK(!sl_case_load(&c, path, err, sizeof err));
    CHECK(strstr(err, "broken.json:3: invalid JSON") != NULL);

    write_file("nopoints.json", "{\"name\": \"t\", \"lab\": 1, \"scene\": \"boxes_on_floor\", \"checks\": [{\"kind\": \"fbo\"}]}");
    snprintf(path, sizeof path, "%s/nopoints.json", tmp_dir);
    CHECK(!sl_case_load(&c, path, err, sizeof err));
    CHECK(strstr(err, "nopoints.json") && strstr(err, "no \"points\""));

    write_file("noscene.json", "{\"name\": \"t\", \"lab\": 1, \"scene\": \"no_such_scene\", \"checks\": [{\"kind\": \"fbo\", \"points\": 1}]}");
    snprintf(path, sizeof path, "%s/noscene.json", tmp_dir);
    CHECK(!sl_case_load(&c, path, err, sizeof err));
    CHECK(strstr(err, "no_such_scene.json") != NULL);

    snprintf(path, sizeof path, "%s/absent.json", tmp_dir);
    CHECK(!sl_case_load(&c, path, err, sizeof err));
    CHECK(strstr(err, "absent.json: cannot read case file") != NULL);
}

static void test_scenes(void) {
    static const char *builtins[] = {"boxes_on_floor", "curved_grazing", "long_ground", "closed_room",
                                     "spot_on_floor", "pole_on_floor", "thin_caster"};
    char err[1024];
    sl_scene s;
    for (size_t i = 0; i < sizeof builtins / sizeof builtins[0]; i++) {
        bool ok = sl_scene_load(&s, builtins[i], err, sizeof err);
        if (!ok) fprintf(stderr, "%s\n", err);
        CHECK(ok);
        CHECK(s.bounds.max[0] > s.bounds.min[0] && s.bounds.max[2] > s.bounds.min[2]);
        CHECK(fabsf(glm_vec3_norm(s.light.direction) - 1) < 1e-5f);
    }
    CHECK(sl_scene_load(&s, "boxes_on_floor", err, sizeof err));
    CHECK(fabsf(s.bounds.min[1]) < 1e-5f); /* the floor is at y = 0 */
    write_file("scene.json", "{\"objects\": [{\"shape\": \"cube\"}]}");
    char path[512];
    snprintf(path, sizeof path, "%s/scene.json", tmp_dir);
    CHECK(!sl_scene_load(&s, path, err, sizeof err));
    CHECK(strstr(err, "objects[0]: unknown shape \"cube\"") != NULL);
}

static void test_meshes(void) {
    sl_mesh_data meshes[] = {sl_mesh_plane(4, 4, 3), sl_mesh_box(1, 2, 3), sl_mesh_sphere(1, 24, 12),
                             sl_mesh_cylinder(0.5f, 2, 24), sl_mesh_torus(1, 0.25f, 24, 12)};
    for (size_t m = 0; m < sizeof meshes / sizeof meshes[0]; m++) {
        sl_mesh_data *d = &meshes[m];
        CHECK(d->vertex_count > 0 && d->index_count % 3 == 0);
        for (int i = 0; i < d->vertex_count; i++) {
            const float *n = d->vertices + i * 6 + 3;
            CHECK(fabsf(sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1) < 1e-4f);
        }
        for (int t = 0; t < d->index_count; t += 3) {
            const float *a = d->vertices + d->indices[t] * 6, *b = d->vertices + d->indices[t + 1] * 6,
                        *c = d->vertices + d->indices[t + 2] * 6;
            vec3 e1 = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2 = {c[0] - a[0], c[1] - a[1], c[2] - a[2]}, g;
            glm_vec3_cross(e1, e2, g);
            /* counter-clockwise seen from outside: the face normal agrees with the vertex normal */
            CHECK(glm_vec3_dot(g, (float *)(a + 3)) > 0);
        }
        sl_mesh_data_free(d);
    }
}

/* A case of lab `lab` with one check, and a result holding `captures`. */
static sl_case grade_case(int lab, sl_check_kind kind) {
    sl_case c;
    memset(&c, 0, sizeof c);
    snprintf(c.name, sizeof c.name, "synthetic");
    c.lab = lab;
    c.width = c.height = 64;
    sl_render_params_defaults(&c.params);
    c.params.lab = lab;
    c.check_count = 1;
    c.checks[0].kind = kind;
    c.checks[0].points = 1;
    c.checks[0].threshold = kind == SL_CHECK_PENUMBRA ? 0.35 : 0.1;
    c.checks[0].fail_fraction = 0.005;
    return c;
}

static void add_capture(sl_case_result *r, const char *name, sl_image image) {
    sl_capture *cap = &r->captures[r->capture_count++];
    snprintf(cap->name, sizeof cap->name, "%s", name);
    cap->is_image = true;
    cap->image = image;
}

static sl_reference image_reference(sl_image image) {
    sl_reference ref;
    memset(&ref, 0, sizeof ref);
    ref.needed = ref.loaded = true;
    ref.image = image;
    return ref;
}

static void test_grade_names_acne(void) {
    sl_case c = grade_case(3, SL_CHECK_VISIBILITY);
    c.params.bias.mode = SL_BIAS_SLOPE_SCALED;
    sl_case_result r = {.finished = true};
    sl_image acne = square(64, 64, 0, 1, 20, 20, 40, 40);
    for (int i = 0; i < 64 * 64; i += 3) acne.data[i] = 0; /* speckles of self-shadowing */
    add_capture(&r, "visibility", acne);
    sl_reference ref = image_reference(square(64, 64, 0, 1, 20, 20, 40, 40));
    ref.lit_mask = square(64, 64, 1, 1, 0, 0, 0, 0); /* the solutions' lit surfaces */
    sl_check_result out;
    sl_grade_check(&c, &c.checks[0], &r, &ref, NULL, &out);
    CHECK(!out.passed && out.points == 0);
    CHECK(strstr(out.message, "shadow acne on 3") != NULL); /* a third of the lit surface */
    CHECK(strstr(out.message, "slope_scaled_bias") != NULL);
    sl_image_free(&out.diff);
    sl_case_result_free(&r);
    sl_reference_free(&ref);
}

static void test_grade_names_peter_panning(void) {
    sl_case c = grade_case(3, SL_CHECK_VISIBILITY);
    c.params.bias.mode = SL_BIAS_CONSTANT;
    sl_case_result r = {.finished = true};
    /* caster's dark side at x 4..10 in both; the shadow starts at 10 in the reference, 18 here */
    sl_image detached = square(64, 64, 0, 1, 18, 10, 50, 50);
    sl_image reference = square(64, 64, 0, 1, 10, 10, 50, 50);
    for (int y = 10; y < 50; y++)
        for (int x = 4; x < 10; x++) detached.data[y * 64 + x] = 0;
    for (int y = 10; y < 50; y++)
        for (int x = 4; x < 10; x++) reference.data[y * 64 + x] = 0;
    add_capture(&r, "visibility", detached);
    sl_reference ref = image_reference(reference);
    ref.lit_mask = square(64, 64, 1, 1, 0, 0, 0, 0); /* the solutions' lit surfaces */
    sl_check_result out;
    sl_grade_check(&c, &c.checks[0], &r, &ref, NULL, &out);
    CHECK(!out.passed);
    CHECK(strstr(out.message, "detached from their casters by about") != NULL);
    CHECK(strstr(out.message, "Peter Panning") != NULL);
    sl_image_free(&out.diff);
    sl_case_result_free(&r);
    sl_reference_free(&ref);
}

/* Lab 5: moments (a square of depth 0.3 on 0.8), blurred along x, y or both by a box of radius 3. */
static sl_image moments_image(bool square_depth, bool blur_x, bool blur_y) {
    sl_image d = square(64, 64, 0.3f, 0.8f, 20, 20, 44, 44), t = sl_image_alloc(64, 64, 1);
    for (int pass = 0; pass < 2; pass++) {
        bool on = pass == 0 ? blur_x : blur_y;
        for (int y = 0; y < 64; y++)
            for (int x = 0; x < 64; x++) {
                float sum = 0;
                for (int i = -3; i <= 3; i++) {
                    int xx = pass == 0 && on ? x + i : x, yy = pass == 1 && on ? y + i : y;
                    xx = xx < 0 ? 0 : xx > 63 ? 63 : xx;
                    yy = yy < 0 ? 0 : yy > 63 ? 63 : yy;
                    sum += d.data[yy * 64 + xx];
                }
                t.data[y * 64 + x] = on ? sum / 7 : d.data[y * 64 + x];
            }
        memcpy(d.data, t.data, sizeof(float) * 64 * 64);
    }
    sl_image m = sl_image_alloc(64, 64, 2);
    for (int i = 0; i < 64 * 64; i++) {
        m.data[2 * i] = d.data[i];
        m.data[2 * i + 1] = square_depth ? d.data[i] * d.data[i] : d.data[i];
    }
    sl_image_free(&d);
    sl_image_free(&t);
    return m;
}

static void add_moments_target(sl_case_result *r, double format, double bits, bool is_float) {
    sl_capture *cap = &r->captures[r->capture_count++];
    snprintf(cap->name, sizeof cap->name, "moments_target");
    /* both framebuffers complete, framebuffer[0] drawing into moments[0] */
    double v[SL_MOMENTS_TARGET_NUMBERS] = {0x8CD5 /* GL_FRAMEBUFFER_COMPLETE */, format, 64, 64, bits, bits, is_float,
                                           0x8D41 /* GL_RENDERBUFFER */, 0, 0, 0, 0, 0x8CD5, 1};
    memcpy(cap->numbers, v, sizeof v);
    cap->number_count = SL_MOMENTS_TARGET_NUMBERS;
}

static void test_grade_names_vsm_mistakes(void) {
    struct { bool square_depth, blur_x, blur_y; double format, bits; bool is_float; const char *says; } mistakes[] = {
        {true, true, true, 0x822F /* GL_RG16F */, 16, true, "stored as GL_RG16F (16-bit float"},
        {false, true, true, 0x8230 /* GL_RG32F */, 32, true, "the second moment equals the first"},
        {true, true, false, 0x8230, 32, true, "blurred along x only"},
        {true, false, false, 0x8230, 32, true, "sharper than the reference's along both x and y"},
        {true, true, true, 0x8230, 32, true, NULL},
    };
    for (size_t m = 0; m < sizeof mistakes / sizeof mistakes[0]; m++) {
        sl_case c = grade_case(5, SL_CHECK_MOMENTS_BLURRED);
        c.checks[0].threshold = 1e-4;
        sl_case_result r = {.finished = true};
        add_capture(&r, "moments_blurred", moments_image(mistakes[m].square_depth, mistakes[m].blur_x, mistakes[m].blur_y));
        add_moments_target(&r, mistakes[m].format, mistakes[m].bits, mistakes[m].is_float);
        sl_reference ref = image_reference(moments_image(true, true, true));
        sl_check_result out;
        sl_grade_check(&c, &c.checks[0], &r, &ref, NULL, &out);
        if (!mistakes[m].says) {
            CHECK(out.passed);
        } else {
            CHECK(!out.passed);
            CHECK(strstr(out.message, mistakes[m].says) != NULL);
            if (!strstr(out.message, mistakes[m].says)) fprintf(stderr, "  said: %s\n", out.message);
        }
        sl_image_free(&out.diff);
        sl_case_result_free(&r);
        sl_reference_free(&ref);
    }
    /* light bleeding: the reference's umbra is a square; lit at 0.4 on a ring with the reduction, 0.2 without */
    for (int swapped = 0; swapped < 2; swapped++) {
        sl_case c = grade_case(5, SL_CHECK_BLEEDING);
        c.params.vsm.bleeding = 0.3f;
        sl_case_result r = {.finished = true};
        sl_image with = square(64, 64, 0, 1, 10, 10, 54, 54), without = square(64, 64, 0, 1, 10, 10, 54, 54);
        for (int y = 20; y < 44; y++)
            for (int x = 20; x < 44; x++)
                if (x < 24 || x >= 40 || y < 24 || y >= 40) {
                    without.data[y * 64 + x] = swapped ? 0.0f : 0.4f;
                    with.data[y * 64 + x] = swapped ? 0.4f : 0.0f;
                }
        add_capture(&r, "visibility", with);
        add_capture(&r, "visibility_unreduced", without);
        sl_reference ref = image_reference(square(64, 64, 0, 1, 10, 10, 54, 54));
        ref.lit_mask = square(64, 64, 1, 1, 0, 0, 0, 0); /* the solutions' lit surfaces */
        sl_check_result out;
        sl_grade_check(&c, &c.checks[0], &r, &ref, NULL, &out);
        CHECK(swapped ? !out.passed : out.passed);
        if (swapped) CHECK(strstr(out.message, "the reduction adds light to the umbra instead") != NULL);
        sl_image_free(&out.diff);
        sl_case_result_free(&r);
        sl_reference_free(&ref);
    }
}

/* A failed check a later one builds on leads its message; a hint shows only with its own symptom, and
 * never over a known cause. */
static void test_grade_leads_with_root_cause(void) {
    sl_case c = grade_case(2, SL_CHECK_VISIBILITY);
    c.check_count = 2;
    c.checks[1] = c.checks[0];
    c.checks[0].kind = SL_CHECK_MATRICES;
    snprintf(c.checks[1].hint, sizeof c.checks[1].hint, "look at the divide");
    c.checks[1].hint_when = 1u << SL_SYMPTOM_MISSING_SHADOW;
    sl_case_result r = {.finished = true};
    add_capture(&r, "visibility", square(64, 64, 0, 1, 20, 20, 30, 30)); /* half the reference's shadow */
    sl_reference ref = image_reference(square(64, 64, 0, 1, 20, 20, 40, 40));
    ref.lit_mask = square(64, 64, 1, 1, 0, 0, 0, 0); /* the solutions' lit surfaces */
    sl_check_result earlier[1] = {{.max_points = 2}};
    snprintf(earlier[0].summary, sizeof earlier[0].summary, "the shadow matrix multiplies Lv * Lp");
    sl_diag_set_cause(&earlier[0], "lab2_shadow_matrix()", SL_CAUSE_WRONG);
    sl_grade_context context = {.earlier = earlier, .earlier_count = 1};
    sl_check_result out;
    sl_grade_check(&c, &c.checks[1], &r, &ref, &context, &out);
    CHECK(!out.passed);
    CHECK(strncmp(out.message, "the light's matrices are wrong (synthetic / ", 44) == 0);
    /* the lead is the matrices check's failure: its cause too */
    CHECK(strcmp(out.cause_function, "lab2_shadow_matrix") == 0 && out.cause_kind && strcmp(out.cause_kind, SL_CAUSE_WRONG) == 0);
    CHECK(strstr(out.message, "the shadow matrix multiplies Lv * Lp): fix the matrices first. Here: ") != NULL);
    CHECK(strstr(out.message, "Hint:") == NULL);
    sl_image_free(&out.diff);
    /* nothing known: the symptom, and the hint that is about it */
    sl_grade_check(&c, &c.checks[1], &r, &ref, NULL, &out);
    CHECK(strstr(out.message, "fix the matrices first") == NULL);
    CHECK(strstr(out.message, "Hint: look at the divide") != NULL);
    sl_image_free(&out.diff);
    /* a hint about another symptom stays out */
    c.checks[1].hint_when = 1u << SL_SYMPTOM_ACNE;
    sl_grade_check(&c, &c.checks[1], &r, &ref, NULL, &out);
    CHECK(strstr(out.message, "Hint:") == NULL);
    sl_image_free(&out.diff);
    sl_case_result_free(&r);
    sl_reference_free(&ref);
}

/* A probe check of `function` over `rows` rows of inputs, with the student's and the solution's outputs. */
static void grade_probe(const char *function, int rows, const float inputs[][SL_PROBE_MAX_INPUTS],
                        const double *student, const double *expected, sl_check_result *out) {
    sl_case c = grade_case(3, SL_CHECK_PROBE);
    const sl_probe_function *f = sl_probe_find(function);
    sl_check *k = &c.checks[0];
    k->function = sl_probe_index(f);
    k->rows = rows;
    k->tolerance = 1e-6;
    k->relative = 2e-3;
    for (int i = 0; i < rows; i++) memcpy(k->inputs[i], inputs[i], sizeof k->inputs[i]);
    sl_case_result r = {.finished = true};
    sl_capture *cap = &r.captures[r.capture_count++];
    snprintf(cap->name, sizeof cap->name, "%s", sl_check_capture_name(&c, k));
    cap->number_count = rows * f->output_count;
    memcpy(cap->numbers, student, sizeof(double) * (size_t)cap->number_count);
    sl_reference ref = {.needed = true, .loaded = true, .number_count = cap->number_count};
    memcpy(ref.numbers, expected, sizeof(double) * (size_t)ref.number_count);
    sl_grade_check(&c, k, &r, &ref, NULL, out);
}

/* What a probe's rows say together: the slope term's function of the angle, a missing clamp, a constant. */
static void test_grade_probe_verdicts(void) {
    static const float rows[][SL_PROBE_MAX_INPUTS] = {
        {1.0f, 0.0005f, 0.0015f, 0.01f}, {0.8f, 0.0005f, 0.0015f, 0.01f}, {0.5f, 0.0005f, 0.0015f, 0.01f},
        {0.1f, 0.0005f, 0.0015f, 0.01f}};
    double expected[4], with_sin[4], unclamped[4], constant[4];
    for (int i = 0; i < 4; i++) {
        double cos_t = rows[i][0], sin_t = sqrt(1 - cos_t * cos_t), tan_t = sin_t / cos_t;
        expected[i] = fmin(rows[i][1] + rows[i][2] * tan_t, rows[i][3]);
        with_sin[i] = fmin(rows[i][1] + rows[i][2] * sin_t, rows[i][3]);
        unclamped[i] = rows[i][1] + rows[i][2] * tan_t;
        constant[i] = 0.004;
    }
    sl_check_result out;
    grade_probe("slope_scaled_bias", 4, rows, with_sin, expected, &out);
    CHECK(!out.passed && strstr(out.message, "sin(theta) where tan(theta) belongs") != NULL);
    CHECK(strstr(out.summary, "sin(theta)") == out.summary);
    grade_probe("slope_scaled_bias", 4, rows, unclamped, expected, &out);
    CHECK(strstr(out.message, "not clamped") != NULL);
    grade_probe("slope_scaled_bias", 4, rows, constant, expected, &out);
    CHECK(strstr(out.message, "a hand-tuned constant") != NULL);
    grade_probe("slope_scaled_bias", 4, rows, expected, expected, &out);
    CHECK(out.passed);
    /* a cap at half of max_bias: said as the multiple it is over two different max_bias, not a factor from
     * the one row where the slope term could be read */
    static const float capped_rows[][SL_PROBE_MAX_INPUTS] = {
        {1.0f, 0.0005f, 0.0015f, 0.01f}, {0.5f, 0.0005f, 0.0015f, 0.01f}, {0.1f, 0.0005f, 0.0015f, 0.01f},
        {0.5f, 0.0005f, 0.0015f, 0.004f}};
    double capped_want[4], capped_got[4];
    for (int i = 0; i < 4; i++) {
        double cos_t = capped_rows[i][0], tan_t = sqrt(1 - cos_t * cos_t) / cos_t;
        double open = capped_rows[i][1] + capped_rows[i][2] * tan_t;
        capped_want[i] = fmin(open, capped_rows[i][3]);
        capped_got[i] = fmin(open, 0.5 * capped_rows[i][3]);
    }
    grade_probe("slope_scaled_bias", 4, capped_rows, capped_got, capped_want, &out);
    CHECK(!out.passed && strstr(out.message, "caps the bias at 0.5 times max_bias") && !strstr(out.message, "factor"));
    if (!strstr(out.message, "caps the bias")) fprintf(stderr, "  capped: %s\n", out.message);

    /* where no verdict names it, the relation the answers keep to the contract's: negated values */
    static const float states[][SL_PROBE_MAX_INPUTS] = {{3, 2.0f, 4.0f, -1}, {3, 1.5f, 3.0f, -1}, {0, 2.0f, 4.0f, -1}};
    double state_want[15] = {1, 2, 4, 0, 0x405, 1, 1.5, 3, 0, 0x405, 0, 0, 0, 0, 0x405};
    double state_got[15];
    memcpy(state_got, state_want, sizeof state_got);
    state_got[1] = -2, state_got[2] = -4, state_got[6] = -1.5, state_got[7] = -3;
    grade_probe("lab3_depth_pass_state", 3, states, state_got, state_want, &out);
    CHECK(!out.passed && strstr(out.message, "factor and units come out negated on every row that differs"));
    if (!strstr(out.message, "negated")) fprintf(stderr, "  negated: %s\n", out.message);
    /* one factor on every value that differs (a sum over 20 samples divided by 16) */
    /* (on a map other than the empty one, where lab 7's own verdict reads the same answers as a weight sum) */
    static const float soft[][SL_PROBE_MAX_INPUTS] = {{SL_PROBE_MAP_CUBE_POSITIVE, 1.5f, 2, 0.5f, 10, 0.005f, 1},
                                                      {SL_PROBE_MAP_CUBE_POSITIVE, -2, 1, 0.5f, 10, 0.005f, 1},
                                                      {SL_PROBE_MAP_CUBE_POSITIVE, 0.5f, -1, 2, 10, 0.005f, 1}};
    double soft_want[3] = {1, 0.5, 0.25}, soft_got[3] = {1.25, 0.625, 0.3125};
    grade_probe("point_shadow_soft", 3, soft, soft_got, soft_want, &out);
    CHECK(!out.passed && strstr(out.message, "1.25 times the contract's"));
    if (!strstr(out.message, "1.25 times")) fprintf(stderr, "  scaled: %s\n", out.message);
    /* the same answers on the empty map: the weights' sum, said as such */
    static const float empty[][SL_PROBE_MAX_INPUTS] = {{SL_PROBE_MAP_CUBE_LIT, 1.5f, 2, 0.5f, 10, 0.005f, 1},
                                                       {SL_PROBE_MAP_CUBE_LIT, -2, 1, 0.5f, 10, 0.005f, 1}};
    double empty_want[2] = {1, 1}, empty_got[2] = {1.25, 1.25};
    grade_probe("point_shadow_soft", 2, empty, empty_got, empty_want, &out);
    CHECK(!out.passed && strstr(out.message, "the weights sum to 1.25, not 1"));
    if (!strstr(out.message, "weights sum")) fprintf(stderr, "  weight sum: %s\n", out.message);
}

/* A failed check's diagnosis is the same for every student it fits, whatever
 * the numbers in their message, and differs between mistakes (the class
 * report counts students per diagnosis). */
static void test_grade_diagnosis_ids(void) {
    sl_case c = grade_case(3, SL_CHECK_VISIBILITY);
    c.params.bias.mode = SL_BIAS_SLOPE_SCALED;
    char ids[2][80], texts[2][320];
    for (int student = 0; student < 2; student++) {
        sl_case_result r = {.finished = true};
        sl_image acne = square(64, 64, 0, 1, 20, 20, 40, 40);
        for (int i = 0; i < 64 * 64; i += 3 + 2 * student) acne.data[i] = 0; /* more or less acne */
        add_capture(&r, "visibility", acne);
        sl_reference ref = image_reference(square(64, 64, 0, 1, 20, 20, 40, 40));
        ref.lit_mask = square(64, 64, 1, 1, 0, 0, 0, 0); /* the solutions' lit surfaces */
        sl_check_result out;
        sl_grade_check(&c, &c.checks[0], &r, &ref, NULL, &out);
        CHECK(!out.passed && out.diagnosis[0]);
        snprintf(ids[student], sizeof ids[student], "%s", out.diagnosis);
        snprintf(texts[student], sizeof texts[student], "%s", out.diagnosis_text);
        sl_image_free(&out.diff);
        sl_case_result_free(&r);
        sl_reference_free(&ref);
    }
    CHECK(strcmp(ids[0], ids[1]) == 0);
    CHECK(strcmp(texts[0], texts[1]) == 0);
    CHECK(strncmp(ids[0], "bias-too-small-or-missing-", 26) == 0);
    if (strncmp(ids[0], "bias-too-small-or-missing-", 26) != 0) fprintf(stderr, "  id: %s (%s)\n", ids[0], texts[0]);
    /* a probe's verdict, named with its function; another verdict, another id */
    static const float rows[][SL_PROBE_MAX_INPUTS] = {{1.0f, 0.0005f, 0.0015f, 0.01f}, {0.5f, 0.0005f, 0.0015f, 0.01f}};
    double expected[2], with_sin[2], constant[2] = {0.004, 0.004};
    for (int i = 0; i < 2; i++) {
        double cos_t = rows[i][0], sin_t = sqrt(1 - cos_t * cos_t);
        expected[i] = fmin(rows[i][1] + rows[i][2] * sin_t / cos_t, rows[i][3]);
        with_sin[i] = fmin(rows[i][1] + rows[i][2] * sin_t, rows[i][3]);
    }
    sl_check_result out;
    grade_probe("slope_scaled_bias", 2, rows, with_sin, expected, &out);
    CHECK(strncmp(out.diagnosis_text, "slope_scaled_bias(): sin(theta) where tan(theta) belongs", 56) == 0);
    char sin_id[80];
    snprintf(sin_id, sizeof sin_id, "%s", out.diagnosis);
    grade_probe("slope_scaled_bias", 2, rows, constant, expected, &out);
    CHECK(strcmp(out.diagnosis, sin_id) != 0 && strncmp(out.diagnosis, "slope-scaled-bias-", 18) == 0);
    /* either verdict: the same function, wrong (one row in the class report) */
    CHECK(strcmp(out.cause_function, "slope_scaled_bias") == 0 && out.cause_kind && strcmp(out.cause_kind, SL_CAUSE_WRONG) == 0);
    grade_probe("slope_scaled_bias", 2, rows, expected, expected, &out);
    CHECK(out.passed && !out.diagnosis[0] && !out.cause_kind);
}

/* A vertical shadow edge whose soft ramp is `near` px wide in the top half and `far` px in the bottom. */
static sl_image ramp(int near, int far) {
    sl_image img = sl_image_alloc(64, 64, 1);
    for (int y = 0; y < 64; y++) {
        int w = y < 32 ? near : far;
        for (int x = 0; x < 64; x++) {
            float v = (float)(x - (32 - w / 2)) / (float)(w > 0 ? w : 1);
            img.data[y * 64 + x] = v < 0 ? 0 : v > 1 ? 1 : v;
        }
    }
    return img;
}

static void test_grade_penumbra_inverted(void) {
    sl_case c = grade_case(4, SL_CHECK_PENUMBRA);
    c.params.filter.mode = SL_FILTER_PCSS;
    c.checks[0].probe_count = 2;
    c.checks[0].probes[0] = (sl_probe){"near", {0, 10}, {63, 10}};
    c.checks[0].probes[1] = (sl_probe){"far", {0, 50}, {63, 50}};
    sl_case_result r = {.finished = true};
    add_capture(&r, "visibility", ramp(20, 3));
    sl_reference ref = image_reference(ramp(3, 20));
    sl_check_result out;
    sl_grade_check(&c, &c.checks[0], &r, &ref, NULL, &out);
    CHECK(!out.passed);
    CHECK(strstr(out.message, "penumbra formula inverted") != NULL);
    sl_case_result_free(&r);
    /* the same widths pass */
    r = (sl_case_result){.finished = true};
    add_capture(&r, "visibility", ramp(3, 20));
    sl_grade_check(&c, &c.checks[0], &r, &ref, NULL, &out);
    CHECK(out.passed && out.points == 1);
    sl_case_result_free(&r);
    sl_reference_free(&ref);
}

static void test_grade_run_failures(void) {
    sl_case c = grade_case(2, SL_CHECK_MATRICES);
    sl_reference ref = {.needed = true, .loaded = true, .number_count = 48};
    sl_check_result out;
    sl_case_result crashed = {.signal = SIGSEGV};
    snprintf(crashed.crashed_in, sizeof crashed.crashed_in, "lab2_light_view");
    sl_grade_check(&c, &c.checks[0], &crashed, &ref, NULL, &out);
    CHECK(strstr(out.message, "crashed (Segmentation fault) in lab2_light_view()") != NULL);
    /* the class report's mistake: the function and the kind of cause */
    CHECK(strcmp(out.cause_function, "lab2_light_view") == 0 && out.cause_kind && strcmp(out.cause_kind, SL_CAUSE_CRASH) == 0);
    sl_case_result hung = {.timed_out = true, .seconds = 20};
    snprintf(hung.crashed_in, sizeof hung.crashed_in, "lab2_shadow_matrix");
    sl_grade_check(&c, &c.checks[0], &hung, &ref, NULL, &out);
    CHECK(strstr(out.message, "timed out after 20 s in lab2_shadow_matrix()") != NULL);
    CHECK(strcmp(out.cause_function, "lab2_shadow_matrix") == 0 && out.cause_kind &&
          strcmp(out.cause_kind, SL_CAUSE_TIMEOUT) == 0);
    /* hung in a draw, no lab function running: the GPU is in a lab shader (Mesa 25+ does not cut loops short) */
    sl_case_result spinning = {.timed_out = true, .seconds = 20};
    snprintf(spinning.crashed_in, sizeof spinning.crashed_in, "drawing_lab2");
    sl_grade_check(&c, &c.checks[0], &spinning, &ref, NULL, &out);
    CHECK(strstr(out.message, "timed out after 20 s while drawing with the shaders of labs 1-2: a shader loop that "
                              "does not end?") != NULL);
    CHECK(!out.cause_kind); /* several labs' shaders: no one function */
    sl_case_result stub = {.finished = true, .not_implemented_count = 1};
    snprintf(stub.not_implemented[0], 64, "lab2_light_view");
    sl_grade_check(&c, &c.checks[0], &stub, &ref, NULL, &out);
    CHECK(strstr(out.message, "not implemented: lab2_light_view() still returns SL_NOT_IMPLEMENTED (TODO(lab2.1)") != NULL);
    CHECK(strcmp(out.cause_function, "lab2_light_view") == 0 && out.cause_kind && strcmp(out.cause_kind, SL_CAUSE_STUB) == 0);
    sl_reference missing = {.needed = true};
    snprintf(missing.error, sizeof missing.error, "reference missing: x/matrices.json");
    sl_grade_check(&c, &c.checks[0], &stub, &missing, NULL, &out);
    CHECK(out.reference_problem && strstr(out.message, "reference missing") != NULL);
}

/* Numbers about state (lab 1's framebuffer) are the runner's word: they pass
 * only with the picture that shows the state used, never alone. */
static void test_grade_state_needs_evidence(void) {
    sl_case c = grade_case(1, SL_CHECK_FBO);
    snprintf(c.name, sizeof c.name, "lab1_synthetic");
    snprintf(c.checks[0].name, sizeof c.checks[0].name, "framebuffer");
    c.checks[1] = c.checks[0];
    c.checks[1].kind = SL_CHECK_DEPTH_MAP;
    snprintf(c.checks[1].name, sizeof c.checks[1].name, "depth");
    c.check_count = 2;
    int size = c.params.shadow_map_size;
    sl_image want = square(size, size, 1, 0.4f, size / 4, size / 4, size / 2, size / 2);
    sl_reference refs[2] = {{0}, image_reference(want)};
    for (int honest = 0; honest < 2; honest++) {
        sl_case_result r = {.finished = true};
        sl_capture *fbo = &r.captures[r.capture_count++];
        snprintf(fbo->name, sizeof fbo->name, "fbo");
        double v[SL_FBO_NUMBERS] = {GL_FRAMEBUFFER_COMPLETE, GL_TEXTURE, 1, 24, size, size, GL_NONE, GL_NONE, GL_NONE, size};
        memcpy(fbo->numbers, v, sizeof v);
        fbo->number_count = SL_FBO_NUMBERS;
        /* forged: a depth map of zeros; honest: the reference's */
        add_capture(&r, "depth_map", honest ? square(size, size, 1, 0.4f, size / 4, size / 4, size / 2, size / 2)
                                            : sl_image_alloc(size, size, 1));
        sl_check_result out[2];
        for (int k = 0; k < 2; k++) sl_grade_check(&c, &c.checks[k], &r, &refs[k], NULL, &out[k]);
        CHECK(out[0].passed && out[1].passed == (honest == 1)); /* the state alone looks right */
        sl_grade_require_evidence(&c, out);
        CHECK(out[0].passed == (honest == 1) && out[0].points == (honest ? 1 : 0));
        if (!honest)
            CHECK(strstr(out[0].message, "would show it used, lab1_synthetic / depth, fails") != NULL &&
                  strstr(out[0].message, "the state alone earns no point") != NULL && out[0].diagnosis[0]);
        sl_case_result_free(&r);
    }
    /* a case with the state and no picture: nothing backs it */
    c.check_count = 1;
    sl_check_result alone = {.passed = true, .points = 1, .max_points = 1};
    sl_grade_require_evidence(&c, &alone);
    CHECK(!alone.passed && alone.points == 0 && strstr(alone.message, "no picture") != NULL);
    sl_image_free(&want);
}

/* A stream as a runner (or lab code posing as one) would write it. */
typedef struct stream {
    char data[1 << 16];
    size_t size;
} stream;

static void put(stream *s, uint32_t type, const char *name, const void *payload, uint64_t length, uint64_t claimed) {
    sl_message_header h = {type, name ? (uint32_t)strlen(name) : 0, claimed};
    memcpy(s->data + s->size, &h, sizeof h);
    s->size += sizeof h;
    if (h.name_length) memcpy(s->data + s->size, name, h.name_length);
    s->size += h.name_length;
    if (length) memcpy(s->data + s->size, payload, (size_t)length);
    s->size += (size_t)length;
}

static void put_visibility(stream *s, int w, int h, int channels) {
    static char buf[SL_IMAGE_HEADER_BYTES + 16 * 16 * 3 * sizeof(float)];
    int32_t dims[3] = {w, h, channels};
    memcpy(buf, dims, sizeof dims);
    size_t n = SL_IMAGE_HEADER_BYTES + (size_t)w * (size_t)h * (size_t)channels * sizeof(float);
    put(s, SL_MSG_IMAGE, "visibility", buf, n, n);
}

/* The grader's side of the channel refuses every lie about lengths and
 * captures, and takes a well-formed stream. */
static void test_channel_rejects_lies(void) {
    sl_case c = grade_case(2, SL_CHECK_VISIBILITY);
    c.width = c.height = 16;
    sl_case_result r;
    static stream s;
    /* well-formed */
    s.size = 0;
    put(&s, SL_MSG_HELLO, NULL, "osmesa\nllvmpipe \033[2Jx", 21, 21);
    put_visibility(&s, 16, 16, 1);
    put(&s, SL_MSG_DONE, NULL, NULL, 0, 0);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(r.finished && !r.protocol_error[0] && r.capture_count == 1);
    CHECK(strcmp(r.backend, "osmesa") == 0 && strchr(r.renderer, '\033') == NULL); /* escapes removed */
    sl_case_result_free(&r);
    /* a payload length near 2^64: refused at the header, nothing allocated */
    s.size = 0;
    put(&s, SL_MSG_IMAGE, "visibility", NULL, 0, UINT64_MAX - 8);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(!r.finished && strstr(r.protocol_error, "bytes where at most") != NULL);
    /* a name length of 2^32 - 1 */
    s.size = 0;
    sl_message_header h = {SL_MSG_STAGE, UINT32_MAX, 0};
    memcpy(s.data, &h, sizeof h);
    s.size = sizeof h;
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(strstr(r.protocol_error, "malformed name") != NULL);
    /* the same capture twice */
    s.size = 0;
    put_visibility(&s, 16, 16, 1);
    put_visibility(&s, 16, 16, 1);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(strstr(r.protocol_error, "\"visibility\" twice") != NULL);
    sl_case_result_free(&r);
    /* a capture the case did not ask for */
    s.size = 0;
    double numbers[SL_MATRICES_NUMBERS] = {0};
    put(&s, SL_MSG_NUMBERS, "depth_map", numbers, sizeof numbers, sizeof numbers);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(strstr(r.protocol_error, "did not ask for") != NULL);
    /* an image whose size is not the case's */
    s.size = 0;
    put_visibility(&s, 8, 8, 1);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(strstr(r.protocol_error, "does not add up") != NULL && r.capture_count == 0);
    /* anything after DONE */
    s.size = 0;
    put(&s, SL_MSG_DONE, NULL, NULL, 0, 0);
    put(&s, SL_MSG_STAGE, "lab1_create_shadow_map", NULL, 0, 0);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(!r.finished && strstr(r.protocol_error, "after DONE") != NULL);
    /* an unknown type, and a name with characters no function has */
    s.size = 0;
    put(&s, 99, NULL, NULL, 0, 0);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(strstr(r.protocol_error, "unknown message type") != NULL);
    s.size = 0;
    put(&s, SL_MSG_NOT_IMPLEMENTED, "../x", NULL, 0, 0);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(strstr(r.protocol_error, "malformed name") != NULL);
    /* The renderer is named once, first, before lab code runs: a second HELLO (lab code renaming the
     * renderer so that slow frames are not compared) and a HELLO after other messages break the rules. */
    s.size = 0;
    put(&s, SL_MSG_HELLO, NULL, "osmesa\nllvmpipe", 15, 15);
    put(&s, SL_MSG_STAGE, "lab2_light_view", NULL, 0, 0);
    put(&s, SL_MSG_HELLO, NULL, "osmesa\nsoftpipe", 15, 15);
    put_visibility(&s, 16, 16, 1);
    put(&s, SL_MSG_DONE, NULL, NULL, 0, 0);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(!r.finished && strstr(r.protocol_error, "a second HELLO") != NULL && r.capture_count == 0);
    CHECK(strcmp(r.renderer, "llvmpipe") == 0); /* the first one stays */
    s.size = 0;
    put(&s, SL_MSG_STAGE, "lab2_light_view", NULL, 0, 0);
    put(&s, SL_MSG_HELLO, NULL, "osmesa\nsoftpipe", 15, 15);
    put(&s, SL_MSG_DONE, NULL, NULL, 0, 0);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(!r.finished && strstr(r.protocol_error, "a HELLO after other messages") != NULL && !r.renderer[0]);
    /* a stream cut off mid-message: not finished, no error (a crash) */
    s.size = 0;
    put(&s, SL_MSG_STAGE, "lab2_light_view", NULL, 0, 0);
    put_visibility(&s, 16, 16, 1);
    sl_run_parse_stream(&c, s.data, s.size - 10, &r);
    CHECK(!r.finished && !r.protocol_error[0] && strcmp(r.crashed_in, "lab2_light_view") == 0);
}

/* A compiler's first error, read from its log, is one line of valid UTF-8
 * whatever the lab file held (a #error with raw bytes, colour codes), and its
 * cut to SL_BUILD_ERROR_MAX falls between characters. */
static void test_build_error_text(void) {
    char log[512], first[SL_BUILD_ERROR_MAX + 8], err[256] = "";
    snprintf(log, sizeof log, "%s/build.log", tmp_dir);
    FILE *f = fopen(log, "wb");
    CHECK(f != NULL);
    if (!f) return;
    fputs("[1/2] Building C object\n", f);
    fputs("lab1.c:3:2: \033[01;31merror: \033[m#error bad \xff\xfe bytes \xc0\xaf \x01 cr\r ", f);
    for (int i = 0; i < 400; i++) fputs("\xc3\xa9", f);
    fputs("\nlab1.c:4:2: error: a second error\n", f);
    fclose(f);
    CHECK(sl_build_failure_first_error(log, NULL, first, sizeof first, err, sizeof err));
    size_t n = strlen(first);
    const char *want = "lab1.c:3:2: error: #error bad \xef\xbf\xbd bytes \xef\xbf\xbd  cr \xc3\xa9";
    CHECK(strncmp(first, want, strlen(want)) == 0);
    CHECK(sl_utf8_is_clean(first, n, 0) && n <= SL_BUILD_ERROR_MAX && n >= SL_BUILD_ERROR_MAX - 4);
    CHECK(n > 5 && strcmp(first + n - 5, "\xc3\xa9...") == 0);
}

/* Text from outside the grader: bytes that are not UTF-8 become U+FFFD (a
 * run of them one), controls '?', newlines stay only where asked; a copy or
 * a cut never splits a character. */
static void test_utf8_clean_and_cut(void) {
    uint32_t cp = 0;
    CHECK(sl_utf8_sequence("\xc3\xa9", 2, &cp) == 2 && cp == 0xE9);
    CHECK(sl_utf8_sequence("\xf0\x9f\x98\x80", 4, &cp) == 4 && cp == 0x1F600);
    CHECK(sl_utf8_sequence("\xf0\x9f\x98", 3, &cp) == 0); /* cut short */
    CHECK(sl_utf8_sequence("\xc0\xaf", 2, NULL) == 0);     /* overlong '/' */
    CHECK(sl_utf8_sequence("\xe0\x80\xaf", 3, NULL) == 0); /* overlong, three bytes */
    CHECK(sl_utf8_sequence("\xed\xb0\x80", 3, NULL) == 0); /* a lone low surrogate */
    char out[256];
    static const struct {
        const char *in;
        size_t len;
        unsigned keep;
        const char *want;
    } cases[] = {
        {"caf\xc3\xa9 \xe6\x97\xa5", 9, 0, "caf\xc3\xa9 \xe6\x97\xa5"},               /* valid text as it is */
        {"a\xff\xfe" "b", 4, 0, "a\xef\xbf\xbd" "b"},                                  /* a run of bad bytes: one U+FFFD */
        {"a\x80" "b\xc0\xaf" "c", 6, 0, "a\xef\xbf\xbd" "b\xef\xbf\xbd" "c"},          /* lone continuation, overlong */
        {"x\xe2\x82", 3, 0, "x\xef\xbf\xbd"},                                           /* cut short at the end */
        {"a\0b", 3, 0, "a?b"},                                                           /* NUL */
        {"\033[2J\rScore: 16/16", 17, 0, "?[2J?Score: 16/16"},                           /* ESC, CR */
        {"one\ntwo\tx", 9, 0, "one?two?x"},                                              /* one line */
        {"one\ntwo\tx", 9, SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB, "one\ntwo\tx"},     /* a block */
        {"\xc2\x9b" "31m \xef\xbf\xbe \x7f", 11, 0, "?31m ? ?"},                        /* C1 CSI, U+FFFE, DEL */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        size_t n = sl_utf8_clean(out, sizeof out, cases[i].in, cases[i].len, cases[i].keep);
        CHECK(n == strlen(cases[i].want) && strcmp(out, cases[i].want) == 0);
        CHECK(sl_utf8_is_clean(out, n, cases[i].keep));
        CHECK(sl_utf8_is_clean(cases[i].in, cases[i].len, cases[i].keep) == (strcmp(cases[i].in, cases[i].want) == 0 &&
                                                                             cases[i].len == strlen(cases[i].want)));
    }
    /* a full buffer stops between characters: "é" is 2 bytes, 5 fit before the NUL */
    CHECK(sl_utf8_clean(out, 6, "\xc3\xa9\xc3\xa9\xc3\xa9", 6, 0) == 4 && strcmp(out, "\xc3\xa9\xc3\xa9") == 0);
    CHECK(sl_utf8_clean(out, 3, "a\xff", 2, 0) == 1 && strcmp(out, "a") == 0); /* no room for U+FFFD */
    /* cuts */
    const char *accented = "d\xc3\xa9j\xc3\xa0 \xe2\x82\xac\xf0\x9f\x98\x80"; /* d é j à space € 😀 */
    CHECK(sl_utf8_cut(accented, 2) == 1 && sl_utf8_cut(accented, 3) == 3 && sl_utf8_cut(accented, 100) == strlen(accented));
    CHECK(sl_utf8_cut(accented, 8) == 7 && sl_utf8_cut(accented, 10) == 10 && sl_utf8_cut(accented, 13) == 10);
    size_t len = strlen(accented);
    CHECK(sl_utf8_tail(accented, len, 4) == len - 4 && sl_utf8_tail(accented, len, 5) == len - 4);
    CHECK(sl_utf8_tail(accented, len, 3) == len && sl_utf8_tail(accented, len, 100) == 0);
    sl_utf8_copy(out, 9, accented);
    CHECK(strcmp(out, "d\xc3\xa9j\xc3\xa0 ") == 0);
    char cut[13];
    snprintf(cut, sizeof cut, "%s", accented); /* snprintf keeps 12 bytes: the emoji's first 2 */
    sl_utf8_trim(cut);
    CHECK(strcmp(cut, "d\xc3\xa9j\xc3\xa0 \xe2\x82\xac") == 0);
    sl_utf8_trim(cut); /* nothing split: nothing dropped */
    CHECK(strcmp(cut, "d\xc3\xa9j\xc3\xa0 \xe2\x82\xac") == 0);
}

/* What comes over the channel is clean where it comes in: the header's
 * backend and renderer are one line each, an error and a capture error are
 * valid UTF-8 without controls, and a long accented error, cut to the
 * result's size and again to a check's message, is cut between characters. */
static void test_channel_cleans_text(void) {
    sl_case c = grade_case(2, SL_CHECK_VISIBILITY);
    c.width = c.height = 16;
    sl_case_result r;
    static stream s;
    s.size = 0;
    static const char hello[] = "osmesa\xff\nllvmpipe\nScore: 16/16\r\033[1A\xc0\xaf";
    put(&s, SL_MSG_HELLO, NULL, hello, sizeof hello - 1, sizeof hello - 1);
    static char error[SL_MSG_TEXT_MAX];
    static const char start[] = "shader error:\n\033[31m\xff\xfe\0bad\r\nScore: 16/16\n";
    memcpy(error, start, sizeof start - 1);
    size_t n = sizeof start - 1;
    while (n + 2 <= sizeof error) { /* "é" to the end: every cut lands in the middle of text */
        memcpy(error + n, "\xc3\xa9", 2);
        n += 2;
    }
    put(&s, SL_MSG_ERROR, NULL, error, n, n);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(strcmp(r.backend, "osmesa\xef\xbf\xbd") == 0);
    CHECK(strcmp(r.renderer, "llvmpipe?Score: 16/16??[1A\xef\xbf\xbd") == 0);
    const char *want = "shader error:\n?[31m\xef\xbf\xbd?bad?\nScore: 16/16\n\xc3\xa9";
    CHECK(strncmp(r.error, want, strlen(want)) == 0);
    size_t e = strlen(r.error);
    CHECK(sl_utf8_is_clean(r.error, e, SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB));
    CHECK(e >= sizeof r.error - 3 && strcmp(r.error + e - 2, "\xc3\xa9") == 0);
    /* graded: the error leads the message, cut to its size between characters */
    sl_reference ref = {.needed = true, .loaded = true};
    sl_check_result out;
    sl_grade_check(&c, &c.checks[0], &r, &ref, NULL, &out);
    size_t m = strlen(out.message);
    CHECK(m >= sizeof out.message - 3 && sl_utf8_is_clean(out.message, m, SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB));
    CHECK(strstr(out.message, "\xef\xbf\xbd\xc3\xa9") == NULL && strcmp(out.message + m - 2, "\xc3\xa9") == 0);
    CHECK(sl_utf8_is_clean(out.summary, strlen(out.summary), SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB) &&
          strcmp(out.summary + strlen(out.summary) - 2, "\xc3\xa9") == 0);
    CHECK(sl_utf8_is_clean(out.diagnosis_text, strlen(out.diagnosis_text), SL_UTF8_KEEP_NEWLINE | SL_UTF8_KEEP_TAB));
    sl_case_result_free(&r);
    /* a capture error */
    s.size = 0;
    put(&s, SL_MSG_CAPTURE_ERROR, "visibility", "no\xff\n\033]0;x\a", 10, 10);
    sl_run_parse_stream(&c, s.data, s.size, &r);
    CHECK(strcmp(r.capture_error, "visibility: no\xef\xbf\xbd\n?]0;x?") == 0);
    sl_case_result_free(&r);
}

static void test_sha256_known_answers(void) {
    /* FIPS 180-4 examples */
    sl_sha256 h;
    char hex[65];
    sl_sha256_init(&h);
    sl_sha256_update(&h, "abc", 3);
    sl_sha256_hex(&h, hex);
    CHECK(strcmp(hex, "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad") == 0);
    sl_sha256_init(&h);
    const char *two = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    sl_sha256_update(&h, two, strlen(two));
    sl_sha256_hex(&h, hex);
    CHECK(strcmp(hex, "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1") == 0);
    sl_sha256_init(&h);
    sl_sha256_hex(&h, hex);
    CHECK(strcmp(hex, "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855") == 0);
    /* a million 'a's, fed in uneven pieces */
    sl_sha256_init(&h);
    char chunk[997];
    memset(chunk, 'a', sizeof chunk);
    size_t left = 1000000;
    while (left > 0) {
        size_t n = left < sizeof chunk ? left : sizeof chunk;
        sl_sha256_update(&h, chunk, n);
        left -= n;
    }
    sl_sha256_hex(&h, hex);
    CHECK(strcmp(hex, "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0") == 0);
}

/* A shadow too small for the pixel count: missing, the check still fails and
 * says so; moved by a pixel, or with the whole shadow present, it passes. */
static void test_grade_small_shadow_missing(void) {
    sl_case c = grade_case(2, SL_CHECK_VISIBILITY);
    c.width = c.height = 200; /* a 6x6 shadow: 0.09% of the image, under the 0.5% allowed */
    sl_image reference = square(200, 200, 0, 1, 100, 100, 106, 106);
    struct { sl_image student; bool passes; const char *says; } tries[] = {
        {square(200, 200, 1, 1, 0, 0, 0, 0), false, "the reference's shadows are missing: 100% of its 36 shadowed pixels"},
        {square(200, 200, 0, 1, 101, 100, 107, 106), true, NULL}, /* one pixel over: renderer noise */
        {square(200, 200, 0, 1, 100, 100, 106, 106), true, NULL},
        /* a quarter of it left: 20 of 36 pixels more than a pixel away from it */
        {square(200, 200, 0, 1, 100, 100, 103, 103), false, "missing: 56% of its 36 shadowed pixels"},
    };
    for (size_t i = 0; i < sizeof tries / sizeof tries[0]; i++) {
        sl_case_result r = {.finished = true};
        add_capture(&r, "visibility", tries[i].student);
        sl_image ref_copy = sl_image_alloc(200, 200, 1);
        memcpy(ref_copy.data, reference.data, sizeof(float) * 200 * 200);
        sl_reference ref = image_reference(ref_copy);
        sl_check_result out;
        sl_grade_check(&c, &c.checks[0], &r, &ref, NULL, &out);
        CHECK(out.passed == tries[i].passes);
        if (tries[i].says) CHECK(strstr(out.message, tries[i].says) != NULL);
        if (!out.passed && tries[i].says) printf("  %s\n", out.message);
        sl_image_free(&out.diff);
        sl_case_result_free(&r);
        sl_reference_free(&ref);
    }
    /* The measure itself: the lit mask leaves out surfaces facing away. */
    sl_image none = square(200, 200, 1, 1, 0, 0, 0, 0);
    sl_image away = square(200, 200, 0, 1, 100, 100, 106, 106); /* the shadowed square faces away */
    long shadowed = 0;
    CHECK(sl_visibility_shadow_lost(&none, &reference, NULL, &shadowed) == 1.0 && shadowed == 36);
    CHECK(sl_visibility_shadow_lost(&none, &reference, &away, &shadowed) == 0.0 && shadowed == 0);
    sl_image_free(&none);
    sl_image_free(&away);
    sl_image_free(&reference);
}

/* Blame on evidence: a failed probe leads a picture's message only when the
 * case runs the function, on a failing row's settings, and the rows predict
 * what the picture shows; a bonus function never answers for a regular check. */
static void test_grade_blames_on_evidence(void) {
    /* a lab 4 grid case, radius 1, whose picture is darker on its lit surfaces */
    sl_case c = grade_case(4, SL_CHECK_VISIBILITY);
    c.params.filter.mode = SL_FILTER_GRID;
    c.params.filter.grid_radius = 1;
    c.params.bias.mode = SL_BIAS_CONSTANT;
    sl_image reference = square(64, 64, 0, 1, 20, 20, 40, 40), darker = square(64, 64, 0, 0.8f, 20, 20, 40, 40);
    /* pcf_grid's probe: two rows on the lit map, radius 0 and radius 1 */
    sl_check probe = {.kind = SL_CHECK_PROBE, .rows = 2, .function = sl_probe_index(sl_probe_find("pcf_grid"))};
    const float lit_row[] = {SL_PROBE_MAP_LIT, 0.5f, 0.5f, 0.5f, 1, 0.005f};
    for (int r = 0; r < 2; r++) {
        memcpy(probe.inputs[r], lit_row, sizeof lit_row);
        probe.inputs[r][6] = (float)r; /* radius */
    }
    sl_probe_failure failure = {.function = probe.function, .check = &probe};
    snprintf(failure.where, sizeof failure.where, "lab4_probes / pcf_grid");
    snprintf(failure.summary, sizeof failure.summary, "the weights sum to 0.8");
    sl_grade_context context = {.probe_failures = &failure, .probe_failure_count = 1};
    struct {
        uint32_t rows;       /* failing rows */
        uint32_t predicts;   /* what they predict */
        bool bonus_function; /* the failure is the bonus cascade_blend's, on a lab 6 case */
        bool leads;
    } tries[] = {
        {1u << 1, 1u << SL_SYMPTOM_TOO_DARK, false, true},   /* radius 1, darker: explains it */
        {1u << 0, 1u << SL_SYMPTOM_TOO_DARK, false, false},  /* radius 0 only: the case never meets it */
        {1u << 1, 1u << SL_SYMPTOM_TOO_LIGHT, false, false}, /* predicts lighter: cannot explain darker */
        {1u << 1, SL_SYMPTOMS_ANY, true, false},             /* a bonus stub: never for a regular check */
    };
    for (size_t i = 0; i < sizeof tries / sizeof tries[0]; i++) {
        sl_case cc = c;
        failure.failing_rows = tries[i].rows;
        for (int r = 0; r < 2; r++) failure.row_predicts[r] = tries[i].predicts;
        failure.function = probe.function;
        if (tries[i].bonus_function) {
            cc.lab = 6; /* blend band 0: the case does not run the bonus */
            cc.params.cascades.blend_band = 0;
            failure.function = sl_probe_index(sl_probe_find("cascade_blend"));
            failure.stub = true;
            probe.function = failure.function;
        }
        sl_case_result r = {.finished = true};
        sl_image student = sl_image_alloc(64, 64, 1), ref_copy = sl_image_alloc(64, 64, 1);
        memcpy(student.data, darker.data, sizeof(float) * 64 * 64);
        memcpy(ref_copy.data, reference.data, sizeof(float) * 64 * 64);
        add_capture(&r, "visibility", student);
        sl_reference ref = image_reference(ref_copy);
        sl_check_result out;
        sl_grade_check(&cc, &cc.checks[0], &r, &ref, &context, &out);
        bool leads = strstr(out.message, "is wrong on its own") != NULL || strstr(out.message, "not implemented") != NULL;
        CHECK(!out.passed && leads == tries[i].leads);
        if (leads != tries[i].leads) printf("  try %zu: %s\n", i, out.message);
        if (tries[i].bonus_function) CHECK(strstr(out.message, "cascade_blend") == NULL);
        sl_image_free(&out.diff);
        sl_case_result_free(&r);
        sl_reference_free(&ref);
    }
    /* a diagnosis's cause that names a function whose probe passes gives way to the candidates */
    sl_case_result r = {.finished = true};
    sl_image student = sl_image_alloc(64, 64, 1), ref_copy = sl_image_alloc(64, 64, 1);
    memcpy(student.data, darker.data, sizeof(float) * 64 * 64);
    memcpy(ref_copy.data, reference.data, sizeof(float) * 64 * 64);
    add_capture(&r, "visibility", student);
    sl_reference ref = image_reference(ref_copy);
    ref.lit_mask = square(64, 64, 1, 1, 0, 0, 0, 0); /* the solutions' lit surfaces */
    sl_grade_context passed = {.probes_passed = 1ull << sl_probe_index(sl_probe_find("pcf_grid"))};
    sl_check_result out;
    sl_grade_check(&c, &c.checks[0], &r, &ref, &passed, &out);
    CHECK(!out.passed && strstr(out.message, "divide by the number of samples in pcf_grid") == NULL);
    CHECK(strstr(out.message, "pcf_grid(), which this symptom suggests, passes its probe") != NULL);
    CHECK(strstr(out.message, "This case ran pcf_grid() with radius 1") != NULL);
    printf("  %s\n", out.message);
    sl_image_free(&out.diff);
    sl_case_result_free(&r);
    sl_reference_free(&ref);
    sl_image_free(&reference);
    sl_image_free(&darker);
}

/* A picture wrong while every function its check runs passes its probe: the message rules them out
 * once ("Ruled out: ..."), with no candidate left to name. */
static void test_grade_rules_out_once(void) {
    sl_case c = grade_case(6, SL_CHECK_CASCADE_INDEX);
    sl_case_result r = {.finished = true};
    add_capture(&r, sl_check_capture_name(&c, &c.checks[0]), square(64, 64, 0, 0, 0, 0, 0, 0));
    sl_reference ref = image_reference(square(64, 64, 1, 0, 0, 0, 32, 64)); /* cascade 1 on the left half */
    sl_grade_context passed = {.probes_passed = ~0ull, .probes_generic = ~0ull};
    sl_check_result out;
    sl_grade_check(&c, &c.checks[0], &r, &ref, &passed, &out);
    printf("  %s\n", out.message);
    CHECK(!out.passed && strstr(out.message, "Ruled out: ") != NULL);
    CHECK(strcasestr(out.message, "ruled out: ruled out") == NULL);
    CHECK(strstr(out.message, "Candidates") == NULL);
    sl_image_free(&out.diff);
    sl_case_result_free(&r);
    sl_reference_free(&ref);
}

/* A function whose probe passed on its written rows alone (no generic row ran) is not ruled out: a term
 * those rows leave at 0 may be the cause. The message says so instead. */
static void test_grade_rules_out_only_on_generic_inputs(void) {
    sl_case c = grade_case(6, SL_CHECK_CASCADE_INDEX);
    sl_case_result r = {.finished = true};
    add_capture(&r, sl_check_capture_name(&c, &c.checks[0]), square(64, 64, 0, 0, 0, 0, 0, 0));
    sl_reference ref = image_reference(square(64, 64, 1, 0, 0, 0, 32, 64));
    sl_grade_context written_only = {.probes_passed = ~0ull, .probes_generic = 0};
    sl_check_result out;
    sl_grade_check(&c, &c.checks[0], &r, &ref, &written_only, &out);
    printf("  %s\n", out.message);
    CHECK(!out.passed && strcasestr(out.message, "ruled out: ") == NULL);
    CHECK(strstr(out.message, "only on its written inputs, not on generic ones: not ruled out") != NULL ||
          strstr(out.message, "only on their written inputs, not on generic ones: not ruled out") != NULL);
    sl_image_free(&out.diff);
    sl_case_result_free(&r);
    sl_reference_free(&ref);
}

/* A GLSL compile error: "not reached", the lab file named as the handout names it, a candidate list on
 * one line, whole lines only (more than fit are counted), and a report's later checks stopped by the
 * same file point back to the first. A compiler's text cut where the channel's buffer ends loses its
 * last, cut line there. */
static void test_grade_compile_error_once(void) {
    static char error[8192];
    int n = snprintf(error, sizeof error, "GLSL compile error in framework/shaders/scene_bias.frag:\n"
                     "labs/lab3_bias/shaders/bias.glsl:9:9: error: no matching function for call to `min(float)'; "
                     "candidates are:\n");
    for (int i = 0; i < 21; i++)
        n += snprintf(error + n, sizeof error - (size_t)n, "labs/lab3_bias/shaders/bias.glsl:9:9: error:    vec%d min(vec%d, float)\n",
                      i, i);
    for (int i = 0; i < 40; i++)
        n += snprintf(error + n, sizeof error - (size_t)n,
                      "labs/lab3_bias/shaders/bias.glsl:%d:2: error: `x%d' undeclared, and a long explanation after it\n",
                      20 + i, i);
    sl_check_result first = {0}, second = {0}, other = {0};
    CHECK(!sl_diag_compile_error(&first, "the runner could not make its context"));
    CHECK(sl_diag_compile_error(&first, error) && first.settled);
    CHECK(strcmp(first.not_compiled, "labs/lab3_bias/shaders/bias.glsl") == 0);
    CHECK(strncmp(first.message, "not reached: labs/lab3_bias/shaders/bias.glsl did not compile:\n", 63) == 0);
    CHECK(strstr(first.message, "candidates are: vec0 min(vec0, float), vec1 min(vec1, float), vec2 min(vec2, float), "
                                "vec3 min(vec3, float) and 17 more\n") != NULL);
    CHECK(strstr(first.message, "error:    ") == NULL && strstr(first.message, "xxxx") == NULL);
    const char *tail = strrchr(first.message, '\n');
    CHECK(tail && strncmp(tail, "\n(and ", 6) == 0 && strstr(tail, " more lines)") != NULL);
    char copy[sizeof first.message];
    snprintf(copy, sizeof copy, "%s", first.message);
    for (char *line = strtok(copy, "\n"); line; line = strtok(NULL, "\n")) { /* whole lines only */
        size_t len = strlen(line);
        CHECK(strncmp(line, "labs/", 5) != 0 || (len > 8 && (strcmp(line + len - 8, "after it") == 0 ||
                                                           strcmp(line + len - 7, "17 more") == 0)));
    }
    CHECK(sl_diag_compile_error(&second, error));
    CHECK(sl_diag_compile_error(&other, "GLSL compile error in framework/shaders/scene.vert:\n"
                                        "framework/shaders/scene.vert:21:22: error: no function with name 'shadow_coord'\n"));
    CHECK(strcmp(other.not_compiled, "framework/shaders/scene.vert") == 0); /* no lab file in error: the program */
    sl_compile_errors_said said = {0};
    sl_diag_compile_error_once(&first, &said);
    sl_diag_compile_error_once(&second, &said);
    sl_diag_compile_error_once(&other, &said);
    CHECK(strstr(first.message, "candidates are") != NULL);
    CHECK(strcmp(second.message, "not reached: labs/lab3_bias/shaders/bias.glsl did not compile (see above)") == 0);
    CHECK(strstr(other.message, "no function with name 'shadow_coord'") != NULL);
    /* from the channel: a probe's compile error longer than its buffer, cut to whole lines */
    sl_case c = grade_case(3, SL_CHECK_PROBE);
    static stream st;
    st.size = 0;
    put(&st, SL_MSG_HELLO, NULL, "osmesa\nllvmpipe", 15, 15);
    size_t length = strlen(error);
    memset(error + length, 'x', 3000);
    put(&st, SL_MSG_CAPTURE_ERROR, "probe_0", error, length + 3000, length + 3000);
    sl_case_result r;
    sl_run_parse_stream(&c, st.data, st.size, &r);
    size_t kept = strlen(r.probe_errors[0]);
    CHECK(kept > 0 && r.probe_errors[0][kept - 1] == '\n' && strstr(r.probe_errors[0], "xxx") == NULL);
    sl_case_result_free(&r);
    printf("  %.200s ... %s\n", first.message, strrchr(first.message, '\n') ? strrchr(first.message, '\n') : "");
}

/* Under --hidden --seed a probe's rows move as its "vary" says: one draw per
 * check and group, so rows keep their relations; kept parameters stay; two
 * seeds give two tables. */
/* Generic probe rows: drawn from the seed (the same seed, the same rows), appended after the written ones,
 * every term of the formula non-zero, and judged by the contract's formula. */

/* A matrix told as the camera it is: each kind of difference named in a camera's terms, none for the
 * same camera or for a matrix that is no camera. */
static void _sl_flat(mat4 m, double out[16]) {
    for (int c = 0; c < 4; c++)
        for (int r = 0; r < 4; r++) out[c * 4 + r] = m[c][r];
}

static void test_camera_differences(void) {
    mat4 m;
    double square[16], wide[16], ortho[16], ortho_far[16], view[16], backwards[16], shear[16];
    char text[600];
    glm_perspective(glm_rad(60.0f), 1.0f, 0.5f, 30.0f, m);
    _sl_flat(m, square);
    glm_perspective(glm_rad(60.0f), 2.0f, 0.5f, 30.0f, m);
    _sl_flat(m, wide);
    CHECK(sl_camera_differences(wide, square, text, sizeof text) && strstr(text, "aspect (width / height) is 2, expected 1"));
    CHECK(!strstr(text, "field of view") && !strstr(text, "depth range"));
    CHECK(!sl_camera_differences(square, square, text, sizeof text) && text[0] == '\0');
    glm_ortho(-5, 5, -4, 4, 1, 20, m);
    _sl_flat(m, ortho);
    glm_ortho(-5, 5, -4, 4, 1, 40, m);
    _sl_flat(m, ortho_far);
    CHECK(sl_camera_differences(ortho_far, ortho, text, sizeof text) && strstr(text, "depth (near, far) [1, 40], expected [1, 20]"));
    CHECK(!strstr(text, "spans x"));
    CHECK(sl_camera_differences(square, ortho, text, sizeof text) && strstr(text, "a perspective projection, where an orthographic"));
    glm_lookat((vec3){1, 8, 6}, (vec3){1, 7.2f, 5.4f}, (vec3){0, 1, 0}, m);
    _sl_flat(m, view);
    glm_lookat((vec3){1, 8, 6}, (vec3){1, 8.8f, 6.6f}, (vec3){0, 1, 0}, m);
    _sl_flat(m, backwards);
    CHECK(sl_camera_differences(backwards, view, text, sizeof text) && strstr(text, "it looks the opposite way"));
    CHECK(!strstr(text, "eye is at")); /* the same eye */
    memcpy(shear, view, sizeof shear);
    shear[4] += 0.5; /* the rotation part no longer orthonormal: not a camera */
    CHECK(sl_camera_differences(shear, view, text, sizeof text) && strstr(text, "no camera's matrix"));
    CHECK(!sl_camera_differences(view, shear, text, sizeof text)); /* an expected matrix that is no camera: nothing */
}

/* A slip of one input that every row follows is named; a slip two readings fit is not. */
static void test_probe_slips(void) {
    write_file("slips.json",
               "{\"name\": \"s\", \"lab\": 2, \"checks\": ["
               " {\"name\": \"coord\", \"kind\": \"probe\", \"points\": 1, \"function\": \"shadow_coord\","
               "  \"rows\": [{\"shadow_matrix\": [0.5,0,0,0, 0,0.5,0,0, 0,0,0.5,0, 0.5,0.5,0.5,1],"
               "             \"world_position\": [1, 2, 3, 1]}]}]}");
    char path[512], err[2048], text[300];
    snprintf(path, sizeof path, "%s/slips.json", tmp_dir);
    static sl_case c;
    CHECK(sl_case_load(&c, path, err, sizeof err));
    CHECK(sl_probe_generic_add(&c, 7) > 0);
    static sl_check swapped;
    swapped = c.checks[0];
    swapped.generic_rows = swapped.rows; /* every row judged by the formula, to make the student's outputs */
    int wp = 16; /* world_position follows the matrix's 16 floats */
    double student[SL_PROBE_MAX_ROWS * 4];
    for (int row = 0; row < swapped.rows; row++) {
        float t = swapped.inputs[row][wp];
        swapped.inputs[row][wp] = swapped.inputs[row][wp + 1];
        swapped.inputs[row][wp + 1] = t;
        CHECK(sl_probe_generic_expected(&swapped, row, &student[row * 4]));
    }
    CHECK(sl_probe_generic_slip(&c.checks[0], student, NULL, text, sizeof text) &&
          strstr(text, "the x and y of world_position swapped"));
    /* outputs of the contract itself: no slip */
    static sl_check same;
    same = c.checks[0];
    same.generic_rows = same.rows;
    for (int row = 0; row < same.rows; row++) CHECK(sl_probe_generic_expected(&same, row, &student[row * 4]));
    CHECK(!sl_probe_generic_slip(&c.checks[0], student, NULL, text, sizeof text) && text[0] == '\0');
    /* every output 0: negating w, zeroing it and more fit alike, so none is named */
    memset(student, 0, sizeof student);
    CHECK(!sl_probe_generic_slip(&c.checks[0], student, NULL, text, sizeof text));

    /* a slip of the formula itself: sin(theta) for tan(theta) in the slope-scaled bias, clamped as asked */
    write_file("slips_bias.json",
               "{\"name\": \"b\", \"lab\": 3, \"checks\": ["
               " {\"name\": \"bias\", \"kind\": \"probe\", \"points\": 1, \"function\": \"slope_scaled_bias\","
               "  \"rows\": [{\"n_dot_l\": 0.5, \"constant_bias\": 0.0005, \"slope\": 0.0015, \"max_bias\": 0.01}]}]}");
    snprintf(path, sizeof path, "%s/slips_bias.json", tmp_dir);
    static sl_case b;
    CHECK(sl_case_load(&b, path, err, sizeof err));
    CHECK(sl_probe_generic_add(&b, 11) > 0);
    const sl_check *bias = &b.checks[0];
    const sl_probe_function *sb = sl_probe_at(bias->function);
    for (int row = 0; row < bias->rows; row++) {
        double cos_theta = sl_probe_row_param(sb, bias->inputs[row], "n_dot_l")[0];
        double sum = sl_probe_row_param(sb, bias->inputs[row], "constant_bias")[0] +
                     sl_probe_row_param(sb, bias->inputs[row], "slope")[0] * sqrt(1 - cos_theta * cos_theta);
        student[row] = fmin(sum, sl_probe_row_param(sb, bias->inputs[row], "max_bias")[0]);
    }
    CHECK(sl_probe_generic_slip(bias, student, NULL, text, sizeof text) == SL_PROBE_SLIP_OF_FORMULA &&
          strstr(text, "as if it computed sin(theta) in place of tan(theta)"));
    /* the contract's own outputs: no slip */
    for (int row = 0; row < bias->rows; row++) {
        double cos_theta = sl_probe_row_param(sb, bias->inputs[row], "n_dot_l")[0];
        double sum = sl_probe_row_param(sb, bias->inputs[row], "constant_bias")[0] +
                     sl_probe_row_param(sb, bias->inputs[row], "slope")[0] * sqrt(1 - cos_theta * cos_theta) / cos_theta;
        student[row] = fmin(sum, sl_probe_row_param(sb, bias->inputs[row], "max_bias")[0]);
    }
    CHECK(!sl_probe_generic_slip(bias, student, NULL, text, sizeof text));

    /* every formula written for its edits gives the contract's outputs */
    CHECK(sl_probe_generic_formulas_agree(err, sizeof err));
    if (err[0]) fprintf(stderr, "  %s\n", err);
    /* an edit no catalogue lists: the parentheses moved, (constant + slope) * tan(theta) */
    for (int row = 0; row < bias->rows; row++) {
        double cos_theta = sl_probe_row_param(sb, bias->inputs[row], "n_dot_l")[0];
        double sum = (sl_probe_row_param(sb, bias->inputs[row], "constant_bias")[0] +
                      sl_probe_row_param(sb, bias->inputs[row], "slope")[0]) *
                     sqrt(1 - cos_theta * cos_theta) / cos_theta;
        student[row] = fmin(sum, sl_probe_row_param(sb, bias->inputs[row], "max_bias")[0]);
    }
    CHECK(sl_probe_generic_slip(bias, student, NULL, text, sizeof text) == SL_PROBE_SLIP_EDIT &&
          strstr(text, "(constant_bias + slope) * tan_theta") && strstr(text, "the parentheses moved"));
    /* and cot(theta) for tan(theta): the division's operands swapped */
    for (int row = 0; row < bias->rows; row++) {
        double cos_theta = sl_probe_row_param(sb, bias->inputs[row], "n_dot_l")[0];
        double sum = sl_probe_row_param(sb, bias->inputs[row], "constant_bias")[0] +
                     sl_probe_row_param(sb, bias->inputs[row], "slope")[0] * cos_theta / sqrt(1 - cos_theta * cos_theta);
        student[row] = fmin(sum, sl_probe_row_param(sb, bias->inputs[row], "max_bias")[0]);
    }
    CHECK(sl_probe_generic_slip(bias, student, NULL, text, sizeof text) == SL_PROBE_SLIP_EDIT &&
          strstr(text, "tan_theta = n_dot_l / sqrt(1 - n_dot_l * n_dot_l)"));
    if (!strstr(text, "tan_theta = n_dot_l")) fprintf(stderr, "  cot: %s\n", text);

    /* the split scheme's t = i / count divided as integers: every inner split at near */
    write_file("slips_splits.json",
               "{\"name\": \"p\", \"lab\": 6, \"checks\": ["
               " {\"name\": \"splits\", \"kind\": \"probe\", \"points\": 1, \"function\": \"lab6_split_distances\","
               "  \"rows\": [{\"near\": 0.3, \"far\": 300, \"count\": 4, \"lambda\": 0.8}]}]}");
    snprintf(path, sizeof path, "%s/slips_splits.json", tmp_dir);
    static sl_case p;
    CHECK(sl_case_load(&p, path, err, sizeof err));
    CHECK(sl_probe_generic_add(&p, 13) > 0);
    const sl_check *splits = &p.checks[0];
    const sl_probe_function *sf = sl_probe_at(splits->function);
    CHECK(sf && sf->output_count == 5);
    for (int row = 0; sf && row < splits->rows; row++) {
        /* with t = 0 every inner split is the near plane, in both schemes (no scheme written out here: the
         * handout holds this file) */
        double near = sl_probe_row_param(sf, splits->inputs[row], "near")[0];
        double far = sl_probe_row_param(sf, splits->inputs[row], "far")[0];
        int count = (int)sl_probe_row_param(sf, splits->inputs[row], "count")[0];
        for (int i = 0; i < 5; i++) student[row * 5 + i] = i > count ? 0 : i == count ? far : near;
    }
    CHECK(sl_probe_generic_slip(splits, student, NULL, text, sizeof text) == SL_PROBE_SLIP_EDIT &&
          strstr(text, "a division of integers"));
    if (!strstr(text, "a division of integers")) fprintf(stderr, "  splits: %s\n", text);
}

static void test_probe_generic_rows(void) {
    write_file("generic.json",
               "{\"name\": \"g\", \"lab\": 4, \"checks\": ["
               " {\"name\": \"bias\", \"kind\": \"probe\", \"points\": 1, \"function\": \"slope_scaled_bias\","
               "  \"rows\": [{\"n_dot_l\": 1.0, \"constant_bias\": 0.0005, \"slope\": 0.0015, \"max_bias\": 0.01}]},"
               " {\"name\": \"grid\", \"kind\": \"probe\", \"points\": 1, \"function\": \"pcf_grid\","
               "  \"rows\": [{\"shadow_map\": \"step\", \"shadow_coord\": [0.5, 0.5, 0.5, 1], \"bias\": 0.005,"
               "            \"radius\": 1}]},"
               " {\"name\": \"poisson\", \"kind\": \"probe\", \"points\": 1, \"function\": \"pcf_poisson\","
               "  \"rows\": [{\"shadow_map\": \"step\", \"shadow_coord\": [0.5, 0.5, 0.5, 1], \"bias\": 0.005,"
               "            \"radius_texels\": 2, \"pixel\": [3, 4]}]}]}");
    char path[512], err[2048];
    snprintf(path, sizeof path, "%s/generic.json", tmp_dir);
    sl_case written, a, b, c;
    CHECK(sl_case_load(&written, path, err, sizeof err));
    a = b = c = written;
    int added = sl_probe_generic_add(&a, 1);
    sl_probe_generic_add(&b, 1);
    sl_probe_generic_add(&c, 2);
    CHECK(added == 2 * SL_PROBE_GENERIC_ROWS); /* pcf_poisson has no formula here: no generic rows */
    CHECK(a.checks[2].generic_rows == 0 && a.checks[2].rows == 1);
    const sl_check *bias = &a.checks[0], *grid = &a.checks[1];
    CHECK(bias->rows == 1 + SL_PROBE_GENERIC_ROWS && bias->generic_rows == SL_PROBE_GENERIC_ROWS);
    CHECK(memcmp(bias->inputs[0], written.checks[0].inputs[0], sizeof bias->inputs[0]) == 0); /* written row kept */
    CHECK(memcmp(a.checks[0].inputs, b.checks[0].inputs, sizeof a.checks[0].inputs) == 0);   /* same seed */
    CHECK(memcmp(a.checks[0].inputs, c.checks[0].inputs, sizeof a.checks[0].inputs) != 0);   /* another seed */
    CHECK(!sl_probe_generic_expected(bias, 0, (double[16]){0}));                              /* a written row */
    bool clamped = false, unclamped = false;
    for (int row = 1; row < bias->rows; row++) {
        const float *in = bias->inputs[row];
        for (int i = 0; i < 4; i++) CHECK(in[i] > 0); /* every term non-zero */
        CHECK(in[0] < 1);
        double e[16], tan_theta = sqrt(1.0 - (double)in[0] * in[0]) / in[0];
        CHECK(sl_probe_generic_expected(bias, row, e));
        double unclamped_bias = in[1] + in[2] * tan_theta;
        CHECK(fabs(e[0] - fmin(unclamped_bias, in[3])) < 1e-6);
        clamped |= unclamped_bias > in[3];
        unclamped |= unclamped_bias < in[3];
        CHECK(strncmp(bias->about[row], "generic: ", 9) == 0);
    }
    CHECK(clamped && unclamped);
    /* the grid: w never 1, radii 1 to 5 all drawn, results between 0 and 1 */
    uint32_t radii = 0;
    for (int row = 1; row < grid->rows; row++) {
        const float *in = grid->inputs[row];
        CHECK(in[4] != 1.0f && in[4] > 0);
        radii |= 1u << (int)in[6];
        double e[16];
        CHECK(sl_probe_generic_expected(grid, row, e) && e[0] >= 0 && e[0] <= 1);
    }
    CHECK(radii == 0x3eu);
}

static void test_hidden_varies_probe_inputs(void) {
    write_file("vary.json",
               "{\"name\": \"v\", \"lab\": 2, \"checks\": [{\"name\": \"m\", \"kind\": \"probe\", \"points\": 1,"
               " \"function\": \"shadow_compare_manual\","
               " \"vary\": {\"shadow_coord\": {\"add\": [0.1, 0.3, 0.1, 0], \"homogeneous\": true},"
               "          \"bias\": {\"scale\": [0.8, 1.25]}},"
               " \"rows\": [{\"shadow_map\": \"step\", \"shadow_coord\": [0.25, 0.5, 0.5, 1], \"bias\": 0.005},"
               "          {\"shadow_map\": \"step\", \"shadow_coord\": [0.125, 0.25, 0.25, 0.5], \"bias\": 0.005},"
               "          {\"shadow_map\": \"step\", \"shadow_coord\": [0.25, 0.5, 0.252, 1], \"bias\": 0.005,"
               "           \"keep\": [\"shadow_coord\"]}]}]}");
    char path[512], err[2048], note[400];
    snprintf(path, sizeof path, "%s/vary.json", tmp_dir);
    sl_case a, b, written;
    CHECK(sl_case_load(&written, path, err, sizeof err));
    a = written;
    b = written;
    sl_hidden_derive(&a, 3, note, sizeof note);
    CHECK(strcmp(note, "function tables varied") == 0);
    sl_hidden_derive(&b, 1003, note, sizeof note);
    const sl_check *ka = &a.checks[0], *kb = &b.checks[0], *kw = &written.checks[0];
    CHECK(memcmp(ka->inputs, kb->inputs, sizeof ka->inputs) != 0); /* another seed, another table */
    CHECK(memcmp(ka->inputs, kw->inputs, sizeof ka->inputs) != 0);
    /* the homogeneous twin still divides to the same point as row 0 */
    for (int i = 0; i < 3; i++)
        CHECK(fabsf(ka->inputs[1][1 + i] / ka->inputs[1][4] - ka->inputs[0][1 + i]) < 1e-6f);
    CHECK(ka->inputs[1][4] == 0.5f && ka->inputs[0][4] == 1.0f);
    /* one bias for every row, within the scale's range */
    CHECK(ka->inputs[0][5] == ka->inputs[2][5] && ka->inputs[0][5] >= 0.004f && ka->inputs[0][5] <= 0.00625f);
    /* the kept coordinate is as written */
    CHECK(memcmp(&ka->inputs[2][1], &kw->inputs[2][1], 4 * sizeof(float)) == 0);
    /* the same seed, the same table */
    sl_case again = written;
    sl_hidden_derive(&again, 3, note, sizeof note);
    CHECK(memcmp(again.checks[0].inputs, ka->inputs, sizeof ka->inputs) == 0);
}

/* Text as editors write it: a byte-order mark, CRLF and lone CR go; bytes
 * that are not UTF-8 text are found at their offset (RFC 3629's cases). */
static void test_text_normalise_and_check(void) {
    char text[] = "\xef\xbb\xbf#version 330\r\nvoid f();\rint x;\r\n";
    sl_text_fix fix;
    size_t n = sl_text_normalize(text, sizeof text - 1, &fix);
    CHECK(n == strlen("#version 330\nvoid f();\nint x;\n") && memcmp(text, "#version 330\nvoid f();\nint x;\n", n) == 0);
    CHECK(fix.bom_removed && fix.crlf == 2 && fix.lone_cr == 1);
    char plain[] = "int x;\n";
    CHECK(sl_text_normalize(plain, 7, &fix) == 7 && !sl_text_fix_any(&fix));
    sl_text_problems p;
    CHECK(sl_text_check("caf\xc3\xa9 \xe6\x97\xa5 \xf0\x9f\x98\x80\n", 15, &p)); /* 2-, 3- and 4-byte forms */
    static const struct {
        const char *text;
        size_t len;
        long long offset;
    } invalid[] = {
        {"ab\xc0\x80", 4, 2},     /* overlong NUL */
        {"a\xed\xa0\x80", 4, 1}, /* a surrogate */
        {"\xf4\x90\x80\x80", 4, 0}, /* past U+10FFFF */
        {"ok\n\xe2\x82", 5, 3},   /* cut short at the end */
        {"x\x80", 2, 1},           /* a lone continuation byte */
        {"\xff", 1, 0},
    };
    for (size_t i = 0; i < sizeof invalid / sizeof invalid[0]; i++) {
        CHECK(!sl_text_check(invalid[i].text, invalid[i].len, &p) && p.invalid_offset == invalid[i].offset);
    }
    CHECK(!sl_text_check("a\nb\nc\0d", 7, &p) && p.nul_offset == 5 && p.nul_line == 3 && p.invalid_offset < 0);
    CHECK(!sl_text_check("\xff\xfe#\0", 4, &p) && p.utf16);
    char said[400];
    sl_text_check("a\nb\xff", 4, &p);
    sl_text_problems_describe(&p, "pcf.glsl", said, sizeof said);
    CHECK(strstr(said, "pcf.glsl: invalid UTF-8 at byte offset 3 (line 2)") != NULL);
}

/* The reference cache: a hit gives the decoded pixels; an entry that does
 * not parse, is cut short, damaged, group-writable or another uid's is
 * ignored and written anew; a folder others may use is no cache. */
static bool same_pixels(const sl_image *a, const sl_image *b) {
    return a->data && b->data && a->width == b->width && a->height == b->height && a->channels == b->channels &&
           memcmp(a->data, b->data, (size_t)a->width * a->height * a->channels * sizeof(float)) == 0;
}

static void test_reference_cache_trust(void) {
    char exr[512], dir[512], entry[700], why[1400];
    snprintf(exr, sizeof exr, "%s/reference.exr", tmp_dir);
    snprintf(dir, sizeof dir, "%s/cache/references", tmp_dir);
    sl_image source = sl_image_alloc(37, 23, 2);
    for (int i = 0; i < 37 * 23 * 2; i++) source.data[i] = (float)i / 97.0f + 0.125f;
    char err[512] = "";
    CHECK(sl_image_write(exr, &source, err, sizeof err));
    sl_image_free(&source);
    sl_image decoded;
    CHECK(sl_image_read(exr, &decoded, err, sizeof err));
    char hash[65];
    CHECK(sl_sha256_file(exr, hash));
    snprintf(entry, sizeof entry, "%s/%s.slref", dir, hash);

    sl_reference_cache *cache = sl_reference_cache_open(dir, why, sizeof why);
    CHECK(cache != NULL);
    if (!cache) return;
    struct stat st;
    CHECK(stat(dir, &st) == 0 && (st.st_mode & 0777) == 0700);
    sl_image got;
    /* a miss decodes and stores, a hit reads the entry: the decode's pixels both times */
    CHECK(sl_reference_cache_read(cache, exr, hash, &got) && same_pixels(&got, &decoded));
    sl_image_free(&got);
    CHECK(stat(entry, &st) == 0 && st.st_uid == geteuid() && (st.st_mode & 0777) == 0600);
    off_t entry_size = st.st_size;
    CHECK(sl_reference_cache_read(cache, exr, hash, &got) && same_pixels(&got, &decoded));
    sl_image_free(&got);
    sl_reference_cache_counts counts = sl_reference_cache_counts_of(cache);
    CHECK(counts.hits == 1 && counts.stored == 1 && counts.ignored == 0);
    /* bytes that are not the manifest's: not from the cache */
    char other[65];
    memset(other, 'a', 64);
    other[64] = '\0';
    CHECK(!sl_reference_cache_read(cache, exr, other, &got) && got.data == NULL);
    CHECK(!sl_reference_cache_read(cache, exr, "not a hash", &got) && got.data == NULL);

    /* each bad entry is ignored (counted), decoded again and rewritten whole */
    int ignored = 0;
    for (int bad = 0; bad < 5; bad++) {
        if (bad == 0) CHECK(truncate(entry, entry_size / 2) == 0); /* cut short */
        if (bad == 1) CHECK(truncate(entry, 0) == 0);
        if (bad == 2) { /* one pixel changed: the pixels' hash does not fit */
            FILE *f = fopen(entry, "r+b");
            CHECK(f && fseek(f, -4, SEEK_END) == 0 && fwrite("\x00\x00\x80\x7f", 1, 4, f) == 4);
            if (f) fclose(f);
        }
        if (bad == 3) CHECK(chmod(entry, 0620) == 0); /* group-writable */
        if (bad == 4) { /* another uid's: only root can make one */
            if (geteuid() != 0 || chown(entry, 65534, 65534) != 0) {
                printf("note: reference_cache_trust: not root, a foreign-owned entry not tried\n");
                continue;
            }
        }
        ignored++;
        CHECK(sl_reference_cache_read(cache, exr, hash, &got) && same_pixels(&got, &decoded));
        sl_image_free(&got);
        counts = sl_reference_cache_counts_of(cache);
        CHECK(counts.ignored == ignored && counts.stored == 1 + ignored);
        CHECK(stat(entry, &st) == 0 && st.st_size == entry_size && st.st_uid == geteuid() &&
              (st.st_mode & 0777) == 0600);
    }
    /* a hit after all that */
    CHECK(sl_reference_cache_read(cache, exr, hash, &got) && same_pixels(&got, &decoded));
    sl_image_free(&got);
    CHECK(sl_reference_cache_counts_of(cache).hits == 2);
    sl_reference_cache_close(cache);

    /* the folders: others may not write the parent, nor use the cache folder; no link */
    CHECK(chmod(dir, 0750) == 0);
    CHECK(sl_reference_cache_open(dir, why, sizeof why) == NULL && strstr(why, "mode 0750"));
    CHECK(chmod(dir, 0700) == 0);
    char parent[512], link_dir[512];
    snprintf(parent, sizeof parent, "%s/cache", tmp_dir);
    CHECK(chmod(parent, 0777) == 0);
    CHECK(sl_reference_cache_open(dir, why, sizeof why) == NULL && strstr(why, "write"));
    CHECK(chmod(parent, 0700) == 0);
    snprintf(link_dir, sizeof link_dir, "%s/cache/linked", tmp_dir);
    CHECK(symlink("references", link_dir) == 0);
    CHECK(sl_reference_cache_open(link_dir, why, sizeof why) == NULL);
    cache = sl_reference_cache_open(dir, why, sizeof why);
    CHECK(cache != NULL);
    sl_reference_cache_close(cache);

    /* the sweep on opening: a dead writer's temporary file and an entry unread for a year go; a live
     * writer's, a fresh one, the entry in use and a file of another name stay */
    pid_t dead = fork();
    if (dead == 0) _exit(0);
    CHECK(dead > 0 && waitpid(dead, NULL, 0) == dead);
    char dead_temp[800], live_temp[800], fresh_temp[800], old_entry[800], other_file[800];
    snprintf(dead_temp, sizeof dead_temp, "%s/.entry-%ld-0", dir, (long)dead);
    snprintf(live_temp, sizeof live_temp, "%s/.decode-%ld-3.exr", dir, (long)getpid());
    snprintf(fresh_temp, sizeof fresh_temp, "%s/.entry-%ld-1", dir, (long)dead);
    snprintf(old_entry, sizeof old_entry, "%s/%064d.slref", dir, 7);
    snprintf(other_file, sizeof other_file, "%s/notes.txt", dir);
    const char *made[] = {dead_temp, live_temp, fresh_temp, old_entry, other_file};
    for (int i = 0; i < 5; i++) {
        FILE *f = fopen(made[i], "wb");
        CHECK(f && fputs("x", f) >= 0);
        if (f) fclose(f);
        struct timespec when[2] = {{time(NULL) - (i == 2 ? 5 : 400L * 24 * 3600), 0}, {0, 0}};
        when[1] = when[0];
        CHECK(utimensat(AT_FDCWD, made[i], when, 0) == 0);
    }
    struct timespec last_year[2] = {{time(NULL) - 400L * 24 * 3600, 0}, {time(NULL) - 400L * 24 * 3600, 0}};
    CHECK(utimensat(AT_FDCWD, entry, last_year, 0) == 0);
    cache = sl_reference_cache_open(dir, why, sizeof why);
    CHECK(cache != NULL);
    if (cache) {
        /* the entry in use is read once (a hit renews it) before a later grade's sweep */
        CHECK(sl_reference_cache_counts_of(cache).removed == 3); /* dead_temp, old_entry and the year-old entry */
        sl_reference_cache_close(cache);
    }
    CHECK(access(dead_temp, F_OK) != 0 && access(old_entry, F_OK) != 0 && access(entry, F_OK) != 0);
    CHECK(access(live_temp, F_OK) == 0 && access(fresh_temp, F_OK) == 0 && access(other_file, F_OK) == 0);
    /* a hit renews the entry's time: stored again (a miss), made a year old while a grade has the
     * folder open, read (a hit): the next grade's sweep keeps it */
    cache = sl_reference_cache_open(dir, why, sizeof why);
    CHECK(cache && sl_reference_cache_read(cache, exr, hash, &got) && sl_reference_cache_counts_of(cache).stored == 1);
    sl_image_free(&got);
    CHECK(utimensat(AT_FDCWD, entry, last_year, 0) == 0);
    CHECK(cache && sl_reference_cache_read(cache, exr, hash, &got) && sl_reference_cache_counts_of(cache).hits == 1);
    sl_image_free(&got);
    if (cache) sl_reference_cache_close(cache);
    cache = sl_reference_cache_open(dir, why, sizeof why);
    CHECK(cache && sl_reference_cache_counts_of(cache).removed == 0);
    if (cache) sl_reference_cache_close(cache);
    CHECK(stat(entry, &st) == 0 && st.st_mtime > time(NULL) - 3600);
    sl_image_free(&decoded);
}

/* The three --bonus policies on the totals where they differ: a bonus smaller
 * and larger than what was lost, and a full score. */
/* The splitter experiments splice with: every definition by braces, comments, directives, structs,
 * interface blocks and prototypes not taken for one; the splice replaces one definition alone. */
static void test_glsl_function_splitter(void) {
    static const char student[] =
        "#version 330 core\n"
        "#define TAP(o) texture(map, uv + (o)) \\\n   * 1.0\n"
        "layout(std140) uniform Lights { vec4 position; } lights;\n"
        "struct Sample { float depth; };\n"
        "float helper(float x);\n"
        "// float commented(float x) { return x; }\n"
        "/* vec2 blocked() { return vec2(0); } */\n"
        "float helper(float x) { if (x > 0.0) { return x; } return -x; }\n"
        "\n"
        "/* the one to fix */\n"
        "float pcf_grid(sampler2D map, vec2 uv,\n"
        "               int radius)\n"
        "{\n"
        "    return 0.0; // }\n"
        "}\n"
        "void main() { gl_FragDepth = helper(1.0); }\n";
    static const char solution[] =
        "float pcf_grid(sampler2D map, vec2 uv, int radius) { float s = 0.0; { s += 1.0; } return s; }\n";
    sl_glsl_function fs[8], gs[8];
    int n = sl_glsl_functions(student, sizeof student - 1, fs, 8);
    CHECK(n == 3);
    if (n != 3) return;
    CHECK(strcmp(fs[0].name, "helper") == 0 && strcmp(fs[1].name, "pcf_grid") == 0 && strcmp(fs[2].name, "main") == 0);
    CHECK(strncmp(student + fs[0].start, "float helper(float x) {", 23) == 0);
    CHECK(student[fs[0].end - 1] == '}' && student[fs[0].end] == '\n');
    CHECK(strncmp(student + fs[1].start, "float pcf_grid(", 15) == 0); /* its comment is not part of it */
    CHECK(strncmp(student + fs[1].end - 3, "\n}\n", 3) == 0 || strncmp(student + fs[1].end - 2, "\n}", 2) == 0);
    CHECK(sl_glsl_find(fs, n, "pcf_grid", 0) == &fs[1] && sl_glsl_find(fs, n, "pcf_grid", 1) == NULL);
    CHECK(sl_glsl_find(fs, n, "commented", 0) == NULL && sl_glsl_find(fs, n, "blocked", 0) == NULL);
    int m = sl_glsl_functions(solution, sizeof solution - 1, gs, 8);
    CHECK(m == 1);
    if (m != 1) return;
    char *spliced = sl_glsl_splice(student, sizeof student - 1, &fs[1], solution, &gs[0]);
    CHECK(spliced != NULL);
    if (!spliced) return;
    CHECK(strstr(spliced, "return 0.0;") == NULL && strstr(spliced, "s += 1.0;") != NULL);
    CHECK(strstr(spliced, "/* the one to fix */\nfloat pcf_grid(sampler2D map, vec2 uv, int radius) { float s") != NULL);
    CHECK(strstr(spliced, "float helper(float x) { if") != NULL && strstr(spliced, "void main() { gl_FragDepth") != NULL);
    sl_glsl_function again[8];
    CHECK(sl_glsl_functions(spliced, strlen(spliced), again, 8) == 3);
    free(spliced);
    /* a lab's C file: braces in its strings and characters are text */
    static const char c_file[] =
        "static const char *_say = \"{ not a block\";\n"
        "sl_status lab2_light_view(const sl_light *light, mat4 dest) {\n"
        "    char open = '{', quote = '\\'';\n"
        "    printf(\"}\\\"}\");\n"
        "    return SL_OK;\n"
        "}\n";
    n = sl_glsl_functions(c_file, sizeof c_file - 1, fs, 8);
    CHECK(n == 1 && strcmp(fs[0].name, "lab2_light_view") == 0 && c_file[fs[0].end] == '\n' &&
          c_file[fs[0].end + 1] == '\0');
    /* unmatched braces: refused, never half a function */
    CHECK(sl_glsl_functions("float f() { return 1.0;\n", 24, fs, 8) == -1);
    CHECK(sl_glsl_functions("float f() { return 1.0; } }\n", 28, fs, 8) == -1);
}

static void test_bonus_policies(void) {
    CHECK(sl_bonus_total(SL_BONUS_APART, 8, 10, 3) == 8);
    CHECK(sl_bonus_total(SL_BONUS_FILL, 8, 10, 1) == 9);
    CHECK(sl_bonus_total(SL_BONUS_FILL, 8, 10, 3) == 10);
    CHECK(sl_bonus_total(SL_BONUS_FILL, 10, 10, 3) == 10);
    CHECK(sl_bonus_total(SL_BONUS_ADD, 8, 10, 3) == 11);
    CHECK(sl_bonus_total(SL_BONUS_ADD, 10, 10, 3) == 13);
    sl_bonus_policy p = SL_BONUS_APART;
    CHECK(sl_bonus_policy_parse("fill", &p) && p == SL_BONUS_FILL);
    CHECK(sl_bonus_policy_parse("add", &p) && p == SL_BONUS_ADD);
    CHECK(sl_bonus_policy_parse("apart", &p) && p == SL_BONUS_APART);
    CHECK(!sl_bonus_policy_parse("extra", &p) && !sl_bonus_policy_parse("", &p));
    CHECK(strcmp(sl_bonus_policy_name(SL_BONUS_FILL), "fill") == 0);
}

int main(int argc, char **argv) {
    static const struct { const char *name; void (*fn)(void); } tests[] = {
        {"compare_neighbourhood", test_compare_neighbourhood},
        {"compare_depth_patterns", test_compare_depth_patterns},
        {"compare_failing_by_kind", test_compare_failing_by_kind},
        {"diag_angle_slips_and_words", test_diag_angle_slips_and_words},
        {"compare_flicker_and_percent", test_compare_flicker_and_percent},
        {"shader_includes_and_lines", test_shader_includes_and_lines},
        {"shader_missing_include", test_shader_missing_include},
        {"shader_text_as_editors_write_it", test_shader_text_as_editors_write_it},
        {"case_files", test_case_files},
        {"scenes", test_scenes},
        {"meshes", test_meshes},
        {"grade_names_acne", test_grade_names_acne},
        {"grade_diagnosis_ids", test_grade_diagnosis_ids},
        {"grade_names_peter_panning", test_grade_names_peter_panning},
        {"grade_names_vsm_mistakes", test_grade_names_vsm_mistakes},
        {"grade_penumbra_inverted", test_grade_penumbra_inverted},
        {"grade_small_shadow_missing", test_grade_small_shadow_missing},
        {"grade_leads_with_root_cause", test_grade_leads_with_root_cause},
        {"grade_probe_verdicts", test_grade_probe_verdicts},
        {"grade_blames_on_evidence", test_grade_blames_on_evidence},
        {"grade_rules_out_once", test_grade_rules_out_once},
        {"grade_rules_out_only_on_generic_inputs", test_grade_rules_out_only_on_generic_inputs},
        {"camera_differences", test_camera_differences},
        {"probe_slips", test_probe_slips},
        {"probe_generic_rows", test_probe_generic_rows},
        {"grade_compile_error_once", test_grade_compile_error_once},
        {"hidden_varies_probe_inputs", test_hidden_varies_probe_inputs},
        {"grade_run_failures", test_grade_run_failures},
        {"grade_state_needs_evidence", test_grade_state_needs_evidence},
        {"shader_include_stays_inside", test_shader_include_stays_inside},
        {"channel_rejects_lies", test_channel_rejects_lies},
        {"utf8_clean_and_cut", test_utf8_clean_and_cut},
        {"build_error_text", test_build_error_text},
        {"channel_cleans_text", test_channel_cleans_text},
        {"sha256_known_answers", test_sha256_known_answers},
        {"text_normalise_and_check", test_text_normalise_and_check},
        {"reference_cache_trust", test_reference_cache_trust},
        {"bonus_policies", test_bonus_policies},
        {"glsl_function_splitter", test_glsl_function_splitter},
    };
    snprintf(tmp_dir, sizeof tmp_dir, "/tmp/sl_unit_XXXXXX");
    if (!mkdtemp(tmp_dir)) return 2;
    int ran = 0;
    for (size_t i = 0; i < sizeof tests / sizeof tests[0]; i++) {
        if (argc > 1 && strcmp(argv[1], tests[i].name) != 0) continue;
        int before = failures;
        tests[i].fn();
        printf("%s %s\n", failures == before ? "ok  " : "FAIL", tests[i].name);
        ran++;
    }
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmp_dir);
    if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", tmp_dir);
    if (ran == 0) {
        fprintf(stderr, "no test named %s\n", argc > 1 ? argv[1] : "");
        return 2;
    }
    return failures ? 1 : 0;
}
