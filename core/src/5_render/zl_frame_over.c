/* SPDX-License-Identifier: MIT */
/*
 * Stage 5, render: scanline and band mode over capacity (issue 25), its
 * planning; zl_frame_rows.c's over_band renders the bands. When the whole
 * frame's plan does not fit the work buffer (more visible primitives than
 * max_triangles, or more crossing a row than max_active), the rows are
 * planned a window at a time: the longest run of whole bands whose
 * primitives fit one plan (zl_frame_over_window), rendered band after band
 * from that plan. A band where not even that fits is rendered in slices
 * (zl_frame_over_slice): a slice keeps, in submission order, the primitives
 * crossing the band's rows from a first id on, as many as fit; the band is
 * rendered slice after slice into the same colour and depth rows, so every
 * pixel still sees the primitives in id order (depth ties and blending as
 * in frame mode). Each window classifies every primitive twice (count,
 * which finds the window, then place), each slice of a band twice more:
 * the cost of the fallback, paid only over capacity; the normal path is
 * untouched. Without the fast paths (ZL_FAST_PATHS=0, zl_config.h) every
 * whole frame is planned here, so zl_frame_plan.c's planning is not in
 * flash: a frame that fits is one window, counted by zl_frame_over_begin.
 */
#include <string.h>

#include "zl_frame_internal.h"
#include "../3_raster/zl_raster.h"

/* Row range [*first, *end) of primitive t of mesh record mi and the active
 * records it takes (its pieces); 0 when it draws nothing. The same
 * classification as zl_frame_plan.c's passes, in its general form. */
static ZL_NOINLINE unsigned prim_rows(const zl_frame *f, unsigned mi, uint32_t t, int32_t *first, int32_t *end)
{
    const zl_frame_mesh *m = &f->meshes[mi];
    const zl_style *sty = style_of(f, mi);
    zl_source s;
    zl_poly poly;
    unsigned k, n, pieces = 0;
    /* a filled triangle cached inside: one piece, or none (without the fast
     * paths the general classification below, the same rows: zl_config.h) */
    int cached = ZL_FAST_PATHS ? zl_frame_rows_cached(f, mi, t, first, end) : -1;
    if (cached >= 0)
        return (unsigned)cached;
    *first = INT16_MAX;
    *end = 0;
    source_of(f, m, &s);
    if ((ZL_FEATURE_LINES || ZL_FEATURE_OUTLINES) && sty != NULL && ext_of(f, mi)->is_lines) {
        zl_active rec;
        if (!prim_record(f, mi, &s, t, &rec))
            return 0;
        *first = rec.row;
        *end = rec.end;
        return 1;
    }
    if (!zl_tri_polygon_geom(&s, sty, t, &poly))
        return 0;
    if (ZL_FEATURE_LINES && sty != NULL && (sty->polygon_front != ZL_POLY_FILL || sty->polygon_back != ZL_POLY_FILL)) {
        poly.light = 255; /* the colour does not matter for the rows */
        poly.flat.r = poly.flat.g = poly.flat.b = 0;
        n = zl_tri_pieces(&s, sty, t, &poly);
        for (k = 0; k < n; k++) {
            zl_active rec;
            if (!zl_tri_piece(&s, sty, t, &poly, k, &rec, NULL, NULL))
                continue;
            pieces++;
            *first = rec.row < *first ? rec.row : *first;
            *end = rec.end > *end ? rec.end : *end;
        }
        return pieces;
    }
    for (k = 1; k + 1 < poly.n; k++) {
        int32_t a, b;
        if (!zl_tri_classify(&poly.v[0], &poly.v[k], &poly.v[k + 1], &m->state, s.width, s.height, &a, &b))
            continue;
        pieces++;
        *first = a < *first ? a : *first;
        *end = b > *end ? b : *end;
    }
    return pieces;
}

/* Mesh record of primitive id, from record mi on (ids rise with records). */
static ZL_SMALL_NOINLINE unsigned mesh_from(const zl_frame *f, unsigned mi, uint32_t id)
{
    while (mi + 1u < f->mesh_count && id >= f->meshes[mi + 1u].tri_base)
        mi++;
    return mi;
}

/* Whether a primitive of `pieces` records on rows [first, end) still fits
 * the slice's per-row counts cnt of rows [r0, r1); if so it is counted. */
static int take_rows(uint32_t *cnt, const zl_frame *f, int32_t r0, int32_t r1, int32_t first, int32_t end,
                     unsigned pieces)
{
    int32_t y, lo = first > r0 ? first : r0, hi = end < r1 ? end : r1;
    for (y = lo; y < hi; y++)
        if (cnt[y - r0] + pieces > f->cfg.max_active)
            return 0;
    for (y = lo; y < hi; y++)
        cnt[y - r0] += pieces;
    return 1;
}

/* The plan of rows [r0, r1) once row_start counts the primitives at
 * their first rows: the counts become bucket starts, the primitives of ids
 * [id_lo, id_hi) crossing those rows go to visible[] bucket by bucket (ids
 * in order), the pool's records to its free list. */
