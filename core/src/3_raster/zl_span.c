/* SPDX-License-Identifier: MIT */
/* Stage 3, raster: span fill (see zl_span.h), the loops every flat and
 * Gouraud pixel runs, and the clears. */
#include "zl_span.h"

void zl_span_state_init(zl_span_state *ss, const zl_state *st, int has_depth, int has_color,
                        zl_format format, uint16_t width)
{
    uint8_t m[3];
    int test = st->depth_test && has_depth;
    ss->func = test ? st->depth_func : (uint8_t)ZL_ALWAYS;
    ss->zwrite = (uint8_t)(test && st->depth_write);
    ss->bpp = (uint8_t)(has_color ? zl_format_bytes(format) : 0);
    ss->format = (uint8_t)format;
    ss->gouraud = st->shading == ZL_SHADE_GOURAUD;
    ss->width = width;
    /* The mask's own bit pattern: a colour with the written channels at 255. */
    pack_color(format, (st->color_mask & ZL_MASK_R) ? 255u : 0u, (st->color_mask & ZL_MASK_G) ? 255u : 0u,
               (st->color_mask & ZL_MASK_B) ? 255u : 0u, m);
    ss->keep[0] = (uint8_t)~m[0];
    ss->keep[1] = (uint8_t)~m[1];
    ss->keep[2] = (uint8_t)~m[2];
}

/* Whether a 32-bit stepper stays inside [0, limit) over n pixels: then the
 * per-pixel clamps can go (both ends checked; the values are linear). */
static int stays_below(uint32_t start, uint32_t step, int32_t n, uint32_t limit)
{
    int64_t end = (int64_t)start + (int64_t)(n - 1) * (int32_t)step;
    return start < limit && end >= 0 && end < (int64_t)limit;
}

/* The common case in its own loop: RGB565 (either byte order), all channels,
 * depth LESS or LEQUAL with write. `func` and `clamp` are constants at each
 * call, so the compiler specialises the loop: without clamping it is a shift,
 * a compare, two stores and an add per pixel. */
static inline void span_flat_565(unsigned func, int clamp, uint16_t *crow, uint16_t *zrow, int32_t n,
                                 uint32_t z, uint32_t dz, uint16_t pixel)
{
    int32_t i;
    for (i = 0; i < n; i++) {
        uint32_t d = clamp ? depth_of(z) : z >> 14;
        if (depth_pass(func, d, zrow[i])) {
            zrow[i] = (uint16_t)d;
            crow[i] = pixel;
        }
        z += dz;
    }
}

/* One pixel of the pair loops, depth d. */
static ZL_ALWAYS_INLINE void flat_pixel(unsigned func, uint16_t *c, uint16_t *zp, uint32_t d, uint16_t pixel)
{
    if (depth_pass(func, d, *zp)) {
        *zp = (uint16_t)d;
        *c = pixel;
    }
}

/* The values of a run of pairs: depth y of its first pixel, its step dy,
 * the colour twice, and the constant 0xFFFF0000. In a struct so that a run
 * takes four arguments, all in registers (GCC reloads a stack argument in
 * the loop). The mask is a value here so that GCC keeps it in a register:
 * an `and` with it packs a depth pair in two instructions, where GCC's own
 * choice (two shifts) takes three. */
typedef struct {
    uint32_t y, dy, both, hi;
} zl_pair_run;

/* One pair of a run at pixel i: 0 when a test fails (nothing written). */
static ZL_ALWAYS_INLINE int flat_pair(unsigned func, uint16_t *cend, uint16_t *zend, int32_t i, uint32_t y,
                                      uint32_t y1, uint32_t both, uint32_t hi)
{
    uint32_t w = pair_load(zend + i);
    if (!pair_pass(func, y, y1, w))
        return 0;
    pair_store(zend + i, (y1 & hi) | (y >> 16));
    pair_store(cend + i, both);
    return 1;
}

/* Flat RGB565 on an exact span from 4-byte aligned rows, four pixels per
 * step: per pair one depth load, two compares, one depth store and one
 * colour store. The index i (a multiple of 4) runs up to 0 from the rows'
 * ends, so the loop end is an add and a branch. Returns the index of the
 * four where a test fails, 0 at the end: the loop is passing pairs alone. */
static ZL_ALWAYS_INLINE int32_t flat_pair_run(unsigned func, uint16_t *cend, uint16_t *zend, int32_t i,
                                              const zl_pair_run *r)
{
    uint32_t y = r->y, dy = r->dy, both = r->both, hi = r->hi;
    for (; i != 0; i += 4) {
        uint32_t y1 = y + dy, y2 = y1 + dy, y3 = y2 + dy;
        /* On a failing test the caller redoes these four pixels one by one,
         * which leaves a pair written here as it is (see span_flat_pairs). */
        if (!flat_pair(func, cend, zend, i, y, y1, both, hi) || !flat_pair(func, cend, zend, i + 2, y2, y3, both, hi))
            return i;
        y = y3 + dy;
    }
    return 0;
}

