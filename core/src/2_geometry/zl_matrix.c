/* SPDX-License-Identifier: MIT */
/* Stage 2, geometry: 4x4 matrices in Q16.16 (building, multiplying and
 * applying them) and the transform limits of a mesh (zl_check_geometry). */
#include "../1_base/zl_internal.h"
#include "zl_geometry.h"

#define M(r, c) m[(r) * 4 + (c)]
#define ZL_COORD_LIMIT ((int32_t)1 << 30) /* +-16384.0: keeps 4 products inside int64 */

void zl_mat4_identity(zl_mat4 *out)
{
    int i;
    for (i = 0; i < 16; i++)
        out->m[i] = (i % 5 == 0) ? ZL_FX_ONE : 0;
}

void zl_mat4_mul(zl_mat4 *out, const zl_mat4 *a, const zl_mat4 *b)
{
    zl_mat4 r;
    int row, col, k;
    for (row = 0; row < 4; row++) {
        for (col = 0; col < 4; col++) {
            /* Each product is pre-shifted by 8 so four of them cannot overflow. */
            int64_t acc = 0;
            for (k = 0; k < 4; k++)
                acc += zl_floor_shift64((int64_t)a->M(row, k) * b->M(k, col), 8);
            r.M(row, col) = zl_fx_sat(zl_floor_shift64(acc + 128, 8));
        }
    }
    *out = r;
}

void zl_mat4_translate(zl_mat4 *out, zl_vec3 t)
{
    zl_mat4_identity(out);
    out->M(0, 3) = t.x;
    out->M(1, 3) = t.y;
    out->M(2, 3) = t.z;
}

void zl_mat4_scale(zl_mat4 *out, zl_vec3 s)
{
    zl_mat4_identity(out);
    out->M(0, 0) = s.x;
    out->M(1, 1) = s.y;
    out->M(2, 2) = s.z;
}

/* Rotation in the plane of axes (i, j): i -> j for a positive angle. */
static void rotate_plane(zl_mat4 *out, int i, int j, zl_angle a)
{
    zl_fixed c = zl_cos(a), s = zl_sin(a);
    zl_mat4_identity(out);
    out->M(i, i) = c;
    out->M(i, j) = -s;
    out->M(j, i) = s;
    out->M(j, j) = c;
}

void zl_mat4_rotate_x(zl_mat4 *out, zl_angle a)
{
    rotate_plane(out, 1, 2, a);
}

void zl_mat4_rotate_y(zl_mat4 *out, zl_angle a)
{
    rotate_plane(out, 2, 0, a);
}

void zl_mat4_rotate_z(zl_mat4 *out, zl_angle a)
{
    rotate_plane(out, 0, 1, a);
}

/* The vectors of zl_mat4_look_at as three components each (loops over them
 * are a third of the code of the unrolled struct forms on a Cortex-M0). */

/* Unit vector along v, Q16.16; ZL_ERR_RANGE for the zero vector. */
static zl_status normalize(const zl_fixed *v, zl_fixed *out)
{
    uint64_t sq = 0;
    int64_t len;
    int k;
    for (k = 0; k < 3; k++)
        sq += (uint64_t)((int64_t)v[k] * v[k]);
    len = zl_isqrt64(sq); /* |v| in Q16.16 units */
    if (len == 0)
        return ZL_ERR_RANGE;
    for (k = 0; k < 3; k++)
        out[k] = (zl_fixed)zl_round_div64((int64_t)v[k] * 65536, len);
    return ZL_OK;
}

/* r = a x b, each component rounded and saturated. */
static void cross(const zl_fixed *a, const zl_fixed *b, zl_fixed *r)
{
    unsigned k;
    for (k = 0; k < 3; k++) {
        unsigned i = NEXT3(k), j = NEXT3(i);
        r[k] = zl_fx_sat(zl_floor_shift64((int64_t)a[i] * b[j] - (int64_t)a[j] * b[i] + 32768, 16));
    }
}

/* a . b rounded; ZL_ERR_RANGE when it leaves +-32767.99998 (so that its
 * negation fits as well). */
static zl_status dot(const zl_fixed *a, const zl_fixed *b, zl_fixed *out)
{
    int64_t d = 0;
    int k;
    for (k = 0; k < 3; k++)
        d += (int64_t)a[k] * b[k];
    d = zl_floor_shift64(d + 32768, 16);
    if (d > INT32_MAX || d < -INT32_MAX)
        return ZL_ERR_RANGE;
    *out = (zl_fixed)d;
    return ZL_OK;
}

