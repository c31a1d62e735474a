/* SPDX-License-Identifier: MIT */
/*
 * Images as textures, for the host port: the one conversion that both
 * zline-img2c (const arrays for firmware) and zline-render --texture use, so
 * a texture is the same texels on the host and on a microcontroller.
 *
 * Input, recognised by its first bytes (not its name):
 *   PPM (P6) or PGM (P5), any maxval 1..65535: opaque (alpha 255); a PGM
 *     is grey (r = g = b). Samples scale to 8 bits as
 *     round(s * 255 / maxval).
 *   PNG, when built with libpng (ZL_HAVE_PNG; Debian: libpng-dev): read as
 *     8-bit RGBA (palette, grey and 16-bit images converted by libpng).
 *     Without libpng a PNG is an error that says how to convert it with
 *     Debian's netpbm: pngtopnm IN.png > IN.ppm, and
 *     pngtopnm -alpha IN.png > IN_alpha.pgm for its alpha.
 *   An optional separate alpha mask: a PGM of the same size (what
 *     pngtopnm -alpha writes), replacing the image's alpha.
 * Sizes 1 .. 4096 on each side (the texture limit of zline.h).
 *
 * Conversion of an 8-bit (r, g, b, a) to a texel (zline.h, TEXEL FORMATS):
 *   ZL_TEXEL_RGB565    the top 5, 6, 5 bits (as pack_color writes a pixel,
 *                      so an RGB565 texel drawn unlit is its pixel); alpha
 *                      is dropped
 *   ZL_TEXEL_RGBA4444  each channel round(c * 15 / 255), which the
 *                      library widens back as c4 * 17 (exact for c = 17 k)
 * Errors name the file and the problem ("FILE: what is wrong").
 */
#ifndef ZL_IMAGE_H
#define ZL_IMAGE_H

#include <stddef.h>
#include <stdint.h>

#include "zline/zline.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ZL_IMAGE_MAX_DIM 4096u

typedef struct {
    uint32_t width, height;
    uint8_t *rgba;  /* 4 bytes a pixel, row by row, top row first (heap) */
    int has_alpha;  /* some pixel has alpha below 255 */
} zl_image;

/* Load path (and, when alpha_path is not NULL, its alpha from that PGM).
 * Returns 0 on success; on failure -1, *img empty, and msg holds
 * "FILE: what is wrong". */
int zl_image_load(zl_image *img, const char *path, const char *alpha_path, char *msg, size_t msg_size);
void zl_image_free(zl_image *img);

/* One texel of the format from 8-bit channels. */
uint16_t zl_image_texel(unsigned r, unsigned g, unsigned b, unsigned a, zl_texel_format format);

/* All texels of img, row by row (stride = width), into out (width * height
 * entries). */
void zl_image_texels(const zl_image *img, zl_texel_format format, uint16_t *out);

/* Whether this build reads PNG files itself (libpng). */
int zl_image_png_supported(void);

#ifdef __cplusplus
}
#endif

#endif /* ZL_IMAGE_H */
