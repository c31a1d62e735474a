/* SPDX-License-Identifier: MIT */
/*
 * Stage 6, visibility: painter's algorithm: sort by depth, draw far to near with no depth buffer.
 *
 * Key: the window depth of the triangle's farthest vertex (after clipping),
 * the classic first step of Newell, Newell and Sancha. Far first; equal keys
 * put the later-submitted triangle first so that the earlier one ends on top,
 * as the z-buffer's LESS keeps the first of two equal depths.
 *
 * The sort is zl_sort_far_first (zl_order.c), an in-place heap sort over
 * the (key, id) pairs planning recorded: O(n log n) comparisons, no extra
 * memory, no recursion, a total order (the id breaks ties).
 *
 * Where it fails (docs/VISIBILITY.md shows each): two triangles that
 * intersect (each is in front over part of the other), three or more that
 * overlap cyclically, and any pair whose farthest-vertex order differs from
 * their order where they overlap (a long triangle reaching far behind a
 * small one it covers). The full Newell algorithm would test and reorder
 * overlapping pairs and split the cyclic ones; this keeps the sort only,
 * which is what small renderers ship.
 */
#include "zl_vis_internal.h"

zl_status zl_painter_draw(zl_vis *v, const zl_vis_target *target, zl_rgb clear)
{
    uint32_t n, e;
    zl_status st;
    if (v == NULL || v->cfg.algorithm != ZL_VIS_PAINTER)
        return ZL_ERR_ARG;
    st = zl_vis_check_target(target);
    if (st != ZL_OK)
        return st;
    if (target->width != v->cfg.width || target->height != v->cfg.height || target->format != v->cfg.format)
        return ZL_ERR_SIZE;
    st = zl_vis_plan(v);
    if (st != ZL_OK)
        return st;
    n = v->needs.triangles;
    zl_sort_far_first(v->keys, v->visible, n);
    zl_vis_clear_target(target, clear);
    for (e = 0; e < n; e++) {
        uint16_t id = v->visible[e];
        zl_source src;
        zl_poly poly;
        uint32_t t;
        unsigned k, mi = zl_vis_source(v, id, &src, &t);
        uint8_t rgb[3], pix[3];
        if (!zl_tri_polygon(&src, t, &poly))
            continue;
        rgb[0] = poly.flat.r;
        rgb[1] = poly.flat.g;
        rgb[2] = poly.flat.b;
        zl_vis_pack((zl_format)target->format, rgb, pix);
        for (k = 1; k + 1 < poly.n; k++) {
            zl_active a;
            if (zl_tri_setup(&a, NULL, &poly.v[0], &poly.v[k], &poly.v[k + 1], &poly, &v->meshes[mi].state,
                             target->width, target->height))
                zl_vis_draw_spans(&a, target, pix, id);
        }
    }
    return ZL_OK;
}
