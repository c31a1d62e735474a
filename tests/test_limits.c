/* SPDX-License-Identifier: MIT */
/*
 * The LIMITS block of zline.h, tested at each edge: inputs at a limit render
 * by the raster contract, inputs one step beyond return the documented error
 * and write nothing. Portable (runs under QEMU too), so the big cases use
 * scanline mode, which renders a 4096 x 4096 frame in a few kilobytes.
 *
 *   - window 4096 x 4096 (scanline mode, every row checked), 4096 x 1 and
 *     1 x 4096 (frame mode); 4097 refused by zl_init and zl_frame_bytes;
 *   - model coordinates and matrix entries at +-16384.0 render, one raw step
 *     beyond is ZL_ERR_RANGE; a clip-space overflow is ZL_ERR_RANGE, also
 *     when it needs the exact per-vertex pass (the cheap bound fails but the
 *     vertices fit, and the other way round);
 *   - vertices far outside the guard band (up to 2^30 pixels): a quad split
 *     along a diagonal that reaches far beyond it still covers every pixel
 *     exactly once, and a huge triangle covers all of a viewport;
 *   - a triangle one subpixel wide covers exactly the pixel whose centre it
 *     holds; half a subpixel snaps to nothing;
 *   - light_dir at and beyond +-1.0;
 *   - too-small strides, odd strides and addresses, work buffers one byte
 *     short or misaligned, unknown vertices, a cyclic BSP tree: the error,
 *     and every guard and payload byte unchanged.
 * Guards and row padding of every buffer are checked after every call.
 */
#include <string.h>

#include "unity.h"
#include "zline/zl_visibility.h"
#include "zline/zline.h"
#include "zt_guard.h"
#include "zt_ref.h"

#define PX(n) ((zl_fixed)((n) * 65536))
#define COORD_LIMIT ((zl_fixed)1 << 30) /* +-16384.0 */

static zt_surface surf;
static zl_context ctx;
static uint8_t snap_color[4096 * 5], snap_depth[4096 * 5];

void setUp(void)
{
    zt_guard_reset();
}

void tearDown(void)
{
}

/* A fresh guarded w x h target (the arena is reset), cleared, no culling. */
static void make(unsigned w, unsigned h, zl_format fmt)
{
    zt_guard_reset();
    TEST_ASSERT_EQUAL_INT(0, zt_surface_make(&surf, w, h, fmt, 1, 1, 6, 4, 0));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &surf.target));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, (zl_rgb){0, 0, 0}, 65535));
    ctx.state.cull = ZL_CULL_NONE;
}

static void snapshot(void)
{
    TEST_ASSERT_TRUE(surf.color_bytes <= sizeof snap_color && surf.depth_bytes <= sizeof snap_depth);
    memcpy(snap_color, surf.color, surf.color_bytes);
    memcpy(snap_depth, surf.depth, surf.depth_bytes);
}

/* Nothing of the surface changed since snapshot(), guards included. */
static void assert_untouched(void)
{
    ZT_ASSERT_SURFACE_INTACT(&surf);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(snap_color, surf.color, surf.color_bytes, "colour written by a failing call");
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(snap_depth, surf.depth, surf.depth_bytes, "depth written by a failing call");
}

static unsigned count_px(uint32_t v)
{
    unsigned x, y, n = 0;
    for (y = 0; y < surf.height; y++)
        for (x = 0; x < surf.width; x++)
            n += zt_get_px(&surf, x, y) == v;
    return n;
}

/* ------------------------------------------------------------ window size */

typedef struct {
    unsigned rows;
    unsigned bad;       /* rows whose coverage differs from the expectation */
    unsigned first_bad;
} big_check;

/* Scanline band of the 4096 x 4096 frame: the triangle (0,0) (4096,0)
 * (0,4096) covers pixels i < 4095 - j of row j (its hypotenuse i + j + 1 =
 * 4096 through the centres is a right edge: not covered), and the
 * one-pixel triangle at the bottom-right corner covers (4095, 4095). */
static int check_big_band(void *user, const zl_band *band)
{
    big_check *c = (big_check *)user;
    const uint16_t *px = (const uint16_t *)band->color;
    unsigned r;
    for (r = 0; r < band->rows; r++) {
        unsigned j = band->first_row + r, i, ok = 1;
        const uint16_t *row = px + (size_t)r * (size_t)band->color_stride / 2;
        unsigned lit = j < 4095 ? 4095 - j : 0;
        for (i = 0; i < 4096 && ok; i++) {
            uint16_t want = i < lit ? 0xFFFFu : 0;
            if (j == 4095 && i == 4095)
                want = 0x001Fu;
            ok = row[i] == want;
        }
        if (!ok) {
            if (c->bad == 0)
                c->first_bad = j;
            c->bad++;
        }
        c->rows++;
    }
    return 0;
}

