/* SPDX-License-Identifier: MIT */
/*
 * The fast path of frame mode against the general path, byte for byte.
 *
 * With a vertex cache, a plain flat RGB565 draw takes zl_tiny_setup /
 * zl_tiny_draw (small triangles: edges by one division per row, depth in 32
 * bits relative to the lowest vertex, short spans without a depth clamp) or
 * zl_tri_setup_flat; without a cache every triangle takes the general
 * polygon path with its exact DDA edges and 64-bit planes. The two are
 * separate implementations of one raster contract, so the same meshes must
 * give the same colour and depth bytes. The meshes are small triangles the
 * way real models have them, plus the cases the fast path's arguments rest
 * on: depths at 0 and at the far end (the unclamped short spans), wide depth
 * ranges (over the 2^25 bound), slivers with steep gradients, vertices
 * beyond 512 pixels (the 32-bit bounds), triangles across the target's
 * edges, and the four combinations of LESS / LEQUAL with back-face culling
 * on and off.
 *
 * Without a vertex cache but with a draw cache (zl_context.draw_cache,
 * zl_draw_cache_bytes() bytes), zl_draw_mesh keeps recent window vertices
 * in a direct-mapped cache of ZL_DRAW_CACHE_SLOTS slots there and takes the
 * same fast path; with neither, the general path. test_shared_vertices
 * draws a mesh whose triangles share vertices, more vertices than slots and
 * triangles whose vertices fight for one slot, through a matrix, some
 * vertices beyond the near and far planes (the clipping path): with the
 * vertex cache, with the draw cache and with neither. This file is also
 * built against a library with ZL_DRAW_CACHE_SLOTS=0
 * (test_fast_paths_general): there a draw cache is not used, so the draw
 * with it is the general path too.
 */
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 96, H = 64, NT = 200, NV = 3 * NT };

static uint32_t rng = 0xC0FFEEu;
static uint32_t next_rand(void)
{
    return zt_rand(&rng);
}
static int32_t rand_range(int32_t lo, int32_t hi) /* inclusive */
{
    return zt_rand_range(&rng, lo, hi);
}

static zl_fixed pos[NV * 3];
static uint16_t idx[NT * 3];
static uint8_t fcol[NT * 3];
static uint16_t color_a[W * H], color_b[W * H], depth_a[W * H], depth_b[W * H];
static uint32_t vcache[NV * 2]; /* ZL_VERTEX_CACHE_BYTES(NV) */
/* zl_draw_mesh's draw cache, one byte more than the library needs */
static uint64_t draw_cache[ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS) / 8 + 1];

/* A depth in Q16.16 (0 .. 1 in pixel space): kind 0 anywhere, 1 near the
 * far end, 2 near 0, 3 anywhere beyond the range (clipped to it). */
static zl_fixed rand_depth(int kind)
{
    switch (kind) {
    case 1:
        return ZL_FX_ONE - rand_range(0, 40);
    case 2:
        return rand_range(0, 40);
    case 3:
        return rand_range(-ZL_FX_ONE / 8, ZL_FX_ONE + ZL_FX_ONE / 8);
    default:
        return rand_range(0, ZL_FX_ONE);
    }
}

/* Triangles of a few pixels around random centres (some across the edges
 * of the target, some far beyond 512 pixels), a few slivers and large ones;
 * depth per triangle near one value, or spread when `wide`. */
