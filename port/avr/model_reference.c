/* SPDX-License-Identifier: MIT */
/*
 * Host side of the ATmega2560 demo's test: prints the lines avr_model.c
 * prints over USART0 for the same frames (without its "# " lines), so
 * run-avr-model.sh compares the two byte for byte. With --needs it prints
 * instead what the frames of the whole turn need: the largest active count
 * over all MODEL_SCENE_FRAMES frames (model_scene.h's MODEL_SCENE_MAX_ACTIVE
 * must cover it) and the triangles kept.
 */
#include <stdio.h>
#include <string.h>

#include "model_scene.h"

/* The sweep's capacity: every triangle of the torus at once. */
#define TORUS_ROOMY_ACTIVE 192u

static int row_print(void *user, const zl_band *band)
{
    const uint8_t *bytes = (const uint8_t *)band->color;
    unsigned i, count = (unsigned)band->width * 2u * band->rows;
    (void)user;
    for (i = 0; i < count; i++)
        printf("%02x", bytes[i]);
    putchar('\n');
    return 0;
}

static int row_nowhere(void *user, const zl_band *band)
{
    (void)user;
    (void)band;
    return 0;
}

static int print_needs(uint64_t *work, size_t bytes)
{
    unsigned i, most_active = 0, most_triangles = 0;
    zl_frame_config roomy;
    model_scene_config(&roomy);
    roomy.max_active = TORUS_ROOMY_ACTIVE;
    for (i = 0; i < MODEL_SCENE_FRAMES; i++) {
        zl_frame_needs_t n;
        int r = model_scene_render((uint16_t)i, &roomy, work, bytes, row_nowhere, NULL, &n);
        if (r != 0) {
            fprintf(stderr, "model_reference: frame %u: error %d\n", i, r);
            return 1;
        }
        if (n.active > most_active)
            most_active = (unsigned)n.active;
        if (n.triangles > most_triangles)
            most_triangles = (unsigned)n.triangles;
    }
    printf("over %u frames: at most %u active, %u triangles kept (MODEL_SCENE_MAX_ACTIVE %u)\n", MODEL_SCENE_FRAMES,
           most_active, most_triangles, MODEL_SCENE_MAX_ACTIVE);
    return most_active > MODEL_SCENE_MAX_ACTIVE;
}

int main(int argc, char **argv)
{
    static uint64_t work[4096];
    unsigned i;
    if (argc == 2 && strcmp(argv[1], "--needs") == 0)
        return print_needs(work, sizeof work);
    for (i = 0; i < MODEL_SCENE_CHECK_FRAMES; i++) {
        uint16_t index = (uint16_t)(i * MODEL_SCENE_CHECK_STEP);
        int r;
        printf("frame %u\n", index);
        r = model_scene_render(index, NULL, work, sizeof work, row_print, NULL, NULL);
        if (r != 0) {
            printf("render error %d\n", -r);
            return 1;
        }
    }
    return 0;
}