/* The run once per depth function, each its own function so that the
 * compiler keeps all of the loop's values in registers. */
#if !defined(ZL_NO_ASM) && defined(__GNUC__) && !defined(__clang__) && defined(__ARM_ARCH_6M__)
/*
 * ARMv6-M (Cortex-M0/M0+): flat_pair_run(ZL_LESS) by hand (issue 13: GCC's
 * loop took about 12.5 instructions a pixel there, spilling to the high
 * registers; this one 35 a step of four). Same values, same return:
 *   r0 cend, r1 zend, r2 i in bytes (negative, a multiple of 8; 0 ends),
 *   r3 y (pixel 0 of the pair), r4 the depth pair w, r5 dy, r6 y + dy,
 *   r7 scratch, r8 the colour pair. A pair passes when y < (w << 16) and
 *   (y1 >> 16) < (w >> 16); then depth (y1 & 0xFFFF0000) | (y >> 16) and
 * the colour are stored. The index of the four is returned when a test
 * fails, 0 at the end. GCC reads Thumb-1 inline assembly in divided
 * syntax (no "s" suffixes); a naked function leaves the registers to it.
 */
#define ZL_ASM_ARG __attribute__((unused)) /* read by the assembly, in r0..r3 */
__attribute__((naked, noinline)) static int32_t flat_pair_run_less(ZL_ASM_ARG uint16_t *cend, ZL_ASM_ARG uint16_t *zend,
                                                                   ZL_ASM_ARG int32_t i, ZL_ASM_ARG const zl_pair_run *r)
{
    __asm__ volatile("push {r4, r5, r6, r7, lr}\n\t"
                     "mov r4, r8\n\t"
                     "push {r4}\n\t"
                     "ldr r4, [r3, #8]\n\t" /* both */
                     "mov r8, r4\n\t"
                     "ldr r5, [r3, #4]\n\t" /* dy */
                     "ldr r3, [r3, #0]\n\t" /* y */
                     "lsl r2, r2, #1\n\t"
                     "beq 3f\n"
                     "1:\n\t"
                     "ldr r4, [r1, r2]\n\t"
                     "lsl r7, r4, #16\n\t"
                     "cmp r3, r7\n\t"
                     "bhs 2f\n\t"
                     "add r6, r3, r5\n\t"
                     "lsr r4, r4, #16\n\t"
                     "lsr r7, r6, #16\n\t"
                     "cmp r7, r4\n\t"
                     "bhs 2f\n\t"
                     "lsl r7, r7, #16\n\t"
                     "lsr r4, r3, #16\n\t"
                     "orr r4, r7\n\t"
                     "str r4, [r1, r2]\n\t"
                     "mov r7, r8\n\t"
                     "str r7, [r0, r2]\n\t"
                     "add r3, r6, r5\n\t"
                     "add r2, #4\n\t"
                     "ldr r4, [r1, r2]\n\t"
                     "lsl r7, r4, #16\n\t"
                     "cmp r3, r7\n\t"
                     "bhs 5f\n\t"
                     "add r6, r3, r5\n\t"
                     "lsr r4, r4, #16\n\t"
                     "lsr r7, r6, #16\n\t"
                     "cmp r7, r4\n\t"
                     "bhs 5f\n\t"
                     "lsl r7, r7, #16\n\t"
                     "lsr r4, r3, #16\n\t"
                     "orr r4, r7\n\t"
                     "str r4, [r1, r2]\n\t"
                     "mov r7, r8\n\t"
                     "str r7, [r0, r2]\n\t"
                     "add r3, r6, r5\n\t"
                     "add r2, #4\n\t"
                     "bne 1b\n"
                     "3:\n\t"
                     "mov r0, #0\n\t"
                     "b 4f\n"
                     "5:\n\t"
                     "sub r2, #4\n"
                     "2:\n\t"
                     "asr r0, r2, #1\n"
                     "4:\n\t"
                     "pop {r4}\n\t"
                     "mov r8, r4\n\t"
                     "pop {r4, r5, r6, r7, pc}");
}
#else
static ZL_NOINLINE int32_t flat_pair_run_less(uint16_t *cend, uint16_t *zend, int32_t i, const zl_pair_run *r)
{
    return flat_pair_run(ZL_LESS, cend, zend, i, r);
}
#endif

static ZL_NOINLINE int32_t flat_pair_run_lequal(uint16_t *cend, uint16_t *zend, int32_t i, const zl_pair_run *r)
{
    return flat_pair_run(ZL_LEQUAL, cend, zend, i, r);
}

