/* SPDX-License-Identifier: MIT */
/*
 * Render state, depth and argument checking against zline.h:
 *   - the eight depth functions (incoming depth equal to, one below and one
 *     above the stored value, per pixel), depth test off (every fragment
 *     passes, depth untouched), depth write off, submission order;
 *   - colour masks per channel for RGB888, RGB565 and RGB565_BE (exact bytes,
 *     high byte first for _BE), zl_clear with colour and depth write masks;
 *   - flat colours (face colours, state colour) and Gouraud colours exact at
 *     vertices placed on covered pixel centres;
 *   - depth within +-1 of the exact plane of the snapped triangle at every
 *     covered pixel (reference in tests/support/zt_ref.c);
 *   - culling with both front-face conventions (y down: (0,0) (10,0) (0,10)
 *     is clockwise as the viewer sees it);
 *   - zero-area and off-screen triangles draw nothing; huge triangles cover
 *     exactly the reference's in-viewport pixels, with depths on the plane:
 *     in pixel space up to the Q16.16 limits (+-32768 px), and through an
 *     identity matrix up to +-100000 px (inside the guard band);
 *   - byte formats at odd addresses and strides;
 *   - invalid arguments return a negative status and write nothing.
 * Guards and row padding of every buffer are checked after every call.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_guard.h"
#include "zt_ref.h"

#define PX(n) ((zl_fixed)((n) * 65536))
#define PXH(n) ((zl_fixed)((n) * 32768))
#define S16(n) ((zl_fixed)((n) * 4096))

#define MAXW 64
#define MAXH 64

static zt_surface surf;
static zl_context ctx;
static uint8_t cov[MAXW * MAXH];
static uint8_t saved_color[MAXW * MAXH * 3 + MAXH * 16], saved_depth[MAXW * MAXH * 2 + MAXH * 16];
static uint16_t dmap[MAXW * MAXH];
static char msg[400];

void setUp(void)
{
    zt_guard_reset();
}

void tearDown(void)
{
}

/* A w x h target of format fmt with padded rows, default state except
 * culling off. */
static void make(unsigned w, unsigned h, zl_format fmt, unsigned cpad, unsigned dpad, unsigned coff)
{
    TEST_ASSERT_TRUE(w <= MAXW && h <= MAXH);
    TEST_ASSERT_EQUAL_INT(0, zt_surface_make(&surf, w, h, fmt, 1, 1, cpad, dpad, coff));
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OK, zl_init(&ctx, &surf.target), "zl_init of the test target");
    ctx.state.cull = ZL_CULL_NONE;
}

/* One triangle: positions (x, y, z each), optional vertex colours. */
typedef struct {
    zl_fixed p[9];
    uint16_t i[3];
    uint8_t vc[9];
    uint8_t fc[3];
    zl_mesh m;
} one_tri;

static const zl_mesh *tri_mesh(one_tri *t, const zl_fixed *v0, const zl_fixed *v1, const zl_fixed *v2,
                               const uint8_t *face, const uint8_t *vcols)
{
    memset(t, 0, sizeof *t);
    memcpy(t->p, v0, 3 * sizeof(zl_fixed));
    memcpy(t->p + 3, v1, 3 * sizeof(zl_fixed));
    memcpy(t->p + 6, v2, 3 * sizeof(zl_fixed));
    t->i[0] = 0;
    t->i[1] = 1;
    t->i[2] = 2;
    t->m.positions = t->p;
    t->m.indices = t->i;
    t->m.vertex_count = 3;
    t->m.triangle_count = 1;
    if (face) {
        memcpy(t->fc, face, 3);
        t->m.face_colors = t->fc;
    }
    if (vcols) {
        memcpy(t->vc, vcols, 9);
        t->m.vertex_colors = t->vc;
    }
    return &t->m;
}

static zl_status draw(const zl_mesh *m)
{
    zl_status st = zl_draw_mesh(&ctx, m, NULL);
    ZT_ASSERT_SURFACE_INTACT(&surf);
    return st;
}

static void save_surface(void)
{
    TEST_ASSERT_TRUE(surf.color_bytes <= sizeof saved_color && surf.depth_bytes <= sizeof saved_depth);
    if (surf.color)
        memcpy(saved_color, surf.color, surf.color_bytes);
    if (surf.depth)
        memcpy(saved_depth, surf.depth, surf.depth_bytes);
}

static void assert_unchanged(const char *what)
{
    ZT_ASSERT_SURFACE_INTACT(&surf);
    if (surf.color)
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(saved_color, surf.color, surf.color_bytes, what);
    if (surf.depth)
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(saved_depth, surf.depth, surf.depth_bytes, what);
}

/* Fill colour and depth with position-dependent values. */
static void scribble(void)
{
    unsigned x, y;
    for (y = 0; y < surf.height; y++)
        for (x = 0; x < surf.width; x++) {
            if (surf.color)
                zt_set_px(&surf, x, y, (0x9137u * (x + 1) + 0x4F1Bu * (y + 3)) & 0xFFFFFFu);
            if (surf.depth)
                zt_set_depth(&surf, x, y, (uint16_t)(0x3A11u * (x + 7) + 0x1D05u * y));
        }
}

static void vtx(zl_fixed *v, zl_fixed x, zl_fixed y, zl_fixed z)
{
    v[0] = x;
    v[1] = y;
    v[2] = z;
}

/* ---------------------------------------------------------------- basics */

static void test_format_bytes(void)
{
    TEST_ASSERT_EQUAL_UINT(2, zl_format_bytes(ZL_FORMAT_RGB565));
    TEST_ASSERT_EQUAL_UINT(2, zl_format_bytes(ZL_FORMAT_RGB565_BE));
    TEST_ASSERT_EQUAL_UINT(3, zl_format_bytes(ZL_FORMAT_RGB888));
    TEST_ASSERT_EQUAL_UINT(0, zl_format_bytes((zl_format)3));
    TEST_ASSERT_EQUAL_UINT(0, zl_format_bytes((zl_format)255));
}

static void test_state_default_and_check(void)
{
    zl_state s, bad;
    memset(&s, 0xEE, sizeof s);
    zl_state_default(&s);
    TEST_ASSERT_EQUAL_UINT(1, s.depth_test != 0);
    TEST_ASSERT_EQUAL_UINT(1, s.depth_write != 0);
    TEST_ASSERT_EQUAL_UINT(ZL_LESS, s.depth_func);
    TEST_ASSERT_EQUAL_UINT(ZL_MASK_RGB, s.color_mask);
    TEST_ASSERT_EQUAL_UINT(ZL_CULL_NONE, s.cull);
    TEST_ASSERT_EQUAL_UINT(ZL_FRONT_CCW, s.front_face);
    TEST_ASSERT_EQUAL_UINT(ZL_SHADE_FLAT, s.shading);
    TEST_ASSERT_EQUAL_UINT(0, s.light_on);
    TEST_ASSERT_EQUAL_UINT(255, s.color.r);
    TEST_ASSERT_EQUAL_UINT(255, s.color.g);
    TEST_ASSERT_EQUAL_UINT(255, s.color.b);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_state_check(&s));

    bad = s;
    bad.depth_func = 8;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_state_check(&bad));
    bad = s;
    bad.depth_func = 255;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_state_check(&bad));
    bad = s;
    bad.cull = 3;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_state_check(&bad));
    bad = s;
    bad.front_face = 2;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_state_check(&bad));
    bad = s;
    bad.shading = 2;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_state_check(&bad));
    TEST_ASSERT_LESS_THAN(0, zl_state_check(NULL));

    /* zl_init sets the default state */
    make(8, 8, ZL_FORMAT_RGB888, 0, 0, 0);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &surf.target));
    TEST_ASSERT_EQUAL_UINT(s.depth_test, ctx.state.depth_test);
    TEST_ASSERT_EQUAL_UINT(s.depth_write, ctx.state.depth_write);
    TEST_ASSERT_EQUAL_UINT(s.depth_func, ctx.state.depth_func);
    TEST_ASSERT_EQUAL_UINT(s.color_mask, ctx.state.color_mask);
    TEST_ASSERT_EQUAL_UINT(s.cull, ctx.state.cull);
    TEST_ASSERT_EQUAL_UINT(s.front_face, ctx.state.front_face);
    TEST_ASSERT_EQUAL_UINT(s.shading, ctx.state.shading);
    TEST_ASSERT_EQUAL_UINT(s.light_on, ctx.state.light_on);
}

/* ------------------------------------------------------------ depth tests */

static int func_passes(unsigned f, uint16_t incoming, uint16_t stored)
{
    switch (f) {
    case ZL_NEVER:
        return 0;
    case ZL_LESS:
        return incoming < stored;
    case ZL_EQUAL:
        return incoming == stored;
    case ZL_LEQUAL:
        return incoming <= stored;
    case ZL_GREATER:
        return incoming > stored;
    case ZL_NOTEQUAL:
        return incoming != stored;
    case ZL_GEQUAL:
        return incoming >= stored;
    default:
        return 1;
    }
}

