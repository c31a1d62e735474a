/* SPDX-License-Identifier: MIT */
/*
 * Visibility without a depth buffer (zl_visibility.h, issue #6).
 *
 * The oracle is the ray caster. It is first checked on its own, on scenes
 * whose answer is worked out by hand: which triangle shows at each pixel,
 * where two interpenetrating triangles swap, the top-left rule on shared
 * edges and on centres exactly on an edge, ties, culling, and the depth gap
 * it reports. Then every other method is compared with it, pixel by pixel,
 * on id images (which source triangle shows):
 *   z-buffer (zl_draw_mesh)  agrees except where the two nearest surfaces are
 *                            within one depth step (gap <= TIE), and covers
 *                            exactly the same pixels;
 *   AET                      the same, and its colour rows equal the z-buffer's
 *                            wherever their ids agree;
 *   painter's                equal on depth-separated scenes; fails (and is
 *                            shown to fail) on intersecting triangles, cyclic
 *                            overlap and a key misorder;
 *   BSP                      a hand-built tree of a split scene, both walk
 *                            orders, from eyes on both sides of every plane.
 * Plus the two back-face tests against each other, and the API's memory and
 * error contract. Sizes are small so the file runs under QEMU in seconds.
 */
#include <string.h>

#include "unity.h"
#include "zline/zl_visibility.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 48, H = 40, NV = 24, NT = 16, NMESH = 3 };

/* One depth step in the ray caster's gap units (1/256 step), plus the
 * oracle's own rounding (a few 1/65536 of a step): pixels whose two nearest
 * surfaces are this close may go either way in a 16-bit depth buffer. */
#define TIE 257

static uint32_t rng = 0x9E3779B9u;
static int32_t rand_range(int32_t lo, int32_t hi) /* inclusive */
{
    return zt_rand_range(&rng, lo, hi);
}

typedef struct {
    zl_fixed pos[NT * 3 * 3]; /* up to three vertices of its own per triangle */
    uint16_t idx[NT * 3];
    uint8_t fcol[NT * 3];
    zl_mesh mesh;
    zl_mat4 mvp;
    int use_mvp;
    zl_state state;
} scene_mesh;

static scene_mesh scene[NMESH];
static int scene_meshes;

static uint8_t zb_color[W * H * 3];
static uint16_t zb_depth[W * H];
static uint16_t zb_ids[W * H];
static uint8_t vis_color[W * H * 3];
static uint16_t vis_ids[W * H];
static uint16_t rc_ids[W * H];
static uint16_t rc_gap[W * H];
static uint64_t work[(96 * 1024) / 8];

static const zl_rgb bg = {0, 0, 0};

/* Face colours carry the global triangle id, so the z-buffer's colour image
 * is an id image: (id >> 8, id & 255, 0x80); the background has b = 0. */
static void id_colors(scene_mesh *m, uint32_t base)
{
    uint32_t t;
    for (t = 0; t < m->mesh.triangle_count; t++) {
        m->fcol[t * 3] = (uint8_t)((base + t) >> 8);
        m->fcol[t * 3 + 1] = (uint8_t)((base + t) & 0xFFu);
        m->fcol[t * 3 + 2] = 0x80;
    }
    m->mesh.face_colors = m->fcol;
}

static void finish_scene(int n)
{
    uint32_t base = 0;
    int i;
    scene_meshes = n;
    for (i = 0; i < n; i++) {
        id_colors(&scene[i], base);
        base += scene[i].mesh.triangle_count;
    }
}

static void mesh_init(scene_mesh *m, uint16_t nv, uint16_t nt)
{
    memset(&m->mesh, 0, sizeof m->mesh);
    m->mesh.positions = m->pos;
    m->mesh.indices = m->idx;
    m->mesh.vertex_count = nv;
    m->mesh.triangle_count = nt;
    m->use_mvp = 0;
    zl_state_default(&m->state);
}

/* ------------------------------------------------------------ renderers */

static void render_zbuffer(void)
{
    zl_target t;
    zl_context ctx;
    int i;
    zt_target_packed(&t, zb_color, zb_depth, W, H, ZL_FORMAT_RGB888);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
    for (i = 0; i < scene_meshes; i++) {
        ctx.state = scene[i].state;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &scene[i].mesh, scene[i].use_mvp ? &scene[i].mvp : NULL));
    }
    for (i = 0; i < W * H; i++) {
        const uint8_t *p = &zb_color[i * 3];
        zb_ids[i] = p[2] == 0x80 ? (uint16_t)(p[0] << 8 | p[1]) : (uint16_t)ZL_VIS_NONE;
    }
}

static void vis_config(zl_vis_config *c, zl_vis_algo algo)
{
    memset(c, 0, sizeof *c);
    c->width = W;
    c->height = H;
    c->algorithm = (uint8_t)algo;
    c->format = ZL_FORMAT_RGB888;
    c->max_meshes = NMESH;
    c->max_vertices = NV * NMESH;
    c->max_triangles = NT * NMESH;
    c->max_active = NT * NMESH * 7;
}

static int collect_row(void *user, const zl_vis_row *row)
{
    int raycast = *(int *)user;
    memcpy(raycast ? rc_ids + (size_t)row->y * W : vis_ids + (size_t)row->y * W, row->ids, W * 2);
    if (raycast) {
        TEST_ASSERT_NOT_NULL(row->gap);
        memcpy(rc_gap + (size_t)row->y * W, row->gap, W * 2);
    } else {
        memcpy(vis_color + (size_t)row->y * W * 3, row->color, W * 3);
    }
    return 0;
}

static void begin_scene(zl_vis *v, zl_vis_algo algo)
{
    zl_vis_config c;
    int i;
    vis_config(&c, algo);
    TEST_ASSERT_TRUE(zl_vis_bytes(&c) <= sizeof work);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_begin(v, &c, work, sizeof work));
    for (i = 0; i < scene_meshes; i++)
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_add_mesh(v, &scene[i].mesh, scene[i].use_mvp ? &scene[i].mvp : NULL,
                                                     &scene[i].state));
}

static void render_rows(zl_vis_algo algo)
{
    zl_vis v;
    int raycast = algo == ZL_VIS_RAYCAST;
    begin_scene(&v, algo);
    TEST_ASSERT_EQUAL_INT(0, zl_vis_render_rows(&v, bg, collect_row, &raycast));
}

/* The same with every capacity exactly what the scene needs: the output
 * must not change (nothing dropped when the pool is exactly full). */
