/* SPDX-License-Identifier: MIT */
/*
 * zline configuration of the ATmega2560 demo (port/avr, issue 23), named by
 * -DZL_CONFIG_HEADER: the mesh stays in flash. avr-gcc copies const data to
 * SRAM unless it is PROGMEM, and an AVR data pointer cannot read program
 * memory, so zline reads the mesh's arrays through zl_config.h's hook with
 * pgm_read_*. The arrays must then lie in the low 64 KB of flash, where
 * pgm_read_* (LPM, 16-bit addresses) reaches: avr-gcc's linker script
 * places .progmem data right after the vectors. The hook needs lines and
 * outlines compiled out (zl_config.h).
 */
#ifndef ZL_AVR_FLASH_H
#define ZL_AVR_FLASH_H

#include <avr/pgmspace.h>

#define ZL_MESH_READ_FIXED(p) ((int32_t)pgm_read_dword(p))
#define ZL_MESH_READ_U16(p) ((uint16_t)pgm_read_word(p))
#define ZL_MESH_READ_U8(p) ((uint8_t)pgm_read_byte(p))

#endif
