/* SPDX-License-Identifier: MIT */
/* Stage 5, render: immediate (frame) mode, meshes, lines and outlines drawn
 * straight into a full target, with the fast path of the cached flat draw. */
#include <string.h>

#include "../1_base/zl_internal.h"
#include "../3_raster/zl_span.h"

/* ZL_VERTEX_CACHE_BYTES and ZL_DRAW_CACHE_BYTES promise 12 bytes per cached
 * vertex, 8 without ZL_FEATURE_EXACT_DEPTH. */
typedef char zl_cache_entry_size[(sizeof(zl_cached_vertex) == ZL_VERTEX_CACHE_ENTRY) ? 1 : -1];
/* The draw cache starts with a zl_vx (8-byte aligned: int64_t), the slots
 * after it stay 8-byte aligned. */
typedef char zl_draw_setup_fits[(sizeof(zl_vx) <= ZL_DRAW_CACHE_SETUP_BYTES) ? 1 : -1];
typedef char zl_draw_setup_keeps_alignment[(ZL_DRAW_CACHE_SETUP_BYTES % 8u == 0) ? 1 : -1];

static int aligned2(const void *p)
{
    return ((uintptr_t)p & 1u) == 0;
}

static zl_status check_target(const zl_target *t)
{
    unsigned bpp;
    if (t->width < 1 || t->height < 1 || t->width > ZL_MAX_DIM || t->height > ZL_MAX_DIM)
        return ZL_ERR_SIZE;
    bpp = zl_format_bytes((zl_format)t->format);
    if (bpp == 0)
        return ZL_ERR_ARG;
    if (!ZL_FEATURE_FORMATS && t->format == ZL_FORMAT_RGB888)
        return ZL_ERR_UNSUPPORTED; /* compiled out (zl_config.h) */
    if (t->color != NULL) {
        if (t->color_stride < (int32_t)(t->width * bpp))
            return ZL_ERR_SIZE;
        /* Native RGB565 is uint16 data; RGB565_BE is a byte stream, any alignment. */
        if (t->format == ZL_FORMAT_RGB565 && (!aligned2(t->color) || (t->color_stride & 1)))
            return ZL_ERR_ARG;
    }
    if (t->depth != NULL) {
        if (t->depth_stride < (int32_t)t->width * 2 || (t->depth_stride & 1))
            return ZL_ERR_SIZE;
        if (!aligned2(t->depth))
            return ZL_ERR_ARG;
    }
    return ZL_OK;
}

zl_status(zl_init)(zl_context *ctx, const zl_target *target)
{
    zl_status st;
    if (ctx == NULL || target == NULL)
        return ZL_ERR_ARG;
    st = check_target(target);
    if (st != ZL_OK)
        return st;
    ctx->target = *target;
    zl_state_default(&ctx->state);
    zl_style_default(&ctx->style);
    ctx->vertex_cache = NULL;
    ctx->vertex_cache_bytes = 0;
    ctx->draw_cache = NULL;
    ctx->draw_cache_bytes = 0;
    return ZL_OK;
}

size_t zl_draw_cache_bytes(void)
{
    return ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS);
}

static uint8_t *color_row(const zl_target *t, int32_t y)
{
    return t->color ? (uint8_t *)t->color + (size_t)y * (size_t)t->color_stride : NULL;
}

static uint16_t *depth_row(const zl_target *t, int32_t y)
{
    return t->depth ? (uint16_t *)(void *)((uint8_t *)t->depth + (size_t)y * (size_t)t->depth_stride)
                    : NULL;
}

