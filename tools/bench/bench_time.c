/* SPDX-License-Identifier: MIT */
/*
 * zline-bench-time: wall-clock milliseconds per frame of the benchmark scene
 * (bench_scene.h: the bunny at 320x240, RGB565) on the host, in the three
 * ways a user draws it:
 *   frame + vertex cache  zl_draw_mesh with ctx.vertex_cache set (the
 *                         headline configuration of the Cortex-M tables)
 *   frame, default call   zl_draw_mesh as zl_init leaves the context
 *   scanline              zl_frame_render with one-row bands, RAM as small
 *                         as the scene allows (zl_frame_needs)
 * Each frame includes its clear. Every frame is timed on its own
 * (CLOCK_MONOTONIC) after a warm-up, the modes taking turns in rounds; the
 * table gives the median, which a few preempted frames do not move, and
 * the fastest frame.
 *
 *   zline-bench-time MODEL [FRAMES]        FRAMES defaults to 2001
 *
 * The three images are compared byte for byte with each other before
 * timing: a benchmark of a path that draws something else measures nothing.
 * Exit status: 0, or 1 when an image differs, 2 on bad arguments or input.
 * Times depend on the machine and its load; docs/MEASUREMENTS.md quotes them with the
 * machine they were measured on, never as a budget.
 */
#define _POSIX_C_SOURCE 199309L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench_scene.h"

#define WARMUP_FRAMES 50

static uint16_t color[BENCH_W * BENCH_H], depth[BENCH_W * BENCH_H];
static uint16_t reference[BENCH_W * BENCH_H];
static const zl_rgb background = {20, 24, 32};

typedef struct {
    zl_mesh mesh;
    zl_mat4 mvp;
    zl_state state;
    void *vertex_cache; /* NULL: the default call */
    size_t vertex_cache_bytes;
    void *work; /* scanline mode's work buffer */
    size_t work_bytes;
    zl_frame_config config;
} scene;

static void draw_frame(const scene *s)
{
    zl_context ctx;
    bench_scene_context(&ctx, color, depth, &s->state);
    ctx.vertex_cache = s->vertex_cache;
    ctx.vertex_cache_bytes = s->vertex_cache_bytes;
    if (zl_draw_mesh(&ctx, &s->mesh, &s->mvp) != ZL_OK)
        exit(2);
}

static int copy_row(void *user, const zl_band *b)
{
    (void)user;
    memcpy(&color[(size_t)b->first_row * BENCH_W], b->color, BENCH_W * 2);
    return 0;
}

static void draw_scanline(const scene *s)
{
    zl_frame f;
    if (zl_frame_begin(&f, &s->config, s->work, s->work_bytes, background, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &s->mesh, &s->mvp, &s->state) != ZL_OK || zl_frame_render(&f, copy_row, NULL) != 0)
        exit(2);
}

/* Size scanline mode's work buffer from what the scene needs. */
static void *scanline_setup(scene *s)
{
    zl_frame f;
    zl_band b;
    zl_frame_needs_t needs;
    memset(&s->config, 0, sizeof s->config);
    s->config.width = BENCH_W;
    s->config.height = BENCH_H;
    s->config.band_rows = 1;
    s->config.format = ZL_FORMAT_RGB565;
    s->config.color_buffers = 1;
    s->config.max_meshes = 1;
    s->config.max_vertices = s->mesh.vertex_count;
    s->config.max_triangles = s->mesh.triangle_count;
    s->config.max_active = (uint32_t)s->mesh.triangle_count * 7u;
    s->work_bytes = zl_frame_bytes(&s->config);
    s->work = malloc(s->work_bytes);
    if (s->work == NULL || zl_frame_begin(&f, &s->config, s->work, s->work_bytes, background, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &s->mesh, &s->mvp, &s->state) != ZL_OK || zl_frame_next_band(&f, &b) != ZL_OK)
        return NULL;
    needs = zl_frame_needs(&f);
    free(s->work);
    s->config.max_triangles = needs.triangles;
    s->config.max_active = needs.active;
    s->work_bytes = zl_frame_bytes(&s->config);
    s->work = malloc(s->work_bytes);
    return s->work;
}