/* The triangle under test, for failure messages. */
static char tri_desc[240];

static void describe(const zl_fixed *v0, const zl_fixed *v1, const zl_fixed *v2, const char *space)
{
    snprintf(tri_desc, sizeof tri_desc, "triangle (%ld,%ld,%ld) (%ld,%ld,%ld) (%ld,%ld,%ld) raw %s",
             (long)v0[0], (long)v0[1], (long)v0[2], (long)v1[0], (long)v1[1], (long)v1[2],
             (long)v2[0], (long)v2[1], (long)v2[2], space);
}

/* Check every covered pixel's depth against the reference plane of t; dmap
 * gets every pixel's depth. */
static void check_depth_tri(const zt_tri *t, const uint8_t *mask)
{
    unsigned x, y;
    for (y = 0; y < surf.height; y++)
        for (x = 0; x < surf.width; x++) {
            zt_depth_ref r;
            uint16_t d = zt_get_depth(&surf, x, y);
            dmap[y * surf.width + x] = d;
            if (!mask[y * surf.width + x])
                continue;
            zt_tri_depth(t, (int32_t)x, (int32_t)y, &r);
            if (d < r.lo || d > r.hi) {
                snprintf(msg, sizeof msg,
                         "depth at (%u,%u) is %u, expected %ld..%ld (exact value rounds to %ld%s); %s",
                         x, y, d, (long)r.lo, (long)r.hi, (long)r.nearest,
                         r.steep ? ", steep: vertex range" : "", tri_desc);
                TEST_FAIL_MESSAGE(msg);
            }
        }
}

static void check_depth_plane(const zl_fixed *v0, const zl_fixed *v1, const zl_fixed *v2,
                              const uint8_t *mask)
{
    zt_tri t;
    zt_tri_init(&t, v0, v1, v2);
    describe(v0, v1, v2, "pixel space");
    check_depth_tri(&t, mask);
}

static void depth_funcs_for(const zl_fixed *v0, const zl_fixed *v1, const zl_fixed *v2)
{
    static const uint8_t face[3] = {0x10, 0x20, 0x30};
    one_tri ot;
    const zl_mesh *m = tri_mesh(&ot, v0, v1, v2, face, NULL);
    zt_tri t;
    unsigned f, wr, x, y, n;
    const unsigned w = surf.width, h = surf.height;

    zt_tri_init(&t, v0, v1, v2);
    n = zt_tri_mask(&t, cov, w, h);
    TEST_ASSERT_EQUAL_UINT(w * h, n); /* the triangle covers the whole target */

    /* measure the incoming depth: ALWAYS, written */
    zt_fill_px(&surf, 0);
    zt_fill_depth(&surf, 0xFFFF);
    ctx.state.depth_test = 1;
    ctx.state.depth_write = 1;
    ctx.state.depth_func = ZL_ALWAYS;
    TEST_ASSERT_EQUAL_INT(ZL_OK, draw(m));
    check_depth_plane(v0, v1, v2, cov);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            TEST_ASSERT_EQUAL_HEX32(0x102030u, zt_get_px(&surf, x, y));
            TEST_ASSERT_TRUE(dmap[y * w + x] > 0 && dmap[y * w + x] < 0xFFFF);
        }

    for (wr = 0; wr < 2; wr++)
        for (f = ZL_NEVER; f <= ZL_ALWAYS; f++) {
            ctx.state.depth_func = (uint8_t)f;
            ctx.state.depth_write = (uint8_t)wr;
            zt_fill_px(&surf, 0x000000u);
            /* stored = incoming - 1, incoming, incoming + 1 in a pattern */
            for (y = 0; y < h; y++)
                for (x = 0; x < w; x++)
                    zt_set_depth(&surf, x, y, (uint16_t)(dmap[y * w + x] + (x + 2 * y) % 3 - 1));
            TEST_ASSERT_EQUAL_INT(ZL_OK, draw(m));
            for (y = 0; y < h; y++)
                for (x = 0; x < w; x++) {
                    uint16_t in = dmap[y * w + x];
                    uint16_t stored = (uint16_t)(in + (x + 2 * y) % 3 - 1);
                    int pass = func_passes(f, in, stored);
                    uint32_t c = zt_get_px(&surf, x, y);
                    uint16_t d = zt_get_depth(&surf, x, y);
                    uint16_t want_d = pass && wr ? in : stored;
                    if (c != (pass ? 0x102030u : 0u) || d != want_d) {
                        snprintf(msg, sizeof msg,
                                 "func %u, depth write %u, pixel (%u,%u): incoming %u stored %u: "
                                 "expected %s and depth %u, got colour 0x%06lX depth %u",
                                 f, wr, x, y, in, stored, pass ? "pass" : "fail", want_d,
                                 (unsigned long)c, d);
                        TEST_FAIL_MESSAGE(msg);
                    }
                }
        }
}

/* All eight functions with incoming == stored, incoming < stored and
 * incoming > stored (by one step), with depth write on and off; a flat and
 * a sloped triangle. */
static void test_depth_functions(void)
{
    zl_fixed a[3], b[3], c[3];
    make(16, 12, ZL_FORMAT_RGB888, 3, 2, 0);
    vtx(a, PX(-20), PX(-20), PX(1) / 2);
    vtx(b, PX(60), PX(-20), PX(1) / 2);
    vtx(c, PX(-20), PX(60), PX(1) / 2);
    depth_funcs_for(a, b, c);
    vtx(a, PX(-20), PX(-20), PX(1) / 5);
    vtx(b, PX(60), PX(-20), PX(4) / 5);
    vtx(c, PX(-20), PX(60), PX(1) / 2);
    depth_funcs_for(a, b, c);
}

/* Depth test off: every fragment passes whatever the function and the
 * stored depth, and depth is not written even with depth_write on. */
static void test_depth_test_off(void)
{
    static const uint8_t face[3] = {0xAB, 0xCD, 0xEF};
    zl_fixed a[3], b[3], c[3];
    one_tri ot;
    const zl_mesh *m;
    zt_tri t;
    unsigned f, x, y;
    make(16, 12, ZL_FORMAT_RGB888, 0, 4, 0);
    vtx(a, PX(1), PXH(3), PX(1) / 3);
    vtx(b, PX(15), PX(2), PX(1) / 4);
    vtx(c, PX(4), PX(11), PX(1));
    m = tri_mesh(&ot, a, b, c, face, NULL);
    zt_tri_init(&t, a, b, c);
    TEST_ASSERT_GREATER_THAN(20, zt_tri_mask(&t, cov, 16, 12));
    for (f = ZL_NEVER; f <= ZL_ALWAYS; f++) {
        scribble();
        for (y = 0; y < 12; y++)
            for (x = 0; x < 16; x++)
                if ((x + y) & 1)
                    zt_set_depth(&surf, x, y, 0); /* nothing is nearer */
        save_surface();
        ctx.state.depth_test = 0;
        ctx.state.depth_write = 1;
        ctx.state.depth_func = (uint8_t)f;
        TEST_ASSERT_EQUAL_INT(ZL_OK, draw(m));
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(saved_depth, surf.depth, surf.depth_bytes,
                                         "depth written with the depth test off");
        for (y = 0; y < 12; y++)
            for (x = 0; x < 16; x++) {
                uint32_t old = (0x9137u * (x + 1) + 0x4F1Bu * (y + 3)) & 0xFFFFFFu;
                TEST_ASSERT_EQUAL_HEX32(cov[y * 16 + x] ? 0xABCDEFu : old, zt_get_px(&surf, x, y));
            }
    }
}

/* Depth write off: colour written where the test passes, depth untouched.
 * Submission order: a near triangle then a far one over it, in one mesh. */