/* Pixels taken one by one after a failing pair (even). */
#define ZL_FAIL_STRETCH 64

/* 2m pixels from 4-byte aligned rows: runs of passing pairs, and between
 * them a pair with a failing test pixel by pixel. A pair the run wrote
 * before it failed is redone too: its test fails now for LESS (d < d) and
 * rewrites the same values for LEQUAL, so the result is unchanged. y (the
 * depth in the top half) is y0 + k*dy at pixel k, which modulo 2^32 is the
 * same as stepping. */
static inline void span_flat_pairs(unsigned func, uint16_t *crow, uint16_t *zrow, int32_t m, uint32_t y0,
                                   uint32_t dy, uint16_t pixel)
{
    uint16_t *cend = crow + 2 * m, *zend = zrow + 2 * m;
    int32_t i = -2 * m;
    zl_pair_run r;
    r.dy = dy;
    r.both = (uint32_t)pixel * 0x10001u;
    r.hi = 0xFFFF0000u;
    while (i != 0) {
        uint32_t y = y0 + (uint32_t)(i + 2 * m) * dy;
        /* The run takes pixels in fours: a lone pair first when needed. */
        if (((uint32_t)i & 2u) == 0) {
            r.y = y;
            i = func == ZL_LESS ? flat_pair_run_less(cend, zend, i, &r) : flat_pair_run_lequal(cend, zend, i, &r);
            if (i == 0)
                break;
            y = y0 + (uint32_t)(i + 2 * m) * dy;
        } else if (flat_pair(func, cend, zend, i, y, y + dy, r.both, r.hi)) {
            i += 2;
            continue;
        }
        {
            /* A pair failed: the next pixels of an occluded stretch are
             * likely to fail too, where a run would stop at once; take up to
             * ZL_FAIL_STRETCH of them one by one (a whole number of pairs,
             * so the runs stay aligned). */
            int32_t stop = i + ZL_FAIL_STRETCH < 0 ? i + ZL_FAIL_STRETCH : 0;
            for (; i != stop; i++, y += dy)
                flat_pixel(func, cend + i, zend + i, y >> 16, pixel);
        }
    }
}

/* Exact flat span: one pixel to align the rows, then pairs, then the last
 * odd pixel, when the rows allow pairs (same alignment, little-endian);
 * else one pixel at a time. */
static inline void span_flat_exact(unsigned func, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                                   uint32_t dz, uint16_t pixel)
{
    int32_t m;
    if (!little_endian() || (((uintptr_t)crow ^ (uintptr_t)zrow) & 2u) != 0) {
        span_flat_565(func, 0, crow, zrow, n, z, dz, pixel);
        return;
    }
    if (((uintptr_t)zrow & 2u) != 0) {
        flat_pixel(func, crow, zrow, z >> 14, pixel);
        crow++;
        zrow++;
        n--;
        z += dz;
    }
    m = n / 2;
    span_flat_pairs(func, crow, zrow, m, z << 2, dz << 2, pixel);
    if (n & 1)
        flat_pixel(func, crow + n - 1, zrow + n - 1, (z + (uint32_t)(n - 1) * dz) >> 14, pixel);
}

uint32_t zl_depth_start_clamp(int64_t w, uint32_t lo14, uint32_t hi14)
{
    if (lo14 > hi14) /* a clipped piece: within +-2^31 by zl_tri_set_planes' bound */
        return (uint32_t)w + (1u << 13); /* modulo 2^32 */
    return (w < (int64_t)lo14 ? lo14 : hi14) + (1u << 13);
}

void zl_span_flat(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                      uint32_t dz, const uint8_t *pix)
{
    unsigned func = ss->func, bpp = ss->bpp;
    int32_t i;
    if (ZL_FAST_PATHS && bpp == 2 && ss->zwrite && ss->keep[0] == 0 && ss->keep[1] == 0 &&
        ((uintptr_t)crow & 1u) == 0 && (func == ZL_LESS || func == ZL_LEQUAL)) { /* (off: zl_config.h) */
        uint16_t pixel, *c16 = (uint16_t *)(void *)crow;
        int exact = stays_below(z, dz, n, 65536u << 14);
        memcpy(&pixel, pix, 2);
        if (func == ZL_LESS && exact)
            span_flat_exact(ZL_LESS, c16, zrow, n, z, dz, pixel);
        else if (func == ZL_LESS)
            span_flat_565(ZL_LESS, 1, c16, zrow, n, z, dz, pixel);
        else if (exact)
            span_flat_exact(ZL_LEQUAL, c16, zrow, n, z, dz, pixel);
        else
            span_flat_565(ZL_LEQUAL, 1, c16, zrow, n, z, dz, pixel);
        return;
    }
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (func == ZL_ALWAYS || depth_pass(func, d, zrow[i])) {
            if (ss->zwrite)
                zrow[i] = (uint16_t)d;
            if (bpp != 0)
                put_pixel(crow + (size_t)i * bpp, bpp, pix, ss->keep);
        }
        z += dz;
    }
}

