/* camera: a matrix read as a camera (see the header). */
#include "camera.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>

#define _SL_PI 3.14159265358979323846

static double _sl_at(const double m[16], int row, int col) { return m[col * 4 + row]; }

static bool _sl_zero(double v, double scale) { return fabs(v) <= 1e-4 * fmax(1, scale); }

static double _sl_dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static bool _sl_read_view(const double m[16], sl_camera_reading *c) {
    double r[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) r[i][j] = _sl_at(m, i, j);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (fabs(_sl_dot3(r[i], r[j]) - (i == j)) > 1e-3) return false;
    if (!_sl_zero(_sl_at(m, 3, 0), 1) || !_sl_zero(_sl_at(m, 3, 1), 1) || !_sl_zero(_sl_at(m, 3, 2), 1) ||
        fabs(_sl_at(m, 3, 3) - 1) > 1e-4)
        return false;
    /* rows of the rotation: the camera's right, up and backward axes in world space; eye = -R^T t */
    for (int j = 0; j < 3; j++) {
        c->eye[j] = 0;
        for (int i = 0; i < 3; i++) c->eye[j] -= r[i][j] * _sl_at(m, i, 3);
        c->up[j] = r[1][j];
        c->forward[j] = -r[2][j];
    }
    c->kind = SL_CAMERA_VIEW;
    return true;
}

static bool _sl_read_perspective(const double m[16], sl_camera_reading *c) {
    double a = _sl_at(m, 2, 2), b = _sl_at(m, 2, 3), sx = _sl_at(m, 0, 0), sy = _sl_at(m, 1, 1);
    if (fabs(_sl_at(m, 3, 2) + 1) > 1e-4 || !_sl_zero(_sl_at(m, 3, 3), 1) || !_sl_zero(_sl_at(m, 3, 0), 1) ||
        !_sl_zero(_sl_at(m, 3, 1), 1) || !_sl_zero(_sl_at(m, 0, 1), sx) || !_sl_zero(_sl_at(m, 1, 0), sy) ||
        !_sl_zero(_sl_at(m, 0, 3), sx) || !_sl_zero(_sl_at(m, 1, 3), sy) || sx == 0 || sy == 0 ||
        fabs(a - 1) < 1e-9 || fabs(a + 1) < 1e-9)
        return false;
    c->kind = SL_CAMERA_PERSPECTIVE;
    c->near = b / (a - 1);
    c->far = b / (a + 1);
    c->fov_deg = 2 * atan(1 / sy) * 180 / _SL_PI;
    c->aspect = sy / sx;
    /* the box at the near plane: x' = (2n x + (r + l) z) / (r - l) over -z */
    double w = 2 * c->near / sx, h = 2 * c->near / sy;
    double cx = _sl_at(m, 0, 2) * w / 2, cy = _sl_at(m, 1, 2) * h / 2;
    c->left = cx - w / 2;
    c->right = cx + w / 2;
    c->bottom = cy - h / 2;
    c->top = cy + h / 2;
    return true;
}

static bool _sl_read_ortho(const double m[16], sl_camera_reading *c) {
    double sx = _sl_at(m, 0, 0), sy = _sl_at(m, 1, 1), sz = _sl_at(m, 2, 2);
    if (sx == 0 || sy == 0 || sz == 0 || fabs(_sl_at(m, 3, 3) - 1) > 1e-4) return false;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 3; j++)
            if (i != j && !_sl_zero(_sl_at(m, i, j), fabs(_sl_at(m, j, j)))) return false;
    c->kind = SL_CAMERA_ORTHO;
    c->left = (-1 - _sl_at(m, 0, 3)) / sx;
    c->right = (1 - _sl_at(m, 0, 3)) / sx;
    c->bottom = (-1 - _sl_at(m, 1, 3)) / sy;
    c->top = (1 - _sl_at(m, 1, 3)) / sy;
    c->near = (_sl_at(m, 2, 3) + 1) / sz;
    c->far = (_sl_at(m, 2, 3) - 1) / sz;
    return true;
}

sl_camera_reading sl_camera_read(const double m[16]) {
    sl_camera_reading c = {.kind = SL_CAMERA_NONE};
    for (int i = 0; i < 16; i++)
        if (!isfinite(m[i])) return c;
    if (_sl_read_view(m, &c) || _sl_read_perspective(m, &c) || _sl_read_ortho(m, &c)) return c;
    return (sl_camera_reading){.kind = SL_CAMERA_NONE};
}

static const char *_sl_kind_name(sl_camera_reading_kind k) {
    switch (k) {
    case SL_CAMERA_VIEW: return "a view matrix (a rotation and a translation)";
    case SL_CAMERA_PERSPECTIVE: return "a perspective projection";
    case SL_CAMERA_ORTHO: return "an orthographic projection";
    default: return "no camera's matrix";
    }
}

typedef struct _sl_text {
    char *out;
    size_t n, used;
} _sl_text;

static void _sl_say(_sl_text *t, const char *fmt, ...) {
    if (t->used >= t->n) return;
    if (t->used) t->used += (size_t)snprintf(t->out + t->used, t->n - t->used, "; ");
    if (t->used >= t->n) return;
    va_list ap;
    va_start(ap, fmt);
    t->used += (size_t)vsnprintf(t->out + t->used, t->n - t->used, fmt, ap);
    va_end(ap);
}

