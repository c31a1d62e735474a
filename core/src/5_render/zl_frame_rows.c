/* SPDX-License-Identifier: MIT */
/*
 * Stage 5, render: the rows of scanline and band mode. Each row walks the
 * active list (sorted by id, so submission order holds), activates the
 * bucket's triangles as it passes their place, fills and steps every active
 * triangle, and retires those past their last row.
 */
#include <string.h>

#include "zl_frame_internal.h"

/* Bytes a pixel of the frame's format: 2 without ZL_FEATURE_FORMATS, where
 * zl_frame_begin refuses RGB888 (a constant the compiler folds). */
static size_t frame_bpp(const zl_frame *f)
{
    return ZL_FEATURE_FORMATS ? zl_format_bytes((zl_format)f->cfg.format) : 2u;
}

static uint8_t mesh_of_id(const zl_frame *f, uint16_t id)
{
    uint8_t mi = 0;
    while ((int32_t)mi + 1 < (int32_t)f->mesh_count && id >= f->meshes[mi + 1].tri_base)
        mi++;
    return mi;
}

static zl_gouraud *gouraud_of(const zl_frame *f, uint16_t slot)
{
    return f->gouraud ? (zl_gouraud *)(void *)(f->gouraud + (size_t)slot * sizeof(zl_gouraud)) : NULL;
}

static zl_texplanes *tex_of(const zl_frame *f, uint16_t slot)
{
    return f->tex ? (zl_texplanes *)(void *)(f->tex + (size_t)slot * sizeof(zl_texplanes)) : NULL;
}

/* A record's flat colour as span_565 writes it (native RGB565), once per
 * record instead of once per row. */
static ZL_ALWAYS_INLINE uint16_t pixel565(const zl_active *a)
{
    return (uint16_t)(((unsigned)(a->rgb[0] >> 3) << 11) | ((unsigned)(a->rgb[1] >> 2) << 5) |
                      (unsigned)(a->rgb[2] >> 3));
}

#if ZL_MUL32_ONLY
/*
 * Without a divide instruction (ZL_MUL32_ONLY) a ZL_KIND_TINY record's
 * edges are walked as zl_tiny_draw walks them (tiny_walk, zl_span.h): an
 * edge's x holds its column ceil(N / den) instead of N, and the remainder
 * column * den - N goes to fields a tiny record leaves unused: lower.rem for
 * the long edge (left), lower.rstep for the current short one (right). The
 * lower short edge keeps N until row mid, where it is divided once: three
 * divisions a triangle instead of two a row.
 */
static ZL_ALWAYS_INLINE void tiny_walk_start(zl_edge *e, int32_t *r)
{
    int32_t x = tiny_x(e->x, e->den);
    *r = x * e->den - e->x;
    e->x = x;
}
#endif

/* Triangle t of a MESH_FLAT mesh with its vertices c cached inside, which
 * planning kept: the record zl_tri_polygon_geom + zl_tri_shade +
 * zl_tri_piece give (one piece, no offset, the lit flat colour), set up as
 * frame mode's draw_cached does (poly: the caller's scratch polygon); with
 * `tiny` (a MESH_ROW565 mesh, render_row_plain's walks) a small one as a
 * ZL_KIND_TINY record, frame mode's zl_tiny_setup and zl_tiny_draw's rows,
 * and only the packed pixel is set (zl_tri_pixel565_lit), the colour the
 * RGB565 walks read. Returns 0 when it has no rows. */
static ZL_ALWAYS_INLINE int setup_cached(const zl_frame_mesh *m, const zl_source *s, uint32_t t,
                                         const zl_cached_vertex *const *c, zl_active *a, zl_poly *poly, int tiny)
{
    int set = -1;
    if (tiny) {
        set = zl_tiny_setup_record(a, c[0], c[1], c[2], s->width, s->height);
        if (set == 0)
            return 0;
#if ZL_MUL32_ONLY
        if (set > 0) {
            tiny_walk_start(&a->left, &a->lower.rem);
            tiny_walk_start(&a->right, &a->lower.rstep);
        }
#endif
    }
    if (set < 0 && !zl_tri_setup_flat(a, c[0], c[1], c[2], &m->state, s->width, s->height))
        return 0;
    if (tiny) { /* an RGB565 walk reads the packed pixel alone */
        a->pix565 = zl_tri_pixel565_lit(s, t, m->lq);
        return 1;
    }
    poly->n = 0; /* flat: no vertex colours for the lighting to scale */
    zl_tri_shade_lit(s, t, poly, m->lq);
    a->rgb[0] = poly->flat.r;
    a->rgb[1] = poly->flat.g;
    a->rgb[2] = poly->flat.b;
    a->light = poly->light;
    a->pix565 = pixel565(a);
    return 1;
}

