/* SPDX-License-Identifier: MIT */
/*
 * The RotatingModel example's scene, in portable C99 (no Arduino calls): a
 * lit cube with one colour per face, turning about two axes, rendered one
 * row at a time (scanline mode) as big-endian RGB565, the bytes an ST7789
 * or ILI9341 takes, with a 2D overlay (frame number, gauge) drawn into each
 * row. The sketch sends the rows to the panel; the host
 * reference (port/arduino/test) renders the same frames to check them.
 */
#ifndef ROTATING_SCENE_INCLUDED
#define ROTATING_SCENE_INCLUDED

#include <stddef.h>
#include <stdint.h>

#include "zline/zline.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The panel area drawn: a 240x240 ST7789 module, or the middle of a
 * 320x240 ILI9341. */
#define ROTATING_SCENE_W 240u
#define ROTATING_SCENE_H 240u
/* One turn takes this many frames. */
#define ROTATING_SCENE_FRAMES 120u

/* zline's work buffer for this scene, in 8-byte words: at least
 * zl_frame_bytes() of rotating_scene_config's configuration (the render
 * call checks it and returns ZL_ERR_ARG if not). */
#define ROTATING_SCENE_WORK_WORDS 397u
/* zl_frame_begin wants the work buffer 8-byte aligned (ZL_ERR_ARG
 * otherwise). uint64_t alone does not ensure it: on AVR its alignment is
 * 1 byte. Declare the buffer as
 *   static uint64_t work[ROTATING_SCENE_WORK_WORDS] ROTATING_SCENE_ALIGN8; */
#if defined(__GNUC__)
#define ROTATING_SCENE_ALIGN8 __attribute__((aligned(8)))
#else
#define ROTATING_SCENE_ALIGN8
#endif

void rotating_scene_config(zl_frame_config *cfg);

/* Render frame `index` (any value; it wraps every ROTATING_SCENE_FRAMES),
 * calling row_fn for each finished row. Returns 0, a negative zl_status,
 * or row_fn's first non-zero return. */
int rotating_scene_render(uint16_t index, uint64_t *work, size_t work_bytes, zl_band_fn row_fn,
                          void *user);

#ifdef __cplusplus
}
#endif

#endif
