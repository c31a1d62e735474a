/* SPDX-License-Identifier: MIT */
/*
 * Lines and points against the LINE RULE of zline.h: hand-drawn masks for
 * the tie cases, a reference written from the rule (exact integers, per
 * major coordinate, no stepping) for random segments in every octant and
 * far outside the target, symmetry (A to B == B to A), the DDA's stated
 * differences, depth along the line against the exact linear value, strips
 * and loops, and points of size 1 and N.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 40, H = 30 };

static uint8_t color[W * H * 3];
static uint16_t depth[W * H];
static zl_context ctx;
static uint8_t want[W * H], got[W * H];

static uint32_t rng = 0x2545F491u;
static int32_t rand_range(int32_t lo, int32_t hi)
{
    return zt_rand_range(&rng, lo, hi);
}

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
    ctx.state.depth_test = 0;
    ctx.state.depth_write = 0;
}

static void clear(void)
{
    zl_rgb black = {0, 0, 0};
    zl_state keep = ctx.state;
    ctx.state.depth_write = 1;
    ctx.state.color_mask = ZL_MASK_RGB;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 65535));
    ctx.state = keep;
}

/* Coverage of the colour buffer (any non-black pixel). */
static unsigned read_mask(uint8_t *m)
{
    unsigned i, n = 0;
    for (i = 0; i < W * H; i++) {
        m[i] = (uint8_t)((color[i * 3] | color[i * 3 + 1] | color[i * 3 + 2]) != 0);
        n += m[i];
    }
    return n;
}

/* Q16.16 from sixteenths of a pixel. */
#define S16(n) ((zl_fixed)((n) * 4096))

static void draw_segment(const zl_fixed *a, const zl_fixed *b, unsigned algo)
{
    zl_fixed pos[6];
    zl_lines l;
    memcpy(pos, a, 3 * sizeof *pos);
    memcpy(pos + 3, b, 3 * sizeof *pos);
    memset(&l, 0, sizeof l);
    l.positions = pos;
    l.vertex_count = 2;
    l.count = 2;
    l.prim = ZL_PRIM_LINES;
    ctx.style.line_algo = (uint8_t)algo;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, NULL));
}

/* Hand masks, '#' covered. */
static void check_mask(const char *const *rows, unsigned nrows, const char *what)
{
    unsigned x, y;
    memset(want, 0, sizeof want);
    for (y = 0; y < nrows; y++)
        for (x = 0; rows[y][x] != '\0'; x++)
            want[y * W + x] = rows[y][x] == '#';
    read_mask(got);
    TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, got, sizeof want, what);
}

static void draw_both_ways(zl_fixed x0, zl_fixed y0, zl_fixed x1, zl_fixed y1, unsigned algo,
                           const char *const *rows, unsigned nrows, const char *what)
{
    zl_fixed a[3] = {x0, y0, 0}, b[3] = {x1, y1, 0};
    clear();
    draw_segment(a, b, algo);
    check_mask(rows, nrows, what);
    clear();
    draw_segment(b, a, algo);
    check_mask(rows, nrows, what);
}

static void test_hand_masks(void)
{
    /* (0.5,0.5) to (5.5,2.5): rows 2X/5 = 0, .4, .8, 1.2, 1.6, 2 */
    static const char *const shallow[] = {"##....", "..##..", "....##"};
    /* (0,0) to (2,1) pixel: column 1 is at 0.5: a tie, rounding down */
    static const char *const tie_x[] = {"##.", "..#"};
    /* the DDA rounds the same tie up */
    static const char *const tie_x_dda[] = {"#..", ".##"};
    /* y-major tie: (0,0) to (1,2): row 1 at x = 0.5, to the smaller column */
    static const char *const tie_y[] = {"#.", "#.", ".#"};
    static const char *const tie_y_dda[] = {"#.", ".#", ".#"};
    /* a diagonal is x-major and exact */
    static const char *const diag[] = {"...#", "..#.", ".#..", "#..."};
    /* a segment within one pixel is that pixel; endpoints in the pixel that
     * contains them: x = 3.0 exactly is pixel 3 */
    static const char *const single[] = {"....", "...#"};
    make_target();
    ctx.state.color.r = 200;
    draw_both_ways(S16(8), S16(8), S16(88), S16(40), ZL_LINE_BRESENHAM, shallow, 3, "shallow");
    draw_both_ways(S16(8), S16(8), S16(40), S16(24), ZL_LINE_BRESENHAM, tie_x, 2, "x tie");
    draw_both_ways(S16(8), S16(8), S16(40), S16(24), ZL_LINE_DDA, tie_x_dda, 2, "x tie dda");
    draw_both_ways(S16(8), S16(8), S16(24), S16(40), ZL_LINE_BRESENHAM, tie_y, 3, "y tie");
    draw_both_ways(S16(8), S16(8), S16(24), S16(40), ZL_LINE_DDA, tie_y_dda, 3, "y tie dda");
    draw_both_ways(S16(3), S16(63), S16(63), S16(3), ZL_LINE_BRESENHAM, diag, 4, "diagonal");
    draw_both_ways(S16(48), S16(16), S16(63), S16(31), ZL_LINE_BRESENHAM, single, 2, "single");
}