static uint16_t tight_ids[W * H];
static void render_rows_tight(zl_vis_algo algo)
{
    zl_vis v;
    zl_vis_config c;
    zl_frame_needs_t needs;
    int raycast = algo == ZL_VIS_RAYCAST, i;
    begin_scene(&v, algo);
    TEST_ASSERT_EQUAL_INT(0, zl_vis_render_rows(&v, bg, collect_row, &raycast));
    needs = zl_vis_needs(&v);
    memcpy(tight_ids, raycast ? rc_ids : vis_ids, sizeof tight_ids);
    vis_config(&c, algo);
    c.max_triangles = needs.triangles;
    c.max_active = needs.active > 0 ? needs.active : 1;
    c.max_vertices = 0;
    for (i = 0; i < scene_meshes; i++)
        c.max_vertices += scene[i].mesh.vertex_count;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_begin(&v, &c, work, zl_vis_bytes(&c)));
    for (i = 0; i < scene_meshes; i++)
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_add_mesh(&v, &scene[i].mesh, scene[i].use_mvp ? &scene[i].mvp : NULL,
                                                     &scene[i].state));
    TEST_ASSERT_EQUAL_INT(0, zl_vis_render_rows(&v, bg, collect_row, &raycast));
    TEST_ASSERT_EQUAL_MEMORY(tight_ids, raycast ? rc_ids : vis_ids, sizeof tight_ids);
}

static void render_painter(void)
{
    zl_vis v;
    zl_vis_target t;
    begin_scene(&v, ZL_VIS_PAINTER);
    memset(&t, 0, sizeof t);
    t.color = vis_color;
    t.color_stride = W * 3;
    t.ids = vis_ids;
    t.ids_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB888;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_painter_draw(&v, &t, bg));
}

typedef struct {
    long covered;   /* pixels some triangle covers */
    long ties;      /* differing ids where the oracle's gap is within TIE */
    long wrong;     /* differing ids with a clear winner */
    long coverage;  /* one says background, the other not */
} agreement;

static agreement compare_ids(const uint16_t *ids)
{
    agreement a = {0, 0, 0, 0};
    int i;
    for (i = 0; i < W * H; i++) {
        a.covered += rc_ids[i] != ZL_VIS_NONE;
        if (ids[i] == rc_ids[i])
            continue;
        if (ids[i] == ZL_VIS_NONE || rc_ids[i] == ZL_VIS_NONE)
            a.coverage++;
        else if (rc_gap[i] <= TIE)
            a.ties++;
        else
            a.wrong++;
    }
    return a;
}

/* ------------------------------------------------ the ray caster by hand */

/* A pixel-space triangle (x, y in pixels as Q16.16 halves, z in 1/1000). */
static void put_tri(scene_mesh *m, int t, const int32_t *xyz2)
{
    int k;
    for (k = 0; k < 3; k++) {
        m->pos[(t * 3 + k) * 3] = xyz2[k * 3] * (ZL_FX_ONE / 2);
        m->pos[(t * 3 + k) * 3 + 1] = xyz2[k * 3 + 1] * (ZL_FX_ONE / 2);
        m->pos[(t * 3 + k) * 3 + 2] = (zl_fixed)((int64_t)xyz2[k * 3 + 2] * ZL_FX_ONE / 1000);
        m->idx[t * 3 + k] = (uint16_t)(t * 3 + k);
    }
}

/* Axis-aligned rectangle [x0, x1) x [y0, y1) in pixels at depth z/1000 as two
 * triangles t, t + 1 (clockwise on screen). */
static void put_rect(scene_mesh *m, int t, int x0, int y0, int x1, int y1, int z)
{
    int32_t a[9] = {2 * x0, 2 * y0, z, 2 * x1, 2 * y0, z, 2 * x1, 2 * y1, z};
    int32_t b[9] = {2 * x0, 2 * y0, z, 2 * x1, 2 * y1, z, 2 * x0, 2 * y1, z};
    put_tri(m, t, a);
    put_tri(m, t + 1, b);
}

static void test_raycast_overlapping_rectangles(void)
{
    int x, y;
    mesh_init(&scene[0], 12, 4);
    put_rect(&scene[0], 0, 4, 4, 20, 20, 501);  /* ids 0, 1: behind */
    put_rect(&scene[0], 2, 10, 10, 30, 30, 500); /* ids 2, 3: in front */
    finish_scene(1);
    render_rows(ZL_VIS_RAYCAST);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int in_a = x >= 4 && x < 20 && y >= 4 && y < 20, in_b = x >= 10 && x < 30 && y >= 10 && y < 30;
            uint16_t id = rc_ids[y * W + x];
            if (in_b) {
                /* the diagonal from (10,10) to (30,30) splits b: below-left is id 3 */
                TEST_ASSERT_EQUAL_UINT16(x - 10 >= y - 10 ? 2 : 3, id);
            } else if (in_a) {
                TEST_ASSERT_EQUAL_UINT16(x - 4 >= y - 4 ? 0 : 1, id);
            } else {
                TEST_ASSERT_EQUAL_UINT16(ZL_VIS_NONE, id);
            }
            if (in_a && in_b) {
                /* Q16.16 depths 32833 and 32768 (z * 65536 / 1000, truncated),
                 * 65 * 65535 units of the window scale apart: 16639.76 in
                 * 1/256 of a step, reported floored. */
                TEST_ASSERT_EQUAL_UINT16(16639, rc_gap[y * W + x]);
            } else if (in_a || in_b) {
                TEST_ASSERT_EQUAL_UINT16(65535, rc_gap[y * W + x]);
            }
        }
}

static void test_raycast_interpenetrating_swap_column(void)
{
    /* A: depth 0 at x = 0 to 0.96 at x = 48, constant in y. B: constant 0.3.
     * A is nearer left of x = 15 (0.3 / 0.96 * 48), B right of it: pixel
     * centres 0.5 .. 14.5 show A, 15.5 .. 47.5 show B. */
    int32_t a1[9] = {0, 0, 0, 96, 0, 960, 96, 80, 960};
    int32_t a2[9] = {0, 0, 0, 96, 80, 960, 0, 80, 0};
    int32_t b1[9] = {0, 0, 300, 96, 0, 300, 96, 80, 300};
    int32_t b2[9] = {0, 0, 300, 96, 80, 300, 0, 80, 300};
    int x, y;
    mesh_init(&scene[0], 12, 4);
    put_tri(&scene[0], 0, a1);
    put_tri(&scene[0], 1, a2);
    put_tri(&scene[0], 2, b1);
    put_tri(&scene[0], 3, b2);
    finish_scene(1);
    render_rows(ZL_VIS_RAYCAST);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            uint16_t id = rc_ids[y * W + x];
            TEST_ASSERT_TRUE(x < 15 ? id <= 1 : id >= 2);
        }
    /* A crossing at 15.0 is a whole pixel from the nearest centres: a clear gap */
    TEST_ASSERT_GREATER_THAN(TIE * 100, rc_gap[5 * W + 14]);
    /* and the AET finds the same column on every row */
    render_rows(ZL_VIS_AET);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            TEST_ASSERT_TRUE(x < 15 ? vis_ids[y * W + x] <= 1 : vis_ids[y * W + x] >= 2);
}