/* ---------------------------------------- Gouraud spans */

/* The lanes of a chunk (zl_span.h, lane colour): each channel's 8.8 value
 * at its first pixel and its step per pixel. */
typedef struct {
    uint32_t l[3];
    int32_t d[3];
} zl_lanes;

/* The lanes of a chunk of n pixels from Q16 channels c (each below 2^24)
 * with Q16 steps dc: 0 when one would leave 0 .. 0xFFFF (then the chunk
 * takes the Q16 steppers, span_gouraud_generic). */
static int lanes_init(zl_lanes *ln, const uint32_t *c, const uint32_t *dc, int32_t n)
{
    int k;
    for (k = 0; k < 3; k++) {
        /* the caller's range check keeps (n - 1) |dc| below 2^24: no overflow */
        int32_t l = (int32_t)(c[k] >> 8), d = zl_lane_step(dc[k]), e = l + (n - 1) * d;
        if (e < 0 || e > 0xFFFF)
            return 0;
        ln->l[k] = (uint32_t)l;
        ln->d[k] = d;
    }
    return 1;
}

/* The RGB565 pixel at k of a chunk. */
static ZL_ALWAYS_INLINE uint32_t lanes_pixel(const zl_lanes *ln, uint32_t k)
{
    return zl_lane565(ln->l[0] + k * (uint32_t)ln->d[0], ln->l[1] + k * (uint32_t)ln->d[1],
                      ln->l[2] + k * (uint32_t)ln->d[2]);
}

/* The values of a Gouraud run (see zl_pair_run): depth y and lane pairs c
 * (pixel at the low half, the next at the high half) of its first pair,
 * and their steps per pair. */
typedef struct {
    uint32_t y, dy, c[3], dc[3];
} zl_gouraud_run;

/* The RGB565 pair of lane pairs r, g, b: zl_lane565 of each half, each
 * channel masked by an immediate (Thumb-2 encodes 0xF800F800 and
 * 0xFC00FC00) and shifted into place by the orr that merges it. */
static ZL_ALWAYS_INLINE uint32_t lane_pair(uint32_t r, uint32_t g, uint32_t b)
{
    return (r & 0xF800F800u) | ((g & 0xFC00FC00u) >> 5) | ((b & 0xF800F800u) >> 11);
}

/* Cortex-M4/M7 (DSP): the pair runs below in assembly; elsewhere in C. */
#if !defined(ZL_NO_ASM) && defined(__GNUC__) && defined(__ARM_ARCH_7EM__) && defined(__ARM_FEATURE_DSP)
#define ZL_GOURAUD_ASM 1
#else
#define ZL_GOURAUD_ASM 0
#endif

#if !ZL_GOURAUD_ASM
/* Gouraud RGB565 on an exact span from 4-byte aligned rows, a pair per step:
 * one depth load, two compares, one depth store and one colour store. As
 * flat_pair_run: i runs up to 0 from the rows' ends, and the result is the
 * index of the pair where a test fails (nothing of it written), or 0. */
static ZL_ALWAYS_INLINE int32_t gouraud_pair_run(unsigned func, uint16_t *cend, uint16_t *zend, int32_t i,
                                                 const zl_gouraud_run *s)
{
    uint32_t y = s->y, dy = s->dy, r = s->c[0], g = s->c[1], b = s->c[2];
    uint32_t dr = s->dc[0], dg = s->dc[1], db = s->dc[2];
    for (; i != 0; i += 2) {
        uint32_t y1 = y + dy, w = pair_load(zend + i);
        if (!pair_pass(func, y, y1, w))
            return i;
        pair_store(zend + i, (y1 & 0xFFFF0000u) | (y >> 16));
        pair_store(cend + i, lane_pair(r, g, b));
        r += dr;
        g += dg;
        b += db;
        y = y1 + dy;
    }
    return 0;
}
#endif

/*
 * On ARMv7E-M (Cortex-M4/M7: PKHTB) with GCC or Clang the runs are written
 * in assembly: the C loop above, instruction for instruction, with every
 * value in a register (GCC's own loop reloads a mask from memory and spends
 * three instructions on the depth pair, 28 a pair instead of 21). The same
 * arithmetic, so the same pixels: the host tests run the C loop, the
 * Cortex-M tests this one, and golden_host_equals_target compares them.
 * Arguments: the pair's colour and depth pointers, the number of pairs
 * (> 0) and the run; returns the number of pairs left when a test fails
 * (nothing of that pair written), 0 at the end.
 */