/* Triangle t of mesh record mi, a MESH_FLAT mesh, when its three vertices
 * are cached inside: set up by setup_cached and inserted at *link. Returns
 * 0, having done nothing, when a vertex needs clipping (or is dropped):
 * then the general path takes the triangle. */
static ZL_ALWAYS_INLINE int activate_cached(zl_frame *f, uint8_t mi, const zl_source *s, uint32_t t, uint16_t *link,
                                            zl_poly *poly, int tiny)
{
    const zl_frame_mesh *m = &f->meshes[mi];
    const uint16_t *idx = m->mesh.indices + t * 3u;
    const zl_cached_vertex *c[3];
    uint16_t slot = f->free_head, i0 = ZL_MESH_IDX(idx, 0), i1 = ZL_MESH_IDX(idx, 1), i2 = ZL_MESH_IDX(idx, 2);
    zl_active *a;
    c[0] = s->cache + i0;
    c[1] = s->cache + i1;
    c[2] = s->cache + i2;
    if (c[0]->x <= ZL_CACHE_INVALID || c[1]->x <= ZL_CACHE_INVALID || c[2]->x <= ZL_CACHE_INVALID)
        return 0;
    if (slot == ZL_LIST_END)
        return 1; /* cannot happen: planning bounded the peak */
    a = &f->pool[slot];
    if (!setup_cached(m, s, t, c, a, poly, tiny))
        return 1;
    f->free_head = a->next;
    a->id = (uint16_t)(m->tri_base + t);
    a->mesh = mi;
    a->next = *link;
    *link = slot;
    return 1;
}

/* The colour planes of a ZL_KIND_TINY_GOURAUD record in slot `slot`: its
 * zl_gouraud slot (f->gouraud, present in a MESH_GOURAUD565 frame). */
typedef char zl_tiny_colour_fits[(sizeof(zl_tiny_colour) <= sizeof(zl_gouraud)) ? 1 : -1];
static zl_tiny_colour *tiny_colour_of(const zl_frame *f, uint16_t slot)
{
    return (zl_tiny_colour *)(void *)(f->gouraud + (size_t)slot * sizeof(zl_gouraud));
}

/* Triangle t of a MESH_GOURAUD565 mesh, when its three vertices are cached
 * inside and it is small: a ZL_KIND_TINY_GOURAUD record (frame mode's
 * zl_tiny_gouraud_setup) inserted at *link. Returns 0, having done nothing,
 * when the general path must take it. */
static ZL_NOINLINE int activate_tiny_gouraud(zl_frame *f, uint8_t mi, const zl_source *s, uint32_t t, uint16_t *link)
{
    const zl_frame_mesh *m = &f->meshes[mi];
    const uint16_t *idx = m->mesh.indices + t * 3u;
    const uint8_t *vc = m->mesh.vertex_colors, *col[3];
    const zl_cached_vertex *c[3];
    uint16_t slot = f->free_head;
    zl_active *a;
    int set;
    c[0] = s->cache + ZL_MESH_IDX(idx, 0);
    c[1] = s->cache + ZL_MESH_IDX(idx, 1);
    c[2] = s->cache + ZL_MESH_IDX(idx, 2);
    if (c[0]->x <= ZL_CACHE_INVALID || c[1]->x <= ZL_CACHE_INVALID || c[2]->x <= ZL_CACHE_INVALID)
        return 0;
    if (slot == ZL_LIST_END)
        return 1; /* cannot happen: planning bounded the peak */
    col[0] = vc + ZL_MESH_IDX(idx, 0) * 3u;
    col[1] = vc + ZL_MESH_IDX(idx, 1) * 3u;
    col[2] = vc + ZL_MESH_IDX(idx, 2) * 3u;
    a = &f->pool[slot];
    set = zl_tiny_gouraud_setup_record(a, tiny_colour_of(f, slot), c, col, s->height);
    if (set <= 0)
        return set == 0; /* no rows: nothing, as the general path draws */
#if ZL_MUL32_ONLY
    tiny_walk_start(&a->left, &a->lower.rem);
    tiny_walk_start(&a->right, &a->lower.rstep);
#endif
    f->free_head = a->next;
    a->id = (uint16_t)(m->tri_base + t);
    a->mesh = mi;
    a->next = *link;
    *link = slot;
    return 1;
}

