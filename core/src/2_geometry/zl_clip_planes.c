/* SPDX-License-Identifier: MIT */
/*
 * Stage 2, geometry: the attribute planes of a clipped triangle, from its
 * original (unclipped) vertices. Clipping decides coverage only; the depth,
 * the Gouraud colour and the texture coordinates of every fan piece come
 * from here, so
 * the vertices the clipper makes (rounded to Q16.16, then snapped to 1/16
 * pixel) do not tilt the planes of steep pieces.
 *
 * Homogeneous 2D interpolation (Olano and Greer, "Triangle scan conversion
 * using 2D homogeneous coordinates", 1997): with M the 3x3 matrix whose
 * columns are the clip-space (x, y, w) of the three vertices and
 * n = (x_ndc, y_ndc, 1) a window position in normalised device coordinates,
 * b = M^-1 n are the vertices' weights divided by the point's w. So for an
 * attribute a linear in clip space, a / w = sum a_i b_i is affine in the
 * window position, with no division by a w that may be zero or negative:
 *     z_clip / w   = sum z_i b_i                        (window depth)
 *     1 / w        = sum b_i                            (exact mapping)
 *     screen-linear colour = sum c_i w_i b_i  (the screen barycentrics are
 *                    w_i b_i; meaningful when every w_i > 0)
 *     perspective-correct a = (sum a_i b_i) / (sum b_i)  (texture
 *                    coordinates, colour: the two planes zl_texplanes
 *                    keeps, divided per pixel by the span loop)
 * M^-1 = adj(M) / det(M), and the rows of adj(M) are the cross products
 * C_i = P_j x P_k of the vertex columns, whose components fit 64 bits
 * (products of two Q16.16 numbers). Every sum below is exact, in 256-bit
 * integers; one rounding division per plane coefficient.
 */
#include <string.h>

#include "zl_geometry.h"

/* ------------------------------------------------ 256-bit integers */

#define BIG_LIMBS 8

/* Two's complement, least significant limb first. */
typedef struct {
    uint32_t d[BIG_LIMBS];
} big;

static void big_set(big *r, int64_t v)
{
    uint64_t u = (uint64_t)v;
    uint32_t fill = v < 0 ? 0xFFFFFFFFu : 0u;
    unsigned k;
    r->d[0] = (uint32_t)u;
    r->d[1] = (uint32_t)(u >> 32);
    for (k = 2; k < BIG_LIMBS; k++)
        r->d[k] = fill;
}

static int big_is_neg(const big *a)
{
    return (a->d[BIG_LIMBS - 1] >> 31) != 0;
}

static int big_is_zero(const big *a)
{
    uint32_t o = 0;
    unsigned k;
    for (k = 0; k < BIG_LIMBS; k++)
        o |= a->d[k];
    return o == 0;
}

static void big_negate(big *a)
{
    uint64_t carry = 1;
    unsigned k;
    for (k = 0; k < BIG_LIMBS; k++) {
        uint64_t s = (uint64_t)(uint32_t)~a->d[k] + carry;
        a->d[k] = (uint32_t)s;
        carry = s >> 32;
    }
}

/* r += a (modulo 2^256). */
static void big_add(big *r, const big *a)
{
    uint64_t carry = 0;
    unsigned k;
    for (k = 0; k < BIG_LIMBS; k++) {
        uint64_t s = (uint64_t)r->d[k] + a->d[k] + carry;
        r->d[k] = (uint32_t)s;
        carry = s >> 32;
    }
}

/* r = a * m. The callers keep |a * m| below 2^255 (the bounds are noted
 * where the numbers are made). */
static ZL_NOINLINE void big_mul(big *r, const big *a, int64_t m)
{
    big t = *a;
    int neg = big_is_neg(&t) != (m < 0);
    uint64_t um = m < 0 ? 0u - (uint64_t)m : (uint64_t)m;
    uint32_t mlo = (uint32_t)um, mhi = (uint32_t)(um >> 32);
    uint64_t carry = 0;
    unsigned k;
    if (big_is_neg(&t))
        big_negate(&t);
    /* two passes of a 32-bit digit each: magnitude times mlo, plus times mhi shifted one limb */
    for (k = 0; k < BIG_LIMBS; k++) {
        uint64_t p = (uint64_t)t.d[k] * mlo + carry;
        r->d[k] = (uint32_t)p;
        carry = p >> 32;
    }
    carry = 0;
    for (k = 0; k + 1 < BIG_LIMBS; k++) {
        uint64_t p = (uint64_t)t.d[k] * mhi + r->d[k + 1] + carry;
        r->d[k + 1] = (uint32_t)p;
        carry = p >> 32;
    }
    if (neg)
        big_negate(r);
}

