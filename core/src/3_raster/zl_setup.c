/* SPDX-License-Identifier: MIT */
/*
 * Stage 3, raster: triangle set-up. Classify (cull, row range) and set up
 * (exact edge steppers and attribute planes) a window-space triangle, and the
 * polygon offset. Rows and spans are in zl_rows.c and zl_span.c.
 *
 * Coverage is decided exactly: at row j (centre y = 16 j + 8 subpixels) an
 * edge from (xt, yt) down to (xb, yb) crosses at
 *     xe = xt + (16 j + 8 - yt) * dx / dy,
 * and the first pixel whose centre is at or right of it is
 *     i = ceil((xe - 8) / 16) = ceil(N / D),
 *     N = (xt - 8) dy + (16 j + 8 - yt) dx,   D = 16 dy.
 * A left edge starts its span at i (centre on the edge: covered), a right edge
 * ends it before i (centre on the edge: not covered); rows run from the first
 * centre at or below the top vertex to the last centre above the bottom one.
 * That is the top-left rule, in integers, and because N/D depends only on the
 * edge's two endpoints, a shared edge splits its pixels identically for both
 * triangles.
 */
#include <string.h>

#include "zl_raster.h"

static ZL_SMALL_NOINLINE int64_t signed_area2(const zl_wvert *a, const zl_wvert *b, const zl_wvert *c)
{
    return ((int64_t)b->x - a->x) * ((int64_t)c->y - a->y) -
           ((int64_t)c->x - a->x) * ((int64_t)b->y - a->y);
}

int zl_tri_classify(const zl_wvert *a, const zl_wvert *b, const zl_wvert *c, const zl_state *st,
                    uint16_t width, uint16_t height, int32_t *first, int32_t *end)
{
    int64_t area = signed_area2(a, b, c);
    int front;
    int32_t xmin, xmax;
    if (area == 0)
        return 0;
    /* y grows down, so a positive area is clockwise as the viewer sees it. */
    front = (area < 0) == (st->front_face == ZL_FRONT_CCW);
    if ((st->cull == ZL_CULL_BACK && !front) || (st->cull == ZL_CULL_FRONT && front))
        return 0;
    *first = first_centre_at_or_after(min3(a->y, b->y, c->y));
    *end = first_centre_at_or_after(max3(a->y, b->y, c->y));
    if (*first < 0)
        *first = 0;
    if (*end > height)
        *end = height;
    if (*first >= *end)
        return 0;
    xmin = min3(a->x, b->x, c->x);
    xmax = max3(a->x, b->x, c->x);
    if (first_centre_at_or_after(xmin) >= width || first_centre_at_or_after(xmax) <= 0)
        return 0;
    return 1;
}

static void edge_init(zl_edge *e, const zl_wvert *top, const zl_wvert *bot, int32_t j)
{
    edge_init_xy(e, top->x, top->y, bot->x, bot->y, j);
}

/* round(s * 2^sh / c), c > 0, split into quotient and remainder so that no
 * intermediate exceeds 64 bits; saturates at +-limit. */
static int64_t muldiv_pow2_slow(int64_t s, unsigned sh, int64_t c, int64_t limit)
{
    int64_t q = s / c, r = s % c;
    if (q > (limit >> sh) || q < -(limit >> sh))
        return q > 0 ? limit : -limit;
    return clamp64(q * ((int64_t)1 << sh) + zl_round_div64(r * ((int64_t)1 << sh), c), -limit, limit);
}

/*
 * The same value, fast when the quotient fits 32 bits (every plane of an
 * ordinary triangle): one 64-by-32 division of |s| 2^sh, by the reciprocal
 * `inv` of c when the caller has one. round(x / c) is floor((x + h) / c)
 * with h = floor(c / 2); for x = -m < 0 that is -floor((m - h + c - 1) / c).
 * A quotient below 2^32 is far inside +-limit.
 */
static int64_t muldiv_pow2(int64_t s, unsigned sh, int64_t c, int64_t limit, const zl_div_inv *inv)
{
    uint64_t m, num;
    uint32_t c32, q;
    if (!ZL_FAST_PATHS || /* off: the division in 64 bits, the same value (zl_config.h) */
        c > UINT32_MAX || s > (INT64_MAX >> (sh + 1)) || s < -(INT64_MAX >> (sh + 1)))
        return muldiv_pow2_slow(s, sh, c, limit);
    c32 = (uint32_t)c;
    m = (uint64_t)(s < 0 ? -s : s) << sh;
    num = s < 0 ? m - c32 / 2u + c32 - 1u : m + c32 / 2u;
    if ((num >> 32) >= c32)
        return muldiv_pow2_slow(s, sh, c, limit);
    q = inv != NULL ? zl_div_inv_q(inv, num) : zl_udiv64_32(num, c32, NULL);
    return s < 0 ? -(int64_t)q : (int64_t)q;
}

