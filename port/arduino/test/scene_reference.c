/* SPDX-License-Identifier: MIT */
/*
 * Host reference of the RotatingModel example: renders frames 0 ..
 * SCENE_CHECK_FRAMES - 1 (scene_checksum.h) of port/arduino/examples/RotatingModel's scene and
 * prints one line per frame, "frame N XXXXXXXX" (the FNV-1a sum of its
 * bytes), the lines the ATmega2560 firmware (avr_scene.c) prints under
 * qemu-system-avr. Also checks that the sketch's static work buffer is
 * large enough. Returns the number of failures.
 */
#include <stdio.h>

#include "rotating_scene.h"
#include "scene_checksum.h"


int main(void)
{
    static uint64_t work[ROTATING_SCENE_WORK_WORDS] ROTATING_SCENE_ALIGN8;
    zl_frame_config cfg;
    size_t need;
    uint16_t i;
    int failures = 0;
    rotating_scene_config(&cfg);
    need = zl_frame_bytes(&cfg);
    fprintf(stderr, "work buffer: %u bytes needed, %u given\n", (unsigned)need, (unsigned)sizeof work);
    if (need == 0 || need > sizeof work)
        failures++;
    for (i = 0; i < SCENE_CHECK_FRAMES; i++) {
        uint32_t sum = SCENE_FNV_BASIS;
        int r = rotating_scene_render((uint16_t)(i * SCENE_CHECK_STEP), work, sizeof work, scene_checksum_row, &sum);
        if (r != 0) {
            fprintf(stderr, "frame %u: render returned %d\n", (unsigned)i, r);
            failures++;
        }
        printf("frame %u %08lx\n", (unsigned)i, (unsigned long)sum);
    }
    return failures;
}
