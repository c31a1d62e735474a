/* SPDX-License-Identifier: MIT */
/*
 * Stage 3, raster: rows of flat and Gouraud triangles. The span of a set-up
 * triangle on the current row and the step to the next (zl_tri_row), all rows
 * of a flat RGB565 triangle at once (zl_tri_rows_flat), and the small
 * triangles of frame mode drawn row by row without a record (zl_tiny_draw).
 */
#include <string.h>

#include "zl_raster.h"

/* depth_start's value from the plane value v at the span start: the clamp
 * moved after the shift (floor division is monotone, so clamping v to
 * [zlo 16, zhi 16] and then shifting equals shifting and then clamping to
 * [zlo / 4, zhi / 4]), so it is 32-bit work whenever v is in range. */
static ZL_ALWAYS_INLINE uint32_t depth_start_shifted(int64_t v, uint32_t lo14, uint32_t hi14)
{
    return zl_depth_start_q14(zl_floor_shift64(v, ZL_ATTR_FRAC - 14), lo14, hi14);
}

/* The depth stepper (Q14, rounding half added) at column x of the current
 * row: the Q20 plane clamped to the vertex range (zlo, zhi are Q16, so the
 * range after the shift is zlo / 4 .. zhi / 4). */
static ZL_ALWAYS_INLINE uint32_t depth_start(const zl_active *t, int64_t zrow, int32_t x)
{
    return depth_start_shifted(zrow + (int64_t)(x - t->ax) * t->z.dx, t->zlo >> 2, t->zhi >> 2);
}

static void row_span(const zl_active *t, const zl_gouraud *g, const zl_span_state *ss, uint8_t *crow,
                     uint16_t *zrow)
{
    int32_t x0 = t->left.x, x1 = t->right.x;
    uint32_t z, dz;
    if (x0 < 0)
        x0 = 0;
    if (x1 > ss->width)
        x1 = ss->width;
    if (x0 >= x1)
        return;
    z = depth_start(t, t->z.row, x0);
    dz = t->dz14;
    crow = crow ? crow + (size_t)x0 * ss->bpp : NULL;
    zrow = zrow ? zrow + x0 : NULL;
    /* A NULL row is an absent buffer, for which zl_span_state_init chose
     * bpp 0 (colour) or ZL_ALWAYS without depth write (depth): said here
     * too, so that no path to a pixel write can see a NULL row (static
     * analysis, tools/lint/run.sh). */
    if ((crow == NULL && ss->bpp != 0) || (zrow == NULL && (ss->zwrite || ss->func != ZL_ALWAYS)))
        return;
    if (g != NULL && ss->gouraud) {
        uint32_t c[3], dc[3];
        int k;
        for (k = 0; k < 3; k++) {
            int64_t v = attr_at(&g->c[k], x0, t->ax, 0, (int64_t)255 << ZL_ATTR_FRAC);
            c[k] = (uint32_t)zl_floor_shift64(v, ZL_ATTR_FRAC - 16) + (1u << 15);
            dc[k] = step32(g->c[k].dx, ZL_ATTR_FRAC - 16);
        }
        zl_span_gouraud(ss, crow, zrow, x1 - x0, z, dz, c, dc);
    } else {
        uint8_t pix[3] = {0, 0, 0};
        pack_color((zl_format)ss->format, t->rgb[0], t->rgb[1], t->rgb[2], pix);
        zl_span_flat(ss, crow, zrow, x1 - x0, z, dz, pix);
    }
}

/* Rows [j, j_end) between the long edge and one short edge (RGB565, depth
 * test func with writes); returns the long edge's N after them.
 * Kept apart from rows_flat_565 (below) on purpose (issue 13): the two share
 * their span (span565_short, zl_span.h) but not their edges and depth. Here
 * an edge is one division per row from a set-up of three numbers and depth
 * is 32-bit; rows_flat_565 steps zl_edge DDAs (two divisions each to set
 * up) and a 64-bit plane, which covers the triangles beyond tiny's 32-bit
 * bounds. Drawing the small triangles through rows_flat_565 instead (one
 * row loop) measured, Cortex-M4 -O2 with the vertex cache: bunny 1,647,631
 * -> 2,221,456 instructions (+573,825), fill 2,336,043 -> 2,346,612
 * (+10,569), tris 6,590,316 -> 9,622,158 (+3,031,842). */
