/* Span fill (see zl_span.h): the loops every flat and Gouraud pixel runs. */
#include "zl_span.h"

void zl_span_state_init(zl_span_state *ss, const zl_state *st, int has_depth, int has_color,
                        zl_format format, uint16_t width)
{
    uint8_t m[3];
    int test = st->depth_test && has_depth;
    ss->func = test ? st->depth_func : (uint8_t)ZL_ALWAYS;
    ss->zwrite = (uint8_t)(test && st->depth_write);
    ss->bpp = has_color ? (uint8_t)zl_format_bytes(format) : 0;
    ss->format = (uint8_t)format;
    ss->gouraud = st->shading == ZL_SHADE_GOURAUD;
    ss->width = width;
    /* The mask's own bit pattern: a colour with the written channels at 255. */
    pack_color(format, (st->color_mask & ZL_MASK_R) ? 255u : 0u, (st->color_mask & ZL_MASK_G) ? 255u : 0u,
               (st->color_mask & ZL_MASK_B) ? 255u : 0u, m);
    ss->keep[0] = (uint8_t)~m[0];
    ss->keep[1] = (uint8_t)~m[1];
    ss->keep[2] = (uint8_t)~m[2];
}

/* Whether a 32-bit stepper stays inside [0, limit) over n pixels: then the
 * per-pixel clamps can go (both ends checked; the values are linear). */
static int stays_below(uint32_t start, uint32_t step, int32_t n, uint32_t limit)
{
    int64_t end = (int64_t)start + (int64_t)(n - 1) * (int32_t)step;
    return start < limit && end >= 0 && end < (int64_t)limit;
}

/* The common case in its own loop: RGB565 (either byte order), all channels,
 * depth LESS or LEQUAL with write. `func` and `clamp` are constants at each
 * call, so the compiler specialises the loop: without clamping it is a shift,
 * a compare, two stores and an add per pixel. */
static inline void span_flat_565(unsigned func, int clamp, uint16_t *crow, uint16_t *zrow, int32_t n,
                                 uint32_t z, uint32_t dz, uint16_t pixel)
{
    int32_t i;
    for (i = 0; i < n; i++) {
        uint32_t d = clamp ? depth_of(z) : z >> 14;
        if (depth_pass(func, d, zrow[i])) {
            zrow[i] = (uint16_t)d;
            crow[i] = pixel;
        }
        z += dz;
    }
}

void zl_span_flat(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                      uint32_t dz, const uint8_t *pix)
{
    unsigned func = ss->func, bpp = ss->bpp;
    int32_t i;
    if (bpp == 2 && ss->zwrite && ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)crow & 1u) == 0 &&
        (func == ZL_LESS || func == ZL_LEQUAL)) {
        uint16_t pixel, *c16 = (uint16_t *)(void *)crow;
        int exact = stays_below(z, dz, n, 65536u << 14);
        memcpy(&pixel, pix, 2);
        if (func == ZL_LESS && exact)
            span_flat_565(ZL_LESS, 0, c16, zrow, n, z, dz, pixel);
        else if (func == ZL_LESS)
            span_flat_565(ZL_LESS, 1, c16, zrow, n, z, dz, pixel);
        else if (exact)
            span_flat_565(ZL_LEQUAL, 0, c16, zrow, n, z, dz, pixel);
        else
            span_flat_565(ZL_LEQUAL, 1, c16, zrow, n, z, dz, pixel);
        return;
    }
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (func == ZL_ALWAYS || depth_pass(func, d, zrow[i])) {
            if (ss->zwrite)
                zrow[i] = (uint16_t)d;
            if (bpp != 0)
                put_pixel(crow + (size_t)i * bpp, bpp, pix, ss->keep);
        }
        z += dz;
    }
}

static void span_gouraud_generic(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                                 uint32_t dz, const uint32_t *c, const uint32_t *dc);

/* Gouraud into RGB565 with no clamping needed (checked per span): the
 * channels are packed straight from their Q16 steppers. `swap` stores the
 * byte-swapped value (RGB565_BE on a little-endian machine). */
static inline void span_gouraud_565(unsigned func, int swap, uint16_t *crow, uint16_t *zrow, int32_t n,
                                    uint32_t z, uint32_t dz, const uint32_t *c, const uint32_t *dc)
{
    uint32_t r = c[0], g = c[1], b = c[2];
    int32_t i;
    for (i = 0; i < n; i++) {
        uint32_t d = z >> 14;
        if (depth_pass(func, d, zrow[i])) {
            uint32_t v = ((r >> 8) & 0xF800u) | ((g >> 13) & 0x07E0u) | (b >> 19);
            zrow[i] = (uint16_t)d;
            crow[i] = (uint16_t)(swap ? ((v >> 8) | (v << 8)) : v);
        }
        z += dz;
        r += dc[0];
        g += dc[1];
        b += dc[2];
    }
}