static void test_window_4096_scanline(void)
{
    static const zl_fixed pos[] = {
        0, 0, 0, PX(4096), 0, 0, 0, PX(4096), 0,
        /* a right triangle whose corner is the centre of pixel (4095, 4095) */
        PX(4095) + PX(1) / 2, PX(4095) + PX(1) / 2, 0, PX(4095) + PX(1) / 2 + PX(1) / 4, PX(4095) + PX(1) / 2, 0,
        PX(4095) + PX(1) / 2, PX(4095) + PX(1) / 2 + PX(1) / 4, 0,
    };
    static const uint16_t idx[] = {0, 1, 2, 3, 4, 5};
    static const uint8_t fc[] = {255, 255, 255, 0, 0, 255};
    zl_mesh mesh = {pos, idx, NULL, fc, 6, 2};
    zl_frame_config cfg;
    zl_frame f;
    zl_state st;
    big_check c = {0, 0, 0};
    size_t bytes;
    void *work;
    memset(&cfg, 0, sizeof cfg);
    cfg.width = ZL_MAX_DIM;
    cfg.height = ZL_MAX_DIM;
    cfg.band_rows = 1;
    cfg.format = ZL_FORMAT_RGB565;
    cfg.color_buffers = 1;
    cfg.max_meshes = 1;
    cfg.max_vertices = 6;
    cfg.max_triangles = 2;
    cfg.max_active = 2;
    bytes = zl_frame_bytes(&cfg);
    TEST_ASSERT_TRUE(bytes > 0);
    work = zt_guard_alloc(bytes);
    TEST_ASSERT_NOT_NULL(work);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, bytes, (zl_rgb){0, 0, 0}, 65535));
    zl_state_default(&st);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &mesh, NULL, &st));
    TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, check_big_band, &c));
    TEST_ASSERT_EQUAL_UINT(0, zt_guard_check());
    TEST_ASSERT_EQUAL_UINT(4096, c.rows);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, c.bad, "rows of the 4096 x 4096 frame differ from the expectation");

    /* one beyond */
    cfg.width = ZL_MAX_DIM + 1;
    TEST_ASSERT_EQUAL_UINT(0, zl_frame_bytes(&cfg));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_frame_begin(&f, &cfg, work, bytes, (zl_rgb){0, 0, 0}, 65535));
    cfg.width = ZL_MAX_DIM;
    cfg.height = ZL_MAX_DIM + 1;
    TEST_ASSERT_EQUAL_UINT(0, zl_frame_bytes(&cfg));
    TEST_ASSERT_EQUAL_UINT(0, zt_guard_check());
}

static void test_window_4096_frame_mode_strips(void)
{
    static const zl_fixed pos[] = {0, 0, 0, PX(4096), 0, 0, 0, PX(4096), 0, PX(4096), PX(4096), 0};
    static const uint16_t idx[] = {0, 1, 2, 2, 1, 3};
    zl_mesh mesh = {pos, idx, NULL, NULL, 4, 2};
    zl_target t;
    unsigned k;
    /* 4096 x 1 and 1 x 4096: every pixel covered exactly once by the two
     * triangles of the square (depth EQUAL after the first pass proves
     * nothing was covered twice: a second cover would fail LESS) */
    for (k = 0; k < 2; k++) {
        unsigned w = k ? 1 : ZL_MAX_DIM, h = k ? ZL_MAX_DIM : 1;
        zt_guard_reset();
        TEST_ASSERT_EQUAL_INT(0, zt_surface_make(&surf, w, h, ZL_FORMAT_RGB565, 1, 1, 2, 2, 0));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &surf.target));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, (zl_rgb){0, 0, 0}, 65535));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, NULL));
        TEST_ASSERT_EQUAL_UINT(w * h, count_px(0xFFFFu));
        ZT_ASSERT_SURFACE_INTACT(&surf);
        /* one beyond: refused, nothing written */
        t = surf.target;
        if (k)
            t.height = ZL_MAX_DIM + 1;
        else
            t.width = ZL_MAX_DIM + 1;
        snapshot();
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_init(&ctx, &t));
        ctx.target = t; /* a target changed behind zl_init's back is checked again */
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_clear(&ctx, (zl_rgb){1, 2, 3}, 0));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_draw_mesh(&ctx, &mesh, NULL));
        assert_untouched();
    }
}

