/* SPDX-License-Identifier: MIT */
/*
 * The ABI check of zl_init and zl_frame_begin (issue 23), from a consumer.
 * Built with the package's flags alone (EXPECT_ABI_ERROR 0) both calls pass
 * the key check; built with a zl_config.h value other than the library's
 * (EXPECT_ABI_ERROR 1: tests/consumer/run.sh adds -DZL_DRAW_CACHE_SLOTS=256)
 * both return ZL_ERR_ABI, write nothing, and the status string names the
 * cause. EXPECT_SLOTS, when given, is the slot count the library was
 * configured with (ZLINE_CONFIG): the consumer must see it too.
 * Exit status: the number of failed checks.
 */
#include <stdio.h>
#include <string.h>

#include "zline/zline.h"

#ifndef EXPECT_ABI_ERROR
#define EXPECT_ABI_ERROR 0
#endif

static int failures;

static void expect(int ok, const char *what)
{
    if (!ok) {
        printf("abi_probe: FAIL %s\n", what);
        failures++;
    }
}

int main(void)
{
    static uint16_t color[8 * 8], depth[8 * 8];
    zl_context ctx;
    zl_target t;
    zl_rgb black = {0, 0, 0};
    zl_status st;
    memset(&t, 0, sizeof t);
    t.color = color;
    t.color_stride = 8 * 2;
    t.depth = depth;
    t.depth_stride = 8 * 2;
    t.width = 8;
    t.height = 8;
    t.format = ZL_FORMAT_RGB565;
    memset(&ctx, 0x5A, sizeof ctx);
    st = zl_init(&ctx, &t);
    printf("abi_probe: zl_init: %d (%s); key %08lx, library's %08lx\n", (int)st, zl_status_string(st),
           (unsigned long)ZL_ABI_KEY, (unsigned long)zl_abi_key());
    if (EXPECT_ABI_ERROR) {
        expect(st == ZL_ERR_ABI, "zl_init returns ZL_ERR_ABI");
        expect(ctx.target.width != 8, "zl_init wrote nothing");
        expect(strstr(zl_status_string(st), "configuration") != NULL, "the status string names the cause");
        expect(zl_frame_begin(NULL, NULL, NULL, 0, black, 0) == ZL_ERR_ABI, "zl_frame_begin returns ZL_ERR_ABI");
        expect(zl_abi_key() != ZL_ABI_KEY, "the keys differ");
    } else {
        expect(st == ZL_OK, "zl_init succeeds");
        expect(zl_frame_begin(NULL, NULL, NULL, 0, black, 0) == ZL_ERR_ARG, "zl_frame_begin checks its arguments");
        expect(zl_abi_key() == ZL_ABI_KEY, "the keys agree");
    }
#ifdef EXPECT_SLOTS
    expect(ZL_DRAW_CACHE_SLOTS == EXPECT_SLOTS, "the consumer sees the library's ZL_DRAW_CACHE_SLOTS");
    expect(zl_draw_cache_bytes() == ZL_DRAW_CACHE_BYTES(EXPECT_SLOTS), "the library has that many slots");
#endif
    printf("abi_probe: %d failed\n", failures);
    return failures;
}
