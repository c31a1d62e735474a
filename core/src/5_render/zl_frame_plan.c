/* SPDX-License-Identifier: MIT */
/*
 * Stage 5, render: planning of scanline and band mode (the first band): fill
 * the vertex cache, classify every triangle once, bound the active set with
 * a difference array, and bucket the visible triangles by first row (the
 * edge table). See zl_frame.c for the whole scheme.
 */
#include <string.h>

#include "zl_frame_internal.h"
#include "../3_raster/zl_raster.h"

void zl_frame_fill_cache(zl_frame *f)
{
    uint16_t mi;
    for (mi = 0; mi < f->mesh_count; mi++) {
        const zl_frame_mesh *m = &f->meshes[mi];
        zl_source s;
        source_of(f, m, &s);
        /* add_record checked the transform limits: the status is ZL_OK */
        if (!(m->flags & MESH_CACHED) && m->mesh.vertex_count != 0)
            (void)zl_cache_vertices(&s, cache_of(f) + m->vert_base, 0, m->mesh.vertex_count);
    }
}

/* State of a classification pass. The count pass (diff != NULL) counts first
 * rows in row_start, adds each primitive's pieces over its rows to diff,
 * writes the ids of the visible primitives in id order to visible[] (while
 * they fit) and their first rows to the keys (while they fit). The place pass
 * (diff == NULL) drops each id into its bucket of visible[]. */
typedef struct {
    int32_t *diff;
    uint16_t *key_a, *key_b; /* spare work-buffer regions holding first rows */
    uint32_t na, nb;         /* their capacities, in keys */
    uint32_t n;              /* visible primitives so far */
    uint8_t *seen;           /* NULL, or a bit per filled triangle id: visible (count pass) */
    int marking;             /* the keys ran out: the count pass marks seen instead */
    int32_t lo, hi;          /* the rows planned: a primitive outside [lo, hi) is dropped */
} plan_pass;

static ZL_ALWAYS_INLINE void mark_seen(const plan_pass *p, uint32_t id)
{
    p->seen[id >> 3] = (uint8_t)(p->seen[id >> 3] | (1u << (id & 7u)));
}

static uint16_t *key_at(const plan_pass *p, uint32_t k)
{
    return k < p->na ? &p->key_a[k] : &p->key_b[k - p->na];
}

/* Record visible primitive id with row range [first, end) and its pieces. */
static ZL_ALWAYS_INLINE void note_rows(zl_frame *f, plan_pass *p, uint32_t id, int32_t first, int32_t end,
                                       unsigned pieces, int window)
{
    if (window && (first >= p->hi || end <= p->lo)) /* the other part of a split frame's */
        return;
    if (p->diff == NULL) {
        f->visible[f->row_start[first]++] = (uint16_t)id;
    } else {
        f->row_start[first]++;
        p->diff[first] += (int32_t)pieces;
        p->diff[end] -= (int32_t)pieces;
        if (p->n < f->cfg.max_triangles)
            f->visible[p->n] = (uint16_t)id;
        if (p->n < p->na + p->nb)
            *key_at(p, p->n) = (uint16_t)first;
    }
    p->n++;
}

/* note_rows for a part of a split frame (p's rows only) or a whole one. */
static ZL_ALWAYS_INLINE void note(zl_frame *f, plan_pass *p, uint32_t id, int32_t first, int32_t end, unsigned pieces)
{
    note_rows(f, p, id, first, end, pieces, ZL_FEATURE_SPLIT && f->part != 0);
}

/* Lines and outline records: one record per primitive. Out of line, like the
 * next one, so its record is not on the stack of the clipping path. */
static ZL_NOINLINE void classify_lines(zl_frame *f, plan_pass *p, unsigned mi, const zl_source *s)
{
    const zl_frame_mesh *m;
    uint32_t t;
    if (!(ZL_FEATURE_LINES || ZL_FEATURE_OUTLINES)) /* compiled out (zl_config.h): no such records */
        return;
    m = &f->meshes[mi];
    for (t = 0; t < m->mesh.triangle_count; t++) {
        zl_active rec;
        if (prim_record(f, mi, s, t, &rec))
            note(f, p, m->tri_base + t, rec.row, rec.end, 1);
    }
}

/* Triangles in line or point polygon modes: the row ranges of their pieces,
 * from a full setup (the colour does not matter here). */