/* ------------------------------------------------------- coordinate range */

static void scale_matrix(zl_mat4 *m, zl_fixed sx, zl_fixed sy)
{
    zl_mat4_identity(m);
    m->m[0] = sx;
    m->m[5] = sy;
    m->m[10] = ZL_FX_ONE / 2; /* z = 0 maps to depth 0 */
}

static void test_model_coordinates_and_matrix_at_the_limit(void)
{
    /* positions at +-16384.0, scaled by 1/16384 (raw 4): clip x, y = +-1,
     * the viewport's edges; the triangle covers the lower-left half */
    zl_fixed pos[] = {-COORD_LIMIT, -COORD_LIMIT, 0, COORD_LIMIT, -COORD_LIMIT, 0, -COORD_LIMIT, COORD_LIMIT, 0};
    static const uint16_t idx[] = {0, 1, 2};
    zl_mesh mesh = {pos, idx, NULL, NULL, 3, 1};
    zl_mat4 m;
    make(16, 16, ZL_FORMAT_RGB888);
    scale_matrix(&m, 4, 4);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, &m));
    /* clip (-1,-1) (1,-1) (-1,1) is window (0,16) (16,16) (0,0): the
     * triangle below the diagonal x = y, which is a right edge */
    TEST_ASSERT_EQUAL_UINT(16 * 17 / 2 - 16, count_px(0xFFFFFFu));
    ZT_ASSERT_SURFACE_INTACT(&surf);

    /* one raw step beyond, in a position: refused before any pixel */
    make(16, 16, ZL_FORMAT_RGB888);
    pos[3] = COORD_LIMIT + 1;
    snapshot();
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &mesh, &m));
    pos[3] = -COORD_LIMIT - 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &mesh, &m));
    assert_untouched();
    pos[3] = COORD_LIMIT;

    /* matrix entries at +-16384.0 with positions of +-1/16384 */
    {
        zl_fixed small[] = {-4, -4, 0, 4, -4, 0, -4, 4, 0};
        zl_mesh sm = {small, idx, NULL, NULL, 3, 1};
        make(16, 16, ZL_FORMAT_RGB888);
        scale_matrix(&m, COORD_LIMIT, -COORD_LIMIT);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &sm, &m));
        TEST_ASSERT_EQUAL_UINT(16 * 17 / 2 - 16, count_px(0xFFFFFFu));
        ZT_ASSERT_SURFACE_INTACT(&surf);
        snapshot();
        scale_matrix(&m, COORD_LIMIT + 1, COORD_LIMIT);
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &sm, &m));
        scale_matrix(&m, COORD_LIMIT, -COORD_LIMIT - 1);
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &sm, &m));
        /* the same in an entry no vertex needs (w row, translation) */
        scale_matrix(&m, 4, 4);
        m.m[15] = ZL_FX_MIN;
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &sm, &m));
        assert_untouched();
    }
}

