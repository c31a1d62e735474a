/* SPDX-License-Identifier: MIT */
/*
 * The camera object (zline/zl_camera.h), against references computed here:
 *   - zl_camera_mvp is proj x view x model: each entry within 4 raw Q16.16
 *     units of the product evaluated in double from the three matrices
 *     (zl_mat4_mul rounds twice; a wrong order is off by far more);
 *   - a draw through a perspective camera takes the exact depth mapping:
 *     a wall facing the camera just beyond the near plane stores, at every
 *     covered pixel, round(65535 (A + B / d)) within +-1, A = f / (f - n),
 *     B = -f n / (f - n), d the wall's distance (the matrix's own rounded
 *     depth is several steps off there, which the test shows, so it can
 *     fail), in frame mode and in scanline mode (zl_frame_add_mesh_camera);
 *   - ctx->state's near_z, far_z are the caller's again after the draw;
 *   - a failed set-up leaves the camera unchanged, NULL gives ZL_ERR_ARG.
 */
#include <string.h>

#include "unity.h"
#include "zline/zl_camera.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_target.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 32, H = 24 };

/* One target for both modes (each test fills it anew): the test fits the
 * ATmega2560's 8 KB of SRAM (tests/CMakeLists.txt, ZLINE_AVR_TESTS). */
static uint16_t color[W * H] ZT_ALIGNED(2), depth[W * H] ZT_ALIGNED(2);

/* Near 0.1, far 100; a square wall of half side 1 at eye distance d = 0.15,
 * centred on the view axis: it covers the whole viewport. */
static const zl_fixed near_q = ZL_FX_ONE / 10, far_q = ZL_FX_INT(100);
static zl_fixed wall_positions[4 * 3];
static const uint16_t wall_indices[6] = {0, 1, 2, 0, 2, 3};
static const uint8_t wall_colors[6] = {200, 100, 50, 200, 100, 50};

static zl_mesh wall_mesh(void)
{
    static const int corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    zl_mesh m;
    int i;
    for (i = 0; i < 4; i++) {
        wall_positions[i * 3 + 0] = ZL_FX_INT(corner[i][0]);
        wall_positions[i * 3 + 1] = ZL_FX_INT(corner[i][1]);
        wall_positions[i * 3 + 2] = 0;
    }
    memset(&m, 0, sizeof m);
    m.positions = wall_positions;
    m.indices = wall_indices;
    m.face_colors = wall_colors;
    m.vertex_count = 4;
    m.triangle_count = 2;
    return m;
}

/* The wall's exact stored depth: n, f and d as the Q16.16 values say. */
static double wall_exact_depth(zl_fixed d_q)
{
    double n = near_q / 65536.0, f = far_q / 65536.0, d = d_q / 65536.0;
    return 65535.0 * (f / (f - n) - f * n / ((f - n) * d));
}

static void camera_of(zl_camera *cam, zl_vec3 eye)
{
    zl_vec3 target = eye, up = {0, ZL_FX_ONE, 0};
    target.z -= ZL_FX_ONE; /* looking down -z */
    zl_camera_init(cam);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_camera_perspective(cam, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(W) / H,
                                                       near_q, far_q));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_camera_look_at(cam, eye, target, up));
}

/* Largest |stored - exact| over covered pixels; fails if none is covered. */
static double depth_error(const uint16_t *z, double exact)
{
    double worst = 0.0;
    int p, covered = 0;
    for (p = 0; p < W * H; p++) {
        double e;
        if (z[p] == 65535)
            continue;
        covered++;
        e = z[p] - exact;
        e = e < 0 ? -e : e;
        worst = e > worst ? e : worst;
    }
    TEST_ASSERT_EQUAL_INT(W * H, covered);
    return worst;
}

static void draw_frame(zl_context *ctx, const zl_mesh *m, const zl_camera *cam, const zl_mat4 *model)
{
    zl_target t;
    zl_rgb bg = {0, 0, 0};
    zt_target_packed(&t, color, depth, W, H, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(ctx, &t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(ctx, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh_camera(ctx, m, cam, model));
}

static void test_wall_depth_is_exact_in_frame_mode(void)
{
    static zl_context ctx;
    zl_camera cam;
    zl_mesh m = wall_mesh();
    zl_mat4 model, mvp;
    zl_vec3 eye = {ZL_FX_INT(3), ZL_FX_INT(-2), ZL_FX_INT(5)}, at;
    zl_fixed d = ZL_FX_ONE * 15 / 100;
    double exact;
    camera_of(&cam, eye);
    at = eye;
    at.z -= d; /* the wall, moved by the model matrix to distance d before the eye */
    zl_mat4_translate(&model, at);
    exact = wall_exact_depth(d);
    draw_frame(&ctx, &m, &cam, &model);
    TEST_ASSERT_TRUE(depth_error(depth, exact) <= 1.0);
    /* The caller's state is as it was: no exact mapping. */
    TEST_ASSERT_EQUAL_INT(0, ctx.state.near_z);
    TEST_ASSERT_EQUAL_INT(0, ctx.state.far_z);
    /* The same matrix without the mapping is more than a step off: the
     * check above can fail. */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_camera_mvp(&cam, &model, &mvp));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, &mvp));
    TEST_ASSERT_TRUE(depth_error(depth, exact) > 1.0);
}

