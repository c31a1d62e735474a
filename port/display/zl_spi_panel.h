/* SPDX-License-Identifier: MIT */
/*
 * SPI RGB565 panels: ST7789 (e.g. 240x240 and 240x320 modules) and ILI9341
 * (320x240), the displays most zline users have. Portable C99: the board
 * gives the driver a bus (chip select, D/C, byte writes, optionally a DMA
 * write and a delay); nothing here touches hardware or allocates.
 *
 * What goes over the wire (both controllers' data sheets, "MIPI DBI type C"
 * 4-wire SPI: D/C low = command byte, high = parameter or pixel data):
 *   init    SWRESET, 120 ms; SLPOUT, 120 ms; COLMOD 0x55 (16 bits per pixel,
 *           RGB565); MADCTL (orientation, RGB/BGR); INVON or INVOFF;
 *           NORON; DISPON (ILI9341 adds its power and frame-rate settings)
 *   window  CASET xs xe, RASET ys ye (16-bit big-endian, inclusive, offset by
 *           the visible area's place in controller RAM), then RAMWR
 *   pixels  RGB565 high byte first: zline's ZL_FORMAT_RGB565_BE rows, sent
 *           as they are
 *
 * Band handover for DMA (zline's scanline or band mode with two colour
 * buffers, cfg.color_buffers = 2): zl_panel_send_band is a zl_band_fn. It
 * waits until the previous band's transfer has ended, then starts this
 * band's transfer and returns at once, so zline renders band N + 1 into its
 * other buffer while band N is still being sent. zline leaves a band's
 * buffer untouched until the band after next is requested, which is after
 * this wait. With one colour buffer use a bus without write_start (blocking
 * writes): the buffer is reused as soon as the callback returns.
 *
 * Errors (a negative zl_status) are returned before anything is sent.
 */
#ifndef ZL_SPI_PANEL_H
#define ZL_SPI_PANEL_H

#include <stddef.h>
#include <stdint.h>

#include "zline/zline.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum { ZL_PANEL_ST7789 = 0, ZL_PANEL_ILI9341 = 1 } zl_panel_controller;

/* MADCTL bits (memory access control): row order, column order, row/column
 * exchange, and BGR colour order (most ILI9341 modules are BGR-wired). */
#define ZL_PANEL_MADCTL_MY 0x80u
#define ZL_PANEL_MADCTL_MX 0x40u
#define ZL_PANEL_MADCTL_MV 0x20u
#define ZL_PANEL_MADCTL_BGR 0x08u

/* Both controllers have 240 x 320 pixels of RAM (320 x 240 with MV). */
#define ZL_PANEL_RAM_SHORT 240u
#define ZL_PANEL_RAM_LONG 320u

typedef struct {
    uint8_t controller;     /* zl_panel_controller */
    uint8_t madctl;         /* ZL_PANEL_MADCTL_* bits */
    uint8_t invert;         /* 1: INVON (most ST7789 IPS modules need it), 0: INVOFF */
    uint16_t width, height; /* visible pixels in this orientation */
    uint16_t x_offset, y_offset; /* where the visible area starts in controller RAM, in
                                    this orientation (e.g. 0, 80 for a 240x240 ST7789
                                    module turned by 180 degrees) */
} zl_panel_config;

/* The board's side. Every function gets `user`. */
typedef struct {
    void *user;
    /* Chip select: 1 selects the panel (CS low on the wire), 0 releases it. */
    void (*select)(void *user, int selected);
    /* D/C line: 0 command, 1 data. The driver calls it only when no write
     * is in flight, so the level is stable for every byte. */
    void (*set_dc)(void *user, int data);
    /* Send count bytes and return when the last one is out. */
    void (*write)(void *user, const uint8_t *bytes, size_t count);
    /* Optional (NULL: write is used): start sending count bytes, e.g. by
     * DMA, and return at once; the bytes stay untouched until write_wait. */
    void (*write_start)(void *user, const uint8_t *bytes, size_t count);
    /* Return when the transfer write_start began has ended (needed with
     * write_start). */
    void (*write_wait)(void *user);
    /* Wait at least ms milliseconds. */
    void (*delay_ms)(void *user, uint32_t ms);
    /* Optional (NULL: the bus cannot fail): nonzero when a transfer since the
     * last call failed or timed out (the board's SPI error or timeout flag),
     * which the call clears. Asked after the set-up, after a window's
     * commands, once a band's bytes are out (with DMA: when the next band or
     * zl_panel_finish waits for them) and in zl_panel_finish. On a failure
     * the call returns ZL_ERR_IO, the panel is released (CS high) and the
     * window closed: the next frame starts with zl_panel_window as usual
     * (after a failed zl_panel_init, with zl_panel_init). */
    int (*status)(void *user);
} zl_panel_bus;

/* Driver state: the caller owns it and never touches its fields. */
typedef struct {
    const zl_panel_bus *bus;
    zl_panel_config cfg;
    uint16_t win_w, win_h; /* the current window (zl_panel_window) */
    uint16_t next_row;     /* the window row the next band must start at */
    uint8_t in_flight;     /* a write_start transfer may still be running */
    uint8_t windowed;      /* a window is open: RAMWR sent, pixels expected */
} zl_panel;

/* Ready-made configurations: a 240x240 ST7789 module (upright, inverted
 * colours as IPS modules need) and a 320x240 ILI9341 (landscape, BGR). */
zl_panel_config zl_panel_config_st7789_240x240(void);
zl_panel_config zl_panel_config_ili9341_320x240(void);

/* Check the configuration and the bus, then initialise the controller.
 * ZL_ERR_ARG: NULL, unknown controller, bus without write/select/set_dc/
 * delay_ms, or write_start without write_wait; ZL_ERR_RANGE: the visible
 * area does not fit the controller's RAM in this orientation. */
zl_status zl_panel_init(zl_panel *p, const zl_panel_config *cfg, const zl_panel_bus *bus);

/* Open the window x, y, w x h of the visible area (partial updates: any
 * place and size inside it) for the following pixels: CASET, RASET,
 * RAMWR. ZL_ERR_RANGE if it is empty or leaves the visible area. */
zl_status zl_panel_window(zl_panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h);

/* zl_band_fn: send a finished band into the open window (user = the
 * zl_panel). Bands must be ZL_FORMAT_RGB565_BE, as wide as the window,
 * and come in order from the window's first row. Returns 0, or a negative
 * zl_status (which stops zl_frame_render) with nothing sent. */
int zl_panel_send_band(void *panel, const zl_band *band);

/* Wait for the last transfer and release the panel. ZL_ERR_ARG if the
 * window was not filled (it is closed all the same). */
zl_status zl_panel_finish(zl_panel *p);

#ifdef __cplusplus
}
#endif

#endif
