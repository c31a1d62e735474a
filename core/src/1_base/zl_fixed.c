/* SPDX-License-Identifier: MIT */
/* Stage 1, base: fixed-point helpers (checked arithmetic, integer square
 * roots, the sine table) that every later stage uses. */
#include <stddef.h>

#include "zline/zl_fixed.h"

/*
 * The tables below in flash on AVR: avr-gcc copies const data to SRAM (a
 * separate address space) unless it is placed in program memory and read
 * with LPM, and their 768 bytes (1,284 before the sine table took 16-bit
 * entries) are a tenth of an ATmega2560's 8 KB
 * (port/avr). avr-libc's PROGMEM and pgm_read_* do that; ZL_NO_PROGMEM
 * keeps them in SRAM. Elsewhere these are plain const arrays and reads.
 */
#if defined(__AVR__) && !defined(ZL_NO_PROGMEM)
#include <avr/pgmspace.h>
#define ZL_TABLE PROGMEM
#define TABLE_U8(t, i) pgm_read_byte(&(t)[i])
#define TABLE_U16(t, i) pgm_read_word(&(t)[i])
#define TABLE_I32(t, i) ((int32_t)pgm_read_dword(&(t)[i]))
#else
#define ZL_TABLE
#define TABLE_U8(t, i) ((t)[i])
#define TABLE_U16(t, i) ((t)[i])
#define TABLE_I32(t, i) ((t)[i])
#endif

zl_status zl_fx_mul_checked(zl_fixed a, zl_fixed b, zl_fixed *out)
{
    int64_t p = zl_floor_shift64((int64_t)a * b + 32768, 16);
    if (out == NULL)
        return ZL_ERR_ARG;
    if (p > INT32_MAX || p < INT32_MIN)
        return ZL_ERR_RANGE;
    *out = (zl_fixed)p;
    return ZL_OK;
}

zl_status zl_fx_div_checked(zl_fixed a, zl_fixed b, zl_fixed *out)
{
    int64_t n = (int64_t)a * 65536;
    int64_t d = b;
    int64_t q;
    if (out == NULL)
        return ZL_ERR_ARG;
    if (b == 0)
        return ZL_ERR_RANGE;
    if (d < 0) {
        n = -n;
        d = -d;
    }
    q = zl_round_div64(n, d);
    if (q > INT32_MAX || q < INT32_MIN)
        return ZL_ERR_RANGE;
    *out = (zl_fixed)q;
    return ZL_OK;
}

zl_status zl_fx_recip_checked(zl_fixed a, zl_fixed *out)
{
    return zl_fx_div_checked(ZL_FX_ONE, a, out);
}

/* Leading zero bits of v != 0: CLZ, one instruction on Cortex-M3 and up. */
static unsigned clz32(uint32_t v)
{
#if defined(__GNUC__) && __SIZEOF_INT__ >= 4 /* __builtin_clz counts in an unsigned int */
    return (unsigned)__builtin_clz(v);
#else
    unsigned n = 0;
    while (!(v & 0x80000000u)) {
        v <<= 1;
        n++;
    }
    return n;
#endif
}

/*
 * One 16-bit digit of (u * 2^16 + u0) / d for a normalised d (top bit set),
 * u < d, u0 < 2^16 (Hacker's Delight, divlu): the estimate from the top
 * half of d is at most 2 too large, and the test against the next digit
 * removes the excess. *r gets the remainder, exact modulo 2^32 because the
 * true remainder is below d.
 */
static uint32_t quotient_digit(uint32_t u, uint32_t u0, uint32_t d, uint32_t *r)
{
    uint32_t dh = d >> 16, dl = d & 0xFFFFu;
    uint32_t q = u / dh, rh = u - q * dh;
    while (q > 0xFFFFu || q * dl > ((rh << 16) | u0)) {
        q--;
        rh += dh;
        if (rh > 0xFFFFu)
            break;
    }
    *r = ((u << 16) | u0) - q * d;
    return q;
}

uint32_t zl_udiv64_32(uint64_t n, uint32_t d, uint32_t *rem)
{
    uint32_t hi = (uint32_t)(n >> 32), lo = (uint32_t)n, q, r;
    if (hi == 0) {
        /* Most numerators: one 32-bit division. */
        q = lo / d;
        r = lo - q * d;
    } else {
        /* Normalise so the divisor's top bit is set, then two digits. */
        unsigned s = clz32(d);
        uint32_t q1;
        if (s != 0) {
            d <<= s;
            hi = (hi << s) | (lo >> (32u - s));
            lo <<= s;
        }
        q1 = quotient_digit(hi, lo >> 16, d, &r);
        q = quotient_digit(r, lo & 0xFFFFu, d, &r);
        q |= q1 << 16;
        r >>= s;
    }
    if (rem != NULL)
        *rem = r;
    return q;
}