static void test_clip_space_overflow(void)
{
    /* each input in range, the product not: x_clip = 16384 * 16384 */
    zl_fixed pos[] = {COORD_LIMIT, 0, 0, 0, PX(1), 0, 0, 0, 0};
    static const uint16_t idx[] = {0, 1, 2};
    zl_mesh mesh = {pos, idx, NULL, NULL, 3, 1};
    zl_mat4 m;
    make(16, 16, ZL_FORMAT_RGB565);
    scale_matrix(&m, COORD_LIMIT, PX(1));
    snapshot();
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &mesh, &m));
    assert_untouched();

    /* x + y with entries 16384: the bound (max |x| + max |y|) * 16384
     * overflows, but every vertex has x = -y, so the exact pass accepts */
    {
        zl_fixed p2[] = {PX(2), PX(-2), 0, PX(-2), PX(2), 0, PX(1), PX(-1), PX(1) / 2};
        zl_mesh m2 = {p2, idx, NULL, NULL, 3, 1};
        zl_mat4_identity(&m);
        m.m[0] = COORD_LIMIT;
        m.m[1] = COORD_LIMIT;
        m.m[10] = ZL_FX_ONE / 2;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m2, &m));
        /* ... and one vertex that does overflow is found */
        p2[6] = PX(2);
        p2[7] = PX(1);
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &m2, &m));
        assert_untouched();
    }

    /* an unused vertex counts too: the rule is per mesh, not per triangle */
    {
        zl_fixed p3[] = {0, 0, 0, PX(1), 0, 0, 0, PX(1), 0, COORD_LIMIT + 1, 0, 0};
        zl_mesh m3 = {p3, idx, NULL, NULL, 4, 1};
        scale_matrix(&m, PX(1), PX(1));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &m3, &m));
        assert_untouched();
    }

    /* scanline mode refuses the same mesh in zl_frame_add_mesh */
    {
        zl_frame_config cfg;
        zl_frame f;
        zl_state st;
        size_t bytes;
        void *work;
        memset(&cfg, 0, sizeof cfg);
        cfg.width = 16;
        cfg.height = 16;
        cfg.band_rows = 1;
        cfg.format = ZL_FORMAT_RGB565;
        cfg.color_buffers = 1;
        cfg.max_meshes = 2;
        cfg.max_vertices = 8;
        cfg.max_triangles = 2;
        cfg.max_active = 2;
        bytes = zl_frame_bytes(&cfg);
        work = zt_guard_alloc(bytes);
        TEST_ASSERT_NOT_NULL(work);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, bytes, (zl_rgb){0, 0, 0}, 65535));
        zl_state_default(&st);
        scale_matrix(&m, COORD_LIMIT, PX(1));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_frame_add_mesh(&f, &mesh, &m, &st));
        scale_matrix(&m, COORD_LIMIT + 1, PX(1));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_frame_add_mesh(&f, &mesh, &m, &st));
        TEST_ASSERT_EQUAL_UINT(0, zt_guard_check());
    }
}

/* ------------------------------------------------------------ guard band */

static void test_far_outside_the_guard_band(void)
{
    /* x_clip = 4 x - 1, y_clip = 1 - 4 y on a 32 x 32 target: window
     * position = 64 * model position, so the quad's corners at +-8000 are
     * 512000 pixels out, four times the guard band. The quad is split along
     * the diagonal x + y = 1/4 (window x + y = 16), which crosses the
     * viewport; both halves are clipped at the guard band, and still every
     * pixel is covered by exactly one of them. */
    const zl_fixed big = PX(8000), q = PX(1) / 4;
    const zl_fixed pos[] = {-big, -big, 0, big, -big + q, 0, -big + q, big, 0, big, big, 0};
    static const uint16_t tri_a[] = {0, 1, 2}, tri_b[] = {2, 1, 3};
    zl_mesh a = {pos, tri_a, NULL, NULL, 4, 1}, b = {pos, tri_b, NULL, NULL, 4, 1};
    zl_mat4 m;
    static uint8_t cover[32 * 32];
    unsigned x, y, k, both = 0, none = 0, on_a = 0;
    zl_mat4_identity(&m);
    m.m[0] = 4 * ZL_FX_ONE;
    m.m[3] = -ZL_FX_ONE;
    m.m[5] = -4 * ZL_FX_ONE;
    m.m[7] = ZL_FX_ONE;
    m.m[10] = ZL_FX_ONE / 2;
    memset(cover, 0, sizeof cover);
    for (k = 0; k < 2; k++) {
        make(32, 32, ZL_FORMAT_RGB565);
        ctx.state.depth_test = 0;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, k ? &b : &a, &m));
        for (y = 0; y < 32; y++)
            for (x = 0; x < 32; x++)
                if (zt_get_px(&surf, x, y) != 0) {
                    cover[y * 32 + x]++;
                    on_a += k == 0;
                }
        ZT_ASSERT_SURFACE_INTACT(&surf);
    }
    for (x = 0; x < 32 * 32; x++) {
        both += cover[x] > 1;
        none += cover[x] == 0;
    }
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, both, "pixels covered by both halves of the quad");
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, none, "pixels covered by neither half of the quad");
    /* the upper-left half: centres with x + y < 16, i.e. i + j < 15 */
    TEST_ASSERT_EQUAL_UINT(15 * 16 / 2, on_a);
}