static void test_depth_write_off_and_order(void)
{
    static const zl_fixed pos[18] = {
        /* near: z = 0.25 */ PX(-10), PX(-10), PX(1) / 4, PX(40), PX(-10), PX(1) / 4, PX(-10), PX(40), PX(1) / 4,
        /* far:  z = 0.75 */ PX(-10), PX(-10), PX(3) / 4, PX(40), PX(-10), PX(3) / 4, PX(-10), PX(40), PX(3) / 4,
    };
    static const uint16_t ind[6] = {0, 1, 2, 3, 4, 5};
    static const uint8_t faces[6] = {1, 2, 3, 4, 5, 6};
    zl_mesh m;
    unsigned x, y;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = ind;
    m.face_colors = faces;
    m.vertex_count = 6;
    m.triangle_count = 2;
    make(12, 8, ZL_FORMAT_RGB888, 1, 0, 0);

    /* depth write on: the near one stays */
    zt_fill_px(&surf, 0);
    zt_fill_depth(&surf, 0xFFFF);
    TEST_ASSERT_EQUAL_INT(ZL_OK, draw(&m));
    for (y = 0; y < 8; y++)
        for (x = 0; x < 12; x++) {
            TEST_ASSERT_EQUAL_HEX32(0x010203u, zt_get_px(&surf, x, y));
            TEST_ASSERT_INT_WITHIN(1, 16383, zt_get_depth(&surf, x, y)); /* 0.25 * 65535 = 16383.75 */
        }
    /* GREATER into depth 0: both pass in turn, the far one (drawn second) stays */
    zt_fill_px(&surf, 0);
    zt_fill_depth(&surf, 0);
    ctx.state.depth_func = ZL_GREATER;
    TEST_ASSERT_EQUAL_INT(ZL_OK, draw(&m));
    for (y = 0; y < 8; y++)
        for (x = 0; x < 12; x++) {
            TEST_ASSERT_EQUAL_HEX32(0x040506u, zt_get_px(&surf, x, y));
            TEST_ASSERT_INT_WITHIN(1, 49151, zt_get_depth(&surf, x, y)); /* 0.75 * 65535 = 49151.25 */
        }
    /* depth write off: both pass against 0xFFFF, the later one wins, depth stays */
    ctx.state.depth_func = ZL_LESS;
    ctx.state.depth_write = 0;
    zt_fill_px(&surf, 0);
    zt_fill_depth(&surf, 0xFFFF);
    TEST_ASSERT_EQUAL_INT(ZL_OK, draw(&m));
    for (y = 0; y < 8; y++)
        for (x = 0; x < 12; x++) {
            TEST_ASSERT_EQUAL_HEX32(0x040506u, zt_get_px(&surf, x, y));
            TEST_ASSERT_EQUAL_HEX16(0xFFFF, zt_get_depth(&surf, x, y));
        }
}

/* A target without colour: depth only (a depth pre-pass). */
static void test_depth_only_target(void)
{
    zl_fixed a[3], b[3], c[3];
    one_tri ot;
    zt_tri t;
    unsigned x, y;
    TEST_ASSERT_EQUAL_INT(0, zt_surface_make(&surf, 16, 16, ZL_FORMAT_RGB565, 0, 1, 0, 2, 0));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &surf.target));
    vtx(a, PXH(1), PXH(1), PX(1) / 8);
    vtx(b, PX(14), PX(3), PX(1) / 2);
    vtx(c, PX(3), PX(15), PX(7) / 8);
    zt_fill_depth(&surf, 0xFFFF);
    TEST_ASSERT_EQUAL_INT(ZL_OK, draw(tri_mesh(&ot, a, b, c, NULL, NULL)));
    zt_tri_init(&t, a, b, c);
    zt_tri_mask(&t, cov, 16, 16);
    check_depth_plane(a, b, c, cov);
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++)
            if (!cov[y * 16 + x])
                TEST_ASSERT_EQUAL_HEX16(0xFFFF, zt_get_depth(&surf, x, y));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, (zl_rgb){1, 2, 3}, 0x4321));
    ZT_ASSERT_SURFACE_INTACT(&surf);
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++)
            TEST_ASSERT_EQUAL_HEX16(0x4321, zt_get_depth(&surf, x, y));
}

/* ------------------------------------------------------------ colour masks */

/* RGB565 value of a colour whose channels are each 0 or 255. */
static uint32_t rgb565_of_extremes(zl_rgb c)
{
    return (c.r ? 0xF800u : 0u) | (c.g ? 0x07E0u : 0u) | (c.b ? 0x001Fu : 0u);
}

static uint32_t mask_bits(zl_format fmt, unsigned mask)
{
    if (fmt == ZL_FORMAT_RGB888)
        return ((mask & ZL_MASK_R) ? 0xFF0000u : 0u) | ((mask & ZL_MASK_G) ? 0x00FF00u : 0u) |
               ((mask & ZL_MASK_B) ? 0x0000FFu : 0u);
    return ((mask & ZL_MASK_R) ? 0xF800u : 0u) | ((mask & ZL_MASK_G) ? 0x07E0u : 0u) |
           ((mask & ZL_MASK_B) ? 0x001Fu : 0u);
}

static uint32_t old_px(zl_format fmt, unsigned x, unsigned y)
{
    uint32_t v = (0x9137u * (x + 1) + 0x4F1Bu * (y + 3)) & 0xFFFFFFu;
    return fmt == ZL_FORMAT_RGB888 ? v : (v & 0xFFFFu);
}

/* Draw a partial triangle with every colour mask; covered pixels get the
 * masked channels of the colour, the others keep theirs (and uncovered
 * pixels keep everything). */
static void color_masks_for(zl_format fmt, unsigned cpad, unsigned coff)
{
    static const zl_rgb colors888[3] = {{0xAA, 0xBB, 0xCC}, {0x00, 0xFF, 0x01}, {0xFE, 0x00, 0x80}};
    static const zl_rgb colors565[4] = {{255, 255, 255}, {0, 0, 0}, {255, 0, 255}, {0, 255, 0}};
    const zl_rgb *colors = fmt == ZL_FORMAT_RGB888 ? colors888 : colors565;
    unsigned ncolors = fmt == ZL_FORMAT_RGB888 ? 3u : 4u;
    zl_fixed a[3], b[3], c[3];
    one_tri ot;
    zt_tri t;
    unsigned ci, mask, x, y;
    make(13, 9, fmt, cpad, 2, coff);
    vtx(a, PXH(1), PXH(1), 0);
    vtx(b, PX(12), PX(2), 0);
    vtx(c, PX(3), PX(9), 0);
    zt_tri_init(&t, a, b, c);
    TEST_ASSERT_GREATER_THAN(10, zt_tri_mask(&t, cov, 13, 9));
    ctx.state.depth_test = 0;
    for (ci = 0; ci < ncolors; ci++)
        for (mask = 0; mask <= ZL_MASK_RGB; mask++) {
            uint8_t face[3];
            uint32_t newv = fmt == ZL_FORMAT_RGB888 ? zt_rgb_packed(colors[ci]) : rgb565_of_extremes(colors[ci]);
            uint32_t mb = mask_bits((zl_format)fmt, mask);
            face[0] = colors[ci].r;
            face[1] = colors[ci].g;
            face[2] = colors[ci].b;
            for (y = 0; y < 9; y++)
                for (x = 0; x < 13; x++)
                    zt_set_px(&surf, x, y, old_px(fmt, x, y));
            ctx.state.color_mask = (uint8_t)mask;
            TEST_ASSERT_EQUAL_INT(ZL_OK, draw(tri_mesh(&ot, a, b, c, face, NULL)));
            for (y = 0; y < 9; y++)
                for (x = 0; x < 13; x++) {
                    uint32_t old = old_px(fmt, x, y);
                    uint32_t want = cov[y * 13 + x] ? ((old & ~mb) | (newv & mb)) : old;
                    uint32_t got = zt_get_px(&surf, x, y);
                    if (want != got) {
                        snprintf(msg, sizeof msg,
                                 "format %u, mask %u, colour (%u,%u,%u), pixel (%u,%u): expected "
                                 "0x%06lX got 0x%06lX (old 0x%06lX)",
                                 (unsigned)fmt, mask, colors[ci].r, colors[ci].g, colors[ci].b, x, y,
                                 (unsigned long)want, (unsigned long)got, (unsigned long)old);
                        TEST_FAIL_MESSAGE(msg);
                    }
                }
        }
}

static void test_color_mask_rgb888(void)
{
    color_masks_for(ZL_FORMAT_RGB888, 0, 0);
    color_masks_for(ZL_FORMAT_RGB888, 5, 3); /* odd stride, unaligned buffer */
}

static void test_color_mask_rgb565(void)
{
    color_masks_for(ZL_FORMAT_RGB565, 0, 0);
    color_masks_for(ZL_FORMAT_RGB565, 6, 0);
}

static void test_color_mask_rgb565_be(void)
{
    color_masks_for(ZL_FORMAT_RGB565_BE, 0, 0);
    color_masks_for(ZL_FORMAT_RGB565_BE, 2, 0);
}

/* Draw a partial triangle (all channels) and clear, on a target whose colour
 * buffer starts `off` bytes past 8-byte alignment with `off` padding bytes
 * per row; every pixel exact, guards and padding intact. */
