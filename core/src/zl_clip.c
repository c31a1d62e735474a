/*
 * Vertex transform, clipping (Sutherland-Hodgman, one plane at a time, in
 * homogeneous clip space) and projection to snapped window coordinates.
 */
#include "zl_internal.h"

enum {
    PLANE_W = 0,      /* w >= 1 raw: keeps every later division defined */
    PLANE_NEAR = 1,   /* z >= 0 */
    PLANE_FAR = 2,    /* z <= w */
    PLANE_LEFT = 3,   /* window x >= -ZL_GUARD_PX */
    PLANE_RIGHT = 4,  /* window x <= width + ZL_GUARD_PX */
    PLANE_TOP = 5,    /* window y >= -ZL_GUARD_PX */
    PLANE_BOTTOM = 6, /* window y <= height + ZL_GUARD_PX */
    PLANE_COUNT = 7
};

static int32_t color_q8(const zl_mesh *m, uint16_t idx, int k)
{
    return m->vertex_colors ? (int32_t)m->vertex_colors[idx * 3u + (unsigned)k] * 256 : 0;
}

int zl_vertex_clip(const zl_source *s, uint16_t idx, zl_cvert *out)
{
    const zl_fixed *p = &s->mesh->positions[idx * 3u];
    zl_vec3 v;
    v.x = p[0];
    v.y = p[1];
    v.z = p[2];
    if (s->mvp != NULL) {
        zl_vec4 c;
        if (zl_transform_point(s->mvp, v, &c) != ZL_OK)
            return 0;
        out->x = c.x;
        out->y = c.y;
        out->z = c.z;
        out->w = c.w;
    } else {
        out->x = v.x;
        out->y = v.y;
        out->z = v.z;
        out->w = ZL_FX_ONE;
    }
    out->r = color_q8(s->mesh, idx, 0);
    out->g = color_q8(s->mesh, idx, 1);
    out->b = color_q8(s->mesh, idx, 2);
    return 1;
}

/* Texture coordinate (Q16.16 of the size) in 1/256 texel, within +-2^23. */
static int32_t texel_q8(zl_fixed c, uint16_t size)
{
    int64_t v = zl_floor_shift64((int64_t)c * size + 128, 8);
    const int64_t lim = (int64_t)1 << 23;
    return (int32_t)(v < -lim ? -lim : (v > lim ? lim : v));
}

/* Texture coordinates of vertex idx under the style (0 without a texture). */
static void tex_coords(const zl_style *sty, uint16_t idx, int32_t *u, int32_t *v)
{
    *u = 0;
    *v = 0;
    if (sty != NULL && sty->texture != NULL && sty->texcoords != NULL) {
        *u = texel_q8(sty->texcoords[idx * 2u], sty->texture->width);
        *v = texel_q8(sty->texcoords[idx * 2u + 1], sty->texture->height);
    }
}

/*
 * Signed distance of v to a plane, positive inside, in 64 bits. The x/y
 * planes come from window x = (x/w + 1) * W/2 >= -G, multiplied through by
 * 2w > 0: W x + (W + 2G) w >= 0; in pixel space window x is x itself.
 */
static int64_t plane_distance(const zl_source *s, unsigned plane, const zl_cvert *v)
{
    const int64_t g = ZL_GUARD_PX;
    const int64_t w = v->w, wd = s->width, ht = s->height;
    int pixel = s->mvp == NULL;
    switch (plane) {
    case PLANE_W:
        return w - 1;
    case PLANE_NEAR:
        return v->z;
    case PLANE_FAR:
        return w - v->z;
    case PLANE_LEFT:
        return pixel ? v->x + g * w : wd * v->x + (wd + 2 * g) * w;
    case PLANE_RIGHT:
        return pixel ? (wd + g) * w - v->x : -wd * v->x + (wd + 2 * g) * w;
    case PLANE_TOP:
        return pixel ? v->y + g * w : -ht * v->y + (ht + 2 * g) * w;
    default:
        return pixel ? (ht + g) * w - v->y : ht * v->y + (ht + 2 * g) * w;
    }
}

