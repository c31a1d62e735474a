/* SPDX-License-Identifier: MIT */
/*
 * Set-up the rendering tests repeat: a render target over packed buffers,
 * a zl_frame_config, and the band copy that turns scanline / band mode
 * output back into a whole frame to compare with frame mode.
 *
 * Plain C99 and Unity, no I/O: the helpers run on the host and on the
 * cross-compiled targets alike.
 */
#ifndef ZT_FRAME_H
#define ZT_FRAME_H

#include <stdint.h>

#include "zline/zline.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A width x height target of format fmt over packed buffers (no row
 * padding): color, and depth (NULL: none, stride 0). */
void zt_target_packed(zl_target *t, void *color, uint16_t *depth, uint16_t width, uint16_t height, zl_format fmt);

/* A zeroed config for width x height in bands of band_rows, one colour
 * buffer of fmt. Gouraud, styles, textures: the caller's to switch on. */
void zt_frame_config_of(zl_frame_config *c, uint16_t width, uint16_t height, uint16_t band_rows, zl_format fmt);
/* The config's capacities. */
void zt_frame_capacity(zl_frame_config *c, uint16_t meshes, uint32_t vertices, uint32_t triangles, uint32_t active);

/* Whole-frame packed buffers a band is copied into (depth may be NULL). */
typedef struct {
    void *color;
    uint16_t *depth;
} zt_frame_copy;

/* Copy band b's rows to their place in the whole-frame buffers. */
void zt_band_copy(const zt_frame_copy *dst, const zl_band *b);
/* The same as a zl_frame_render callback: user is a zt_frame_copy. */
int zt_band_copy_fn(void *user, const zl_band *b);
/* Take every band with zl_frame_next_band, copying each into dst, and
 * assert the frame ends with ZL_DONE. */
void zt_frame_drain(zl_frame *f, const zt_frame_copy *dst);

/* Pixel p (row-major index) of a packed colour buffer of format fmt, at
 * the format's precision: ch[] = r, g, b as stored (5/6/5 bits for both
 * RGB565 byte orders, 8 for RGB888) and bits[] how many bits each has. */
void zt_read_channels(const uint8_t *color, zl_format fmt, unsigned p, unsigned ch[3], unsigned bits[3]);

#ifdef __cplusplus
}
#endif

#endif /* ZT_FRAME_H */
