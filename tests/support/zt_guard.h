/* SPDX-License-Identifier: MIT */
/*
 * Guarded test buffers.
 *
 * Every colour and depth buffer a test hands to zline comes from a static
 * arena through zt_guard_alloc: the payload sits between two zones of guard
 * bytes holding a known position-dependent pattern, and zt_guard_check()
 * reports any guard byte that changed. No malloc, no files: the helpers run
 * on the host and on Cortex-M alike.
 *
 * zt_surface wraps a zl_target whose rows may carry padding bytes beyond
 * width * bpp (stride > row length); the padding is filled with the guard
 * pattern as well and zt_surface_check() verifies it with the guards, so a
 * write past the right edge of a row is caught, not only one past the end.
 */
#ifndef ZT_GUARD_H
#define ZT_GUARD_H

#include <stddef.h>
#include <stdint.h>

#include "zline/zline.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ZT_GUARD_BYTES 64u                    /* guard zone on each side */
/* The whole arena, static. A target with less RAM gives a smaller one (the
 * ATmega2560's run, port/avr/run-avr-test.sh); UINT32_C: 64u * 1024u is 0
 * where unsigned has 16 bits. */
#ifndef ZT_GUARD_ARENA_BYTES
#define ZT_GUARD_ARENA_BYTES (UINT32_C(64) * 1024u)
#endif
#define ZT_GUARD_MAX_BLOCKS 32u

/* Forget every allocation (the arena is reused from its start). */
void zt_guard_reset(void);
/* bytes of payload, 8-byte aligned, guards on both sides; NULL when full. The
 * payload is zero-filled. */
void *zt_guard_alloc(size_t bytes);
/* Number of guard bytes (over all live blocks) that differ from the pattern. */
size_t zt_guard_check(void);
/* Text naming the first damaged guard found by the last check ("" if none). */
const char *zt_guard_report(void);
/* The byte the guard pattern holds at a given position (also used for row padding). */
uint8_t zt_guard_pattern(size_t index);

/* A render target whose buffers are guarded. */
typedef struct {
    zl_target target;
    uint8_t *color;       /* first byte of row 0 (== target.color), may be NULL */
    uint8_t *depth;       /* first byte of depth row 0 (== target.depth), may be NULL */
    size_t color_bytes;   /* stride * height */
    size_t depth_bytes;
    unsigned bpp;         /* bytes per pixel (2 for an unknown format) */
    unsigned width, height;
    unsigned color_offset; /* guard bytes in front of the colour buffer */
} zt_surface;

/*
 * Allocate guarded colour (unless format_bytes of fmt is 0 or with_color == 0)
 * and depth buffers for a width x height target of format fmt. Each row gets
 * color_pad / depth_pad padding bytes (depth_pad must be even). color_offset
 * (0..7) shifts the colour buffer off 8-byte alignment. Pixels are zeroed,
 * padding gets the guard pattern. Returns 0, or -1 when the arena is full.
 */
int zt_surface_make(zt_surface *s, unsigned width, unsigned height, zl_format fmt, int with_color,
                    int with_depth, unsigned color_pad, unsigned depth_pad, unsigned color_offset);
/* Guard bytes plus row-padding bytes that changed; 0 when all is intact. */
size_t zt_surface_check(const zt_surface *s);

/*
 * Pixel access in a format-independent packed form:
 *   RGB888    0xRRGGBB (bytes R, G, B in memory)
 *   RGB565    the native uint16 value
 *   RGB565_BE (byte0 << 8) | byte1, i.e. the RGB565 value
 */
uint32_t zt_get_px(const zt_surface *s, unsigned x, unsigned y);
void zt_set_px(zt_surface *s, unsigned x, unsigned y, uint32_t v);
uint16_t zt_get_depth(const zt_surface *s, unsigned x, unsigned y);
void zt_set_depth(zt_surface *s, unsigned x, unsigned y, uint16_t d);
void zt_fill_px(zt_surface *s, uint32_t v);
void zt_fill_depth(zt_surface *s, uint16_t d);
/* mask[y * width + x] = (pixel == v). Returns how many matched. */
unsigned zt_mask_of_px(const zt_surface *s, uint32_t v, uint8_t *mask);

/* Packed 0xRRGGBB of a zl_rgb. */
uint32_t zt_rgb_packed(zl_rgb c);

/* Assert (Unity) that the surface's guards and padding are intact. */
#define ZT_ASSERT_SURFACE_INTACT(s) \
    TEST_ASSERT_EQUAL_UINT_MESSAGE(0, zt_surface_check(s), zt_guard_report())

#ifdef __cplusplus
}
#endif

#endif /* ZT_GUARD_H */
