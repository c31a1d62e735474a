/* SPDX-License-Identifier: MIT */
/*
 * zl_frame_bound (zl_sizing.h) against what scenes really need: for random
 * meshes (triangles in a ball, fans of triangles sharing one edge, small
 * triangles on a sphere, long slivers) and random cameras, viewports, bands
 * and orientations, the frame sized by the bound plans every pose without
 * ZL_ERR_CAPACITY, and zl_frame_needs (the planner's exact count) never
 * exceeds its capacities. Also: the fallback when the model may be clipped,
 * the bound's use (well below all triangles for a fine mesh), bad arguments.
 */
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

enum { NV = 384, NT = 640 };

static uint32_t rng = 777u;
static zl_fixed positions[NV * 3];
static uint16_t indices[NT * 3];
static zl_mesh mesh;
static uint64_t work[160 * 1024 / 8];

static zl_fixed rand_unit(void) /* -1 .. 1 */
{
    return zt_rand_range(&rng, -ZL_FX_ONE, ZL_FX_ONE);
}

static void set_vertex(uint16_t i, zl_fixed x, zl_fixed y, zl_fixed z)
{
    positions[i * 3] = x;
    positions[i * 3 + 1] = y;
    positions[i * 3 + 2] = z;
}

static void random_mesh(int kind)
{
    uint16_t nt = (uint16_t)zt_rand_range(&rng, 1, NV / 3), nv = (uint16_t)(nt * 3), i;
    for (i = 0; i < nt; i++) {
        zl_angle a = (zl_angle)zt_rand_range(&rng, 0, ZL_ANGLE_TURN - 1);
        zl_angle b = (zl_angle)zt_rand_range(&rng, -ZL_ANGLE_TURN / 4, ZL_ANGLE_TURN / 4);
        zl_fixed cx = zl_fx_mul(zl_cos(a), zl_cos(b)), cy = zl_sin(b), cz = zl_fx_mul(zl_sin(a), zl_cos(b));
        uint16_t v = (uint16_t)(i * 3);
        switch (kind) {
        case 0: /* anywhere in the cube */
            set_vertex(v, rand_unit(), rand_unit(), rand_unit());
            set_vertex((uint16_t)(v + 1), rand_unit(), rand_unit(), rand_unit());
            set_vertex((uint16_t)(v + 2), rand_unit(), rand_unit(), rand_unit());
            break;
        case 1: /* pages of a book: one shared edge along y */
            set_vertex(v, 0, -ZL_FX_ONE, 0);
            set_vertex((uint16_t)(v + 1), 0, ZL_FX_ONE, 0);
            set_vertex((uint16_t)(v + 2), zl_cos(a), rand_unit() / 4, zl_sin(a));
            break;
        case 2: /* small triangles on the unit sphere */
            set_vertex(v, cx, cy, cz);
            set_vertex((uint16_t)(v + 1), cx + rand_unit() / 16, cy + rand_unit() / 16, cz);
            set_vertex((uint16_t)(v + 2), cx, cy + rand_unit() / 16, cz + rand_unit() / 16);
            break;
        default: /* slivers through the middle */
            set_vertex(v, cx, cy, cz);
            set_vertex((uint16_t)(v + 1), -cx, -cy, -cz);
            set_vertex((uint16_t)(v + 2), -cx + rand_unit() / 64, -cy, -cz + rand_unit() / 64);
            break;
        }
    }
    for (i = 0; i < nv; i++)
        indices[i] = (uint16_t)(zt_rand_range(&rng, 0, 7) == 0 ? zt_rand_range(&rng, 0, nv - 1) : i);
    mesh.positions = positions;
    mesh.indices = indices;
    mesh.vertex_colors = NULL;
    mesh.face_colors = NULL;
    mesh.vertex_count = nv;
    mesh.triangle_count = nt;
}

static void random_camera(zl_orbit_camera *cam)
{
    cam->fovy = zl_angle_from_deg(ZL_FX_INT(zt_rand_range(&rng, 15, 110)));
    cam->near_z = zt_rand_range(&rng, ZL_FX_ONE / 100, ZL_FX_ONE / 2);
    cam->far_z = ZL_FX_INT(zt_rand_range(&rng, 4, 200));
    /* mostly clear of the near plane (the tight bound), sometimes not (the fallback) */
    cam->distance = zt_rand_range(&rng, ZL_FX_ONE, ZL_FX_INT(8));
}

