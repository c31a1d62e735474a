/* SPDX-License-Identifier: MIT */
/*
 * The OLED demo's animation: the benchmark bunny (bunny.obj, normalised to a
 * largest extent of 2) turning about its vertical axis, OLED_SCENE_FRAMES
 * frames of OLED_SCENE_DEGREES_PER_FRAME degrees each, at the panel's
 * 128x64, rendered in zline's scanline mode (one row of depth), with a 2D
 * overlay drawn into each row (zl_overlay.h): the frame number and a gauge
 * of the turn.
 *
 * Portable: the firmware (oled_demo.c) renders it into the SSD0323 and the
 * host reference (host/oled_reference.c) renders the same frames into files;
 * the CI test compares the two through the same RGB565 -> grey rule
 * (port/display/zl_grey4.h).
 */
#ifndef ZL_OLED_SCENE_H
#define ZL_OLED_SCENE_H

#include <stddef.h>

#include "zline/zline.h"

#define OLED_SCENE_W 128
#define OLED_SCENE_H 64
#define OLED_SCENE_FRAMES 24
#define OLED_SCENE_DEGREES_PER_FRAME 15

/* The scanline-mode configuration of every frame (capacities cover every
 * angle of the animation with a margin; see oled_scene.c). */
void oled_scene_config(zl_frame_config *cfg);

/* Render frame `index` (0 .. OLED_SCENE_FRAMES - 1) in `work` (8-byte
 * aligned, at least zl_frame_bytes of the configuration), handing each
 * finished row to `row_fn`. Returns what zl_frame_render returns: 0 when all
 * rows are out, a negative zl_status, or row_fn's non-zero value. When
 * `needs` is not NULL it receives what the frame needed (zl_frame_needs). */
int oled_scene_render(int index, void *work, size_t work_bytes, zl_band_fn row_fn, void *user,
                      zl_frame_needs_t *needs);

#endif
