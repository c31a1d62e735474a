/* SPDX-License-Identifier: MIT */
/*
 * The consumer tests' program: what a firmware would do with zline, checked
 * against a reference computed here, independently of the library.
 *
 * Scene, in pixel space (NULL matrix), 16 x 16 RGB565, scanline mode:
 *   a green square [6,10) x [6,10) at depth 0.25, submitted first,
 *   a red square   [4,12) x [4,12) at depth 0.5, behind it,
 * each square two triangles with corners on pixel corners, so no pixel
 * centre (x + 0.5, y + 0.5) lies on an outer edge: the covered pixels are
 * exactly the squares, whatever the fill rule does on the inner diagonal.
 * Expected, per pixel: green inside the small square (the depth test keeps
 * it in front of the red one drawn later), red in the rest of the large
 * one, the clear colour elsewhere.
 *
 * Prints "consumer: <how it was built>: N pixels wrong" and returns the
 * number of failures (0 = pass), on the host and on a Cortex-M under QEMU.
 */
#include <stdio.h>

#include "zline/zline.h"

#ifndef CONSUMER_HOW
#define CONSUMER_HOW "unnamed"
#endif

#define W 16
#define H 16

#define RGB565(r, g, b) ((uint16_t)((((r) >> 3) << 11) | (((g) >> 2) << 5) | ((b) >> 3)))

static const zl_rgb clear_rgb = {0, 0, 96};

#define P(x, y, z) ZL_FX_INT(x), ZL_FX_INT(y), (z)
static const zl_fixed positions[] = {
    P(6, 6, ZL_FX_ONE / 4), P(10, 6, ZL_FX_ONE / 4), P(10, 10, ZL_FX_ONE / 4), P(6, 10, ZL_FX_ONE / 4),
    P(4, 4, ZL_FX_ONE / 2), P(12, 4, ZL_FX_ONE / 2), P(12, 12, ZL_FX_ONE / 2), P(4, 12, ZL_FX_ONE / 2),
};
/* Both windings per square: culling is off by default, but the test does
 * not depend on it. */
static const uint16_t indices[] = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
static const uint8_t face_colors[] = {0, 255, 0, 0, 255, 0, 255, 0, 0, 255, 0, 0};

static uint16_t expected_pixel(int x, int y)
{
    if (x >= 6 && x < 10 && y >= 6 && y < 10)
        return RGB565(0, 255, 0);
    if (x >= 4 && x < 12 && y >= 4 && y < 12)
        return RGB565(255, 0, 0);
    return RGB565(clear_rgb.r, clear_rgb.g, clear_rgb.b);
}

typedef struct {
    unsigned wrong, rows;
} tally;

/* Each finished row, as a display driver would get it. */
static int check_row(void *user, const zl_band *band)
{
    tally *t = (tally *)user;
    uint16_t r, x;
    for (r = 0; r < band->rows; r++) {
        const uint16_t *px = (const uint16_t *)((const uint8_t *)band->color + (long)r * band->color_stride);
        for (x = 0; x < band->width; x++) {
            if (px[x] != expected_pixel(x, band->first_row + r)) {
                if (t->wrong < 8)
                    printf("consumer: pixel (%u, %u) is %04x, expected %04x\n", (unsigned)x,
                           (unsigned)(band->first_row + r), (unsigned)px[x],
                           (unsigned)expected_pixel(x, band->first_row + r));
                t->wrong++;
            }
        }
        t->rows++;
    }
    return 0;
}

int main(void)
{
    static uint64_t work[1024]; /* 8 KB, 8-byte aligned */
    zl_mesh mesh = {positions, indices, NULL, face_colors, 8, 4};
    zl_frame_config cfg = {0};
    zl_state state;
    zl_frame frame;
    tally t = {0, 0};
    int failures = 0;

    zl_state_default(&state);
    cfg.width = W;
    cfg.height = H;
    cfg.band_rows = 1; /* scanline mode */
    cfg.format = ZL_FORMAT_RGB565;
    cfg.color_buffers = 1;
    cfg.max_meshes = 1;
    cfg.max_vertices = 8;
    cfg.max_triangles = 4;
    cfg.max_active = 4;
    if (zl_frame_bytes(&cfg) > sizeof work ||
        zl_frame_begin(&frame, &cfg, work, sizeof work, clear_rgb, 65535) != ZL_OK ||
        zl_frame_add_mesh(&frame, &mesh, NULL, &state) != ZL_OK || zl_frame_render(&frame, check_row, &t) != 0) {
        printf("consumer: %s: zline refused the scene\n", CONSUMER_HOW);
        return 1;
    }
    if (t.rows != H) {
        printf("consumer: %s: %u rows arrived, expected %u\n", CONSUMER_HOW, t.rows, (unsigned)H);
        failures++;
    }
    if (t.wrong != 0)
        failures++;
    printf("consumer: %s: zline %s, %u pixels wrong\n", CONSUMER_HOW, ZL_VERSION_STRING, t.wrong);
    return failures;
}