/* Scanline mode draws the rows of its ZL_KIND_TINY records with
 * tiny_cols and tiny_fill (zl_span.h), this loop's row body. This loop keeps
 * its own copy: built from those helpers it measured (Cortex-M4 -O2, GCC
 * 12.2) bunny with the vertex cache 1,647,545 -> 1,663,957 (+16,412, +1.0 %)
 * and tris 6,587,244 -> 6,677,356 (+90,112), the register allocation of
 * zl_tiny_draw's four copies. */

static ZL_ALWAYS_INLINE int32_t tiny_rows(const zl_tiny *tt, const zl_span_state *ss, unsigned func, int long_left,
                                          int32_t j, int32_t j_end, int32_t nl, const zl_tiny_edge *se,
                                          uint8_t *color, int32_t color_stride, uint8_t *depth,
                                          int32_t depth_stride, uint16_t pixel, uint32_t *zrow, int32_t *lwalk)
{
    const int32_t dl = tt->lng.d, il = tt->lng.inc, ds = se->d, is = se->inc, width = ss->width;
    int32_t ns = se->n;
    uint32_t zr = *zrow;
#if ZL_MUL32_ONLY
    /* the long edge walks on from the upper rows (lwalk: its x and remainder) */
    int32_t xl = lwalk[0], rl = lwalk[1], xs = tiny_x(ns, ds), rs = xs * ds - ns;
#else
    (void)lwalk;
#endif
    color += (size_t)j * (size_t)color_stride;
    depth += (size_t)j * (size_t)depth_stride;
    for (; j < j_end; j++) {
#if ZL_MUL32_ONLY
        int32_t xa = xl, xb = xs;
#else
        int32_t xa = tiny_x(nl, dl), xb = tiny_x(ns, ds);
#endif
        int32_t x0 = long_left ? xa : xb, x1 = long_left ? xb : xa;
        x0 = x0 < 0 ? 0 : x0;
        x1 = x1 > width ? width : x1;
        if (x0 < x1) {
            uint16_t *cp = (uint16_t *)(void *)color + x0, *zb = (uint16_t *)(void *)depth + x0;
            /* the depth start of depth_start_shifted, in 32 bits (tiny_depth):
             * wrapping arithmetic, exact because the sum fits */
            int32_t v = (int32_t)(zr + (uint32_t)(x0 - tt->ax) * tt->zdx);
            uint32_t zq;
            int32_t n = x1 - x0;
            v = v < tt->zlo ? tt->zlo : (v > tt->zhi ? tt->zhi : v);
            zq = ((uint32_t)v >> (ZL_ATTR_FRAC - 14)) + tt->zbase;
            if (n > ZL_SHORT_SPAN) {
                uint8_t pix[3] = {0, 0, 0};
                memcpy(pix, &pixel, 2);
                zl_span_flat(ss, (uint8_t *)cp, zb, n, zq, tt->dz14, pix);
            } else {
                /* No clamp: these pixels are inside the triangle, where the
                 * plane is within the vertex range; the start is within 2^10
                 * (Q20) of it and each of at most ZL_SHORT_SPAN - 1 steps
                 * within one Q14 unit, so zq stays within 32 (Q14) of
                 * [0, 65535 2^14] + 2^13: below 2^30, where depth_of is a
                 * shift. (A gradient step32 clamped cannot have two pixels
                 * inside a triangle.) */
                span565_short(cp, zb, n, zq, tt->dz14, pixel, func, 1);
            }
        }
        nl += il;
        ns += is;
#if ZL_MUL32_ONLY
        tiny_walk(&xl, &rl, il, dl);
        tiny_walk(&xs, &rs, is, ds);
#endif
        zr += tt->zdy;
        color += color_stride;
        depth += depth_stride;
    }
    *zrow = zr;
#if ZL_MUL32_ONLY
    lwalk[0] = xl;
    lwalk[1] = rl;
#endif
    return nl;
}