#if ZL_GOURAUD_ASM
/* One pair of the run (r0 colour, r1 depth pointer; y, dy, r, g, b and
 * their steps in r4 .. r11, zl_gouraud_run's order): the tests TEST1 and
 * TEST2 branch to 2f on a failing pixel, before anything is written. */
#define ZL_GOURAUD_PAIR_ASM(TEST1, TEST2)                                                                          \
    "ldr lr, [r1]\n\t" TEST1 "add r12, r4, r5\n\t"                                                                 \
    "lsr r3, lr, #16\n\t"                                                                                          \
    "cmp r3, r12, lsr #16\n\t" TEST2 "pkhtb lr, r12, r4, asr #16\n\t"                                              \
    "str lr, [r1], #4\n\t"                                                                                         \
    "and r3, r6, #0xF800F800\n\t"                                                                                  \
    "and lr, r7, #0xFC00FC00\n\t"                                                                                  \
    "orr r3, r3, lr, lsr #5\n\t"                                                                                   \
    "and lr, r8, #0xF800F800\n\t"                                                                                  \
    "orr r3, r3, lr, lsr #11\n\t"                                                                                  \
    "str r3, [r0], #4\n\t"                                                                                         \
    "add r4, r12, r5\n\t"                                                                                          \
    "add r6, r6, r9\n\t"                                                                                           \
    "add r7, r7, r10\n\t"                                                                                          \
    "add r8, r8, r11\n\t"
/* The run: two pairs a loop step (an odd count enters at the second),
 * until the depth pointer reaches the end (r2); returns the depth pointer
 * of the failing pair, or the end. */
#define ZL_GOURAUD_RUN_ASM(TEST1, TEST2)                                                                           \
    __asm__ volatile("push {r4-r11, lr}\n\t"                                                                       \
                     "ldm r3, {r4-r11}\n\t"                                                                       \
                     "sub r3, r2, r1\n\t"                                                                         \
                     "tst r3, #4\n\t"                                                                             \
                     "bne 3f\n"                                                                                    \
                     "1:\n\t" ZL_GOURAUD_PAIR_ASM(TEST1, TEST2) "3:\n\t" ZL_GOURAUD_PAIR_ASM(TEST1, TEST2)       \
                     "cmp r1, r2\n\t"                                                                             \
                     "bne 1b\n"                                                                                    \
                     "2:\n\t"                                                                                     \
                     "mov r0, r1\n\t"                                                                             \
                     "pop {r4-r11, pc}")
/* LESS: y0 < w_lo << 16, then w_hi > y1_hi; LEQUAL: y0_hi <= w_lo, then
 * w_hi >= y1_hi (pair_pass). naked: the body is the whole function, its
 * parameters in r0 .. r3. */
__attribute__((naked, noinline)) static uint16_t *gouraud_pairs_less_asm(
    uint16_t *c __attribute__((unused)), uint16_t *z __attribute__((unused)),
    const uint16_t *zend __attribute__((unused)), const zl_gouraud_run *s __attribute__((unused)))
{
    ZL_GOURAUD_RUN_ASM("cmp r4, lr, lsl #16\n\tbhs 2f\n\t", "bls 2f\n\t");
}

__attribute__((naked, noinline)) static uint16_t *gouraud_pairs_lequal_asm(
    uint16_t *c __attribute__((unused)), uint16_t *z __attribute__((unused)),
    const uint16_t *zend __attribute__((unused)), const zl_gouraud_run *s __attribute__((unused)))
{
    ZL_GOURAUD_RUN_ASM("uxth r3, lr\n\tcmp r3, r4, lsr #16\n\tblo 2f\n\t", "blo 2f\n\t");
}

static int32_t gouraud_pair_run_less(uint16_t *cend, uint16_t *zend, int32_t i, const zl_gouraud_run *s)
{
    return (int32_t)(gouraud_pairs_less_asm(cend + i, zend + i, zend, s) - zend);
}

static int32_t gouraud_pair_run_lequal(uint16_t *cend, uint16_t *zend, int32_t i, const zl_gouraud_run *s)
{
    return (int32_t)(gouraud_pairs_lequal_asm(cend + i, zend + i, zend, s) - zend);
}
#else
static ZL_NOINLINE int32_t gouraud_pair_run_less(uint16_t *cend, uint16_t *zend, int32_t i,
                                                 const zl_gouraud_run *s)
{
    return gouraud_pair_run(ZL_LESS, cend, zend, i, s);
}

static ZL_NOINLINE int32_t gouraud_pair_run_lequal(uint16_t *cend, uint16_t *zend, int32_t i,
                                                   const zl_gouraud_run *s)
{
    return gouraud_pair_run(ZL_LEQUAL, cend, zend, i, s);
}
#endif

