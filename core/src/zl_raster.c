/*
 * Triangle scan conversion: classify (cull, row range), setup (edge steppers
 * and attribute planes), and per-row span generation and fill.
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

#include "zl_internal.h"
#include "zl_span.h"

/* ceil(v / 2^SUB) of a subpixel coordinate minus the half-pixel offset:
 * the index of the first row (or column) whose centre is at or after v. */
static int32_t first_centre_at_or_after(int32_t v)
{
    /* Window coordinates stay below 2^23 (zl_config.h): 32 bits suffice. */
    return zl_floor_shift32(v - ZL_SUB_HALF + ZL_SUB_ONE - 1, ZL_SUB_BITS);
}

static int64_t signed_area2(const zl_wvert *a, const zl_wvert *b, const zl_wvert *c)
{
    return ((int64_t)b->x - a->x) * ((int64_t)c->y - a->y) -
           ((int64_t)c->x - a->x) * ((int64_t)b->y - a->y);
}

static int32_t min3(int32_t a, int32_t b, int32_t c)
{
    int32_t m = a < b ? a : b;
    return m < c ? m : c;
}

static int32_t max3(int32_t a, int32_t b, int32_t c)
{
    int32_t m = a > b ? a : b;
    return m > c ? m : c;
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

/* Start edge top -> bot (top->y < bot->y) at row j. Window coordinates stay
 * below 2^23, so dx, dy, 16 dy and 16 dx fit 32 bits; only N needs 64. When
 * N fits 32 bits too (every edge of an on-screen triangle), the quotients
 * are 32-bit divisions and the remainders, which lie in [0, 16 dy), are
 * exact in wrapping 32-bit arithmetic. */
static void edge_init_xy(zl_edge *e, int32_t xt, int32_t yt, int32_t xb, int32_t yb, int32_t j)
{
    int32_t dy = yb - yt, dx = xb - xt;
    int32_t d = dy * ZL_SUB_ONE, dx16 = dx * ZL_SUB_ONE;
    int64_t n = (int64_t)(xt - ZL_SUB_HALF) * dy + (int64_t)(j * ZL_SUB_ONE + ZL_SUB_HALF - yt) * dx;
    int32_t q, step;
    if (n > INT32_MIN && n <= INT32_MAX) {
        int32_t n32 = (int32_t)n;
        q = n32 / d;
        if (n32 % d > 0) /* ceil */
            q += 1;
    } else {
        q = (int32_t)zl_ceil_div64(n, d);
    }
    step = dx16 / d;
    if (dx16 % d < 0) /* floor */
        step -= 1;
    e->x = q;
    e->rem = (int32_t)((uint32_t)q * (uint32_t)d - (uint32_t)(uint64_t)n);
    e->den = d;
    e->step = step;
    e->rstep = (int32_t)((uint32_t)dx16 - (uint32_t)step * (uint32_t)d);
}

static void edge_init(zl_edge *e, const zl_wvert *top, const zl_wvert *bot, int32_t j)
{
    edge_init_xy(e, top->x, top->y, bot->x, bot->y, j);
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

static int64_t clamp64(int64_t v, int64_t lo, int64_t hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
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
    if (c > UINT32_MAX || s > (INT64_MAX >> (sh + 1)) || s < -(INT64_MAX >> (sh + 1)))
        return muldiv_pow2_slow(s, sh, c, limit);
    c32 = (uint32_t)c;
    m = (uint64_t)(s < 0 ? -s : s) << sh;
    num = s < 0 ? m - c32 / 2u + c32 - 1u : m + c32 / 2u;
    if ((num >> 32) >= c32)
        return muldiv_pow2_slow(s, sh, c, limit);
    q = inv != NULL ? zl_div_inv_q(inv, num) : zl_udiv64_32(num, c32, NULL);
    return s < 0 ? -(int64_t)q : (int64_t)q;
}

typedef struct {
    int64_t dx1, dy1, dx2, dy2, c; /* edge vectors from v0 and their cross product (!= 0) */
    int32_t ax, ay;                /* anchor pixel */
    int64_t ox, oy;                /* anchor centre minus v0, subpixels */
    int32_t first;
    const zl_div_inv *inv;            /* reciprocal of |c|, or NULL when |c| >= 2^32 */
    uint32_t c32;                  /* |c| when inv is set */
    int small;                     /* every |dx|, |dy| below 2^17 (int16 vertices) */
} plane_frame;

/* A triangle's plane frame in 32 bits, for vertices within the int16 range
 * (every cached vertex): edge vectors, anchor offsets and the reciprocal of
 * |cross| (which must then be below 2^32). */
typedef struct {
    int32_t dx1, dy1, dx2, dy2; /* v1 - v0, v2 - v0 of the sorted vertices */
    int32_t ox, oy;             /* anchor pixel centre minus v0, subpixels */
    int32_t rows;               /* first row minus the anchor row */
    int neg;                    /* the cross product is negative */
    uint32_t c32;               /* |cross| */
    zl_div_inv inv;             /* its reciprocal, set only when c32 >= 2^16 */
} small_frame;

/* round(x / c) as muldiv_pow2 rounds, by the frame's reciprocal; 0 when
 * the quotient would not fit 32 bits (then the caller takes the long way). */
static ZL_ALWAYS_INLINE int round_div_inv(int64_t x, const small_frame *f, int64_t *q)
{
    uint32_t c = f->c32, r;
    uint64_t m = x < 0 ? (uint64_t)0 - (uint64_t)x : (uint64_t)x;
    uint64_t num = x < 0 ? m + (c - 1u - c / 2u) : m + c / 2u;
    if ((num >> 32) >= c)
        return 0;
    r = zl_div_inv_q(&f->inv, num);
    *q = x < 0 ? -(int64_t)r : (int64_t)r;
    return 1;
}

/*
 * The same rounding for a divisor below 2^16 (the cross product of a
 * triangle of fewer than 128 square pixels, most of a real mesh):
 * schoolbook division in two 16-bit digits, two 32-bit divisions and no
 * reciprocal. 0 under the same condition as round_div_inv (a quotient of
 * 2^32 or more, which muldiv_pow2 might saturate), so the numerator is
 * below c 2^32 < 2^48.
 */
static ZL_ALWAYS_INLINE int round_div_small(int64_t x, uint32_t c, int64_t *q)
{
    uint64_t m = x < 0 ? (uint64_t)0 - (uint64_t)x : (uint64_t)x;
    uint64_t num = x < 0 ? m + (c - 1u - c / 2u) : m + c / 2u;
    uint32_t hi, q1, q0;
    if ((num >> 32) >= c)
        return 0;
    hi = (uint32_t)(num >> 16);
    q1 = hi / c;
    q0 = (((hi - q1 * c) << 16) | (uint32_t)(num & 0xFFFFu)) / c; /* the remainder is below 2^16 */
    m = ((uint64_t)q1 << 16) + q0;
    *q = x < 0 ? -(int64_t)m : (int64_t)m;
    return 1;
}

/* round(x / |cross|) by the cheaper of the two ways. */
static ZL_ALWAYS_INLINE int round_div_frame(int64_t x, const small_frame *f, int64_t *q)
{
    return f->c32 < 65536u ? round_div_small(x, f->c32, q) : round_div_inv(x, f, q);
}

/*
 * plane_setup's values in the common case: small vertices and value
 * differences d1 = a1 - a0, d2 = a2 - a0 within 32 bits, so ga and gb are
 * sums of two 32x32-bit products, every shifted numerator stays below 2^60,
 * and quotients that fit 32 bits (far inside the limits: no saturation).
 * Returns 0 without writing when a quotient does not fit.
 */
static ZL_ALWAYS_INLINE int plane_small(zl_attr *at, const small_frame *f, int64_t a0, int32_t d1, int32_t d2)
{
    int64_t ga = (int64_t)d1 * f->dy2 - (int64_t)d2 * f->dy1;
    int64_t gb = (int64_t)f->dx1 * d2 - (int64_t)f->dx2 * d1, dx, dy, off;
    if (f->neg) {
        ga = -ga;
        gb = -gb;
    }
    if (!round_div_frame(ga * (1 << (ZL_SUB_BITS + ZL_ATTR_FRAC - 16)), f, &dx) ||
        !round_div_frame(gb * (1 << (ZL_SUB_BITS + ZL_ATTR_FRAC - 16)), f, &dy) ||
        !round_div_frame((ga * f->ox + gb * f->oy) * (1 << (ZL_ATTR_FRAC - 16)), f, &off))
        return 0;
    at->dx = dx;
    at->dy = dy;
    at->row = a0 * (1 << (ZL_ATTR_FRAC - 16)) + off + (int64_t)f->rows * dy;
    return 1;
}

/* The difference a1 - a0 as 32 bits, or 0 when it does not fit. */
static int diff32(int64_t a1, int64_t a0, int32_t *d)
{
    int64_t v = a1 - a0;
    if (v < -INT32_MAX || v > INT32_MAX)
        return 0;
    *d = (int32_t)((uint32_t)a1 - (uint32_t)a0); /* the low words: 32x32 multiplies follow */
    return 1;
}

/* diff32 of two depths (uint32, Q16) in 32-bit arithmetic: the wrapped
 * difference is the true one exactly when its sign agrees with the
 * comparison. */
static ZL_ALWAYS_INLINE int depth_diff32(uint32_t a1, uint32_t a0, int32_t *d)
{
    int32_t v = (int32_t)(a1 - a0);
    if ((a1 >= a0) != (v >= 0) || v == INT32_MIN)
        return 0;
    *d = v;
    return 1;
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
    if (plane_fast(at, pf, a0, a1, a2))
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

/* Per-pixel step of a Q20 gradient as a 32-bit stepper of `frac` bits.
 * Only spans of 2+ pixels step, and there the gradient is bounded by the
 * value range, so the clamp never bites where it matters. */
static uint32_t step32(int64_t d, unsigned shift)
{
    return (uint32_t)(int32_t)clamp64(zl_floor_shift64(d, shift), -((int64_t)1 << 30), (int64_t)1 << 30);
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

int zl_tri_setup(zl_active *t, zl_gouraud *g, const zl_wvert *a, const zl_wvert *b,
                 const zl_wvert *c, const zl_poly *poly, const zl_state *st, uint16_t width,
                 uint16_t height)
{
    return zl_tri_setup_ex(t, g, NULL, NULL, a, b, c, poly, st, width, height);
}

int zl_style_needs_planes(const zl_style *sty)
{
    return sty != NULL && ((sty->texture != NULL && sty->texcoords != NULL) || sty->persp_gouraud);
}

/* Texture and perspective planes (see zl_texplanes). q_k = 2^24 wmin / w_k:
 * 1/w up to a per-triangle scale, which cancels in (u q) / q. */
static void tex_setup(zl_texplanes *tp, zl_gouraud *g, const zl_style *sty, const zl_wvert *const *v,
                      const zl_poly *poly, const plane_frame *pf, const zl_state *st)
{
    /* poly is the p of a zl_tpoly (zl_tri_setup_ex's contract): the
     * attributes of vertex v[k] are at its index in poly->v. */
    const zl_tpoly *tpoly = (const zl_tpoly *)(const void *)poly;
    int64_t q[3], a[3], b[3], u[3], vv[3], w[3], wmin;
    int k, persp = sty->tex_mapping == ZL_TEX_PERSPECTIVE;
    for (k = 0; k < 3; k++) {
        size_t i = (size_t)(v[k] - poly->v);
        u[k] = tpoly->u[i];
        vv[k] = tpoly->v[i];
        w[k] = tpoly->w[i];
    }
    wmin = w[0] < w[1] ? w[0] : w[1];
    wmin = wmin < w[2] ? wmin : w[2];
    for (k = 0; k < 3; k++) {
        q[k] = zl_round_div64(wmin << 24, w[k]);
        if (q[k] < 256)
            q[k] = 256; /* a w ratio beyond 2^16 inside one triangle */
    }
    plane_setup(&tp->q, pf, q[0], q[1], q[2]);
    memset(&tp->u, 0, sizeof tp->u);
    memset(&tp->v, 0, sizeof tp->v);
    if (sty->texture != NULL && sty->texcoords != NULL) {
        for (k = 0; k < 3; k++) {
            a[k] = persp ? zl_floor_shift64(u[k] * q[k] + ((int64_t)1 << 23), 24) : u[k];
            b[k] = persp ? zl_floor_shift64(vv[k] * q[k] + ((int64_t)1 << 23), 24) : vv[k];
        }
        plane_setup(&tp->u, pf, a[0], a[1], a[2]);
        plane_setup(&tp->v, pf, b[0], b[1], b[2]);
    }
    if (g != NULL && sty->persp_gouraud && st->shading == ZL_SHADE_GOURAUD) {
        int ch;
        for (ch = 0; ch < 3; ch++) {
            for (k = 0; k < 3; k++) {
                int64_t cq = ch == 0 ? v[k]->r : (ch == 1 ? v[k]->g : v[k]->b);
                a[k] = zl_floor_shift64(cq * 256 * q[k] + ((int64_t)1 << 23), 24);
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
    if (cross != 0 && cross >= -(int64_t)UINT32_MAX && cross <= (int64_t)UINT32_MAX) {
        pf.c32 = (uint32_t)(cross < 0 ? -cross : cross);
        zl_div_inv_init(&inv, pf.c32);
        pf.inv = &inv;
    }
    pf.small = pf.dx1 > -(1 << 17) && pf.dx1 < (1 << 17) && pf.dy1 < (1 << 17) && pf.dx2 > -(1 << 17) &&
               pf.dx2 < (1 << 17) && pf.dy2 < (1 << 17); /* dy >= 0: the vertices are sorted by y */
    pf.ax = (int32_t)zl_floor_shift64(v[0]->x, ZL_SUB_BITS);
    pf.ay = (int32_t)zl_floor_shift64(v[0]->y, ZL_SUB_BITS);
    pf.ox = (int64_t)pf.ax * ZL_SUB_ONE + ZL_SUB_HALF - v[0]->x;
    pf.oy = (int64_t)pf.ay * ZL_SUB_ONE + ZL_SUB_HALF - v[0]->y;
    pf.first = first;
    t->ax = pf.ax;
    plane_setup(&t->z, &pf, v[0]->z, v[1]->z, v[2]->z);
    t->dz14 = step32(t->z.dx, ZL_ATTR_FRAC - 14);
    t->zlo = v[0]->z;
    t->zhi = v[0]->z;
    for (k = 1; k < 3; k++) {
        if (v[k]->z < t->zlo)
            t->zlo = v[k]->z;
        if (v[k]->z > t->zhi)
            t->zhi = v[k]->z;
    }
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
    if (tp != NULL && zl_style_needs_planes(sty))
        tex_setup(tp, g, sty, v, poly, &pf, st);
}

/* Start value at column x of a Q20 attribute, clamped to [lo, hi]. */
static int64_t attr_at(const zl_attr *a, int32_t x, int32_t ax, int64_t lo, int64_t hi)
{
    return clamp64(a->row + (int64_t)(x - ax) * a->dx, lo, hi);
}

/* depth_start's value from the plane value v at the span start: the clamp
 * moved after the shift (floor division is monotone, so clamping v to
 * [zlo 16, zhi 16] and then shifting equals shifting and then clamping to
 * [zlo / 4, zhi / 4]), so it is 32-bit work whenever v is in range. */
static ZL_ALWAYS_INLINE uint32_t depth_start_shifted(int64_t v, uint32_t lo14, uint32_t hi14)
{
    int64_t w = zl_floor_shift64(v, ZL_ATTR_FRAC - 14);
    uint32_t z = w < 0 ? 0u : (w > (int64_t)hi14 ? hi14 : (uint32_t)w);
    return (z < lo14 ? lo14 : z) + (1u << 13);
}

/* The depth stepper (Q14, rounding half added) at column x of the current
 * row: the Q20 plane clamped to the vertex range (zlo, zhi are Q16, so the
 * range after the shift is zlo / 4 .. zhi / 4). */
static ZL_ALWAYS_INLINE uint32_t depth_start(const zl_active *t, int64_t zrow, int32_t x)
{
    return depth_start_shifted(zrow + (int64_t)(x - t->ax) * t->z.dx, t->zlo >> 2, t->zhi >> 2);
}

static void row_span(const zl_active *t, const zl_gouraud *g, const zl_span_state *ss, uint8_t *crow,
                     uint16_t *zrow)
{
    int32_t x0 = t->left.x, x1 = t->right.x;
    uint32_t z, dz;
    if (x0 < 0)
        x0 = 0;
    if (x1 > ss->width)
        x1 = ss->width;
    if (x0 >= x1)
        return;
    z = depth_start(t, t->z.row, x0);
    dz = t->dz14;
    crow = crow ? crow + (size_t)x0 * ss->bpp : NULL;
    zrow = zrow ? zrow + x0 : NULL;
    /* A NULL row is an absent buffer, for which zl_span_state_init chose
     * bpp 0 (colour) or ZL_ALWAYS without depth write (depth): said here
     * too, so that no path to a pixel write can see a NULL row (static
     * analysis, tools/lint/run.sh). */
    if ((crow == NULL && ss->bpp != 0) || (zrow == NULL && (ss->zwrite || ss->func != ZL_ALWAYS)))
        return;
    if (g != NULL && ss->gouraud) {
        uint32_t c[3], dc[3];
        int k;
        for (k = 0; k < 3; k++) {
            int64_t v = attr_at(&g->c[k], x0, t->ax, 0, (int64_t)255 << ZL_ATTR_FRAC);
            c[k] = (uint32_t)zl_floor_shift64(v, ZL_ATTR_FRAC - 16) + (1u << 15);
            dc[k] = step32(g->c[k].dx, ZL_ATTR_FRAC - 16);
        }
        zl_span_gouraud(ss, crow, zrow, x1 - x0, z, dz, c, dc);
    } else {
        uint8_t pix[3] = {0, 0, 0};
        pack_color((zl_format)ss->format, t->rgb[0], t->rgb[1], t->rgb[2], pix);
        zl_span_flat(ss, crow, zrow, x1 - x0, z, dz, pix);
    }
}

/* Sort three cached vertices by y with sort3's comparisons (so the same
 * order on ties), and find their rows [first, end) in a target of `height`
 * rows and the row `mid` where the lower short edge takes over. 0 when no
 * row is in the target. */
static ZL_ALWAYS_INLINE int cached_rows(const zl_cached_vertex **v, uint16_t height, int32_t *first, int32_t *mid,
                                        int32_t *end)
{
    const zl_cached_vertex *t;
    int32_t m;
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
    *first = first_centre_at_or_after(v[0]->y);
    *end = first_centre_at_or_after(v[2]->y);
    if (*first < 0)
        *first = 0;
    if (*end > height)
        *end = height;
    m = first_centre_at_or_after(v[1]->y);
    *mid = m < *first ? *first : (m > *end ? *end : m);
    return *first < *end;
}

/* The rest of a small frame, once its edge vectors are in: the divisor
 * |cross| (below 2^32) and its reciprocal where round_div_frame uses one,
 * and the anchor pixel of the sorted v0. Returns the anchor column. */
static ZL_ALWAYS_INLINE int32_t small_frame_anchor(small_frame *f, const zl_cached_vertex *v0, int32_t first,
                                                   int64_t cross)
{
    int32_t ax = zl_floor_shift32(v0->x, ZL_SUB_BITS), ay = zl_floor_shift32(v0->y, ZL_SUB_BITS);
    f->neg = cross < 0;
    f->c32 = (uint32_t)(cross < 0 ? -cross : cross);
    f->ox = ax * ZL_SUB_ONE + ZL_SUB_HALF - v0->x;
    f->oy = ay * ZL_SUB_ONE + ZL_SUB_HALF - v0->y;
    f->rows = first - ay;
    if (f->c32 >= 65536u) /* round_div_frame uses the reciprocal only then */
        zl_div_inv_init(&f->inv, f->c32);
    return ax;
}

/* zl_tri_setup_flat's triangle by the general setup (zl_tri_classify and
 * zl_tri_setup_rows on window vertices), for numbers beyond 32 bits. Out of
 * line, so the common case does not carry its frame. */
static ZL_NOINLINE int setup_flat_general(zl_active *t, const zl_cached_vertex *const *c, const zl_state *st,
                                          uint16_t width, uint16_t height)
{
    zl_wvert w[3];
    int32_t first, end;
    unsigned k;
    for (k = 0; k < 3; k++) {
        w[k].x = c[k]->x;
        w[k].y = c[k]->y;
        w[k].z = c[k]->z;
        w[k].r = 0; /* vertex colours only matter to Gouraud shading */
        w[k].g = 0;
        w[k].b = 0;
    }
    if (!zl_tri_classify(&w[0], &w[1], &w[2], st, width, height, &first, &end))
        return 0;
    zl_tri_setup_rows(t, NULL, NULL, NULL, &w[0], &w[1], &w[2], NULL, st, first, end);
    return 1;
}

/*
 * The 32-bit setup of zl_tri_setup_flat: 1 set up, 0 no row or column in
 * the target, -1 when its numbers leave the 32-bit shortcuts (|cross| >=
 * 2^32, depth differences beyond 2^31, a quotient beyond 32 bits).
 */
static int setup_flat_32(zl_active *t, const zl_cached_vertex *a, const zl_cached_vertex *b,
                         const zl_cached_vertex *c, uint16_t width, uint16_t height)
{
    const zl_cached_vertex *v[3], *v0, *v1, *v2;
    int32_t first, end, mid, ax, d1, d2;
    int64_t cross;
    small_frame f;
    zl_edge upper;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    if (!cached_rows(v, height, &first, &mid, &end) || first_centre_at_or_after(min3(a->x, b->x, c->x)) >= width ||
        first_centre_at_or_after(max3(a->x, b->x, c->x)) <= 0)
        return 0;
    v0 = v[0];
    v1 = v[1];
    v2 = v[2];
    f.dx1 = v1->x - v0->x;
    f.dy1 = v1->y - v0->y;
    f.dx2 = v2->x - v0->x;
    f.dy2 = v2->y - v0->y;
    cross = (int64_t)f.dx1 * f.dy2 - (int64_t)f.dx2 * f.dy1;
    if (cross < -(int64_t)UINT32_MAX || cross > (int64_t)UINT32_MAX || !depth_diff32(v1->z, v0->z, &d1) ||
        !depth_diff32(v2->z, v0->z, &d2))
        return -1;
    ax = small_frame_anchor(&f, v0, first, cross);
    if (!plane_small(&t->z, &f, v0->z, d1, d2))
        return -1;
    t->kind = ZL_KIND_TRI;
    t->row = (int16_t)first;
    t->mid = (int16_t)mid;
    t->end = (int16_t)end;
    t->lower_is_left = (uint8_t)(cross <= 0);
    edge_init_xy(cross > 0 ? &t->left : &t->right, v0->x, v0->y, v2->x, v2->y, first);
    if (mid < end)
        edge_init_xy(&t->lower, v1->x, v1->y, v2->x, v2->y, mid);
    if (first < mid)
        edge_init_xy(&upper, v0->x, v0->y, v1->x, v1->y, first);
    else
        upper = t->lower;
    if (cross > 0)
        t->right = upper;
    else
        t->left = upper;
    t->ax = ax;
    t->dz14 = step32(t->z.dx, ZL_ATTR_FRAC - 14);
    t->zlo = v0->z < v1->z ? v0->z : v1->z;
    t->zlo = v2->z < t->zlo ? v2->z : t->zlo;
    t->zhi = v0->z > v1->z ? v0->z : v1->z;
    t->zhi = v2->z > t->zhi ? v2->z : t->zhi;
    return 1;
}

int zl_tri_setup_flat(zl_active *t, const zl_cached_vertex *a, const zl_cached_vertex *b,
                      const zl_cached_vertex *c, const zl_state *st, uint16_t width, uint16_t height)
{
    int set = setup_flat_32(t, a, b, c, width, height);
    if (set >= 0)
        return set;
    {
        const zl_cached_vertex *v[3];
        v[0] = a;
        v[1] = b;
        v[2] = c;
        return setup_flat_general(t, v, st, width, height);
    }
}


/* ---------------------------------------- small flat triangles, frame mode */

/* Spans up to this many pixels are filled in place by the row loops below;
 * longer ones go to zl_span_flat, whose loops pay a set-up to run faster
 * per pixel. */
#define ZL_SHORT_SPAN 6

/*
 * A cached flat triangle drawn without a zl_active record, for the common
 * frame-mode case: every number of it fits 32 bits. Its edges are not
 * stepped by the DDA of zl_edge but evaluated per row, x(j) = ceil(N(j) /
 * D) with N(j) = N(first) + (j - first) 16 dx: the same quotient the DDA
 * keeps, from one division, and a set-up of three numbers per edge instead
 * of two divisions and two products. For the small triangles of a real mesh
 * (a few rows each) that is the cheaper side of the trade.
 */
/* The edge from (xt, yt) down to (xb, yb) from row j0 on. The caller has
 * checked the triangle's bound (zl_tiny_setup), so N fits 32 bits. */
static ZL_ALWAYS_INLINE void tiny_edge_init(zl_tiny_edge *e, int32_t xt, int32_t yt, int32_t xb, int32_t yb,
                                            int32_t j0)
{
    int32_t dy = yb - yt, dx = xb - xt;
    e->n = (xt - ZL_SUB_HALF) * dy + (j0 * ZL_SUB_ONE + ZL_SUB_HALF - yt) * dx;
    e->inc = dx * ZL_SUB_ONE;
    e->d = dy * ZL_SUB_ONE;
}

/* ceil(n / d), d > 0: C division truncates, which is the ceiling below 0. */
static ZL_ALWAYS_INLINE int32_t tiny_x(int32_t n, int32_t d)
{
    int32_t q = n / d;
    return q * d < n ? q + 1 : q;
}

/*
 * The depth plane of a small triangle in 32 bits. A row's span starts at a
 * pixel centre inside the triangle, where the exact plane lies within the
 * vertex range [zlo, zhi] and the rounded one within 2^10 of it (half a
 * unit of gradient per pixel and row from the anchor, at most 2^13 of
 * them). Relative to off, the largest multiple of 64 (Q20) not above the
 * lowest vertex depth, that value fits 32 bits when zhi - zlo < 2^25, and
 * floor(v / 64) = floor((v - off) / 64) + off / 64 keeps the shift exact.
 * The row and gradient values themselves may be anything (far outside the
 * triangle for a sliver): they are kept modulo 2^32, which leaves a sum
 * that fits exact. 0 when the depth range is too wide.
 */
static void tiny_depth(zl_tiny *tt, const zl_attr *z, uint32_t zlo, uint32_t zhi)
{
    uint32_t off = (zlo >> 2) << (ZL_ATTR_FRAC - 14); /* the low word of off, which is all that matters */
    tt->zr = (uint32_t)(uint64_t)z->row - off;
    tt->zdy = (uint32_t)(uint64_t)z->dy;
    tt->zdx = (uint32_t)(uint64_t)z->dx;
    tt->zlo = (int32_t)((zlo << (ZL_ATTR_FRAC - 16)) - off); /* 0 .. 63 */
    tt->zhi = (int32_t)((zhi << (ZL_ATTR_FRAC - 16)) - off);
    tt->zbase = (zlo >> 2) + (1u << 13);
    /* step32 of a gradient below 2^32 (plane_small's quotients): no clamp */
    tt->dz14 = (uint32_t)zl_floor_shift64(z->dx, ZL_ATTR_FRAC - 14);
}

int zl_tiny_setup(zl_tiny *tt, const zl_cached_vertex *a, const zl_cached_vertex *b, const zl_cached_vertex *c,
                  uint16_t width, uint16_t height)
{
    const zl_cached_vertex *v[3], *v0, *v1, *v2;
    int32_t first, end, mid, ax, d1, d2, cross;
    uint32_t zlo, zhi;
    small_frame f;
    zl_attr z;
    /* zl_tri_classify's column test is left out: a triangle entirely left or
     * right of the target clamps every span to nothing in the row loop, so
     * it draws the same nothing, and on-screen meshes save the test. */
    (void)width;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    if (!cached_rows(v, height, &first, &mid, &end))
        return 0;
    v0 = v[0];
    v1 = v[1];
    v2 = v[2];
    f.dx1 = v1->x - v0->x;
    f.dy1 = v1->y - v0->y;
    f.dx2 = v2->x - v0->x;
    f.dy2 = v2->y - v0->y;
    /* Every |x| below 2^13 and a height below 2^13 subpixels: then each edge's
     * N = (xt - 8) dy + (16 j + 8 - yt) dx, on its rows, stays below
     * 2^13 (2^13 + 8 + 2^14) < 2^28 in magnitude, the cross product below
     * 2^29, and 32-bit arithmetic is exact. */
    zlo = v0->z < v1->z ? (v0->z < v2->z ? v0->z : v2->z) : (v1->z < v2->z ? v1->z : v2->z);
    zhi = v0->z > v1->z ? (v0->z > v2->z ? v0->z : v2->z) : (v1->z > v2->z ? v1->z : v2->z);
    if (a->x <= -8192 || a->x >= 8192 || b->x <= -8192 || b->x >= 8192 || c->x <= -8192 || c->x >= 8192 ||
        f.dy2 >= 8192 || zhi - zlo >= (1u << 25)) /* (tiny_depth's bound) */
        return -1;
    d1 = (int32_t)(v1->z - v0->z); /* below 2^25 in magnitude */
    d2 = (int32_t)(v2->z - v0->z);
    tiny_edge_init(&tt->lng, v0->x, v0->y, v2->x, v2->y, first);
    if (first < mid) /* only edges with rows are read */
        tiny_edge_init(&tt->up, v0->x, v0->y, v1->x, v1->y, first);
    if (mid < end)
        tiny_edge_init(&tt->low, v1->x, v1->y, v2->x, v2->y, mid);
    cross = f.dx1 * f.dy2 - f.dx2 * f.dy1;
    ax = small_frame_anchor(&f, v0, first, cross);
    if (!plane_small(&z, &f, v0->z, d1, d2))
        return -1;
    tiny_depth(tt, &z, zlo, zhi);
    tt->ax = ax;
    tt->first = first;
    tt->mid = mid;
    tt->end = end;
    tt->long_left = cross > 0;
    return 1;
}

/* Rows [j, j_end) between the long edge and one short edge (RGB565, depth
 * test func with writes); returns the long edge's N after them. */
static ZL_ALWAYS_INLINE int32_t tiny_rows(const zl_tiny *tt, const zl_span_state *ss, unsigned func, int long_left,
                                          int32_t j, int32_t j_end, int32_t nl, const zl_tiny_edge *se,
                                          uint8_t *color, int32_t color_stride, uint8_t *depth,
                                          int32_t depth_stride, uint16_t pixel, uint32_t *zrow)
{
    const int32_t dl = tt->lng.d, il = tt->lng.inc, ds = se->d, is = se->inc, width = ss->width;
    int32_t ns = se->n;
    uint32_t zr = *zrow;
    color += (size_t)j * (size_t)color_stride;
    depth += (size_t)j * (size_t)depth_stride;
    for (; j < j_end; j++) {
        int32_t xa = tiny_x(nl, dl), xb = tiny_x(ns, ds);
        int32_t x0 = long_left ? xa : xb, x1 = long_left ? xb : xa;
        x0 = x0 < 0 ? 0 : x0;
        x1 = x1 > width ? width : x1;
        if (x0 < x1) {
            uint16_t *cp = (uint16_t *)(void *)color + x0, *zb = (uint16_t *)(void *)depth + x0;
            /* the depth start of depth_start_shifted, in 32 bits (tiny_depth):
             * wrapping arithmetic, exact because the sum fits */
            int32_t v = (int32_t)(zr + (uint32_t)(x0 - tt->ax) * tt->zdx);
            uint32_t zq;
            int32_t i, n = x1 - x0;
            v = v < tt->zlo ? tt->zlo : (v > tt->zhi ? tt->zhi : v);
            zq = ((uint32_t)v >> (ZL_ATTR_FRAC - 14)) + tt->zbase;
            if (n > ZL_SHORT_SPAN) {
                uint8_t pix[3] = {0, 0, 0};
                memcpy(pix, &pixel, 2);
                zl_span_flat(ss, (uint8_t *)cp, zb, n, zq, tt->dz14, pix);
            } else {
                /* No clamp: these pixels are inside the triangle, where the
                 * plane is within the vertex range; the start is within 2^10
                 * (Q20) of it and each of at most ZL_SHORT_SPAN - 1 steps
                 * within one Q14 unit, so zq stays within 32 (Q14) of
                 * [0, 65535 2^14] + 2^13: below 2^30, where depth_of is a
                 * shift. (A gradient step32 clamped cannot have two pixels
                 * inside a triangle.) */
                for (i = 0; i < n; i++) {
                    uint32_t d = zq >> 14;
                    if (depth_pass(func, d, zb[i])) {
                        zb[i] = (uint16_t)d;
                        cp[i] = pixel;
                    }
                    zq += tt->dz14;
                }
            }
        }
        nl += il;
        ns += is;
        zr += tt->zdy;
        color += color_stride;
        depth += depth_stride;
    }
    *zrow = zr;
    return nl;
}

static ZL_ALWAYS_INLINE void tiny_draw(const zl_tiny *tt, const zl_span_state *ss, unsigned func, int long_left,
                                       uint8_t *color, int32_t color_stride, uint8_t *depth, int32_t depth_stride,
                                       uint16_t pixel)
{
    uint32_t zrow = tt->zr;
    int32_t nl = tt->lng.n;
    if (tt->first < tt->mid)
        nl = tiny_rows(tt, ss, func, long_left, tt->first, tt->mid, nl, &tt->up, color, color_stride, depth,
                       depth_stride, pixel, &zrow);
    if (tt->mid < tt->end)
        (void)tiny_rows(tt, ss, func, long_left, tt->mid, tt->end, nl, &tt->low, color, color_stride, depth,
                        depth_stride, pixel, &zrow);
}

void zl_tiny_draw(const zl_tiny *tt, const zl_span_state *ss, uint8_t *color, int32_t color_stride, uint8_t *depth,
                  int32_t depth_stride, uint16_t pixel)
{
    /* func and the side of the long edge as constants: four loops */
    if (ss->func == ZL_LESS) {
        if (tt->long_left)
            tiny_draw(tt, ss, ZL_LESS, 1, color, color_stride, depth, depth_stride, pixel);
        else
            tiny_draw(tt, ss, ZL_LESS, 0, color, color_stride, depth, depth_stride, pixel);
    } else {
        if (tt->long_left)
            tiny_draw(tt, ss, ZL_LEQUAL, 1, color, color_stride, depth, depth_stride, pixel);
        else
            tiny_draw(tt, ss, ZL_LEQUAL, 0, color, color_stride, depth, depth_stride, pixel);
    }
}

int zl_tiny_span_state(const zl_span_state *ss, const void *color, int32_t color_stride, const void *depth)
{
    return color != NULL && depth != NULL && ss->format == ZL_FORMAT_RGB565 && ss->bpp == 2 && ss->zwrite &&
           ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)color & 1u) == 0 && (color_stride & 1) == 0 &&
           (ss->func == ZL_LESS || ss->func == ZL_LEQUAL);
}


/*
 * The rows of a flat triangle in the common case: RGB565 (native order,
 * aligned rows, every channel), depth test `func` (LESS or LEQUAL, a
 * constant at each call) with depth writes. Short spans are written here,
 * pixel by pixel exactly as zl_span_flat writes them (the depth clamp
 * included); the loop keeps the edges' positions and errors in locals.
 */
static ZL_ALWAYS_INLINE void rows_flat_565(const zl_active *t, const zl_span_state *ss, unsigned func,
                                           uint8_t *color, int32_t color_stride, uint8_t *depth,
                                           int32_t depth_stride, const uint8_t *pix, int32_t dx32)
{
    int32_t lx = t->left.x, lrem = t->left.rem, rx = t->right.x, rrem = t->right.rem;
    const zl_edge *le = &t->left, *re = &t->right;
    int32_t row = t->row, width = ss->width;
    int64_t zrow = t->z.row;
    uint32_t dz = t->dz14, lo14 = t->zlo >> 2, hi14 = t->zhi >> 2; /* the clamp range after the shift */
    uint16_t pixel;
    memcpy(&pixel, pix, 2);
    color += (size_t)row * (size_t)color_stride;
    depth += (size_t)row * (size_t)depth_stride;
    for (;;) {
        int32_t x0 = lx < 0 ? 0 : lx, x1 = rx > width ? width : rx, n = x1 - x0;
        if (n > 0) {
            uint16_t *c = (uint16_t *)(void *)color + x0, *zb = (uint16_t *)(void *)depth + x0;
            uint32_t z = depth_start_shifted(zrow + (int64_t)(x0 - t->ax) * dx32, lo14, hi14);
            if (n > ZL_SHORT_SPAN) {
                zl_span_flat(ss, (uint8_t *)c, zb, n, z, dz, pix);
            } else {
                int32_t i;
                for (i = 0; i < n; i++) {
                    uint32_t d = depth_of(z);
                    if (depth_pass(func, d, zb[i])) {
                        zb[i] = (uint16_t)d;
                        c[i] = pixel;
                    }
                    z += dz;
                }
            }
        }
        if (++row >= t->end)
            return;
        /* edge_step on the locals */
        lx += le->step;
        lrem -= le->rstep;
        if (lrem < 0) {
            lrem += le->den;
            lx++;
        }
        rx += re->step;
        rrem -= re->rstep;
        if (rrem < 0) {
            rrem += re->den;
            rx++;
        }
        zrow += t->z.dy;
        color += color_stride;
        depth += depth_stride;
        if (row == t->mid) {
            if (t->lower_is_left) {
                le = &t->lower;
                lx = le->x;
                lrem = le->rem;
            } else {
                re = &t->lower;
                rx = re->x;
                rrem = re->rem;
            }
        }
    }
}

/*
 * Every row of a flat-shaded triangle into a whole target (frame mode): the
 * same spans as zl_tri_row row by row, with the edges and the depth row in
 * locals, so a row costs its span and two edge steps. The record is left
 * as set up. Rows are color_stride / depth_stride bytes apart; a NULL
 * buffer is one the span state does not write (zl_span_state_init).
 */
void zl_tri_rows_flat(const zl_active *t, const zl_span_state *ss, uint8_t *color, int32_t color_stride,
                      uint8_t *depth, int32_t depth_stride)
{
    zl_edge left = t->left, right = t->right;
    int64_t zrow = t->z.row;
    int32_t row = t->row, width = ss->width;
    unsigned bpp = ss->bpp;
    uint8_t pix[3] = {0, 0, 0};
    if ((color == NULL && bpp != 0) || (depth == NULL && (ss->zwrite || ss->func != ZL_ALWAYS)))
        return; /* as in row_span */
    pack_color((zl_format)ss->format, t->rgb[0], t->rgb[1], t->rgb[2], pix);
    if (color != NULL && depth != NULL && ss->format == ZL_FORMAT_RGB565 && bpp == 2 && ss->zwrite &&
        ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)color & 1u) == 0 && (color_stride & 1) == 0 &&
        t->z.dx >= INT32_MIN && t->z.dx <= INT32_MAX) {
        if (ss->func == ZL_LESS) {
            rows_flat_565(t, ss, ZL_LESS, color, color_stride, depth, depth_stride, pix, (int32_t)t->z.dx);
            return;
        }
        if (ss->func == ZL_LEQUAL) {
            rows_flat_565(t, ss, ZL_LEQUAL, color, color_stride, depth, depth_stride, pix, (int32_t)t->z.dx);
            return;
        }
    }
    if (color != NULL)
        color += (size_t)row * (size_t)color_stride;
    if (depth != NULL)
        depth += (size_t)row * (size_t)depth_stride;
    for (;;) {
        int32_t x0 = left.x < 0 ? 0 : left.x, x1 = right.x > width ? width : right.x;
        if (x0 < x1)
            zl_span_flat(ss, color != NULL ? color + (size_t)x0 * bpp : NULL,
                         depth != NULL ? (uint16_t *)(void *)depth + x0 : NULL, x1 - x0, depth_start(t, zrow, x0),
                         t->dz14, pix);
        if (++row >= t->end)
            return;
        edge_step(&left);
        edge_step(&right);
        zrow += t->z.dy;
        if (color != NULL)
            color += color_stride;
        if (depth != NULL)
            depth += depth_stride;
        if (row == t->mid) {
            if (t->lower_is_left)
                left = t->lower;
            else
                right = t->lower;
        }
    }
}

int zl_tri_row(zl_active *t, zl_gouraud *g, const zl_span_state *ss, uint8_t *color_row,
               uint16_t *depth_row)
{
    int k;
    row_span(t, g, ss, color_row, depth_row);
    edge_step(&t->left);
    edge_step(&t->right);
    t->z.row += t->z.dy;
    if (g != NULL && ss->gouraud)
        for (k = 0; k < 3; k++)
            g->c[k].row += g->c[k].dy;
    t->row++;
    if (t->row == t->mid && t->row < t->end) {
        if (t->lower_is_left)
            t->left = t->lower;
        else
            t->right = t->lower;
    }
    return t->row < t->end;
}

/* ------------------------------------------------- textures, perspective */

/* One texel coordinate (1/256 texel) to a wrapped or clamped texel index. */
static inline uint32_t texel_index(int64_t c8, uint16_t size, unsigned wrap)
{
    int64_t i = zl_floor_shift64(c8, 8);
    if (wrap == ZL_WRAP_CLAMP)
        return (uint32_t)(i < 0 ? 0 : (i >= size ? size - 1 : i));
    return (uint32_t)i & (uint32_t)(size - 1u); /* two's complement: modulo a power of two */
}

/* (a q) / q for the perspective planes: one reciprocal R = 2^44 / Q and a
 * multiplication; Q (q times 16) is clamped to 2^12 .. 2^29 so R fits 32
 * bits and a R fits 64. */
static inline uint64_t persp_recip(int64_t q)
{
    if (q < ((int64_t)1 << 12))
        q = (int64_t)1 << 12;
    if (q > ((int64_t)1 << 29))
        q = (int64_t)1 << 29;
    return ((uint64_t)1 << 44) / (uint64_t)q;
}

static inline int64_t persp_apply(int64_t a, uint64_t r)
{
    return zl_floor_shift64(a * (int64_t)r, 20);
}

static void unpack565(uint16_t t, unsigned *r, unsigned *g, unsigned *b)
{
    unsigned r5 = t >> 11, g6 = (t >> 5) & 63u, b5 = t & 31u;
    *r = (r5 << 3) | (r5 >> 2);
    *g = (g6 << 2) | (g6 >> 4);
    *b = (b5 << 3) | (b5 >> 2);
}

/* Whether an affine coordinate plane (Q12 texels, stepped per pixel) stays
 * within +-2^30 over a span of n pixels: then 32 bits hold it exactly. */
static int affine_fits(int64_t a, int64_t da, int32_t n)
{
    const int64_t lim = (int64_t)1 << 30;
    int64_t end = a + (int64_t)(n - 1) * da;
    return a > -lim && a < lim && end > -lim && end < lim && da > -lim && da < lim;
}

static inline uint16_t texel_at(const zl_texture *tex, int64_t u8, int64_t v8)
{
    return tex->texels[(size_t)texel_index(v8, tex->height, tex->wrap_t) * tex->stride +
                       texel_index(u8, tex->width, tex->wrap_s)];
}

static inline void span_tex565(unsigned func, const zl_texture *tex, int persp, unsigned every, unsigned shift,
                               uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz, int64_t U,
                               int64_t dU, int64_t V, int64_t dV, int64_t Q, int64_t dQ)
{
    int32_t i;
    if (!persp) {
        /* affine: 32-bit steppers (affine_fits checked the range) */
        int32_t u = (int32_t)U, du = (int32_t)dU, v = (int32_t)V, dv = (int32_t)dV;
        for (i = 0; i < n; i++) {
            uint32_t d = depth_of(z);
            if (depth_pass(func, d, zrow[i])) {
                zrow[i] = (uint16_t)d;
                crow[i] = texel_at(tex, zl_floor_shift64(u, 4), zl_floor_shift64(v, 4));
            }
            z += dz;
            u += du;
            v += dv;
        }
        return;
    }
    {
        int64_t u8 = 0, v8 = 0, su = 0, sv = 0;
        for (i = 0; i < n; i++) {
            uint32_t d = depth_of(z);
            if (every == 1) {
                uint64_t r = persp_recip(Q);
                u8 = persp_apply(U, r);
                v8 = persp_apply(V, r);
            } else if ((i & (int32_t)(every - 1)) == 0) {
                uint64_t r = persp_recip(Q), r2 = persp_recip(Q + (int64_t)every * dQ);
                u8 = persp_apply(U, r);
                v8 = persp_apply(V, r);
                su = zl_floor_shift64(persp_apply(U + (int64_t)every * dU, r2) - u8, shift);
                sv = zl_floor_shift64(persp_apply(V + (int64_t)every * dV, r2) - v8, shift);
            }
            if (depth_pass(func, d, zrow[i])) {
                zrow[i] = (uint16_t)d;
                crow[i] = texel_at(tex, u8, v8);
            }
            z += dz;
            Q += dQ;
            U += dU;
            V += dV;
            u8 += su;
            v8 += sv;
        }
    }
}

static void row_span_ex(const zl_active *t, const zl_gouraud *g, const zl_texplanes *tp, const zl_style *sty,
                        const zl_span_state *ss, uint8_t *crow, uint16_t *zrow)
{
    const zl_texture *tex = sty->texcoords != NULL ? sty->texture : NULL;
    const int64_t f16 = 1 << (ZL_ATTR_FRAC - 16), big = (int64_t)1 << 40;
    int32_t x0 = t->left.x, x1 = t->right.x, i, n;
    int persp = sty->tex_mapping == ZL_TEX_PERSPECTIVE, pg = g != NULL && ss->gouraud;
    unsigned every = sty->tex_every > 1 ? sty->tex_every : 1u, shift = 0, func = ss->func, light = t->light;
    uint32_t z, dz;
    int64_t U = 0, V = 0, Q, dU = 0, dV = 0, dQ, C[3] = {0, 0, 0}, dC[3] = {0, 0, 0};
    int64_t u8 = 0, v8 = 0, su = 0, sv = 0;
    uint8_t pix[3] = {0, 0, 0};
    int k;
    if (x0 < 0)
        x0 = 0;
    if (x1 > ss->width)
        x1 = ss->width;
    if (x0 >= x1)
        return;
    n = x1 - x0;
    while ((1u << shift) < every)
        shift++;
    z = (uint32_t)zl_floor_shift64(attr_at(&t->z, x0, t->ax, (int64_t)t->zlo * f16, (int64_t)t->zhi * f16),
                                   ZL_ATTR_FRAC - 14) + (1u << 13);
    dz = step32(t->z.dx, ZL_ATTR_FRAC - 14);
    Q = attr_at(&tp->q, x0, t->ax, -big, big);
    dQ = tp->q.dx;
    if (tex != NULL) {
        U = attr_at(&tp->u, x0, t->ax, -big, big);
        V = attr_at(&tp->v, x0, t->ax, -big, big);
        dU = tp->u.dx;
        dV = tp->v.dx;
    }
    if (pg)
        for (k = 0; k < 3; k++) {
            C[k] = attr_at(&g->c[k], x0, t->ax, -big, big);
            dC[k] = g->c[k].dx;
        }
    crow = crow ? crow + (size_t)x0 * ss->bpp : NULL;
    zrow = zrow ? zrow + x0 : NULL;
    if ((crow == NULL && ss->bpp != 0) || (zrow == NULL && (ss->zwrite || func != ZL_ALWAYS)))
        return; /* as in row_span */
    if (tex != NULL && light == 255 && ss->format == ZL_FORMAT_RGB565 && ss->bpp == 2 && ss->zwrite &&
        ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)crow & 1u) == 0 && (func == ZL_LESS || func == ZL_LEQUAL) &&
        (persp || (affine_fits(U, dU, n) && affine_fits(V, dV, n)))) {
        /* The common case in its own loop: the texel is the pixel (RGB565,
         * unlit, all channels), depth LESS or LEQUAL with writes; the same
         * values as the general loop below, computed with fewer steps. */
        if (func == ZL_LESS)
            span_tex565(ZL_LESS, tex, persp, every, shift, (uint16_t *)(void *)crow, zrow, n, z, dz, U, dU, V, dV, Q, dQ);
        else
            span_tex565(ZL_LEQUAL, tex, persp, every, shift, (uint16_t *)(void *)crow, zrow, n, z, dz, U, dU, V, dV, Q,
                        dQ);
        return;
    }
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (tex != NULL) {
            if (!persp) {
                u8 = zl_floor_shift64(U, 4);
                v8 = zl_floor_shift64(V, 4);
            } else if (every == 1) {
                uint64_t r = persp_recip(Q);
                u8 = persp_apply(U, r);
                v8 = persp_apply(V, r);
            } else if ((i & (int32_t)(every - 1)) == 0) {
                /* exact here and N pixels on; linear steps between */
                uint64_t r = persp_recip(Q), r2 = persp_recip(Q + (int64_t)every * dQ);
                u8 = persp_apply(U, r);
                v8 = persp_apply(V, r);
                su = zl_floor_shift64(persp_apply(U + (int64_t)every * dU, r2) - u8, shift);
                sv = zl_floor_shift64(persp_apply(V + (int64_t)every * dV, r2) - v8, shift);
            }
        }
        if (func == ZL_ALWAYS || depth_pass(func, d, zrow[i])) {
            if (ss->zwrite)
                zrow[i] = (uint16_t)d;
            if (ss->bpp != 0) {
                unsigned r, gg, b;
                if (tex != NULL) {
                    uint16_t tx = tex->texels[(size_t)texel_index(v8, tex->height, tex->wrap_t) * tex->stride +
                                              texel_index(u8, tex->width, tex->wrap_s)];
                    unpack565(tx, &r, &gg, &b);
                    if (light != 255) {
                        r = (r * light + 127) / 255;
                        gg = (gg * light + 127) / 255;
                        b = (b * light + 127) / 255;
                    }
                } else if (pg) {
                    /* perspective Gouraud: (c q) / q, c in Q16 of 0..255 */
                    uint64_t rq = persp_recip(Q);
                    int64_t cc[3];
                    for (k = 0; k < 3; k++) {
                        cc[k] = zl_floor_shift64(persp_apply(C[k], rq) + (1 << 15), 16);
                        cc[k] = cc[k] < 0 ? 0 : (cc[k] > 255 ? 255 : cc[k]);
                    }
                    r = (unsigned)cc[0];
                    gg = (unsigned)cc[1];
                    b = (unsigned)cc[2];
                } else {
                    r = t->rgb[0];
                    gg = t->rgb[1];
                    b = t->rgb[2];
                }
                pack_color((zl_format)ss->format, r, gg, b, pix);
                put_pixel(crow + (size_t)i * ss->bpp, ss->bpp, pix, ss->keep);
            }
        }
        z += dz;
        Q += dQ;
        U += dU;
        V += dV;
        u8 += su;
        v8 += sv;
        for (k = 0; k < 3; k++)
            C[k] += dC[k];
    }
}