/* plane_small for a general frame when its vertices are small. */
static int plane_fast(zl_attr *at, const plane_frame *pf, int64_t a0, int64_t a1, int64_t a2)
{
    small_frame f;
    int32_t d1, d2;
    if (pf->inv == NULL || !pf->small || !diff32(a1, a0, &d1) || !diff32(a2, a0, &d2))
        return 0;
    f.dx1 = (int32_t)pf->dx1;
    f.dy1 = (int32_t)pf->dy1;
    f.dx2 = (int32_t)pf->dx2;
    f.dy2 = (int32_t)pf->dy2;
    f.ox = (int32_t)pf->ox;
    f.oy = (int32_t)pf->oy;
    f.rows = pf->first - pf->ay;
    f.neg = pf->c < 0;
    f.c32 = pf->c32;
    f.inv = *pf->inv;
#if ZL_MUL32_ONLY
    if ((d1 | d2) != 0 && f.c32 < 65536u) /* round_div_small's reciprocal (see small_frame) */
        zl_div16_init(&f.d16, f.c32);
    else
        zl_div16_none(&f.d16);
#endif
    return plane_small(at, &f, a0, d1, d2);
}

/* Attribute plane through values a0, a1, a2 (Q16) at the sorted vertices. */
static void plane_setup(zl_attr *at, const plane_frame *pf, int64_t a0, int64_t a1, int64_t a2)
{
    const unsigned sh = ZL_SUB_BITS + (ZL_ATTR_FRAC - 16);
    int64_t da1 = a1 - a0, da2 = a2 - a0;
    /* Solve da = alpha dx + beta dy for both edges (Cramer): alpha = ga / c,
     * beta = gb / c; then make the denominator positive. */
    int64_t ga = da1 * pf->dy2 - da2 * pf->dy1;
    int64_t gb = pf->dx1 * da2 - pf->dx2 * da1;
    int64_t c = pf->c, base;
    if (ZL_FAST_PATHS && plane_fast(at, pf, a0, a1, a2)) /* the same values, cheaper (zl_config.h) */
        return;
    if (c < 0) {
        c = -c;
        ga = -ga;
        gb = -gb;
    }
    at->dx = muldiv_pow2(ga, sh, c, ZL_GRAD_LIMIT, pf->inv);
    at->dy = muldiv_pow2(gb, sh, c, ZL_GRAD_LIMIT, pf->inv);
    /* Value at the anchor pixel's centre, less than half a pixel from v0. */
    base = a0 * (1 << (ZL_ATTR_FRAC - 16)) +
           muldiv_pow2(ga * pf->ox + gb * pf->oy, ZL_ATTR_FRAC - 16, c, (int64_t)1 << 44, pf->inv);
    at->row = base + (int64_t)(pf->first - pf->ay) * at->dy;
}

/* ------------------------------------ the depth plane of the unsnapped triangle */

/* Bit length of v (0 for 0): CLZ where the compiler has it. */
static ZL_ALWAYS_INLINE unsigned bits64(uint64_t v)
{
    uint32_t hi = (uint32_t)(v >> 32), w = hi != 0 ? hi : (uint32_t)v;
    unsigned n = hi != 0 ? 32u : 0u;
#if defined(__GNUC__) && __SIZEOF_INT__ >= 4 /* __builtin_clz counts in an unsigned int */
    return w == 0 ? 0u : n + 32u - (unsigned)__builtin_clz(w);
#else
    while (w != 0) {
        w >>= 1;
        n++;
    }
    return n;
#endif
}

/*
 * round(g 2^k / c32) (zl_depth_plane_exact's gradients: c = c32 2^s, k
 * holds the -s): the numerator shifted left as far as 2^62 allows (exact),
 * divided by the reciprocal of c32 (>= 2^31, so any numerator below 2^63
 * qualifies), and the rest of the shift applied to the quotient (relative
 * error below 2^-30 then); saturated at ZL_GRAD_LIMIT.
 */
static int64_t scaled_quotient(int64_t g, const zl_div_inv *inv, uint32_t c32, int k)
{
    uint64_t m = g < 0 ? (uint64_t)0 - (uint64_t)g : (uint64_t)g;
    uint64_t q;
    int t;
    if (m == 0)
        return 0;
    if (k >= 0) {
        int whole; /* the shift reaches k: the rounding half c32 / 2 goes in */
        t = 62 - (int)bits64(m);
        whole = t >= k;
        if (whole)
            t = k;
        q = zl_div_inv_q(inv, (m << t) + (whole ? c32 / 2u : 0u));
        if (k - t >= 43 || (q >> (43 - (k - t))) != 0)
            q = (uint64_t)ZL_GRAD_LIMIT;
        else
            q <<= k - t;
    } else {
        q = zl_div_inv_q(inv, m); /* m < 2^63 */
        q = -k >= 40 ? 0 : (q + ((uint64_t)1 << (-k - 1))) >> -k;
    }
    if (q > (uint64_t)ZL_GRAD_LIMIT)
        q = (uint64_t)ZL_GRAD_LIMIT;
    return g < 0 ? -(int64_t)q : (int64_t)q;
}

