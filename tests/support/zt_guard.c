/* SPDX-License-Identifier: MIT */
/* Guarded test buffers: see zt_guard.h. */
#include "zt_guard.h"

#include <stdio.h>
#include <string.h>

/* uint64_t storage keeps the arena 8-byte aligned on every target. */
static uint64_t arena_words[ZT_GUARD_ARENA_BYTES / 8u];

typedef struct {
    size_t start;  /* offset of the leading guard in the arena */
    size_t bytes;  /* payload bytes (the trailing guard follows them) */
} zt_block;

static zt_block blocks[ZT_GUARD_MAX_BLOCKS];
static unsigned block_count;
static size_t arena_used;
static char report[160];

static uint8_t *arena_bytes(void)
{
    return (uint8_t *)(void *)arena_words;
}

uint8_t zt_guard_pattern(size_t index)
{
    /* Position dependent and never constant over a run: a stray memset or a
     * shifted copy changes it. */
    uint32_t v = (uint32_t)index * 2654435761u;
    return (uint8_t)((v >> 24) ^ 0xA5u ^ (uint8_t)index);
}

void zt_guard_reset(void)
{
    block_count = 0;
    arena_used = 0;
    report[0] = '\0';
}

void *zt_guard_alloc(size_t bytes)
{
    size_t rounded = (bytes + 7u) & ~(size_t)7u;
    size_t need = ZT_GUARD_BYTES + rounded + ZT_GUARD_BYTES;
    uint8_t *a = arena_bytes();
    size_t i, start;
    if (block_count >= ZT_GUARD_MAX_BLOCKS || need > ZT_GUARD_ARENA_BYTES - arena_used)
        return NULL;
    start = arena_used;
    for (i = 0; i < ZT_GUARD_BYTES; i++)
        a[start + i] = zt_guard_pattern(start + i);
    memset(a + start + ZT_GUARD_BYTES, 0, rounded);
    /* The rounding slack belongs to the trailing guard. */
    for (i = ZT_GUARD_BYTES + bytes; i < need; i++)
        a[start + i] = zt_guard_pattern(start + i);
    blocks[block_count].start = start;
    blocks[block_count].bytes = bytes;
    block_count++;
    arena_used += need;
    return a + start + ZT_GUARD_BYTES;
}

size_t zt_guard_check(void)
{
    const uint8_t *a = arena_bytes();
    size_t bad = 0;
    unsigned b;
    report[0] = '\0';
    for (b = 0; b < block_count; b++) {
        size_t start = blocks[b].start;
        size_t payload_end = start + ZT_GUARD_BYTES + blocks[b].bytes;
        size_t end = start + ZT_GUARD_BYTES + ((blocks[b].bytes + 7u) & ~(size_t)7u) + ZT_GUARD_BYTES;
        size_t i;
        for (i = start; i < end; i++) {
            if (i >= start + ZT_GUARD_BYTES && i < payload_end)
                continue;
            if (a[i] != zt_guard_pattern(i)) {
                if (bad == 0) {
                    long rel = i < start + ZT_GUARD_BYTES ? -(long)(start + ZT_GUARD_BYTES - i)
                                                          : (long)(i - payload_end);
                    snprintf(report, sizeof report,
                             "guard of block %u damaged: %s guard, byte %ld from the payload",
                             b, i < start + ZT_GUARD_BYTES ? "leading" : "trailing", rel);
                }
                bad++;
            }
        }
    }
    return bad;
}

const char *zt_guard_report(void)
{
    return report;
}

static size_t arena_offset(const uint8_t *p)
{
    return (size_t)(p - arena_bytes());
}

static void fill_padding(uint8_t *row0, size_t stride, size_t used, unsigned rows)
{
    unsigned r;
    size_t i;
    for (r = 0; r < rows; r++) {
        uint8_t *row = row0 + (size_t)r * stride;
        for (i = used; i < stride; i++)
            row[i] = zt_guard_pattern(arena_offset(row + i));
    }
}

static size_t check_padding(const uint8_t *row0, size_t stride, size_t used, unsigned rows,
                            const char *what)
{
    size_t bad = 0;
    unsigned r;
    size_t i;
    for (r = 0; r < rows; r++) {
        const uint8_t *row = row0 + (size_t)r * stride;
        for (i = used; i < stride; i++) {
            if (row[i] != zt_guard_pattern(arena_offset(row + i))) {
                if (bad == 0 && report[0] == '\0')
                    snprintf(report, sizeof report, "%s row padding damaged: row %u byte %u", what, r,
                             (unsigned)i);
                bad++;
            }
        }
    }
    return bad;
}

