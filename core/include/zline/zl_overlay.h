/* SPDX-License-Identifier: MIT */
/*
 * 2D overlays: rectangles, lines, text and images drawn in pixel space over
 * the 3D, into a full frame or into a band as zl_frame produces it (a HUD,
 * a gauge's numbers, a menu). Integer only, no heap, no state.
 *
 * A canvas is a window of rows of the frame: a zl_target (every row) or a
 * zl_band (its rows). Every call takes frame coordinates (x right, y down,
 * pixel (0, 0) top left) and writes only the pixels of the canvas, so the
 * same calls made on every band of a frame, in the same order, give the
 * bytes they give on the full frame: output is identical in frame, scanline
 * and band modes. Draw into a band in the zl_frame_render callback (or
 * after zl_frame_next_band) before it goes to the display. Depth is neither
 * tested nor written; later calls draw over earlier ones.
 *
 * Colours are packed as zline packs any colour (RGB565 keeps the top bits
 * of each 8-bit channel), for the formats of zl_format.
 *
 *   rectangle   the pixels x <= px < x + w, y <= py < y + h (empty when w
 *               or h is 0); the outline is the rectangle's border, 1 pixel.
 *   line        from (x0, y0) to (x1, y1) inclusive, n = max(|dx|, |dy|)
 *               + 1 pixels: pixel i (0 .. n - 1) steps i along the major
 *               axis and round(i |d_minor| / (n - 1)) along the other
 *               (halves away from (x0, y0)), toward (x1, y1). Endpoints
 *               in -16384 .. 16383 (ZL_ERR_RANGE otherwise).
 *   text        the built-in 5x7 font (ASCII 32..126; any other byte is
 *               drawn as '?'), each glyph pixel a scale x scale square;
 *               glyph k of a line has its top-left corner at
 *               (x + 6 k scale, y), '\n' starts a new line 8 scale pixels
 *               lower at x. Only the glyph's set pixels are written.
 *   image       a zl_texture (the output of tools/img2c) at (x, y), one
 *               texel per pixel, unscaled. RGB565 texels are copied;
 *               RGBA4444 ones are blended as zline's ZL_BLEND_ALPHA with
 *               a = 17 * texel alpha: new = round((src a + old (255 - a)) / 255)
 *               per 8-bit channel (old widened by bit replication), so
 *               alpha 0 leaves the pixel and 15 replaces it.
 */
#ifndef ZL_OVERLAY_H
#define ZL_OVERLAY_H

#include "zline.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct {
    void *color;          /* the canvas' first row, column 0 */
    int32_t color_stride; /* bytes from one row to the next */
    uint16_t width;       /* columns 0 .. width - 1 */
    uint16_t first_row;   /* frame row of the canvas' first row */
    uint16_t rows;        /* rows first_row .. first_row + rows - 1 */
    uint8_t format;       /* zl_format */
} zl_canvas;

/* The canvas of a full target, or of a band. ZL_ERR_ARG for a NULL or
 * colourless target/band, an unknown format, no rows or columns, or a
 * stride below width * bpp. Pixels are written bytewise: any alignment. */
zl_status zl_canvas_of_target(zl_canvas *c, const zl_target *t);
zl_status zl_canvas_of_band(zl_canvas *c, const zl_band *b);

/* Every drawing call returns ZL_ERR_ARG for a NULL or invalid canvas (or a
 * NULL text or image), ZL_OK otherwise, also when nothing falls in it. */
zl_status zl_canvas_fill_rect(const zl_canvas *c, int16_t x, int16_t y, uint16_t w, uint16_t h, zl_rgb color);
zl_status zl_canvas_rect(const zl_canvas *c, int16_t x, int16_t y, uint16_t w, uint16_t h, zl_rgb color);
zl_status zl_canvas_line(const zl_canvas *c, int16_t x0, int16_t y0, int16_t x1, int16_t y1, zl_rgb color);
/* scale 1 .. 16 (ZL_ERR_RANGE otherwise). */
zl_status zl_canvas_text(const zl_canvas *c, int16_t x, int16_t y, const char *text, uint8_t scale,
                         zl_rgb color);
/* ZL_ERR_ARG for texels NULL, an unknown texel format or a stride below width. */
zl_status zl_canvas_image(const zl_canvas *c, int16_t x, int16_t y, const zl_texture *image);

/* The font's cell: a glyph is 5 x 7 pixels in a 6 x 8 cell (at scale 1). */
#define ZL_FONT_W 5
#define ZL_FONT_H 7
#define ZL_FONT_ADVANCE 6
#define ZL_FONT_LINE 8
/* Width in pixels of the widest line of text at scale (the cells, including
 * the last glyph's blank column), 0 for "" or NULL. */
uint32_t zl_text_width(const char *text, uint8_t scale);
/* Glyph column `col` (0 .. 4) of character ch: bit r set when row r (0 top)
 * is drawn; characters outside 32..126 give '?''s columns. */
uint8_t zl_font_column(char ch, unsigned col);

#ifdef __cplusplus
}
#endif

#endif /* ZL_OVERLAY_H */
