/* SPDX-License-Identifier: MIT */
/*
 * Stage 4, primitives: the rows of lines and points (the LINE RULE of
 * zline.h): one record per segment stepped along its major axis, depth
 * tested and written per pixel, and the anti-aliased coverage blend.
 */
#include <string.h>

#include "../3_raster/zl_raster.h"

/* ------------------------------------------------------ lines and points */

/* Stored depth of a Q32 line depth, clamped to the range. */
static inline uint32_t line_depth(int64_t zq32)
{
    int64_t d = zl_floor_shift64(zq32 + ((int64_t)1 << 31), 32);
    return (uint32_t)clamp64(d, 0, 65535);
}

static inline void plot(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t x, uint32_t d,
                        const uint8_t *pix)
{
    unsigned func = ss->func;
    if (x < 0 || x >= ss->width)
        return;
    if (func != ZL_ALWAYS && !depth_pass(func, d, zrow[x]))
        return;
    if (ss->zwrite)
        zrow[x] = (uint16_t)d;
    if (ss->bpp != 0)
        put_pixel(crow + (size_t)x * ss->bpp, ss->bpp, pix, ss->keep);
}

/* Blend colour (r, g, b) into pixel x with weight w (0..255), after the
 * depth test; antialiased lines never write depth. */
static void blend(const zl_span_state *ss, const zl_active *t, uint8_t *crow, uint16_t *zrow, int32_t x, uint32_t d,
                  unsigned w)
{
    uint8_t *p, pix[3] = {0, 0, 0};
    unsigned old[3], k;
    if (w == 0 || x < 0 || x >= ss->width || ss->bpp == 0)
        return;
    if (ss->func != ZL_ALWAYS && !depth_pass(ss->func, d, zrow[x]))
        return;
    p = crow + (size_t)x * ss->bpp;
    if (ss->format == ZL_FORMAT_RGB888) {
        old[0] = p[0];
        old[1] = p[1];
        old[2] = p[2];
    } else {
        uint16_t v;
        unsigned r5, g6, b5;
        if (ss->format == ZL_FORMAT_RGB565)
            memcpy(&v, p, 2);
        else
            v = (uint16_t)(((unsigned)p[0] << 8) | p[1]);
        r5 = v >> 11;
        g6 = (v >> 5) & 63u;
        b5 = v & 31u;
        old[0] = (r5 << 3) | (r5 >> 2);
        old[1] = (g6 << 2) | (g6 >> 4);
        old[2] = (b5 << 3) | (b5 >> 2);
    }
    for (k = 0; k < 3; k++)
        old[k] = (old[k] * (255u - w) + t->rgb[k] * w + 127u) / 255u;
    pack_color((zl_format)ss->format, old[0], old[1], old[2], pix);
    put_pixel(p, ss->bpp, pix, ss->keep);
}

/* Weight (0..255) of the pixel below the ideal line: its distance to the
 * upper pixel's centre, the fraction f / D of a pixel. */
static inline unsigned aa_weight(const zl_edge *e)
{
    int64_t f = (int64_t)e->den - 1 - e->rem;
    return (unsigned)((f * 255 + e->den / 2) / e->den);
}

static void aa_step(zl_active *t)
{
    t->ax += t->right.step;
    edge_step(&t->left);
    t->z.row += t->z.dx;
    t->right.x--;
}

/* Antialiased line row: two pixels per column (x-major) or row (y-major),
 * rows floor(n) and floor(n) + 1 of the ideal minor coordinate n, weighted
 * by their distance to it. An x-major row r takes the columns whose floor(n)
 * is r - 1 (as the lower pixel) or r (as the upper one); the record stays at
 * the first column of the row's run. */
static int aa_row(zl_active *t, const zl_span_state *ss, uint8_t *crow, uint16_t *zrow)
{
    int32_t r = t->row;
    if (!t->lower_is_left) {
        unsigned w = aa_weight(&t->left);
        uint32_t d = line_depth(t->z.row);
        blend(ss, t, crow, zrow, t->left.x, d, 255u - w);
        blend(ss, t, crow, zrow, t->left.x + 1, d, w);
        if (t->right.x > 1)
            aa_step(t);
        else
            t->row = t->end;
    } else {
        zl_active l = *t;
        int saved = 0;
        while (l.right.x > 0 && l.left.x <= r) {
            unsigned w = aa_weight(&l.left);
            uint32_t d = line_depth(l.z.row);
            if (l.left.x == r - 1) {
                blend(ss, t, crow, zrow, l.ax, d, w);
            } else {
                if (!saved) {
                    t->left = l.left;
                    t->ax = l.ax;
                    t->right.x = l.right.x;
                    t->z.row = l.z.row;
                    saved = 1;
                }
                blend(ss, t, crow, zrow, l.ax, d, 255u - w);
            }
            aa_step(&l);
        }
        if (!saved) {
            /* nothing of this run reaches the next row's upper pixels */
            t->left = l.left;
            t->ax = l.ax;
            t->right.x = l.right.x;
            t->z.row = l.z.row;
            if (l.right.x == 0)
                t->row = t->end;
        }
    }
    if (t->row < t->end)
        t->row++;
    return t->row < t->end;
}

int zl_prim_row(zl_active *t, const zl_span_state *ss, uint8_t *color_row, uint16_t *depth_row)
{
    uint8_t pix[3] = {0, 0, 0};
    if (t->kind == ZL_KIND_LINE_AA)
        return aa_row(t, ss, color_row, depth_row);
    pack_color((zl_format)ss->format, t->rgb[0], t->rgb[1], t->rgb[2], pix);
    if (t->kind == ZL_KIND_POINT) {
        uint32_t d = line_depth(t->z.row);
        int32_t x;
        for (x = t->left.x; x < t->right.x; x++)
            plot(ss, color_row, depth_row, x, d, pix);
        t->row++;
        return t->row < t->end;
    }
    /* Line: the pixels of this row, walking the major axis. A y-major line
     * has one per row; an x-major one a run, until its minor coordinate
     * (the row) changes. */
    if (ss->bpp == 2 && ss->format == ZL_FORMAT_RGB565 && ss->zwrite && ss->func == ZL_LESS && ss->keep[0] == 0 &&
        ss->keep[1] == 0 && ((uintptr_t)color_row & 1u) == 0) {
        /* The common case in its own loop (RGB565, all channels, LESS with
         * writes): the same pixels and values as plot() below. */
        uint16_t *crow = (uint16_t *)(void *)color_row, pixel;
        memcpy(&pixel, pix, 2);
        for (;;) {
            int32_t x = t->lower_is_left ? t->ax : t->left.x;
            uint32_t d = line_depth(t->z.row);
            if (x >= 0 && x < ss->width && d < depth_row[x]) {
                depth_row[x] = (uint16_t)d;
                crow[x] = pixel;
            }
            if (--t->right.x == 0) {
                t->row = t->end;
                return 0;
            }
            t->ax += t->right.step;
            edge_step(&t->left);
            t->z.row += t->z.dx;
            if (!t->lower_is_left || t->left.x != t->row)
                break;
        }
        t->row++;
        return t->row < t->end;
    }
    for (;;) {
        int32_t x = t->lower_is_left ? t->ax : t->left.x;
        plot(ss, color_row, depth_row, x, line_depth(t->z.row), pix);
        if (--t->right.x == 0) {
            t->row = t->end;
            return 0;
        }
        t->ax += t->right.step;
        edge_step(&t->left);
        t->z.row += t->z.dx;
        if (!t->lower_is_left || t->left.x != t->row)
            break;
    }
    t->row++;
    return t->row < t->end;
}