static void test_raycast_top_left_rule(void)
{
    /* Triangle with vertices on pixel centres: (2.5,2.5), (8.5,2.5), (2.5,8.5).
     * Top edge y = 2.5 (interior below): centres on it covered. Left edge
     * x = 2.5: covered. Hypotenuse x + y = 11: centres on it not covered. */
    int32_t t0[9] = {5, 5, 100, 17, 5, 100, 5, 17, 100};
    int x, y, n = 0;
    mesh_init(&scene[0], 3, 1);
    put_tri(&scene[0], 0, t0);
    finish_scene(1);
    render_rows(ZL_VIS_RAYCAST);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int expect = x >= 2 && y >= 2 && x + y + 1 < 11; /* centre (x+.5)+(y+.5) < 11 */
            TEST_ASSERT_EQUAL_INT(expect, rc_ids[y * W + x] == 0);
            n += expect;
        }
    TEST_ASSERT_EQUAL_INT(21, n); /* 6 + 5 + 4 + 3 + 2 + 1 */
}

static void test_raycast_shared_edges_cover_once_and_ties_go_first(void)
{
    /* A 2x2 grid of rectangles split along diagonals, all at one depth,
     * covered twice (ids 0..7 and, coplanar, 8..15): every centre in the
     * square is covered, by exactly the first copy, with gap 0. */
    int x, y;
    mesh_init(&scene[0], 48, 16);
    put_rect(&scene[0], 0, 3, 3, 13, 11, 400);
    put_rect(&scene[0], 2, 13, 3, 27, 11, 400);
    put_rect(&scene[0], 4, 3, 11, 13, 25, 400);
    put_rect(&scene[0], 6, 13, 11, 27, 25, 400);
    memcpy(&scene[0].pos[24 * 3], scene[0].pos, 24 * 3 * sizeof(zl_fixed));
    for (x = 0; x < 24; x++)
        scene[0].idx[24 + x] = (uint16_t)(24 + x);
    finish_scene(1);
    render_rows(ZL_VIS_RAYCAST);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int in = x >= 3 && x < 27 && y >= 3 && y < 25;
            uint16_t id = rc_ids[y * W + x];
            TEST_ASSERT_EQUAL_INT(in, id != ZL_VIS_NONE);
            if (in) {
                TEST_ASSERT_TRUE(id < 8);
                TEST_ASSERT_EQUAL_UINT16(0, rc_gap[y * W + x]);
            }
        }
}

static void test_raycast_culls_by_winding(void)
{
    int32_t cw[9] = {4, 4, 100, 40, 4, 100, 4, 40, 100};  /* clockwise on screen */
    int32_t ccw[9] = {60, 4, 100, 60, 40, 100, 90, 4, 100}; /* counter-clockwise */
    int i, n0 = 0, n1 = 0;
    mesh_init(&scene[0], 6, 2);
    put_tri(&scene[0], 0, cw);
    put_tri(&scene[0], 1, ccw);
    scene[0].state.cull = ZL_CULL_BACK; /* front = CCW by default */
    finish_scene(1);
    render_rows(ZL_VIS_RAYCAST);
    for (i = 0; i < W * H; i++) {
        n0 += rc_ids[i] == 0;
        n1 += rc_ids[i] == 1;
    }
    TEST_ASSERT_EQUAL_INT(0, n0);
    TEST_ASSERT_GREATER_THAN(100, n1);
    scene[0].state.front_face = ZL_FRONT_CW;
    render_rows(ZL_VIS_RAYCAST);
    n0 = n1 = 0;
    for (i = 0; i < W * H; i++) {
        n0 += rc_ids[i] == 0;
        n1 += rc_ids[i] == 1;
    }
    TEST_ASSERT_GREATER_THAN(100, n0);
    TEST_ASSERT_EQUAL_INT(0, n1);
}

/* ------------------------------------------------ random scenes vs oracle */

static void random_scene(void)
{
    int i, t;
    for (i = 0; i < NMESH; i++) {
        scene_mesh *m = &scene[i];
        mesh_init(m, NV, NT);
        m->use_mvp = rand_range(0, 2) != 0;
        for (t = 0; t < NV; t++) {
            if (m->use_mvp) {
                m->pos[t * 3] = rand_range(-3 * ZL_FX_ONE, 3 * ZL_FX_ONE);
                m->pos[t * 3 + 1] = rand_range(-3 * ZL_FX_ONE, 3 * ZL_FX_ONE);
                m->pos[t * 3 + 2] = rand_range(-4 * ZL_FX_ONE, 4 * ZL_FX_ONE);
            } else {
                int32_t reach = rand_range(0, 4) == 0 ? 3000 : 70;
                m->pos[t * 3] = rand_range(-reach, reach + 2 * W) * (ZL_FX_ONE / 2) + rand_range(0, 32767);
                m->pos[t * 3 + 1] = rand_range(-reach, reach + 2 * H) * (ZL_FX_ONE / 2) + rand_range(0, 32767);
                m->pos[t * 3 + 2] = rand_range(-ZL_FX_ONE / 8, ZL_FX_ONE + ZL_FX_ONE / 8);
            }
        }
        for (t = 0; t < NT * 3; t++)
            m->idx[t] = (uint16_t)rand_range(0, NV - 1);
        if (m->use_mvp) {
            zl_mat4 proj, view, rot;
            zl_vec3 eye = {rand_range(-ZL_FX_ONE, ZL_FX_ONE), rand_range(-ZL_FX_ONE, ZL_FX_ONE), ZL_FX_INT(3)};
            zl_vec3 target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, rand_range(5000, 20000), ZL_FX_INT(W) / H,
                                                             ZL_FX_ONE / 10, ZL_FX_INT(rand_range(5, 100))));
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
            zl_mat4_rotate_y(&rot, rand_range(0, 65535));
            zl_mat4_mul(&view, &view, &rot);
            zl_mat4_mul(&m->mvp, &proj, &view);
        }
        m->state.cull = (uint8_t)rand_range(0, 2);
        m->state.front_face = (uint8_t)rand_range(0, 1);
    }
    finish_scene(NMESH);
}