/* ---- the reference, written from the rule */

/* Snap a Q16.16 coordinate to 1/16 px (nearest, ties up), then the pixel. */
static int64_t pixel_of(zl_fixed v)
{
    int64_t s = ((int64_t)v + (1 << 11)) >> 12; /* arithmetic shift: floor */
    return s >> 4;
}

static int64_t floor_div(int64_t n, int64_t d) /* d > 0 */
{
    int64_t q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}

/* Nearest integer to n / d (d > 0), an exact half rounding down. */
static int64_t nearest_down(int64_t n, int64_t d)
{
    /* ceil(n/d - 1/2) = ceil((2n - d) / 2d) = -floor((d - 2n) / 2d) */
    return -floor_div(d - 2 * n, 2 * d);
}

static unsigned reference_mask(int64_t X0, int64_t Y0, int64_t X1, int64_t Y1, int dda, uint8_t *m)
{
    int64_t dx = X1 - X0, dy = Y1 - Y0, adx = dx < 0 ? -dx : dx, ady = dy < 0 ? -dy : dy, k, n = 0;
    memset(m, 0, W * H);
    if (adx >= ady) {
        int64_t lo = X0 < X1 ? X0 : X1, hi = X0 < X1 ? X1 : X0;
        int64_t sx = X0 < X1 ? X0 : X1, sy = X0 < X1 ? Y0 : Y1, ddy = X0 < X1 ? dy : -dy;
        int64_t s16 = adx ? floor_div(2 * ddy * 65536 + adx, 2 * adx) : 0;
        for (k = lo; k <= hi; k++) {
            int64_t y;
            if (adx == 0)
                y = Y0;
            else if (dda)
                y = sy + floor_div((k - sx) * s16 + 32768, 65536);
            else if (dx > 0)
                y = Y0 + nearest_down((k - X0) * dy, dx);
            else /* the same line, with a positive denominator */
                y = Y0 + nearest_down((k - X0) * -dy, -dx);
            if (k >= 0 && k < W && y >= 0 && y < H) {
                m[y * W + k] = 1;
                n++;
            }
        }
    } else {
        int64_t lo = Y0 < Y1 ? Y0 : Y1, hi = Y0 < Y1 ? Y1 : Y0;
        int64_t sx = Y0 < Y1 ? X0 : X1, sy = Y0 < Y1 ? Y0 : Y1, ddx = Y0 < Y1 ? dx : -dx;
        int64_t s16 = floor_div(2 * ddx * 65536 + ady, 2 * ady);
        for (k = lo; k <= hi; k++) {
            int64_t x;
            if (dda)
                x = sx + floor_div((k - sy) * s16 + 32768, 65536);
            else if (dy > 0)
                x = X0 + nearest_down((k - Y0) * dx, dy);
            else
                x = X0 + nearest_down((k - Y0) * -dx, -dy);
            if (x >= 0 && x < W && k >= 0 && k < H) {
                m[k * W + x] = 1;
                n++;
            }
        }
    }
    return (unsigned)n;
}