zl_status zl_mat4_look_at(zl_mat4 *out, zl_vec3 eye, zl_vec3 target, zl_vec3 up)
{
    const zl_fixed e[3] = {eye.x, eye.y, eye.z}, t[3] = {target.x, target.y, target.z}, u[3] = {up.x, up.y, up.z};
    zl_fixed axis[3][3], dir[3], up1[3], tr[3]; /* axis: s, u, f (the camera's x, y, -z) */
    int r, k;
    if (out == NULL)
        return ZL_ERR_ARG;
    /* The view direction must be representable, and so must the translation
     * (the eye's distance from the origin along each camera axis). */
    for (k = 0; k < 3; k++) {
        int64_t d = (int64_t)t[k] - e[k];
        if (d > INT32_MAX || d < INT32_MIN)
            return ZL_ERR_RANGE;
        dir[k] = (zl_fixed)d;
    }
    /* up is normalised first, so the cross product of two unit vectors
     * cannot saturate (a unit up gives itself back exactly). */
    if (normalize(dir, axis[2]) != ZL_OK || normalize(u, up1) != ZL_OK)
        return ZL_ERR_RANGE;
    cross(axis[2], up1, dir);
    if (normalize(dir, axis[0]) != ZL_OK)
        return ZL_ERR_RANGE;
    cross(axis[0], axis[2], axis[1]);
    for (r = 0; r < 3; r++)
        if (dot(axis[r], e, &tr[r]) != ZL_OK)
            return ZL_ERR_RANGE;
    zl_mat4_identity(out);
    for (r = 0; r < 3; r++) { /* rows s, u, -f; translations -s.eye, -u.eye, f.eye */
        for (k = 0; k < 3; k++)
            out->M(r, k) = r == 2 ? -axis[r][k] : axis[r][k];
        out->M(r, 3) = r == 2 ? tr[r] : -tr[r];
    }
    return ZL_OK;
}

zl_status zl_mat4_perspective(zl_mat4 *out, zl_angle fovy, zl_fixed aspect, zl_fixed near_z,
                              zl_fixed far_z)
{
    zl_fixed half_sin, half_cos, cot, a, b;
    if (out == NULL)
        return ZL_ERR_ARG;
    if (fovy <= 0 || fovy >= ZL_ANGLE_TURN / 2 || aspect < ZL_FX_ONE / 64 ||
        aspect > 64 * ZL_FX_ONE || near_z <= 0 || far_z <= near_z)
        return ZL_ERR_RANGE;
    half_sin = zl_sin(fovy / 2);
    half_cos = zl_cos(fovy / 2);
    if (zl_fx_div_checked(half_cos, half_sin, &cot) != ZL_OK)
        return ZL_ERR_RANGE;
    /* A = f / (f - n), B = -f n / (f - n): the pseudodepth constants. */
    if (zl_fx_div_checked(far_z, far_z - near_z, &a) != ZL_OK)
        return ZL_ERR_RANGE;
    {
        int64_t fn = (int64_t)far_z * near_z; /* Q32 */
        int64_t q = zl_round_div64(fn, (int64_t)(far_z - near_z)); /* Q16 */
        if (q > INT32_MAX)
            return ZL_ERR_RANGE;
        b = (zl_fixed)-q;
    }
    for (int i = 0; i < 16; i++)
        out->m[i] = 0;
    if (zl_fx_div_checked(cot, aspect, &out->M(0, 0)) != ZL_OK)
        return ZL_ERR_RANGE;
    out->M(1, 1) = cot;
    /* z_clip = A * (-z_eye) + B, w_clip = -z_eye: z_clip / w_clip = A + B / distance. */
    out->M(2, 2) = -a;
    out->M(2, 3) = b;
    out->M(3, 2) = -ZL_FX_ONE;
    return ZL_OK;
}

zl_status zl_mat4_ortho(zl_mat4 *out, zl_fixed l, zl_fixed r, zl_fixed b, zl_fixed t, zl_fixed near_z,
                        zl_fixed far_z)
{
    zl_fixed sx, sy, sz;
    if (out == NULL)
        return ZL_ERR_ARG;
    if (r <= l || t <= b || far_z <= near_z)
        return ZL_ERR_RANGE;
    /* Differences are formed in 64 bits: r - l may exceed Q16.16. */
    if ((int64_t)r - l > INT32_MAX || (int64_t)t - b > INT32_MAX || (int64_t)far_z - near_z > INT32_MAX)
        return ZL_ERR_RANGE;
    if (zl_fx_div_checked(2 * ZL_FX_ONE, r - l, &sx) != ZL_OK ||
        zl_fx_div_checked(2 * ZL_FX_ONE, t - b, &sy) != ZL_OK ||
        zl_fx_div_checked(ZL_FX_ONE, far_z - near_z, &sz) != ZL_OK)
        return ZL_ERR_RANGE;
    zl_mat4_identity(out);
    out->M(0, 0) = sx;
    out->M(0, 3) = zl_fx_sat(-zl_round_div64(((int64_t)r + l) * 65536, (int64_t)r - l));
    out->M(1, 1) = sy;
    out->M(1, 3) = zl_fx_sat(-zl_round_div64(((int64_t)t + b) * 65536, (int64_t)t - b));
    /* depth = (distance - n) / (f - n): 0 at near, 1 at far, w = 1. */
    out->M(2, 2) = -sz;
    out->M(2, 3) = zl_fx_sat(-zl_round_div64((int64_t)near_z * 65536, (int64_t)far_z - near_z));
    return ZL_OK;
}

static int in_coord_range(zl_fixed v)
{
    return v >= -ZL_COORD_LIMIT && v <= ZL_COORD_LIMIT;
}

