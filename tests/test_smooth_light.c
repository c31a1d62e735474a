/* SPDX-License-Identifier: MIT */
/*
 * Smooth (per-vertex) lighting, zl_light_vertices, against an independent
 * double-precision model of the SMOOTH LIGHTING equation of zline.h: the
 * model matrix inverted by Gaussian elimination, unit vectors by a Newton
 * square root, the power by repeated multiplication (no libm, so the test
 * also runs under QEMU on cores without an FPU). Every channel must be
 * within 1 of the exact value (the header's bound); the worst error seen is
 * printed. Plus argument errors (nothing written), and a lit sphere drawn in
 * frame mode and in scanline and band mode, byte-identical.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

static uint32_t rng = 2024u;
static uint32_t next_rand(void)
{
    return zt_rand(&rng);
}
static int32_t rand_range(int32_t lo, int32_t hi) /* inclusive */
{
    return (int32_t)((uint32_t)lo + next_rand() % ((uint32_t)hi - (uint32_t)lo + 1u)); /* modulo 2^32 */
}

/* ---------------------------------------------------------------- model */

static double dabs(double x)
{
    return x < 0 ? -x : x;
}

static double dsqrt(double x)
{
    double r = x > 1 ? x : 1;
    int k;
    if (x <= 0)
        return 0;
    for (k = 0; k < 200; k++) {
        double n = 0.5 * (r + x / r);
        if (dabs(n - r) <= 1e-17 * n)
            break;
        r = n;
    }
    return r;
}

static int unit(double *v)
{
    double l = dsqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l == 0)
        return 0;
    v[0] /= l;
    v[1] /= l;
    v[2] /= l;
    return 1;
}

/* Inverse of a 3x3 by Gauss-Jordan with partial pivoting; 0 if singular. */
static int invert3(const double *a_in, double *inv)
{
    double a[9];
    int r, c, k;
    memcpy(a, a_in, sizeof a);
    for (k = 0; k < 9; k++)
        inv[k] = (k % 4 == 0) ? 1.0 : 0.0;
    for (c = 0; c < 3; c++) {
        int p = c;
        for (r = c + 1; r < 3; r++)
            if (dabs(a[r * 3 + c]) > dabs(a[p * 3 + c]))
                p = r;
        if (a[p * 3 + c] == 0)
            return 0;
        for (k = 0; k < 3; k++) {
            double t = a[c * 3 + k];
            a[c * 3 + k] = a[p * 3 + k];
            a[p * 3 + k] = t;
            t = inv[c * 3 + k];
            inv[c * 3 + k] = inv[p * 3 + k];
            inv[p * 3 + k] = t;
        }
        {
            double d = a[c * 3 + c];
            for (k = 0; k < 3; k++) {
                a[c * 3 + k] /= d;
                inv[c * 3 + k] /= d;
            }
        }
        for (r = 0; r < 3; r++) {
            double f;
            if (r == c)
                continue;
            f = a[r * 3 + c];
            for (k = 0; k < 3; k++) {
                a[r * 3 + k] -= f * a[c * 3 + k];
                inv[r * 3 + k] -= f * inv[c * 3 + k];
            }
        }
    }
    return 1;
}

static void mul3(const double *m, const double *v, double *out)
{
    int r;
    for (r = 0; r < 3; r++)
        out[r] = m[r * 3] * v[0] + m[r * 3 + 1] * v[1] + m[r * 3 + 2] * v[2];
}

static double ipow(double x, unsigned e)
{
    double r = 1;
    while (e--)
        r *= x;
    return r;
}

static double channel(const zl_rgb *c, int k)
{
    return k == 0 ? c->r : k == 1 ? c->g : c->b;
}

/* The exact colour of one vertex (before rounding, after the clamp at
 * 255); *ill set when a d_i is so close to 0 that the specular cut-off is
 * ill-conditioned (the test skips those). */