static void test_random_segments_match_the_rule_both_ways(void)
{
    int i, algo;
    unsigned total = 0;
    char msg[160];
    make_target();
    ctx.state.color.g = 255;
    for (i = 0; i < 3000; i++) {
        zl_fixed a[3], b[3];
        int32_t reach = (i % 5 == 0) ? 3000 : (i % 5 == 1 ? 30000 : 60);
        a[0] = rand_range(-reach * 16, (W + reach) * 16) * 4096 + rand_range(0, 4095);
        a[1] = rand_range(-reach * 16, (H + reach) * 16) * 4096 + rand_range(0, 4095);
        b[0] = rand_range(-reach * 16, (W + reach) * 16) * 4096 + rand_range(0, 4095);
        b[1] = rand_range(-reach * 16, (H + reach) * 16) * 4096 + rand_range(0, 4095);
        if (i % 7 == 0) /* axis-aligned and diagonal cases */
            b[1] = a[1];
        if (i % 11 == 0)
            b[0] = a[0];
        if (i % 13 == 0) {
            b[0] = a[0] + 40 * 65536;
            b[1] = a[1] + 40 * 65536;
        }
        a[2] = b[2] = 0;
        for (algo = 0; algo < 2; algo++) {
            int64_t X0 = pixel_of(a[0]), Y0 = pixel_of(a[1]), X1 = pixel_of(b[0]), Y1 = pixel_of(b[1]);
            unsigned n;
            n = reference_mask(X0, Y0, X1, Y1, algo == ZL_LINE_DDA, want);
            total += n;
            clear();
            draw_segment(a, b, (unsigned)algo);
            read_mask(got);
            snprintf(msg, sizeof msg, "segment %d algo %d (%ld,%ld)-(%ld,%ld)", i, algo, (long)X0, (long)Y0,
                     (long)X1, (long)Y1);
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, got, sizeof want, msg);
            clear();
            draw_segment(b, a, (unsigned)algo);
            read_mask(got);
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(want, got, sizeof want, msg);
        }
    }
    TEST_ASSERT_GREATER_THAN(5000, total); /* the segments did cross the target */
}

/* The DDA equals Bresenham except at exact halves for lines shorter than
 * 256 pixels: check with segments whose slope makes no halves (odd DX). */
static void test_dda_equals_bresenham_without_ties(void)
{
    int i;
    make_target();
    ctx.state.color.b = 255;
    for (i = 0; i < 500; i++) {
        zl_fixed a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
        int32_t dx = rand_range(0, 18) * 2 + 1, dy = rand_range(-dx, dx);
        a[0] = rand_range(0, 1) * 65536 + 32768;
        a[1] = rand_range(dx, H - dx > dx ? H - dx : dx) * 65536 + 32768;
        b[0] = a[0] + dx * 65536;
        b[1] = a[1] + dy * 65536;
        if (i & 1) { /* and the y-major case */
            zl_fixed t = a[0];
            a[0] = a[1];
            a[1] = t;
            t = b[0];
            b[0] = b[1];
            b[1] = t;
        }
        clear();
        draw_segment(a, b, ZL_LINE_BRESENHAM);
        read_mask(want);
        clear();
        draw_segment(a, b, ZL_LINE_DDA);
        read_mask(got);
        TEST_ASSERT_EQUAL_MEMORY(want, got, sizeof want);
    }
}

/* Depth along the line within +-1 of the exact linear value, and the depth
 * test against a plane. */