/* Set up the pieces of triangle `id` and insert them, in order, at *link
 * (where the render walk of the active list has reached the first record
 * with a greater id). */
static ZL_NOINLINE void activate(zl_frame *f, uint16_t id, uint16_t *link)
{
    uint8_t mi = mesh_of_id(f, id);
    const zl_frame_mesh *m = &f->meshes[mi];
    const zl_style *sty = style_of(f, mi);
    int lines = (ZL_FEATURE_LINES || ZL_FEATURE_OUTLINES) && sty != NULL && ext_of(f, mi)->is_lines;
    uint32_t t = id - m->tri_base;
    zl_source s;
    zl_tpoly tpoly; /* texture attributes only when the style needs them */
    zl_poly *poly = &tpoly.p;
    unsigned k, n = 1;
    source_of(f, m, &s);
    if (ZL_FAST_PATHS && !lines && (m->flags & MESH_FLAT) && activate_cached(f, mi, &s, t, link, poly, 0))
        return;
    if (!lines) {
        if (!(zl_style_planes(sty) ? zl_tri_polygon_tex(&s, sty, t, &tpoly)
                                         : zl_tri_polygon_geom(&s, sty, t, poly)))
            return;
        zl_tri_shade(&s, t, poly);
        n = zl_tri_pieces(&s, sty, t, poly);
    }
    for (k = 0; k < n; k++) {
        uint16_t slot = f->free_head;
        zl_active *a;
        if (slot == ZL_LIST_END)
            break; /* cannot happen: planning bounded the peak */
        a = &f->pool[slot];
        if (lines ? !prim_record(f, mi, &s, t, a)
                  : !zl_tri_piece(&s, sty, t, poly, k, a, gouraud_of(f, slot), tex_of(f, slot)))
            continue;
        f->free_head = a->next;
        a->id = id;
        a->mesh = mi;
        a->next = *link;
        *link = slot;
        link = &a->next;
    }
}

/* Return the record at *link, which has no rows left, to the free list. */
static void retire(zl_frame *f, uint16_t *link, zl_active *a, uint16_t slot)
{
    *link = a->next;
    a->next = f->free_head;
    f->free_head = slot;
}

/* Row y: one walk of the active list (sorted by id) fills every record's
 * span in id order; the triangles starting on this row (visible[i .. end))
 * are set up and inserted as the walk passes their place, so they need no
 * walk of their own. Setting up writes no pixel, so the order of the spans,
 * and hence every pixel, is as if all were activated first; a finished
 * record is freed before later ones are set up, which only lowers the peak. */
static ZL_NOINLINE void render_row_styled(zl_frame *f, uint16_t y, uint16_t i, uint16_t end, uint8_t *crow,
                                          uint16_t *zrow)
{
    uint16_t *link = &f->active_head;
    for (;;) {
        uint16_t slot = *link;
        zl_active *a;
        const zl_style *sty;
        const zl_span_state *ss;
        int more;
        if (i < end && (slot == ZL_LIST_END || f->pool[slot].id > f->visible[i])) {
            activate(f, f->visible[i++], link);
            continue;
        }
        if (slot == ZL_LIST_END)
            break;
        a = &f->pool[slot];
        if ((int32_t)a->row != (int32_t)y) { /* a later piece of a clipped triangle: not started */
            link = &a->next;
            continue;
        }
        sty = style_of(f, a->mesh);
        ss = &f->meshes[a->mesh].span;
        if (a->kind != ZL_KIND_TRI)
            more = zl_prim_row(a, ss, crow, zrow);
        else if (f->tex != NULL && zl_style_planes(sty))
            more = zl_tri_row_ex(a, gouraud_of(f, slot), tex_of(f, slot), sty, ss, crow, zrow);
        else
            more = zl_tri_row(a, gouraud_of(f, slot), ss, crow, zrow);
        if (more)
            link = &a->next;
        else
            retire(f, link, a, slot);
    }
}

