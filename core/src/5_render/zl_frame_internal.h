/* SPDX-License-Identifier: MIT */
/*
 * Stage 5, render: the records of scanline and band mode shared by its three
 * files (zl_frame.c submission, zl_frame_plan.c planning, zl_frame_rows.c
 * rows, zl_frame_over.c planning over capacity). Calls run rows -> over ->
 * plan -> submission helpers, never back.
 */
#ifndef ZL_FRAME_INTERNAL_H
#define ZL_FRAME_INTERNAL_H

#include "../1_base/zl_internal.h"
#include "../3_raster/zl_span.h"

struct zl_frame_mesh {
    zl_mesh mesh;
    zl_mat4 mvp;
    zl_state state;
    zl_span_state span;
    uint8_t flags;      /* MESH_*, in bytes that were padding: the layout does not change */
    uint8_t cull_code;  /* culled_area_sign of the state, plus 1 (0, 1 or 2) */
    uint32_t tri_base, vert_base;
    int32_t lq[3];      /* the state's light, zl_light_prepare'd once (not per triangle) */
};

#define MESH_MVP 1u       /* mvp holds the transform (else pixel space) */
#define MESH_FLAT 2u      /* plain flat fill: cached triangles set up by zl_tri_setup_flat */
#define MESH_ROW565 4u    /* MESH_FLAT with RGB565 spans, depth LESS or LEQUAL written, every channel */
#define MESH_CACHED 8u    /* its vertex cache entries were filled when it was added */
#define MESH_GOURAUD565 16u /* plain Gouraud fill (vertex colours as they are) with MESH_ROW565's spans and
                               Gouraud records: small cached triangles are ZL_KIND_TINY_GOURAUD records */

/* Per-mesh record of the styled features (only with cfg.styled). */
typedef struct {
    zl_style style;
    zl_lines lines;     /* is_lines == 1 */
    zl_mesh mesh;       /* is_lines == 2: the outlined mesh ... */
    zl_outline outline; /* ... and its outline */
    uint8_t is_lines;
} zl_frame_ext;

#define ALIGN8(n) (((n) + 7u) & ~(size_t)7u)

/* The work buffer's regions in order (zl_frame_layout); L_TOTAL: the end. */
enum {
    L_MESHES,
    L_VCACHE,
    L_ROW_START,
    L_VISIBLE,
    L_POOL,
    L_GOURAUD,
    L_EXT,
    L_TEX,
    L_DEPTH,
    L_COLOR0,
    L_COLOR1,
    L_TOTAL
};

typedef struct {
    size_t at[L_TOTAL + 1]; /* byte offsets of the regions */
} layout;

ZL_SHARED_STATIC zl_frame_ext *ext_of(const zl_frame *f, unsigned mi)
{
    return f->ext ? (zl_frame_ext *)(void *)(f->ext + (size_t)mi * sizeof(zl_frame_ext)) : NULL;
}

ZL_SHARED_STATIC const zl_style *style_of(const zl_frame *f, unsigned mi)
{
    return f->ext ? &ext_of(f, mi)->style : NULL;
}

ZL_SHARED_STATIC zl_cached_vertex *cache_of(const zl_frame *f)
{
    return (zl_cached_vertex *)(void *)f->vcache;
}

ZL_SHARED_STATIC void source_of(const zl_frame *f, const zl_frame_mesh *m, zl_source *s)
{
    s->mesh = &m->mesh;
    s->mvp = (m->flags & MESH_MVP) ? &m->mvp : NULL;
    s->state = &m->state;
    s->cache = cache_of(f) + m->vert_base;
    s->width = f->cfg.width;
    s->height = f->cfg.height;
}

/* Record of primitive t of a lines or outline mesh record. */
ZL_SHARED_STATIC int prim_record(const zl_frame *f, unsigned mi, const zl_source *s, uint32_t t, zl_active *rec)
{
    const zl_frame_ext *e = ext_of(f, mi);
    if (e->is_lines == 2)
        return zl_outline_record(s, &e->mesh, &e->outline, &e->style, t, rec);
    return zl_lines_record(s, &e->lines, &e->style, &f->meshes[mi].state, t, rec);
}

/* Offsets of every region of the work buffer (zl_frame.c); 0 when the
 * configuration is invalid. */
int zl_frame_layout(const zl_frame_config *c, layout *l);
/* A part of a split frame asked for the balanced split row: the row with
 * half the cached vertices above it, set as the part's window
 * (zl_frame_split.c; both parts compute the same). */
void zl_frame_split_resolve(zl_frame *f);
/* Every mesh's vertices into the vertex cache, but those add_record cached
 * (zl_frame_plan.c). */
void zl_frame_fill_cache(zl_frame *f);
/* Planning, on the first band (zl_frame_plan.c). */
zl_status zl_frame_plan(zl_frame *f);
/* Over capacity's classification of primitive t of mesh record mi, the
 * count pass's fast case (zl_frame_plan.c): a filled triangle whose three
 * vertices are cached inside gives 1 and its rows [*first, *end), or 0 when
 * it draws nothing; -1 for every other primitive (the general case). */
int zl_frame_rows_cached(const zl_frame *f, unsigned mi, uint32_t t, int32_t *first, int32_t *end);
/* Over capacity (zl_frame_over.c): after zl_frame_plan's ZL_ERR_CAPACITY on
 * a whole frame (without the fast paths, zl_config.h: on every whole frame,
 * having filled the vertex cache), check that every primitive fits alone
 * (else ZL_ERR_CAPACITY) and set the whole frame's needs. Then, a band at
 * a time from row r0: the end of the longest window of whole bands from r0
 * that one plan holds, planned (r0 when not even one band fits: no plan);
 * or the plan of rows [r0, r1) from primitive id_lo on, as many as fit
 * (*id_hi: the first left out). */
zl_status zl_frame_over_begin(zl_frame *f);
uint16_t zl_frame_over_window(zl_frame *f, uint16_t r0);
void zl_frame_over_slice(zl_frame *f, uint16_t r0, uint16_t r1, uint32_t id_lo, uint32_t *id_hi);

#endif /* ZL_FRAME_INTERNAL_H */
