/* sl_bench_baseline: a plain shadow-mapping program, as a graphics tutorial
 * writes it, for the benchmark (`shadowlab --bench`, row plain-gl-3x3) to
 * compare the labs with on the same machine in the same run. It answers labs
 * 1-4, so it lives with the solutions and only a staff build's viewer has it
 * (sl_bench_plain_gl in framework/sl_bench.h): one depth pass into a 24-bit depth texture, one camera
 * pass with diffuse and specular light and an N×N PCF loop that compares
 * each tap with `texture(...).r` (a sampler2D, GL_NEAREST). No lab code and
 * none of the framework's renderer: its own shaders and state, the scene's
 * meshes and the framework's default light camera. */
#ifndef SL_BENCH_BASELINE_H
#define SL_BENCH_BASELINE_H

#include <stdbool.h>
#include <stddef.h>

#include "sl_bench.h"
#include "sl_mesh.h"
#include "sl_scene.h"

typedef struct sl_bench_baseline {
    GLuint framebuffer, depth_texture, depth_program, camera_program;
    GLuint queries[3]; /* timestamps: start, after the depth pass, after the camera pass */
    sl_mesh meshes[SL_SCENE_MAX_OBJECTS];
    int mesh_count, map_size;
    mat4 light_view_projection;
} sl_bench_baseline;

/* radius: the PCF loop runs from -radius to radius in x and y (1: 3×3). */
bool sl_bench_baseline_init(sl_bench_baseline *b, const sl_scene *scene, int map_size, int radius, char *err,
                            size_t err_size);
/* Draws one frame into framebuffer 0; pass_ms gets the depth and the camera
 * pass's times from the previous call's timer queries (0 on the first). */
void sl_bench_baseline_draw(sl_bench_baseline *b, const sl_scene *scene, int width, int height, double pass_ms[2]);
void sl_bench_baseline_destroy(sl_bench_baseline *b);

/* The same, as the benchmark takes it: sl_bench_set_plain_gl(&sl_bench_baseline_program). */
extern const sl_bench_plain_gl sl_bench_baseline_program;

#endif
