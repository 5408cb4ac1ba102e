#define _POSIX_C_SOURCE 200809L
#include "sl_viewer_options.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "sl_bench.h"
#include "sl_viewer_capture.h"
#include "sl_viewer_keys.h"
#include "sl_viewer_split.h"

/* The offscreen backends of this build, for messages: "osmesa, egl or window". */
static const char *_sl_backend_choices(void) { return sl_backend_choices(); }

static void _sl_viewer_usage(FILE *f) {
    fprintf(f,
            "usage: shadowlab [options]\n"
            "  --lab N             labs in use: 1 depth map, 2 shadows, 3 bias, 4 filtering, 5 VSM,\n"
            "                      6 cascades, 7 cube maps (a point light); default 7 for a point light, else 4\n"
            "  --scene NAME|FILE   a built-in scene (boxes_on_floor, spot_on_floor, curved_grazing,\n"
            "                      pole_on_floor, thin_caster, long_ground, cascade_field, closed_room,\n"
            "                      stacked_occluders) or a scene\n"
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
            "  --blur R            lab 5: blur radius of the moments in texels; default 2\n"
            "  --bleeding A        lab 5: light-bleeding reduction amount 0..0.99; default 0.3\n"
            "  --min-variance V    lab 5: minimum variance; default 2e-5\n"
            "  --moments-size N    lab 5: the moments maps' size; default 512, 0: --map-size's\n"
            "  --pcf               lab 5: lab 4's filter instead of VSM (key P)\n"
            "  --cascades N        lab 6: cascades, 1..4; default 4\n"
            "  --lambda X          lab 6: the split scheme's weight, 0 uniform .. 1 logarithmic; default 0.8\n"
            "  --show-cascades     lab 6: tint each pixel by the cascade it uses\n"
            "  --blend-band X      lab 6 (bonus): blend the last fraction X of each cascade with the next\n"
            "  --freeze            lab 6: freeze the camera's frustum and look at it, its slices and\n"
            "                      their light boxes from above\n"
            "  --no-snap           lab 6: undo texel snapping (each light box recentred on its sphere): the\n"
            "                      shimmer that snapping removes (key T)\n"
            "  --camera-path PATH  the camera moves back and forth by itself: slide (%.2f m each way) or\n"
            "                      turn (%.0f degrees each way); one period is %.0f s, or --frames K frames\n"
            "  --path-fits-cascades lab 6: the path moves only the camera the cascades are fitted to; the\n"
            "                      picture stays, so what changes is what the shadows do\n"
            "  --mark-changes      with --frames K and --screenshot FILE.png: the first frame, with every\n"
            "                      pixel a later frame changed painted red (shimmer, on paper)\n"
            "  --visibility        show the visibility term alone (what the grader compares)\n"
            "  --show-map          show the shadow map in a corner (lab 7: the six cube faces as a cross)\n"
            "  --soft              lab 7: the soft lookup (20 directions)\n"
            "  --soft-radius R     lab 7: its disk at the far plane, world units; default 0.35\n"
            "  --cube-bias B       lab 7: the lookup's bias, in distance / far; default 0.004 (0.01 soft)\n"
            "  --cube-pass MODE    lab 7: auto, six or layered (auto: layered where the lab does it)\n"
            "  --frames K          render K frames, then exit (for scripts)\n"
            "  --screenshot FILE   save the last frame as PNG (with --frames); FILE.gif: every frame, as\n"
            "                      an animated GIF (10 frames a second, looping)\n"
            "  --headless          render offscreen, with the default headless backend (%s in\n"
            "                      this build)\n"
            "  --backend NAME      offscreen backend: %s (implies --headless; window: a\n"
            "                      hidden window, where there is a display but no headless GL)\n"
            "  --labs-dir DIR      lab sources to load shaders from; default this build's\n"
            "  --overlay           draw the on-screen text (lab, parameters, pass times); the default in a\n"
            "                      window without --frames\n"
            "  --no-overlay        no on-screen text; the default with --frames (screenshots, figures)\n"
            "  --caption TEXT      a line of text at the bottom of the picture, with or without the\n"
            "                      overlay (labels for slide figures)\n"
            "  --text-scale N      the overlay's and caption's font pixel size (1-8); default from the\n"
            "                      frame's size: 1, 2 from 800x480 up, 3 from 1600x1000 up\n"
            "  --frame-dir DIR     save every frame as DIR/001.png, 002.png ... (with --frames: an animation)\n"
            "  --batch FILE        run each line of FILE (FILE -: standard input) as a headless run's options,\n"
            "                      quoted as in a shell, one after another in this process (figures:\n"
            "                      the image module loads once); no other options with it. Around each\n"
            "                      run it prints 'shadowlab: batch line N' (stdout and stderr) and\n"
            "                      'shadowlab: batch line N: exit S' (stdout); exit 1 if any failed\n"
            "  --serve PORT        render offscreen and show the viewer in a browser at the URL it prints,\n"
            "                      http://127.0.0.1:PORT/?token=... (keys, drags and the wheel work there);\n"
            "                      only that URL connects (its random token), not another site's page\n"
            "  --serve-address A   the address --serve listens on; default 127.0.0.1 (this machine\n"
            "                      only; 0.0.0.0: every network this machine is on, still with the token)\n"
            "  --screenshot-dir DIR where X saves shadowlab-NNN.png (made if missing); default the current\n"
            "                      folder, with --serve shadowlab-screenshots\n"
            "  --keys KEYS         press these keys before the first frame, e.g. --keys 'OG' (overlay,\n"
            "                      frustum) or --keys 'BB]' (letters, digits, [ ] - = , .; not Esc)\n"
            "  --frustum           draw the light's frustum in the scene\n"
            "  --animate           turn the light around the scene (with --frames: a fixed step per frame)\n"
            "  --solutions         start with the solutions' code (builds that have solutions/: key U)\n"
            "  --lecture           for a lecture hall: the overlay as one line of TrueType text sized from\n"
            "                      the window (lab, technique, the setting just changed, frame time), its\n"
            "                      panels and labels on key I; the frustum thin and translucent; on in\n"
            "                      --headless screenshots too (--no-overlay leaves it out)\n"
            "  --font FILE         the TrueType font of --lecture's text; default DejaVu Sans (Debian:\n"
            "                      fonts-dejavu-core); a font that cannot be read: the bitmap font, said once\n"
            "  --labels            label what is drawn, with or without the overlay: a legend for the\n"
            "                      cascade colours (lab 6), the cube faces in the cross (lab 7), a marker at\n"
            "                      a spot or point light\n"
            "  --list-keys         print every key as LAB<tab>KEYS<tab>WHAT (LAB: all, 5-7, or case) and exit\n"
            "  --case NAME         render what the grader renders for case NAME (grader/cases/NAME.json),\n"
            "                      beside the reference and their difference (red: a shadow missing,\n"
            "                      blue: one too many), each labelled, with the check's criterion; depth\n"
            "                      and distance images stretched to their own range (printed)\n"
            "  --check NAME        with --case: the check to show first (as the case file names it)\n",
            (double)_SL_PATH_SLIDE_METRES, (double)_SL_PATH_TURN_DEGREES, _SL_PATH_SECONDS, sl_backend_name(sl_backend_default_headless()), _sl_backend_choices());
    _sl_viewer_split_usage(f);
    _sl_viewer_print_keys(f);
    sl_bench_usage(f);
}

