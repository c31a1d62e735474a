/* SPDX-License-Identifier: MIT */
/* Small linear algebra for the tests' floating-point references (the
 * clipped-triangle tests solve for homogeneous barycentrics). */
#ifndef ZT_LINEAR_H
#define ZT_LINEAR_H

#include "zline/zline.h"

/* Vertices of a triangle clipped to two planes: at most five. */
#define ZT_CLIP_MAX 5

/* Solve a x = r (3x3) by Gaussian elimination with partial pivoting; a and
 * r are overwritten. Returns 0 when a is singular, else 1. */
int zt_solve3(long double a[3][3], long double r[3], long double x[3]);

/* Triangle v (clip space) clipped to 0 <= z <= w, the near and far planes
 * (Sutherland-Hodgman in long double, independent of zline's clipper): its
 * vertices' x, y, z, w into out, made[k] non-zero where the clipping made
 * vertex k. Returns the vertex count (0: nothing left). */
int zt_clip_near_far(const zl_vec4 v[3], long double out[ZT_CLIP_MAX][4], int made[ZT_CLIP_MAX]);

#endif
