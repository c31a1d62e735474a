/* SPDX-License-Identifier: MIT */
/*
 * Stage 3, raster: rows of styled triangles (zl_tri_row_ex): textures,
 * affine or perspective-correct, perspective-correct Gouraud, the texel
 * fetch with its wrap rule and texel formats, and blending.
 */
#include <string.h>

#include "zl_raster.h"
#include "zl_span_tex.h"

/* ------------------------------------------------- textures, perspective */

/* One texel coordinate (1/256 texel) to a wrapped or clamped texel index,
 * for a power-of-two size (the fast loop's textures). */
static inline uint32_t texel_index(int64_t c8, uint16_t size, unsigned wrap)
{
    int64_t i = zl_floor_shift64(c8, 8);
    if (wrap == ZL_WRAP_CLAMP)
        return (uint32_t)(i < 0 ? 0 : (i >= size ? size - 1 : i));
    return (uint32_t)i & (uint32_t)(size - 1u); /* two's complement: modulo a power of two */
}

/* The same for any size 1 .. 4096: repeat is the non-negative remainder
 * (C's % truncates towards zero, so a negative one moves up by size). */
static inline uint32_t texel_index_any(int64_t c8, uint16_t size, unsigned wrap)
{
    int64_t i;
    if ((size & (size - 1u)) == 0 || wrap == ZL_WRAP_CLAMP)
        return texel_index(c8, size, wrap);
    i = zl_floor_shift64(c8, 8) % (int64_t)size;
    return (uint32_t)(i < 0 ? i + size : i);
}

/* A texel as 8-bit r, g, b and alpha (255 for RGB565). */
static void unpack_texel(uint16_t t, unsigned format, unsigned *r, unsigned *g, unsigned *b, unsigned *a)
{
    if (format == ZL_TEXEL_RGBA4444) {
        *r = (unsigned)(t >> 12) * 17u;
        *g = (unsigned)((t >> 8) & 15u) * 17u;
        *b = (unsigned)((t >> 4) & 15u) * 17u;
        *a = (unsigned)(t & 15u) * 17u;
    } else {
        unsigned r5 = t >> 11, g6 = (t >> 5) & 63u, b5 = t & 31u;
        *r = (r5 << 3) | (r5 >> 2);
        *g = (g6 << 2) | (g6 >> 4);
        *b = (b5 << 3) | (b5 >> 2);
        *a = 255;
    }
}

/* The texture at (u8, v8), in 1/256 texel, as 8-bit r, g, b, a (out[0..3]):
 * the texel containing it, or with ZL_FILTER_BILINEAR the four texels
 * around p = c - 1/2 weighted by the fractions of p in 1/256 (zline.h,
 * TEXTURE FILTERING). Every product stays below 2^24: 32-bit sums. */
static void tex_sample(const zl_texture *tex, unsigned filter, int64_t u8, int64_t v8, unsigned *out)
{
    if (filter != ZL_FILTER_BILINEAR) {
        uint16_t tx = tex->texels[(size_t)texel_index_any(v8, tex->height, tex->wrap_t) * tex->stride +
                                  texel_index_any(u8, tex->width, tex->wrap_s)];
        unpack_texel(tx, tex->format, &out[0], &out[1], &out[2], &out[3]);
        return;
    }
    {
        const int64_t pu = u8 - 128, pv = v8 - 128;
        /* the fraction of a floor: conversion to unsigned is modulo 2^N, so
         * the low byte of a negative p is its floor's fraction too */
        const unsigned fx = (unsigned)(uint64_t)pu & 255u, fy = (unsigned)(uint64_t)pv & 255u;
        const size_t x0 = (size_t)texel_index_any(pu, tex->width, tex->wrap_s);
        const size_t x1 = (size_t)texel_index_any(pu + 256, tex->width, tex->wrap_s);
        const uint16_t *r0 = tex->texels + (size_t)texel_index_any(pv, tex->height, tex->wrap_t) * tex->stride;
        const uint16_t *r1 = tex->texels + (size_t)texel_index_any(pv + 256, tex->height, tex->wrap_t) * tex->stride;
        unsigned c[4][4], k;
        unpack_texel(r0[x0], tex->format, &c[0][0], &c[0][1], &c[0][2], &c[0][3]);
        unpack_texel(r0[x1], tex->format, &c[1][0], &c[1][1], &c[1][2], &c[1][3]);
        unpack_texel(r1[x0], tex->format, &c[2][0], &c[2][1], &c[2][2], &c[2][3]);
        unpack_texel(r1[x1], tex->format, &c[3][0], &c[3][1], &c[3][2], &c[3][3]);
        for (k = 0; k < 4; k++) {
            uint32_t top = c[0][k] * (256u - fx) + c[1][k] * fx, bottom = c[2][k] * (256u - fx) + c[3][k] * fx;
            out[k] = (unsigned)((top * (256u - fy) + bottom * fy + 32768u) >> 16);
        }
    }
}

