/* SPDX-License-Identifier: MIT */
/* Targets, frame configs and band copies for the tests (zt_frame.h). */
#include "zt_frame.h"

#include <string.h>

#include "unity.h"

void zt_target_packed(zl_target *t, void *color, uint16_t *depth, uint16_t width, uint16_t height, zl_format fmt)
{
    memset(t, 0, sizeof *t);
    t->color = color;
    t->color_stride = (int32_t)(width * zl_format_bytes(fmt));
    t->depth = depth;
    t->depth_stride = depth != NULL ? width * 2 : 0;
    t->width = width;
    t->height = height;
    t->format = (uint8_t)fmt;
}

void zt_frame_config_of(zl_frame_config *c, uint16_t width, uint16_t height, uint16_t band_rows, zl_format fmt)
{
    memset(c, 0, sizeof *c);
    c->width = width;
    c->height = height;
    c->band_rows = band_rows;
    c->format = (uint8_t)fmt;
    c->color_buffers = 1;
}

void zt_frame_capacity(zl_frame_config *c, uint16_t meshes, uint32_t vertices, uint32_t triangles, uint32_t active)
{
    c->max_meshes = meshes;
    c->max_vertices = vertices;
    c->max_triangles = triangles;
    c->max_active = active;
}

void zt_band_copy(const zt_frame_copy *dst, const zl_band *b)
{
    size_t row_bytes = (size_t)b->width * zl_format_bytes((zl_format)b->format);
    uint16_t r;
    for (r = 0; r < b->rows; r++) {
        size_t y = (size_t)b->first_row + r;
        memcpy((uint8_t *)dst->color + y * row_bytes, (const uint8_t *)b->color + (size_t)r * (size_t)b->color_stride,
               row_bytes);
        if (dst->depth != NULL)
            memcpy(dst->depth + y * b->width, (const uint8_t *)b->depth + (size_t)r * (size_t)b->depth_stride,
                   (size_t)b->width * 2);
    }
}

int zt_band_copy_fn(void *user, const zl_band *b)
{
    zt_band_copy((const zt_frame_copy *)user, b);
    return 0;
}

void zt_frame_drain(zl_frame *f, const zt_frame_copy *dst)
{
    zl_band band;
    zl_status rc;
    while ((rc = zl_frame_next_band(f, &band)) == ZL_OK)
        zt_band_copy(dst, &band);
    TEST_ASSERT_EQUAL_INT(ZL_DONE, rc);
}

void zt_read_channels(const uint8_t *color, zl_format fmt, unsigned p, unsigned ch[3], unsigned bits[3])
{
    uint16_t v;
    if (fmt == ZL_FORMAT_RGB888) {
        ch[0] = color[p * 3];
        ch[1] = color[p * 3 + 1];
        ch[2] = color[p * 3 + 2];
        bits[0] = bits[1] = bits[2] = 8;
        return;
    }
    if (fmt == ZL_FORMAT_RGB565)
        memcpy(&v, color + p * 2, 2);
    else
        v = (uint16_t)((color[p * 2] << 8) | color[p * 2 + 1]);
    ch[0] = v >> 11;
    ch[1] = (v >> 5) & 63u;
    ch[2] = v & 31u;
    bits[0] = 5;
    bits[1] = 6;
    bits[2] = 5;
}
