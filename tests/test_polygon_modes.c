/* SPDX-License-Identifier: MIT */
/*
 * Polygon modes (point, line, fill per front and back face, as
 * glPolygonMode) and polygon offset (factor * max slope + units * r), in
 * frame mode; tests/test_frame_modes.c checks the scanline modes give the
 * same bytes. References are written here from the rules in zline.h.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 48, H = 40 };

static uint8_t color[W * H * 3];
static uint16_t depth[W * H];
static zl_context ctx;
static uint8_t want[W * H], got[W * H];

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

/* Pixels of a given red value. */
static unsigned read_red(uint8_t r, uint8_t *m)
{
    unsigned i, n = 0;
    for (i = 0; i < W * H; i++) {
        m[i] = color[i * 3] == r;
        n += m[i];
    }
    return n;
}

static int64_t floor_div(int64_t n, int64_t d)
{
    int64_t q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}

/* The line rule: pixels of the segment between pixels (X0,Y0), (X1,Y1). */
static void rule_segment(int64_t X0, int64_t Y0, int64_t X1, int64_t Y1, uint8_t *m)
{
    int64_t dx = X1 - X0, dy = Y1 - Y0, k;
    int xmajor = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
    int64_t lo = xmajor ? (X0 < X1 ? X0 : X1) : (Y0 < Y1 ? Y0 : Y1);
    int64_t hi = xmajor ? (X0 < X1 ? X1 : X0) : (Y0 < Y1 ? Y1 : Y0);
    for (k = lo; k <= hi; k++) {
        int64_t n = xmajor ? (k - X0) * dy : (k - Y0) * dx, d = xmajor ? dx : dy, o;
        if (d < 0) {
            n = -n;
            d = -d;
        }
        /* nearest, halves down: ceil(n/d - 1/2) */
        o = d == 0 ? 0 : -floor_div(d - 2 * n, 2 * d);
        if (xmajor && k >= 0 && k < W && Y0 + o >= 0 && Y0 + o < H)
            m[(Y0 + o) * W + k] = 1;
        if (!xmajor && k >= 0 && k < H && X0 + o >= 0 && X0 + o < W)
            m[k * W + X0 + o] = 1;
    }
}

/* Pixel of a pixel-space coordinate given in sixteenths. */
#define S16(n) ((zl_fixed)((n) * 4096))

static zl_fixed tri_pos[9];
static const uint16_t tri_idx[3] = {0, 1, 2};
static const uint8_t red1[3] = {10, 0, 0};

static void set_tri(const int32_t *xy16, zl_fixed z)
{
    int k;
    for (k = 0; k < 3; k++) {
        tri_pos[k * 3] = S16(xy16[k * 2]);
        tri_pos[k * 3 + 1] = S16(xy16[k * 2 + 1]);
        tri_pos[k * 3 + 2] = z;
    }
}

static void draw_tri(void)
{
    zl_mesh m = {tri_pos, tri_idx, NULL, red1, 3, 1};
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
}

static void wire_reference(const int32_t *xy16)
{
    int k;
    memset(want, 0, sizeof want);
    for (k = 0; k < 3; k++) {
        const int32_t *a = &xy16[k * 2], *b = &xy16[((k + 1) % 3) * 2];
        rule_segment(a[0] / 16, a[1] / 16, b[0] / 16, b[1] / 16, want);
    }
}

static void test_line_and_point_modes_per_face(void)
{
    /* Clockwise on screen (y down) ... */
    static const int32_t cw[6] = {40, 24, 600, 200, 120, 560};
    /* ... and the same triangle counter-clockwise. */
    static const int32_t ccw[6] = {40, 24, 120, 560, 600, 200};
    unsigned n_fill;
    make_target();
    ctx.state.depth_test = 0;
    ctx.style.polygon_front = ZL_POLY_LINE;
    ctx.style.polygon_back = ZL_POLY_FILL;
    /* front faces are counter-clockwise: ccw is front -> wireframe */
    clear();
    set_tri(ccw, 0);
    draw_tri();
    wire_reference(ccw);
    read_red(10, got);
    TEST_ASSERT_EQUAL_MEMORY(want, got, sizeof want);
    /* cw is a back face -> filled */
    clear();
    set_tri(cw, 0);
    draw_tri();
    n_fill = read_red(10, got);
    TEST_ASSERT_GREATER_THAN(100, n_fill);
    /* the same with the faces swapped */
    ctx.style.polygon_front = ZL_POLY_FILL;
    ctx.style.polygon_back = ZL_POLY_LINE;
    clear();
    draw_tri();
    wire_reference(cw);
    read_red(10, got);
    TEST_ASSERT_EQUAL_MEMORY(want, got, sizeof want);
    /* point mode: the vertex pixels */
    ctx.style.polygon_back = ZL_POLY_POINT;
    clear();
    draw_tri();
    memset(want, 0, sizeof want);
    want[(24 / 16) * W + 40 / 16] = 1;
    want[(200 / 16) * W + 600 / 16] = 1;
    want[(560 / 16) * W + 120 / 16] = 1;
    read_red(10, got);
    TEST_ASSERT_EQUAL_MEMORY(want, got, sizeof want);
    /* culling comes first: a culled back face draws nothing in any mode */
    ctx.state.cull = ZL_CULL_BACK;
    clear();
    draw_tri();
    TEST_ASSERT_EQUAL_UINT32(0, read_red(10, got));
    /* a zero-area triangle draws nothing either */
    {
        static const int32_t flat[6] = {40, 40, 400, 40, 200, 40};
        ctx.state.cull = ZL_CULL_NONE;
        ctx.style.polygon_front = ZL_POLY_LINE;
        ctx.style.polygon_back = ZL_POLY_LINE;
        set_tri(flat, 0);
        clear();
        draw_tri();
        TEST_ASSERT_EQUAL_UINT32(0, read_red(10, got));
    }
}