static ZL_ALWAYS_INLINE void tiny_draw(const zl_tiny *tt, const zl_span_state *ss, unsigned func, int long_left,
                                       uint8_t *color, int32_t color_stride, uint8_t *depth, int32_t depth_stride,
                                       uint16_t pixel)
{
    uint32_t zrow = tt->zr;
    int32_t nl = tt->lng.n, lwalk[2] = {0, 0};
#if ZL_MUL32_ONLY
    lwalk[0] = tiny_x(nl, tt->lng.d); /* tiny_walk's start: one division */
    lwalk[1] = lwalk[0] * tt->lng.d - nl;
#endif
    if (tt->first < tt->mid)
        nl = tiny_rows(tt, ss, func, long_left, tt->first, tt->mid, nl, &tt->up, color, color_stride, depth,
                       depth_stride, pixel, &zrow, lwalk);
    if (tt->mid < tt->end)
        (void)tiny_rows(tt, ss, func, long_left, tt->mid, tt->end, nl, &tt->low, color, color_stride, depth,
                        depth_stride, pixel, &zrow, lwalk);
}

void zl_tiny_draw(const zl_tiny *tt, const zl_span_state *ss, uint8_t *color, int32_t color_stride, uint8_t *depth,
                  int32_t depth_stride, uint16_t pixel)
{
    /* func and the side of the long edge as constants: four loops */
    if (ss->func == ZL_LESS) {
        if (tt->long_left)
            tiny_draw(tt, ss, ZL_LESS, 1, color, color_stride, depth, depth_stride, pixel);
        else
            tiny_draw(tt, ss, ZL_LESS, 0, color, color_stride, depth, depth_stride, pixel);
    } else {
        if (tt->long_left)
            tiny_draw(tt, ss, ZL_LEQUAL, 1, color, color_stride, depth, depth_stride, pixel);
        else
            tiny_draw(tt, ss, ZL_LEQUAL, 0, color, color_stride, depth, depth_stride, pixel);
    }
}

/* ---------------------------------------- small Gouraud triangles */

/*
 * A short Gouraud span (RGB565, test func with writes) of a small triangle:
 * zl_span_gouraud's pixels (lane colour, zl_span.h: lanes (c >> 8) stepped
 * by dl) without its range checks, which cannot fail here. Its pixels are
 * inside the triangle, where the exact mix lies in 0 .. 255; the start
 * (clamped to that range, see colour_start) is within 2^10 (Q20) of it,
 * 2^6 in Q16, and each of at most ZL_SHORT_SPAN - 1 steps within one Q16
 * unit of the exact gradient: every Q16 value stays within 2^7 of
 * exact * 2^16 + 2^15, far inside 0 .. 2^24, and every lane within a few
 * units of exact * 256 + 128, inside 0 .. 0xFFFF.
 */
static ZL_ALWAYS_INLINE void gouraud_short(uint16_t *cp, uint16_t *zb, int32_t n, uint32_t z, uint32_t dz,
                                           uint32_t r, uint32_t g, uint32_t b, const int32_t *dl, unsigned func)
{
    uint32_t dr = (uint32_t)dl[0], dg = (uint32_t)dl[1], db = (uint32_t)dl[2];
    int32_t i;
    r >>= 8;
    g >>= 8;
    b >>= 8;
    for (i = 0; i < n; i++) {
        uint32_t d = z >> 14; /* unclamped: see tiny_rows */
        if (depth_pass(func, d, zb[i])) {
            zb[i] = (uint16_t)d;
            cp[i] = (uint16_t)zl_lane565(r, g, b);
        }
        z += dz;
        r += dr;
        g += dg;
        b += db;
    }
}

