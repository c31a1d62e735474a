/* SPDX-License-Identifier: MIT */
/*
 * The Gouraud colour bound (zline.h, Gouraud colour) on long spans, against
 * the exact rational mix written here.
 *
 * RGB565 Gouraud spans step their colour in 8.8 "lanes" (zl_span.h): the
 * step is rounded to 1/256 and drifts along a span, restarting every 512
 * pixels. The contract bounds the result: each channel the top bits of a
 * value within -0.6 .. +1.6 (8-bit units) of the exact mix e at the pixel
 * centre, so within one RGB565 step of floor(e / 8) or floor(e / 4); RGB888
 * within +-1 of e. test_paths_match_reference.c checks every path on a
 * 32 x 32 target, whose spans are too short for the drift to show; here the
 * triangles span a 1040-pixel-wide target (two chunks and a part), with
 * steep and shallow colour gradients and vertex colours at 0 and 255 (the
 * clamps), and small ones too (the cached small-triangle path), in RGB565,
 * RGB565_BE and RGB888, through zl_draw_mesh, zl_draw_mesh with the vertex
 * cache and zl_frame in scanline mode. One triangle per draw over a cleared
 * target, so every covered pixel is written.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"

#define W 1040
#define H 6
#define CASES 24

void setUp(void) {}
void tearDown(void) {}

enum { PATH_DRAW, PATH_DRAW_CACHED, PATH_SCANLINE, PATH_COUNT };
static const char *const path_names[PATH_COUNT] = {"draw", "draw+cache", "scanline"};
static const char *const format_names[3] = {"RGB565", "RGB565_BE", "RGB888"};

static uint32_t rng = 0x6B0u;
static zl_fixed pos[9];
static uint16_t idx[3] = {0, 1, 2};
static uint8_t vcol[9];
static uint8_t color_buf[W * H * 3];
static uint16_t depth_buf[W * H];
static uint32_t vcache[3 * 2]; /* ZL_VERTEX_CACHE_BYTES(3) */
/* PATH_DRAW's draw cache (zl_context.draw_cache): the small-cache path */
static uint64_t draw_cache[ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS) / 8 + 1];
static uint64_t work[8192];
static const zl_rgb black = {0, 0, 0};
static char msg[300];
static long covered_checked; /* pixels checked against the mix (not vacuous) */

/* A vertex colour channel: often 0 or 255 (where the clamps and the lane
 * range checks act), else anything. */
static uint8_t rand_channel(void)
{
    int32_t k = zt_rand_range(&rng, 0, 5);
    return (uint8_t)(k == 0 ? 0 : k == 1 ? 255 : zt_rand_range(&rng, 0, 255));
}

/* Case n: a wide triangle across the target (long spans; a third of them
 * with a nearly constant colour, whose small steps round the most), or a
 * small one (2 .. 8 pixels, the cached small-triangle path). */
static void random_triangle(int n)
{
    unsigned k;
    int small = n % 4 == 3;
    int32_t cx = zt_rand_range(&rng, 0, W - 1), cy = zt_rand_range(&rng, 0, H - 1);
    for (k = 0; k < 3; k++) {
        int32_t x, y;
        if (small) {
            x = zt_rand_range(&rng, (cx - 4) * 16, (cx + 4) * 16);
            y = zt_rand_range(&rng, (cy - 3) * 16, (cy + 3) * 16);
        } else {
            /* two vertices beyond the left and right edges, the third anywhere */
            x = k == 0 ? zt_rand_range(&rng, -40 * 16, 0) : k == 1 ? zt_rand_range(&rng, W * 16, (W + 40) * 16)
                                                              : zt_rand_range(&rng, -40 * 16, (W + 40) * 16);
            y = zt_rand_range(&rng, -3 * 16, (H + 3) * 16);
        }
        pos[k * 3] = (zl_fixed)(x * 4096);
        pos[k * 3 + 1] = (zl_fixed)(y * 4096);
        pos[k * 3 + 2] = (zl_fixed)zt_rand_range(&rng, 6554, 58982); /* 0.1 .. 0.9 */
    }
    for (k = 0; k < 9; k++)
        vcol[k] = rand_channel();
    if (n % 3 == 1) /* a shallow gradient: each channel within 3 of the first vertex's */
        for (k = 3; k < 9; k++)
            vcol[k] = (uint8_t)(vcol[k % 3] + 3 > 255 ? 255 - zt_rand_range(&rng, 0, 3)
                                                         : vcol[k % 3] + zt_rand_range(&rng, 0, 3));
}

static void make_target(zl_target *tg, zl_format fmt)
{
    zt_target_packed(tg, color_buf, depth_buf, W, H, fmt);
}

static void mesh_of(zl_mesh *m)
{
    memset(m, 0, sizeof *m);
    m->positions = pos;
    m->indices = idx;
    m->vertex_colors = vcol;
    m->vertex_count = 3;
    m->triangle_count = 1;
}

/* Scanline output lands where frame mode draws, for the same checks. */
static zt_frame_copy to_buffers = {color_buf, depth_buf};

