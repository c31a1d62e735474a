/* SPDX-License-Identifier: MIT */
/*
 * An independent reference for the RASTER CONTRACT of zline.h, written from
 * the contract alone: per pixel, exact 64-bit integer arithmetic, no
 * incremental stepping, no floating point.
 *
 *   snapping  x, y (Q16.16 pixels) to 1/2^ZL_SUBPIXEL_BITS px, nearest,
 *             ties towards +infinity: s = floor((v + step/2) / step)
 *   coverage  the pixel centre (i + 1/2, j + 1/2) against the three edge
 *             functions of the snapped triangle; a centre exactly on an
 *             edge counts only for a top edge (horizontal, interior below,
 *             y down) or a left edge (interior to its right); zero area is
 *             empty; both windings.
 *   depth     the exact value of the snapped triangle's depth plane at the
 *             centre, on the stored scale: vertex depth = z_q16 * 65535 /
 *             65536, a rational computed without rounding; the contract
 *             allows stored values within +-1 of it.
 *
 * Coordinates are kept in "half subpixels" (2 * snapped value) so that pixel
 * centres are integers for every ZL_SUBPIXEL_BITS, including 0.
 *
 * zt_poly_covers is a second, differently built coverage rule for whole
 * polygons (mesh outlines): the top-left rule is exactly "sample at
 * (x + e, y + e^2) for an infinitesimal e > 0", so a centre is covered by a
 * simple polygon when that perturbed point is inside by the even-odd
 * crossing test, which reduces to exact integer sign tests.
 */
#ifndef ZT_REF_H
#define ZT_REF_H

#include <stdint.h>

#include "zline/zline.h"

#ifdef __cplusplus
extern "C" {
#endif

#define ZT_SUB (1 << ZL_SUBPIXEL_BITS) /* subpixels per pixel */

/* Snapped coordinate of a Q16.16 value, in subpixels. */
int64_t zt_snap(zl_fixed v);
/* The same for a window position beyond the Q16.16 range (raw * 2^-16 px,
 * |raw| < 2^46), as reached through a matrix. */
int64_t zt_snap64(int64_t raw);
/* Half-subpixel units: 2 * zt_snap(v). */
int64_t zt_snap2(zl_fixed v);
/* Centre of pixel index i in half-subpixel units: (2i + 1) * ZT_SUB. */
int64_t zt_centre2(int32_t i);

/* floor(n / d) and ceil(n / d), d > 0 (own versions, not zl_fixed.h's). */
int64_t zt_floor_div(int64_t n, int64_t d);
int64_t zt_ceil_div(int64_t n, int64_t d);

typedef struct {
    int64_t x[3], y[3]; /* snapped, half subpixels, in clockwise-on-screen order */
    int64_t z[3];       /* raw Q16.16 window depth of each (reordered) vertex */
    int64_t area;       /* doubled signed area after reordering: > 0, or 0 = empty */
    int orient;         /* winding of the input order: +1 clockwise on screen (y down),
                           -1 counter-clockwise, 0 zero area after snapping */
    int32_t px0, py0, px1, py1; /* pixel index box that can contain covered centres
                                   (inclusive; px0 > px1 when empty) */
} zt_tri;

/* Set up from three vertices, each x, y, z in Q16.16 (pixel space, NULL matrix). */
void zt_tri_init(zt_tri *t, const zl_fixed *p0, const zl_fixed *p1, const zl_fixed *p2);
/* The same with 64-bit raw values: xyz[3k + 0..2] for vertex k (x, y in
 * 2^-16 px, may exceed Q16.16; z raw Q16.16 window depth). */
void zt_tri_init64(zt_tri *t, const int64_t *xyz);
/* Set up from already snapped half-subpixel coordinates (z = 0). */
void zt_tri_init_snapped2(zt_tri *t, const int64_t *x2, const int64_t *y2);
/* Is pixel (i, j)'s centre covered? */
int zt_tri_covers(const zt_tri *t, int32_t i, int32_t j);
/* mask[j * w + i] = coverage for the w x h pixels at the origin; returns the count. */
unsigned zt_tri_mask(const zt_tri *t, uint8_t *mask, unsigned w, unsigned h);

/* Expected stored depth at a covered pixel. */
typedef struct {
    int32_t lo, hi;    /* the stored value must lie in lo..hi */
    int32_t nearest;   /* the exact value rounded (ties up), for messages */
    int steep;         /* the plane changes by more than 2^19 steps per pixel in x or y:
                          lo..hi is then the vertices' range (the contract's clamp) */
} zt_depth_ref;

void zt_tri_depth(const zt_tri *t, int32_t i, int32_t j, zt_depth_ref *out);

/*
 * Coverage of pixel (i, j) by the simple polygon x2[k], y2[k] (k < n, half
 * subpixel units, either winding) under the top-left rule. Independent of
 * zt_tri_covers; for a triangle both agree.
 */
int zt_poly_covers(const int64_t *x2, const int64_t *y2, unsigned n, int32_t i, int32_t j);

/* xorshift32 PRNG; the state must start non-zero. */
uint32_t zt_rand(uint32_t *state);
/* Uniform-ish integer in lo..hi inclusive (hi - lo < 2^31). */
int32_t zt_rand_range(uint32_t *state, int32_t lo, int32_t hi);
/* xorshift64 (13, 7, 17), the high 32 bits of the new state; the state must
 * start non-zero. A second generator, not a replacement: the tests seeded
 * with it keep the scenes they were written with. */
uint32_t zt_rand64(uint64_t *state);
/* lo + zt_rand64() % (hi - lo + 1), lo..hi inclusive (hi - lo < 2^31). */
int32_t zt_rand64_range(uint64_t *state, int32_t lo, int32_t hi);

/* floor(sqrt(v)). */
uint64_t zt_isqrt(uint64_t v);

#ifdef __cplusplus
}
#endif

#endif /* ZT_REF_H */