uint32_t zl_isqrt64(uint64_t v)
{
    /* Bit-by-bit method: one result bit per iteration, no division. */
    uint64_t res = 0;
    uint64_t bit = (uint64_t)1 << 62;
    while (bit > v)
        bit >>= 2;
    while (bit != 0) {
        if (v >= res + bit) {
            v -= res + bit;
            res = (res >> 1) + bit;
        } else {
            res >>= 1;
        }
        bit >>= 2;
    }
    return (uint32_t)res;
}

#if defined(__ARM_FEATURE_IDIV) || !defined(__arm__)
/* 16 sqrt(i + 1/2), rounded (255 at most): square roots of 8-bit mantissas. */
static const uint8_t sqrt_start[256] ZL_TABLE = {
    11, 20, 25, 30, 34, 38, 41, 44, 47, 49, 52, 54, 57, 59, 61, 63,
    65, 67, 69, 71, 72, 74, 76, 78, 79, 81, 82, 84, 85, 87, 88, 90,
    91, 93, 94, 95, 97, 98, 99, 101, 102, 103, 104, 106, 107, 108, 109, 110,
    111, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127,
    128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143,
    144, 144, 145, 146, 147, 148, 149, 150, 151, 151, 152, 153, 154, 155, 156, 156,
    157, 158, 159, 160, 160, 161, 162, 163, 164, 164, 165, 166, 167, 167, 168, 169,
    170, 170, 171, 172, 173, 173, 174, 175, 176, 176, 177, 178, 179, 179, 180, 181,
    181, 182, 183, 183, 184, 185, 186, 186, 187, 188, 188, 189, 190, 190, 191, 192,
    192, 193, 194, 194, 195, 196, 196, 197, 198, 198, 199, 200, 200, 201, 201, 202,
    203, 203, 204, 205, 205, 206, 206, 207, 208, 208, 209, 210, 210, 211, 211, 212,
    213, 213, 214, 214, 215, 216, 216, 217, 217, 218, 219, 219, 220, 220, 221, 221,
    222, 223, 223, 224, 224, 225, 225, 226, 227, 227, 228, 228, 229, 229, 230, 230,
    231, 232, 232, 233, 233, 234, 234, 235, 235, 236, 237, 237, 238, 238, 239, 239,
    240, 240, 241, 241, 242, 242, 243, 243, 244, 244, 245, 246, 246, 247, 247, 248,
    248, 249, 249, 250, 250, 251, 251, 252, 252, 253, 253, 254, 254, 255, 255, 255,
};

/*
 * Where division is an instruction (Cortex-M3 and up, hosts): a start from
 * the table (v's top 7..8 bits, an even shift), one Newton step
 * x' = (x + v/x) / 2, which never lands below floor(sqrt(v)), and a single
 * correction. The start is within 1/256 relative, so x' is at most one too
 * large; checked exhaustively over all 2^32 inputs when it was written (and
 * around every square in tests/test_fastdiv.c).
 */
uint32_t zl_isqrt32(uint32_t v)
{
    uint32_t x;
    unsigned len, e;
    if (v < 2)
        return v;
    len = 32u - clz32(v);
    e = len > 8 ? (len - 7u) & ~1u : 0u;
    x = ((uint32_t)TABLE_U8(sqrt_start, v >> e) << (e >> 1)) >> 4; /* >= 1 */
    x = (x + v / x) >> 1;
    if (x > 0xFFFFu)
        x = 0xFFFFu; /* floor(sqrt(2^32 - 1)); x * x must not wrap */
    if (x * x > v)
        x--;
    return x;
}
#else
/* Bit by bit, no division: for cores without a divide instruction (Cortex-M0). */
uint32_t zl_isqrt32(uint32_t v)
{
    uint32_t res = 0;
    uint32_t bit = (uint32_t)1 << 30;
    while (bit > v)
        bit >>= 2;
    while (bit != 0) {
        if (v >= res + bit) {
            v -= res + bit;
            res = (res >> 1) + bit;
        } else {
            res >>= 1;
        }
        bit >>= 2;
    }
    return res;
}
#endif

zl_fixed zl_fx_sqrt(zl_fixed a)
{
    /* sqrt(a / 2^16) * 2^16 = sqrt(a * 2^16): exact floor via the 64-bit root. */
    if (a <= 0)
        return 0;
    return (zl_fixed)zl_isqrt64((uint64_t)a << 16);
}

/* The sine at the nodes i = 0..256 of the first quarter (i quarter turns /
 * 256), round(65536 sin) in Q16.16; node 256 is 1.0. */
#define SIN_QUARTER_END 65536
#if ZL_FAST_PATHS
/* sin(i * quarter turn / 256) in Q16.16, i = 0..255 (generated, rounded);
 * i = 256 is 1.0 (SIN_QUARTER_END). Every entry below it fits 16 bits, so
 * the table takes 512 bytes of flash instead of 1,028 as int32_t. */