static double now_ms(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

typedef void (*draw_fn)(const scene *);
/* Frame times of every mode, interleaved: ROUND_FRAMES frames of each mode
 * in turn until each has `frames`, so a slow spell of the machine (another
 * process, a virtual machine's neighbour) falls on every mode alike. */
#define ROUND_FRAMES 25
static void time_modes(const draw_fn *draws, const scene *s, unsigned modes, double **ms, int frames)
{
    int done = 0, i;
    unsigned m;
    for (m = 0; m < modes; m++)
        for (i = 0; i < WARMUP_FRAMES; i++)
            draws[m](&s[m]);
    while (done < frames) {
        int n = frames - done < ROUND_FRAMES ? frames - done : ROUND_FRAMES;
        for (m = 0; m < modes; m++)
            for (i = 0; i < n; i++) {
                double t0 = now_ms();
                draws[m](&s[m]);
                ms[m][done + i] = now_ms() - t0;
            }
        done += n;
    }
}

int main(int argc, char **argv)
{
    static const char *names[] = {"frame + vertex cache", "frame, default call (no caller cache)",
                                  "scanline (one-row bands)"};
    static const draw_fn draws[] = {draw_frame, draw_frame, draw_scanline};
    zl_obj obj;
    scene s[3];
    double *ms[3];
    int frames = argc == 3 ? atoi(argv[2]) : 2001, failed = 0;
    unsigned m;
    if (argc < 2 || argc > 3 || frames < 1 || frames > 1000000) {
        fprintf(stderr, "usage: %s MODEL [FRAMES 1..1000000]\n", argv[0]);
        return 2;
    }
    if (bench_scene_load(argv[1], &obj, &s[0].mesh, &s[0].mvp, &s[0].state) != 0)
        return 2;
    s[0].vertex_cache_bytes = ZL_VERTEX_CACHE_BYTES(s[0].mesh.vertex_count);
    s[0].vertex_cache = malloc(s[0].vertex_cache_bytes) /* malloc aligns for any type */;
    s[1] = s[0];
    s[1].vertex_cache = NULL;
    s[1].vertex_cache_bytes = 0;
    s[2] = s[1];
    for (m = 0; m < 3; m++)
        ms[m] = malloc((size_t)frames * sizeof *ms[m]);
    if (s[0].vertex_cache == NULL || ms[0] == NULL || ms[1] == NULL || ms[2] == NULL || scanline_setup(&s[2]) == NULL)
        return 2;
    for (m = 0; m < 3; m++) {
        draws[m](&s[m]);
        if (m == 0)
            memcpy(reference, color, sizeof color);
        else if (memcmp(reference, color, sizeof color) != 0) {
            fprintf(stderr, "%s: the image differs from frame mode's\n", names[m]);
            failed = 1;
        }
    }
    printf("| mode | median ms/frame | fastest ms/frame |\n|---|---:|---:|\n");
    time_modes(draws, s, 3, ms, frames);
    for (m = 0; m < 3; m++) {
        qsort(ms[m], (size_t)frames, sizeof *ms[m], by_value);
        printf("| %s | %.4f | %.4f |\n", names[m], ms[m][frames / 2], ms[m][0]);
    }
    printf("\n%d frames per mode after %d warm-up frames, in rounds of %d a mode, %dx%d RGB565.\n", frames,
           WARMUP_FRAMES, ROUND_FRAMES, BENCH_W, BENCH_H);
    for (m = 0; m < 3; m++)
        free(ms[m]);
    free(s[0].vertex_cache);
    free(s[2].work);
    zl_obj_free(&obj);
    return failed;
}
