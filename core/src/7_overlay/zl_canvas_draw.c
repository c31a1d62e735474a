/* SPDX-License-Identifier: MIT */
/* Overlay lines and text (see zl_overlay.h). */
#include "zl_overlay_internal.h"

/* ------------------------------------------------------------------- lines */

#define LINE_LIMIT 16384

/*
 * Pixel i of a line moves q(i) = floor((2 i d + m) / (2 m)) along its minor
 * axis (d = |minor delta| <= m = |major delta|): round(i d / m), halves up.
 * q is non-decreasing, so the pixels with q(i) in [qa, qb] are a range of i.
 */
static uint32_t first_i_reaching(uint32_t qa, uint32_t d, uint32_t m) /* qa >= 1, d >= 1 */
{
    uint64_t num = 2u * (uint64_t)m * qa - m, den = 2u * (uint64_t)d;
    return (uint32_t)((num + den - 1u) / den); /* smallest i with 2 i d >= num */
}

static uint32_t last_i_within(uint32_t qb, uint32_t d, uint32_t m) /* d >= 1 */
{
    uint64_t num = 2u * (uint64_t)m * qb + m, den = 2u * (uint64_t)d;
    return (uint32_t)((num + den - 1u) / den) - 1u; /* largest i with 2 i d < num */
}

/* Narrow [*lo, *hi] to the pixels whose coordinate c0 + s q(i) lies in
 * [a, b], q(i) = i on the major axis (major != 0), else the minor rule.
 * Returns 0 when none is left. */
static int clip_axis(int32_t c0, int32_t s, int32_t a, int32_t b, uint32_t d, uint32_t m, int major, uint32_t *lo,
                     uint32_t *hi)
{
    int32_t qa = s > 0 ? a - c0 : c0 - b, qb = s > 0 ? b - c0 : c0 - a;
    uint32_t ilo, ihi;
    if (qa < 0)
        qa = 0;
    if (qb > (int32_t)d)
        qb = (int32_t)d;
    if (qa > qb)
        return 0;
    if (major) {
        ilo = (uint32_t)qa;
        ihi = (uint32_t)qb;
    } else if (d == 0) {
        ilo = 0; /* q(i) = 0 for every i, inside [qa, qb] */
        ihi = m;
    } else {
        ilo = qa == 0 ? 0 : first_i_reaching((uint32_t)qa, d, m);
        ihi = (uint32_t)qb == d ? m : last_i_within((uint32_t)qb, d, m);
    }
    if (ilo > *lo)
        *lo = ilo;
    if (ihi < *hi)
        *hi = ihi;
    return *lo <= *hi;
}

static uint32_t abs_diff(int32_t a, int32_t b)
{
    return a > b ? (uint32_t)(a - b) : (uint32_t)(b - a);
}

