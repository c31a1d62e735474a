/* SPDX-License-Identifier: MIT */
/*
 * Two cores, one frame (zl_frame_split) on two POSIX threads: every random
 * scene of test_frame_modes.c (plain and styled, every band height), split
 * at a random row, must equal frame mode's image byte for byte (the
 * reference of that test: zl_draw_mesh into a whole target, an independent
 * path), and the benchmark bunny split at the balanced row and at others
 * must equal both frame mode and one thread's bands. Built once more with
 * ThreadSanitizer (tests/host/CMakeLists.txt: test_frame_dual_tsan): the
 * threads share the mesh records and the vertex cache read-only and nothing
 * else.
 */
#define _POSIX_C_SOURCE 200112L /* pthread_barrier_t */
#define ZT_FRAME_DUAL 1
#include "../test_frame_modes.c"

#include <pthread.h>
#include <stdio.h>

#include "../../tools/bench/bench_scene.h"

static uint64_t second_work[(512 * 1024) / 8];
static uint32_t split_rng = 777u;

typedef struct {
    zl_frame frame;
    zl_band_fn fn;
    void *user;
    pthread_barrier_t *prepared;
    int result;
} part_job;

/* zline.h's protocol: prepare, the barrier, the bands. */
static int prepare_and_render(zl_frame *f, pthread_barrier_t *prepared, zl_band_fn fn, void *user)
{
    zl_status st = zl_frame_prepare(f);
    pthread_barrier_wait(prepared);
    return st != ZL_OK ? st : zl_frame_render(f, fn, user);
}

static void *render_part(void *arg)
{
    part_job *job = arg;
    job->result = prepare_and_render(&job->frame, job->prepared, job->fn, job->user);
    return NULL;
}

/* Split f at `row` (0: zl_frame_split's balanced row), the second part on a
 * thread of its own, the first on this one. */
static int render_split(zl_frame *f, uint16_t row, zl_band_fn fn, void *user_first, void *user_second)
{
    part_job job;
    pthread_t t;
    pthread_barrier_t prepared;
    int first;
    size_t bytes = zl_frame_part_bytes(&f->cfg);
    TEST_ASSERT_TRUE(bytes > 0 && bytes <= sizeof second_work);
    TEST_ASSERT_EQUAL_INT(ZL_ERR_SIZE, zl_frame_split(f, &job.frame, second_work, bytes - 1, row));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_split(f, &job.frame, second_work, bytes, row));
    if (f->end_row < f->cfg.height) /* split: refused a second time */
        TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_split(f, &job.frame, second_work, bytes, row));
    TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_next_band(&job.frame, &(zl_band){0})); /* not prepared */
    TEST_ASSERT_EQUAL_INT(0, pthread_barrier_init(&prepared, NULL, 2));
    job.fn = fn;
    job.user = user_second;
    job.prepared = &prepared;
    job.result = -1;
    TEST_ASSERT_EQUAL_INT(0, pthread_create(&t, NULL, render_part, &job)); /* a full barrier */
    first = prepare_and_render(f, &prepared, fn, user_first);
    TEST_ASSERT_EQUAL_INT(0, pthread_join(t, NULL));
    pthread_barrier_destroy(&prepared);
    return first | job.result;
}

int zt_dual_render(zl_frame *f, zl_band_fn fn, void *user_first, void *user_second)
{
    uint16_t row = (uint16_t)zt_rand_range(&split_rng, 0, f->cfg.height);
    return render_split(f, row, fn, user_first, user_second);
}

/* ---------------------------------------------------------------- bunny */

static uint16_t ref_color[BENCH_W * BENCH_H], ref_depth[BENCH_W * BENCH_H];
static uint16_t one_color[BENCH_W * BENCH_H], one_depth[BENCH_W * BENCH_H];
static uint16_t two_color[BENCH_W * BENCH_H], two_depth[BENCH_W * BENCH_H];
static uint64_t bunny_work[(1024 * 1024) / 8], bunny_second[(1024 * 1024) / 8];

/* Each thread copies its bands to their rows: disjoint rows, no race. */
static int copy_rows(void *user, const zl_band *b)
{
    int *rows = user;
    zt_frame_copy dst;
    dst.color = two_color;
    dst.depth = two_depth;
    zt_band_copy(&dst, b);
    *rows += b->rows;
    return 0;
}