static void test_depth_along_the_line(void)
{
    int i;
    make_target();
    ctx.state.depth_test = 1;
    ctx.state.depth_write = 1;
    ctx.state.depth_func = ZL_LESS;
    ctx.state.color.r = 255;
    for (i = 0; i < 300; i++) {
        zl_fixed a[3], b[3];
        int64_t X0, Y0, X1, Y1, dm, k, z0, z1, exact_num;
        int xmajor;
        a[0] = rand_range(0, W * 16 - 1) * 4096;
        a[1] = rand_range(0, H * 16 - 1) * 4096;
        b[0] = rand_range(0, W * 16 - 1) * 4096;
        b[1] = rand_range(0, H * 16 - 1) * 4096;
        a[2] = rand_range(0, 65536);
        b[2] = rand_range(0, 65536);
        clear();
        draw_segment(a, b, ZL_LINE_BRESENHAM);
        X0 = pixel_of(a[0]);
        Y0 = pixel_of(a[1]);
        X1 = pixel_of(b[0]);
        Y1 = pixel_of(b[1]);
        xmajor = (X1 > X0 ? X1 - X0 : X0 - X1) >= (Y1 > Y0 ? Y1 - Y0 : Y0 - Y1);
        dm = xmajor ? (X1 > X0 ? X1 - X0 : X0 - X1) : (Y1 > Y0 ? Y1 - Y0 : Y0 - Y1);
        z0 = (int64_t)a[2] * 65535; /* stored scale times 65536 */
        z1 = (int64_t)b[2] * 65535;
        reference_mask(X0, Y0, X1, Y1, 0, want);
        for (k = 0; k < W * H; k++) {
            int64_t x = k % W, y = k / W, u, exact;
            if (!want[k])
                continue;
            u = xmajor ? (X1 > X0 ? x - X0 : X0 - x) : (Y1 > Y0 ? y - Y0 : Y0 - y);
            /* z0 + (z1 - z0) u / dm in stored steps, rounded */
            exact_num = dm == 0 ? z0 : z0 + (z1 - z0) * u / dm;
            exact = (exact_num + 32768) >> 16;
            TEST_ASSERT_INT_WITHIN(1, exact, depth[k]);
        }
    }
}

static void test_depth_test_against_a_plane(void)
{
    /* a full-screen triangle pair at depth 0.5, then a line from 0.1 to 0.9
     * with LESS: exactly the pixels nearer than 0.5 show */
    static const zl_fixed quad[] = {0, 0, 32768, S16(W * 16), 0, 32768, 0, S16(H * 16), 32768,
                                    S16(W * 16), S16(H * 16), 32768};
    static const uint16_t qidx[] = {0, 1, 2, 1, 3, 2};
    static const uint8_t grey[] = {1, 1, 1, 1, 1, 1};
    zl_mesh m = {quad, qidx, NULL, grey, 4, 2};
    zl_fixed a[3] = {S16(8), S16(8 + 16 * 5), 6554}, b[3] = {S16(8 + 16 * 30), S16(8 + 16 * 5), 58982};
    int x, shown = 0;
    make_target();
    ctx.state.depth_test = 1;
    ctx.state.depth_write = 1;
    ctx.state.depth_func = ZL_LESS;
    ctx.state.color.r = 255;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
    draw_segment(a, b, ZL_LINE_BRESENHAM);
    for (x = 0; x <= 30; x++) {
        /* exact depth along the line: 0.1 + 0.8 x / 30; x = 15 is a tie */
        int nearer = (6554 * 30 + (58982 - 6554) * x) < 32768 * 30;
        int on = color[(5 * W + x) * 3] == 255;
        if (x == 15)
            continue;
        shown += on;
        TEST_ASSERT_EQUAL_INT(nearer, on);
    }
    TEST_ASSERT_EQUAL_INT(15, shown);
}

/* Strips and loops: the union of their segments. */
static void test_strip_and_loop_cover_their_segments(void)
{
    static const zl_fixed pts[] = {S16(24), S16(24), 0, S16(300), S16(60), 0, S16(120), S16(400), 0,
                                   S16(500), S16(300), 0};
    static const uint16_t idx[] = {0, 1, 2, 3};
    uint8_t acc[W * H];
    zl_lines l;
    int prim, k, n;
    make_target();
    ctx.state.color.g = 255;
    for (prim = ZL_PRIM_LINE_STRIP; prim <= ZL_PRIM_LINE_LOOP; prim++) {
        n = prim == ZL_PRIM_LINE_LOOP ? 4 : 3;
        memset(acc, 0, sizeof acc);
        for (k = 0; k < n; k++) {
            unsigned i2;
            const zl_fixed *p = &pts[k * 3], *q = &pts[((k + 1) % 4) * 3];
            reference_mask(pixel_of(p[0]), pixel_of(p[1]), pixel_of(q[0]), pixel_of(q[1]), 0, want);
            for (i2 = 0; i2 < W * H; i2++)
                acc[i2] |= want[i2];
        }
        memset(&l, 0, sizeof l);
        l.positions = pts;
        l.indices = idx;
        l.vertex_count = 4;
        l.count = 4;
        l.prim = (uint8_t)prim;
        clear();
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, NULL));
        read_mask(got);
        TEST_ASSERT_EQUAL_MEMORY(acc, got, sizeof acc);
        TEST_ASSERT_EQUAL_UINT32((uint32_t)n, zl_lines_primitives(&l));
    }
}