/* r += a * m */
static ZL_NOINLINE void big_addmul(big *r, const big *a, int64_t m)
{
    big t;
    big_mul(&t, a, m);
    big_add(r, &t);
}

static unsigned big_bits(const big *a) /* of a non-negative number */
{
    int k;
    for (k = BIG_LIMBS - 1; k >= 0; k--) {
        if (a->d[k] != 0) {
            uint32_t v = a->d[k];
            unsigned n = 0;
            while (v != 0) {
                v >>= 1;
                n++;
            }
            return (unsigned)k * 32u + n;
        }
    }
    return 0;
}

static int big_cmp(const big *a, const big *b) /* non-negative numbers */
{
    int k;
    for (k = BIG_LIMBS - 1; k >= 0; k--)
        if (a->d[k] != b->d[k])
            return a->d[k] < b->d[k] ? -1 : 1;
    return 0;
}

static void big_sub(big *r, const big *a) /* r -= a, r >= a >= 0 */
{
    uint64_t borrow = 0;
    unsigned k;
    for (k = 0; k < BIG_LIMBS; k++) {
        uint64_t s = (uint64_t)r->d[k] - a->d[k] - borrow;
        r->d[k] = (uint32_t)s;
        borrow = (s >> 32) & 1u;
    }
}

static void big_shl(big *a, unsigned n) /* n < 256, non-negative a that stays below 2^255 */
{
    unsigned limbs = n / 32u, bits = n % 32u;
    int k;
    for (k = BIG_LIMBS - 1; k >= 0; k--) {
        uint32_t hi = (unsigned)k >= limbs ? a->d[(unsigned)k - limbs] : 0u;
        uint32_t lo = (unsigned)k >= limbs + 1u ? a->d[(unsigned)k - limbs - 1u] : 0u;
        a->d[k] = bits == 0 ? hi : (hi << bits) | (lo >> (32u - bits));
    }
}

static void big_shr1(big *a) /* non-negative a */
{
    unsigned k;
    for (k = 0; k + 1 < BIG_LIMBS; k++)
        a->d[k] = (a->d[k] >> 1) | (a->d[k + 1] << 31);
    a->d[BIG_LIMBS - 1] >>= 1;
}

/* round(num / den) for den > 0 (half-way away from zero), saturated to
 * +-limit: binary long division, one bit of the quotient a step, so about
 * as many steps as the quotient has bits (at most 64). */
static int64_t big_div_round(const big *num, const big *den, int64_t limit)
{
    big r = *num, d = *den;
    int neg = big_is_neg(&r);
    unsigned nb, db, s, i;
    uint64_t q = 0;
    if (neg)
        big_negate(&r);
    nb = big_bits(&r);
    db = big_bits(&d);
    if (nb > db + 62)
        return neg ? -limit : limit;
    s = nb > db ? nb - db : 0;
    big_shl(&d, s);
    for (i = 0; i <= s; i++) {
        q <<= 1;
        if (big_cmp(&r, &d) >= 0) {
            big_sub(&r, &d);
            q |= 1u;
        }
        big_shr1(&d);
    }
    /* r < den: round half up (in magnitude) when 2 r >= den */
    big_shl(&r, 1);
    if (big_cmp(&r, den) >= 0)
        q++;
    if (q > (uint64_t)limit)
        q = (uint64_t)limit;
    return neg ? -(int64_t)q : (int64_t)q;
}

/* ------------------------------------------------ the planes */

/* The window position of pixel centres in device coordinates, as integer
 * fractions: n_x = (sx (2X) + ox) / dd, n_y = (sy (2Y) + oy) / dd,
 * n_w = ow / dd, for X, Y window coordinates (2X odd at a centre). With a
 * matrix x_ndc = (2X - W) / W and y_ndc = (H - 2Y) / H, both over W H; in
 * pixel space the clip x, y are the window position itself (w = 1.0). */
typedef struct {
    int64_t sx, ox, sy, oy, ow, dd;
} viewport;

/* The solve of one triangle at one anchor pixel: the cross products, the
 * positive denominator den = det(M) dd, the anchor's device position. */
typedef struct {
    int64_t c[3][3]; /* C_i, sign-flipped with det so that den > 0 */
    big den;
    viewport vp;
    int64_t kx, ky;  /* sx (2 ax + 1) + ox, sy (2 ay + 1) + oy: below 2^31 */
} hsolve;

/* G . (kx, ky, ow): G's plane value numerator at the anchor (|G| < 2^128:
 * below 2^162). */
