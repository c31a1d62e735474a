/* SPDX-License-Identifier: MIT */
/* Overlay canvases, rectangles and images (see zl_overlay.h). */
#include <string.h>

#include "zl_overlay_internal.h"

static unsigned format_bpp(uint8_t format)
{
    return zl_format_bytes((zl_format)format);
}

int zl_ov_canvas_ok(const zl_canvas *c)
{
    unsigned bpp;
    if (c == NULL || c->color == NULL || c->width == 0 || c->rows == 0)
        return 0;
    bpp = format_bpp(c->format);
    return bpp != 0 && c->color_stride >= (int32_t)c->width * (int32_t)bpp;
}

static zl_status canvas_from(zl_canvas *out, void *color, int32_t stride, uint16_t width, uint16_t first_row,
                             uint16_t rows, uint8_t format)
{
    zl_canvas c;
    if (out == NULL)
        return ZL_ERR_ARG;
    c.color = color;
    c.color_stride = stride;
    c.width = width;
    c.first_row = first_row;
    c.rows = rows;
    c.format = format;
    if (!zl_ov_canvas_ok(&c))
        return ZL_ERR_ARG;
    *out = c;
    return ZL_OK;
}

zl_status zl_canvas_of_target(zl_canvas *c, const zl_target *t)
{
    if (t == NULL)
        return ZL_ERR_ARG;
    return canvas_from(c, t->color, t->color_stride, t->width, 0, t->height, t->format);
}

zl_status zl_canvas_of_band(zl_canvas *c, const zl_band *b)
{
    if (b == NULL)
        return ZL_ERR_ARG;
    return canvas_from(c, b->color, b->color_stride, b->width, b->first_row, b->rows, b->format);
}

