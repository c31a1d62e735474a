/* SPDX-License-Identifier: MIT */
/*
 * zline-bench-time: wall-clock milliseconds per frame of the benchmark scene
 * (bench_scene.h: the bunny at 320x240, RGB565) on the host, shaded three
 * ways (as port/cortex-m/bench/scenes.c shades them, issue 21):
 *   bunny                 one lit flat colour per triangle
 *   bunny_gouraud         a colour per vertex (from its position), Gouraud
 *   bunny_smooth          zl_light_vertices per frame (ambient + one
 *                         directional light, area-weighted vertex normals
 *                         of zl_obj_compute_normals), Gouraud
 * each in the three ways a user draws it:
 *   frame + vertex cache  zl_draw_mesh with ctx.vertex_cache set (the
 *                         headline configuration of the Cortex-M tables)
 *   frame, default call   zl_draw_mesh as zl_init leaves the context
 *   scanline              zl_frame_render with one-row bands, RAM as small
 *                         as the scene allows (zl_frame_needs)
 *   scanline, 2 threads   the same frame split across two POSIX threads
 *                         (zl_frame_split, cfg.parts = 2): this thread and a
 *                         worker started once, meeting at barriers (start,
 *                         prepared, done) every frame
 * Each frame includes its clear. Every frame is timed on its own
 * (CLOCK_MONOTONIC) after a warm-up, the modes taking turns in rounds; the
 * table gives the median, which a few preempted frames do not move, and
 * the fastest frame.
 *
 *   zline-bench-time MODEL [FRAMES]        FRAMES defaults to 2001
 *
 * The three images of a scene are compared byte for byte with each other before
 * timing: a benchmark of a path that draws something else measures nothing.
 * Exit status: 0, or 1 when an image differs, 2 on bad arguments or input.
 * Times depend on the machine and its load; docs/MEASUREMENTS.md quotes them with the
 * machine they were measured on, never as a budget.
 */
#define _POSIX_C_SOURCE 200112L /* clock_gettime, pthread_barrier_t */
#include <pthread.h>
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
    void *work2; /* the second thread's (zl_frame_part_bytes) */
    size_t work2_bytes;
    zl_frame_config config;
    /* bunny_smooth: lit again every frame into lit (the mesh's colours) */
    const zl_lighting *lighting;
    const zl_mat4 *modelview;
    const int16_t *normals;
    uint8_t *lit;
} scene;

/* zl_light_vertices of a lit scene, as part of its frame. */
static void light(const scene *s)
{
    zl_mesh m;
    if (s->lighting == NULL)
        return;
    m = s->mesh;
    m.vertex_colors = NULL;
    if (zl_light_vertices(s->lighting, s->modelview, &m, s->normals, s->lit) != ZL_OK)
        exit(2);
}

static void draw_frame(const scene *s)
{
    zl_context ctx;
    light(s);
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
    light(s);
    if (zl_frame_begin(&f, &s->config, s->work, s->work_bytes, background, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &s->mesh, &s->mvp, &s->state) != ZL_OK || zl_frame_render(&f, copy_row, NULL) != 0)
        exit(2);
}

/* The two-thread frame: the worker renders `second` of each frame between
 * the barriers; `quit` (read after the start barrier) ends it. */
static pthread_barrier_t start_frame, prepared, frame_done;
static zl_frame second;
static int quit, worker_failed;

static void *worker(void *arg)
{
    (void)arg;
    for (;;) {
        int bad;
        pthread_barrier_wait(&start_frame);
        if (quit)
            return NULL;
        bad = zl_frame_prepare(&second) != ZL_OK;
        pthread_barrier_wait(&prepared);
        bad |= zl_frame_render(&second, copy_row, NULL) != 0;
        worker_failed |= bad;
        pthread_barrier_wait(&frame_done);
    }
}

