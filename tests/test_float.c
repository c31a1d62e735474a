/* SPDX-License-Identifier: MIT */
/*
 * zl_float.h, the optional float/double helpers, against integer references
 * written here (round half up of exact dyadic or rational values) and
 * against the fixed-point calls they stand for (matrices byte for byte).
 */
#include <string.h>

#include "unity.h"
#include "zline/zl_float.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

static uint32_t rng = 99u;

/* floor(n / d) for d > 0, any sign of n */
static int64_t floor_div(int64_t n, int64_t d)
{
    int64_t q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}

static void test_fixed_from_double_rounds_to_nearest(void)
{
    int i;
    for (i = 0; i < 20000; i++) {
        /* a / 2^20: exact in double; its Q16.16 value is a / 16, nearest = floor((a + 8) / 16) */
        int64_t a = (int64_t)zt_rand_range(&rng, -2000000000, 2000000000) * (i % 3 == 0 ? 16 : 1);
        double v = (double)a / 1048576.0;
        TEST_ASSERT_EQUAL_INT64(floor_div(a + 8, 16), zl_fx_from_double(v));
        TEST_ASSERT_EQUAL_INT64(zl_fx_from_double((double)(float)v), zl_fx_from_float((float)v));
    }
    TEST_ASSERT_EQUAL_INT64(ZL_FX_ONE / 2, zl_fx_from_double(0.5));
    TEST_ASSERT_EQUAL_INT64(1, zl_fx_from_double(0.5 / 65536.0));   /* a half rounds up */
    TEST_ASSERT_EQUAL_INT64(0, zl_fx_from_double(-0.5 / 65536.0));  /* up, also below zero */
    TEST_ASSERT_EQUAL_INT64(0, zl_fx_from_double(0.49999999999999994 / 65536.0));
    TEST_ASSERT_EQUAL_INT64(ZL_FX_MAX, zl_fx_from_double(1e12));
    TEST_ASSERT_EQUAL_INT64(ZL_FX_MAX, zl_fx_from_double(32767.99999));
    TEST_ASSERT_EQUAL_INT64(ZL_FX_MIN, zl_fx_from_double(-1e12));
    TEST_ASSERT_EQUAL_INT64(ZL_FX_MIN, zl_fx_from_double(-32768.0));
    {
        volatile double zero = 0.0;
        TEST_ASSERT_EQUAL_INT64(0, zl_fx_from_double(zero / zero)); /* NaN */
    }
    TEST_ASSERT_TRUE(zl_fx_to_double(ZL_FX_ONE * 3 / 4) == 0.75);
    TEST_ASSERT_TRUE(zl_fx_to_float(-ZL_FX_ONE / 4) == -0.25f);
}

static void test_angles_match_the_fixed_point_call(void)
{
    int i;
    for (i = 0; i < 20000; i++) { /* degrees exact in Q16.16: the same rounding as zl_angle_from_deg */
        zl_fixed deg = zt_rand_range(&rng, -ZL_FX_INT(720), ZL_FX_INT(720));
        if (i % 4 == 0)
            deg = ZL_FX_INT(zt_rand_range(&rng, -720, 720)) + (i % 8 == 0 ? ZL_FX_HALF : 0);
        TEST_ASSERT_EQUAL_INT64(zl_angle_from_deg(deg), zl_angle_from_degrees_d(zl_fx_to_double(deg)));
    }
    TEST_ASSERT_EQUAL_INT64(8192, zl_angle_from_degrees_f(45.0f));
    TEST_ASSERT_EQUAL_INT64(-16384, zl_angle_from_degrees_d(-90.0));
    TEST_ASSERT_EQUAL_INT64(32768, zl_angle_from_radians_d(3.14159265358979323846));
    TEST_ASSERT_EQUAL_INT64(16384, zl_angle_from_radians_f(1.5707964f));
    for (i = -720; i <= 720; i += 7) /* radians: within a unit of the same angle in degrees */
        TEST_ASSERT_INT_WITHIN(1, zl_angle_from_degrees_d(i),
                               zl_angle_from_radians_d((double)i * 3.14159265358979323846 / 180.0));
}

static void test_colours_and_intensities(void)
{
    int i;
    for (i = -100; i <= 1200; i++) { /* i / 1024: 255 i / 1024 exact */
        int64_t want = floor_div(255 * (int64_t)i + 512, 1024);
        want = want < 0 ? 0 : (want > 255 ? 255 : want);
        TEST_ASSERT_EQUAL_INT64(want, zl_unit8_d((double)i / 1024.0));
        TEST_ASSERT_EQUAL_INT64(want, zl_unit8_f((float)i / 1024.0f));
    }
    {
        zl_rgb c = zl_rgb_f(1.0f, 0.5f, 0.0f);
        TEST_ASSERT_EQUAL_UINT8(255, c.r);
        TEST_ASSERT_EQUAL_UINT8(128, c.g); /* 127.5 rounds up */
        TEST_ASSERT_EQUAL_UINT8(0, c.b);
    }
}