zl_status zl_clear(zl_context *ctx, zl_rgb color, uint16_t depth)
{
    zl_span_state ss;
    zl_status st;
    int32_t y;
    int clear_depth;
    if (ctx == NULL)
        return ZL_ERR_ARG;
    st = check_target(&ctx->target);
    if (st == ZL_OK)
        st = zl_state_check(&ctx->state);
    if (st != ZL_OK)
        return st;
    zl_span_state_init(&ss, &ctx->state, 1, ctx->target.color != NULL, (zl_format)ctx->target.format,
                       ctx->target.width);
    /* Rows without gaps between them (stride = row bytes) are one run: a
     * single fill, without the per-row set-up (without the fast paths,
     * zl_config.h: row by row, the same bytes). */
    clear_depth = ctx->target.depth != NULL && ctx->state.depth_write;
    if (ZL_FAST_PATHS && clear_depth && ctx->target.depth_stride == (int32_t)ctx->target.width * 2) {
        zl_fill16(ctx->target.depth, depth, (uint32_t)ctx->target.width * ctx->target.height);
        clear_depth = 0;
    }
    if (ZL_FAST_PATHS && ss.bpp == 2 && ss.keep[0] == 0 && ss.keep[1] == 0 && ctx->target.format == ZL_FORMAT_RGB565 &&
        ctx->target.color_stride == (int32_t)ctx->target.width * 2) {
        uint8_t pix[3] = {0, 0, 0};
        uint16_t v;
        pack_color(ZL_FORMAT_RGB565, color.r, color.g, color.b, pix);
        memcpy(&v, pix, 2);
        zl_fill16((uint16_t *)ctx->target.color, v, (uint32_t)ctx->target.width * ctx->target.height);
        ss.bpp = 0;
    }
    for (y = 0; y < ctx->target.height && (ss.bpp != 0 || clear_depth); y++) {
        if (ss.bpp != 0)
            zl_fill_color_row(color_row(&ctx->target, y), &ss, color);
        if (clear_depth)
            zl_fill16(depth_row(&ctx->target, y), depth, ctx->target.width);
    }
    return ZL_OK;
}

/* Draw one set-up triangle, line or point into the target, all its rows. */
static void draw_rows(const zl_context *ctx, zl_active *t, zl_gouraud *g, zl_texplanes *tp,
                      const zl_span_state *ss)
{
    if (t->kind != ZL_KIND_TRI) {
        while (zl_prim_row(t, ss, color_row(&ctx->target, t->row), depth_row(&ctx->target, t->row)))
            ;
        return;
    }
    if (ZL_FAST_PATHS && tp == NULL && !ss->gouraud) { /* else zl_tri_row's rows below: the same spans */
        zl_tri_rows_flat(t, ss, (uint8_t *)ctx->target.color, ctx->target.color_stride, (uint8_t *)ctx->target.depth,
                         ctx->target.depth_stride);
        return;
    }
    if (tp != NULL) {
        while (zl_tri_row_ex(t, g, tp, &ctx->style, ss, color_row(&ctx->target, t->row),
                             depth_row(&ctx->target, t->row)))
            ;
        return;
    }
    while (zl_tri_row(t, g, ss, color_row(&ctx->target, t->row), depth_row(&ctx->target, t->row)))
        ;
}

/* Whether a filled polygon has a piece that survives culling and bounds, so
 * culled triangles skip shading. Line and point modes always go on. */
static int may_draw(const zl_source *src, const zl_style *sty, const zl_poly *poly)
{
    unsigned k;
    if (sty->polygon_front != ZL_POLY_FILL || sty->polygon_back != ZL_POLY_FILL)
        return 1;
    for (k = 1; k + 1 < poly->n; k++) {
        int32_t first, end;
        if (zl_tri_classify(&poly->v[0], &poly->v[k], &poly->v[k + 1], src->state, src->width, src->height,
                            &first, &end))
            return 1;
    }
    return 0;
}

/* Set up and draw every piece of a triangle's polygon. Out of line, so its
 * records are not on the stack of the clipping path. */
static ZL_NOINLINE void draw_pieces(const zl_context *ctx, const zl_source *src, uint32_t t, const zl_poly *poly,
                                    const zl_span_state *ss)
{
    unsigned k, n = zl_tri_pieces(src, &ctx->style, t, poly);
    for (k = 0; k < n; k++) {
        zl_active tri;
        zl_gouraud g;
        zl_texplanes tp;
        if (zl_tri_piece(src, &ctx->style, t, poly, k, &tri, &g, &tp))
            draw_rows(ctx, &tri, &g, zl_style_planes(&ctx->style) ? &tp : NULL, ss);
    }
}

