/* SPDX-License-Identifier: MIT */
/*
 * Texture mapping: a checkerboard floor receding towards the horizon,
 * against a reference computed here (in double) from the camera: for every
 * pixel centre the point of the floor plane seen through it and its texture
 * coordinate. Each texel has its own colour, so a pixel tells exactly which
 * texel was sampled. Perspective-correct mapping must sample the texel of
 * the reference within the stated error (zline.h, TEXTURES) plus what the
 * 1/16 pixel snapping can move; affine mapping must be visibly different;
 * exact-every-N within its stated bound. Also wrap and clamp, by hand.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 64, H = 48, TS = 32 };

/* Own fabs and floor: no libm needed on any target. */
static double abs_d(double x)
{
    return x < 0 ? -x : x;
}

static double floor_d(double x)
{
    double t = (double)(long long)x;
    return t > x ? t - 1 : t;
}

static uint16_t color[W * H];
static uint16_t depth[W * H];
static uint16_t texels[TS * TS];
static zl_context ctx;

/* Texel (i, j): red = i, green = j (5 and 6 bit fields). */
static void make_texture(void)
{
    int i, j;
    for (j = 0; j < TS; j++)
        for (i = 0; i < TS; i++)
            texels[j * TS + i] = (uint16_t)((i << 11) | (j << 5) | 31);
}

static void make_target(void)
{
    zl_target t;
    memset(&t, 0, sizeof t);
    t.color = color;
    t.color_stride = W * 2;
    t.depth = depth;
    t.depth_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB565;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
}

static void clear(void)
{
    zl_rgb black = {0, 0, 0};
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 65535));
}

/* The floor: y = 0, x in -8..8, z in -1..-41; s = (x + 8) / 32, t = 3 (-1 - z) / 40
 * (half the texture across, 3 repeats along). */
static const zl_fixed floor_pos[] = {-ZL_FX_INT(8), 0, -ZL_FX_INT(1),  ZL_FX_INT(8), 0, -ZL_FX_INT(1),
                                     ZL_FX_INT(8),  0, -ZL_FX_INT(41), -ZL_FX_INT(8), 0, -ZL_FX_INT(41)};
static const zl_fixed floor_uv[] = {0, 0, ZL_FX_HALF, 0, ZL_FX_HALF, ZL_FX_INT(3), 0, ZL_FX_INT(3)};
static const uint16_t floor_idx[] = {0, 1, 2, 0, 2, 3};

static zl_mat4 mvp;

/* Looking right (target x 4) the floor's corner (-8, 0, -1) is behind the
 * eye, so both triangles cross the eye plane; looking ahead (x 0) every
 * corner is in front. */
static void camera_to(zl_fixed target_x)
{
    zl_mat4 proj, view;
    zl_vec3 eye = {0, ZL_FX_ONE, 0}, target = {target_x, ZL_FX_ONE / 2, -ZL_FX_INT(10)}, up = {ZL_FX_ONE / 8, ZL_FX_ONE, 0};
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(70)), ZL_FX_INT(W) / H,
                                                     ZL_FX_ONE / 4, ZL_FX_INT(100)));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
    zl_mat4_mul(&mvp, &proj, &view);
}

static void camera(void)
{
    camera_to(ZL_FX_INT(4));
}

/* Reference texture coordinate in texels at window position (px, py), or 0
 * when the ray misses the floor: solve clip.x = ndcx clip.w, clip.y = ndcy
 * clip.w for the floor point (x, 0, z). */