static ZL_NOINLINE void classify_pieces(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                        const zl_style *sty)
{
    uint32_t t;
    if (!ZL_FEATURE_LINES) /* compiled out (zl_config.h): no line or point modes (zl_style_check) */
        return;
    for (t = 0; t < m->mesh.triangle_count; t++) {
        zl_poly poly;
        unsigned k, n, pieces = 0;
        int32_t first = INT16_MAX, end = 0;
        if (!zl_tri_polygon_geom(s, sty, t, &poly))
            continue;
        poly.light = 255;
        poly.flat.r = poly.flat.g = poly.flat.b = 0;
        n = zl_tri_pieces(s, sty, t, &poly);
        for (k = 0; k < n; k++) {
            zl_active rec;
            if (!zl_tri_piece(s, sty, t, &poly, k, &rec, NULL, NULL))
                continue;
            pieces++;
            if (rec.row < first)
                first = rec.row;
            if (rec.end > end)
                end = rec.end;
        }
        if (pieces != 0)
            note(f, p, m->tri_base + t, first, end, pieces);
    }
}

/* zl_tri_classify of a triangle whose three vertices are cached inside the
 * clip volume (then its polygon is the triangle itself, one piece): the
 * same area test, row range and column test, on the int16 coordinates
 * (whose products fit 64 bits). cull_sign: culled_area_sign. */
static ZL_ALWAYS_INLINE int classify_cached(const zl_cached_vertex *a, const zl_cached_vertex *b,
                                            const zl_cached_vertex *c, int cull_sign, uint16_t width,
                                            uint16_t height, int32_t *first, int32_t *end)
{
    int32_t ymin = a->y, xmin = a->x, ymax, xmax;
#if ZL_MUL32_ONLY
    /* no 64-bit multiply: products and compare in 32 bits where they are
     * exact there (two __aeabi_lmul a triangle saved on ARMv6-M) */
    if (zl_area_fits32(b->x - a->x, c->y - a->y, c->x - a->x, b->y - a->y)) {
        int32_t p = (b->x - a->x) * (c->y - a->y), q = (c->x - a->x) * (b->y - a->y);
        if (p == q || (p < q ? -1 : 1) == cull_sign)
            return 0;
    } else
#endif
    {
        int64_t p = (int64_t)(b->x - a->x) * (c->y - a->y), q = (int64_t)(c->x - a->x) * (b->y - a->y);
        if (p == q || (p < q ? -1 : 1) == cull_sign)
            return 0;
    }
    ymax = ymin;
    xmax = xmin;
    if (b->y < ymin)
        ymin = b->y;
    if (b->y > ymax)
        ymax = b->y;
    if (c->y < ymin)
        ymin = c->y;
    if (c->y > ymax)
        ymax = c->y;
    *first = first_centre_at_or_after(ymin);
    *end = first_centre_at_or_after(ymax);
    if (*first < 0)
        *first = 0;
    if (*end > height)
        *end = height;
    if (*first >= *end)
        return 0;
    if (b->x < xmin)
        xmin = b->x;
    if (b->x > xmax)
        xmax = b->x;
    if (c->x < xmin)
        xmin = c->x;
    if (c->x > xmax)
        xmax = c->x;
    return first_centre_at_or_after(xmin) < width && first_centre_at_or_after(xmax) > 0;
}

int zl_frame_rows_cached(const zl_frame *f, unsigned mi, uint32_t t, int32_t *first, int32_t *end)
{
    const zl_frame_mesh *m = &f->meshes[mi];
    const zl_style *sty = style_of(f, mi);
    const uint16_t *idx;
    const zl_cached_vertex *cache = cache_of(f) + m->vert_base, *c0, *c1, *c2;
    if (sty != NULL && (ext_of(f, mi)->is_lines || sty->polygon_front != ZL_POLY_FILL ||
                        sty->polygon_back != ZL_POLY_FILL))
        return -1;
    idx = m->mesh.indices + (size_t)t * 3u;
    c0 = &cache[ZL_MESH_IDX(idx, 0)];
    c1 = &cache[ZL_MESH_IDX(idx, 1)];
    c2 = &cache[ZL_MESH_IDX(idx, 2)];
    if (c0->x <= ZL_CACHE_INVALID || c1->x <= ZL_CACHE_INVALID || c2->x <= ZL_CACHE_INVALID)
        return -1;
    return classify_cached(c0, c1, c2, (int)m->cull_code - 1, f->cfg.width, f->cfg.height, first, end);
}

