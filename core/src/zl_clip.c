/*
 * Vertex transform, clipping (Sutherland-Hodgman, one plane at a time, in
 * homogeneous clip space) and projection to snapped window coordinates.
 */
#include <stddef.h>
#include <string.h>

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

/* floor(n / d) for n >= 0 whose quotient fits 32 bits: one 32-bit division
 * when n does (most vertices), else the 64/32 one, never the libgcc call. */
static inline uint32_t udiv_small(uint64_t n, uint32_t d)
{
    if ((n >> 32) == 0)
        return (uint32_t)n / d;
    return zl_udiv64_32(n, d, NULL);
}

/* zl_round_div64(n, w) for w >= 1, any n: it equals floor((n + floor(w/2)) / w),
 * which the 64/32 division gives when that is non-negative and fits. */
static int32_t round_div_w(int64_t n, int32_t w)
{
    int64_t m = n + (w >> 1);
    if (m >= 0 && (uint64_t)m < ((uint64_t)(uint32_t)w << 32))
        return (int32_t)udiv_small((uint64_t)m, (uint32_t)w);
    return (int32_t)zl_floor_div64(m, w);
}

/*
 * round(z / w * 65535 * 65536) for 0 <= z <= w, w >= 1: the 64/32 division
 * of n = z * (2^32 - 2^16) + w/2 < w * 2^32 (so the quotient fits 32 bits).
 * For w below 2^20 (clip w below 16.0, most scenes) it is schoolbook long
 * division in digits of 12, 12 and 8 bits: every partial remainder is below
 * w, so remainder * 2^12 plus the next digit fits 32 bits and each digit is
 * one 32-bit division, no correction step. Where division is a library call
 * (Cortex-M0) the general 64/32 division is used throughout.
 */
static ZL_ALWAYS_INLINE uint32_t depth_q16(uint32_t z, uint32_t w)
{
    uint64_t n = ((uint64_t)z << 32) - ((uint64_t)z << 16) + (w >> 1); /* shifts: no multiply */
#if defined(__ARM_FEATURE_IDIV) || !defined(__arm__)
    if (w < (1u << 20)) {
        uint32_t hi = (uint32_t)(n >> 32), lo = (uint32_t)n, r, q2, q1, q0;
        r = (hi << 12) | (lo >> 20); /* hi < w */
        q2 = r / w;
        r -= q2 * w;
        r = (r << 12) | ((lo >> 8) & 0xFFFu);
        q1 = r / w;
        r -= q1 * w;
        r = (r << 8) | (lo & 0xFFu);
        q0 = r / w;
        return (q2 << 20) | (q1 << 8) | q0;
    }
#endif
    return udiv_small(n, w);
}

