/* SPDX-License-Identifier: MIT */
/*
 * Stage 3, raster: what the set-up, row and span files share.
 * Internal to the raster stage and the primitives built on it.
 */
#ifndef ZL_RASTER_H
#define ZL_RASTER_H

#include "../1_base/zl_internal.h"
#include "zl_span.h"

/* ceil(v / 2^SUB) of a subpixel coordinate minus the half-pixel offset:
 * the index of the first row (or column) whose centre is at or after v. */
ZL_SHARED_STATIC int32_t first_centre_at_or_after(int32_t v)
{
    /* Window coordinates stay below 2^23 (zl_config.h): 32 bits suffice. */
    return zl_floor_shift32(v - ZL_SUB_HALF + ZL_SUB_ONE - 1, ZL_SUB_BITS);
}

ZL_SHARED_STATIC int32_t min3(int32_t a, int32_t b, int32_t c)
{
    int32_t m = a < b ? a : b;
    return m < c ? m : c;
}

ZL_SHARED_STATIC int32_t max3(int32_t a, int32_t b, int32_t c)
{
    int32_t m = a > b ? a : b;
    return m > c ? m : c;
}

/* Start edge top -> bot (top->y < bot->y) at row j. Window coordinates stay
 * below 2^23, so dx, dy, 16 dy and 16 dx fit 32 bits; only N needs 64. When
 * N fits 32 bits too (every edge of an on-screen triangle), the quotients
 * are 32-bit divisions and the remainders, which lie in [0, 16 dy), are
 * exact in wrapping 32-bit arithmetic. */
ZL_SHARED_STATIC void edge_init_xy(zl_edge *e, int32_t xt, int32_t yt, int32_t xb, int32_t yb, int32_t j)
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

ZL_SHARED_STATIC void edge_step(zl_edge *e)
{
    e->x += e->step;
    e->rem -= e->rstep;
    if (e->rem < 0) {
        e->rem += e->den;
        e->x += 1;
    }
}