static void model_color(const zl_lighting *lt, const zl_mat4 *model, const int16_t *n, const zl_fixed *pos,
                        const uint8_t *mat, double out[3], int *ill)
{
    double m3[9], inv[9], nn[3], view[3], vm[3];
    double d[ZL_MAX_LIGHTS], s[ZL_MAX_LIGHTS];
    unsigned i;
    int k, lit;
    for (k = 0; k < 9; k++)
        m3[k] = model ? model->m[(k / 3) * 4 + k % 3] / 65536.0 : (k % 4 == 0 ? 1.0 : 0.0);
    TEST_ASSERT_TRUE(invert3(m3, inv));
    nn[0] = n[0];
    nn[1] = n[1];
    nn[2] = n[2];
    lit = unit(nn);
    view[0] = lt->viewer.x;
    view[1] = lt->viewer.y;
    view[2] = lt->viewer.z;
    unit(view);
    *ill = 0;
    for (i = 0; i < lt->light_count; i++) {
        const zl_light *L = &lt->lights[i];
        double l[3] = {0, 0, 0}, lm[3], h[3], hm[3];
        if (L->point) { /* P = M^-1 (q - t) in model space, lm = unit(P - pos) */
            double q[3];
            q[0] = L->position.x / 65536.0 - (model ? model->m[3] / 65536.0 : 0);
            q[1] = L->position.y / 65536.0 - (model ? model->m[7] / 65536.0 : 0);
            q[2] = L->position.z / 65536.0 - (model ? model->m[11] / 65536.0 : 0);
            mul3(inv, q, lm);
            for (k = 0; k < 3; k++)
                lm[k] -= pos[k] / 65536.0;
            if (dsqrt(lm[0] * lm[0] + lm[1] * lm[1] + lm[2] * lm[2]) < 1.0 / 64)
                *ill = 1; /* at the light: its direction is ill-conditioned */
            unit(lm);
        } else {
            l[0] = L->dir.x;
            l[1] = L->dir.y;
            l[2] = L->dir.z;
            unit(l);
            mul3(inv, l, lm);
            unit(lm);
        }
        d[i] = lit ? nn[0] * lm[0] + nn[1] * lm[1] + nn[2] * lm[2] : 0;
        if (dabs(d[i]) < 1e-6 && lit)
            *ill = 1;
        if (d[i] < 0)
            d[i] = 0;
        s[i] = 0;
        if (d[i] > 0 && (L->specular.r | L->specular.g | L->specular.b) != 0) {
            double x;
            if (L->point) { /* in model space: unit(lm + unit(M^-1 v)) */
                mul3(inv, view, vm);
                unit(vm);
                for (k = 0; k < 3; k++)
                    hm[k] = lm[k] + vm[k];
                if (!unit(hm))
                    continue;
            } else {
                for (k = 0; k < 3; k++)
                    h[k] = l[k] + view[k];
                if (!unit(h))
                    continue;
                mul3(inv, h, hm);
                unit(hm);
            }
            x = nn[0] * hm[0] + nn[1] * hm[1] + nn[2] * hm[2];
            s[i] = ipow(x < 0 ? 0 : x, lt->shininess);
        }
    }
    for (k = 0; k < 3; k++) {
        double m = mat ? mat[k] : channel(&lt->material, k);
        double f = channel(&lt->ambient, k), c;
        for (i = 0; i < lt->light_count; i++)
            f += channel(&lt->lights[i].diffuse, k) * d[i];
        c = m * f / 255.0;
        for (i = 0; i < lt->light_count; i++)
            c += channel(&lt->lights[i].specular, k) * s[i];
        out[k] = c > 255 ? 255 : c;
    }
}

/* ---------------------------------------------------------------- tests */

enum { NV = 400 };
static int16_t normals[NV * 3];
static uint8_t vcolors[NV * 3];
static uint8_t out[NV * 3 + 16];
static zl_fixed positions[NV * 3];

static zl_rgb rand_rgb(void)
{
    zl_rgb c;
    c.r = (uint8_t)next_rand();
    c.g = (uint8_t)next_rand();
    c.b = (uint8_t)next_rand();
    return c;
}