static int reference(double px, double py, double *u, double *v)
{
    double m[16], nx = px / W * 2 - 1, ny = 1 - py / H * 2;
    double a11, a12, b1, a21, a22, b2, det, x, z;
    int k;
    for (k = 0; k < 16; k++)
        m[k] = mvp.m[k] / 65536.0;
    /* row r of M times (x, 0, z, 1) = m[r*4] x + m[r*4+2] z + m[r*4+3] */
    a11 = m[0] - nx * m[12];
    a12 = m[2] - nx * m[14];
    b1 = -(m[3] - nx * m[15]);
    a21 = m[4] - ny * m[12];
    a22 = m[6] - ny * m[14];
    b2 = -(m[7] - ny * m[15]);
    det = a11 * a22 - a12 * a21;
    if (det == 0)
        return 0;
    x = (b1 * a22 - a12 * b2) / det;
    z = (a11 * b2 - b1 * a21) / det;
    if (x < -8 || x > 8 || z > -1 || z < -41)
        return 0;
    *u = (x + 8) / 32 * TS;
    *v = (-1 - z) * 3 / 40 * TS;
    return 1;
}

typedef struct {
    int pixels, exact, within, checked, off1;
    double worst; /* largest distance (texels) of a sample outside the reference texel */
} stats;

/* Distance from coordinate c to the texel with wrapped index i (0 inside it). */
static double texel_distance(double c, int i)
{
    double base = floor_d(c / TS) * TS, best = 1e9;
    int k;
    for (k = -1; k <= 1; k++) {
        double lo = base + k * TS + i, d = c < lo ? lo - c : (c > lo + 1 ? c - lo - 1 : 0);
        if (d < best)
            best = d;
    }
    return best;
}

static void compare(stats *s, double extra)
{
    int x, y;
    memset(s, 0, sizeof *s);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            double u, v, ux, vx, uy, vy, du, dv, eu, ev, tu, tv;
            uint16_t p = color[y * W + x];
            int iu = p >> 11, iv = (p >> 5) & 31;
            if (!reference(x + 0.5, y + 0.5, &u, &v))
                continue;
            if (depth[y * W + x] == 65535)
                continue; /* a pixel whose centre the snapped floor does not cover */
            s->pixels++;
            if (!reference(x + 1.5, y + 0.5, &ux, &vx) || !reference(x + 0.5, y + 1.5, &uy, &vy))
                continue;
            du = abs_d(ux - u) + abs_d(uy - u);
            dv = abs_d(vx - v) + abs_d(vy - v);
            if (du > 0.5 || dv > 0.5)
                continue; /* minified: the texel changes within the pixel */
            s->checked++;
            tu = texel_distance(u, iu);
            tv = texel_distance(v, iv);
            s->exact += tu == 0 && tv == 0;
            /* stated error of the interpolation: |c| / 2^16 + 1/128 texel;
             * plus what the geometry moves: vertices snapped to 1/16 pixel
             * (1/16 pixel of the local gradient) and the Q16.16 transform
             * and 1/w rounding of far vertices (1/32 texel here) */
            eu = u / 65536 + 1.0 / 128 + 1.0 / 32 + du / 16 + extra * du;
            ev = v / 65536 + 1.0 / 128 + 1.0 / 32 + dv / 16 + extra * dv;
            if (tu <= eu && tv <= ev)
                s->within++;
            if (tu <= 1 && tv <= 1)
                s->off1++;
            if (tu > s->worst)
                s->worst = tu;
            if (tv > s->worst)
                s->worst = tv;
        }
}

static void draw_floor(unsigned mapping, unsigned every)
{
    static zl_texture tex;
    zl_mesh m = {floor_pos, floor_idx, NULL, NULL, 4, 2};
    tex.texels = texels;
    tex.width = TS;
    tex.height = TS;
    tex.stride = TS;
    tex.wrap_s = ZL_WRAP_REPEAT;
    tex.wrap_t = ZL_WRAP_REPEAT;
    ctx.style.texture = &tex;
    ctx.style.texcoords = floor_uv;
    ctx.style.tex_mapping = (uint8_t)mapping;
    ctx.style.tex_every = (uint8_t)every;
    clear();
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, &mvp));
}