/* One pixel of the lane loops: depth d, RGB565 value v. */
static ZL_ALWAYS_INLINE void lane_pixel(unsigned func, uint16_t *c, uint16_t *zp, uint32_t d, uint32_t v)
{
    if (depth_pass(func, d, *zp)) {
        *zp = (uint16_t)d;
        *c = (uint16_t)v;
    }
}

/* The run state at pixel k of a chunk. */
static void run_at(zl_gouraud_run *s, const zl_lanes *ln, uint32_t k, uint32_t z, uint32_t dz)
{
    int j;
    s->y = (z + k * dz) << 2;
    for (j = 0; j < 3; j++) {
        uint32_t lo = ln->l[j] + k * (uint32_t)ln->d[j];
        s->c[j] = lo * 0x10001u + ((uint32_t)ln->d[j] << 16);
    }
}

/* n (even) pixels from pixel k0 of a chunk, on 4-byte aligned rows: runs of
 * passing pairs, and between them a failing pair pixel by pixel. */
static void lanes_pairs(unsigned func, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t k0, uint32_t z,
                        uint32_t dz, const zl_lanes *ln)
{
    zl_gouraud_run s;
    uint16_t *cend = crow + n, *zend = zrow + n;
    int32_t i = -n;
    int j;
    s.dy = dz << 2;
    for (j = 0; j < 3; j++)
        s.dc[j] = ((uint32_t)ln->d[j] << 1) * 0x10001u;
    run_at(&s, ln, k0, z, dz);
    for (;;) {
        uint32_t k;
        i = func == ZL_LESS ? gouraud_pair_run_less(cend, zend, i, &s) : gouraud_pair_run_lequal(cend, zend, i, &s);
        if (i == 0)
            return;
        k = k0 + (uint32_t)(i + n);
        lane_pixel(func, cend + i, zend + i, (z + k * dz) >> 14, lanes_pixel(ln, k));
        lane_pixel(func, cend + i + 1, zend + i + 1, (z + (k + 1) * dz) >> 14, lanes_pixel(ln, k + 1));
        i += 2;
        if (i == 0)
            return;
        run_at(&s, ln, k + 2, z, dz);
    }
}

/* A chunk in native RGB565 from rows whose alignment allows pairs, depth
 * test func (LESS or LEQUAL) with writes, z exact: an aligning pixel,
 * pairs, a last odd pixel. */
static void lanes_fast(unsigned func, uint16_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                       const zl_lanes *ln)
{
    uint32_t k = 0;
    if (((uintptr_t)zrow & 2u) != 0) {
        lane_pixel(func, crow, zrow, z >> 14, lanes_pixel(ln, 0));
        k = 1;
    }
    if (n - (int32_t)k >= 2)
        lanes_pairs(func, crow + k, zrow + k, (n - (int32_t)k) & ~1, k, z, dz, ln);
    if (((n - (int32_t)k) & 1) != 0)
        lane_pixel(func, crow + n - 1, zrow + n - 1, (z + (uint32_t)(n - 1) * dz) >> 14, lanes_pixel(ln, (uint32_t)(n - 1)));
}

/* A chunk in either RGB565 byte order under any span state: the lane
 * pixels one by one (zl_span_flat's generic loop). */
static void lanes_generic(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                          const zl_lanes *ln)
{
    unsigned func = ss->func;
    int32_t i;
    /* Without a depth buffer zl_span_state_init chose ZL_ALWAYS and no
     * writes: said here too, so that no path to zrow[i] sees NULL. */
    if (zrow == NULL && (ss->zwrite || func != ZL_ALWAYS))
        return;
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (func == ZL_ALWAYS || depth_pass(func, d, zrow[i])) {
            uint32_t v = lanes_pixel(ln, (uint32_t)i);
            uint8_t pix[2];
            if (ss->zwrite)
                zrow[i] = (uint16_t)d;
            if (ss->format == ZL_FORMAT_RGB565_BE) {
                pix[0] = (uint8_t)(v >> 8);
                pix[1] = (uint8_t)v;
            } else {
                uint16_t v16 = (uint16_t)v;
                memcpy(pix, &v16, 2);
            }
            put_pixel(crow + (size_t)i * 2u, 2, pix, ss->keep);
        }
        z += dz;
    }
}

static void span_gouraud_generic(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                                 uint32_t dz, const uint32_t *c, const uint32_t *dc);

/* Whether a chunk can take lanes_fast: native RGB565 with every channel,
 * LESS or LEQUAL with depth writes, rows that pair up, z exact. Only
 * speed depends on it (addresses included): the pixels do not. */
static int lanes_fast_ok(const zl_span_state *ss, const uint8_t *crow, const uint16_t *zrow, int32_t n, uint32_t z,
                         uint32_t dz)
{
    return ss->format == ZL_FORMAT_RGB565 && ss->zwrite && ss->keep[0] == 0 && ss->keep[1] == 0 &&
           (ss->func == ZL_LESS || ss->func == ZL_LEQUAL) && little_endian() && ((uintptr_t)crow & 1u) == 0 &&
           (((uintptr_t)crow ^ (uintptr_t)zrow) & 2u) == 0 && stays_below(z, dz, n, 65536u << 14);
}

