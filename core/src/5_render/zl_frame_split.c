/* SPDX-License-Identifier: MIT */
/*
 * Stage 5, render: a frame split across two cores (zline.h, "two cores, one
 * frame"). zl_frame_split makes the second part's zl_frame: the same mesh
 * records, vertex cache and style records, its own edge table, active
 * records and bands in the second work buffer. zl_frame_prepare transforms
 * a part's half of the vertices; planning (zl_frame_plan.c) keeps only the
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
    return l->at[L_TOTAL] - l->at[L_ROW_START];
}

size_t zl_frame_part_bytes(const zl_frame_config *cfg)
{
    layout l;
    if (cfg == NULL || !zl_frame_layout(cfg, &l))
        return 0;
    return part_bytes(&l);
}

/* Rows [0, row) to the first part, [row, height) to the second. */
static void set_rows(zl_frame *f, uint16_t row)
{
    if (f->part == 1)
        f->end_row = row;
    else
        f->next_row = row;
}

/* Every 4th cached vertex counted on its row (in the part's own row
 * starts, which planning clears next): the first row with half of them
 * above it. */
#define SPLIT_SAMPLE 4u

void zl_frame_split_resolve(zl_frame *f)
{
    const zl_cached_vertex *c = cache_of(f);
    uint16_t h = f->cfg.height, y, *count = f->row_start;
    uint32_t v, total = 0, seen = 0;
    memset(count, 0, ((size_t)h + 1) * sizeof(uint16_t));
    for (v = 0; v < f->vertex_count; v += SPLIT_SAMPLE) {
        int32_t row;
        if (c[v].x <= ZL_CACHE_INVALID)
            continue;
        row = first_centre_at_or_after(c[v].y);
        if (row < 0 || row >= h || count[row] == UINT16_MAX)
            continue;
        count[row]++;
        total++;
    }
    y = (uint16_t)(h / 2u);
    if (total != 0)
        for (y = 0; y < h && 2u * (seen + count[y]) < total; y++)
            seen += count[y];
    y = (uint16_t)(y + 1u > h ? h : y + 1u);
    set_rows(f, (uint16_t)(y - y % f->cfg.band_rows));
}

zl_status zl_frame_split(zl_frame *f, zl_frame *second, void *work, size_t work_bytes, uint16_t split_row)
{
    layout l;
    uint8_t *w = work;
    if (!ZL_FEATURE_SPLIT) /* compiled out (zl_config.h) */
        return ZL_ERR_UNSUPPORTED;
    if (f == NULL || second == NULL || work == NULL || second == f || ((uintptr_t)work & 7u) != 0)
        return ZL_ERR_ARG;
    if (f->depth_band == NULL || f->planned || f->over || f->part != 0 || !zl_frame_layout(&f->cfg, &l))
        return ZL_ERR_ARG; /* never begun, planned or split already */
    if (work_bytes < part_bytes(&l))
        return ZL_ERR_SIZE;
    if (split_row > f->cfg.height)
        split_row = f->cfg.height;
    split_row = (uint16_t)(split_row - split_row % f->cfg.band_rows);
    *second = *f;
    second->row_start = (uint16_t *)(void *)w;
    second->visible = (uint16_t *)(void *)(w + (l.at[L_VISIBLE] - l.at[L_ROW_START]));
    second->pool = (zl_active *)(void *)(w + (l.at[L_POOL] - l.at[L_ROW_START]));
    second->gouraud = f->cfg.gouraud ? w + (l.at[L_GOURAUD] - l.at[L_ROW_START]) : NULL;
    second->tex = f->cfg.textured ? w + (l.at[L_TEX] - l.at[L_ROW_START]) : NULL;
    second->depth_band = (uint16_t *)(void *)(w + (l.at[L_DEPTH] - l.at[L_ROW_START]));
    second->color_band[0] = w + (l.at[L_COLOR0] - l.at[L_ROW_START]);
    second->color_band[1] =
        f->cfg.color_buffers == 2 ? w + (l.at[L_COLOR1] - l.at[L_ROW_START]) : second->color_band[0];
    f->part = 1;
    second->part = 2;
    f->split_row = second->split_row = split_row;
    if (split_row != 0) { /* else zl_frame_split_resolve, in planning */
        set_rows(f, split_row);
        set_rows(second, split_row);
    }
    return ZL_OK;
}

/* A part's half of every mesh's vertices not cached by the submission: the
 * first part the vertices [0, n / 2) of the n of the frame, the second the
 * rest, mesh by mesh. */
zl_status zl_frame_prepare(zl_frame *f)
{
    uint32_t half, from, to;
    uint16_t mi;
    if (!ZL_FEATURE_SPLIT) /* compiled out (zl_config.h) */
        return ZL_ERR_UNSUPPORTED;
    if (f == NULL || f->part == 0 || f->prepared || f->planned)
        return ZL_ERR_ARG;
    half = f->vertex_count / 2u;
    from = f->part == 1 ? 0 : half;
    to = f->part == 1 ? half : f->vertex_count;
    for (mi = 0; mi < f->mesh_count; mi++) {
        const zl_frame_mesh *m = &f->meshes[mi];
        uint32_t a = m->vert_base, b = m->vert_base + m->mesh.vertex_count;
        zl_source s;
        if ((m->flags & MESH_CACHED) || b <= from || a >= to)
            continue;
        if (a < from)
            a = from;
        if (b > to)
            b = to;
        source_of(f, m, &s);
        /* the submission checked the transform limits: ZL_OK */
        (void)zl_cache_vertices(&s, cache_of(f) + m->vert_base, (uint16_t)(a - m->vert_base),
                                (uint16_t)(b - a));
    }
    f->prepared = 1;
    return ZL_OK;
}