static void random_mesh(int depth_kind, int wide)
{
    int t, k;
    for (t = 0; t < NT; t++) {
        int32_t cx = rand_range(-8, W + 8), cy = rand_range(-8, H + 8), size = rand_range(1, 12);
        zl_fixed z = rand_depth(depth_kind);
        int shape = rand_range(0, 19);
        if (shape == 0) { /* far outside the 32-bit shortcuts */
            cx += rand_range(0, 1) ? 700 : -700;
            size = 40;
        } else if (shape == 1) {
            size = 60; /* large */
        }
        for (k = 0; k < 3; k++) {
            int32_t v = t * 3 + k;
            int32_t dx = rand_range(-size, size), dy = rand_range(-size, size);
            if (shape == 2 && k == 2) { /* a sliver: the third vertex near the first two's line */
                dx = (rand_range(-size, size) + rand_range(-size, size)) / 2;
                dy = dx + rand_range(-1, 1);
            }
            pos[v * 3] = (cx + dx) * ZL_FX_ONE + rand_range(0, ZL_FX_ONE - 1);
            pos[v * 3 + 1] = (cy + dy) * ZL_FX_ONE + rand_range(0, ZL_FX_ONE - 1);
            pos[v * 3 + 2] = wide ? rand_depth(depth_kind) : z + rand_range(-300, 300);
            idx[t * 3 + k] = (uint16_t)v;
        }
        fcol[t * 3] = (uint8_t)next_rand();
        fcol[t * 3 + 1] = (uint8_t)next_rand();
        fcol[t * 3 + 2] = (uint8_t)next_rand();
    }
}

enum { NO_DRAW_CACHE, WITH_DRAW_CACHE };

/* Draw m twice over a cleared RGB565 target, through the vertex cache
 * `cache` when given, else through the draw cache when asked (neither: the
 * general path). The second draw ties every fragment, and the cache starts
 * empty again for it. */
static void draw_twice(uint16_t *color, uint16_t *depth, void *cache, size_t cache_bytes, int with_draw_cache,
                       const zl_state *st, const zl_mesh *m, const zl_mat4 *mvp)
{
    zl_target tg;
    zl_context ctx;
    zl_rgb bg = {1, 2, 3};
    zt_target_packed(&tg, color, depth, W, H, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
    ctx.state = *st;
    if (cache != NULL) {
        ctx.vertex_cache = cache;
        ctx.vertex_cache_bytes = cache_bytes;
    }
    if (with_draw_cache) {
        ctx.draw_cache = draw_cache;
        ctx.draw_cache_bytes = sizeof draw_cache;
    }
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, m, mvp));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, m, mvp));
}

static void test_cached_small_triangles_equal_the_general_path(void)
{
    zl_mesh m;
    long written = 0;
    int scene;
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.face_colors = fcol;
    m.vertex_count = NV;
    m.triangle_count = NT;
    for (scene = 0; scene < 64; scene++) {
        zl_state st;
        int i;
        zl_state_default(&st);
        st.depth_func = (scene & 1) ? ZL_LEQUAL : ZL_LESS;
        st.cull = (scene & 2) ? ZL_CULL_BACK : ZL_CULL_NONE;
        /* lit where the light is compiled in (test_features: refused otherwise) */
        st.light_on = (uint8_t)(ZL_FEATURE_LIGHTING && ((scene >> 2) & 1));
        random_mesh((scene >> 3) & 3, (scene >> 5) & 1);
        draw_twice(color_a, depth_a, vcache, sizeof vcache, NO_DRAW_CACHE, &st, &m, NULL);
        draw_twice(color_b, depth_b, NULL, 0, NO_DRAW_CACHE, &st, &m, NULL);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(depth_b, depth_a, sizeof depth_a, "depth differs from the general path");
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(color_b, color_a, sizeof color_a, "colour differs from the general path");
        draw_twice(color_a, depth_a, NULL, 0, WITH_DRAW_CACHE, &st, &m, NULL);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(depth_b, depth_a, sizeof depth_a, "depth (draw cache) differs from the general path");
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(color_b, color_a, sizeof color_a, "colour (draw cache) differs from the general path");
        for (i = 0; i < W * H; i++)
            written += depth_a[i] != 65535;
    }
    /* The scenes must cover a good part of the target for the comparison to mean anything. */
    TEST_ASSERT_GREATER_THAN(64L * W * H / 4, written);
}

enum { GW = 64, GH = 41, NP = GW * GH, NS = 1500 }; /* NP > 1024 slots */

static zl_fixed gpos[NP * 3];
static uint16_t gidx[NS * 3];
static uint8_t gcol[NS * 3];
static uint32_t gcache[NP * 2]; /* ZL_VERTEX_CACHE_BYTES(NP) */

