/* SPDX-License-Identifier: MIT */
/*
 * Outlines: the edge list (adjacency) of small meshes by hand, and the
 * silhouette and crease edges of a cube seen from many places against a
 * selection written here in model space (the sign of n . (eye - p) per face,
 * the dihedral angle from the face normals), drawn with the same line rule
 * for comparison; then outlines over the shaded cube with a depth offset.
 */
#include <string.h>

#include "unity.h"
#include "zline/zline.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 64, H = 48 };

static uint8_t color[W * H * 3];
static uint16_t depth[W * H];
static uint8_t want[W * H * 3];
static zl_context ctx;

/* A cube of side 2 at the origin, 12 triangles, outward normals, CCW seen
 * from outside. */
static const zl_fixed cube_pos[] = {
    -ZL_FX_ONE, -ZL_FX_ONE, -ZL_FX_ONE, ZL_FX_ONE, -ZL_FX_ONE, -ZL_FX_ONE, ZL_FX_ONE, ZL_FX_ONE, -ZL_FX_ONE,
    -ZL_FX_ONE, ZL_FX_ONE,  -ZL_FX_ONE, -ZL_FX_ONE, -ZL_FX_ONE, ZL_FX_ONE, ZL_FX_ONE, -ZL_FX_ONE, ZL_FX_ONE,
    ZL_FX_ONE,  ZL_FX_ONE,  ZL_FX_ONE,  -ZL_FX_ONE, ZL_FX_ONE,  ZL_FX_ONE};
static const uint16_t cube_idx[] = {4, 5, 6, 4, 6, 7, /* +z */ 1, 0, 3, 1, 3, 2, /* -z */
                                    5, 1, 2, 5, 2, 6, /* +x */ 0, 4, 7, 0, 7, 3, /* -x */
                                    7, 6, 2, 7, 2, 3, /* +y */ 0, 1, 5, 0, 5, 4 /* -y */};
static const zl_mesh cube = {cube_pos, cube_idx, NULL, NULL, 8, 12};

static void make_target(void)
{
    zl_target t;
    memset(&t, 0, sizeof t);
    t.color = color;
    t.color_stride = W * 3;
    t.depth = depth;
    t.depth_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB888;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
}

static void clear(void)
{
    zl_rgb black = {0, 0, 0};
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 65535));
}

static void test_edge_lists(void)
{
    static const zl_fixed quad_pos[12] = {0};
    static const uint16_t quad_idx[] = {0, 1, 2, 0, 2, 3};
    zl_mesh quad = {quad_pos, quad_idx, NULL, NULL, 4, 2};
    zl_mesh_edge e[36];
    uint32_t n, i, borders = 0;
    n = zl_mesh_edges(&cube, e, 36);
    TEST_ASSERT_EQUAL_UINT32(18, n); /* 12 cube edges + 6 face diagonals */
    for (i = 0; i < n; i++) {
        TEST_ASSERT_TRUE(e[i].v0 < e[i].v1);
        TEST_ASSERT_TRUE(e[i].t1 != ZL_NO_TRIANGLE);
        TEST_ASSERT_TRUE(e[i].t0 != e[i].t1);
        if (i > 0)
            TEST_ASSERT_TRUE(e[i - 1].v0 < e[i].v0 || (e[i - 1].v0 == e[i].v0 && e[i - 1].v1 < e[i].v1));
    }
    n = zl_mesh_edges(&quad, e, 6);
    TEST_ASSERT_EQUAL_UINT32(5, n);
    for (i = 0; i < n; i++)
        borders += e[i].t1 == ZL_NO_TRIANGLE;
    TEST_ASSERT_EQUAL_UINT32(4, borders);
    /* the diagonal 0-2 joins both triangles */
    TEST_ASSERT_EQUAL_UINT16(0, e[1].v0);
    TEST_ASSERT_EQUAL_UINT16(2, e[1].v1);
    TEST_ASSERT_EQUAL_UINT16(0, e[1].t0);
    TEST_ASSERT_EQUAL_UINT16(1, e[1].t1);
    TEST_ASSERT_EQUAL_UINT32(0, zl_mesh_edges(&quad, e, 5)); /* too small */
}

/* Model-space reference: face normal and the sign of n . (eye - p0). */
static void face_normal(uint16_t t, int64_t *n)
{
    const uint16_t *i = &cube_idx[t * 3];
    int64_t a[3], b[3];
    int k;
    for (k = 0; k < 3; k++) {
        a[k] = (int64_t)cube_pos[i[1] * 3 + k] - cube_pos[i[0] * 3 + k];
        b[k] = (int64_t)cube_pos[i[2] * 3 + k] - cube_pos[i[0] * 3 + k];
    }
    n[0] = a[1] * b[2] - a[2] * b[1];
    n[1] = a[2] * b[0] - a[0] * b[2];
    n[2] = a[0] * b[1] - a[1] * b[0];
}

static int faces_eye(uint16_t t, const int32_t *eye)
{
    int64_t n[3], d = 0;
    int k;
    face_normal(t, n);
    for (k = 0; k < 3; k++)
        d += (n[k] >> 16) * ((int64_t)eye[k] - cube_pos[cube_idx[t * 3] * 3 + k]);
    return d > 0;
}

