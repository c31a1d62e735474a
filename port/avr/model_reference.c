/* SPDX-License-Identifier: MIT */
/*
 * Host side of the ATmega2560 demo's test: prints the lines avr_model.c
 * prints over USART0 for the same frames (without its "# " lines), so
 * run-avr-model.sh compares the two byte for byte. The host renders with
 * room for every triangle (model_scene_roomy_config), the firmware over
 * capacity: the comparison checks those frames too. With --needs it prints
 * instead what the 48 frames of the turn need and the replans the
 * firmware's capacities take, and fails unless they are model_scene.h's
 * MODEL_SCENE_* figures (CTest avr_model_capacity).
 */
#include <stdio.h>
#include <string.h>

#include "model_scene.h"

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

/* The turn's needs with room for everything (most active records, most
 * triangles kept), then the plans the firmware's capacities take over it
 * (model_scene.h's MODEL_SCENE_* must match both). */
static int print_needs(uint64_t *work, size_t bytes)
{
    unsigned i, most_active = 0, most_triangles = 0, most_replans = 0, replans = 0, checked = 0;
    zl_frame_config roomy;
    model_scene_roomy_config(&roomy);
    for (i = 0; i < MODEL_SCENE_FRAMES; i++) {
        zl_frame_needs_t n, tight;
        int r = model_scene_render((uint16_t)i, &roomy, work, bytes, row_nowhere, NULL, &n);
        if (r == 0)
            r = model_scene_render((uint16_t)i, NULL, work, bytes, row_nowhere, NULL, &tight);
        if (r != 0) {
            fprintf(stderr, "model_reference: frame %u: error %d\n", i, r);
            return 1;
        }
        if (n.replans != 0) {
            fprintf(stderr, "model_reference: frame %u: %u replans with room for everything\n", i,
                    (unsigned)n.replans);
            return 1;
        }
        if (n.active > most_active)
            most_active = (unsigned)n.active;
        if (n.triangles > most_triangles)
            most_triangles = (unsigned)n.triangles;
        if (tight.replans > most_replans)
            most_replans = (unsigned)tight.replans;
        replans += (unsigned)tight.replans;
        if (i % MODEL_SCENE_CHECK_STEP == 0 && i / MODEL_SCENE_CHECK_STEP < MODEL_SCENE_CHECK_FRAMES)
            checked += (unsigned)tight.replans; /* the firmware's "# replans" */
    }
    printf("over %u frames: at most %u active, %u triangles kept (MODEL_SCENE_NEEDS_ACTIVE %u, "
           "MODEL_SCENE_MAX_TRIANGLES %u)\n",
           MODEL_SCENE_FRAMES, most_active, most_triangles, MODEL_SCENE_NEEDS_ACTIVE, MODEL_SCENE_MAX_TRIANGLES);
    printf("with the firmware's %u active records: %u replans, at most %u in a frame (MODEL_SCENE_REPLANS %u, "
           "MODEL_SCENE_MOST_REPLANS %u); %u in the %u frames the test compares\n",
           MODEL_SCENE_MAX_ACTIVE, replans, most_replans, MODEL_SCENE_REPLANS, MODEL_SCENE_MOST_REPLANS, checked,
           MODEL_SCENE_CHECK_FRAMES);
    return most_active != MODEL_SCENE_NEEDS_ACTIVE || most_triangles > MODEL_SCENE_MAX_TRIANGLES ||
           replans != MODEL_SCENE_REPLANS || most_replans != MODEL_SCENE_MOST_REPLANS;
}

int main(int argc, char **argv)
{
    static uint64_t work[16384];
    zl_frame_config roomy;
    unsigned i;
    if (argc == 2 && strcmp(argv[1], "--needs") == 0)
        return print_needs(work, sizeof work);
    model_scene_roomy_config(&roomy);
    for (i = 0; i < MODEL_SCENE_CHECK_FRAMES; i++) {
        uint16_t index = (uint16_t)(i * MODEL_SCENE_CHECK_STEP);
        int r;
        printf("frame %u\n", index);
        r = model_scene_render(index, &roomy, work, sizeof work, row_print, NULL, NULL);
        if (r != 0) {
            printf("render error %d\n", -r);
            return 1;
        }
    }
    return 0;
}
