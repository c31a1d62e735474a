/* SPDX-License-Identifier: MIT */
/* ST7789 / ILI9341 over SPI: see zl_spi_panel.h. */
#include "zl_spi_panel.h"

/* Command numbers: ST7789VW and ILI9341 data sheets (the MIPI DCS set both
 * share, and the ILI9341's panel settings). */
enum {
    CMD_SWRESET = 0x01,
    CMD_SLPOUT = 0x11,
    CMD_NORON = 0x13,
    CMD_INVOFF = 0x20,
    CMD_INVON = 0x21,
    CMD_GAMSET = 0x26,
    CMD_DISPON = 0x29,
    CMD_CASET = 0x2A,
    CMD_RASET = 0x2B,
    CMD_RAMWR = 0x2C,
    CMD_MADCTL = 0x36,
    CMD_COLMOD = 0x3A,
    ILI_FRMCTR1 = 0xB1,
    ILI_DISCTRL = 0xB6,
    ILI_PWCTR1 = 0xC0,
    ILI_PWCTR2 = 0xC1,
    ILI_VMCTR1 = 0xC5,
    ILI_VMCTR2 = 0xC7
};

#define COLMOD_RGB565 0x55u /* 16 bits per pixel on both interfaces */
/* SWRESET and SLPOUT: the data sheets ask for 5 ms before the next command
 * and 120 ms before SLPOUT / SLPIN; 120 ms after both covers every case. */
#define RESET_DELAY_MS 120u
#define SLPOUT_DELAY_MS 120u

zl_panel_config zl_panel_config_st7789_240x240(void)
{
    zl_panel_config c = {0};
    c.controller = ZL_PANEL_ST7789;
    c.madctl = 0;
    c.invert = 1;
    c.width = 240;
    c.height = 240;
    return c;
}

zl_panel_config zl_panel_config_ili9341_320x240(void)
{
    zl_panel_config c = {0};
    c.controller = ZL_PANEL_ILI9341;
    c.madctl = ZL_PANEL_MADCTL_MV | ZL_PANEL_MADCTL_BGR;
    c.invert = 0;
    c.width = 320;
    c.height = 240;
    return c;
}

/* --- bytes on the bus ---------------------------------------------------- */

static void wait_transfer(zl_panel *p)
{
    if (p->in_flight) {
        p->bus->write_wait(p->bus->user);
        p->in_flight = 0;
    }
}

/* A command byte and its parameters. Only called with no transfer in
 * flight, so D/C never changes under a byte still being sent. */
static void command(const zl_panel *p, uint8_t cmd, const uint8_t *params, size_t count)
{
    p->bus->set_dc(p->bus->user, 0);
    p->bus->write(p->bus->user, &cmd, 1);
    if (count > 0) {
        p->bus->set_dc(p->bus->user, 1);
        p->bus->write(p->bus->user, params, count);
    }
}

static void command_delay(const zl_panel *p, uint8_t cmd, uint32_t ms)
{
    command(p, cmd, NULL, 0);
    p->bus->delay_ms(p->bus->user, ms);
}

/* The bus's verdict on the transfers since the last check (bus->status):
 * on a failure, release the panel and close the window, so that nothing of
 * the failed frame is relied on and the next one starts afresh. */
static zl_status bus_check(zl_panel *p)
{
    if (p->bus->status == NULL || p->bus->status(p->bus->user) == 0)
        return ZL_OK;
    p->bus->select(p->bus->user, 0);
    p->windowed = 0;
    p->in_flight = 0;
    return ZL_ERR_IO;
}

/* Start (or, without DMA, do) a pixel transfer; D/C is already high. */
static void send_pixels(zl_panel *p, const uint8_t *bytes, size_t count)
{
    if (p->bus->write_start != NULL) {
        p->bus->write_start(p->bus->user, bytes, count);
        p->in_flight = 1;
    } else {
        p->bus->write(p->bus->user, bytes, count);
    }
}

/* --- set-up -------------------------------------------------------------- */

static int bus_ok(const zl_panel_bus *b)
{
    return b != NULL && b->select != NULL && b->set_dc != NULL && b->write != NULL && b->delay_ms != NULL &&
           (b->write_start == NULL || b->write_wait != NULL);
}

static zl_status config_check(const zl_panel_config *c)
{
    uint32_t ram_w = (c->madctl & ZL_PANEL_MADCTL_MV) ? ZL_PANEL_RAM_LONG : ZL_PANEL_RAM_SHORT;
    uint32_t ram_h = (c->madctl & ZL_PANEL_MADCTL_MV) ? ZL_PANEL_RAM_SHORT : ZL_PANEL_RAM_LONG;
    if (c->controller != ZL_PANEL_ST7789 && c->controller != ZL_PANEL_ILI9341)
        return ZL_ERR_ARG;
    if (c->width == 0 || c->height == 0 || (uint32_t)c->x_offset + c->width > ram_w ||
        (uint32_t)c->y_offset + c->height > ram_h)
        return ZL_ERR_RANGE;
    return ZL_OK;
}

/* The ILI9341's panel settings (its data sheet's power-on sequence values
 * for a 2.8" TFT): power, VCOM, frame rate 70 Hz, display function, gamma. */
