/* SPDX-License-Identifier: MIT */
/*
 * Stage 2, geometry: smooth (per-vertex) lighting, the SMOOTH LIGHTING
 * equation of zline.h. Once per call the lights are brought into model space
 * (the adjugate of the model matrix's 3x3, so no per-vertex inverse) as Q30
 * unit vectors, with their Blinn-Phong half vectors; then each vertex costs
 * one square root and one division (its normal made a Q30 unit vector) and,
 * per light, two 64-bit dot products and the specular power.
 *
 * Error budget (what the bound of zline.h rests on): unit vectors are within
 * a few 2^-30 of exact, so cosines are too and x^e (e <= 128) within
 * 2^-22; the diffuse and specular factors are rounded to Q12 (2^-13 each, at
 * most 4 lights x 255 / 2^13 = 0.125 of a colour step each for diffuse and
 * specular) and the final rounding adds 1/2: below 0.76 in all.
 */
#include "zl_geometry.h"

#define Q30 ((int64_t)1 << 30)

/* Per-light numbers, prepared once per call. */
typedef struct {
    int32_t l[3], h[3];   /* model-space unit light and half vectors, Q30 (directional) */
    int64_t p[3];         /* a point light's model-space position, Q16.16 */
    uint32_t d[3], s[3];  /* diffuse and specular colour */
    int spec;             /* the light has a specular colour (and, directional, a half vector) */
    int point;
} sl_light;

/* Scale v[0..2] by one power of two so the largest magnitude has `bits`
 * bits (left: exact; right: floor). 0 when every component is 0. */
static int scale3(int64_t *v, unsigned bits)
{
    uint64_t big = mag64(v[0]) | mag64(v[1]) | mag64(v[2]);
    unsigned len, k;
    if (big == 0)
        return 0;
    len = bit_length64(big);
    for (k = 0; k < 3; k++) {
        if (len > bits)
            v[k] = zl_floor_shift64(v[k], len - bits);
        else
            v[k] = v[k] * ((int64_t)1 << (bits - len)); /* |v| < 2^bits after: no overflow */
    }
    return 1;
}

/* v / |v| as Q30; 0 when v is zero. */
static int unit30(const int64_t *vin, int32_t *out)
{
    int64_t v[3];
    uint64_t sq;
    uint32_t len;
    unsigned k;
    v[0] = vin[0];
    v[1] = vin[1];
    v[2] = vin[2];
    if (!scale3(v, 30)) /* |v_k| < 2^30, so the squares sum below 3 * 2^60 */
        return 0;
    sq = (uint64_t)(v[0] * v[0]) + (uint64_t)(v[1] * v[1]) + (uint64_t)(v[2] * v[2]);
    len = zl_isqrt64(sq); /* >= 2^29: the largest component has 30 bits */
    for (k = 0; k < 3; k++)
        out[k] = (int32_t)zl_round_div64(v[k] * Q30, (int64_t)len); /* |v_k| 2^30 < 2^60 */
    return 1;
}

/* unit(inv * v) as Q30 for a direction v of the lights' space (any int64
 * components; scaled to 20 bits first so the products stay below 2^62). */
static int to_model(const int64_t inv[9], const int64_t *vin, int32_t *out)
{
    int64_t v[3], t[3];
    unsigned r;
    v[0] = vin[0];
    v[1] = vin[1];
    v[2] = vin[2];
    if (!scale3(v, 20))
        return 0;
    for (r = 0; r < 3; r++)
        t[r] = inv[r * 3] * v[0] + inv[r * 3 + 1] * v[1] + inv[r * 3 + 2] * v[2];
    return unit30(t, out);
}

/* Light i's numbers; vu: the unit viewer (lights' space), vm: in model
 * space; have_view: the viewer is not zero. */
static int prepare_light(const zl_light *L, const zl_mat4 *model, const int64_t inv[9], const int32_t *vu,
                         int have_view, sl_light *pl)
{
    int64_t l[3], vv[3];
    int32_t lu[3];
    unsigned k;
    pl->d[0] = L->diffuse.r;
    pl->d[1] = L->diffuse.g;
    pl->d[2] = L->diffuse.b;
    pl->s[0] = L->specular.r;
    pl->s[1] = L->specular.g;
    pl->s[2] = L->specular.b;
    pl->spec = (L->specular.r | L->specular.g | L->specular.b) != 0;
    pl->point = L->point != 0;
    if (pl->spec && !have_view)
        return 0;
    if (pl->point) /* its vectors are per vertex */
        return zl_light_point_to_model(model, L->position, pl->p);
    l[0] = L->dir.x;
    l[1] = L->dir.y;
    l[2] = L->dir.z;
    if (!unit30(l, lu) || !to_model(inv, l, pl->l))
        return 0;
    if (!pl->spec)
        return 1;
    for (k = 0; k < 3; k++)
        vv[k] = (int64_t)lu[k] + vu[k];
    pl->spec = to_model(inv, vv, pl->h); /* 0: half vector of zero, no specular */
    return 1;
}

