/* Fixed-point helpers: checked arithmetic, integer square roots, sine table. */
#include <stddef.h>

#include "zline/zl_fixed.h"

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
#if defined(__GNUC__)
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
/*
 * Newton's iteration from above, where division is an instruction (Cortex-M3
 * and up, hosts): x' = (x + v/x) / 2 decreases to floor(sqrt(v)) and stops
 * there; from a start within a factor of 2 it takes 3 to 5 steps.
 */
uint32_t zl_isqrt32(uint32_t v)
{
    uint32_t x, y;
    unsigned len = 0;
    if (v < 2)
        return v;
#if defined(__GNUC__)
    len = 32u - (unsigned)__builtin_clz(v);
#else
    for (x = v; x != 0; x >>= 1)
        len++;
#endif
    x = (uint32_t)1 << ((len + 1) / 2); /* >= sqrt(v) */
    y = (x + v / x) >> 1;
    while (y < x) {
        x = y;
        y = (x + v / x) >> 1;
    }
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

/* sin(i * quarter turn / 256) in Q16.16, i = 0..256 (generated, rounded). */
static const int32_t sin_quarter[257] = {
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
    65536,};

/* Sine of the first quarter: a in 0..16384 (16384 = 90 degrees). Linear
 * interpolation between table entries 64 angle units apart, rounded. */
static zl_fixed sin_first_quarter(int32_t a)
{
    int32_t i = a >> 6;
    int32_t frac = a & 63;
    int32_t lo, hi;
    if (i >= 256)
        return sin_quarter[256];
    lo = sin_quarter[i];
    hi = sin_quarter[i + 1];
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
