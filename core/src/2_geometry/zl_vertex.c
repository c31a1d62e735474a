/* SPDX-License-Identifier: MIT */
/*
 * Stage 2, geometry: vertices. Fetch and transform a vertex to clip space
 * (Q16.16, 64-bit accumulation), its outcode against the seven clip planes,
 * projection and snapping to window coordinates, and the vertex cache (each
 * vertex transformed, tested and projected once per draw or frame).
 */
#include <stddef.h>
#include <string.h>

#include "zl_geometry.h"

/* Bit length of v (0 for 0): CLZ where the compiler has it. */
static ZL_ALWAYS_INLINE unsigned bits_u32(uint32_t v)
{
#if defined(__GNUC__) && __SIZEOF_INT__ >= 4 /* __builtin_clz counts in an unsigned int */
    return v == 0 ? 0u : 32u - (unsigned)__builtin_clz(v);
#else
    unsigned n = 0;
    while (v != 0) {
        v >>= 1;
        n++;
    }
    return n;
#endif
}

/* The low word of v >> s for 0 <= s <= 31, v >> s below 2^32: 32-bit
 * operations only (a variable 64-bit shift is a library call on some
 * targets). */
static ZL_ALWAYS_INLINE uint32_t shr_low(uint64_t v, unsigned s)
{
    uint32_t hi = (uint32_t)(v >> 32), lo = (uint32_t)v;
    return s == 0 ? lo : (lo >> s) | (hi << (32u - s));
}

/*
 * The residual of a window coordinate (zl_wvert fx, fy): 2^ZL_FINE_BITS
 * times (exact - snapped) subpixels, where exact = h + c h / w (neg 0) or
 * h - c h / w (neg 1) from the transform's unrounded sums c and w (2^-32
 * units, w > 0) and snapped is the coordinate the rasteriser uses (from the
 * rounded Q16.16 clip coordinates). |c| h 2^12 / w by one 64/32 division of
 * the sums shifted until w fits 32 bits: with |c| <= 4 w the quotient is
 * below 2^29 and its error below 1/8 unit (relative 2^-31). Saturated to
 * int16; 0 beyond |c| = 4 w (outside every guard band: never drawn
 * unclipped).
 */
static int16_t fine_residual(int64_t c, int64_t w, uint32_t h, int neg, int32_t snapped)
{
    uint64_t ac = c < 0 ? (uint64_t)0 - (uint64_t)c : (uint64_t)c, n;
    uint32_t d, e;
    unsigned s;
    int64_t r;
    if (w <= 0 || ac > ((uint64_t)w << 2))
        return 0;
    s = bits_u32((uint32_t)((uint64_t)w >> 32)); /* |w| < 2^47: s <= 15 */
    d = shr_low((uint64_t)w, s);                  /* >= 2^31 when s > 0 */
    n = ((ac >> s) * h) << ZL_FINE_BITS;          /* below 2^34 2^15 2^12 */
    e = zl_udiv64_32(n, d, NULL);
    r = ((int64_t)h << ZL_FINE_BITS) + (neg ? -(int64_t)e : (int64_t)e) - (int64_t)snapped * (1 << ZL_FINE_BITS);
    return (int16_t)(r < -32767 ? -32767 : (r > 32767 ? 32767 : r));
}

/*
 * The exact pseudodepth (zline.h, Pseudodepth) of eye distance d = dq / 2^32
 * (dq the clip w's 64-bit sum, Q32, before rounding; below 2^47) for near
 * n = N / 2^16 and far f = F / 2^16, in 1/65536 steps:
 *     round(65535 * 2^16 * f (d - n) / ((f - n) d)) = round((2^32 - 2^16) X / Y),
 * clamped to 0 .. 65535 * 2^16, with X = F (dq - nq), Y = (F - N) dq.
 * dq is brought below 2^32 by a right shift s <= 15 (relative error below
 * 2^-31), nq = N 2^16 by the same shift, exactly (16 - s >= 1); X and Y
 * (below 2^63) are brought below 2^32 together (X <= Y); one 64/32 division
 * gives the quotient. The truncations move the result by less than
 * 4 f / (f - n) units of 2^-16 step: 1/8000 step when f >= 2n.
 */
