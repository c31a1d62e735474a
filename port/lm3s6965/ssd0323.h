/* SPDX-License-Identifier: MIT */
/*
 * SSD0323 OLED driver for the LM3S6965 evaluation board: the OSRAM Pictiva
 * 128x64 panel, 4-bit grey, on SSI0.
 *
 * Wiring (LM3S6965 evaluation board; QEMU's lm3s6965evb models the same):
 *   PA2 SSI0Clk, PA3 SSI0Fss (the OLED's chip select, driven low by the SSI
 *   for every frame), PA5 SSI0Tx: alternate function, to the OLED
 *   PC7 D/C: low = command bytes, high = display data
 *   PD0 the SD card's chip select on the same bus: kept high (card
 *   deselected). QEMU routes this line to its OLED model's select too, so
 *   the OLED only listens while PD0 is high.
 *
 * Display RAM: 64 columns of bytes x 80 rows (the panel shows 64 rows), two
 * pixels a byte, the left pixel in the high nibble (no remapping). A window
 * (column and row address ranges) is filled left to right, top to bottom.
 */
#ifndef ZL_SSD0323_H
#define ZL_SSD0323_H

#include <stddef.h>
#include <stdint.h>

#include "zline/zline.h"

#define SSD0323_WIDTH 128
#define SSD0323_HEIGHT 64

/* Set up the GPIO pins and SSI0 (SPI mode 3, 8 bits, 50 MHz / 14 = 3.6 MHz,
 * under the controller's 250 ns clock period) and send the controller's
 * initialisation sequence. Needs the system clock running (lm3s_clock_init). */
void ssd0323_init(void);

/* The window for the following data: pixel columns x0 .. x1 (x0 even, x1
 * odd: a byte holds two pixels) and rows y0 .. y1, inclusive. Returns 0, or
 * -1 (and sends nothing) if the window is outside the panel. */
int ssd0323_window(uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1);

/* Send display data bytes (two pixels each) into the current window. */
void ssd0323_data(const uint8_t *bytes, size_t count);

/* zline's row callback (zl_band_fn): converts each finished RGB565 row
 * (full panel width) to 4-bit grey (port/display/zl_grey4.h) and sends it.
 * Set the window to the whole panel first. Returns non-zero, stopping the
 * frame, for a band that is not a full-width RGB565 band. */
int ssd0323_send_band(void *user, const zl_band *band);

#endif