static void random_normal(int16_t *n)
{
    int k;
    switch (rand_range(0, 4)) {
    case 0: /* tiny */
        for (k = 0; k < 3; k++)
            n[k] = (int16_t)rand_range(-2, 2);
        break;
    case 1: /* extremes */
        for (k = 0; k < 3; k++)
            n[k] = (int16_t)(rand_range(0, 2) == 0 ? -32768 : rand_range(-32767, 32767));
        break;
    default: { /* about unit length in Q14, as the tools write them */
        double v[3];
        do {
            for (k = 0; k < 3; k++)
                v[k] = rand_range(-10000, 10000) / 10000.0;
        } while (!unit(v));
        for (k = 0; k < 3; k++)
            n[k] = (int16_t)(v[k] * 16384.0 + (v[k] < 0 ? -0.5 : 0.5));
    }
    }
}

static zl_vec3 rand_dir(void)
{
    zl_vec3 d;
    do {
        int big = rand_range(0, 3) == 0;
        d.x = big ? rand_range(-2000000000, 2000000000) : rand_range(-70000, 70000);
        d.y = big ? rand_range(-2000000000, 2000000000) : rand_range(-70000, 70000);
        d.z = big ? rand_range(-2000000000, 2000000000) : rand_range(-70000, 70000);
    } while (d.x == 0 && d.y == 0 && d.z == 0);
    return d;
}

static void random_matrix(zl_mat4 *m)
{
    zl_mat4 r, t;
    int k;
    switch (rand_range(0, 2)) {
    case 0: { /* rotation x uniform scale: OpenGL's case */
        zl_fixed s = rand_range(ZL_FX_ONE / 8, 8 * ZL_FX_ONE);
        zl_vec3 sv;
        sv.x = sv.y = sv.z = s;
        zl_mat4_rotate_x(&r, rand_range(0, 65535));
        zl_mat4_rotate_y(&t, rand_range(0, 65535));
        zl_mat4_mul(m, &r, &t);
        zl_mat4_rotate_z(&t, rand_range(0, 65535));
        zl_mat4_mul(&r, m, &t);
        zl_mat4_scale(&t, sv);
        zl_mat4_mul(m, &r, &t);
        break;
    }
    case 1: /* any well-conditioned matrix */
        for (;;) {
            double a[9], inv[9];
            zl_mat4_identity(m);
            for (k = 0; k < 9; k++) {
                m->m[(k / 3) * 4 + k % 3] = rand_range(-4 * ZL_FX_ONE, 4 * ZL_FX_ONE);
                a[k] = m->m[(k / 3) * 4 + k % 3] / 65536.0;
            }
            if (invert3(a, inv)) {
                double big = 0;
                for (k = 0; k < 9; k++)
                    big = dabs(inv[k]) > big ? dabs(inv[k]) : big;
                if (big < 4)
                    break;
            }
        }
        break;
    default: /* a view-like matrix with translation */
        zl_mat4_rotate_y(&r, rand_range(0, 65535));
        zl_mat4_identity(&t);
        t.m[3] = rand_range(-ZL_FX_ONE * 100, ZL_FX_ONE * 100);
        t.m[11] = rand_range(-ZL_FX_ONE * 100, ZL_FX_ONE * 100);
        zl_mat4_mul(m, &t, &r);
        break;
    }
}

