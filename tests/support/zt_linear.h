/* SPDX-License-Identifier: MIT */
/* Small linear algebra for the tests' floating-point references (the
 * clipped-triangle tests solve for homogeneous barycentrics). */
#ifndef ZT_LINEAR_H
#define ZT_LINEAR_H

/* Solve a x = r (3x3) by Gaussian elimination with partial pivoting; a and
 * r are overwritten. Returns 0 when a is singular, else 1. */
int zt_solve3(long double a[3][3], long double r[3], long double x[3]);

#endif