/* A longer span of a small Gouraud triangle: zl_span_gouraud, out of line
 * so that the short spans' colours stay in registers. */
static ZL_NOINLINE void gouraud_long(const zl_span_state *ss, uint16_t *cp, uint16_t *zb, int32_t n, uint32_t z,
                                     uint32_t dz, uint32_t r, uint32_t g, uint32_t b, const uint32_t *dc)
{
    uint32_t c[3];
    c[0] = r;
    c[1] = g;
    c[2] = b;
    zl_span_gouraud(ss, (uint8_t *)cp, zb, n, z, dz, c, dc);
}

/* The Q16 start (rounding half added) of a colour plane whose 32-bit value
 * at the span's first pixel is v: attr_at's clamp to 0 .. 255, one compare
 * when it does not bite. */
static ZL_ALWAYS_INLINE uint32_t colour_start(uint32_t v)
{
    int32_t cv = (int32_t)v;
    if (v > (UINT32_C(255) << ZL_ATTR_FRAC))
        cv = cv < 0 ? 0 : (INT32_C(255) << ZL_ATTR_FRAC);
    return ((uint32_t)cv >> (ZL_ATTR_FRAC - 16)) + (1u << 15);
}

/* Rows [j, j_end) of a small Gouraud triangle between its long edge and one
 * short edge, as tiny_rows; the colour planes' values at (ax, row) in
 * cr[0..2] (scalars in the loop, so that they stay in registers). Each
 * span starts its colours as row_span does (attr_at's clamp, then Q16 with
 * the rounding half): 32-bit values, exact at covered pixels (see
 * zl_tiny_gouraud_setup). Returns the long edge's N after them. */
static ZL_ALWAYS_INLINE int32_t tiny_gouraud_rows(const zl_tiny_gouraud *tg, const zl_span_state *ss, unsigned func,
                                                  int long_left, int32_t j, int32_t j_end, int32_t nl,
                                                  const zl_tiny_edge *se, uint8_t *color, int32_t color_stride,
                                                  uint8_t *depth, int32_t depth_stride, uint32_t *zrow,
                                                  uint32_t *cr, int32_t *lwalk)
{
    const zl_tiny *tt = &tg->t;
    const int32_t dl = tt->lng.d, il = tt->lng.inc, ds = se->d, is = se->inc, width = ss->width;
    int32_t ns = se->n;
    uint32_t zr = *zrow, rr = cr[0], gr = cr[1], br = cr[2];
#if ZL_MUL32_ONLY
    /* the edges walked as tiny_rows walks them (lwalk: the long edge's x and remainder) */
    int32_t xl = lwalk[0], rl = lwalk[1], xs = tiny_x(ns, ds), rs = xs * ds - ns;
#else
    (void)lwalk;
#endif
    color += (size_t)j * (size_t)color_stride;
    depth += (size_t)j * (size_t)depth_stride;
    for (; j < j_end; j++) {
        int32_t x0, x1;
#if ZL_MUL32_ONLY
        x0 = long_left ? xl : xs;
        x1 = long_left ? xs : xl;
        x0 = x0 < 0 ? 0 : x0;
        x1 = x1 > width ? width : x1;
#else
        tiny_cols(nl, dl, ns, ds, long_left, width, &x0, &x1);
#endif
        if (x0 < x1) {
            uint16_t *cp = (uint16_t *)(void *)color + x0, *zb = (uint16_t *)(void *)depth + x0;
            uint32_t dx = (uint32_t)(x0 - tt->ax);
            int32_t v = (int32_t)(zr + dx * tt->zdx), n = x1 - x0;
            uint32_t zq, r, g, b;
            v = v < tt->zlo ? tt->zlo : (v > tt->zhi ? tt->zhi : v);
            zq = ((uint32_t)v >> (ZL_ATTR_FRAC - 14)) + tt->zbase;
            r = colour_start(rr + dx * tg->c.cdx[0]);
            g = colour_start(gr + dx * tg->c.cdx[1]);
            b = colour_start(br + dx * tg->c.cdx[2]);
            if (n <= ZL_SHORT_SPAN)
                gouraud_short(cp, zb, n, zq, tt->dz14, r, g, b, tg->c.dl, func);
            else
                gouraud_long(ss, cp, zb, n, zq, tt->dz14, r, g, b, tg->c.dc16);
        }
        nl += il;
        ns += is;
#if ZL_MUL32_ONLY
        tiny_walk(&xl, &rl, il, dl);
        tiny_walk(&xs, &rs, is, ds);
#endif
        zr += tt->zdy;
        rr += tg->c.cdy[0];
        gr += tg->c.cdy[1];
        br += tg->c.cdy[2];
        color += color_stride;
        depth += depth_stride;
    }
    *zrow = zr;
    cr[0] = rr;
    cr[1] = gr;
    cr[2] = br;
#if ZL_MUL32_ONLY
    lwalk[0] = xl;
    lwalk[1] = rl;
#endif
    return nl;
}

