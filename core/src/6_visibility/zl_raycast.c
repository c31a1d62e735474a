/* SPDX-License-Identifier: MIT */
/*
 * Stage 6, visibility: the reference ray caster: for every pixel centre, the nearest triangle
 * along the view ray.
 *
 * After the projective transform a view ray through a pixel centre is the
 * line of constant window (x, y), and every triangle is still planar, so
 * casting the ray is: find the triangles whose window-space outline contains
 * the centre, and compare their depth planes there. Both steps are done here
 * from first principles, pixel by pixel, with no incremental stepping and no
 * code shared with the rasteriser beyond the geometry itself (zl_tri_polygon:
 * transform, clipping, projection, snapping):
 *
 *   coverage  exact edge functions of the snapped vertices at the centre, in
 *             half-subpixel units (so centres are integers), with the
 *             top-left rule for centres on an edge: an edge a -> b of a
 *             triangle ordered so its doubled area is positive (clockwise as
 *             seen, y down) has the interior where
 *                 E(p) = (bx - ax)(py - ay) - (by - ay)(px - ax) > 0,
 *             whose gradient (-(by - ay), bx - ax) points into the triangle:
 *             the edge is a left edge when by < ay (interior to its right)
 *             and a top edge when by == ay and bx > ax (interior below).
 *   depth     barycentric: the three edge functions at the centre are the
 *             weights (each in 0..area for a covered centre, summing to the
 *             area), so z = zmin + sum w_k (z_k - zmin) / area, in 64 bits
 *             because sum w_k (z_k - zmin) <= area * 2^32 < 2^63 once the
 *             weights are scaled below 2^31. The result is on the zl_wvert
 *             scale, 65536 units per stored depth step: exact (floored) for
 *             triangles of doubled area below 2^31 half-subpixel units
 *             (about 2900 pixels across), within a few units otherwise.
 *   nearest   the smallest depth, ties to the lowest id (submission order),
 *             and the gap to the second-nearest surface, reported so tests
 *             can tell a real disagreement from a near tie.
 *
 * Cost: every active piece at every pixel of its bounding box row, so this is
 * an oracle for tests and a fallback view, not a renderer for a frame rate.
 */
#include "zl_vis_internal.h"

/* Edge a -> b at centre (px, py): the weight of the opposite vertex, or -1
 * when the centre is outside (or on the edge and the edge is neither top nor
 * left). */
static int64_t edge_weight(int64_t ax, int64_t ay, int64_t bx, int64_t by, int64_t px, int64_t py)
{
    int64_t dx = bx - ax, dy = by - ay;
    int64_t e = dx * (py - ay) - dy * (px - ax);
    if (e > 0)
        return e;
    if (e == 0 && (dy < 0 || (dy == 0 && dx > 0)))
        return 0;
    return -1;
}

static unsigned bit_length(uint64_t v)
{
    unsigned n = 0;
    while (v != 0) {
        v >>= 1;
        n++;
    }
    return n;
}

/* Does the piece cover centre (px, py)? Then its depth in *z. */
static int cast(const zl_vis_rtri *r, int64_t px, int64_t py, uint64_t *z)
{
    int64_t w0, w1, w2, area = r->area;
    uint32_t zmin;
    unsigned len;
    uint64_t n;
    w2 = edge_weight(r->x[0], r->y[0], r->x[1], r->y[1], px, py);
    if (w2 < 0)
        return 0;
    w0 = edge_weight(r->x[1], r->y[1], r->x[2], r->y[2], px, py);
    if (w0 < 0)
        return 0;
    w1 = edge_weight(r->x[2], r->y[2], r->x[0], r->y[0], px, py);
    if (w1 < 0)
        return 0;
    len = bit_length((uint64_t)area);
    if (len > 31) {
        unsigned sh = len - 31;
        w0 = zl_floor_shift64(w0, sh);
        w1 = zl_floor_shift64(w1, sh);
        w2 = zl_floor_shift64(w2, sh);
        area = zl_floor_shift64(area, sh);
    }
    zmin = r->z[0];
    if (r->z[1] < zmin)
        zmin = r->z[1];
    if (r->z[2] < zmin)
        zmin = r->z[2];
    n = (uint64_t)w0 * (r->z[0] - zmin) + (uint64_t)w1 * (r->z[1] - zmin) + (uint64_t)w2 * (r->z[2] - zmin);
    *z = zmin + n / (uint64_t)area;
    if (r->wide) { /* back to the zl_wvert scale, clamped as the stored depth is */
        int64_t d = ((int64_t)*z - ((int64_t)1 << 31)) * 256;
        *z = (uint64_t)(d < 0 ? 0 : (d > (int64_t)65535 << 16 ? (int64_t)65535 << 16 : d));
    }
    return 1;
}

/* A piece of a clipped triangle casts against the original triangle's
 * plane (as the z-buffer draws it): its vertices' depths from
 * zl_tri_orig_depths3, unclamped, in 1/256 step biased by 2^31 (so
 * -2^23 .. 2^23 steps fit; beyond, the clamped polygon depths stay). */
static ZL_NOINLINE void wide_depths(zl_vis_rtri *r, const zl_source *src, uint32_t t)
{
    int32_t x[3], y[3];
    int64_t z[3];
    int k;
    for (k = 0; k < 3; k++) {
        x[k] = (int32_t)(r->x[k] / 2);
        y[k] = (int32_t)(r->y[k] / 2);
    }
    if (!zl_tri_orig_depths3(src, t, x, y, z))
        return;
    for (k = 0; k < 3; k++)
        if (z[k] < -((int64_t)1 << 39) || z[k] >= ((int64_t)1 << 39))
            return;
    for (k = 0; k < 3; k++)
        r->z[k] = (uint32_t)(zl_floor_shift64(z[k], 8) + ((int64_t)1 << 31));
    r->wide = 1;
}

