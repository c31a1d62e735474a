/* SPDX-License-Identifier: MIT */
/*
 * Stage 2, geometry: flat lighting from a zl_lighting (FLAT LIGHTING in
 * zl_face_light.h). The face normal and the Q14 light follow zl_light.c's
 * flat rule step for step, so that one equivalent light gives its colours.
 */
#include "zline/zl_face_light.h"
#include "zl_geometry.h"

#define Q14 (1 << 14)
#define UNIT_SQ ((int64_t)1 << 32)       /* |v|^2 of a Q16 unit vector */
#define UNIT_TOLERANCE ((int64_t)1 << 19) /* 1/8192 of it: a rounded unit vector */

/* Per-light numbers in model space, Q14 as the flat rule uses them (a
 * point light's per face, from its model-space position p, Q16.16). */
typedef struct {
    int32_t l[3], h[3];
    int spec;
    int point;
    int64_t p[3];
} fl_light;

/* Shift v right (floor) until every component is below 2^bits. */
static void shrink3(int64_t *v, unsigned bits)
{
    unsigned len = bit_length64(mag64(v[0]) | mag64(v[1]) | mag64(v[2])), k;
    if (len > bits)
        for (k = 0; k < 3; k++)
            v[k] = zl_floor_shift64(v[k], len - bits);
}

/* v as a Q16 unit vector: as it is when already unit within the tolerance
 * (and in Q16 range), else v / |v| rounded. 0 for the zero vector. */