int zl_depth_plane_exact(zl_attr *z, uint32_t *zlo, uint32_t *zhi, const zl_fine_vert *v, int32_t ax, int32_t ay,
                         int32_t first)
{
    const int64_t top = (int64_t)65535 << 16, slack = 256; /* Q16: the computed plane's rounding */
    int64_t x0 = (int64_t)v[0].x * (1 << ZL_FINE_BITS) + v[0].fx, y0 = (int64_t)v[0].y * (1 << ZL_FINE_BITS) + v[0].fy;
    int64_t dx1 = (int64_t)v[1].x * (1 << ZL_FINE_BITS) + v[1].fx - x0;
    int64_t dy1 = (int64_t)v[1].y * (1 << ZL_FINE_BITS) + v[1].fy - y0;
    int64_t dx2 = (int64_t)v[2].x * (1 << ZL_FINE_BITS) + v[2].fx - x0;
    int64_t dy2 = (int64_t)v[2].y * (1 << ZL_FINE_BITS) + v[2].fy - y0;
    int64_t c, d1 = (int64_t)v[1].z - v[0].z, d2 = (int64_t)v[2].z - v[0].z, ga, gb, gx, gy, ox, oy, margin, lo, hi;
    uint64_t ac;
    uint32_t c32, r = 0;
    zl_div_inv inv;
    int s, k;
    /* |dx|, |dy| below 2^17 subpixels: fine differences below 2^29.1, their
     * products (and c) below 2^59.2, ga and gb below 2^62.2 */
    for (k = 1; k < 3; k++)
        if (v[k].x - v[0].x <= -(INT32_C(1) << 17) || v[k].x - v[0].x >= (INT32_C(1) << 17) || v[k].y - v[0].y <= -(INT32_C(1) << 17) ||
            v[k].y - v[0].y >= (INT32_C(1) << 17))
            return 0;
    c = dx1 * dy2 - dx2 * dy1;
    if (c == 0)
        return 0;
    ga = d1 * dy2 - d2 * dy1;
    gb = dx1 * d2 - dx2 * d1;
    if (c < 0) {
        c = -c;
        ga = -ga;
        gb = -gb;
    }
    /* c = c32 2^s with c32 in [2^31, 2^32) (exact when s <= 0) */
    ac = (uint64_t)c;
    s = (int)bits64(ac) - 32;
    c32 = s >= 0 ? (uint32_t)(ac >> s) : (uint32_t)(ac << -s);
    zl_div_inv_init(&inv, c32);
    /* Q20 per pixel = g 2^(4 + 4 + ZL_FINE_BITS) / c: a pixel is 2^(4 + ZL_FINE_BITS) fine units */
    gx = scaled_quotient(ga, &inv, c32, ZL_SUB_BITS + ZL_FINE_BITS + (ZL_ATTR_FRAC - 16) - s);
    gy = scaled_quotient(gb, &inv, c32, ZL_SUB_BITS + ZL_FINE_BITS + (ZL_ATTR_FRAC - 16) - s);
    /* the anchor pixel's centre from v0, in fine units (below 2^18) */
    ox = ((int64_t)ax * ZL_SUB_ONE + ZL_SUB_HALF) * (1 << ZL_FINE_BITS) - x0;
    oy = ((int64_t)ay * ZL_SUB_ONE + ZL_SUB_HALF) * (1 << ZL_FINE_BITS) - y0;
    z->dx = gx;
    z->dy = gy;
    z->row = (int64_t)v[0].z * (1 << (ZL_ATTR_FRAC - 16)) +
             zl_floor_shift64(gx * ox + gy * oy + ((int64_t)1 << (ZL_SUB_BITS + ZL_FINE_BITS - 1)),
                              ZL_SUB_BITS + ZL_FINE_BITS) +
             (int64_t)(first - ay) * gy;
    /*
     * A pixel centre the snapped triangle covers is within max |f| (fine
     * units) of the unsnapped one on each axis, so the plane there is
     * within (|gx| + |gy|) max |f| of the vertex range: the clamp range.
     * When that leaves 0 .. 65535 by more than a quarter step, the span
     * loops' unclamped steps could leave it too: 0, the snapped plane.
     */
    for (k = 0; k < 3; k++) {
        uint32_t f = (uint32_t)(v[k].fx < 0 ? -v[k].fx : v[k].fx), g = (uint32_t)(v[k].fy < 0 ? -v[k].fy : v[k].fy);
        r = f > r ? f : r;
        r = g > r ? g : r;
    }
    margin = zl_floor_shift64(((gx < 0 ? -gx : gx) + (gy < 0 ? -gy : gy)) >> (ZL_ATTR_FRAC - 16), 0) * (int64_t)r;
    margin = (margin >> (ZL_SUB_BITS + ZL_FINE_BITS)) + slack;
    lo = (int64_t)(v[0].z < v[1].z ? v[0].z : v[1].z);
    lo = (int64_t)v[2].z < lo ? (int64_t)v[2].z : lo;
    hi = (int64_t)(v[0].z > v[1].z ? v[0].z : v[1].z);
    hi = (int64_t)v[2].z > hi ? (int64_t)v[2].z : hi;
    lo -= margin;
    hi += margin;
    if ((lo < 0 || hi > top) && margin >= ((int64_t)1 << 14))
        return 0;
    *zlo = (uint32_t)clamp64(lo, 0, top);
    *zhi = (uint32_t)clamp64(hi, 0, top);
    return 1;
}

static void sort3(const zl_wvert **v)
{
    const zl_wvert *t;
    if (v[1]->y < v[0]->y) {
        t = v[0];
        v[0] = v[1];
        v[1] = t;
    }
    if (v[2]->y < v[1]->y) {
        t = v[1];
        v[1] = v[2];
        v[2] = t;
    }
    if (v[1]->y < v[0]->y) {
        t = v[0];
        v[0] = v[1];
        v[1] = t;
    }
}

/* zl_depth_plane_exact of the sorted window vertices v (res: the residuals
 * of a, b, c, 6 values) into t. */