/* activate() without style records: a filled triangle, no texture planes. */
static ZL_NOINLINE void activate_plain(zl_frame *f, uint16_t id, uint16_t *link)
{
    uint8_t mi = mesh_of_id(f, id);
    const zl_frame_mesh *m = &f->meshes[mi];
    uint32_t t = id - m->tri_base;
    zl_source s;
    zl_poly poly;
    unsigned k, n;
    source_of(f, m, &s);
    if ((m->flags & MESH_FLAT) && activate_cached(f, mi, &s, t, link, &poly, (m->flags & MESH_ROW565) != 0))
        return;
    if (ZL_SMALL_TRIANGLE_SETUP && (m->flags & MESH_GOURAUD565) && activate_tiny_gouraud(f, mi, &s, t, link))
        return;
    if (!zl_tri_polygon_geom(&s, NULL, t, &poly))
        return;
    zl_tri_shade_lit(&s, t, &poly, m->lq);
    n = zl_tri_pieces(&s, NULL, t, &poly);
    for (k = 0; k < n; k++) {
        uint16_t slot = f->free_head;
        zl_active *a;
        if (slot == ZL_LIST_END)
            break; /* cannot happen: planning bounded the peak */
        a = &f->pool[slot];
        if (!zl_tri_piece(&s, NULL, t, &poly, k, a, gouraud_of(f, slot), tex_of(f, slot)))
            continue;
        a->pix565 = pixel565(a);
        f->free_head = a->next;
        a->id = id;
        a->mesh = mi;
        a->next = *link;
        *link = slot;
        link = &a->next;
    }
}

/* zl_raster.c's edge_step. */
static ZL_ALWAYS_INLINE void edge_step(zl_edge *e)
{
    e->x += e->step;
    e->rem -= e->rstep;
    if (e->rem < 0) {
        e->rem += e->den;
        e->x += 1;
    }
}

/* The depth plane at column x0 when its gradient needs more than 32 bits
 * (rare: out of line, so the common case stays one multiply-accumulate). */
static ZL_NOINLINE int64_t plane_wide(const zl_active *a, int32_t x0)
{
    return a->z.row + (int64_t)(x0 - a->ax) * a->z.dx;
}

/* Spans up to this many pixels are written in place by span_565; longer ones
 * go to zl_span_flat (zl_raster.c's ZL_SHORT_SPAN). */
#define SHORT_SPAN 6

/*
 * row_span of a flat triangle record of a MESH_ROW565 mesh, columns
 * [x0, x1) (clipped to the row, x0 < x1) of the band's row buffers (both
 * present, 2-byte aligned), depth test `func` (ZL_LESS or ZL_LEQUAL, a
 * constant at each call): depth_start's clamped plane value, with the clamp
 * after the shift (floor division is monotone, so clamping to [zlo 16,
 * zhi 16] and then shifting equals shifting and then clamping to [zlo / 4,
 * zhi / 4]); a short span pixel by pixel as zl_span_flat writes it.
 */
static ZL_ALWAYS_INLINE void span_565(const zl_active *a, const zl_span_state *ss, unsigned func, uint8_t *crow,
                                      uint16_t *zrow, int32_t x0, int32_t x1)
{
    int32_t n = x1 - x0;
    int64_t v, w;
    uint32_t z, dz = a->dz14, lo14 = a->zlo >> 2, hi14 = a->zhi >> 2;
    int32_t dx32 = (int32_t)a->z.dx; /* kept only when it is the whole gradient */
    uint16_t pixel = a->pix565; /* set on activation (activate_plain) */
    uint16_t *c, *zb;
    if (a->z.dx == (int64_t)dx32) /* a 32-bit gradient: one multiply-accumulate */
        v = a->z.row + (int64_t)dx32 * (x0 - a->ax);
    else
        v = plane_wide(a, x0);
    w = zl_floor_shift64(v, ZL_ATTR_FRAC - 14);
    z = zl_depth_start_q14(w, lo14, hi14);
    if (n > SHORT_SPAN) {
        uint8_t pix[3];
        memcpy(pix, &pixel, 2); /* pack_color's native RGB565 */
        pix[2] = 0;
        zl_span_flat(ss, crow + (size_t)x0 * 2u, zrow + x0, n, z, dz, pix);
        return;
    }
    c = (uint16_t *)(void *)crow + x0;
    zb = zrow + x0;
    span565_short(c, zb, n, z, dz, pixel, func, 0);
}

/* The span of a ZL_KIND_TINY record on its row, columns [x0, x1). */
static ZL_ALWAYS_INLINE void tiny_row(const zl_active *a, const zl_span_state *ss, unsigned func, int32_t x0, int32_t x1,
                                      uint8_t *crow, uint16_t *zrow)
{
    tiny_fill(ss, func, x0, x1, (uint32_t)a->right.rem, (uint32_t)a->left.rstep, (int32_t)a->zlo, (int32_t)a->zhi,
              (uint32_t)a->left.rem, a->dz14, a->ax, (uint16_t *)(void *)crow, zrow, a->pix565);
}