/* Blend (r, g, b) with alpha a (1..255) into the pixel at p (see BLENDING
 * in zline.h): the old pixel widened to 8 bits per channel, the result
 * packed and written through the colour mask. */
static void blend_pixel(uint8_t *p, const zl_span_state *ss, unsigned mode, const unsigned *src, unsigned a)
{
    unsigned old[3], out[3], k;
    uint8_t pix[3] = {0, 0, 0};
    if (ss->format == ZL_FORMAT_RGB888) {
        old[0] = p[0];
        old[1] = p[1];
        old[2] = p[2];
    } else {
        uint16_t v;
        unsigned a8;
        if (ss->format == ZL_FORMAT_RGB565)
            memcpy(&v, p, 2);
        else
            v = (uint16_t)(((unsigned)p[0] << 8) | p[1]);
        unpack_texel(v, ZL_TEXEL_RGB565, &old[0], &old[1], &old[2], &a8);
    }
    for (k = 0; k < 3; k++) {
        if (mode == ZL_BLEND_ADD) {
            unsigned v = old[k] + div255(src[k] * a);
            out[k] = v > 255u ? 255u : v;
        } else {
            out[k] = div255(src[k] * a + old[k] * (255u - a));
        }
    }
    pack_color((zl_format)ss->format, out[0], out[1], out[2], pix);
    put_pixel(p, ss->bpp, pix, ss->keep);
}

/* floor(a r / 2^sh) (sh <= 31) for |a| >= 2^31, where a r leaves 64 bits:
 * a = hi 2^31 + lo with 0 <= lo < 2^31, so floor(a r / 2^sh) =
 * hi r 2^(31 - sh) + floor(lo r / 2^sh) exactly (the first term is a whole
 * number). Exact for |a| < 2^51 (a texture coordinate of Q16.16 on a
 * 4096-texel texture gives |a| < 2^45); beyond, saturated (fuzz_style's
 * finding: a r overflowed, undefined behaviour). */
static ZL_NOINLINE int64_t persp_apply_wide(int64_t a, uint64_t r, unsigned sh)
{
    const int64_t lim = (int64_t)1 << 51;
    int64_t hi, lo;
    if (a >= lim || a <= -lim)
        return a > 0 ? (int64_t)1 << 62 : -((int64_t)1 << 62);
    hi = zl_floor_shift64(a, 31);
    lo = a - hi * ((int64_t)1 << 31);
    return hi * (int64_t)(r << (31u - sh)) + (int64_t)(((uint64_t)lo * r) >> sh);
}

/* (a q) / q from the plane value a and r = persp_recip(q), for |a| < 2^31
 * (then a r fits 64 bits: r <= 2^32): a texture coordinate plane (u q in
 * units 2^-16 q texel, zl_internal.h) in 1/256 texel. The spans that use
 * it check their planes once (persp_fits). */
static ZL_ALWAYS_INLINE int64_t persp_apply_fast(int64_t a, uint64_t r)
{
    return zl_floor_shift64(a * (int64_t)r, ZL_PERSP_SHIFT);
}

/* floor(a r / 2^sh) for any a: the wide form where a leaves 31 bits. */
static inline int64_t persp_apply_by(int64_t a, uint64_t r, unsigned sh)
{
    if ((uint64_t)a + ((uint64_t)1 << 31) < ((uint64_t)1 << 32))
        return zl_floor_shift64(a * (int64_t)r, sh);
    return persp_apply_wide(a, r, sh);
}

/* persp_apply_fast for any a. */
static inline int64_t persp_apply(int64_t a, uint64_t r)
{
    return persp_apply_by(a, r, ZL_PERSP_SHIFT);
}

/* Whether a perspective plane a, stepped by da, stays within +-2^31 over n
 * steps (linear: its ends bound it), so persp_apply_fast takes it. da is
 * bounded first, so the product cannot overflow (n < 2^16). */
