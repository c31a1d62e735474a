/* SPDX-License-Identifier: MIT */
/*
 * zl_context's fixed RAM and the draw cache in caller memory (issue 23).
 *
 * zl_context holds no cache of its own: sizeof(zl_context) <= 1024 bytes in
 * every configuration (this file is built for each target CTest covers).
 * zl_draw_mesh's post-transform cache lives in memory the caller gives
 * (zl_context.draw_cache): zl_draw_cache_bytes() is 144 bytes of set-up
 * plus 10 a slot (0 for a library without the cache); a draw uses a cache
 * of that size, 8-byte aligned, and writes it (its tags are reset each
 * draw), and never touches one that is too small or misaligned, or any
 * byte past the size it asked for.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_target.h"

void setUp(void) {}
void tearDown(void) {}

enum { W = 32, H = 24, FILL = 0xA5 };

static uint16_t color[W * H] ZT_ALIGNED(2), depth[W * H] ZT_ALIGNED(2);
/* room for the cache at an offset of 8 (aligned) or 4 (misaligned), and
 * guard bytes after it; one word more, as a uint64_t array is not 8-byte
 * aligned on every target (avr-gcc aligns it to 1): arena_start() is the
 * first 8-byte boundary in it */
#define ARENA_BYTES (ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS) + 64u)
static uint64_t arena_words[ARENA_BYTES / 8 + 1];

static uint8_t *arena_start(void)
{
    uint8_t *p = (uint8_t *)arena_words;
    return p + (8u - (unsigned)((uintptr_t)p & 7u)) % 8u;
}

static void test_context_fits_one_kilobyte(void)
{
    printf("sizeof(zl_context) = %u bytes\n", (unsigned)sizeof(zl_context));
    TEST_ASSERT_LESS_OR_EQUAL(1024, sizeof(zl_context));
}

static void test_draw_cache_size(void)
{
    size_t slots = ZL_DRAW_CACHE_SLOTS;
    /* a slot: the window vertex (x, y: 2 bytes each, z: 4, with the exact
     * depth plane's two 2-byte residuals) and a 2-byte tag */
    size_t slot = ZL_FEATURE_EXACT_DEPTH ? 2u + 2u + 4u + 4u + 2u : 2u + 2u + 4u + 2u;
    TEST_ASSERT_EQUAL_UINT32(slots > 0 ? 144u + slot * slots : 0u, (uint32_t)zl_draw_cache_bytes());
    TEST_ASSERT_EQUAL_UINT32((uint32_t)zl_draw_cache_bytes(), (uint32_t)ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS));
}

/* One flat triangle in pixel space, drawn with the draw cache at
 * `offset` bytes into the arena, `bytes` long; returns how many arena bytes
 * changed, and checks none past offset + zl_draw_cache_bytes(). */
static size_t draw_with_cache(size_t offset, size_t bytes)
{
    static const zl_fixed pos[9] = {2 * ZL_FX_ONE,  2 * ZL_FX_ONE,  ZL_FX_ONE / 2, 28 * ZL_FX_ONE, 4 * ZL_FX_ONE,
                                    ZL_FX_ONE / 2, 8 * ZL_FX_ONE, 20 * ZL_FX_ONE, ZL_FX_ONE / 2};
    static const uint16_t idx[3] = {0, 1, 2};
    zl_target tg;
    zl_context ctx;
    zl_mesh m;
    zl_rgb bg = {0, 0, 0};
    uint8_t *a = arena_start();
    size_t i, changed = 0;
    memset(a, FILL, ARENA_BYTES);
    memset(&m, 0, sizeof m);
    m.positions = pos;
    m.indices = idx;
    m.vertex_count = 3;
    m.triangle_count = 1;
    zt_target_packed(&tg, color, depth, W, H, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    TEST_ASSERT_NULL(ctx.draw_cache);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
    ctx.draw_cache = a + offset;
    ctx.draw_cache_bytes = bytes;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &m, NULL));
    for (i = 0; i < ARENA_BYTES; i++)
        if (a[i] != FILL) {
            changed++;
            TEST_ASSERT_TRUE_MESSAGE(i >= offset && i < offset + zl_draw_cache_bytes(), "a byte outside the cache");
        }
    for (i = 0; i < W * H; i++)
        if (depth[i] != 65535)
            return changed;
    TEST_FAIL_MESSAGE("the triangle drew nothing");
    return changed;
}

static void test_draw_cache_used_when_it_fits(void)
{
    size_t need = zl_draw_cache_bytes();
    if (need == 0) { /* a library without the cache never touches one */
        TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)draw_with_cache(8, ARENA_BYTES - 8));
        return;
    }
    /* the tags of every slot are reset: at least 2 bytes a slot change */
    TEST_ASSERT_GREATER_OR_EQUAL(2u * ZL_DRAW_CACHE_SLOTS, draw_with_cache(8, need));
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)draw_with_cache(8, need - 1));
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)draw_with_cache(4, need + 4));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_context_fits_one_kilobyte);
    RUN_TEST(test_draw_cache_size);
    RUN_TEST(test_draw_cache_used_when_it_fits);
    return UNITY_END();
}
