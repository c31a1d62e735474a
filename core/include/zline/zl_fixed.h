/* SPDX-License-Identifier: MIT */
/*
 * zline fixed-point arithmetic: the one definition of every number format.
 *
 * zl_fixed is Q16.16: a signed 32-bit integer holding value * 65536.
 *   range      -32768.0 .. +32767.99998 (raw INT32_MIN .. INT32_MAX)
 *   resolution 1/65536 = 0.0000153
 * Products and quotients widen to 64 bits before they are narrowed, so the
 * only loss is the final rounding. Rounding is to nearest, ties towards
 * +infinity (floor(x + 1/2)), everywhere, so host and target agree bit for bit.
 *
 * zl_angle is a binary angle: 65536 units per full turn (1 unit = 0.0055
 * degrees). Angles wrap naturally modulo a turn.
 *
 * The unchecked inline helpers assume their documented ranges; the *_checked
 * variants return ZL_ERR_RANGE instead of wrapping and are what the public
 * matrix builders use on caller input.
 */
#ifndef ZLINE_FIXED_H
#define ZLINE_FIXED_H

#include <stdint.h>

#include "zl_config.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef int32_t zl_fixed;
typedef int32_t zl_angle;

#define ZL_FX_FRAC_BITS 16
#define ZL_FX_ONE ((zl_fixed)65536)
#define ZL_FX_HALF ((zl_fixed)32768)
#define ZL_FX_MAX ((zl_fixed)INT32_MAX)
#define ZL_FX_MIN ((zl_fixed)INT32_MIN)
#define ZL_ANGLE_TURN 65536

/* Integer to Q16.16; caller keeps |i| <= 32767. */
#define ZL_FX_INT(i) ((zl_fixed)((i) * 65536))

/* Status codes: 0 is success, errors are small negative numbers. */
typedef enum {
    ZL_OK = 0,
    ZL_DONE = 1,            /* zl_frame_next_band: every row has been produced */
    ZL_ERR_ARG = -1,        /* NULL pointer, unknown enum value, bad order of calls */
    ZL_ERR_RANGE = -2,      /* a number outside its documented range */
    ZL_ERR_SIZE = -3,       /* a buffer or dimension too small or too large */
    ZL_ERR_CAPACITY = -4,   /* the scene needs more than the frame was sized for */
    ZL_ERR_IO = -5,         /* a display bus reported a failed or timed-out transfer (port/display) */
    ZL_ERR_ABI = -6,        /* application and library built with different struct sizes or
                               configuration (zl_init, zl_frame_begin: ZL_ABI_KEY) */
    ZL_ERR_UNSUPPORTED = -7 /* a feature this build of the library leaves out */
} zl_status;

/*
 * floor(n / 2^shift) for signed 64-bit n. Right-shifting a negative number is
 * implementation-defined in C99; every compiler zline targets shifts
 * arithmetically (checked here by the preprocessor), which is exactly floor.
 * Elsewhere the portable division below is used.
 */
static inline int64_t zl_floor_shift64(int64_t n, unsigned shift)
{
#if ((-1) >> 1) == -1
    /* implementation-defined, not undefined: the #if checked the arithmetic shift */
    /* cppcheck-suppress shiftNegativeLHS */
    return n >> shift;
#else
    int64_t d = (int64_t)1 << shift;
    int64_t q = n / d;
    if ((n % d) < 0)
        q -= 1;
    return q;
#endif
}

/* floor(n / 2^shift) for signed 32-bit n, as zl_floor_shift64. */
static inline int32_t zl_floor_shift32(int32_t n, unsigned shift)
{
#if ((-1) >> 1) == -1
    return n >> shift;
#else
    return (int32_t)zl_floor_shift64(n, shift);
#endif
}