static void any_alignment_for(zl_format fmt, unsigned off)
{
    static const uint8_t face[3] = {255, 0, 255};
    const uint32_t newv = fmt == ZL_FORMAT_RGB888 ? 0xFF00FFu : 0xF81Fu;
    zl_fixed a[3], b[3], c[3];
    one_tri ot;
    zt_tri t;
    unsigned x, y;
    vtx(a, PXH(1), PXH(1), 0);
    vtx(b, PX(12), PX(2), 0);
    vtx(c, PX(3), PX(9), 0);
    zt_tri_init(&t, a, b, c);
    TEST_ASSERT_GREATER_THAN(10, zt_tri_mask(&t, cov, 13, 9));
    zt_guard_reset();
    make(13, 9, fmt, off, 2, off);
    ctx.state.depth_test = 0;
    for (y = 0; y < 9; y++)
        for (x = 0; x < 13; x++)
            zt_set_px(&surf, x, y, old_px(fmt, x, y));
    TEST_ASSERT_EQUAL_INT(ZL_OK, draw(tri_mesh(&ot, a, b, c, face, NULL)));
    for (y = 0; y < 9; y++)
        for (x = 0; x < 13; x++)
            TEST_ASSERT_EQUAL_HEX32(cov[y * 13 + x] ? newv : old_px(fmt, x, y), zt_get_px(&surf, x, y));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, (zl_rgb){0, 255, 0}, 0));
    ZT_ASSERT_SURFACE_INTACT(&surf);
    for (y = 0; y < 9; y++)
        for (x = 0; x < 13; x++)
            TEST_ASSERT_EQUAL_HEX32(fmt == ZL_FORMAT_RGB888 ? 0x00FF00u : 0x07E0u, zt_get_px(&surf, x, y));
}

/* RGB888 is 3 bytes per pixel: any address, any stride >= 3 * width. */
static void test_rgb888_any_alignment(void)
{
    unsigned off;
    for (off = 1; off < 8; off++)
        any_alignment_for(ZL_FORMAT_RGB888, off);
}

/*
 * RGB565_BE at an odd address and with an odd stride. zline.h asks only
 * color_stride >= width * bpp of a colour buffer (a void *), and RGB565_BE
 * is defined byte by byte (high byte first, for SPI panels), so by the
 * header as written this must work. (If the library means to require 2-byte
 * alignment for the 16-bit formats, zline.h should say so; this test then
 * changes to expect the documented error.)
 */
static void test_rgb565_be_odd_alignment(void)
{
    unsigned off;
    for (off = 1; off < 4; off += 2)
        any_alignment_for(ZL_FORMAT_RGB565_BE, off);
}

/* The exact bytes of pure colours in each format. */
static void test_pixel_bytes(void)
{
    static const struct {
        zl_rgb c;
        uint8_t be0, be1;
        uint16_t native;
    } cases[] = {
        {{255, 0, 0}, 0xF8, 0x00, 0xF800},
        {{0, 255, 0}, 0x07, 0xE0, 0x07E0},
        {{0, 0, 255}, 0x00, 0x1F, 0x001F},
        {{255, 255, 255}, 0xFF, 0xFF, 0xFFFF},
        {{255, 0, 255}, 0xF8, 0x1F, 0xF81F},
    };
    zl_fixed a[3], b[3], c[3];
    one_tri ot;
    unsigned k;
    vtx(a, PX(-4), PX(-4), 0);
    vtx(b, PX(20), PX(-4), 0);
    vtx(c, PX(-4), PX(20), 0);
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        uint8_t face[3];
        uint16_t nat;
        face[0] = cases[k].c.r;
        face[1] = cases[k].c.g;
        face[2] = cases[k].c.b;
        zt_guard_reset();
        make(4, 3, ZL_FORMAT_RGB565_BE, 0, 0, 0);
        ctx.state.depth_test = 0;
        TEST_ASSERT_EQUAL_INT(ZL_OK, draw(tri_mesh(&ot, a, b, c, face, NULL)));
        TEST_ASSERT_EQUAL_HEX8(cases[k].be0, surf.color[0]);
        TEST_ASSERT_EQUAL_HEX8(cases[k].be1, surf.color[1]);
        TEST_ASSERT_EQUAL_HEX8(cases[k].be0, surf.color[2 * 11]);
        TEST_ASSERT_EQUAL_HEX8(cases[k].be1, surf.color[2 * 11 + 1]);

        zt_guard_reset();
        make(4, 3, ZL_FORMAT_RGB565, 0, 0, 0);
        ctx.state.depth_test = 0;
        TEST_ASSERT_EQUAL_INT(ZL_OK, draw(tri_mesh(&ot, a, b, c, face, NULL)));
        memcpy(&nat, surf.color + 2 * 5, 2);
        TEST_ASSERT_EQUAL_HEX16(cases[k].native, nat);

        zt_guard_reset();
        make(4, 3, ZL_FORMAT_RGB888, 0, 0, 0);
        ctx.state.depth_test = 0;
        TEST_ASSERT_EQUAL_INT(ZL_OK, draw(tri_mesh(&ot, a, b, c, face, NULL)));
        TEST_ASSERT_EQUAL_HEX8(cases[k].c.r, surf.color[3 * 7]);
        TEST_ASSERT_EQUAL_HEX8(cases[k].c.g, surf.color[3 * 7 + 1]);
        TEST_ASSERT_EQUAL_HEX8(cases[k].c.b, surf.color[3 * 7 + 2]);
    }
}

/* zl_clear: colour under the colour mask, depth under the depth write mask
 * (not under the depth test: glClear ignores it), every format. */
static void clear_for(zl_format fmt)
{
    const zl_rgb col = fmt == ZL_FORMAT_RGB888 ? (zl_rgb){0x12, 0x34, 0x56} : (zl_rgb){255, 0, 255};
    const uint32_t newv = fmt == ZL_FORMAT_RGB888 ? 0x123456u : 0xF81Fu;
    unsigned mask, wr, dt, x, y;
    make(11, 7, fmt, fmt == ZL_FORMAT_RGB888 ? 1u : 2u, 2, 0);
    for (dt = 0; dt < 2; dt++)
        for (wr = 0; wr < 2; wr++)
            for (mask = 0; mask <= ZL_MASK_RGB; mask++) {
                uint32_t mb = mask_bits(fmt, mask);
                scribble();
                for (y = 0; y < 7; y++)
                    for (x = 0; x < 11; x++)
                        zt_set_px(&surf, x, y, old_px(fmt, x, y));
                save_surface();
                ctx.state.color_mask = (uint8_t)mask;
                ctx.state.depth_write = (uint8_t)wr;
                ctx.state.depth_test = (uint8_t)dt;
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, col, 0x2468));
                ZT_ASSERT_SURFACE_INTACT(&surf);
                for (y = 0; y < 7; y++)
                    for (x = 0; x < 11; x++) {
                        uint32_t old = old_px(fmt, x, y);
                        uint16_t old_d;
                        memcpy(&old_d, saved_depth + y * (unsigned)surf.target.depth_stride + 2 * x, 2);
                        TEST_ASSERT_EQUAL_HEX32((old & ~mb) | (newv & mb), zt_get_px(&surf, x, y));
                        TEST_ASSERT_EQUAL_HEX16(wr ? 0x2468 : old_d, zt_get_depth(&surf, x, y));
                    }
            }
}

static void test_clear_masks(void)
{
    clear_for(ZL_FORMAT_RGB888);
    zt_guard_reset();
    clear_for(ZL_FORMAT_RGB565);
    zt_guard_reset();
    clear_for(ZL_FORMAT_RGB565_BE);
}

/* ---------------------------------------------------------------- colours */

/* Flat colour: the face colour; without face colours the state's colour,
 * even when vertex colours are given (they are for Gouraud). */
