/* SPDX-License-Identifier: MIT */
/*
 * Stage 6, visibility: the scene of the visibility methods: work-buffer layout, mesh submission,
 * planning, and the helpers the methods share.
 *
 * Planning follows zl_frame: every vertex is transformed once into the
 * vertex cache; every triangle goes through zl_tri_polygon (transform, clip,
 * project, snap) and its fan pieces through the classification of the
 * method (zl_tri_classify for the AET and painter's, the ray caster's own
 * for the oracle); a difference array over rows bounds the pieces active at
 * once, so capacity errors come before any output; the row methods then
 * bucket the kept triangle ids by first row (the edge table) with a counting
 * sort, the painter's method records each one's sort key.
 */
#include <string.h>

#include "zl_vis_internal.h"

typedef struct {
    size_t vcache, visible, row_start, keys, pool, edges, act, free_slots, flags, inset, color, ids,
        gap, total;
} layout;

/* The layout is summed in 32 bits, which hold every configuration's total:
 * where size_t has 16 bits (AVR) a size_t sum would wrap, and a buffer of the
 * wrapped size would pass zl_vis_begin with regions overlapping. */
static uint32_t align8_32(uint32_t n)
{
    return (n + 7u) & ~UINT32_C(7);
}

/* A total beyond SIZE_MAX is refused: no buffer of that size can exist. */
static int fits_size_t(uint32_t total)
{
#if SIZE_MAX < UINT32_MAX
    return total <= SIZE_MAX;
#else
    (void)total;
    return 1;
#endif
}

static int layout_of(const zl_vis_config *c, layout *l)
{
    uint32_t bpp = (uint32_t)zl_format_bytes((zl_format)c->format), pool = 0, diff, at;
    int rows = c->algorithm == ZL_VIS_AET || c->algorithm == ZL_VIS_RAYCAST;
    if (c->width < 1 || c->height < 1 || c->width > ZL_MAX_DIM || c->height > ZL_MAX_DIM || bpp == 0 ||
        c->algorithm < ZL_VIS_AET || c->algorithm > ZL_VIS_RAYCAST || c->max_meshes < 1 || c->max_meshes > 255 ||
        c->max_triangles > 65535 || c->max_vertices > UINT32_C(65535) * 255u || (rows && (c->max_active < 1 || c->max_active > 65534)))
        return 0;
    memset(l, 0, sizeof *l);
    diff = ((uint32_t)c->height + 1) * (uint32_t)sizeof(int32_t);
    if (c->algorithm == ZL_VIS_AET)
        pool = (uint32_t)c->max_active * (uint32_t)sizeof(zl_active);
    else if (c->algorithm == ZL_VIS_RAYCAST)
        pool = (uint32_t)c->max_active * (uint32_t)sizeof(zl_vis_rtri);
    if (rows && pool < diff)
        pool = diff; /* planning borrows the pool for its difference array */
    at = align8_32((uint32_t)c->max_meshes * (uint32_t)sizeof(zl_vis_mesh));
    l->vcache = (size_t)at;
    at += align8_32((uint32_t)c->max_vertices * (uint32_t)sizeof(zl_cached_vertex));
    l->visible = (size_t)at;
    at += align8_32((uint32_t)c->max_triangles * (uint32_t)sizeof(uint16_t));
    if (c->algorithm == ZL_VIS_PAINTER) {
        l->keys = (size_t)at;
        at += align8_32((uint32_t)c->max_triangles * (uint32_t)sizeof(uint32_t));
        l->total = (size_t)at;
        return fits_size_t(at);
    }
    l->row_start = (size_t)at;
    at += align8_32(((uint32_t)c->height + 1) * (uint32_t)sizeof(uint16_t));
    l->pool = (size_t)at;
    at += align8_32(pool);
    if (c->algorithm == ZL_VIS_AET) {
        l->edges = (size_t)at;
        at += align8_32((uint32_t)c->max_active * 2 * (uint32_t)sizeof(zl_vis_edge));
        l->act = (size_t)at;
        at += align8_32((uint32_t)c->max_active * (uint32_t)sizeof(uint16_t));
        l->free_slots = (size_t)at;
        at += align8_32((uint32_t)c->max_active * (uint32_t)sizeof(uint16_t));
        l->inset = (size_t)at;
        at += align8_32((uint32_t)c->max_active * (uint32_t)sizeof(uint16_t));
        l->flags = (size_t)at;
        at += align8_32((uint32_t)c->max_active);
    }
    l->ids = (size_t)at;
    at += align8_32((uint32_t)c->width * (uint32_t)sizeof(uint16_t));
    if (c->algorithm == ZL_VIS_RAYCAST) {
        l->gap = (size_t)at;
        at += align8_32((uint32_t)c->width * (uint32_t)sizeof(uint16_t));
    }
    l->color = (size_t)at;
    at += align8_32((uint32_t)c->width * bpp);
    l->total = (size_t)at;
    return fits_size_t(at);
}

