/* SPDX-License-Identifier: MIT */
/*
 * Stage 6, visibility: scan-line hidden-surface removal with an extended active edge table: no
 * depth buffer, one row of output at a time.
 *
 * Polygon table: every kept triangle piece is set up by zl_tri_setup when
 * its first row comes up (the edge table is the bucket of triangle ids by
 * first row that planning builds, as in zl_frame). Its record carries the
 * exact edge steppers (x and slope as integer plus error term), its depth
 * plane (value and per-pixel/per-row gradients, Q20 of a depth step) and its
 * colour and id.
 *
 * Active edge list: two entries per live piece, one where its span starts on
 * the row (its left edge's first pixel) and one where it ends (the right
 * edge's), each referring to its polygon. Between rows the steppers move and
 * the list keeps its previous order; an insertion sort repairs it, which
 * costs one comparison per entry when no edges crossed (coherence).
 *
 * Resolving a row: walking the list left to right keeps the set of pieces
 * covering the current span (between two consecutive crossings), ordered
 * nearest first at the span's left end; that order is also kept from one span
 * to the next and repaired by insertion sort. The nearest piece at the left
 * end shows until another piece becomes nearer: since both depths are linear
 * in x, piece q overtakes the front piece inside [a, b) only if it is nearer
 * at b - 1, and then at a single column found by bisection on the exact
 * integer depths. The span is split there (interpenetrating polygons) and
 * the rest resolved the same way. Ties go to the earlier triangle, as LESS.
 *
 * The depths compared are the z-buffer's own planes at 2^-20 of a depth step,
 * before the rounding to 16 bits; so the result equals the z-buffer's except
 * where two surfaces are within about one depth step at a pixel centre, where
 * the z-buffer's rounded values cannot tell them apart and this can.
 */
#include "zl_vis_internal.h"

#define LIVE 1u

static int nearer(const zl_active *p, const zl_active *q, int32_t x)
{
    int64_t zp = zl_vis_depth_at(p, x), zq = zl_vis_depth_at(q, x);
    return zp < zq || (zp == zq && p->id < q->id);
}

typedef struct {
    zl_vis *v;
    zl_active *pool;
    unsigned bpp;
    uint8_t bg[3];
    uint32_t k; /* pieces in the span set */
} aet;

static void fill_bg(aet *s, int32_t a, int32_t b)
{
    int32_t i;
    zl_vis_fill(s->v->color_row + (size_t)a * s->bpp, s->bpp, s->bg, b - a);
    for (i = a; i < b; i++)
        s->v->id_row[i] = ZL_VIS_NONE;
}

static void fill_piece(aet *s, const zl_active *t, int32_t a, int32_t b)
{
    uint8_t pix[3];
    int32_t i;
    zl_vis_pack((zl_format)s->v->cfg.format, t->rgb, pix);
    zl_vis_fill(s->v->color_row + (size_t)a * s->bpp, s->bpp, pix, b - a);
    for (i = a; i < b; i++)
        s->v->id_row[i] = t->id;
}

/* Columns a .. b - 1, covered by exactly the pieces of the span set. */
static void resolve(aet *s, int32_t a, int32_t b)
{
    uint16_t *set = s->v->inset;
    zl_active *pool = s->pool;
    uint32_t i, j;
    if (a >= b)
        return;
    if (s->k == 0) {
        fill_bg(s, a, b);
        return;
    }
    while (a < b) {
        const zl_active *front;
        int32_t split = b;
        /* Nearest first at a: usually already so from the previous span. */
        for (i = 1; i < s->k; i++) {
            uint16_t q = set[i];
            for (j = i; j > 0 && nearer(&pool[q], &pool[set[j - 1]], a); j--)
                set[j] = set[j - 1];
            set[j] = q;
        }
        front = &pool[set[0]];
        for (i = 1; i < s->k; i++) {
            const zl_active *q = &pool[set[i]];
            int32_t lo = a, hi = split - 1;
            if (hi <= lo || !nearer(q, front, hi))
                continue;
            /* q is not nearer at lo, nearer at hi: find the first column. */
            while (hi - lo > 1) {
                int32_t mid = lo + (hi - lo) / 2;
                if (nearer(q, front, mid))
                    hi = mid;
                else
                    lo = mid;
            }
            split = hi;
        }
        fill_piece(s, front, a, split);
        a = split;
    }
}

static void set_remove(aet *s, uint16_t slot)
{
    uint16_t *set = s->v->inset;
    uint32_t i;
    for (i = 0; i < s->k; i++)
        if (set[i] == slot)
            break;
    if (i == s->k)
        return;
    for (; i + 1 < s->k; i++)
        set[i] = set[i + 1];
    s->k--;
}

static int32_t clamp_x(int32_t x, int32_t w)
{
    return x < 0 ? 0 : (x > w ? w : x);
}

