/* SPDX-License-Identifier: MIT */
/*
 * Stage 5, render: scanline and band mode, the whole frame a band of rows at
 * a time. This file: the work-buffer layout and the submission of meshes,
 * lines and outlines; planning is in zl_frame_plan.c, rows in
 * zl_frame_rows.c.
 *
 * Planning (first zl_frame_next_band):
 *   1. every vertex is transformed once into the vertex cache (a mesh with a
 *      matrix already when it is added: filling the cache answers the
 *      transform limits there);
 *   2. every triangle is classified once (culling, clipping, row range) and
 *      its first row counted; a difference array over rows bounds how many
 *      triangles are active at once, so capacity errors come before any pixel;
 *      the visible ids go to visible[] in id order and their first rows to
 *      work-buffer regions that are idle until the first row (pool, Gouraud
 *      and texture records, depth and colour bands);
 *   3. a stable counting sort, in place, buckets the visible ids by first row
 *      (the edge table), in submission order within a bucket. Only when the
 *      first rows did not fit in the idle regions are the triangles
 *      classified a second time to place them.
 * Per row: one walk of the active list, which stays sorted by id so every
 * pixel sees triangles in submission order (as frame mode does), fills each
 * active triangle's span of the row and steps it to the next; the bucket's
 * triangles are set up and inserted as the walk passes their place; a
 * triangle leaves after its last row. Work per row is proportional to the
 * active triangles only.
 */
#include <string.h>

#include "zl_frame_internal.h"

/* n rounded up to a multiple of 8, in 32 bits (zl_frame_layout). */
static uint32_t align8_32(uint32_t n)
{
    return (n + 7u) & ~UINT32_C(7);
}

/* Offsets of every region of the work buffer. The one place that decides
 * sizes, so zl_frame_bytes is exact by construction. Summed in 32 bits, which
 * hold every configuration's total (under 2^28 bytes): where size_t has 16
 * bits (AVR) a size_t sum would wrap, and a buffer of the wrapped size would
 * pass zl_frame_begin with regions overlapping. A total beyond SIZE_MAX is
 * refused (0), as no buffer of that size can exist. */
int zl_frame_layout(const zl_frame_config *c, layout *l)
{
    uint32_t bpp = (uint32_t)zl_format_bytes((zl_format)c->format);
    uint32_t pool, gouraud, diff, band_px, size[L_TOTAL], total = 0;
    unsigned k;
    if (c->width < 1 || c->height < 1 || c->width > ZL_MAX_DIM || c->height > ZL_MAX_DIM || bpp == 0 ||
        c->band_rows < 1 || c->band_rows > c->height || c->color_buffers < 1 || c->color_buffers > 2 ||
        c->max_meshes < 1 || c->max_meshes > 255 || c->max_triangles > 65535 || c->max_active < 1 ||
        c->max_active > 65534 || c->max_vertices > UINT32_C(65535) * 255u || c->parts > 2)
        return 0; /* (65535u * 255u wraps where unsigned has 16 bits) */
    band_px = (uint32_t)c->width * c->band_rows;
    pool = (uint32_t)c->max_active * (uint32_t)sizeof(zl_active);
    gouraud = c->gouraud ? (uint32_t)c->max_active * (uint32_t)sizeof(zl_gouraud) : 0;
    /* Planning borrows the pool for a difference array of int32 per row. */
    diff = ((uint32_t)c->height + 1u) * (uint32_t)sizeof(int32_t);
    if (align8_32(pool) + gouraud < diff)
        gouraud = diff - align8_32(pool);
    size[L_MESHES] = (uint32_t)c->max_meshes * (uint32_t)sizeof(zl_frame_mesh);
    size[L_VCACHE] = (uint32_t)c->max_vertices * (uint32_t)sizeof(zl_cached_vertex);
    size[L_ROW_START] = ((uint32_t)c->height + 1u) * (uint32_t)sizeof(uint16_t);
    size[L_VISIBLE] = (uint32_t)c->max_triangles * (uint32_t)sizeof(uint16_t);
    size[L_POOL] = pool;
    size[L_GOURAUD] = gouraud;
    size[L_EXT] = c->styled ? (uint32_t)c->max_meshes * (uint32_t)sizeof(zl_frame_ext) : 0;
    size[L_TEX] = c->textured ? (uint32_t)c->max_active * (uint32_t)sizeof(zl_texplanes) : 0;
    size[L_DEPTH] = band_px * 2u;
    size[L_COLOR0] = band_px * bpp;
    size[L_COLOR1] = c->color_buffers == 2 ? band_px * bpp : 0;
    for (k = 0; k < L_TOTAL; k++) { /* each region 8-byte aligned */
        l->at[k] = (size_t)total;
        total += align8_32(size[k]);
    }
#if SIZE_MAX < UINT32_MAX
    if (total > SIZE_MAX)
        return 0;
#endif
    l->at[L_TOTAL] = (size_t)total;
    return 1;
}

