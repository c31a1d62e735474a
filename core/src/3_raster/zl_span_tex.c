/* SPDX-License-Identifier: MIT */
/*
 * Stage 3, raster: the blended and bilinear span loops of native RGB565
 * (see zl_span_tex.h), split from zl_rows_styled.c, which picks them.
 */
#include "zl_span_tex.h"

/*
 * Lanes of the blended spans: red and blue of a pixel in the two 16-bit
 * halves of one word (red high), so one multiply and one add treat both.
 * Every value a lane holds stays below 65536 (noted at each step), so no
 * lane carries into the other and each lane computes exactly what the
 * per-channel code (blend_pixel) does.
 */
#define ZL_LANES_LO UINT32_C(0x00FF00FF)

/* The old RGB565 pixel widened to 8 bits a channel (bit replication):
 * red and blue as lanes, green alone. r5 * 33 >> 2 is (r5 << 3) | (r5 >> 2)
 * (at most 1023 before the shift); the mask drops what red's shift moves
 * into blue's lane. */
static ZL_ALWAYS_INLINE uint32_t widen_rb(uint32_t old)
{
    uint32_t t = old & 0xF81Fu;
    uint32_t rb5 = (t | (t << 5)) & UINT32_C(0x001F001F);
    return ((rb5 * 33u) >> 2) & ZL_LANES_LO;
}

static ZL_ALWAYS_INLINE uint32_t widen_g(uint32_t old)
{
    return ((((old >> 5) & 63u) * 65u) >> 4);
}

/* div255 in each lane of x + 128 (x + 128 at most 65153 a lane, and
 * x + 128 + (x + 128) >> 8 at most 65407): the rounded quotients, in the
 * top byte of each lane. */
static ZL_ALWAYS_INLINE uint32_t div255_lanes_hi(uint32_t x128)
{
    return x128 + ((x128 >> 8) & ZL_LANES_LO);
}

/* The RGB565 pixel of lanes whose quotients are in the top byte of each
 * lane (rbq) and green's (gq: its quotient in bits 8..15). */
static ZL_ALWAYS_INLINE uint16_t pack_hi(uint32_t rbq, uint32_t gq)
{
    return (uint16_t)(((rbq >> 16) & 0xF800u) | ((gq >> 5) & 0x07E0u) | ((rbq >> 11) & 0x1Fu));
}

/* Alpha: div255(s a + o (255 - a)) a channel, s a as lanes plus 128 each
 * (sa_rb) and alone plus 128 (sa_g); each sum is at most 255 * 255 + 128. */
static ZL_ALWAYS_INLINE uint16_t blend_alpha_lanes(uint32_t old, uint32_t sa_rb, uint32_t sa_g, uint32_t na)
{
    uint32_t rb = div255_lanes_hi(widen_rb(old) * na + sa_rb);
    uint32_t g = widen_g(old) * na + sa_g;
    return pack_hi(rb, g + (g >> 8));
}

/* Additive: min(255, o + add) a channel, add already rounded (at most 255,
 * so a lane sum is at most 510: bit 8 says it saturates). */
static ZL_ALWAYS_INLINE uint16_t blend_add_lanes(uint32_t old, uint32_t add_rb, uint32_t add_g)
{
    uint32_t rb = widen_rb(old) + add_rb, g = widen_g(old) + add_g;
    uint32_t over = rb & UINT32_C(0x01000100);
    rb = (rb | (over - (over >> 8))) & ZL_LANES_LO;
    if (g > 255u)
        g = 255u;
    return (uint16_t)(((rb >> 8) & 0xF800u) | ((g >> 2) << 5) | ((rb & 0xFFu) >> 3));
}

/* A texel's channels as lanes (red, blue) and green, 8 bits each. */
static ZL_ALWAYS_INLINE void texel_lanes(uint16_t tx, unsigned format, uint32_t *rb, uint32_t *g)
{
    if (format == ZL_TEXEL_RGBA4444) {
        *rb = (((uint32_t)(tx >> 12) << 16) | ((tx >> 4) & 15u)) * 17u;
        *g = ((tx >> 8) & 15u) * 17u;
    } else {
        *rb = widen_rb(tx);
        *g = widen_g(tx);
    }
}

