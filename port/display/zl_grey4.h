/* SPDX-License-Identifier: MIT */
/*
 * RGB565 -> 4-bit grey: the one conversion rule of zline's greyscale panels
 * (the SSD0323 OLED of port/lm3s6965). The firmware and the host reference
 * renderer both include this header, so a frame on the emulated panel and
 * the host's rendering of it go through exactly the same function.
 *
 * Rule: expand each channel to 8 bits by bit replication (r5 -> r5 << 3 |
 * r5 >> 2, so 31 -> 255 and 0 -> 0), take the ITU-R BT.601 luma with the
 * weights in 1/256 (77 R + 150 G + 29 B, they sum to 256), round to nearest,
 * and keep the top 4 bits of the 8-bit luma (0..255 -> 0..15, each grey
 * level covering 16 luma steps). Exact integer arithmetic: the largest sum
 * is 256 * 255 + 128, far inside 32 bits.
 */
#ifndef ZL_GREY4_H
#define ZL_GREY4_H

#include <stdint.h>

static inline uint8_t zl_grey4_from_rgb565(uint16_t c)
{
    uint32_t r5 = (uint32_t)(c >> 11) & 31u;
    uint32_t g6 = (uint32_t)(c >> 5) & 63u;
    uint32_t b5 = (uint32_t)c & 31u;
    uint32_t r8 = (r5 << 3) | (r5 >> 2);
    uint32_t g8 = (g6 << 2) | (g6 >> 4);
    uint32_t b8 = (b5 << 3) | (b5 >> 2);
    uint32_t luma = (77u * r8 + 150u * g8 + 29u * b8 + 128u) >> 8; /* 0..255 */
    return (uint8_t)(luma >> 4);
}

/* Pack a row of `width` RGB565 pixels (width even) into width / 2 bytes of
 * 4-bit grey, two pixels a byte, the left pixel in the high nibble: the
 * SSD0323's display RAM layout without nibble remapping. */
static inline void zl_grey4_pack_row(uint8_t *out, const uint16_t *rgb565, uint16_t width)
{
    uint16_t x;
    for (x = 0; x + 1u < width; x += 2u)
        out[x / 2u] = (uint8_t)((zl_grey4_from_rgb565(rgb565[x]) << 4) | zl_grey4_from_rgb565(rgb565[x + 1u]));
}

#endif