/* One span of a ZL_KIND_TINY_GOURAUD record (its fields: ZL_KIND_TINY's),
 * exactly tiny_gouraud_rows' span on that row. */
static ZL_ALWAYS_INLINE void tiny_gouraud_span(const zl_active *a, const zl_tiny_colour *tc, const zl_span_state *ss,
                                               unsigned func, int32_t x0, int32_t x1, uint8_t *crow, uint16_t *zrow)
{
    uint16_t *cp = (uint16_t *)(void *)crow + x0, *zb = zrow + x0;
    uint32_t dx = (uint32_t)(x0 - a->ax);
    int32_t v = (int32_t)((uint32_t)a->right.rem + dx * (uint32_t)a->left.rstep), n = x1 - x0;
    int32_t zlo = (int32_t)a->zlo, zhi = (int32_t)a->zhi;
    uint32_t zq, r, g, b;
    v = v < zlo ? zlo : (v > zhi ? zhi : v);
    zq = ((uint32_t)v >> (ZL_ATTR_FRAC - 14)) + (uint32_t)a->left.rem;
    r = colour_start(tc->cr[0] + dx * tc->cdx[0]);
    g = colour_start(tc->cr[1] + dx * tc->cdx[1]);
    b = colour_start(tc->cr[2] + dx * tc->cdx[2]);
    if (n <= ZL_SHORT_SPAN)
        gouraud_short(cp, zb, n, zq, a->dz14, r, g, b, tc->dl, func);
    else
        gouraud_long(ss, cp, zb, n, zq, a->dz14, r, g, b, tc->dc16);
}

void zl_tiny_gouraud_span(const zl_active *a, const zl_tiny_colour *tc, const zl_span_state *ss, int32_t x0,
                          int32_t x1, uint8_t *crow, uint16_t *zrow)
{
    if (ss->func == ZL_LESS)
        tiny_gouraud_span(a, tc, ss, ZL_LESS, x0, x1, crow, zrow);
    else
        tiny_gouraud_span(a, tc, ss, ZL_LEQUAL, x0, x1, crow, zrow);
}

static ZL_ALWAYS_INLINE void tiny_gouraud_draw(const zl_tiny_gouraud *tg, const zl_span_state *ss, unsigned func,
                                               int long_left, uint8_t *color, int32_t color_stride, uint8_t *depth,
                                               int32_t depth_stride)
{
    const zl_tiny *tt = &tg->t;
    uint32_t zrow = tt->zr, cr[3];
    int32_t nl = tt->lng.n, lwalk[2] = {0, 0};
#if ZL_MUL32_ONLY
    lwalk[0] = tiny_x(nl, tt->lng.d); /* tiny_walk's start: one division */
    lwalk[1] = lwalk[0] * tt->lng.d - nl;
#endif
    cr[0] = tg->c.cr[0];
    cr[1] = tg->c.cr[1];
    cr[2] = tg->c.cr[2];
    if (tt->first < tt->mid)
        nl = tiny_gouraud_rows(tg, ss, func, long_left, tt->first, tt->mid, nl, &tt->up, color, color_stride, depth,
                               depth_stride, &zrow, cr, lwalk);
    if (tt->mid < tt->end)
        (void)tiny_gouraud_rows(tg, ss, func, long_left, tt->mid, tt->end, nl, &tt->low, color, color_stride, depth,
                                depth_stride, &zrow, cr, lwalk);
}