/* Filled triangle t that needs clipping (or is dropped): the row range of
 * every fan triangle of its polygon. Out of line, so the polygon is not on
 * the stack (nor in the registers) of the loop below. */
static ZL_ALWAYS_INLINE void polygon_rows(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                          const zl_style *sty, uint32_t t, int window)
{
    zl_poly poly;
    unsigned k, pieces = 0;
    int32_t first = INT16_MAX, end = 0;
    if (!zl_tri_polygon_geom(s, sty, t, &poly))
        return;
    for (k = 1; k + 1 < poly.n; k++) {
        int32_t a, b;
        if (!zl_tri_classify(&poly.v[0], &poly.v[k], &poly.v[k + 1], &m->state, s->width, s->height, &a, &b))
            continue;
        pieces++;
        if (a < first)
            first = a;
        if (b > end)
            end = b;
    }
    if (pieces != 0)
        note_rows(f, p, m->tri_base + t, first, end, pieces, window);
}

static ZL_NOINLINE void classify_polygon(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                         const zl_style *sty, uint32_t t)
{
    polygon_rows(f, p, m, s, sty, t, 0);
}

/* classify_polygon for a part of a split frame: its rows only. */
static ZL_NOINLINE void classify_polygon_window(zl_frame *f, plan_pass *p, const zl_frame_mesh *m,
                                                const zl_source *s, const zl_style *sty, uint32_t t)
{
    polygon_rows(f, p, m, s, sty, t, 1);
}

/* classify_fill's count pass when a bit array follows the keys (p->seen):
 * with `marking` (from triangle `from` on) a bit a visible triangle instead
 * of its id and first row; without it ids and first rows until the keys are
 * full, then it stops. Returns the triangle it stopped before. */
static ZL_ALWAYS_INLINE uint32_t fill_pass(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                           const zl_style *sty, uint32_t from, int marking)
{
    uint16_t w = f->cfg.width, h = f->cfg.height;
    uint32_t t, count = m->mesh.triangle_count, n = p->n, id = m->tri_base + from;
    uint32_t max_visible = f->cfg.max_triangles, na = p->na, nkeys = p->na + p->nb;
    const uint16_t *idx;
    const zl_cached_vertex *cache = s->cache;
    uint16_t *row_start = f->row_start, *visible = f->visible;
    int32_t *diff = p->diff;
    uint8_t *seen = p->seen;
    int cull_sign = (int)m->cull_code - 1;
    if (from >= count) /* an empty mesh may have no index array: no arithmetic on NULL */
        return from;
    idx = m->mesh.indices + (size_t)from * 3u;
    for (t = from; t < count; t++, id++, idx += 3) {
        int32_t first, end;
        const zl_cached_vertex *c0 = &cache[ZL_MESH_IDX(idx, 0)], *c1 = &cache[ZL_MESH_IDX(idx, 1)],
                               *c2 = &cache[ZL_MESH_IDX(idx, 2)];
        if (c0->x <= ZL_CACHE_INVALID || c1->x <= ZL_CACHE_INVALID || c2->x <= ZL_CACHE_INVALID) {
            p->n = n;
            classify_polygon(f, p, m, s, sty, t);
            if (marking && p->n != n)
                mark_seen(p, id);
            n = p->n;
            continue;
        }
        if (!classify_cached(c0, c1, c2, cull_sign, w, h, &first, &end))
            continue;
        row_start[first]++;
        diff[first] += 1;
        diff[end] -= 1;
        n++;
        if (marking) { /* the place pass needs the bit alone */
            seen[id >> 3] = (uint8_t)(seen[id >> 3] | (1u << (id & 7u)));
            continue;
        }
        if (n - 1u < max_visible)
            visible[n - 1u] = (uint16_t)id;
        if (n - 1u < na) {
            p->key_a[n - 1u] = (uint16_t)first;
        } else if (n - 1u < nkeys) {
            p->key_b[n - 1u - na] = (uint16_t)first;
        } else { /* the keys are full: the rest is marked (start_marking) */
            t++;
            break;
        }
    }
    p->n = n;
    return t;
}

