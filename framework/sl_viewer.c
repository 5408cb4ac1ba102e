#define _POSIX_C_SOURCE 200809L
#include "sl_viewer.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_bench.h"
#include "sl_case_view.h"
#include "sl_context.h"
#include "sl_log.h"
#include "sl_renderer.h"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

typedef struct _sl_viewer {
    sl_context *ctx;
    sl_renderer renderer;
    sl_scene scene;
    sl_render_params params;
    bool dragging;
    double last_x, last_y;
    bool dirty_title;
} _sl_viewer;

/* The headless backends of this build, for messages: "osmesa or egl", "egl". */
static const char *_sl_backend_choices(void) {
    bool osmesa = sl_backend_available(SL_BACKEND_OSMESA), egl = sl_backend_available(SL_BACKEND_EGL);
    return osmesa && egl ? "osmesa or egl" : (osmesa ? "osmesa" : "egl");
}

static void _sl_usage(FILE *f) {
    fprintf(f,
            "usage: shadowlab [options]\n"
            "  --lab N             labs in use: 1 depth map, 2 shadows, 3 bias, 4 filtering, 7 cube maps\n"
            "                      (a point light); default the highest this build has for the scene's light\n"
            "  --scene NAME|FILE   a built-in scene (boxes_on_floor, spot_on_floor, curved_grazing,\n"
            "                      pole_on_floor, thin_caster, long_ground, closed_room) or a scene\n"
            "                      .json; default boxes_on_floor\n"
            "  --size WxH          window size; default 960x640\n"
            "  --map-size N        shadow map size in texels; default 1024 (lab 7: each cube face, 512)\n"
            "  --compare MODE      manual (sampler2D) or hardware (sampler2DShadow)\n"
            "  --bias X            constant depth bias; default 0.005\n"
            "  --bias-mode MODE    lab 3: none, constant, slope, polygon-offset, front-culling,\n"
            "                      normal-offset, midpoint (the extension); default slope\n"
            "  --filter MODE       lab 4: none, hardware, grid, poisson, pcss; default grid\n"
            "  --kernel R          lab 4: grid radius in texels (1 = 3x3); default 1\n"
            "  --poisson-radius R  lab 4: Poisson disk radius in texels; default 2.5\n"
            "  --light-size S      lab 4: the light's size in world units (PCSS)\n"
            "  --visibility        show the visibility term alone (what the grader compares)\n"
            "  --show-map          show the shadow map in a corner (lab 7: the six cube faces as a cross)\n"
            "  --soft              lab 7: the soft lookup (20 directions)\n"
            "  --soft-radius R     lab 7: its disk at the far plane, world units; default 0.35\n"
            "  --cube-bias B       lab 7: the lookup's bias, in distance / far; default 0.004 (0.01 soft)\n"
            "  --cube-pass MODE    lab 7: auto, six or layered (auto: layered where the lab does it)\n"
            "  --frames K          render K frames, then exit (for scripts)\n"
            "  --screenshot FILE   save the last frame as PNG (with --frames)\n"
            "  --headless          render without a window or display, with the default headless\n"
            "                      backend (%s in this build)\n"
            "  --backend NAME      headless backend: %s (implies --headless)\n"
            "  --labs-dir DIR      lab sources to load shaders from; default this build's\n"
            "  --case NAME         render what the grader renders for case NAME (grader/cases/NAME.json),\n"
            "                      beside the reference and their difference (red: a shadow missing,\n"
            "                      blue: one too many); Tab, Space and D switch the view\n"
            "lab 7 keys: 7 lab 7, M the six faces as a cross, S soft/hard, L six passes/layered/auto,\n"
            "      [ ] cube bias, arrows move the point light (x, z), PgUp PgDn (y)\n"
            "keys: 1-4 lab, V visibility, M shadow map, C compare mode (labs 2-3), [ ] bias,\n"
            "      B bias mode (lab 3), F filter (lab 4), - = kernel size or light size (lab 4),\n"
            "      arrows move the light, mouse drag orbit, wheel zoom, Esc quit;\n"
            "      shaders reload when their files change\n",
            sl_backend_name(sl_backend_default_headless()), _sl_backend_choices());
    sl_bench_usage(f);
}