/* floor(n / d) for d > 0. */
static inline int64_t zl_floor_div64(int64_t n, int64_t d)
{
    int64_t q;
    /* Most operands fit 32 bits: a 32-bit division is one instruction on
     * Cortex-M3/M4 where the 64-bit one is a ~60-instruction libgcc call.
     * Same quotient either way. */
    if (n >= INT32_MIN && n <= INT32_MAX && d <= INT32_MAX) {
        int32_t n32 = (int32_t)n, d32 = (int32_t)d;
        int32_t q32 = n32 / d32;
        if (n32 % d32 < 0)
            q32 -= 1;
        return q32;
    }
    q = n / d;
    if ((n % d) < 0)
        q -= 1;
    return q;
}

/* ceil(n / d) for d > 0. */
static inline int64_t zl_ceil_div64(int64_t n, int64_t d)
{
    return -zl_floor_div64(-n, d);
}

/* round(n / d) with ties towards +infinity, d > 0: floor((2n + d) / 2d).
 * Caller keeps |n| below 2^62. */
static inline int64_t zl_round_div64(int64_t n, int64_t d)
{
    return zl_floor_div64(2 * n + d, 2 * d);
}

/*
 * Unsigned 64-by-32 division with a 32-bit quotient: returns floor(n / d) and,
 * when rem is not NULL, stores n mod d.
 * PRECONDITION: d != 0 and (n >> 32) < d, i.e. the quotient fits 32 bits.
 * d == 0 is a division by zero as in C; (n >> 32) >= d gives an unspecified
 * quotient and remainder (no undefined behaviour).
 * Exact for every such input. Two 32-bit divisions at most (one when n fits
 * 32 bits), where the C 64-bit division is a libgcc call of ~60..200
 * instructions on Cortex-M.
 */
uint32_t zl_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem);

/* Saturate a 64-bit value into zl_fixed. */
static inline zl_fixed zl_fx_sat(int64_t v)
{
    if (v > INT32_MAX)
        return ZL_FX_MAX;
    if (v < INT32_MIN)
        return ZL_FX_MIN;
    return (zl_fixed)v;
}

/* a * b, rounded; caller keeps the product inside Q16.16. */
static inline zl_fixed zl_fx_mul(zl_fixed a, zl_fixed b)
{
    return (zl_fixed)zl_floor_shift64((int64_t)a * b + 32768, 16);
}

/* a / b, rounded; b != 0 and the quotient inside Q16.16. */
static inline zl_fixed zl_fx_div(zl_fixed a, zl_fixed b)
{
    int64_t n = (int64_t)a * 65536;
    if (b < 0) {
        n = -n;
        b = -b;
    }
    return (zl_fixed)zl_round_div64(n, b);
}

/* Checked variants: ZL_ERR_RANGE when the exact result leaves Q16.16 or b == 0. */
zl_status zl_fx_mul_checked(zl_fixed a, zl_fixed b, zl_fixed *out);
zl_status zl_fx_div_checked(zl_fixed a, zl_fixed b, zl_fixed *out);
/* 1 / a, rounded; ZL_ERR_RANGE for a == 0 or |a| < 2 (raw), whose reciprocal overflows. */
zl_status zl_fx_recip_checked(zl_fixed a, zl_fixed *out);

/* floor(sqrt(v)) for 32- and 64-bit unsigned integers. */
uint32_t zl_isqrt32(uint32_t v);
uint32_t zl_isqrt64(uint64_t v);
/* sqrt of a non-negative Q16.16 value, rounded down; negative input gives 0. */
zl_fixed zl_fx_sqrt(zl_fixed a);

/*
 * Sine and cosine of a binary angle, Q16.16 in [-1, 1], from a 257-entry
 * quarter-wave table with linear interpolation. Largest error 1/65536 (one
 * unit) against the exact value rounded, checked in tests/test_fixed.c.
 */
zl_fixed zl_sin(zl_angle a);
zl_fixed zl_cos(zl_angle a);

/* Degrees (Q16.16) to a binary angle, rounded. */
zl_angle zl_angle_from_deg(zl_fixed deg);

#ifdef __cplusplus
}
#endif

#endif /* ZLINE_FIXED_H */