static void ili9341_panel_settings(const zl_panel *p)
{
    static const uint8_t pwctr1[] = {0x23}, pwctr2[] = {0x10}, vmctr1[] = {0x3E, 0x28}, vmctr2[] = {0x86};
    static const uint8_t frmctr1[] = {0x00, 0x18}, disctrl[] = {0x08, 0x82, 0x27}, gamset[] = {0x01};
    command(p, ILI_PWCTR1, pwctr1, sizeof pwctr1);
    command(p, ILI_PWCTR2, pwctr2, sizeof pwctr2);
    command(p, ILI_VMCTR1, vmctr1, sizeof vmctr1);
    command(p, ILI_VMCTR2, vmctr2, sizeof vmctr2);
    command(p, ILI_FRMCTR1, frmctr1, sizeof frmctr1);
    command(p, ILI_DISCTRL, disctrl, sizeof disctrl);
    command(p, CMD_GAMSET, gamset, sizeof gamset);
}

zl_status zl_panel_init(zl_panel *p, const zl_panel_config *cfg, const zl_panel_bus *bus)
{
    uint8_t colmod = COLMOD_RGB565, madctl;
    zl_status s;
    if (p == NULL || cfg == NULL || !bus_ok(bus))
        return ZL_ERR_ARG;
    s = config_check(cfg);
    if (s != ZL_OK)
        return s;
    p->bus = bus;
    p->cfg = *cfg;
    p->win_w = p->win_h = p->next_row = 0;
    p->in_flight = p->windowed = 0;
    madctl = cfg->madctl;
    bus->select(bus->user, 1);
    command_delay(p, CMD_SWRESET, RESET_DELAY_MS);
    command_delay(p, CMD_SLPOUT, SLPOUT_DELAY_MS);
    if (cfg->controller == ZL_PANEL_ILI9341)
        ili9341_panel_settings(p);
    command(p, CMD_COLMOD, &colmod, 1);
    command(p, CMD_MADCTL, &madctl, 1);
    command(p, cfg->invert ? CMD_INVON : CMD_INVOFF, NULL, 0);
    command(p, CMD_NORON, NULL, 0);
    command(p, CMD_DISPON, NULL, 0);
    bus->select(bus->user, 0);
    return bus_check(p);
}

/* --- drawing ------------------------------------------------------------- */

static void put_range(uint8_t out[4], uint32_t first, uint32_t last)
{
    out[0] = (uint8_t)(first >> 8);
    out[1] = (uint8_t)(first & 0xFFu);
    out[2] = (uint8_t)(last >> 8);
    out[3] = (uint8_t)(last & 0xFFu);
}

zl_status zl_panel_window(zl_panel *p, uint16_t x, uint16_t y, uint16_t w, uint16_t h)
{
    uint8_t cols[4], rows[4];
    uint32_t x0, y0;
    if (p == NULL || p->bus == NULL)
        return ZL_ERR_ARG;
    if (w == 0 || h == 0 || (uint32_t)x + w > p->cfg.width || (uint32_t)y + h > p->cfg.height)
        return ZL_ERR_RANGE;
    wait_transfer(p);
    x0 = (uint32_t)p->cfg.x_offset + x;
    y0 = (uint32_t)p->cfg.y_offset + y;
    put_range(cols, x0, x0 + w - 1u);
    put_range(rows, y0, y0 + h - 1u);
    p->bus->select(p->bus->user, 1);
    command(p, CMD_CASET, cols, sizeof cols);
    command(p, CMD_RASET, rows, sizeof rows);
    command(p, CMD_RAMWR, NULL, 0);
    p->bus->set_dc(p->bus->user, 1); /* every byte from here on is pixel data */
    p->win_w = w;
    p->win_h = h;
    p->next_row = 0;
    p->windowed = 1;
    return bus_check(p);
}

static zl_status band_check(const zl_panel *p, const zl_band *b)
{
    if (p == NULL || b == NULL || b->color == NULL || !p->windowed || b->format != ZL_FORMAT_RGB565_BE)
        return ZL_ERR_ARG;
    if (b->width != p->win_w || b->first_row != p->next_row || b->rows == 0 ||
        (uint32_t)b->first_row + b->rows > p->win_h || b->color_stride < (int32_t)b->width * 2)
        return ZL_ERR_RANGE;
    return ZL_OK;
}

int zl_panel_send_band(void *panel, const zl_band *band)
{
    zl_panel *p = panel;
    const uint8_t *row;
    size_t row_bytes;
    zl_status s = band_check(p, band);
    if (s != ZL_OK)
        return s;
    row = band->color;
    row_bytes = (size_t)band->width * 2u;
    /* The previous band's transfer must end before this one starts (one
     * DMA channel); zline is done with this band's buffer already. */
    wait_transfer(p);
    s = bus_check(p); /* the window's commands or the previous band */
    if (s != ZL_OK)
        return s;
    if ((size_t)band->color_stride == row_bytes) {
        send_pixels(p, row, row_bytes * band->rows);
    } else {
        /* Rows with padding between them: one transfer each, in order. */
        uint16_t r;
        for (r = 0; r < band->rows; r++) {
            wait_transfer(p);
            send_pixels(p, row + (size_t)r * (size_t)band->color_stride, row_bytes);
        }
    }
    p->next_row = (uint16_t)(p->next_row + band->rows);
    return p->in_flight ? 0 : bus_check(p); /* with DMA: at the next wait */
}

zl_status zl_panel_finish(zl_panel *p)
{
    int filled;
    if (p == NULL || p->bus == NULL)
        return ZL_ERR_ARG;
    wait_transfer(p);
    if (bus_check(p) != ZL_OK)
        return ZL_ERR_IO; /* released and closed */
    filled = p->windowed && p->next_row == p->win_h;
    p->bus->select(p->bus->user, 0);
    p->windowed = 0;
    return filled ? ZL_OK : ZL_ERR_ARG;
}
