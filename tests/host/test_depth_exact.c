/* SPDX-License-Identifier: MIT */
/*
 * The exact depth mapping (zline.h, Pseudodepth; zl_state near_z, far_z):
 * every vertex's window depth against the exact pseudodepth
 *     65535 (A + B / d),  A = f / (f - n),  B = -f n / (f - n)
 * of the Q16.16 near n and far f and the exact eye distance d of the Q16.16
 * vertex and camera, computed here independently of the core: d from the
 * look-at matrix's third row and the vertex in 64-bit integers (an exact
 * multiple of 2^-32), the formula in long double (64-bit mantissa: its
 * error is below 10^-12 step here).
 *
 * On the benchmark scene (the bunny, zline-render's default camera) the
 * per-vertex error and the mean signed error (the bias) are printed and
 * bounded; the old mapping (z_clip / w_clip, near_z = far_z = 0) is
 * measured too, and must show the bias of the issue, so the reference is
 * seen to detect it. Then random cameras and vertices, through both the
 * vertex cache (scanline and frame modes) and the clipping path, which must
 * agree bit for bit.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "../../core/src/1_base/zl_internal.h"
#include "unity.h"
#include "zl_obj.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

static uint64_t rng = 0x2545F4914F6CDD1Dull;

static uint32_t rnd32(void)
{
    return zt_rand64(&rng);
}

/* Uniform in [lo, hi] (raw Q16.16). */
static int32_t rnd_range(int32_t lo, int32_t hi)
{
    return zt_rand64_range(&rng, lo, hi);
}

/* Exact eye distance of p, in 2^-32 units: minus the view's third row. */
static int64_t eye_distance_q32(const zl_mat4 *view, const zl_fixed *p)
{
    return -((int64_t)view->m[8] * p[0] + (int64_t)view->m[9] * p[1] + (int64_t)view->m[10] * p[2] +
             (int64_t)view->m[11] * 65536);
}

/* 65535 (A + B/d) in steps, from the raw Q16.16 n and f and d in 2^-32 units. */
static long double exact_depth(int32_t n, int32_t f, int64_t dq)
{
    long double d = (long double)dq / 4294967296.0L, nn = n / 65536.0L, ff = f / 65536.0L;
    long double v = 65535.0L * ff * (d - nn) / ((ff - nn) * d);
    return v < 0 ? 0 : (v > 65535.0L ? 65535.0L : v);
}

typedef struct {
    zl_mat4 view, mvp;
    zl_state state;
    int32_t n, f;
} camera;

static void make_camera(camera *c, zl_vec3 eye, zl_vec3 target, zl_fixed fov_deg, uint16_t w, uint16_t h,
                        int32_t n, int32_t f)
{
    zl_mat4 proj;
    zl_vec3 up = {0, ZL_FX_ONE, 0};
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_look_at(&c->view, eye, target, up));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_mat4_perspective(&proj, zl_angle_from_deg(fov_deg),
                                                     (zl_fixed)(((int64_t)w * 65536 + h / 2) / h), n, f));
    zl_mat4_mul(&c->mvp, &proj, &c->view);
    zl_state_default(&c->state);
    c->state.near_z = n;
    c->state.far_z = f;
    c->n = n;
    c->f = f;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_state_check(&c->state));
}

typedef struct {
    unsigned count;
    double max_abs, sum, sum_stored, max_stored;
} stats;

/*
 * Vertex i of mesh through the cache and through the clipping path; adds its
 * error to st. Returns 0 when the vertex is outside the view volume.
 */