size_t zl_frame_bytes(const zl_frame_config *cfg)
{
    layout l;
    if (cfg == NULL || !zl_frame_layout(cfg, &l))
        return 0;
    return l.at[L_TOTAL];
}

zl_status(zl_frame_begin)(zl_frame *f, const zl_frame_config *cfg, void *work, size_t work_bytes,
                         zl_rgb clear_color, uint16_t clear_depth)
{
    layout l;
    uint8_t *w = work;
    if (f == NULL || cfg == NULL || work == NULL)
        return ZL_ERR_ARG;
    if (((uintptr_t)work & 7u) != 0)
        return ZL_ERR_ARG;
    if (!zl_frame_layout(cfg, &l))
        return ZL_ERR_SIZE;
    if ((!ZL_FEATURE_FORMATS && cfg->format == ZL_FORMAT_RGB888) || (!ZL_FEATURE_SPLIT && cfg->parts == 2))
        return ZL_ERR_UNSUPPORTED; /* compiled out (zl_config.h) */
    if (work_bytes < l.at[L_TOTAL])
        return ZL_ERR_SIZE;
    memset(f, 0, sizeof *f);
    f->cfg = *cfg;
    f->clear_color = clear_color;
    f->clear_depth = clear_depth;
    f->end_row = cfg->height;
    f->meshes = (zl_frame_mesh *)(void *)(w + l.at[L_MESHES]);
    f->vcache = w + l.at[L_VCACHE];
    f->row_start = (uint16_t *)(void *)(w + l.at[L_ROW_START]);
    f->visible = (uint16_t *)(void *)(w + l.at[L_VISIBLE]);
    f->pool = (zl_active *)(void *)(w + l.at[L_POOL]);
    f->gouraud = cfg->gouraud ? w + l.at[L_GOURAUD] : NULL;
    f->ext = cfg->styled ? w + l.at[L_EXT] : NULL;
    f->tex = cfg->textured ? w + l.at[L_TEX] : NULL;
    f->depth_band = (uint16_t *)(void *)(w + l.at[L_DEPTH]);
    f->color_band[0] = w + l.at[L_COLOR0];
    f->color_band[1] = cfg->color_buffers == 2 ? w + l.at[L_COLOR1] : w + l.at[L_COLOR0];
    f->active_head = ZL_LIST_END;
    return ZL_OK;
}

static int is_default_style(const zl_style *s)
{
    zl_style d;
    zl_style_default(&d);
    return s->polygon_front == d.polygon_front && s->polygon_back == d.polygon_back &&
           s->point_size == d.point_size && s->line_algo == d.line_algo && s->offset_factor == d.offset_factor &&
           s->offset_units == d.offset_units && s->texture == d.texture && s->persp_gouraud == d.persp_gouraud &&
           s->toon_bands == d.toon_bands && s->line_aa == d.line_aa && s->blend == d.blend;
}

/* Record the style of mesh record mi (default when NULL), and lines. */
static void set_ext(zl_frame *f, unsigned mi, const zl_style *style, const zl_lines *lines, const zl_mesh *omesh,
                    const zl_outline *outline)
{
    zl_frame_ext *e = ext_of(f, mi);
    if (e == NULL)
        return;
    if (style != NULL)
        e->style = *style;
    else
        zl_style_default(&e->style);
    e->is_lines = lines != NULL ? 1 : (outline != NULL ? 2 : 0);
    if (lines != NULL)
        e->lines = *lines;
    if (outline != NULL) {
        e->mesh = *omesh;
        e->outline = *outline;
    }
}

