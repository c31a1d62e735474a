/* SPDX-License-Identifier: MIT */
/*
 * zline-obj2c round trip: the arrays it generated at build time (compiled
 * into this test) equal, element for element, what the OBJ loader gives for
 * the same file and options.
 *   test_obj2c BUNNY.obj TETRA.obj [FLOOR.obj]
 * FLOOR.obj (port/host/models/floor.obj) has texture coordinates: the
 * generated texcoords equal zl_obj_load_file_tex's and the file's vt lines.
 */
#include <stdio.h>
#include <string.h>

#include "bunny_mesh.h"
#include "floor_mesh.h"
#include "tetra_mesh.h"
#include "bunny_n_mesh.h"
#include "tetra_nc_mesh.h"
#include "unity.h"
#include "zl_obj.h"

static const char *bunny_path, *tetra_path, *floor_path;

void setUp(void) {}
void tearDown(void) {}

static void check(const char *path, int normalize, const zl_mesh *gen, uint32_t vcount, uint32_t tcount,
                  int colors_expected)
{
    zl_obj obj;
    zl_obj_options opt;
    char msg[256];
    zl_obj_options_default(&opt);
    opt.normalize = normalize;
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, zl_obj_load_file(&obj, path, &opt, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(obj.vertex_count, vcount);
    TEST_ASSERT_EQUAL_UINT(obj.triangle_count, tcount);
    TEST_ASSERT_EQUAL_UINT(obj.vertex_count, gen->vertex_count);
    TEST_ASSERT_EQUAL_UINT(obj.triangle_count, gen->triangle_count);
    TEST_ASSERT_EQUAL_MEMORY(obj.positions, gen->positions, 3 * 4 * obj.vertex_count);
    TEST_ASSERT_EQUAL_MEMORY(obj.indices, gen->indices, 3 * 2 * obj.triangle_count);
    if (colors_expected) {
        TEST_ASSERT_NOT_NULL(obj.vertex_colors);
        TEST_ASSERT_NOT_NULL(gen->vertex_colors);
        TEST_ASSERT_EQUAL_MEMORY(obj.vertex_colors, gen->vertex_colors, 3 * obj.vertex_count);
    } else {
        TEST_ASSERT_NULL(gen->vertex_colors);
    }
    TEST_ASSERT_NULL(gen->face_colors);
    zl_obj_free(&obj);
}

static void test_bunny_normalized(void)
{
    check(bunny_path, 1, &bunny_mesh, BUNNY_VERTEX_COUNT, BUNNY_TRIANGLE_COUNT, 0);
    TEST_ASSERT_EQUAL_INT(0, BUNNY_HAS_VERTEX_COLORS);
}

/* --normals angle: the loader's angle-weighted normals, and the same mesh */
static void test_bunny_normals(void)
{
    zl_obj obj;
    zl_obj_options opt;
    char msg[256];
    uint32_t k;
    TEST_ASSERT_EQUAL_INT(1, BUNNY_N_HAS_NORMALS);
    check(bunny_path, 1, &bunny_n_mesh, BUNNY_N_VERTEX_COUNT, BUNNY_N_TRIANGLE_COUNT, 0);
    zl_obj_options_default(&opt);
    opt.normalize = 1;
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_file(&obj, bunny_path, &opt, msg, sizeof msg));
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_compute_normals(&obj, ZL_OBJ_NORMALS_ANGLE));
    for (k = 0; k < 3 * BUNNY_N_VERTEX_COUNT; k++)
        TEST_ASSERT_EQUAL_INT(obj.normals[k], bunny_n_normals[k]);
    zl_obj_free(&obj);
}

static void test_tetra_with_colors(void)
{
    /* a quad and a negative index in the file: 5 triangles in all */
    TEST_ASSERT_EQUAL_UINT(5, TETRA_TRIANGLE_COUNT);
    TEST_ASSERT_EQUAL_INT(1, TETRA_HAS_VERTEX_COLORS);
    check(tetra_path, 0, &tetra_mesh, TETRA_VERTEX_COUNT, TETRA_TRIANGLE_COUNT, 1);
    TEST_ASSERT_TRUE(tetra_mesh.vertex_colors == tetra_vertex_colors);
    TEST_ASSERT_EQUAL_INT(-ZL_FX_ONE * 3 / 2, tetra_positions[0]);
    TEST_ASSERT_EQUAL_UINT(255, tetra_vertex_colors[0]);
}

static void test_tetra_without_colors(void)
{
    TEST_ASSERT_EQUAL_INT(0, TETRA_NC_HAS_VERTEX_COLORS);
    check(tetra_path, 0, &tetra_nc_mesh, TETRA_NC_VERTEX_COUNT, TETRA_NC_TRIANGLE_COUNT, 0);
}

/* The textured floor: 4 vertices (no vertex uses two vt), texcoords
 * (s, t) = (u, 1 - v) of its vt lines, as the loader gives them. */
static void test_floor_texcoords(void)
{
    zl_obj obj;
    char msg[256];
    unsigned k;
    TEST_ASSERT_EQUAL_INT(1, FLOOR_HAS_TEXCOORDS);
    TEST_ASSERT_EQUAL_INT(0, TETRA_HAS_TEXCOORDS);
    TEST_ASSERT_EQUAL_UINT(4, FLOOR_VERTEX_COUNT);
    /* the file pairs x = -4, 4 with u = 0, 2 and z = 0, -16 with v = 0, 4:
     * s = (x + 4) / 4, t = 1 - v = 1 + z / 4 */
    for (k = 0; k < 4; k++) {
        TEST_ASSERT_EQUAL_INT32((floor_positions[3 * k] + ZL_FX_INT(4)) / 4, floor_texcoords[2 * k]);
        TEST_ASSERT_EQUAL_INT32(ZL_FX_ONE + floor_positions[3 * k + 2] / 4, floor_texcoords[2 * k + 1]);
    }
    if (floor_path == NULL)
        return;
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK, zl_obj_load_file_tex(&obj, floor_path, NULL, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(obj.vertex_count, FLOOR_VERTEX_COUNT);
    TEST_ASSERT_EQUAL_MEMORY(obj.positions, floor_positions, 3 * 4 * obj.vertex_count);
    TEST_ASSERT_EQUAL_MEMORY(obj.indices, floor_indices, 3 * 2 * obj.triangle_count);
    TEST_ASSERT_EQUAL_MEMORY(obj.texcoords, floor_texcoords, 2 * 4 * obj.vertex_count);
    zl_obj_free(&obj);
}

int main(int argc, char **argv)
{
    if (argc != 3 && argc != 4) {
        fprintf(stderr, "usage: test_obj2c BUNNY.obj TETRA.obj [FLOOR.obj]\n");
        return 2;
    }
    bunny_path = argv[1];
    tetra_path = argv[2];
    floor_path = argc == 4 ? argv[3] : NULL;
    UNITY_BEGIN();
    RUN_TEST(test_bunny_normalized);
    RUN_TEST(test_bunny_normals);
    RUN_TEST(test_tetra_with_colors);
    RUN_TEST(test_floor_texcoords);
    RUN_TEST(test_tetra_without_colors);
    return UNITY_END();
}