void zl_project(const zl_source *s, const zl_cvert *v, zl_wvert *out)
{
    int64_t z = v->z < 0 ? 0 : v->z;
    if (s->mvp != NULL) {
        /* Rounded window position in subpixels: (x/w + 1) * W/2 * 2^SUB, and
         * (1 - y/w) * H/2 * 2^SUB with row 0 at the top. */
        int32_t w = v->w < 1 ? 1 : v->w;
        out->x = round_div_w(((int64_t)v->x + w) * s->width * (ZL_SUB_ONE / 2), w);
        out->y = round_div_w(((int64_t)w - v->y) * s->height * (ZL_SUB_ONE / 2), w);
        if (z > w)
            z = w;
        out->z = depth_q16((uint32_t)z, (uint32_t)w);
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

/* zl_cache_vertex by its definition: transform, 7 planes, projection. */
static zl_cached_vertex cache_vertex_generic(const zl_source *s, uint16_t idx)
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

/*
 * The fast path of the vertex cache, with a matrix: the same numbers as
 * cache_vertex_generic, with the per-draw work hoisted out of the vertex loop.
 */
#define COORD_LIMIT ((uint32_t)1 << 30) /* zl_matrix.c's limit: +-16384.0 */

typedef struct {
    zl_fixed m[16];      /* the matrix (a copy: no reloads after each store); every entry within +-COORD_LIMIT */
    int64_t bias[4];     /* translation column * 2^16 + 2^15: rounding folded in */
    uint32_t wd, ht;     /* viewport */
    uint32_t gx, gy;     /* W + 2G, H + 2G: the guard-band planes */
    uint32_t hx, hy;     /* W * 2^SUB / 2, H * 2^SUB / 2: the window centre */
    uint32_t pfast;      /* P: positions within [-P, P) need no range checks */
    uint32_t qx, qy;     /* window quotients below these are inside and in range */
} vx_setup;

/* |v| <= 2^30, the coordinate and matrix entry limit, in one compare. */
static int in_limit(zl_fixed v)
{
    return (uint32_t)v + COORD_LIMIT <= 2u * COORD_LIMIT;
}

static uint32_t abs32(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

/* min(a, b) where b may be negative (then 0). */
static uint32_t limit_below(uint32_t a, int32_t b)
{
    return b <= 0 ? 0u : ((uint32_t)b < a ? (uint32_t)b : a);
}

/*
 * The largest power of two P <= 2^30 (or 0) such that no row of the
 * transform can leave Q16.16 for a position with every |coordinate| <= P:
 * with S = |m0| + |m1| + |m2| (below 2^32), |acc| <= S P + |bias| < 2^47.
 */
static uint32_t fast_bound(const vx_setup *vs)
{
    const int64_t lim = (int64_t)1 << 47;
    uint32_t p = COORD_LIMIT;
    int r;
    for (r = 0; r < 4; r++) {
        const zl_fixed *m = &vs->m[r * 4];
        uint64_t sum = (uint64_t)abs32(m[0]) + abs32(m[1]) + abs32(m[2]);
        int64_t b = vs->bias[r] < 0 ? -vs->bias[r] : vs->bias[r]; /* below 2^47 */
        while (p != 0 && (int64_t)(sum * p) >= lim - b)
            p >>= 1;
    }
    return p;
}

/* 0 when a matrix entry is out of range: then every vertex is invalid. */
static int vx_prepare(const zl_source *s, vx_setup *vs)
{
    const zl_fixed *m = s->mvp->m;
    int k;
    for (k = 0; k < 16; k++)
        if (!in_limit(m[k]))
            return 0;
    for (k = 0; k < 16; k++)
        vs->m[k] = m[k];
    for (k = 0; k < 4; k++)
        vs->bias[k] = (int64_t)m[k * 4 + 3] * ZL_FX_ONE + 32768;
    vs->wd = s->width;
    vs->ht = s->height;
    vs->gx = s->width + 2u * ZL_GUARD_PX;
    vs->gy = s->height + 2u * ZL_GUARD_PX;
    vs->hx = s->width * (uint32_t)(ZL_SUB_ONE / 2);
    vs->hy = s->height * (uint32_t)(ZL_SUB_ONE / 2);
    vs->pfast = fast_bound(vs);
    /* See vx_fast: x inside its planes and window x in [INT16_MIN + 2,
     * INT16_MAX] when q < hx + G 2^SUB and q < 32767 - hx; y likewise with
     * [INT16_MIN, INT16_MAX]. */
    vs->qx = limit_below(vs->hx + (uint32_t)ZL_GUARD_PX * ZL_SUB_ONE, 32767 - (int32_t)vs->hx);
    vs->qy = limit_below(vs->hy + (uint32_t)ZL_GUARD_PX * ZL_SUB_ONE, 32768 - (int32_t)vs->hy);
    if (ZL_SUB_ONE < 2)
        vs->qx = vs->qy = 0; /* h is not W 2^SUB / 2 then: no fast path */
    return 1;
}

/* Row r of the transform, rounded as zl_transform_point; 0 if it leaves Q16.16.
 * Three 32x32->64 multiply-accumulates (SMLAL on Cortex-M3/M4); the result
 * fits when acc is in [-2^47, 2^47), i.e. its high word in [-2^15, 2^15). */
static int vx_row(const vx_setup *vs, int r, const zl_fixed *p, int32_t *out)
{
    const zl_fixed *m = &vs->m[r * 4];
    int64_t acc = vs->bias[r] + (int64_t)m[0] * p[0] + (int64_t)m[1] * p[1] + (int64_t)m[2] * p[2];
    if ((uint32_t)((uint64_t)acc >> 32) + 0x8000u > 0xFFFFu)
        return 0;
    *out = (int32_t)zl_floor_shift64(acc, 16);
    return 1;
}

/*
 * Inside all 7 planes of zl_outcode: w >= 1, 0 <= z <= w, and the left/right
 * pair W x + (W + 2G) w >= 0, -W x + (W + 2G) w >= 0 is W |x| <= (W + 2G) w
 * (w > 0); likewise for y. Unsigned 32x32->64 products: exact.
 */
static int vx_inside(const vx_setup *vs, uint32_t ax, uint32_t ay, int32_t z, int32_t w)
{
    if (w < 1 || z < 0 || z > w)
        return 0;
    return (uint64_t)ax * vs->wd <= (uint64_t)vs->gx * (uint32_t)w &&
           (uint64_t)ay * vs->ht <= (uint64_t)vs->gy * (uint32_t)w;
}

/*
 * zl_project's round((c + w) * h / w) as h + round(c * h / w), both exact:
 * h is an integer. With n = c h, round(n / w) = floor((n + w/2) / w) is
 * -floor((-n + w - 1 - w/2) / w) for n < 0, so one unsigned division of
 * |n| plus a small offset serves both signs; inside the guard band the
 * quotient is below 2^25, and |n| usually fits 32 bits (one UDIV).
 */
static int32_t vx_window(uint32_t h, int32_t c, int neg, uint32_t w)
{
    uint32_t ac = c < 0 ? 0u - (uint32_t)c : (uint32_t)c;
    uint32_t half = w >> 1;
    uint32_t q = udiv_small((uint64_t)ac * h + (neg ? w - 1u - half : half), w);
    return neg ? (int32_t)h - (int32_t)q : (int32_t)(h + q);
}

static ZL_NOINLINE zl_cached_vertex vx_cache(const vx_setup *vs, const zl_fixed *p)
{
    zl_cached_vertex c;
    int32_t x, y, z, w, wx, wy;
    c.x = ZL_CACHE_INVALID;
    c.y = 0;
    c.z = 0;
    if (!in_limit(p[0]) || !in_limit(p[1]) || !in_limit(p[2]) || !vx_row(vs, 0, p, &x) ||
        !vx_row(vs, 1, p, &y) || !vx_row(vs, 2, p, &z) || !vx_row(vs, 3, p, &w))
        return c;
    c.x = ZL_CACHE_COMPLEX;
    if (!vx_inside(vs, x < 0 ? 0u - (uint32_t)x : (uint32_t)x, y < 0 ? 0u - (uint32_t)y : (uint32_t)y, z, w))
        return c;
    wx = vx_window(vs->hx, x, x < 0, (uint32_t)w);
    wy = vx_window(vs->hy, y, y > 0, (uint32_t)w); /* row 0 at the top: (w - y) h / w */
    if (wx <= ZL_CACHE_INVALID || wx > INT16_MAX || wy < INT16_MIN || wy > INT16_MAX)
        return c;
    c.x = (int16_t)wx;
    c.y = (int16_t)wy;
    c.z = depth_q16((uint32_t)z, (uint32_t)w);
    return c;
}

/* Row r of the transform when no range check is needed (vs->pfast). */
static ZL_ALWAYS_INLINE int32_t vx_row_fast(const vx_setup *vs, int r, const zl_fixed *p)
{
    const zl_fixed *m = &vs->m[r * 4];
    int64_t acc = vs->bias[r] + (int64_t)m[0] * p[0] + (int64_t)m[1] * p[1] + (int64_t)m[2] * p[2];
    return (int32_t)zl_floor_shift64(acc, 16); /* |acc| < 2^47 */
}

/*
 * vx_cache for the common vertex, same numbers, or 0 when it cannot tell
 * (then vx_cache decides). Positions within [-P, P): no range checks. With
 * n = |c| h and q = floor((n + off) / w), 0 <= off < w, as vx_window: q is
 * at least floor(n / w), so q < h + G 2^SUB gives n < (h + G 2^SUB) w,
 * which is the pair of x planes multiplied by 2^SUB / 2 (W |x| <= (W + 2G) w).
 * The window coordinate h -+ q is then in range when q < qx (qy).
 */
static ZL_ALWAYS_INLINE int vx_fast(const vx_setup *vs, const zl_fixed *p, zl_cached_vertex *c)
{
    uint32_t pf = vs->pfast, ax, ay, q;
    uint64_t n;
    int32_t x, y, z, w, wx;
    if ((((uint32_t)p[0] + pf) | ((uint32_t)p[1] + pf) | ((uint32_t)p[2] + pf)) >= 2u * pf)
        return 0;
    /* Each row where it is needed: the compiler keeps the order. */
    w = vx_row_fast(vs, 3, p);
    z = vx_row_fast(vs, 2, p);
    if (w < 1 || (uint32_t)z > (uint32_t)w) {
        c->x = ZL_CACHE_COMPLEX; /* outside the w, near or far plane */
        c->y = 0;
        c->z = 0;
        return 1;
    }
    x = vx_row_fast(vs, 0, p);
    ax = x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
    /* vx_window's offset: w/2, or w - 1 - w/2 = (w - 1)/2 for the negative side */
    n = (uint64_t)ax * vs->hx + (((uint32_t)w - (x < 0)) >> 1);
    if ((n >> 32) != 0)
        return 0;
    q = (uint32_t)n / (uint32_t)w;
    if (q >= vs->qx)
        return 0;
    wx = x < 0 ? (int32_t)vs->hx - (int32_t)q : (int32_t)(vs->hx + q);
    y = vx_row_fast(vs, 1, p);
    ay = y < 0 ? 0u - (uint32_t)y : (uint32_t)y;
    n = (uint64_t)ay * vs->hy + (((uint32_t)w - (y > 0)) >> 1); /* row 0 at the top: (w - y) h / w */
    if ((n >> 32) != 0)
        return 0;
    q = (uint32_t)n / (uint32_t)w;
    if (q >= vs->qy)
        return 0;
    c->x = (int16_t)wx;
    c->y = (int16_t)(y > 0 ? (int32_t)vs->hy - (int32_t)q : (int32_t)(vs->hy + q));
    c->z = depth_q16((uint32_t)z, (uint32_t)w);
    return 1;
}

zl_cached_vertex zl_cache_vertex(const zl_source *s, uint16_t idx)
{
    vx_setup vs;
    if (s->mvp == NULL)
        return cache_vertex_generic(s, idx);
    if (!vx_prepare(s, &vs)) {
        zl_cached_vertex c = {ZL_CACHE_INVALID, 0, 0};
        return c;
    }
    {
        const zl_fixed *p = &s->mesh->positions[idx * 3u];
        zl_cached_vertex c;
        if (!vx_fast(&vs, p, &c))
            c = vx_cache(&vs, p);
        return c;
    }
}

zl_status zl_cache_vertices(const zl_source *s, zl_cached_vertex *cache, uint16_t first, uint16_t count)
{
    const zl_cached_vertex bad = {ZL_CACHE_INVALID, 0, 0};
    const zl_fixed *p = &s->mesh->positions[first * 3u];
    zl_cached_vertex *c = &cache[first], *end = c + count;
    zl_status st = ZL_OK;
    vx_setup vs;
    if (s->mvp == NULL) {
        /* Pixel space: nothing can be out of range. */
        uint32_t v;
        for (v = first; v < (uint32_t)first + count; v++)
            cache[v] = cache_vertex_generic(s, (uint16_t)v);
        return ZL_OK;
    }
    if (!vx_prepare(s, &vs)) {
        for (; c != end; c++)
            *c = bad;
        return ZL_ERR_RANGE;
    }
    for (; c != end; c++, p += 3) {
        if (vx_fast(&vs, p, c))
            continue;
        *c = vx_cache(&vs, p);
        if (c->x == ZL_CACHE_INVALID)
            st = ZL_ERR_RANGE;
    }
    return st;
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

/* trunc(c / 4) clamped to [-2^14, 2^14]: the light direction in Q14. */
static ZL_ALWAYS_INLINE int32_t light_q14(zl_fixed c)
{
    /* c / 4 as floor((c + 3) / 4) for negative c */
    int32_t v = zl_floor_shift32(c + (c < 0 ? 3 : 0), 2);
    if ((uint32_t)v + (1u << 14) > (1u << 15))
        v = v < 0 ? -(1 << 14) : (1 << 14);
    return v;
}

/* Bit length of v (0 for 0). */
static unsigned bit_length32(uint32_t v)
{
#if defined(__GNUC__)
    return v == 0 ? 0u : 32u - (unsigned)__builtin_clz(v); /* CLZ */
#else
    unsigned n = 0;
    while (v != 0) {
        v >>= 1;
        n++;
    }
    return n;
#endif
}

/* |v| <= 2^30 for all three: one compare for the common case (every
 * v + 2^30 below 2^31), the exact test otherwise (v = 2^30). */
static ZL_ALWAYS_INLINE int in_limit3(const zl_fixed *p)
{
    if ((((uint32_t)p[0] + COORD_LIMIT) | ((uint32_t)p[1] + COORD_LIMIT) | ((uint32_t)p[2] + COORD_LIMIT)) <
        2u * COORD_LIMIT)
        return 1;
    return in_limit(p[0]) && in_limit(p[1]) && in_limit(p[2]);
}

/* The normal of any triangle, scaled below 2^14: edges brought below 2^30
 * so the 64-bit cross product cannot overflow, then the normal shifted. */
static ZL_NOINLINE void large_normal(const zl_fixed *pos, const uint16_t *idx, int32_t *m)
{
    const zl_fixed *p0 = &pos[idx[0] * 3u], *p1 = &pos[idx[1] * 3u], *p2 = &pos[idx[2] * 3u];
    int64_t e[6], n[3];
    unsigned k, shift;
    for (k = 0; k < 3; k++) {
        e[k] = (int64_t)p1[k] - p0[k];
        e[k + 3] = (int64_t)p2[k] - p0[k];
    }
    shift = shift_below(max_abs(e, 6), 30);
    for (k = 0; k < 6; k++)
        e[k] = zl_floor_shift64(e[k], shift);
    n[0] = e[1] * e[5] - e[2] * e[4];
    n[1] = e[2] * e[3] - e[0] * e[5];
    n[2] = e[0] * e[4] - e[1] * e[3];
    shift = shift_below(max_abs(n, 3), 14);
    for (k = 0; k < 3; k++)
        m[k] = (int32_t)zl_floor_shift64(n[k], shift);
}

/*
 * Lambert intensity 0..255 of the face (p0, p1, p2), front side by winding.
 * Only 8 bits come out, so the normal is scaled to 14 bits and the rest is
 * 32-bit arithmetic (one 32-bit square root and division): this runs once
 * per drawn triangle, so it must be cheap on a Cortex-M. The numbers are
 * those of the 64-bit definition (large_normal) for every triangle.
 *
 * Small triangles (most of a mesh) take a 32-bit path: with every edge in
 * [-2^14, 2^14) the cross product stays within 2^29. The edges are taken
 * modulo 2^32; with the first vertex within +-2^30, a wrapped difference in
 * that range is the true one (a true one 2^32 away would need |p0| >= 2^31 -
 * 2^14). The shift to 14 bits is the bit length of the largest component,
 * which is the bit length of the OR of all three.
 */
static ZL_NOINLINE unsigned face_intensity(const zl_source *s, const uint16_t *idx, const int32_t *lq)
{
    const zl_fixed *pos = s->mesh->positions;
    const zl_fixed *p0 = &pos[idx[0] * 3u], *p1 = &pos[idx[1] * 3u], *p2 = &pos[idx[2] * 3u];
    const zl_state *st = s->state;
    const uint32_t x0 = (uint32_t)p0[0], y0 = (uint32_t)p0[1], z0 = (uint32_t)p0[2], half = 1u << 14;
    const uint32_t e0 = (uint32_t)p1[0] - x0, e1 = (uint32_t)p1[1] - y0, e2 = (uint32_t)p1[2] - z0;
    const uint32_t e3 = (uint32_t)p2[0] - x0, e4 = (uint32_t)p2[1] - y0, e5 = (uint32_t)p2[2] - z0;
    int32_t m0, m1, m2, dot, cosv;
    uint32_t len;
    /* every edge in [-2^14, 2^14) iff each e + 2^14 is below 2^15 */
    if (((e0 + half) | (e1 + half) | (e2 + half) | (e3 + half) | (e4 + half) | (e5 + half)) < 2u * half &&
        in_limit3(p0)) {
        const int32_t a0 = (int32_t)e0, a1 = (int32_t)e1, a2 = (int32_t)e2;
        const int32_t b0 = (int32_t)e3, b1 = (int32_t)e4, b2 = (int32_t)e5;
        uint32_t mag;
        m0 = a1 * b2 - a2 * b1;
        m1 = a2 * b0 - a0 * b2;
        m2 = a0 * b1 - a1 * b0;
        mag = abs32(m0) | abs32(m1) | abs32(m2);
        if (mag >= (1u << 14)) {
            unsigned sh = bit_length32(mag) - 14u;
            m0 = zl_floor_shift32(m0, sh);
            m1 = zl_floor_shift32(m1, sh);
            m2 = zl_floor_shift32(m2, sh);
        }
    } else {
        int32_t m[3];
        large_normal(pos, idx, m);
        m0 = m[0];
        m1 = m[1];
        m2 = m[2];
    }
    /* light_dir is a unit vector in Q16; in Q14, clamped to [-1, 1], the three
     * products and their sum stay inside 32 bits whatever the caller passed. */
    dot = m0 * lq[0] + m1 * lq[1] + m2 * lq[2]; /* zl_light_prepare: front-face sign included */
    if (dot <= 0)
        return st->ambient; /* before the square root: a zero normal has dot 0 */
    len = zl_isqrt32((uint32_t)(m0 * m0 + m1 * m1 + m2 * m2)); /* >= 1: the normal is not 0 */
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

/* Non-zero iff the vertex colour is not black; r and g in one 32-bit load
 * where they are adjacent (always, in practice). */
static ZL_ALWAYS_INLINE uint32_t rgb_bits(const zl_wvert *v)
{
    if (offsetof(zl_wvert, g) == offsetof(zl_wvert, r) + sizeof(uint16_t)) {
        uint32_t rg;
        memcpy(&rg, (const unsigned char *)v + offsetof(zl_wvert, r), sizeof rg);
        return rg | v->b;
    }
    return (uint32_t)v->r | v->g | v->b;
}

static ZL_ALWAYS_INLINE zl_rgb face_color(const zl_source *s, uint32_t t)
{
    const uint8_t *fc = s->mesh->face_colors;
    return fc ? (zl_rgb){fc[t * 3], fc[t * 3 + 1], fc[t * 3 + 2]} : s->state->color;
}

/* Flat colour and lighting of source triangle t into poly. */
static ZL_ALWAYS_INLINE void shade(const zl_source *s, uint32_t t, const uint16_t *idx, zl_poly *poly,
                                    const int32_t *lq)
{
    unsigned i, k, n;
    uint32_t any = 0;
    zl_rgb c;
    if (!s->state->light_on) {
        poly->flat = face_color(s, t);
        poly->light = 255;
        return;
    }
    i = face_intensity(s, idx, lq); /* first: fewer values live across it */
    c = face_color(s, t);
    n = poly->n;
    poly->light = (uint8_t)i;
    poly->flat.r = scale255(c.r, i);
    poly->flat.g = scale255(c.g, i);
    poly->flat.b = scale255(c.b, i);
    /* black stays black (scale255_q8(0, i) is 0): no vertex colours, the common case */
    k = 0;
    if (n >= 3) {
        any = rgb_bits(&poly->v[0]) | rgb_bits(&poly->v[1]) | rgb_bits(&poly->v[2]);
        k = 3;
    }
    for (; k < n; k++)
        any |= rgb_bits(&poly->v[k]);
    if (any == 0)
        return;
    for (k = 0; k < n; k++) {
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

void zl_light_prepare(const zl_state *st, int32_t lq[3])
{
    /* the dot product's sign flips with the winding of the front face:
     * flipping the light instead gives the same sum, once per draw */
    int32_t sign = st->front_face == ZL_FRONT_CW ? -1 : 1;
    lq[0] = sign * light_q14(st->light_dir.x);
    lq[1] = sign * light_q14(st->light_dir.y);
    lq[2] = sign * light_q14(st->light_dir.z);
}

uint16_t zl_tri_pixel565_lit(const zl_source *s, uint32_t t, const int32_t lq[3])
{
    zl_rgb c = face_color(s, t);
    unsigned r = c.r, g = c.g, b = c.b;
    if (s->state->light_on) {
        unsigned i = face_intensity(s, &s->mesh->indices[t * 3u], lq);
        r = scale255(r, i);
        g = scale255(g, i);
        b = scale255(b, i);
    }
    return (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
}

void zl_tri_shade_lit(const zl_source *s, uint32_t t, zl_poly *poly, const int32_t lq[3])
{
    shade(s, t, &s->mesh->indices[t * 3u], poly, lq);
}

void zl_tri_shade(const zl_source *s, uint32_t t, zl_poly *poly)
{
    int32_t lq[3] = {0, 0, 0};
    if (s->state->light_on) /* unlit: shade reads no light */
        zl_light_prepare(s->state, lq);
    shade(s, t, &s->mesh->indices[t * 3u], poly, lq);
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
