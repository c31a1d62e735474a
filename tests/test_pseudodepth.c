/* SPDX-License-Identifier: MIT */
/*
 * Pseudodepth: near -> 0, far -> 65535, monotonic, A + B/z, linear in
 * screen space through the whole pipeline, and the precision function.
 * Expected values come from the formula evaluated in double precision here,
 * independent of the integer code under test.
 */
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_target.h"

void setUp(void) {}
void tearDown(void) {}

#define N_NEAR (ZL_FX_ONE / 2)
#define N_FAR ZL_FX_INT(100)

static double formula(double n, double f, double z)
{
    double a = f / (f - n), b = -f * n / (f - n);
    return (a + b / z) * 65535.0;
}

static void test_near_far_monotonic_formula(void)
{
    zl_fixed z;
    uint16_t prev = 0;
    TEST_ASSERT_EQUAL_UINT16(0, zl_depth_of_distance(N_NEAR, N_FAR, N_NEAR));
    TEST_ASSERT_EQUAL_UINT16(65535, zl_depth_of_distance(N_NEAR, N_FAR, N_FAR));
    TEST_ASSERT_EQUAL_UINT16(0, zl_depth_of_distance(N_NEAR, N_FAR, 1));
    TEST_ASSERT_EQUAL_UINT16(65535, zl_depth_of_distance(N_NEAR, N_FAR, ZL_FX_MAX));
    for (z = N_NEAR; z <= N_FAR; z += 997) {
        uint16_t d = zl_depth_of_distance(N_NEAR, N_FAR, z);
        double e = formula(0.5, 100.0, z / 65536.0);
        TEST_ASSERT_TRUE(d >= prev);
        TEST_ASSERT_TRUE(d > e - 0.51 && d < e + 0.51); /* rounded correctly */
        prev = d;
    }
}

/* Draw a fronto-parallel square at eye distance `dist` through the pipeline
 * and return the depth stored at the centre pixel. */
static uint16_t pipeline_depth(zl_fixed dist, const zl_mat4 *proj)
{
    static uint16_t depth[8 * 8] ZT_ALIGNED(2);
    zl_target t;
    zl_context ctx;
    zl_rgb black = {0, 0, 0};
    zl_fixed s = dist; /* half-size grows with distance: always covers the view */
    zl_fixed pos[12] = {-s, -s, -dist, s, -s, -dist, s, s, -dist, -s, s, -dist};
    uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    zl_mesh m;
    memset(&t, 0, sizeof t);
    memset(&m, 0, sizeof m);
    t.depth = depth;
    t.depth_stride = 16;
    t.width = 8;
    t.height = 8;
    t.format = ZL_FORMAT_RGB565;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
    zl_clear(&ctx, black, 65535);
    m.positions = pos;
    m.indices = idx;
    m.vertex_count = 4;
    m.triangle_count = 2;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, proj));
    return depth[4 * 8 + 4];
}

static void test_pipeline_agrees_with_formula(void)
{
    zl_mat4 proj;
    static const int dists_q8[] = {128, 200, 256, 512, 1000, 2560, 6400, 20000, 25599};
    unsigned i;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, 16384, ZL_FX_ONE, N_NEAR, N_FAR));
    for (i = 0; i < sizeof dists_q8 / sizeof dists_q8[0]; i++) {
        zl_fixed z = (zl_fixed)dists_q8[i] * 256; /* zl_fixed: int may have 16 bits */
        uint16_t got = pipeline_depth(z, &proj);
        /* The matrix holds A and B rounded to Q16.16: allow 2 steps. */
        TEST_ASSERT_INT_WITHIN(2, zl_depth_of_distance(N_NEAR, N_FAR, z), got);
    }
}

/*
 * Linear in screen space: a plane tilted along x, seen through the pipeline.
 * At each pixel centre of the middle row the depth stored (stepped purely by
 * addition) must equal the depth of the eye-space point that pixel sees.
 * A quad from (x, -1, -2) to (x, 1, -(2 + 3 (x + 1))) for x in [-1, 1].
 */
