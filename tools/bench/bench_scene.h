/* SPDX-License-Identifier: MIT */
/*
 * The benchmark scene shared by zline's host benchmarks: bunny.obj at
 * 320x240, bounding box centred and scaled to a largest extent of 2.0,
 * camera at (0, 0, 3.5) looking at the origin, vertical field of view 60
 * degrees, near 0.1, far 100, back faces culled, one flat colour per
 * triangle (a directional light), 16-bit depth.
 */
#ifndef ZLINE_BENCH_SCENE_H
#define ZLINE_BENCH_SCENE_H

#include "zl_obj.h"
#include "zline/zline.h"

#define BENCH_W 320
#define BENCH_H 240

/* Load the model (normalised) and build the scene's matrix and state.
 * Returns 0 on success; prints the loader's message otherwise. */
int bench_scene_load(const char *path, zl_obj *obj, zl_mesh *mesh, zl_mat4 *mvp, zl_state *state);

/* A frame-mode context on BENCH_W x BENCH_H RGB565 colour and depth arrays,
 * cleared to the benchmark's background and far depth, with `state`. Exits
 * with status 2 if zl_init refuses (it cannot for these arguments). */
void bench_scene_context(zl_context *ctx, uint16_t *color, uint16_t *depth, const zl_state *state);

#endif