size_t zl_vis_bytes(const zl_vis_config *cfg)
{
    layout l;
    if (cfg == NULL || !layout_of(cfg, &l))
        return 0;
    return l.total;
}

zl_status zl_vis_begin(zl_vis *v, const zl_vis_config *cfg, void *work, size_t work_bytes)
{
    layout l;
    uint8_t *w = work;
    if (v == NULL || cfg == NULL || work == NULL || ((uintptr_t)work & 7u) != 0)
        return ZL_ERR_ARG;
    if (!layout_of(cfg, &l))
        return ZL_ERR_SIZE;
    if (work_bytes < l.total)
        return ZL_ERR_SIZE;
    memset(v, 0, sizeof *v);
    v->cfg = *cfg;
    v->meshes = (zl_vis_mesh *)(void *)w;
    v->vcache = w + l.vcache;
    v->visible = (uint16_t *)(void *)(w + l.visible);
    if (cfg->algorithm == ZL_VIS_PAINTER) {
        v->keys = (uint32_t *)(void *)(w + l.keys);
        return ZL_OK;
    }
    v->row_start = (uint16_t *)(void *)(w + l.row_start);
    v->pool = w + l.pool;
    if (cfg->algorithm == ZL_VIS_AET) {
        v->edges = w + l.edges;
        v->act = (uint16_t *)(void *)(w + l.act);
        v->free_slots = (uint16_t *)(void *)(w + l.free_slots);
        v->inset = (uint16_t *)(void *)(w + l.inset);
        v->flags = w + l.flags;
    } else {
        v->gap_row = (uint16_t *)(void *)(w + l.gap);
    }
    v->id_row = (uint16_t *)(void *)(w + l.ids);
    v->color_row = w + l.color;
    return ZL_OK;
}

zl_status zl_vis_add_mesh(zl_vis *v, const zl_mesh *mesh, const zl_mat4 *mvp, const zl_state *state)
{
    zl_vis_mesh *m;
    zl_status st;
    if (v == NULL || state == NULL || v->planned)
        return ZL_ERR_ARG;
    st = zl_check_geometry(mesh, mvp);
    if (st == ZL_OK)
        st = zl_state_check(state);
    if (st != ZL_OK)
        return st;
    if (v->mesh_count >= v->cfg.max_meshes || v->vertex_count + mesh->vertex_count > v->cfg.max_vertices ||
        v->triangle_total + mesh->triangle_count > 65535u)
        return ZL_ERR_CAPACITY;
    m = &v->meshes[v->mesh_count];
    m->mesh = *mesh;
    m->has_mvp = mvp != NULL;
    if (mvp != NULL)
        m->mvp = *mvp;
    m->state = *state;
    m->tri_base = v->triangle_total;
    m->vert_base = v->vertex_count;
    v->mesh_count++;
    v->vertex_count += mesh->vertex_count;
    v->triangle_total += mesh->triangle_count;
    return ZL_OK;
}

zl_frame_needs_t zl_vis_needs(const zl_vis *v)
{
    zl_frame_needs_t none = {0, 0, 0};
    return v ? v->needs : none;
}

static zl_cached_vertex *cache_of(const zl_vis *v)
{
    return (zl_cached_vertex *)v->vcache;
}

static void source_of(const zl_vis *v, const zl_vis_mesh *m, zl_source *s)
{
    s->mesh = &m->mesh;
    s->mvp = m->has_mvp ? &m->mvp : NULL;
    s->state = &m->state;
    s->cache = cache_of(v) + m->vert_base;
    s->width = v->cfg.width;
    s->height = v->cfg.height;
}

unsigned zl_vis_mesh_of(const zl_vis *v, uint16_t id)
{
    unsigned mi = 0;
    while (mi + 1u < v->mesh_count && id >= v->meshes[mi + 1u].tri_base)
        mi++;
    return mi;
}

unsigned zl_vis_source(const zl_vis *v, uint16_t id, zl_source *s, uint32_t *t)
{
    unsigned mi = zl_vis_mesh_of(v, id);
    source_of(v, &v->meshes[mi], s);
    *t = id - v->meshes[mi].tri_base;
    return mi;
}

