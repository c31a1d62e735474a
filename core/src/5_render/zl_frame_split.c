/* SPDX-License-Identifier: MIT */
/*
 * Stage 5, render: a frame split across two cores (zline.h, "two cores, one
 * frame"). zl_frame_split finishes the shared part (the vertex cache) on the
 * first core and makes the second part's zl_frame: the same mesh records,
 * vertex cache and style records, its own edge table, active records and
 * bands in the second work buffer. Planning (zl_frame_plan.c) keeps only the
 * triangles of a part's rows; zl_frame_rows.c's catch_up brings the second
 * part's records to its first row.
 */
#include <string.h>

#include "zl_frame_internal.h"
#include "../3_raster/zl_raster.h"

/* The second part's layout: zl_frame_layout's regions from the row starts
 * on, at the same offsets from there (the style records' room, used only
 * with cfg.styled, stays unused: the records are shared). */
static size_t part_bytes(const layout *l)
{
    return l->total - l->row_start;
}

size_t zl_frame_part_bytes(const zl_frame_config *cfg)
{
    layout l;
    if (cfg == NULL || !zl_frame_layout(cfg, &l))
        return 0;
    return part_bytes(&l);
}

/* Vertices of the meshes add_record did not cache (pixel space, or too many
 * at that point), which planning would otherwise cache on both cores. */
static void cache_remaining(zl_frame *f)
{
    uint16_t mi;
    for (mi = 0; mi < f->mesh_count; mi++) {
        zl_frame_mesh *m = &f->meshes[mi];
        zl_source s;
        if ((m->flags & MESH_CACHED) || m->mesh.vertex_count == 0)
            continue;
        source_of(f, m, &s);
        (void)zl_cache_vertices(&s, cache_of(f) + m->vert_base, 0, m->mesh.vertex_count);
        m->flags = (uint8_t)(m->flags | MESH_CACHED);
    }
}

/* The row that splits the cached vertices in two halves, counted per row in
 * `count` (height + 1 counters of the second work buffer, free until the
 * second core starts): the first row with at least half of them above. */
static uint16_t balanced_row(const zl_frame *f, uint16_t *count)
{
    const zl_cached_vertex *c = cache_of(f);
    uint16_t h = f->cfg.height, y;
    uint32_t v, total = 0, seen = 0;
    memset(count, 0, ((size_t)h + 1) * sizeof(uint16_t));
    for (v = 0; v < f->vertex_count; v++) {
        int32_t row;
        if (c[v].x <= ZL_CACHE_INVALID)
            continue;
        row = first_centre_at_or_after(c[v].y);
        if (row < 0 || row >= h || count[row] == UINT16_MAX)
            continue;
        count[row]++;
        total++;
    }
    for (y = 0; y < h; y++) {
        seen += count[y];
        if (2u * seen >= total)
            return (uint16_t)(y + 1u);
    }
    return (uint16_t)(h / 2u);
}

zl_status zl_frame_split(zl_frame *f, zl_frame *second, void *work, size_t work_bytes, uint16_t split_row)
{
    layout l;
    uint8_t *w = work;
    uint16_t h, band;
    if (f == NULL || second == NULL || work == NULL || second == f || ((uintptr_t)work & 7u) != 0)
        return ZL_ERR_ARG;
    if (f->depth_band == NULL || f->planned || f->next_row != 0 || f->end_row != f->cfg.height ||
        !zl_frame_layout(&f->cfg, &l)) /* never begun, already planned or split */
        return ZL_ERR_ARG;
    if (work_bytes < part_bytes(&l))
        return ZL_ERR_SIZE;
    h = f->cfg.height;
    band = f->cfg.band_rows;
    cache_remaining(f);
    if (split_row == 0)
        split_row = balanced_row(f, (uint16_t *)(void *)w);
    if (split_row > h)
        split_row = h;
    split_row = (uint16_t)(split_row - split_row % band);
    *second = *f;
    second->row_start = (uint16_t *)(void *)w;
    second->visible = (uint16_t *)(void *)(w + (l.visible - l.row_start));
    second->pool = (zl_active *)(void *)(w + (l.pool - l.row_start));
    second->gouraud = f->cfg.gouraud ? w + (l.gouraud - l.row_start) : NULL;
    second->tex = f->cfg.textured ? w + (l.tex - l.row_start) : NULL;
    second->depth_band = (uint16_t *)(void *)(w + (l.depth - l.row_start));
    second->color_band[0] = w + (l.color0 - l.row_start);
    second->color_band[1] = f->cfg.color_buffers == 2 ? w + (l.color1 - l.row_start) : second->color_band[0];
    second->next_row = split_row;
    second->end_row = h;
    f->end_row = split_row;
    return ZL_OK;
}