static void test_matches_the_exact_equation(void)
{
    static const uint8_t shin[] = {0, 1, 2, 3, 5, 8, 16, 31, 64, 100, 128};
    double worst = 0;
    long checked = 0, skipped = 0;
    int round_no;
    char msg[160];
    for (round_no = 0; round_no < 120; round_no++) {
        zl_lighting lt;
        zl_mat4 model;
        zl_mesh mesh;
        int use_model = rand_range(0, 4) != 0, with_colors = rand_range(0, 1);
        unsigned i;
        int v, k;
        zl_lighting_default(&lt);
        lt.ambient = rand_rgb();
        lt.material = rand_rgb();
        lt.light_count = (uint8_t)rand_range(0, ZL_MAX_LIGHTS);
        lt.shininess = shin[rand_range(0, (int32_t)sizeof shin - 1)];
        lt.viewer = rand_dir();
        for (i = 0; i < lt.light_count; i++) {
            lt.lights[i].dir = rand_dir();
            if (rand_range(0, 2) == 0) { /* a point light, within 8 units */
                lt.lights[i].point = 1;
                lt.lights[i].position.x = rand_range(-8 * ZL_FX_ONE, 8 * ZL_FX_ONE);
                lt.lights[i].position.y = rand_range(-8 * ZL_FX_ONE, 8 * ZL_FX_ONE);
                lt.lights[i].position.z = rand_range(-8 * ZL_FX_ONE, 8 * ZL_FX_ONE);
            }
            lt.lights[i].diffuse = rand_rgb();
            if (rand_range(0, 2) != 0)
                lt.lights[i].specular = rand_rgb();
            if (rand_range(0, 3) == 0) { /* dim lights: no clamping at 255 */
                lt.lights[i].diffuse.r /= 4;
                lt.lights[i].diffuse.g /= 4;
                lt.lights[i].diffuse.b /= 4;
                lt.lights[i].specular.r /= 4;
                lt.lights[i].specular.g /= 4;
                lt.lights[i].specular.b /= 4;
                lt.ambient.r /= 4;
            }
        }
        random_matrix(&model);
        for (v = 0; v < NV * 3; v++)
            vcolors[v] = (uint8_t)next_rand();
        for (v = 0; v < NV; v++)
            random_normal(&normals[v * 3]);
        for (v = 0; v < NV * 3; v++) /* read by point lights only */
            positions[v] = rand_range(-2 * ZL_FX_ONE, 2 * ZL_FX_ONE);
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = positions;
        mesh.vertex_count = NV;
        mesh.vertex_colors = with_colors ? vcolors : NULL;
        memset(out, 0xA5, sizeof out);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_light_vertices(&lt, use_model ? &model : NULL, &mesh, normals, out));
        for (k = NV * 3; k < (int)sizeof out; k++)
            TEST_ASSERT_EQUAL_HEX8(0xA5, out[k]);
        for (v = 0; v < NV; v++) {
            double ref[3];
            int ill;
            model_color(&lt, use_model ? &model : NULL, &normals[v * 3], &positions[v * 3],
                        with_colors ? &vcolors[v * 3] : NULL, ref, &ill);
            if (ill) {
                skipped++;
                continue;
            }
            for (k = 0; k < 3; k++) {
                double e = dabs(out[v * 3 + k] - ref[k]);
                if (e > worst)
                    worst = e;
                if (e >= 1.0) {
                    snprintf(msg, sizeof msg, "round %d vertex %d channel %d: %u, exact %.4f (e=%u)", round_no, v,
                             k, out[v * 3 + k], ref[k], lt.shininess);
                    TEST_FAIL_MESSAGE(msg);
                    return;
                }
            }
            checked++;
        }
    }
    snprintf(msg, sizeof msg, "%ld vertices checked (%ld at a specular cut-off skipped), worst error %.4f", checked,
             skipped, worst);
    TEST_MESSAGE(msg);
    TEST_ASSERT_TRUE(checked > 40000);
}

static void test_zero_normal_and_no_lights_give_ambient(void)
{
    zl_lighting lt;
    zl_mesh mesh;
    int16_t n[6] = {0, 0, 0, 0, 0, 16384};
    uint8_t c[6];
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = positions;
    mesh.vertex_count = 2;
    zl_lighting_default(&lt);
    lt.material.r = 200;
    lt.material.g = 100;
    lt.material.b = 0;
    lt.ambient.r = 51;
    lt.ambient.g = 255;
    lt.ambient.b = 255;
    lt.light_count = 1; /* along +z, white */
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_light_vertices(&lt, NULL, &mesh, n, c));
    TEST_ASSERT_EQUAL_UINT8(40, c[0]); /* 200 * 51 / 255 */
    TEST_ASSERT_EQUAL_UINT8(100, c[1]);
    TEST_ASSERT_EQUAL_UINT8(0, c[2]);
    TEST_ASSERT_EQUAL_UINT8(240, c[3]); /* 200 * (51 + 255) / 255, facing the light */
    TEST_ASSERT_EQUAL_UINT8(200, c[4]);
    TEST_ASSERT_EQUAL_UINT8(0, c[5]);
}

