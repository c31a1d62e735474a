/* SPDX-License-Identifier: MIT */
/*
 * Instructions per pixel of the issue #5 loops on Cortex-M (QEMU mps2,
 * -icount shift=6, counted with TIMER0 exactly as bench.c does): frame mode,
 * 320x240 RGB565 with a 16-bit depth buffer, depth LESS with writes, every
 * fragment passing (each pixel is written once):
 *   line          239 Bresenham segments of 320 pixels (x-major, one row step
 *                 each), 76480 pixels
 *   line_aa       the same segments antialiased (two blended pixels a column)
 *   tex_affine    a screen-filling textured quad (2 triangles), affine
 *   tex_persp     the same, perspective-correct, a reciprocal every pixel
 *   tex_persp16   the same, exact every 16 pixels
 *   flat          the same quad untextured, for comparison
 *   tex_alpha     (issue 15) the textured quad, affine, with an RGBA4444
 *                 texture (no texel of alpha 0) alpha-blended over the
 *                 cleared frame: texel alpha times constant alpha 200
 *   blend         the flat quad alpha-blended at constant alpha 128
 *   blend_add     the flat quad blended additively at constant alpha 128
 *   tex_bilinear  the textured quad (RGB565), affine, bilinear filtering
 *   tex_persp_tilt, tex_persp16_tilt  perspective texture on a floor that
 *                 recedes in depth (1/w varies along every row, so the
 *                 per-pixel and per-16 reciprocals really divide; the quads
 *                 above lie in the screen plane, where 1/w is constant)
 * Each count is one whole zl_draw_* call (setup included) divided by the
 * pixels written; the clear is not counted. Prints "FEATURE tag name
 * instructions pixels per_pixel_x100".
 */
#include <stdio.h>
#include <string.h>

#include "bench_timer.h"
#include "budget.h"
#include "zline/zline.h"

#ifndef BENCH_TAG
#define BENCH_TAG "features"
#endif

enum { W = 320, H = 240, TS = 64 };

static uint16_t color_buf[W * H];
static uint16_t depth_buf[W * H];
static uint16_t texels[TS * TS];
static uint16_t texels4444[TS * TS];

static zl_context ctx;
/* zl_draw_mesh's draw cache (zl_context.draw_cache) at the library's size:
 * the default call's cached path, as zl_context held it before issue 23. */
static uint64_t draw_cache_buf[ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS) / 8 + 1];

static void reset(void)
{
    zl_rgb bg = {0, 0, 0};
    zl_state_default(&ctx.state);
    zl_style_default(&ctx.style);
    zl_clear(&ctx, bg, 65535);
}

static unsigned written(void)
{
    unsigned i, n = 0;
    for (i = 0; i < W * H; i++)
        n += depth_buf[i] != 65535;
    return n;
}

/* Print a loop's count and check it against its budget (budgets.txt):
 * returns 1 when over budget, so a slower loop fails CTest. The INTERVAL
 * line names the loop's marks for profile.sh (TAGS=features-O2 SCENE=line). */
static int report(const char *name, unsigned first, unsigned pixels)
{
    uint32_t insns = bench_between(first, first + 1);
    printf("INTERVAL %s %s total %lu %u %u\n", BENCH_TAG, name, (unsigned long)insns, first, first + 1);
    printf("FEATURE %s %s %lu %u %lu\n", BENCH_TAG, name, (unsigned long)insns, pixels,
           pixels ? (unsigned long)((uint64_t)insns * 100u / pixels) : 0ul);
    return bench_check_budget(BENCH_TAG, BENCH_BUDGETS, name, insns);
}

/* 239 segments from (0, k) to (319, k + 1), pixel centres, depth 0.5. */
static zl_fixed line_pos[240 * 2 * 3];