static void test_silhouettes_and_creases_match_model_space(void)
{
    zl_mesh_edge e[36], sel[36];
    uint32_t n, i, views, nsel, total = 0;
    zl_outline o;
    zl_lines l;
    uint16_t pairs[72];
    int pass;
    uint32_t rng = 99;
    make_target();
    ctx.state.depth_test = 0;
    n = zl_mesh_edges(&cube, e, 36);
    memset(&o, 0, sizeof o);
    o.edges = e;
    o.edge_count = n;
    o.color.r = 255;
    o.crease_cos = ZL_FX_ONE / 2; /* 60 degrees */
    for (views = 0; views < 60; views++)
        for (pass = 0; pass < 2; pass++) {
            zl_mat4 proj, view, mvp;
            int32_t eye[3];
            zl_vec3 ev, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
            int k;
            for (k = 0; k < 3; k++) {
                rng ^= rng << 13;
                rng ^= rng >> 17;
                rng ^= rng << 5;
                eye[k] = (int32_t)(rng % (8u * 65536u)) - 4 * 65536;
            }
            if (eye[0] > -2 * 65536 && eye[0] < 2 * 65536 && eye[1] > -2 * 65536 && eye[1] < 2 * 65536 &&
                eye[2] > -2 * 65536 && eye[2] < 2 * 65536)
                eye[2] = 4 * 65536 + 1000; /* keep out of the cube */
            ev.x = eye[0];
            ev.y = eye[1];
            ev.z = eye[2];
            if (zl_mat4_look_at(&view, ev, target, up) != ZL_OK)
                continue;
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)),
                                                             ZL_FX_INT(W) / H, ZL_FX_ONE / 10, ZL_FX_INT(50)));
            zl_mat4_mul(&mvp, &proj, &view);
            o.silhouettes = (uint8_t)(pass == 0);
            o.creases = (uint8_t)(pass == 1);
            /* reference selection */
            nsel = 0;
            for (i = 0; i < n; i++) {
                int f0 = faces_eye(e[i].t0, eye), f1 = faces_eye(e[i].t1, eye);
                int64_t n0[3], n1[3];
                face_normal(e[i].t0, n0);
                face_normal(e[i].t1, n1);
                /* the cube's normals are axis-aligned: perpendicular or equal */
                if ((pass == 0 && f0 != f1) ||
                    (pass == 1 && (f0 || f1) &&
                     (n0[0] >> 16) * (n1[0] >> 16) + (n0[1] >> 16) * (n1[1] >> 16) + (n0[2] >> 16) * (n1[2] >> 16) == 0))
                    sel[nsel++] = e[i];
            }
            for (i = 0; i < nsel; i++) {
                pairs[i * 2] = sel[i].v0;
                pairs[i * 2 + 1] = sel[i].v1;
            }
            total += nsel;
            memset(&l, 0, sizeof l);
            l.positions = cube_pos;
            l.indices = pairs;
            l.vertex_count = 8;
            l.count = (uint16_t)(nsel * 2);
            l.prim = ZL_PRIM_LINES;
            ctx.state.color.r = 255;
            ctx.state.color.g = 0;
            ctx.state.color.b = 0;
            clear();
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, &mvp));
            memcpy(want, color, sizeof want);
            clear();
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_outlines(&ctx, &cube, &mvp, &o));
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, color, sizeof want, pass ? "creases" : "silhouettes");
        }
    TEST_ASSERT_GREATER_THAN(300, total);
}

/* Over the shaded cube with LEQUAL and an offset, the silhouette shows on
 * every one of its pixels; without the offset part of it is lost. */
static void test_outline_over_the_mesh(void)
{
    static const uint8_t grey[36] = {0};
    zl_mesh shaded = cube;
    zl_mesh_edge e[36];
    zl_outline o;
    zl_mat4 proj, view, mvp;
    zl_vec3 eye = {ZL_FX_INT(3), ZL_FX_INT(2), ZL_FX_INT(4)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    uint8_t alone[W * H];
    int i, off;
    unsigned n_alone = 0, shown[2] = {0, 0};
    make_target();
    shaded.face_colors = grey;
    memset(&o, 0, sizeof o);
    o.edges = e;
    o.edge_count = zl_mesh_edges(&cube, e, 36);
    o.silhouettes = 1;
    o.color.g = 255;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(W) / H,
                                                     ZL_FX_ONE / 10, ZL_FX_INT(50)));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
    zl_mat4_mul(&mvp, &proj, &view);
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_outlines(&ctx, &cube, &mvp, &o));
    for (i = 0; i < W * H; i++) {
        alone[i] = color[i * 3 + 1] == 255;
        n_alone += alone[i];
    }
    TEST_ASSERT_GREATER_THAN(40, n_alone);
    for (off = 0; off < 2; off++) {
        ctx.state.cull = ZL_CULL_BACK;
        ctx.state.depth_func = ZL_LESS;
        ctx.style.offset_units = 0;
        clear();
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &shaded, &mvp));
        ctx.state.depth_func = ZL_LEQUAL;
        ctx.style.offset_units = off ? -ZL_FX_INT(2000) : 0;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_outlines(&ctx, &cube, &mvp, &o));
        for (i = 0; i < W * H; i++)
            shown[off] += alone[i] && color[i * 3 + 1] == 255;
    }
    TEST_ASSERT_EQUAL_UINT32(n_alone, shown[1]);
    TEST_ASSERT_LESS_THAN(n_alone, shown[0]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_edge_lists);
    RUN_TEST(test_silhouettes_and_creases_match_model_space);
    RUN_TEST(test_outline_over_the_mesh);
    return UNITY_END();
}