/* Points: the N x N pixels with centres in (x - N/2, x + N/2]. */
static void test_points(void)
{
    static const char *const p1[] = {"", "", "...#"};
    /* size 2 at (3.0, 2.0): centres 2.5 and 3.5 in (2, 4], rows 1.5, 2.5 in (1, 3] */
    static const char *const p2[] = {"", "..##", "..##"};
    /* size 3 at (3.5, 2.5): columns 2..4, rows 1..3 */
    static const char *const p3[] = {"", "..###", "..###", "..###"};
    /* size 2 at (3.03, 2.97), snapped to (3.0625, 3.0): columns with centres
     * in (2.0625, 4.0625] = 2, 3; rows with centres in (2, 4] = 2, 3 */
    static const char *const p4[] = {"", "", "..##", "..##"};
    zl_fixed pos[3];
    zl_lines l;
    make_target();
    ctx.state.color.b = 255;
    memset(&l, 0, sizeof l);
    l.positions = pos;
    l.vertex_count = 1;
    l.count = 1;
    l.prim = ZL_PRIM_POINTS;
    pos[2] = 0;

    pos[0] = S16(48 + 5);
    pos[1] = S16(32 + 15);
    ctx.style.point_size = 1;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, NULL));
    check_mask(p1, 3, "size 1");

    pos[0] = S16(48);
    pos[1] = S16(32);
    ctx.style.point_size = 2;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, NULL));
    check_mask(p2, 3, "size 2 on pixel corners");

    pos[0] = S16(56);
    pos[1] = S16(40);
    ctx.style.point_size = 3;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, NULL));
    check_mask(p3, 4, "size 3 on a centre");

    pos[0] = 3 * 65536 + 2000; /* 3.03 -> snaps to 3 + 1/16 */
    pos[1] = 3 * 65536 - 2000; /* 2.97 -> 3 - 1/16 */
    ctx.style.point_size = 2;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, NULL));
    check_mask(p4, 4, "size 2 off centre");

    /* a big point at the corner is clamped, a point behind the far plane is not drawn */
    pos[0] = 0;
    pos[1] = 0;
    ctx.style.point_size = 64;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, NULL));
    TEST_ASSERT_EQUAL_UINT32(32 * 30, read_mask(got));
    pos[2] = 65536 + 100;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&ctx, &l, NULL));
    TEST_ASSERT_EQUAL_UINT32(0, read_mask(got));
}

/* The weights an antialiased segment a-b gives each pixel (0 off it):
 * round(255 f) below the ideal line and 255 minus that above, f the exact
 * fraction of the minor coordinate (reference in exact integers). */
static void aa_expected(const zl_fixed *a, const zl_fixed *b, uint8_t *expect)
{
    int64_t X0 = pixel_of(a[0]), Y0 = pixel_of(a[1]), X1 = pixel_of(b[0]), Y1 = pixel_of(b[1]);
    int64_t dx = X1 - X0, dy = Y1 - Y0, k;
    int xmajor = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy), x;
    memset(expect, 0, W * H);
    for (k = xmajor ? (X0 < X1 ? X0 : X1) : (Y0 < Y1 ? Y0 : Y1); k <= (xmajor ? (X0 < X1 ? X1 : X0) : (Y0 < Y1 ? Y1 : Y0)); k++) {
        /* n = base + num / den exactly, den > 0 */
        int64_t num = xmajor ? (k - X0) * dy : (k - Y0) * dx, den = xmajor ? dx : dy, fl, f, wl;
        int64_t base = xmajor ? Y0 : X0;
        if (den < 0) {
            num = -num;
            den = -den;
        }
        if (den == 0) {
            num = 0;
            den = 1;
        }
        fl = floor_div(num, den);
        f = num - fl * den;             /* fraction f / den */
        wl = (f * 255 + den / 2) / den; /* weight of floor + 1 */
        for (x = 0; x < 2; x++) {
            int64_t m = base + fl + x, w = x ? wl : 255 - wl;
            int64_t px = xmajor ? k : m, py = xmajor ? m : k;
            if (px >= 0 && px < W && py >= 0 && py < H)
                expect[py * W + px] = (uint8_t)w;
        }
    }
}

