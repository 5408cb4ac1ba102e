/* The light camera the framework draws lab 1's depth map with before lab 2's
 * matrices are in use: staff code, in a library of its own
 * (sl_light_camera_staff, framework/CMakeLists.txt) that the grader, a staff
 * build's viewer and shadowlab-light-table link, and no runner. It is lab 2's
 * light view (and, for a spot light, its projection), so the students' handout
 * does not hold it. The grader computes a lab 1 case's cameras with it and
 * sends them in the job; every build reads the matrices of the lights the
 * scenes and lab 1's cases use from a table (framework/sl_light_cameras.inc,
 * which `shadowlab-light-table` prints from this function). */
#include <math.h>

#include "sl_light_camera.h"

bool sl_light_camera_compute(const sl_light *light, const sl_aabb *bounds, mat4 view, mat4 projection) {
    vec3 up = {0, 1, 0}, dir, eye, centre;
    glm_vec3_copy((float *)light->direction, dir);
    if (fabsf(dir[1]) > 0.99f) glm_vec3_copy((vec3){0, 0, 1}, up);
    if (light->type == SL_LIGHT_DIRECTIONAL) {
        /* a loose box around the scene's bounding sphere */
        glm_vec3_center((float *)bounds->min, (float *)bounds->max, centre);
        float radius = glm_vec3_distance((float *)bounds->min, (float *)bounds->max) / 2;
        glm_vec3_scale(dir, -2 * radius, eye);
        glm_vec3_add(centre, eye, eye);
        glm_lookat(eye, centre, up, view);
        glm_ortho(-radius, radius, -radius, radius, radius * 0.5f, radius * 3.5f, projection);
    } else {
        /* the cone (a point light: the cone of its spot angle along its direction) */
        glm_vec3_copy((float *)light->position, eye);
        glm_vec3_add(eye, dir, centre);
        glm_lookat(eye, centre, up, view);
        glm_perspective(glm_rad(2 * light->spot_angle_deg), 1, light->near, light->far, projection);
    }
    return true;
}