static int depth_plane_wvert(zl_active *t, const zl_wvert *const *v, const zl_wvert *a, const zl_wvert *b,
                             const int16_t *res, const plane_frame *pf)
{
    zl_fine_vert f[3];
    int k;
    for (k = 0; k < 3; k++) {
        unsigned i = v[k] == a ? 0u : (v[k] == b ? 2u : 4u);
        f[k].x = v[k]->x;
        f[k].y = v[k]->y;
        f[k].fx = res[i];
        f[k].fy = res[i + 1];
        f[k].z = v[k]->z;
    }
    return zl_depth_plane_exact(&t->z, &t->zlo, &t->zhi, f, pf->ax, pf->ay, pf->first);
}

/* The residuals of a, b, c (6 values into res) when they are the vertices
 * of poly, an unclipped triangle; else 0 (the snapped plane). */
static int poly_residuals(const zl_poly *poly, const zl_wvert *a, const zl_wvert *b, const zl_wvert *c, int16_t *res)
{
    const zl_wvert *v[3];
    int k;
    if (!ZL_FEATURE_EXACT_DEPTH) /* compiled out (zl_config.h): the exact plane's code goes */
        return 0;
    if (poly == NULL || poly->clipped || poly->n != 3)
        return 0;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    for (k = 0; k < 3; k++) {
        unsigned i = v[k] == &poly->v[0] ? 0u : (v[k] == &poly->v[1] ? 1u : (v[k] == &poly->v[2] ? 2u : 3u));
        if (i > 2u)
            return 0;
        if (poly->fx[i] == ZL_FINE_NONE)
            return 0;
        res[2 * k] = poly->fx[i];
        res[2 * k + 1] = poly->fy[i];
    }
    return 1;
}

int zl_tri_setup(zl_active *t, zl_gouraud *g, const zl_wvert *a, const zl_wvert *b,
                 const zl_wvert *c, const zl_poly *poly, const zl_state *st, uint16_t width,
                 uint16_t height)
{
    return zl_tri_setup_ex(t, g, NULL, NULL, a, b, c, poly, st, width, height);
}

int zl_style_needs_planes(const zl_style *sty)
{
    return sty != NULL &&
           ((sty->texture != NULL && sty->texcoords != NULL) || sty->persp_gouraud || sty->blend != ZL_BLEND_OFF);
}

/*
 * The frame of the texture planes through a triangle's vertices at their
 * unsnapped positions (issue 22: texels exact), in fine units (2^-16
 * pixel) as zl_depth_plane_exact's: one reciprocal of the cross product
 * for all of a triangle's texture planes. Vertices without residuals take
 * their snapped positions (residual 0), which still gains the planes' exact
 * gradients of the Q20 vertex values.
 */
typedef struct {
    int64_t dx1, dy1, dx2, dy2; /* edge vectors from v0, fine units (below 2^29.1) */
    int64_t ox, oy;             /* the anchor pixel's centre from v0, fine units */
    int32_t rows;               /* first - ay */
    uint32_t c32;               /* |c| = c32 2^s, c32 in [2^31, 2^32) */
    int s, neg;
    zl_div_inv inv;
} fine_frame;

/* fine_frame of the sorted vertices v with residuals fr (fx, fy of v[k] at
 * 2k, 2k + 1; NULL: none); 0 when it cannot take them (an edge of 8192
 * pixels or more, or degenerate): then the snapped plane_setup. */
static int fine_frame_init(fine_frame *ff, const zl_wvert *const *v, const int16_t *fr, const plane_frame *pf)
{
    int64_t x[3], y[3], c;
    uint64_t ac;
    int k;
    if (!pf->small || pf->c == 0)
        return 0;
    for (k = 0; k < 3; k++) {
        x[k] = (int64_t)v[k]->x * (1 << ZL_FINE_BITS) + (fr != NULL ? fr[2 * k] : 0);
        y[k] = (int64_t)v[k]->y * (1 << ZL_FINE_BITS) + (fr != NULL ? fr[2 * k + 1] : 0);
    }
    ff->dx1 = x[1] - x[0];
    ff->dy1 = y[1] - y[0];
    ff->dx2 = x[2] - x[0];
    ff->dy2 = y[2] - y[0];
    c = ff->dx1 * ff->dy2 - ff->dx2 * ff->dy1;
    if (c == 0)
        return 0;
    ff->neg = c < 0;
    ac = (uint64_t)(c < 0 ? -c : c);
    ff->s = (int)bits64(ac) - 32;
    ff->c32 = ff->s >= 0 ? (uint32_t)(ac >> ff->s) : (uint32_t)(ac << -ff->s);
    zl_div_inv_init(&ff->inv, ff->c32);
    ff->ox = pf->ox * (1 << ZL_FINE_BITS) - (x[0] - (int64_t)v[0]->x * (1 << ZL_FINE_BITS));
    ff->oy = pf->oy * (1 << ZL_FINE_BITS) - (y[0] - (int64_t)v[0]->y * (1 << ZL_FINE_BITS));
    ff->rows = pf->first - pf->ay;
    return 1;
}

/* The Q20 plane through values a0, a1, a2 of `frac` fraction bits (12 to
 * 20; |a| at most 2^31, so a difference times an edge vector, below
 * 2^32 2^29.1, keeps the cross products below 2^63) at the vertices of ff:
 * gradients rounded once from the exact quotients (zl_depth_plane_exact's),
 * the anchor value rounded once. */