/* Whether every triangle of a draw is a plain flat-shaded fill: no polygon
 * modes, offset, toon bands, texture or perspective planes. Then a triangle
 * whose vertices are all cached inside the clip volume can skip the general
 * polygon path (draw_cached). */
static int plain_flat(const zl_context *ctx)
{
    const zl_style *sty = &ctx->style;
    return ctx->state.shading == ZL_SHADE_FLAT && sty->polygon_front == ZL_POLY_FILL &&
           sty->polygon_back == ZL_POLY_FILL && sty->offset_factor == 0 && sty->offset_units == 0 &&
           sty->toon_bands == 0 && !zl_style_planes(sty);
}

/* Whether every triangle of a draw is a plain Gouraud fill with the vertex
 * colours as they are: plain_flat's style, light off, vertex colours given.
 * Then a cached triangle inside the clip volume can skip the general
 * polygon path too (draw_plain_gouraud). */
static int plain_gouraud(const zl_context *ctx, const zl_mesh *mesh)
{
    const zl_style *sty = &ctx->style;
    return ctx->state.shading == ZL_SHADE_GOURAUD && !ctx->state.light_on && mesh->vertex_colors != NULL &&
           sty->polygon_front == ZL_POLY_FILL && sty->polygon_back == ZL_POLY_FILL && sty->offset_factor == 0 &&
           sty->offset_units == 0 && sty->toon_bands == 0 && !zl_style_planes(sty);
}

/* Triangle t of any draw through the general path: polygon (clipped when
 * it must be), cull, shade, pieces. Out of line, so its big frame (a
 * textured polygon) is not on the stack of the fast loop. */
static ZL_NOINLINE void draw_general(const zl_context *ctx, const zl_source *src, uint32_t t, const zl_span_state *ss,
                                     int planes)
{
    zl_tpoly tpoly; /* the texture attributes are only filled when the style needs them */
    zl_poly *poly = &tpoly.p;
    if (!(planes ? zl_tri_polygon_tex(src, &ctx->style, t, &tpoly) : zl_tri_polygon_geom(src, &ctx->style, t, poly)) ||
        !may_draw(src, &ctx->style, poly))
        return;
    zl_tri_shade(src, t, poly);
    draw_pieces(ctx, src, t, poly, ss);
}

/*
 * A visible triangle of a plain flat draw from the vertex cache (the caller
 * culled it): the same record as zl_tri_polygon_geom + may_draw +
 * zl_tri_shade + zl_tri_piece give (one piece, no offset, the lit flat
 * colour), classified once. With `tiny` (zl_tiny_span_state) a small
 * triangle needs no record at all.
 */
/*
 * A visible triangle of a plain Gouraud draw from the vertex cache (the
 * caller culled it): a small one set up and drawn without a record
 * (zl_tiny_gouraud_setup, the same planes and pixels as the general path).
 * 0 for any other: the caller's caller takes it through the general path,
 * so that path's stack is not added to this one's.
 */
static ZL_ALWAYS_INLINE int draw_visible_gouraud(const zl_context *ctx, const zl_source *src, uint32_t t,
                                                 const zl_span_state *ss, const zl_cached_vertex *const *c, int tiny)
{
    if (tiny) {
        const uint16_t *idx = src->mesh->indices + t * 3u;
        const uint8_t *vc = src->mesh->vertex_colors, *col[3];
        zl_tiny_gouraud tg;
        int set;
        col[0] = vc + ZL_MESH_IDX(idx, 0) * 3u;
        col[1] = vc + ZL_MESH_IDX(idx, 1) * 3u;
        col[2] = vc + ZL_MESH_IDX(idx, 2) * 3u;
        set = zl_tiny_gouraud_setup(&tg, c, col, src->height);
        if (set > 0)
            zl_tiny_gouraud_draw(&tg, ss, (uint8_t *)ctx->target.color, ctx->target.color_stride,
                                 (uint8_t *)ctx->target.depth, ctx->target.depth_stride);
        return set >= 0;
    }
    return 0;
}