static int check_vertex(const camera *c, const zl_mesh *mesh, uint16_t i, uint16_t w, uint16_t h, stats *st)
{
    zl_source s;
    zl_cached_vertex cv;
    zl_cvert v;
    zl_wvert pv;
    long double want;
    double err, err_stored;
    memset(&s, 0, sizeof s);
    s.mesh = mesh;
    s.mvp = &c->mvp;
    s.state = &c->state;
    s.width = w;
    s.height = h;
    TEST_ASSERT_TRUE(zl_vertex_clip(&s, i, &v));
    if (zl_outcode(&s, &v) != 0)
        return 0;
    zl_project(&s, &v, &pv);
    cv = zl_cache_vertex(&s, i);
    if (cv.x != ZL_CACHE_COMPLEX) /* else only the clipping path draws it */
        TEST_ASSERT_EQUAL_UINT32(pv.z, cv.z);
    want = exact_depth(c->n, c->f, eye_distance_q32(&c->view, &mesh->positions[i * 3u]));
    err = (double)((long double)pv.z / 65536.0L - want);
    err_stored = (double)((long double)((pv.z + 32768u) >> 16) - want);
    st->count++;
    st->sum += err;
    st->sum_stored += err_stored;
    if (fabs(err) > st->max_abs)
        st->max_abs = fabs(err);
    if (fabs(err_stored) > st->max_stored)
        st->max_stored = fabs(err_stored);
    return 1;
}

/* The benchmark scene: the bunny as zline-render draws it by default. */
static void test_benchmark_scene_unbiased(void)
{
    zl_obj obj;
    zl_obj_options opt;
    zl_mesh mesh;
    camera c;
    stats now, old;
    char msg[256];
    zl_vec3 eye = {0, 0, ZL_FX_ONE * 7 / 2}, target = {0, 0, 0};
    uint32_t i;
    zl_obj_options_default(&opt);
    opt.normalize = 1; /* as zline-render and the benchmark: largest extent 2, centred */
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_OBJ_OK,
                                  zl_obj_load_file(&obj, ZLINE_SOURCE_DIR "/port/host/models/bunny.obj", &opt,
                                                   msg, sizeof msg),
                                  msg);
    mesh = zl_obj_mesh(&obj);
    /* near 0.1 and far 100 as zline-render rounds them */
    make_camera(&c, eye, target, ZL_FX_INT(60), 320, 240, 6554, ZL_FX_INT(100));
    memset(&now, 0, sizeof now);
    memset(&old, 0, sizeof old);
    for (i = 0; i < mesh.vertex_count; i++)
        check_vertex(&c, &mesh, (uint16_t)i, 320, 240, &now);
    c.state.near_z = c.state.far_z = 0; /* the old mapping: z_clip / w_clip */
    for (i = 0; i < mesh.vertex_count; i++)
        check_vertex(&c, &mesh, (uint16_t)i, 320, 240, &old);
    printf("benchmark scene, %u vertices, error in steps against 65535 (A + B/d):\n", now.count);
    printf("  exact mapping:   max |error| %.6f, mean %+.6f; stored (rounded) max %.4f, mean %+.4f\n",
           now.max_abs, now.sum / now.count, now.max_stored, now.sum_stored / now.count);
    printf("  z_clip / w_clip: max |error| %.6f, mean %+.6f; stored (rounded) max %.4f, mean %+.4f\n",
           old.max_abs, old.sum / old.count, old.max_stored, old.sum_stored / old.count);
    TEST_ASSERT_TRUE(now.count > 1000);
    TEST_ASSERT_TRUE(now.max_abs < 0.001);
    TEST_ASSERT_TRUE(now.max_stored <= 0.501);
    TEST_ASSERT_TRUE(fabs(now.sum / now.count) < 0.02);
    TEST_ASSERT_TRUE(fabs(now.sum_stored / now.count) < 0.02);
    /* the reference sees the old mapping's bias (issue #14: about +0.1) */
    TEST_ASSERT_TRUE(old.sum / old.count > 0.05);
    zl_obj_free(&obj);
}

/*
 * Random cameras (near 1/64 .. 4, far 2 near .. 32767) and random vertices
 * in front of them, many close to the near plane where the depth is
 * steepest; both paths, error within 1/1000 step.
 */
