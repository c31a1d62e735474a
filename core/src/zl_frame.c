/*
 * Scanline and band mode: the whole frame a band of rows at a time.
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

#include "zl_internal.h"
#include "zl_span.h"

struct zl_frame_mesh {
    zl_mesh mesh;
    zl_mat4 mvp;
    zl_state state;
    zl_span_state span;
    uint8_t flags;      /* MESH_*, in bytes that were padding: the layout does not change */
    uint8_t cull_code;  /* culled_area_sign of the state, plus 1 (0, 1 or 2) */
    uint32_t tri_base, vert_base;
};

#define MESH_MVP 1u       /* mvp holds the transform (else pixel space) */
#define MESH_FLAT 2u      /* plain flat fill: cached triangles set up by zl_tri_setup_flat */
#define MESH_ROW565 4u    /* MESH_FLAT with RGB565 spans, depth LESS or LEQUAL written, every channel */
#define MESH_CACHED 8u    /* its vertex cache entries were filled when it was added */

/* Per-mesh record of the styled features (only with cfg.styled). */
typedef struct {
    zl_style style;
    zl_lines lines;     /* is_lines == 1 */
    zl_mesh mesh;       /* is_lines == 2: the outlined mesh ... */
    zl_outline outline; /* ... and its outline */
    uint8_t is_lines;
} zl_frame_ext;

#define ALIGN8(n) (((n) + 7u) & ~(size_t)7u)

typedef struct {
    size_t meshes, vcache, row_start, visible, pool, gouraud, ext, tex, depth, color0, color1, total;
} layout;

/* Offsets of every region of the work buffer. The one place that decides
 * sizes, so zl_frame_bytes is exact by construction. */
static int layout_of(const zl_frame_config *c, layout *l)
{
    size_t bpp = zl_format_bytes((zl_format)c->format);
    size_t pool, gouraud, diff, band_px;
    if (c->width < 1 || c->height < 1 || c->width > ZL_MAX_DIM || c->height > ZL_MAX_DIM || bpp == 0 ||
        c->band_rows < 1 || c->band_rows > c->height || c->color_buffers < 1 || c->color_buffers > 2 ||
        c->max_meshes < 1 || c->max_meshes > 255 || c->max_triangles > 65535 || c->max_active < 1 ||
        c->max_active > 65534 || c->max_vertices > 65535u * 255u)
        return 0;
    band_px = (size_t)c->width * c->band_rows;
    pool = (size_t)c->max_active * sizeof(zl_active);
    gouraud = c->gouraud ? (size_t)c->max_active * sizeof(zl_gouraud) : 0;
    /* Planning borrows the pool for a difference array of int32 per row. */
    diff = ((size_t)c->height + 1) * sizeof(int32_t);
    l->meshes = 0;
    l->vcache = l->meshes + ALIGN8((size_t)c->max_meshes * sizeof(zl_frame_mesh));
    l->row_start = l->vcache + ALIGN8((size_t)c->max_vertices * sizeof(zl_cached_vertex));
    l->visible = l->row_start + ALIGN8(((size_t)c->height + 1) * sizeof(uint16_t));
    l->pool = l->visible + ALIGN8((size_t)c->max_triangles * sizeof(uint16_t));
    l->gouraud = l->pool + ALIGN8(pool);
    if (ALIGN8(pool) + gouraud < diff)
        gouraud = diff - ALIGN8(pool);
    l->ext = l->gouraud + ALIGN8(gouraud);
    l->tex = l->ext + (c->styled ? ALIGN8((size_t)c->max_meshes * sizeof(zl_frame_ext)) : 0);
    l->depth = l->tex + (c->textured ? ALIGN8((size_t)c->max_active * sizeof(zl_texplanes)) : 0);
    l->color0 = l->depth + ALIGN8(band_px * 2);
    l->color1 = l->color0 + ALIGN8(band_px * bpp);
    l->total = l->color1 + (c->color_buffers == 2 ? ALIGN8(band_px * bpp) : 0);
    return 1;
}