int zl_tri_row_ex(zl_active *t, zl_gouraud *g, zl_texplanes *tp, const zl_style *sty, const zl_span_state *ss,
                  uint8_t *color_row, uint16_t *depth_row)
{
    int k;
    if (tp == NULL || !zl_style_needs_planes(sty))
        return zl_tri_row(t, g, ss, color_row, depth_row);
    row_span_ex(t, sty->persp_gouraud ? g : NULL, tp, sty, ss, color_row, depth_row);
    edge_step(&t->left);
    edge_step(&t->right);
    t->z.row += t->z.dy;
    if (g != NULL && ss->gouraud)
        for (k = 0; k < 3; k++)
            g->c[k].row += g->c[k].dy;
    tp->u.row += tp->u.dy;
    tp->v.row += tp->v.dy;
    tp->q.row += tp->q.dy;
    t->row++;
    if (t->row == t->mid && t->row < t->end) {
        if (t->lower_is_left)
            t->left = t->lower;
        else
            t->right = t->lower;
    }
    return t->row < t->end;
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

void zl_tri_apply_offset(zl_active *t, int64_t offset)
{
    const int64_t top = (int64_t)65535 << 16;
    int64_t o16 = zl_floor_shift64(offset, ZL_ATTR_FRAC - 16);
    t->z.row += offset;
    t->zlo = (uint32_t)clamp64((int64_t)t->zlo + o16, 0, top);
    t->zhi = (uint32_t)clamp64((int64_t)t->zhi + o16, 0, top);
}

/* ------------------------------------------------------ lines and points */

/* Stored depth of a Q32 line depth, clamped to the range. */
static inline uint32_t line_depth(int64_t zq32)
{
    int64_t d = zl_floor_shift64(zq32 + ((int64_t)1 << 31), 32);
    return (uint32_t)clamp64(d, 0, 65535);
}

static inline void plot(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t x, uint32_t d,
                        const uint8_t *pix)
{
    unsigned func = ss->func;
    if (x < 0 || x >= ss->width)
        return;
    if (func != ZL_ALWAYS && !depth_pass(func, d, zrow[x]))
        return;
    if (ss->zwrite)
        zrow[x] = (uint16_t)d;
    if (ss->bpp != 0)
        put_pixel(crow + (size_t)x * ss->bpp, ss->bpp, pix, ss->keep);
}

/* Blend colour (r, g, b) into pixel x with weight w (0..255), after the
 * depth test; antialiased lines never write depth. */
static void blend(const zl_span_state *ss, const zl_active *t, uint8_t *crow, uint16_t *zrow, int32_t x, uint32_t d,
                  unsigned w)
{
    uint8_t *p, pix[3] = {0, 0, 0};
    unsigned old[3], k;
    if (w == 0 || x < 0 || x >= ss->width || ss->bpp == 0)
        return;
    if (ss->func != ZL_ALWAYS && !depth_pass(ss->func, d, zrow[x]))
        return;
    p = crow + (size_t)x * ss->bpp;
    if (ss->format == ZL_FORMAT_RGB888) {
        old[0] = p[0];
        old[1] = p[1];
        old[2] = p[2];
    } else {
        uint16_t v;
        unsigned r5, g6, b5;
        if (ss->format == ZL_FORMAT_RGB565)
            memcpy(&v, p, 2);
        else
            v = (uint16_t)(((unsigned)p[0] << 8) | p[1]);
        r5 = v >> 11;
        g6 = (v >> 5) & 63u;
        b5 = v & 31u;
        old[0] = (r5 << 3) | (r5 >> 2);
        old[1] = (g6 << 2) | (g6 >> 4);
        old[2] = (b5 << 3) | (b5 >> 2);
    }
    for (k = 0; k < 3; k++)
        old[k] = (old[k] * (255u - w) + t->rgb[k] * w + 127u) / 255u;
    pack_color((zl_format)ss->format, old[0], old[1], old[2], pix);
    put_pixel(p, ss->bpp, pix, ss->keep);
}

/* Weight (0..255) of the pixel below the ideal line: its distance to the
 * upper pixel's centre, the fraction f / D of a pixel. */
static inline unsigned aa_weight(const zl_edge *e)
{
    int64_t f = (int64_t)e->den - 1 - e->rem;
    return (unsigned)((f * 255 + e->den / 2) / e->den);
}

static void aa_step(zl_active *t)
{
    t->ax += t->right.step;
    edge_step(&t->left);
    t->z.row += t->z.dx;
    t->right.x--;
}

/* Antialiased line row: two pixels per column (x-major) or row (y-major),
 * rows floor(n) and floor(n) + 1 of the ideal minor coordinate n, weighted
 * by their distance to it. An x-major row r takes the columns whose floor(n)
 * is r - 1 (as the lower pixel) or r (as the upper one); the record stays at
 * the first column of the row's run. */
static int aa_row(zl_active *t, const zl_span_state *ss, uint8_t *crow, uint16_t *zrow)
{
    int32_t r = t->row;
    if (!t->lower_is_left) {
        unsigned w = aa_weight(&t->left);
        uint32_t d = line_depth(t->z.row);
        blend(ss, t, crow, zrow, t->left.x, d, 255u - w);
        blend(ss, t, crow, zrow, t->left.x + 1, d, w);
        if (t->right.x > 1)
            aa_step(t);
        else
            t->row = t->end;
    } else {
        zl_active l = *t;
        int saved = 0;
        while (l.right.x > 0 && l.left.x <= r) {
            unsigned w = aa_weight(&l.left);
            uint32_t d = line_depth(l.z.row);
            if (l.left.x == r - 1) {
                blend(ss, t, crow, zrow, l.ax, d, w);
            } else {
                if (!saved) {
                    t->left = l.left;
                    t->ax = l.ax;
                    t->right.x = l.right.x;
                    t->z.row = l.z.row;
                    saved = 1;
                }
                blend(ss, t, crow, zrow, l.ax, d, 255u - w);
            }
            aa_step(&l);
        }
        if (!saved) {
            /* nothing of this run reaches the next row's upper pixels */
            t->left = l.left;
            t->ax = l.ax;
            t->right.x = l.right.x;
            t->z.row = l.z.row;
            if (l.right.x == 0)
                t->row = t->end;
        }
    }
    if (t->row < t->end)
        t->row++;
    return t->row < t->end;
}

int zl_prim_row(zl_active *t, const zl_span_state *ss, uint8_t *color_row, uint16_t *depth_row)
{
    uint8_t pix[3] = {0, 0, 0};
    if (t->kind == ZL_KIND_LINE_AA)
        return aa_row(t, ss, color_row, depth_row);
    pack_color((zl_format)ss->format, t->rgb[0], t->rgb[1], t->rgb[2], pix);
    if (t->kind == ZL_KIND_POINT) {
        uint32_t d = line_depth(t->z.row);
        int32_t x;
        for (x = t->left.x; x < t->right.x; x++)
            plot(ss, color_row, depth_row, x, d, pix);
        t->row++;
        return t->row < t->end;
    }
    /* Line: the pixels of this row, walking the major axis. A y-major line
     * has one per row; an x-major one a run, until its minor coordinate
     * (the row) changes. */
    if (ss->bpp == 2 && ss->format == ZL_FORMAT_RGB565 && ss->zwrite && ss->func == ZL_LESS && ss->keep[0] == 0 &&
        ss->keep[1] == 0 && ((uintptr_t)color_row & 1u) == 0) {
        /* The common case in its own loop (RGB565, all channels, LESS with
         * writes): the same pixels and values as plot() below. */
        uint16_t *crow = (uint16_t *)(void *)color_row, pixel;
        memcpy(&pixel, pix, 2);
        for (;;) {
            int32_t x = t->lower_is_left ? t->ax : t->left.x;
            uint32_t d = line_depth(t->z.row);
            if (x >= 0 && x < ss->width && d < depth_row[x]) {
                depth_row[x] = (uint16_t)d;
                crow[x] = pixel;
            }
            if (--t->right.x == 0) {
                t->row = t->end;
                return 0;
            }
            t->ax += t->right.step;
            edge_step(&t->left);
            t->z.row += t->z.dx;
            if (!t->lower_is_left || t->left.x != t->row)
                break;
        }
        t->row++;
        return t->row < t->end;
    }
    for (;;) {
        int32_t x = t->lower_is_left ? t->ax : t->left.x;
        plot(ss, color_row, depth_row, x, line_depth(t->z.row), pix);
        if (--t->right.x == 0) {
            t->row = t->end;
            return 0;
        }
        t->ax += t->right.step;
        edge_step(&t->left);
        t->z.row += t->z.dx;
        if (!t->lower_is_left || t->left.x != t->row)
            break;
    }
    t->row++;
    return t->row < t->end;
}
