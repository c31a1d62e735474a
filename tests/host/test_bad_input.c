/* SPDX-License-Identifier: MIT */
/*
 * Bad input end to end, and the LIMITS that need more memory than the
 * portable suite may use (host only):
 *   - an OBJ coordinate beyond Q16.16 is a FILE:LINE error; one inside
 *     Q16.16 but beyond the transform limit (+-16384.0) loads, and then
 *     zl_draw_mesh / zl_frame_add_mesh refuse it with ZL_ERR_RANGE and write
 *     nothing (a guarded target, compared byte for byte);
 *   - a mesh of 65535 vertices and 65535 triangles (the uint16 limit) draws
 *     in frame and scanline mode with identical bytes; one more triangle in
 *     the frame is ZL_ERR_CAPACITY;
 *   - a 4096 x 4096 target (ZL_MAX_DIM) in frame mode equals scanline mode
 *     byte for byte on a perspective scene with clipped triangles.
 */
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "zl_obj.h"
#include "zline/zline.h"

static char msg[256];

void setUp(void)
{
}

void tearDown(void)
{
}

static void test_obj_coordinate_beyond_q16(void)
{
    zl_obj obj;
    static const char text[] = "v 0 0 0\nv 40000 0 0\nv 0 1 0\nf 1 2 3\n";
    zl_obj_status st = zl_obj_load_mem(&obj, text, sizeof text - 1, "big.obj", NULL, msg, sizeof msg);
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_ERR_PARSE, st);
    TEST_ASSERT_NOT_NULL(strstr(msg, "big.obj:2:"));
    TEST_ASSERT_NOT_NULL(strstr(msg, "Q16.16"));
    TEST_ASSERT_NULL(obj.positions);
    TEST_ASSERT_NULL(obj.indices);
}

/* A guarded full target: 64 guard bytes around each plane. */
typedef struct {
    uint8_t *color_block, *depth_block;
    size_t color_bytes, depth_bytes;
    zl_target t;
} big_target;

#define GUARD 64u

static void big_make(big_target *b, unsigned w, unsigned h)
{
    b->color_bytes = (size_t)w * h * 2;
    b->depth_bytes = (size_t)w * h * 2;
    b->color_block = (uint8_t *)malloc(b->color_bytes + 2 * GUARD);
    b->depth_block = (uint8_t *)malloc(b->depth_bytes + 2 * GUARD);
    TEST_ASSERT_TRUE(b->color_block != NULL);
    TEST_ASSERT_TRUE(b->depth_block != NULL);
    memset(b->color_block, 0xA5, b->color_bytes + 2 * GUARD);
    memset(b->depth_block, 0x5A, b->depth_bytes + 2 * GUARD);
    b->t.color = b->color_block + GUARD;
    b->t.color_stride = (int32_t)(w * 2);
    b->t.depth = (uint16_t *)(void *)(b->depth_block + GUARD);
    b->t.depth_stride = (int32_t)(w * 2);
    b->t.width = (uint16_t)w;
    b->t.height = (uint16_t)h;
    b->t.format = ZL_FORMAT_RGB565;
}

static int big_guards_intact(const big_target *b)
{
    size_t i;
    for (i = 0; i < GUARD; i++)
        if (b->color_block[i] != 0xA5 || b->color_block[GUARD + b->color_bytes + i] != 0xA5 ||
            b->depth_block[i] != 0x5A || b->depth_block[GUARD + b->depth_bytes + i] != 0x5A)
            return 0;
    return 1;
}

static void big_free(big_target *b)
{
    free(b->color_block);
    free(b->depth_block);
}

static void camera(zl_mat4 *mvp, zl_fixed aspect)
{
    zl_mat4 proj, view;
    zl_vec3 eye = {ZL_FX_INT(1), ZL_FX_INT(2), ZL_FX_INT(3)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(70)), aspect,
                                                     ZL_FX_ONE / 4, ZL_FX_INT(50)));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
    zl_mat4_mul(mvp, &proj, &view);
}