/* As zline packs any colour: RGB565 keeps each channel's top bits. */
zl_ov_pixel zl_ov_pack(uint8_t format, unsigned r, unsigned g, unsigned b)
{
    zl_ov_pixel p;
    memset(&p, 0, sizeof p);
    if (format == ZL_FORMAT_RGB888) {
        p.bytes[0] = (uint8_t)r;
        p.bytes[1] = (uint8_t)g;
        p.bytes[2] = (uint8_t)b;
        p.bpp = 3;
    } else {
        uint16_t v = (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
        if (format == ZL_FORMAT_RGB565_BE) {
            p.bytes[0] = (uint8_t)(v >> 8);
            p.bytes[1] = (uint8_t)(v & 0xFFu);
        } else {
            memcpy(p.bytes, &v, 2); /* native byte order */
        }
        p.bpp = 2;
    }
    return p;
}

/* Pixel (x, canvas row) of the canvas, both inside it. */
static uint8_t *pixel_at(const zl_canvas *c, int32_t x, int32_t row, unsigned bpp)
{
    return (uint8_t *)c->color + (size_t)row * (size_t)c->color_stride + (size_t)x * bpp;
}

static int32_t clamp32(int32_t v, int32_t lo, int32_t hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

void zl_ov_fill_box(const zl_canvas *c, int32_t x0, int32_t y0, int32_t x1, int32_t y1, const zl_ov_pixel *px)
{
    int32_t top = (int32_t)c->first_row, bottom = top + (int32_t)c->rows, y;
    x0 = clamp32(x0, 0, (int32_t)c->width);
    x1 = clamp32(x1, 0, (int32_t)c->width);
    y0 = clamp32(y0, top, bottom);
    y1 = clamp32(y1, top, bottom);
    for (y = y0; y < y1; y++) {
        uint8_t *p = pixel_at(c, x0, y - top, px->bpp);
        int32_t x;
        for (x = x0; x < x1; x++, p += px->bpp)
            memcpy(p, px->bytes, px->bpp);
    }
}

zl_status zl_canvas_fill_rect(const zl_canvas *c, int16_t x, int16_t y, uint16_t w, uint16_t h, zl_rgb color)
{
    zl_ov_pixel px;
    if (!zl_ov_canvas_ok(c))
        return ZL_ERR_ARG;
    px = zl_ov_pack(c->format, color.r, color.g, color.b);
    zl_ov_fill_box(c, x, y, (int32_t)x + w, (int32_t)y + h, &px);
    return ZL_OK;
}

zl_status zl_canvas_rect(const zl_canvas *c, int16_t x, int16_t y, uint16_t w, uint16_t h, zl_rgb color)
{
    int32_t x1 = (int32_t)x + w, y1 = (int32_t)y + h;
    zl_ov_pixel px;
    if (!zl_ov_canvas_ok(c))
        return ZL_ERR_ARG;
    if (w == 0 || h == 0)
        return ZL_OK;
    px = zl_ov_pack(c->format, color.r, color.g, color.b);
    zl_ov_fill_box(c, x, y, x1, (int32_t)y + 1, &px);          /* top */
    zl_ov_fill_box(c, x, y1 - 1, x1, y1, &px);                 /* bottom */
    zl_ov_fill_box(c, x, (int32_t)y + 1, (int32_t)x + 1, y1 - 1, &px); /* left */
    zl_ov_fill_box(c, x1 - 1, (int32_t)y + 1, x1, y1 - 1, &px);        /* right */
    return ZL_OK;
}

/* ------------------------------------------------------------------ images */

/* An 8-bit channel of the pixel at p (RGB565 widened by bit replication). */
static void unpack_pixel(const uint8_t *p, uint8_t format, unsigned rgb[3])
{
    uint16_t v;
    if (format == ZL_FORMAT_RGB888) {
        rgb[0] = p[0];
        rgb[1] = p[1];
        rgb[2] = p[2];
        return;
    }
    if (format == ZL_FORMAT_RGB565)
        memcpy(&v, p, 2);
    else
        v = (uint16_t)(((unsigned)p[0] << 8) | p[1]);
    rgb[0] = ((unsigned)(v >> 11) << 3) | (unsigned)(v >> 13);
    rgb[1] = (((unsigned)(v >> 5) & 63u) << 2) | (((unsigned)(v >> 5) & 63u) >> 4);
    rgb[2] = (((unsigned)v & 31u) << 3) | (((unsigned)v & 31u) >> 2);
}

/* A texel as 8-bit r, g, b and alpha (RGB565: opaque, bit replication;
 * RGBA4444: 17 times each 4-bit channel). */
static unsigned unpack_texel(uint16_t t, uint8_t texel_format, unsigned rgb[3])
{
    if (texel_format == ZL_TEXEL_RGBA4444) {
        rgb[0] = ((unsigned)(t >> 12) & 15u) * 17u;
        rgb[1] = ((unsigned)(t >> 8) & 15u) * 17u;
        rgb[2] = ((unsigned)(t >> 4) & 15u) * 17u;
        return ((unsigned)t & 15u) * 17u;
    }
    rgb[0] = ((unsigned)(t >> 11) << 3) | (unsigned)(t >> 13);
    rgb[1] = (((unsigned)(t >> 5) & 63u) << 2) | (((unsigned)(t >> 5) & 63u) >> 4);
    rgb[2] = (((unsigned)t & 31u) << 3) | (((unsigned)t & 31u) >> 2);
    return 255u;
}

/* round(x / 255) for x <= 255 * 255, in 32 bits (16-bit int safe). */
static unsigned div255_round(uint32_t x)
{
    return (unsigned)((x + 127u) / 255u);
}

static void put_texel(uint8_t *p, uint8_t format, uint16_t t, uint8_t texel_format)
{
    unsigned src[3], old[3], k;
    unsigned a = unpack_texel(t, texel_format, src);
    zl_ov_pixel px;
    if (a == 0)
        return;
    if (a < 255u) {
        unpack_pixel(p, format, old);
        for (k = 0; k < 3; k++)
            src[k] = div255_round((uint32_t)src[k] * a + (uint32_t)old[k] * (255u - a));
    }
    px = zl_ov_pack(format, src[0], src[1], src[2]);
    memcpy(p, px.bytes, px.bpp);
}

zl_status zl_canvas_image(const zl_canvas *c, int16_t x, int16_t y, const zl_texture *image)
{
    int32_t top, x0, x1, y0, y1, row;
    unsigned bpp;
    if (!zl_ov_canvas_ok(c) || image == NULL || image->texels == NULL || image->stride < image->width ||
        image->format > ZL_TEXEL_RGBA4444)
        return ZL_ERR_ARG;
    bpp = format_bpp(c->format);
    top = (int32_t)c->first_row;
    x0 = clamp32(x, 0, (int32_t)c->width);
    x1 = clamp32((int32_t)x + image->width, 0, (int32_t)c->width);
    y0 = clamp32(y, top, top + (int32_t)c->rows);
    y1 = clamp32((int32_t)y + image->height, top, top + (int32_t)c->rows);
    if (x0 >= x1 || y0 >= y1)
        return ZL_OK; /* nothing inside: (x0 - x) may be negative, no pointer may be formed from it */
    for (row = y0; row < y1; row++) {
        const uint16_t *src = image->texels + (size_t)(row - y) * image->stride + (size_t)(x0 - x);
        uint8_t *p = pixel_at(c, x0, row - top, bpp);
        int32_t col;
        for (col = x0; col < x1; col++, p += bpp)
            put_texel(p, c->format, *src++, image->format);
    }
    return ZL_OK;
}