static void test_flat_colours(void)
{
    static const uint8_t face[3] = {9, 99, 199};
    static const uint8_t vcols[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    zl_fixed a[3], b[3], c[3];
    one_tri ot;
    zt_tri t;
    unsigned x, y;
    make(10, 10, ZL_FORMAT_RGB888, 0, 0, 0);
    ctx.state.depth_test = 0;
    vtx(a, PX(0), PX(0), 0);
    vtx(b, PX(10), PX(1), 0);
    vtx(c, PX(2), PX(10), 0);
    zt_tri_init(&t, a, b, c);
    zt_tri_mask(&t, cov, 10, 10);

    TEST_ASSERT_EQUAL_INT(ZL_OK, draw(tri_mesh(&ot, a, b, c, face, vcols)));
    for (y = 0; y < 10; y++)
        for (x = 0; x < 10; x++)
            TEST_ASSERT_EQUAL_HEX32(cov[y * 10 + x] ? 0x0963C7u : 0u, zt_get_px(&surf, x, y));

    zt_fill_px(&surf, 0);
    ctx.state.color.r = 0x31;
    ctx.state.color.g = 0x41;
    ctx.state.color.b = 0x59;
    TEST_ASSERT_EQUAL_INT(ZL_OK, draw(tri_mesh(&ot, a, b, c, NULL, vcols)));
    for (y = 0; y < 10; y++)
        for (x = 0; x < 10; x++)
            TEST_ASSERT_EQUAL_HEX32(cov[y * 10 + x] ? 0x314159u : 0u, zt_get_px(&surf, x, y));
}

/*
 * Gouraud: a vertex on a covered pixel centre gets exactly its own colour.
 * Only a vertex where two top/left edges meet is covered: the top-left
 * corner of (2.5,2.5) (20.5,2.5) (2.5,20.5), and the left tip of (2.5,11.5)
 * (20.5,2.5) (20.5,20.5). Each of the three vertex slots takes the covered
 * position in turn, in both windings; every other covered pixel's channels
 * lie between the vertex colours' extremes.
 */
static void test_gouraud_vertices(void)
{
    static const zl_fixed shapes[2][6] = {
        {PXH(5), PXH(5), PXH(41), PXH(5), PXH(5), PXH(41)},
        {PXH(5), PXH(23), PXH(41), PXH(5), PXH(41), PXH(41)},
    };
    static const unsigned covered_px[2][2] = {{2, 2}, {2, 11}};
    static const uint8_t palettes[3][9] = {
        {200, 17, 90, 3, 250, 128, 77, 140, 9},
        {0, 0, 0, 255, 255, 255, 255, 0, 128},
        {255, 255, 255, 0, 0, 0, 1, 254, 127},
    };
    unsigned s, rot, wind, pal, x, y, k;
    make(24, 24, ZL_FORMAT_RGB888, 2, 0, 0);
    ctx.state.depth_test = 0;
    ctx.state.shading = ZL_SHADE_GOURAUD;
    for (s = 0; s < 2; s++)
        for (pal = 0; pal < 3; pal++)
            for (rot = 0; rot < 3; rot++)
                for (wind = 0; wind < 2; wind++) {
                    zl_fixed v[3][3];
                    uint8_t vc[9];
                    one_tri ot;
                    zt_tri t;
                    unsigned slot_of[3]; /* shape vertex k goes to mesh slot slot_of[k] */
                    uint8_t lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
                    uint32_t want, got;
                    for (k = 0; k < 3; k++) {
                        unsigned slot = (k + rot) % 3;
                        if (wind && slot != 0)
                            slot = 3 - slot; /* swap slots 1 and 2 */
                        slot_of[k] = slot;
                        vtx(v[slot], shapes[s][2 * k], shapes[s][2 * k + 1], 0);
                    }
                    memcpy(vc, palettes[pal], 9);
                    for (k = 0; k < 9; k++) {
                        lo[k % 3] = vc[k] < lo[k % 3] ? vc[k] : lo[k % 3];
                        hi[k % 3] = vc[k] > hi[k % 3] ? vc[k] : hi[k % 3];
                    }
                    zt_fill_px(&surf, 0x000000u);
                    TEST_ASSERT_EQUAL_INT(ZL_OK, draw(tri_mesh(&ot, v[0], v[1], v[2], NULL, vc)));
                    zt_tri_init(&t, v[0], v[1], v[2]);
                    zt_tri_mask(&t, cov, 24, 24);
                    TEST_ASSERT_TRUE(cov[covered_px[s][1] * 24 + covered_px[s][0]]);
                    /* the covered vertex is shape vertex 0, now in slot slot_of[0] */
                    want = ((uint32_t)vc[3 * slot_of[0]] << 16) | ((uint32_t)vc[3 * slot_of[0] + 1] << 8) |
                           vc[3 * slot_of[0] + 2];
                    got = zt_get_px(&surf, covered_px[s][0], covered_px[s][1]);
                    if (want != got) {
                        snprintf(msg, sizeof msg,
                                 "shape %u palette %u rotation %u winding %u: vertex pixel (%u,%u) "
                                 "expected 0x%06lX got 0x%06lX",
                                 s, pal, rot, wind, covered_px[s][0], covered_px[s][1],
                                 (unsigned long)want, (unsigned long)got);
                        TEST_FAIL_MESSAGE(msg);
                    }
                    for (y = 0; y < 24; y++)
                        for (x = 0; x < 24; x++) {
                            uint32_t p = zt_get_px(&surf, x, y);
                            uint8_t ch[3];
                            if (!cov[y * 24 + x]) {
                                TEST_ASSERT_EQUAL_HEX32(0, p);
                                continue;
                            }
                            ch[0] = (uint8_t)(p >> 16);
                            ch[1] = (uint8_t)(p >> 8);
                            ch[2] = (uint8_t)p;
                            for (k = 0; k < 3; k++)
                                if (ch[k] < lo[k] || ch[k] > hi[k]) {
                                    snprintf(msg, sizeof msg,
                                             "pixel (%u,%u) channel %u = %u outside %u..%u", x, y,
                                             k, ch[k], lo[k], hi[k]);
                                    TEST_FAIL_MESSAGE(msg);
                                }
                        }
                }
}

/* ------------------------------------------------------------ depth plane */

static void random_tri16(uint32_t *seed, unsigned cat, int32_t *x, int32_t *y)
{
    int k;
    int32_t span = cat == 0 ? 16 * 16 : (cat == 1 ? 64 * 16 : 160 * 16);
    int32_t bx = zt_rand_range(seed, -8 * 16, 72 * 16), by = zt_rand_range(seed, -8 * 16, 72 * 16);
    for (k = 0; k < 3; k++) {
        x[k] = bx + zt_rand_range(seed, -span, span);
        y[k] = by + zt_rand_range(seed, -span, span);
    }
    if (cat == 3) { /* sliver */
        int32_t den = zt_rand_range(seed, 2, 9), num = zt_rand_range(seed, 0, den);
        x[2] = x[0] + (x[1] - x[0]) * num / den + zt_rand_range(seed, -4, 4);
        y[2] = y[0] + (y[1] - y[0]) * num / den + zt_rand_range(seed, -4, 4);
    }
}

/* Draw `drawn` (with mvp) with depth ALWAYS + write into a depth buffer
 * holding a sentinel: coverage must match the reference triangle t, covered
 * depths its plane, uncovered depths keep the sentinel. tri_desc describes
 * the triangle. Returns the covered pixel count. */
static unsigned depth_case_ref(const zt_tri *t, const zl_fixed (*drawn)[3], const zl_mat4 *mvp)
{
    static const uint8_t face[3] = {0x77, 0x66, 0x55};
    const unsigned w = surf.width, h = surf.height;
    one_tri ot;
    unsigned x, y, n;
    zl_status st;
    zt_fill_px(&surf, 0);
    zt_fill_depth(&surf, 0xA5A5);
    st = zl_draw_mesh(&ctx, tri_mesh(&ot, drawn[0], drawn[1], drawn[2], face, NULL), mvp);
    ZT_ASSERT_SURFACE_INTACT(&surf);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OK, st, tri_desc);
    n = zt_tri_mask(t, cov, w, h);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            int c = zt_get_px(&surf, x, y) == 0x776655u;
            if (c != cov[y * w + x]) {
                snprintf(msg, sizeof msg, "coverage of (%u,%u): expected %d got %d; %s", x, y,
                         cov[y * w + x], c, tri_desc);
                TEST_FAIL_MESSAGE(msg);
            }
            if (!c)
                TEST_ASSERT_EQUAL_HEX16(0xA5A5, zt_get_depth(&surf, x, y));
        }
    check_depth_tri(t, cov);
    return n;
}

/* The same in pixel space (NULL matrix). */
static unsigned depth_case(const zl_fixed (*v)[3])
{
    zt_tri t;
    zt_tri_init(&t, v[0], v[1], v[2]);
    describe(v[0], v[1], v[2], "pixel space");
    return depth_case_ref(&t, v, NULL);
}

/* Random triangles with random vertex depths in [0, 1]: every covered pixel
 * within +-1 of the exact plane (vertex range for nearly edge-on ones). */
static void test_depth_plane_random(void)
{
    uint32_t seed = 0x0BADF00Du;
    unsigned n, covered = 0;
    make(64, 64, ZL_FORMAT_RGB888, 3, 2, 0);
    ctx.state.depth_func = ZL_ALWAYS;
    for (n = 0; n < 1500; n++) {
        int32_t x[3], y[3];
        zl_fixed v[3][3];
        int k;
        random_tri16(&seed, n % 4, x, y);
        for (k = 0; k < 3; k++) {
            v[k][0] = S16(x[k]);
            v[k][1] = S16(y[k]);
            v[k][2] = (n % 10 == 0) ? (k == 0 ? 0 : PX(1)) : zt_rand_range(&seed, 0, PX(1));
        }
        covered += depth_case((const zl_fixed(*)[3])v);
    }
    TEST_ASSERT_GREATER_THAN(100000, covered);
}

/* ---------------------------------------------------------------- culling */