static uint32_t depth_exact(uint64_t dq, uint32_t n, uint32_t f)
{
    uint32_t d, nq, x, y;
    uint64_t xx, yy;
    unsigned s;
    if (dq <= (uint64_t)n << 16)
        return 0;
    if (dq >= (uint64_t)f << 16)
        return 0xFFFF0000u;
    s = bits_u32((uint32_t)(dq >> 32)); /* 0 .. 15 */
    d = shr_low(dq, s);
    nq = n << (16u - s); /* exact: N 2^16 >> s < d < 2^32 */
    xx = (uint64_t)f * (d - nq);
    yy = (uint64_t)(f - n) * d;
    s = bits_u32((uint32_t)(yy >> 32)); /* 0 .. 31: yy < 2^63 */
    x = shr_low(xx, s);
    y = shr_low(yy, s); /* >= 2^31 when shifted, >= 1 always (f > n, d > nq) */
    if (x > y)
        x = y;
    /* x (2^32 - 2^16) + y/2 < 2^64 for x <= y < 2^32: the quotient fits 32 bits */
    return zl_udiv64_32(((uint64_t)x << 32) - ((uint64_t)x << 16) + (y >> 1), y, NULL);
}

/* The exact mapping's depth of a vertex whose clip w sum (Q32) is dq. */
static uint32_t depth_of_wsum(const zl_state *st, int64_t dq)
{
    return depth_exact(dq > 0 ? (uint64_t)dq : 0u, (uint32_t)st->near_z, (uint32_t)st->far_z);
}

/* The same for the model position p under s's matrix: w's sum as
 * zl_transform_point forms it, not rounded (it fits 64 bits when the
 * transform succeeded). Out of line: its frame (and the division's) is not
 * on top of the transform's in zl_vertex_clip, the clipper's deepest stack
 * path. */
static ZL_NOINLINE uint32_t vertex_exact_depth(const zl_source *s, const zl_fixed *p)
{
    const zl_fixed *m = &s->mvp->m[12];
    return depth_of_wsum(s->state, (int64_t)m[0] * ZL_MESH_POS(p, 0) + (int64_t)m[1] * ZL_MESH_POS(p, 1) +
                                       (int64_t)m[2] * ZL_MESH_POS(p, 2) + (int64_t)m[3] * ZL_FX_ONE);
}

/* Row r of the transform of p, unrounded (2^-32 units; below 2^47 when
 * zl_transform_point succeeded). */
static int64_t transform_sum(const zl_mat4 *m, int r, const zl_fixed *p)
{
    const zl_fixed *row = &m->m[r * 4];
    return (int64_t)row[0] * ZL_MESH_POS(p, 0) + (int64_t)row[1] * ZL_MESH_POS(p, 1) +
           (int64_t)row[2] * ZL_MESH_POS(p, 2) + (int64_t)row[3] * ZL_FX_ONE;
}

void zl_vertex_residuals(const zl_source *s, uint16_t idx, const zl_wvert *w, int16_t *fx, int16_t *fy)
{
    *fx = *fy = ZL_FINE_NONE;
    /* the exact mapping only (ZL_FEATURE_EXACT_DEPTH needs ZL_FEATURE_DEPTH_MAP, zl_config.h) */
    if (ZL_FEATURE_EXACT_DEPTH && s->mvp != NULL && s->state != NULL && s->state->far_z != 0) {
        const zl_fixed *p = &s->mesh->positions[idx * 3u];
        int64_t ws = transform_sum(s->mvp, 3, p), xs = transform_sum(s->mvp, 0, p), ys = transform_sum(s->mvp, 1, p);
        *fx = fine_residual(xs, ws, s->width * (uint32_t)(ZL_SUB_ONE / 2), xs < 0, w->x);
        *fy = fine_residual(ys, ws, s->height * (uint32_t)(ZL_SUB_ONE / 2), ys > 0, w->y);
    }
}