void zl_tiny_gouraud_draw(const zl_tiny_gouraud *tg, const zl_span_state *ss, uint8_t *color, int32_t color_stride,
                          uint8_t *depth, int32_t depth_stride)
{
    /* func and the side of the long edge as constants: four loops */
    if (ss->func == ZL_LESS) {
        if (tg->t.long_left)
            tiny_gouraud_draw(tg, ss, ZL_LESS, 1, color, color_stride, depth, depth_stride);
        else
            tiny_gouraud_draw(tg, ss, ZL_LESS, 0, color, color_stride, depth, depth_stride);
    } else {
        if (tg->t.long_left)
            tiny_gouraud_draw(tg, ss, ZL_LEQUAL, 1, color, color_stride, depth, depth_stride);
        else
            tiny_gouraud_draw(tg, ss, ZL_LEQUAL, 0, color, color_stride, depth, depth_stride);
    }
}

int zl_tiny_span_state(const zl_span_state *ss, const void *color, int32_t color_stride, const void *depth)
{
    return color != NULL && depth != NULL && ss->format == ZL_FORMAT_RGB565 && ss->bpp == 2 && ss->zwrite &&
           ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)color & 1u) == 0 && (color_stride & 1) == 0 &&
           (ss->func == ZL_LESS || ss->func == ZL_LEQUAL);
}

/*
 * Kept apart from tiny_rows (above) on purpose: see there for why and the
 * measured cost of one loop for both.
 * The rows of a flat triangle in the common case: RGB565 (native order,
 * aligned rows, every channel), depth test `func` (LESS or LEQUAL, a
 * constant at each call) with depth writes. Short spans are written here,
 * pixel by pixel exactly as zl_span_flat writes them (the depth clamp
 * included); the loop keeps the edges' positions and errors in locals.
 */
static ZL_ALWAYS_INLINE void rows_flat_565(const zl_active *t, const zl_span_state *ss, unsigned func,
                                           uint8_t *color, int32_t color_stride, uint8_t *depth,
                                           int32_t depth_stride, const uint8_t *pix, int32_t dx32)
{
    int32_t lx = t->left.x, lrem = t->left.rem, rx = t->right.x, rrem = t->right.rem;
    const zl_edge *le = &t->left, *re = &t->right;
    int32_t row = t->row, width = ss->width;
    int64_t zrow = t->z.row;
    uint32_t dz = t->dz14, lo14 = t->zlo >> 2, hi14 = t->zhi >> 2; /* the clamp range after the shift */
    uint16_t pixel;
    memcpy(&pixel, pix, 2);
    color += (size_t)row * (size_t)color_stride;
    depth += (size_t)row * (size_t)depth_stride;
    for (;;) {
        int32_t x0 = lx < 0 ? 0 : lx, x1 = rx > width ? width : rx, n = x1 - x0;
        if (n > 0) {
            uint16_t *c = (uint16_t *)(void *)color + x0, *zb = (uint16_t *)(void *)depth + x0;
            uint32_t z = depth_start_shifted(zrow + (int64_t)(x0 - t->ax) * dx32, lo14, hi14);
            if (n > ZL_SHORT_SPAN) {
                zl_span_flat(ss, (uint8_t *)c, zb, n, z, dz, pix);
            } else {
                span565_short(c, zb, n, z, dz, pixel, func, 0);
            }
        }
        if (++row >= t->end)
            return;
        /* edge_step on the locals */
        lx += le->step;
        lrem -= le->rstep;
        if (lrem < 0) {
            lrem += le->den;
            lx++;
        }
        rx += re->step;
        rrem -= re->rstep;
        if (rrem < 0) {
            rrem += re->den;
            rx++;
        }
        zrow += t->z.dy;
        color += color_stride;
        depth += depth_stride;
        if (row == t->mid) {
            if (t->lower_is_left) {
                le = &t->lower;
                lx = le->x;
                lrem = le->rem;
            } else {
                re = &t->lower;
                rx = re->x;
                rrem = re->rem;
            }
        }
    }
}

