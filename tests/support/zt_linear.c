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

/* One Sutherland-Hodgman pass: plane 0 keeps z >= 0, plane 1 keeps w - z >= 0. */
static int clip_pass(int plane, long double src[][4], const int *src_made, int n, long double dst[][4],
                     int *dst_made)
{
    int k, c, m = 0;
    for (k = 0; k < n; k++) {
        const long double *a = src[k], *b = src[(k + 1) % n];
        long double da = plane == 0 ? a[2] : a[3] - a[2], db = plane == 0 ? b[2] : b[3] - b[2];
        if (da >= 0) {
            for (c = 0; c < 4; c++)
                dst[m][c] = a[c];
            dst_made[m++] = src_made[k];
        }
        if ((da >= 0) != (db >= 0)) {
            long double s = da / (da - db);
            for (c = 0; c < 4; c++)
                dst[m][c] = a[c] + s * (b[c] - a[c]);
            dst_made[m++] = 1;
        }
    }
    return m;
}

int zt_clip_near_far(const zl_vec4 v[3], long double out[ZT_CLIP_MAX][4], int made[ZT_CLIP_MAX])
{
    long double mid[ZT_CLIP_MAX][4];
    int mid_made[ZT_CLIP_MAX], k, n;
    for (k = 0; k < 3; k++) {
        out[k][0] = v[k].x;
        out[k][1] = v[k].y;
        out[k][2] = v[k].z;
        out[k][3] = v[k].w;
        made[k] = 0;
    }
    n = clip_pass(0, out, made, 3, mid, mid_made); /* a triangle cut by one plane: at most 4 */
    return clip_pass(1, mid, mid_made, n, out, made);
}