static void random_segment(int i, zl_fixed *a, zl_fixed *b)
{
    int32_t reach = i % 3 == 0 ? 400 : 30;
    a[0] = rand_range(-reach * 16, (W + reach) * 16) * 4096;
    a[1] = rand_range(-reach * 16, (H + reach) * 16) * 4096;
    b[0] = rand_range(-reach * 16, (W + reach) * 16) * 4096;
    b[1] = rand_range(-reach * 16, (H + reach) * 16) * 4096;
}

/* Antialiased lines: white on black, so each pixel holds its weight
 * (aa_expected). */
static void test_antialiased_lines_against_the_weights(void)
{
    static uint8_t expect[W * H];
    int i;
    make_target();
    ctx.state.color.r = 255;
    ctx.state.color.g = 255;
    ctx.state.color.b = 255;
    ctx.style.line_aa = 1;
    for (i = 0; i < 1500; i++) {
        zl_fixed a[3] = {0, 0, 0}, b[3] = {0, 0, 0};
        int x, y;
        random_segment(i, a, b);
        aa_expected(a, b, expect);
        clear();
        draw_segment(a, b, ZL_LINE_BRESENHAM);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++)
                TEST_ASSERT_EQUAL_UINT8(expect[y * W + x], color[(y * W + x) * 3 + 1]);
        clear();
        draw_segment(b, a, ZL_LINE_BRESENHAM);
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++)
                TEST_ASSERT_EQUAL_UINT8(expect[y * W + x], color[(y * W + x) * 3 + 1]);
    }
    ctx.style.line_aa = 0;
}

/* A channel of the coverage blend (zline.h, LINES): old and new 8-bit
 * values, weight w, by a plain division. */
static unsigned aa_mix(unsigned old, unsigned c, unsigned w)
{
    return (old * (255u - w) + c * w + 127u) / 255u;
}

/* Antialiased lines into RGB565 (the loop of that format): a coloured line
 * over a coloured background (random colours), each pixel the background's 8-bit widening
 * blended by its weight (aa_expected), then packed; depth tests ALWAYS,
 * LESS passing everywhere, and LESS failing everywhere (nothing drawn). */
static void test_antialiased_lines_rgb565(void)
{
    static uint16_t c565[W * H];
    static uint8_t expect[W * H];
    unsigned bg[3], fg[3];
    zl_rgb bgc;
    zl_target t;
    int i;
    memset(&t, 0, sizeof t);
    t.color = c565;
    t.color_stride = W * 2;
    t.depth = depth;
    t.depth_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB565;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
    ctx.style.line_aa = 1;
    for (i = 0; i < 1500; i++) {
        zl_fixed a[3] = {0, 0, ZL_FX_HALF}, b[3] = {0, 0, ZL_FX_HALF};
        int mode = i % 3, k;
        for (k = 0; k < 3; k++) { /* random colours: every rounding case over the run */
            bg[k] = (unsigned)rand_range(0, 255);
            fg[k] = (unsigned)rand_range(0, 255);
        }
        bgc.r = (uint8_t)bg[0];
        bgc.g = (uint8_t)bg[1];
        bgc.b = (uint8_t)bg[2];
        ctx.state.color.r = (uint8_t)fg[0];
        ctx.state.color.g = (uint8_t)fg[1];
        ctx.state.color.b = (uint8_t)fg[2];
        random_segment(i, a, b);
        aa_expected(a, b, expect);
        ctx.state.depth_test = (uint8_t)(mode != 0);
        ctx.state.depth_func = ZL_LESS;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bgc, mode == 2 ? 0 : 65535));
        draw_segment(i & 1 ? a : b, i & 1 ? b : a, ZL_LINE_BRESENHAM);
        for (k = 0; k < W * H; k++) {
            uint16_t old = c565[k];
            /* the clear colour as stored (5, 6, 5 bits), widened back by bit replication */
            unsigned w = mode == 2 ? 0u : expect[k], o[3], r5 = bg[0] >> 3, g6 = bg[1] >> 2, b5 = bg[2] >> 3;
            uint16_t want565;
            o[0] = aa_mix((r5 << 3) | (r5 >> 2), fg[0], w);
            o[1] = aa_mix((g6 << 2) | (g6 >> 4), fg[1], w);
            o[2] = aa_mix((b5 << 3) | (b5 >> 2), fg[2], w);
            want565 = (uint16_t)(((o[0] >> 3) << 11) | ((o[1] >> 2) << 5) | (o[2] >> 3));
            TEST_ASSERT_EQUAL_HEX16(want565, old);
        }
    }
    ctx.style.line_aa = 0;
    make_target();
}

