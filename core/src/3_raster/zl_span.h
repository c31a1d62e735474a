/* SPDX-License-Identifier: MIT */
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
    if (ZL_FEATURE_FORMATS && f == ZL_FORMAT_RGB888) { /* off, RGB565 only (zl_init, zl_frame_begin) */
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
    if (!ZL_FEATURE_DEPTH_FUNCS) /* compiled out (zl_config.h): LESS, LEQUAL or ALWAYS (zl_state_check) */
        return func == ZL_LESS ? d < stored : (func == ZL_LEQUAL ? d <= stored : 1);
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

/*
 * The short RGB565 span of the row loops (zl_rows.c's rows_flat_565 and
 * tiny_rows, zl_frame_rows.c's span_565): n pixels of colour `pixel` at c
 * and depth at zb, depth z (Q14, rounding half added) stepped by dz, test
 * `func` (ZL_LESS or ZL_LEQUAL, a constant at each call), depth written:
 * exactly what zl_span_flat writes. `unclamped` (a constant): the caller
 * knows z stays below 2^30, where depth_of is the shift alone.
 */
static ZL_ALWAYS_INLINE void span565_short(uint16_t *c, uint16_t *zb, int32_t n, uint32_t z, uint32_t dz,
                                          uint16_t pixel, unsigned func, int unclamped)
{
    int32_t i;
    for (i = 0; i < n; i++) {
        uint32_t d = unclamped ? z >> 14 : depth_of(z);
        if (depth_pass(func, d, zb[i])) {
            zb[i] = (uint16_t)d;
            c[i] = pixel;
        }
        z += dz;
    }
}

/* Spans up to this many pixels are filled in place by the row loops;
 * longer ones go to zl_span_flat, whose loops pay a set-up to run faster
 * per pixel. */
#define ZL_SHORT_SPAN 6

void zl_span_flat(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                  const uint8_t *pix);

/* ceil(n / d), d > 0: C division truncates, which is the ceiling below 0. */
static ZL_ALWAYS_INLINE int32_t tiny_x(int32_t n, int32_t d)
{
    int32_t q = n / d;
    return q * d < n ? q + 1 : q;
}

/* The pixel-pair helpers of zl_span.c's flat loops and zl_span_tex.c's
 * blend tables. */
/* Two pixels per step need little-endian 16-bit pairs in a 32-bit word. */
static inline int little_endian(void)
{
    const uint16_t probe = 1;
    uint8_t first;
    memcpy(&first, &probe, 1);
    return first == 1;
}

/* Tell the compiler a row pointer is 4-byte aligned (checked by the caller),
 * so that the memcpy of a pixel pair is one 32-bit load or store even where
 * unaligned access is not allowed (Cortex-M0). */
#if defined(__GNUC__)
#define ZL_ALIGNED4(p) __builtin_assume_aligned((p), 4)
#else
#define ZL_ALIGNED4(p) ((void *)(p))
#endif

/* Two 16-bit values at p as one 32-bit word (little-endian: p[0] low). The
 * memcpy is free of aliasing trouble and compiles to one load or store. */
static ZL_ALWAYS_INLINE uint32_t pair_load(const uint16_t *p)
{
    uint32_t w;
    memcpy(&w, ZL_ALIGNED4(p), 4);
    return w;
}

static ZL_ALWAYS_INLINE void pair_store(uint16_t *p, uint32_t w)
{
    memcpy(ZL_ALIGNED4(p), &w, 4);
}

/* The pair loops keep depth as y = z << 2 (exact: z < 2^30 on an exact span),
 * so y's top half is the depth d, and both tests of a pair come straight from
 * the stored pair w: d0 against w's low half (y0 < s0 << 16 is d0 < s0),
 * d1 against its high half. */
static ZL_ALWAYS_INLINE int pair_pass(unsigned func, uint32_t y0, uint32_t y1, uint32_t w)
{
    if (func == ZL_LESS)
        return y0 < (w << 16) && (y1 >> 16) < (w >> 16);
    return (y0 >> 16) <= (w & 0xFFFFu) && (y1 >> 16) <= (w >> 16);
}

#if ZL_MUL32_ONLY
/* No divide instruction (ZL_MUL32_ONLY): an edge's x = ceil(n / d) is
 * divided once, then walked from row to row with its remainder r = x d - n
 * in [0, d): n grows by inc, and x moves one column per d the remainder
 * leaves [0, d) by. Exactly tiny_x's value on every row; the steps add up
 * to the edge's travel in columns, which the triangle's rows span anyway.
 * zl_tiny_draw's rows and scanline mode's ZL_KIND_TINY records use it. */
static ZL_ALWAYS_INLINE void tiny_walk(int32_t *x, int32_t *r, int32_t inc, int32_t d)
{
    int32_t xv = *x, rv = *r - inc;
    while (rv < 0) {
        rv += d;
        xv++;
    }
    while (rv >= d) {
        rv -= d;
        xv--;
    }
    *x = xv;
    *r = rv;
}
#endif

/*
 * One row of a small triangle (zl_tiny, zl_internal.h), shared by frame
 * mode's tiny_rows (zl_rows.c) and scanline mode's ZL_KIND_TINY records
 * (zl_frame_rows.c). tiny_cols: its columns [*x0, *x1), from ceil(nl / dl)
 * (the long edge) to ceil(ns / ds) (the short one), sides by long_left,
 * clipped to [0, width). tiny_fill, for x0 < x1: depth from the 32-bit
 * plane zr (at column ax of this row) stepped by zdx, clamped to [zlo, zhi]
 * and shifted plus zbase (zl_setup_fast.c's tiny_depth); colour `pixel`
 * (native RGB565) at crow, depth at zrow, test func (ZL_LESS or ZL_LEQUAL,
 * a constant) with writes. Two helpers, so a caller loads the plane only
 * for a row with pixels. zl_rows.c's tiny_rows keeps a copy of this row
 * body: it says why, with the measured cost of using these.
 */
static ZL_ALWAYS_INLINE void tiny_cols(int32_t nl, int32_t dl, int32_t ns, int32_t ds, int long_left, int32_t width,
                                       int32_t *x0, int32_t *x1)
{
    int32_t xa = tiny_x(nl, dl), xb = tiny_x(ns, ds);
    int32_t a = long_left ? xa : xb, b = long_left ? xb : xa;
    *x0 = a < 0 ? 0 : a;
    *x1 = b > width ? width : b;
}

static ZL_ALWAYS_INLINE void tiny_fill(const zl_span_state *ss, unsigned func, int32_t x0, int32_t x1, uint32_t zr,
                                       uint32_t zdx, int32_t zlo, int32_t zhi, uint32_t zbase, uint32_t dz14,
                                       int32_t ax, uint16_t *crow, uint16_t *zrow, uint16_t pixel)
{
    uint16_t *cp = crow + x0, *zb = zrow + x0;
    /* the depth start of depth_start_shifted, in 32 bits (tiny_depth):
     * wrapping arithmetic, exact because the sum fits */
    int32_t v = (int32_t)(zr + (uint32_t)(x0 - ax) * zdx);
    uint32_t zq;
    int32_t n = x1 - x0;
    v = v < zlo ? zlo : (v > zhi ? zhi : v);
    zq = ((uint32_t)v >> (ZL_ATTR_FRAC - 14)) + zbase;
    if (n > ZL_SHORT_SPAN) {
        uint8_t pix[3] = {0, 0, 0};
        memcpy(pix, &pixel, 2);
        zl_span_flat(ss, (uint8_t *)cp, zb, n, zq, dz14, pix);
    } else {
        /* No clamp: these pixels are inside the triangle, where the
         * plane is within the vertex range; the start is within 2^10
         * (Q20) of it and each of at most ZL_SHORT_SPAN - 1 steps
         * within one Q14 unit, so zq stays within 32 (Q14) of
         * [0, 65535 2^14] + 2^13: below 2^30, where depth_of is a
         * shift. (A gradient step32 clamped cannot have two pixels
         * inside a triangle.) */
        span565_short(cp, zb, n, zq, dz14, pixel, func, 1);
    }
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
    if (ZL_FEATURE_FORMATS && bpp == 3) /* off, RGB565 only */
        p[2] = (uint8_t)((p[2] & keep[2]) | (pix[2] & (uint8_t)~keep[2]));
}

/* Colour channel of a Q16 stepper value with rounding added, clamped 0..255. */
static inline unsigned channel_of(uint32_t c)
{
    uint32_t v = c >> 16;
    if (v > 255u)
        v = c >= 0x80000000u ? 0u : 255u;
    return (unsigned)v;
}

/*
 * Lane colour: how every RGB565 Gouraud pixel (either byte order) gets its
 * colour, the bound of zline.h's Gouraud clause. A span with Q16 colour
 * steppers c (rounding half added) and steps dc is cut into chunks of
 * ZL_LANE_CHUNK pixels from its first; at pixel k of a chunk whose steppers
 * start at c, each channel is the 8.8 value (a "lane")
 *     l_k = (c >> 8) + k d,   d = zl_lane_step(dc) = round(dc / 256),
 * and the pixel is zl_lane565 of the three: their top 5, 6, 5 bits. A
 * chunk whose lanes would leave 0 .. 0xFFFF takes the Q16 steppers
 * instead (clamped, as RGB888 always does). Two lanes fit a 32-bit word,
 * so the pair loop steps a channel of two pixels with one add and packs a
 * pair in five instructions (zl_span.c); the value does not depend on the
 * loop that writes it, so frame and scanline modes agree. Precision: the
 * start is below the stepper by under 1/256, the step off by at most 1/512
 * (+ 1/65536 from dc) a pixel, so over 511 steps a lane stays within about
 * 1 (8-bit units) of the stepper, itself the exact mix + 0.5: within one
 * RGB565 step (4 or 8 units) of the exact value.
 */
#define ZL_LANE_CHUNK 512
static ZL_ALWAYS_INLINE int32_t zl_lane_step(uint32_t dc)
{
    return zl_floor_shift32((int32_t)dc + (1 << 7), 8);
}
static ZL_ALWAYS_INLINE uint32_t zl_lane565(uint32_t r, uint32_t g, uint32_t b)
{
    return (r & 0xF800u) | ((g & 0xFC00u) >> 5) | (b >> 11);
}

/* Fill n pixels of a span from column 0 of crow/zrow: depth z (Q14 with the
 * rounding half added) stepped by dz, one packed colour pix. */
void zl_span_flat(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                  const uint8_t *pix);
/* The same with Q16 colour steppers c (rounding half added) stepped by dc;
 * RGB565 (either byte order) in lane colour (above). */
void zl_span_gouraud(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                     const uint32_t *c, const uint32_t *dc);

#endif
