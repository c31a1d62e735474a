/* SPDX-License-Identifier: MIT */
/*
 * The classic worked example of edge-table depth interpolation, checked
 * against the project's own edge steppers and depth plane (white-box: it
 * reads the internal stepper state).
 *
 * Triangle a=(3,1,1), b=(7,4,2), c=(4,7,4) as (x, y, z). In the form
 * (y_max, x at y_min, dx/dy, z at y_min, dz/dy) the edge table holds
 *   at y=1: ac = (7, 3, 1/6, 1, 3/6), ab = (4, 3, 4/3, 1, 1/3)
 *   at y=4: cb = (7, 7, -1, 2, 2/3)
 * and stepping gives
 *   y=2: ac x=3.1667 z=1.5,    ab x=4.3333 z=1.3333
 *   y=3: ac x=3.3333 z=2.0,    ab x=5.6667 z=1.6667
 *
 * Mapping to zline: scan line y is the row whose centre is at window
 * y + 0.5, so the example's point (x, y) sits at window (x + 0.5, y + 0.5);
 * z maps to window depth z/4. The stepper holds the exact crossing as
 * x - rem/den (in pixels, relative to the centre offset), so each expected
 * x is checked exactly as a rational, and z at the crossing from the plane.
 */
#include "../core/src/1_base/zl_internal.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static zl_wvert vert(int x, int y, int z)
{
    zl_wvert v;
    v.x = x * 16 + 8;
    v.y = y * 16 + 8;
    v.z = (uint32_t)z * 65535u * 16384u; /* z/4 of the depth range, Q16 */
    v.r = v.g = v.b = 0;
    return v;
}

/* 6 * (exact crossing x of edge e) in the example's units. */
static int64_t crossing_x6(const zl_edge *e, int64_t *den)
{
    *den = e->den;
    return 6 * ((int64_t)e->x * e->den - e->rem);
}

/* Depth at the crossing, in units of the example's z (Q20 / (65535/4)). */
static double crossing_z(const zl_active *t, const zl_edge *e)
{
    double x = (double)e->x - (double)e->rem / e->den;
    double v = (double)t->z.row + (x - t->ax) * (double)t->z.dx;
    return v / (double)(INT32_C(1) << 20) / 65535.0 * 4.0;
}

static void check_edge(const zl_active *t, const zl_edge *e, int x6_expected, double z_expected)
{
    int64_t den, x6 = crossing_x6(e, &den);
    TEST_ASSERT_EQUAL_INT64((int64_t)x6_expected * den, x6);
    TEST_ASSERT_TRUE(crossing_z(t, e) > z_expected - 0.0005 && crossing_z(t, e) < z_expected + 0.0005);
}

static void test_worked_example(void)
{
    zl_wvert a = vert(3, 1, 1), b = vert(7, 4, 2), c = vert(4, 7, 4);
    zl_state st;
    zl_poly poly;
    zl_active t;
    zl_span_state ss;
    static uint16_t zrow[16];
    zl_state_default(&st);
    poly.flat = st.color;
    zl_span_state_init(&ss, &st, 1, 0, ZL_FORMAT_RGB565, 16);
    TEST_ASSERT_EQUAL_INT(1, zl_tri_setup(&t, NULL, &a, &b, &c, &poly, &st, 16, 16));
    TEST_ASSERT_EQUAL_INT(1, t.row);  /* y_min of the edge table */
    TEST_ASSERT_EQUAL_INT(7, t.end);  /* y_max: the row at y=7 is a bottom vertex, excluded */
    TEST_ASSERT_EQUAL_INT(4, t.mid);  /* cb enters the edge table at y=4 */
    /* y=1: ac (left) x=3 z=1, ab (right) x=3 z=1 */
    check_edge(&t, &t.left, 18, 1.0);
    check_edge(&t, &t.right, 18, 1.0);
    zl_tri_row(&t, NULL, &ss, NULL, zrow);
    /* y=2: ac x=3.1667 (19/6) z=1.5, ab x=4.3333 (26/6) z=1.3333 */
    check_edge(&t, &t.left, 19, 1.5);
    check_edge(&t, &t.right, 26, 4.0 / 3.0);
    zl_tri_row(&t, NULL, &ss, NULL, zrow);
    /* y=3: ac x=3.3333 z=2.0, ab x=5.6667 (34/6) z=1.6667 */
    check_edge(&t, &t.left, 20, 2.0);
    check_edge(&t, &t.right, 34, 5.0 / 3.0);
    zl_tri_row(&t, NULL, &ss, NULL, zrow);
    /* y=4: cb replaces ab: x=7 z=2; ac x=3.5 z=2.5 */
    check_edge(&t, &t.right, 42, 2.0);
    check_edge(&t, &t.left, 21, 2.5);
    /* dx/dy of the steppers: ac 1/6 -> step 0, ab 4/3 -> 1 + carry, cb -1 */
    TEST_ASSERT_EQUAL_INT(-1, t.right.step);
    TEST_ASSERT_EQUAL_INT(0, t.right.rstep);
    TEST_ASSERT_EQUAL_INT(0, t.left.step);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_worked_example);
    return UNITY_END();
}