unsigned zl_outcode(const zl_source *s, const zl_cvert *v)
{
    unsigned code = 0, p;
    for (p = 0; p < PLANE_COUNT; p++)
        if (plane_distance(s, p, v) < 0)
            code |= 1u << p;
    return code;
}

static uint16_t color_out(int32_t c)
{
    if (c < 0)
        return 0;
    return (uint16_t)(c > 255 * 256 ? 255 * 256 : c);
}

void zl_project(const zl_source *s, const zl_cvert *v, zl_wvert *out)
{
    int64_t z = v->z < 0 ? 0 : v->z;
    if (s->mvp != NULL) {
        /* Rounded window position in subpixels: (x/w + 1) * W/2 * 2^SUB, and
         * (1 - y/w) * H/2 * 2^SUB with row 0 at the top. */
        int64_t w = v->w < 1 ? 1 : v->w;
        int64_t q, r;
        out->x = (int32_t)zl_round_div64(((int64_t)v->x + w) * s->width * (ZL_SUB_ONE / 2), w);
        out->y = (int32_t)zl_round_div64((w - v->y) * s->height * (ZL_SUB_ONE / 2), w);
        /* depth * 65535 * 65536 = z / w * 65535 * 65536, rounded, split as
         * quotient and remainder so no product exceeds 64 bits. */
        if (z > w)
            z = w;
        q = z * 65535 / w;
        r = z * 65535 % w;
        out->z = (uint32_t)(q * 65536 + zl_round_div64(r * 65536, w));
    } else {
        /* Pixel space: x, y are Q16.16 pixels, z is depth 0..1 in Q16.16. */
        out->x = (int32_t)zl_floor_shift64((int64_t)v->x + (1 << (15 - ZL_SUB_BITS)), 16 - ZL_SUB_BITS);
        out->y = (int32_t)zl_floor_shift64((int64_t)v->y + (1 << (15 - ZL_SUB_BITS)), 16 - ZL_SUB_BITS);
        if (z > ZL_FX_ONE)
            z = ZL_FX_ONE;
        out->z = (uint32_t)(z * 65535);
    }
    out->r = color_out(v->r);
    out->g = color_out(v->g);
    out->b = color_out(v->b);
}

zl_cached_vertex zl_cache_vertex(const zl_source *s, uint16_t idx)
{
    zl_cached_vertex c;
    zl_cvert v;
    zl_wvert w;
    c.x = ZL_CACHE_INVALID;
    c.y = 0;
    c.z = 0;
    if (!zl_vertex_clip(s, idx, &v))
        return c;
    c.x = ZL_CACHE_COMPLEX;
    if (zl_outcode(s, &v) != 0)
        return c;
    zl_project(s, &v, &w);
    /* INT16_MIN and INT16_MIN + 1 are the markers, so they never hold data. */
    if (w.x <= ZL_CACHE_INVALID || w.x > INT16_MAX || w.y < INT16_MIN || w.y > INT16_MAX)
        return c;
    c.x = (int16_t)w.x;
    c.y = (int16_t)w.y;
    c.z = w.z;
    return c;
}

static unsigned bit_length(uint64_t v)
{
    unsigned n = 0;
    while (v != 0) {
        v >>= 1;
        n++;
    }
    return n;
}

static int32_t lerp(int32_t a, int32_t b, int64_t t30)
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
    unsigned len = bit_length((uint64_t)den);
    if (len > 32) {
        num = zl_floor_shift64(num, len - 32);
        den = zl_floor_shift64(den, len - 32);
    }
    t = den > 0 ? (num * ((int64_t)1 << 30)) / den : 0; /* Q30 in [0, 1] */
    res->x = lerp(in->x, out->x, t);
    res->y = lerp(in->y, out->y, t);
    res->z = lerp(in->z, out->z, t);
    res->w = lerp(in->w, out->w, t);
    res->r = lerp(in->r, out->r, t);
    res->g = lerp(in->g, out->g, t);
    res->b = lerp(in->b, out->b, t);
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

/* Largest magnitude of n values. */
static int64_t max_abs(const int64_t *v, unsigned n)
{
    int64_t big = 0;
    unsigned k;
    for (k = 0; k < n; k++) {
        int64_t a = v[k] < 0 ? -v[k] : v[k];
        if (a > big)
            big = a;
    }
    return big;
}

