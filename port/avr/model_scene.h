/* SPDX-License-Identifier: MIT */
/*
 * The ATmega2560 demo's scene (port/avr, issue 23), in portable C99: a lit
 * low-poly torus (torus.obj, converted by zline-obj2c at build time) turning
 * about two axes, 160x128 (the ST7735 panels sold for these boards),
 * rendered one row at a time (scanline mode) as big-endian RGB565. The
 * firmware (avr_model.c) and the host reference (model_reference.c) both
 * run this code and print the same lines, so the test compares the frames
 * byte for byte.
 */
#ifndef MODEL_SCENE_INCLUDED
#define MODEL_SCENE_INCLUDED

#include <stddef.h>
#include <stdint.h>

#include "zline/zline.h"

#define MODEL_SCENE_W 160u
#define MODEL_SCENE_H 128u
/* One turn takes this many frames. */
#define MODEL_SCENE_FRAMES 48u
/* The frames both sides print: 0, 6, 12, ... 42 (every pose class of the
 * turn: the hole seen edge-on, from above, from below). */
#define MODEL_SCENE_CHECK_FRAMES 8u
#define MODEL_SCENE_CHECK_STEP 6u
/* Active triangle records: the most any row of any frame of the turn needs
 * (model_reference --needs prints it over all 48 frames) plus a margin; a
 * frame that needed more would stop with ZL_ERR_CAPACITY, never overflow. */
#define MODEL_SCENE_MAX_ACTIVE 26u

/* zline's work buffer in 8-byte words: at least zl_frame_bytes() of
 * model_scene_config (checked at render time: ZL_ERR_ARG if not). The
 * AVR's pointers are 2 bytes, so it needs less there than on the host. */
#define MODEL_SCENE_WORK_WORDS 610u
#if defined(__GNUC__)
#define MODEL_SCENE_ALIGN8 __attribute__((aligned(8)))
#else
#define MODEL_SCENE_ALIGN8
#endif

void model_scene_config(zl_frame_config *cfg);

/* Render frame `index` (wraps every MODEL_SCENE_FRAMES) with configuration
 * cfg (NULL: model_scene_config's), calling row_fn for each finished row;
 * with needs != NULL, also store what the frame needed. Returns 0, a
 * negative zl_status, or row_fn's first non-zero return. */
int model_scene_render(uint16_t index, const zl_frame_config *cfg, uint64_t *work, size_t work_bytes,
                       zl_band_fn row_fn, void *user, zl_frame_needs_t *needs);

#endif
