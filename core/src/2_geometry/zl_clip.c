/* SPDX-License-Identifier: MIT */
/*
 * Stage 2, geometry: clipping. A triangle whose vertices are not all inside
 * is clipped one plane at a time (Sutherland-Hodgman, in homogeneous clip
 * space) and its polygon projected and snapped (zl_vertex.c); with texture
 * coordinates carried through; the lit colour from zl_light.c; line segments
 * and points clipped the same way. The output of stage 2 is a convex polygon
 * in window space, the input of the raster stage.
 */
#include <stddef.h>
#include <string.h>

#include "zl_geometry.h"

static ZL_SMALL_NOINLINE int32_t lerp(int32_t a, int32_t b, int64_t t30)
{
    return (int32_t)(a + zl_floor_shift64(((int64_t)b - a) * t30 + ((int64_t)1 << 29), 30));
}

/*
 * The point where edge in -> out crosses the plane; din >= 0 > dout. The
 * parameter is always measured from the inside vertex, so the edge shared by
 * two triangles gives the same point in both: clipping stays watertight.
 */
static int64_t intersect(const zl_cvert *in, const zl_cvert *out, int64_t din, int64_t dout, unsigned plane,
                         zl_cvert *res)
{
    int64_t num = din, den = din - dout; /* den > 0, num < den */
    int64_t t;
    unsigned len = bit_length64((uint64_t)den);
    if (len > 32) {
        num = zl_floor_shift64(num, len - 32);
        den = zl_floor_shift64(den, len - 32);
    }
    t = den > 0 ? (num * ((int64_t)1 << 30)) / den : 0; /* Q30 in [0, 1] */
    res->x = lerp(in->x, out->x, t);
    res->y = lerp(in->y, out->y, t);
    res->z = lerp(in->z, out->z, t);
    res->w = lerp(in->w, out->w, t);
    /* between two colours: stays in 0 .. 255 * 256 */
    res->r = (uint16_t)lerp(in->r, out->r, t);
    res->g = (uint16_t)lerp(in->g, out->g, t);
    res->b = (uint16_t)lerp(in->b, out->b, t);
    res->zd = ZL_ZD_NONE; /* a vertex made here: depth z / w */
    /* Put the new vertex exactly on the planes whose equation is simple. */
    if (plane == PLANE_NEAR)
        res->z = 0;
    else if (plane == PLANE_FAR)
        res->z = res->w;
    else if (plane == PLANE_W && res->w < 1)
        res->w = 1;
    return t;
}

/* Clip polygon src (n vertices) against one plane into dst; returns the count. */
static unsigned clip_plane(const zl_source *s, unsigned plane, const zl_cvert *src, unsigned n,
                           zl_cvert *dst)
{
    unsigned i, m = 0;
    for (i = 0; i < n; i++) {
        const zl_cvert *a = &src[i], *b = &src[(i + 1) % n];
        int64_t da = plane_distance(s, plane, a), db = plane_distance(s, plane, b);
        if (da >= 0)
            dst[m++] = *a;
        if ((da >= 0) != (db >= 0)) {
            if (da >= 0)
                (void)intersect(a, b, da, db, plane, &dst[m++]);
            else
                (void)intersect(b, a, db, da, plane, &dst[m++]);
        }
    }
    return m;
}

/* All three vertices cached inside: the fast path of scanline mode. */
static int polygon_from_cache(const zl_source *s, const uint16_t *idx, zl_poly *out)
{
    unsigned k;
    for (k = 0; k < 3; k++) {
        const zl_cached_vertex *c = &s->cache[ZL_MESH_IDX(idx, k)];
        zl_wvert *w = &out->v[k];
        w->x = c->x;
        w->y = c->y;
        w->z = c->z;
        out->fx[k] = ZL_CV_FX(c);
        out->fy[k] = ZL_CV_FY(c);
        w->r = (uint16_t)color_q8(s->mesh, ZL_MESH_IDX(idx, k), 0);
        w->g = (uint16_t)color_q8(s->mesh, ZL_MESH_IDX(idx, k), 1);
        w->b = (uint16_t)color_q8(s->mesh, ZL_MESH_IDX(idx, k), 2);
    }
    out->n = 3;
    out->clipped = 0;
    return 1;
}