/* What a blended span takes its colour from: a flat colour, a texture that
 * repeats (zl_repeat_pow2), any other power-of-two texture. */
enum { ZL_BLEND_FLAT, ZL_BLEND_REPEAT, ZL_BLEND_TEXTURE };

/*
 * Blended spans in their own loop (the common case of BLENDING): native
 * RGB565, all channels, depth LESS or LEQUAL, a flat colour (src, already
 * lit) or an unlit affine texture of power-of-two size; exactly the values
 * of the general loop (blend_pixel), with the constant parts hoisted and
 * red and blue in lanes (above).
 */
static ZL_ALWAYS_INLINE void span_blend565(uint32_t leq, unsigned mode, int zwrite, unsigned kind,
                                           const zl_texture *tex, const zl_repeat_pow2 *rp, unsigned alpha,
                                           const unsigned *src, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                                           uint32_t dz, uint32_t u, uint32_t du, uint32_t v, uint32_t dv)
{
    uint32_t srb, sg, na = 255u - alpha;
    int32_t i;
    /* the texture's fields in locals: the loop's stores cannot change them */
    const uint16_t *rtx = rp->texels;
    if (kind == ZL_BLEND_TEXTURE && tex == NULL)
        return; /* cannot happen (the caller chose the kind from tex): for the analyser */
    const uint32_t rum = rp->umask, rvm = rp->vmask;
    const unsigned fmt = tex != NULL ? tex->format : 0u;
    uint8_t alpha_of[16]; /* div255(alpha 17 t) of each RGBA4444 texel alpha t */
    if (kind != ZL_BLEND_FLAT && fmt == ZL_TEXEL_RGBA4444)
        for (i = 0; i < 16; i++)
            alpha_of[i] = (uint8_t)div255(alpha * (unsigned)i * 17u);
    if (mode == ZL_BLEND_ADD) { /* flat: the rounded share */
        srb = ((uint32_t)div255(src[0] * alpha) << 16) | div255(src[2] * alpha);
        sg = div255(src[1] * alpha);
    } else { /* flat: s a + 128 */
        srb = ((uint32_t)(src[0] * alpha) << 16) + src[2] * alpha + UINT32_C(0x00800080);
        sg = src[1] * alpha + 128u;
    }
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (pass_lt_leq(d, zrow[i], leq)) {
            uint32_t old = crow[i], arb = srb, ag = sg, nk = na;
            unsigned a = alpha;
            if (kind != ZL_BLEND_FLAT) {
                uint32_t crb, cg;
                /* power-of-two sizes (the caller checked), wrap or clamp per
                 * axis; repeat on both by zl_repeat_pow2, v as its v' */
                uint16_t tx = kind == ZL_BLEND_REPEAT
                                  ? texel_repeat(rtx, rum, rvm, u, v)
                                  : tex->texels[(size_t)texel_wrap32((int32_t)v, tex->height, tex->wrap_t) * tex->stride +
                                                texel_wrap32((int32_t)u, tex->width, tex->wrap_s)];
                texel_lanes(tx, fmt, &crb, &cg);
                if (fmt == ZL_TEXEL_RGBA4444)
                    a = alpha_of[tx & 15u];
                nk = 255u - a;
                if (mode == ZL_BLEND_ADD) {
                    /* div255 of c a in each lane: at most 65025 + 128 */
                    arb = (div255_lanes_hi(crb * a + UINT32_C(0x00800080)) >> 8) & ZL_LANES_LO;
                    ag = div255((unsigned)(cg * a)); /* cg < 256 */
                } else {
                    arb = crb * a + UINT32_C(0x00800080);
                    ag = cg * a + 128u;
                }
            }
            if (kind == ZL_BLEND_FLAT || a != 0) { /* flat: the caller drops alpha 0 */
                if (zwrite)
                    zrow[i] = (uint16_t)d;
                crow[i] = mode == ZL_BLEND_ADD ? blend_add_lanes(old, arb, ag) : blend_alpha_lanes(old, arb, ag, nk);
            }
        }
        z += dz;
        u += du;
        v += dv;
    }
}