zl_status zl_transform_point(const zl_mat4 *m, zl_vec3 v, zl_vec4 *out)
{
    zl_fixed *res[4];
    int row;
    if (m == NULL || out == NULL)
        return ZL_ERR_ARG;
    if (!in_coord_range(v.x) || !in_coord_range(v.y) || !in_coord_range(v.z))
        return ZL_ERR_RANGE;
    res[0] = &out->x;
    res[1] = &out->y;
    res[2] = &out->z;
    res[3] = &out->w;
    for (row = 0; row < 4; row++) {
        const zl_fixed *r = &m->m[row * 4];
        int64_t acc;
        if (!in_coord_range(r[0]) || !in_coord_range(r[1]) || !in_coord_range(r[2]) ||
            !in_coord_range(r[3]))
            return ZL_ERR_RANGE;
        acc = (int64_t)r[0] * v.x + (int64_t)r[1] * v.y + (int64_t)r[2] * v.z +
              (int64_t)r[3] * ZL_FX_ONE;
        acc = zl_floor_shift64(acc + 32768, 16);
        if (acc > INT32_MAX || acc < INT32_MIN)
            return ZL_ERR_RANGE;
        *res[row] = (zl_fixed)acc;
    }
    return ZL_OK;
}

/* Every vertex transformed (zl_transform_point checks its coordinates too). */
static zl_status transform_every_vertex(const zl_fixed *positions, uint32_t vertex_count, const zl_mat4 *mvp)
{
    uint32_t i;
    for (i = 0; i < vertex_count * 3u; i += 3) {
        zl_vec3 v;
        zl_vec4 c;
        v.x = ZL_MESH_POS(positions, i);
        v.y = ZL_MESH_POS(positions, i + 1);
        v.z = ZL_MESH_POS(positions, i + 2);
        if (zl_transform_point(mvp, v, &c) != ZL_OK)
            return ZL_ERR_RANGE;
    }
    return ZL_OK;
}

/*
 * The transform limits of zline.h's LIMITS block, checked once per draw
 * before any pixel: with a matrix, every entry and every vertex coordinate
 * within +-16384.0, and no vertex whose clip-space position leaves Q16.16.
 * A bound from the largest coordinate per axis settles the last part for
 * ordinary scenes in one pass over the positions; only when the bound could
 * overflow is every vertex transformed. Pixel space (no matrix) takes any
 * Q16.16 position: x, y are clipped to the guard band, z to 0..1.
 */
zl_status zl_check_positions(const zl_fixed *positions, uint32_t vertex_count, const zl_mat4 *mvp)
{
    int64_t big[4] = {0, 0, 0, ZL_FX_ONE};
    uint32_t i, n;
    int row, k, exact = 0;
    if (mvp == NULL)
        return ZL_OK;
    for (i = 0; i < 16; i++)
        if (!in_coord_range(mvp->m[i]))
            return ZL_ERR_RANGE;
    if (positions == NULL)
        return ZL_OK;
    if (!ZL_FAST_PATHS) /* no bound: the same answer, less code (zl_config.h) */
        return transform_every_vertex(positions, vertex_count, mvp);
    n = vertex_count * 3u;
    /* The OR of the |coordinates| per axis is at least their largest and
     * below twice it: when all three ORs are below the limit, every
     * coordinate is in range and the ORs serve as the bound (a looser one:
     * at worst the exact pass below runs). Else the precise pass. */
    {
        uint32_t o[3] = {0, 0, 0};
        for (i = 0; i < n; i += 3) {
            o[0] |= abs32(ZL_MESH_POS(positions, i));
            o[1] |= abs32(ZL_MESH_POS(positions, i + 1));
            o[2] |= abs32(ZL_MESH_POS(positions, i + 2));
        }
        if ((o[0] | o[1] | o[2]) < (uint32_t)ZL_COORD_LIMIT) {
            for (k = 0; k < 3; k++)
                big[k] = o[k];
            n = 0; /* no precise pass */
        }
    }
    for (i = 0; i < n; i += 3) {
        for (k = 0; k < 3; k++) {
            zl_fixed v = ZL_MESH_POS(positions, i + (uint32_t)k);
            int64_t a = v < 0 ? -(int64_t)v : v;
            if (!in_coord_range(v))
                return ZL_ERR_RANGE;
            if (a > big[k])
                big[k] = a;
        }
    }
    /* |row . (p, 1)| <= sum |m_rk| big_k: four products below 2^60 each. */
    for (row = 0; row < 4; row++) {
        int64_t bound = 0;
        for (k = 0; k < 4; k++) {
            int64_t e = mvp->m[row * 4 + k];
            bound += (e < 0 ? -e : e) * big[k];
        }
        if (zl_floor_shift64(bound + 32768, 16) > INT32_MAX)
            exact = 1;
    }
    return exact ? transform_every_vertex(positions, vertex_count, mvp) : ZL_OK;
}

zl_status zl_check_geometry(const zl_mesh *m, const zl_mat4 *mvp)
{
    zl_status st = zl_check_mesh(m, mvp == NULL);
    if (st != ZL_OK)
        return st;
    return zl_check_positions(m->positions, m->vertex_count, mvp);
}
