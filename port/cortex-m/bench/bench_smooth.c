/* SPDX-License-Identifier: MIT */
/*
 * Smooth lighting on Cortex-M (issue 15): the lit-Gouraud bunny of scenes.h
 * (SCENE_BUNNY_SMOOTH: 1839 vertices, area-weighted normals, a key light
 * with Blinn-Phong specular and a fill light in eye space), counted as
 * bench.c counts (QEMU mps2, -icount shift=6, TIMER0):
 *   light     zl_light_vertices over every vertex of the mesh (the lights
 *             brought into model space once, then each vertex lit once)
 *   frame     light + zl_clear + zl_draw_mesh of the lit mesh, Gouraud,
 *             with the vertex cache (as the benchmark's bunny frame):
 *             320x240 RGB565 and 16-bit depth
 *   scanline  light + the zl_frame frame with one-row bands (begin, add,
 *             every band)
 *   draw      the frame without the lighting (zl_clear + zl_draw_mesh of
 *             the mesh with its per-vertex colours): "the bunny with
 *             per-vertex colours" of issue 13, against the flat bunny
 *             frame (bench.c's bunny_vcache); its own budget line
 * frame and scanline give the same image (their colour hashes are printed
 * and compared). Each count is checked against budgets.txt. Prints
 * "INTERVAL tag bunny_smooth key instructions from to" (from, to: its marks,
 * for profile.sh: TAGS=smooth-O2 SCENE=bunny_smooth KEY=draw).
 */
#include <stdio.h>
#include <string.h>

#include "bench_timer.h"
#include "budget.h"
#include "scenes.h"

#ifndef BENCH_TAG
#define BENCH_TAG "smooth"
#endif

#define W SCENE_W
#define H SCENE_H

static uint16_t color_buf[W * H];
static uint16_t depth_buf[W * H];
static uint32_t vcache_buf[3 * 2048]; /* ZL_VERTEX_CACHE_BYTES: 12 bytes a vertex */
static uint64_t work[96 * 1024 / 8];

static uint32_t fnv1a(const void *p, size_t n, uint32_t h)
{
    const uint8_t *b = (const uint8_t *)p;
    while (n--)
        h = (h ^ *b++) * 16777619u;
    return h;
}

/* The interval between marks m and m + 1, with its marks (for profile.sh). */
static int report(const char *key, unsigned m)
{
    uint32_t insns = bench_between(m, m + 1);
    printf("INTERVAL %s bunny_smooth %s %lu %u %u\n", BENCH_TAG, key, (unsigned long)insns, m, m + 1);
    return bench_check_budget(BENCH_TAG, BENCH_BUDGETS, key, insns);
}

/* zl_light_vertices of the scene again, into its own array. */
static zl_status light(const scene *s)
{
    zl_mesh m = s->mesh;
    m.vertex_colors = NULL;
    return zl_light_vertices(&s->lighting, &s->modelview, &m, s->normals, s->lit);
}

int main(void)
{
    scene s;
    zl_context ctx;
    zl_target tg;
    zl_frame_config cfg;
    zl_frame f;
    zl_band b;
    zl_status st;
    zl_rgb bg = {20, 24, 32};
    unsigned m;
    int failed = 0;
    uint32_t h_frame, h_scan = 2166136261u;
    if (bench_timer_init("bench_smooth") != 0)
        return 100;
    if (scene_make(&s, SCENE_BUNNY_SMOOTH) != 0 || ZL_VERTEX_CACHE_BYTES(s.mesh.vertex_count) > sizeof vcache_buf)
        return 101;

    /* lighting alone */
    m = bench_stamp_count();
    mark();
    st = light(&s);
    mark();
    if (st != ZL_OK)
        return 102;
    failed += report("light", m);

    /* frame mode: light + clear + draw */
    memset(&tg, 0, sizeof tg);
    tg.color = color_buf;
    tg.color_stride = W * 2;
    tg.depth = depth_buf;
    tg.depth_stride = W * 2;
    tg.width = W;
    tg.height = H;
    tg.format = ZL_FORMAT_RGB565;
    if (zl_init(&ctx, &tg) != ZL_OK)
        return 103;
    ctx.state = s.state;
    ctx.vertex_cache = vcache_buf;
    ctx.vertex_cache_bytes = sizeof vcache_buf;
    m = bench_stamp_count();
    mark();
    light(&s);
    zl_clear(&ctx, bg, 65535);
    st = zl_draw_mesh(&ctx, &s.mesh, &s.mvp);
    mark();
    if (st != ZL_OK)
        return 104;
    failed += report("frame", m);
    h_frame = fnv1a(color_buf, sizeof color_buf, 2166136261u);
    /* the frame without the lighting: the bunny with per-vertex colours */
    m = bench_stamp_count();
    mark();
    zl_clear(&ctx, bg, 65535);
    st = zl_draw_mesh(&ctx, &s.mesh, &s.mvp);
    mark();
    if (st != ZL_OK)
        return 108;
    failed += report("draw", m);

    /* scanline mode: light + the banded frame (capacities planned untimed) */
    memset(&cfg, 0, sizeof cfg);
    cfg.width = W;
    cfg.height = H;
    cfg.band_rows = 1;
    cfg.format = ZL_FORMAT_RGB565;
    cfg.color_buffers = 1;
    cfg.gouraud = 1;
    cfg.max_meshes = 1;
    cfg.max_vertices = s.mesh.vertex_count;
    cfg.max_triangles = s.mesh.triangle_count;
    cfg.max_active = 256;
    if (zl_frame_bytes(&cfg) > sizeof work || zl_frame_begin(&f, &cfg, work, sizeof work, bg, 65535) != ZL_OK ||
        zl_frame_add_mesh(&f, &s.mesh, &s.mvp, &s.state) != ZL_OK)
        return 105;
    st = zl_frame_next_band(&f, &b);
    if (st != ZL_OK && st != ZL_DONE)
        return 106;
    cfg.max_triangles = zl_frame_needs(&f).triangles;
    cfg.max_active = zl_frame_needs(&f).active;
    m = bench_stamp_count();
    mark();
    light(&s);
    zl_frame_begin(&f, &cfg, work, zl_frame_bytes(&cfg), bg, 65535);
    zl_frame_add_mesh(&f, &s.mesh, &s.mvp, &s.state);
    while ((st = zl_frame_next_band(&f, &b)) == ZL_OK)
        ;
    mark();
    if (st != ZL_DONE)
        return 107;
    failed += report("scanline", m);
    /* the same bands again, untimed, for the image hash */
    zl_frame_begin(&f, &cfg, work, zl_frame_bytes(&cfg), bg, 65535);
    zl_frame_add_mesh(&f, &s.mesh, &s.mvp, &s.state);
    while (zl_frame_next_band(&f, &b) == ZL_OK)
        h_scan = fnv1a(b.color, W * 2, h_scan);
    printf("RESULT %s bunny_smooth vertices %u triangles %u work_bytes %lu\n", BENCH_TAG,
           (unsigned)s.mesh.vertex_count, (unsigned)s.mesh.triangle_count, (unsigned long)zl_frame_bytes(&cfg));
    printf("RESULT %s bunny_smooth color_hash frame %08lx scanline %08lx\n", BENCH_TAG, (unsigned long)h_frame,
           (unsigned long)h_scan);
    if (h_frame != h_scan) {
        printf("bench_smooth: frame and scanline images differ\n");
        failed++;
    }
    return failed;
}