size_t zl_frame_bytes(const zl_frame_config *cfg)
{
    layout l;
    if (cfg == NULL || !layout_of(cfg, &l))
        return 0;
    return l.total;
}

zl_status zl_frame_begin(zl_frame *f, const zl_frame_config *cfg, void *work, size_t work_bytes,
                         zl_rgb clear_color, uint16_t clear_depth)
{
    layout l;
    uint8_t *w = work;
    if (f == NULL || cfg == NULL || work == NULL)
        return ZL_ERR_ARG;
    if (((uintptr_t)work & 7u) != 0)
        return ZL_ERR_ARG;
    if (!layout_of(cfg, &l))
        return ZL_ERR_SIZE;
    if (work_bytes < l.total)
        return ZL_ERR_SIZE;
    memset(f, 0, sizeof *f);
    f->cfg = *cfg;
    f->clear_color = clear_color;
    f->clear_depth = clear_depth;
    f->meshes = (zl_frame_mesh *)(void *)(w + l.meshes);
    f->vcache = w + l.vcache;
    f->row_start = (uint16_t *)(void *)(w + l.row_start);
    f->visible = (uint16_t *)(void *)(w + l.visible);
    f->pool = (zl_active *)(void *)(w + l.pool);
    f->gouraud = cfg->gouraud ? w + l.gouraud : NULL;
    f->ext = cfg->styled ? w + l.ext : NULL;
    f->tex = cfg->textured ? w + l.tex : NULL;
    f->depth_band = (uint16_t *)(void *)(w + l.depth);
    f->color_band[0] = w + l.color0;
    f->color_band[1] = cfg->color_buffers == 2 ? w + l.color1 : w + l.color0;
    f->active_head = ZL_LIST_END;
    return ZL_OK;
}

static zl_frame_ext *ext_of(const zl_frame *f, unsigned mi)
{
    return f->ext ? (zl_frame_ext *)(void *)(f->ext + (size_t)mi * sizeof(zl_frame_ext)) : NULL;
}

static const zl_style *style_of(const zl_frame *f, unsigned mi)
{
    return f->ext ? &ext_of(f, mi)->style : NULL;
}