/* The sign of the window-space area (zl_tri_classify's) of the triangles the
 * state culls: y grows down, so a negative area is counter-clockwise on
 * screen. 0 when neither side is culled by area alone. */
static int culled_area_sign(const zl_state *st)
{
    int front_sign = st->front_face == ZL_FRONT_CCW ? -1 : 1;
    if (st->cull == ZL_CULL_BACK)
        return -front_sign;
    if (st->cull == ZL_CULL_FRONT)
        return front_sign;
    return 0;
}

/* MESH_FLAT and MESH_ROW565 of a mesh record (sty: its style, NULL for the
 * default): a flat fill without polygon modes, offset, toon bands, texture
 * or perspective planes is one zl_tri_setup_flat record per cached
 * triangle (as frame mode's draw_cached), and its rows may take the RGB565
 * loop of render_row_plain. */
static unsigned mesh_flags(const zl_frame *f, const zl_frame_mesh *m, const zl_style *sty)
{
    const zl_span_state *ss = &m->span;
    int row565;
    if (!ZL_FAST_PATHS) /* off (zl_config.h): every triangle takes activate's general set-up, the same pixels */
        return 0;
    row565 = ss->format == ZL_FORMAT_RGB565 && ss->bpp == 2 && ss->zwrite && ss->keep[0] == 0 && ss->keep[1] == 0 &&
             (ss->func == ZL_LESS || ss->func == ZL_LEQUAL);
    if (sty != NULL && (sty->polygon_front != ZL_POLY_FILL || sty->polygon_back != ZL_POLY_FILL ||
                        sty->offset_factor != 0 || sty->offset_units != 0 || sty->toon_bands != 0 ||
                        zl_style_planes(sty)))
        return 0;
    /* MESH_GOURAUD565: frame mode's plain_gouraud (zl_draw.c), without style
     * records (render_row_plain's walks) and with a Gouraud slot a record */
    if (m->state.shading == ZL_SHADE_GOURAUD)
        return row565 && sty == NULL && f->ext == NULL && f->gouraud != NULL && !m->state.light_on &&
                       m->mesh.vertex_colors != NULL
                   ? MESH_GOURAUD565
                   : 0;
    if (m->state.shading != ZL_SHADE_FLAT)
        return 0;
    return row565 ? MESH_FLAT | MESH_ROW565 : MESH_FLAT;
}

/* zl_check_geometry, with the transform limits answered by transforming the
 * vertices into the mesh's vertex cache entries when a matrix is given and
 * they fit (zl_cache_vertices fails exactly when zl_check_positions does);
 * *cached tells whether it did, so planning need not transform them. */
static zl_status check_and_cache(const zl_frame *f, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *state,
                                 int *cached)
{
    zl_status st = zl_check_mesh(mesh, mvp == NULL);
    zl_source s;
    *cached = 0;
    if (st != ZL_OK)
        return st;
    if (mvp == NULL || mesh->vertex_count == 0 || f->vertex_count + mesh->vertex_count > f->cfg.max_vertices ||
        f->cfg.parts == 2) /* a split frame's parts transform (zl_frame_prepare) */
        return zl_check_positions(mesh->positions, mesh->vertex_count, mvp);
    s.mesh = mesh;
    s.mvp = mvp;
    s.state = state;
    s.cache = NULL;
    s.width = f->cfg.width;
    s.height = f->cfg.height;
    *cached = 1;
    return zl_cache_vertices(&s, cache_of(f) + f->vertex_count, 0, mesh->vertex_count);
}

