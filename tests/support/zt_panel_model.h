/* SPDX-License-Identifier: MIT */
/*
 * A software model of an ST7789 / ILI9341 display controller on 4-wire SPI,
 * written from the two data sheets, independent of the driver it checks
 * (port/display/zl_spi_panel.c; it includes nothing of it). It sees exactly what the wire carries:
 * every byte with the chip-select and D/C levels of its moment, and the
 * delays between commands. From that it keeps the controller's state and
 * its 240 x 320 frame memory, and records the first protocol error:
 *
 *   - a byte while the chip is not selected; a data byte before any command
 *   - an unknown command, or a command given the wrong number of parameters
 *   - a command sooner than 5 ms after SWRESET or SLPOUT; SLPOUT sooner than
 *     120 ms after SWRESET
 *   - CASET / RASET with start > end or beyond the RAM of the orientation
 *   - pixel data with COLMOD not 16 bits per pixel, an odd byte count at the
 *     next command, or more pixels than the window holds
 *   - D/C changed while a DMA transfer is in flight, or a transfer started
 *     before the previous one was waited for
 *
 * Memory addressing (MADCTL): the address counters run in the orientation's
 * coordinates, x (columns) 0 .. 239 and y (rows) 0 .. 319, or 320 x 240 with
 * MV; MX mirrors x, MY mirrors y within that range, and MV stores (x, y) at
 * RAM column y, row x. zt_panel_pixel reads back through the same mapping.
 *
 * DMA: write_start only records the buffer; the bytes are fed to the model
 * when write_wait is called. So a driver or renderer that reuses a buffer
 * before the transfer has ended shows up as wrong pixels, as on a board.
 */
#ifndef ZT_PANEL_MODEL_H
#define ZT_PANEL_MODEL_H

#include <stddef.h>
#include <stdint.h>


/* Controllers, and MADCTL bits as the data sheets define them. */
enum { ZT_PANEL_ST7789 = 0, ZT_PANEL_ILI9341 = 1 };
#define ZT_MADCTL_MY 0x80u
#define ZT_MADCTL_MX 0x40u
#define ZT_MADCTL_MV 0x20u

#define ZT_PANEL_RAM_W 240u
#define ZT_PANEL_RAM_H 320u

typedef struct {
    uint8_t controller;         /* ZT_PANEL_*: which commands exist */
    uint16_t ram[ZT_PANEL_RAM_H][ZT_PANEL_RAM_W];
    /* wire state */
    uint8_t selected, dc;
    /* command parser */
    int16_t cmd;                /* current command, -1 before the first */
    uint8_t params[16];
    uint32_t nparams;           /* parameter (or pixel data) bytes since the command */
    uint8_t finished;           /* the command's end has been checked (no new bytes since) */
    /* controller state */
    uint8_t colmod, madctl, sleeping, display_on, inverted;
    uint16_t xs, xe, ys, ye;    /* window, orientation coordinates */
    uint16_t x, y;              /* RAMWR address counter */
    uint8_t high;               /* pending first byte of a pixel */
    uint8_t window_full;        /* every pixel of the window has been written */
    uint32_t ms_since_reset, ms_since_cmd;
    uint8_t reset_seen;
    uint16_t last_timed_cmd;    /* SWRESET or SLPOUT, whose delay counts */
    /* DMA emulation */
    const uint8_t *dma_bytes;
    size_t dma_count;
    uint8_t dma_busy;
    /* results */
    uint32_t bytes, pixels, transfers;
    int errors;
    char first_error[120];
} zt_panel_model;

/* Power-on state: RAM filled with `fill`, nothing selected, sleeping. */
void zt_panel_model_reset(zt_panel_model *m, uint8_t controller, uint16_t fill);

/* The wire, as a board's SPI would drive it: chip select (1 = selected),
 * D/C (0 command, 1 data), blocking writes, a DMA write (start, then wait:
 * deferred as described above) and delays. */
void zt_panel_select(zt_panel_model *m, int selected);
void zt_panel_set_dc(zt_panel_model *m, int data);
void zt_panel_write(zt_panel_model *m, const uint8_t *bytes, size_t count);
void zt_panel_dma_start(zt_panel_model *m, const uint8_t *bytes, size_t count);
void zt_panel_dma_wait(zt_panel_model *m);
void zt_panel_delay_ms(zt_panel_model *m, uint32_t ms);

/* The pixel at (x, y) of the orientation the model is in (its MADCTL);
 * 0 outside the RAM. */
uint16_t zt_panel_pixel(const zt_panel_model *m, uint32_t x, uint32_t y);

/* Check the end of the byte stream so far (as a next command would) and
 * return the error count; first_error says what went wrong first. More
 * bytes may follow. */
int zt_panel_model_check(zt_panel_model *m);

#endif
