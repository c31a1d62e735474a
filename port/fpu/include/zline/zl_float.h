/* SPDX-License-Identifier: MIT */
/*
 * Float and double convenience for parts with an FPU (optional; include it
 * yourself): scene values written as numbers instead of Q16.16 and binary
 * angles. Header only, static inline: the core library stays free of
 * floating point (CTest core_no_float_symbols), and a program that does not
 * call these pays nothing. No libm: the one square root is computed here.
 *
 * Every conversion rounds to the NEAREST fixed-point value (halves up, as
 * zline rounds) and saturates at the ends of its range (NaN gives 0); then the
 * fixed-point call does the rest, so
 *     zl_mat4_perspective_d(&m, 45.0, 4.0 / 3, 0.1, 100.0)
 * is exactly
 *     zl_mat4_perspective(&m, zl_angle_from_degrees_d(45.0), zl_fx_from_double(4.0 / 3),
 *                         zl_fx_from_double(0.1), zl_fx_from_double(100.0))
 * (tests/test_float.c checks each helper against the fixed-point calls).
 * Angles are in degrees (zl_angle_from_radians_* for radians); colours and
 * intensities in 0 .. 1 (to 0 .. 255). The _f forms take float, the _d
 * forms double (a float converts to double exactly, so the _f forms round
 * the same way).
 */
#ifndef ZL_FLOAT_H
#define ZL_FLOAT_H

#include "zline/zline.h"