static int polygon_clipped(const zl_source *s, const uint16_t *idx, zl_poly *out)
{
    zl_cvert a[ZL_MAX_POLY], b[ZL_MAX_POLY];
    zl_cvert *src = a, *dst = b, *tmp;
    unsigned all_out = 0x7Fu, any_out = 0, plane, n = 3, k;
    for (k = 0; k < 3; k++) { /* the outcodes folded as they come: no array on this deep frame */
        unsigned code;
        if (!zl_vertex_clip(s, ZL_MESH_IDX(idx, k), &a[k]))
            return 0;
        code = zl_outcode(s, &a[k]);
        all_out &= code;
        any_out |= code;
    }
    if (all_out != 0)
        return 0;
    for (plane = 0; plane < PLANE_COUNT && n >= 3; plane++) {
        if (!(any_out & (1u << plane)))
            continue;
        n = clip_plane(s, plane, src, n, dst);
        tmp = src;
        src = dst;
        dst = tmp;
    }
    if (n < 3)
        return 0;
    for (k = 0; k < n; k++)
        zl_project(s, &src[k], &out->v[k]);
    out->n = (uint8_t)n; /* at most ZL_MAX_POLY */
    out->clipped = (uint8_t)any_out; /* the 7 plane bits: non-zero when clipped */
    return 1;
}

int zl_tri_polygon(const zl_source *s, uint32_t t, zl_poly *out)
{
    return zl_tri_polygon_ex(s, NULL, t, out);
}

/* The residuals of an unclipped triangle polygon_clipped made (the
 * unsnapped positions of its depth plane). Out of line: not on top of the
 * clipper's frame. */
static ZL_NOINLINE void poly_residuals(const zl_source *s, const uint16_t *idx, zl_poly *out)
{
    unsigned k;
    for (k = 0; k < 3; k++)
        zl_vertex_residuals(s, ZL_MESH_IDX(idx, k), &out->v[k], &out->fx[k], &out->fy[k]);
}

int zl_tri_polygon_geom(const zl_source *s, const zl_style *sty, uint32_t t, zl_poly *out)
{
    const uint16_t *idx = &s->mesh->indices[t * 3u];
    int ok;
    (void)sty;
    if (s->cache != NULL) {
        int16_t x0 = s->cache[ZL_MESH_IDX(idx, 0)].x, x1 = s->cache[ZL_MESH_IDX(idx, 1)].x,
                x2 = s->cache[ZL_MESH_IDX(idx, 2)].x;
        if (x0 == ZL_CACHE_INVALID || x1 == ZL_CACHE_INVALID || x2 == ZL_CACHE_INVALID)
            return 0;
        if (x0 != ZL_CACHE_COMPLEX && x1 != ZL_CACHE_COMPLEX && x2 != ZL_CACHE_COMPLEX)
            return polygon_from_cache(s, idx, out); /* the residuals from the cache */
    }
    ok = polygon_clipped(s, idx, out);
    if (ok && !out->clipped) {
        if (s->mvp != NULL && s->state != NULL && ZL_DEPTH_MAPPED(s->state))
            poly_residuals(s, idx, out);
        else /* no exact mapping: the snapped plane (zl_vertex_residuals' answer, without the calls) */
            out->fx[0] = out->fx[1] = out->fx[2] = ZL_FINE_NONE;
    }
    return ok;
}

/* ---------------------------------------- texture coordinates through clipping */

typedef struct {
    zl_cvert c;
    int32_t u, v; /* 1/256 texel */
} tcvert;

/* clip_plane with texture coordinates, interpolated with the parameter of
 * the very same intersection. */
static unsigned clip_plane_tex(const zl_source *s, unsigned plane, const tcvert *src, unsigned n, tcvert *dst)
{
    unsigned i, m = 0;
    for (i = 0; i < n; i++) {
        const tcvert *a = &src[i], *b = &src[(i + 1) % n];
        int64_t da = plane_distance(s, plane, &a->c), db = plane_distance(s, plane, &b->c);
        if (da >= 0)
            dst[m++] = *a;
        if ((da >= 0) != (db >= 0)) {
            const tcvert *in = da >= 0 ? a : b, *out = da >= 0 ? b : a;
            tcvert *r = &dst[m++];
            int64_t t = intersect(&in->c, &out->c, da >= 0 ? da : db, da >= 0 ? db : da, plane, &r->c);
            r->u = lerp(in->u, out->u, t);
            r->v = lerp(in->v, out->v, t);
        }
    }
    return m;
}

static int32_t w_of(const zl_source *s, int32_t w)
{
    return s->mvp != NULL ? (w < 1 ? 1 : w) : ZL_FX_ONE;
}

/* Clipped: the same steps as polygon_clipped, carrying u and v. Out of
 * line (as the next one): only one of the two big frames is ever live. */