static void test_random_cameras_exact(void)
{
    stats st;
    unsigned k, j;
    zl_fixed pos[3 * 64];
    uint16_t idx[3] = {0, 1, 2};
    memset(&st, 0, sizeof st);
    for (k = 0; k < 300u; k++) {
        camera c;
        zl_mesh mesh;
        zl_vec3 eye, target;
        int32_t n = rnd_range(ZL_FX_ONE / 64, 4 * ZL_FX_ONE);
        int32_t f = rnd_range(2 * n, (k & 1) ? 32767 * ZL_FX_ONE : 40 * n);
        if (f > 32767 * ZL_FX_ONE)
            f = 32767 * ZL_FX_ONE;
        eye.x = rnd_range(-ZL_FX_INT(50), ZL_FX_INT(50));
        eye.y = rnd_range(-ZL_FX_INT(50), ZL_FX_INT(50));
        eye.z = rnd_range(-ZL_FX_INT(50), ZL_FX_INT(50));
        target.x = eye.x + rnd_range(-ZL_FX_INT(40), ZL_FX_INT(40));
        target.y = eye.y + rnd_range(-ZL_FX_INT(40), ZL_FX_INT(40));
        target.z = eye.z + rnd_range(-ZL_FX_INT(40), ZL_FX_INT(40)) + ZL_FX_INT(1);
        make_camera(&c, eye, target, rnd_range(ZL_FX_INT(20), ZL_FX_INT(120)), 320, 240, n, f);
        /* points along the view direction (the look-at's -third row) */
        for (j = 0; j < 64u; j++) {
            int64_t d = j < 16u ? (int64_t)n + rnd_range(0, n / 8 + 1)              /* near the near plane */
                                : (int64_t)n + (int64_t)(rnd32() % (uint32_t)(f - n)); /* anywhere */
            int a;
            if (j >= 16u && d > ZL_FX_INT(200))
                d = ZL_FX_INT(200) + d % ZL_FX_INT(100); /* positions stay within +-16384 */
            for (a = 0; a < 3; a++) {
                int64_t p = (&eye.x)[a] - ((int64_t)c.view.m[8 + a] * d >> 16) +
                            rnd_range(-ZL_FX_ONE / 64, ZL_FX_ONE / 64);
                pos[j * 3u + (unsigned)a] = (zl_fixed)p;
            }
        }
        memset(&mesh, 0, sizeof mesh);
        mesh.positions = pos;
        mesh.indices = idx;
        mesh.vertex_count = 64;
        mesh.triangle_count = 1;
        for (j = 0; j < 64u; j++)
            check_vertex(&c, &mesh, (uint16_t)j, 320, 240, &st);
    }
    printf("random cameras, %u vertices inside: max |error| %.6f step, mean %+.6f\n", st.count, st.max_abs,
           st.sum / st.count);
    TEST_ASSERT_TRUE(st.count > 5000);
    TEST_ASSERT_TRUE(st.max_abs < 0.001);
    TEST_ASSERT_TRUE(st.max_stored <= 0.501);
}

/* Both 0 or 0 < near < far; anything else is ZL_ERR_RANGE. */
static void test_state_check(void)
{
    zl_state s;
    zl_state_default(&s);
    TEST_ASSERT_EQUAL_INT(0, s.near_z);
    TEST_ASSERT_EQUAL_INT(0, s.far_z);
    s.near_z = ZL_FX_ONE;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_state_check(&s));
    s.far_z = ZL_FX_ONE;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_state_check(&s));
    s.far_z = ZL_FX_ONE + 1;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_state_check(&s));
    s.near_z = 0;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_state_check(&s));
    s.near_z = -1;
    TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_state_check(&s));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_state_check);
    RUN_TEST(test_benchmark_scene_unbiased);
    RUN_TEST(test_random_cameras_exact);
    return UNITY_END();
}
