/* SPDX-License-Identifier: MIT */
/*
 * Stage 3, raster: the 32-bit set-ups of the common case. A flat triangle
 * whose vertices are in the vertex cache (int16 window coordinates) is set up
 * in 32-bit products with one reciprocal of the area (zl_tri_setup_flat), and
 * a small one gets the compact record of zl_tiny_draw (zl_tiny_setup), or
 * in scanline mode the same numbers in a ZL_KIND_TINY pool record
 * (zl_tiny_setup_record). They give the same numbers as zl_tri_setup
 * (zl_setup.c) and return "use the general set-up" outside their ranges.
 */
#include <string.h>

/* GCC before 6 (Debian's avr-gcc 5.4) loses track of which fields a set-up
 * wrote once it is inlined, and calls the ones read after a successful
 * set-up (return 1, every field written) maybe uninitialized. */
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 6
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include "zl_raster.h"

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
                                                   int64_t cross, int planes)
{
    int32_t ax = zl_floor_shift32(v0->x, ZL_SUB_BITS), ay = zl_floor_shift32(v0->y, ZL_SUB_BITS);
    f->neg = cross < 0;
    f->c32 = (uint32_t)(cross < 0 ? -cross : cross);
    f->ox = ax * ZL_SUB_ONE + ZL_SUB_HALF - v0->x;
    f->oy = ay * ZL_SUB_ONE + ZL_SUB_HALF - v0->y;
    f->rows = first - ay;
    if (f->c32 >= 65536u) /* round_div_frame uses the reciprocal only then */
        zl_div_inv_init(&f->inv, f->c32);
#if ZL_MUL32_ONLY
    /* round_div_small's reciprocal, when a plane is not constant (planes) */
    if (planes && f->c32 < 65536u)
        zl_div16_init(&f->d16, f->c32);
    else
        zl_div16_none(&f->d16);
#else
    (void)planes;
#endif
    return ax;
}

/* zl_depth_plane_exact of three sorted cached vertices, anchored at column
 * ax of v[0]'s row. Out of line: the set-ups without the exact mapping do
 * not carry its frame (+19 instructions a triangle on the Cortex-M4 bunny
 * in line). */
static ZL_NOINLINE int cached_depth_plane(zl_attr *z, uint32_t *zlo, uint32_t *zhi, const zl_cached_vertex *const *v, int32_t ax,
                              int32_t first)
{
    zl_fine_vert f[3];
    int k;
    for (k = 0; k < 3; k++) {
        f[k].x = v[k]->x;
        f[k].y = v[k]->y;
        f[k].fx = ZL_CV_FX(v[k]);
        f[k].fy = ZL_CV_FY(v[k]);
        f[k].z = v[k]->z;
    }
    return zl_depth_plane_exact(z, zlo, zhi, f, ax, zl_floor_shift32(v[0]->y, ZL_SUB_BITS), first);
}

/* zl_tri_setup_flat's triangle by the general setup (zl_tri_classify and
 * zl_tri_setup_rows on window vertices), for numbers beyond 32 bits. Out of
 * line, so the common case does not carry its frame. */
static ZL_NOINLINE int setup_flat_general(zl_active *t, const zl_cached_vertex *const *c, const zl_state *st,
                                          uint16_t width, uint16_t height)
{
    zl_wvert w[3];
    int16_t res[6];
    int32_t first, end;
    unsigned k;
    int exact;
    for (k = 0; k < 3; k++) {
        w[k].x = c[k]->x;
        w[k].y = c[k]->y;
        w[k].z = c[k]->z;
        res[2 * k] = ZL_CV_FX(c[k]);
        res[2 * k + 1] = ZL_CV_FY(c[k]);
        w[k].r = 0; /* vertex colours only matter to Gouraud shading */
        w[k].g = 0;
        w[k].b = 0;
    }
    exact = ZL_CV_FX(c[0]) != ZL_FINE_NONE;
    if (!zl_tri_classify(&w[0], &w[1], &w[2], st, width, height, &first, &end))
        return 0;
    zl_tri_setup_rows_res(t, NULL, NULL, NULL, &w[0], &w[1], &w[2], NULL, exact ? res : NULL, st, first, end);
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
    int32_t first, end, mid, ax;
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
    if (ZL_CV_FX(v0) == ZL_FINE_NONE) { /* no exact mapping: the plane through the snapped vertices */
        int32_t d1, d2;
        if (cross < -(int64_t)UINT32_MAX || cross > (int64_t)UINT32_MAX || !depth_diff32(v1->z, v0->z, &d1) ||
            !depth_diff32(v2->z, v0->z, &d2))
            return -1;
        ax = small_frame_anchor(&f, v0, first, cross, (d1 | d2) != 0);
        if (!plane_small(&t->z, &f, v0->z, d1, d2))
            return -1;
        t->zlo = v0->z < v1->z ? v0->z : v1->z;
        t->zlo = v2->z < t->zlo ? v2->z : t->zlo;
        t->zhi = v0->z > v1->z ? v0->z : v1->z;
        t->zhi = v2->z > t->zhi ? v2->z : t->zhi;
    } else {
        ax = zl_floor_shift32(v0->x, ZL_SUB_BITS);
        if (!cached_depth_plane(&t->z, &t->zlo, &t->zhi, v, ax, first))
            return -1;
    }
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
    return 1;
}