static void bunny_frame(zl_frame *f, const zl_frame_config *cfg, const zl_mesh *mesh, const zl_mat4 *mvp,
                        const zl_state *st, void *work_buf, size_t bytes)
{
    zl_rgb bg = {20, 24, 32};
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_begin(f, cfg, work_buf, bytes, bg, 65535));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_add_mesh(f, mesh, mvp, st));
}

static void test_bunny_two_threads_equal_one(void)
{
    static const uint16_t bands[] = {1, 8, BENCH_H};
    static const uint16_t rows[] = {0, 1, 60, 121, 200, BENCH_H};
    zl_obj obj;
    zl_mesh mesh;
    zl_mat4 mvp;
    zl_state st;
    zl_context ctx;
    unsigned b, r;
    long drawn = 0;
    if (bench_scene_load(ZLINE_SOURCE_DIR "/port/host/models/bunny.obj", &obj, &mesh, &mvp, &st) != 0)
        TEST_FAIL_MESSAGE("cannot load port/host/models/bunny.obj");
    bench_scene_context(&ctx, ref_color, ref_depth, &st);
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&ctx, &mesh, &mvp));
    for (r = 0; r < BENCH_W * BENCH_H; r++)
        drawn += ref_depth[r] != 65535;
    TEST_ASSERT_GREATER_THAN(BENCH_W * BENCH_H / 10, drawn);
    for (b = 0; b < sizeof bands / sizeof bands[0]; b++) {
        zl_frame_config cfg;
        zl_frame f, second;
        zl_band band;
        zt_frame_copy one;
        size_t bytes;
        zt_frame_config_of(&cfg, BENCH_W, BENCH_H, bands[b], ZL_FORMAT_RGB565);
        cfg.parts = (uint8_t)(b != 1 ? 2 : 0);
        zt_frame_capacity(&cfg, 1, mesh.vertex_count, mesh.triangle_count, 512);
        bytes = zl_frame_bytes(&cfg);
        TEST_ASSERT_TRUE(bytes > 0 && bytes <= sizeof bunny_work);
        one.color = one_color;
        one.depth = one_depth;
        bunny_frame(&f, &cfg, &mesh, &mvp, &st, bunny_work, bytes);
        TEST_ASSERT_EQUAL_INT(0, zl_frame_render(&f, zt_band_copy_fn, &one));
        TEST_ASSERT_EQUAL_MEMORY(ref_color, one_color, sizeof ref_color);
        TEST_ASSERT_EQUAL_MEMORY(ref_depth, one_depth, sizeof ref_depth);
        /* the balanced row lies well inside the bunny's rows */
        bunny_frame(&f, &cfg, &mesh, &mvp, &st, bunny_work, bytes);
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_split(&f, &second, bunny_second, sizeof bunny_second, 0));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_prepare(&f));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_ARG, zl_frame_prepare(&f)); /* once */
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_prepare(&second));
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_frame_next_band(&second, &band)); /* resolves the row */
        if (bands[b] < BENCH_H / 4) /* else the row rounds down to a band's edge */
            TEST_ASSERT_TRUE(band.first_row > BENCH_H / 4 && band.first_row < BENCH_H * 3 / 4);
        for (r = 0; r < sizeof rows / sizeof rows[0]; r++) {
            int seen_first = 0, seen_second = 0;
            memset(two_color, 0, sizeof two_color);
            memset(two_depth, 0, sizeof two_depth);
            bunny_frame(&f, &cfg, &mesh, &mvp, &st, bunny_work, bytes);
            TEST_ASSERT_EQUAL_INT(0, render_split(&f, rows[r], copy_rows, &seen_first, &seen_second));
            TEST_ASSERT_EQUAL_INT(BENCH_H, seen_first + seen_second);
            TEST_ASSERT_EQUAL_MEMORY(one_color, two_color, sizeof one_color);
            TEST_ASSERT_EQUAL_MEMORY(one_depth, two_depth, sizeof one_depth);
        }
    }
    zl_obj_free(&obj);
}

void zt_dual_tests(void)
{
    RUN_TEST(test_bunny_two_threads_equal_one);
}