static void fine_plane(zl_attr *at, const fine_frame *ff, int64_t a0, int64_t a1, int64_t a2, int frac)
{
    int64_t d1 = a1 - a0, d2 = a2 - a0;
    int64_t ga = d1 * ff->dy2 - d2 * ff->dy1, gb = ff->dx1 * d2 - ff->dx2 * d1;
    const int k = ZL_SUB_BITS + ZL_FINE_BITS + (ZL_ATTR_FRAC - frac) - ff->s;
    if (ff->neg) {
        ga = -ga;
        gb = -gb;
    }
    at->dx = scaled_quotient(ga, &ff->inv, ff->c32, k);
    at->dy = scaled_quotient(gb, &ff->inv, ff->c32, k);
    at->row = a0 * (1 << (ZL_ATTR_FRAC - frac)) +
              zl_floor_shift64(at->dx * ff->ox + at->dy * ff->oy + ((int64_t)1 << (ZL_SUB_BITS + ZL_FINE_BITS - 1)),
                               ZL_SUB_BITS + ZL_FINE_BITS) +
              (int64_t)ff->rows * at->dy;
}

/* The vertex values of texture coordinate c (tpoly->u or ->v, 1/256
 * texel) for the planes: as they are (affine: the planes take them as
 * Q(ZL_ATTR_FRAC - ZL_TEX_SHIFT), which is Q16 texels per ZL_ATTR_FRAC),
 * or u q / 2^20 (perspective, from q in Q20: units of 2^-16 q texel,
 * zl_internal.h). */
static void tex_values(int64_t *a, const int32_t *c, const size_t *idx, const int64_t *q, int persp)
{
    const unsigned sh = 44 - ZL_PERSP_SHIFT; /* with persp_recip's 2^44 / q: (u q / 2^sh) (2^44 / q) / 2^ZL_PERSP_SHIFT = u */
    int k;
    for (k = 0; k < 3; k++)
        a[k] = persp ? zl_floor_shift64(c[idx[k]] * q[k] + ((int64_t)1 << (sh - 1)), sh) : c[idx[k]];
}

/* The q, u and v planes through the unsnapped vertices (fr: residuals, or
 * NULL for the snapped positions); 0 when fine_frame_init cannot take the
 * triangle. Out of line, so that its frame is not on the stack of the
 * snapped path's divisions (Cortex-M0's stack bound). */
static ZL_NOINLINE int tex_planes_fine(zl_texplanes *tp, const zl_style *sty, const zl_wvert *const *v,
                                       const zl_tpoly *tpoly, const size_t *idx, const int64_t *q, const int16_t *fr,
                                       const plane_frame *pf)
{
    fine_frame ff;
    int64_t a[3];
    int persp = sty->tex_mapping == ZL_TEX_PERSPECTIVE;
    if (!fine_frame_init(&ff, v, fr, pf))
        return 0;
    fine_plane(&tp->q, &ff, q[0], q[1], q[2], 20);
    if (sty->texture != NULL && sty->texcoords != NULL) {
        tex_values(a, tpoly->u, idx, q, persp);
        fine_plane(&tp->u, &ff, a[0], a[1], a[2], persp ? ZL_ATTR_FRAC : ZL_ATTR_FRAC - ZL_TEX_SHIFT);
        tex_values(a, tpoly->v, idx, q, persp);
        fine_plane(&tp->v, &ff, a[0], a[1], a[2], persp ? ZL_ATTR_FRAC : ZL_ATTR_FRAC - ZL_TEX_SHIFT);
    }
    return 1;
}

/* The vertex values of tex_values as plane_setup takes them (Q16 for a Q20
 * plane): perspective ones rounded, affine ones moved up (their planes
 * step Q16 texels, zl_internal.h). */
static void tex_values_q16(int64_t *a, int persp)
{
    int k;
    for (k = 0; k < 3; k++)
        a[k] = persp ? zl_floor_shift64(a[k] + 8, 4) : a[k] * (1 << (ZL_TEX_SHIFT - 4));
}

/* The same through the snapped vertices (plane_setup: Q16 values). */
static void tex_planes_snapped(zl_texplanes *tp, const zl_style *sty, const zl_tpoly *tpoly, const size_t *idx,
                               const int64_t *q, const plane_frame *pf)
{
    int64_t a[3];
    int persp = sty->tex_mapping == ZL_TEX_PERSPECTIVE;
    plane_setup(&tp->q, pf, zl_floor_shift64(q[0] + 8, 4), zl_floor_shift64(q[1] + 8, 4), zl_floor_shift64(q[2] + 8, 4));
    if (sty->texture != NULL && sty->texcoords != NULL) {
        tex_values(a, tpoly->u, idx, q, persp);
        tex_values_q16(a, persp);
        plane_setup(&tp->u, pf, a[0], a[1], a[2]);
        tex_values(a, tpoly->v, idx, q, persp);
        tex_values_q16(a, persp);
        plane_setup(&tp->v, pf, a[0], a[1], a[2]);
    }
}

/* Texture and perspective planes (see zl_texplanes). q_k = 2^24 wmin / w_k:
 * 1/w up to a per-triangle scale, which cancels in (u q) / q. The vertex
 * values of q and u q are kept to Q20 (4 bits more than the Q16 the planes
 * take elsewhere) and the planes go through the unsnapped vertices (fr:
 * their residuals, or NULL), so that the texel is exact but within 1/64
 * texel of a boundary (zline.h, TEXTURES). */