/* The RGB565 loop (LESS with writes, all channels) covers the same pixels
 * with the same depths as the general one. */
static void test_rgb565_loop_matches_the_rule(void)
{
    static uint16_t c565[W * H], z565[W * H];
    zl_target t;
    zl_context c;
    zl_rgb black = {0, 0, 0};
    int i, k;
    make_target();
    memset(&t, 0, sizeof t);
    t.color = c565;
    t.color_stride = W * 2;
    t.depth = z565;
    t.depth_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB565;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&c, &t));
    ctx.state.depth_test = 1;
    ctx.state.depth_write = 1;
    ctx.state.color.r = 255;
    c.state.color.r = 255;
    for (i = 0; i < 500; i++) {
        zl_fixed a[3], b[3];
        zl_lines l;
        zl_fixed pos[6];
        a[0] = rand_range(-200 * 16, (W + 200) * 16) * 4096;
        a[1] = rand_range(-200 * 16, (H + 200) * 16) * 4096;
        b[0] = rand_range(-200 * 16, (W + 200) * 16) * 4096;
        b[1] = rand_range(-200 * 16, (H + 200) * 16) * 4096;
        a[2] = rand_range(0, 65535);
        b[2] = rand_range(0, 65535);
        clear();
        draw_segment(a, b, ZL_LINE_BRESENHAM); /* RGB888: the general loop */
        memcpy(pos, a, sizeof a);
        memcpy(pos + 3, b, sizeof b);
        memset(&l, 0, sizeof l);
        l.positions = pos;
        l.vertex_count = 2;
        l.count = 2;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&c, black, 65535));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_lines(&c, &l, NULL));
        /* the pixels against the rule's own reference too (the RGB565 runs) */
        reference_mask(pixel_of(a[0]), pixel_of(a[1]), pixel_of(b[0]), pixel_of(b[1]), 0, want);
        for (k = 0; k < W * H; k++) {
            TEST_ASSERT_EQUAL_UINT16(depth[k], z565[k]);
            TEST_ASSERT_EQUAL_INT(color[k * 3] != 0, c565[k] != 0);
            TEST_ASSERT_EQUAL_INT(want[k], c565[k] != 0);
        }
    }
}

static void test_invalid_arguments(void)
{
    zl_fixed pos[6] = {0};
    uint16_t bad[2] = {0, 2};
    zl_lines l;
    make_target();
    memset(&l, 0, sizeof l);
    l.positions = pos;
    l.vertex_count = 2;
    l.count = 2;
    l.prim = 4;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_lines(&ctx, &l, NULL));
    l.prim = ZL_PRIM_LINES;
    l.indices = bad;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_lines(&ctx, &l, NULL));
    l.indices = NULL;
    ctx.style.point_size = 0;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_lines(&ctx, &l, NULL));
    ctx.style.point_size = 1;
    ctx.style.polygon_front = 3;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_lines(&ctx, &l, NULL));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_lines(&ctx, NULL, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_hand_masks);
    RUN_TEST(test_random_segments_match_the_rule_both_ways);
    RUN_TEST(test_dda_equals_bresenham_without_ties);
    RUN_TEST(test_depth_along_the_line);
    RUN_TEST(test_depth_test_against_a_plane);
    RUN_TEST(test_strip_and_loop_cover_their_segments);
    RUN_TEST(test_points);
    RUN_TEST(test_antialiased_lines_against_the_weights);
    RUN_TEST(test_antialiased_lines_rgb565);
    RUN_TEST(test_rgb565_loop_matches_the_rule);
    RUN_TEST(test_invalid_arguments);
    return UNITY_END();
}
