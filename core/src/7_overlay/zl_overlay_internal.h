/* SPDX-License-Identifier: MIT */
/* What the overlay's files share: the font table and the clipped pixel
 * writers (zl_canvas.c). */
#ifndef ZL_OVERLAY_INTERNAL_H
#define ZL_OVERLAY_INTERNAL_H

#include <stdint.h>

#include "zline/zl_overlay.h"

/* 95 glyphs x 5 columns, ASCII 32..126 (zl_font5x7.c). */
extern const uint8_t zl_font5x7[95 * 5];

/* A colour as the canvas stores it: bpp bytes in memory order. */
typedef struct {
    uint8_t bytes[3];
    uint8_t bpp;
} zl_ov_pixel;

/* Whether the canvas can be drawn on (see zl_canvas_of_target). */
int zl_ov_canvas_ok(const zl_canvas *c);
zl_ov_pixel zl_ov_pack(uint8_t format, unsigned r, unsigned g, unsigned b);
/* Fill the half-open box [x0, x1) x [y0, y1) of frame pixels, clipped to
 * the canvas (empty boxes draw nothing). */
void zl_ov_fill_box(const zl_canvas *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, const zl_ov_pixel *px);

#endif