static void tex_setup(zl_texplanes *tp, zl_gouraud *g, const zl_style *sty, const zl_wvert *const *v,
                      const zl_poly *poly, const plane_frame *pf, const zl_state *st, const int16_t *fr)
{
    /* poly is the p of a zl_tpoly (zl_tri_setup_ex's contract): the
     * attributes of vertex v[k] are at its index in poly->v. */
    const zl_tpoly *tpoly = (const zl_tpoly *)(const void *)poly;
    int64_t q[3], a[3], wmin;
    size_t idx[3];
    int k, ch;
    for (k = 0; k < 3; k++)
        idx[k] = (size_t)(v[k] - poly->v);
    wmin = tpoly->w[idx[0]] < tpoly->w[idx[1]] ? tpoly->w[idx[0]] : tpoly->w[idx[1]];
    wmin = wmin < tpoly->w[idx[2]] ? wmin : tpoly->w[idx[2]];
    for (k = 0; k < 3; k++) {
        q[k] = zl_round_div64(wmin << 28, tpoly->w[idx[k]]); /* Q20 */
        if (q[k] < 4096)
            q[k] = 4096; /* a w ratio beyond 2^16 inside one triangle */
    }
    tp->persp = 0;
    memset(&tp->u, 0, sizeof tp->u);
    memset(&tp->v, 0, sizeof tp->v);
    if (!tex_planes_fine(tp, sty, v, tpoly, idx, q, fr, pf))
        tex_planes_snapped(tp, sty, tpoly, idx, q, pf);
    if (g != NULL && sty->persp_gouraud && st->shading == ZL_SHADE_GOURAUD) {
        for (ch = 0; ch < 3; ch++) {
            for (k = 0; k < 3; k++) {
                int64_t cq = ch == 0 ? v[k]->r : (ch == 1 ? v[k]->g : v[k]->b);
                a[k] = zl_floor_shift64(cq * 256 * q[k] + ((int64_t)1 << 27), 28);
            }
            plane_setup(&g->c[ch], pf, a[0], a[1], a[2]);
        }
    }
}

int zl_tri_setup_ex(zl_active *t, zl_gouraud *g, zl_texplanes *tp, const zl_style *sty, const zl_wvert *a,
                    const zl_wvert *b, const zl_wvert *c, const zl_poly *poly, const zl_state *st,
                    uint16_t width, uint16_t height)
{
    int32_t first, end;
    if (!zl_tri_classify(a, b, c, st, width, height, &first, &end))
        return 0;
    zl_tri_setup_rows(t, g, tp, sty, a, b, c, poly, st, first, end);
    return 1;
}

void zl_tri_setup_rows(zl_active *t, zl_gouraud *g, zl_texplanes *tp, const zl_style *sty, const zl_wvert *a,
                       const zl_wvert *b, const zl_wvert *c, const zl_poly *poly, const zl_state *st, int32_t first,
                       int32_t end)
{
    int16_t res[6];
    zl_tri_setup_rows_res(t, g, tp, sty, a, b, c, poly, poly_residuals(poly, a, b, c, res) ? res : NULL, st, first,
                          end);
}

/* The reciprocal of plane_frame's cross product and its small-frame test
 * serve the fast paths' plane divisions and the texture planes; without
 * either (zl_config.h) they are not computed (plane_setup's general
 * division takes every plane). */
#define FRAME_EXTRAS (ZL_FAST_PATHS || ZL_FEATURE_TEXTURES || ZL_FEATURE_BLEND)

