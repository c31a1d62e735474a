/* SPDX-License-Identifier: MIT */
/*
 * What a firmware that draws calls of zline (tools/size/config-size.sh):
 * frame mode (zl_draw_mesh with a style, lines, outlines), scanline mode
 * (zl_frame_* with a styled mesh, lines and outlines), the matrices. The
 * arguments come from the caller, so nothing is folded away; the partial
 * link keeps what this reaches of the core. Never run.
 * ZL_SIZE_PROBE_FRAME=0 leaves frame mode's calls out, ZL_SIZE_PROBE_SCANLINE=0
 * scanline mode's: the flash of a firmware that draws in one mode only.
 */
#include "zline/zline.h"

#ifndef ZL_SIZE_PROBE_FRAME
#define ZL_SIZE_PROBE_FRAME 1
#endif
#ifndef ZL_SIZE_PROBE_SCANLINE
#define ZL_SIZE_PROBE_SCANLINE 1
#endif

typedef struct {
    zl_context *ctx;
    zl_frame *frame;
    const zl_frame_config *cfg;
    void *work;
    size_t work_bytes;
    const zl_mesh *mesh;
    const zl_lines *lines;
    const zl_outline *outline;
    zl_mesh_edge *edges;
    const zl_state *state;
    const zl_style *style;
    const zl_target *target;
    zl_band_fn band;
} zl_size_args;

int zl_size_probe(const zl_size_args *a);

int zl_size_probe(const zl_size_args *a)
{
    zl_mat4 p, v, m;
    zl_rgb black = {0, 0, 0};
    int r = 0;
    zl_vec3 eye = {0, 0, ZL_FX_INT(3)}, at = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    r |= zl_mat4_perspective(&p, ZL_ANGLE_TURN / 8, ZL_FX_ONE, ZL_FX_ONE / 4, ZL_FX_INT(16));
    r |= zl_mat4_look_at(&v, eye, at, up);
    zl_mat4_mul(&m, &p, &v);
    zl_mat4_rotate_y(&v, (zl_angle)a->work_bytes);
    zl_mat4_mul(&m, &m, &v);
    r |= (int)zl_mesh_edges(a->mesh, a->edges, 64);
#if ZL_SIZE_PROBE_FRAME
    r |= zl_init(a->ctx, a->target);
    r |= zl_clear(a->ctx, black, 65535);
    r |= zl_draw_mesh(a->ctx, a->mesh, &m);
    r |= zl_draw_lines(a->ctx, a->lines, &m);
    r |= zl_draw_outlines(a->ctx, a->mesh, &m, a->outline);
#endif
#if ZL_SIZE_PROBE_SCANLINE
    r |= zl_frame_begin(a->frame, a->cfg, a->work, a->work_bytes, black, 65535);
    r |= zl_frame_add_mesh_styled(a->frame, a->mesh, &m, a->state, a->style);
    r |= zl_frame_add_lines(a->frame, a->lines, &m, a->state, a->style);
    r |= zl_frame_add_outlines(a->frame, a->mesh, &m, a->state, a->style, a->outline);
    r |= zl_frame_render(a->frame, a->band, (void *)(uintptr_t)a);
#endif
    return r;
}
