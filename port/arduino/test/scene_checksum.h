/* SPDX-License-Identifier: MIT */
/*
 * The frame checksum both sides of the AVR check compute: FNV-1a (32-bit)
 * over every byte of every row of a frame, in order. The host reference and
 * the ATmega2560 firmware share this code; the FNV constants are the
 * published ones, so a wrong frame on either side changes the sum.
 */
#ifndef SCENE_CHECKSUM_H
#define SCENE_CHECKSUM_H

#include <stdint.h>

#include "zline/zline.h"

/* The frames both sides render: 0, 15, 30, ... 105, spread over a turn. */
#define SCENE_CHECK_FRAMES 8u
#define SCENE_CHECK_STEP 15u

#define SCENE_FNV_BASIS UINT32_C(2166136261)
#define SCENE_FNV_PRIME UINT32_C(16777619)

/* user: a uint32_t running sum, started at SCENE_FNV_BASIS. */
static int scene_checksum_row(void *user, const zl_band *band)
{
    uint32_t *sum = (uint32_t *)user;
    const uint8_t *bytes = (const uint8_t *)band->color;
    uint32_t count = (uint32_t)band->width * 2u * band->rows;
    uint32_t i;
    for (i = 0; i < count; i++)
        *sum = (*sum ^ bytes[i]) * SCENE_FNV_PRIME;
    return 0;
}

#endif