int zl_tri_setup_flat(zl_active *t, const zl_cached_vertex *a, const zl_cached_vertex *b,
                      const zl_cached_vertex *c, const zl_state *st, uint16_t width, uint16_t height)
{
    /* without ZL_FAST_PATHS (zl_config.h) every triangle takes the general set-up: the same pixels */
    int set = ZL_FAST_PATHS ? setup_flat_32(t, a, b, c, width, height) : -1;
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

/*
 * A cached flat triangle drawn without a zl_active record, for the common
 * frame-mode case: every number of it fits 32 bits. Its edges are not
 * stepped by the DDA of zl_edge but evaluated per row, x(j) = ceil(N(j) /
 * D) with N(j) = N(first) + (j - first) 16 dx: the same quotient the DDA
 * keeps, from one division, and a set-up of three numbers per edge instead
 * of two divisions and two products. For the small triangles of a real mesh
 * (a few rows each) that is the cheaper side of the trade.
 */
#if ZL_SMALL_TRIANGLE_SETUP /* (zl_config.h; off, zl_internal.h's stubs send every triangle to the general set-up) */
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
static ZL_ALWAYS_INLINE void tiny_depth(zl_tiny *tt, const zl_attr *z, uint32_t zlo, uint32_t zhi)
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

/* The plane frame f into *out, for more planes: its reciprocal only where
 * it was made (round_div_frame reads it only then). */
static ZL_ALWAYS_INLINE void frame_out(small_frame *out, const small_frame *f)
{
    out->dx1 = f->dx1;
    out->dy1 = f->dy1;
    out->dx2 = f->dx2;
    out->dy2 = f->dy2;
    out->ox = f->ox;
    out->oy = f->oy;
    out->rows = f->rows;
    out->neg = f->neg;
    out->c32 = f->c32;
    if (f->c32 >= 65536u)
        out->inv = f->inv;
#if ZL_MUL32_ONLY
    out->d16 = f->d16;
#endif
}

/* tiny_setup on v[0..2], which it sorts by y; with fout, its plane frame
 * goes there for more planes (zl_tiny_gouraud_setup). The frame stays a
 * local: through a pointer GCC -Os keeps it in memory (+2 % on the flat
 * bunny, +3 % on tris, Cortex-M4 and rv32). */
static ZL_ALWAYS_INLINE int tiny_setup_v(zl_tiny *tt, const zl_cached_vertex **v, uint16_t height,
                                         small_frame *fout, int exact)
{
    const zl_cached_vertex *v0, *v1, *v2;
    int32_t first, end, mid, ax, d1, d2, cross;
    uint32_t zlo, zhi;
    small_frame f;
    zl_attr z;
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
    if (v0->x <= -8192 || v0->x >= 8192 || v1->x <= -8192 || v1->x >= 8192 || v2->x <= -8192 || v2->x >= 8192 ||
        f.dy2 >= 8192 || zhi - zlo >= (UINT32_C(1) << 25)) /* (tiny_depth's bound) */
        return -1;
    d1 = (int32_t)(v1->z - v0->z); /* below 2^25 in magnitude */
    d2 = (int32_t)(v2->z - v0->z);
    tiny_edge_init(&tt->lng, v0->x, v0->y, v2->x, v2->y, first);
    if (first < mid) /* only edges with rows are read */
        tiny_edge_init(&tt->up, v0->x, v0->y, v1->x, v1->y, first);
    if (mid < end)
        tiny_edge_init(&tt->low, v1->x, v1->y, v2->x, v2->y, mid);
    cross = f.dx1 * f.dy2 - f.dx2 * f.dy1;
    ax = small_frame_anchor(&f, v0, first, cross, (d1 | d2) != 0);
    if (!exact ? !plane_small(&z, &f, v0->z, d1, d2)
               : !cached_depth_plane(&z, &zlo, &zhi, v, ax, first) || zhi - zlo >= (UINT32_C(1) << 25))
        return -1;
    tiny_depth(tt, &z, zlo, zhi);
    tt->ax = ax;
    tt->first = first;
    tt->mid = mid;
    tt->end = end;
    tt->long_left = cross > 0;
    if (fout != NULL)
        frame_out(fout, &f);
    return 1;
}

static ZL_ALWAYS_INLINE int tiny_setup(zl_tiny *tt, const zl_cached_vertex *a, const zl_cached_vertex *b,
                                       const zl_cached_vertex *c, uint16_t width, uint16_t height)
{
    const zl_cached_vertex *v[3];
    /* zl_tri_classify's column test is left out: a triangle entirely left or
     * right of the target clamps every span to nothing in the row loop, so
     * it draws the same nothing, and on-screen meshes save the test. */
    (void)width;
    v[0] = a;
    v[1] = b;
    v[2] = c;
    /* one instance a depth mapping: the snapped plane's is the set-up of before issue 22 */
    if (ZL_CV_FX(a) == ZL_FINE_NONE)
        return tiny_setup_v(tt, v, height, NULL, 0);
    return tiny_setup_v(tt, v, height, NULL, 1);
}

int zl_tiny_setup(zl_tiny *tt, const zl_cached_vertex *a, const zl_cached_vertex *b, const zl_cached_vertex *c,
                  uint16_t width, uint16_t height)
{
    return tiny_setup(tt, a, b, c, width, height);
}

/* ---------------------------------------- small Gouraud triangles, frame mode */

/*
 * round_div_small (zl_raster.h) of x = n 2^k, for |n| 2^(k - 16) < 2^31,
 * 16 <= k <= 24 and c < 2^16 (d: its zl_div16), in two 32-bit divisions:
 * floor((|x| + bias) / c) in 16-bit digits, (|n| << (k - 16)) / c for the
 * high one, then the remainder (below c) with 16 bits shifted in (below
 * c 2^16 <= 2^32 with the bias). 0 when the quotient might reach 2^31 (then the caller takes
 * plane_small, whose limit is 2^32).
 */
static ZL_ALWAYS_INLINE int round_div_shift(int32_t n, unsigned k, const zl_div16 *d, int32_t *q)
{
    uint32_t c = d->c, m = (n < 0 ? 0u - (uint32_t)n : (uint32_t)n) << (k - 16);
    uint32_t bias = n < 0 ? c - 1u - c / 2u : c / 2u;
    uint32_t q0, u;
#if ZL_MUL32_ONLY
    if (m >= c * ((1u << 15) - 1u)) /* q0 >= 2^15 - 1; below it m < c 2^16, as zl_div16_q needs */
        return 0;
    q0 = zl_div16_q(d, m);
#else
    q0 = m / c;
    if (q0 >= (1u << 15) - 1u)
        return 0;
#endif
    u = (q0 << 16) + zl_div16_q(d, ((m - q0 * c) << 16) + bias);
    *q = n < 0 ? -(int32_t)u : (int32_t)u;
    return 1;
}

/*
 * plane_small's colour plane (vertex colours c0, c0 + e1, c0 + e2 in 8-bit
 * units, each << 16) on a small frame with |cross| below 2^16, in 32 bits:
 * the gradients' factor 2^16 taken out of the products, which then fit
 * (|e| <= 255, |dx| < 2^14, dy < 2^13, |ox|, |oy| <= 8: |ga| < 2^22,
 * |gb| < 2^23, the offset's numerator below 2^27, each shifted by k - 16
 * below 2^31). The row value modulo 2^32. 0 when a quotient is out of
 * round_div_shift's range.
 */
static ZL_ALWAYS_INLINE int colour_plane_small(const small_frame *f, const zl_div16 *d, int32_t c0, int32_t e1,
                                               int32_t e2, uint32_t *row, uint32_t *dx, uint32_t *dy)
{
    int32_t ga = e1 * f->dy2 - e2 * f->dy1, gb = f->dx1 * e2 - f->dx2 * e1, qx, qy, off;
    if (f->neg) {
        ga = -ga;
        gb = -gb;
    }
    if (!round_div_shift(ga, ZL_SUB_BITS + ZL_ATTR_FRAC, d, &qx) ||
        !round_div_shift(gb, ZL_SUB_BITS + ZL_ATTR_FRAC, d, &qy) ||
        !round_div_shift(ga * f->ox + gb * f->oy, ZL_ATTR_FRAC, d, &off))
        return 0;
    *dx = (uint32_t)qx;
    *dy = (uint32_t)qy;
    *row = ((uint32_t)c0 << ZL_ATTR_FRAC) + (uint32_t)off + (uint32_t)f->rows * (uint32_t)qy;
    return 1;
}

/* Colour channel ch of the sorted vertices' colours c into tc: 0 when it
 * needs the general set-up. d: the zl_div16 of f->c32 when that is below
 * 2^16 (one reciprocal for the three channels). */
static ZL_ALWAYS_INLINE int colour_plane(zl_tiny_colour *tc, const small_frame *f, const zl_div16 *d,
                                         const uint8_t *const *c, int ch)
{
    int32_t c0 = ZL_MESH_U8(c[0], ch), e1 = (int32_t)ZL_MESH_U8(c[1], ch) - c0, e2 = (int32_t)ZL_MESH_U8(c[2], ch) - c0;
    zl_attr a;
    if (f->c32 < 65536u && colour_plane_small(f, d, c0, e1, e2, &tc->cr[ch], &tc->cdx[ch], &tc->cdy[ch])) {
        tc->dc16[ch] = (uint32_t)zl_floor_shift32((int32_t)tc->cdx[ch], ZL_ATTR_FRAC - 16);
        return 1;
    }
    if (!plane_small(&a, f, (int64_t)c0 << 16, e1 * 65536, e2 * 65536))
        return 0;
    tc->cr[ch] = (uint32_t)(uint64_t)a.row;
    tc->cdy[ch] = (uint32_t)(uint64_t)a.dy;
    tc->cdx[ch] = (uint32_t)(uint64_t)a.dx;
    tc->dc16[ch] = step32(a.dx, ZL_ATTR_FRAC - 16);
    return 1;
}

/*
 * zl_tiny_setup for a Gouraud triangle: its edges and depth as zl_tiny, and
 * the three colour planes the general set-up makes (zl_tri_setup_rows:
 * vertex colour << 16 into plane_setup, which plane_small matches), kept
 * modulo 2^32 like the depth plane. At a pixel the triangle covers a
 * colour plane lies within 2^10 (Q20) of the vertex range, so its 32-bit
 * value there is the exact one and the row loop clamps it as attr_at
 * clamps. col[k] are the 3 bytes (r, g, b) of vertex v[k]. Same returns as
 * zl_tiny_setup.
 */
static ZL_ALWAYS_INLINE int tiny_gouraud_setup(zl_tiny *tt, zl_tiny_colour *tc, const zl_cached_vertex *const *v,
                                               const uint8_t *const *col, uint16_t height)
{
    const zl_cached_vertex *s[3];
    const uint8_t *c[3];
    small_frame f;
    zl_div16 d;
    int set, k, ch;
    s[0] = v[0];
    s[1] = v[1];
    s[2] = v[2];
    /* read only when set (|cross| >= 2^16), which GCC cannot follow here */
    f.inv.d = f.inv.v = 0;
    f.inv.shift = 0;
    set = tiny_setup_v(tt, s, height, &f, ZL_CV_FX(s[0]) != ZL_FINE_NONE);
    if (set <= 0)
        return set;
    for (k = 0; k < 3; k++) /* the colours in the sorted order */
        c[k] = s[k] == v[0] ? col[0] : (s[k] == v[1] ? col[1] : col[2]);

#if ZL_MUL32_ONLY
    d = f.d16; /* the depth plane's reciprocal serves the colour planes */
    if (d.c == 0) { /* a constant depth plane made none; plane_small below may need it too */
        zl_div16_init(&d, f.c32 < 65536u ? f.c32 : 1u);
        f.d16 = d;
    }
#else
    d.c = f.c32; /* read only when below 2^16 */
#endif
    for (ch = 0; ch < 3; ch++) {
        if (!colour_plane(tc, &f, &d, c, ch))
            return -1;
        tc->dl[ch] = zl_lane_step(tc->dc16[ch]);
    }
    return 1;
}

int zl_tiny_gouraud_setup(zl_tiny_gouraud *tg, const zl_cached_vertex *const *v, const uint8_t *const *col,
                          uint16_t height)
{
    return tiny_gouraud_setup(&tg->t, &tg->c, v, col, height);
}

/* ---------------------------------------- small flat triangles, scanline mode */

/* An edge of a zl_tiny in a record's zl_edge (ZL_KIND_TINY): N in x, its
 * change per row in step, the divisor in den (rem and rstep unused). */
static ZL_ALWAYS_INLINE void tiny_edge_in(zl_edge *e, const zl_tiny_edge *te)
{
    e->x = te->n;
    e->step = te->inc;
    e->den = te->d;
}

/* A set-up zl_tiny into record r (ZL_KIND_TINY's layout), kind aside. */
static ZL_ALWAYS_INLINE void tiny_record(zl_active *r, const zl_tiny *tt)
{
    tiny_edge_in(&r->left, &tt->lng);
    if (tt->first < tt->mid) { /* only edges with rows were set up */
        tiny_edge_in(&r->right, &tt->up);
        if (tt->mid < tt->end)
            tiny_edge_in(&r->lower, &tt->low);
    } else {
        tiny_edge_in(&r->right, &tt->low);
    }
    /* the 32-bit plane in the unused DDA fields: the row value steps with the
     * short edge (right), so it is kept apart from lower (see ZL_KIND_TINY);
     * the values are modulo 2^32 (tiny_depth), their bits kept as int32 */
    r->left.rem = (int32_t)tt->zbase; /* below 2^31: (zlo >> 2) + 2^13 */
    r->left.rstep = (int32_t)tt->zdx;
    r->right.rem = (int32_t)tt->zr;
    r->right.rstep = (int32_t)tt->zdy;
    r->zlo = (uint32_t)tt->zlo;
    r->zhi = (uint32_t)tt->zhi;
    r->dz14 = tt->dz14;
    r->ax = tt->ax;
    r->row = (int16_t)tt->first;
    r->mid = (int16_t)tt->mid;
    r->end = (int16_t)tt->end;
    r->lower_is_left = (uint8_t)tt->long_left;
}

int zl_tiny_setup_record(zl_active *r, const zl_cached_vertex *a, const zl_cached_vertex *b, const zl_cached_vertex *c,
                         uint16_t width, uint16_t height)
{
    zl_tiny tt; /* in line: its fields go straight to the record */
    int set;
    tt.low.n = tt.low.inc = tt.low.d = 0; /* set below when they have rows: GCC cannot tell */
    tt.up.n = tt.up.inc = tt.up.d = 0;
    set = tiny_setup(&tt, a, b, c, width, height);
    if (set <= 0)
        return set;
    r->kind = ZL_KIND_TINY;
    tiny_record(r, &tt);
    return 1;
}

int zl_tiny_gouraud_setup_record(zl_active *r, zl_tiny_colour *tc, const zl_cached_vertex *const *v,
                                 const uint8_t *const *col, uint16_t height)
{
    zl_tiny tt; /* in line: its fields go straight to the record, the colour planes to tc */
    int set;
    tt.low.n = tt.low.inc = tt.low.d = 0; /* set when they have rows: GCC cannot tell */
    tt.up.n = tt.up.inc = tt.up.d = 0;
    set = tiny_gouraud_setup(&tt, tc, v, col, height);
    if (set <= 0)
        return set;
    r->kind = ZL_KIND_TINY_GOURAUD;
    tiny_record(r, &tt);
    return 1;
}
#endif /* ZL_SMALL_TRIANGLE_SETUP */