static void test_obj_beyond_transform_limit_writes_nothing(void)
{
    zl_obj obj;
    static const char text[] = "v 0 0 0\nv 20000 0 0\nv 0 1 0\nf 1 2 3\n";
    big_target b;
    zl_context ctx;
    zl_mat4 mvp;
    zl_mesh mesh;
    uint8_t *before;
    TEST_ASSERT_EQUAL_INT(ZL_OBJ_OK, zl_obj_load_mem(&obj, text, sizeof text - 1, "far.obj", NULL, msg, sizeof msg));
    mesh = zl_obj_mesh(&obj);
    big_make(&b, 64, 48);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &b.t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, (zl_rgb){10, 20, 30}, 65535));
    before = (uint8_t *)malloc(b.color_bytes + b.depth_bytes);
    TEST_ASSERT_TRUE(before != NULL);
    memcpy(before, b.t.color, b.color_bytes);
    memcpy(before + b.color_bytes, b.t.depth, b.depth_bytes);
    camera(&mvp, ZL_FX_ONE * 4 / 3);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &mesh, &mvp));
    TEST_ASSERT_EQUAL_MEMORY(before, b.t.color, b.color_bytes);
    TEST_ASSERT_EQUAL_MEMORY(before + b.color_bytes, b.t.depth, b.depth_bytes);
    TEST_ASSERT_TRUE(big_guards_intact(&b));
    /* scanline mode refuses it at submission */
    {
        zl_frame_config cfg;
        zl_frame f;
        zl_state st;
        size_t bytes;
        uint64_t *work;
        memset(&cfg, 0, sizeof cfg);
        cfg.width = 64;
        cfg.height = 48;
        cfg.band_rows = 1;
        cfg.format = ZL_FORMAT_RGB565;
        cfg.color_buffers = 1;
        cfg.max_meshes = 1;
        cfg.max_vertices = 3;
        cfg.max_triangles = 1;
        cfg.max_active = 1;
        bytes = zl_frame_bytes(&cfg);
        work = (uint64_t *)calloc((bytes + 7) / 8, 8);
        TEST_ASSERT_TRUE(work != NULL);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, bytes, (zl_rgb){0, 0, 0}, 65535));
        zl_state_default(&st);
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_frame_add_mesh(&f, &mesh, &mvp, &st));
        free(work);
    }
    free(before);
    big_free(&b);
    zl_obj_free(&obj);
}

/* Render `n` meshes in scanline mode (band of `band` rows) and compare every
 * band with the full target t. Returns the number of differing rows. */
static unsigned scanline_vs_frame(const zl_target *t, const zl_mesh *meshes, const zl_mat4 *const *mvps,
                                  unsigned n, uint16_t band, uint32_t max_active)
{
    zl_frame_config cfg;
    zl_frame f;
    zl_state st;
    zl_band bd;
    size_t bytes;
    uint64_t *work;
    unsigned i, bad = 0;
    uint32_t verts = 0, tris = 0;
    for (i = 0; i < n; i++) {
        verts += meshes[i].vertex_count;
        tris += meshes[i].triangle_count;
    }
    memset(&cfg, 0, sizeof cfg);
    cfg.width = t->width;
    cfg.height = t->height;
    cfg.band_rows = band;
    cfg.format = ZL_FORMAT_RGB565;
    cfg.color_buffers = 1;
    cfg.max_meshes = (uint16_t)n;
    cfg.max_vertices = verts;
    cfg.max_triangles = tris;
    cfg.max_active = max_active;
    bytes = zl_frame_bytes(&cfg);
    TEST_ASSERT_TRUE(bytes > 0);
    work = (uint64_t *)calloc((bytes + 7) / 8, 8);
    TEST_ASSERT_TRUE(work != NULL);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, bytes, (zl_rgb){10, 20, 30}, 65535));
    zl_state_default(&st);
    for (i = 0; i < n; i++)
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &meshes[i], mvps[i], &st));
    while (zl_frame_next_band(&f, &bd) == ZL_OK) {
        unsigned r;
        for (r = 0; r < bd.rows; r++) {
            size_t y = (size_t)bd.first_row + r;
            const uint8_t *want_c = (const uint8_t *)t->color + y * (size_t)t->color_stride;
            const uint8_t *want_z = (const uint8_t *)t->depth + y * (size_t)t->depth_stride;
            if (memcmp(want_c, (const uint8_t *)bd.color + (size_t)r * (size_t)bd.color_stride, (size_t)t->width * 2) ||
                memcmp(want_z, (const uint8_t *)bd.depth + (size_t)r * (size_t)bd.depth_stride, (size_t)t->width * 2))
                bad++;
        }
    }
    free(work);
    return bad;
}

