/* SPDX-License-Identifier: MIT */
/*
 * Stage 2, geometry: what smooth and flat lighting share for lights given in
 * world (or eye) space: the model matrix's 3x3 inverted up to a known
 * factor, and a point light's position brought into model space, once per
 * call (so no vertex is transformed for lighting).
 */
#include "zl_geometry.h"

#define QUOTIENT_LIMIT ((uint64_t)1 << 46) /* Q16.16: 2^30, far beyond any position */

/* The entries scaled by one power of two to 20 bits (exact when they grow,
 * floored when they shrink); returns that power (a = a_in 2^-p). */
static int scale_to_20_bits(int64_t *a, unsigned count)
{
    uint64_t big = 0;
    unsigned k, len;
    for (k = 0; k < count; k++)
        big |= mag64(a[k]);
    if (big == 0)
        return 0;
    len = bit_length64(big);
    for (k = 0; k < count; k++)
        a[k] = len > 20 ? zl_floor_shift64(a[k], len - 20) : a[k] * ((int64_t)1 << (20 - len));
    return (int)len - 20;
}

int zl_light_inverse3(const zl_mat4 *model, int64_t inv[9], uint64_t *det_out, int *exp_out)
{
    int64_t a[9], det;
    unsigned k;
    int p;
    if (model == NULL) {
        for (k = 0; k < 9; k++)
            inv[k] = (k % 4u == 0) ? 1 : 0;
        *det_out = 1;
        *exp_out = 0;
        return 1;
    }
    for (k = 0; k < 9; k++)
        a[k] = model->m[(k / 3u) * 4u + k % 3u];
    /* 20 bits: cofactors below 2^41, the determinant below 3 x 2^61 */
    p = scale_to_20_bits(a, 9);
    inv[0] = a[4] * a[8] - a[5] * a[7];
    inv[1] = a[2] * a[7] - a[1] * a[8];
    inv[2] = a[1] * a[5] - a[2] * a[4];
    inv[3] = a[5] * a[6] - a[3] * a[8];
    inv[4] = a[0] * a[8] - a[2] * a[6];
    inv[5] = a[2] * a[3] - a[0] * a[5];
    inv[6] = a[3] * a[7] - a[4] * a[6];
    inv[7] = a[1] * a[6] - a[0] * a[7];
    inv[8] = a[0] * a[4] - a[1] * a[3];
    det = a[0] * inv[0] + a[1] * inv[3] + a[2] * inv[6];
    if (det == 0)
        return 0;
    if (det < 0) {
        for (k = 0; k < 9; k++)
            inv[k] = -inv[k];
        det = -det;
    }
    *det_out = (uint64_t)det;
    /* the real 3x3 is a 2^(p - 16), so its inverse is adj(a) / det(a) 2^(16 - p) */
    *exp_out = 16 - p;
    return 1;
}

/* round(num 2^s / den), its magnitude saturated at QUOTIENT_LIMIT; den > 0
 * and below 2^63. For s > 0 the quotient is extended bit by bit (the
 * remainder stays below den, so doubling it cannot overflow). */
static int64_t quotient_pow2(int64_t num, uint64_t den, int s)
{
    uint64_t m = mag64(num), q = m / den, r = m % den;
    int i;
    for (i = 0; i < s && q < QUOTIENT_LIMIT; i++) {
        q <<= 1;
        r <<= 1;
        if (r >= den) {
            r -= den;
            q |= 1u;
        }
    }
    if (s >= 0) {
        if (r >= den - r) /* 2r >= den without overflow: round half up */
            q++;
    } else {
        q = -s >= 63 ? 0 : (q + ((uint64_t)1 << (-s - 1))) >> -s; /* (the remainder's part is below a unit) */
    }
    q = q > QUOTIENT_LIMIT ? QUOTIENT_LIMIT : q;
    return num < 0 ? -(int64_t)q : (int64_t)q;
}

int zl_light_point_to_model(const zl_mat4 *model, zl_vec3 position, int64_t out[3])
{
    int64_t inv[9], v[3];
    uint64_t det;
    int e, j;
    unsigned r;
    if (!zl_light_inverse3(model, inv, &det, &e))
        return 0;
    v[0] = (int64_t)position.x - (model != NULL ? model->m[3] : 0);
    v[1] = (int64_t)position.y - (model != NULL ? model->m[7] : 0);
    v[2] = (int64_t)position.z - (model != NULL ? model->m[11] : 0);
    j = scale_to_20_bits(v, 3); /* products below 2^61, their sums below 2^63 */
    for (r = 0; r < 3; r++)
        out[r] = quotient_pow2(inv[r * 3] * v[0] + inv[r * 3 + 1] * v[1] + inv[r * 3 + 2] * v[2], det, e + j);
    return 1;
}