/* Wireframe edges are depth-tested: behind a filled triangle they hide. */
static void test_wireframe_is_depth_tested(void)
{
    static const int32_t back[6] = {24, 24, 700, 100, 100, 600};
    static const int32_t front[6] = {300, 0, 760, 620, 0, 620};
    static const uint8_t red2[3] = {20, 0, 0};
    zl_fixed fpos[9];
    zl_mesh fm = {fpos, tri_idx, NULL, red2, 3, 1};
    uint8_t cover[W * H];
    int k, hidden = 0;
    make_target();
    /* the coverage of the front triangle alone */
    for (k = 0; k < 3; k++) {
        fpos[k * 3] = S16(front[k * 2]);
        fpos[k * 3 + 1] = S16(front[k * 2 + 1]);
        fpos[k * 3 + 2] = ZL_FX_ONE / 5;
    }
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &fm, NULL));
    read_red(20, cover);
    /* front filled first, then the wireframe behind it */
    ctx.style.polygon_front = ZL_POLY_LINE;
    ctx.style.polygon_back = ZL_POLY_LINE;
    set_tri(back, ZL_FX_ONE / 2);
    draw_tri();
    wire_reference(back);
    read_red(10, got);
    for (k = 0; k < W * H; k++) {
        hidden += want[k] && cover[k];
        TEST_ASSERT_EQUAL_INT(want[k] && !cover[k], got[k]);
    }
    TEST_ASSERT_GREATER_THAN(10, hidden);
}

/* Offset = factor * max(|dz/dx|, |dz/dy|) + units: a triangle whose depth
 * goes 0.25 .. 0.75 over 64 pixels in x has a slope of 0.5 * 65535 / 64
 * steps per pixel. */
static void test_offset_amount(void)
{
    static const int32_t big[6] = {0, 0, 64 * 16, 0, 0, 64 * 16};
    uint16_t base[W * H];
    int i, f, u;
    make_target();
    set_tri(big, 0);
    tri_pos[2] = ZL_FX_ONE / 4;
    tri_pos[5] = ZL_FX_ONE * 3 / 4;
    tri_pos[8] = ZL_FX_ONE / 4;
    clear();
    draw_tri();
    memcpy(base, depth, sizeof base);
    for (f = -2; f <= 2; f++)
        for (u = -3; u <= 3; u += 3) {
            /* expected offset in steps, exact: f * 0.5 * 65535 / 64 + u */
            int64_t num = (int64_t)f * 65535 + (int64_t)u * 128, den = 128;
            ctx.style.offset_factor = f * ZL_FX_ONE;
            ctx.style.offset_units = u * ZL_FX_ONE;
            clear();
            draw_tri();
            for (i = 0; i < W * H; i++)
                if (color[i * 3] == 10)
                    TEST_ASSERT_INT_WITHIN(1, base[i] + floor_div(num + den / 2, den), depth[i]);
        }
}

/* The decal case: a floor receding from the camera, and a smaller decal
 * quad lying in the same plane with its own vertices. Drawn after the floor
 * with LESS it z-fights; with offset (-1, -1) it shows on every pixel. */