static int is_default_style(const zl_style *s)
{
    zl_style d;
    zl_style_default(&d);
    return s->polygon_front == d.polygon_front && s->polygon_back == d.polygon_back &&
           s->point_size == d.point_size && s->line_algo == d.line_algo && s->offset_factor == d.offset_factor &&
           s->offset_units == d.offset_units && s->texture == d.texture && s->persp_gouraud == d.persp_gouraud &&
           s->toon_bands == d.toon_bands && s->line_aa == d.line_aa;
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
static unsigned mesh_flags(const zl_frame_mesh *m, const zl_style *sty)
{
    const zl_span_state *ss = &m->span;
    unsigned flags;
    if (m->state.shading != ZL_SHADE_FLAT)
        return 0;
    if (sty != NULL && (sty->polygon_front != ZL_POLY_FILL || sty->polygon_back != ZL_POLY_FILL ||
                        sty->offset_factor != 0 || sty->offset_units != 0 || sty->toon_bands != 0 ||
                        zl_style_needs_planes(sty)))
        return 0;
    flags = MESH_FLAT;
    if (ss->format == ZL_FORMAT_RGB565 && ss->bpp == 2 && ss->zwrite && ss->keep[0] == 0 && ss->keep[1] == 0 &&
        (ss->func == ZL_LESS || ss->func == ZL_LEQUAL))
        flags |= MESH_ROW565;
    return flags;
}

static zl_cached_vertex *cache_of(const zl_frame *f)
{
    return (zl_cached_vertex *)(void *)f->vcache;
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
    if (mvp == NULL || mesh->vertex_count == 0 || f->vertex_count + mesh->vertex_count > f->cfg.max_vertices)
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
    if (f == NULL || state == NULL || f->planned)
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
    if (!f->cfg.textured && zl_style_needs_planes(style))
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
    m->tri_base = f->triangle_total;
    m->vert_base = f->vertex_count;
    set_ext(f, f->mesh_count, style, lines, omesh, outline);
    m->flags = (uint8_t)((lines == NULL && outline == NULL ? mesh_flags(m, style_of(f, f->mesh_count)) : 0u) |
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
    if (st != ZL_OK)
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

static void source_of(const zl_frame *f, const zl_frame_mesh *m, zl_source *s)
{
    s->mesh = &m->mesh;
    s->mvp = (m->flags & MESH_MVP) ? &m->mvp : NULL;
    s->state = &m->state;
    s->cache = cache_of(f) + m->vert_base;
    s->width = f->cfg.width;
    s->height = f->cfg.height;
}

/* Record of primitive t of a lines or outline mesh record. */
static int prim_record(const zl_frame *f, unsigned mi, const zl_source *s, uint32_t t, zl_active *rec)
{
    const zl_frame_ext *e = ext_of(f, mi);
    if (e->is_lines == 2)
        return zl_outline_record(s, &e->mesh, &e->outline, &e->style, t, rec);
    return zl_lines_record(s, &e->lines, &e->style, &f->meshes[mi].state, t, rec);
}

static void fill_cache(zl_frame *f)
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
} plan_pass;

static uint16_t *key_at(const plan_pass *p, uint32_t k)
{
    return k < p->na ? &p->key_a[k] : &p->key_b[k - p->na];
}

/* Record visible primitive id with row range [first, end) and its pieces. */
static ZL_ALWAYS_INLINE void note(zl_frame *f, plan_pass *p, uint32_t id, int32_t first, int32_t end, unsigned pieces)
{
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

/* Lines and outline records: one record per primitive. Out of line, like the
 * next one, so its record is not on the stack of the clipping path. */
static ZL_NOINLINE void classify_lines(zl_frame *f, plan_pass *p, unsigned mi, const zl_source *s)
{
    const zl_frame_mesh *m = &f->meshes[mi];
    uint32_t t;
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

/* The index of the first row (or column) whose centre is at or after
 * subpixel coordinate v (zl_raster.c's first_centre_at_or_after). */
static int32_t centre_at_or_after(int32_t v)
{
    return zl_floor_shift32(v - ZL_SUB_HALF + ZL_SUB_ONE - 1, ZL_SUB_BITS);
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
    int64_t p = (int64_t)(b->x - a->x) * (c->y - a->y), q = (int64_t)(c->x - a->x) * (b->y - a->y);
    ymax = ymin;
    xmax = xmin;
    if (p == q || (p < q ? -1 : 1) == cull_sign)
        return 0;
    if (b->y < ymin)
        ymin = b->y;
    if (b->y > ymax)
        ymax = b->y;
    if (c->y < ymin)
        ymin = c->y;
    if (c->y > ymax)
        ymax = c->y;
    *first = centre_at_or_after(ymin);
    *end = centre_at_or_after(ymax);
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
    return centre_at_or_after(xmin) < width && centre_at_or_after(xmax) > 0;
}

/* Filled triangle t that needs clipping (or is dropped): the row range of
 * every fan triangle of its polygon. Out of line, so the polygon is not on
 * the stack (nor in the registers) of the loop below. */
static ZL_NOINLINE void classify_polygon(zl_frame *f, plan_pass *p, const zl_frame_mesh *m, const zl_source *s,
                                         const zl_style *sty, uint32_t t)
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
        note(f, p, m->tri_base + t, first, end, pieces);
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
        const zl_cached_vertex *c0 = &cache[idx[0]], *c1 = &cache[idx[1]], *c2 = &cache[idx[2]];
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

static ZL_NOINLINE zl_status plan(zl_frame *f)
{
    layout l;
    uint8_t *base = (uint8_t *)(void *)f->meshes;
    uint32_t running = 0, start = 0, peak = 0, slot, visible;
    uint16_t h = f->cfg.height, j;
    size_t diff_bytes = ALIGN8(((size_t)h + 1) * sizeof(int32_t));
    plan_pass p;
    if (!layout_of(&f->cfg, &l)) /* cannot fail: zl_frame_begin checked the configuration */
        return ZL_ERR_ARG;
    /* Until the first row the pool (after the difference array), the
     * Gouraud records and everything from the texture planes to the colour
     * bands are free: room for the first rows of the visible primitives,
     * which then need no second classification. */
    p.diff = (int32_t *)(void *)f->pool;
    p.key_a = (uint16_t *)(void *)(base + l.pool + diff_bytes);
    p.na = l.ext - l.pool > diff_bytes ? (uint32_t)((l.ext - l.pool - diff_bytes) / sizeof(uint16_t)) : 0;
    p.key_b = (uint16_t *)(void *)(base + l.tex);
    p.nb = (uint32_t)((l.total - l.tex) / sizeof(uint16_t));
    fill_cache(f);
    memset(f->row_start, 0, ((size_t)h + 1) * sizeof(uint16_t));
    memset(p.diff, 0, ((size_t)h + 1) * sizeof(int32_t));
    visible = classify_pass(f, &p);
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
    if (visible <= p.na + p.nb) {
        place_by_keys(f, &p, visible);
    } else { /* the keys did not fit: classify again */
        p.diff = NULL;
        classify_pass(f, &p);
    }
    /* The pool's free list: every record, in order. */
    for (slot = 0; slot < f->cfg.max_active; slot++)
        f->pool[slot].next = (uint16_t)(slot + 1u < f->cfg.max_active ? slot + 1u : ZL_LIST_END);
    f->free_head = 0;
    f->active_head = ZL_LIST_END;
    return ZL_OK;
}

static uint8_t mesh_of_id(const zl_frame *f, uint16_t id)
{
    uint8_t mi = 0;
    while (mi + 1 < f->mesh_count && id >= f->meshes[mi + 1].tri_base)
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

/* Triangle t of a MESH_FLAT mesh with its vertices c cached inside, which
 * planning kept: the record zl_tri_polygon_geom + zl_tri_shade +
 * zl_tri_piece give (one piece, no offset, the lit flat colour), set up as
 * frame mode's draw_cached does (poly: the caller's scratch polygon).
 * Returns 0 when it has no rows (never). */
static ZL_ALWAYS_INLINE int setup_cached(const zl_frame_mesh *m, const zl_source *s, uint32_t t,
                                         const zl_cached_vertex *const *c, zl_active *a, zl_poly *poly)
{
    if (!zl_tri_setup_flat(a, c[0], c[1], c[2], &m->state, s->width, s->height))
        return 0;
    poly->n = 0; /* flat: no vertex colours for the lighting to scale */
    zl_tri_shade(s, t, poly);
    a->rgb[0] = poly->flat.r;
    a->rgb[1] = poly->flat.g;
    a->rgb[2] = poly->flat.b;
    a->light = poly->light;
    return 1;
}

/* Triangle t of mesh record mi, a MESH_FLAT mesh, when its three vertices
 * are cached inside: set up by setup_cached and inserted at *link. Returns
 * 0, having done nothing, when a vertex needs clipping (or is dropped):
 * then the general path takes the triangle. */
static ZL_ALWAYS_INLINE int activate_cached(zl_frame *f, uint8_t mi, const zl_source *s, uint32_t t, uint16_t *link,
                                            zl_poly *poly)
{
    const zl_frame_mesh *m = &f->meshes[mi];
    const uint16_t *idx = m->mesh.indices + t * 3u;
    const zl_cached_vertex *c[3];
    uint16_t slot = f->free_head, i0 = idx[0], i1 = idx[1], i2 = idx[2];
    zl_active *a;
    c[0] = s->cache + i0;
    c[1] = s->cache + i1;
    c[2] = s->cache + i2;
    if (c[0]->x <= ZL_CACHE_INVALID || c[1]->x <= ZL_CACHE_INVALID || c[2]->x <= ZL_CACHE_INVALID)
        return 0;
    if (slot == ZL_LIST_END)
        return 1; /* cannot happen: planning bounded the peak */
    a = &f->pool[slot];
    if (!setup_cached(m, s, t, c, a, poly))
        return 1;
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
    int lines = sty != NULL && ext_of(f, mi)->is_lines;
    uint32_t t = id - m->tri_base;
    zl_source s;
    zl_tpoly tpoly; /* texture attributes only when the style needs them */
    zl_poly *poly = &tpoly.p;
    unsigned k, n = 1;
    source_of(f, m, &s);
    if (!lines && (m->flags & MESH_FLAT) && activate_cached(f, mi, &s, t, link, poly))
        return;
    if (!lines) {
        if (!(zl_style_needs_planes(sty) ? zl_tri_polygon_tex(&s, sty, t, &tpoly)
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
        if (a->row != y) { /* a later piece of a clipped triangle: not started */
            link = &a->next;
            continue;
        }
        sty = style_of(f, a->mesh);
        ss = &f->meshes[a->mesh].span;
        if (a->kind != ZL_KIND_TRI)
            more = zl_prim_row(a, ss, crow, zrow);
        else if (f->tex != NULL && zl_style_needs_planes(sty))
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
    if ((m->flags & MESH_FLAT) && activate_cached(f, mi, &s, t, link, &poly))
        return;
    if (!zl_tri_polygon_geom(&s, NULL, t, &poly))
        return;
    zl_tri_shade(&s, t, &poly);
    n = zl_tri_pieces(&s, NULL, t, &poly);
    for (k = 0; k < n; k++) {
        uint16_t slot = f->free_head;
        zl_active *a;
        if (slot == ZL_LIST_END)
            break; /* cannot happen: planning bounded the peak */
        a = &f->pool[slot];
        if (!zl_tri_piece(&s, NULL, t, &poly, k, a, gouraud_of(f, slot), tex_of(f, slot)))
            continue;
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
    int32_t n = x1 - x0, k;
    int64_t v, w;
    uint32_t z, dz = a->dz14, lo14 = a->zlo >> 2, hi14 = a->zhi >> 2;
    int32_t dx32 = (int32_t)a->z.dx; /* kept only when it is the whole gradient */
    uint16_t pixel = (uint16_t)(((unsigned)(a->rgb[0] >> 3) << 11) | ((unsigned)(a->rgb[1] >> 2) << 5) |
                                (unsigned)(a->rgb[2] >> 3));
    uint16_t *c, *zb;
    if (a->z.dx == (int64_t)dx32) /* a 32-bit gradient: one multiply-accumulate */
        v = a->z.row + (int64_t)dx32 * (x0 - a->ax);
    else
        v = plane_wide(a, x0);
    w = zl_floor_shift64(v, ZL_ATTR_FRAC - 14);
    z = w < 0 ? 0u : (w > (int64_t)hi14 ? hi14 : (uint32_t)w);
    z = (z < lo14 ? lo14 : z) + (1u << 13);
    if (n > SHORT_SPAN) {
        uint8_t pix[3];
        memcpy(pix, &pixel, 2); /* pack_color's native RGB565 */
        pix[2] = 0;
        zl_span_flat(ss, crow + (size_t)x0 * 2u, zrow + x0, n, z, dz, pix);
        return;
    }
    c = (uint16_t *)(void *)crow + x0;
    zb = zrow + x0;
    for (k = 0; k < n; k++) {
        uint32_t d = depth_of(z);
        if (depth_pass(func, d, zb[k])) {
            zb[k] = (uint16_t)d;
            c[k] = pixel;
        }
        z += dz;
    }
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
 * render_row_plain() when every mesh is MESH_ROW565 with depth test `func`
 * (then all their span states are the same): the walk with each record's
 * span and steps in line.
 */
static ZL_ALWAYS_INLINE void rows_565(zl_frame *f, uint16_t y, uint16_t i, uint16_t end, uint8_t *crow,
                                      uint16_t *zrow, unsigned func)
{
    uint16_t *link = &f->active_head;
    zl_active *pool = f->pool;
    const uint16_t *visible = f->visible;
    const zl_span_state *ss = &f->meshes[0].span;
    for (;;) {
        uint16_t slot = *link;
        zl_active *a;
        int32_t x0, x1;
        if (i < end && (slot == ZL_LIST_END || pool[slot].id > visible[i])) {
            activate_plain(f, visible[i++], link);
            continue;
        }
        if (slot == ZL_LIST_END)
            break;
        a = &pool[slot];
        if (a->row != y) { /* a later piece of a clipped triangle, not started */
            link = &a->next;
            continue;
        }
        x0 = a->left.x < 0 ? 0 : a->left.x;
        x1 = a->right.x > ss->width ? ss->width : a->right.x;
        if (x0 < x1)
            span_565(a, ss, func, crow, zrow, x0, x1);
        if (row_step(a))
            link = &a->next;
        else
            retire(f, link, a, slot);
    }
}

static ZL_NOINLINE void render_row_less(zl_frame *f, uint16_t y, uint16_t i, uint16_t end, uint8_t *crow,
                                        uint16_t *zrow)
{
    rows_565(f, y, i, end, crow, zrow, ZL_LESS);
}

static ZL_NOINLINE void render_row_lequal(zl_frame *f, uint16_t y, uint16_t i, uint16_t end, uint8_t *crow,
                                          uint16_t *zrow)
{
    rows_565(f, y, i, end, crow, zrow, ZL_LEQUAL);
}

/* render_row_styled() without style records: every record is a filled
 * triangle without texture planes (add_record refuses anything else). */
static ZL_NOINLINE void render_row_plain(zl_frame *f, uint16_t y, uint16_t i, uint16_t end, uint8_t *crow,
                                         uint16_t *zrow)
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
        if (a->row != y) { /* a later piece of a clipped triangle, not started */
            link = &a->next;
            continue;
        }
        m = &meshes[a->mesh];
        if (m->flags & MESH_ROW565) {
            int32_t x0 = a->left.x < 0 ? 0 : a->left.x, x1 = a->right.x > m->span.width ? m->span.width : a->right.x;
            if (x0 < x1) {
                if (m->span.func == ZL_LESS)
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

static void render_row(zl_frame *f, uint16_t y, uint8_t *crow, uint16_t *zrow)
{
    uint16_t i = y == 0 ? 0 : f->row_start[y - 1], end = f->row_start[y];
    unsigned mi, flags = 0, func = 0;
    if (f->ext != NULL) {
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

zl_status zl_frame_next_band(zl_frame *f, zl_band *band)
{
    uint16_t rows, r, w;
    size_t bpp;
    uint8_t *color;
    uint8_t pix[3] = {0, 0, 0};
    uint16_t pix16;
    if (f == NULL || band == NULL)
        return ZL_ERR_ARG;
    if (!f->planned) {
        zl_status st = plan(f);
        if (st != ZL_OK)
            return st;
        f->planned = 1;
    }
    if (f->next_row >= f->cfg.height)
        return ZL_DONE;
    w = f->cfg.width;
    bpp = zl_format_bytes((zl_format)f->cfg.format);
    rows = (uint16_t)(f->cfg.height - f->next_row);
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
    zl_frame_needs_t none = {0, 0};
    return f ? f->needs : none;
}
