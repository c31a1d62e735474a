/* SPDX-License-Identifier: MIT */
/*
 * zl_light_faces (zl_face_light.h): flat shading from a zl_lighting.
 *   - one equivalent light gives exactly the image of zl_state's light_dir
 *     (frames compared byte for byte, both windings, lights in model space
 *     and in world space under quarter-turn model matrices);
 *   - several coloured lights with specular, under rotated and uniformly
 *     scaled model matrices, against the FLAT LIGHTING equation evaluated
 *     here in double precision (within the integer rule's rounding);
 *   - bad arguments write nothing.
 */
#include <string.h>

#include "unity.h"
#include "zline/zline.h"
#include "zt_frame.h"
#include "zt_ref.h"
#include "zt_target.h"

void setUp(void) {}
void tearDown(void) {}

#if ZT_SMALL_RAM /* three frames of 24x20 fit the ATmega2560's 8 KB with the rest */
enum { W = 24, H = 20, NV = 30, NT = 10 };
#else
enum { W = 40, H = 32, NV = 30, NT = 10 };
#endif

static uint32_t rng = 4242u;
static zl_fixed positions[NV * 3];
static uint16_t indices[NT * 3];
static uint8_t face_colors[NT * 3], lit[NT * 3];
static zl_mesh mesh;

static double sqrt_d(double s) /* Newton from above; s >= 0 */
{
    double x = s > 1.0 ? s : 1.0;
    int i;
    if (s <= 0.0)
        return 0.0;
    for (i = 0; i < 200; i++) {
        double n = 0.5 * (x + s / x);
        if (!(n < x))
            break;
        x = n;
    }
    return x;
}

static void random_mesh(void)
{
    int i;
    for (i = 0; i < NV * 3; i++)
        positions[i] = zt_rand_range(&rng, -ZL_FX_INT(2), ZL_FX_INT(2));
    for (i = 0; i < NT * 3; i++) {
        indices[i] = (uint16_t)(i % NV);
        face_colors[i] = (uint8_t)zt_rand(&rng);
    }
    mesh.positions = positions;
    mesh.indices = indices;
    mesh.vertex_colors = NULL;
    mesh.face_colors = face_colors;
    mesh.vertex_count = NV;
    mesh.triangle_count = NT;
}

/* A random direction as a rounded Q16 unit vector (what light_dir holds). */
static zl_vec3 random_unit(void)
{
    double v[3], len;
    zl_vec3 u;
    do {
        v[0] = zt_rand_range(&rng, -1000, 1000);
        v[1] = zt_rand_range(&rng, -1000, 1000);
        v[2] = zt_rand_range(&rng, -1000, 1000);
        len = sqrt_d(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    } while (len < 10.0);
    u.x = (zl_fixed)(v[0] / len * 65536.0 + (v[0] < 0 ? -0.5 : 0.5));
    u.y = (zl_fixed)(v[1] / len * 65536.0 + (v[1] < 0 ? -0.5 : 0.5));
    u.z = (zl_fixed)(v[2] / len * 65536.0 + (v[2] < 0 ? -0.5 : 0.5));
    return u;
}

static zl_vec3 mat_dir(const zl_mat4 *m, zl_vec3 v) /* the 3x3 times v (exact for quarter turns) */
{
    zl_vec3 o;
    o.x = (zl_fixed)(((int64_t)m->m[0] * v.x + (int64_t)m->m[1] * v.y + (int64_t)m->m[2] * v.z) / 65536);
    o.y = (zl_fixed)(((int64_t)m->m[4] * v.x + (int64_t)m->m[5] * v.y + (int64_t)m->m[6] * v.z) / 65536);
    o.z = (zl_fixed)(((int64_t)m->m[8] * v.x + (int64_t)m->m[9] * v.y + (int64_t)m->m[10] * v.z) / 65536);
    return o;
}

static uint16_t frame_a[W * H] ZT_ALIGNED(2), frame_b[W * H] ZT_ALIGNED(2), depth[W * H] ZT_ALIGNED(2);

static void draw(uint16_t *color, const zl_mesh *m, const zl_mat4 *mvp, const zl_state *st)
{
    static zl_context ctx;
    zl_target t;
    zl_rgb bg = {0, 0, 0};
    zt_target_packed(&t, color, depth, W, H, ZL_FORMAT_RGB565);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&ctx, &t));
    ctx.state = *st;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&ctx, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, m, mvp));
}