/* One bilinear tap index of a power-of-two axis, from its floor index. */
static ZL_ALWAYS_INLINE uint32_t tap_pow2(int32_t i, uint16_t size, unsigned wrap)
{
    if (wrap == ZL_WRAP_CLAMP)
        return (uint32_t)(i < 0 ? 0 : (i >= size ? size - 1 : i));
    return (uint32_t)i & (uint32_t)(size - 1u);
}

/* A 565 texel's channel widened to 8 bits (shift, mask, replicate). */
static ZL_ALWAYS_INLINE unsigned ch565(unsigned t, unsigned k)
{
    unsigned c;
    if (k == 0) {
        c = t >> 11;
        return (c << 3) | (c >> 2);
    }
    if (k == 1) {
        c = (t >> 5) & 63u;
        return (c << 2) | (c >> 4);
    }
    c = t & 31u;
    return (c << 3) | (c >> 2);
}

/*
 * Bilinear spans in their own loop: an unlit affine RGB565 texture of
 * power-of-two size, unblended, into native RGB565 with all channels and
 * depth LESS or LEQUAL with writes; exactly tex_sample's values.
 */
static ZL_ALWAYS_INLINE void span_bilinear565(unsigned func, const zl_texture *tex, uint16_t *crow, uint16_t *zrow,
                                              int32_t n, uint32_t z, uint32_t dz, int32_t u, int32_t du, int32_t v,
                                              int32_t dv)
{
    int32_t i;
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (depth_pass(func, d, zrow[i])) {
            int32_t pu = zl_floor_shift32(u, ZL_TEX_SHIFT) - 128, pv = zl_floor_shift32(v, ZL_TEX_SHIFT) - 128;
            unsigned fx = (uint32_t)pu & 255u, fy = (uint32_t)pv & 255u, k, o[3];
            int32_t iu = zl_floor_shift32(pu, 8), iv = zl_floor_shift32(pv, 8);
            uint32_t x0 = tap_pow2(iu, tex->width, tex->wrap_s), x1 = tap_pow2(iu + 1, tex->width, tex->wrap_s);
            const uint16_t *r0 = tex->texels + (size_t)tap_pow2(iv, tex->height, tex->wrap_t) * tex->stride;
            const uint16_t *r1 = tex->texels + (size_t)tap_pow2(iv + 1, tex->height, tex->wrap_t) * tex->stride;
            unsigned t00 = r0[x0], t10 = r0[x1], t01 = r1[x0], t11 = r1[x1];
            for (k = 0; k < 3; k++) {
                uint32_t top = ch565(t00, k) * (256u - fx) + ch565(t10, k) * fx;
                uint32_t bottom = ch565(t01, k) * (256u - fx) + ch565(t11, k) * fx;
                o[k] = (unsigned)((top * (256u - fy) + bottom * fy + 32768u) >> 16);
            }
            zrow[i] = (uint16_t)d;
            crow[i] = (uint16_t)(((o[0] >> 3) << 11) | ((o[1] >> 2) << 5) | (o[2] >> 3));
        }
        z += dz;
        u += du;
        v += dv;
    }
}

/* span_blend565 with the blend mode and the colour's source as constants,
 * the depth test LESS or LEQUAL (pass_lt_leq): each its own function, so
 * that each loop gets the registers to itself. */
#define ZL_BLEND_ARGS                                                                                               \
    uint32_t leq, int zwrite, const zl_texture *tex, const zl_repeat_pow2 *rp, unsigned alpha, const unsigned *src, \
        uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz, uint32_t u, uint32_t du, uint32_t v,   \
        uint32_t dv
#define ZL_BLEND_PASS leq, zwrite, tex, rp, alpha, src, crow, zrow, n, z, dz, u, du, v, dv
#define ZL_BLEND_LOOP(NAME, MODE, KIND)                                                                             \
    static ZL_NOINLINE void NAME(ZL_BLEND_ARGS)                                                                     \
    {                                                                                                               \
        span_blend565(leq, MODE, zwrite, KIND, tex, rp, alpha, src, crow, zrow, n, z, dz, u, du, v, dv);           \
    }