int zl_aet_render_rows(zl_vis *v, zl_rgb clear, zl_vis_row_fn fn, void *user)
{
    zl_vis_edge *edges = (zl_vis_edge *)v->edges;
    const int32_t w = v->cfg.width;
    uint32_t n_act = 0, n_free, n_edges = 0, i, j;
    uint8_t clear_rgb[3];
    uint16_t y;
    aet s;
    zl_status st = zl_vis_plan(v);
    if (st != ZL_OK)
        return st;
    s.v = v;
    s.pool = (zl_active *)v->pool;
    s.bpp = zl_format_bytes((zl_format)v->cfg.format);
    s.k = 0;
    clear_rgb[0] = clear.r;
    clear_rgb[1] = clear.g;
    clear_rgb[2] = clear.b;
    zl_vis_pack((zl_format)v->cfg.format, clear_rgb, s.bg);
    n_free = v->cfg.max_active;
    for (i = 0; i < n_free; i++)
        v->free_slots[i] = (uint16_t)(n_free - 1u - i);
    for (y = 0; y < v->cfg.height; y++) {
        uint16_t begin = y == 0 ? 0 : v->row_start[y - 1], end = v->row_start[y], b;
        int32_t pos = 0;
        zl_vis_row row;
        int rc;
        /* Polygon table: set up the pieces of the triangles starting here. */
        for (b = begin; b < end; b++) {
            zl_source src;
            zl_poly poly;
            uint32_t t;
            unsigned k, mi = zl_vis_source(v, v->visible[b], &src, &t);
            if (!zl_tri_polygon(&src, t, &poly))
                continue;
            for (k = 1; k + 1 < poly.n && n_free > 0; k++) {
                uint16_t slot = v->free_slots[n_free - 1u];
                zl_active *a = &s.pool[slot];
                if (!zl_tri_setup(a, NULL, &poly.v[0], &poly.v[k], &poly.v[k + 1], &poly, &v->meshes[mi].state,
                                  v->cfg.width, v->cfg.height))
                    continue;
                if (ZL_FEATURE_EXACT_CLIP && poly.clipped) /* the original triangle's depth plane, as the z-buffer's */
                    zl_tri_orig_piece(&src, NULL, t, &poly, &poly.v[0], &poly.v[k], &poly.v[k + 1], a, NULL, NULL);
                n_free--;
                a->id = v->visible[b];
                v->flags[slot] = 0;
                v->act[n_act++] = slot;
            }
        }
        /* Pieces whose first row this is put their two edges in the list. */
        for (i = 0; i < n_act; i++) {
            uint16_t slot = v->act[i];
            if ((int32_t)s.pool[slot].row == (int32_t)y && !(v->flags[slot] & LIVE)) {
                v->flags[slot] |= LIVE;
                edges[n_edges].slot = slot;
                edges[n_edges].leave = 0;
                edges[n_edges + 1].slot = slot;
                edges[n_edges + 1].leave = 1;
                n_edges += 2;
            }
        }
        /* Crossings of this row; keep the previous order, repair it. */
        for (i = 0; i < n_edges; i++) {
            const zl_active *a = &s.pool[edges[i].slot];
            edges[i].x = clamp_x(edges[i].leave ? a->right.x : a->left.x, w);
        }
        for (i = 1; i < n_edges; i++) {
            zl_vis_edge e = edges[i];
            for (j = i; j > 0 && edges[j - 1].x > e.x; j--)
                edges[j] = edges[j - 1];
            edges[j] = e;
        }
        /* Walk the spans between consecutive crossings. */
        s.k = 0;
        for (i = 0; i < n_edges;) {
            int32_t x = edges[i].x;
            resolve(&s, pos, x);
            for (; i < n_edges && edges[i].x == x; i++) {
                uint16_t slot = edges[i].slot;
                const zl_active *a = &s.pool[slot];
                if (edges[i].leave)
                    set_remove(&s, slot);
                else if (clamp_x(a->left.x, w) < clamp_x(a->right.x, w))
                    v->inset[s.k++] = slot;
            }
            pos = x;
        }
        resolve(&s, pos, w);
        row.y = y;
        row.width = v->cfg.width;
        row.color = v->color_row;
        row.ids = v->id_row;
        row.gap = NULL;
        rc = fn(user, &row);
        if (rc != 0)
            return rc;
        /* Step the live pieces; retire the finished ones and their edges. */
        for (i = 0; i < n_act;) {
            uint16_t slot = v->act[i];
            if ((v->flags[slot] & LIVE) && !zl_vis_step(&s.pool[slot], 1)) {
                v->flags[slot] = 0;
                v->free_slots[n_free++] = slot;
                v->act[i] = v->act[--n_act];
            } else {
                i++;
            }
        }
        for (i = 0, j = 0; i < n_edges; i++)
            if (v->flags[edges[i].slot] & LIVE)
                edges[j++] = edges[i];
        n_edges = j;
    }
    return 0;
}
