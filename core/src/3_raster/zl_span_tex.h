/* SPDX-License-Identifier: MIT */
/*
 * The texture and blend span loops of native RGB565 (zl_span_tex.c) and
 * what they share with zl_rows_styled.c's general loop: power-of-two
 * texel addressing, div255, the depth range check.
 */
#ifndef ZLINE_SPAN_TEX_H
#define ZLINE_SPAN_TEX_H

#include "zl_span.h"

static inline int is_pow2(uint16_t n)
{
    return (n & (n - 1u)) == 0;
}

/* round(x / 255) for 0 <= x <= 255 * 255, without a division. */
static inline unsigned div255(unsigned x)
{
    x += 128u;
    return (x + (x >> 8)) >> 8;
}

/* Whether a span's depth stepper z (Q14, rounding half added) stays below
 * 2^30 over its n pixels, where depth_of is the shift alone (both ends
 * checked: the values are linear). */
static inline int depth_exact(uint32_t z, uint32_t dz, int32_t n)
{
    int64_t end = (int64_t)z + (int64_t)(n - 1) * (int32_t)dz;
    return z < (65536u << 14) && end >= 0 && end < ((int64_t)65536 << 14);
}

/* The texel of affine coordinates (u, v) of ZL_TEX_FRAC (F) fraction bits
 * on a texture that repeats on both axes, power-of-two width, height and
 * stride (stride 2^s): the texel_index values
 * ((v >> F) & (h - 1)) * stride + ((u >> F) & (w - 1)) as two masks, an
 * add and a shift, from u and from v' = v << s (both stepped as 32-bit
 * words): the masks take bits F.. of u, which are floor(u / 2^F) modulo
 * 2^(32 - F) (two's complement; wrapping adds keep them), and bits F + s..
 * of v', the same bits of v moved to the row's offset. The two fields do
 * not overlap (stride >= width), so the add carries nothing;
 * (h - 1) << s << F must fit 32 bits. */
typedef struct {
    const uint16_t *texels;
    uint32_t umask, vmask; /* (w - 1) << F; (h - 1) << (s + F) */
    unsigned s;
} zl_repeat_pow2;

/* Whether a texture takes zl_repeat_pow2, which it then fills in. */
static inline int repeat_pow2_of(const zl_texture *tex, zl_repeat_pow2 *rp)
{
    unsigned s = 0;
    if (tex->wrap_s != ZL_WRAP_REPEAT || tex->wrap_t != ZL_WRAP_REPEAT || !is_pow2(tex->stride))
        return 0;
    while ((1u << s) < tex->stride)
        s++;
    if (((uint32_t)(tex->height - 1u) << s) >= (UINT32_C(1) << (32 - ZL_TEX_FRAC)))
        return 0;
    rp->texels = tex->texels;
    rp->umask = (uint32_t)(tex->width - 1u) << ZL_TEX_FRAC;
    rp->vmask = (uint32_t)(tex->height - 1u) << (s + ZL_TEX_FRAC);
    rp->s = s;
    return 1;
}

static ZL_ALWAYS_INLINE uint16_t texel_repeat(const uint16_t *texels, uint32_t umask, uint32_t vmask, uint32_t u,
                                              uint32_t v)
{
    return texels[((u & umask) + (v & vmask)) >> ZL_TEX_FRAC];
}

/* texel_index for an affine coordinate of 32 bits (ZL_TEX_FRAC fraction
 * bits; power-of-two size). */
static ZL_ALWAYS_INLINE uint32_t texel_wrap32(int32_t c, uint16_t size, unsigned wrap)
{
    int32_t i = zl_floor_shift32(c, ZL_TEX_FRAC);
    if (wrap == ZL_WRAP_CLAMP)
        return (uint32_t)(i < 0 ? 0 : (i >= size ? size - 1 : i));
    return (uint32_t)i & (uint32_t)(size - 1u);
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

/* persp_recip(q) from r = persp_recip(q0) of a nearby q0 (the previous
 * pixel's): with q' = q clamped as persp_recip clamps it and the remainder
 * e = 2^44 - r q' (r <= 2^32, q' <= 2^29: the product fits 63 bits),
 * floor(2^44 / q') = r + floor(e / q'). No division when 0 <= e < q' (r
 * is already the quotient), a 32-bit one when |e| < 2^31, else the full
 * one: exact in every case. */
static ZL_ALWAYS_INLINE uint64_t persp_recip_near(uint64_t r, int64_t q)
{
    const int64_t qc = q < ((int64_t)1 << 12) ? ((int64_t)1 << 12) : (q > ((int64_t)1 << 29) ? ((int64_t)1 << 29) : q);
    int64_t e = ((int64_t)1 << 44) - (int64_t)(r * (uint64_t)qc);
    if (e >= 0 && e < qc)
        return r;
    if (e > -((int64_t)1 << 31) && e < ((int64_t)1 << 31)) {
        int32_t e32 = (int32_t)e, q32 = (int32_t)qc, d = e32 / q32;
        if (d * q32 > e32) /* C truncates: floor for a negative e */
            d--;
        return (uint64_t)((int64_t)r + d);
    }
    return ((uint64_t)1 << 44) / (uint64_t)qc;
}

/* The depth test of the LESS / LEQUAL loops below and in zl_rows_styled.c:
 * d < stored (LESS) or d <= stored (LEQUAL) as d < stored + leq, leq 1 for
 * LEQUAL (stored + 1 is at most 65536): one compare either way, so one
 * loop serves both tests. */
static ZL_ALWAYS_INLINE int pass_lt_leq(uint32_t d, uint32_t stored, uint32_t leq)
{
    return d < stored + leq;
}

/* Blended spans (zl_span_tex.c): native RGB565, all channels, depth func
 * LESS or LEQUAL (zwrite: with writes), mode ZL_BLEND_ALPHA or ZL_BLEND_ADD,
 * a flat colour src (tex NULL) or an unlit affine power-of-two texture at
 * Q12 coordinates u, v stepped by du, dv (32 bits: affine_fits); exactly
 * the values of zl_rows_styled.c's blend_pixel. */
void zl_span_blend565(unsigned func, unsigned mode, int zwrite, const zl_texture *tex, unsigned alpha,
                      const unsigned *src, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                      int32_t u, int32_t du, int32_t v, int32_t dv);

/* Bilinear spans (zl_span_tex.c): an unlit affine RGB565 texture of
 * power-of-two size, unblended, into native RGB565 with all channels, depth
 * func LESS or LEQUAL with writes; exactly tex_sample's values. */
void zl_span_bilinear565(unsigned func, const zl_texture *tex, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                         uint32_t dz, int32_t u, int32_t du, int32_t v, int32_t dv);

#endif