static void test_zbuffer_and_aet_agree_with_the_ray_caster(void)
{
    long covered = 0, zb_ties = 0, aet_ties = 0, aet_zb_ties = 0;
    int n, i;
    for (n = 0; n < 40; n++) {
        agreement a;
        random_scene();
        render_zbuffer();
        render_rows_tight(ZL_VIS_RAYCAST);
        a = compare_ids(zb_ids);
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, a.coverage, "z-buffer covers other pixels than the ray caster");
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, a.wrong, "z-buffer shows a surface clearly behind another");
        covered += a.covered;
        zb_ties += a.ties;
        render_rows_tight(ZL_VIS_AET);
        a = compare_ids(vis_ids);
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, a.coverage, "AET covers other pixels than the ray caster");
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, a.wrong, "AET shows a surface clearly behind another");
        aet_ties += a.ties;
        /* AET against the z-buffer: same colours where the ids agree, and
         * where they do not, it is a near tie. */
        for (i = 0; i < W * H; i++) {
            if (vis_ids[i] == zb_ids[i]) {
                TEST_ASSERT_EQUAL_MEMORY(&zb_color[i * 3], &vis_color[i * 3], 3);
            } else {
                TEST_ASSERT_TRUE(rc_gap[i] <= TIE);
                aet_zb_ties++;
            }
        }
    }
    /* Random triangles with random vertex depths intersect a lot, so there
     * are near ties; they must stay a small fraction of the covered pixels. */
    TEST_ASSERT_GREATER_THAN(40L * W * H / 4, covered);
    TEST_ASSERT_LESS_THAN(covered / 100, zb_ties);
    TEST_ASSERT_LESS_THAN(covered / 1000 + 1, aet_ties);
    TEST_ASSERT_LESS_THAN(covered / 100, aet_zb_ties);
}

static void test_aet_splits_spans_of_interpenetrating_pairs(void)
{
    /* Many pairs of long thin triangles crossing in depth at varying
     * columns: every row has spans that must be split. */
    int n, t;
    long ties = 0, covered = 0;
    for (n = 0; n < 20; n++) {
        agreement a;
        mesh_init(&scene[0], NT * 3, NT);
        for (t = 0; t < NT; t++) {
            int32_t y0 = rand_range(-4, 2 * H), y1 = y0 + rand_range(4, 30);
            int32_t za = rand_range(0, 1000), zb = rand_range(0, 1000);
            int32_t tri[9] = {rand_range(-10, 10), y0, za, 2 * W + rand_range(-10, 10), (y0 + y1) / 2, zb,
                              rand_range(-10, 10), y1, za};
            put_tri(&scene[0], t, tri);
        }
        finish_scene(1);
        render_rows(ZL_VIS_RAYCAST);
        render_rows(ZL_VIS_AET);
        a = compare_ids(vis_ids);
        TEST_ASSERT_EQUAL_INT(0, a.coverage);
        TEST_ASSERT_EQUAL_INT(0, a.wrong);
        ties += a.ties;
        covered += a.covered;
    }
    TEST_ASSERT_GREATER_THAN(20L * W * H / 4, covered);
    TEST_ASSERT_LESS_THAN(covered / 1000 + 1, ties);
}

/* ----------------------------------------------------------- painter's */

static void test_painter_equals_zbuffer_on_depth_separated_scenes(void)
{
    int n, t, i;
    for (n = 0; n < 30; n++) {
        /* Each triangle in its own depth slab, slabs in random order: the
         * farthest-vertex key orders every overlapping pair correctly. */
        mesh_init(&scene[0], NT * 3, NT);
        for (t = 0; t < NT; t++) {
            int32_t z = 30 + 60 * ((t * 7 + n) % NT);
            int32_t tri[9];
            int k;
            for (k = 0; k < 3; k++) {
                tri[k * 3] = rand_range(-20, 2 * W + 20);
                tri[k * 3 + 1] = rand_range(-20, 2 * H + 20);
                tri[k * 3 + 2] = z + rand_range(0, 50);
            }
            put_tri(&scene[0], t, tri);
        }
        scene[0].state.cull = (uint8_t)rand_range(0, 2);
        finish_scene(1);
        render_zbuffer();
        render_rows(ZL_VIS_RAYCAST);
        render_painter();
        for (i = 0; i < W * H; i++) {
            TEST_ASSERT_EQUAL_UINT16(zb_ids[i], vis_ids[i]);
            TEST_ASSERT_EQUAL_UINT16(rc_ids[i], vis_ids[i]);
            TEST_ASSERT_EQUAL_MEMORY(&zb_color[i * 3], &vis_color[i * 3], 3);
        }
    }
}

static long painter_wrong_pixels(void)
{
    agreement a;
    render_rows(ZL_VIS_RAYCAST);
    render_painter();
    a = compare_ids(vis_ids);
    TEST_ASSERT_EQUAL_INT(0, a.coverage); /* it covers the right pixels, only the order is wrong */
    return a.wrong;
}

static void test_painter_failure_cases(void)
{
    /* Intersecting: A tilts from depth 0.1 (left) to 0.9 (right), B is flat
     * at 0.5 over the same rectangle. A's farthest vertex is farther, so A
     * is drawn first and B covers all of it: wrong on A's near (left) half. */
    int32_t a1[9] = {8, 8, 100, 88, 8, 900, 88, 72, 900};
    int32_t a2[9] = {8, 8, 100, 88, 72, 900, 8, 72, 100};
    int32_t b1[9] = {8, 8, 500, 88, 8, 500, 88, 72, 500};
    int32_t b2[9] = {8, 8, 500, 88, 72, 500, 8, 72, 500};
    /* Cyclic: three planks (two triangles each), each over the next at one
     * end and under it at the other: S1 along the top, near at its left;
     * S2 down the right side, near at its top; S3 diagonal from the bottom
     * right (near) to the top left (far). S2 covers S1, S3 covers S2, S1
     * covers S3: no drawing order is right. */
    int32_t p1a[9] = {4, 8, 200, 92, 8, 600, 92, 20, 600}, p1b[9] = {4, 8, 200, 92, 20, 600, 4, 20, 200};
    int32_t p2a[9] = {76, 4, 200, 88, 4, 200, 88, 76, 600}, p2b[9] = {76, 4, 200, 88, 76, 600, 76, 76, 600};
    int32_t p3a[9] = {90, 66, 200, 90, 78, 200, 8, 16, 600}, p3b[9] = {90, 66, 200, 8, 16, 600, 8, 4, 600};
    /* Key misorder without a cycle or an intersection: a long sliver (near
     * end 0.15 at the left, far point 0.95 at the right) lies in front of a
     * small flat triangle at 0.3 wherever they overlap (x < 8 px, where the
     * sliver is nearer than 0.26), but its farthest vertex makes the key
     * draw it first. */
    int32_t s1[9] = {4, 30, 150, 94, 34, 950, 4, 44, 150};
    int32_t s2[9] = {6, 24, 300, 16, 24, 300, 6, 60, 300};
    long wrong;
    mesh_init(&scene[0], 12, 4);
    put_tri(&scene[0], 0, a1);
    put_tri(&scene[0], 1, a2);
    put_tri(&scene[0], 2, b1);
    put_tri(&scene[0], 3, b2);
    finish_scene(1);
    wrong = painter_wrong_pixels();
    TEST_ASSERT_GREATER_THAN(300, wrong); /* about half of the 40 x 32 rectangle */

    mesh_init(&scene[0], 18, 6);
    put_tri(&scene[0], 0, p1a);
    put_tri(&scene[0], 1, p1b);
    put_tri(&scene[0], 2, p2a);
    put_tri(&scene[0], 3, p2b);
    put_tri(&scene[0], 4, p3a);
    put_tri(&scene[0], 5, p3b);
    finish_scene(1);
    wrong = painter_wrong_pixels();
    TEST_ASSERT_GREATER_THAN(10, wrong); /* no order of the three is right */
    render_rows(ZL_VIS_AET);
    TEST_ASSERT_EQUAL_INT(0, compare_ids(vis_ids).wrong);

    mesh_init(&scene[0], 6, 2);
    put_tri(&scene[0], 0, s1);
    put_tri(&scene[0], 1, s2);
    finish_scene(1);
    wrong = painter_wrong_pixels();
    TEST_ASSERT_GREATER_THAN(10, wrong);
    /* while the AET and the z-buffer get all three right */
    render_rows(ZL_VIS_AET);
    TEST_ASSERT_EQUAL_INT(0, compare_ids(vis_ids).wrong);
}