static ZL_ALWAYS_INLINE void draw_visible(const zl_context *ctx, const zl_source *src, uint32_t t, const zl_span_state *ss,
                                     const zl_cached_vertex *const *c, int tiny, const int32_t *lq)
{
    zl_poly poly;
    zl_active tri;
    int set;
    poly.n = 0; /* flat: no vertex colours for the lighting to scale */
    if (tiny) {
        zl_tiny tt;
        set = zl_tiny_setup(&tt, c[0], c[1], c[2], src->width, src->height);
        if (set == 0)
            return;
        if (set > 0) {
            zl_tiny_draw(&tt, ss, (uint8_t *)ctx->target.color, ctx->target.color_stride, (uint8_t *)ctx->target.depth,
                         ctx->target.depth_stride, zl_tri_pixel565_lit(src, t, lq));
            return;
        }
    }
    if (!zl_tri_setup_flat(&tri, c[0], c[1], c[2], &ctx->state, src->width, src->height))
        return;
    zl_tri_shade_lit(src, t, &poly, lq);
    tri.rgb[0] = poly.flat.r;
    tri.rgb[1] = poly.flat.g;
    tri.rgb[2] = poly.flat.b;
    tri.light = poly.light;
    draw_rows(ctx, &tri, NULL, NULL, ss);
}

static int culled_area_sign(const zl_state *st);

/*
 * zl_draw_mesh's post-transform cache in the caller's ctx->draw_cache
 * (no vertex cache): slot i & (ZL_DRAW_CACHE_SLOTS - 1) holds the window vertex of
 * vertex i when its tag is i. The bunny's triangles reuse a vertex far
 * apart (median index spread in a triangle: 333), so a direct-mapped cache
 * of 1024 slots misses 24 % of its 11022 lookups (256 slots: 45 %); each
 * miss is one zl_vx_vertex.
 */
typedef struct {
    zl_cached_vertex *v;
    uint16_t *tag;
    const zl_vx *vx;
} small_cache;

#if ZL_DRAW_CACHE_SLOTS > 0
/* Vertex i through the small cache, copied to *out: a later vertex of the
 * same triangle may take its slot. */
static ZL_ALWAYS_INLINE void small_fetch(const zl_source *src, const small_cache *sc, uint16_t i,
                                         zl_cached_vertex *out)
{
    unsigned slot = i & (ZL_DRAW_CACHE_SLOTS - 1u);
    if (sc->tag[slot] != i) {
        zl_vx_vertex(src, sc->vx, i, &sc->v[slot]);
        sc->tag[slot] = i;
    }
    *out = sc->v[slot];
}
#endif

/*
 * The triangles from t on of a plain flat draw with the vertex cache (or,
 * with sc, the small cache), or with `gouraud` of a plain Gouraud draw,
 * up to the first that needs the general path (a vertex to clip; for
 * Gouraud also a triangle draw_visible_gouraud leaves to it): returns its
 * index, or the triangle count. Most culled
 * triangles end in this loop, before any copy: zl_tri_classify's area test
 * on the cached int16 coordinates (the products fit 64 bits). A triangle
 * with an invalid vertex is dropped, as zl_tri_polygon_geom drops it. The
 * caller runs the general path, so its stack is not added to this loop's.
 */