/* The count pass once the keys are full (p->marking): no ids nor first rows
 * to write, a bit a visible triangle, for place_fill_seen. */
static ZL_NOINLINE void classify_fill_marking(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                              const zl_style *sty, uint32_t from)
{
    (void)fill_pass(f, p, m, s, sty, from, 1);
}

/* The keys are full: mark the visible triangles so far (their ids are in
 * visible[], in id order, unless there are more than it holds: then
 * planning fails on capacity and nothing is placed). */
static void start_marking(const zl_frame *f, plan_pass *p)
{
    uint32_t k;
    for (k = 0; k < p->n && k < f->cfg.max_triangles; k++)
        mark_seen(p, f->visible[k]);
    p->marking = 1;
}

/* The count pass while the keys last, with a bit array to go on in. */
static ZL_NOINLINE void classify_fill_may_mark(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                               const zl_style *sty)
{
    uint32_t stop = fill_pass(f, p, m, s, sty, 0, 0);
    if (stop < m->mesh.triangle_count) {
        start_marking(f, p);
        classify_fill_marking(f, p, m, s, sty, stop);
    }
}

/* Filled triangles: the row range of every fan triangle of the polygon;
 * a triangle with its three vertices cached inside is its own polygon, one
 * piece, classified on the cache (and noted here with the counters in
 * locals: note's work for one piece). */
static ZL_NOINLINE void classify_fill(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                      const zl_style *sty)
{
    uint16_t w = f->cfg.width, h = f->cfg.height;
    uint32_t t, count = m->mesh.triangle_count, n = p->n, id = m->tri_base;
    uint32_t max_visible = f->cfg.max_triangles, na = p->na, nkeys = p->na + p->nb;
    const uint16_t *idx = m->mesh.indices;
    const zl_cached_vertex *cache = s->cache;
    uint16_t *row_start = f->row_start, *visible = f->visible;
    int32_t *diff = p->diff;
    int cull_sign = (int)m->cull_code - 1;
    for (t = 0; t < count; t++, id++, idx += 3) {
        int32_t first, end;
        const zl_cached_vertex *c0 = &cache[ZL_MESH_IDX(idx, 0)], *c1 = &cache[ZL_MESH_IDX(idx, 1)],
                               *c2 = &cache[ZL_MESH_IDX(idx, 2)];
        if (c0->x <= ZL_CACHE_INVALID || c1->x <= ZL_CACHE_INVALID || c2->x <= ZL_CACHE_INVALID) {
            p->n = n;
            classify_polygon(f, p, m, s, sty, t);
            n = p->n;
            continue;
        }
        if (!classify_cached(c0, c1, c2, cull_sign, w, h, &first, &end))
            continue;
        if (diff == NULL) {
            visible[row_start[first]++] = (uint16_t)id;
        } else {
            row_start[first]++;
            diff[first] += 1;
            diff[end] -= 1;
            if (n < max_visible)
                visible[n] = (uint16_t)id;
            if (n < na)
                p->key_a[n] = (uint16_t)first;
            else if (n < nkeys)
                p->key_b[n - na] = (uint16_t)first;
        }
        n++;
    }
    p->n = n;
}

/* classify_fill without the fast paths (zl_config.h): the same rows, from
 * one out-of-line copy of the classification on the cache. */
static ZL_NOINLINE void classify_fill_compact(zl_frame *f, plan_pass *p, const zl_frame_mesh *m,
                                              const zl_source *s, const zl_style *sty)
{
    unsigned mi = (unsigned)(m - f->meshes);
    uint32_t t, id = m->tri_base;
    for (t = 0; t < m->mesh.triangle_count; t++, id++) {
        int32_t first, end;
        int cached = zl_frame_rows_cached(f, mi, t, &first, &end);
        if (cached < 0)
            classify_polygon(f, p, m, s, sty, t);
        else if (cached > 0)
            note(f, p, id, first, end, 1);
    }
}

/* The place pass of classify_fill when the count pass marked the visible
 * triangles in p->seen: only those, and of a triangle cached inside only its
 * first row (classify_cached's), which is all placing needs. */
