/* SPDX-License-Identifier: MIT */
/*
 * Golden scenes, host equals target: the same source renders the scenes of
 * scenes.h in frame mode (zl_draw_mesh into a full target) and in scanline
 * and band mode (zl_frame_next_band, 1 and 7 rows), and writes each image as
 * a file PREFIX-SCENE-MODE.bin: the colour buffer (RGB565, native order:
 * both sides are little-endian) followed by the 16-bit depth buffer. On
 * Cortex-M the files reach the host through semihosting (newlib's fopen and
 * fwrite, port/cortex-m/syscalls.c); the host build of this file writes the
 * same names with another prefix, and compare.cmake checks they are byte for
 * byte the same. Each file's FNV-1a hash is printed too.
 *
 * PREFIX is GOLDEN_PREFIX: "target" in the Cortex-M build, "host" in bench/host.
 * Exit status: the number of scenes that failed to render.
 */
#include <stdio.h>
#include <string.h>

#include "scenes.h"

#ifndef GOLDEN_PREFIX
#define GOLDEN_PREFIX "golden"
#endif

#define W SCENE_W
#define H SCENE_H

/* colour then depth of one whole frame, and the scanline work buffer */
static uint16_t image[2 * W * H];
static uint64_t work[160 * 1024 / 8];

static uint32_t fnv1a(const void *p, size_t n)
{
    const uint8_t *b = (const uint8_t *)p;
    uint32_t h = 2166136261u;
    while (n--)
        h = (h ^ *b++) * 16777619u;
    return h;
}

static int save(const char *prefix, const char *scene_name, const char *mode)
{
    char path[128];
    FILE *f;
    size_t n = sizeof image;
    int ok;
    snprintf(path, sizeof path, "%s-%s-%s.bin", prefix, scene_name, mode);
    f = fopen(path, "wb");
    if (f == NULL) {
        printf("golden: cannot write %s\n", path);
        return 1;
    }
    ok = fwrite(image, 1, n, f) == n;
    ok = (fclose(f) == 0) && ok;
    printf("%s %08lx\n", path, (unsigned long)fnv1a(image, n));
    return !ok;
}

static int render_frame(const scene *s)
{
    unsigned k;
    zl_context ctx;
    zl_target t;
    zl_rgb bg = {20, 24, 32};
    memset(&t, 0, sizeof t);
    t.color = image;
    t.color_stride = W * 2;
    t.depth = image + W * H;
    t.depth_stride = W * 2;
    t.width = W;
    t.height = H;
    t.format = ZL_FORMAT_RGB565;
    if (zl_init(&ctx, &t) != ZL_OK)
        return 1;
    ctx.state = s->state;
    if (zl_clear(&ctx, bg, 65535) != ZL_OK)
        return 1;
    if (s->styled)
        ctx.style = s->style;
    if (zl_draw_mesh(&ctx, &s->mesh, &s->mvp) != ZL_OK)
        return 1;
    for (k = 0; k < s->extra_count; k++) {
        ctx.state = s->extra_state[k];
        ctx.style = s->extra_style[k];
        if (zl_draw_mesh(&ctx, &s->extra_mesh[k], &s->extra_mvp[k]) != ZL_OK)
            return 1;
    }
    return 0;
}

/* Submit a scene's meshes to a frame. */
static zl_status add_scene(zl_frame *f, const scene *s)
{
    zl_status st;
    unsigned k;
    if (!s->styled)
        return zl_frame_add_mesh(f, &s->mesh, &s->mvp, &s->state);
    st = zl_frame_add_mesh_styled(f, &s->mesh, &s->mvp, &s->state, &s->style);
    for (k = 0; k < s->extra_count && st == ZL_OK; k++)
        st = zl_frame_add_mesh_styled(f, &s->extra_mesh[k], &s->extra_mvp[k], &s->extra_state[k], &s->extra_style[k]);
    return st;
}

/* Scanline/band configuration for a scene, capacities exactly what it needs
 * (zl_frame_needs after a first planning with generous ones). */