/* Every light's numbers and the viewer in model space (vm, Q30: a point
 * light's half vectors are made per vertex from it). */
static int prepare(const zl_lighting *lt, const zl_mat4 *model, sl_light *pl, int32_t *vm)
{
    int64_t inv[9], view[3];
    uint64_t det;
    int32_t vu[3];
    unsigned i;
    int have_view, e;
    if (!zl_light_inverse3(model, inv, &det, &e))
        return 0;
    view[0] = lt->viewer.x;
    view[1] = lt->viewer.y;
    view[2] = lt->viewer.z;
    have_view = unit30(view, vu);
    vm[0] = vm[1] = vm[2] = 0;
    if (have_view && !to_model(inv, view, vm))
        return 0;
    for (i = 0; i < lt->light_count; i++)
        if (!prepare_light(&lt->lights[i], model, inv, vu, have_view, &pl[i]))
            return 0;
    return 1;
}

/* x^e for x in [0, 1] as Q30, by squaring: each product rounded. */
static uint32_t pow30(uint32_t x, unsigned e)
{
    uint32_t r = (uint32_t)Q30;
    while (e != 0) {
        if (e & 1u)
            r = (uint32_t)(((uint64_t)r * x + (UINT32_C(1) << 29)) >> 30);
        e >>= 1;
        if (e != 0)
            x = (uint32_t)(((uint64_t)x * x + (UINT32_C(1) << 29)) >> 30);
    }
    return r;
}

/* n . u for a Q30 unit normal and unit vector, as a Q30 cosine clamped to
 * [0, 1] (0 for a negative one). */
static uint32_t cos30(const int32_t *n, const int32_t *u)
{
#if ZL_MUL32_ONLY /* the same products without __aeabi_lmul */
    int64_t dot = zl_mul_s32_split(n[0], u[0]) + zl_mul_s32_split(n[1], u[1]) + zl_mul_s32_split(n[2], u[2]);
#else
    int64_t dot = (int64_t)n[0] * u[0] + (int64_t)n[1] * u[1] + (int64_t)n[2] * u[2]; /* |.| < 3 * 2^60 */
#endif
    int64_t c;
    if (dot <= 0)
        return 0;
    c = (dot + ((int64_t)1 << 29)) >> 30; /* dot > 0: the shift is a floor */
    return c > Q30 ? (uint32_t)Q30 : (uint32_t)c;
}

/*
 * The normal as a Q30 unit vector; 0 for a zero normal. The normal is first
 * scaled so its largest component has 15 or 16 bits (exact), so |n| is in
 * [2^14, 2^15 sqrt 3]; the square root, isqrt plus one Newton step, is
 * |n| 2^16 within a few units, and one reciprocal serves the three
 * components.
 */
static int normal30(const int16_t *nin, int32_t *u)
{
    int32_t n[3];
    uint32_t big, q, r0, r16, rec;
    unsigned k, sh = 0;
    n[0] = nin[0];
    n[1] = nin[1];
    n[2] = nin[2];
    big = abs32(n[0]) | abs32(n[1]) | abs32(n[2]);
    if (big == 0)
        return 0;
    while ((big << sh) < (1u << 14))
        sh++;
    for (k = 0; k < 3; k++)
        n[k] *= (int32_t)1 << sh; /* |n_k| <= 2^15 */
    q = (uint32_t)(n[0] * n[0]) + (uint32_t)(n[1] * n[1]) + (uint32_t)(n[2] * n[2]); /* <= 3 * 2^30 */
    r0 = zl_isqrt32(q);                                                                 /* >= 2^14 */
    /* |n| = r0 + f, f in [0, 1): f ~ (q - r0^2) / (2 r0); q - r0^2 <= 2 r0 < 2^17 */
    r16 = r0 * 65536u + ((q - r0 * r0) * 32768u) / r0;
    rec = zl_udiv64_32((uint64_t)1 << 61, r16, NULL); /* 2^45 / |n|, at most 2^31 */
    for (k = 0; k < 3; k++)
#if ZL_MUL32_ONLY /* in two 32-bit products: |n_k| <= 2^15, rec <= 2^31 (2^31 for |n| = 2^14) */
        u[k] = (int32_t)zl_floor_shift64((int64_t)(n[k] * (int32_t)(rec >> 16)) * 65536 +
                                             (int64_t)(n[k] * (int32_t)(rec & 0xFFFFu)) + (1 << 14),
                                         15);
#else
        u[k] = (int32_t)zl_floor_shift64((int64_t)n[k] * rec + (1 << 14), 15);
#endif
    return 1;
}