/* Pythagorean quadruples (a, b, c) / d: unit vectors exact in rationals. */
static void test_unit_vectors(void)
{
    static const int quad[4][4] = {{2, 3, 6, 7}, {1, 4, 8, 9}, {2, 6, 9, 11}, {0, 0, 5, 5}};
    int q, s, sign;
    for (q = 0; q < 4; q++)
        for (s = 1; s < 2000; s = s * 3 + 1)
            for (sign = 0; sign < 8; sign++) {
                double x = quad[q][0] * s * (sign & 1 ? -1.0 : 1.0) / 64.0;
                double y = quad[q][1] * s * (sign & 2 ? -1.0 : 1.0) / 64.0;
                double z = quad[q][2] * s * (sign & 4 ? -1.0 : 1.0) / 64.0;
                zl_vec3 u = zl_unit_vec3_d(x, y, z), f = zl_unit_vec3_f((float)x, (float)y, (float)z);
                int64_t d = quad[q][3];
                /* round half up of 65536 a / d */
                TEST_ASSERT_EQUAL_INT64(floor_div(2 * 65536 * (int64_t)quad[q][0] * (sign & 1 ? -1 : 1) + d, 2 * d), u.x);
                TEST_ASSERT_EQUAL_INT64(floor_div(2 * 65536 * (int64_t)quad[q][1] * (sign & 2 ? -1 : 1) + d, 2 * d), u.y);
                TEST_ASSERT_EQUAL_INT64(floor_div(2 * 65536 * (int64_t)quad[q][2] * (sign & 4 ? -1 : 1) + d, 2 * d), u.z);
                TEST_ASSERT_EQUAL_MEMORY(&u, &f, sizeof u);
            }
    {
        zl_vec3 z = zl_unit_vec3_d(0, 0, 0);
        TEST_ASSERT_EQUAL_INT64(0, z.x | z.y | z.z);
    }
}

static void test_lights(void)
{
    static const double dir[3] = {2, 3, 6}, diffuse[3] = {1, 0.5, 0}, specular[3] = {0.25, 0.25, 0.25};
    static const float dirf[3] = {2, 3, 6}, diffusef[3] = {1, 0.5f, 0}, specularf[3] = {0.25f, 0.25f, 0.25f};
    zl_light l = zl_light_d(dir, diffuse, specular), lf = zl_light_f(dirf, diffusef, specularf);
    zl_state st;
    TEST_ASSERT_EQUAL_INT64(floor_div(2 * 65536 * 2 + 7, 14), l.dir.x);
    TEST_ASSERT_EQUAL_INT64(floor_div(2 * 65536 * 6 + 7, 14), l.dir.z);
    TEST_ASSERT_EQUAL_UINT8(128, l.diffuse.g);
    TEST_ASSERT_EQUAL_UINT8(64, l.specular.b); /* 63.75 */
    TEST_ASSERT_EQUAL_MEMORY(&l.dir, &lf.dir, sizeof l.dir); /* field by field: the struct has padding */
    TEST_ASSERT_EQUAL_MEMORY(&l.diffuse, &lf.diffuse, sizeof l.diffuse);
    TEST_ASSERT_EQUAL_MEMORY(&l.specular, &lf.specular, sizeof l.specular);
    TEST_ASSERT_EQUAL_UINT8(0, l.point);
    TEST_ASSERT_EQUAL_UINT8(0, lf.point);
    {
        static const double at[3] = {1.5, -2, 0.25};
        zl_light p = zl_point_light_d(at, diffuse, specular);
        TEST_ASSERT_EQUAL_UINT8(1, p.point);
        TEST_ASSERT_EQUAL_INT64(ZL_FX_ONE * 3 / 2, p.position.x);
        TEST_ASSERT_EQUAL_INT64(-ZL_FX_INT(2), p.position.y);
        TEST_ASSERT_EQUAL_INT64(ZL_FX_ONE / 4, p.position.z);
        TEST_ASSERT_EQUAL_UINT8(128, p.diffuse.g);
    }
    zl_state_default(&st);
    zl_state_light_f(&st, 0, 0, -3, 0.25f);
    TEST_ASSERT_EQUAL_UINT8(1, st.light_on);
    TEST_ASSERT_EQUAL_INT64(-ZL_FX_ONE, st.light_dir.z);
    TEST_ASSERT_EQUAL_INT64(0, st.light_dir.x);
    TEST_ASSERT_EQUAL_UINT8(64, st.ambient);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_state_check(&st));
}