/* Kept pieces of triangle t, their row range and farthest vertex depth. */
static unsigned classify(const zl_vis *v, const zl_vis_mesh *m, uint32_t t, int32_t *first, int32_t *end,
                         uint32_t *zfar)
{
    zl_source s;
    zl_poly poly;
    unsigned k, pieces = 0;
    source_of(v, m, &s);
    if (!zl_tri_polygon(&s, t, &poly))
        return 0;
    *first = INT16_MAX;
    *end = 0;
    *zfar = 0;
    for (k = 1; k + 1 < poly.n; k++) {
        int32_t a, b;
        if (v->cfg.algorithm == ZL_VIS_RAYCAST) {
            zl_vis_rtri r;
            if (!zl_vis_rtri_init(&r, &poly.v[0], &poly.v[k], &poly.v[k + 1], &m->state, v->cfg.width,
                                  v->cfg.height, &a))
                continue;
            b = r.end;
        } else if (!zl_tri_classify(&poly.v[0], &poly.v[k], &poly.v[k + 1], &m->state, v->cfg.width,
                                    v->cfg.height, &a, &b)) {
            continue;
        }
        pieces++;
        if (a < *first)
            *first = a;
        if (b > *end)
            *end = b;
    }
    if (pieces != 0)
        for (k = 0; k < poly.n; k++)
            if (poly.v[k].z > *zfar)
                *zfar = poly.v[k].z;
    return pieces;
}

/* One pass over all triangles. place = 0: count first rows and add pieces to
 * the difference array (row methods), or store ids and keys (painter's);
 * place = 1: put the ids into their buckets. */
static uint32_t scene_pass(zl_vis *v, int32_t *diff, int place)
{
    uint32_t kept = 0;
    uint16_t mi;
    for (mi = 0; mi < v->mesh_count; mi++) {
        const zl_vis_mesh *m = &v->meshes[mi];
        uint32_t t;
        for (t = 0; t < m->mesh.triangle_count; t++) {
            int32_t first, end;
            uint32_t zfar;
            uint16_t id = (uint16_t)(m->tri_base + t);
            unsigned pieces = classify(v, m, t, &first, &end, &zfar);
            if (pieces == 0)
                continue;
            if (v->cfg.algorithm == ZL_VIS_PAINTER) {
                if (kept < v->cfg.max_triangles) {
                    v->visible[kept] = id;
                    v->keys[kept] = zfar;
                }
            } else if (place) {
                v->visible[v->row_start[first]++] = id;
            } else {
                v->row_start[first]++;
                diff[first] += (int32_t)pieces;
                diff[end] -= (int32_t)pieces;
            }
            kept++;
        }
    }
    return kept;
}

zl_status zl_vis_plan(zl_vis *v)
{
    uint16_t mi, j, h = v->cfg.height;
    int32_t *diff;
    uint32_t running = 0, peak = 0, start = 0;
    if (v->planned)
        return ZL_ERR_ARG; /* a scene renders once */
    v->planned = 1;
    for (mi = 0; mi < v->mesh_count; mi++) {
        const zl_vis_mesh *m = &v->meshes[mi];
        zl_source s;
        uint16_t k;
        source_of(v, m, &s);
        for (k = 0; k < m->mesh.vertex_count; k++)
            cache_of(v)[m->vert_base + k] = zl_cache_vertex(&s, k);
    }
    if (v->cfg.algorithm == ZL_VIS_PAINTER) {
        v->needs.triangles = scene_pass(v, NULL, 0);
        v->needs.active = 0;
        return v->needs.triangles > v->cfg.max_triangles ? ZL_ERR_CAPACITY : ZL_OK;
    }
    diff = (int32_t *)v->pool;
    memset(v->row_start, 0, ((size_t)h + 1) * sizeof(uint16_t));
    memset(diff, 0, ((size_t)h + 1) * sizeof(int32_t));
    v->needs.triangles = scene_pass(v, diff, 0);
    for (j = 0; j < h; j++) {
        running += (uint32_t)diff[j];
        if (running > peak)
            peak = running;
    }
    v->needs.active = peak;
    if (v->needs.triangles > v->cfg.max_triangles || v->needs.active > v->cfg.max_active)
        return ZL_ERR_CAPACITY;
    for (j = 0; j <= h; j++) {
        uint16_t n = v->row_start[j];
        v->row_start[j] = (uint16_t)start;
        start += n;
    }
    scene_pass(v, NULL, 1);
    return ZL_OK;
}

/* ---------------------------------------------------------------- helpers */