static int little_endian(void)
{
    const uint16_t probe = 1;
    uint8_t first;
    memcpy(&first, &probe, 1);
    return first == 1;
}

/* The Gouraud fast path applies: RGB565, every channel, LESS or LEQUAL with
 * depth write, an aligned row, and no stepper leaving its range. */
static int gouraud_fast(const zl_span_state *ss, const uint8_t *crow, int32_t n, uint32_t z, uint32_t dz,
                        const uint32_t *c, const uint32_t *dc)
{
    int k;
    if (ss->bpp != 2 || !ss->zwrite || ss->keep[0] != 0 || ss->keep[1] != 0 || ((uintptr_t)crow & 1u) != 0 ||
        (ss->func != ZL_LESS && ss->func != ZL_LEQUAL) || !stays_below(z, dz, n, 65536u << 14))
        return 0;
    for (k = 0; k < 3; k++)
        if (!stays_below(c[k], dc[k], n, 256u << 16))
            return 0;
    return 1;
}

void zl_span_gouraud(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                         uint32_t dz, const uint32_t *c, const uint32_t *dc)
{
    if (gouraud_fast(ss, crow, n, z, dz, c, dc)) {
        uint16_t *c16 = (uint16_t *)(void *)crow;
        int swap = ss->format == ZL_FORMAT_RGB565_BE && little_endian();
        if (ss->func == ZL_LESS && swap)
            span_gouraud_565(ZL_LESS, 1, c16, zrow, n, z, dz, c, dc);
        else if (ss->func == ZL_LESS)
            span_gouraud_565(ZL_LESS, 0, c16, zrow, n, z, dz, c, dc);
        else if (swap)
            span_gouraud_565(ZL_LEQUAL, 1, c16, zrow, n, z, dz, c, dc);
        else
            span_gouraud_565(ZL_LEQUAL, 0, c16, zrow, n, z, dz, c, dc);
        return;
    }
    span_gouraud_generic(ss, crow, zrow, n, z, dz, c, dc);
}

static void span_gouraud_generic(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                                 uint32_t dz, const uint32_t *c, const uint32_t *dc)
{
    uint32_t r = c[0], g = c[1], b = c[2];
    unsigned func = ss->func, bpp = ss->bpp;
    int32_t i;
    uint8_t pix[3] = {0, 0, 0};
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (func == ZL_ALWAYS || depth_pass(func, d, zrow[i])) {
            if (ss->zwrite)
                zrow[i] = (uint16_t)d;
            if (bpp != 0) {
                pack_color((zl_format)ss->format, channel_of(r), channel_of(g), channel_of(b), pix);
                put_pixel(crow + (size_t)i * bpp, bpp, pix, ss->keep);
            }
        }
        z += dz;
        r += dc[0];
        g += dc[1];
        b += dc[2];
    }
}

void zl_fill16(uint16_t *p, uint16_t v, uint32_t n)
{
    /* Clears are a large share of a small frame: two pixels per 32-bit store
     * once p is 4-byte aligned. The uint32_t view of the same bytes is the
     * usual way to fill a buffer; the values agree whatever the byte order. */
    uint32_t pair;
    uint16_t two[2];
    two[0] = v;
    two[1] = v;
    memcpy(&pair, two, 4);
    if (n > 0 && ((uintptr_t)p & 3u) != 0) {
        *p++ = v;
        n--;
    }
    {
        uint32_t *q = (uint32_t *)(void *)p, k;
        for (k = 0; k < n / 2; k++)
            q[k] = pair;
    }
    if (n & 1u)
        p[n - 1] = v;
}

void zl_fill_color_row(uint8_t *row, const zl_span_state *ss, zl_rgb c)
{
    uint8_t pix[3] = {0, 0, 0};
    uint16_t i;
    pack_color((zl_format)ss->format, c.r, c.g, c.b, pix);
    if (ss->bpp == 2 && ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)row & 1u) == 0) {
        uint16_t v;
        memcpy(&v, pix, 2);
        zl_fill16((uint16_t *)(void *)row, v, ss->width);
        return;
    }
    for (i = 0; i < ss->width; i++)
        put_pixel(row + (size_t)i * ss->bpp, ss->bpp, pix, ss->keep);
}