/* Number of right shifts that bring big below 2^bits. */
static unsigned shift_below(int64_t big, unsigned bits)
{
    unsigned len = 0;
    uint64_t v = (uint64_t)big;
    if (big < ((int64_t)1 << bits))
        return 0;
#if defined(__GNUC__)
    len = 64u - (unsigned)__builtin_clzll(v); /* CLZ: one instruction per word */
#else
    while (v != 0) {
        v >>= 1;
        len++;
    }
#endif
    return len - bits;
}

static int32_t light_q14(zl_fixed c)
{
    int32_t v = c / 4;
    return v > (1 << 14) ? (1 << 14) : (v < -(1 << 14) ? -(1 << 14) : v);
}

/*
 * Lambert intensity 0..255 of the face (p0, p1, p2), front side by winding.
 * Only 8 bits come out, so the normal is scaled to 14 bits and the rest is
 * 32-bit arithmetic (one 32-bit square root and division): this runs once
 * per drawn triangle, so it must be cheap on a Cortex-M.
 */
static unsigned face_intensity(const zl_source *s, const uint16_t *idx)
{
    const zl_fixed *pos = s->mesh->positions;
    const zl_state *st = s->state;
    int64_t e[6], n[3], big;
    int32_t m[3], dot, cosv;
    uint32_t len;
    unsigned k, shift;
    for (k = 0; k < 3; k++) {
        e[k] = (int64_t)pos[idx[1] * 3u + k] - pos[idx[0] * 3u + k];
        e[k + 3] = (int64_t)pos[idx[2] * 3u + k] - pos[idx[0] * 3u + k];
    }
    big = max_abs(e, 6);
    if (big < ((int64_t)1 << 14)) {
        /* Small triangles (most of a mesh): the same products in 32 bits. */
        int32_t a[6];
        for (k = 0; k < 6; k++)
            a[k] = (int32_t)e[k];
        n[0] = a[1] * a[5] - a[2] * a[4];
        n[1] = a[2] * a[3] - a[0] * a[5];
        n[2] = a[0] * a[4] - a[1] * a[3];
    } else {
        /* Edges below 2^30 so the cross product fits 64 bits... */
        shift = shift_below(big, 30);
        for (k = 0; k < 6; k++)
            e[k] = zl_floor_shift64(e[k], shift);
        n[0] = e[1] * e[5] - e[2] * e[4];
        n[1] = e[2] * e[3] - e[0] * e[5];
        n[2] = e[0] * e[4] - e[1] * e[3];
    }
    /* ... and the normal below 2^14, enough for 8 bits of intensity. */
    shift = shift_below(max_abs(n, 3), 14);
    for (k = 0; k < 3; k++)
        m[k] = (int32_t)zl_floor_shift64(n[k], shift);
    len = zl_isqrt32((uint32_t)(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]));
    if (len == 0)
        return st->ambient;
    /* light_dir is a unit vector in Q16; in Q14, clamped to [-1, 1], the three
     * products and their sum stay inside 32 bits whatever the caller passed. */
    dot = m[0] * light_q14(st->light_dir.x) + m[1] * light_q14(st->light_dir.y) +
          m[2] * light_q14(st->light_dir.z);
    if (st->front_face == ZL_FRONT_CW)
        dot = -dot;
    if (dot <= 0)
        return st->ambient;
    cosv = dot / (int32_t)len; /* Q14 */
    if (cosv > (1 << 14))
        cosv = 1 << 14;
    return st->ambient + (unsigned)(((255 - st->ambient) * cosv + (1 << 13)) >> 14);
}

static uint8_t scale255(unsigned c, unsigned i)
{
    return (uint8_t)((c * i + 127) / 255);
}

static uint16_t scale255_q8(unsigned c, unsigned i)
{
    return (uint16_t)((c * i + 127) / 255);
}