int zl_vertex_clip(const zl_source *s, uint16_t idx, zl_cvert *out)
{
    const zl_fixed *p = &s->mesh->positions[idx * 3u];
    zl_vec3 v;
    v.x = ZL_MESH_POS(p, 0);
    v.y = ZL_MESH_POS(p, 1);
    v.z = ZL_MESH_POS(p, 2);
    if (s->mvp != NULL) {
        zl_vec4 c;
        if (zl_transform_point(s->mvp, v, &c) != ZL_OK)
            return 0;
        out->x = c.x;
        out->y = c.y;
        out->z = c.z;
        out->w = c.w;
        out->zd = s->state != NULL && ZL_DEPTH_MAPPED(s->state) ? vertex_exact_depth(s, p) : ZL_ZD_NONE;
    } else {
        out->x = v.x;
        out->y = v.y;
        out->z = v.z;
        out->w = ZL_FX_ONE;
        out->zd = ZL_ZD_NONE;
    }
    out->r = (uint16_t)color_q8(s->mesh, idx, 0); /* 0 .. 255 * 256 */
    out->g = (uint16_t)color_q8(s->mesh, idx, 1);
    out->b = (uint16_t)color_q8(s->mesh, idx, 2);
    return 1;
}

#if !ZL_FAST_PATHS
int64_t zl_plane_distance(const zl_source *s, unsigned plane, const zl_cvert *v)
{
    return plane_distance_of(s, plane, v);
}
#endif

unsigned zl_outcode(const zl_source *s, const zl_cvert *v)
{
    unsigned code = 0, p;
    for (p = 0; p < PLANE_COUNT; p++)
        if (plane_distance(s, p, v) < 0)
            code |= 1u << p;
    return code;
}