/* zl_tiny_draw's steps after a row of a ZL_KIND_TINY record: 0 when it has
 * no rows left. The plane's row value wraps modulo 2^32 (tiny_depth): its
 * bits are added as uint32. */
static ZL_ALWAYS_INLINE int tiny_step(zl_active *a)
{
    int32_t row = a->row + 1;
#if ZL_MUL32_ONLY
    a->right.rem = (int32_t)((uint32_t)a->right.rem + (uint32_t)a->right.rstep);
    a->row = (int16_t)row;
    if (row >= a->end)
        return 0;
    if (row == a->mid) { /* the plane in right.rem and rstep stays */
        a->right.x = a->lower.x;
        a->right.step = a->lower.step;
        a->right.den = a->lower.den;
        tiny_walk_start(&a->right, &a->lower.rstep);
    } else {
        tiny_walk(&a->right.x, &a->lower.rstep, a->right.step, a->right.den);
    }
    tiny_walk(&a->left.x, &a->lower.rem, a->left.step, a->left.den);
#else
    a->left.x += a->left.step;
    a->right.x += a->right.step;
    a->right.rem = (int32_t)((uint32_t)a->right.rem + (uint32_t)a->right.rstep);
    a->row = (int16_t)row;
    if (row >= a->end)
        return 0;
    if (row == a->mid) { /* the plane in right.rem and rstep stays */
        a->right.x = a->lower.x;
        a->right.step = a->lower.step;
        a->right.den = a->lower.den;
    }
#endif
    return 1;
}

/* zl_tri_row's steps after the span: 0 when the record has no rows left. */
static ZL_ALWAYS_INLINE int row_step(zl_active *a)
{
    int32_t row = a->row + 1;
    edge_step(&a->left);
    edge_step(&a->right);
    a->z.row += a->z.dy;
    a->row = (int16_t)row;
    if (row >= a->end)
        return 0;
    if (row == a->mid) {
        if (a->lower_is_left)
            a->left = a->lower;
        else
            a->right = a->lower;
    }
    return 1;
}

/*
 * The row walk of scanline mode without style records (every record a
 * filled triangle without texture planes: add_record refuses anything
 * else). With `uniform` (a constant at each call) every mesh is MESH_ROW565
 * with depth test `func` (then all their span states are the same) and each
 * record's span and steps are in line; without it the walk asks each
 * record's mesh. One definition for render_row_less, render_row_lequal and
 * render_row_plain. Merged from two copies (issue 13), measured on Cortex-M4
 * -O2: scanline bunny -468 instructions, fill +480, tris -480, fill_gouraud 0.
 */
static ZL_ALWAYS_INLINE void rows_walk(zl_frame *f, uint16_t y, uint16_t i, uint16_t end, uint8_t *crow,
                                       uint16_t *zrow, int uniform, unsigned func)
{
    uint16_t *link = &f->active_head;
    zl_active *pool = f->pool;
    const uint16_t *visible = f->visible;
    const zl_frame_mesh *meshes = f->meshes;
    zl_gouraud *gouraud = (zl_gouraud *)(void *)f->gouraud;
    for (;;) {
        uint16_t slot = *link;
        zl_active *a;
        const zl_frame_mesh *m;
        int more;
        if (i < end && (slot == ZL_LIST_END || pool[slot].id > visible[i])) {
            activate_plain(f, visible[i++], link);
            continue;
        }
        if (slot == ZL_LIST_END)
            break;
        a = &pool[slot];
        if ((int32_t)a->row != (int32_t)y) { /* a later piece of a clipped triangle, not started */
            link = &a->next;
            continue;
        }
        m = uniform ? &meshes[0] : &meshes[a->mesh];
        if (ZL_SMALL_TRIANGLE_SETUP && (a->kind == ZL_KIND_TINY || (!uniform && a->kind == ZL_KIND_TINY_GOURAUD))) {
            /* only in MESH_ROW565 (MESH_GOURAUD565) meshes; never without the small set-up (zl_config.h) */
            int32_t x0, x1;
#if ZL_MUL32_ONLY
            { /* tiny_cols with the walked columns (tiny_walk_start) */
                int32_t lo = a->lower_is_left ? a->left.x : a->right.x, hi = a->lower_is_left ? a->right.x : a->left.x;
                x0 = lo < 0 ? 0 : lo;
                x1 = hi > m->span.width ? m->span.width : hi;
            }
#else
            tiny_cols(a->left.x, a->left.den, a->right.x, a->right.den, a->lower_is_left, m->span.width, &x0, &x1);
#endif
            if (!uniform && a->kind == ZL_KIND_TINY_GOURAUD) {
                zl_tiny_colour *tc = tiny_colour_of(f, slot);
                if (x0 < x1)
                    zl_tiny_gouraud_span(a, tc, &m->span, x0, x1, crow, zrow);
                tc->cr[0] += tc->cdy[0];
                tc->cr[1] += tc->cdy[1];
                tc->cr[2] += tc->cdy[2];
            } else if (x0 < x1) {
                if (uniform)
                    tiny_row(a, &m->span, func, x0, x1, crow, zrow);
                else if (m->span.func == ZL_LESS)
                    tiny_row(a, &m->span, ZL_LESS, x0, x1, crow, zrow);
                else
                    tiny_row(a, &m->span, ZL_LEQUAL, x0, x1, crow, zrow);
            }
            more = tiny_step(a);
        } else if (uniform || (m->flags & MESH_ROW565)) {
            int32_t x0 = a->left.x < 0 ? 0 : a->left.x, x1 = a->right.x > m->span.width ? m->span.width : a->right.x;
            if (x0 < x1) {
                if (uniform)
                    span_565(a, &m->span, func, crow, zrow, x0, x1);
                else if (m->span.func == ZL_LESS)
                    span_565(a, &m->span, ZL_LESS, crow, zrow, x0, x1);
                else
                    span_565(a, &m->span, ZL_LEQUAL, crow, zrow, x0, x1);
            }
            more = row_step(a);
        } else {
            more = zl_tri_row(a, gouraud != NULL ? gouraud + slot : NULL, &m->span, crow, zrow);
        }
        if (more)
            link = &a->next;
        else
            retire(f, link, a, slot);
    }
}