/* ------------------------------------------------------------------ BSP */

/*
 * A hand-built tree (what tools/bsp writes) for two unit squares crossing at
 * right angles:
 *   square A in the plane x = 0 (y, z in -1..1): the root, plane n = (1,0,0);
 *   square B in the plane z = 0 (x, y in -1..1) crosses that plane, so it is
 *     split into B+ (x 0..1, in front of the root: node 1) and B- (x -1..0,
 *     behind: node 2), each in the plane z = 0.
 * The split is at x = 0 exactly, so the pieces cover exactly B's pixels; but
 * each piece is two triangles with its own diagonal, so which of B's two
 * source ids (2, 3) a pixel gets differs from the unsplit B between the
 * diagonals: that is the split-edge exception, and the test compares
 * surfaces (A or B) and counts the id swaps separately.
 */
static const zl_fixed bsp_pos[] = {
    /* A: x = 0 */
    0, -65536, -65536, 0, 65536, -65536, 0, 65536, 65536, 0, -65536, 65536,
    /* B+: z = 0, x 0..1 */
    0, -65536, 0, 65536, -65536, 0, 65536, 65536, 0, 0, 65536, 0,
    /* B-: z = 0, x -1..0 */
    -65536, -65536, 0, 0, -65536, 0, 0, 65536, 0, -65536, 65536, 0,
};
/* Triangles wound counter-clockwise seen from +x (A), +z (B). Source ids:
 * A = 0, 1; B = 2, 3 in the unsplit mesh below. */
static const uint16_t bsp_idx[] = {
    0, 1, 2, 0, 2, 3,     /* A, node 0 */
    4, 5, 6, 4, 6, 7,     /* B+, node 1 */
    8, 9, 10, 8, 10, 11,  /* B-, node 2 */
};
static const uint16_t bsp_src[] = {0, 1, 2, 3, 2, 3};
static const zl_bsp_node bsp_nodes[] = {
    {{65536, 0, 0}, 0, 0, 2, 1, 2},
    {{0, 0, 65536}, 0, 2, 2, ZL_BSP_LEAF, ZL_BSP_LEAF},
    {{0, 0, 65536}, 0, 4, 2, ZL_BSP_LEAF, ZL_BSP_LEAF},
};

/* The same two squares unsplit, for the z-buffer and the ray caster. */
static const zl_fixed plain_pos[] = {
    0, -65536, -65536, 0, 65536, -65536, 0, 65536, 65536, 0, -65536, 65536,
    -65536, -65536, 0, 65536, -65536, 0, 65536, 65536, 0, -65536, 65536, 0,
};
static const uint16_t plain_idx[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};

/* Window position of a model point (double: the test's own projection). */
static void project(const zl_mat4 *m, double x, double y, double z, double *wx, double *wy)
{
    double c[4];
    int r;
    for (r = 0; r < 4; r++)
        c[r] = (m->m[r * 4] * x + m->m[r * 4 + 1] * y + m->m[r * 4 + 2] * z + m->m[r * 4 + 3] * 65536.0) / 65536.0;
    *wx = (c[0] / c[3] + 1) * W / 2;
    *wy = (1 - c[1] / c[3]) * H / 2;
}

/* Squared distance from (px, py) to the segment a-b. */
static double seg_dist(double px, double py, double ax, double ay, double bx, double by)
{
    double dx = bx - ax, dy = by - ay, t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy);
    double qx, qy;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    qx = ax + t * dx - px;
    qy = ay + t * dy - py;
    return qx * qx + qy * qy; /* squared */
}

/* Is pixel i's centre within 1/8 pixel of B's top or bottom edge, the two
 * edges the split put a new vertex on (at x = 0)? Snapping that vertex moves
 * the outline by up to 1/32 pixel there. */
static int near_split_edge(const zl_mat4 *mvp, int i)
{
    double px = i % W + 0.5, py = i / W + 0.5, ax, ay, bx, by;
    int s;
    for (s = -1; s <= 1; s += 2) {
        project(mvp, -65536.0, s * 65536.0, 0, &ax, &ay);
        project(mvp, 65536.0, s * 65536.0, 0, &bx, &by);
        if (seg_dist(px, py, ax, ay, bx, by) <= 0.125 * 0.125)
            return 1;
    }
    return 0;
}

/* Compare surfaces (A: ids 0, 1; B: 2, 3) with the oracle; pixels at the
 * split edges are counted apart. */
static long split_outline;
static agreement compare_surfaces(const zl_mat4 *mvp)
{
    agreement a = {0, 0, 0, 0};
    int i;
    for (i = 0; i < W * H; i++) {
        uint16_t p = vis_ids[i], q = rc_ids[i];
        a.covered += q != ZL_VIS_NONE;
        if (p == q || (p != ZL_VIS_NONE && q != ZL_VIS_NONE && p / 2 == q / 2))
            continue;
        if (near_split_edge(mvp, i)) {
            split_outline++;
            continue;
        }
        if (p == ZL_VIS_NONE || q == ZL_VIS_NONE)
            a.coverage++;
        else if (rc_gap[i] <= TIE)
            a.ties++;
        else
            a.wrong++;
    }
    return a;
}