static ZL_SMALL_NOINLINE uint16_t color_out(int32_t c)
{
    if (c < 0)
        return 0;
    return (uint16_t)(c > INT32_C(255) * 256 ? INT32_C(255) * 256 : c);
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
 * one 32-bit division, no correction step. On Cortex-M0, where a division
 * is a library call whose cost grows with the quotient's bits, the three
 * short quotients still cost less than zl_udiv64_32's normalisation and two
 * 16-bit digits (issue 13: bunny frame -178 K instructions there). Other
 * cores without a divide instruction take the general 64/32 division.
 */
static ZL_ALWAYS_INLINE uint32_t depth_q16(uint32_t z, uint32_t w)
{
    uint64_t n = ((uint64_t)z << 32) - ((uint64_t)z << 16) + (w >> 1); /* shifts: no multiply */
#if defined(__ARM_FEATURE_IDIV) || !defined(__arm__) || ZL_MUL32_ONLY
    if (ZL_FAST_PATHS && w < (UINT32_C(1) << 20)) { /* off: the one division (zl_config.h) */
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
        out->z = v->zd != ZL_ZD_NONE ? v->zd : depth_q16((uint32_t)z, (uint32_t)w);
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
    int16_t fx, fy;
    c.x = ZL_CACHE_INVALID;
    c.y = 0;
    c.z = 0;
    ZL_CV_SET_FINE(&c, 0, 0);
    if (!zl_vertex_clip(s, idx, &v))
        return c;
    c.x = ZL_CACHE_COMPLEX;
    if (zl_outcode(s, &v) != 0)
        return c;
    zl_project(s, &v, &w);
    zl_vertex_residuals(s, idx, &w, &fx, &fy);
    ZL_CV_SET_FINE(&c, fx, fy);
    /* INT16_MIN and INT16_MIN + 1 are the markers, so they never hold data. */
    if (w.x <= ZL_CACHE_INVALID || w.x > INT16_MAX || w.y < INT16_MIN || w.y > INT16_MAX)
        return c;
    c.x = (int16_t)w.x;
    c.y = (int16_t)w.y;
    c.z = w.z;
    return c;
}

/* The fast path of the vertex cache, with a matrix (zl_vx, zl_internal.h). */
typedef zl_vx vx_setup;

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

/* Every matrix entry in range. */
static int matrix_in_limit(const zl_mat4 *m)
{
    int k;
    for (k = 0; k < 16; k++)
        if (!in_limit(m->m[k]))
            return 0;
    return 1;
}

/* 0 when a matrix entry is out of range: then every vertex is invalid. */
static int vx_prepare(const zl_source *s, vx_setup *vs)
{
    const zl_fixed *m = s->mvp->m;
    int k;
    if (!matrix_in_limit(s->mvp))
        return 0;
    for (k = 0; k < 16; k++)
        vs->m[k] = m[k];
    for (k = 0; k < 4; k++)
        vs->bias[k] = (int64_t)m[k * 4 + 3] * ZL_FX_ONE + 32768;
    vs->wd = s->width;
    vs->ht = s->height;
    vs->gx = (uint32_t)s->width + 2u * ZL_GUARD_PX;
    vs->gy = (uint32_t)s->height + 2u * ZL_GUARD_PX;
    vs->hx = s->width * (uint32_t)(ZL_SUB_ONE / 2);
    vs->hy = s->height * (uint32_t)(ZL_SUB_ONE / 2);
    vs->pfast = fast_bound(vs);
    vs->exact = s->state != NULL && ZL_DEPTH_MAPPED(s->state) ? s->state : NULL;
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
    int64_t acc = vs->bias[r] + (int64_t)m[0] * ZL_MESH_POS(p, 0) + (int64_t)m[1] * ZL_MESH_POS(p, 1) +
                  (int64_t)m[2] * ZL_MESH_POS(p, 2);
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

/* Row r of the transform, unrounded (2^-32 units): bias[r] holds 2^15 of rounding. */
static ZL_ALWAYS_INLINE int64_t vx_sum(const vx_setup *vs, int r, const zl_fixed *p)
{
    const zl_fixed *m = &vs->m[r * 4];
    return vs->bias[r] - 32768 + (int64_t)m[0] * ZL_MESH_POS(p, 0) + (int64_t)m[1] * ZL_MESH_POS(p, 1) +
           (int64_t)m[2] * ZL_MESH_POS(p, 2);
}

/* The residuals (zl_wvert fx, fy) of a cached vertex c, set up to its
 * snapped x and y, as clip_residuals makes them. Out of line: once per
 * vertex, and the transform's registers are free by then. */
static ZL_NOINLINE void vx_residuals(const vx_setup *vs, const zl_fixed *p, zl_cached_vertex *c)
{
    int64_t w, x, y;
    ZL_CV_SET_FINE(c, ZL_FINE_NONE, ZL_FINE_NONE);
    if (!ZL_FEATURE_EXACT_DEPTH || vs->exact == NULL)
        return; /* ZL_FINE_NONE: the snapped plane */
    w = vx_sum(vs, 3, p);
    x = vx_sum(vs, 0, p);
    y = vx_sum(vs, 1, p);
    ZL_CV_SET_FINE(c, fine_residual(x, w, vs->hx, x < 0, c->x), fine_residual(y, w, vs->hy, y > 0, c->y));
}

static ZL_NOINLINE zl_cached_vertex vx_cache(const vx_setup *vs, const zl_fixed *p)
{
    zl_cached_vertex c;
    int32_t x, y, z, w, wx, wy;
    c.x = ZL_CACHE_INVALID;
    c.y = 0;
    c.z = 0;
    ZL_CV_SET_FINE(&c, 0, 0);
    if (!in_limit(ZL_MESH_POS(p, 0)) || !in_limit(ZL_MESH_POS(p, 1)) || !in_limit(ZL_MESH_POS(p, 2)) ||
        !vx_row(vs, 0, p, &x) || !vx_row(vs, 1, p, &y) || !vx_row(vs, 2, p, &z) || !vx_row(vs, 3, p, &w))
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
    vx_residuals(vs, p, &c);
    if (vs->exact != NULL) {
        const zl_fixed *m = &vs->m[12];
        /* bias[3] holds 2^15 for the rounding: the sum itself is without it */
        c.z = depth_of_wsum(vs->exact, vs->bias[3] - 32768 + (int64_t)m[0] * ZL_MESH_POS(p, 0) +
                                           (int64_t)m[1] * ZL_MESH_POS(p, 1) + (int64_t)m[2] * ZL_MESH_POS(p, 2));
    } else {
        c.z = depth_q16((uint32_t)z, (uint32_t)w);
    }
    return c;
}

#if !ZL_MUL32_ONLY
/* Row r of the transform when no range check is needed (vs->pfast). */
static ZL_ALWAYS_INLINE int32_t vx_row_fast(const vx_setup *vs, int r, const zl_fixed *p)
{
    const zl_fixed *m = &vs->m[r * 4];
    int64_t acc = vs->bias[r] + (int64_t)m[0] * ZL_MESH_POS(p, 0) + (int64_t)m[1] * ZL_MESH_POS(p, 1) +
                  (int64_t)m[2] * ZL_MESH_POS(p, 2);
    return (int32_t)zl_floor_shift64(acc, 16); /* |acc| < 2^47 */
}
#endif

#if ZL_MUL32_ONLY
/* A position split for vx_row_split: p = h 2^16 + l, h = floor(p / 2^16)
 * (as uint32, mod 2^32), l in [0, 2^16). */
typedef struct {
    uint32_t h0, l0, h1, l1, h2, l2;
} vx_split;

/* One product of vx_row_split: m p = (m ph + mh pl) 2^16 + ml pl, into the
 * high sum *hi (multiples of 2^16, with floor(ml pl / 2^16)) and the low one. */
static ZL_ALWAYS_INLINE void split_mac(uint32_t *hi, uint32_t *lo, zl_fixed m, uint32_t ph, uint32_t pl)
{
    uint32_t u = ((uint32_t)m & 0xFFFFu) * pl;
    *hi += (uint32_t)m * ph + (uint32_t)zl_floor_shift32(m, 16) * pl + (u >> 16);
    *lo += u & 0xFFFFu;
}

/*
 * vx_row_fast in 32-bit products (ZL_MUL32_ONLY: no 64-bit multiply). With
 * p = ph 2^16 + pl and m = mh 2^16 + ml (ph, mh the floors of p / 2^16 and
 * m / 2^16; pl, ml in [0, 2^16)), each product is m p = (m ph + mh pl) 2^16
 * + ml pl, with ml pl < 2^32, so
 *   floor((m3 2^16 + 2^15 + sum m p) / 2^16)
 *     = m3 + sum (m ph + mh pl + floor(ml pl / 2^16))
 *       + floor((2^15 + sum (ml pl mod 2^16)) / 2^16)
 * exactly. The result fits int32 (the fast bound), so the sum taken mod 2^32
 * is it: three 32-bit multiplies a product instead of one __aeabi_lmul.
 */
static ZL_ALWAYS_INLINE int32_t vx_row_split(const vx_setup *vs, int r, const vx_split *ps)
{
    const zl_fixed *m = &vs->m[r * 4];
    uint32_t hi = (uint32_t)m[3], lo = 32768u;
    split_mac(&hi, &lo, m[0], ps->h0, ps->l0);
    split_mac(&hi, &lo, m[1], ps->h1, ps->l1);
    split_mac(&hi, &lo, m[2], ps->h2, ps->l2);
    return (int32_t)(hi + (lo >> 16));
}

/* a b + c into *out when it is below 2^32 (then 1, else 0), in 32-bit
 * products: the test (n >> 32) != 0 of vx_fast without a 64-bit multiply. */
static ZL_ALWAYS_INLINE int mul_add_32(uint32_t a, uint32_t b, uint32_t c, uint32_t *out)
{
    uint32_t small = a < b ? a : b, large = a < b ? b : a, t, lo;
    if ((small >> 16) != 0)
        return 0; /* both at least 2^16 */
    t = (large >> 16) * small;
    if ((t >> 16) != 0)
        return 0;
    lo = (large & 0xFFFFu) * small;
    t = (t << 16) + lo;
    if (t < lo)
        return 0;
    t += c;
    if (t < c)
        return 0;
    *out = t;
    return 1;
}
#endif

/*
 * vx_cache for the common vertex, same numbers, or 0 when it cannot tell
 * (then vx_cache decides). Positions within [-P, P): no range checks. With
 * n = |c| h and q = floor((n + off) / w), 0 <= off < w, as vx_window: q is
 * at least floor(n / w), so q < h + G 2^SUB gives n < (h + G 2^SUB) w,
 * which is the pair of x planes multiplied by 2^SUB / 2 (W |x| <= (W + 2G) w).
 * The window coordinate h -+ q is then in range when q < qx (qy).
 */
static ZL_ALWAYS_INLINE int vx_fast(const vx_setup *vs, const zl_fixed *p, zl_cached_vertex *c, int exact)
{
    uint32_t pf = vs->pfast, ax, ay, q;
    int32_t x, y, z, w, wx;
    int64_t wsum = 0;
#if ZL_MUL32_ONLY
    vx_split ps;
    uint32_t n;
#else
    uint64_t n;
#endif
    if ((((uint32_t)ZL_MESH_POS(p, 0) + pf) | ((uint32_t)ZL_MESH_POS(p, 1) + pf) |
         ((uint32_t)ZL_MESH_POS(p, 2) + pf)) >= 2u * pf)
        return 0;
#if ZL_MUL32_ONLY
    ps.h0 = (uint32_t)zl_floor_shift32(ZL_MESH_POS(p, 0), 16);
    ps.l0 = (uint32_t)ZL_MESH_POS(p, 0) & 0xFFFFu;
    ps.h1 = (uint32_t)zl_floor_shift32(ZL_MESH_POS(p, 1), 16);
    ps.l1 = (uint32_t)ZL_MESH_POS(p, 1) & 0xFFFFu;
    ps.h2 = (uint32_t)zl_floor_shift32(ZL_MESH_POS(p, 2), 16);
    ps.l2 = (uint32_t)ZL_MESH_POS(p, 2) & 0xFFFFu;
    if (exact) {
        wsum = vs->bias[3] + (int64_t)vs->m[12] * ZL_MESH_POS(p, 0) + (int64_t)vs->m[13] * ZL_MESH_POS(p, 1) +
               (int64_t)vs->m[14] * ZL_MESH_POS(p, 2);
        w = (int32_t)zl_floor_shift64(wsum, 16);
    } else {
        w = vx_row_split(vs, 3, &ps);
    }
    z = vx_row_split(vs, 2, &ps);
#else
    /* Each row where it is needed: the compiler keeps the order. */
    wsum = vs->bias[3] + (int64_t)vs->m[12] * ZL_MESH_POS(p, 0) + (int64_t)vs->m[13] * ZL_MESH_POS(p, 1) +
           (int64_t)vs->m[14] * ZL_MESH_POS(p, 2);
    w = (int32_t)zl_floor_shift64(wsum, 16); /* vx_row_fast of row 3 */
    z = vx_row_fast(vs, 2, p);
#endif
    if (w < 1 || (uint32_t)z > (uint32_t)w) {
        c->x = ZL_CACHE_COMPLEX; /* outside the w, near or far plane */
        c->y = 0;
        c->z = 0;
        ZL_CV_SET_FINE(c, 0, 0);
        return 1;
    }
#if ZL_MUL32_ONLY
    x = vx_row_split(vs, 0, &ps);
    ax = x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
    if (!mul_add_32(ax, vs->hx, ((uint32_t)w - (x < 0)) >> 1, &n))
        return 0;
#else
    x = vx_row_fast(vs, 0, p);
    ax = x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
    /* vx_window's offset: w/2, or w - 1 - w/2 = (w - 1)/2 for the negative side */
    n = (uint64_t)ax * vs->hx + (((uint32_t)w - (x < 0)) >> 1);
    if ((n >> 32) != 0)
        return 0;
#endif
    q = (uint32_t)n / (uint32_t)w;
    if (q >= vs->qx)
        return 0;
    wx = x < 0 ? (int32_t)vs->hx - (int32_t)q : (int32_t)(vs->hx + q);
#if ZL_MUL32_ONLY
    y = vx_row_split(vs, 1, &ps);
    ay = y < 0 ? 0u - (uint32_t)y : (uint32_t)y;
    if (!mul_add_32(ay, vs->hy, ((uint32_t)w - (y > 0)) >> 1, &n))
        return 0;
#else
    y = vx_row_fast(vs, 1, p);
    ay = y < 0 ? 0u - (uint32_t)y : (uint32_t)y;
    n = (uint64_t)ay * vs->hy + (((uint32_t)w - (y > 0)) >> 1); /* row 0 at the top: (w - y) h / w */
    if ((n >> 32) != 0)
        return 0;
#endif
    q = (uint32_t)n / (uint32_t)w;
    if (q >= vs->qy)
        return 0;
    c->x = (int16_t)wx;
    c->y = (int16_t)(y > 0 ? (int32_t)vs->hy - (int32_t)q : (int32_t)(vs->hy + q));
    if (exact)
        vx_residuals(vs, p, c);
    else
        ZL_CV_SET_FINE(c, ZL_FINE_NONE, ZL_FINE_NONE);
    /* the exact mapping from w's sum without bias[3]'s 2^15 of rounding */
    c->z = exact ? depth_of_wsum(vs->exact, wsum - 32768) : depth_q16((uint32_t)z, (uint32_t)w);
    return 1;
}

/*
 * Without the fast paths (ZL_FAST_PATHS=0, zl_config.h) every cached vertex
 * is cache_vertex_generic's: vx_cache computes the same vertex (the same
 * transform rows and their range, the same 7 planes, projection, residuals
 * and depth), faster, and its code goes. Invalid exactly when vx_cache's
 * is: a coordinate or matrix entry beyond the limits, or a row beyond
 * Q16.16 (zl_transform_point).
 */
int zl_vx_prepare(const zl_source *s, zl_vx *vx)
{
    if (!ZL_FAST_PATHS)
        return s->mvp == NULL || matrix_in_limit(s->mvp);
    return s->mvp == NULL || vx_prepare(s, vx);
}

void zl_vx_vertex(const zl_source *s, const zl_vx *vx, uint16_t idx, zl_cached_vertex *out)
{
    const zl_fixed *p = &s->mesh->positions[idx * 3u];
    if (s->mvp == NULL || !ZL_FAST_PATHS)
        *out = cache_vertex_generic(s, idx);
    else if (!vx_fast(vx, p, out, vx->exact != NULL))
        *out = vx_cache(vx, p);
}

zl_cached_vertex zl_cache_vertex(const zl_source *s, uint16_t idx)
{
    vx_setup vs;
    if (s->mvp == NULL || !ZL_FAST_PATHS)
        return cache_vertex_generic(s, idx);
    if (!vx_prepare(s, &vs)) {
        zl_cached_vertex c;
        c.x = ZL_CACHE_INVALID;
        c.y = 0;
        c.z = 0;
        ZL_CV_SET_FINE(&c, 0, 0);
        return c;
    }
    {
        const zl_fixed *p = &s->mesh->positions[idx * 3u];
        zl_cached_vertex c;
        if (!vx_fast(&vs, p, &c, vs.exact != NULL))
            c = vx_cache(&vs, p);
        return c;
    }
}

/* zl_cache_vertices with a matrix and without the fast paths: every vertex
 * by the definition (zl_vx_prepare's comment), none when a matrix entry is
 * out of range. */
static ZL_NOINLINE zl_status cache_by_definition(const zl_source *s, zl_cached_vertex *cache, uint16_t first,
                                                 uint16_t count)
{
    zl_status st = matrix_in_limit(s->mvp) ? ZL_OK : ZL_ERR_RANGE;
    uint32_t v;
    for (v = first; v < (uint32_t)first + count; v++) {
        cache[v] = cache_vertex_generic(s, (uint16_t)v); /* invalid throughout when the matrix is */
        if (cache[v].x == ZL_CACHE_INVALID)
            st = ZL_ERR_RANGE;
    }
    return st;
}

zl_status zl_cache_vertices(const zl_source *s, zl_cached_vertex *cache, uint16_t first, uint16_t count)
{
    zl_cached_vertex bad;
    const zl_fixed *p = &s->mesh->positions[first * 3u];
    zl_cached_vertex *c = &cache[first], *end = c + count;
    zl_status st = ZL_OK;
    vx_setup vs;
    bad.x = ZL_CACHE_INVALID;
    bad.y = 0;
    bad.z = 0;
    ZL_CV_SET_FINE(&bad, 0, 0);
    if (!ZL_FAST_PATHS && s->mvp != NULL)
        return cache_by_definition(s, cache, first, count);
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
    /* Two loops: vx_fast inlined once per depth mapping, no test a vertex. */
    if (vs.exact != NULL) {
        for (; c != end; c++, p += 3) {
            if (vx_fast(&vs, p, c, 1))
                continue;
            *c = vx_cache(&vs, p);
            if (c->x == ZL_CACHE_INVALID)
                st = ZL_ERR_RANGE;
        }
        return st;
    }
    for (; c != end; c++, p += 3) {
        if (vx_fast(&vs, p, c, 0))
            continue;
        *c = vx_cache(&vs, p);
        if (c->x == ZL_CACHE_INVALID)
            st = ZL_ERR_RANGE;
    }
    return st;
}
