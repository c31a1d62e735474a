/* SPDX-License-Identifier: MIT */
/*
 * Stage 2, geometry: lighting. The light direction prepared once per draw,
 * the face normal and its diffuse intensity (an integer square root), and the
 * lit flat colour of a triangle, straight as an RGB565 pixel for the frame
 * fast path or into the polygon record for every other path.
 */
#include <string.h>

#include "zl_geometry.h"

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
#if defined(__GNUC__) && __SIZEOF_INT__ >= 4 /* __builtin_clz counts in an unsigned int */
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
    if ((((uint32_t)ZL_MESH_POS(p, 0) + COORD_LIMIT) | ((uint32_t)ZL_MESH_POS(p, 1) + COORD_LIMIT) |
         ((uint32_t)ZL_MESH_POS(p, 2) + COORD_LIMIT)) < 2u * COORD_LIMIT)
        return 1;
    return in_limit(ZL_MESH_POS(p, 0)) && in_limit(ZL_MESH_POS(p, 1)) && in_limit(ZL_MESH_POS(p, 2));
}

/* The normal of any triangle, scaled below 2^14: edges brought below 2^30
 * so the 64-bit cross product cannot overflow, then the normal shifted. */
static ZL_NOINLINE void large_normal(const zl_fixed *pos, const uint16_t *idx, int32_t *m)
{
    const zl_fixed *p0 = &pos[ZL_MESH_IDX(idx, 0) * 3u], *p1 = &pos[ZL_MESH_IDX(idx, 1) * 3u],
                   *p2 = &pos[ZL_MESH_IDX(idx, 2) * 3u];
    int64_t e[6], n[3];
    unsigned k, shift;
    for (k = 0; k < 3; k++) {
        e[k] = (int64_t)ZL_MESH_POS(p1, k) - ZL_MESH_POS(p0, k);
        e[k + 3] = (int64_t)ZL_MESH_POS(p2, k) - ZL_MESH_POS(p0, k);
    }
    shift = shift_below(max_abs(e, 6), 30);
    for (k = 0; k < 6; k++)
        e[k] = zl_floor_shift64(e[k], shift);
    for (k = 0; k < 3; k++) { /* n = e[0..2] x e[3..5] */
        unsigned i = NEXT3(k), j = NEXT3(i);
        n[k] = e[i] * e[3 + j] - e[j] * e[3 + i];
    }
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
    const zl_fixed *p0 = &pos[ZL_MESH_IDX(idx, 0) * 3u], *p1 = &pos[ZL_MESH_IDX(idx, 1) * 3u],
                   *p2 = &pos[ZL_MESH_IDX(idx, 2) * 3u];
    const zl_state *st = s->state;
    const uint32_t x0 = (uint32_t)ZL_MESH_POS(p0, 0), y0 = (uint32_t)ZL_MESH_POS(p0, 1),
                   z0 = (uint32_t)ZL_MESH_POS(p0, 2), half = 1u << 14;
    const uint32_t e0 = (uint32_t)ZL_MESH_POS(p1, 0) - x0, e1 = (uint32_t)ZL_MESH_POS(p1, 1) - y0,
                   e2 = (uint32_t)ZL_MESH_POS(p1, 2) - z0;
    const uint32_t e3 = (uint32_t)ZL_MESH_POS(p2, 0) - x0, e4 = (uint32_t)ZL_MESH_POS(p2, 1) - y0,
                   e5 = (uint32_t)ZL_MESH_POS(p2, 2) - z0;
    int32_t m0, m1, m2, dot, cosv;
    uint32_t len;
    /* every edge in [-2^14, 2^14) iff each e + 2^14 is below 2^15 */
    if (ZL_FAST_PATHS && /* off: large_normal's same numbers for every triangle (zl_config.h) */
        ((e0 + half) | (e1 + half) | (e2 + half) | (e3 + half) | (e4 + half) | (e5 + half)) < 2u * half &&
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
#if ZL_MUL32_ONLY
    return (uint8_t)zl_div255_small(c * i + 127); /* c, i <= 255 */
#else
    return (uint8_t)((c * i + 127) / 255);
#endif
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
    return fc ? (zl_rgb){ZL_MESH_U8(fc, t * 3), ZL_MESH_U8(fc, t * 3 + 1), ZL_MESH_U8(fc, t * 3 + 2)} : s->state->color;
}

/* Flat colour and lighting of source triangle t into poly. */
static ZL_ALWAYS_INLINE void shade(const zl_source *s, uint32_t t, const uint16_t *idx, zl_poly *poly,
                                    const int32_t *lq)
{
    unsigned i, k, n;
    uint32_t any = 0;
    zl_rgb c;
    if (!ZL_FEATURE_LIGHTING || !s->state->light_on) { /* off: light_on is refused (zl_state_check) */
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

void zl_light_prepare(const zl_state *st, int32_t lq[3])
{
    /* the dot product's sign flips with the winding of the front face:
     * flipping the light instead gives the same sum, once per draw */
    int32_t sign = st->front_face == ZL_FRONT_CW ? -1 : 1;
    if (!ZL_FEATURE_LIGHTING) { /* compiled out (zl_config.h): nothing reads it */
        lq[0] = lq[1] = lq[2] = 0;
        return;
    }
    lq[0] = sign * light_q14(st->light_dir.x);
    lq[1] = sign * light_q14(st->light_dir.y);
    lq[2] = sign * light_q14(st->light_dir.z);
}

uint16_t zl_tri_pixel565_lit(const zl_source *s, uint32_t t, const int32_t lq[3])
{
    zl_rgb c = face_color(s, t);
    unsigned r = c.r, g = c.g, b = c.b;
    if (ZL_FEATURE_LIGHTING && s->state->light_on) {
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
    if (ZL_FEATURE_LIGHTING && s->state->light_on) /* unlit: shade reads no light */
        zl_light_prepare(s->state, lq);
    if (!ZL_FAST_PATHS) { /* one copy of shade() (zl_config.h); else inlined here too, a call less */
        zl_tri_shade_lit(s, t, poly, lq);
        return;
    }
    shade(s, t, &s->mesh->indices[t * 3u], poly, lq);
}