static const uint16_t sin_quarter[256] ZL_TABLE = {
    0, 402, 804, 1206, 1608, 2010, 2412, 2814,
    3216, 3617, 4019, 4420, 4821, 5222, 5623, 6023,
    6424, 6824, 7224, 7623, 8022, 8421, 8820, 9218,
    9616, 10014, 10411, 10808, 11204, 11600, 11996, 12391,
    12785, 13180, 13573, 13966, 14359, 14751, 15143, 15534,
    15924, 16314, 16703, 17091, 17479, 17867, 18253, 18639,
    19024, 19409, 19792, 20175, 20557, 20939, 21320, 21699,
    22078, 22457, 22834, 23210, 23586, 23961, 24335, 24708,
    25080, 25451, 25821, 26190, 26558, 26925, 27291, 27656,
    28020, 28383, 28745, 29106, 29466, 29824, 30182, 30538,
    30893, 31248, 31600, 31952, 32303, 32652, 33000, 33347,
    33692, 34037, 34380, 34721, 35062, 35401, 35738, 36075,
    36410, 36744, 37076, 37407, 37736, 38064, 38391, 38716,
    39040, 39362, 39683, 40002, 40320, 40636, 40951, 41264,
    41576, 41886, 42194, 42501, 42806, 43110, 43412, 43713,
    44011, 44308, 44604, 44898, 45190, 45480, 45769, 46056,
    46341, 46624, 46906, 47186, 47464, 47741, 48015, 48288,
    48559, 48828, 49095, 49361, 49624, 49886, 50146, 50404,
    50660, 50914, 51166, 51417, 51665, 51911, 52156, 52398,
    52639, 52878, 53114, 53349, 53581, 53812, 54040, 54267,
    54491, 54714, 54934, 55152, 55368, 55582, 55794, 56004,
    56212, 56418, 56621, 56823, 57022, 57219, 57414, 57607,
    57798, 57986, 58172, 58356, 58538, 58718, 58896, 59071,
    59244, 59415, 59583, 59750, 59914, 60075, 60235, 60392,
    60547, 60700, 60851, 60999, 61145, 61288, 61429, 61568,
    61705, 61839, 61971, 62101, 62228, 62353, 62476, 62596,
    62714, 62830, 62943, 63054, 63162, 63268, 63372, 63473,
    63572, 63668, 63763, 63854, 63944, 64031, 64115, 64197,
    64277, 64354, 64429, 64501, 64571, 64639, 64704, 64766,
    64827, 64884, 64940, 64993, 65043, 65091, 65137, 65180,
    65220, 65259, 65294, 65328, 65358, 65387, 65413, 65436,
    65457, 65476, 65492, 65505, 65516, 65525, 65531, 65535,
};

#define sin_node(i) ((i) == 256 ? SIN_QUARTER_END : (int32_t)TABLE_U16(sin_quarter, i))
#else
/*
 * Without the fast paths (zl_config.h) the nodes come from the Taylor
 * polynomial of sin(pi t / 2), t = i / 256, to degree 13 in Q30 (Horner's
 * rule, products below 2^62, floor shifts): the table's values exactly at
 * every node (its error, below 2^-28, is far inside the 0.0034 by which the
 * nearest node misses a rounding tie; tests/test_fixed.c checks each node
 * against its own reference), in 28 bytes of coefficients instead of 512.
 */
static const int32_t sin_taylor_q30[7] ZL_TABLE = {1686629713, -693598668, 85569306, -5026995, 172272, -3864, 61};

static int32_t sin_node(int32_t i)
{
    int64_t t = (int64_t)i * (1 << 22), t2 = zl_floor_shift64(t * t, 30), p = TABLE_I32(sin_taylor_q30, 6);
    int k;
    for (k = 5; k >= 0; k--)
        p = TABLE_I32(sin_taylor_q30, k) + zl_floor_shift64(p * t2, 30);
    return (int32_t)zl_floor_shift64(zl_floor_shift64(p * t, 30) + (1 << 13), 14);
}
#endif

/* Sine of the first quarter: a in 0..16384 (16384 = 90 degrees). Linear
 * interpolation between table entries 64 angle units apart, rounded. */
static zl_fixed sin_first_quarter(int32_t a)
{
    int32_t i = a >> 6;
    int32_t frac = a & 63;
    int32_t lo, hi;
    if (i >= 256)
        return SIN_QUARTER_END;
    lo = sin_node(i);
    hi = sin_node(i + 1);
    return lo + (((hi - lo) * frac + 32) >> 6);
}

zl_fixed zl_sin(zl_angle a)
{
    int32_t t = (int32_t)((uint32_t)a & 0xFFFFu); /* angle modulo a turn */
    if (t <= 16384)
        return sin_first_quarter(t);
    if (t <= 32768)
        return sin_first_quarter(32768 - t);
    if (t <= 49152)
        return -sin_first_quarter(t - 32768);
    return -sin_first_quarter(65536 - t);
}

zl_fixed zl_cos(zl_angle a)
{
    return zl_sin((zl_angle)((uint32_t)a + 16384u));
}

zl_angle zl_angle_from_deg(zl_fixed deg)
{
    /* angle = deg * 65536 / 360, rounded; deg is Q16.16 so divide by 360 * 65536 / 65536. */
    return (zl_angle)zl_round_div64((int64_t)deg * 65536, (int64_t)360 * 65536);
}