static void test_culling(void)
{
    static const uint8_t face[3] = {0x21, 0x43, 0x65};
    zl_fixed a[3], b[3], c[3];
    one_tri ot;
    zt_tri t;
    unsigned cull, front, wind, n;
    make(16, 16, ZL_FORMAT_RGB888, 0, 0, 0);
    ctx.state.depth_test = 0;
    /* (0,0) (10,0) (0,10): clockwise as seen on screen */
    vtx(a, PX(0), PX(0), 0);
    vtx(b, PX(10), PX(0), 0);
    vtx(c, PX(0), PX(10), 0);
    zt_tri_init(&t, a, b, c);
    TEST_ASSERT_EQUAL_INT(1, t.orient); /* the reference calls it clockwise too */
    n = zt_tri_mask(&t, cov, 16, 16);
    TEST_ASSERT_EQUAL_UINT(45, n);
    for (cull = ZL_CULL_NONE; cull <= ZL_CULL_FRONT; cull++)
        for (front = ZL_FRONT_CCW; front <= ZL_FRONT_CW; front++)
            for (wind = 0; wind < 2; wind++) { /* 0: clockwise, 1: counter-clockwise */
                int is_front = (wind == 0) == (front == ZL_FRONT_CW);
                int drawn = cull == ZL_CULL_NONE || (cull == ZL_CULL_BACK && is_front) ||
                            (cull == ZL_CULL_FRONT && !is_front);
                unsigned got;
                ctx.state.cull = (uint8_t)cull;
                ctx.state.front_face = (uint8_t)front;
                zt_fill_px(&surf, 0);
                TEST_ASSERT_EQUAL_INT(ZL_OK, draw(wind ? tri_mesh(&ot, a, c, b, face, NULL)
                                                       : tri_mesh(&ot, a, b, c, face, NULL)));
                got = zt_mask_of_px(&surf, 0x214365u, cov);
                if (got != (drawn ? n : 0u)) {
                    snprintf(msg, sizeof msg,
                             "cull %u front %u, %s triangle: expected %u pixels, got %u", cull, front,
                             wind ? "counter-clockwise" : "clockwise", drawn ? n : 0u, got);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
    /* one mesh with both windings: (0,0) (10,0) (0,10) clockwise and
     * (16,16) (10,0) (0,10) counter-clockwise; CULL_BACK with FRONT_CCW keeps
     * the second only, with FRONT_CW the first only */
    {
        static const zl_fixed pos[12] = {PX(0), PX(0), 0, PX(10), PX(0), 0, PX(0), PX(10), 0,
                                         PX(16), PX(16), 0};
        static const uint16_t ind[6] = {0, 1, 2, 3, 1, 2};
        static const uint8_t faces[6] = {1, 1, 1, 2, 2, 2};
        zl_mesh m;
        zt_tri t2;
        unsigned n2;
        memset(&m, 0, sizeof m);
        m.positions = pos;
        m.indices = ind;
        m.face_colors = faces;
        m.vertex_count = 4;
        m.triangle_count = 2;
        zt_tri_init(&t2, &pos[9], &pos[3], &pos[6]);
        TEST_ASSERT_EQUAL_INT(-1, t2.orient);
        n2 = zt_tri_mask(&t2, cov, 16, 16);
        TEST_ASSERT_GREATER_THAN(30, n2);
        ctx.state.cull = ZL_CULL_BACK;
        ctx.state.front_face = ZL_FRONT_CCW;
        zt_fill_px(&surf, 0);
        TEST_ASSERT_EQUAL_INT(ZL_OK, draw(&m));
        TEST_ASSERT_EQUAL_UINT(0, zt_mask_of_px(&surf, 0x010101u, cov));
        TEST_ASSERT_EQUAL_UINT(n2, zt_mask_of_px(&surf, 0x020202u, cov));
        ctx.state.front_face = ZL_FRONT_CW;
        zt_fill_px(&surf, 0);
        TEST_ASSERT_EQUAL_INT(ZL_OK, draw(&m));
        TEST_ASSERT_EQUAL_UINT(n, zt_mask_of_px(&surf, 0x010101u, cov));
        TEST_ASSERT_EQUAL_UINT(0, zt_mask_of_px(&surf, 0x020202u, cov));
    }
}

/* ------------------------------------------------- nothing to draw at all */

static void expect_nothing(const zl_fixed *a, const zl_fixed *b, const zl_fixed *c, const char *what)
{
    static const uint8_t face[3] = {0xFF, 0xFF, 0xFF};
    one_tri ot;
    zt_tri t;
    zt_tri_init(&t, a, b, c);
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, zt_tri_mask(&t, cov, surf.width, surf.height), what);
    scribble();
    save_surface();
    ctx.state.depth_func = ZL_ALWAYS;
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OK, draw(tri_mesh(&ot, a, b, c, face, NULL)), what);
    assert_unchanged(what);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OK, draw(tri_mesh(&ot, a, c, b, face, NULL)), what);
    assert_unchanged(what);
}

static void test_zero_area_draws_nothing(void)
{
    zl_fixed a[3], b[3], c[3];
    make(12, 12, ZL_FORMAT_RGB888, 1, 2, 0);
    vtx(a, PXH(1), PXH(1), 0);
    vtx(b, PXH(11), PXH(11), 0);
    vtx(c, PXH(21), PXH(21), 0);
    expect_nothing(a, b, c, "collinear through centres");
    vtx(c, PXH(1), PXH(1), PX(1));
    expect_nothing(a, b, c, "two equal vertices");
    vtx(b, PXH(1), PXH(1), PX(1) / 2);
    expect_nothing(a, b, c, "three equal vertices");
    vtx(a, PX(0), PXH(5), 0);
    vtx(b, PX(12), PXH(5), 0);
    vtx(c, PX(6), PXH(5) + 1000, 0); /* collinear once snapped */
    expect_nothing(a, b, c, "collinear after snapping");
    vtx(a, PXH(7), PX(-3), 0);
    vtx(b, PXH(7), PX(20), 0);
    vtx(c, PXH(7) - 2047, PX(5), 0);
    expect_nothing(a, b, c, "vertical, collinear after snapping");
}

static void test_offscreen_draws_nothing(void)
{
    zl_fixed a[3], b[3], c[3];
    make(16, 16, ZL_FORMAT_RGB888, 2, 2, 0);
    vtx(a, PX(-10), PX(2), 0);
    vtx(b, PX(-1), PX(8), 0);
    vtx(c, PX(-7), PX(14), 0);
    expect_nothing(a, b, c, "left");
    vtx(a, PX(17), PX(2), 0);
    vtx(b, PX(30), PX(8), 0);
    vtx(c, PX(20), PX(14), 0);
    expect_nothing(a, b, c, "right");
    vtx(a, PX(2), PX(-17), 0);
    vtx(b, PX(8), PX(-1), 0);
    vtx(c, PX(14), PX(-9), 0);
    expect_nothing(a, b, c, "above");
    vtx(a, PX(2), PX(16), 0);
    vtx(b, PX(8), PX(40), 0);
    vtx(c, PX(14), PX(16), 0);
    expect_nothing(a, b, c, "below, top edge on the border");
    vtx(a, PXH(1), PX(-5), 0);
    vtx(b, PXH(1), PX(25), 0);
    vtx(c, PX(-9), PX(10), 0);
    expect_nothing(a, b, c, "right edge through the centres of column 0");
    vtx(a, PX(-20), PX(-20), 0);
    vtx(b, PXH(41), PX(-20), 0);
    vtx(c, PX(-20), PXH(41), 0);
    expect_nothing(a, b, c, "bounding box covers the target, x + y < 0.5 does not");
    vtx(a, PX(-10), PX(-10), 0);
    vtx(b, PXH(1), PX(-10), 0);
    vtx(c, PX(-10), PXH(1), 0);
    expect_nothing(a, b, c, "bounding box corner on the centre of (0,0)");
    vtx(a, PX(30000), PX(30000), 0);
    vtx(b, PX(32000), PX(30000), 0);
    vtx(c, PX(30000), PX(32000), 0);
    expect_nothing(a, b, c, "far away");
    vtx(a, PX(-32768), PX(-32768), 0);
    vtx(b, PX(-20000), PX(-32768), 0);
    vtx(c, PX(-32768), PX(-1), 0);
    expect_nothing(a, b, c, "far away, negative");
    vtx(a, PX(-32768), PX(17), 0);
    vtx(b, ZL_FX_MAX, PX(17), 0);
    vtx(c, PX(0), ZL_FX_MAX, 0);
    expect_nothing(a, b, c, "huge, just below");
}

/* ------------------------------------------------------- huge triangles */

/*
 * Vertices tens of thousands of pixels away (the Q16.16 range ends at
 * +-32768 px, far inside the guard band, so nothing is clipped): coverage
 * must be exactly the reference's in-viewport pixels, depth within +-1 of
 * the plane, nothing written out of bounds. Edges through the viewport are
 * built from two grid points inside it, stretched tens of thousands of
 * pixels both ways, so the edge passes exactly through those points (often
 * pixel centres).
 */