ZL_SHARED_STATIC ZL_SMALL_NOINLINE int64_t clamp64(int64_t v, int64_t lo, int64_t hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* Per-pixel step of a Q20 gradient as a 32-bit stepper of `frac` bits.
 * Only spans of 2+ pixels step, and there the gradient is bounded by the
 * value range, so the clamp never bites where it matters. */
ZL_SHARED_STATIC ZL_SMALL_NOINLINE uint32_t step32(int64_t d, unsigned shift)
{
    return (uint32_t)(int32_t)clamp64(zl_floor_shift64(d, shift), -((int64_t)1 << 30), (int64_t)1 << 30);
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

/*
 * Division by one divisor c (1 <= c < 2^16) many times, of numerators
 * x < c 2^16 (quotients below 2^16): where there is no divide instruction
 * (ZL_MUL32_ONLY) by a reciprocal made once (one division for all the
 * triangle's planes), else by the instruction. The reciprocal is Moller and
 * Granlund's ("Improved division by invariant integers", 2011, algorithm 4)
 * for one 16-bit digit: c shifted left by s into [2^15, 2^16), v =
 * floor((2^32 - 1) / (c << s)) - 2^16; then a quotient costs one 16x16-bit
 * product and at most two corrections, and is exact (tests/test_div16.c
 * checks it against the division for every divisor).
 */
typedef struct {
    uint32_t c;
#if ZL_MUL32_ONLY
    uint32_t cn, v;
    unsigned s;
#endif
} zl_div16;

/* No divisor yet (c = 0): zl_div16_q must not be called. */
static ZL_ALWAYS_INLINE void zl_div16_none(zl_div16 *d)
{
    d->c = 0;
#if ZL_MUL32_ONLY
    d->cn = d->v = 0;
    d->s = 0;
#endif
}

static ZL_ALWAYS_INLINE void zl_div16_init(zl_div16 *d, uint32_t c)
{
    d->c = c;
#if ZL_MUL32_ONLY
    d->s = 0;
    d->cn = c;
    while (d->cn < 0x8000u) {
        d->cn <<= 1;
        d->s++;
    }
    d->v = 0xFFFFFFFFu / d->cn - 0x10000u;
#endif
}

/* floor(x / c) for x < c 2^16. */
static ZL_ALWAYS_INLINE uint32_t zl_div16_q(const zl_div16 *d, uint32_t x)
{
#if ZL_MUL32_ONLY
    uint32_t xn = x << d->s, u1 = xn >> 16, u0 = xn & 0xFFFFu; /* u1 < cn: x << s < cn 2^16 */
    uint32_t p = d->v * u1, q0 = (p & 0xFFFFu) + u0;
    uint32_t q1 = (p >> 16) + u1 + (q0 >> 16), r;
    q0 &= 0xFFFFu;
    q1 = (q1 + 1u) & 0xFFFFu;
    r = (u0 - q1 * d->cn) & 0xFFFFu;
    if (r > q0) {
        q1 = (q1 - 1u) & 0xFFFFu;
        r = (r + d->cn) & 0xFFFFu;
    }
    if (r >= d->cn)
        q1++;
    return q1;
#else
    return x / d->c;
#endif
}

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
#if ZL_MUL32_ONLY
    zl_div16 d16;               /* c32's zl_div16 when below 2^16 and the frame has a plane that
                                   is not constant (else c = 0: round_div_small reads it only for
                                   a numerator of c or more, which a constant plane has not) */
#endif
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
 * schoolbook division in two 16-bit digits, two 32-bit divisions (without
 * a divide instruction, two zl_div16_q of the frame's d16). 0 under the same condition as round_div_inv (a quotient of
 * 2^32 or more, which muldiv_pow2 might saturate), so the numerator is
 * below c 2^32 < 2^48.
 */
static ZL_ALWAYS_INLINE int round_div_small(int64_t x, const small_frame *f, int64_t *q)
{
    uint32_t c = f->c32;
    uint64_t m = x < 0 ? (uint64_t)0 - (uint64_t)x : (uint64_t)x;
    uint64_t num = x < 0 ? m + (c - 1u - c / 2u) : m + c / 2u;
    uint32_t hi, q1, q0;
    if ((num >> 32) >= c)
        return 0;
    hi = (uint32_t)(num >> 16); /* below c 2^16, as the remainder's 16 bits shifted in below */
#if ZL_MUL32_ONLY
    if (num < c) { /* a constant plane's (x = 0): no division */
        *q = 0;
        return 1;
    }
    q1 = zl_div16_q(&f->d16, hi);
    q0 = zl_div16_q(&f->d16, ((hi - q1 * c) << 16) | (uint32_t)(num & 0xFFFFu));
#else
    q1 = hi / c;
    q0 = (((hi - q1 * c) << 16) | (uint32_t)(num & 0xFFFFu)) / c; /* the remainder is below 2^16 */
#endif
    m = ((uint64_t)q1 << 16) + q0;
    *q = x < 0 ? -(int64_t)m : (int64_t)m;
    return 1;
}

/* round(x / |cross|) by the cheaper of the two ways. */
static ZL_ALWAYS_INLINE int round_div_frame(int64_t x, const small_frame *f, int64_t *q)
{
    return f->c32 < 65536u ? round_div_small(x, f, q) : round_div_inv(x, f, q);
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
#if ZL_MUL32_ONLY
    int64_t ga = zl_mul_s32_split(d1, f->dy2) - zl_mul_s32_split(d2, f->dy1);
    int64_t gb = zl_mul_s32_split(f->dx1, d2) - zl_mul_s32_split(f->dx2, d1), dx, dy, off;
#else
    int64_t ga = (int64_t)d1 * f->dy2 - (int64_t)d2 * f->dy1;
    int64_t gb = (int64_t)f->dx1 * d2 - (int64_t)f->dx2 * d1, dx, dy, off;
#endif
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
ZL_SHARED_STATIC int diff32(int64_t a1, int64_t a0, int32_t *d)
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

/* Start value at column x of a Q20 attribute, clamped to [lo, hi]. */
ZL_SHARED_STATIC int64_t attr_at(const zl_attr *a, int32_t x, int32_t ax, int64_t lo, int64_t hi)
{
    return clamp64(a->row + (int64_t)(x - ax) * a->dx, lo, hi);
}

/* A vertex for zl_depth_plane_exact: snapped subpixels, residuals
 * (zl_wvert fx, fy) and depth (Q16). */
typedef struct {
    int32_t x, y, fx, fy;
    uint32_t z;
} zl_fine_vert;

/*
 * The depth plane of a triangle (v sorted by y as the set-up sorts them)
 * through its vertices at their unsnapped positions (issue 22), anchored
 * at the centre of pixel (ax, ay) and stepped to row `first` as
 * plane_setup anchors it, and the range [zlo, zhi] (Q16) its values at the
 * pixel centres the snapped triangle covers lie in. 0 when the caller must
 * take the plane through the snapped vertices instead: an edge of 2^17
 * subpixels or more, a degenerate unsnapped triangle, or a range that
 * leaves the depth range. Every set-up calls it, so all give the same
 * plane.
 */
int zl_depth_plane_exact(zl_attr *z, uint32_t *zlo, uint32_t *zhi, const zl_fine_vert *v, int32_t ax, int32_t ay,
                         int32_t first);

/* ZL_SHORT_SPAN and tiny_x: zl_span.h (shared with scanline mode's rows). */

#endif /* ZL_RASTER_H */