zl_status zl_canvas_line(const zl_canvas *c, int16_t x0, int16_t y0, int16_t x1, int16_t y1, zl_rgb color)
{
    uint32_t dx = abs_diff(x0, x1), dy = abs_diff(y0, y1), m, d, lo = 0, hi, q, rem, i;
    int32_t sx = x1 >= x0 ? 1 : -1, sy = y1 >= y0 ? 1 : -1, top;
    int x_major = dx >= dy;
    zl_ov_pixel px;
    if (!zl_ov_canvas_ok(c))
        return ZL_ERR_ARG;
    if (x0 < -LINE_LIMIT || x0 >= LINE_LIMIT || y0 < -LINE_LIMIT || y0 >= LINE_LIMIT || x1 < -LINE_LIMIT ||
        x1 >= LINE_LIMIT || y1 < -LINE_LIMIT || y1 >= LINE_LIMIT)
        return ZL_ERR_RANGE;
    m = x_major ? dx : dy;
    d = x_major ? dy : dx;
    hi = m;
    top = (int32_t)c->first_row;
    if (!clip_axis(x0, sx, 0, (int32_t)c->width - 1, x_major ? m : d, m, x_major, &lo, &hi) ||
        !clip_axis(y0, sy, top, top + (int32_t)c->rows - 1, x_major ? d : m, m, !x_major, &lo, &hi))
        return ZL_OK;
    px = zl_ov_pack(c->format, color.r, color.g, color.b);
    if (m == 0) {
        zl_ov_fill_box(c, x0, y0, (int32_t)x0 + 1, (int32_t)y0 + 1, &px);
        return ZL_OK;
    }
    /* q(lo) and its remainder, then one step at a time (d <= m: q grows by
     * at most 1 a step). Below 2^31: m, d < 2^15 and lo <= m. */
    q = (2u * lo * d + m) / (2u * m);
    rem = (2u * lo * d + m) % (2u * m);
    for (i = lo; i <= hi; i++) {
        int32_t major = (int32_t)i, minor = (int32_t)q;
        int32_t x = (int32_t)x0 + sx * (x_major ? major : minor);
        int32_t y = (int32_t)y0 + sy * (x_major ? minor : major);
        zl_ov_fill_box(c, x, y, x + 1, y + 1, &px);
        rem += 2u * d;
        if (rem >= 2u * m) {
            rem -= 2u * m;
            q++;
        }
    }
    return ZL_OK;
}

/* -------------------------------------------------------------------- text */

#define MAX_SCALE 16u

uint8_t zl_font_column(char ch, unsigned col)
{
    unsigned code = (unsigned char)ch;
    if (code < 32u || code > 126u)
        code = '?';
    return col < ZL_FONT_W ? zl_font5x7[(code - 32u) * ZL_FONT_W + col] : 0;
}

uint32_t zl_text_width(const char *text, uint8_t scale)
{
    uint32_t widest = 0, cells = 0;
    if (text == NULL)
        return 0;
    for (; *text != '\0'; text++) {
        cells = *text == '\n' ? 0 : cells + 1u;
        if (cells > widest)
            widest = cells;
    }
    return widest * ZL_FONT_ADVANCE * scale;
}

/* The glyph's set pixels as scale x scale squares, clipped by the caller's
 * row range check and zl_ov_fill_box. */
static void draw_glyph(const zl_canvas *c, int32_t x, int32_t y, char ch, int32_t scale, const zl_ov_pixel *px)
{
    unsigned col, row;
    for (col = 0; col < ZL_FONT_W; col++) {
        uint8_t bits = zl_font_column(ch, col);
        int32_t gx = x + (int32_t)col * scale;
        for (row = 0; bits != 0; row++, bits = (uint8_t)(bits >> 1)) {
            if (bits & 1u) {
                int32_t gy = y + (int32_t)row * scale;
                zl_ov_fill_box(c, gx, gy, gx + scale, gy + scale, px);
            }
        }
    }
}

zl_status zl_canvas_text(const zl_canvas *c, int16_t x, int16_t y, const char *text, uint8_t scale,
                         zl_rgb color)
{
    int32_t top, bottom, cx = x, cy = y, s = scale;
    zl_ov_pixel px;
    if (!zl_ov_canvas_ok(c) || text == NULL)
        return ZL_ERR_ARG;
    if (scale < 1u || scale > MAX_SCALE)
        return ZL_ERR_RANGE;
    px = zl_ov_pack(c->format, color.r, color.g, color.b);
    top = (int32_t)c->first_row;
    bottom = top + (int32_t)c->rows;
    for (; *text != '\0'; text++) {
        if (*text == '\n') {
            cx = x;
            cy += ZL_FONT_LINE * s;
            continue;
        }
        /* only glyphs crossing the canvas' rows and columns cost anything */
        if (cy < bottom && cy + ZL_FONT_H * s > top && cx < (int32_t)c->width && cx + ZL_FONT_W * s > 0)
            draw_glyph(c, cx, cy, *text, s, &px);
        cx += ZL_FONT_ADVANCE * s;
    }
    return ZL_OK;
}
