/* SPDX-License-Identifier: MIT */
/* Fixed-point arithmetic: rounding, range errors, square roots, sine table. */
#include "unity.h"
#include "zline/zline.h"

void setUp(void) {}
void tearDown(void) {}

static void test_mul_div_round_to_nearest(void)
{
    zl_fixed r;
    TEST_ASSERT_EQUAL_INT(ZL_FX_INT(6), zl_fx_mul(ZL_FX_INT(2), ZL_FX_INT(3)));
    TEST_ASSERT_EQUAL_INT(-ZL_FX_INT(6), zl_fx_mul(-ZL_FX_INT(2), ZL_FX_INT(3)));
    /* 1 raw * 0.5 = 0.5 raw: ties round towards +infinity. */
    TEST_ASSERT_EQUAL_INT(1, zl_fx_mul(1, ZL_FX_HALF));
    TEST_ASSERT_EQUAL_INT(0, zl_fx_mul(-1, ZL_FX_HALF));
    TEST_ASSERT_EQUAL_INT(21845, zl_fx_div(ZL_FX_ONE, ZL_FX_INT(3))); /* 21845.33 */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_fx_div_checked(ZL_FX_INT(7), ZL_FX_INT(2), &r));
    TEST_ASSERT_EQUAL_INT(ZL_FX_INT(7) / 2, r);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_fx_div_checked(-ZL_FX_INT(7), -ZL_FX_INT(2), &r));
    TEST_ASSERT_EQUAL_INT(ZL_FX_INT(7) / 2, r);
}

static void test_checked_ops_report_range_errors(void)
{
    zl_fixed r = 1234;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_fx_mul_checked(ZL_FX_INT(300), ZL_FX_INT(300), &r));
    TEST_ASSERT_EQUAL_INT(1234, r); /* untouched on error */
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_fx_div_checked(ZL_FX_ONE, 0, &r));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_fx_div_checked(ZL_FX_INT(30000), 1, &r));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_fx_recip_checked(1, &r));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_fx_recip_checked(ZL_FX_INT(4), &r));
    TEST_ASSERT_EQUAL_INT(ZL_FX_ONE / 4, r);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_fx_mul_checked(1, 1, NULL));
}

static void test_isqrt_is_exact_floor(void)
{
    uint32_t i;
    for (i = 0; i < 5000; i++) {
        uint32_t r = zl_isqrt32(i);
        TEST_ASSERT_TRUE(r * r <= i && (r + 1) * (r + 1) > i);
    }
    {
        /* Random values over the whole range, and squares and their neighbours. */
        uint32_t x = 2463534242u, k;
        for (k = 0; k < 20000; k++) {
            uint32_t r;
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            r = zl_isqrt32(x >> (k % 32));
            TEST_ASSERT_TRUE((uint64_t)r * r <= (x >> (k % 32)) && ((uint64_t)r + 1) * (r + 1) > (x >> (k % 32)));
        }
        for (k = 1; k < 65536; k += 37) {
            TEST_ASSERT_EQUAL_UINT(k, zl_isqrt32(k * k));
            TEST_ASSERT_EQUAL_UINT(k - 1, zl_isqrt32(k * k - 1));
        }
    }
    TEST_ASSERT_EQUAL_UINT(65535u, zl_isqrt32(0xFFFFFFFFu));
    TEST_ASSERT_EQUAL_UINT(0xFFFFFFFFu, zl_isqrt64(0xFFFFFFFFFFFFFFFFull));
    TEST_ASSERT_EQUAL_UINT(3037000499u, zl_isqrt64(9223372036854775807ull));
    TEST_ASSERT_EQUAL_INT(ZL_FX_INT(3), zl_fx_sqrt(ZL_FX_INT(9)));
    TEST_ASSERT_EQUAL_INT(92681, zl_fx_sqrt(ZL_FX_INT(2))); /* floor(sqrt(2) * 65536) */
    TEST_ASSERT_EQUAL_INT(0, zl_fx_sqrt(-5));
}

/* Reference sine in integers: Taylor series in 64-bit fixed point (Q40),
 * independent of the table. */
static int64_t ref_sin_q16(int32_t a)
{
    /* x = a * 2 pi / 65536 in Q40; pi in Q40 = 3454217652358 */
    const int64_t pi_q40 = 3454217652358LL;
    int64_t x, term, sum;
    int k;
    a &= 0xFFFF;
    if (a >= 32768)
        return -ref_sin_q16(a - 32768);
    if (a > 16384)
        a = 32768 - a;
    x = (int64_t)a * (pi_q40 / 32768); /* a * 2pi/65536 */
    term = x;
    sum = x;
    for (k = 1; k < 12; k++) {
        /* term *= -x^2 / ((2k)(2k+1)), in Q40 with 128-bit-free splitting */
        int64_t x2 = (x >> 20) * (x >> 20); /* Q40 */
        term = -((term >> 20) * (x2 >> 20)) / ((2 * k) * (2 * k + 1));
        sum += term;
    }
    return (sum + ((int64_t)1 << 23)) >> 24; /* Q40 -> Q16, rounded */
}

/* floor(a b / 2^60) for |a|, |b| < 2^62, from 32-bit halves (a unit or two
 * of 2^-60 low: the truncated partial products). */
static int64_t mul_q60(int64_t a, int64_t b)
{
    int neg = (a < 0) != (b < 0);
    uint64_t ua = (uint64_t)(a < 0 ? -a : a), ub = (uint64_t)(b < 0 ? -b : b);
    uint64_t ah = ua >> 32, al = ua & 0xFFFFFFFFu, bh = ub >> 32, bl = ub & 0xFFFFFFFFu;
    uint64_t m = ah * bh * 16u + ((ah * bl + al * bh) >> 28) + ((al * bl) >> 60);
    return neg ? -(int64_t)m : (int64_t)m;
}

