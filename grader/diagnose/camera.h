/* camera: a 4x4 matrix read as the camera it is, so that a wrong matrix is told in a camera's terms
 * (where it looks from and along, its field of view, aspect, near and far, its box) rather than by
 * its entries. Any probe whose output is a matrix (a light's view or projection, a cube face's) gets
 * this reading when no verdict of its lab names the mistake. */
#ifndef SL_DIAGNOSE_CAMERA_H
#define SL_DIAGNOSE_CAMERA_H

#include <stdbool.h>
#include <stddef.h>

typedef enum sl_camera_reading_kind {
    SL_CAMERA_NONE,        /* not a camera's matrix (a product of several, or garbage) */
    SL_CAMERA_VIEW,        /* rigid: a rotation and a translation */
    SL_CAMERA_PERSPECTIVE, /* GL's perspective projection (glm_perspective, glm_frustum) */
    SL_CAMERA_ORTHO,       /* GL's orthographic projection (glm_ortho) */
} sl_camera_reading_kind;

typedef struct sl_camera_reading {
    sl_camera_reading_kind kind;
    double eye[3], forward[3], up[3];     /* a view: world space */
    double fov_deg, aspect;               /* a perspective: vertical field of view, width / height */
    double left, right, bottom, top;      /* an ortho box; a perspective's at the near plane */
    double near, far;
} sl_camera_reading;

/* Reads m (column-major, as cglm and GL hold it: m[col * 4 + row]) as a camera. */
sl_camera_reading sl_camera_read(const double m[16]);

/* What differs between the student's camera and the expected one, in the camera's terms ("it looks
 * along (0, 0.8, 0.6), the opposite way: expected (0, -0.8, -0.6); aspect 2, expected 1"). Writes ""
 * and returns false when either is not a camera, or when they read the same. */
bool sl_camera_differences(const double student[16], const double expected[16], char *out, size_t n);

#endif