static int unit16(const int64_t *vin, int64_t *out)
{
    int64_t v[3], sq;
    uint32_t len;
    unsigned k;
    for (k = 0; k < 3; k++)
        v[k] = vin[k];
    if ((mag64(v[0]) | mag64(v[1]) | mag64(v[2])) == 0)
        return 0;
    if ((mag64(v[0]) | mag64(v[1]) | mag64(v[2])) < ((uint64_t)1 << 18)) {
        sq = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        if (sq >= UNIT_SQ - UNIT_TOLERANCE && sq <= UNIT_SQ + UNIT_TOLERANCE) {
            for (k = 0; k < 3; k++)
                out[k] = v[k];
            return 1;
        }
    }
    shrink3(v, 30);
    len = zl_isqrt64((uint64_t)(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    if (len == 0)
        return 0;
    for (k = 0; k < 3; k++)
        out[k] = zl_round_div64(v[k] * 65536, (int64_t)len);
    return 1;
}

/* Cofactor matrix of the 3x3 (Q32): adj(M) = cof^T, M^-1 = adj / det. */
static int cofactors(const zl_mat4 *m, int64_t c[9])
{
    const zl_fixed *a = m->m;
    int r, k;
    int64_t det;
    for (r = 0; r < 3; r++)
        for (k = 0; k < 3; k++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
            c[r * 3 + k] = (int64_t)a[r1 * 4 + k1] * a[r2 * 4 + k2] - (int64_t)a[r1 * 4 + k2] * a[r2 * 4 + k1];
        }
    /* det's sign, from the first row (entries within +-16384.0 keep it in 64 bits after a shift) */
    det = zl_floor_shift64(c[0], 16) * a[0] + zl_floor_shift64(c[1], 16) * a[1] + zl_floor_shift64(c[2], 16) * a[2];
    if (det == 0)
        return 0;
    if (det < 0)
        for (k = 0; k < 9; k++)
            c[k] = -c[k];
    return 1;
}

/* Direction d (Q16, the lights' space) into model space as a Q16 unit
 * vector: M^-1 d up to a positive factor = adj(M) d, in Q16 (adj / 2^32). */
static int to_model(const int64_t *cof, const int64_t *d, int64_t *out)
{
    int64_t v[3], dd[3];
    unsigned k, shift = 0, len;
    if (cof == NULL)
        return unit16(d, out);
    for (k = 0; k < 3; k++)
        dd[k] = d[k];
    shrink3(dd, 17); /* a unit Q16 vector is not shifted */
    len = bit_length64(mag64(cof[0]) | mag64(cof[1]) | mag64(cof[2]) | mag64(cof[3]) | mag64(cof[4]) | mag64(cof[5]) |
                     mag64(cof[6]) | mag64(cof[7]) | mag64(cof[8]));
    if (len > 44)
        shift = len - 44; /* products below 2^61, sums below 2^63 */
    for (k = 0; k < 3; k++) /* adj = cof^T: row k of adj is column k of cof */
        v[k] = zl_floor_shift64(cof[k], shift) * dd[0] + zl_floor_shift64(cof[3 + k], shift) * dd[1] +
               zl_floor_shift64(cof[6 + k], shift) * dd[2];
    for (k = 0; k < 3; k++) /* back to Q16: exact for a quarter turn, whose cofactors are 0 or +-2^32 */
        v[k] = zl_floor_shift64(v[k] + ((int64_t)1 << (31 - shift)), 32 - shift);
    return unit16(v, out);
}

/* A Q16 unit vector in Q14 as the flat rule takes light_dir: c / 4 towards
 * zero, clamped to +-1, and the front face's sign. */
static void to_q14(const int64_t *u, int32_t sign, int32_t *out)
{
    unsigned k;
    for (k = 0; k < 3; k++) {
        int64_t c = u[k], v = zl_floor_shift64(c + (c < 0 ? 3 : 0), 2);
        v = v > Q14 ? Q14 : (v < -Q14 ? -Q14 : v);
        out[k] = sign * (int32_t)v;
    }
}

/* The viewer in model space as a Q16 unit vector; 0 when it is zero. */
static int model_viewer(const zl_lighting *lt, const int64_t *cof, int64_t *vm)
{
    int64_t d[3];
    d[0] = lt->viewer.x, d[1] = lt->viewer.y, d[2] = lt->viewer.z;
    return to_model(cof, d, vm);
}

/* Every light's numbers; vm: the viewer in model space, for the half
 * vectors of point lights. */
static int prepare(const zl_lighting *lt, const zl_mat4 *model, int32_t sign, fl_light *out, int64_t *vm)
{
    int64_t cof[9], view[3], u[3], l[3], h[3];
    const int64_t *c = NULL;
    unsigned i, k;
    if (model != NULL) {
        if (!cofactors(model, cof))
            return 0;
        c = cof;
    }
    for (i = 0; i < lt->light_count; i++) {
        const zl_light *li = &lt->lights[i];
        int64_t d[3];
        out[i].point = li->point != 0;
        out[i].spec = (li->specular.r | li->specular.g | li->specular.b) != 0;
        if (out[i].point) { /* its vectors are per face (point_face) */
            if (!zl_light_point_to_model(model, li->position, out[i].p))
                return 0;
            if (out[i].spec && !model_viewer(lt, c, vm))
                return 0;
            continue;
        }
        d[0] = li->dir.x, d[1] = li->dir.y, d[2] = li->dir.z;
        if (!unit16(d, l) || !to_model(c, d, u))
            return 0;
        to_q14(u, sign, out[i].l);
        if (!out[i].spec)
            continue;
        d[0] = lt->viewer.x, d[1] = lt->viewer.y, d[2] = lt->viewer.z;
        if (!unit16(d, view))
            return 0;
        for (k = 0; k < 3; k++)
            h[k] = l[k] + view[k];
        if (!unit16(h, h)) { /* light straight behind the viewer: no specular */
            out[i].spec = 0;
            continue;
        }
        if (!to_model(c, h, u))
            return 0;
        to_q14(u, sign, out[i].h);
    }
    return 1;
}

/* The face normal scaled below 2^14, as zl_light.c's 64-bit definition. */
static void face_normal(const zl_fixed *p0, const zl_fixed *p1, const zl_fixed *p2, int32_t *m)
{
    int64_t e[6], n[3];
    unsigned k;
    for (k = 0; k < 3; k++) {
        e[k] = (int64_t)p1[k] - p0[k];
        e[k + 3] = (int64_t)p2[k] - p0[k];
    }
    {
        uint64_t big = 0;
        for (k = 0; k < 6; k++)
            big = mag64(e[k]) > big ? mag64(e[k]) : big;
        if (big >= ((uint64_t)1 << 30)) {
            unsigned sh = bit_length64(big) - 30;
            for (k = 0; k < 6; k++)
                e[k] = zl_floor_shift64(e[k], sh);
        }
    }
    n[0] = e[1] * e[5] - e[2] * e[4];
    n[1] = e[2] * e[3] - e[0] * e[5];
    n[2] = e[0] * e[4] - e[1] * e[3];
    {
        uint64_t big = mag64(n[0]) > mag64(n[1]) ? mag64(n[0]) : mag64(n[1]);
        big = mag64(n[2]) > big ? mag64(n[2]) : big;
        if (big >= ((uint64_t)1 << 14)) {
            unsigned sh = bit_length64(big) - 14;
            for (k = 0; k < 3; k++)
                n[k] = zl_floor_shift64(n[k], sh);
        }
    }
    for (k = 0; k < 3; k++)
        m[k] = (int32_t)n[k];
}

/* Q14 cosine of normal m (below 2^14) with a Q14 direction, 0 when not positive. */
static int32_t cos14(const int32_t *m, const int32_t *d, uint32_t len)
{
    int32_t dot = m[0] * d[0] + m[1] * d[1] + m[2] * d[2], c;
    if (dot <= 0)
        return 0;
    c = dot / (int32_t)len;
    return c > Q14 ? Q14 : c;
}

static uint32_t pow14(uint32_t x, unsigned e)
{
    uint32_t r = Q14;
    while (e-- > 0)
        r = (r * x + (1u << 13)) >> 14;
    return r;
}

static void light_face(const zl_lighting *lt, const fl_light *fl, const int32_t *m, zl_rgb mat, uint8_t *out)
{
    uint32_t diffuse[3], spec[3], len = zl_isqrt32((uint32_t)(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]));
    const uint8_t mc[3] = {mat.r, mat.g, mat.b};
    unsigned i, k;
    diffuse[0] = lt->ambient.r, diffuse[1] = lt->ambient.g, diffuse[2] = lt->ambient.b;
    spec[0] = spec[1] = spec[2] = 0;
    for (i = 0; len != 0 && i < lt->light_count; i++) {
        const zl_light *li = &lt->lights[i];
        uint32_t d = (uint32_t)cos14(m, fl[i].l, len), s = 0;
        if (d == 0)
            continue;
        if (fl[i].spec)
            s = pow14((uint32_t)cos14(m, fl[i].h, len), lt->shininess);
        diffuse[0] += (li->diffuse.r * d + (1u << 13)) >> 14;
        diffuse[1] += (li->diffuse.g * d + (1u << 13)) >> 14;
        diffuse[2] += (li->diffuse.b * d + (1u << 13)) >> 14;
        spec[0] += (li->specular.r * s + (1u << 13)) >> 14;
        spec[1] += (li->specular.g * s + (1u << 13)) >> 14;
        spec[2] += (li->specular.b * s + (1u << 13)) >> 14;
    }
    for (k = 0; k < 3; k++) {
        uint32_t c = (mc[k] * diffuse[k] + 127u) / 255u + spec[k];
        out[k] = (uint8_t)(c > 255u ? 255u : c);
    }
}

/* A point light's Q14 vectors for the triangle p0 p1 p2: l = P - c with c
 * its centroid (computed as 3P - (p0 + p1 + p2), exact), and with specular
 * h = unit(unit(l) + vm). A face whose centroid is at the light gets none. */
static void point_face(const fl_light *pl, const int64_t *vm, int32_t sign, const zl_fixed *p0, const zl_fixed *p1,
                       const zl_fixed *p2, fl_light *out)
{
    int64_t l[3], u[3];
    unsigned k;
    *out = *pl;
    for (k = 0; k < 3; k++)
        l[k] = 3 * pl->p[k] - ((int64_t)p0[k] + p1[k] + p2[k]); /* |P| <= 2^46 */
    if (!unit16(l, u)) {
        out->l[0] = out->l[1] = out->l[2] = 0; /* cos14 is then 0: no light */
        return;
    }
    to_q14(u, sign, out->l);
    if (!out->spec)
        return;
    for (k = 0; k < 3; k++)
        l[k] = u[k] + vm[k];
    out->spec = unit16(l, u);
    if (out->spec)
        to_q14(u, sign, out->h);
}

static int mesh_ok(const zl_mesh *mesh)
{
    uint32_t i;
    if (mesh->triangle_count > 0 && (mesh->indices == NULL || mesh->positions == NULL))
        return 0;
    for (i = 0; i < (uint32_t)mesh->triangle_count * 3u; i++)
        if (mesh->indices[i] >= mesh->vertex_count)
            return 0;
    return 1;
}

static int positions_ok(const zl_mesh *mesh)
{
    uint32_t i;
    for (i = 0; i < (uint32_t)mesh->vertex_count * 3u; i++)
        if (!in_limit(mesh->positions[i]))
            return 0;
    return 1;
}

zl_status zl_light_faces(const zl_lighting *lt, const zl_mat4 *model, const zl_mesh *mesh, uint8_t front_face,
                         uint8_t *colors)
{
    fl_light fl[ZL_MAX_LIGHTS], face[ZL_MAX_LIGHTS];
    int64_t vm[3] = {0, 0, 0};
    int32_t sign = front_face == ZL_FRONT_CW ? -1 : 1;
    uint32_t t;
    unsigned i;
    int points = 0;
    if (lt == NULL || mesh == NULL || colors == NULL || front_face > ZL_FRONT_CW || !mesh_ok(mesh))
        return ZL_ERR_ARG;
    if (lt->light_count > ZL_MAX_LIGHTS || lt->shininess > ZL_MAX_SHININESS || !positions_ok(mesh) ||
        !prepare(lt, model, sign, fl, vm))
        return ZL_ERR_RANGE;
    for (i = 0; i < lt->light_count; i++)
        points |= fl[i].point;
    for (t = 0; t < mesh->triangle_count; t++) {
        const uint16_t *idx = mesh->indices + (size_t)t * 3u;
        const zl_fixed *p0 = mesh->positions + (size_t)idx[0] * 3u, *p1 = mesh->positions + (size_t)idx[1] * 3u,
                       *p2 = mesh->positions + (size_t)idx[2] * 3u;
        const uint8_t *fc = mesh->face_colors;
        zl_rgb mat = lt->material;
        int32_t m[3];
        if (fc != NULL)
            mat.r = fc[t * 3], mat.g = fc[t * 3 + 1], mat.b = fc[t * 3 + 2];
        face_normal(p0, p1, p2, m);
        if (!points) {
            light_face(lt, fl, m, mat, colors + (size_t)t * 3u);
            continue;
        }
        for (i = 0; i < lt->light_count; i++)
            if (fl[i].point)
                point_face(&fl[i], vm, sign, p0, p1, p2, &face[i]);
            else
                face[i] = fl[i];
        light_face(lt, face, m, mat, colors + (size_t)t * 3u);
    }
    return ZL_OK;
}