static void test_largest_pixel_space_triangle_is_exact(void)
{
    /* Pixel space holds +-32768 pixels, all inside the guard band: coverage
     * equals the reference exactly even at the extremes. */
    zl_fixed pos[9];
    static const uint16_t idx[] = {0, 1, 2};
    zl_mesh mesh = {pos, idx, NULL, NULL, 3, 1};
    zt_tri ref;
    unsigned x, y, mism = 0, lit = 0;
    /* an edge from one corner of the Q16.16 range to the other, just off
     * the diagonal through the viewport */
    pos[0] = ZL_FX_MIN; pos[1] = ZL_FX_MIN + PX(3) + 12345; pos[2] = 0;
    pos[3] = ZL_FX_MAX; pos[4] = ZL_FX_MAX; pos[5] = 0;
    pos[6] = ZL_FX_MAX; pos[7] = ZL_FX_MIN; pos[8] = 0;
    make(32, 32, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, NULL));
    zt_tri_init(&ref, &pos[0], &pos[3], &pos[6]);
    for (y = 0; y < 32; y++)
        for (x = 0; x < 32; x++) {
            int want = zt_tri_covers(&ref, (int32_t)x, (int32_t)y) != 0;
            mism += (zt_get_px(&surf, x, y) != 0) != want;
            lit += (unsigned)want;
        }
    TEST_ASSERT_EQUAL_UINT(0, mism);
    TEST_ASSERT_TRUE(lit > 0 && lit < 32 * 32);
    ZT_ASSERT_SURFACE_INTACT(&surf);
}

/* ------------------------------------------------------- smallest triangle */

static void test_one_subpixel_triangle(void)
{
    const zl_fixed s = ZL_FX_ONE >> ZL_SUBPIXEL_BITS; /* one subpixel */
    const zl_fixed c = PX(5) + PX(1) / 2;            /* centre of pixel 5 */
    zl_fixed pos[9];
    static const uint16_t idx[] = {0, 1, 2};
    zl_mesh mesh = {pos, idx, NULL, NULL, 3, 1};
    int dx, dy;
    /* the right angle at the centre of pixel (5, 5), legs one subpixel:
     * that centre is on a top and a left edge, covered; moved by one
     * subpixel in any direction, the triangle holds no centre */
    for (dy = -1; dy <= 1; dy++) {
        for (dx = -1; dx <= 1; dx++) {
            unsigned want = dx == 0 && dy == 0;
            zt_tri ref;
            pos[0] = c + dx * s; pos[1] = c + dy * s; pos[2] = 0;
            pos[3] = c + dx * s + s; pos[4] = c + dy * s; pos[5] = 0;
            pos[6] = c + dx * s; pos[7] = c + dy * s + s; pos[8] = 0;
            make(12, 12, ZL_FORMAT_RGB888);
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, NULL));
            TEST_ASSERT_EQUAL_UINT(want, count_px(0xFFFFFFu));
            if (want)
                TEST_ASSERT_EQUAL_HEX32(0xFFFFFFu, zt_get_px(&surf, 5, 5));
            zt_tri_init(&ref, &pos[0], &pos[3], &pos[6]);
            TEST_ASSERT_EQUAL_UINT(want, zt_tri_covers(&ref, 5, 5) ? 1u : 0u);
            ZT_ASSERT_SURFACE_INTACT(&surf);
        }
    }
    /* legs of half a subpixel snap to a zero-area triangle: nothing */
    pos[0] = c; pos[1] = c;
    pos[3] = c + s / 2 - 1; pos[4] = c;
    pos[6] = c; pos[7] = c + s / 2 - 1;
    make(12, 12, ZL_FORMAT_RGB888);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, NULL));
    TEST_ASSERT_EQUAL_UINT(0, count_px(0xFFFFFFu));
    ZT_ASSERT_SURFACE_INTACT(&surf);
}

/* ------------------------------------------------------------ render state */

static void test_light_dir_range(void)
{
    static const zl_fixed pos[] = {0, 0, 0, PX(8), 0, 0, 0, PX(8), 0};
    static const uint16_t idx[] = {0, 1, 2};
    zl_mesh mesh = {pos, idx, NULL, NULL, 3, 1};
    zl_state s;
    zl_state_default(&s);
    s.light_on = 1;
    s.light_dir.x = -ZL_FX_ONE;
    s.light_dir.y = ZL_FX_ONE;
    s.light_dir.z = ZL_FX_ONE;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_state_check(&s));
    s.light_dir.y = ZL_FX_ONE + 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_state_check(&s));
    s.light_on = 0; /* unused without lighting */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_state_check(&s));
    /* the fuzzer's case: a huge light vector overflowed the dot product */
    make(12, 12, ZL_FORMAT_RGB565);
    ctx.state.light_on = 1;
    ctx.state.light_dir.x = ZL_FX_MIN;
    ctx.state.light_dir.y = ZL_FX_MIN;
    ctx.state.light_dir.z = ZL_FX_MIN;
    snapshot();
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &mesh, NULL));
    assert_untouched();
}