static ZL_NOINLINE void render_row_less(zl_frame *f, uint16_t y, uint16_t i, uint16_t end, uint8_t *crow,
                                        uint16_t *zrow)
{
    rows_walk(f, y, i, end, crow, zrow, 1, ZL_LESS);
}

static ZL_NOINLINE void render_row_lequal(zl_frame *f, uint16_t y, uint16_t i, uint16_t end, uint8_t *crow,
                                          uint16_t *zrow)
{
    rows_walk(f, y, i, end, crow, zrow, 1, ZL_LEQUAL);
}

static ZL_NOINLINE void render_row_plain(zl_frame *f, uint16_t y, uint16_t i, uint16_t end, uint8_t *crow,
                                         uint16_t *zrow)
{
    rows_walk(f, y, i, end, crow, zrow, 0, 0);
}

static ZL_ALWAYS_INLINE void render_row(zl_frame *f, uint16_t y, uint8_t *crow, uint16_t *zrow)
{
    uint16_t i = y == 0 ? 0 : f->row_start[y - 1], end = f->row_start[y];
    unsigned mi, flags = 0, func = 0;
    /* Without the fast paths (zl_config.h) the styled walk takes every row:
     * the same records and spans through zl_tri_row, and no copy of the
     * walk, its set-up (activate_plain) and its RGB565 spans in flash. */
    if (f->ext != NULL || !ZL_FAST_PATHS) {
        render_row_styled(f, y, i, end, crow, zrow);
        return;
    }
    /* Every mesh MESH_ROW565 with the same depth test: the walk in line. */
    if (f->mesh_count != 0) {
        flags = MESH_ROW565;
        func = f->meshes[0].span.func;
    }
    for (mi = 0; mi < f->mesh_count; mi++) {
        flags &= f->meshes[mi].flags;
        if (f->meshes[mi].span.func != func)
            flags = 0;
    }
    if (flags == 0)
        render_row_plain(f, y, i, end, crow, zrow);
    else if (func == ZL_LESS)
        render_row_less(f, y, i, end, crow, zrow);
    else
        render_row_lequal(f, y, i, end, crow, zrow);
}

/*
 * The second part of a split frame (zl_frame_split) starts at row next_row,
 * but its triangles crossing that row start above it: the rows above, from
 * the first one of those triangles (the only ones its planning kept there),
 * are walked into the band's first row, which is not handed out, so every
 * record reaches the split row exactly as one core's walk leaves it.
 */
static ZL_NOINLINE void catch_up(zl_frame *f)
{
    uint16_t y = 0, w = f->cfg.width;
    uint16_t *zrow = f->depth_band;
    while (y < f->next_row && f->row_start[y] == 0) /* bucket ends: empty before the first */
        y++;
    if (y >= f->next_row)
        return;
    zl_fill16(zrow, f->clear_depth, w);
    memset(f->color_band[0], 0, (size_t)w * frame_bpp(f));
    for (; y < f->next_row; y++)
        render_row(f, y, f->color_band[0], zrow);
}