static ZL_ALWAYS_INLINE uint32_t draw_plain_body(const zl_context *ctx, const zl_source *src, const zl_span_state *ss,
                                                 uint32_t t, int cull_sign, int tiny, const small_cache *sc,
                                                 int gouraud)
{
    int32_t lq[3];
    const uint16_t *idx;
    const zl_cached_vertex *cache = src->cache;
    uint32_t n = src->mesh->triangle_count, flip = cull_sign < 0 ? 0xFFFFFFFFu : 0u;
    (void)sc;
    /* A mesh without triangles may have no index array: no pointer
     * arithmetic on NULL, even by zero (undefined; clang's UBSan says so). */
    if (t >= n)
        return n;
    idx = src->mesh->indices + t * 3u;
    zl_light_prepare(&ctx->state, lq);
    for (; t < n; t++, idx += 3) {
        const zl_cached_vertex *c[3];
        int32_t x0, x1, x2, y0;
        int64_t area;
#if ZL_DRAW_CACHE_SLOTS > 0
        zl_cached_vertex v[3];
        if (sc != NULL) {
            small_fetch(src, sc, ZL_MESH_IDX(idx, 0), &v[0]);
            small_fetch(src, sc, ZL_MESH_IDX(idx, 1), &v[1]);
            small_fetch(src, sc, ZL_MESH_IDX(idx, 2), &v[2]);
            c[0] = &v[0];
            c[1] = &v[1];
            c[2] = &v[2];
        } else
#endif
        {
            c[0] = cache + ZL_MESH_IDX(idx, 0);
            c[1] = cache + ZL_MESH_IDX(idx, 1);
            c[2] = cache + ZL_MESH_IDX(idx, 2);
        }
        x0 = c[0]->x;
        x1 = c[1]->x;
        x2 = c[2]->x;
        if (x0 <= ZL_CACHE_INVALID || x1 <= ZL_CACHE_INVALID || x2 <= ZL_CACHE_INVALID) {
            if (x0 != ZL_CACHE_INVALID && x1 != ZL_CACHE_INVALID && x2 != ZL_CACHE_INVALID)
                return t;
            continue;
        }
        y0 = c[0]->y;
#if ZL_MUL32_ONLY
        /* no 64-bit multiply: the area in 32 bits where it is exact there */
        if (zl_area_fits32(x1 - x0, c[2]->y - y0, x2 - x0, c[1]->y - y0))
            area = (x1 - x0) * (c[2]->y - y0) - (x2 - x0) * (c[1]->y - y0);
        else
#endif
            area = (int64_t)(x1 - x0) * (c[2]->y - y0) - (int64_t)(x2 - x0) * (c[1]->y - y0);
        /* culled: the area's sign is cull_sign; for a non-zero area that is
         * its high word's sign bit against flip's */
        if (area == 0 || (cull_sign != 0 && (((uint32_t)((uint64_t)area >> 32) ^ flip) >> 31) == 0))
            continue;
        if (!gouraud)
            draw_visible(ctx, src, t, ss, c, tiny, lq);
        else if (!draw_visible_gouraud(ctx, src, t, ss, c, tiny))
            return t;
    }
    return n;
}

static uint32_t draw_plain(const zl_context *ctx, const zl_source *src, const zl_span_state *ss, uint32_t t,
                           int cull_sign, int tiny)
{
    return draw_plain_body(ctx, src, ss, t, cull_sign, tiny, NULL, 0);
}

/* draw_plain for a plain Gouraud draw (plain_gouraud). */
static uint32_t draw_plain_gouraud(const zl_context *ctx, const zl_source *src, const zl_span_state *ss, uint32_t t,
                                   int cull_sign, int tiny)
{
    return draw_plain_body(ctx, src, ss, t, cull_sign, tiny, NULL, 1);
}

#if ZL_DRAW_CACHE_SLOTS > 0
static uint32_t draw_plain_small(const zl_context *ctx, const zl_source *src, const zl_span_state *ss, uint32_t t,
                                 int cull_sign, int tiny, const small_cache *sc)
{
    return draw_plain_body(ctx, src, ss, t, cull_sign, tiny, sc, 0);
}

/* draw_plain_small for a plain Gouraud draw (plain_gouraud). */
static uint32_t draw_plain_small_gouraud(const zl_context *ctx, const zl_source *src, const zl_span_state *ss,
                                         uint32_t t, int cull_sign, int tiny, const small_cache *sc)
{
    return draw_plain_body(ctx, src, ss, t, cull_sign, tiny, sc, 1);
}

/* A plain flat draw (or, with `gouraud`, a plain Gouraud draw) without the
 * vertex cache, through ctx->draw_cache: the set-up vx, the slots' vertices,
 * their tags. */