static int persp_fits(int64_t a, int64_t da, int32_t n)
{
    const int64_t lim = (int64_t)1 << 31;
    int64_t end;
    if (a <= -lim || a >= lim || da <= -lim || da >= lim)
        return 0;
    end = a + (int64_t)n * da;
    return end > -lim && end < lim;
}

/* Whether an affine coordinate plane (Q16 texels, ZL_TEX_FRAC, stepped per
 * pixel) stays within +-2^30 over a span of n pixels (16384 texels): then
 * 32 bits hold it exactly. */
static int affine_fits(int64_t a, int64_t da, int32_t n)
{
    const int64_t lim = (int64_t)1 << 30;
    int64_t end;
    if (a <= -lim || a >= lim || da <= -lim || da >= lim)
        return 0; /* da first: (n - 1) da cannot overflow after it */
    end = a + (int64_t)(n - 1) * da;
    return end > -lim && end < lim;
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
                crow[i] = texel_at(tex, zl_floor_shift64(u, ZL_TEX_SHIFT), zl_floor_shift64(v, ZL_TEX_SHIFT));
            }
            z += dz;
            u += du;
            v += dv;
        }
        return;
    }
    {
        int64_t u8 = 0, v8 = 0, su = 0, sv = 0;
        uint64_t r = persp_recip(Q); /* every 1: the previous pixel's, for persp_recip_near */
        for (i = 0; i < n; i++) {
            uint32_t d = depth_of(z);
            if (every == 1) {
                r = persp_recip_near(r, Q);
                u8 = persp_apply(U, r);
                v8 = persp_apply(V, r);
            } else if ((i & (int32_t)(every - 1)) == 0) {
                uint64_t r2 = persp_recip(Q + (int64_t)every * dQ);
                r = persp_recip(Q);
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

/* span_tex565's affine loop on a zl_repeat_pow2 texture, v as v' (above);
 * depth z shifted alone when `clamp` is 0 (the caller checked the range). */
static ZL_ALWAYS_INLINE void span_tex565_repeat(uint32_t leq, int clamp, const uint16_t *texels, uint32_t umask,
                                                uint32_t vmask, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                                                uint32_t dz, uint32_t u, uint32_t du, uint32_t v, uint32_t dv)
{
    const uint16_t *zend = zrow + n;
    while (zrow != zend) {
        uint32_t d = clamp ? depth_of(z) : z >> 14;
        if (pass_lt_leq(d, *zrow, leq)) {
            *zrow = (uint16_t)d;
            *crow = texel_repeat(texels, umask, vmask, u, v);
        }
        zrow++;
        crow++;
        z += dz;
        u += du;
        v += dv;
    }
}

/* span_tex565's perspective loop exact every `every` (2^shift) pixels on a
 * zl_repeat_pow2 texture: one reciprocal a segment (its end's, which is
 * the next segment's start: the planes are stepped by exact adds, so
 * every start is the value the general loop computes there; stepped from
 * the start's by persp_recip_near, exact), and between
 * the exact points the 1/256-texel coordinates stepped as 32-bit words,
 * read through the masks moved to 8 fraction bits (zl_repeat_pow2, the
 * same argument: the masks keep bits that wrapping adds keep). */
static ZL_ALWAYS_INLINE void span_persp_repeat(uint32_t leq, const zl_repeat_pow2 *rp, unsigned every,
                                               unsigned shift, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                                               uint32_t dz, int64_t U, int64_t dU, int64_t V, int64_t dV, int64_t Q,
                                               int64_t dQ)
{
    const uint16_t *tx = rp->texels;
    const uint32_t um = rp->umask >> ZL_TEX_SHIFT, vm = rp->vmask >> ZL_TEX_SHIFT;
    const unsigned s = rp->s;
    const uint16_t *zend = zrow + n;
    uint64_t r = persp_recip(Q);
    int64_t u8 = persp_apply_fast(U, r), v8 = persp_apply_fast(V, r);
    while (zrow != zend) {
        int32_t m = zend - zrow < (int32_t)every ? (int32_t)(zend - zrow) : (int32_t)every;
        uint64_t r2 = persp_recip_near(r, Q + (int64_t)every * dQ); /* from the start's */
        int64_t u8n = persp_apply_fast(U + (int64_t)every * dU, r2), v8n = persp_apply_fast(V + (int64_t)every * dV, r2);
        /* conversion to unsigned is modulo 2^32: the low bits the masks read */
        uint32_t u = (uint32_t)(uint64_t)u8, v = (uint32_t)(uint64_t)v8 << s;
        uint32_t su = (uint32_t)(uint64_t)zl_floor_shift64(u8n - u8, shift);
        uint32_t sv = (uint32_t)(uint64_t)zl_floor_shift64(v8n - v8, shift) << s;
        for (; m > 0; m--) {
            uint32_t d = depth_of(z);
            if (pass_lt_leq(d, *zrow, leq)) {
                *zrow = (uint16_t)d;
                *crow = tx[((u & um) + (v & vm)) >> 8];
            }
            zrow++;
            crow++;
            z += dz;
            u += su;
            v += sv;
        }
        Q += (int64_t)every * dQ;
        U += (int64_t)every * dU;
        V += (int64_t)every * dV;
        u8 = u8n;
        v8 = v8n;
        r = r2;
    }
}

/* span_tex565's perspective loop exact at every pixel on a zl_repeat_pow2
 * texture: the reciprocal from the previous pixel's (persp_recip_near),
 * the texel through the masks at 8 fraction bits (span_persp_repeat). */
static ZL_NOINLINE void span_persp1_repeat(uint32_t leq, const zl_repeat_pow2 *rp, uint16_t *crow, uint16_t *zrow,
                                           int32_t n, uint32_t z, uint32_t dz, int64_t U, int64_t dU, int64_t V,
                                           int64_t dV, int64_t Q, int64_t dQ)
{
    const uint16_t *tx = rp->texels;
    const uint32_t um = rp->umask >> ZL_TEX_SHIFT, vm = rp->vmask >> ZL_TEX_SHIFT;
    const unsigned s = rp->s;
    uint64_t r = persp_recip(Q);
    int32_t i;
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        r = persp_recip_near(r, Q);
        if (pass_lt_leq(d, zrow[i], leq)) {
            /* conversion to unsigned is modulo 2^32: the low bits the masks read */
            uint32_t u = (uint32_t)(uint64_t)persp_apply_fast(U, r), v = (uint32_t)(uint64_t)persp_apply_fast(V, r) << s;
            zrow[i] = (uint16_t)d;
            crow[i] = tx[((u & um) + (v & vm)) >> 8];
        }
        z += dz;
        Q += dQ;
        U += dU;
        V += dV;
    }
}

static ZL_NOINLINE void span_persp_repeat_any(unsigned func, const zl_repeat_pow2 *rp, unsigned every,
                                              unsigned shift, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                                              uint32_t dz, int64_t U, int64_t dU, int64_t V, int64_t dV, int64_t Q,
                                              int64_t dQ)
{
    span_persp_repeat(func == ZL_LEQUAL, rp, every, shift, crow, zrow, n, z, dz, U, dU, V, dV, Q, dQ);
}

static ZL_NOINLINE void span_tex565_repeat_any(unsigned func, const zl_repeat_pow2 *rp, uint16_t *crow,
                                               uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz, int64_t U,
                                               int64_t dU, int64_t V, int64_t dV)
{
    /* the low 32 bits of the 64-bit planes: conversion to unsigned is modulo 2^32 */
    uint32_t u = (uint32_t)(uint64_t)U, du = (uint32_t)(uint64_t)dU, v = (uint32_t)(uint64_t)V << rp->s,
             dv = (uint32_t)(uint64_t)dV << rp->s;
    const uint16_t *tx = rp->texels;
    uint32_t um = rp->umask, vm = rp->vmask;
    int exact = depth_exact(z, dz, n);
    /* constants for the common case (LESS, z exact): its loop has no add
     * for the test (leq 0) and no clamp */
    if (exact && func == ZL_LESS)
        span_tex565_repeat(0, 0, tx, um, vm, crow, zrow, n, z, dz, u, du, v, dv);
    else
        span_tex565_repeat(func == ZL_LEQUAL, 1, tx, um, vm, crow, zrow, n, z, dz, u, du, v, dv);
}

static void row_span_ex(const zl_active *t, const zl_gouraud *g, const zl_texplanes *tp, const zl_style *sty,
                        const zl_span_state *ss, uint8_t *crow, uint16_t *zrow)
{
    const zl_texture *tex = sty->texcoords != NULL ? sty->texture : NULL;
    const int64_t f16 = 1 << (ZL_ATTR_FRAC - 16), big = (int64_t)1 << 40;
    int32_t x0 = t->left.x, x1 = t->right.x, i, n;
    int persp = sty->tex_mapping == ZL_TEX_PERSPECTIVE, pg = g != NULL && ss->gouraud && sty->persp_gouraud;
    int lg = g != NULL && ss->gouraud && !sty->persp_gouraud; /* screen-linear Gouraud (blending) */
    unsigned blend = sty->blend;
    uint32_t lc[3] = {0, 0, 0}, ldc[3] = {0, 0, 0};
    unsigned a, tc[4] = {0, 0, 0, 0}, filter = sty->tex_filter;
    int sampled;
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
    if (lg)
        for (k = 0; k < 3; k++) {
            /* as row_span's Gouraud span (zl_rows.c): Q16 steppers, rounding half added */
            int64_t v = attr_at(&g->c[k], x0, t->ax, 0, (int64_t)255 << ZL_ATTR_FRAC);
            lc[k] = (uint32_t)zl_floor_shift64(v, ZL_ATTR_FRAC - 16) + (1u << 15);
            ldc[k] = step32(g->c[k].dx, ZL_ATTR_FRAC - 16);
        }
    crow = crow ? crow + (size_t)x0 * ss->bpp : NULL;
    zrow = zrow ? zrow + x0 : NULL;
    if ((crow == NULL && ss->bpp != 0) || (zrow == NULL && (ss->zwrite || func != ZL_ALWAYS)))
        return; /* as in row_span */
    if (ZL_FAST_SPANS && tex != NULL && blend == ZL_BLEND_OFF && filter == ZL_FILTER_NEAREST && tex->format == ZL_TEXEL_RGB565 &&
        is_pow2(tex->width) &&
        is_pow2(tex->height) && light == 255 && ss->format == ZL_FORMAT_RGB565 && ss->bpp == 2 && ss->zwrite &&
        ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)crow & 1u) == 0 && (func == ZL_LESS || func == ZL_LEQUAL) &&
        (persp ? persp_fits(U, dU, n + (int32_t)every) && persp_fits(V, dV, n + (int32_t)every)
               : affine_fits(U, dU, n) && affine_fits(V, dV, n))) {
        /* The common case in its own loop: the texel is the pixel (RGB565,
         * unlit, all channels), depth LESS or LEQUAL with writes; the same
         * values as the general loop below, computed with fewer steps. */
        zl_repeat_pow2 rp;
        if (persp && every == 1 && repeat_pow2_of(tex, &rp)) {
            span_persp1_repeat(func == ZL_LEQUAL, &rp, (uint16_t *)(void *)crow, zrow, n, z, dz, U, dU, V, dV, Q, dQ);
            return;
        }
        if (persp && every > 1 && repeat_pow2_of(tex, &rp)) {
            span_persp_repeat_any(func, &rp, every, shift, (uint16_t *)(void *)crow, zrow, n, z, dz, U, dU, V, dV, Q,
                                  dQ);
            return;
        }
        if (!persp && repeat_pow2_of(tex, &rp)) {
            span_tex565_repeat_any(func, &rp, (uint16_t *)(void *)crow, zrow, n, z, dz, U, dU, V, dV);
            return;
        }
        if (func == ZL_LESS)
            span_tex565(ZL_LESS, tex, persp, every, shift, (uint16_t *)(void *)crow, zrow, n, z, dz, U, dU, V, dV, Q, dQ);
        else
            span_tex565(ZL_LEQUAL, tex, persp, every, shift, (uint16_t *)(void *)crow, zrow, n, z, dz, U, dU, V, dV, Q,
                        dQ);
        return;
    }
    if (ZL_FAST_SPANS && tex != NULL && blend == ZL_BLEND_OFF && filter == ZL_FILTER_BILINEAR && !persp && light == 255 &&
        tex->format == ZL_TEXEL_RGB565 && is_pow2(tex->width) && is_pow2(tex->height) &&
        ss->format == ZL_FORMAT_RGB565 && ss->bpp == 2 && ss->zwrite && ss->keep[0] == 0 && ss->keep[1] == 0 &&
        ((uintptr_t)crow & 1u) == 0 && (func == ZL_LESS || func == ZL_LEQUAL) && affine_fits(U, dU, n) &&
        affine_fits(V, dV, n)) {
        zl_span_bilinear565(func, tex, (uint16_t *)(void *)crow, zrow, n, z, dz, (int32_t)U, (int32_t)dU, (int32_t)V,
                            (int32_t)dV);
        return;
    }
    if (ZL_FAST_SPANS && blend != ZL_BLEND_OFF && !pg && !lg && ss->format == ZL_FORMAT_RGB565 && ss->bpp == 2 && zrow != NULL &&
        ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)crow & 1u) == 0 && (func == ZL_LESS || func == ZL_LEQUAL) &&
        (tex == NULL || (!persp && light == 255 && filter == ZL_FILTER_NEAREST && is_pow2(tex->width) && is_pow2(tex->height) &&
                         affine_fits(U, dU, n) && affine_fits(V, dV, n)))) {
        unsigned src[3];
        src[0] = t->rgb[0];
        src[1] = t->rgb[1];
        src[2] = t->rgb[2];
        if (sty->alpha != 0 || tex != NULL) /* constant alpha 0 discards every fragment */
            zl_span_blend565(func, blend, ss->zwrite, tex, sty->alpha, src, (uint16_t *)(void *)crow, zrow, n, z, dz,
                              (int32_t)U, (int32_t)dU, (int32_t)V, (int32_t)dV);
        return;
    }
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (tex != NULL) {
            if (!persp) {
                u8 = zl_floor_shift64(U, ZL_TEX_SHIFT);
                v8 = zl_floor_shift64(V, ZL_TEX_SHIFT);
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
        /* blending's alpha; a fragment of alpha 0 is discarded (no colour, no depth) */
        sampled = 0;
        a = 255u;
        if (blend != ZL_BLEND_OFF) {
            a = sty->alpha;
            if (tex != NULL && tex->format == ZL_TEXEL_RGBA4444) {
                tex_sample(tex, filter, u8, v8, tc);
                sampled = 1;
                a = div255(a * tc[3]);
            }
        }
        if (a != 0 && (func == ZL_ALWAYS || depth_pass(func, d, zrow[i]))) {
            if (ss->zwrite)
                zrow[i] = (uint16_t)d;
            if (ss->bpp != 0) {
                unsigned r, gg, b;
                if (tex != NULL) {
                    if (!sampled)
                        tex_sample(tex, filter, u8, v8, tc);
                    r = tc[0];
                    gg = tc[1];
                    b = tc[2];
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
                        cc[k] = zl_floor_shift64(persp_apply_by(C[k], rq, 20) + (1 << 15), 16);
                        cc[k] = cc[k] < 0 ? 0 : (cc[k] > 255 ? 255 : cc[k]);
                    }
                    r = (unsigned)cc[0];
                    gg = (unsigned)cc[1];
                    b = (unsigned)cc[2];
                } else if (lg) {
                    r = channel_of(lc[0]);
                    gg = channel_of(lc[1]);
                    b = channel_of(lc[2]);
                } else {
                    r = t->rgb[0];
                    gg = t->rgb[1];
                    b = t->rgb[2];
                }
                if (blend != ZL_BLEND_OFF) {
                    unsigned src[3];
                    src[0] = r;
                    src[1] = gg;
                    src[2] = b;
                    blend_pixel(crow + (size_t)i * ss->bpp, ss, blend, src, a);
                } else {
                    pack_color((zl_format)ss->format, r, gg, b, pix);
                    put_pixel(crow + (size_t)i * ss->bpp, ss->bpp, pix, ss->keep);
                }
            }
        }
        z += dz;
        Q += dQ;
        U += dU;
        V += dV;
        u8 += su;
        v8 += sv;
        for (k = 0; k < 3; k++) {
            C[k] += dC[k];
            lc[k] += ldc[k];
        }
    }
}

int zl_tri_row_ex(zl_active *t, zl_gouraud *g, zl_texplanes *tp, const zl_style *sty, const zl_span_state *ss,
                  uint8_t *color_row, uint16_t *depth_row)
{
    int k;
    /* without textures and blending (zl_config.h) no style needs planes */
    if (!(ZL_FEATURE_TEXTURES || ZL_FEATURE_BLEND) || tp == NULL || !zl_style_needs_planes(sty))
        return zl_tri_row(t, g, ss, color_row, depth_row);
    if (tp->persp) {
        /* a clipped triangle across the eye plane: its affine texture is
         * perspective-correct (zline.h, Clipping); the span loop is that of
         * perspective styles, so the common spans' code stays as it was */
        zl_style ps = *sty;
        ps.tex_mapping = ZL_TEX_PERSPECTIVE;
        row_span_ex(t, ps.persp_gouraud || ps.blend != ZL_BLEND_OFF ? g : NULL, tp, &ps, ss, color_row, depth_row);
    } else {
        row_span_ex(t, sty->persp_gouraud || sty->blend != ZL_BLEND_OFF ? g : NULL, tp, sty, ss, color_row, depth_row);
    }
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
