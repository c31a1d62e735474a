/* SPDX-License-Identifier: MIT */
/*
 * Stage 6, visibility: the two back-face tests of the lecture.
 *
 * Viewpoint culling (before projection): the triangle's plane in model space
 * n . p = n . p0 with n = (p1 - p0) x (p2 - p0); the eye sees the side n
 * points to when n . (eye - p0) > 0. That is the determinant of the three
 * vectors p1 - p0, p2 - p0, eye - p0: with Q16.16 inputs the edge vectors
 * need 33 bits, n 66 and the product 99, so it is computed exactly in a
 * small signed 128-bit arithmetic. Seen from that side, with a right-handed
 * model-view and a projection that does not mirror, the vertices run
 * counter-clockwise on screen.
 *
 * View-direction culling (after projection): the sign of the signed area of
 * the snapped window-space polygon, which is what zl_tri_classify culls by.
 */
#include "zl_vis_internal.h"

typedef struct {
    uint64_t lo, hi; /* two's complement */
} i128;

static i128 i128_neg(i128 a)
{
    i128 r;
    r.lo = ~a.lo + 1u;
    r.hi = ~a.hi + (r.lo == 0 ? 1u : 0u);
    return r;
}

static i128 i128_add(i128 a, i128 b)
{
    i128 r;
    r.lo = a.lo + b.lo;
    r.hi = a.hi + b.hi + (r.lo < a.lo ? 1u : 0u);
    return r;
}

static int i128_sign(i128 a)
{
    if (a.hi & 0x8000000000000000u)
        return -1;
    return (a.hi | a.lo) != 0;
}

/* Unsigned 64 x 64 -> 128 from 32-bit halves. */
static i128 mul_u64(uint64_t a, uint64_t b)
{
    uint64_t a0 = a & 0xFFFFFFFFu, a1 = a >> 32, b0 = b & 0xFFFFFFFFu, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (p01 & 0xFFFFFFFFu) + (p10 & 0xFFFFFFFFu);
    i128 r;
    r.lo = (p00 & 0xFFFFFFFFu) | (mid << 32);
    r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
    return r;
}

static uint64_t mag(int64_t v)
{
    return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
}

/* a * b for |a|, |b| < 2^63. */
static i128 mul_s64(int64_t a, int64_t b)
{
    i128 r = mul_u64(mag(a), mag(b));
    return (a < 0) != (b < 0) ? i128_neg(r) : r;
}

/* a * b with a a 128-bit value below 2^126 in magnitude and |b| < 2^33; the
 * product must stay below 2^127 (callers' ranges guarantee it). */
static i128 mul_128_s64(i128 a, int64_t b)
{
    int neg = i128_sign(a) < 0;
    i128 m = neg ? i128_neg(a) : a, lo, hi;
    uint64_t bm = mag(b);
    lo = mul_u64(m.lo, bm);
    hi = mul_u64(m.hi, bm);
    lo.hi += hi.lo;
    if ((b < 0) != neg)
        lo = i128_neg(lo);
    return lo;
}

int zl_cull_viewpoint(const zl_mesh *mesh, uint32_t t, zl_vec3 eye, uint8_t front_face)
{
    const zl_fixed *p0, *p1, *p2;
    int64_t e1[3], e2[3], d[3];
    i128 n[3], dot;
    int k, s;
    if (mesh == NULL || mesh->positions == NULL || mesh->indices == NULL || t >= mesh->triangle_count ||
        front_face > ZL_FRONT_CW)
        return -1;
    for (k = 0; k < 3; k++)
        if (mesh->indices[t * 3u + (unsigned)k] >= mesh->vertex_count)
            return -1;
    p0 = &mesh->positions[mesh->indices[t * 3u] * 3u];
    p1 = &mesh->positions[mesh->indices[t * 3u + 1u] * 3u];
    p2 = &mesh->positions[mesh->indices[t * 3u + 2u] * 3u];
    for (k = 0; k < 3; k++) {
        e1[k] = (int64_t)p1[k] - p0[k];
        e2[k] = (int64_t)p2[k] - p0[k];
    }
    d[0] = (int64_t)eye.x - p0[0];
    d[1] = (int64_t)eye.y - p0[1];
    d[2] = (int64_t)eye.z - p0[2];
    n[0] = i128_add(mul_s64(e1[1], e2[2]), i128_neg(mul_s64(e1[2], e2[1])));
    n[1] = i128_add(mul_s64(e1[2], e2[0]), i128_neg(mul_s64(e1[0], e2[2])));
    n[2] = i128_add(mul_s64(e1[0], e2[1]), i128_neg(mul_s64(e1[1], e2[0])));
    dot = i128_add(i128_add(mul_128_s64(n[0], d[0]), mul_128_s64(n[1], d[1])), mul_128_s64(n[2], d[2]));
    s = i128_sign(dot);
    if (s == 0)
        return -1;
    /* n towards the eye: counter-clockwise as seen. */
    return front_face == ZL_FRONT_CCW ? s > 0 : s < 0;
}

int zl_cull_projected(const zl_mesh *mesh, uint32_t t, const zl_mat4 *mvp, uint16_t width, uint16_t height,
                      uint8_t front_face)
{
    zl_source src;
    zl_state st;
    zl_poly poly;
    int64_t area = 0;
    unsigned k;
    if (mesh == NULL || mvp == NULL || t >= mesh->triangle_count || front_face > ZL_FRONT_CW || width < 1 ||
        height < 1 || width > ZL_MAX_DIM || height > ZL_MAX_DIM || zl_check_mesh(mesh, 0) != ZL_OK)
        return -1;
    zl_state_default(&st);
    src.mesh = mesh;
    src.mvp = mvp;
    src.state = &st;
    src.cache = NULL;
    src.width = width;
    src.height = height;
    if (!zl_tri_polygon(&src, t, &poly))
        return -1;
    /* Doubled signed area of the polygon (the sum over its fan). */
    for (k = 1; k + 1 < poly.n; k++) {
        const zl_wvert *a = &poly.v[0], *b = &poly.v[k], *c = &poly.v[k + 1];
        area += ((int64_t)b->x - a->x) * ((int64_t)c->y - a->y) - ((int64_t)c->x - a->x) * ((int64_t)b->y - a->y);
    }
    if (area == 0)
        return -1;
    /* y down: a negative area is counter-clockwise as the viewer sees it. */
    return (area < 0) == (front_face == ZL_FRONT_CCW);
}