static int run_lines(int aa)
{
    zl_lines l;
    zl_status st;
    unsigned k, first;
    for (k = 0; k < 239; k++) {
        zl_fixed *p = &line_pos[k * 6];
        p[0] = ZL_FX_HALF;
        p[1] = (zl_fixed)(k * 65536u + 32768u);
        p[2] = ZL_FX_HALF;
        p[3] = (zl_fixed)(319 * 65536 + 32768);
        p[4] = (zl_fixed)((k + 1) * 65536u + 32768u);
        p[5] = ZL_FX_HALF;
    }
    memset(&l, 0, sizeof l);
    l.positions = line_pos;
    l.vertex_count = 239 * 2;
    l.count = 239 * 2;
    l.prim = ZL_PRIM_LINES;
    reset();
    ctx.style.line_aa = (uint8_t)aa;
    first = bench_stamp_count();
    mark();
    st = zl_draw_lines(&ctx, &l, NULL);
    mark();
    if (st != ZL_OK)
        return 1;
    /* antialiased lines write no depth: count their columns instead */
    return report(aa ? "line_aa" : "line", first, aa ? 239u * 320u : written());
}

/* A screen-filling quad in pixel space, texture repeated 4 x 3 times. */
static const zl_fixed quad_pos[] = {0, 0, ZL_FX_HALF, ZL_FX_INT(W), 0, ZL_FX_HALF,
                                    ZL_FX_INT(W), ZL_FX_INT(H), ZL_FX_HALF, 0, ZL_FX_INT(H), ZL_FX_HALF};
static const zl_fixed quad_uv[] = {0, 0, ZL_FX_INT(4), 0, ZL_FX_INT(4), ZL_FX_INT(3), 0, ZL_FX_INT(3)};
static const uint16_t quad_idx[] = {0, 1, 2, 0, 2, 3};

/* blend: zl_blend of the draw; with a texture, the RGBA4444 one */
static int run_quad_blend(const char *name, int textured, unsigned mapping, unsigned every, unsigned blend,
                          unsigned alpha);

static int bilinear; /* the next textured quads filter bilinearly */

static int run_quad(const char *name, int textured, unsigned mapping, unsigned every)
{
    return run_quad_blend(name, textured, mapping, every, ZL_BLEND_OFF, 255);
}

static int run_quad_blend(const char *name, int textured, unsigned mapping, unsigned every, unsigned blend,
                          unsigned alpha)
{
    zl_mesh m = {quad_pos, quad_idx, NULL, NULL, 4, 2};
    zl_texture tex;
    zl_status st;
    unsigned first;
    memset(&tex, 0, sizeof tex);
    tex.texels = texels;
    tex.width = TS;
    tex.height = TS;
    tex.stride = TS;
    if (blend != ZL_BLEND_OFF) {
        tex.texels = texels4444;
        tex.format = ZL_TEXEL_RGBA4444;
    }
    reset();
    ctx.style.blend = (uint8_t)blend;
    ctx.style.alpha = (uint8_t)alpha;
    if (textured) {
        ctx.style.texture = &tex;
        ctx.style.texcoords = quad_uv;
        ctx.style.tex_mapping = (uint8_t)mapping;
        ctx.style.tex_every = (uint8_t)every;
        ctx.style.tex_filter = (uint8_t)(bilinear ? ZL_FILTER_BILINEAR : ZL_FILTER_NEAREST);
    }
    first = bench_stamp_count();
    mark();
    st = zl_draw_mesh(&ctx, &m, NULL);
    mark();
    if (st != ZL_OK)
        return 1;
    return report(name, first, written());
}

/* A floor 16 wide from 1.5 to 40 units ahead, 1 unit below the eye, seen
 * through a 60 degree perspective: the lower half of the screen, texture
 * repeated 8 x 20 times. Pixels are those of the clipped floor. */