static void test_look_at_range(void)
{
    zl_mat4 m;
    zl_vec3 eye = {PX(-32767), PX(-32767), PX(-32767)}, target, up = {0, ZL_FX_ONE, 0};
    /* the fuzzer's case: the translation dot(f, eye) = -56754 does not fit
     * (it saturated, then -INT32_MIN overflowed) */
    target.x = eye.x + ZL_FX_ONE;
    target.y = eye.y + ZL_FX_ONE;
    target.z = eye.z + ZL_FX_ONE;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_look_at(&m, eye, target, up));
    target.x = 0;
    target.y = 0;
    target.z = 0;
    /* target - eye beyond Q16.16 */
    eye.x = PX(-30000);
    eye.y = 0;
    eye.z = 0;
    target.x = PX(30000);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_look_at(&m, eye, target, up));
    /* a long up vector is fine (normalised first), a zero one is not */
    eye.x = 0;
    eye.z = PX(3);
    target.x = 0;
    up.y = ZL_FX_MAX;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&m, eye, target, up));
    TEST_ASSERT_EQUAL_INT(ZL_FX_ONE, m.m[5]);
    TEST_ASSERT_EQUAL_INT(-PX(3), m.m[11]);
    up.y = 0;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_mat4_look_at(&m, eye, target, up));
    /* the eye at the edge of the range, looking at the origin */
    eye.z = PX(32767);
    up.y = ZL_FX_ONE;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&m, eye, target, up));
    TEST_ASSERT_EQUAL_INT(-PX(32767), m.m[11]);
}

/* ------------------------------------------------ too-small buffers, guards */

static void test_too_small_strides_write_nothing(void)
{
    static const zl_fixed pos[] = {0, 0, 0, PX(8), 0, 0, 0, PX(8), 0};
    static const uint16_t idx[] = {0, 1, 2};
    zl_mesh mesh = {pos, idx, NULL, NULL, 3, 1};
    zl_target t;
    zl_context c2;
    unsigned fmt;
    for (fmt = 0; fmt < 3; fmt++) {
        unsigned bpp = zl_format_bytes((zl_format)fmt);
        zt_guard_reset();
        TEST_ASSERT_EQUAL_INT(0, zt_surface_make(&surf, 8, 8, (zl_format)fmt, 1, 1, 4, 4, 0));
        snapshot();
        t = surf.target;
        t.color_stride = (int32_t)(8 * bpp - 1);
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_init(&c2, &t));
        t.color_stride = -(int32_t)(8 * bpp);
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_init(&c2, &t));
        t = surf.target;
        t.depth_stride = 8 * 2 - 2;
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_init(&c2, &t));
        t.depth_stride = 8 * 2 + 1; /* odd */
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_init(&c2, &t));
        t = surf.target;
        t.format = 3; /* unknown */
        TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_init(&c2, &t));
        if (fmt == ZL_FORMAT_RGB565) { /* uint16 data; RGB565_BE is bytes */
            t = surf.target;
            t.color_stride += 1; /* odd RGB565 stride */
            TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_init(&c2, &t));
        }
        /* a target broken after zl_init: zl_clear and zl_draw_mesh check it again */
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&c2, &surf.target));
        c2.target.color_stride = (int32_t)(8 * bpp - 1);
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_clear(&c2, (zl_rgb){1, 2, 3}, 7));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_draw_mesh(&c2, &mesh, NULL));
        c2.target = surf.target;
        c2.target.depth_stride = 3;
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_draw_mesh(&c2, &mesh, NULL));
        assert_untouched();
    }
}

static void test_bad_mesh_writes_nothing(void)
{
    static const zl_fixed pos[] = {0, 0, 0, PX(8), 0, 0, 0, PX(8), 0};
    uint16_t idx[] = {0, 1, 2, 0, 2, 3}; /* vertex 3 does not exist */
    zl_mesh mesh = {pos, idx, NULL, NULL, 3, 2};
    make(12, 12, ZL_FORMAT_RGB565);
    snapshot();
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &mesh, NULL));
    mesh.indices = NULL;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, &mesh, NULL));
    mesh.indices = idx;
    mesh.positions = NULL;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, &mesh, NULL));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, NULL, NULL));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(NULL, &mesh, NULL));
    ctx.state.depth_func = 8;
    mesh.positions = pos;
    mesh.triangle_count = 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, &mesh, NULL));
    assert_untouched();
}