static void test_floor_perspective_matches_reference(void)
{
    stats s;
    char msg[200];
    make_texture();
    make_target();
    camera();
    draw_floor(ZL_TEX_PERSPECTIVE, 0);
    compare(&s, 0);
    snprintf(msg, sizeof msg, "perspective: %d pixels, %d checked, %d exact, %d within, worst %.4f texel", s.pixels,
             s.checked, s.exact, s.within, s.worst);
    TEST_MESSAGE(msg);
    TEST_ASSERT_GREATER_THAN(W * H / 5, s.checked);
    TEST_ASSERT_EQUAL_INT_MESSAGE(s.checked, s.within, msg);
    TEST_ASSERT_GREATER_OR_EQUAL_MESSAGE(s.checked * 95 / 100, s.exact, msg);
}

/* Affine mapping where it is defined: every vertex in front of the eye (a
 * triangle across the eye plane is mapped perspective-correctly, zline.h
 * Clipping; test_clip_attrs checks that). */
static void test_floor_affine_is_visibly_different(void)
{
    stats s;
    char msg[200];
    make_texture();
    make_target();
    camera_to(0);
    draw_floor(ZL_TEX_AFFINE, 0);
    compare(&s, 0);
    snprintf(msg, sizeof msg, "affine: %d checked, %d exact, %d within one texel, worst %.2f texels", s.checked,
             s.exact, s.off1, s.worst);
    TEST_MESSAGE(msg);
    /* most pixels sample a wrong texel, many of them far off */
    TEST_ASSERT_LESS_THAN_MESSAGE(s.checked / 2, s.exact, msg);
    TEST_ASSERT_GREATER_THAN_MESSAGE(4.0, s.worst, msg);
}

/* Exact every 16 pixels: within the stated bound plus N^2/8 times the
 * coordinate's second derivative along the row (measured here) plus N/256
 * texel (the truncated linear step). */
static void test_floor_exact_every_16(void)
{
    stats s;
    char msg[200];
    int x, y;
    double d2 = 0;
    make_texture();
    make_target();
    camera();
    for (y = 0; y < H; y++)
        for (x = 1; x + 1 < W; x++) {
            double a, b, c, e, f, g;
            if (reference(x - 0.5, y + 0.5, &a, &e) && reference(x + 0.5, y + 0.5, &b, &f) &&
                reference(x + 1.5, y + 0.5, &c, &g)) {
                double s2 = abs_d(a - 2 * b + c) > abs_d(e - 2 * f + g) ? abs_d(a - 2 * b + c) : abs_d(e - 2 * f + g);
                if (abs_d(c - a) < 1 && abs_d(g - e) < 1 && s2 > d2)
                    d2 = s2;
            }
        }
    draw_floor(ZL_TEX_PERSPECTIVE, 16);
    compare(&s, 0);
    snprintf(msg, sizeof msg, "every 16: %d checked, %d exact, worst %.4f texel, bound adds %.4f", s.checked,
             s.exact, s.worst, 16.0 * 16 / 8 * d2);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE_MESSAGE(s.worst <= 16.0 * 16 / 8 * d2 + 16.0 / 256 + 1.0 / 32, msg);
    TEST_ASSERT_GREATER_OR_EQUAL_MESSAGE(s.checked * 9 / 10, s.exact, msg);
}

/* Wrap and clamp by hand, in pixel space (no perspective: both mappings
 * agree): an 8 x 8 quad showing s, t from -0.5 to 1.5 of a 4 x 4 texture. */