/* A chunk of an RGB565 span (either byte order): lanes when they fit. */
static void gouraud_chunk(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z, uint32_t dz,
                          const uint32_t *c, const uint32_t *dc)
{
    zl_lanes ln;
    if (!lanes_init(&ln, c, dc, n))
        span_gouraud_generic(ss, crow, zrow, n, z, dz, c, dc);
    else if (ZL_FAST_PATHS && zrow != NULL && lanes_fast_ok(ss, crow, zrow, n, z, dz)) /* (off: zl_config.h) */
        lanes_fast(ss->func, (uint16_t *)(void *)crow, zrow, n, z, dz, &ln);
    else
        lanes_generic(ss, crow, zrow, n, z, dz, &ln);
}

void zl_span_gouraud(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                         uint32_t dz, const uint32_t *c, const uint32_t *dc)
{
    int32_t k;
    /* Without the fast paths (zl_config.h) every span takes the per-channel
     * loop: the same pixels as the packed lanes, less code. */
    if (!ZL_FAST_PATHS || ss->bpp != 2 || !stays_below(c[0], dc[0], n, UINT32_C(256) << 16) || !stays_below(c[1], dc[1], n, UINT32_C(256) << 16) ||
        !stays_below(c[2], dc[2], n, UINT32_C(256) << 16)) {
        span_gouraud_generic(ss, crow, zrow, n, z, dz, c, dc);
        return;
    }
    if (n <= ZL_LANE_CHUNK) { /* the common case */
        gouraud_chunk(ss, crow, zrow, n, z, dz, c, dc);
        return;
    }
    for (k = 0; k < n; k += ZL_LANE_CHUNK) {
        uint32_t ck[3];
        ck[0] = c[0] + (uint32_t)k * dc[0];
        ck[1] = c[1] + (uint32_t)k * dc[1];
        ck[2] = c[2] + (uint32_t)k * dc[2];
        gouraud_chunk(ss, crow + (size_t)k * 2u, zrow != NULL ? zrow + k : NULL,
                      n - k < ZL_LANE_CHUNK ? n - k : ZL_LANE_CHUNK, z + (uint32_t)k * dz, dz, ck, dc);
    }
}

static void span_gouraud_generic(const zl_span_state *ss, uint8_t *crow, uint16_t *zrow, int32_t n, uint32_t z,
                                 uint32_t dz, const uint32_t *c, const uint32_t *dc)
{
    uint32_t r = c[0], g = c[1], b = c[2];
    unsigned func = ss->func, bpp = ss->bpp;
    int32_t i;
    uint8_t pix[3] = {0, 0, 0};
    if (zrow == NULL && (ss->zwrite || func != ZL_ALWAYS))
        return; /* as in lanes_generic */
    for (i = 0; i < n; i++) {
        uint32_t d = depth_of(z);
        if (func == ZL_ALWAYS || depth_pass(func, d, zrow[i])) {
            if (ss->zwrite)
                zrow[i] = (uint16_t)d;
            if (bpp != 0) {
                pack_color((zl_format)ss->format, channel_of(r), channel_of(g), channel_of(b), pix);
                put_pixel(crow + (size_t)i * bpp, bpp, pix, ss->keep);
            }
        }
        z += dz;
        r += dc[0];
        g += dc[1];
        b += dc[2];
    }
}

/* Sixteen pixels of a fill: eight words, one STM on ARM. */
typedef struct {
    uint32_t w[8];
} zl_fill_block;

/*
 * On ARMv7-M (Cortex-M3/M4/M7) with GCC or Clang: 32 pixels per two
 * store-multiples of eight registers that hold the pixel pair, about a
 * third of the instructions of the block copies below (which reload the
 * block for every store). ZL_NO_ASM=1 keeps the portable loop everywhere;
 * the host tests run the C loop and the Cortex-M tests this one, and both
 * compare images with each other (golden_host_equals_target).
 */
#if !defined(ZL_NO_ASM) && defined(__GNUC__) && (defined(__ARM_ARCH_7M__) || defined(__ARM_ARCH_7EM__))
#define ZL_FILL_ASM 1
/* blocks x 64 bytes of the word pair from p (4-byte aligned) on; blocks > 0.
 * naked, its parameters in r0 (p), r1 (pair), r2 (blocks): with operands
 * left to the compiler, a -O0 hard-float build keeps r7 as its frame pointer
 * and finds no register for them ("impossible constraints", issue 24). r7
 * is saved and restored here, so a frame-pointer build keeps it. */