/* One channel of the equation: (m f + 127) / 255, f the ambient plus the
 * diffuse sum (Q12), then the specular sum c_spec, rounded from Q12 and
 * clamped. */
static ZL_ALWAYS_INLINE uint8_t light_channel(uint32_t m, uint32_t f, uint32_t c_spec)
{
    uint32_t c;
#if ZL_MUL32_ONLY
    c = zl_div255_31(m * f + 127u); /* m f < 2^31 */
#else
    c = (m * f + 127u) / 255u; /* m f < 2^31 */
#endif
    c = (c + c_spec + 2048u) >> 12;
    return (uint8_t)(c > 255u ? 255u : c);
}

/* The common case, one light without specular, in a loop of its own: the
 * general loop's values (its specular terms are 0 here) without its
 * per-light arrays, about half its instructions a vertex on Cortex-M4. */
static void light_one_diffuse(const sl_light *l, const uint32_t amb[3], const uint32_t mtl[3], const uint8_t *vc,
                              const int16_t *normals, uint8_t *colors, uint32_t count)
{
    const uint32_t d0 = l->d[0], d1 = l->d[1], d2 = l->d[2], a0 = amb[0], a1 = amb[1], a2 = amb[2];
    uint32_t v;
    for (v = 0; v < count; v++) {
        int32_t u[3];
        uint32_t d = normal30(&normals[v * 3u], u) ? cos30(u, l->l) : 0, d12 = (d + (UINT32_C(1) << 17)) >> 18;
        uint8_t *out = &colors[v * 3u];
        const uint8_t *mat = vc != NULL ? &vc[v * 3u] : NULL;
        out[0] = light_channel(mat != NULL ? mat[0] : mtl[0], a0 + d0 * d12, 0);
        out[1] = light_channel(mat != NULL ? mat[1] : mtl[1], a1 + d1 * d12, 0);
        out[2] = light_channel(mat != NULL ? mat[2] : mtl[2], a2 + d2 * d12, 0);
    }
}

/* A point light's vectors at model-space position pos (Q16.16): l =
 * unit(P - pos) and, with specular, h = unit(l + vm) (*spec 0 when that is
 * zero). 0 when the vertex is at the light (no light reaches it). */
static int point_vectors(const sl_light *pl, const int32_t *vm, const zl_fixed *pos, int32_t *l, int32_t *h,
                         int *spec)
{
    int64_t v[3];
    unsigned k;
    for (k = 0; k < 3; k++)
        v[k] = pl->p[k] - pos[k]; /* |P| <= 2^46, |pos| < 2^31 */
    if (!unit30(v, l))
        return 0;
    *spec = pl->spec;
    if (*spec) {
        for (k = 0; k < 3; k++)
            v[k] = (int64_t)l[k] + vm[k];
        *spec = unit30(v, h);
    }
    return 1;
}

/* The diffuse and specular factors (Q12) of point light pl at model-space
 * position pos, for unit normal u (lit: the normal is not zero). */
static ZL_NOINLINE void light_factors(const sl_light *pl, const int32_t *vm, const zl_fixed *pos, const int32_t *u,
                                      int lit, unsigned shininess, uint32_t *d12, uint32_t *s12)
{
    int32_t l[3], h[3];
    int spec = 0;
    uint32_t d = 0;
    if (lit && point_vectors(pl, vm, pos, l, h, &spec))
        d = cos30(u, l);
    *d12 = (d + (UINT32_C(1) << 17)) >> 18;
    *s12 = 0;
    if (d != 0 && spec)
        *s12 = (pow30(cos30(u, h), shininess) + (UINT32_C(1) << 17)) >> 18;
}

/* Directional lights first, point lights after, each in their order (the
 * sums over lights are exact integers: the order changes no colour);
 * returns the number of directional ones. */
static unsigned directional_first(sl_light *pl, unsigned n)
{
    unsigned i, j, nd = 0;
    for (i = 0; i < n; i++) {
        sl_light l = pl[i];
        if (l.point)
            continue;
        for (j = i; j > nd; j--) /* shift the point lights before it up by one */
            pl[j] = pl[j - 1];
        pl[nd++] = l;
    }
    return nd;
}

/* What the vertex loop reads (light_loop). */
typedef struct {
    const sl_light *pl; /* directional lights first (directional_first), nd of nl */
    unsigned nd, nl, shininess;
    const int32_t *vm;
    const uint32_t *amb, *mtl;
    const uint8_t *vc;
    const int16_t *normals;
    const zl_fixed *positions;
    uint8_t *colors;
    uint32_t count;
} sl_pass;

/* Every vertex by the general equation; with_points a constant at each
 * call, so that directional-only lighting has no call in its loop. */