static zl_status add_record(zl_frame *f, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *state,
                            const zl_style *style, const zl_lines *lines, const zl_mesh *omesh,
                            const zl_outline *outline)
{
    zl_frame_mesh *m;
    zl_status st = ZL_OK;
    int cached = 0;
    if (f == NULL || state == NULL || f->planned || f->over || f->depth_band == NULL) /* planned, or never begun */
        return ZL_ERR_ARG;
    if (lines == NULL && outline == NULL)
        st = check_and_cache(f, mesh, mvp, state, &cached);
    if (st == ZL_OK)
        st = zl_state_check(state);
    if (st == ZL_OK && style != NULL)
        st = zl_style_check(style);
    if (st != ZL_OK)
        return st;
    if (state->shading == ZL_SHADE_GOURAUD && !f->cfg.gouraud)
        return ZL_ERR_CAPACITY;
    if (!f->cfg.styled && (lines != NULL || outline != NULL || (style != NULL && !is_default_style(style))))
        return ZL_ERR_CAPACITY;
    if (!f->cfg.textured && zl_style_planes(style))
        return ZL_ERR_CAPACITY;
    if (f->mesh_count >= f->cfg.max_meshes || f->vertex_count + mesh->vertex_count > f->cfg.max_vertices ||
        f->triangle_total + mesh->triangle_count > 65535u)
        return ZL_ERR_CAPACITY;
    m = &f->meshes[f->mesh_count];
    m->mesh = *mesh;
    if (mvp != NULL)
        m->mvp = *mvp;
    m->state = *state;
    zl_span_state_init(&m->span, state, 1, 1, (zl_format)f->cfg.format, f->cfg.width);
    zl_light_prepare(state, m->lq);
    m->tri_base = f->triangle_total;
    m->vert_base = f->vertex_count;
    set_ext(f, f->mesh_count, style, lines, omesh, outline);
    m->flags = (uint8_t)((lines == NULL && outline == NULL ? mesh_flags(f, m, style_of(f, f->mesh_count)) : 0u) |
                         (mvp != NULL ? MESH_MVP : 0u) | (cached ? MESH_CACHED : 0u));
    m->cull_code = (uint8_t)(culled_area_sign(state) + 1);
    f->mesh_count++;
    f->vertex_count += mesh->vertex_count;
    f->triangle_total += mesh->triangle_count;
    return ZL_OK;
}

zl_status zl_frame_add_mesh(zl_frame *f, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *state)
{
    return add_record(f, mesh, mvp, state, NULL, NULL, NULL, NULL);
}

zl_status zl_frame_add_mesh_styled(zl_frame *f, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *state,
                                   const zl_style *style)
{
    return add_record(f, mesh, mvp, state, style, NULL, NULL, NULL);
}

zl_status zl_frame_add_lines(zl_frame *f, const zl_lines *lines, const zl_mat4 *mvp, const zl_state *state,
                             const zl_style *style)
{
    zl_mesh m;
    zl_status st = zl_check_lines(lines);
    zl_style d;
    if (!ZL_FEATURE_LINES) /* compiled out (zl_config.h): zl_check_lines said so, the rest goes */
        return st;
    if (st == ZL_OK) /* the transform limits (LIMITS in zline.h) */
        st = zl_check_positions(lines->positions, lines->vertex_count, mvp);
    if (st != ZL_OK)
        return st;
    if (style == NULL) {
        zl_style_default(&d);
        style = &d;
    }
    zl_lines_mesh(lines, &m);
    return add_record(f, &m, mvp, state, style, lines, NULL, NULL);
}

zl_status zl_frame_add_outlines(zl_frame *f, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *state,
                                const zl_style *style, const zl_outline *outline)
{
    zl_mesh m;
    zl_status st = zl_check_mesh(mesh, mvp == NULL);
    zl_style d;
    if (st == ZL_OK)
        st = zl_check_outline(mesh, outline);
    if (st != ZL_OK || !ZL_FEATURE_OUTLINES) /* compiled out (zl_config.h): zl_check_outline said so */
        return st;
    if (outline->edge_count > 65535u)
        return ZL_ERR_CAPACITY;
    if (style == NULL) {
        zl_style_default(&d);
        style = &d;
    }
    /* A view with the positions only: outline edges are transformed per
     * segment, not cached. */
    m = *mesh;
    m.indices = NULL;
    m.vertex_colors = NULL;
    m.face_colors = NULL;
    m.vertex_count = 0;
    m.triangle_count = (uint16_t)outline->edge_count;
    return add_record(f, &m, mvp, state, style, NULL, mesh, outline);
}