static void test_bsp_both_orders_match_the_oracle_from_every_side(void)
{
    static uint32_t mask[(W + 31) / 32 * H + H];
    zl_bsp bsp;
    zl_vis_target t;
    zl_mat4 proj, view;
    zl_vec3 up = {0, ZL_FX_ONE, 0}, target = {0, 0, 0};
    int e, order, i;
    long ties = 0, split_edge = 0;
    memset(&bsp, 0, sizeof bsp);
    bsp.positions = bsp_pos;
    bsp.indices = bsp_idx;
    bsp.source = bsp_src;
    bsp.nodes = bsp_nodes;
    bsp.vertex_count = 12;
    bsp.triangle_count = 6;
    bsp.node_count = 3;
    bsp.root = 0;
    bsp.depth = 2;
    TEST_ASSERT_TRUE(zl_bsp_mask_bytes(W, H) <= sizeof mask);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(W) / H,
                                                     ZL_FX_ONE / 10, ZL_FX_INT(20)));
    for (e = 0; e < 8; e++) {
        /* eyes in all four quadrants around the crossing, above and below */
        zl_vec3 eye;
        eye.x = (e & 1) ? ZL_FX_INT(3) : -ZL_FX_INT(3);
        eye.z = (e & 2) ? ZL_FX_INT(3) : -ZL_FX_INT(3);
        eye.y = (e & 4) ? ZL_FX_INT(1) : -ZL_FX_ONE / 2;
        eye.x += rand_range(-20000, 20000);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
        mesh_init(&scene[0], 8, 4);
        memcpy(scene[0].pos, plain_pos, sizeof plain_pos);
        memcpy(scene[0].idx, plain_idx, sizeof plain_idx);
        scene[0].use_mvp = 1;
        zl_mat4_mul(&scene[0].mvp, &proj, &view);
        finish_scene(1);
        render_zbuffer();
        render_rows(ZL_VIS_RAYCAST);
        for (order = 0; order < 2; order++) {
            agreement a;
            memset(&t, 0, sizeof t);
            t.color = vis_color;
            t.color_stride = W * 3;
            t.ids = vis_ids;
            t.ids_stride = W * 2;
            t.width = W;
            t.height = H;
            t.format = ZL_FORMAT_RGB888;
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_bsp_draw(&bsp, &scene[0].mvp, eye, &scene[0].state, &t, bg,
                                                     (zl_bsp_order)order, mask, sizeof mask));
            a = compare_surfaces(&scene[0].mvp);
            TEST_ASSERT_EQUAL_INT(0, a.wrong);
            TEST_ASSERT_EQUAL_INT(0, a.coverage);
            TEST_ASSERT_GREATER_THAN(W * H / 10, a.covered);
            ties += a.ties;
            for (i = 0; i < W * H; i++) {
                split_edge += vis_ids[i] != zb_ids[i] && vis_ids[i] / 2 == zb_ids[i] / 2;
                /* a surface swap against the z-buffer only at a near tie or the split outline */
                TEST_ASSERT_TRUE(vis_ids[i] / 2 == zb_ids[i] / 2 || rc_gap[i] <= TIE || near_split_edge(&scene[0].mvp, i));
            }
        }
    }
    /* The pieces' diagonals differ from B's own: ids 2 and 3 swap between
     * them (the split-edge exception), and the two surfaces are near a tie
     * only along their line of intersection. */
    TEST_ASSERT_GREATER_THAN(0, split_edge);
    TEST_ASSERT_LESS_THAN(16, split_outline); /* a handful of pixels over 16 frames */
    TEST_ASSERT_LESS_THAN(16L * W * H / 4, split_edge);
    TEST_ASSERT_LESS_THAN(16L * W * H / 50, ties);
}

static void test_bsp_front_to_back_early_out_and_errors(void)
{
    static uint32_t mask[(W + 31) / 32 * H + H];
    static const zl_fixed wall_pos[] = {-ZL_FX_INT(50), -ZL_FX_INT(50), 0, ZL_FX_INT(50), -ZL_FX_INT(50), 0,
                                        ZL_FX_INT(50), ZL_FX_INT(50), 0, -ZL_FX_INT(50), ZL_FX_INT(50), 0,
                                        -ZL_FX_INT(50), -ZL_FX_INT(50), -ZL_FX_ONE, ZL_FX_INT(50), -ZL_FX_INT(50), -ZL_FX_ONE,
                                        ZL_FX_INT(50), ZL_FX_INT(50), -ZL_FX_ONE, -ZL_FX_INT(50), ZL_FX_INT(50), -ZL_FX_ONE};
    static const uint16_t wall_idx[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    static const uint16_t wall_src[] = {0, 1, 5, 5};
    /* Root: a wall (z = 0) filling the view; behind it (node 1, z = -1) a
     * second one, which must not show in either order. */
    static const zl_bsp_node wall_nodes[] = {{{0, 0, 65536}, 0, 0, 2, ZL_BSP_LEAF, 1},
                                             {{0, 0, 65536}, -((int64_t)1 << 32), 2, 2, ZL_BSP_LEAF, ZL_BSP_LEAF}};
    static const zl_bsp_node bad_nodes[] = {{{0, 0, 65536}, 0, 0, 2, 5, ZL_BSP_LEAF}, {{0, 0, 65536}, 0, 0, 0, ZL_BSP_LEAF, ZL_BSP_LEAF}};
    static const zl_bsp_node loop_nodes[] = {{{0, 0, 65536}, 0, 0, 2, 0, ZL_BSP_LEAF}, {{0, 0, 65536}, 0, 0, 0, ZL_BSP_LEAF, ZL_BSP_LEAF}};
    zl_bsp bsp;
    zl_vis_target t;
    zl_state st;
    zl_mat4 proj, view, mvp;
    zl_vec3 eye = {0, 0, ZL_FX_INT(2)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    int i;
    memset(&bsp, 0, sizeof bsp);
    bsp.positions = wall_pos;
    bsp.indices = wall_idx;
    bsp.source = wall_src;
    bsp.nodes = wall_nodes;
    bsp.vertex_count = 8;
    bsp.triangle_count = 4;
    bsp.node_count = 2;
    bsp.depth = 2;
    zl_state_default(&st);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(W) / H,
                                                     ZL_FX_ONE / 10, ZL_FX_INT(20)));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
    zl_mat4_mul(&mvp, &proj, &view);
    memset(&t, 0, sizeof t);
    t.ids = vis_ids;
    t.ids_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB565;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_bsp_draw(&bsp, &mvp, eye, &st, &t, bg, ZL_BSP_FRONT_TO_BACK, mask, sizeof mask));
    for (i = 0; i < W * H; i++)
        TEST_ASSERT_TRUE(vis_ids[i] <= 1);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_bsp_draw(&bsp, &mvp, eye, &st, &t, bg, ZL_BSP_BACK_TO_FRONT, NULL, 0));
    for (i = 0; i < W * H; i++)
        TEST_ASSERT_TRUE(vis_ids[i] <= 1);
    /* from behind, the back wall shows */
    {
        zl_vec3 behind = {0, 0, -ZL_FX_INT(3)};
        zl_mat4 v2, m2;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&v2, behind, target, up));
        zl_mat4_mul(&m2, &proj, &v2);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_bsp_draw(&bsp, &m2, behind, &st, &t, bg, ZL_BSP_FRONT_TO_BACK, mask, sizeof mask));
        for (i = 0; i < W * H; i++)
            TEST_ASSERT_EQUAL_UINT16(5, vis_ids[i]);
    }
    /* mask checks */
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_bsp_draw(&bsp, &mvp, eye, &st, &t, bg, ZL_BSP_FRONT_TO_BACK, NULL, 0));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_bsp_draw(&bsp, &mvp, eye, &st, &t, bg, ZL_BSP_FRONT_TO_BACK, mask,
                                                   zl_bsp_mask_bytes(W, H) - 1));
    TEST_ASSERT_EQUAL_INT(0, zl_bsp_mask_bytes(0, H));
    /* malformed trees are refused before any pixel */
    for (i = 0; i < W * H; i++)
        vis_ids[i] = 7;
    bsp.nodes = bad_nodes;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_bsp_draw(&bsp, &mvp, eye, &st, &t, bg, ZL_BSP_BACK_TO_FRONT, NULL, 0));
    bsp.nodes = loop_nodes;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_bsp_draw(&bsp, &mvp, eye, &st, &t, bg, ZL_BSP_BACK_TO_FRONT, NULL, 0));
    bsp.nodes = wall_nodes;
    bsp.depth = ZL_BSP_MAX_DEPTH + 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_bsp_draw(&bsp, &mvp, eye, &st, &t, bg, ZL_BSP_BACK_TO_FRONT, NULL, 0));
    for (i = 0; i < W * H; i++)
        TEST_ASSERT_EQUAL_UINT16(7, vis_ids[i]);
}