static void value_num(big *n, const big g[3], const hsolve *h)
{
    big_mul(n, &g[0], h->kx);
    big_addmul(n, &g[1], h->ky);
    big_addmul(n, &g[2], h->vp.ow);
}

/* One plane from the sum G = sum a_i C_i: the value at the anchor pixel's
 * centre and the change per pixel and row, Q20 of the unit, times
 * scale / den (den may be h->den times a factor). With |scale| < 2^40
 * every product is below 2^202. Out of line (as the callers), so only one
 * attribute's numbers are on the stack at a time. */
static ZL_NOINLINE void plane_from(zl_attr *at, const big g[3], const hsolve *h, int64_t scale, const big *den)
{
    big n, t;
    value_num(&n, g, h);
    big_mul(&t, &n, scale);
    at->row = big_div_round(&t, den, (int64_t)1 << 60);
    big_mul(&n, &g[0], 2 * h->vp.sx);
    big_mul(&t, &n, scale);
    at->dx = big_div_round(&t, den, ZL_GRAD_LIMIT);
    big_mul(&n, &g[1], 2 * h->vp.sy);
    big_mul(&t, &n, scale);
    at->dy = big_div_round(&t, den, ZL_GRAD_LIMIT);
}

/* g = sum_i a_i C_i, |a_i| < 2^63 (so each component is below 2^128). */
static void weighted(big g[3], const hsolve *h, const int64_t a[3])
{
    unsigned i, k;
    for (k = 0; k < 3; k++) {
        big t;
        big_set(&g[k], 0);
        for (i = 0; i < 3; i++) {
            big_set(&t, h->c[i][k]);
            big_addmul(&g[k], &t, a[i]);
        }
    }
}

/* The plane of sum a_i b_i, times scale / (den * dfac). */
static ZL_NOINLINE void attr_plane(zl_attr *at, const hsolve *h, const int64_t a[3], int64_t scale, int64_t dfac)
{
    big g[3], den;
    weighted(g, h, a);
    big_mul(&den, &h->den, dfac);
    plane_from(at, g, h, scale, &den);
}

/* Exact mapping: z_w = A + B / w = f (1 - n / w) / (f - n), w of the
 * Q16.16 clip vertices (the vertices' own exact depths zd_i cannot serve:
 * they are clamped to the depth range, and a clipped triangle has a vertex
 * outside it), 1 / w = sum b_i = G1 . k / den with G1 = sum C_i:
 *     z_w = f (den - n G1 . k) / ((f - n) den).
 * G1 < 2^66, n and f < 2^31: the value numerator is below 2^161 before the
 * scale 65535 2^20 (< 2^36): within 2^197; den (f - n) below 2^151. */
static ZL_NOINLINE void exact_depth_plane(zl_attr *z, const hsolve *h, int64_t nr, int64_t fr)
{
    static const int64_t one[3] = {1, 1, 1};
    const int64_t scale = (int64_t)65535 << ZL_ATTR_FRAC;
    big g[3], num, dq;
    weighted(g, h, one);
    value_num(&num, g, h);
    big_mul(&num, &num, -nr);
    big_add(&num, &h->den);
    big_mul(&num, &num, fr);
    big_mul(&num, &num, scale);
    big_mul(&dq, &h->den, fr - nr);
    z->row = big_div_round(&num, &dq, (int64_t)1 << 60);
    big_mul(&num, &g[0], 2 * h->vp.sx);
    big_mul(&num, &num, -nr * fr);
    big_mul(&num, &num, scale);
    z->dx = big_div_round(&num, &dq, ZL_GRAD_LIMIT);
    big_mul(&num, &g[1], 2 * h->vp.sy);
    big_mul(&num, &num, -nr * fr);
    big_mul(&num, &num, scale);
    z->dy = big_div_round(&num, &dq, ZL_GRAD_LIMIT);
}

/* The triangle's vertices (P = (x, y, w), z, colour) and its solve. 0 when
 * a vertex cannot be transformed or det M = 0 (a triangle edge-on through
 * the eye: no plane). */