static void test_wall_depth_is_exact_in_scanline_mode(void)
{
    static uint64_t work[160] ZT_ALIGNED(8); /* 1280 bytes: the frame needs fewer (asserted below) */
    zl_frame_config cfg;
    zl_frame f;
    zl_camera cam;
    zl_state st;
    zl_mesh m = wall_mesh();
    zl_mat4 model;
    zl_vec3 eye = {0, 0, ZL_FX_INT(2)}, at = {0, 0, 0};
    zl_fixed d = ZL_FX_ONE * 12 / 100;
    zl_rgb bg = {0, 0, 0};
    zt_frame_copy out;
    camera_of(&cam, eye);
    at.z = eye.z - d;
    zl_mat4_translate(&model, at);
    zt_frame_config_of(&cfg, W, H, 1, ZL_FORMAT_RGB565);
    zt_frame_capacity(&cfg, 1, 4, 2, 4);
    TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
    zl_state_default(&st);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh_camera(&f, &m, &cam, &model, &st));
    memset(depth, 0, sizeof depth); /* nothing of the frame-mode test is left */
    out.color = color;
    out.depth = depth;
    zt_frame_drain(&f, &out);
    TEST_ASSERT_TRUE(depth_error(depth, wall_exact_depth(d)) <= 1.0);
}

/* Entry (r, c) of a x b x c in double. */
static double product3(const zl_mat4 *a, const zl_mat4 *b, const zl_mat4 *c, int r, int col)
{
    double sum = 0.0;
    int i, j;
    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)
            sum += (a->m[r * 4 + i] / 65536.0) * (b->m[i * 4 + j] / 65536.0) * (c->m[j * 4 + col] / 65536.0);
    return sum;
}

static void test_mvp_is_proj_view_model(void)
{
    zl_camera cam;
    zl_mat4 model, rot, scale, mvp;
    zl_vec3 eye = {ZL_FX_INT(2), ZL_FX_INT(1), ZL_FX_INT(3)}, s = {ZL_FX_ONE * 3 / 2, ZL_FX_ONE * 3 / 2,
                                                                    ZL_FX_ONE * 3 / 2};
    int e;
    camera_of(&cam, eye);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_camera_look_at(&cam, eye, (zl_vec3){0, 0, 0}, (zl_vec3){0, ZL_FX_ONE, 0}));
    zl_mat4_rotate_y(&rot, 5000);
    zl_mat4_scale(&scale, s);
    zl_mat4_mul(&model, &rot, &scale);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_camera_mvp(&cam, &model, &mvp));
    for (e = 0; e < 16; e++) {
        double want = product3(&cam.proj, &cam.view, &model, e / 4, e % 4) * 65536.0, diff = mvp.m[e] - want;
        TEST_ASSERT_TRUE(diff <= 4.0 && diff >= -4.0);
    }
    /* No model: proj x view. */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_camera_mvp(&cam, NULL, &mvp));
    zl_mat4_identity(&model);
    for (e = 0; e < 16; e++) {
        double want = product3(&cam.proj, &cam.view, &model, e / 4, e % 4) * 65536.0, diff = mvp.m[e] - want;
        TEST_ASSERT_TRUE(diff <= 4.0 && diff >= -4.0);
    }
}

static void test_errors_change_nothing(void)
{
    zl_camera cam, before;
    zl_mat4 mvp;
    zl_state st;
    zl_vec3 eye = {0, 0, ZL_FX_INT(4)};
    camera_of(&cam, eye);
    before = cam;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_camera_perspective(&cam, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_ONE,
                                                              ZL_FX_INT(2), ZL_FX_ONE));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_camera_look_at(&cam, eye, eye, (zl_vec3){0, ZL_FX_ONE, 0}));
    TEST_ASSERT_EQUAL_MEMORY(&before, &cam, sizeof cam);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_camera_perspective(NULL, 1000, ZL_FX_ONE, ZL_FX_ONE, ZL_FX_INT(2)));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_camera_mvp(NULL, NULL, &mvp));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_camera_mvp(&cam, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh_camera(NULL, NULL, &cam, NULL));
    zl_state_default(&st);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_add_mesh_camera(NULL, NULL, &cam, NULL, NULL));
    /* An orthographic camera has no mapping to make exact. */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_camera_ortho(&cam, -ZL_FX_ONE, ZL_FX_ONE, -ZL_FX_ONE, ZL_FX_ONE, ZL_FX_ONE,
                                                 ZL_FX_INT(10)));
    st.near_z = 5;
    st.far_z = 6;
    zl_camera_apply_depth(&cam, &st);
    TEST_ASSERT_EQUAL_INT(0, st.near_z);
    TEST_ASSERT_EQUAL_INT(0, st.far_z);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_mvp_is_proj_view_model);
    RUN_TEST(test_wall_depth_is_exact_in_frame_mode);
    RUN_TEST(test_wall_depth_is_exact_in_scanline_mode);
    RUN_TEST(test_errors_change_nothing);
    return UNITY_END();
}