static void test_errors_write_nothing(void)
{
    zl_lighting lt;
    zl_mesh mesh;
    zl_mat4 sing;
    int16_t n[3] = {0, 0, 16384};
    uint8_t c[3] = {7, 7, 7};
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = positions;
    mesh.vertex_count = 1;
    zl_lighting_default(&lt);
    lt.light_count = 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_vertices(NULL, NULL, &mesh, n, c));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_vertices(&lt, NULL, NULL, n, c));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_vertices(&lt, NULL, &mesh, NULL, c));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_vertices(&lt, NULL, &mesh, n, NULL));
    lt.light_count = ZL_MAX_LIGHTS + 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_light_vertices(&lt, NULL, &mesh, n, c));
    lt.light_count = 1;
    lt.shininess = ZL_MAX_SHININESS + 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_light_vertices(&lt, NULL, &mesh, n, c));
    lt.shininess = 10;
    lt.lights[0].dir.z = 0;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_light_vertices(&lt, NULL, &mesh, n, c));
    lt.lights[0].dir.z = ZL_FX_ONE;
    lt.lights[0].specular.g = 1;
    lt.viewer.z = 0;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_light_vertices(&lt, NULL, &mesh, n, c));
    lt.viewer.z = ZL_FX_ONE;
    zl_mat4_identity(&sing);
    sing.m[5] = 0; /* rank 2 */
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_light_vertices(&lt, &sing, &mesh, n, c));
    TEST_ASSERT_EQUAL_UINT8(7, c[0]);
    TEST_ASSERT_EQUAL_UINT8(7, c[1]);
    TEST_ASSERT_EQUAL_UINT8(7, c[2]);
    /* a point light reads the positions: none is an argument error */
    lt.lights[0].point = 1;
    mesh.positions = NULL;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_vertices(&lt, NULL, &mesh, n, c));
    TEST_ASSERT_EQUAL_UINT8(7, c[0]);
    mesh.positions = positions;
    lt.lights[0].point = 0;
    /* a light straight behind the viewer: no half vector, no specular, no error */
    lt.lights[0].dir.z = -ZL_FX_ONE;
    n[2] = -16384;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_light_vertices(&lt, NULL, &mesh, n, c));
    TEST_ASSERT_EQUAL_UINT8(255, c[0]); /* ambient 51 + diffuse 255, white: clamped */
}

/* A lit sphere drawn in frame mode and in scanline / band mode. */
enum { W = 64, H = 56, SEG = 10, RINGS = 7, SV = SEG * (RINGS + 1), ST = SEG * RINGS * 2 };
static zl_fixed sp_pos[SV * 3];
static int16_t sp_nrm[SV * 3];
static uint16_t sp_idx[ST * 3];
static uint8_t sp_lit[SV * 3];
static uint16_t fb_color[W * H], fb_depth[W * H];
static uint64_t work[96 * 1024 / 8];

typedef struct {
    int mismatches;
} cmp_ctx;

static int compare_band(void *user, const zl_band *b)
{
    cmp_ctx *cc = (cmp_ctx *)user;
    int r;
    for (r = 0; r < b->rows; r++) {
        const uint8_t *row = (const uint8_t *)b->color + r * b->color_stride;
        if (memcmp(row, &fb_color[(b->first_row + r) * W], W * 2) != 0)
            cc->mismatches++;
    }
    return 0;
}