ZL_BLEND_LOOP(blend_alpha_flat, ZL_BLEND_ALPHA, ZL_BLEND_FLAT)
ZL_BLEND_LOOP(blend_alpha_repeat, ZL_BLEND_ALPHA, ZL_BLEND_REPEAT)
ZL_BLEND_LOOP(blend_alpha_texture, ZL_BLEND_ALPHA, ZL_BLEND_TEXTURE)
ZL_BLEND_LOOP(blend_add_flat, ZL_BLEND_ADD, ZL_BLEND_FLAT)
ZL_BLEND_LOOP(blend_add_repeat, ZL_BLEND_ADD, ZL_BLEND_REPEAT)
ZL_BLEND_LOOP(blend_add_texture, ZL_BLEND_ADD, ZL_BLEND_TEXTURE)

/*
 * A flat colour blended over RGB565: each output channel depends on the
 * same channel of the old pixel alone (5 or 6 bits), so the span's result
 * is three tables, built here with the loop's own lane arithmetic (the
 * same values as blend_alpha_lanes / blend_add_lanes, channel by channel),
 * then one load a channel per pixel. Worth it from ZL_BLEND_TABLE_MIN
 * pixels: building (about 1050 instructions on Cortex-M4) costs what the
 * table loop saves on some 60 pixels.
 */
enum { ZL_BLEND_TABLE_MIN = 64 };

typedef struct {
    uint16_t r[32], g[64], b[32];
} zl_blend_table565;

/* Green of old values i and i + 32 (6 bits) widened to 8, as two lanes. */
static ZL_ALWAYS_INLINE uint32_t green_pair(uint32_t i)
{
    return (((i + 32u) << 2 | (i + 32u) >> 4) << 16) | (i << 2) | (i >> 4);
}

/* The tables, 32 steps: red and blue of index i as two lanes, green of i
 * and i + 32 as two lanes (each lane below 2^16, as in the loops above). */
static void blend_table_build(zl_blend_table565 *t, unsigned mode, unsigned alpha, const unsigned *src)
{
    uint32_t i, na = 255u - alpha;
    if (mode == ZL_BLEND_ADD) { /* blend_add_lanes: min(255, o + add) a channel */
        uint32_t arb = ((uint32_t)div255(src[0] * alpha) << 16) | div255(src[2] * alpha);
        uint32_t ag2 = div255(src[1] * alpha) * UINT32_C(0x00010001);
        for (i = 0; i < 32u; i++) {
            uint32_t w = (i << 3) | (i >> 2), rb = ((w << 16) | w) + arb, g = green_pair(i) + ag2;
            uint32_t over = rb & UINT32_C(0x01000100), gover = g & UINT32_C(0x01000100);
            rb = (rb | (over - (over >> 8))) & ZL_LANES_LO;
            g = (g | (gover - (gover >> 8))) & ZL_LANES_LO;
            t->r[i] = (uint16_t)((rb >> 8) & 0xF800u);
            t->b[i] = (uint16_t)((rb & 0xFFu) >> 3);
            t->g[i] = (uint16_t)(((g & 0xFFu) >> 2) << 5);
            t->g[i + 32u] = (uint16_t)((g >> 18) << 5);
        }
        return;
    }
    /* blend_alpha_lanes: div255(s a + o (255 - a)) a channel */
    {
        uint32_t srb = ((uint32_t)(src[0] * alpha) << 16) + src[2] * alpha + UINT32_C(0x00800080);
        uint32_t sg2 = (src[1] * alpha + 128u) * UINT32_C(0x00010001);
        for (i = 0; i < 32u; i++) {
            uint32_t wn = ((i << 3) | (i >> 2)) * na;
            uint32_t q = div255_lanes_hi(((wn << 16) | wn) + srb), g = div255_lanes_hi(green_pair(i) * na + sg2);
            t->r[i] = (uint16_t)((q >> 16) & 0xF800u);
            t->b[i] = (uint16_t)((q >> 11) & 0x1Fu);
            t->g[i] = (uint16_t)((g >> 5) & 0x07E0u);
            t->g[i + 32u] = (uint16_t)((g >> 21) & 0x07E0u);
        }
    }
}