/* ------------------------------------------------------------- culling */

static void test_viewpoint_and_projected_culling_agree(void)
{
    static zl_fixed pos[9];
    static const uint16_t idx[3] = {0, 1, 2};
    zl_mesh m;
    zl_mat4 proj, view, mvp;
    zl_vec3 up = {0, ZL_FX_ONE, 0};
    int n, agree = 0, undecided = 0, disagree = 0, k;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.vertex_count = 3;
    m.triangle_count = 1;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(W) / H,
                                                     ZL_FX_ONE / 10, ZL_FX_INT(50)));
    /* by hand: a triangle in z = 0, counter-clockwise seen from +z */
    pos[0] = 0;
    pos[1] = 0;
    pos[2] = 0;
    pos[3] = ZL_FX_ONE;
    pos[4] = 0;
    pos[5] = 0;
    pos[6] = 0;
    pos[7] = ZL_FX_ONE;
    pos[8] = 0;
    {
        zl_vec3 front = {ZL_FX_ONE / 4, ZL_FX_ONE / 4, ZL_FX_INT(3)}, back = {ZL_FX_ONE / 4, ZL_FX_ONE / 4, -ZL_FX_INT(3)};
        zl_vec3 target = {ZL_FX_ONE / 4, ZL_FX_ONE / 4, 0}, edge_on = {ZL_FX_INT(5), ZL_FX_ONE / 4, 0};
        TEST_ASSERT_EQUAL_INT(1, zl_cull_viewpoint(&m, 0, front, ZL_FRONT_CCW));
        TEST_ASSERT_EQUAL_INT(0, zl_cull_viewpoint(&m, 0, front, ZL_FRONT_CW));
        TEST_ASSERT_EQUAL_INT(0, zl_cull_viewpoint(&m, 0, back, ZL_FRONT_CCW));
        TEST_ASSERT_EQUAL_INT(-1, zl_cull_viewpoint(&m, 0, edge_on, ZL_FRONT_CCW));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, front, target, up));
        zl_mat4_mul(&mvp, &proj, &view);
        TEST_ASSERT_EQUAL_INT(1, zl_cull_projected(&m, 0, &mvp, W, H, ZL_FRONT_CCW));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, back, target, up));
        zl_mat4_mul(&mvp, &proj, &view);
        TEST_ASSERT_EQUAL_INT(0, zl_cull_projected(&m, 0, &mvp, W, H, ZL_FRONT_CCW));
    }
    for (n = 0; n < 3000; n++) {
        zl_vec3 eye = {rand_range(-4 * ZL_FX_ONE, 4 * ZL_FX_ONE), rand_range(-4 * ZL_FX_ONE, 4 * ZL_FX_ONE),
                       rand_range(-4 * ZL_FX_ONE, 4 * ZL_FX_ONE)};
        zl_vec3 target = {rand_range(-ZL_FX_ONE / 2, ZL_FX_ONE / 2), rand_range(-ZL_FX_ONE / 2, ZL_FX_ONE / 2),
                          rand_range(-ZL_FX_ONE / 2, ZL_FX_ONE / 2)};
        uint8_t ff = (uint8_t)rand_range(0, 1);
        int vp, pr;
        for (k = 0; k < 9; k++)
            pos[k] = rand_range(-2 * ZL_FX_ONE, 2 * ZL_FX_ONE);
        if (zl_mat4_look_at(&view, eye, target, up) != ZL_OK)
            continue;
        zl_mat4_mul(&mvp, &proj, &view);
        vp = zl_cull_viewpoint(&m, 0, eye, ff);
        pr = zl_cull_projected(&m, 0, &mvp, W, H, ff);
        if (pr < 0 || vp < 0) {
            undecided++; /* nothing on screen, or exactly edge-on */
            continue;
        }
        if (vp != pr) {
            /* Only where snapping to 1/16 pixel decides the winding: the
             * projected triangle (the test's own projection in double) is
             * thinner than the snapping error, i.e. its doubled area is
             * below perimeter / 8 pixels (each vertex moves up to 1/32 pixel
             * in x and y). A triangle reaching behind the near plane has no
             * such projection; there the eye must be nearly in its plane. */
            double wx[3], wy[3], ww[3], area, per = 0;
            for (k = 0; k < 3; k++) {
                double c[4];
                int r;
                for (r = 0; r < 4; r++)
                    c[r] = (mvp.m[r * 4] * (double)pos[k * 3] + mvp.m[r * 4 + 1] * (double)pos[k * 3 + 1] +
                            mvp.m[r * 4 + 2] * (double)pos[k * 3 + 2] + mvp.m[r * 4 + 3] * 65536.0) / 65536.0;
                ww[k] = c[3] / 65536.0;
                wx[k] = (c[0] / c[3] + 1) * W / 2;
                wy[k] = (1 - c[1] / c[3]) * H / 2;
            }
            if (ww[0] > 0.1 && ww[1] > 0.1 && ww[2] > 0.1) {
                area = (wx[1] - wx[0]) * (wy[2] - wy[0]) - (wx[2] - wx[0]) * (wy[1] - wy[0]);
                for (k = 0; k < 3; k++) {
                    double dx = wx[(k + 1) % 3] - wx[k], dy = wy[(k + 1) % 3] - wy[k];
                    per += (dx < 0 ? -dx : dx) + (dy < 0 ? -dy : dy);
                }
                TEST_ASSERT_TRUE_MESSAGE((area < 0 ? -area : area) <= per / 8,
                                         "culling tests disagree on a triangle facing clearly");
            } else {
                double e1[3], e2[3], nn[3], d[3], dot, ln, ld;
                for (k = 0; k < 3; k++) {
                    e1[k] = pos[3 + k] - pos[k];
                    e2[k] = pos[6 + k] - pos[k];
                }
                d[0] = (double)eye.x - pos[0];
                d[1] = (double)eye.y - pos[1];
                d[2] = (double)eye.z - pos[2];
                nn[0] = e1[1] * e2[2] - e1[2] * e2[1];
                nn[1] = e1[2] * e2[0] - e1[0] * e2[2];
                nn[2] = e1[0] * e2[1] - e1[1] * e2[0];
                dot = nn[0] * d[0] + nn[1] * d[1] + nn[2] * d[2];
                ln = nn[0] * nn[0] + nn[1] * nn[1] + nn[2] * nn[2];
                ld = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                TEST_ASSERT_TRUE_MESSAGE(dot * dot < 1e-4 * ln * ld, "culling tests disagree on a clipped triangle");
            }
            disagree++;
            continue;
        }
        agree++;
    }
    TEST_ASSERT_GREATER_THAN(1000, agree);
    TEST_ASSERT_LESS_OR_EQUAL(agree / 200, disagree);
}