__attribute__((naked, noinline)) static void fill_blocks_stm(uint16_t *p __attribute__((unused)),
                                                             uint32_t pair __attribute__((unused)),
                                                             uint32_t blocks __attribute__((unused)))
{
    __asm__ volatile("push {r4, r5, r6, r7, r8, lr}\n\t"
                     "mov r3, r1\n\t"
                     "mov r4, r1\n\t"
                     "mov r5, r1\n\t"
                     "mov r6, r1\n\t"
                     "mov r7, r1\n\t"
                     "mov r8, r1\n\t"
                     "mov r12, r1\n"
                     "1:\n\t"
                     "stmia r0!, {r1, r3, r4, r5, r6, r7, r8, r12}\n\t"
                     "stmia r0!, {r1, r3, r4, r5, r6, r7, r8, r12}\n\t"
                     "subs r2, r2, #1\n\t"
                     "bne 1b\n\t"
                     "pop {r4, r5, r6, r7, r8, pc}");
}
#elif !defined(ZL_NO_ASM) && defined(__GNUC__) && !defined(__clang__) && defined(__ARM_ARCH_6M__)
#define ZL_FILL_ASM 1
/* The same on ARMv6-M (Cortex-M0/M0+), whose store-multiple takes low
 * registers only: four of them, four stores a block (issue 13: the block
 * copies below took about 23 instructions a block there). GCC reads
 * Thumb-1 inline assembly in divided syntax: "sub" sets the flags. */
static void fill_blocks_stm(uint16_t *p, uint32_t pair, uint32_t blocks)
{
    __asm__ volatile("mov r3, %[v]\n\t"
                     "mov r4, %[v]\n\t"
                     "mov r5, %[v]\n\t"
                     "mov r6, %[v]\n"
                     "1:\n\t"
                     "stmia %[d]!, {r3, r4, r5, r6}\n\t"
                     "stmia %[d]!, {r3, r4, r5, r6}\n\t"
                     "stmia %[d]!, {r3, r4, r5, r6}\n\t"
                     "stmia %[d]!, {r3, r4, r5, r6}\n\t"
                     "sub %[n], #1\n\t"
                     "bne 1b"
                     : [d] "+l"(p), [n] "+l"(blocks)
                     : [v] "l"(pair)
                     : "r3", "r4", "r5", "r6", "cc", "memory");
}
#else
#define ZL_FILL_ASM 0
#endif

void zl_fill16(uint16_t *p, uint16_t v, uint32_t n)
{
    /* Clears are a large share of a small frame: once p is 4-byte aligned,
     * two pixels per 32-bit word and sixteen per block copy (GCC makes it
     * a store-multiple of registers that hold the pair). memcpy, not a
     * uint32_t pointer, so no object is accessed through a foreign type;
     * the pair's value is the same whatever the byte order. */
    zl_fill_block b;
    uint32_t pair, k;
    uint16_t two[2];
    if (!ZL_FAST_PATHS) { /* a pixel a step (zl_config.h) */
        while (n-- > 0)
            *p++ = v;
        return;
    }
    two[0] = v;
    two[1] = v;
    memcpy(&pair, two, 4);
    for (k = 0; k < 8; k++)
        b.w[k] = pair;
    if (n > 0 && ((uintptr_t)p & 3u) != 0) {
        *p++ = v;
        n--;
    }
#if ZL_FILL_ASM
    if (n >= 32) {
        fill_blocks_stm(p, pair, n / 32);
        p += n & ~31u;
        n &= 31u;
    }
#else
    for (; n >= 32; n -= 32, p += 32) { /* two blocks a step: half the loop overhead */
        memcpy(ZL_ALIGNED4(p), &b, sizeof b);
        memcpy(ZL_ALIGNED4(p + 16), &b, sizeof b);
    }
#endif
    if (n >= 16) {
        memcpy(ZL_ALIGNED4(p), &b, sizeof b);
        n -= 16;
        p += 16;
    }
    for (; n >= 2; n -= 2, p += 2)
        memcpy(ZL_ALIGNED4(p), &pair, 4);
    if (n != 0)
        *p = v;
}

void zl_fill_color_row(uint8_t *row, const zl_span_state *ss, zl_rgb c)
{
    uint8_t pix[3] = {0, 0, 0};
    uint16_t i;
    pack_color((zl_format)ss->format, c.r, c.g, c.b, pix);
    if (ss->bpp == 2 && ss->keep[0] == 0 && ss->keep[1] == 0 && ((uintptr_t)row & 1u) == 0) {
        uint16_t v;
        memcpy(&v, pix, 2);
        zl_fill16((uint16_t *)(void *)row, v, ss->width);
        return;
    }
    for (i = 0; i < ss->width; i++)
        put_pixel(row + (size_t)i * ss->bpp, ss->bpp, pix, ss->keep);
}