static ZL_ALWAYS_INLINE void light_loop(const sl_pass *p, int with_points)
{
    const sl_light *pl = p->pl;
    uint32_t v;
    unsigned i, k;
    for (v = 0; v < p->count; v++) {
        int32_t u[3];
        uint32_t d12[ZL_MAX_LIGHTS], s12[ZL_MAX_LIGHTS];
        const uint8_t *mat = p->vc != NULL ? &p->vc[v * 3u] : NULL;
        int lit = normal30(&p->normals[v * 3u], u);
        for (i = 0; i < p->nd; i++) {
            uint32_t d = lit ? cos30(u, pl[i].l) : 0;
            d12[i] = (d + (UINT32_C(1) << 17)) >> 18;
            s12[i] = 0;
            if (d != 0 && pl[i].spec)
                s12[i] = (pow30(cos30(u, pl[i].h), p->shininess) + (UINT32_C(1) << 17)) >> 18;
        }
        for (; with_points && i < p->nl; i++)
            light_factors(&pl[i], p->vm, &p->positions[v * 3u], u, lit, p->shininess, &d12[i], &s12[i]);
        for (k = 0; k < 3; k++) {
            uint32_t f = p->amb[k], cs = 0;
            for (i = 0; i < p->nl; i++) {
                f += pl[i].d[k] * d12[i]; /* below 5 * 255 * 2^12 < 2^23 */
                cs += pl[i].s[k] * s12[i];
            }
            p->colors[v * 3u + k] = light_channel(mat != NULL ? mat[k] : p->mtl[k], f, cs);
        }
    }
}

zl_status zl_light_vertices(const zl_lighting *lt, const zl_mat4 *model, const zl_mesh *mesh,
                            const int16_t *normals, uint8_t *colors)
{
    sl_light pl[ZL_MAX_LIGHTS];
    sl_pass pass;
    const uint8_t *vc;
    int32_t vm[3];
    uint32_t count, amb[3], mtl[3];
    unsigned i, nl, nd, shininess;
    int points = 0;
    if (lt == NULL || mesh == NULL)
        return ZL_ERR_ARG;
    if (lt->light_count > ZL_MAX_LIGHTS || lt->shininess > ZL_MAX_SHININESS)
        return ZL_ERR_RANGE;
    count = mesh->vertex_count;
    if (count != 0 && (normals == NULL || colors == NULL))
        return ZL_ERR_ARG;
    for (i = 0; i < lt->light_count; i++)
        points |= lt->lights[i].point != 0;
    if (points && count != 0 && mesh->positions == NULL)
        return ZL_ERR_ARG; /* a point light reads the positions */
    if (!prepare(lt, model, pl, vm))
        return ZL_ERR_RANGE;
    nl = lt->light_count;
    nd = directional_first(pl, nl);
    vc = mesh->vertex_colors;
    /* in locals: a store to colors (bytes) may alias *lt, which the loop
     * would otherwise read again after every one */
    amb[0] = lt->ambient.r * 4096u;
    amb[1] = lt->ambient.g * 4096u;
    amb[2] = lt->ambient.b * 4096u;
    mtl[0] = lt->material.r;
    mtl[1] = lt->material.g;
    mtl[2] = lt->material.b;
    shininess = lt->shininess;
    if (nl == 1 && !pl[0].spec && !pl[0].point) {
        light_one_diffuse(&pl[0], amb, mtl, vc, normals, colors, count);
        return ZL_OK;
    }
    pass.pl = pl;
    pass.nd = nd;
    pass.nl = nl;
    pass.shininess = shininess;
    pass.vm = vm;
    pass.amb = amb;
    pass.mtl = mtl;
    pass.vc = vc;
    pass.normals = normals;
    pass.positions = mesh->positions;
    pass.colors = colors;
    pass.count = count;
    if (nd == nl)
        light_loop(&pass, 0); /* no call in the loop: directional lights keep their registers */
    else
        light_loop(&pass, 1);
    return ZL_OK;
}

void zl_lighting_default(zl_lighting *lt)
{
    unsigned i;
    lt->ambient.r = lt->ambient.g = lt->ambient.b = 51;
    lt->material.r = lt->material.g = lt->material.b = 255;
    lt->light_count = 0;
    lt->shininess = 0;
    lt->viewer.x = 0;
    lt->viewer.y = 0;
    lt->viewer.z = ZL_FX_ONE;
    for (i = 0; i < ZL_MAX_LIGHTS; i++) {
        lt->lights[i].dir.x = 0;
        lt->lights[i].dir.y = 0;
        lt->lights[i].dir.z = ZL_FX_ONE;
        lt->lights[i].diffuse.r = lt->lights[i].diffuse.g = lt->lights[i].diffuse.b = 255;
        lt->lights[i].specular.r = lt->lights[i].specular.g = lt->lights[i].specular.b = 0;
        lt->lights[i].point = 0;
        lt->lights[i].position.x = lt->lights[i].position.y = lt->lights[i].position.z = 0;
    }
}