static void test_max_vertices_and_triangles(void)
{
    const unsigned nv = 65535, nt = 65535, gw = 256;
    zl_fixed *pos = (zl_fixed *)malloc((size_t)nv * 3 * sizeof(zl_fixed));
    uint16_t *idx = (uint16_t *)malloc((size_t)nt * 3 * sizeof(uint16_t));
    zl_mesh mesh, one;
    const zl_mat4 *none[2] = {NULL, NULL};
    big_target b;
    zl_context ctx;
    unsigned i, t = 0, lit = 0;
    TEST_ASSERT_TRUE(pos != NULL);
    TEST_ASSERT_TRUE(idx != NULL);
    /* vertex i at grid point (i % 256, i / 256) pixels; two triangles per
     * cell in row-major order until 65535 of them */
    for (i = 0; i < nv; i++) {
        pos[i * 3] = ZL_FX_INT((int32_t)(i % gw));
        pos[i * 3 + 1] = ZL_FX_INT((int32_t)(i / gw));
        pos[i * 3 + 2] = ZL_FX_ONE / 2;
    }
    for (i = 0; t < nt; i++) {
        unsigned x = i % gw, y = i / gw, v = y * gw + x;
        if (x == gw - 1)
            continue;
        idx[t * 3] = (uint16_t)v;
        idx[t * 3 + 1] = (uint16_t)(v + 1);
        idx[t * 3 + 2] = (uint16_t)(v + gw);
        t++;
        if (t == nt)
            break;
        idx[t * 3] = (uint16_t)(v + 1);
        idx[t * 3 + 1] = (uint16_t)(v + gw + 1);
        idx[t * 3 + 2] = (uint16_t)(v + gw);
        t++;
    }
    mesh.positions = pos;
    mesh.indices = idx;
    mesh.vertex_colors = NULL;
    mesh.face_colors = NULL;
    mesh.vertex_count = (uint16_t)nv;
    mesh.triangle_count = (uint16_t)nt;
    big_make(&b, 256, 256);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &b.t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, (zl_rgb){10, 20, 30}, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, NULL));
    TEST_ASSERT_TRUE(big_guards_intact(&b));
    for (i = 0; i < 256u * 256u; i++)
        lit += ((const uint16_t *)b.t.color)[i] == 0xFFFFu;
    /* 32767 whole cells, each exactly its pixel, and half of the next */
    TEST_ASSERT_INT_WITHIN(1, 32767, lit);
    TEST_ASSERT_EQUAL_UINT(0, scanline_vs_frame(&b.t, &mesh, none, 1, 7, 4096));

    /* one triangle more in the same frame: over the 65535 triangles a frame
     * numbers */
    {
        zl_frame_config cfg;
        zl_frame f;
        zl_state st;
        size_t bytes;
        uint64_t *work;
        one = mesh;
        one.triangle_count = 1;
        memset(&cfg, 0, sizeof cfg);
        cfg.width = 256;
        cfg.height = 256;
        cfg.band_rows = 1;
        cfg.format = ZL_FORMAT_RGB565;
        cfg.color_buffers = 1;
        cfg.max_meshes = 2;
        cfg.max_vertices = 2u * nv;
        cfg.max_triangles = 65535;
        cfg.max_active = 4096;
        bytes = zl_frame_bytes(&cfg);
        work = (uint64_t *)calloc((bytes + 7) / 8, 8);
        TEST_ASSERT_TRUE(work != NULL);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, bytes, (zl_rgb){0, 0, 0}, 65535));
        zl_state_default(&st);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &mesh, NULL, &st));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_frame_add_mesh(&f, &one, NULL, &st));
        cfg.max_triangles = 65536;
        TEST_ASSERT_EQUAL_UINT(0, zl_frame_bytes(&cfg));
        free(work);
    }
    big_free(&b);
    free(pos);
    free(idx);
}

static void test_window_4096_frame_equals_scanline(void)
{
    /* a cube of 12 triangles seen from close by, most of them clipped by the
     * near plane or the viewport, plus one far beyond the guard band */
    static const zl_fixed pos[] = {
        ZL_FX_INT(-1), ZL_FX_INT(-1), ZL_FX_INT(-1), ZL_FX_INT(1), ZL_FX_INT(-1), ZL_FX_INT(-1),
        ZL_FX_INT(1),  ZL_FX_INT(1),  ZL_FX_INT(-1), ZL_FX_INT(-1), ZL_FX_INT(1), ZL_FX_INT(-1),
        ZL_FX_INT(-1), ZL_FX_INT(-1), ZL_FX_INT(1),  ZL_FX_INT(1),  ZL_FX_INT(-1), ZL_FX_INT(1),
        ZL_FX_INT(1),  ZL_FX_INT(1),  ZL_FX_INT(1),  ZL_FX_INT(-1), ZL_FX_INT(1),  ZL_FX_INT(1),
        ZL_FX_INT(-9000), ZL_FX_INT(-2), ZL_FX_INT(-9000), ZL_FX_INT(9000), ZL_FX_INT(-2), ZL_FX_INT(-9000),
        0, ZL_FX_INT(-2), ZL_FX_INT(9000),
    };
    static const uint16_t idx[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                   2, 3, 7, 2, 7, 6, 1, 2, 6, 1, 6, 5, 0, 4, 7, 0, 7, 3, 8, 9, 10};
    static uint8_t fc[13 * 3];
    zl_mesh mesh = {pos, idx, NULL, fc, 11, 13};
    const zl_mat4 *mvps[1];
    zl_mat4 mvp;
    big_target b;
    zl_context ctx;
    unsigned i;
    for (i = 0; i < sizeof fc; i++)
        fc[i] = (uint8_t)(i * 53u + 17u);
    camera(&mvp, ZL_FX_ONE);
    mvps[0] = &mvp;
    big_make(&b, ZL_MAX_DIM, ZL_MAX_DIM);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &b.t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, (zl_rgb){10, 20, 30}, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, &mvp));
    TEST_ASSERT_TRUE(big_guards_intact(&b));
    TEST_ASSERT_EQUAL_UINT(0, scanline_vs_frame(&b.t, &mesh, mvps, 1, 1, 13 * 7));
    big_free(&b);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_obj_coordinate_beyond_q16);
    RUN_TEST(test_obj_beyond_transform_limit_writes_nothing);
    RUN_TEST(test_max_vertices_and_triangles);
    RUN_TEST(test_window_4096_frame_equals_scanline);
    return UNITY_END();
}