/* Over capacity: the rows above r0 of the plan's primitives that start
 * there, walked without writing a pixel: every mesh's span width set to 0,
 * so every span, line run and point is clipped away, which brings their
 * records to row r0 exactly as a whole walk would. */
static ZL_NOINLINE void dry_rows(zl_frame *f, uint16_t r0, uint8_t *crow, uint16_t *zrow)
{
    uint16_t y = 0, mi;
    while (y < r0 && f->row_start[y] == 0) /* bucket ends: empty before the first */
        y++;
    if (y >= r0)
        return;
    for (mi = 0; mi < f->mesh_count; mi++)
        f->meshes[mi].span.width = 0;
    for (; y < r0; y++)
        render_row(f, y, crow, zrow);
    for (mi = 0; mi < f->mesh_count; mi++)
        f->meshes[mi].span.width = f->cfg.width;
}

/* Over capacity (zl_frame_over.c plans): the band of `rows` rows at
 * next_row into `color` and the depth band, from the current window's plan,
 * or from a new window's, or in slices of primitives when not even the band
 * fits one plan. */
static ZL_NOINLINE zl_status over_band(zl_frame *f, uint16_t rows, uint8_t *color)
{
    uint16_t r, w = f->cfg.width, r0 = f->next_row, r1 = (uint16_t)(f->next_row + rows);
    size_t bpp = frame_bpp(f);
    uint32_t id_lo = 0;
    uint8_t pix[3] = {0, 0, 0};
    pack_color((zl_format)f->cfg.format, f->clear_color.r, f->clear_color.g, f->clear_color.b, pix);
    for (r = 0; r < rows; r++) { /* zl_frame_next_band's clear */
        uint8_t *crow = color + (size_t)r * w * bpp;
        uint16_t i;
        for (i = 0; i < w; i++)
            memcpy(crow + (size_t)i * bpp, pix, bpp);
        zl_fill16(f->depth_band + (size_t)r * w, f->clear_depth, w);
    }
    if (r0 >= f->over_end) { /* a new window, when its first band fits one plan */
        uint16_t end = zl_frame_over_window(f, r0); /* and its plan */
        if (end > r0) {
            if (ZL_FAST_PATHS || r0 != 0 || end != f->end_row) /* (else the whole frame's plan: no replan) */
                f->needs.replans++;
            dry_rows(f, r0, color, f->depth_band);
            f->over_end = end;
        }
    }
    if (r0 < f->over_end) { /* the window's plan: its records go on from the band above */
        for (r = 0; r < rows; r++)
            render_row(f, (uint16_t)(r0 + r), color + (size_t)r * w * bpp, f->depth_band + (size_t)r * w);
        return ZL_OK;
    }
    while (id_lo < f->triangle_total) {
        uint32_t id_hi;
        zl_frame_over_slice(f, r0, r1, id_lo, &id_hi);
        f->needs.replans++;
        if (id_hi == id_lo) /* cannot happen: zl_frame_over_begin checked every primitive alone */
            return ZL_ERR_CAPACITY;
        dry_rows(f, r0, color, f->depth_band);
        for (r = 0; r < rows; r++)
            render_row(f, (uint16_t)(r0 + r), color + (size_t)r * w * bpp, f->depth_band + (size_t)r * w);
        id_lo = id_hi;
    }
    return ZL_OK;
}

/* Describe the band of `rows` rows at next_row in `color` and move on. */
static ZL_ALWAYS_INLINE void band_done(zl_frame *f, zl_band *band, uint16_t rows, uint8_t *color, uint16_t w,
                                        size_t bpp)
{
    band->first_row = f->next_row;
    band->rows = rows;
    band->width = w;
    band->format = f->cfg.format;
    band->color = color;
    band->color_stride = (int32_t)(w * bpp);
    band->depth = f->depth_band;
    band->depth_stride = (int32_t)w * 2;
    f->next_row = (uint16_t)(f->next_row + rows);
    if (f->cfg.color_buffers == 2)
        f->band_index ^= 1u;
}

/* zl_frame_next_band over capacity (f->over): the band in
 * slices (zl_frame_over.c). Its own function, so the bands of a frame that
 * fits test nothing more than before. */