void zl_tri_setup_rows_res(zl_active *t, zl_gouraud *g, zl_texplanes *tp, const zl_style *sty, const zl_wvert *a,
                           const zl_wvert *b, const zl_wvert *c, const zl_poly *poly, const int16_t *res,
                           const zl_state *st, int32_t first, int32_t end)
{
    const zl_wvert *v[3];
    int32_t mid;
    int64_t cross;
    plane_frame pf;
    zl_div_inv inv;
    zl_edge upper;
    int long_left, k;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    sort3(v);
    cross = signed_area2(v[0], v[1], v[2]);
    long_left = cross > 0; /* v1 right of the long edge v0 -> v2 */
    mid = first_centre_at_or_after(v[1]->y);
    if (mid < first)
        mid = first;
    if (mid > end)
        mid = end;
    t->kind = ZL_KIND_TRI;
    t->row = (int16_t)first;
    t->mid = (int16_t)mid;
    t->end = (int16_t)end;
    t->lower_is_left = (uint8_t)!long_left;
    if (long_left)
        edge_init(&t->left, v[0], v[2], first);
    else
        edge_init(&t->right, v[0], v[2], first);
    if (mid < end)
        edge_init(&t->lower, v[1], v[2], mid);
    if (first < mid) {
        edge_init(&upper, v[0], v[1], first);
    } else {
        upper = t->lower;
    }
    if (long_left)
        t->right = upper;
    else
        t->left = upper;

    pf.dx1 = (int64_t)v[1]->x - v[0]->x;
    pf.dy1 = (int64_t)v[1]->y - v[0]->y;
    pf.dx2 = (int64_t)v[2]->x - v[0]->x;
    pf.dy2 = (int64_t)v[2]->y - v[0]->y;
    pf.c = cross;
    pf.inv = NULL;
    pf.c32 = 0;
    if (FRAME_EXTRAS && cross != 0 && cross >= -(int64_t)UINT32_MAX && cross <= (int64_t)UINT32_MAX) {
        pf.c32 = (uint32_t)(cross < 0 ? -cross : cross);
        zl_div_inv_init(&inv, pf.c32);
        pf.inv = &inv;
    }
    pf.small = FRAME_EXTRAS && pf.dx1 > -(INT32_C(1) << 17) && pf.dx1 < (INT32_C(1) << 17) &&
               pf.dy1 < (INT32_C(1) << 17) && pf.dx2 > -(INT32_C(1) << 17) && pf.dx2 < (INT32_C(1) << 17) &&
               pf.dy2 < (INT32_C(1) << 17); /* dy >= 0: the vertices are sorted by y */
    pf.ax = (int32_t)zl_floor_shift64(v[0]->x, ZL_SUB_BITS);
    pf.ay = (int32_t)zl_floor_shift64(v[0]->y, ZL_SUB_BITS);
    pf.ox = (int64_t)pf.ax * ZL_SUB_ONE + ZL_SUB_HALF - v[0]->x;
    pf.oy = (int64_t)pf.ay * ZL_SUB_ONE + ZL_SUB_HALF - v[0]->y;
    pf.first = first;
    t->ax = pf.ax;
    if (!ZL_FEATURE_EXACT_DEPTH || res == NULL || !depth_plane_wvert(t, v, a, b, res, &pf)) {
        plane_setup(&t->z, &pf, v[0]->z, v[1]->z, v[2]->z);
        t->zlo = v[0]->z;
        t->zhi = v[0]->z;
        for (k = 1; k < 3; k++) {
            if (v[k]->z < t->zlo)
                t->zlo = v[k]->z;
            if (v[k]->z > t->zhi)
                t->zhi = v[k]->z;
        }
    }
    t->dz14 = step32(t->z.dx, ZL_ATTR_FRAC - 14);
    if (poly != NULL) { /* NULL: the caller sets the colour and light itself */
        t->rgb[0] = poly->flat.r;
        t->rgb[1] = poly->flat.g;
        t->rgb[2] = poly->flat.b;
        t->light = poly->light;
    }
    if (g != NULL && st->shading == ZL_SHADE_GOURAUD) {
        /* Colours are Q8; the plane takes Q16. */
        plane_setup(&g->c[0], &pf, (int64_t)v[0]->r * 256, (int64_t)v[1]->r * 256, (int64_t)v[2]->r * 256);
        plane_setup(&g->c[1], &pf, (int64_t)v[0]->g * 256, (int64_t)v[1]->g * 256, (int64_t)v[2]->g * 256);
        plane_setup(&g->c[2], &pf, (int64_t)v[0]->b * 256, (int64_t)v[1]->b * 256, (int64_t)v[2]->b * 256);
    }
    if ((ZL_FEATURE_TEXTURES || ZL_FEATURE_BLEND) && tp != NULL && zl_style_needs_planes(sty)) {
        int16_t fr[6]; /* compiled out with both features (zl_config.h) */
        for (k = 0; k < 3 && res != NULL; k++) {
            unsigned i = v[k] == a ? 0u : (v[k] == b ? 2u : 4u);
            fr[2 * k] = res[i];
            fr[2 * k + 1] = res[i + 1];
        }
        tex_setup(tp, g, sty, v, poly, &pf, st, res != NULL ? fr : NULL);
    }
}

/* Q16 value (stored scale) of a Q20 plane anchored at the centre of pixel
 * (ax, ay), at subpixel position (x, y): whole pixels, then the 1/16
 * remainder, so that no product exceeds 2^61 (|dx|, |dy| <= 2^43, offsets
 * within the guard band). */
static int64_t plane_at(const zl_attr *p, int32_t ax, int32_t ay, int32_t x, int32_t y)
{
    int64_t ox = (int64_t)x - ((int64_t)ax * ZL_SUB_ONE + ZL_SUB_HALF);
    int64_t oy = (int64_t)y - ((int64_t)ay * ZL_SUB_ONE + ZL_SUB_HALF);
    int64_t v = p->row + zl_floor_shift64(ox, ZL_SUB_BITS) * p->dx + zl_floor_shift64(oy, ZL_SUB_BITS) * p->dy;
    v += zl_floor_shift64((ox & (ZL_SUB_ONE - 1)) * p->dx + (oy & (ZL_SUB_ONE - 1)) * p->dy, ZL_SUB_BITS);
    return zl_floor_shift64(v, ZL_ATTR_FRAC - 16);
}

int zl_tri_exact_depths3(const zl_poly *poly, const zl_wvert *a, const zl_wvert *b, const zl_wvert *c,
                         const int32_t x[3], const int32_t y[3], int64_t z[3])
{
    const zl_wvert *v[3];
    zl_fine_vert f[3];
    int16_t res[6];
    zl_attr p;
    uint32_t lo, hi;
    int k;
    if (!poly_residuals(poly, a, b, c, res))
        return 0;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    sort3(v); /* the set-up's order, so its rounding */
    for (k = 0; k < 3; k++) {
        unsigned i = v[k] == a ? 0u : (v[k] == b ? 2u : 4u);
        f[k].x = v[k]->x;
        f[k].y = v[k]->y;
        f[k].fx = res[i];
        f[k].fy = res[i + 1];
        f[k].z = v[k]->z;
    }
    if (!zl_depth_plane_exact(&p, &lo, &hi, f, 0, 0, 0))
        return 0;
    for (k = 0; k < 3; k++)
        z[k] = plane_at(&p, 0, 0, x[k], y[k]);
    return 1;
}