static void draw_small(zl_context *ctx, const zl_source *src, const zl_span_state *ss, const zl_vx *vx, int gouraud)
{
    small_cache sc;
    uint32_t t, n = src->mesh->triangle_count;
    int cull_sign = culled_area_sign(&ctx->state);
    int tiny = zl_tiny_span_state(ss, ctx->target.color, ctx->target.color_stride, ctx->target.depth);
    unsigned k;
    sc.v = (zl_cached_vertex *)(void *)((uint8_t *)ctx->draw_cache + ZL_DRAW_CACHE_SETUP_BYTES);
    sc.tag = (uint16_t *)(void *)((uint8_t *)ctx->draw_cache + ZL_DRAW_CACHE_SETUP_BYTES +
                                  (size_t)ZL_DRAW_CACHE_SLOTS * sizeof(zl_cached_vertex));
    sc.vx = vx;
    for (k = 0; k < ZL_DRAW_CACHE_SLOTS; k++)
        sc.tag[k] = (uint16_t)(k ^ 1u); /* never k's own index: every slot empty */
    if (gouraud) {
        for (t = draw_plain_small_gouraud(ctx, src, ss, 0, cull_sign, tiny, &sc); t < n;
             t = draw_plain_small_gouraud(ctx, src, ss, t + 1, cull_sign, tiny, &sc))
            draw_general(ctx, src, t, ss, 0);
        return;
    }
    for (t = draw_plain_small(ctx, src, ss, 0, cull_sign, tiny, &sc); t < n;
         t = draw_plain_small(ctx, src, ss, t + 1, cull_sign, tiny, &sc))
        draw_general(ctx, src, t, ss, 0);
}

/* Whether the caller gave a draw cache this library can use. */
static int draw_cache_usable(const zl_context *ctx)
{
    return ctx->draw_cache != NULL && ((uintptr_t)ctx->draw_cache & 7u) == 0 &&
           ctx->draw_cache_bytes >= ZL_DRAW_CACHE_BYTES(ZL_DRAW_CACHE_SLOTS);
}
#endif

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

/* The checks every draw call starts with: context, target, state, style. */
static zl_status check_context(const zl_context *ctx)
{
    zl_status st;
    if (ctx == NULL)
        return ZL_ERR_ARG;
    st = check_target(&ctx->target);
    if (st == ZL_OK)
        st = zl_state_check(&ctx->state);
    if (st == ZL_OK)
        st = zl_style_check(&ctx->style);
    return st;
}

/* A draw's vertex source: the context's state and target, no cache. */
static void source_init(zl_source *src, const zl_context *ctx, const zl_mesh *mesh, const zl_mat4 *mvp)
{
    src->mesh = mesh;
    src->mvp = mvp;
    src->state = &ctx->state;
    src->cache = NULL;
    src->width = ctx->target.width;
    src->height = ctx->target.height;
}

zl_status zl_draw_mesh(zl_context *ctx, const zl_mesh *mesh, const zl_mat4 *mvp)
{
    zl_source src;
    zl_span_state ss;
    zl_status st;
    uint32_t t;
    int planes;
    st = check_context(ctx);
    if (st == ZL_OK)
        st = zl_check_mesh(mesh, mvp == NULL);
    if (st != ZL_OK)
        return st;
    source_init(&src, ctx, mesh, mvp);
    if (ctx->vertex_cache != NULL && ((uintptr_t)ctx->vertex_cache & 3u) == 0 &&
        ctx->vertex_cache_bytes >= ZL_VERTEX_CACHE_BYTES(mesh->vertex_count)) {
        /* Transform each vertex once; triangles read the cache exactly as
         * scanline mode does, so the pixels do not change. Filling it
         * answers zl_check_positions too (zl_cache_vertices), before any
         * pixel is drawn. */
        st = zl_cache_vertices(&src, (zl_cached_vertex *)ctx->vertex_cache, 0, mesh->vertex_count);
        src.cache = (zl_cached_vertex *)ctx->vertex_cache;
    } else {
        st = zl_check_positions(mesh->positions, mesh->vertex_count, mvp);
    }
    if (st != ZL_OK)
        return st;
    zl_span_state_init(&ss, &ctx->state, ctx->target.depth != NULL, ctx->target.color != NULL,
                       (zl_format)ctx->target.format, ctx->target.width);
    planes = zl_style_planes(&ctx->style);
#if ZL_DRAW_CACHE_SLOTS > 0
    if (src.cache == NULL && draw_cache_usable(ctx)) {
        int flat = plain_flat(ctx);
        /* the set-up in the draw cache, not on the stack of the general path */
        zl_vx *vx = (zl_vx *)ctx->draw_cache;
        if ((flat || plain_gouraud(ctx, mesh)) && zl_vx_prepare(&src, vx)) {
            draw_small(ctx, &src, &ss, vx, !flat);
            return ZL_OK;
        }
    }
#endif
    if (ZL_FAST_PATHS && src.cache != NULL && plain_flat(ctx)) { /* (off: draw_general, the same pixels) */
        int cull_sign = culled_area_sign(&ctx->state);
        int tiny = zl_tiny_span_state(&ss, ctx->target.color, ctx->target.color_stride, ctx->target.depth);
        for (t = draw_plain(ctx, &src, &ss, 0, cull_sign, tiny); t < mesh->triangle_count;
             t = draw_plain(ctx, &src, &ss, t + 1, cull_sign, tiny))
            draw_general(ctx, &src, t, &ss, 0);
        return ZL_OK;
    }
    if (ZL_FAST_PATHS && src.cache != NULL && plain_gouraud(ctx, mesh)) {
        int cull_sign = culled_area_sign(&ctx->state);
        int tiny = zl_tiny_span_state(&ss, ctx->target.color, ctx->target.color_stride, ctx->target.depth);
        for (t = draw_plain_gouraud(ctx, &src, &ss, 0, cull_sign, tiny); t < mesh->triangle_count;
             t = draw_plain_gouraud(ctx, &src, &ss, t + 1, cull_sign, tiny))
            draw_general(ctx, &src, t, &ss, 0);
        return ZL_OK;
    }
    for (t = 0; t < mesh->triangle_count; t++)
        draw_general(ctx, &src, t, &ss, planes);
    return ZL_OK;
}