static ZL_NOINLINE void place_fill_seen(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                        const zl_style *sty)
{
    uint32_t t, count = m->mesh.triangle_count, id = m->tri_base;
    const uint16_t *idx = m->mesh.indices;
    const zl_cached_vertex *cache = s->cache;
    const uint8_t *seen = p->seen;
    uint16_t *row_start = f->row_start, *visible = f->visible;
    for (t = 0; t < count; t++, id++, idx += 3) {
        int32_t first;
        const zl_cached_vertex *c0, *c1, *c2;
        if (!(seen[id >> 3] & (1u << (id & 7u))))
            continue;
        c0 = &cache[ZL_MESH_IDX(idx, 0)];
        c1 = &cache[ZL_MESH_IDX(idx, 1)];
        c2 = &cache[ZL_MESH_IDX(idx, 2)];
        if (c0->x <= ZL_CACHE_INVALID || c1->x <= ZL_CACHE_INVALID || c2->x <= ZL_CACHE_INVALID) {
            classify_polygon(f, p, m, s, sty, t);
            continue;
        }
        first = first_centre_at_or_after(min3(c0->y, c1->y, c2->y));
        if (first < 0)
            first = 0;
        visible[row_start[first]++] = (uint16_t)id;
    }
}

/* Whether a triangle with these window y (subpixels) crosses a row in
 * [lo, hi): its first row first_centre_at_or_after(ymin) is below hi, that
 * is ymin <= y_hi = (hi - 1) * ONE + HALF, and its end row
 * first_centre_at_or_after(ymax) is above lo, that is ymax > y_lo = lo * ONE
 * + HALF. A vertex at a time, so the other part's triangles cost a few
 * compares (classify_cached then tests as for one core). */
static ZL_ALWAYS_INLINE int in_rows(int32_t a, int32_t b, int32_t c, int32_t y_lo, int32_t y_hi, int part)
{
    /* the first part's rows start at 0, where classify_cached tests the
     * end row anyway; the second's end at the height, where it tests the
     * first: one side each */
    if (part == 1)
        return a <= y_hi || b <= y_hi || c <= y_hi;
    return a > y_lo || b > y_lo || c > y_lo;
}

/* classify_fill for one part of a split frame: without the bit array (the
 * keys' second pass places by classifying again), triangles outside the
 * part's rows dropped first. */
static ZL_ALWAYS_INLINE void fill_window(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                         const zl_style *sty, int part)
{
    uint16_t w = f->cfg.width, h = f->cfg.height;
    uint32_t t, count = m->mesh.triangle_count, n = p->n, id = m->tri_base;
    uint32_t max_visible = f->cfg.max_triangles, na = p->na, nkeys = p->na + p->nb;
    const uint16_t *idx = m->mesh.indices;
    const zl_cached_vertex *cache = s->cache;
    uint16_t *row_start = f->row_start, *visible = f->visible;
    int32_t *diff = p->diff;
    int32_t y_lo = p->lo * ZL_SUB_ONE + ZL_SUB_HALF, y_hi = (p->hi - 1) * ZL_SUB_ONE + ZL_SUB_HALF;
    int cull_sign = (int)m->cull_code - 1;
    for (t = 0; t < count; t++, id++, idx += 3) {
        int32_t first, end;
        const zl_cached_vertex *c0 = &cache[ZL_MESH_IDX(idx, 0)], *c1 = &cache[ZL_MESH_IDX(idx, 1)],
                               *c2 = &cache[ZL_MESH_IDX(idx, 2)];
        if (c0->x <= ZL_CACHE_INVALID || c1->x <= ZL_CACHE_INVALID || c2->x <= ZL_CACHE_INVALID) {
            p->n = n;
            classify_polygon_window(f, p, m, s, sty, t);
            n = p->n;
            continue;
        }
        if (!in_rows(c0->y, c1->y, c2->y, y_lo, y_hi, part) ||
            !classify_cached(c0, c1, c2, cull_sign, w, h, &first, &end))
            continue;
        if (diff == NULL) {
            visible[row_start[first]++] = (uint16_t)id;
        } else {
            row_start[first]++;
            diff[first] += 1;
            diff[end] -= 1;
            if (n < max_visible)
                visible[n] = (uint16_t)id;
            if (n < na)
                p->key_a[n] = (uint16_t)first;
            else if (n < nkeys)
                p->key_b[n - na] = (uint16_t)first;
        }
        n++;
    }
    p->n = n;
}