static void test_one_light_equals_light_dir(void)
{
    int round;
    for (round = 0; round < 200; round++) {
        zl_mat4 proj, view, model, mvp;
        zl_vec3 eye = {0, 0, ZL_FX_INT(6)}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
        zl_state legacy, plain;
        zl_lighting lt;
        zl_mesh lit_mesh;
        uint8_t a = (uint8_t)zt_rand_range(&rng, 0, 255);
        int world = round % 2; /* lights in world space under a quarter-turn model matrix */
        random_mesh();
        zl_mat4_rotate_y(&model, (zl_angle)(ZL_ANGLE_TURN / 4 * zt_rand_range(&rng, 0, 3)));
        if (zt_rand_range(&rng, 0, 1)) {
            zl_mat4 rx;
            zl_mat4_rotate_x(&rx, (zl_angle)(ZL_ANGLE_TURN / 4 * zt_rand_range(&rng, 0, 3)));
            zl_mat4_mul(&model, &rx, &model);
        }
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(50)), ZL_FX_INT(W) / H,
                                                         ZL_FX_ONE / 4, ZL_FX_INT(40)));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&view, eye, target, up));
        zl_mat4_mul(&mvp, &proj, &view);
        zl_mat4_mul(&mvp, &mvp, &model);
        zl_state_default(&legacy);
        legacy.front_face = (uint8_t)zt_rand_range(&rng, 0, 1);
        legacy.cull = (uint8_t)zt_rand_range(&rng, 0, 2);
        legacy.light_on = 1;
        legacy.ambient = a;
        legacy.light_dir = random_unit();
        plain = legacy;
        plain.light_on = 0;
        zl_lighting_default(&lt);
        lt.ambient.r = lt.ambient.g = lt.ambient.b = a;
        lt.light_count = 1;
        lt.lights[0].dir = world ? mat_dir(&model, legacy.light_dir) : legacy.light_dir;
        lt.lights[0].diffuse.r = lt.lights[0].diffuse.g = lt.lights[0].diffuse.b = (uint8_t)(255 - a);
        lt.lights[0].specular.r = lt.lights[0].specular.g = lt.lights[0].specular.b = 0;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_light_faces(&lt, world ? &model : NULL, &mesh, legacy.front_face, lit));
        lit_mesh = mesh;
        lit_mesh.face_colors = lit;
        draw(frame_a, &mesh, &mvp, &legacy);
        draw(frame_b, &lit_mesh, &mvp, &plain);
        TEST_ASSERT_EQUAL_MEMORY(frame_a, frame_b, sizeof frame_a);
    }
}