static void test_wrap_and_clamp(void)
{
    static const zl_fixed quad[] = {0, 0, 0, ZL_FX_INT(8), 0, 0, ZL_FX_INT(8), ZL_FX_INT(8), 0, 0, ZL_FX_INT(8), 0};
    static const zl_fixed uv[] = {-ZL_FX_HALF, -ZL_FX_HALF, ZL_FX_INT(1) + ZL_FX_HALF, -ZL_FX_HALF,
                                  ZL_FX_INT(1) + ZL_FX_HALF, ZL_FX_INT(1) + ZL_FX_HALF, -ZL_FX_HALF,
                                  ZL_FX_INT(1) + ZL_FX_HALF};
    static const uint16_t idx[] = {0, 1, 2, 0, 2, 3};
    zl_mesh m = {quad, idx, NULL, NULL, 4, 2};
    zl_texture tex;
    int x, y, wrap, mapping;
    make_texture();
    make_target();
    memset(&tex, 0, sizeof tex);
    tex.texels = texels;
    tex.width = 4;
    tex.height = 4;
    tex.stride = TS;
    ctx.style.texture = &tex;
    ctx.style.texcoords = uv;
    for (mapping = 0; mapping < 2; mapping++)
        for (wrap = 0; wrap < 2; wrap++) {
            tex.wrap_s = (uint8_t)wrap;
            tex.wrap_t = (uint8_t)wrap;
            ctx.style.tex_mapping = (uint8_t)mapping;
            clear();
            TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
            for (y = 0; y < 8; y++)
                for (x = 0; x < 8; x++) {
                    /* pixel centre x + 0.5 maps to s = -0.5 + (x + 0.5) / 4,
                     * texel floor_d(4 s) = x - 2 (exactly, no tie) */
                    int i = x - 2, j = y - 2;
                    uint16_t p = color[y * W + x];
                    if (wrap == ZL_WRAP_REPEAT) {
                        i &= 3;
                        j &= 3;
                    } else {
                        i = i < 0 ? 0 : (i > 3 ? 3 : i);
                        j = j < 0 ? 0 : (j > 3 ? 3 : j);
                    }
                    TEST_ASSERT_EQUAL_HEX16((uint16_t)((i << 11) | (j << 5) | 31), p);
                }
        }
}

/* Repeat on power-of-two textures over long spans, by hand: the whole
 * target, texel coordinates (in texels) cu = -37 + 3/4 x and
 * cv = 5 - 5/4 y, so the steps are fractions, both signs, and the texel
 * a pixel centre shows is floor(c) modulo the size, never at a tie (the
 * centre's fraction is 1/8, 3/8, 5/8 or 7/8). A 16 x 8 texture in rows of
 * 32 texels and a 32 x 32 one, affine and perspective mapping (exact,
 * and exact every 8 and 16 pixels: in pixel space w is 1, and the steps,
 * whole 1/256 texels, are exact), depth tests LESS and LEQUAL. */
static void test_repeat_pow2_long_spans(void)
{
    static const zl_fixed quad[] = {0, 0, 0, ZL_FX_INT(W), 0, 0, ZL_FX_INT(W), ZL_FX_INT(H), 0, 0, ZL_FX_INT(H), 0};
    static const uint16_t idx[] = {0, 1, 2, 0, 2, 3};
    static const uint16_t sizes[2][2] = {{16, 8}, {32, 32}};
    zl_fixed uv[8];
    zl_mesh m = {quad, idx, NULL, NULL, 4, 2};
    zl_texture tex;
    int x, y, k, mapping, func;
    make_texture();
    make_target();
    for (k = 0; k < 2; k++) {
        int tw = sizes[k][0], th = sizes[k][1];
        memset(&tex, 0, sizeof tex);
        tex.texels = texels;
        tex.width = (uint16_t)tw;
        tex.height = (uint16_t)th;
        tex.stride = TS;
        /* s = cu / tw, t = cv / th at the corners, exact in Q16 */
        uv[0] = uv[6] = (zl_fixed)(-37 * 65536 / tw);
        uv[2] = uv[4] = (zl_fixed)((-37 + 3 * W / 4) * 65536 / tw);
        uv[1] = uv[3] = (zl_fixed)(5 * 65536 / th);
        uv[5] = uv[7] = (zl_fixed)((5 - 5 * H / 4) * 65536 / th);
        ctx.style.texture = &tex;
        ctx.style.texcoords = uv;
        for (mapping = 0; mapping < 4; mapping++) /* affine, perspective exact, every 8, every 16 */
            for (func = 0; func < 2; func++) {
                ctx.style.tex_mapping = (uint8_t)(mapping != 0);
                ctx.style.tex_every = (uint8_t)(mapping < 2 ? 0 : 4 << mapping);
                ctx.state.depth_func = (uint8_t)(func ? ZL_LEQUAL : ZL_LESS);
                clear();
                TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
                for (y = 0; y < H; y++)
                    for (x = 0; x < W; x++) {
                        /* 8 c at the centre: -296 + 6 x + 3 and 40 - 10 y - 5 */
                        int i = (int)floor_d((-296 + 6 * x + 3) / 8.0) & (tw - 1);
                        int j = (int)floor_d((40 - 10 * y - 5) / 8.0) & (th - 1);
                        TEST_ASSERT_EQUAL_HEX16((uint16_t)((i << 11) | (j << 5) | 31), color[y * W + x]);
                    }
            }
    }
    ctx.state.depth_func = ZL_LESS;
    ctx.style.tex_every = 0;
}

