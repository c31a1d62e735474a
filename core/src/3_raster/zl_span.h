/*
 * Span fill: the per-pixel loops of flat and Gouraud spans, and row clears
 * (zl_span.c). The pixel helpers are inline here because the texture and
 * line loops of zl_raster.c use them per pixel too.
 */
#ifndef ZLINE_SPAN_H
#define ZLINE_SPAN_H

#include <string.h>

#include "../1_base/zl_internal.h"

/* Memory bytes of colour c in a format (2 or 3 of them). */
static inline void pack_color(zl_format f, unsigned r, unsigned g, unsigned b, uint8_t out[3])
{
    if (f == ZL_FORMAT_RGB888) {
        out[0] = (uint8_t)r;
        out[1] = (uint8_t)g;
        out[2] = (uint8_t)b;
    } else {
        uint16_t v = (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
        if (f == ZL_FORMAT_RGB565_BE) {
            out[0] = (uint8_t)(v >> 8);
            out[1] = (uint8_t)(v & 0xFFu);
        } else {
            memcpy(out, &v, 2); /* native byte order */
        }
        out[2] = 0;
    }
}

static ZL_ALWAYS_INLINE int depth_pass(unsigned func, uint32_t d, uint32_t stored)
{
    switch (func) {
    case ZL_NEVER:
        return 0;
    case ZL_LESS:
        return d < stored;
    case ZL_EQUAL:
        return d == stored;
    case ZL_LEQUAL:
        return d <= stored;
    case ZL_GREATER:
        return d > stored;
    case ZL_NOTEQUAL:
        return d != stored;
    case ZL_GEQUAL:
        return d >= stored;
    default:
        return 1;
    }
}

/* Depth of a Q14 stepper value with the rounding half already added:
 * clamped to 0..65535 (a wrapped negative value is huge). */
static ZL_ALWAYS_INLINE uint32_t depth_of(uint32_t zq)
{
    uint32_t d = zq >> 14;
    if (d > 65535u)
        d = zq >= 0x80000000u ? 0u : 65535u;
    return d;
}

/* The start of a span's depth stepper (Q14, rounding half added) from the
 * plane's value w (Q14) at its first pixel, clamped to the record's range
 * [lo14, hi14] (zlo / 4, zhi / 4). An inverted range (lo14 > hi14) marks a
 * piece of a clipped triangle, whose depth plane is the original
 * triangle's (zl_tri_set_planes): there w may leave the depth range at a
 * pixel the snapped polygon covers just beyond the near or far plane, and
 * is kept (wrapping, |w| < 2^31) so the span's next pixels stay on the
 * plane; depth_of clamps each pixel. In range, the common case, w itself. */
uint32_t zl_depth_start_clamp(int64_t w, uint32_t lo14, uint32_t hi14);
static ZL_ALWAYS_INLINE uint32_t zl_depth_start_q14(int64_t w, uint32_t lo14, uint32_t hi14)
{
    if (w >= (int64_t)lo14 && w <= (int64_t)hi14)
        return (uint32_t)w + (1u << 13);
    return zl_depth_start_clamp(w, lo14, hi14);
}

/* Write one pixel's bytes, keeping the masked-off bits of the old pixel.
 * Byte by byte, so RGB565_BE rows (a byte stream) may have any alignment;
 * the fast span loop below uses 16-bit stores when it can. */
static inline void put_pixel(uint8_t *p, unsigned bpp, const uint8_t *pix, const uint8_t *keep)
{
    p[0] = (uint8_t)((p[0] & keep[0]) | (pix[0] & (uint8_t)~keep[0]));
    p[1] = (uint8_t)((p[1] & keep[1]) | (pix[1] & (uint8_t)~keep[1]));
    if (bpp == 3)
        p[2] = (uint8_t)((p[2] & keep[2]) | (pix[2] & (uint8_t)~keep[2]));
}

/* Colour channel of a Q16 stepper value with rounding added, clamped 0..255. */
static inline unsigned channel_of(uint32_t c)
{
    uint32_t v = c >> 16;
    if (v > 255u)
        v = c >= 0x80000000u ? 0u : 255u;
    return v;
}

/* Fill n pixels of a span from column 0 of crow/zrow: depth z (Q14 with the
 * rounding half added) stepped by dz, one packed colour pix. */
void zl_span_flat(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                  const uint8_t *pix);
/* The same with Q16 colour steppers c (rounding half added) stepped by dc. */
void zl_span_gouraud(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                     const uint32_t *c, const uint32_t *dc);

#endif
