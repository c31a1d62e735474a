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
/*
 * Capacities (issue 23): the firmware's work buffer holds fewer active
 * triangle records than the busiest rows need, and zline renders those
 * frames over capacity (zline.h, Sizing): rows planned again a window at a
 * time and rendered in passes, byte-identical, slower. model_reference
 * --needs (CTest avr_model_capacity) renders the 48 frames of the turn with
 * room for everything and with these capacities, and fails unless the turn
 * needs exactly MODEL_SCENE_NEEDS_ACTIVE records at most, keeps at most
 * MODEL_SCENE_MAX_TRIANGLES triangles (the front faces: no replan for
 * those) and takes exactly MODEL_SCENE_REPLANS replans, at most
 * MODEL_SCENE_MOST_REPLANS in one frame: a change of scene or of zline that
 * moves them must update them and README.md's figures.
 */
#define MODEL_SCENE_MAX_ACTIVE 33u
#define MODEL_SCENE_MAX_TRIANGLES 150u
#define MODEL_SCENE_NEEDS_ACTIVE 40u
#define MODEL_SCENE_REPLANS 198u
#define MODEL_SCENE_MOST_REPLANS 22u

/* zline's work buffer in 8-byte words: at least zl_frame_bytes() of
 * model_scene_config (checked at render time: ZL_ERR_ARG if not). The
 * AVR's pointers are 2 bytes, so it needs less there than on the host. */
#define MODEL_SCENE_WORK_WORDS 810u
#if defined(__GNUC__)
#define MODEL_SCENE_ALIGN8 __attribute__((aligned(8)))
#else
#define MODEL_SCENE_ALIGN8
#endif

/* The firmware's configuration, and the host's with room for every
 * triangle of the torus at once (no replans). */
void model_scene_config(zl_frame_config *cfg);
void model_scene_roomy_config(zl_frame_config *cfg);

/* Render frame `index` (wraps every MODEL_SCENE_FRAMES) with configuration
 * cfg (NULL: model_scene_config's), calling row_fn for each finished row;
 * with needs != NULL, also store what the frame needed. Returns 0, a
 * negative zl_status, or row_fn's first non-zero return. */
int model_scene_render(uint16_t index, const zl_frame_config *cfg, uint64_t *work, size_t work_bytes,
                       zl_band_fn row_fn, void *user, zl_frame_needs_t *needs);

#endif
