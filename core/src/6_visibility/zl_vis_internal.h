/* SPDX-License-Identifier: MIT */
/*
 * Internals shared by the visibility methods of zl_visibility.h: the scene
 * (meshes, vertex cache, kept triangles), span filling without a depth
 * buffer, and the edge stepping of zl_tri_row without its span.
 */
#ifndef ZLINE_VIS_INTERNAL_H
#define ZLINE_VIS_INTERNAL_H

#include "../1_base/zl_internal.h"
#include "zline/zl_visibility.h"

struct zl_vis_mesh {
    zl_mesh mesh;
    zl_mat4 mvp;
    zl_state state;
    uint8_t has_mvp;
    uint32_t tri_base, vert_base;
};

/* Ray caster: one window-space triangle piece, set up for exact tests. */
typedef struct {
    int64_t x[3], y[3]; /* vertices in half subpixels (2 * snapped), area > 0 order */
    int64_t area;       /* doubled signed area in those units, > 0 */
    uint32_t z[3];      /* window depth, zl_wvert scale; with wide, 2^31 + 256 steps */
    int32_t px0, px1;   /* candidate columns px0 .. px1 - 1 */
    int16_t first, end; /* candidate rows first .. end - 1 */
    uint16_t id;
    uint8_t rgb[3];
    uint8_t wide;       /* a piece of a clipped triangle: z is the original
                           triangle's depth, which may leave 0 .. 65535 (in
                           the tail padding: the record does not grow) */
} zl_vis_rtri;

/* AET: one entry of the active edge list. */
typedef struct {
    int32_t x;     /* first column at or right of the edge on this row, clamped to 0..width */
    uint16_t slot; /* the polygon (triangle piece) it bounds */
    uint8_t leave; /* 0: the polygon starts at x, 1: it ends before x */
    uint8_t pad;
} zl_vis_edge;

/* Source of triangle `id` of the scene; returns the mesh index. */
unsigned zl_vis_source(const zl_vis *v, uint16_t id, zl_source *s, uint32_t *t);
/* Mesh index of a scene-wide triangle id. */
unsigned zl_vis_mesh_of(const zl_vis *v, uint16_t id);
/* Plan the scene once (cache, classification, capacities). */
zl_status zl_vis_plan(zl_vis *v);
/* Memory bytes of a colour (2 or 3). */
void zl_vis_pack(zl_format f, const uint8_t *rgb, uint8_t out[3]);
/* Fill n pixels of a row with a packed colour. */
void zl_vis_fill(uint8_t *row, unsigned bpp, const uint8_t *pix, int32_t n);
/* Step a set-up triangle to its next row as zl_tri_row does, without the
 * span (the z plane too when with_z). Returns 0 when no rows are left. */
int zl_vis_step(zl_active *t, int with_z);
/* Draw every remaining row of a set-up triangle into a target, no depth test. */
void zl_vis_draw_spans(zl_active *t, const zl_vis_target *tg, const uint8_t *pix, uint16_t id);
/* Check a zl_vis_target; ZL_OK or the error. */
zl_status zl_vis_check_target(const zl_vis_target *t);
/* Clear a target's colour and ids. */
void zl_vis_clear_target(const zl_vis_target *t, zl_rgb clear);

int zl_aet_render_rows(zl_vis *v, zl_rgb clear, zl_vis_row_fn fn, void *user);
int zl_raycast_render_rows(zl_vis *v, zl_rgb clear, zl_vis_row_fn fn, void *user);
/* Ray caster's own classification of a fan piece: culling by its winding,
 * candidate rows [*first, end) and columns from the bounding box; 0 when it
 * can cover no pixel centre of the target. */
int zl_vis_rtri_init(zl_vis_rtri *r, const zl_wvert *a, const zl_wvert *b, const zl_wvert *c,
                     const zl_state *st, uint16_t width, uint16_t height, int32_t *first);

/* Depth of a set-up triangle at column x of its current row: the Q20 plane
 * of zl_tri_setup, clamped to the vertices' range as the span writer does. */
static inline int64_t zl_vis_depth_at(const zl_active *t, int32_t x)
{
    int64_t v = t->z.row + (int64_t)(x - t->ax) * t->z.dx;
    int64_t lo = (int64_t)t->zlo * (1 << (ZL_ATTR_FRAC - 16)), hi = (int64_t)t->zhi * (1 << (ZL_ATTR_FRAC - 16));
    if (lo > hi) { /* a piece of a clipped triangle (zl_tri_set_planes): the stored range */
        lo = 0;
        hi = (int64_t)65535 << ZL_ATTR_FRAC;
    }
    return v < lo ? lo : (v > hi ? hi : v);
}

/* zl_order.c: sort (key, id) pairs far first, equal keys later id first:
 * the painter's order, used by zl_painter_draw and zl_painter_order. */
void zl_sort_far_first(uint32_t *keys, uint16_t *ids, uint32_t n);

#endif /* ZLINE_VIS_INTERNAL_H */