int zt_surface_make(zt_surface *s, unsigned width, unsigned height, zl_format fmt, int with_color,
                    int with_depth, unsigned color_pad, unsigned depth_pad, unsigned color_offset)
{
    unsigned bpp = zl_format_bytes(fmt);
    memset(s, 0, sizeof *s);
    if (bpp == 0) /* unknown format (tests of argument checks): lay out 2 bytes */
        bpp = 2;
    s->width = width;
    s->height = height;
    s->bpp = bpp;
    s->color_offset = color_offset;
    s->target.width = (uint16_t)width;
    s->target.height = (uint16_t)height;
    s->target.format = (uint8_t)fmt;
    if (with_color) {
        size_t stride = (size_t)width * bpp + color_pad;
        uint8_t *p = (uint8_t *)zt_guard_alloc(stride * height + color_offset);
        size_t i;
        if (p == NULL)
            return -1;
        /* The bytes skipped for the offset count as guard too. */
        for (i = 0; i < color_offset; i++)
            p[i] = zt_guard_pattern(arena_offset(p + i));
        s->color = p + color_offset;
        s->color_bytes = stride * height;
        s->target.color = s->color;
        s->target.color_stride = (int32_t)stride;
        fill_padding(s->color, stride, (size_t)width * bpp, height);
    }
    if (with_depth) {
        size_t stride = (size_t)width * 2u + depth_pad;
        uint8_t *p = (uint8_t *)zt_guard_alloc(stride * height);
        if (p == NULL)
            return -1;
        s->depth = p;
        s->depth_bytes = stride * height;
        s->target.depth = (uint16_t *)(void *)p;
        s->target.depth_stride = (int32_t)stride;
        fill_padding(s->depth, stride, (size_t)width * 2u, height);
    }
    return 0;
}

size_t zt_surface_check(const zt_surface *s)
{
    size_t bad = zt_guard_check();
    if (s->color) {
        unsigned i;
        /* the bytes skipped in front of an offset colour buffer */
        for (i = 1; i <= s->color_offset; i++) {
            if (s->color[-(long)i] != zt_guard_pattern(arena_offset(s->color - i))) {
                if (bad == 0 && report[0] == '\0')
                    snprintf(report, sizeof report, "byte %u before the colour buffer damaged", i);
                bad++;
            }
        }
        bad += check_padding(s->color, (size_t)s->target.color_stride, (size_t)s->width * s->bpp,
                             s->height, "colour");
    }
    if (s->depth)
        bad += check_padding(s->depth, (size_t)s->target.depth_stride, (size_t)s->width * 2u,
                             s->height, "depth");
    return bad;
}

uint32_t zt_get_px(const zt_surface *s, unsigned x, unsigned y)
{
    const uint8_t *p = s->color + (size_t)y * (size_t)s->target.color_stride + (size_t)x * s->bpp;
    uint16_t v;
    switch (s->target.format) {
    case ZL_FORMAT_RGB888:
        return ((uint32_t)p[0] << 16) | ((uint32_t)p[1] << 8) | p[2];
    case ZL_FORMAT_RGB565:
        memcpy(&v, p, 2);
        return v;
    case ZL_FORMAT_RGB565_BE:
        return ((uint32_t)p[0] << 8) | p[1];
    default:
        return 0;
    }
}

void zt_set_px(zt_surface *s, unsigned x, unsigned y, uint32_t v)
{
    uint8_t *p = s->color + (size_t)y * (size_t)s->target.color_stride + (size_t)x * s->bpp;
    uint16_t h = (uint16_t)v;
    switch (s->target.format) {
    case ZL_FORMAT_RGB888:
        p[0] = (uint8_t)(v >> 16);
        p[1] = (uint8_t)(v >> 8);
        p[2] = (uint8_t)v;
        break;
    case ZL_FORMAT_RGB565:
        memcpy(p, &h, 2);
        break;
    case ZL_FORMAT_RGB565_BE:
        p[0] = (uint8_t)(v >> 8);
        p[1] = (uint8_t)v;
        break;
    default:
        break;
    }
}

uint16_t zt_get_depth(const zt_surface *s, unsigned x, unsigned y)
{
    uint16_t d;
    memcpy(&d, s->depth + (size_t)y * (size_t)s->target.depth_stride + (size_t)x * 2u, 2);
    return d;
}

void zt_set_depth(zt_surface *s, unsigned x, unsigned y, uint16_t d)
{
    memcpy(s->depth + (size_t)y * (size_t)s->target.depth_stride + (size_t)x * 2u, &d, 2);
}

void zt_fill_px(zt_surface *s, uint32_t v)
{
    unsigned x, y;
    for (y = 0; y < s->height; y++)
        for (x = 0; x < s->width; x++)
            zt_set_px(s, x, y, v);
}

void zt_fill_depth(zt_surface *s, uint16_t d)
{
    unsigned x, y;
    for (y = 0; y < s->height; y++)
        for (x = 0; x < s->width; x++)
            zt_set_depth(s, x, y, d);
}

unsigned zt_mask_of_px(const zt_surface *s, uint32_t v, uint8_t *mask)
{
    unsigned x, y, n = 0;
    for (y = 0; y < s->height; y++)
        for (x = 0; x < s->width; x++) {
            uint8_t m = zt_get_px(s, x, y) == v;
            mask[y * s->width + x] = m;
            n += m;
        }
    return n;
}

uint32_t zt_rgb_packed(zl_rgb c)
{
    return ((uint32_t)c.r << 16) | ((uint32_t)c.g << 8) | c.b;
}
