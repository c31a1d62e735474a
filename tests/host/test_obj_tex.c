/* SPDX-License-Identifier: MIT */
/*
 * OBJ texture coordinates (zl_obj_load_mem_tex): kept per vertex as
 * (s, t) = (u, 1 - v) in Q16.16, vertices split where a position is used
 * with different vt (a seam), the plain loader unchanged.
 */
#include <string.h>

#include "unity.h"
#include "zl_obj.h"

void setUp(void) {}
void tearDown(void) {}

static zl_obj obj;
static char msg[256];

static zl_fixed fx(double v)
{
    return (zl_fixed)(v * 65536.0 + (v < 0 ? -0.5 : 0.5));
}

static void test_quad_without_seams(void)
{
    static const char text[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                               "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                               "f 1/1 2/2 3/3 4/4\n";
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem_tex(&obj, text, sizeof text - 1, "q.obj", NULL, msg, sizeof msg));
    TEST_ASSERT_EQUAL_UINT32(4, obj.vertex_count);
    TEST_ASSERT_EQUAL_UINT32(2, obj.triangle_count);
    TEST_ASSERT_NOT_NULL(obj.texcoords);
    {
        uint32_t i;
        for (i = 0; i < 4; i++) {
            /* the vertex at position (x, y) has vt (x, y): s = x, t = 1 - y */
            zl_fixed x = obj.positions[i * 3], y = obj.positions[i * 3 + 1];
            TEST_ASSERT_EQUAL_INT32(x, obj.texcoords[i * 2]);
            TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE - y, obj.texcoords[i * 2 + 1]);
        }
    }
    zl_obj_free(&obj);
    /* the plain loader keeps none */
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem(&obj, text, sizeof text - 1, "q.obj", NULL, msg, sizeof msg));
    TEST_ASSERT_NULL(obj.texcoords);
    TEST_ASSERT_EQUAL_UINT32(4, obj.vertex_count);
    zl_obj_free(&obj);
}

static void test_seam_splits_vertices(void)
{
    /* two triangles sharing the edge 2-3, each with its own vt there */
    static const char text[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                               "vt 0.25 0.5\nvt 0.75 0.5\nvt 0.5 1\nvt 0 0\nvt 1 0\n"
                               "f 1/4 2/5 3/1\n"
                               "f 1/2 3/3 4/5\n";
    uint32_t t, k, seen = 0;
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem_tex(&obj, text, sizeof text - 1, "s.obj", NULL, msg, sizeof msg));
    /* positions 1 and 3 are used with two vt each: 4 + 2 vertices */
    TEST_ASSERT_EQUAL_UINT32(6, obj.vertex_count);
    TEST_ASSERT_EQUAL_UINT32(2, obj.triangle_count);
    /* every corner carries its own face's vt */
    for (t = 0; t < 2; t++)
        for (k = 0; k < 3; k++) {
            uint16_t i = obj.indices[t * 3 + k];
            zl_fixed x = obj.positions[i * 3], y = obj.positions[i * 3 + 1];
            zl_fixed s = obj.texcoords[i * 2], tt = obj.texcoords[i * 2 + 1];
            if (t == 0 && x == 0 && y == 0) {
                TEST_ASSERT_EQUAL_INT32(fx(0), s);
                TEST_ASSERT_EQUAL_INT32(fx(1), tt);
                seen++;
            }
            if (t == 1 && x == 0 && y == 0) {
                TEST_ASSERT_EQUAL_INT32(fx(0.75), s);
                TEST_ASSERT_EQUAL_INT32(fx(0.5), tt);
                seen++;
            }
            if (t == 0 && x == ZL_FX_ONE && y == ZL_FX_ONE) {
                TEST_ASSERT_EQUAL_INT32(fx(0.25), s);
                seen++;
            }
            if (t == 1 && x == ZL_FX_ONE && y == ZL_FX_ONE) {
                TEST_ASSERT_EQUAL_INT32(fx(0.5), s);
                TEST_ASSERT_EQUAL_INT32(0, tt);
                seen++;
            }
        }
    TEST_ASSERT_EQUAL_UINT32(4, seen);
    zl_obj_free(&obj);
}