/* One pixel through the tables (below 2^16: each entry has its own bits). */
static ZL_ALWAYS_INLINE uint32_t blend_table_pixel(const uint16_t *tr, const uint16_t *tg, const uint16_t *tb,
                                                   uint32_t old)
{
    return (uint16_t)(tr[old >> 11] | tg[(old >> 5) & 63u] | tb[old & 31u]);
}

/* The table loop; `unclamped` (a constant): z stays below 2^30
 * (depth_exact), where depth_of is the shift alone. */
static ZL_ALWAYS_INLINE void blend_table_span(const zl_blend_table565 *t, uint32_t leq, int zwrite, int unclamped,
                                              uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz)
{
    int32_t i;
    for (i = 0; i < n; i++) {
        uint32_t d = unclamped ? z >> 14 : depth_of(z);
        if (pass_lt_leq(d, zrow[i], leq)) {
            /* read before the depth store (the rows may alias as far as the
             * compiler knows): GCC's ARMv6-M loop is 46.6 instructions a
             * pixel this way, 60 the other */
            uint32_t old = crow[i];
            if (zwrite)
                zrow[i] = (uint16_t)d;
            crow[i] = (uint16_t)(t->r[old >> 11] | t->g[(old >> 5) & 63u] | t->b[old & 31u]);
        }
        z += dz;
    }
}

/* The table loop with depth writes on an exact span (z < 2^30) from rows
 * of the same alignment, little-endian, two pixels a step as zl_span.c's
 * flat pair loops (zl_span.h: depth kept as y = z << 2): per pair one
 * depth load and store, one colour load and store. n even, rows 4-byte
 * aligned; a pair whose test fails is taken pixel by pixel. */
static ZL_ALWAYS_INLINE void blend_table_pairs(const uint16_t *tr, const uint16_t *tg, const uint16_t *tb,
                                               unsigned func, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t y,
                                               uint32_t dy)
{
    uint16_t *cend = crow + n, *zend = zrow + n;
    int32_t i;
    for (i = -n; i != 0; i += 2) {
        uint32_t y1 = y + dy, w = pair_load(zend + i);
        if (pair_pass(func, y, y1, w)) {
            uint32_t old = pair_load(cend + i);
            pair_store(zend + i, (y1 & 0xFFFF0000u) | (y >> 16));
            pair_store(cend + i, blend_table_pixel(tr, tg, tb, old & 0xFFFFu) |
                                     (blend_table_pixel(tr, tg, tb, old >> 16) << 16));
        } else {
            if (depth_pass(func, y >> 16, zend[i])) {
                zend[i] = (uint16_t)(y >> 16);
                cend[i] = (uint16_t)blend_table_pixel(tr, tg, tb, cend[i]);
            }
            if (depth_pass(func, y1 >> 16, zend[i + 1])) {
                zend[i + 1] = (uint16_t)(y1 >> 16);
                cend[i + 1] = (uint16_t)blend_table_pixel(tr, tg, tb, cend[i + 1]);
            }
        }
        y = y1 + dy;
    }
}

/* Pairs pay where there are registers and bit-field extracts: Cortex-M4
 * -O2 29.0 instructions a pixel of bench_features' blend against 31.2 one
 * pixel a step; on ARMv6-M (Cortex-M0) they cost more: 49.5 against 46.6. */
#if defined(__ARM_ARCH_6M__)
#define ZL_BLEND_TABLE_PAIRS 0
#else
#define ZL_BLEND_TABLE_PAIRS 1
#endif

/* The pair loop once per depth function, each its own function taking the
 * tables by pointer, so that the compiler keeps the three in registers
 * (inlined, it recomputes each from the stack pointer at every load). */