static void test_work_buffer_short_or_misaligned_writes_nothing(void)
{
    static const zl_fixed pos[] = {0, 0, 0, PX(8), 0, 0, 0, PX(8), 0};
    static const uint16_t idx[] = {0, 1, 2};
    zl_mesh mesh = {pos, idx, NULL, NULL, 3, 1};
    zl_frame_config cfg;
    zl_frame f;
    zl_state st;
    zl_band band;
    size_t bytes, i;
    uint8_t *work, *copy;
    unsigned bands = 0;
    memset(&cfg, 0, sizeof cfg);
    cfg.width = 24;
    cfg.height = 10;
    cfg.band_rows = 3;
    cfg.format = ZL_FORMAT_RGB888;
    cfg.color_buffers = 2;
    cfg.gouraud = 1;
    cfg.max_meshes = 1;
    cfg.max_vertices = 3;
    cfg.max_triangles = 1;
    cfg.max_active = 1;
    bytes = zl_frame_bytes(&cfg);
    TEST_ASSERT_TRUE(bytes > 0);
    work = (uint8_t *)zt_guard_alloc(bytes + 8);
    copy = (uint8_t *)zt_guard_alloc(bytes + 8);
    TEST_ASSERT_NOT_NULL(work);
    TEST_ASSERT_NOT_NULL(copy);
    for (i = 0; i < bytes + 8; i++)
        work[i] = copy[i] = (uint8_t)(i * 7u + 1u);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_frame_begin(&f, &cfg, work, bytes - 1, (zl_rgb){0, 0, 0}, 0));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_frame_begin(&f, &cfg, work, 0, (zl_rgb){0, 0, 0}, 0));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_begin(&f, &cfg, work + 1, bytes + 7, (zl_rgb){0, 0, 0}, 0));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_begin(&f, &cfg, work + 4, bytes + 4, (zl_rgb){0, 0, 0}, 0));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_begin(&f, &cfg, NULL, bytes, (zl_rgb){0, 0, 0}, 0));
    cfg.band_rows = 0;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_frame_begin(&f, &cfg, work, bytes, (zl_rgb){0, 0, 0}, 0));
    cfg.band_rows = 3;
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(copy, work, bytes + 8, "a failing zl_frame_begin wrote to the work buffer");
    TEST_ASSERT_EQUAL_UINT(0, zt_guard_check());

    /* exactly zl_frame_bytes: every band checked against the guards */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, bytes, (zl_rgb){1, 2, 3}, 9));
    zl_state_default(&st);
    st.shading = ZL_SHADE_GOURAUD;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &mesh, NULL, &st));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_frame_add_mesh(&f, &mesh, NULL, &st));
    while (zl_frame_next_band(&f, &band) == ZL_OK) {
        TEST_ASSERT_EQUAL_UINT(0, zt_guard_check());
        TEST_ASSERT_TRUE((const uint8_t *)band.color >= work &&
                         (const uint8_t *)band.color + (size_t)band.color_stride * band.rows <= work + bytes);
        bands++;
    }
    TEST_ASSERT_EQUAL_UINT(4, bands);
    /* the 8 spare bytes after zl_frame_bytes were not touched either */
    TEST_ASSERT_EQUAL_MEMORY(copy + bytes, work + bytes, 8);
    TEST_ASSERT_EQUAL_UINT(0, zt_guard_check());
}

/* The fuzz_bsp finding: a cyclic tree drawn front to back is refused
 * (ZL_ERR_CAPACITY), and the mask, colour and ids stay as they were (the
 * mask used to be cleared before the tree was walked). */