static ZL_NOINLINE int solve_of(const zl_source *s, uint32_t t, int32_t ax, int32_t ay, hsolve *h, int32_t z[3],
                                int32_t w[3], uint16_t rgb[3][3])
{
    const uint16_t *idx = &s->mesh->indices[t * 3u];
    int32_t p[3][3];
    big t1;
    unsigned i, k;
    for (i = 0; i < 3; i++) {
        zl_cvert v;
        if (!zl_vertex_clip(s, ZL_MESH_IDX(idx, i), &v))
            return 0;
        p[i][0] = v.x;
        p[i][1] = v.y;
        p[i][2] = v.w;
        z[i] = v.z;
        w[i] = v.w;
        rgb[i][0] = v.r;
        rgb[i][1] = v.g;
        rgb[i][2] = v.b;
    }
    /* C_i = P_j x P_k, (i, j, k) cyclic: each component a difference of
     * two products of Q16.16 numbers, below 2^63 in magnitude (at most one
     * of the products can reach 2^62). */
    for (i = 0; i < 3; i++) {
        const int32_t *a = p[NEXT3(i)], *b = p[NEXT3(NEXT3(i))];
        for (k = 0; k < 3; k++) {
            unsigned j = NEXT3(k), l = NEXT3(j);
            h->c[i][k] = (int64_t)a[j] * b[l] - (int64_t)a[l] * b[j];
        }
    }
    if (s->mvp != NULL) {
        h->vp.sx = s->height;
        h->vp.ox = -(int64_t)s->width * s->height;
        h->vp.sy = -(int64_t)s->width;
        h->vp.oy = (int64_t)s->width * s->height;
        h->vp.ow = (int64_t)s->width * s->height;
        h->vp.dd = (int64_t)s->width * s->height;
    } else {
        h->vp.sx = 1;
        h->vp.ox = 0;
        h->vp.sy = 1;
        h->vp.oy = 0;
        h->vp.ow = 2;
        h->vp.dd = 2;
    }
    /* |2 ax + 1| < 2^19 within the guard band, H <= 2^12, W H <= 2^24 */
    h->kx = h->vp.sx * (2 * (int64_t)ax + 1) + h->vp.ox;
    h->ky = h->vp.sy * (2 * (int64_t)ay + 1) + h->vp.oy;
    /* det M = P_0 . C_0 (below 2^96), times dd (below 2^24) */
    big_set(&h->den, 0);
    for (k = 0; k < 3; k++) {
        big_set(&t1, h->c[0][k]);
        big_addmul(&h->den, &t1, p[0][k]);
    }
    if (big_is_zero(&h->den))
        return 0;
    big_mul(&h->den, &h->den, h->vp.dd);
    if (big_is_neg(&h->den)) {
        /* negating every C_i negates every numerator: den > 0 */
        big_negate(&h->den);
        for (i = 0; i < 3; i++)
            for (k = 0; k < 3; k++)
                h->c[i][k] = -h->c[i][k]; /* |c| < 2^63: no overflow */
    }
    return 1;
}

/* The depth numerator sum at a window position given as (kx, ky, ow)
 * over den * dmul, and that denominator (see exact_depth_plane for the
 * exact mapping); g is G of the mode (sum z_i C_i, or sum C_i when exact). */
static void depth_num(big *num, big *dq, const big g[3], const hsolve *h, int64_t kx, int64_t ky, int64_t ow,
                      int64_t dmul, int64_t nr, int64_t fr)
{
    big_mul(num, &g[0], kx);
    big_addmul(num, &g[1], ky);
    big_addmul(num, &g[2], ow);
    big_mul(dq, &h->den, dmul);
    if (fr != 0) {
        big_mul(num, num, -nr);
        big_add(num, dq);
        big_mul(num, num, fr);
        big_mul(dq, dq, fr - nr);
    }
}

/* Depths (Q16 of the stored scale, unclamped) at three subpixel positions,
 * once the triangle is solved (out of line: its numbers are not on the
 * stack while the vertices are transformed). A position at subpixel x is at
 * 2X = x / 8: n_x = (sx x + 8 ox) / (8 dd); |sx x| < 2^35, so the
 * numerators stay below 2^164 before the scale 65535 2^16 (< 2^32). */
static ZL_NOINLINE void depths3(const hsolve *h, const int32_t zc[3], int64_t nr, int64_t fr, const int32_t x[3],
                                const int32_t y[3], int64_t z[3])
{
    int64_t a[3];
    big g[3];
    unsigned i;
    for (i = 0; i < 3; i++)
        a[i] = fr != 0 ? 1 : zc[i];
    weighted(g, h, a);
    for (i = 0; i < 3; i++) {
        big num, dq;
        depth_num(&num, &dq, g, h, h->vp.sx * x[i] + 8 * h->vp.ox, h->vp.sy * y[i] + 8 * h->vp.oy, 8 * h->vp.ow, 8,
                  nr, fr);
        big_mul(&num, &num, (int64_t)65535 << 16);
        z[i] = big_div_round(&num, &dq, (int64_t)1 << 60);
    }
}

