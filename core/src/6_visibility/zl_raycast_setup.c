/* SPDX-License-Identifier: MIT */
/*
 * Stage 6, visibility: the ray caster's per-triangle set-up (window-space
 * edge functions and bounds, see zl_raycast.c for the method). It is its own
 * file because the scene planner (zl_vis_scene.c) classifies triangles with
 * it, and the ray caster's row loop (zl_raycast.c) runs above the planner.
 */
#include "zl_vis_internal.h"

static int64_t min3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a < b ? a : b;
    return m < c ? m : c;
}

static int64_t max3(int64_t a, int64_t b, int64_t c)
{
    int64_t m = a > b ? a : b;
    return m > c ? m : c;
}

int zl_vis_rtri_init(zl_vis_rtri *r, const zl_wvert *a, const zl_wvert *b, const zl_wvert *c,
                     const zl_state *st, uint16_t width, uint16_t height, int32_t *first)
{
    const zl_wvert *v[3];
    const int64_t s = ZL_SUB_ONE; /* half-subpixel units per half pixel */
    int64_t area, lo, hi;
    int front, k;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    for (k = 0; k < 3; k++) {
        r->x[k] = 2 * (int64_t)v[k]->x;
        r->y[k] = 2 * (int64_t)v[k]->y;
    }
    area = (r->x[1] - r->x[0]) * (r->y[2] - r->y[0]) - (r->y[1] - r->y[0]) * (r->x[2] - r->x[0]);
    if (area == 0)
        return 0;
    /* area > 0: clockwise as the viewer sees it (y down). */
    front = st->front_face == ZL_FRONT_CW ? area > 0 : area < 0;
    if ((st->cull == ZL_CULL_BACK && !front) || (st->cull == ZL_CULL_FRONT && front))
        return 0;
    if (area < 0) {
        const zl_wvert *t = v[1];
        v[1] = v[2];
        v[2] = t;
        area = -area;
        for (k = 0; k < 3; k++) {
            r->x[k] = 2 * (int64_t)v[k]->x;
            r->y[k] = 2 * (int64_t)v[k]->y;
        }
    }
    r->area = area;
    r->wide = 0;
    for (k = 0; k < 3; k++)
        r->z[k] = v[k]->z;
    r->rgb[0] = 0;
    r->rgb[1] = 0;
    r->rgb[2] = 0;
    /* Centre of row j: 2 s j + s. Rows with a centre inside [ymin, ymax]. */
    lo = zl_ceil_div64(min3(r->y[0], r->y[1], r->y[2]) - s, 2 * s);
    hi = zl_floor_div64(max3(r->y[0], r->y[1], r->y[2]) - s, 2 * s) + 1;
    if (lo < 0)
        lo = 0;
    if (hi > height)
        hi = height;
    if (lo >= hi)
        return 0;
    *first = (int32_t)lo;
    r->first = (int16_t)lo;
    r->end = (int16_t)hi;
    lo = zl_ceil_div64(min3(r->x[0], r->x[1], r->x[2]) - s, 2 * s);
    hi = zl_floor_div64(max3(r->x[0], r->x[1], r->x[2]) - s, 2 * s) + 1;
    if (lo < 0)
        lo = 0;
    if (hi > width)
        hi = width;
    if (lo >= hi)
        return 0;
    r->px0 = (int32_t)lo;
    r->px1 = (int32_t)hi;
    return 1;
}