static void test_shared_vertices(void)
{
    zl_mesh m;
    zl_mat4 mvp;
    long written = 0;
    int scene, i, j, t;
    memset(&m, 0, sizeof m);
    memset(&mvp, 0, sizeof mvp);
    /* clip space = object space, w = 1: x, y in [-1.25, 1.25] (the guard
     * band beyond the window), z in [-0.06, 1.06] (some vertices clipped) */
    mvp.m[0] = mvp.m[5] = mvp.m[10] = mvp.m[15] = ZL_FX_ONE;
    m.positions = gpos;
    m.indices = gidx;
    m.face_colors = gcol;
    m.vertex_count = NP;
    m.triangle_count = NS;
    for (scene = 0; scene < 16; scene++) {
        zl_state st;
        zl_state_default(&st);
        st.depth_func = (scene & 1) ? ZL_LEQUAL : ZL_LESS;
        st.cull = (scene & 2) ? ZL_CULL_BACK : ZL_CULL_NONE;
        st.light_on = (uint8_t)(ZL_FEATURE_LIGHTING && ((scene >> 2) & 1)); /* as above */
        for (j = 0; j < GH; j++)
            for (i = 0; i < GW; i++) {
                zl_fixed *p = &gpos[(j * GW + i) * 3];
                p[0] = (i - GW / 2) * (ZL_FX_ONE * 5 / 2 / GW) + rand_range(-600, 600);
                p[1] = (j - GH / 2) * (ZL_FX_ONE * 5 / 2 / GH) + rand_range(-600, 600);
                p[2] = (scene & 8) ? rand_range(-ZL_FX_ONE / 16, ZL_FX_ONE + ZL_FX_ONE / 16)
                                   : rand_range(ZL_FX_ONE / 4, ZL_FX_ONE / 2);
            }
        for (t = 0; t < NS; t++) {
            uint16_t *ix = &gidx[t * 3];
            int kind = rand_range(0, 7);
            i = rand_range(0, GW - 2);
            j = rand_range(0, GH - 2);
            ix[0] = (uint16_t)(j * GW + i);
            ix[1] = (uint16_t)(j * GW + i + 1 + (kind & 1) * GW);
            ix[2] = (uint16_t)((j + 1) * GW + i);
            if (kind == 0) { /* three vertices 1024 apart: one slot of the small cache */
                int v = rand_range(0, NP - 2049);
                ix[0] = (uint16_t)v;
                ix[1] = (uint16_t)(v + 1024);
                ix[2] = (uint16_t)(v + 2048);
            }
            if (kind == 2) { /* the other winding */
                uint16_t tmp = ix[1];
                ix[1] = ix[2];
                ix[2] = tmp;
            }
            gcol[t * 3] = (uint8_t)next_rand();
            gcol[t * 3 + 1] = (uint8_t)next_rand();
            gcol[t * 3 + 2] = (uint8_t)next_rand();
        }
        draw_twice(color_a, depth_a, gcache, sizeof gcache, NO_DRAW_CACHE, &st, &m, &mvp);
        draw_twice(color_b, depth_b, NULL, 0, WITH_DRAW_CACHE, &st, &m, &mvp);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(depth_a, depth_b, sizeof depth_a, "depth differs with the draw cache");
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(color_a, color_b, sizeof color_a, "colour differs with the draw cache");
        draw_twice(color_b, depth_b, NULL, 0, NO_DRAW_CACHE, &st, &m, &mvp);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(depth_a, depth_b, sizeof depth_a, "depth differs without any cache");
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(color_a, color_b, sizeof color_a, "colour differs without any cache");
        for (i = 0; i < W * H; i++)
            written += depth_a[i] != 65535;
    }
    TEST_ASSERT_GREATER_THAN(16L * W * H / 4, written);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_cached_small_triangles_equal_the_general_path);
    RUN_TEST(test_shared_vertices);
    return UNITY_END();
}