/* Plan the mesh turned by yaw, pitch, roll with the sized config; assert it fits. */
static void plan_pose(const zl_frame_config *cfg, const zl_orbit_camera *cam, zl_angle yaw, zl_angle pitch,
                      zl_angle roll, uint8_t cull)
{
    zl_mat4 proj, view, ry, rx, rz, m, mvp;
    zl_vec3 eye = {0, 0, 0}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_frame frame;
    zl_state st;
    zl_band band;
    zl_rgb black = {0, 0, 0};
    zl_frame_needs_t n;
    zl_status s;
    eye.z = cam->distance;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, cam->fovy,
                                                     (zl_fixed)(((int64_t)cfg->width << 16) / cfg->height),
                                                     cam->near_z, cam->far_z));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
    zl_mat4_rotate_y(&ry, yaw);
    zl_mat4_rotate_x(&rx, pitch);
    zl_mat4_rotate_z(&rz, roll);
    zl_mat4_mul(&m, &rx, &ry);
    zl_mat4_mul(&m, &rz, &m);
    zl_mat4_mul(&mvp, &view, &m);
    zl_mat4_mul(&mvp, &proj, &mvp);
    zl_state_default(&st);
    st.cull = cull;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&frame, cfg, work, sizeof work, black, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&frame, &mesh, &mvp, &st));
    s = zl_frame_next_band(&frame, &band);
    n = zl_frame_needs(&frame);
    TEST_ASSERT_TRUE_MESSAGE(n.active <= cfg->max_active, "a pose needs more active triangles than the bound");
    TEST_ASSERT_TRUE_MESSAGE(n.triangles <= cfg->max_triangles, "a pose keeps more triangles than the bound");
    TEST_ASSERT_TRUE_MESSAGE(s == ZL_OK || s == ZL_DONE, "the bound's frame could not render a pose");
}

static void test_bound_holds_for_random_meshes_and_poses(void)
{
    int round, pose, tight = 0;
    for (round = 0; round < 160; round++) {
        zl_frame_config cfg;
        zl_orbit_camera cam;
        size_t bytes;
        random_mesh(round % 4);
        random_camera(&cam);
        memset(&cfg, 0, sizeof cfg);
        cfg.width = (uint16_t)zt_rand_range(&rng, 8, 160);
        cfg.height = (uint16_t)zt_rand_range(&rng, 8, 160);
        cfg.band_rows = (uint16_t)zt_rand_range(&rng, 1, cfg.height);
        cfg.format = ZL_FORMAT_RGB565;
        cfg.color_buffers = 1;
        bytes = zl_frame_bound(&cfg, &mesh, &cam, (unsigned)zt_rand_range(&rng, 1, 12));
        TEST_ASSERT_TRUE(bytes > 0);
        TEST_ASSERT_EQUAL_UINT32(bytes, zl_frame_bytes(&cfg));
        if (bytes > sizeof work)
            continue;
        tight += cfg.max_active <= mesh.triangle_count;
        for (pose = 0; pose < 24; pose++)
            plan_pose(&cfg, &cam, (zl_angle)zt_rand_range(&rng, 0, ZL_ANGLE_TURN - 1),
                      (zl_angle)zt_rand_range(&rng, 0, ZL_ANGLE_TURN - 1),
                      (zl_angle)zt_rand_range(&rng, 0, ZL_ANGLE_TURN - 1), (uint8_t)zt_rand_range(&rng, 0, 2));
    }
    TEST_ASSERT_TRUE(tight > 80); /* most cameras were clear of the near plane: the sweep bound ran */
}

/* A fine closed mesh (a UV sphere of 24 x 12 quads): the bound is well below
 * its triangle count, and the frame it sizes holds every pose tried. */