int _sl_viewer_options_parse(int argc, char **argv, _sl_viewer *v, _sl_viewer_options *o) {
    *o = (_sl_viewer_options){.scene_name = "boxes_on_floor", .width = 960, .height = 640,
                              .backend = sl_backend_default_headless(), .light_size = -1, .overlay_option = -1};
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
                           strcmp(a, "--camera-path") == 0 || strcmp(a, "--check") == 0 ||
                           strcmp(a, "--backend") == 0 || strcmp(a, "--blur") == 0 ||
                           strcmp(a, "--bleeding") == 0 || strcmp(a, "--min-variance") == 0 ||
                           strcmp(a, "--moments-size") == 0 ||
                           strcmp(a, "--cascades") == 0 || strcmp(a, "--lambda") == 0 || strcmp(a, "--blend-band") == 0 ||
                           strcmp(a, "--caption") == 0 || strcmp(a, "--frame-dir") == 0 || strcmp(a, "--keys") == 0 ||
                           strcmp(a, "--text-scale") == 0 || strcmp(a, "--serve") == 0 || strcmp(a, "--serve-address") == 0 ||
                           strcmp(a, "--screenshot-dir") == 0 || strcmp(a, "--font") == 0 ||
                           strcmp(a, "--cube-pass") == 0 || strcmp(a, "--soft-radius") == 0 || strcmp(a, "--cube-bias") == 0 ||
                           strcmp(a, "--split") == 0;
        if (takes_value && !next) {
            fprintf(stderr, "shadowlab: %s needs a value\n", a);
            return 2;
        }
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            _sl_viewer_usage(stdout);
            return 0;
        } else if (strcmp(a, "--list-keys") == 0) {
            _sl_viewer_list_keys(stdout);
            return 0;
        } else if (strcmp(a, "--lecture") == 0) {
            v->lecture = true;
        } else if (strcmp(a, "--font") == 0) {
            v->font = next;
        } else if (strcmp(a, "--labels") == 0) {
            v->labels = true;
        } else if (strcmp(a, "--lab") == 0) {
            v->params.lab = atoi(next);
            o->lab_given = true;
            if (v->params.lab < 1 || v->params.lab > SL_RENDERER_MAX_LAB || !sl_lab_folder(v->params.lab)) {
                fprintf(stderr, "shadowlab: --lab must be one of this build's labs (1..%d; a lab number whose "
                                "folder is missing is not in this build yet)\n", SL_RENDERER_MAX_LAB);
                return 2;
            }
        } else if (strcmp(a, "--scene") == 0) {
            o->scene_name = next;
        } else if (strcmp(a, "--size") == 0) {
            if (sscanf(next, "%dx%d", &o->width, &o->height) != 2 || o->width < 16 || o->height < 16) {
                fprintf(stderr, "shadowlab: --size expects WxH, e.g. 800x600\n");
                return 2;
            }
        } else if (strcmp(a, "--map-size") == 0) {
            v->params.shadow_map_size = atoi(next);
            if (v->params.shadow_map_size < 16 || v->params.shadow_map_size > 8192) {
                fprintf(stderr, "shadowlab: --map-size must be 16..8192\n");
                return 2;
            }
            v->params.cube.map_size = v->params.shadow_map_size < 2048 ? v->params.shadow_map_size : 2048;
        } else if (strcmp(a, "--compare") == 0) {
            if (strcmp(next, "manual") == 0) v->params.compare = SL_COMPARE_MANUAL;
            else if (strcmp(next, "hardware") == 0) v->params.compare = SL_COMPARE_HARDWARE;
            else {
                fprintf(stderr, "shadowlab: --compare is manual or hardware\n");
                return 2;
            }
        } else if (strcmp(a, "--bias") == 0) {
            v->params.bias.constant = (float)atof(next);
        } else if (strcmp(a, "--bias-mode") == 0) {
            if (!sl_bias_mode_parse(next, &v->params.bias.mode)) {
                fprintf(stderr, "shadowlab: --bias-mode is none, constant, slope, polygon-offset, front-culling, "
                                "normal-offset or midpoint\n");
                return 2;
            }
        } else if (strcmp(a, "--filter") == 0) {
            if (!sl_filter_mode_parse(next, &v->params.filter.mode)) {
                fprintf(stderr, "shadowlab: --filter is none, hardware, grid, poisson or pcss\n");
                return 2;
            }
        } else if (strcmp(a, "--kernel") == 0) {
            v->params.filter.grid_radius = atoi(next);
            if (v->params.filter.grid_radius < 0 || v->params.filter.grid_radius > 16) {
                fprintf(stderr, "shadowlab: --kernel is a radius 0..16\n");
                return 2;
            }
        } else if (strcmp(a, "--poisson-radius") == 0) {
            v->params.filter.poisson_radius = (float)atof(next);
            if (v->params.filter.poisson_radius <= 0 || v->params.filter.poisson_radius > 64) {
                fprintf(stderr, "shadowlab: --poisson-radius is 0..64 texels\n");
                return 2;
            }
        } else if (strcmp(a, "--blur") == 0) { /* lab 5 */
            v->params.vsm.blur_radius = atoi(next);
            if (v->params.vsm.blur_radius < 0 || v->params.vsm.blur_radius > 32) {
                fprintf(stderr, "shadowlab: --blur is a radius 0..32 texels\n");
                return 2;
            }
        } else if (strcmp(a, "--bleeding") == 0) {
            v->params.vsm.bleeding = (float)atof(next);
            if (v->params.vsm.bleeding < 0 || v->params.vsm.bleeding > 0.99f) {
                fprintf(stderr, "shadowlab: --bleeding is an amount 0..0.99\n");
                return 2;
            }
        } else if (strcmp(a, "--min-variance") == 0) {
            v->params.vsm.min_variance = (float)atof(next);
        } else if (strcmp(a, "--moments-size") == 0) {
            v->params.vsm.map_size = atoi(next);
            if (v->params.vsm.map_size != 0 && (v->params.vsm.map_size < 16 || v->params.vsm.map_size > 8192)) {
                fprintf(stderr, "shadowlab: --moments-size must be 16..8192, or 0 for the shadow map's size\n");
                return 2;
            }
        } else if (strcmp(a, "--pcf") == 0) {
            v->params.vsm_off = true;
        } else if (strcmp(a, "--light-size") == 0) {
            o->light_size = (float)atof(next);
        } else if (strcmp(a, "--frames") == 0) {
            o->frames = atoi(next);
        } else if (strcmp(a, "--screenshot") == 0) {
            o->screenshot = next;
        } else if (strcmp(a, "--labs-dir") == 0) {
            o->labs_dir = next;
        } else if (strcmp(a, "--case") == 0) {
            o->case_name = next;
        } else if (strcmp(a, "--check") == 0) {
            o->check_name = next;
        } else if (strcmp(a, "--cascades") == 0) { /* lab 6 */
            v->params.cascades.count = atoi(next);
            if (v->params.cascades.count < 1 || v->params.cascades.count > SL_MAX_CASCADES) {
                fprintf(stderr, "shadowlab: --cascades is 1..%d\n", SL_MAX_CASCADES);
                return 2;
            }
        } else if (strcmp(a, "--lambda") == 0) {
            v->params.cascades.lambda = (float)atof(next);
            if (v->params.cascades.lambda < 0 || v->params.cascades.lambda > 1) {
                fprintf(stderr, "shadowlab: --lambda is 0..1\n");
                return 2;
            }
        } else if (strcmp(a, "--blend-band") == 0) {
            v->params.cascades.blend_band = (float)atof(next);
            if (v->params.cascades.blend_band < 0 || v->params.cascades.blend_band > 1) {
                fprintf(stderr, "shadowlab: --blend-band is 0..1\n");
                return 2;
            }
        } else if (strcmp(a, "--show-cascades") == 0) {
            v->params.cascades.show_cascades = true;
        } else if (strcmp(a, "--freeze") == 0) {
            o->freeze = true;
        } else if (strcmp(a, "--mark-changes") == 0) {
            v->mark_changes = true;
        } else if (strcmp(a, "--path-fits-cascades") == 0) {
            v->path_fit_only = true;
        } else if (strcmp(a, "--no-snap") == 0) {
            v->params.cascades.unsnapped = true;
        } else if (strcmp(a, "--camera-path") == 0) {
            v->camera_path = _SL_PATH_NONE;
            for (int k = 1; k < 3; k++)
                if (strcmp(next, _sl_viewer_path_name(k)) == 0) v->camera_path = k;
            if (v->camera_path == _SL_PATH_NONE) {
                fprintf(stderr, "shadowlab: --camera-path is slide or turn\n");
                return 2;
            }
        } else if (strcmp(a, "--visibility") == 0) {
            v->params.output = SL_OUTPUT_VISIBILITY;
        } else if (strcmp(a, "--overlay") == 0 || strcmp(a, "--no-overlay") == 0) {
            o->overlay_option = strcmp(a, "--overlay") == 0;
        } else if (strcmp(a, "--text-scale") == 0) {
            v->text_scale = atoi(next);
            if (v->text_scale < 1 || v->text_scale > 8) {
                fprintf(stderr, "shadowlab: --text-scale is 1..8\n");
                return 2;
            }
        } else if (strcmp(a, "--keys") == 0) {
            for (const char *k = next; *k; k++)
                if (!strchr("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789[]-=,.", *k)) {
                    fprintf(stderr, "shadowlab: --keys takes letters, digits and [ ] - = , ., not '%c'\n", *k);
                    return 2;
                }
            v->keys = next;
        } else if (strcmp(a, "--frame-dir") == 0) {
            v->frame_dir = next;
        } else if (strcmp(a, "--caption") == 0) {
            v->caption = next;
        } else if (strcmp(a, "--frustum") == 0) {
            v->show_frustum = true;
        } else if (strcmp(a, "--animate") == 0) {
            v->animate_light = true;
        } else if (strcmp(a, "--solutions") == 0) {
            if (!v->second_functions) {
                fprintf(stderr, "shadowlab: --solutions: this build has no solutions beside its labs (a student "
                                "handout, or a build of the solutions themselves)\n");
                return 2;
            }
            v->show_second = true;
        } else if (strcmp(a, "--soft") == 0) {
            v->params.cube.soft = true;
            if (v->params.cube.bias == SL_CUBE_HARD_BIAS) v->params.cube.bias = SL_CUBE_SOFT_BIAS;
        } else if (strcmp(a, "--soft-radius") == 0) {
            v->params.cube.soft_radius = (float)atof(next);
            if (!(v->params.cube.soft_radius >= 0 && v->params.cube.soft_radius <= 100)) {
                fprintf(stderr, "shadowlab: --soft-radius is 0..100 world units\n");
                return 2;
            }
        } else if (strcmp(a, "--cube-bias") == 0) {
            v->params.cube.bias = (float)atof(next);
            if (!(v->params.cube.bias >= 0 && v->params.cube.bias <= 1)) {
                fprintf(stderr, "shadowlab: --cube-bias is 0..1 (distance / far)\n");
                return 2;
            }
        } else if (strcmp(a, "--cube-pass") == 0) {
            if (!sl_cube_pass_parse(next, &v->params.cube.pass)) {
                fprintf(stderr, "shadowlab: --cube-pass is auto, six or layered\n");
                return 2;
            }
        } else if (strcmp(a, "--split") == 0) {
            if (!_sl_viewer_split_parse(v, next)) return 2;
        } else if (strcmp(a, "--show-map") == 0) {
            v->params.show_shadow_map = true;
        } else if (strcmp(a, "--serve") == 0) {
            char *end = NULL;
            o->serve_port = (int)strtol(next, &end, 10);
            if (!end || *end || o->serve_port < 1 || o->serve_port > 65535) {
                fprintf(stderr, "shadowlab: --serve takes a port, 1..65535\n");
                return 2;
            }
        } else if (strcmp(a, "--serve-address") == 0) {
            o->serve_address = next;
        } else if (strcmp(a, "--screenshot-dir") == 0) {
            v->screenshot_dir = next;
        } else if (strcmp(a, "--headless") == 0) {
            o->headless = true;
        } else if (strcmp(a, "--backend") == 0) {
            if (!sl_backend_parse(next, &o->backend) || !sl_backend_available(o->backend)) {
                fprintf(stderr, "shadowlab: --backend is %s in this build\n", _sl_backend_choices());
                return 2;
            }
            o->headless = true;
        } else {
            fprintf(stderr, "shadowlab: unknown option %s\n", a);
            _sl_viewer_usage(stderr);
            return 2;
        }
        if (takes_value) i++;
    }
    if ((o->screenshot || o->case_name) && o->headless && o->frames <= 0) o->frames = 1;
    if (o->screenshot && o->frames <= 0) o->frames = 3;
    if (o->serve_port && (o->frames > 0 || o->screenshot)) {
        fprintf(stderr, "shadowlab: --serve runs until stopped (Ctrl-C): not with --frames or --screenshot\n");
        return 2;
    }
    if (o->serve_port && !sl_serve_available()) {
        char why[512];
        sl_serve_start(&(sl_serve_desc){.port = o->serve_port}, why, sizeof why);
        fprintf(stderr, "shadowlab: %s\n", why);
        return 2;
    }
    if (o->serve_port) o->headless = true; /* offscreen; the page shows it */
    /* A page's X never writes into the folder the viewer runs in, only into one it names. */
    if (o->serve_port && !v->screenshot_dir) v->screenshot_dir = "shadowlab-screenshots";
    if (o->headless && o->frames <= 0 && !o->serve_port) {
        fprintf(stderr, "shadowlab: --headless needs --frames K (and usually --screenshot FILE)\n");
        return 2;
    }
    o->gif = _sl_viewer_is_gif(o->screenshot);
    if (v->mark_changes && (o->gif || !o->screenshot || o->frames < 2)) {
        fprintf(stderr, "shadowlab: --mark-changes needs --frames K (2 or more) and --screenshot FILE.png\n");
        return 2;
    }
    if (v->split.given && o->case_name) {
        fprintf(stderr, "shadowlab: --case shows the grader's pictures side by side already: not with --split\n");
        return 2;
    }
    if (o->gif && o->case_name) {
        fprintf(stderr, "shadowlab: --case saves one picture: --screenshot FILE.png\n");
        return 2;
    }
    return -1;
}