/* The FLAT LIGHTING equation in double precision, for one triangle. */
static void reference(const zl_lighting *lt, const double rot[9], double scale, int cw, uint32_t t, double out[3])
{
    const zl_fixed *p0 = positions + indices[t * 3] * 3, *p1 = positions + indices[t * 3 + 1] * 3;
    const zl_fixed *p2 = positions + indices[t * 3 + 2] * 3;
    double e[6], n[3], len, A[3], S[3] = {0, 0, 0}, m[3];
    int k, i;
    for (k = 0; k < 3; k++) {
        e[k] = (double)(p1[k] - p0[k]);
        e[k + 3] = (double)(p2[k] - p0[k]);
    }
    n[0] = e[1] * e[5] - e[2] * e[4];
    n[1] = e[2] * e[3] - e[0] * e[5];
    n[2] = e[0] * e[4] - e[1] * e[3];
    len = sqrt_d(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    m[0] = face_colors[t * 3], m[1] = face_colors[t * 3 + 1], m[2] = face_colors[t * 3 + 2];
    A[0] = lt->ambient.r, A[1] = lt->ambient.g, A[2] = lt->ambient.b;
    for (i = 0; i < lt->light_count && len > 0; i++) {
        const zl_light *li = &lt->lights[i];
        double l[3] = {li->dir.x, li->dir.y, li->dir.z}, v[3] = {lt->viewer.x, lt->viewer.y, lt->viewer.z};
        double lm[3], h[3], hm[3], d = 0, s = 0, ll, lv, lh;
        ll = sqrt_d(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
        lv = sqrt_d(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (k = 0; k < 3; k++)
            h[k] = l[k] / ll + v[k] / lv;
        lh = sqrt_d(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
        for (k = 0; k < 3; k++) { /* model space: R^T (the scale does not turn a direction) */
            lm[k] = (rot[k] * l[0] + rot[3 + k] * l[1] + rot[6 + k] * l[2]) / ll;
            hm[k] = (rot[k] * h[0] + rot[3 + k] * h[1] + rot[6 + k] * h[2]) / lh;
        }
        if (li->point) { /* l = P - c, P = M^-1 q = R^T q / scale, c the centroid; h = unit(unit(l) + R^T v) */
            double q[3] = {li->position.x / 65536.0, li->position.y / 65536.0, li->position.z / 65536.0};
            for (k = 0; k < 3; k++)
                lm[k] = (rot[k] * q[0] + rot[3 + k] * q[1] + rot[6 + k] * q[2]) / scale -
                        ((double)p0[k] + p1[k] + p2[k]) / 3.0 / 65536.0;
            ll = sqrt_d(lm[0] * lm[0] + lm[1] * lm[1] + lm[2] * lm[2]);
            if (ll == 0)
                continue;
            for (k = 0; k < 3; k++) {
                lm[k] /= ll;
                hm[k] = lm[k] + (rot[k] * v[0] + rot[3 + k] * v[1] + rot[6 + k] * v[2]) / lv;
            }
            lh = sqrt_d(hm[0] * hm[0] + hm[1] * hm[1] + hm[2] * hm[2]);
            for (k = 0; k < 3; k++)
                hm[k] = lh > 0 ? hm[k] / lh : 0;
        }
        for (k = 0; k < 3; k++) {
            d += (cw ? -n[k] : n[k]) / len * lm[k];
            s += (cw ? -n[k] : n[k]) / len * hm[k];
        }
        if (d <= 0)
            continue;
        A[0] += li->diffuse.r * d, A[1] += li->diffuse.g * d, A[2] += li->diffuse.b * d;
        if (li->specular.r | li->specular.g | li->specular.b) {
            double p = 1; /* max(0, s)^e, 0^0 = 1 */
            for (k = 0; k < lt->shininess; k++)
                p *= s > 0 ? s : 0;
            S[0] += li->specular.r * p, S[1] += li->specular.g * p, S[2] += li->specular.b * p;
        }
    }
    for (k = 0; k < 3; k++) {
        double c = m[k] * A[k] / 255.0 + S[k];
        out[k] = c > 255.0 ? 255.0 : c;
    }
}

static void test_many_lights_against_the_equation(void)
{
    int round;
    for (round = 0; round < 300; round++) {
        zl_lighting lt;
        zl_mat4 rot, scale, model;
        zl_vec3 sv;
        double r[9];
        int i, k, cw = zt_rand_range(&rng, 0, 1);
        uint32_t t;
        zl_fixed s = (zl_fixed[]){ZL_FX_ONE / 2, ZL_FX_ONE, ZL_FX_INT(3)}[zt_rand_range(&rng, 0, 2)];
        random_mesh();
        zl_lighting_default(&lt);
        lt.ambient.r = (uint8_t)zt_rand_range(&rng, 0, 80);
        lt.ambient.g = (uint8_t)zt_rand_range(&rng, 0, 80);
        lt.ambient.b = (uint8_t)zt_rand_range(&rng, 0, 80);
        lt.light_count = (uint8_t)zt_rand_range(&rng, 0, ZL_MAX_LIGHTS);
        lt.shininess = (uint8_t)zt_rand_range(&rng, 0, 64);
        lt.viewer = random_unit();
        for (i = 0; i < lt.light_count; i++) {
            lt.lights[i].dir = random_unit();
            lt.lights[i].dir.x *= zt_rand_range(&rng, 1, 3); /* any length */
            lt.lights[i].diffuse.r = (uint8_t)zt_rand(&rng);
            lt.lights[i].diffuse.g = (uint8_t)zt_rand(&rng);
            lt.lights[i].diffuse.b = (uint8_t)zt_rand(&rng);
            lt.lights[i].specular.r = (uint8_t)(zt_rand(&rng) % 128);
            lt.lights[i].specular.g = (uint8_t)(zt_rand(&rng) % 128);
            lt.lights[i].specular.b = (uint8_t)(zt_rand(&rng) % 128);
            if (zt_rand_range(&rng, 0, 2) == 0) { /* a point light, world space, within 6 units */
                lt.lights[i].point = 1;
                lt.lights[i].position.x = zt_rand_range(&rng, -ZL_FX_INT(6), ZL_FX_INT(6));
                lt.lights[i].position.y = zt_rand_range(&rng, -ZL_FX_INT(6), ZL_FX_INT(6));
                lt.lights[i].position.z = zt_rand_range(&rng, -ZL_FX_INT(6), ZL_FX_INT(6));
            }
        }
        zl_mat4_rotate_y(&rot, (zl_angle)zt_rand_range(&rng, 0, ZL_ANGLE_TURN - 1));
        zl_mat4_rotate_x(&model, (zl_angle)zt_rand_range(&rng, 0, ZL_ANGLE_TURN - 1));
        zl_mat4_mul(&rot, &model, &rot);
        sv.x = sv.y = sv.z = s;
        zl_mat4_scale(&scale, sv);
        zl_mat4_mul(&model, &rot, &scale);
        for (i = 0; i < 3; i++)
            for (k = 0; k < 3; k++)
                r[i * 3 + k] = rot.m[i * 4 + k] / 65536.0;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_light_faces(&lt, &model, &mesh, (uint8_t)cw, lit));
        for (t = 0; t < NT; t++) {
            double want[3];
            reference(&lt, r, s / 65536.0, cw, t, want);
            for (k = 0; k < 3; k++) {
                double diff = lit[t * 3 + k] - want[k];
                TEST_ASSERT_TRUE_MESSAGE(diff < 3.5 && diff > -3.5, "a face colour is off the FLAT LIGHTING equation");
            }
        }
    }
}

static void test_bad_arguments_write_nothing(void)
{
    zl_lighting lt;
    zl_mat4 singular;
    zl_vec3 zero = {0, 0, 0};
    random_mesh();
    zl_lighting_default(&lt);
    lt.light_count = 1;
    memset(lit, 0xA5, sizeof lit);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_faces(NULL, NULL, &mesh, 0, lit));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_faces(&lt, NULL, NULL, 0, lit));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_faces(&lt, NULL, &mesh, 0, NULL));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_faces(&lt, NULL, &mesh, 2, lit));
    lt.light_count = ZL_MAX_LIGHTS + 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_light_faces(&lt, NULL, &mesh, 0, lit));
    lt.light_count = 1;
    lt.shininess = ZL_MAX_SHININESS + 1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_light_faces(&lt, NULL, &mesh, 0, lit));
    lt.shininess = 0;
    lt.lights[0].dir = zero;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_light_faces(&lt, NULL, &mesh, 0, lit));
    lt.lights[0].dir.z = ZL_FX_ONE;
    zl_mat4_scale(&singular, zero);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_light_faces(&lt, &singular, &mesh, 0, lit));
    indices[0] = NV;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_light_faces(&lt, NULL, &mesh, 0, lit));
    indices[0] = 0;
    {
        size_t i;
        for (i = 0; i < sizeof lit; i++)
            TEST_ASSERT_EQUAL_HEX8(0xA5, lit[i]);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_bad_arguments_write_nothing);
    RUN_TEST(test_one_light_equals_light_dir);
    RUN_TEST(test_many_lights_against_the_equation);
    return UNITY_END();
}