zl_status zl_draw_outlines(zl_context *ctx, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_outline *outline)
{
    zl_source src;
    zl_span_state ss;
    zl_status st;
    uint32_t k;
    st = check_context(ctx);
    if (st == ZL_OK)
        st = zl_check_mesh(mesh, mvp == NULL);
    if (st == ZL_OK)
        st = zl_check_outline(mesh, outline);
    if (st != ZL_OK || !ZL_FEATURE_OUTLINES) /* compiled out (zl_config.h): zl_check_outline said so */
        return st;
    source_init(&src, ctx, mesh, mvp);
    zl_span_state_init(&ss, &ctx->state, ctx->target.depth != NULL, ctx->target.color != NULL,
                       (zl_format)ctx->target.format, ctx->target.width);
    for (k = 0; k < outline->edge_count; k++) {
        zl_active rec;
        if (zl_outline_record(&src, mesh, outline, &ctx->style, k, &rec))
            draw_rows(ctx, &rec, NULL, NULL, &ss);
    }
    return ZL_OK;
}

zl_status zl_draw_lines(zl_context *ctx, const zl_lines *lines, const zl_mat4 *mvp)
{
    zl_source src;
    zl_span_state ss;
    zl_status st;
    zl_mesh m;
    uint32_t k, n;
    st = check_context(ctx);
    if (st == ZL_OK)
        st = zl_check_lines(lines);
    if (st == ZL_OK) /* the transform limits (LIMITS in zline.h) */
        st = zl_check_positions(lines->positions, lines->vertex_count, mvp);
    if (st != ZL_OK || !ZL_FEATURE_LINES) /* compiled out (zl_config.h): zl_check_lines said so */
        return st;
    zl_lines_mesh(lines, &m);
    src.mesh = &m;
    src.mvp = mvp;
    src.state = &ctx->state;
    src.cache = NULL;
    src.width = ctx->target.width;
    src.height = ctx->target.height;
    zl_span_state_init(&ss, &ctx->state, ctx->target.depth != NULL, ctx->target.color != NULL,
                       (zl_format)ctx->target.format, ctx->target.width);
    n = zl_lines_primitives(lines);
    for (k = 0; k < n; k++) {
        zl_active rec;
        if (zl_lines_record(&src, lines, &ctx->style, &ctx->state, k, &rec))
            draw_rows(ctx, &rec, NULL, NULL, &ss);
    }
    return ZL_OK;
}