static ZL_NOINLINE int tex_clipped(const zl_source *s, const zl_style *sty, const uint16_t *idx, zl_tpoly *out)
{
    tcvert a[ZL_MAX_POLY], b[ZL_MAX_POLY];
    tcvert *src = a, *dst = b, *tmp;
    unsigned codes[3], any_out, plane, n = 3, k;
    for (k = 0; k < 3; k++) {
        if (!zl_vertex_clip(s, ZL_MESH_IDX(idx, k), &a[k].c))
            return 0;
        tex_coords(sty, ZL_MESH_IDX(idx, k), &a[k].u, &a[k].v);
        codes[k] = zl_outcode(s, &a[k].c);
    }
    any_out = codes[0] | codes[1] | codes[2];
    if ((codes[0] & codes[1] & codes[2]) != 0)
        return 0;
    for (plane = 0; plane < PLANE_COUNT && n >= 3; plane++) {
        if (!(any_out & (1u << plane)))
            continue;
        n = clip_plane_tex(s, plane, src, n, dst);
        tmp = src;
        src = dst;
        dst = tmp;
    }
    if (n < 3)
        return 0;
    for (k = 0; k < n; k++) {
        zl_project(s, &src[k].c, &out->p.v[k]);
        out->u[k] = src[k].u;
        out->v[k] = src[k].v;
        out->w[k] = w_of(s, src[k].c.w);
    }
    out->p.n = (uint8_t)n;
    out->p.clipped = 1;
    return 1;
}

/* Whether the triangle needs clipping (-1 when it cannot be transformed),
 * with w and the texture coordinates of its vertices. */
static ZL_NOINLINE int tex_vertices(const zl_source *s, const zl_style *sty, const uint16_t *idx, zl_tpoly *out)
{
    unsigned k, any_out = 0;
    for (k = 0; k < 3; k++) {
        zl_cvert c;
        if (!zl_vertex_clip(s, ZL_MESH_IDX(idx, k), &c))
            return -1;
        tex_coords(sty, ZL_MESH_IDX(idx, k), &out->u[k], &out->v[k]);
        out->w[k] = w_of(s, c.w);
        any_out |= zl_outcode(s, &c);
    }
    return any_out != 0;
}

int zl_tri_polygon_tex(const zl_source *s, const zl_style *sty, uint32_t t, zl_tpoly *out)
{
    const uint16_t *idx = &s->mesh->indices[t * 3u];
    int clip = tex_vertices(s, sty, idx, out);
    if (clip < 0)
        return 0;
    if (clip)
        return tex_clipped(s, sty, idx, out);
    /* Not clipped: the geometry exactly as zl_tri_polygon_geom gives it
     * (from the cache in scanline mode), attributes of the vertices. */
    return zl_tri_polygon_geom(s, sty, t, &out->p);
}

int zl_tri_polygon_ex(const zl_source *s, const zl_style *sty, uint32_t t, zl_poly *out)
{
    if (!zl_tri_polygon_geom(s, sty, t, out))
        return 0;
    zl_tri_shade(s, t, out);
    return 1;
}

/* ------------------------------------------------------ lines and points */

static void lvert_of(const zl_source *s, const zl_cvert *v, zl_lvert *out)
{
    zl_wvert w;
    zl_project(s, v, &w);
    out->x = w.x;
    out->y = w.y;
    out->z = w.z;
}

int zl_segment_make(const zl_source *s, uint16_t ia, uint16_t ib, int skip_a, int skip_b, zl_segment *out)
{
    zl_cvert a, b, t;
    unsigned ca, cb, plane;
    if (!zl_vertex_clip(s, ia, &a) || !zl_vertex_clip(s, ib, &b))
        return 0;
    ca = zl_outcode(s, &a);
    cb = zl_outcode(s, &b);
    if ((ca & cb) != 0)
        return 0;
    /* An end moved by clipping is no longer the shared vertex: keep its pixel. */
    out->skip = (skip_a && ca == 0 ? 1u : 0u) | (skip_b && cb == 0 ? 2u : 0u);
    for (plane = 0; plane < PLANE_COUNT; plane++) {
        int64_t da, db;
        if (!((ca | cb) & (1u << plane)))
            continue;
        da = plane_distance(s, plane, &a);
        db = plane_distance(s, plane, &b);
        if (da < 0 && db < 0)
            return 0;
        /* Measured from the inside end, as for triangles: A to B and B to A
         * give the same point. */
        if (da < 0) {
            intersect(&b, &a, db, da, plane, &t);
            a = t;
        } else if (db < 0) {
            intersect(&a, &b, da, db, plane, &t);
            b = t;
        }
    }
    lvert_of(s, &a, &out->a);
    lvert_of(s, &b, &out->b);
    return 1;
}

int zl_point_make(const zl_source *s, uint16_t idx, zl_lvert *out)
{
    zl_cvert v;
    if (!zl_vertex_clip(s, idx, &v) || zl_outcode(s, &v) != 0)
        return 0;
    lvert_of(s, &v, out);
    return 1;
}