static void test_depth_linear_in_screen_space(void)
{
    enum { W = 64, H = 8 };
    static uint16_t depth[W * H];
    zl_mat4 proj;
    zl_target t;
    zl_context ctx;
    zl_mesh m;
    zl_rgb black = {0, 0, 0};
    const zl_fixed one = ZL_FX_ONE;
    zl_fixed pos[12] = {-one, -one, -2 * one, one, -one, -8 * one, one, one, -8 * one, -one, one, -2 * one};
    uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    int i, checked = 0;
    memset(&t, 0, sizeof t);
    memset(&m, 0, sizeof m);
    t.depth = depth;
    t.depth_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB565;
    /* fovy 90 degrees and aspect 1 (non-square pixels): x_ndc = x_eye / dist */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, 16384, ZL_FX_ONE, ZL_FX_ONE, N_FAR));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
    zl_clear(&ctx, black, 65535);
    m.positions = pos;
    m.indices = idx;
    m.vertex_count = 4;
    m.triangle_count = 2;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, &proj));
    for (i = 0; i < W; i++) {
        /* Pixel centre -> x_ndc; the ray x_eye = x_ndc * d meets the plane
         * d = 2 + 3 (x_eye + 1) at d = 5 / (1 - 3 * x_ndc). */
        double xn = ((i + 0.5) / W) * 2.0 - 1.0;
        double denom = 1.0 - 3.0 * xn;
        double d, xe, expected;
        if (denom <= 0)
            continue;
        d = 5.0 / denom;
        xe = xn * d;
        if (xe <= -0.99 || xe >= 0.99)
            continue; /* off the quad */
        expected = formula(1.0, 100.0, d);
        TEST_ASSERT_TRUE_MESSAGE(depth[(H / 2) * W + i] != 65535, "pixel of the quad not drawn");
        TEST_ASSERT_INT_WITHIN(2, (int64_t)(expected + 0.5), depth[(H / 2) * W + i]);
        checked++;
    }
    TEST_ASSERT_GREATER_THAN(5, checked);
}

static void test_precision_function_matches_mapping(void)
{
    static const int z_units[] = {1, 2, 5, 10, 20, 50};
    unsigned i;
    /* Far away, 16 bits at n = 0.5, f = 100: dz = k z^2 / (1 - k z). */
    for (i = 0; i < sizeof z_units / sizeof z_units[0]; i++) {
        zl_fixed z = ZL_FX_INT(z_units[i]);
        zl_fixed dz = zl_depth_resolution(N_NEAR, N_FAR, z, 16);
        double k = (100.0 - 0.5) / (65535.0 * 100.0 * 0.5);
        double zz = z_units[i];
        double e = k * zz * zz / (1 - k * zz) * 65536.0;
        double before = formula(0.5, 100.0, zz), after = formula(0.5, 100.0, zz + dz / 65536.0);
        TEST_ASSERT_TRUE(dz >= e - 2 && dz <= e + 2);
        /* One step of depth across dz, and less than one across 0.99 dz. */
        TEST_ASSERT_TRUE(after - before >= 0.999);
        TEST_ASSERT_TRUE(formula(0.5, 100.0, zz + 0.99 * dz / 65536.0) - before < 1.0);
    }
    TEST_ASSERT_EQUAL_INT(ZL_FX_MAX, zl_depth_resolution(N_NEAR, N_FAR, ZL_FX_INT(30000), 4));
    TEST_ASSERT_EQUAL_INT(ZL_FX_MAX, zl_depth_resolution(N_NEAR, N_FAR, ZL_FX_ONE, 0));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_near_far_monotonic_formula);
    RUN_TEST(test_pipeline_agrees_with_formula);
    RUN_TEST(test_depth_linear_in_screen_space);
    RUN_TEST(test_precision_function_matches_mapping);
    return UNITY_END();
}