static void draw_two_threads(const scene *s)
{
    zl_frame f;
    int bad;
    light(s);
    if (zl_frame_begin(&f, &s->config, s->work, s->work_bytes, background, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &s->mesh, &s->mvp, &s->state) != ZL_OK ||
        zl_frame_split(&f, &second, s->work2, s->work2_bytes, 0) != ZL_OK)
        exit(2);
    pthread_barrier_wait(&start_frame);
    bad = zl_frame_prepare(&f) != ZL_OK;
    pthread_barrier_wait(&prepared);
    bad |= zl_frame_render(&f, copy_row, NULL) != 0;
    pthread_barrier_wait(&frame_done);
    if (bad || worker_failed)
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
    s->config.gouraud = s->state.shading == ZL_SHADE_GOURAUD;
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

/* A colour channel from a model coordinate, as scenes.c's channel_of. */
static uint8_t channel_of(zl_fixed p)
{
    int32_t c = 40 + (int32_t)(((int32_t)p + ZL_FX_ONE) / 655);
    return (uint8_t)(c < 0 ? 0 : c > 255 ? 255 : c);
}

/* The shading of scene k (0 flat, 1 bunny_gouraud, 2 bunny_smooth) on the
 * loaded bunny: colours into `colors` (3 per vertex). */
static int shade(scene *s, int k, const zl_obj *obj, uint8_t *colors, zl_lighting *lt, zl_mat4 *view)
{
    uint32_t i;
    zl_mat4 proj;
    zl_vec3 eye = {0, 0, ZL_FX_ONE * 7 / 2}, target = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
    if (k == 0)
        return 0;
    s->state.light_on = 0;
    s->state.shading = ZL_SHADE_GOURAUD;
    s->mesh.vertex_colors = colors;
    if (k == 1) {
        for (i = 0; i < 3u * s->mesh.vertex_count; i++)
            colors[i] = channel_of(s->mesh.positions[i]);
        return 0;
    }
    if (zl_mat4_perspective(&proj, zl_angle_from_deg(ZL_FX_INT(60)), ZL_FX_INT(BENCH_W) / BENCH_H, ZL_FX_ONE / 10,
                            ZL_FX_INT(100)) != ZL_OK ||
        zl_mat4_look_at(view, eye, target, up) != ZL_OK)
        return 1;
    zl_lighting_default(lt);
    lt->ambient.r = lt->ambient.g = lt->ambient.b = 40;
    lt->material.r = 230;
    lt->material.g = 200;
    lt->material.b = 160;
    lt->light_count = 1;
    lt->lights[0].dir.x = ZL_FX_ONE * 3 / 8;
    lt->lights[0].dir.y = ZL_FX_HALF;
    lt->lights[0].dir.z = ZL_FX_ONE * 3 / 4;
    lt->lights[0].diffuse.r = lt->lights[0].diffuse.g = lt->lights[0].diffuse.b = 215;
    s->lighting = lt;
    s->modelview = view;
    s->normals = obj->normals;
    s->lit = colors;
    light(s);
    return 0;
}

/* The three modes of scene k: 0 when they draw the same image, timed. */
static int run_scene(const char *scene_name, const scene *base, int frames)
{
    static const char *names[] = {"frame + vertex cache", "frame, default call (no caller cache)",
                                  "scanline (one-row bands)", "scanline, 2 threads (zl_frame_split)"};
    static const draw_fn draws[] = {draw_frame, draw_frame, draw_scanline, draw_two_threads};
    scene s[4];
    double *ms[4];
    int failed = 0;
    unsigned m;
    s[0] = *base;
    s[0].vertex_cache_bytes = ZL_VERTEX_CACHE_BYTES(s[0].mesh.vertex_count);
    s[0].vertex_cache = malloc(s[0].vertex_cache_bytes) /* malloc aligns for any type */;
    s[1] = s[0];
    s[1].vertex_cache = NULL;
    s[1].vertex_cache_bytes = 0;
    s[2] = s[1];
    for (m = 0; m < 4; m++)
        ms[m] = malloc((size_t)frames * sizeof *ms[m]);
    if (s[0].vertex_cache == NULL || ms[0] == NULL || ms[1] == NULL || ms[2] == NULL || ms[3] == NULL ||
        scanline_setup(&s[2]) == NULL)
        exit(2);
    s[3] = s[2];
    s[3].config.parts = 2;
    s[3].work_bytes = zl_frame_bytes(&s[3].config);
    s[3].work = malloc(s[3].work_bytes);
    s[3].work2_bytes = zl_frame_part_bytes(&s[3].config);
    s[3].work2 = malloc(s[3].work2_bytes);
    if (s[3].work == NULL || s[3].work2 == NULL)
        exit(2);
    for (m = 0; m < 4; m++) {
        draws[m](&s[m]);
        if (m == 0)
            memcpy(reference, color, sizeof color);
        else if (memcmp(reference, color, sizeof color) != 0) {
            fprintf(stderr, "%s, %s: the image differs from frame mode's\n", scene_name, names[m]);
            failed = 1;
        }
    }
    time_modes(draws, s, 4, ms, frames);
    for (m = 0; m < 4; m++) {
        qsort(ms[m], (size_t)frames, sizeof *ms[m], by_value);
        printf("| %s | %s | %.4f | %.4f |\n", scene_name, names[m], ms[m][frames / 2], ms[m][0]);
        free(ms[m]);
    }
    free(s[0].vertex_cache);
    free(s[2].work);
    free(s[3].work);
    free(s[3].work2);
    return failed;
}

int main(int argc, char **argv)
{
    static const char *scene_names[] = {"bunny", "bunny_gouraud", "bunny_smooth"};
    zl_obj obj;
    scene base;
    zl_lighting lighting;
    zl_mat4 view;
    uint8_t *colors;
    pthread_t worker_thread;
    int frames = argc == 3 ? atoi(argv[2]) : 2001, failed = 0, k;
    if (argc < 2 || argc > 3 || frames < 1 || frames > 1000000) {
        fprintf(stderr, "usage: %s MODEL [FRAMES 1..1000000]\n", argv[0]);
        return 2;
    }
    memset(&base, 0, sizeof base);
    if (bench_scene_load(argv[1], &obj, &base.mesh, &base.mvp, &base.state) != 0)
        return 2;
    if (zl_obj_compute_normals(&obj, ZL_OBJ_NORMALS_AREA) != ZL_OBJ_OK)
        return 2;
    colors = malloc(3u * base.mesh.vertex_count + 1u);
    if (colors == NULL)
        return 2;
    if (pthread_barrier_init(&start_frame, NULL, 2) != 0 || pthread_barrier_init(&prepared, NULL, 2) != 0 ||
        pthread_barrier_init(&frame_done, NULL, 2) != 0 || pthread_create(&worker_thread, NULL, worker, NULL) != 0)
        return 2;
    printf("| scene | mode | median ms/frame | fastest ms/frame |\n|---|---|---:|---:|\n");
    for (k = 0; k < 3; k++) {
        scene s = base;
        if (shade(&s, k, &obj, colors, &lighting, &view) != 0)
            return 2;
        failed |= run_scene(scene_names[k], &s, frames);
    }
    quit = 1;
    pthread_barrier_wait(&start_frame);
    pthread_join(worker_thread, NULL);
    printf("\n%d frames per mode after %d warm-up frames, in rounds of %d a mode, %dx%d RGB565; bunny_smooth's "
           "frames include zl_light_vertices.\n",
           frames, WARMUP_FRAMES, ROUND_FRAMES, BENCH_W, BENCH_H);
    free(colors);
    zl_obj_free(&obj);
    return failed;
}