static void _sl_update_title(_sl_viewer *v) {
    GLFWwindow *w = sl_context_window(v->ctx);
    if (!w) return;
    const sl_frame_info *info = sl_renderer_info(&v->renderer);
    char title[512], settings[160];
    const sl_render_params *p = &v->params;
    if (p->lab == 7 && v->scene.light.type == SL_LIGHT_POINT)
        snprintf(settings, sizeof settings, "cube map %d, bias %.4f, %s, %s", p->cube.map_size, p->cube.bias,
                 p->cube.soft ? "soft (20 directions)" : "hard",
                 info->cube_layered ? "one layered pass" : "six passes");
    else if (p->lab <= 2)
        snprintf(settings, sizeof settings, "%s compare, bias %.4f", p->compare == SL_COMPARE_HARDWARE ? "hardware" : "manual",
                 p->bias.constant);
    else
        snprintf(settings, sizeof settings, "bias: %s %.4f%s%s", sl_bias_mode_name(p->bias.mode), p->bias.constant,
                 p->lab >= 4 ? ", filter: " : "", p->lab >= 4 ? sl_filter_mode_name(p->filter.mode) : "");
    if (p->lab >= 4 && p->filter.mode == SL_FILTER_GRID)
        snprintf(settings + strlen(settings), sizeof settings - strlen(settings), " %dx%d", 2 * p->filter.grid_radius + 1,
                 2 * p->filter.grid_radius + 1);
    if (p->lab >= 4 && p->filter.mode == SL_FILTER_POISSON)
        snprintf(settings + strlen(settings), sizeof settings - strlen(settings), " r=%.1f", p->filter.poisson_radius);
    if (p->lab >= 4 && p->filter.mode == SL_FILTER_PCSS)
        snprintf(settings + strlen(settings), sizeof settings - strlen(settings), " light %.2f", v->scene.light.size);
    int n = snprintf(title, sizeof title, "shadowlab — lab %d — %s — %s%s", p->lab, v->scene.name, settings,
                     p->output == SL_OUTPUT_VISIBILITY ? " — visibility" : "");
    if (info->not_implemented_count > 0 && n > 0 && (size_t)n < sizeof title)
        snprintf(title + n, sizeof title - (size_t)n, " — not implemented: %s%s", info->not_implemented[0],
                 info->not_implemented_count > 1 ? ", ..." : "");
    glfwSetWindowTitle(w, title);
}

static void _sl_move_light(sl_light *light, float yaw, float pitch) {
    vec3 d;
    glm_vec3_copy(light->direction, d);
    float y = atan2f(d[0], d[2]) + yaw;
    float p = asinf(glm_clamp(d[1], -1, 1)) + pitch;
    p = glm_clamp(p, glm_rad(-89), glm_rad(-5));
    light->direction[0] = cosf(p) * sinf(y);
    light->direction[1] = sinf(p);
    light->direction[2] = cosf(p) * cosf(y);
}