static ZL_NOINLINE zl_status next_band_over(zl_frame *f, zl_band *band)
{
    uint16_t rows = (uint16_t)(f->end_row - f->next_row);
    uint8_t *color = f->color_band[f->band_index];
    zl_status st;
    if (f->next_row >= f->end_row)
        return ZL_DONE;
    if (rows > f->cfg.band_rows)
        rows = f->cfg.band_rows;
    st = over_band(f, rows, color);
    if (st != ZL_OK)
        return st;
    band_done(f, band, rows, color, f->cfg.width, frame_bpp(f));
    return ZL_OK;
}

/* zl_frame_next_band without the fast paths (zl_config.h) on a whole
 * frame: every frame is planned as over capacity's are, a window of bands
 * at a time (a frame that fits is one window), so the planning of
 * zl_frame_plan.c and the band loop below are not in flash. The same
 * pixels, needs and errors; planning classifies every primitive twice
 * (count, place) where zl_frame_plan classifies once or twice. */
static ZL_NOINLINE zl_status next_band_compact(zl_frame *f, zl_band *band)
{
    if (f->depth_band == NULL) /* a zeroed zl_frame, never begun */
        return ZL_ERR_ARG;
    if (!f->over) {
        zl_status st = zl_frame_over_begin(f);
        if (st != ZL_OK)
            return st;
        f->over = 1;
    }
    return next_band_over(f, band);
}

zl_status zl_frame_next_band(zl_frame *f, zl_band *band)
{
    uint16_t rows, r, w;
    size_t bpp;
    uint8_t *color;
    uint8_t pix[3] = {0, 0, 0};
    uint16_t pix16;
    /* A zeroed zl_frame (never begun) fails in zl_frame_plan's layout check
     * with ZL_ERR_ARG (tests/test_frame_faults.c). */
    if (f == NULL || band == NULL)
        return ZL_ERR_ARG;
    if (!ZL_FAST_PATHS && !(ZL_FEATURE_SPLIT && f->part != 0))
        return next_band_compact(f, band);
    if (!f->planned) { /* first band, or over capacity (then planned stays 0: no test added per band) */
        zl_status st;
        if (f->over)
            return next_band_over(f, band);
        st = zl_frame_plan(f);
        if (st == ZL_ERR_CAPACITY && f->part == 0) { /* a whole frame: band by band */
            st = zl_frame_over_begin(f);
            if (st != ZL_OK)
                return st;
            f->over = 1;
            return next_band_over(f, band);
        }
        if (st != ZL_OK)
            return st;
        f->planned = 1;
        if (ZL_FEATURE_SPLIT && f->next_row != 0) /* the second part of a split frame */
            catch_up(f);
    }
    if (f->next_row >= f->end_row)
        return ZL_DONE;
    w = f->cfg.width;
    bpp = frame_bpp(f);
    rows = (uint16_t)(f->end_row - f->next_row);
    if (rows > f->cfg.band_rows)
        rows = f->cfg.band_rows;
    color = f->color_band[f->band_index];
    /* The clear colour in the band's format, every channel written (what
     * zl_fill_color_row does with the default state's span settings). */
    pack_color((zl_format)f->cfg.format, f->clear_color.r, f->clear_color.g, f->clear_color.b, pix);
    memcpy(&pix16, pix, 2);
    for (r = 0; r < rows; r++) {
        uint8_t *crow = color + (size_t)r * w * bpp;
        uint16_t *zrow = f->depth_band + (size_t)r * w;
        if (bpp == 2) { /* rows of an 8-byte aligned band, an even number of bytes apart */
            zl_fill16((uint16_t *)(void *)crow, pix16, w);
        } else {
            uint16_t i;
            for (i = 0; i < w; i++)
                memcpy(crow + (size_t)i * 3u, pix, 3);
        }
        zl_fill16(zrow, f->clear_depth, w);
        render_row(f, (uint16_t)(f->next_row + r), crow, zrow);
    }
    band_done(f, band, rows, color, w, bpp);
    return ZL_OK;
}

int zl_frame_render(zl_frame *f, zl_band_fn fn, void *user)
{
    zl_band band;
    zl_status st;
    if (fn == NULL)
        return ZL_ERR_ARG;
    while ((st = zl_frame_next_band(f, &band)) == ZL_OK) {
        int r = fn(user, &band);
        if (r != 0)
            return r;
    }
    return st == ZL_DONE ? 0 : st;
}

zl_frame_needs_t zl_frame_needs(const zl_frame *f)
{
    zl_frame_needs_t none = {0, 0, 0};
    return f ? f->needs : none;
}