static void render(zl_format fmt, unsigned path, const zl_state *st)
{
    zl_mesh m;
    mesh_of(&m);
    if (path == PATH_SCANLINE) {
        zl_frame_config cfg;
        zl_frame f;
        zt_frame_config_of(&cfg, W, H, 1, fmt);
        zt_frame_capacity(&cfg, 1, 3, 1, 8);
        cfg.gouraud = 1;
        TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, black, 65535));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &m, NULL, st));
        TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, zt_band_copy_fn, &to_buffers));
    } else {
        zl_target tg;
        zl_context ctx;
        make_target(&tg, fmt);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, black, 65535));
        ctx.state = *st;
        if (path == PATH_DRAW_CACHED) {
            ctx.vertex_cache = vcache;
            ctx.vertex_cache_bytes = sizeof vcache;
        } else {
            ctx.draw_cache = draw_cache;
            ctx.draw_cache_bytes = sizeof draw_cache;
        }
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
    }
}

/* The exact mix of channel c at pixel (i, j) as num / area (area > 0),
 * from the snapped vertices (half-subpixel units). */
static void exact_mix(int32_t i, int32_t j, unsigned c, int64_t *num, int64_t *area)
{
    int64_t x[3], y[3], e[3], cx = zt_centre2(i), cy = zt_centre2(j), a;
    unsigned k;
    for (k = 0; k < 3; k++) {
        x[k] = zt_snap2(pos[k * 3]);
        y[k] = zt_snap2(pos[k * 3 + 1]);
    }
    for (k = 0; k < 3; k++) {
        unsigned p = (k + 1) % 3, q = (k + 2) % 3;
        e[k] = (x[q] - x[p]) * (cy - y[p]) - (y[q] - y[p]) * (cx - x[p]);
    }
    a = e[0] + e[1] + e[2];
    *num = 0;
    for (k = 0; k < 3; k++)
        *num += e[k] * vcol[k * 3 + c];
    if (a < 0) {
        a = -a;
        *num = -*num;
    }
    *area = a;
}

static int64_t clamp_to(int64_t v, int64_t hi)
{
    return v < 0 ? 0 : v > hi ? hi : v;
}


/* Every pixel of the target against the bound: covered pixels by the exact
 * mix, the others untouched (black). 1 on the first failure. */
static int check(zl_format fmt, const char *what)
{
    zt_tri tri;
    int32_t i, j;
    zt_tri_init(&tri, pos, pos + 3, pos + 6);
    for (j = 0; j < H; j++)
        for (i = 0; i < W; i++) {
            unsigned p = (unsigned)(j * W + i), ch[3], bits[3], c;
            int covered = zt_tri_covers(&tri, i, j);
            covered_checked += covered;
            zt_read_channels(color_buf, fmt, p, ch, bits);
            for (c = 0; c < 3; c++) {
                int64_t num, area, lo, hi;
                if (!covered) {
                    lo = hi = 0;
                } else {
                    exact_mix(i, j, c, &num, &area);
                    if (fmt == ZL_FORMAT_RGB888) { /* within +-1 of e */
                        lo = clamp_to(zt_floor_div(num - area, area), 255);
                        hi = clamp_to(zt_ceil_div(num + area, area), 255);
                    } else { /* the top bits of a value in e - 0.6 .. e + 1.6 */
                        int64_t step = (int64_t)1 << (8 - bits[c]);
                        lo = zt_floor_div(clamp_to(zt_floor_div(10 * num - 6 * area, 10 * area), 255), step);
                        hi = zt_floor_div(clamp_to(zt_floor_div(10 * num + 16 * area, 10 * area), 255), step);
                    }
                }
                if ((int64_t)ch[c] < lo || (int64_t)ch[c] > hi) {
                    snprintf(msg, sizeof msg, "%s: pixel (%d,%d) %s channel %u is %u, allowed %ld..%ld", what, (int)i,
                             (int)j, covered ? "covered" : "not covered", c, ch[c], (long)lo, (long)hi);
                    TEST_FAIL_MESSAGE(msg);
                    return 1;
                }
            }
        }
    return 0;
}

static void test_gouraud_within_the_bound_on_long_spans(void)
{
    int n;
    unsigned fmt, path;
    /* the formats compiled in: RGB565 alone with ZL_FEATURE_FORMATS 0 */
    const unsigned formats = ZL_FEATURE_FORMATS ? 3u : 1u;
    zl_state st;
    zl_state_default(&st);
    st.shading = ZL_SHADE_GOURAUD;
    st.cull = ZL_CULL_NONE;
    for (n = 0; n < CASES; n++) {
        random_triangle(n);
        for (fmt = 0; fmt < formats; fmt++)
            for (path = 0; path < PATH_COUNT; path++) {
                char what[120];
                render((zl_format)fmt, path, &st);
                snprintf(what, sizeof what, "case %d, %s, %s", n, format_names[fmt], path_names[path]);
                if (check((zl_format)fmt, what))
                    return;
            }
    }
    /* not vacuous: the wide triangles cover a good part of the target */
    TEST_ASSERT_GREATER_THAN((long)CASES * (long)formats * PATH_COUNT * W * H / 10, covered_checked);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_gouraud_within_the_bound_on_long_spans);
    return UNITY_END();
}