static void _sl_key(GLFWwindow *w, int key, int scancode, int action, int mods) {
    (void)scancode;
    (void)mods;
    if (action == GLFW_RELEASE) return;
    _sl_viewer *v = glfwGetWindowUserPointer(w);
    switch (key) {
    case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(w, GLFW_TRUE); break;
    case GLFW_KEY_1: v->params.lab = 1; break;
    case GLFW_KEY_2: v->params.lab = 2; break;
    case GLFW_KEY_3: v->params.lab = 3; break;
    case GLFW_KEY_4: v->params.lab = 4; break;
    /* lab 7 */
    case GLFW_KEY_7: v->params.lab = 7; break;
    case GLFW_KEY_S:
        /* soft or hard, each with the bias it needs unless the bias was changed by hand */
        v->params.cube.soft = !v->params.cube.soft;
        if (v->params.cube.soft && v->params.cube.bias == SL_CUBE_HARD_BIAS) v->params.cube.bias = SL_CUBE_SOFT_BIAS;
        else if (!v->params.cube.soft && v->params.cube.bias == SL_CUBE_SOFT_BIAS) v->params.cube.bias = SL_CUBE_HARD_BIAS;
        break;
    case GLFW_KEY_L: v->params.cube.pass = (sl_cube_pass)((v->params.cube.pass + 1) % SL_CUBE_PASS_COUNT); break;
    case GLFW_KEY_PAGE_UP:
    case GLFW_KEY_PAGE_DOWN:
        if (v->scene.light.type == SL_LIGHT_POINT) v->scene.light.position[1] += key == GLFW_KEY_PAGE_UP ? 0.2f : -0.2f;
        break;
    case GLFW_KEY_B: v->params.bias.mode = (sl_bias_mode)((v->params.bias.mode + 1) % SL_BIAS_MODE_COUNT); break;
    case GLFW_KEY_F: v->params.filter.mode = (sl_filter_mode)((v->params.filter.mode + 1) % SL_FILTER_MODE_COUNT); break;
    case GLFW_KEY_EQUAL:
    case GLFW_KEY_MINUS: {
        int step = key == GLFW_KEY_EQUAL ? 1 : -1;
        sl_filter_settings *f = &v->params.filter;
        if (f->mode == SL_FILTER_GRID) f->grid_radius = f->grid_radius + step < 0 ? 0 : f->grid_radius + step;
        else if (f->mode == SL_FILTER_POISSON) f->poisson_radius = glm_clamp(f->poisson_radius * (step > 0 ? 1.25f : 0.8f), 0.5f, 64);
        else if (f->mode == SL_FILTER_PCSS) v->scene.light.size = glm_clamp(v->scene.light.size * (step > 0 ? 1.25f : 0.8f), 0.01f, 10);
        break;
    }
    case GLFW_KEY_V: v->params.output = v->params.output == SL_OUTPUT_SHADED ? SL_OUTPUT_VISIBILITY : SL_OUTPUT_SHADED; break;
    case GLFW_KEY_M: v->params.show_shadow_map = !v->params.show_shadow_map; break;
    case GLFW_KEY_C: v->params.compare = v->params.compare == SL_COMPARE_MANUAL ? SL_COMPARE_HARDWARE : SL_COMPARE_MANUAL; break;
    case GLFW_KEY_LEFT_BRACKET:
    case GLFW_KEY_RIGHT_BRACKET: {
        bool up = key == GLFW_KEY_RIGHT_BRACKET;
        float *bias = v->params.lab == 7 ? &v->params.cube.bias : &v->params.bias.constant;
        *bias = up ? (*bias > 0 ? *bias * 2 : 0.0005f) : *bias * 0.5f;
        break;
    }
    case GLFW_KEY_LEFT:
    case GLFW_KEY_RIGHT:
    case GLFW_KEY_UP:
    case GLFW_KEY_DOWN:
        if (v->scene.light.type == SL_LIGHT_POINT) {
            /* a point light moves in the room (x, z); PgUp/PgDn move it up and down */
            v->scene.light.position[0] += key == GLFW_KEY_LEFT ? -0.2f : key == GLFW_KEY_RIGHT ? 0.2f : 0;
            v->scene.light.position[2] += key == GLFW_KEY_UP ? -0.2f : key == GLFW_KEY_DOWN ? 0.2f : 0;
        } else {
            _sl_move_light(&v->scene.light, key == GLFW_KEY_LEFT ? -0.05f : key == GLFW_KEY_RIGHT ? 0.05f : 0,
                           key == GLFW_KEY_UP ? 0.05f : key == GLFW_KEY_DOWN ? -0.05f : 0);
        }
        break;
    default: return;
    }
    v->dirty_title = true;
}

static void _sl_mouse_button(GLFWwindow *w, int button, int action, int mods) {
    (void)mods;
    _sl_viewer *v = glfwGetWindowUserPointer(w);
    if (button == GLFW_MOUSE_BUTTON_LEFT) {
        v->dragging = action == GLFW_PRESS;
        glfwGetCursorPos(w, &v->last_x, &v->last_y);
    }
}