/* ------------------------------------------------------------------ API */

static int count_rows(void *user, const zl_vis_row *row)
{
    (void)row;
    ++*(int *)user;
    return 0;
}

static void test_sizes_capacities_and_errors(void)
{
    zl_vis_config c;
    zl_vis v;
    zl_vis_target t;
    size_t need;
    int rows = 0, algo;
    for (algo = ZL_VIS_AET; algo <= ZL_VIS_RAYCAST; algo++) {
        vis_config(&c, (zl_vis_algo)algo);
        need = zl_vis_bytes(&c);
        TEST_ASSERT_TRUE(need > 0 && need <= sizeof work);
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_vis_begin(&v, &c, work, need - 1));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_vis_begin(&v, &c, (uint8_t *)work + 4, need));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_begin(&v, &c, work, need));
    }
    vis_config(&c, ZL_VIS_AET);
    c.algorithm = 9;
    TEST_ASSERT_EQUAL_INT(0, zl_vis_bytes(&c));
    vis_config(&c, ZL_VIS_AET);
    c.max_active = 0;
    TEST_ASSERT_EQUAL_INT(0, zl_vis_bytes(&c));
    c.algorithm = ZL_VIS_PAINTER; /* the painter's method has no active set */
    TEST_ASSERT_TRUE(zl_vis_bytes(&c) > 0);
    /* Ten full-height triangles need ten active pieces: capacity error
     * before any row, then the needs are known. */
    mesh_init(&scene[0], 30, 10);
    {
        int i;
        for (i = 0; i < 10; i++) {
            int32_t tri[9] = {2 * i, -2, 100, 2 * i + 40, H, 100, 2 * i, 2 * H + 2, 100};
            put_tri(&scene[0], i, tri);
        }
    }
    finish_scene(1);
    for (algo = ZL_VIS_AET; algo <= ZL_VIS_RAYCAST; algo += 2) {
        vis_config(&c, (zl_vis_algo)algo);
        c.max_active = 9;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_begin(&v, &c, work, sizeof work));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_add_mesh(&v, &scene[0].mesh, NULL, &scene[0].state));
        rows = 0;
        TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_vis_render_rows(&v, bg, count_rows, &rows));
        TEST_ASSERT_EQUAL_INT(0, rows);
        TEST_ASSERT_EQUAL_UINT32(10, zl_vis_needs(&v).active);
        TEST_ASSERT_EQUAL_UINT32(10, zl_vis_needs(&v).triangles);
        c.max_active = 10;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_begin(&v, &c, work, sizeof work));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_add_mesh(&v, &scene[0].mesh, NULL, &scene[0].state));
        TEST_ASSERT_EQUAL_INT(0, zl_vis_render_rows(&v, bg, count_rows, &rows));
        TEST_ASSERT_EQUAL_INT(H, rows);
        /* a scene renders once */
        TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_vis_render_rows(&v, bg, count_rows, &rows));
    }
    /* painter: too few triangles; wrong target; rows API refused */
    vis_config(&c, ZL_VIS_PAINTER);
    c.max_triangles = 9;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_begin(&v, &c, work, sizeof work));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_vis_add_mesh(&v, &scene[0].mesh, NULL, &scene[0].state));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_vis_render_rows(&v, bg, count_rows, &rows));
    memset(&t, 0, sizeof t);
    t.ids = vis_ids;
    t.ids_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB888;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_painter_draw(&v, &t, bg));
    TEST_ASSERT_EQUAL_UINT32(10, zl_vis_needs(&v).triangles);
    t.width = W - 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_painter_draw(&v, &t, bg));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_painter_draw(NULL, &t, bg));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_vis_add_mesh(&v, NULL, NULL, &scene[0].state));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_raycast_overlapping_rectangles);
    RUN_TEST(test_raycast_interpenetrating_swap_column);
    RUN_TEST(test_raycast_top_left_rule);
    RUN_TEST(test_raycast_shared_edges_cover_once_and_ties_go_first);
    RUN_TEST(test_raycast_culls_by_winding);
    RUN_TEST(test_zbuffer_and_aet_agree_with_the_ray_caster);
    RUN_TEST(test_aet_splits_spans_of_interpenetrating_pairs);
    RUN_TEST(test_painter_equals_zbuffer_on_depth_separated_scenes);
    RUN_TEST(test_painter_failure_cases);
    RUN_TEST(test_bsp_both_orders_match_the_oracle_from_every_side);
    RUN_TEST(test_bsp_front_to_back_early_out_and_errors);
    RUN_TEST(test_viewpoint_and_projected_culling_agree);
    RUN_TEST(test_sizes_capacities_and_errors);
    return UNITY_END();
}
