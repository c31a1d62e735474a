/* SPDX-License-Identifier: MIT */
/*
 * OBJ normals: vn kept per vertex (Q14) when faces use them, carried through
 * the vt split, and computed normals (zl_obj_compute_normals) by area and
 * by angle against hand-worked values.
 */
#include <string.h>

#include "unity.h"
#include "zl_obj.h"

void setUp(void) {}
void tearDown(void) {}

static zl_obj obj;
static char msg[256];

static void assert_normal(int x, int y, int z, const int16_t *n)
{
    TEST_ASSERT_INT_WITHIN(0, x, n[0]);
    TEST_ASSERT_INT_WITHIN(0, y, n[1]);
    TEST_ASSERT_INT_WITHIN(0, z, n[2]);
}

static void test_vn_kept_and_normalised(void)
{
    /* vn of any length; vertex 4 has two different vn (smoothed) */
    static const char text[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                               "vn 0 0 2\nvn 3 0 4\nvn 0 3 4\n"
                               "f 1//1 2//2 4//2\nf 1//1 4//3 3//3\n";
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem(&obj, text, sizeof text - 1, "n.obj", NULL, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL(obj.normals);
    assert_normal(0, 0, 16384, &obj.normals[0]);
    assert_normal(9830, 0, 13107, &obj.normals[3]);  /* (0.6, 0, 0.8) */
    assert_normal(0, 9830, 13107, &obj.normals[6]);
    /* (0.6, 0.6, 1.6) / |.| = (0.3313, 0.3313, 0.8835) */
    assert_normal(5428, 5428, 14474, &obj.normals[9]);
    zl_obj_free(&obj);
    /* no vn: no normals */
    {
        static const char plain[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem(&obj, plain, sizeof plain - 1, "p.obj", NULL, msg, sizeof msg));
        TEST_ASSERT_NULL(obj.normals);
        zl_obj_free(&obj);
    }
}

static void test_vn_follow_the_vt_split(void)
{
    static const char text[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                               "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\nvt 0.5 0.5\n"
                               "vn 0 0 1\nvn 1 0 0\n"
                               "f 1/1/1 2/2/2 4/4/2\nf 1/5/1 4/4/2 3/3/1\n";
    uint32_t i;
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem_tex(&obj, text, sizeof text - 1, "s.obj", NULL, msg, sizeof msg));
    TEST_ASSERT_EQUAL_UINT32(5, obj.vertex_count); /* vertex 1 split by vt */
    TEST_ASSERT_NOT_NULL(obj.normals);
    for (i = 0; i < obj.vertex_count; i++) {
        zl_fixed x = obj.positions[i * 3], y = obj.positions[i * 3 + 1];
        if (x == 0) /* vertices 1 and 3: vn 1 */
            assert_normal(0, 0, 16384, &obj.normals[i * 3]);
        else if (y == 0) /* vertex 2: vn 2 */
            assert_normal(16384, 0, 0, &obj.normals[i * 3]);
    }
    zl_obj_free(&obj);
}

/* Three faces of a unit cube meeting at the origin, triangulated so that
 * the origin is in one triangle of the z face and in two of the others. By
 * angle (90 degrees from each face) it gets -(1,1,1)/sqrt 3 whatever the
 * triangulation; by area the z face counts half. */
static void test_computed_normals_area_and_angle(void)
{
    static const char text[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\n"
                               /* bottom z = 0 (outward -z): one triangle at the origin */
                               "f 1 4 2\nf 2 4 3\n"
                               /* y = 0 (outward -y): one triangle at the origin */
                               "f 1 2 6\nf 1 6 5\n"
                               /* x = 0 (outward -x) */
                               "f 1 5 7\nf 1 7 4\n";
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem(&obj, text, sizeof text - 1, "c.obj", NULL, msg, sizeof msg));
    TEST_ASSERT_NULL(obj.normals);
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_compute_normals(&obj, ZL_OBJ_NORMALS_ANGLE));
    assert_normal(-9459, -9459, -9459, &obj.normals[0]);
    /* vertex 2 (1,0,0): 45 + 45 degrees on z, 90 on y: (0,-1,-1)/sqrt 2 */
    assert_normal(0, -11585, -11585, &obj.normals[3]);
    assert_normal(0, 0, -16384, &obj.normals[6]); /* vertex 3: the z face only */
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_compute_normals(&obj, ZL_OBJ_NORMALS_AREA));
    /* origin: areas z 1/2, y 1, x 1: (-1, -1, -1/2) / 1.5 */
    assert_normal(-10923, -10923, -5461, &obj.normals[0]);
    /* vertex 2: z 1/2 + 1/2, y 1/2: (0, -1/2, -1) / |.| = (0, -0.4472, -0.8944) */
    assert_normal(0, -7327, -14654, &obj.normals[3]);
    assert_normal(0, 0, -16384, &obj.normals[6]);
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_ERR_ARG, zl_obj_compute_normals(&obj, (zl_obj_normal_weight)7));
    zl_obj_free(&obj);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_vn_kept_and_normalised);
    RUN_TEST(test_vn_follow_the_vt_split);
    RUN_TEST(test_computed_normals_area_and_angle);
    return UNITY_END();
}