int zl_tri_orig_depths3(const zl_source *s, uint32_t t, const int32_t x[3], const int32_t y[3], int64_t z[3])
{
    hsolve h;
    int32_t zc[3], w[3];
    uint16_t rgb[3][3];
    int exact = s->mvp != NULL && ZL_DEPTH_MAPPED(s->state);
    if (!solve_of(s, t, 0, 0, &h, zc, w, rgb))
        return 0;
    depths3(&h, zc, exact ? s->state->near_z : 0, exact ? s->state->far_z : 0, x, y, z);
    return 1;
}

int zl_tri_orig_planes(const zl_source *s, uint32_t t, int32_t ax, int32_t ay, int colour, uint8_t light,
                       zl_attr *z, zl_attr col[3])
{
    hsolve h;
    int32_t zc[3], w[3];
    uint16_t rgb[3][3];
    int64_t a[3];
    unsigned i, ch;
    int done = 1;
    if (!solve_of(s, t, ax, ay, &h, zc, w, rgb))
        return 0;
    if (s->mvp != NULL && ZL_DEPTH_MAPPED(s->state)) {
        exact_depth_plane(z, &h, s->state->near_z, s->state->far_z);
    } else {
        /* z_w = z_clip / w = sum z_i b_i, stored scale 65535, Q20 */
        for (i = 0; i < 3; i++)
            a[i] = zc[i];
        attr_plane(z, &h, a, (int64_t)65535 << ZL_ATTR_FRAC, 1);
    }
    if (colour && w[0] > 0 && w[1] > 0 && w[2] > 0) {
        /* Screen-linear colour: sum c_i w_i b_i, Q8 colours (< 2^16) times
         * w (< 2^31); the light scales by light / 255, Q8 to Q20 is 2^12. */
        for (ch = 0; ch < 3; ch++) {
            for (i = 0; i < 3; i++)
                a[i] = (int64_t)rgb[i][ch] * w[i];
            attr_plane(&col[ch], &h, a, (int64_t)light << (ZL_ATTR_FRAC - 8), 255);
        }
        done |= 2;
    }
    return done;
}

/* zl_texplanes from the original triangle: q = 2^28 wmin / w = 2^28 wmin
 * sum b_i (wmin, the clipped polygon's least clip w, keeps q within 2^28 on
 * the piece, as tex_setup's per-triangle scale does), u q / 2^20 =
 * 256 wmin sum u_i b_i (u in 1/256 texel: |u_i wmin| < 2^54; units of
 * 2^-16 q texel, zl_internal.h), or affine 256 sum u_i w_i b_i (Q16
 * texels); perspective colour c q / 2^24 in Q16 of 0 .. 255,
 * from Q8 colours times light / 255: sum c_i wmin b_i times 2^12 light /
 * 255. A triangle with a vertex at w <= 0 has no screen-linear
 * interpolation: its affine texture is perspective-correct (tp->persp). */
int zl_tri_orig_texplanes(const zl_source *s, const zl_style *sty, uint32_t tri, const zl_active *t, int32_t wmin,
                          zl_texplanes *tp, zl_attr col[3])
{
    hsolve h;
    int32_t zc[3], w[3];
    uint16_t rgb[3][3];
    int64_t a[3];
    unsigned i, ch;
    int persp;
    if (!solve_of(s, tri, t->ax, t->row, &h, zc, w, rgb))
        return 0;
    for (i = 0; i < 3; i++)
        a[i] = wmin;
    attr_plane(&tp->q, &h, a, (int64_t)1 << 28, 1);
    persp = sty->tex_mapping == ZL_TEX_PERSPECTIVE || w[0] <= 0 || w[1] <= 0 || w[2] <= 0;
    tp->persp = (uint8_t)(persp && sty->tex_mapping != ZL_TEX_PERSPECTIVE);
    memset(&tp->u, 0, sizeof tp->u);
    memset(&tp->v, 0, sizeof tp->v);
    if (sty->texture != NULL && sty->texcoords != NULL) {
        for (ch = 0; ch < 2; ch++) { /* u, then v */
            for (i = 0; i < 3; i++) {
                int32_t c[2];
                tex_coords(sty, ZL_MESH_IDX(s->mesh->indices, tri * 3u + i), &c[0], &c[1]);
                a[i] = (int64_t)c[ch] * (persp ? wmin : w[i]);
            }
            attr_plane(ch == 0 ? &tp->u : &tp->v, &h, a, (int64_t)1 << ZL_TEX_SHIFT, 1);
        }
    }
    if (col == NULL)
        return 1;
    for (ch = 0; ch < 3; ch++) {
        for (i = 0; i < 3; i++)
            a[i] = (int64_t)rgb[i][ch] * wmin;
        attr_plane(&col[ch], &h, a, (int64_t)t->light << 12, 255);
    }
    return 3;
}