/* A face without vt in a file whose other faces have them: (0, 0) at its
 * corners. A face that mixes corners with and without vt is an error
 * (issue 26), and so is a vt that Q16.16 cannot hold (once clamped). */
static void test_faces_without_vt_get_zero(void)
{
    static const char text[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0.5 0.5\nf 1/1 2/1 3/1\nf 1 3 4\n";
    static const char mixed[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0.5 0.5\nf 1/1 2 3\n";
    static const char huge_u[] = "v 0 0 0\nvt 32768 0\n";
    static const char huge_v[] = "v 0 0 0\nvt 0 0\nvt 0 -32767\n";
    static const char edge[] = "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt -32768 -32766.99998\nf 1/1 2/1 3/1\n";
    uint32_t i;
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem_tex(&obj, text, sizeof text - 1, "m.obj", NULL, msg, sizeof msg));
    /* 1, 2, 3 with the vt; 1, 3, 4 without it: split into 6 vertices. */
    TEST_ASSERT_EQUAL_UINT32(6, obj.vertex_count);
    for (i = 0; i < 6; i++) {
        unsigned tri = i < 3 ? 0u : 1u, c = i % 3u;
        uint16_t v = obj.indices[tri * 3 + c];
        TEST_ASSERT_EQUAL_INT32(tri == 0 ? fx(0.5) : 0, obj.texcoords[v * 2]);     /* u */
        TEST_ASSERT_EQUAL_INT32(tri == 0 ? fx(0.5) : 0, obj.texcoords[v * 2 + 1]); /* t = 1 - v */
    }
    zl_obj_free(&obj);
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_ERR_PARSE, zl_obj_load_mem_tex(&obj, mixed, sizeof mixed - 1, "m.obj", NULL, msg, sizeof msg));
    TEST_ASSERT_TRUE_MESSAGE(strstr(msg, "m.obj:5: a face mixes corners") != NULL, msg);
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_ERR_LIMIT, zl_obj_load_mem_tex(&obj, huge_u, sizeof huge_u - 1, "m.obj", NULL, msg, sizeof msg));
    TEST_ASSERT_TRUE_MESSAGE(strstr(msg, "m.obj:2: texture coordinate (32768, 0) is outside") != NULL, msg);
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_ERR_LIMIT, zl_obj_load_mem_tex(&obj, huge_v, sizeof huge_v - 1, "m.obj", NULL, msg, sizeof msg));
    TEST_ASSERT_TRUE_MESSAGE(strstr(msg, "m.obj:3: texture coordinate") != NULL, msg);
    /* The extremes Q16.16 holds: u = -32768, 1 - v = 32767.99998. */
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, zl_obj_load_mem_tex(&obj, edge, sizeof edge - 1, "m.obj", NULL, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_INT32(INT32_MIN, obj.texcoords[0]);
    zl_obj_free(&obj);
}

/* A negative vt index counts back from the last vt defined before the
 * face's line, not from the end of the file. */
static void test_relative_vt_counts_back_from_the_face(void)
{
    static const char text[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                               "vt 0.25 0\nvt 0.5 0\nvt 0.75 0\n"
                               "f 1/-3 2/-2 3/-1\n"
                               "vt 0.125 0\nvt 0.0625 0\n";
    uint32_t i;
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem_tex(&obj, text, sizeof text - 1, "r.obj", NULL, msg, sizeof msg));
    TEST_ASSERT_EQUAL_UINT32(3, obj.vertex_count);
    for (i = 0; i < 3; i++) {
        zl_fixed x = obj.positions[i * 3], y = obj.positions[i * 3 + 1];
        double want = x != 0 ? 0.5 : y != 0 ? 0.75 : 0.25;
        TEST_ASSERT_EQUAL_INT32(fx(want), obj.texcoords[i * 2]);
    }
    zl_obj_free(&obj);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_quad_without_seams);
    RUN_TEST(test_seam_splits_vertices);
    RUN_TEST(test_faces_without_vt_get_zero);
    RUN_TEST(test_relative_vt_counts_back_from_the_face);
    return UNITY_END();
}
