/* SPDX-License-Identifier: MIT */
/* Linear algebra for the tests' references (zt_linear.h). */
#include "zt_linear.h"

/* |v| without fabsl, which avr-libc does not have (the suite on the ATmega2560). */
static long double magnitude(long double v)
{
    return v < 0 ? -v : v;
}

static void swap_rows(long double a[3][3], long double r[3], int i, int p)
{
    int k;
    long double t;
    for (k = 0; k < 3; k++) {
        t = a[i][k];
        a[i][k] = a[p][k];
        a[p][k] = t;
    }
    t = r[i];
    r[i] = r[p];
    r[p] = t;
}

int zt_solve3(long double a[3][3], long double r[3], long double x[3])
{
    int i, j, k;
    for (i = 0; i < 3; i++) {
        int p = i;
        for (j = i + 1; j < 3; j++)
            if (magnitude(a[j][i]) > magnitude(a[p][i]))
                p = j;
        if (a[p][i] == 0)
            return 0;
        swap_rows(a, r, i, p);
        for (j = i + 1; j < 3; j++) {
            long double f = a[j][i] / a[i][i];
            for (k = i; k < 3; k++)
                a[j][k] -= f * a[i][k];
            r[j] -= f * r[i];
        }
    }
    for (i = 2; i >= 0; i--) {
        long double s = r[i];
        for (k = i + 1; k < 3; k++)
            s -= a[i][k] * x[k];
        x[i] = s / a[i][i];
    }
    return 1;
}