static bool _sl_differ(double a, double b) { return fabs(a - b) > 1e-3 * fmax(1, fmax(fabs(a), fabs(b))); }

static double _sl_angle_deg(const double a[3], const double b[3]) {
    double d = _sl_dot3(a, b) / sqrt(_sl_dot3(a, a) * _sl_dot3(b, b));
    return acos(fmax(-1, fmin(1, d))) * 180 / _SL_PI;
}

static void _sl_directions(_sl_text *t, const char *what, const double s[3], const double e[3]) {
    double angle = _sl_angle_deg(s, e);
    if (angle > 179.9)
        _sl_say(t, "%s the opposite way: (%.3g, %.3g, %.3g), expected (%.3g, %.3g, %.3g)", what, s[0], s[1], s[2],
                e[0], e[1], e[2]);
    else if (angle > 0.1)
        _sl_say(t, "%s (%.3g, %.3g, %.3g), %.3g degrees off the expected (%.3g, %.3g, %.3g)", what, s[0], s[1], s[2],
                angle, e[0], e[1], e[2]);
}

static void _sl_range(_sl_text *t, const char *what, double s0, double s1, double e0, double e1) {
    if (_sl_differ(s0, e0) || _sl_differ(s1, e1))
        _sl_say(t, "%s [%.4g, %.4g], expected [%.4g, %.4g]", what, s0, s1, e0, e1);
}

bool sl_camera_differences(const double student[16], const double expected[16], char *out, size_t n) {
    _sl_text t = {out, n, 0};
    out[0] = '\0';
    sl_camera_reading s = sl_camera_read(student), e = sl_camera_read(expected);
    if (e.kind == SL_CAMERA_NONE) return false;
    if (s.kind != e.kind && e.kind == SL_CAMERA_VIEW) {
        /* a view whose rotation lost its right and up rows (zero, or NaN) while its backward row is whole: a
         * lookat whose up vector lies along the viewing direction, whose cross product is zero */
        double right = 0, up = 0, back = 0;
        for (int j = 0; j < 3; j++) {
            right += _sl_at(student, 0, j) * _sl_at(student, 0, j);
            up += _sl_at(student, 1, j) * _sl_at(student, 1, j);
            back += _sl_at(student, 2, j) * _sl_at(student, 2, j);
        }
        if (fabs(back - 1) < 1e-3 && !(right > 1e-6 && up > 1e-6)) {
            _sl_say(&t, "its right and up axes are %s, its viewing axis whole: a lookat whose up vector is parallel to "
                        "the direction it looks along (their cross product is zero) — where the direction is (nearly) "
                        "vertical, take another up vector, (0, 0, 1)",
                    isnan(right) || isnan(up) ? "not finite" : "zero");
            return true;
        }
    }
    if (s.kind != e.kind) {
        _sl_say(&t, "as a camera it is %s, where %s is expected", _sl_kind_name(s.kind), _sl_kind_name(e.kind));
        return true;
    }
    if (s.kind == SL_CAMERA_VIEW) {
        if (_sl_differ(s.eye[0], e.eye[0]) || _sl_differ(s.eye[1], e.eye[1]) || _sl_differ(s.eye[2], e.eye[2]))
            _sl_say(&t, "its eye is at (%.3g, %.3g, %.3g), expected (%.3g, %.3g, %.3g)", s.eye[0], s.eye[1], s.eye[2],
                    e.eye[0], e.eye[1], e.eye[2]);
        _sl_directions(&t, "it looks", s.forward, e.forward);
        if (_sl_angle_deg(s.forward, e.forward) <= 0.1) _sl_directions(&t, "its up is", s.up, e.up);
    } else if (s.kind == SL_CAMERA_PERSPECTIVE) {
        if (_sl_differ(s.fov_deg, e.fov_deg))
            _sl_say(&t, "its vertical field of view is %.4g degrees, expected %.4g", s.fov_deg, e.fov_deg);
        if (_sl_differ(s.aspect, e.aspect)) _sl_say(&t, "its aspect (width / height) is %.4g, expected %.4g", s.aspect, e.aspect);
        _sl_range(&t, "its depth range (near, far) is", s.near, s.far, e.near, e.far);
        if (!_sl_differ(s.fov_deg, e.fov_deg) && !_sl_differ(s.aspect, e.aspect) &&
            (_sl_differ(s.left + s.right, e.left + e.right) || _sl_differ(s.bottom + s.top, e.bottom + e.top)))
            _sl_say(&t, "it is off-centre: its near plane spans x [%.3g, %.3g], y [%.3g, %.3g], expected x [%.3g, %.3g], "
                        "y [%.3g, %.3g]", s.left, s.right, s.bottom, s.top, e.left, e.right, e.bottom, e.top);
    } else {
        _sl_range(&t, "its box spans x", s.left, s.right, e.left, e.right);
        _sl_range(&t, "y", s.bottom, s.top, e.bottom, e.top);
        _sl_range(&t, "depth (near, far)", s.near, s.far, e.near, e.far);
    }
    return t.used > 0;
}