#define ZL_TABLE_PAIRS(NAME, FUNC)                                                                                  \
    static ZL_NOINLINE void NAME(const uint16_t *tr, const uint16_t *tg, const uint16_t *tb, uint16_t *crow,       \
                                 uint16_t *zrow, int32_t n, uint32_t y, uint32_t dy)                               \
    {                                                                                                               \
        blend_table_pairs(tr, tg, tb, FUNC, crow, zrow, n, y, dy);                                                  \
    }
ZL_TABLE_PAIRS(blend_table_pairs_less, ZL_LESS)
ZL_TABLE_PAIRS(blend_table_pairs_lequal, ZL_LEQUAL)

static ZL_NOINLINE void blend_table_any(unsigned mode, unsigned alpha, const unsigned *src, unsigned func, int zwrite,
                                        uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz)
{
    zl_blend_table565 t;
    uint32_t leq = func == ZL_LEQUAL;
    blend_table_build(&t, mode, alpha, src);
    if (ZL_BLEND_TABLE_PAIRS && zwrite && depth_exact(z, dz, n) && little_endian() &&
        (((uintptr_t)crow ^ (uintptr_t)zrow) & 2u) == 0) {
        if (((uintptr_t)zrow & 2u) != 0) { /* one pixel to align the rows */
            blend_table_span(&t, leq, 1, 1, crow++, zrow++, 1, z, dz);
            n--;
            z += dz;
        }
        (func == ZL_LESS ? blend_table_pairs_less : blend_table_pairs_lequal)(t.r, t.g, t.b, crow, zrow, n & ~1,
                                                                              z << 2, dz << 2);
        if (n & 1)
            blend_table_span(&t, leq, 1, 1, crow + n - 1, zrow + n - 1, 1, z + (uint32_t)(n - 1) * dz, dz);
    } else if (zwrite && depth_exact(z, dz, n)) {
        blend_table_span(&t, leq, 1, 1, crow, zrow, n, z, dz);
    } else {
        blend_table_span(&t, leq, zwrite, 0, crow, zrow, n, z, dz);
    }
}

void zl_span_blend565(unsigned func, unsigned mode, int zwrite, const zl_texture *tex, unsigned alpha,
                              const unsigned *src, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                              int32_t u32, int32_t du32, int32_t v32, int32_t dv32)
{
    if (!ZL_FEATURE_BLEND) /* compiled out (zl_config.h): unreachable, the code goes */
        return;
    if (tex == NULL && n >= ZL_BLEND_TABLE_MIN) {
        blend_table_any(mode, alpha, src, func, zwrite, crow, zrow, n, z, dz);
        return;
    }
    zl_repeat_pow2 rpv = {NULL, 0, 0, 0};
    const zl_repeat_pow2 *rp = &rpv;
    unsigned kind = tex == NULL ? ZL_BLEND_FLAT : (repeat_pow2_of(tex, &rpv) ? ZL_BLEND_REPEAT : ZL_BLEND_TEXTURE);
    uint32_t u = (uint32_t)u32, du = (uint32_t)du32, v = (uint32_t)v32, dv = (uint32_t)dv32;
    if (kind == ZL_BLEND_REPEAT) { /* v' = v << s (zl_repeat_pow2) */
        v <<= rpv.s;
        dv <<= rpv.s;
    }
    uint32_t leq = func == ZL_LEQUAL;
    if (mode == ZL_BLEND_ALPHA)
        (kind == ZL_BLEND_FLAT ? blend_alpha_flat
                               : kind == ZL_BLEND_REPEAT ? blend_alpha_repeat : blend_alpha_texture)(ZL_BLEND_PASS);
    else
        (kind == ZL_BLEND_FLAT ? blend_add_flat : kind == ZL_BLEND_REPEAT ? blend_add_repeat : blend_add_texture)(
            ZL_BLEND_PASS);
}

/* The second stage of a bilinear channel: (top (256 - fy) + bottom fy +
 * 32768) >> 16, top and bottom below 2^16. */
static ZL_ALWAYS_INLINE uint32_t bilerp_y(uint32_t top, uint32_t bottom, uint32_t fy)
{
    return (top * (256u - fy) + bottom * fy + 32768u) >> 16;
}