static ZL_NOINLINE void classify_fill_first(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                            const zl_style *sty)
{
    fill_window(f, p, m, s, sty, 1);
}

static ZL_NOINLINE void classify_fill_second(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                             const zl_style *sty)
{
    fill_window(f, p, m, s, sty, 2);
}

/* classify_pass for one part of a split frame. */
static ZL_NOINLINE uint32_t classify_pass_window(zl_frame *f, plan_pass *p)
{
    uint16_t mi;
    p->n = 0;
    for (mi = 0; mi < f->mesh_count; mi++) {
        const zl_frame_mesh *m = &f->meshes[mi];
        const zl_style *sty = style_of(f, mi);
        zl_source s;
        source_of(f, m, &s);
        if (sty != NULL && ext_of(f, mi)->is_lines)
            classify_lines(f, p, mi, &s);
        else if (sty != NULL && (sty->polygon_front != ZL_POLY_FILL || sty->polygon_back != ZL_POLY_FILL))
            classify_pieces(f, p, m, &s, sty);
        else if (f->part == 1)
            classify_fill_first(f, p, m, &s, sty);
        else
            classify_fill_second(f, p, m, &s, sty);
    }
    return p->n;
}

/* One pass over every primitive of every mesh; returns the visible ones. */
static uint32_t classify_pass(zl_frame *f, plan_pass *p)
{
    uint16_t mi;
    p->n = 0;
    for (mi = 0; mi < f->mesh_count; mi++) {
        const zl_frame_mesh *m = &f->meshes[mi];
        const zl_style *sty = style_of(f, mi);
        zl_source s;
        source_of(f, m, &s);
        if (sty != NULL && ext_of(f, mi)->is_lines)
            classify_lines(f, p, mi, &s);
        else if (sty != NULL && (sty->polygon_front != ZL_POLY_FILL || sty->polygon_back != ZL_POLY_FILL))
            classify_pieces(f, p, m, &s, sty);
        else if (ZL_FAST_PATHS && p->marking && p->diff == NULL)
            place_fill_seen(f, p, m, &s, sty);
        else if (ZL_FAST_PATHS && p->marking)
            classify_fill_marking(f, p, m, &s, sty, 0);
        else if (ZL_FAST_PATHS && p->seen != NULL && p->diff != NULL)
            classify_fill_may_mark(f, p, m, &s, sty);
        else if (!ZL_FAST_PATHS)
            classify_fill_compact(f, p, m, &s, sty);
        else
            classify_fill(f, p, m, &s, sty);
    }
    return p->n;
}

/* Bucket visible[0 .. n) by the first rows in the keys, stably and in place:
 * each key becomes its element's place, then the permutation is applied a
 * cycle at a time. row_start holds the bucket starts and ends at the ends. */
static void place_by_keys(zl_frame *f, const plan_pass *p, uint32_t n)
{
    uint16_t *row_start = f->row_start, *visible = f->visible;
    uint32_t k;
    if (n <= p->na) { /* all keys in the first region (the usual case) */
        uint16_t *key = p->key_a;
        for (k = 0; k < n; k++)
            key[k] = row_start[key[k]]++;
        for (k = 0; k < n; k++) {
            while (key[k] != k) {
                uint16_t j = key[k], id = visible[k];
                visible[k] = visible[j];
                visible[j] = id;
                key[k] = key[j];
                key[j] = j;
            }
        }
        return;
    }
    for (k = 0; k < n; k++) {
        uint16_t *key = key_at(p, k);
        *key = row_start[*key]++;
    }
    for (k = 0; k < n; k++) {
        uint16_t *key = key_at(p, k);
        while (*key != k) {
            uint16_t j = *key, id = visible[k];
            uint16_t *kj = key_at(p, j);
            visible[k] = visible[j];
            visible[j] = id;
            *key = *kj;
            *kj = j;
        }
    }
}

/* When the keys may not all fit (more triangles than keys), a bit per
 * triangle id at the end of the larger key region, taken from the keys: if
 * the count pass fills the keys it marks the visible triangles instead, so
 * that the second pass visits those alone, and only for their first rows
 * (the triangle-rate scene: 8,192 triangles, about 2,300 keys; Cortex-M4
 * -O2 planning 1.86 M -> 1.4 M instructions). Otherwise none. */