/*
 * Every row of a flat-shaded triangle into a whole target (frame mode): the
 * same spans as zl_tri_row row by row, with the edges and the depth row in
 * locals, so a row costs its span and two edge steps. The record is left
 * as set up. Rows are color_stride / depth_stride bytes apart; a NULL
 * buffer is one the span state does not write (zl_span_state_init).
 */
void zl_tri_rows_flat(const zl_active *t, const zl_span_state *ss, uint8_t *color, int32_t color_stride,
                      uint8_t *depth, int32_t depth_stride)
{
    zl_edge left = t->left, right = t->right;
    int64_t zrow = t->z.row;
    int32_t row = t->row, width = ss->width;
    unsigned bpp = ss->bpp;
    uint8_t pix[3] = {0, 0, 0};
    if ((color == NULL && bpp != 0) || (depth == NULL && (ss->zwrite || ss->func != ZL_ALWAYS)))
        return; /* as in row_span */
    pack_color((zl_format)ss->format, t->rgb[0], t->rgb[1], t->rgb[2], pix);
    if (ZL_FAST_PATHS && color != NULL && depth != NULL && ss->format == ZL_FORMAT_RGB565 && bpp == 2 &&
        ss->zwrite && ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)color & 1u) == 0 &&
        (color_stride & 1) == 0 && t->z.dx >= INT32_MIN && t->z.dx <= INT32_MAX) { /* (off: zl_config.h) */
        if (ss->func == ZL_LESS) {
            rows_flat_565(t, ss, ZL_LESS, color, color_stride, depth, depth_stride, pix, (int32_t)t->z.dx);
            return;
        }
        if (ss->func == ZL_LEQUAL) {
            rows_flat_565(t, ss, ZL_LEQUAL, color, color_stride, depth, depth_stride, pix, (int32_t)t->z.dx);
            return;
        }
    }
    if (color != NULL)
        color += (size_t)row * (size_t)color_stride;
    if (depth != NULL)
        depth += (size_t)row * (size_t)depth_stride;
    for (;;) {
        int32_t x0 = left.x < 0 ? 0 : left.x, x1 = right.x > width ? width : right.x;
        if (x0 < x1)
            zl_span_flat(ss, color != NULL ? color + (size_t)x0 * bpp : NULL,
                         depth != NULL ? (uint16_t *)(void *)depth + x0 : NULL, x1 - x0, depth_start(t, zrow, x0),
                         t->dz14, pix);
        if (++row >= t->end)
            return;
        edge_step(&left);
        edge_step(&right);
        zrow += t->z.dy;
        if (color != NULL)
            color += color_stride;
        if (depth != NULL)
            depth += depth_stride;
        if (row == t->mid) {
            if (t->lower_is_left)
                left = t->lower;
            else
                right = t->lower;
        }
    }
}

int zl_tri_row(zl_active *t, zl_gouraud *g, const zl_span_state *ss, uint8_t *color_row,
               uint16_t *depth_row)
{
    int k;
    row_span(t, g, ss, color_row, depth_row);
    edge_step(&t->left);
    edge_step(&t->right);
    t->z.row += t->z.dy;
    if (g != NULL && ss->gouraud)
        for (k = 0; k < 3; k++)
            g->c[k].row += g->c[k].dy;
    t->row++;
    if (t->row == t->mid && t->row < t->end) {
        if (t->lower_is_left)
            t->left = t->lower;
        else
            t->right = t->lower;
    }
    return t->row < t->end;
}