static void test_lit_sphere_identical_in_frame_and_scanline_mode(void)
{
    static const uint16_t bands[] = {1, 3, H};
    zl_lighting lt;
    zl_mesh mesh;
    zl_mat4 proj, view, rot, mv, mvp;
    zl_vec3 eye = {0, 0, 3 * ZL_FX_ONE}, at = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    zl_context ctx;
    zl_target tg;
    zl_state st;
    zl_rgb bg = {10, 20, 30};
    int r, s, t = 0;
    unsigned b;
    for (r = 0; r <= RINGS; r++)
        for (s = 0; s < SEG; s++) {
            int v = r * SEG + s;
            zl_angle th = (zl_angle)(r * 32768 / RINGS), ph = (zl_angle)(s * 65536 / SEG);
            zl_fixed x = zl_fx_mul(zl_sin(th), zl_cos(ph)), y = zl_cos(th), z = zl_fx_mul(zl_sin(th), zl_sin(ph));
            sp_pos[v * 3] = x;
            sp_pos[v * 3 + 1] = y;
            sp_pos[v * 3 + 2] = z;
            sp_nrm[v * 3] = (int16_t)(x / 4);
            sp_nrm[v * 3 + 1] = (int16_t)(y / 4);
            sp_nrm[v * 3 + 2] = (int16_t)(z / 4);
        }
    for (r = 0; r < RINGS; r++)
        for (s = 0; s < SEG; s++) {
            uint16_t a = (uint16_t)(r * SEG + s), c = (uint16_t)(r * SEG + (s + 1) % SEG);
            uint16_t a2 = (uint16_t)(a + SEG), c2 = (uint16_t)(c + SEG);
            sp_idx[t++] = a;
            sp_idx[t++] = a2;
            sp_idx[t++] = c;
            sp_idx[t++] = c;
            sp_idx[t++] = a2;
            sp_idx[t++] = c2;
        }
    TEST_ASSERT_EQUAL_INT(ST * 3, t);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, 8192, ZL_FX_ONE * W / H, ZL_FX_ONE / 4, 20 * ZL_FX_ONE));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, at, up));
    zl_mat4_rotate_y(&rot, 5000);
    zl_mat4_mul(&mv, &view, &rot);
    zl_mat4_mul(&mvp, &proj, &mv);
    memset(&mesh, 0, sizeof mesh);
    mesh.positions = sp_pos;
    mesh.indices = sp_idx;
    mesh.vertex_count = SV;
    mesh.triangle_count = ST;
    zl_lighting_default(&lt);
    lt.material.r = 230;
    lt.material.g = 120;
    lt.material.b = 60;
    lt.light_count = 2;
    lt.shininess = 24;
    lt.lights[0].dir.x = ZL_FX_ONE;
    lt.lights[0].dir.y = ZL_FX_ONE;
    lt.lights[0].specular.r = lt.lights[0].specular.g = lt.lights[0].specular.b = 200;
    lt.lights[1].dir.x = -ZL_FX_ONE;
    lt.lights[1].diffuse.r = 40;
    lt.lights[1].diffuse.g = 40;
    lt.lights[1].diffuse.b = 120;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_light_vertices(&lt, &mv, &mesh, sp_nrm, sp_lit));
    mesh.vertex_colors = sp_lit;

    zt_target_packed(&tg, fb_color, fb_depth, W, H, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &tg));
    ctx.state.shading = ZL_SHADE_GOURAUD;
    ctx.state.cull = ZL_CULL_BACK;
    st = ctx.state;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, &mvp));
    for (b = 0; b < sizeof bands / sizeof bands[0]; b++) {
        zl_frame_config cfg;
        zl_frame f;
        cmp_ctx cc = {0};
        zt_frame_config_of(&cfg, W, H, bands[b], ZL_FORMAT_RGB565);
        zt_frame_capacity(&cfg, 1, SV, ST, ST);
        cfg.gouraud = 1;
        TEST_ASSERT_TRUE(zl_frame_bytes(&cfg) <= sizeof work);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(&f, &mesh, &mvp, &st));
        TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, compare_band, &cc));
        TEST_ASSERT_EQUAL_INT(0, cc.mismatches);
    }
    /* and it is lit: the sphere's pixels are not all one colour */
    {
        int k, differ = 0;
        for (k = 1; k < W * H; k++)
            differ += fb_color[k] != fb_color[k - 1] && fb_depth[k] != 65535 && fb_depth[k - 1] != 65535;
        TEST_ASSERT_TRUE(differ > 100);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_matches_the_exact_equation);
    RUN_TEST(test_zero_normal_and_no_lights_give_ambient);
    RUN_TEST(test_errors_write_nothing);
    RUN_TEST(test_lit_sphere_identical_in_frame_and_scanline_mode);
    return UNITY_END();
}