static void test_bsp_malformed_tree_writes_nothing(void)
{
    static const zl_fixed pos[] = {0, 0, 0, PX(4), 0, 0, 0, PX(4), 0};
    static const uint16_t idx[] = {0, 1, 2}, src[] = {0};
    zl_bsp_node nodes[2];
    zl_bsp bsp;
    zl_vis_target t;
    zl_state st;
    zl_mat4 m;
    zl_vec3 eye = {0, 0, PX(3)};
    size_t mask_bytes = zl_bsp_mask_bytes(12, 8), i;
    uint8_t *mask, *color;
    uint16_t *ids;
    zt_guard_reset();
    mask = (uint8_t *)zt_guard_alloc(mask_bytes);
    color = (uint8_t *)zt_guard_alloc(12 * 8 * 2);
    ids = (uint16_t *)zt_guard_alloc(12 * 8 * 2);
    TEST_ASSERT_TRUE(mask != NULL && color != NULL && ids != NULL);
    memset(mask, 0x77, mask_bytes);
    memset(color, 0x55, 12 * 8 * 2);
    memset(ids, 0x33, 12 * 8 * 2);
    memset(nodes, 0, sizeof nodes);
    nodes[0].n[2] = ZL_FX_ONE;
    nodes[0].count = 1;
    nodes[0].front = 1;
    nodes[0].back = ZL_BSP_LEAF;
    nodes[1].n[2] = ZL_FX_ONE;
    nodes[1].front = 0; /* back to the root: a cycle */
    nodes[1].back = ZL_BSP_LEAF;
    memset(&bsp, 0, sizeof bsp);
    bsp.positions = pos;
    bsp.indices = idx;
    bsp.source = src;
    bsp.nodes = nodes;
    bsp.vertex_count = 3;
    bsp.triangle_count = 1;
    bsp.node_count = 2;
    bsp.root = 0;
    bsp.depth = 2;
    memset(&t, 0, sizeof t);
    t.color = color;
    t.color_stride = 24;
    t.ids = ids;
    t.ids_stride = 24;
    t.width = 12;
    t.height = 8;
    t.format = ZL_FORMAT_RGB565;
    zl_state_default(&st);
    zl_mat4_identity(&m);
    m.m[10] = ZL_FX_ONE / 2;
    m.m[11] = ZL_FX_ONE / 2;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_CAPACITY, zl_bsp_draw(&bsp, &m, eye, &st, &t, (zl_rgb){1, 2, 3},
                                                       ZL_BSP_FRONT_TO_BACK, mask, mask_bytes));
    for (i = 0; i < mask_bytes; i++)
        TEST_ASSERT_EQUAL_HEX8(0x77, mask[i]);
    for (i = 0; i < 12 * 8 * 2; i++) {
        TEST_ASSERT_EQUAL_HEX8(0x55, color[i]);
        TEST_ASSERT_EQUAL_HEX8(0x33, ((uint8_t *)ids)[i]);
    }
    TEST_ASSERT_EQUAL_UINT(0, zt_guard_check());
    /* the same tree without the cycle draws */
    nodes[1].front = ZL_BSP_LEAF;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_bsp_draw(&bsp, &m, eye, &st, &t, (zl_rgb){1, 2, 3}, ZL_BSP_FRONT_TO_BACK,
                                             mask, mask_bytes));
    TEST_ASSERT_EQUAL_UINT(0, zt_guard_check());
}

/* Lines and points obey the same transform limits as meshes. */
static void test_lines_coordinates_at_the_limit(void)
{
    zl_fixed pos[] = {-COORD_LIMIT, -COORD_LIMIT / 2, 0, COORD_LIMIT, COORD_LIMIT / 2, 0};
    zl_lines l;
    zl_mat4 m;
    memset(&l, 0, sizeof l);
    l.positions = pos;
    l.vertex_count = 2;
    l.count = 2;
    l.prim = ZL_PRIM_LINES;
    make(16, 16, ZL_FORMAT_RGB565);
    scale_matrix(&m, 4, 4);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, &m));
    TEST_ASSERT_TRUE(count_px(0xFFFFu) >= 16);
    ZT_ASSERT_SURFACE_INTACT(&surf);
    make(16, 16, ZL_FORMAT_RGB565);
    snapshot();
    pos[3] = COORD_LIMIT + 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_lines(&ctx, &l, &m));
    pos[3] = COORD_LIMIT;
    scale_matrix(&m, COORD_LIMIT + 1, 4);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_lines(&ctx, &l, &m));
    scale_matrix(&m, COORD_LIMIT, 4); /* 16384 * 16384: clip space overflows */
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_lines(&ctx, &l, &m));
    assert_untouched();
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_window_4096_scanline);
    RUN_TEST(test_window_4096_frame_mode_strips);
    RUN_TEST(test_model_coordinates_and_matrix_at_the_limit);
    RUN_TEST(test_clip_space_overflow);
    RUN_TEST(test_lines_coordinates_at_the_limit);
    RUN_TEST(test_far_outside_the_guard_band);
    RUN_TEST(test_largest_pixel_space_triangle_is_exact);
    RUN_TEST(test_one_subpixel_triangle);
    RUN_TEST(test_light_dir_range);
    RUN_TEST(test_look_at_range);
    RUN_TEST(test_too_small_strides_write_nothing);
    RUN_TEST(test_bad_mesh_writes_nothing);
    RUN_TEST(test_work_buffer_short_or_misaligned_writes_nothing);
    RUN_TEST(test_bsp_malformed_tree_writes_nothing);
    return UNITY_END();
}