void zl_tri_set_planes(zl_active *t, zl_gouraud *g, const zl_wvert *a, const zl_wvert *b, const zl_wvert *c,
                       const zl_attr *z, const zl_attr *col, int wrap)
{
    const int64_t top = (int64_t)65535 << 16;
    const zl_wvert *v[3];
    int64_t lo, hi;
    int k;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    t->z = *z;
    t->dz14 = step32(z->dx, ZL_ATTR_FRAC - 14);
    /* Every covered centre is a convex combination of the three vertices,
     * so the plane there lies within its values at them. */
    lo = hi = plane_at(z, t->ax, t->row, v[0]->x, v[0]->y);
    for (k = 1; k < 3; k++) {
        int64_t e = plane_at(z, t->ax, t->row, v[k]->x, v[k]->y);
        lo = e < lo ? e : lo;
        hi = e > hi ? e : hi;
    }
    if (wrap && lo > -top && hi < 2 * top) {
        /* the inverted range: no clamp at span starts (zl_depth_start_q14);
         * the stepper stays within +-2^31 (Q14) */
        t->zlo = 0xFFFFFFFFu;
        t->zhi = 0;
    } else {
        t->zlo = (uint32_t)clamp64(lo - 1, 0, top);
        t->zhi = (uint32_t)clamp64(hi + 1, 0, top);
    }
    if (g != NULL && col != NULL) {
        g->c[0] = col[0];
        g->c[1] = col[1];
        g->c[2] = col[2];
    }
}

/* ------------------------------------------------------ polygon offset */

int64_t zl_tri_offset(const zl_wvert *a, const zl_wvert *b, const zl_wvert *c, const zl_style *sty)
{
    /* units * r: r is one stored step, 2^20 in Q20; units is Q16.16. */
    int64_t off;
    if (sty == NULL || (sty->offset_factor == 0 && sty->offset_units == 0))
        return 0;
    off = (int64_t)sty->offset_units * (1 << (ZL_ATTR_FRAC - 16));
    if (sty->offset_factor != 0) {
        /* The depth plane's gradients as plane_setup solves them (Cramer). */
        const unsigned sh = ZL_SUB_BITS + (ZL_ATTR_FRAC - 16);
        const int64_t limit = (int64_t)65535 << ZL_ATTR_FRAC; /* the whole range per pixel */
        int64_t dx1 = (int64_t)b->x - a->x, dy1 = (int64_t)b->y - a->y;
        int64_t dx2 = (int64_t)c->x - a->x, dy2 = (int64_t)c->y - a->y;
        int64_t da1 = (int64_t)b->z - a->z, da2 = (int64_t)c->z - a->z;
        int64_t ga = da1 * dy2 - da2 * dy1, gb = dx1 * da2 - dx2 * da1, cr = dx1 * dy2 - dx2 * dy1;
        int64_t mx, my, m;
        if (cr == 0)
            return off;
        if (cr < 0)
            cr = -cr;
        ga = ga < 0 ? -ga : ga;
        gb = gb < 0 ? -gb : gb;
        mx = muldiv_pow2(ga, sh, cr, limit, NULL);
        my = muldiv_pow2(gb, sh, cr, limit, NULL);
        m = mx > my ? mx : my;
        /* |factor| <= 2^24 and m <= 2^36: the product fits 64 bits. */
        off += zl_floor_shift64((int64_t)sty->offset_factor * m, 16);
    }
    return off;
}

int64_t zl_tri_offset_plane(const zl_attr *z, const zl_style *sty)
{
    const int64_t limit = (int64_t)65535 << ZL_ATTR_FRAC; /* as zl_tri_offset */
    int64_t off, mx, my;
    if (sty == NULL || (sty->offset_factor == 0 && sty->offset_units == 0))
        return 0;
    off = (int64_t)sty->offset_units * (1 << (ZL_ATTR_FRAC - 16));
    mx = z->dx < 0 ? -z->dx : z->dx;
    my = z->dy < 0 ? -z->dy : z->dy;
    mx = mx > my ? mx : my;
    mx = mx > limit ? limit : mx;
    /* |factor| <= 2^24 and mx <= 2^36: the product fits 64 bits. */
    return off + zl_floor_shift64((int64_t)sty->offset_factor * mx, 16);
}

void zl_tri_apply_offset(zl_active *t, int64_t offset)
{
    const int64_t top = (int64_t)65535 << 16;
    int64_t o16 = zl_floor_shift64(offset, ZL_ATTR_FRAC - 16);
    t->z.row += offset;
    if (t->zlo > t->zhi)
        return; /* a clipped piece without a clamp range (zl_tri_set_planes) */
    t->zlo = (uint32_t)clamp64((int64_t)t->zlo + o16, 0, top);
    t->zhi = (uint32_t)clamp64((int64_t)t->zhi + o16, 0, top);
}