static void test_bound_is_useful_for_a_fine_mesh(void)
{
    enum { SEG = 24, RINGS = 12 };
    zl_frame_config cfg;
    zl_orbit_camera cam;
    uint16_t r, s, t = 0;
    int pose;
    for (r = 0; r <= RINGS; r++)
        for (s = 0; s < SEG; s++) {
            zl_angle lat = (zl_angle)(-ZL_ANGLE_TURN / 4 + ZL_ANGLE_TURN / 2 * r / RINGS);
            zl_angle lon = (zl_angle)(ZL_ANGLE_TURN * s / SEG);
            set_vertex((uint16_t)(r * SEG + s), zl_fx_mul(zl_cos(lat), zl_cos(lon)), zl_sin(lat),
                       zl_fx_mul(zl_cos(lat), zl_sin(lon)));
        }
    for (r = 0; r < RINGS && t + 2 <= NT; r++)
        for (s = 0; s < SEG && t + 2 <= NT; s++) {
            uint16_t a = (uint16_t)(r * SEG + s), b = (uint16_t)(r * SEG + (s + 1) % SEG);
            uint16_t c = (uint16_t)(a + SEG), d = (uint16_t)(b + SEG);
            uint16_t *p = indices + t * 3;
            p[0] = a, p[1] = b, p[2] = d, p[3] = a, p[4] = d, p[5] = c;
            t = (uint16_t)(t + 2);
        }
    mesh.positions = positions;
    mesh.indices = indices;
    mesh.vertex_count = (RINGS + 1) * SEG;
    mesh.triangle_count = t;
    memset(&cfg, 0, sizeof cfg);
    cfg.width = cfg.height = 128;
    cfg.band_rows = 8;
    cfg.color_buffers = 1;
    cam.fovy = zl_angle_from_deg(ZL_FX_INT(45));
    cam.near_z = ZL_FX_ONE / 10;
    cam.far_z = ZL_FX_INT(100);
    cam.distance = ZL_FX_INT(3);
    TEST_ASSERT_TRUE(zl_frame_bound(&cfg, &mesh, &cam, 24) > 0);
    TEST_ASSERT_TRUE(cfg.max_active * 2u < t);
    for (pose = 0; pose < 200; pose++)
        plan_pose(&cfg, &cam, (zl_angle)zt_rand_range(&rng, 0, ZL_ANGLE_TURN - 1),
                  (zl_angle)zt_rand_range(&rng, 0, ZL_ANGLE_TURN - 1),
                  (zl_angle)zt_rand_range(&rng, 0, ZL_ANGLE_TURN - 1), ZL_CULL_NONE);
}

/* The worst pose, built: a disc of small triangles whose plane (normal
 * (2, 3, 6) / 7, far from the sweep's grid directions at low precision) is
 * turned into the plane of the middle row, each triangle straddling it by
 * about half a pixel: every triangle is active on that row. The bound must
 * reach the triangle count, at every precision (the widening for the
 * directions between grid points is what makes it). */
static void test_bound_holds_for_a_disc_seen_edge_on(void)
{
    /* rows: the disc's two in-plane axes and its normal, orthonormal */
    static const int32_t basis[3][3] = {{3, -6, 2}, {2, 3, 6}, {6, 2, -3}};
    zl_frame_config cfg;
    zl_orbit_camera cam;
    zl_mat4 proj, view, model, mvp;
    zl_vec3 eye = {0, 0, ZL_FX_INT(3)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_frame frame;
    zl_state st;
    zl_band band;
    zl_rgb black = {0, 0, 0};
    uint16_t i, t = 0, k;
    unsigned precision;
    for (i = 0; i < 100; i++) { /* 10 x 10 triangles across the disc */
        zl_fixed a = (zl_fixed)((i % 10) * ZL_FX_ONE / 6 - ZL_FX_ONE * 3 / 4);
        zl_fixed b = (zl_fixed)((i / 10) * ZL_FX_ONE / 6 - ZL_FX_ONE * 3 / 4);
        zl_fixed corner[3][3]; /* in-plane a, b and the offset along the normal */
        zl_fixed eps = ZL_FX_ONE / 64, side = ZL_FX_ONE / 8;
        corner[0][0] = a, corner[0][1] = b, corner[0][2] = eps;
        corner[1][0] = a + side, corner[1][1] = b, corner[1][2] = -eps;
        corner[2][0] = a, corner[2][1] = b + side, corner[2][2] = 0;
        for (k = 0; k < 3; k++) {
            int c;
            for (c = 0; c < 3; c++) /* model = a u + b w + e n, u, n, w the basis rows */
                positions[(t * 3 + k) * 3 + c] = (zl_fixed)(((int64_t)corner[k][0] * basis[0][c] +
                                                             (int64_t)corner[k][2] * basis[1][c] +
                                                             (int64_t)corner[k][1] * basis[2][c]) / 7);
            indices[t * 3 + k] = (uint16_t)(t * 3 + k);
        }
        t++;
    }
    mesh.positions = positions;
    mesh.indices = indices;
    mesh.vertex_count = (uint16_t)(t * 3);
    mesh.triangle_count = t;
    /* the model matrix takes n to +y: its rows are u, n, w */
    zl_mat4_identity(&model);
    for (i = 0; i < 3; i++)
        for (k = 0; k < 3; k++)
            model.m[i * 4 + k] = (zl_fixed)(basis[i][k] * ZL_FX_ONE / 7);
    cam.fovy = zl_angle_from_deg(ZL_FX_INT(45));
    cam.near_z = ZL_FX_ONE / 10;
    cam.far_z = ZL_FX_INT(100);
    cam.distance = ZL_FX_INT(3);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, cam.fovy, ZL_FX_ONE, cam.near_z, cam.far_z));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
    zl_mat4_mul(&mvp, &view, &model);
    zl_mat4_mul(&mvp, &proj, &mvp);
    for (precision = 1; precision <= 9; precision++) {
        zl_frame_needs_t n;
        memset(&cfg, 0, sizeof cfg);
        cfg.width = cfg.height = 63; /* odd: a row's centre on the disc's plane */
        cfg.band_rows = 4;
        cfg.color_buffers = 1;
        TEST_ASSERT_TRUE(zl_frame_bound(&cfg, &mesh, &cam, precision) > 0);
        cfg.max_active = 8u * t; /* to see the need, not to fail on it */
        zl_state_default(&st);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&frame, &cfg, work, sizeof work, black, 65535));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&frame, &mesh, &mvp, &st));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&frame, &band));
        n = zl_frame_needs(&frame);
        TEST_ASSERT_EQUAL_UINT32(t, n.active); /* the pose is the worst one */
        memset(&cfg, 0, sizeof cfg);
        cfg.width = cfg.height = 63;
        cfg.band_rows = 4;
        cfg.color_buffers = 1;
        TEST_ASSERT_TRUE(zl_frame_bound(&cfg, &mesh, &cam, precision) > 0);
        TEST_ASSERT_EQUAL_UINT32(t, cfg.max_active);
    }
}