static void test_lighting_modulates_and_invalid_textures(void)
{
    zl_texture tex;
    zl_fixed uv[6] = {0};
    make_target();
    memset(&tex, 0, sizeof tex);
    tex.texels = texels;
    tex.width = 0; /* any size 1 .. 4096 is valid (zline.h, TEXEL FORMATS AND SIZES) */
    tex.height = 4;
    tex.stride = 4;
    ctx.style.texture = &tex;
    ctx.style.texcoords = uv;
    {
        zl_fixed p[9] = {0};
        uint16_t i3[3] = {0, 1, 2};
        zl_mesh m = {p, i3, NULL, NULL, 3, 1};
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_draw_mesh(&ctx, &m, NULL));
        tex.width = 4;
        tex.stride = 2;
        TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_draw_mesh(&ctx, &m, NULL));
        tex.stride = 4;
        ctx.style.texcoords = NULL;
        TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_draw_mesh(&ctx, &m, NULL));
        ctx.style.texcoords = uv;
        ctx.style.tex_every = 3;
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_draw_mesh(&ctx, &m, NULL));
        ctx.style.tex_every = 8;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
    }
}

/* The RGB565 fast loop and the general loop (RGB888 here) sample the same
 * texels: random textured triangles in both formats, the RGB888 image
 * converted to RGB565 must equal the other bit for bit. */
static void test_fast_and_general_loops_agree(void)
{
    static uint8_t c888[W * H * 3];
    static uint16_t d2[W * H];
    static zl_fixed pos[9], uv[6];
    static const uint16_t idx[3] = {0, 1, 2};
    zl_mesh m = {pos, idx, NULL, NULL, 3, 1};
    zl_texture tex;
    zl_target t2;
    zl_context c2;
    zl_rgb black = {0, 0, 0};
    uint32_t rng = 7;
    int n, k, i;
    make_texture();
    make_target();
    camera();
    memset(&t2, 0, sizeof t2);
    t2.color = c888;
    t2.color_stride = W * 3;
    t2.depth = d2;
    t2.depth_stride = W * 2;
    t2.width = W;
    t2.height = H;
    t2.format = ZL_FORMAT_RGB888;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&c2, &t2));
    memset(&tex, 0, sizeof tex);
    tex.texels = texels;
    tex.width = TS;
    tex.height = TS / 2;
    tex.stride = TS;
    for (n = 0; n < 200; n++) {
        for (k = 0; k < 9; k++) {
            rng ^= rng << 13;
            rng ^= rng >> 17;
            rng ^= rng << 5;
            pos[k] = (zl_fixed)(rng % (6u * 65536u)) - 3 * 65536;
        }
        for (k = 0; k < 6; k++) {
            rng ^= rng << 13;
            rng ^= rng >> 17;
            rng ^= rng << 5;
            uv[k] = (zl_fixed)(rng % (8u * 65536u)) - 4 * 65536;
        }
        tex.wrap_s = (uint8_t)(n & 1);
        tex.wrap_t = (uint8_t)((n >> 1) & 1);
        ctx.style.texture = &tex;
        ctx.style.texcoords = uv;
        ctx.style.tex_mapping = (uint8_t)(n % 3 != 0);
        ctx.style.tex_every = (uint8_t)(n % 3 == 2 ? 8 : 0);
        c2.style = ctx.style;
        clear();
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&c2, black, 65535));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, &mvp));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&c2, &m, &mvp));
        for (i = 0; i < W * H; i++) {
            uint16_t from888 = (uint16_t)(((c888[i * 3] >> 3) << 11) | ((c888[i * 3 + 1] >> 2) << 5) | (c888[i * 3 + 2] >> 3));
            TEST_ASSERT_EQUAL_HEX16(from888, color[i]);
            TEST_ASSERT_EQUAL_UINT16(d2[i], depth[i]);
        }
    }
}