#ifdef __cplusplus
extern "C" {
#endif

/* --------------------------------------------------------------- scalars */

/* v rounded to the nearest integer, halves up (zline's own rounding,
 * zl_round_div64), clamped to lo .. hi; NaN -> 0. Exact: v - floor(v) has
 * no rounding error for |v| < 2^52. */
static inline double zl_float_round_clamp_(double v, double lo, double hi)
{
    double fl;
    if (v != v)
        return 0.0;
    if (v <= lo)
        return lo;
    if (v >= hi)
        return hi;
    fl = (double)(int64_t)v; /* towards zero */
    if (fl > v)
        fl -= 1.0;           /* floor */
    return v - fl >= 0.5 ? fl + 1.0 : fl;
}

static inline zl_fixed zl_fx_from_double(double v)
{
    return (zl_fixed)zl_float_round_clamp_(v * 65536.0, -2147483648.0, 2147483647.0);
}
static inline zl_fixed zl_fx_from_float(float v)
{
    return zl_fx_from_double((double)v);
}
static inline double zl_fx_to_double(zl_fixed v)
{
    return (double)v / 65536.0;
}
static inline float zl_fx_to_float(zl_fixed v)
{
    return (float)zl_fx_to_double(v);
}

/* Degrees or radians to a binary angle (65536 a turn), not wrapped. */
static inline zl_angle zl_angle_from_degrees_d(double deg)
{
    return (zl_angle)zl_float_round_clamp_(deg * 65536.0 / 360.0, -2147483648.0, 2147483647.0);
}
static inline zl_angle zl_angle_from_degrees_f(float deg)
{
    return zl_angle_from_degrees_d((double)deg);
}
static inline zl_angle zl_angle_from_radians_d(double rad)
{
    return (zl_angle)zl_float_round_clamp_(rad * (32768.0 / 3.14159265358979323846), -2147483648.0,
                                           2147483647.0);
}
static inline zl_angle zl_angle_from_radians_f(float rad)
{
    return zl_angle_from_radians_d((double)rad);
}

/* 0 .. 1 to 0 .. 255 (an intensity, an ambient level, a colour channel). */
static inline uint8_t zl_unit8_d(double v)
{
    return (uint8_t)zl_float_round_clamp_(v * 255.0, 0.0, 255.0);
}
static inline uint8_t zl_unit8_f(float v)
{
    return zl_unit8_d((double)v);
}

/* ------------------------------------------------------ vectors, colours */

static inline zl_vec3 zl_vec3_d(double x, double y, double z)
{
    zl_vec3 v;
    v.x = zl_fx_from_double(x);
    v.y = zl_fx_from_double(y);
    v.z = zl_fx_from_double(z);
    return v;
}
static inline zl_vec3 zl_vec3_f(float x, float y, float z)
{
    return zl_vec3_d((double)x, (double)y, (double)z);
}

static inline zl_rgb zl_rgb_d(double r, double g, double b)
{
    zl_rgb c;
    c.r = zl_unit8_d(r);
    c.g = zl_unit8_d(g);
    c.b = zl_unit8_d(b);
    return c;
}
static inline zl_rgb zl_rgb_f(float r, float g, float b)
{
    return zl_rgb_d((double)r, (double)g, (double)b);
}

/* sqrt by Newton's method from above, for s in [1, 3] (see zl_unit_vec3_d). */
static inline double zl_float_sqrt_1_3_(double s)
{
    double x = 2.0;
    int i;
    for (i = 0; i < 64; i++) {
        double next = 0.5 * (x + s / x);
        if (!(next < x))
            break;
        x = next;
    }
    return x;
}

/* (x, y, z) scaled to unit length, then rounded: a light direction
 * (zl_state.light_dir, zl_light.dir). The zero vector gives zero. */
static inline zl_vec3 zl_unit_vec3_d(double x, double y, double z)
{
    double ax = x < 0 ? -x : x, ay = y < 0 ? -y : y, az = z < 0 ? -z : z, m = ax, len;
    m = ay > m ? ay : m;
    m = az > m ? az : m;
    if (!(m > 0.0))
        return zl_vec3_d(0.0, 0.0, 0.0);
    x /= m; /* the largest component is +-1: the sum of squares is in [1, 3] */
    y /= m;
    z /= m;
    len = zl_float_sqrt_1_3_(x * x + y * y + z * z);
    return zl_vec3_d(x / len, y / len, z / len);
}
static inline zl_vec3 zl_unit_vec3_f(float x, float y, float z)
{
    return zl_unit_vec3_d((double)x, (double)y, (double)z);
}

/* ------------------------------------------------------------------ lights */

/* A directional light (zl_lighting): direction towards it (normalised
 * here), diffuse and specular colours in 0 .. 1. */
static inline zl_light zl_light_d(const double dir[3], const double diffuse[3], const double specular[3])
{
    zl_light l;
    l.dir = zl_unit_vec3_d(dir[0], dir[1], dir[2]);
    l.diffuse = zl_rgb_d(diffuse[0], diffuse[1], diffuse[2]);
    l.specular = zl_rgb_d(specular[0], specular[1], specular[2]);
    l.point = 0;
    l.position = zl_vec3_d(0.0, 0.0, 0.0);
    return l;
}
/* A point light at position (the lights' space), colours as zl_light_d. */
static inline zl_light zl_point_light_d(const double position[3], const double diffuse[3], const double specular[3])
{
    static const double along_z[3] = {0.0, 0.0, 1.0};
    zl_light l = zl_light_d(along_z, diffuse, specular);
    l.point = 1;
    l.position = zl_vec3_d(position[0], position[1], position[2]);
    return l;
}
static inline zl_light zl_light_f(const float dir[3], const float diffuse[3], const float specular[3])
{
    double d[3], c[3], s[3];
    int i;
    for (i = 0; i < 3; i++) {
        d[i] = (double)dir[i];
        c[i] = (double)diffuse[i];
        s[i] = (double)specular[i];
    }
    return zl_light_d(d, c, s);
}

/* Flat lighting of zl_state: light on, towards (x, y, z) (normalised),
 * ambient 0 .. 1. */
static inline void zl_state_light_d(zl_state *st, double x, double y, double z, double ambient)
{
    st->light_on = 1;
    st->light_dir = zl_unit_vec3_d(x, y, z);
    st->ambient = zl_unit8_d(ambient);
}
static inline void zl_state_light_f(zl_state *st, float x, float y, float z, float ambient)
{
    zl_state_light_d(st, (double)x, (double)y, (double)z, (double)ambient);
}

/* ---------------------------------------------------------------- matrices */

/* 16 entries, row-major as zl_mat4 (m[row * 4 + col]). */
static inline zl_mat4 zl_mat4_d(const double m[16])
{
    zl_mat4 r;
    int i;
    for (i = 0; i < 16; i++)
        r.m[i] = zl_fx_from_double(m[i]);
    return r;
}
static inline zl_mat4 zl_mat4_f(const float m[16])
{
    zl_mat4 r;
    int i;
    for (i = 0; i < 16; i++)
        r.m[i] = zl_fx_from_float(m[i]);
    return r;
}

static inline zl_status zl_mat4_perspective_d(zl_mat4 *out, double fovy_degrees, double aspect, double near_z,
                                              double far_z)
{
    return zl_mat4_perspective(out, zl_angle_from_degrees_d(fovy_degrees), zl_fx_from_double(aspect),
                               zl_fx_from_double(near_z), zl_fx_from_double(far_z));
}
static inline zl_status zl_mat4_perspective_f(zl_mat4 *out, float fovy_degrees, float aspect, float near_z,
                                              float far_z)
{
    return zl_mat4_perspective_d(out, (double)fovy_degrees, (double)aspect, (double)near_z, (double)far_z);
}

static inline zl_status zl_mat4_ortho_d(zl_mat4 *out, double l, double r, double b, double t, double near_z,
                                        double far_z)
{
    return zl_mat4_ortho(out, zl_fx_from_double(l), zl_fx_from_double(r), zl_fx_from_double(b),
                         zl_fx_from_double(t), zl_fx_from_double(near_z), zl_fx_from_double(far_z));
}

static inline zl_status zl_mat4_look_at_d(zl_mat4 *out, const double eye[3], const double target[3],
                                          const double up[3])
{
    return zl_mat4_look_at(out, zl_vec3_d(eye[0], eye[1], eye[2]), zl_vec3_d(target[0], target[1], target[2]),
                           zl_vec3_d(up[0], up[1], up[2]));
}
static inline zl_status zl_mat4_look_at_f(zl_mat4 *out, const float eye[3], const float target[3],
                                          const float up[3])
{
    return zl_mat4_look_at(out, zl_vec3_f(eye[0], eye[1], eye[2]), zl_vec3_f(target[0], target[1], target[2]),
                           zl_vec3_f(up[0], up[1], up[2]));
}

static inline void zl_mat4_translate_d(zl_mat4 *out, double x, double y, double z)
{
    zl_mat4_translate(out, zl_vec3_d(x, y, z));
}
static inline void zl_mat4_scale_d(zl_mat4 *out, double x, double y, double z)
{
    zl_mat4_scale(out, zl_vec3_d(x, y, z));
}
static inline void zl_mat4_rotate_x_d(zl_mat4 *out, double degrees)
{
    zl_mat4_rotate_x(out, zl_angle_from_degrees_d(degrees));
}
static inline void zl_mat4_rotate_y_d(zl_mat4 *out, double degrees)
{
    zl_mat4_rotate_y(out, zl_angle_from_degrees_d(degrees));
}
static inline void zl_mat4_rotate_z_d(zl_mat4 *out, double degrees)
{
    zl_mat4_rotate_z(out, zl_angle_from_degrees_d(degrees));
}
static inline void zl_mat4_translate_f(zl_mat4 *out, float x, float y, float z)
{
    zl_mat4_translate_d(out, (double)x, (double)y, (double)z);
}
static inline void zl_mat4_scale_f(zl_mat4 *out, float x, float y, float z)
{
    zl_mat4_scale_d(out, (double)x, (double)y, (double)z);
}
static inline void zl_mat4_rotate_x_f(zl_mat4 *out, float degrees)
{
    zl_mat4_rotate_x_d(out, (double)degrees);
}
static inline void zl_mat4_rotate_y_f(zl_mat4 *out, float degrees)
{
    zl_mat4_rotate_y_d(out, (double)degrees);
}
static inline void zl_mat4_rotate_z_f(zl_mat4 *out, float degrees)
{
    zl_mat4_rotate_z_d(out, (double)degrees);
}

#ifdef __cplusplus
}
#endif

#endif /* ZL_FLOAT_H */