static const zl_fixed floor_pos[] = {ZL_FX_INT(-8), ZL_FX_INT(-1), -(ZL_FX_INT(3) / 2),
                                     ZL_FX_INT(8),  ZL_FX_INT(-1), -(ZL_FX_INT(3) / 2),
                                     ZL_FX_INT(8),  ZL_FX_INT(-1), ZL_FX_INT(-40),
                                     ZL_FX_INT(-8), ZL_FX_INT(-1), ZL_FX_INT(-40)};
static const zl_fixed floor_uv[] = {0, 0, ZL_FX_INT(8), 0, ZL_FX_INT(8), ZL_FX_INT(20), 0, ZL_FX_INT(20)};

static int run_floor(const char *name, unsigned every)
{
    zl_mesh m = {floor_pos, quad_idx, NULL, NULL, 4, 2};
    zl_texture tex;
    zl_mat4 proj;
    zl_status st;
    unsigned first;
    if (zl_mat4_perspective(&proj, ZL_ANGLE_TURN / 6, ZL_FX_INT(4) / 3, ZL_FX_INT(1), ZL_FX_INT(100)) != ZL_OK)
        return 1;
    memset(&tex, 0, sizeof tex);
    tex.texels = texels;
    tex.width = TS;
    tex.height = TS;
    tex.stride = TS;
    reset();
    ctx.style.texture = &tex;
    ctx.style.texcoords = floor_uv;
    ctx.style.tex_mapping = ZL_TEX_PERSPECTIVE;
    ctx.style.tex_every = (uint8_t)every;
    first = bench_stamp_count();
    mark();
    st = zl_draw_mesh(&ctx, &m, &proj);
    mark();
    if (st != ZL_OK)
        return 1;
    return report(name, first, written());
}

int main(void)
{
    zl_target tg;
    int failed = 0;
    unsigned i;
    if (bench_timer_init("bench_features") != 0)
        return 100;
    for (i = 0; i < TS * TS; i++)
        texels[i] = (uint16_t)((((i % TS) / 8 + (i / TS) / 8) & 1) ? 0xFFE0u : 0x001Fu);
    for (i = 0; i < TS * TS; i++) /* the checker with alpha 1..15 along each row */
        texels4444[i] = (uint16_t)((((i % TS) / 8 + (i / TS) / 8) & 1) ? 0xFF00u : 0x00F0u) | (1u + (i % 15u));
    memset(&tg, 0, sizeof tg);
    tg.color = color_buf;
    tg.color_stride = W * 2;
    tg.depth = depth_buf;
    tg.depth_stride = W * 2;
    tg.width = W;
    tg.height = H;
    tg.format = ZL_FORMAT_RGB565;
    if (zl_init(&ctx, &tg) != ZL_OK)
        return 101;
    ctx.draw_cache = draw_cache_buf;
    ctx.draw_cache_bytes = sizeof draw_cache_buf;
    printf("# %s: FEATURE tag name instructions pixels instructions_per_pixel_x100\n", BENCH_TAG);
    failed += run_lines(0);
    failed += run_lines(1);
    failed += run_quad("flat", 0, 0, 0);
    failed += run_quad("tex_affine", 1, ZL_TEX_AFFINE, 0);
    failed += run_quad("tex_persp", 1, ZL_TEX_PERSPECTIVE, 0);
    failed += run_quad("tex_persp16", 1, ZL_TEX_PERSPECTIVE, 16);
    failed += run_quad_blend("tex_alpha", 1, ZL_TEX_AFFINE, 0, ZL_BLEND_ALPHA, 200);
    failed += run_quad_blend("blend", 0, 0, 0, ZL_BLEND_ALPHA, 128);
    failed += run_quad_blend("blend_add", 0, 0, 0, ZL_BLEND_ADD, 128);
    bilinear = 1;
    failed += run_quad("tex_bilinear", 1, ZL_TEX_AFFINE, 0);
    bilinear = 0;
    failed += run_floor("tex_persp_tilt", 0);
    failed += run_floor("tex_persp16_tilt", 16);
    return failed;
}