static void test_huge_triangles(void)
{
    uint32_t seed = 0x5EED1234u;
    zl_fixed v[3][3];
    unsigned n, covered = 0, partial = 0;
    make(64, 64, ZL_FORMAT_RGB888, 3, 2, 0);
    ctx.state.depth_func = ZL_ALWAYS;

    /* the extremes: the diagonal y = x through the whole viewport (a left
     * edge: centres on it covered) */
    vtx(v[0], ZL_FX_MIN, ZL_FX_MIN, 0);
    vtx(v[1], ZL_FX_MAX, ZL_FX_MIN, PX(1) / 2);
    vtx(v[2], ZL_FX_MAX, ZL_FX_MAX, PX(1));
    TEST_ASSERT_EQUAL_UINT(64 * 65 / 2, depth_case((const zl_fixed(*)[3])v));
    /* the whole viewport */
    vtx(v[0], PX(-30000), PX(-30000), PX(1) / 3);
    vtx(v[1], PX(32000), PX(-30000), PX(1) / 3);
    vtx(v[2], PX(-30000), PX(32000), PX(1) / 3);
    TEST_ASSERT_EQUAL_UINT(64 * 64, depth_case((const zl_fixed(*)[3])v));

    for (n = 0; n < 400; n++) {
        int32_t px, py, dx, dy, m, k2, sgn;
        int64_t ax, ay, bx, by, wx, wy;
        int k;
        if (n & 1) { /* on pixel centres, whole-pixel directions */
            px = zt_rand_range(&seed, 0, 63) * 16 + 8;
            py = zt_rand_range(&seed, 0, 63) * 16 + 8;
            dx = zt_rand_range(&seed, -6, 6) * 16;
            dy = zt_rand_range(&seed, -6, 6) * 16;
        } else {
            px = zt_rand_range(&seed, 0, 64 * 16);
            py = zt_rand_range(&seed, 0, 64 * 16);
            dx = zt_rand_range(&seed, -200, 200);
            dy = zt_rand_range(&seed, -200, 200);
        }
        if (dx == 0 && dy == 0)
            dx = 16;
        /* stretch to about 25000 px (in sixteenths) */
        m = 400000 / ((dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy) ? (dx < 0 ? -dx : dx) : (dy < 0 ? -dy : dy));
        ax = px - (int64_t)m * dx;
        ay = py - (int64_t)m * dy;
        bx = px + (int64_t)m * dx;
        by = py + (int64_t)m * dy;
        sgn = (zt_rand(&seed) & 1) ? 1 : -1;
        k2 = zt_rand_range(&seed, 1, m);
        wx = px + (int64_t)sgn * k2 * (-dy) + zt_rand_range(&seed, -16 * 16, 16 * 16);
        wy = py + (int64_t)sgn * k2 * dx + zt_rand_range(&seed, -16 * 16, 16 * 16);
        vtx(v[0], S16(ax), S16(ay), 0);
        vtx(v[1], S16(bx), S16(by), 0);
        vtx(v[2], (zl_fixed)(wx * 4096), (zl_fixed)(wy * 4096), 0);
        for (k = 0; k < 3; k++)
            v[k][2] = zt_rand_range(&seed, 0, PX(1));
        {
            unsigned c = depth_case((const zl_fixed(*)[3])v);
            covered += c;
            partial += c > 0 && c < 64 * 64;
        }
    }
    TEST_ASSERT_GREATER_THAN(200, partial);
    TEST_ASSERT_GREATER_THAN(100000, covered);
}

/*
 * Beyond the Q16.16 pixel range: vertices up to 100000 px away, reached
 * through a matrix. zline.h does not spell out the viewport transform; this
 * assumes OpenGL's with rows counted downwards and the contract's depth
 * range (near z = 0, far z = w):
 *     x_w = (x/w + 1) W/2,  y_w = (1 - y/w) H/2,  z_w = z/w,
 * and test_clip_space_mapping checks that assumption on small triangles
 * first. With the identity matrix (w = 1) and W = H = 64, a window position
 * of s sixteenths of a pixel is the clip coordinate s * 128 - 65536 (x) or
 * 65536 - s * 128 (y) in raw Q16.16: exact, no rounding. 100000 px is
 * inside the 131072 px guard band, so no clipping: the coverage must be the
 * reference's for the unclipped triangle.
 */
static const zl_mat4 identity = {{65536, 0, 0, 0, 0, 65536, 0, 0, 0, 0, 65536, 0, 0, 0, 0, 65536}};

/* Triangle with window positions xs[k], ys[k] in sixteenths of a pixel
 * (possibly beyond Q16.16 px) and depths z[k], drawn through the identity
 * matrix on the 64 x 64 target. */
static unsigned clip_case(const int64_t *xs, const int64_t *ys, const zl_fixed *z)
{
    zl_fixed c[3][3];
    int64_t ref[9];
    zt_tri t;
    int k;
    TEST_ASSERT_TRUE(surf.width == 64 && surf.height == 64);
    for (k = 0; k < 3; k++) {
        c[k][0] = (zl_fixed)(xs[k] * 128 - 65536);
        c[k][1] = (zl_fixed)(65536 - ys[k] * 128);
        c[k][2] = z[k];
        ref[3 * k] = xs[k] * 4096;
        ref[3 * k + 1] = ys[k] * 4096;
        ref[3 * k + 2] = z[k];
    }
    zt_tri_init64(&t, ref);
    snprintf(tri_desc, sizeof tri_desc,
             "triangle (%ld,%ld) (%ld,%ld) (%ld,%ld) in 1/16 px, z (%ld,%ld,%ld), clip space "
             "x,y raw (%ld,%ld) (%ld,%ld) (%ld,%ld)",
             (long)xs[0], (long)ys[0], (long)xs[1], (long)ys[1], (long)xs[2], (long)ys[2], (long)z[0],
             (long)z[1], (long)z[2], (long)c[0][0], (long)c[0][1], (long)c[1][0], (long)c[1][1],
             (long)c[2][0], (long)c[2][1]);
    return depth_case_ref(&t, (const zl_fixed(*)[3])c, &identity);
}

/* The assumed viewport transform, on triangles inside the Q16.16 range. */
static void test_clip_space_mapping(void)
{
    uint32_t seed = 0x7A11C0DEu;
    unsigned n;
    make(64, 64, ZL_FORMAT_RGB888, 1, 2, 0);
    ctx.state.depth_func = ZL_ALWAYS;
    for (n = 0; n < 300; n++) {
        int32_t x[3], y[3];
        int64_t xs[3], ys[3];
        zl_fixed z[3];
        int k;
        random_tri16(&seed, n % 4, x, y);
        for (k = 0; k < 3; k++) {
            xs[k] = x[k];
            ys[k] = y[k];
            z[k] = zt_rand_range(&seed, 0, PX(1));
        }
        clip_case(xs, ys, z);
    }
}

/* Vertices up to 100000 px away, with edges through the viewport. */
static void test_huge_triangles_clip_space(void)
{
    uint32_t seed = 0x0DDBA11u;
    unsigned n, covered = 0, partial = 0;
    int64_t xs[3], ys[3];
    zl_fixed z[3];
    make(64, 64, ZL_FORMAT_RGB888, 3, 2, 0);
    ctx.state.depth_func = ZL_ALWAYS;

    /* the whole viewport (hypotenuse x + y = 6250 px) */
    xs[0] = -1600000, ys[0] = -1600000, xs[1] = 1700000, ys[1] = -1600000;
    xs[2] = -1600000, ys[2] = 1700000;
    z[0] = z[1] = z[2] = PX(1) / 3;
    TEST_ASSERT_EQUAL_UINT(64 * 64, clip_case(xs, ys, z));
    /* the diagonal y = x from -100000 to +100000 px: a left edge */
    xs[0] = -1600000, ys[0] = -1600000, xs[1] = 1600000, ys[1] = -1600000;
    xs[2] = 1600000, ys[2] = 1600000;
    z[0] = 0, z[1] = PX(1) / 2, z[2] = PX(1);
    TEST_ASSERT_EQUAL_UINT(64 * 65 / 2, clip_case(xs, ys, z));

    for (n = 0; n < 400; n++) {
        int32_t px, py, dx, dy, m, k2, sgn, big;
        int k;
        if (n & 1) { /* on pixel centres, whole-pixel directions */
            px = zt_rand_range(&seed, 0, 63) * 16 + 8;
            py = zt_rand_range(&seed, 0, 63) * 16 + 8;
            dx = zt_rand_range(&seed, -6, 6) * 16;
            dy = zt_rand_range(&seed, -6, 6) * 16;
        } else {
            px = zt_rand_range(&seed, 0, 64 * 16);
            py = zt_rand_range(&seed, 0, 64 * 16);
            dx = zt_rand_range(&seed, -300, 300);
            dy = zt_rand_range(&seed, -300, 300);
        }
        if (dx == 0 && dy == 0)
            dx = 16;
        big = (dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy) ? (dx < 0 ? -dx : dx) : (dy < 0 ? -dy : dy);
        m = 1600000 / big; /* about 100000 px */
        xs[0] = px - (int64_t)m * dx;
        ys[0] = py - (int64_t)m * dy;
        xs[1] = px + (int64_t)m * dx;
        ys[1] = py + (int64_t)m * dy;
        sgn = (zt_rand(&seed) & 1) ? 1 : -1;
        k2 = zt_rand_range(&seed, 1, m);
        xs[2] = px + (int64_t)sgn * k2 * (-dy) + zt_rand_range(&seed, -256, 256);
        ys[2] = py + (int64_t)sgn * k2 * dx + zt_rand_range(&seed, -256, 256);
        for (k = 0; k < 3; k++)
            z[k] = zt_rand_range(&seed, 0, PX(1));
        {
            unsigned c = clip_case(xs, ys, z);
            covered += c;
            partial += c > 0 && c < 64 * 64;
        }
    }
    TEST_ASSERT_GREATER_THAN(200, partial);
    TEST_ASSERT_GREATER_THAN(100000, covered);
}

