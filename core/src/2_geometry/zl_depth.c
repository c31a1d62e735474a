/* SPDX-License-Identifier: MIT */
/* Stage 2, geometry: pseudodepth, the distance -> depth mapping and its
 * precision, in integers. */
#include "zline/zline.h"
#include "zl_geometry.h"

/* Shift num and den right together until den fits `bits` bits; keeps the ratio. */
static void scale_down(int64_t *num, int64_t *den, unsigned bits)
{
    unsigned len = bit_length64((uint64_t)*den);
    if (len > bits) {
        *num = zl_floor_shift64(*num, len - bits);
        *den = zl_floor_shift64(*den, len - bits);
    }
}

uint16_t zl_depth_of_distance(zl_fixed near_z, zl_fixed far_z, zl_fixed z)
{
    /* depth = 65535 * f (z - n) / ((f - n) z), from A + B/z with A = f/(f-n),
     * B = -fn/(f-n). Numerator and denominator are Q32 products; they are
     * scaled down together to 31 bits so the 65535 factor fits. */
    int64_t num, den, d;
    if (near_z <= 0 || far_z <= near_z)
        return 0;
    if (z <= near_z)
        return 0;
    if (z >= far_z)
        return 65535;
    num = (int64_t)far_z * (z - near_z);
    den = (int64_t)(far_z - near_z) * z;
    scale_down(&num, &den, 31);
    d = zl_round_div64(num * 65535, den);
    return (uint16_t)(d > 65535 ? 65535 : d);
}

zl_fixed zl_depth_resolution(zl_fixed near_z, zl_fixed far_z, zl_fixed z, unsigned bits)
{
    /* One depth step is 1/S of the range, S = 2^bits - 1. From
     * S (B/z - B/(z + dz)) = 1 with B = -fn/(f-n):
     *     dz = (f - n) z^2 / (S f n - (f - n) z)
     * In raw Q16.16 units F, N, Z this is dz_raw = (F-N) Z^2 / (S F N - (F-N) Z). */
    int64_t s, fn, x, denom, num;
    unsigned len, sh = 0;
    if (bits < 1 || bits > 16 || near_z <= 0 || far_z <= near_z || z <= 0)
        return ZL_FX_MAX;
    s = ((int64_t)1 << bits) - 1;
    fn = (int64_t)far_z * near_z;    /* < 2^62 */
    x = (int64_t)(far_z - near_z) * z; /* < 2^62 */
    len = bit_length64((uint64_t)fn);
    if (len + bits > 62)
        sh = len + bits - 62;
    fn = zl_floor_shift64(fn, sh);
    x = zl_floor_shift64(x, sh);
    denom = s * fn - x;
    if (denom <= 0)
        return ZL_FX_MAX;
    num = x;
    /* dz_raw = Z * num / denom: keep num below 2^31 so Z * num fits. */
    len = bit_length64((uint64_t)num);
    if (len > 31) {
        num = zl_floor_shift64(num, len - 31);
        denom = zl_floor_shift64(denom, len - 31);
        if (denom <= 0)
            return ZL_FX_MAX;
    }
    {
        int64_t dz = zl_ceil_div64((int64_t)z * num, denom);
        return dz > INT32_MAX ? ZL_FX_MAX : (zl_fixed)dz;
    }
}