/* A camera inside the model's sphere may clip: the always-sufficient 8 x triangles. */
static void test_clipped_poses_get_the_safe_capacity(void)
{
    zl_frame_config cfg;
    zl_orbit_camera cam = {0, ZL_FX_ONE / 10, ZL_FX_INT(100), ZL_FX_ONE};
    cam.fovy = zl_angle_from_deg(ZL_FX_INT(60));
    random_mesh(0);
    memset(&cfg, 0, sizeof cfg);
    cfg.width = cfg.height = 32;
    cfg.band_rows = 1;
    cfg.color_buffers = 1;
    TEST_ASSERT_TRUE(zl_frame_bound(&cfg, &mesh, &cam, 8) > 0);
    TEST_ASSERT_EQUAL_UINT32(8u * mesh.triangle_count, cfg.max_active);
    TEST_ASSERT_EQUAL_UINT32(mesh.triangle_count, cfg.max_triangles);
}

static void test_bad_arguments(void)
{
    zl_frame_config cfg, before;
    zl_orbit_camera cam = {0, ZL_FX_ONE / 10, ZL_FX_INT(100), ZL_FX_INT(3)};
    cam.fovy = zl_angle_from_deg(ZL_FX_INT(45));
    random_mesh(2);
    memset(&cfg, 0, sizeof cfg);
    cfg.width = cfg.height = 32;
    cfg.band_rows = 1;
    cfg.color_buffers = 1;
    before = cfg;
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_bound(NULL, &mesh, &cam, 8));
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_bound(&cfg, NULL, &cam, 8));
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_bound(&cfg, &mesh, NULL, 8));
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_bound(&cfg, &mesh, &cam, 0));
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_bound(&cfg, &mesh, &cam, 65));
    cam.far_z = cam.near_z;
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_bound(&cfg, &mesh, &cam, 8));
    cam.far_z = ZL_FX_INT(100);
    indices[0] = mesh.vertex_count; /* out of bounds */
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_bound(&cfg, &mesh, &cam, 8));
    indices[0] = 0;
    positions[0] = ZL_FX_INT(16385); /* beyond the transform's range */
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_bound(&cfg, &mesh, &cam, 8));
    cfg.band_rows = 0; /* zl_frame_bytes refuses it */
    positions[0] = 0;
    TEST_ASSERT_EQUAL_UINT32(0, zl_frame_bound(&cfg, &mesh, &cam, 8));
    before.band_rows = 0;
    TEST_ASSERT_EQUAL_MEMORY(&before, &cfg, sizeof cfg);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_bad_arguments);
    RUN_TEST(test_clipped_poses_get_the_safe_capacity);
    RUN_TEST(test_bound_is_useful_for_a_fine_mesh);
    RUN_TEST(test_bound_holds_for_a_disc_seen_edge_on);
    RUN_TEST(test_bound_holds_for_random_meshes_and_poses);
    return UNITY_END();
}