/* ------------------------------------------------------ invalid arguments */

/* zl_init must fail with `want`, or with any negative status when want is
 * ZL_OK, and leave the buffers alone. */
static void expect_init_fails(const zl_target *t, zl_status want, const char *what)
{
    zl_context c;
    zl_status st;
    save_surface();
    st = zl_init(&c, t);
    if (want != ZL_OK)
        TEST_ASSERT_EQUAL_INT_MESSAGE(want, st, what);
    else
        TEST_ASSERT_LESS_THAN_MESSAGE(0, st, what);
    assert_unchanged(what);
}

static void test_invalid_init(void)
{
    zl_target t;
    zl_context c;
    make(8, 6, ZL_FORMAT_RGB888, 0, 0, 0);
    scribble();
    save_surface();
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_init(NULL, &surf.target));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_init(&c, NULL));
    assert_unchanged("NULL");

    t = surf.target;
    t.format = 3;
    expect_init_fails(&t, ZL_ERR_ARG, "unknown format 3");
    t.format = 255;
    expect_init_fails(&t, ZL_ERR_ARG, "unknown format 255");
    t = surf.target;
    t.width = 0;
    expect_init_fails(&t, ZL_ERR_SIZE, "width 0");
    t = surf.target;
    t.height = 0;
    expect_init_fails(&t, ZL_ERR_SIZE, "height 0");
    t = surf.target;
    t.width = ZL_MAX_DIM + 1;
    t.color_stride = (ZL_MAX_DIM + 1) * 3;
    t.depth_stride = (ZL_MAX_DIM + 1) * 2;
    expect_init_fails(&t, ZL_ERR_SIZE, "width above ZL_MAX_DIM");
    t = surf.target;
    t.height = ZL_MAX_DIM + 1;
    expect_init_fails(&t, ZL_ERR_SIZE, "height above ZL_MAX_DIM");
    t = surf.target;
    t.color_stride = 8 * 3 - 1;
    expect_init_fails(&t, ZL_ERR_SIZE, "colour stride one byte short");
    t = surf.target;
    t.color_stride = 0;
    expect_init_fails(&t, ZL_ERR_SIZE, "colour stride 0");
    t = surf.target;
    t.color_stride = -24;
    expect_init_fails(&t, ZL_OK, "negative colour stride");
    t = surf.target;
    t.depth_stride = 8 * 2 - 2;
    expect_init_fails(&t, ZL_ERR_SIZE, "depth stride one pixel short");
    t = surf.target;
    t.depth_stride = 8 * 2 + 1;
    expect_init_fails(&t, ZL_OK, "odd depth stride");
    t = surf.target;
    t.depth_stride = -16;
    expect_init_fails(&t, ZL_OK, "negative depth stride");
    t = surf.target;
    t.format = ZL_FORMAT_RGB565;
    t.color_stride = 8 * 2 - 1;
    expect_init_fails(&t, ZL_ERR_SIZE, "RGB565 stride short");

    /* zl_clear with NULL */
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_clear(NULL, (zl_rgb){1, 2, 3}, 7));
    assert_unchanged("zl_clear(NULL)");
}

/* A valid 3-triangle mesh covering the whole target: the last triangle is
 * spoiled in various ways; nothing at all may be drawn. */
static void test_invalid_draw(void)
{
    static const zl_fixed pos[12] = {PX(-5), PX(-5), PX(1) / 4, PX(40), PX(-5), PX(1) / 4,
                                     PX(-5), PX(40), PX(1) / 4, PX(40), PX(40), PX(1) / 4};
    uint16_t ind[9] = {0, 1, 2, 1, 3, 2, 0, 1, 2};
    static const uint8_t faces[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    static const uint8_t vcols[12] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    zl_mesh m, bad;
    zl_state good_state;
    make(8, 6, ZL_FORMAT_RGB888, 1, 2, 0);
    ctx.state.depth_test = 0; /* the last triangle would win every pixel */
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = ind;
    m.face_colors = faces;
    m.vertex_colors = vcols;
    m.vertex_count = 4;
    m.triangle_count = 3;
    good_state = ctx.state;
    scribble();
    save_surface();

    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(NULL, &m, NULL));
    assert_unchanged("NULL context");
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, NULL, NULL));
    assert_unchanged("NULL mesh");
    bad = m;
    bad.positions = NULL;
    TEST_ASSERT_LESS_THAN(0, zl_draw_mesh(&ctx, &bad, NULL));
    assert_unchanged("NULL positions");
    bad = m;
    bad.indices = NULL;
    TEST_ASSERT_LESS_THAN(0, zl_draw_mesh(&ctx, &bad, NULL));
    assert_unchanged("NULL indices");

    ind[8] = 4; /* == vertex_count */
    TEST_ASSERT_LESS_THAN(0, zl_draw_mesh(&ctx, &m, NULL));
    assert_unchanged("index == vertex_count in the last triangle");
    ind[8] = 0xFFFF;
    TEST_ASSERT_LESS_THAN(0, zl_draw_mesh(&ctx, &m, NULL));
    assert_unchanged("index 65535 in the last triangle");
    ind[8] = 2;
    ind[6] = 7;
    ctx.state.shading = ZL_SHADE_GOURAUD;
    TEST_ASSERT_LESS_THAN(0, zl_draw_mesh(&ctx, &m, NULL));
    assert_unchanged("index out of range, Gouraud");
    ctx.state.shading = ZL_SHADE_FLAT;
    ind[6] = 0;
    bad = m;
    bad.vertex_count = 0;
    TEST_ASSERT_LESS_THAN(0, zl_draw_mesh(&ctx, &bad, NULL));
    assert_unchanged("vertex_count 0");

    ctx.state.depth_func = 8;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, &m, NULL));
    assert_unchanged("depth_func 8");
    ctx.state = good_state;
    ctx.state.cull = 3;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, &m, NULL));
    assert_unchanged("cull 3");
    ctx.state = good_state;
    ctx.state.front_face = 2;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, &m, NULL));
    assert_unchanged("front_face 2");
    ctx.state = good_state;
    ctx.state.shading = 2;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, &m, NULL));
    assert_unchanged("shading 2");
    ctx.state = good_state;

    /* an empty mesh is fine and draws nothing */
    bad = m;
    bad.triangle_count = 0;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &bad, NULL));
    assert_unchanged("no triangles");

    /* and the valid mesh does draw (so the checks above meant something) */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
    ZT_ASSERT_SURFACE_INTACT(&surf);
    {
        unsigned x, y;
        for (y = 0; y < 6; y++)
            for (x = 0; x < 8; x++)
                TEST_ASSERT_EQUAL_HEX32(0x070809u, zt_get_px(&surf, x, y));
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_format_bytes);
    RUN_TEST(test_state_default_and_check);
    RUN_TEST(test_depth_functions);
    RUN_TEST(test_depth_test_off);
    RUN_TEST(test_depth_write_off_and_order);
    RUN_TEST(test_depth_only_target);
    RUN_TEST(test_color_mask_rgb888);
    RUN_TEST(test_color_mask_rgb565);
    RUN_TEST(test_color_mask_rgb565_be);
    RUN_TEST(test_pixel_bytes);
    RUN_TEST(test_clear_masks);
    RUN_TEST(test_flat_colours);
    RUN_TEST(test_gouraud_vertices);
    RUN_TEST(test_depth_plane_random);
    RUN_TEST(test_culling);
    RUN_TEST(test_zero_area_draws_nothing);
    RUN_TEST(test_offscreen_draws_nothing);
    RUN_TEST(test_huge_triangles);
    RUN_TEST(test_clip_space_mapping);
    RUN_TEST(test_huge_triangles_clip_space);
    RUN_TEST(test_invalid_init);
    RUN_TEST(test_invalid_draw);
    RUN_TEST(test_rgb888_any_alignment);
    RUN_TEST(test_rgb565_be_odd_alignment); /* last: a misaligned access may trap */
    return UNITY_END();
}