/*
 * span_bilinear565 on a texture that repeats on both axes (zl_repeat_pow2):
 * the taps by masks (p = c - 1/2 is u - 2^(F - 1) in QF, F = ZL_TEX_FRAC;
 * its bits F - 8 .. F - 1 are the fraction in 1/256, bits F.. the floor,
 * both kept by wrapping adds),
 * and the first stage (along x) of red and blue in the two 16-bit lanes of
 * a word: c (256 - fx) + c' fx is at most 255 * 256 a lane. The second
 * stage needs 24 bits a channel, so it takes them one by one. Exactly
 * tex_sample's values.
 */
static ZL_ALWAYS_INLINE void span_bilinear565_repeat(uint32_t leq, const zl_repeat_pow2 *rp, uint16_t *crow,
                                                     uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz, uint32_t u,
                                                     uint32_t du, uint32_t v, uint32_t dv)
{
    const uint16_t *tx = rp->texels;
    const uint32_t wm = rp->umask >> ZL_TEX_FRAC, rm = rp->vmask >> ZL_TEX_FRAC, stride = UINT32_C(1) << rp->s;
    int32_t i;
    u -= UINT32_C(1) << (ZL_TEX_FRAC - 1);
    v -= UINT32_C(1) << (ZL_TEX_FRAC - 1);
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (pass_lt_leq(d, zrow[i], leq)) {
            uint32_t fx = (u >> ZL_TEX_SHIFT) & 255u, fy = (v >> ZL_TEX_SHIFT) & 255u, gx = 256u - fx;
            uint32_t x0 = (u >> ZL_TEX_FRAC) & wm, x1 = (x0 + 1u) & wm;
            uint32_t y0 = ((v >> ZL_TEX_FRAC) << rp->s) & rm, y1 = (y0 + stride) & rm;
            uint32_t t00 = tx[y0 + x0], t10 = tx[y0 + x1], t01 = tx[y1 + x0], t11 = tx[y1 + x1];
            uint32_t top = widen_rb(t00) * gx + widen_rb(t10) * fx;
            uint32_t bottom = widen_rb(t01) * gx + widen_rb(t11) * fx;
            uint32_t gt = widen_g(t00) * gx + widen_g(t10) * fx, gb = widen_g(t01) * gx + widen_g(t11) * fx;
            uint32_t r = bilerp_y(top >> 16, bottom >> 16, fy), b = bilerp_y(top & 0xFFFFu, bottom & 0xFFFFu, fy);
            uint32_t g = bilerp_y(gt, gb, fy);
            zrow[i] = (uint16_t)d;
            crow[i] = (uint16_t)(((r >> 3) << 11) | ((g >> 2) << 5) | (b >> 3));
        }
        z += dz;
        u += du;
        v += dv;
    }
}

static ZL_NOINLINE void bilinear_repeat_any(unsigned func, const zl_repeat_pow2 *rp, uint16_t *crow, uint16_t *zrow,
                                            int32_t n, uint32_t z, uint32_t dz, uint32_t u, uint32_t du, uint32_t v,
                                            uint32_t dv)
{
    span_bilinear565_repeat(func == ZL_LEQUAL, rp, crow, zrow, n, z, dz, u, du, v, dv);
}

void zl_span_bilinear565(unsigned func, const zl_texture *tex, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                         uint32_t dz, int32_t u, int32_t du, int32_t v, int32_t dv)
{
    if (!ZL_FEATURE_TEXTURES) /* compiled out (zl_config.h): unreachable, the code goes */
        return;
    zl_repeat_pow2 rp;
    if (repeat_pow2_of(tex, &rp)) {
        bilinear_repeat_any(func, &rp, crow, zrow, n, z, dz, (uint32_t)u, (uint32_t)du, (uint32_t)v, (uint32_t)dv);
        return;
    }
    if (func == ZL_LESS)
        span_bilinear565(ZL_LESS, tex, crow, zrow, n, z, dz, u, du, v, dv);
    else
        span_bilinear565(ZL_LEQUAL, tex, crow, zrow, n, z, dz, u, du, v, dv);
}