static void _sl_cursor(GLFWwindow *w, double x, double y) {
    _sl_viewer *v = glfwGetWindowUserPointer(w);
    if (!v->dragging) return;
    sl_camera_orbit(&v->scene.camera, (float)(v->last_x - x) * 0.01f, (float)(y - v->last_y) * 0.01f, 1);
    v->last_x = x;
    v->last_y = y;
}

static void _sl_scroll(GLFWwindow *w, double dx, double dy) {
    (void)dx;
    _sl_viewer *v = glfwGetWindowUserPointer(w);
    sl_camera_orbit(&v->scene.camera, 0, 0, powf(0.9f, (float)dy));
}

int sl_viewer_main(int argc, char **argv) {
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--bench") == 0) return sl_bench_main(argc, argv);
    _sl_viewer v = {0};
    sl_render_params_defaults(&v.params);
    const char *scene_name = "boxes_on_floor", *screenshot = NULL, *labs_dir = NULL, *case_name = NULL;
    int frames = 0, width = 960, height = 640;
    bool headless = false;
    sl_backend backend = sl_backend_default_headless();
    float light_size = -1;
    bool lab_given = false;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *next = i + 1 < argc ? argv[i + 1] : NULL;
        bool takes_value = strcmp(a, "--lab") == 0 || strcmp(a, "--scene") == 0 || strcmp(a, "--size") == 0 ||
                           strcmp(a, "--map-size") == 0 || strcmp(a, "--compare") == 0 ||
                           strcmp(a, "--bias") == 0 || strcmp(a, "--frames") == 0 ||
                           strcmp(a, "--screenshot") == 0 || strcmp(a, "--labs-dir") == 0 ||
                           strcmp(a, "--bias-mode") == 0 || strcmp(a, "--filter") == 0 ||
                           strcmp(a, "--kernel") == 0 || strcmp(a, "--light-size") == 0 ||
                           strcmp(a, "--poisson-radius") == 0 || strcmp(a, "--case") == 0 ||
                           strcmp(a, "--backend") == 0 || strcmp(a, "--cube-pass") == 0 ||
                           strcmp(a, "--soft-radius") == 0 || strcmp(a, "--cube-bias") == 0;
        if (takes_value && !next) {
            fprintf(stderr, "shadowlab: %s needs a value\n", a);
            return 2;
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            _sl_usage(stdout);
            return 0;
        } else if (strcmp(a, "--lab") == 0) {
            v.params.lab = atoi(next);
            lab_given = true;
            if (v.params.lab < 1 || v.params.lab > SL_RENDERER_MAX_LAB || !sl_lab_folder(v.params.lab)) {
                fprintf(stderr, "shadowlab: --lab must be one of this build's labs (1..%d; a lab number whose "
                                "folder is missing is not in this build yet)\n", SL_RENDERER_MAX_LAB);
                return 2;
            }
        } else if (strcmp(a, "--scene") == 0) {
            scene_name = next;
        } else if (strcmp(a, "--size") == 0) {
            if (sscanf(next, "%dx%d", &width, &height) != 2 || width < 16 || height < 16) {
                fprintf(stderr, "shadowlab: --size expects WxH, e.g. 800x600\n");
                return 2;
            }
        } else if (strcmp(a, "--map-size") == 0) {
            v.params.shadow_map_size = atoi(next);
            if (v.params.shadow_map_size < 16 || v.params.shadow_map_size > 8192) {
                fprintf(stderr, "shadowlab: --map-size must be 16..8192\n");
                return 2;
            }
            v.params.cube.map_size = v.params.shadow_map_size < 2048 ? v.params.shadow_map_size : 2048;
        } else if (strcmp(a, "--compare") == 0) {
            if (strcmp(next, "manual") == 0) v.params.compare = SL_COMPARE_MANUAL;
            else if (strcmp(next, "hardware") == 0) v.params.compare = SL_COMPARE_HARDWARE;
            else {
                fprintf(stderr, "shadowlab: --compare is manual or hardware\n");
                return 2;
            }
        } else if (strcmp(a, "--bias") == 0) {
            v.params.bias.constant = (float)atof(next);
        } else if (strcmp(a, "--bias-mode") == 0) {
            if (!sl_bias_mode_parse(next, &v.params.bias.mode)) {
                fprintf(stderr, "shadowlab: --bias-mode is none, constant, slope, polygon-offset, front-culling, "
                                "normal-offset or midpoint\n");
                return 2;
            }
        } else if (strcmp(a, "--filter") == 0) {
            if (!sl_filter_mode_parse(next, &v.params.filter.mode)) {
                fprintf(stderr, "shadowlab: --filter is none, hardware, grid, poisson or pcss\n");
                return 2;
            }
        } else if (strcmp(a, "--kernel") == 0) {
            v.params.filter.grid_radius = atoi(next);
            if (v.params.filter.grid_radius < 0 || v.params.filter.grid_radius > 16) {
                fprintf(stderr, "shadowlab: --kernel is a radius 0..16\n");
                return 2;
            }
        } else if (strcmp(a, "--poisson-radius") == 0) {
            v.params.filter.poisson_radius = (float)atof(next);
            if (v.params.filter.poisson_radius <= 0 || v.params.filter.poisson_radius > 64) {
                fprintf(stderr, "shadowlab: --poisson-radius is 0..64 texels\n");
                return 2;
            }
        } else if (strcmp(a, "--light-size") == 0) {
            light_size = (float)atof(next);
        } else if (strcmp(a, "--frames") == 0) {
            frames = atoi(next);
        } else if (strcmp(a, "--screenshot") == 0) {
            screenshot = next;
        } else if (strcmp(a, "--labs-dir") == 0) {
            labs_dir = next;
        } else if (strcmp(a, "--case") == 0) {
            case_name = next;
        } else if (strcmp(a, "--visibility") == 0) {
            v.params.output = SL_OUTPUT_VISIBILITY;
        } else if (strcmp(a, "--soft") == 0) {
            v.params.cube.soft = true;
            if (v.params.cube.bias == SL_CUBE_HARD_BIAS) v.params.cube.bias = SL_CUBE_SOFT_BIAS;
        } else if (strcmp(a, "--soft-radius") == 0) {
            v.params.cube.soft_radius = (float)atof(next);
            if (!(v.params.cube.soft_radius >= 0 && v.params.cube.soft_radius <= 100)) {
                fprintf(stderr, "shadowlab: --soft-radius is 0..100 world units\n");
                return 2;
            }
        } else if (strcmp(a, "--cube-bias") == 0) {
            v.params.cube.bias = (float)atof(next);
            if (!(v.params.cube.bias >= 0 && v.params.cube.bias <= 1)) {
                fprintf(stderr, "shadowlab: --cube-bias is 0..1 (distance / far)\n");
                return 2;
            }
        } else if (strcmp(a, "--cube-pass") == 0) {
            if (!sl_cube_pass_parse(next, &v.params.cube.pass)) {
                fprintf(stderr, "shadowlab: --cube-pass is auto, six or layered\n");
                return 2;
            }
        } else if (strcmp(a, "--show-map") == 0) {
            v.params.show_shadow_map = true;
        } else if (strcmp(a, "--headless") == 0) {
            headless = true;
        } else if (strcmp(a, "--backend") == 0) {
            if (!sl_backend_parse(next, &backend) || !sl_backend_available(backend)) {
                fprintf(stderr, "shadowlab: --backend is %s in this build\n", _sl_backend_choices());
                return 2;
            }
            headless = true;
        } else {
            fprintf(stderr, "shadowlab: unknown option %s\n", a);
            _sl_usage(stderr);
            return 2;
        }
        if (takes_value) i++;
    }
    if ((screenshot || case_name) && headless && frames <= 0) frames = 1;
    if (screenshot && frames <= 0) frames = 3;
    if (headless && frames <= 0) {
        fprintf(stderr, "shadowlab: --headless needs --frames K (and usually --screenshot FILE)\n");
        return 2;
    }

    if (case_name) {
        sl_case_view_desc cv = {.case_name = case_name, .labs_dir = labs_dir, .headless = headless,
                                .backend = backend, .frames = frames, .screenshot = screenshot};
        return sl_case_view_main(&cv);
    }
    char err[16384];
    if (!sl_scene_load(&v.scene, scene_name, err, sizeof err)) {
        fprintf(stderr, "shadowlab: %s\n", err);
        return 1;
    }
    if (light_size > 0) v.scene.light.size = light_size;
    if (!lab_given) {
        /* the highest lab for the scene's light: lab 7 casts from a point light, the others from a sun or a spot */
        v.params.lab = v.scene.light.type == SL_LIGHT_POINT && sl_lab_folder(7) ? 7 : 4;
        while (v.params.lab > 1 && !sl_lab_folder(v.params.lab)) v.params.lab--;
    }
    sl_context_desc cd = {
        .backend = headless ? backend : SL_BACKEND_GLFW,
        .width = width,
        .height = height,
        .title = "shadowlab",
        .resizable = true,
    };
    v.ctx = sl_context_create(&cd, err, sizeof err);
    if (!v.ctx) {
        fprintf(stderr, "shadowlab: %s\n", err);
        return 1;
    }
    sl_renderer_desc rd = {.labs_dir = labs_dir};
    if (!sl_renderer_init(&v.renderer, &rd, err, sizeof err) ||
        !sl_renderer_set_scene(&v.renderer, &v.scene, err, sizeof err)) {
        fprintf(stderr, "shadowlab: %s\n", err);
        sl_context_destroy(v.ctx);
        return 1;
    }
    printf("shadowlab: %s through %s, %s labs from %s\n", sl_context_renderer_name(), sl_backend_name(sl_context_backend(v.ctx)),
           sl_build_labs_kind, v.renderer.labs_dir);
    /* 0 would do too (the EGL backend binds its own for it); the name says what is meant. */
    GLuint target = sl_context_default_framebuffer(v.ctx);

    GLFWwindow *window = sl_context_window(v.ctx);
    if (window) {
        glfwSetWindowUserPointer(window, &v);
        glfwSetKeyCallback(window, _sl_key);
        glfwSetMouseButtonCallback(window, _sl_mouse_button);
        glfwSetCursorPosCallback(window, _sl_cursor);
        glfwSetScrollCallback(window, _sl_scroll);
    }
    int rendered = 0;
    double last_reload_check = 0;
    char reported_missing[512] = "-";
    const char *reported_shader_error = NULL;
    int status = 0;
    v.dirty_title = true;
    while (!sl_context_should_close(v.ctx)) {
        double now = window ? glfwGetTime() : 0;
        if (window && now - last_reload_check > 0.25) {
            last_reload_check = now;
            bool reloaded = false;
            if (!sl_renderer_reload_changed(&v.renderer, &reloaded, err, sizeof err))
                fprintf(stderr, "shadowlab: shader reload failed, keeping the previous version:\n%s\n", err);
            else if (reloaded)
                printf("shadowlab: shaders reloaded\n");
        }
        int fw, fh;
        sl_context_framebuffer_size(v.ctx, &fw, &fh);
        sl_renderer_draw(&v.renderer, &v.scene, &v.params, target, fw, fh);
        const sl_frame_info *info = sl_renderer_info(&v.renderer);
        if (info->shader_error != reported_shader_error) {
            reported_shader_error = info->shader_error;
            if (info->shader_error)
                fprintf(stderr, "shadowlab: lab %d's shaders do not compile, so it is switched off until you fix "
                                "them (they reload when saved):\n%s\n", info->shader_error_lab, info->shader_error);
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
            _sl_update_title(&v);
            v.dirty_title = false;
        }
        rendered++;
        if (frames > 0 && rendered >= frames) {
            if (screenshot) {
                sl_image shot;
                glFinish();
                if (!sl_capture_framebuffer(target, fw, fh, 3, &shot) || !sl_image_write(screenshot, &shot, err, sizeof err)) {
                    fprintf(stderr, "shadowlab: cannot save the screenshot: %s\n", err);
                    status = 1;
                } else {
                    printf("shadowlab: saved %s (%dx%d)\n", screenshot, fw, fh);
                }
                sl_image_free(&shot);
            }
            break;
        }
        sl_context_end_frame(v.ctx);
    }
    sl_renderer_destroy(&v.renderer);
    sl_context_destroy(v.ctx);
    return status;
}