/* The same in Q60 (error below 2^-55, so round(65536 sin) is exact unless
 * the value is that close to a rounding tie), for the nodes: four times the
 * work of ref_sin_q16 (on the ATmega2560 the sweep took 50 s with it). */
static int64_t ref_sin_exact_q16(int32_t a) /* a in 0 .. 16384: the first quarter's nodes */
{
    const int64_t pi_q60 = INT64_C(3622009729038561421); /* pi 2^60, rounded */
    int64_t x, x2, term, sum;
    int k;
    x = (int64_t)a * (pi_q60 / 32768); /* a 2 pi / 65536, below 2^61 */
    x2 = mul_q60(x, x);
    term = x;
    sum = x;
    for (k = 1; k < 16; k++) {
        term = -mul_q60(term, x2) / ((2 * k) * (2 * k + 1));
        sum += term;
    }
    return (sum + ((int64_t)1 << 43)) >> 44; /* Q60 -> Q16, rounded */
}

static void test_sine_table_within_one_unit(void)
{
    int32_t a;
    int32_t worst = 0;
    /* every angle of a period and a half, both functions: the header
     * promises one unit (1/65536) from the rounded exact value */
    for (a = -70000; a < 70000; a++) {
        int64_t e = ref_sin_q16(a);
        int64_t d = zl_sin(a) - e;
        if (d < 0)
            d = -d;
        if (d > worst)
            worst = (int32_t)d;
        TEST_ASSERT_INT_WITHIN(1, ref_sin_q16(a + 16384), zl_cos(a));
    }
    TEST_ASSERT_LESS_OR_EQUAL(1, worst);
    /* at the nodes (every 64 units of the first quarter) the sine is the
     * exact value rounded, whether a table or (ZL_FAST_PATHS=0) a
     * polynomial gives it: test_fixed_fast_paths_off */
    for (a = 0; a <= 16384; a += 64)
        TEST_ASSERT_EQUAL_INT64(ref_sin_exact_q16(a), zl_sin(a));
    TEST_ASSERT_EQUAL_INT(0, zl_sin(0));
    TEST_ASSERT_EQUAL_INT(ZL_FX_ONE, zl_sin(16384));
    TEST_ASSERT_EQUAL_INT(-ZL_FX_ONE, zl_sin(49152));
    TEST_ASSERT_EQUAL_INT(ZL_FX_ONE, zl_cos(0));
    TEST_ASSERT_EQUAL_INT(16384, zl_angle_from_deg(ZL_FX_INT(90)));
    TEST_ASSERT_EQUAL_INT(10923, zl_angle_from_deg(ZL_FX_INT(60))); /* 10922.67 */
}

static void test_matrices(void)
{
    zl_mat4 m, r, p;
    zl_vec3 v = {ZL_FX_INT(1), ZL_FX_INT(2), ZL_FX_INT(3)};
    zl_vec3 eye = {0, 0, ZL_FX_INT(5)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_vec4 o;
    zl_mat4_rotate_z(&r, 16384); /* 90 degrees: x -> y */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_transform_point(&r, v, &o));
    TEST_ASSERT_EQUAL_INT(-ZL_FX_INT(2), o.x);
    TEST_ASSERT_EQUAL_INT(ZL_FX_INT(1), o.y);
    TEST_ASSERT_EQUAL_INT(ZL_FX_ONE, o.w);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&m, eye, target, up));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_transform_point(&m, v, &o));
    TEST_ASSERT_EQUAL_INT(ZL_FX_INT(1), o.x);
    TEST_ASSERT_EQUAL_INT(ZL_FX_INT(2), o.y);
    TEST_ASSERT_EQUAL_INT(-ZL_FX_INT(2), o.z); /* 3 - 5: in front of the camera */
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_look_at(&m, eye, eye, up));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_look_at(&m, eye, target, (zl_vec3){0, 0, ZL_FX_ONE}));
    zl_mat4_translate(&m, v);
    zl_mat4_scale(&p, (zl_vec3){ZL_FX_INT(2), ZL_FX_INT(2), ZL_FX_INT(2)});
    zl_mat4_mul(&r, &m, &p); /* scale, then translate */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_transform_point(&r, v, &o));
    TEST_ASSERT_EQUAL_INT(ZL_FX_INT(3), o.x);
    TEST_ASSERT_EQUAL_INT(ZL_FX_INT(9), o.z);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_transform_point(&r, (zl_vec3){ZL_FX_MAX, 0, 0}, &o));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_perspective(&p, 0, ZL_FX_ONE, ZL_FX_ONE, ZL_FX_INT(2)));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_perspective(&p, 10000, ZL_FX_ONE, ZL_FX_INT(2), ZL_FX_INT(2)));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_perspective(&p, 10000, 0, ZL_FX_ONE, ZL_FX_INT(2)));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_ortho(&p, ZL_FX_ONE, ZL_FX_ONE, 0, 1, 0, 1));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_mat4_perspective(NULL, 10000, ZL_FX_ONE, ZL_FX_ONE, ZL_FX_INT(2)));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_mul_div_round_to_nearest);
    RUN_TEST(test_checked_ops_report_range_errors);
    RUN_TEST(test_isqrt_is_exact_floor);
    RUN_TEST(test_sine_table_within_one_unit);
    RUN_TEST(test_matrices);
    return UNITY_END();
}
