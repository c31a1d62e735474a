/* SPDX-License-Identifier: MIT */
/*
 * zline-oled-reference: the host's rendering of the OLED demo's frames
 * (../oled_scene.c), each reduced to the panel's 4-bit grey by the same
 * function the firmware uses (port/display/zl_grey4.h), written as
 * DIR/frame-NN.pgm (binary PGM, 128x64, maxval 15: one byte per pixel, the
 * grey level 0..15). The CI test (../oled_test.py) compares these with the
 * QEMU captures of the emulated OLED, byte for byte.
 *
 *   zline-oled-reference DIR
 *
 * Also prints the work-buffer size and the largest zl_frame_needs() over
 * the animation, the figures oled_scene.c's capacities come from.
 * Exit status 0, or 1 with a message.
 */
#include <stdio.h>
#include <string.h>

#include "oled_scene.h"
#include "zl_grey4.h"

typedef struct {
    uint8_t grey[OLED_SCENE_H][OLED_SCENE_W];
} grey_image;

static int store_row(void *user, const zl_band *band)
{
    grey_image *img = user;
    const uint16_t *px = band->color;
    uint16_t x;
    if (band->first_row >= OLED_SCENE_H || band->rows != 1 || band->width != OLED_SCENE_W)
        return 1;
    for (x = 0; x < band->width; x++)
        img->grey[band->first_row][x] = zl_grey4_from_rgb565(px[x]);
    return 0;
}

static int write_pgm(const char *path, const grey_image *img)
{
    FILE *f = fopen(path, "wb");
    int ok;
    if (f == NULL)
        return -1;
    ok = fprintf(f, "P5\n%d %d\n15\n", OLED_SCENE_W, OLED_SCENE_H) > 0 &&
         fwrite(img->grey, 1, sizeof img->grey, f) == sizeof img->grey;
    return (fclose(f) == 0 && ok) ? 0 : -1;
}

int main(int argc, char **argv)
{
    static uint64_t work[65536 / 8];
    static grey_image img;
    zl_frame_config cfg;
    zl_frame_needs_t most = {0, 0, 0};
    size_t bytes;
    int i;
    if (argc != 2) {
        fprintf(stderr, "usage: zline-oled-reference DIR\n");
        return 1;
    }
    oled_scene_config(&cfg);
    bytes = zl_frame_bytes(&cfg);
    printf("work buffer: %lu bytes\n", (unsigned long)bytes);
    if (bytes == 0 || bytes > sizeof work) {
        fprintf(stderr, "zline-oled-reference: the scene's work buffer does not fit\n");
        return 1;
    }
    for (i = 0; i < OLED_SCENE_FRAMES; i++) {
        char path[4096];
        zl_frame_needs_t needs;
        int r;
        memset(&img, 0, sizeof img);
        r = oled_scene_render(i, work, bytes, store_row, &img, &needs);
        if (needs.triangles > most.triangles)
            most.triangles = needs.triangles;
        if (needs.active > most.active)
            most.active = needs.active;
        if (r != 0) {
            fprintf(stderr, "zline-oled-reference: frame %d: render failed (%d)\n", i, r);
            return 1;
        }
        if (snprintf(path, sizeof path, "%s/frame-%02d.pgm", argv[1], i) >= (int)sizeof path ||
            write_pgm(path, &img) != 0) {
            fprintf(stderr, "zline-oled-reference: cannot write %s\n", path);
            return 1;
        }
    }
    printf("frames: %d written to %s\n", OLED_SCENE_FRAMES, argv[1]);
    printf("largest needs: %lu triangles (capacity %lu), %lu active (capacity %lu)\n",
           (unsigned long)most.triangles, (unsigned long)cfg.max_triangles, (unsigned long)most.active,
           (unsigned long)cfg.max_active);
    return 0;
}