/* Flat colour and lighting of source triangle t into poly. */
static void shade(const zl_source *s, uint32_t t, const uint16_t *idx, zl_poly *poly)
{
    const zl_state *st = s->state;
    const uint8_t *fc = s->mesh->face_colors;
    unsigned i, k;
    poly->flat = fc ? (zl_rgb){fc[t * 3], fc[t * 3 + 1], fc[t * 3 + 2]} : st->color;
    poly->light = 255;
    if (!st->light_on)
        return;
    i = face_intensity(s, idx);
    poly->light = (uint8_t)i;
    poly->flat.r = scale255(poly->flat.r, i);
    poly->flat.g = scale255(poly->flat.g, i);
    poly->flat.b = scale255(poly->flat.b, i);
    for (k = 0; k < poly->n; k++) {
        poly->v[k].r = scale255_q8(poly->v[k].r, i);
        poly->v[k].g = scale255_q8(poly->v[k].g, i);
        poly->v[k].b = scale255_q8(poly->v[k].b, i);
    }
}

/* All three vertices cached inside: the fast path of scanline mode. */
static int polygon_from_cache(const zl_source *s, const uint16_t *idx, zl_poly *out)
{
    unsigned k;
    for (k = 0; k < 3; k++) {
        const zl_cached_vertex *c = &s->cache[idx[k]];
        zl_wvert *w = &out->v[k];
        w->x = c->x;
        w->y = c->y;
        w->z = c->z;
        w->r = (uint16_t)color_q8(s->mesh, idx[k], 0);
        w->g = (uint16_t)color_q8(s->mesh, idx[k], 1);
        w->b = (uint16_t)color_q8(s->mesh, idx[k], 2);
    }
    out->n = 3;
    return 1;
}

static int polygon_clipped(const zl_source *s, const uint16_t *idx, zl_poly *out)
{
    zl_cvert a[ZL_MAX_POLY], b[ZL_MAX_POLY];
    zl_cvert *src = a, *dst = b, *tmp;
    unsigned codes[3], all_out, any_out, plane, n = 3, k;
    for (k = 0; k < 3; k++) {
        if (!zl_vertex_clip(s, idx[k], &a[k]))
            return 0;
        codes[k] = zl_outcode(s, &a[k]);
    }
    all_out = codes[0] & codes[1] & codes[2];
    any_out = codes[0] | codes[1] | codes[2];
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
    out->n = n;
    return 1;
}

int zl_tri_polygon(const zl_source *s, uint32_t t, zl_poly *out)
{
    return zl_tri_polygon_ex(s, NULL, t, out);
}

int zl_tri_polygon_geom(const zl_source *s, const zl_style *sty, uint32_t t, zl_poly *out)
{
    const uint16_t *idx = &s->mesh->indices[t * 3u];
    int ok;
    (void)sty;
    if (s->cache != NULL) {
        int16_t x0 = s->cache[idx[0]].x, x1 = s->cache[idx[1]].x, x2 = s->cache[idx[2]].x;
        if (x0 == ZL_CACHE_INVALID || x1 == ZL_CACHE_INVALID || x2 == ZL_CACHE_INVALID)
            return 0;
        if (x0 != ZL_CACHE_COMPLEX && x1 != ZL_CACHE_COMPLEX && x2 != ZL_CACHE_COMPLEX)
            ok = polygon_from_cache(s, idx, out);
        else
            ok = polygon_clipped(s, idx, out);
    } else {
        ok = polygon_clipped(s, idx, out);
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
        if (!zl_vertex_clip(s, idx[k], &a[k].c))
            return 0;
        tex_coords(sty, idx[k], &a[k].u, &a[k].v);
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
    out->p.n = n;
    return 1;
}

/* Whether the triangle needs clipping (-1 when it cannot be transformed),
 * with w and the texture coordinates of its vertices. */
static ZL_NOINLINE int tex_vertices(const zl_source *s, const zl_style *sty, const uint16_t *idx, zl_tpoly *out)
{
    unsigned k, any_out = 0;
    for (k = 0; k < 3; k++) {
        zl_cvert c;
        if (!zl_vertex_clip(s, idx[k], &c))
            return -1;
        tex_coords(sty, idx[k], &out->u[k], &out->v[k]);
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

void zl_tri_shade(const zl_source *s, uint32_t t, zl_poly *poly)
{
    shade(s, t, &s->mesh->indices[t * 3u], poly);
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