static void place(zl_frame *f, uint16_t r0, uint16_t r1, uint32_t id_lo, uint32_t id_hi)
{
    uint32_t id, start = 0, slot;
    unsigned mi = 0;
    uint16_t j;
    for (j = 0; j <= f->cfg.height; j++) { /* counts -> bucket starts */
        uint16_t c = f->row_start[j];
        f->row_start[j] = (uint16_t)start;
        start += c;
    }
    for (id = id_lo; id < id_hi; id++) {
        int32_t first, end;
        mi = mesh_from(f, mi, id);
        if (prim_rows(f, mi, id - f->meshes[mi].tri_base, &first, &end) != 0 && first < r1 && end > r0)
            f->visible[f->row_start[first]++] = (uint16_t)id;
    }
    for (slot = 0; slot < f->cfg.max_active; slot++)
        f->pool[slot].next = (uint16_t)(slot + 1u < f->cfg.max_active ? slot + 1u : ZL_LIST_END);
    f->free_head = 0;
    f->active_head = ZL_LIST_END;
}

/* Plan the slice of rows [r0, r1) from primitive id_lo: the primitives
 * crossing those rows, in id order, while max_triangles and max_active
 * hold, bucketed by first row; *id_hi: the id the slice stopped before.
 * The per-row counts borrow the pool, whose region (with the Gouraud one
 * after it) holds height + 1 int32 (zl_frame_layout). */
void zl_frame_over_slice(zl_frame *f, uint16_t r0, uint16_t r1, uint32_t id_lo, uint32_t *id_hi)
{
    uint32_t *cnt = (uint32_t *)(void *)f->pool;
    uint32_t id, n = 0;
    unsigned mi = 0;
    memset(f->row_start, 0, ((size_t)f->cfg.height + 1) * sizeof(uint16_t));
    memset(cnt, 0, (size_t)(r1 - r0) * sizeof(uint32_t));
    for (id = id_lo; id < f->triangle_total; id++) {
        int32_t first, end;
        unsigned pieces;
        mi = mesh_from(f, mi, id);
        pieces = prim_rows(f, mi, id - f->meshes[mi].tri_base, &first, &end);
        if (pieces == 0 || first >= r1 || end <= r0)
            continue;
        if (n >= f->cfg.max_triangles || !take_rows(cnt, f, r0, r1, first, end, pieces))
            break;
        f->row_start[first]++;
        n++;
    }
    *id_hi = id;
    place(f, r0, r1, id_lo, id);
}

/* One classification pass from row r0: every primitive reaching r0 or below
 * counted at its first row (row_start) and its records over its rows (a
 * difference array in the pool, as planning's). 0 when one primitive alone
 * does not fit (max_triangles 0, or more pieces than max_active); the
 * counts are whole either way (the needs of a refused frame). */
static int count_from(zl_frame *f, uint16_t r0, int32_t *diff)
{
    uint16_t h = f->cfg.height;
    uint32_t id;
    unsigned mi = 0;
    int fits = 1;
    memset(f->row_start, 0, ((size_t)h + 1) * sizeof(uint16_t));
    memset(diff, 0, ((size_t)h + 1) * sizeof(int32_t));
    for (id = 0; id < f->triangle_total; id++) {
        int32_t first, end;
        unsigned pieces;
        mi = mesh_from(f, mi, id);
        pieces = prim_rows(f, mi, id - f->meshes[mi].tri_base, &first, &end);
        if (pieces == 0 || end <= r0)
            continue;
        if (f->cfg.max_triangles == 0 || pieces > f->cfg.max_active)
            fits = 0;
        f->row_start[first]++;
        diff[first] += (int32_t)pieces;
        diff[end] -= (int32_t)pieces;
    }
    return fits;
}

/* The end of the longest window of whole bands from row r0 whose
 * primitives fit in one plan: those crossing it at most max_triangles, at
 * most max_active records on each of its rows; r0 when not even its first
 * band fits (then the band goes in slices). A window is planned here, from
 * the same counts: the primitives crossing it are those counted with a
 * first row above its end, so the counts need no second pass. */
uint16_t zl_frame_over_window(zl_frame *f, uint16_t r0)
{
    int32_t *diff = (int32_t *)(void *)f->pool;
    uint16_t y, end_ok = r0;
    uint32_t kept = 0, active = 0;
    /* every primitive fits alone (zl_frame_over_begin checked); row 0's
     * counts are still there from zl_frame_over_begin, called just before
     * the first band */
    if (r0 != 0)
        (void)count_from(f, r0, diff);
    for (y = 0; y < f->end_row; y++) { /* the counted primitives crossing row y */
        kept += f->row_start[y];
        active = (uint32_t)((int32_t)active + diff[y]);
        if (y < r0)
            continue;
        if (kept > f->cfg.max_triangles || active > f->cfg.max_active)
            break;
        if ((uint16_t)(y + 1u) % f->cfg.band_rows == 0 || y + 1u == f->end_row)
            end_ok = (uint16_t)(y + 1u);
    }
    if (end_ok > r0)
        place(f, r0, end_ok, 0, f->triangle_total);
    return end_ok;
}

zl_status zl_frame_over_begin(zl_frame *f)
{
    int32_t *diff = (int32_t *)(void *)f->pool;
    uint32_t running = 0;
    uint16_t y;
    int fits;
    if (!ZL_FAST_PATHS) /* every frame starts here (zl_frame_next_band): no plan filled the cache */
        zl_frame_fill_cache(f);
    fits = count_from(f, 0, diff);
    /* the whole frame's needs, as zl_frame_plan reports them */
    f->needs.triangles = 0;
    f->needs.active = 0;
    for (y = 0; y < f->cfg.height; y++) {
        f->needs.triangles += f->row_start[y];
        running = (uint32_t)((int32_t)running + diff[y]);
        if (running > f->needs.active)
            f->needs.active = running;
    }
    return fits ? ZL_OK : ZL_ERR_CAPACITY; /* else one primitive alone does not fit */
}