static void test_matrices_match_the_fixed_point_calls(void)
{
    zl_mat4 a, b;
    double m[16];
    float mf[16];
    const double eye[3] = {1.5, 2.25, 3.0}, target[3] = {0.1, -0.2, 0.3}, up[3] = {0, 1, 0};
    const float eyef[3] = {1.5f, 2.25f, 3.0f}, targetf[3] = {0.1f, -0.2f, 0.3f}, upf[3] = {0, 1, 0};
    int i;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective_d(&a, 45.0, 4.0 / 3.0, 0.1, 100.0));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&b, zl_angle_from_deg(ZL_FX_INT(45)), 87381, 6554, ZL_FX_INT(100)));
    TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective_f(&a, 45.0f, 1.0f, 0.5f, 20.0f));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&b, 8192, ZL_FX_ONE, ZL_FX_HALF, ZL_FX_INT(20)));
    TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_perspective_d(&a, 45.0, 1.0, 2.0, 1.0));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_ortho_d(&a, -2, 2, -1.5, 1.5, 0.25, 10));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_ortho(&b, -ZL_FX_INT(2), ZL_FX_INT(2), -ZL_FX_ONE * 3 / 2, ZL_FX_ONE * 3 / 2,
                                               ZL_FX_ONE / 4, ZL_FX_INT(10)));
    TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at_d(&a, eye, target, up));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&b, zl_vec3_d(1.5, 2.25, 3.0), zl_vec3_d(0.1, -0.2, 0.3),
                                                 zl_vec3_d(0, 1, 0)));
    TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at_f(&a, eyef, targetf, upf));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&b, zl_vec3_f(1.5f, 2.25f, 3.0f), zl_vec3_f(0.1f, -0.2f, 0.3f),
                                                 zl_vec3_f(0, 1, 0)));
    TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    for (i = 0; i < 200; i++) {
        zl_fixed deg = zt_rand_range(&rng, -ZL_FX_INT(400), ZL_FX_INT(400));
        zl_vec3 v;
        v.x = zt_rand_range(&rng, -ZL_FX_INT(100), ZL_FX_INT(100));
        v.y = zt_rand_range(&rng, -ZL_FX_INT(100), ZL_FX_INT(100));
        v.z = zt_rand_range(&rng, -ZL_FX_INT(100), ZL_FX_INT(100));
        zl_mat4_rotate_x_d(&a, zl_fx_to_double(deg));
        zl_mat4_rotate_x(&b, zl_angle_from_deg(deg));
        TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
        zl_mat4_rotate_y_d(&a, zl_fx_to_double(deg));
        zl_mat4_rotate_y(&b, zl_angle_from_deg(deg));
        TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
        zl_mat4_rotate_z_d(&a, zl_fx_to_double(deg));
        zl_mat4_rotate_z(&b, zl_angle_from_deg(deg));
        TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
        zl_mat4_translate_d(&a, zl_fx_to_double(v.x), zl_fx_to_double(v.y), zl_fx_to_double(v.z));
        zl_mat4_translate(&b, v);
        TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
        zl_mat4_scale_d(&a, zl_fx_to_double(v.x), zl_fx_to_double(v.y), zl_fx_to_double(v.z));
        zl_mat4_scale(&b, v);
        TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    }
    zl_mat4_rotate_y_f(&a, 30.0f);
    zl_mat4_rotate_y(&b, zl_angle_from_deg(ZL_FX_INT(30)));
    TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    zl_mat4_translate_f(&a, 1.0f, -2.5f, 0.125f);
    zl_mat4_translate(&b, zl_vec3_d(1.0, -2.5, 0.125));
    TEST_ASSERT_EQUAL_MEMORY(&b, &a, sizeof a);
    for (i = 0; i < 16; i++) {
        m[i] = (double)(i - 8) / 3.0;
        mf[i] = (float)m[i];
    }
    a = zl_mat4_d(m);
    b = zl_mat4_f(mf);
    for (i = 0; i < 16; i++) {
        /* (i - 8) / 3 in Q16.16, half up: floor((2 * 65536 (i - 8) + 3) / 6) */
        TEST_ASSERT_EQUAL_INT64(floor_div(2 * 65536 * (int64_t)(i - 8) + 3, 6), a.m[i]);
        TEST_ASSERT_EQUAL_INT64(zl_fx_from_double((double)mf[i]), b.m[i]);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_fixed_from_double_rounds_to_nearest);
    RUN_TEST(test_angles_match_the_fixed_point_call);
    RUN_TEST(test_colours_and_intensities);
    RUN_TEST(test_unit_vectors);
    RUN_TEST(test_lights);
    RUN_TEST(test_matrices_match_the_fixed_point_calls);
    return UNITY_END();
}