static int config_for(const scene *s, uint16_t band_rows, zl_frame_config *cfg)
{
    unsigned k;
    zl_frame f;
    zl_band b;
    zl_frame_needs_t needs;
    zl_rgb bg = {0, 0, 0};
    zl_status st;
    memset(cfg, 0, sizeof *cfg);
    cfg->width = W;
    cfg->height = H;
    cfg->band_rows = band_rows;
    cfg->format = ZL_FORMAT_RGB565;
    cfg->color_buffers = 1;
    cfg->gouraud = s->gouraud;
    cfg->max_meshes = (uint16_t)(1u + s->extra_count);
    cfg->max_vertices = s->mesh.vertex_count;
    cfg->max_triangles = s->mesh.triangle_count;
    for (k = 0; k < s->extra_count; k++) {
        cfg->max_vertices += s->extra_mesh[k].vertex_count;
        cfg->max_triangles += s->extra_mesh[k].triangle_count;
    }
    cfg->max_active = 512;
    cfg->styled = s->styled;
    cfg->textured = s->styled;
    if (zl_frame_bytes(cfg) > sizeof work || zl_frame_begin(&f, cfg, work, sizeof work, bg, 65535) != ZL_OK ||
        add_scene(&f, s) != ZL_OK)
        return 1;
    st = zl_frame_next_band(&f, &b); /* plans the frame */
    if (st != ZL_OK && st != ZL_DONE && st != ZL_ERR_CAPACITY)
        return 1;
    needs = zl_frame_needs(&f);
    cfg->max_triangles = needs.triangles > 0 ? needs.triangles : 1;
    cfg->max_active = needs.active > 0 ? needs.active : 1;
    return 0;
}

static int render_bands(const scene *s, uint16_t band_rows)
{
    zl_frame_config cfg;
    zl_frame f;
    zl_band b;
    zl_status st;
    zl_rgb bg = {20, 24, 32};
    if (config_for(s, band_rows, &cfg) != 0) {
        printf("golden: %s: cannot plan the frame\n", s->name);
        return 1;
    }
    if (zl_frame_begin(&f, &cfg, work, zl_frame_bytes(&cfg), bg, 65535) != ZL_OK || add_scene(&f, s) != ZL_OK)
        return 1;
    while ((st = zl_frame_next_band(&f, &b)) == ZL_OK) {
        uint16_t r;
        for (r = 0; r < b.rows; r++) {
            memcpy(image + (size_t)(b.first_row + r) * W,
                   (const uint8_t *)b.color + (size_t)r * (size_t)b.color_stride, W * 2);
            memcpy(image + W * H + (size_t)(b.first_row + r) * W,
                   (const uint8_t *)b.depth + (size_t)r * (size_t)b.depth_stride, W * 2);
        }
    }
    return st != ZL_DONE;
}

int main(void)
{
    const char *prefix = GOLDEN_PREFIX; /* the port's start-up passes no arguments */
    int which, failed = 0;
    for (which = 0; which < SCENE_COUNT; which++) {
        scene s;
        if (scene_make(&s, which) != 0) {
            printf("golden: scene %d: cannot build the camera\n", which);
            failed++;
            continue;
        }
        memset(image, 0, sizeof image);
        if (render_frame(&s) || save(prefix, s.name, "frame")) {
            printf("golden: %s frame mode failed\n", s.name);
            failed++;
        }
        memset(image, 0, sizeof image);
        if (render_bands(&s, 1) || save(prefix, s.name, "scanline")) {
            printf("golden: %s scanline mode failed\n", s.name);
            failed++;
        }
        if (which == SCENE_BUNNY || which == SCENE_TETRA || which == SCENE_BUNNY_SMOOTH || which == SCENE_TEXTURED ||
            which == SCENE_BUNNY_GOURAUD) {
            memset(image, 0, sizeof image);
            if (render_bands(&s, 7) || save(prefix, s.name, "band7")) {
                printf("golden: %s band mode failed\n", s.name);
                failed++;
            }
        }
    }
    return failed;
}
