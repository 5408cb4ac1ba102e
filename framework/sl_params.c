#include "sl_params.h"

#include "sl_lab_dependencies.h" /* generated from lab_dependencies.cmake */

#include <string.h>

void sl_render_params_defaults(sl_render_params *p) {
    *p = (sl_render_params){
        .lab = 4, /* labs 1-4 build on each other; 5 (VSM) and 6 (cascades) are techniques of their own (--lab N) */
        .shadow_map_size = 1024,
        .compare = SL_COMPARE_MANUAL,
        .bias = {
            .mode = SL_BIAS_SLOPE_SCALED,
            .constant = 0.005f,
            .slope = 0.003f,
            .max_bias = 0.03f,
            .polygon_offset_factor = 2.0f,
            .polygon_offset_units = 4.0f,
            .normal_offset = 1.5f,
        },
        .filter = {.mode = SL_FILTER_GRID, .grid_radius = 1, .poisson_radius = 2.5f},
        /* 512: filtered moments need fewer texels than a depth map for the same softness, and
         * the blur costs per texel (labs/lab5_vsm/README.md, "Performance") */
        .vsm = {.blur_radius = 2, .min_variance = 0.00002f, .bleeding = 0.3f, .map_size = 512},
        .output = SL_OUTPUT_SHADED,
        .cascades = {.count = 4, .lambda = 0.8f, .max_distance = 0, .caster_margin = 40.0f},
        .cube = {.map_size = 512, .bias = SL_CUBE_HARD_BIAS, .soft = false, .soft_radius = 0.35f,
                 .pass = SL_CUBE_PASS_AUTO},
    };
}

static const char *const _sl_bias_names[SL_BIAS_MODE_COUNT] = {
    "none", "constant", "slope", "polygon-offset", "front-culling", "normal-offset", "midpoint",
};
static const char *const _sl_filter_names[SL_FILTER_MODE_COUNT] = {"none", "hardware", "grid", "poisson", "pcss"};

static bool _sl_find_name(const char *const *names, int count, const char *name, int *index) {
    for (int i = 0; i < count; i++)
        if (strcmp(name, names[i]) == 0) {
            *index = i;
            return true;
        }
    return false;
}

const char *sl_bias_mode_name(sl_bias_mode mode) {
    return (unsigned)mode < SL_BIAS_MODE_COUNT ? _sl_bias_names[mode] : "?";
}

bool sl_bias_mode_parse(const char *name, sl_bias_mode *mode) {
    int i;
    if (!_sl_find_name(_sl_bias_names, SL_BIAS_MODE_COUNT, name, &i)) return false;
    *mode = (sl_bias_mode)i;
    return true;
}

const char *sl_filter_mode_name(sl_filter_mode mode) {
    return (unsigned)mode < SL_FILTER_MODE_COUNT ? _sl_filter_names[mode] : "?";
}

bool sl_filter_mode_parse(const char *name, sl_filter_mode *mode) {
    int i;
    if (!_sl_find_name(_sl_filter_names, SL_FILTER_MODE_COUNT, name, &i)) return false;
    *mode = (sl_filter_mode)i;
    return true;
}

const char *sl_lab_folder(int lab) {
    static const char *const folders[SL_LAB_COUNT + 1] = {NULL, "lab1_depth_fbo", "lab2_projective", "lab3_bias",
                                                          "lab4_pcf", "lab5_vsm", "lab6_cascades", "lab7_cube"};
    return lab >= 1 && lab <= SL_LAB_COUNT ? folders[lab] : NULL;
}

const char *sl_lab_title(int lab) {
    static const char *const titles[SL_LAB_MAX + 1] = {"",
                                                       "depth FBO",
                                                       "projective lookup",
                                                       "bias & culling",
                                                       "PCF & PCSS",
                                                       "variance shadow maps",
                                                       "cascaded shadow maps",
                                                       "cube-map shadows"};
    return lab >= 1 && lab <= SL_LAB_MAX ? titles[lab] : "?";
}

const float sl_cascade_colours[SL_MAX_CASCADES][3] = {
    {1.0f, 0.35f, 0.3f}, {0.35f, 1.0f, 0.35f}, {0.35f, 0.5f, 1.0f}, {1.0f, 0.9f, 0.3f}};

const char *sl_cascade_colour(int cascade, float rgb[3]) {
    static const float none[3] = {0.3f, 0.3f, 0.3f};
    static const char *const names[SL_MAX_CASCADES + 1] = {"red", "green", "blue", "yellow", "grey"};
    bool in_range = cascade >= 0 && cascade < SL_MAX_CASCADES;
    for (int c = 0; c < 3; c++) rgb[c] = in_range ? sl_cascade_colours[cascade][c] : none[c];
    return names[in_range ? cascade : SL_MAX_CASCADES];
}

static const char *const _sl_cube_pass_names[SL_CUBE_PASS_COUNT] = {"auto", "six", "layered"};

const char *sl_cube_pass_name(sl_cube_pass pass) {
    return (unsigned)pass < SL_CUBE_PASS_COUNT ? _sl_cube_pass_names[pass] : "?";
}

bool sl_cube_pass_parse(const char *name, sl_cube_pass *pass) {
    int i;
    if (!_sl_find_name(_sl_cube_pass_names, SL_CUBE_PASS_COUNT, name, &i)) return false;
    *pass = (sl_cube_pass)i;
    return true;
}

static const char *const _sl_cube_face_names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};

const char *sl_cube_face_name(int face) { return face >= 0 && face < 6 ? _sl_cube_face_names[face] : "?"; }

int sl_cube_face_parse(const char *name) {
    int i;
    return _sl_find_name(_sl_cube_face_names, 6, name, &i) ? i : -1;
}

bool sl_lab_builds_on(int lab, int earlier) {
    static const unsigned masks[] = SL_LAB_BUILDS_ON_MASKS;
    if (lab < 1 || lab >= (int)(sizeof masks / sizeof masks[0]) || earlier < 1 || earlier >= lab) return false;
    return (masks[lab] >> earlier) & 1u;
}

bool sl_lab_shows(int lab, int earlier) {
    static const unsigned masks[] = SL_LAB_SHOWS_MASKS;
    if (lab < 1 || lab >= (int)(sizeof masks / sizeof masks[0]) || earlier < 1 || earlier >= lab) return false;
    return (masks[lab] >> earlier) & 1u;
}

bool sl_lab_given_light_camera(int lab) {
    static const bool given[SL_LAB_MAX + 1] = {[1] = true};
    return lab >= 0 && lab <= SL_LAB_MAX && given[lab];
}