static void reserve_seen(const zl_frame *f, plan_pass *p)
{
    uint32_t ids = f->triangle_total, words = (ids + 15u) / 16u; /* in keys */
    p->seen = NULL;
    p->marking = 0;
    if (!ZL_FAST_PATHS || ids <= p->na + p->nb) /* without the fast paths: classify twice */
        return;
    if (p->nb >= words && p->nb >= p->na) {
        p->nb -= words;
        p->seen = (uint8_t *)(void *)(p->key_b + p->nb);
    } else if (p->na >= words) {
        p->na -= words;
        p->seen = (uint8_t *)(void *)(p->key_a + p->na);
    } else {
        return;
    }
    memset(p->seen, 0, (size_t)words * sizeof(uint16_t));
}

zl_status zl_frame_plan(zl_frame *f)
{
    layout l;
    uint8_t *pool;
    int window = ZL_FEATURE_SPLIT && f->part != 0; /* a part of a split frame: its rows only */
    uint32_t running = 0, start = 0, peak = 0, slot, visible;
    uint16_t h = f->cfg.height, j;
    size_t diff_bytes = ALIGN8(((size_t)h + 1) * sizeof(int32_t));
    plan_pass p;
    if (!zl_frame_layout(&f->cfg, &l)) /* cannot fail: zl_frame_begin checked the configuration */
        return ZL_ERR_ARG;
    if (window) {
        if (!f->prepared) /* its share of the vertex cache (zl_frame_prepare) */
            return ZL_ERR_ARG;
        if (f->split_row == 0)
            zl_frame_split_resolve(f);
    }
    /* regions by their offsets from the pool (the second part of a split
     * frame has the same offsets from there on: zl_frame_split) */
    pool = (uint8_t *)(void *)f->pool;
    p.lo = f->next_row;
    p.hi = f->end_row;
    /* Until the first row the pool (after the difference array), the
     * Gouraud records and everything from the texture planes to the colour
     * bands are free: room for the first rows of the visible primitives,
     * which then need no second classification. */
    p.diff = (int32_t *)(void *)f->pool;
    p.key_a = (uint16_t *)(void *)(pool + diff_bytes);
    p.na = l.at[L_EXT] - l.at[L_POOL] > diff_bytes
               ? (uint32_t)((l.at[L_EXT] - l.at[L_POOL] - diff_bytes) / sizeof(uint16_t))
               : 0;
    p.key_b = (uint16_t *)(void *)(pool + (l.at[L_TEX] - l.at[L_POOL]));
    p.nb = (uint32_t)((l.at[L_TOTAL] - l.at[L_TEX]) / sizeof(uint16_t));
    if (window) { /* no bit array: a part's keys rarely run out */
        p.seen = NULL;
        p.marking = 0;
    } else {
        reserve_seen(f, &p);
    }
    if (!window) /* the parts cached theirs (zl_frame_prepare) */
        zl_frame_fill_cache(f);
    memset(f->row_start, 0, ((size_t)h + 1) * sizeof(uint16_t));
    memset(p.diff, 0, ((size_t)h + 1) * sizeof(int32_t));
    visible = window ? classify_pass_window(f, &p) : classify_pass(f, &p);
    f->needs.triangles = visible;
    for (j = 0; j < h; j++) {
        running += (uint32_t)p.diff[j];
        if (running > peak)
            peak = running;
    }
    f->needs.active = peak;
    if (f->needs.triangles > f->cfg.max_triangles || f->needs.active > f->cfg.max_active)
        return ZL_ERR_CAPACITY;
    /* Counts -> bucket starts; placing advances each to its bucket's end. */
    for (j = 0; j <= h; j++) {
        uint16_t n = f->row_start[j];
        f->row_start[j] = (uint16_t)start;
        start += n;
    }
    if (!p.marking && visible <= p.na + p.nb) {
        place_by_keys(f, &p, visible);
    } else { /* the keys did not fit: classify again */
        p.diff = NULL;
        (void)(window ? classify_pass_window(f, &p) : classify_pass(f, &p));
    }
    /* The pool's free list: every record, in order. */
    for (slot = 0; slot < f->cfg.max_active; slot++)
        f->pool[slot].next = (uint16_t)(slot + 1u < f->cfg.max_active ? slot + 1u : ZL_LIST_END);
    f->free_head = 0;
    f->active_head = ZL_LIST_END;
    return ZL_OK;
}