static void test_decal(void)
{
    static const zl_fixed floor_pos[] = {-ZL_FX_INT(4), 0, -ZL_FX_INT(1), ZL_FX_INT(4), 0, -ZL_FX_INT(1),
                                         ZL_FX_INT(4), 0, -ZL_FX_INT(30), -ZL_FX_INT(4), 0, -ZL_FX_INT(30)};
    static const zl_fixed decal_pos[] = {-ZL_FX_INT(1) - 1234, 0, -ZL_FX_INT(2) - 777,
                                         ZL_FX_INT(1) + 4321, 0, -ZL_FX_INT(2) - 55,
                                         ZL_FX_INT(1) + 999, 0, -ZL_FX_INT(9) - 3210,
                                         -ZL_FX_INT(1) - 87, 0, -ZL_FX_INT(9) - 31};
    static const uint16_t quad[] = {0, 1, 2, 0, 2, 3};
    static const uint8_t grey[] = {50, 50, 50, 50, 50, 50}, blue[] = {200, 0, 0, 200, 0, 0};
    zl_mesh floor_m = {floor_pos, quad, NULL, grey, 4, 2}, decal_m = {decal_pos, quad, NULL, blue, 4, 2};
    zl_mat4 proj, view, mvp;
    zl_vec3 eye = {0, ZL_FX_ONE, ZL_FX_INT(1)}, target = {0, 0, -ZL_FX_INT(6)}, up = {0, ZL_FX_ONE, 0};
    uint8_t cover[W * H];
    unsigned covered, shown;
    make_target();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(W) / H,
                                                     ZL_FX_ONE / 10, ZL_FX_INT(50)));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
    zl_mat4_mul(&mvp, &proj, &view);
    /* the decal's own coverage */
    ctx.state.depth_test = 0;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &decal_m, &mvp));
    covered = read_red(200, cover);
    TEST_ASSERT_GREATER_THAN(100, covered);
    ctx.state.depth_test = 1;
    ctx.state.depth_func = ZL_LESS;
    /* without offset: some pixels show, some do not */
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &floor_m, &mvp));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &decal_m, &mvp));
    shown = read_red(200, got);
    {
        char m[120];
        snprintf(m, sizeof m, "decal without offset: %u of %u pixels show", shown, covered);
        TEST_MESSAGE(m);
    }
    TEST_ASSERT_GREATER_THAN(0, shown);
    TEST_ASSERT_LESS_THAN(covered, shown);
    /* with offset (-1, -1): every decal pixel */
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &floor_m, &mvp));
    ctx.style.offset_factor = -ZL_FX_ONE;
    ctx.style.offset_units = -ZL_FX_ONE;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &decal_m, &mvp));
    read_red(200, got);
    TEST_ASSERT_EQUAL_MEMORY(cover, got, sizeof got);
}

/* Toon: the Lambert intensity of each face quantised to N bands, coloured
 * from the table. Three faces at known angles to the light. */
static void test_toon_bands(void)
{
    static const zl_rgb table[4] = {{10, 0, 0}, {80, 0, 0}, {160, 0, 0}, {240, 0, 0}};
    /* a pixel-space triangle whose normal (p1 - p0) x (p2 - p0) is +z */
    static const zl_fixed pos[] = {0, 0, 0, ZL_FX_INT(30), 0, 0, 0, ZL_FX_INT(30), 0};
    static const uint16_t idx[] = {0, 1, 2};
    /* light at angle a from the normal: intensity = ambient + (255 - ambient) cos a */
    static const int32_t lx[] = {0, 46341, 60547, 64540}; /* 0, 45, 67.5, 80 degrees (sin) */
    static const int32_t lz[] = {65536, 46341, 25080, 11380};
    static const unsigned want_band[] = {3, 2, 1, 0}; /* 255, 180.3, 97.6, 44.3 with ambient 0 -> N = 4 bands */
    zl_mesh m = {pos, idx, NULL, NULL, 3, 1};
    int k;
    make_target();
    ctx.state.light_on = 1;
    ctx.state.ambient = 0;
    ctx.style.toon_bands = 4;
    ctx.style.toon_colors = table;
    for (k = 0; k < 4; k++) {
        ctx.state.light_dir.x = lx[k];
        ctx.state.light_dir.y = 0;
        ctx.state.light_dir.z = lz[k];
        clear();
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
        TEST_ASSERT_EQUAL_UINT8(table[want_band[k]].r, color[(5 * W + 5) * 3]);
    }
    /* N = 1: everything lit takes the one colour; a null table is refused */
    ctx.style.toon_bands = 1;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
    TEST_ASSERT_EQUAL_UINT8(10, color[(5 * W + 5) * 3]);
    ctx.style.toon_colors = NULL;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, &m, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_line_and_point_modes_per_face);
    RUN_TEST(test_wireframe_is_depth_tested);
    RUN_TEST(test_offset_amount);
    RUN_TEST(test_decal);
    RUN_TEST(test_toon_bands);
    return UNITY_END();
}