/* Perspective-correct Gouraud: red goes 0 .. 255 from the near edge of the
 * floor to the far one (linear in z); the reference is the floor point seen
 * through each pixel centre. Screen-linear Gouraud must be far off. */
static void test_perspective_gouraud(void)
{
    static const uint8_t vcol[] = {0, 0, 0, 0, 0, 0, 255, 0, 0, 255, 0, 0};
    static uint8_t c888[W * H * 3];
    static uint16_t d2[W * H];
    zl_mesh m = {floor_pos, floor_idx, vcol, NULL, 4, 2};
    zl_target t2;
    zl_context c2;
    zl_rgb black = {0, 0, 0};
    int pass, x, y, checked = 0, worst[2] = {0, 0};
    camera();
    memset(&t2, 0, sizeof t2);
    t2.color = c888;
    t2.color_stride = W * 3;
    t2.depth = d2;
    t2.depth_stride = W * 2;
    t2.width = W;
    t2.height = H;
    t2.format = ZL_FORMAT_RGB888;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&c2, &t2));
    c2.state.shading = ZL_SHADE_GOURAUD;
    for (pass = 0; pass < 2; pass++) {
        c2.style.persp_gouraud = (uint8_t)(pass == 0);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&c2, black, 65535));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&c2, &m, &mvp));
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                double u, v, ref;
                int e;
                if (d2[y * W + x] == 65535 || !reference(x + 0.5, y + 0.5, &u, &v))
                    continue;
                ref = v / (3.0 * TS) * 255.0; /* v = 3 (-1 - z) / 40 texels of TS */
                e = (int)(c888[(y * W + x) * 3] - ref + (c888[(y * W + x) * 3] >= ref ? 0.5 : -0.5));
                e = e < 0 ? -e : e;
                if (e > worst[pass])
                    worst[pass] = e;
                checked += pass == 0;
            }
    }
    {
        char msg[120];
        snprintf(msg, sizeof msg, "Gouraud: perspective worst %d, screen-linear worst %d (of 255), %d pixels", worst[0],
                 worst[1], checked);
        TEST_MESSAGE(msg);
        TEST_ASSERT_GREATER_THAN(W * H / 4, checked);
        TEST_ASSERT_LESS_OR_EQUAL_MESSAGE(2, worst[0], msg);
        TEST_ASSERT_GREATER_THAN_MESSAGE(20, worst[1], msg);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_floor_perspective_matches_reference);
    RUN_TEST(test_floor_affine_is_visibly_different);
    RUN_TEST(test_floor_exact_every_16);
    RUN_TEST(test_wrap_and_clamp);
    RUN_TEST(test_repeat_pow2_long_spans);
    RUN_TEST(test_fast_and_general_loops_agree);
    RUN_TEST(test_perspective_gouraud);
    RUN_TEST(test_lighting_modulates_and_invalid_textures);
    return UNITY_END();
}