/* An unclipped triangle casts against the depth plane the z-buffer gives
 * it (through its unsnapped vertices, zl_tri_exact_depths3): its values at
 * the snapped vertices, wide as wide_depths makes them. */
static ZL_NOINLINE void exact_depths(zl_vis_rtri *r, const zl_poly *poly, const zl_wvert *a, const zl_wvert *b,
                                     const zl_wvert *c)
{
    int32_t x[3], y[3];
    int64_t z[3];
    int k;
    for (k = 0; k < 3; k++) {
        x[k] = (int32_t)(r->x[k] / 2);
        y[k] = (int32_t)(r->y[k] / 2);
    }
    if (!zl_tri_exact_depths3(poly, a, b, c, x, y, z))
        return;
    for (k = 0; k < 3; k++)
        if (z[k] < -((int64_t)1 << 39) || z[k] >= ((int64_t)1 << 39))
            return;
    for (k = 0; k < 3; k++)
        r->z[k] = (uint32_t)(zl_floor_shift64(z[k], 8) + ((int64_t)1 << 31));
    r->wide = 1;
}

int zl_raycast_render_rows(zl_vis *v, zl_rgb clear, zl_vis_row_fn fn, void *user)
{
    zl_vis_rtri *pool = (zl_vis_rtri *)v->pool;
    const int64_t s = ZL_SUB_ONE;
    unsigned bpp = zl_format_bytes((zl_format)v->cfg.format);
    uint32_t count = 0;
    uint8_t bg[3], clear_rgb[3];
    uint16_t y, i;
    zl_status st = zl_vis_plan(v);
    if (st != ZL_OK)
        return st;
    clear_rgb[0] = clear.r;
    clear_rgb[1] = clear.g;
    clear_rgb[2] = clear.b;
    zl_vis_pack((zl_format)v->cfg.format, clear_rgb, bg);
    for (y = 0; y < v->cfg.height; y++) {
        uint16_t begin = y == 0 ? 0 : v->row_start[y - 1], end = v->row_start[y];
        uint32_t b;
        zl_vis_row row;
        int64_t py = 2 * s * y + s;
        int rc;
        /* Retire finished pieces first, so the pool never holds more than
         * planning counted (order does not matter: ties go by id). */
        for (b = 0; b < count;) {
            if ((int32_t)pool[b].end <= (int32_t)y)
                pool[b] = pool[--count];
            else
                b++;
        }
        /* Activate the edge-table bucket of this row. */
        for (b = begin; b < end; b++) {
            zl_source src;
            zl_poly poly;
            uint32_t t;
            unsigned k, mi = zl_vis_source(v, v->visible[b], &src, &t);
            if (!zl_tri_polygon(&src, t, &poly))
                continue;
            for (k = 1; k + 1 < poly.n && count < v->cfg.max_active; k++) {
                zl_vis_rtri *r = &pool[count];
                int32_t f;
                if (!zl_vis_rtri_init(r, &poly.v[0], &poly.v[k], &poly.v[k + 1], &v->meshes[mi].state,
                                      v->cfg.width, v->cfg.height, &f))
                    continue;
                if (poly.clipped) {
                    if (ZL_FEATURE_EXACT_CLIP) /* off: the piece's own depths, as the z-buffer's */
                        wide_depths(r, &src, t);
                } else if (poly.n == 3 && poly.fx[0] != ZL_FINE_NONE) { /* the exact mapping's plane */
                    exact_depths(r, &poly, &poly.v[0], &poly.v[k], &poly.v[k + 1]);
                }
                r->id = v->visible[b];
                r->rgb[0] = poly.flat.r;
                r->rgb[1] = poly.flat.g;
                r->rgb[2] = poly.flat.b;
                count++;
            }
        }
        for (i = 0; i < (uint16_t)v->cfg.width; i++) { /* width <= ZL_MAX_DIM, checked at begin */
            int64_t px = 2 * s * i + s;
            uint64_t z1 = UINT64_MAX, z2 = UINT64_MAX;
            const zl_vis_rtri *best = NULL;
            uint64_t gap;
            for (b = 0; b < count; b++) {
                const zl_vis_rtri *r = &pool[b];
                uint64_t z;
                if ((int32_t)r->first > (int32_t)y || i < r->px0 || i >= r->px1 || !cast(r, px, py, &z))
                    continue;
                if (best == NULL || z < z1 || (z == z1 && r->id < best->id)) {
                    z2 = z1;
                    z1 = z;
                    best = r;
                } else if (z < z2) {
                    z2 = z;
                }
            }
            if (best == NULL) {
                v->id_row[i] = ZL_VIS_NONE;
                v->gap_row[i] = 65535;
                zl_vis_fill(v->color_row + (size_t)i * bpp, bpp, bg, 1);
                continue;
            }
            gap = z2 == UINT64_MAX ? 65535u : (z2 - z1) >> 8;
            v->id_row[i] = best->id;
            v->gap_row[i] = (uint16_t)(gap > 65535u ? 65535u : gap);
            {
                uint8_t pix[3];
                zl_vis_pack((zl_format)v->cfg.format, best->rgb, pix);
                zl_vis_fill(v->color_row + (size_t)i * bpp, bpp, pix, 1);
            }
        }
        row.y = y;
        row.width = v->cfg.width;
        row.color = v->color_row;
        row.ids = v->id_row;
        row.gap = v->gap_row;
        rc = fn(user, &row);
        if (rc != 0)
            return rc;
    }
    return 0;
}