void zl_vis_pack(zl_format f, const uint8_t *rgb, uint8_t out[3])
{
    if (f == ZL_FORMAT_RGB888) {
        out[0] = rgb[0];
        out[1] = rgb[1];
        out[2] = rgb[2];
    } else {
        uint16_t px = (uint16_t)(((unsigned)(rgb[0] >> 3) << 11) | ((unsigned)(rgb[1] >> 2) << 5) | (unsigned)(rgb[2] >> 3));
        if (f == ZL_FORMAT_RGB565_BE) {
            out[0] = (uint8_t)(px >> 8);
            out[1] = (uint8_t)(px & 0xFFu);
        } else {
            memcpy(out, &px, 2); /* native byte order */
        }
        out[2] = 0;
    }
}

void zl_vis_fill(uint8_t *row, unsigned bpp, const uint8_t *pix, int32_t n)
{
    int32_t i;
    if (bpp == 2) {
        uint16_t px, *p = (uint16_t *)(void *)row;
        memcpy(&px, pix, 2);
        for (i = 0; i < n; i++)
            p[i] = px;
    } else {
        for (i = 0; i < n; i++) {
            row[i * 3] = pix[0];
            row[i * 3 + 1] = pix[1];
            row[i * 3 + 2] = pix[2];
        }
    }
}

static void edge_step(zl_edge *e)
{
    e->x += e->step;
    e->rem -= e->rstep;
    if (e->rem < 0) {
        e->rem += e->den;
        e->x += 1;
    }
}

int zl_vis_step(zl_active *t, int with_z)
{
    edge_step(&t->left);
    edge_step(&t->right);
    if (with_z)
        t->z.row += t->z.dy;
    t->row++;
    if (t->row == t->mid && t->row < t->end) {
        if (t->lower_is_left)
            t->left = t->lower;
        else
            t->right = t->lower;
    }
    return t->row < t->end;
}

zl_status zl_vis_check_target(const zl_vis_target *t)
{
    unsigned bpp;
    if (t == NULL)
        return ZL_ERR_ARG;
    if (t->width < 1 || t->height < 1 || t->width > ZL_MAX_DIM || t->height > ZL_MAX_DIM)
        return ZL_ERR_SIZE;
    bpp = zl_format_bytes((zl_format)t->format);
    if (bpp == 0)
        return ZL_ERR_ARG;
    if (t->color != NULL) {
        if (t->color_stride < (int32_t)(t->width * bpp))
            return ZL_ERR_SIZE;
        if (bpp == 2 && ((((uintptr_t)t->color) & 1u) || (t->color_stride & 1)))
            return ZL_ERR_ARG;
    }
    if (t->ids != NULL) {
        if (t->ids_stride < (int32_t)t->width * 2 || (t->ids_stride & 1))
            return ZL_ERR_SIZE;
        if (((uintptr_t)t->ids) & 1u)
            return ZL_ERR_ARG;
    }
    return ZL_OK;
}

void zl_vis_clear_target(const zl_vis_target *t, zl_rgb clear)
{
    unsigned bpp = zl_format_bytes((zl_format)t->format);
    uint8_t rgb[3], pix[3];
    uint16_t y, x;
    rgb[0] = clear.r;
    rgb[1] = clear.g;
    rgb[2] = clear.b;
    zl_vis_pack((zl_format)t->format, rgb, pix);
    for (y = 0; y < t->height; y++) {
        if (t->color != NULL)
            zl_vis_fill((uint8_t *)t->color + (size_t)y * (size_t)t->color_stride, bpp, pix, t->width);
        if (t->ids != NULL) {
            uint16_t *r = (uint16_t *)(void *)((uint8_t *)t->ids + (size_t)y * (size_t)t->ids_stride);
            for (x = 0; x < t->width; x++)
                r[x] = ZL_VIS_NONE;
        }
    }
}

void zl_vis_draw_spans(zl_active *t, const zl_vis_target *tg, const uint8_t *pix, uint16_t id)
{
    unsigned bpp = zl_format_bytes((zl_format)tg->format);
    do {
        int32_t x0 = t->left.x < 0 ? 0 : t->left.x, x1 = t->right.x > tg->width ? tg->width : t->right.x;
        if (x0 < x1) {
            if (tg->color != NULL)
                zl_vis_fill((uint8_t *)tg->color + (size_t)t->row * (size_t)tg->color_stride + (size_t)x0 * bpp, bpp,
                            pix, x1 - x0);
            if (tg->ids != NULL) {
                uint16_t *r = (uint16_t *)(void *)((uint8_t *)tg->ids + (size_t)t->row * (size_t)tg->ids_stride);
                int32_t i;
                for (i = x0; i < x1; i++)
                    r[i] = id;
            }
        }
    } while (zl_vis_step(t, 0));
}
