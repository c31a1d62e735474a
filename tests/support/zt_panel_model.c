/* SPDX-License-Identifier: MIT */
/* ST7789 / ILI9341 controller model: see zt_panel_model.h. */
#include "zt_panel_model.h"

#include <stdio.h>
#include <string.h>

enum { ANY = 0xFFFF };

/* Commands with their parameter counts (min, max; RAMWR: any number of
 * pixel bytes) and which controllers have them, from the data sheets'
 * command tables. ILI9341's DISCTRL (B6h) has 4 parameters of which drivers
 * commonly send the first 3; the controller keeps the others. */
typedef struct {
    uint8_t cmd;
    uint16_t min, max;
    uint8_t st7789, ili9341;
} command_info;

static const command_info commands[] = {
    {0x00, 0, 0, 1, 1},     /* NOP */
    {0x01, 0, 0, 1, 1},     /* SWRESET */
    {0x10, 0, 0, 1, 1},     /* SLPIN */
    {0x11, 0, 0, 1, 1},     /* SLPOUT */
    {0x13, 0, 0, 1, 1},     /* NORON */
    {0x20, 0, 0, 1, 1},     /* INVOFF */
    {0x21, 0, 0, 1, 1},     /* INVON */
    {0x26, 1, 1, 1, 1},     /* GAMSET */
    {0x28, 0, 0, 1, 1},     /* DISPOFF */
    {0x29, 0, 0, 1, 1},     /* DISPON */
    {0x2A, 4, 4, 1, 1},     /* CASET */
    {0x2B, 4, 4, 1, 1},     /* RASET */
    {0x2C, 0, ANY, 1, 1},   /* RAMWR */
    {0x36, 1, 1, 1, 1},     /* MADCTL */
    {0x3A, 1, 1, 1, 1},     /* COLMOD */
    {0xB1, 2, 2, 0, 1},     /* ILI9341 FRMCTR1 */
    {0xB6, 3, 4, 0, 1},     /* ILI9341 DISCTRL */
    {0xC0, 1, 1, 0, 1},     /* ILI9341 PWCTR1 */
    {0xC1, 1, 1, 0, 1},     /* ILI9341 PWCTR2 */
    {0xC5, 2, 2, 0, 1},     /* ILI9341 VMCTR1 */
    {0xC7, 1, 1, 0, 1},     /* ILI9341 VMCTR2 */
};

static const command_info *lookup(const zt_panel_model *m, int cmd)
{
    size_t i;
    for (i = 0; i < sizeof commands / sizeof commands[0]; i++) {
        if (commands[i].cmd == cmd)
            return (m->controller == ZT_PANEL_ST7789 ? commands[i].st7789 : commands[i].ili9341) ? &commands[i]
                                                                                                 : NULL;
    }
    return NULL;
}

static void fail(zt_panel_model *m, const char *what, unsigned a, unsigned b)
{
    if (m->errors++ == 0)
        snprintf(m->first_error, sizeof m->first_error, "%s (%u, %u) at byte %lu", what, a, b,
                 (unsigned long)m->bytes);
}

static uint32_t limit_x(const zt_panel_model *m)
{
    return (m->madctl & ZT_MADCTL_MV) ? ZT_PANEL_RAM_H : ZT_PANEL_RAM_W;
}

static uint32_t limit_y(const zt_panel_model *m)
{
    return (m->madctl & ZT_MADCTL_MV) ? ZT_PANEL_RAM_W : ZT_PANEL_RAM_H;
}

/* Orientation coordinates -> RAM cell; NULL outside. */
static uint16_t *cell(zt_panel_model *m, uint32_t x, uint32_t y)
{
    uint32_t lx = limit_x(m), ly = limit_y(m), col, row;
    if (x >= lx || y >= ly)
        return NULL;
    if (m->madctl & ZT_MADCTL_MX)
        x = lx - 1u - x;
    if (m->madctl & ZT_MADCTL_MY)
        y = ly - 1u - y;
    col = (m->madctl & ZT_MADCTL_MV) ? y : x;
    row = (m->madctl & ZT_MADCTL_MV) ? x : y;
    return &m->ram[row][col];
}

uint16_t zt_panel_pixel(const zt_panel_model *m, uint32_t x, uint32_t y)
{
    const uint16_t *c = cell((zt_panel_model *)m, x, y);
    return c != NULL ? *c : 0;
}

static void controller_defaults(zt_panel_model *m)
{
    m->colmod = 0x66; /* 18 bits per pixel after reset, on both */
    m->madctl = 0;
    m->sleeping = 1;
    m->display_on = 0;
    m->inverted = 0;
    m->xs = 0;
    m->xe = ZT_PANEL_RAM_W - 1u;
    m->ys = 0;
    m->ye = ZT_PANEL_RAM_H - 1u;
}

void zt_panel_model_reset(zt_panel_model *m, uint8_t controller, uint16_t fill)
{
    uint32_t x, y;
    memset(m, 0, sizeof *m);
    m->controller = controller;
    for (y = 0; y < ZT_PANEL_RAM_H; y++)
        for (x = 0; x < ZT_PANEL_RAM_W; x++)
            m->ram[y][x] = fill;
    m->cmd = -1;
    controller_defaults(m);
}

/* --- the end of a command, when the next begins ---------------------------- */

static void finish_command(zt_panel_model *m)
{
    const command_info *info = m->cmd >= 0 ? lookup(m, m->cmd) : NULL;
    if (info == NULL || m->finished)
        return;
    m->finished = 1; /* a second check does not report it again */
    if (m->cmd == 0x2C) {
        if (m->nparams % 2u != 0)
            fail(m, "RAMWR ended in the middle of a pixel", m->nparams, 0);
    } else if (m->nparams < info->min) {
        fail(m, "command got too few parameters (command, count)", (unsigned)m->cmd, m->nparams);
    }
}

static uint16_t be16(const uint8_t *p)
{
    return (uint16_t)((p[0] << 8) | p[1]);
}

static void set_range(zt_panel_model *m, uint16_t *start, uint16_t *end, uint32_t limit, const char *what)
{
    uint16_t s = be16(m->params), e = be16(m->params + 2);
    if (s > e || e >= limit) {
        fail(m, what, s, e);
        return;
    }
    *start = s;
    *end = e;
}

/* A command byte (D/C low). */
static void start_command(zt_panel_model *m, uint8_t cmd)
{
    finish_command(m);
    m->cmd = cmd;
    m->nparams = 0;
    m->finished = 0;
    if (lookup(m, cmd) == NULL) {
        fail(m, "unknown command", cmd, m->controller);
        return;
    }
    if (m->last_timed_cmd != 0 && m->ms_since_cmd < 5u)
        fail(m, "command sooner than 5 ms after SWRESET/SLPOUT (command, ms)", cmd, m->ms_since_cmd);
    if (cmd == 0x11 && m->reset_seen && m->ms_since_reset < 120u)
        fail(m, "SLPOUT sooner than 120 ms after SWRESET (ms)", m->ms_since_reset, 0);
    m->last_timed_cmd = 0;
    switch (cmd) {
    case 0x01:
        controller_defaults(m);
        m->reset_seen = 1;
        m->ms_since_reset = 0;
        m->last_timed_cmd = cmd;
        m->ms_since_cmd = 0;
        break;
    case 0x10:
        m->sleeping = 1;
        break;
    case 0x11:
        m->sleeping = 0;
        m->last_timed_cmd = cmd;
        m->ms_since_cmd = 0;
        break;
    case 0x20:
    case 0x21:
        m->inverted = (uint8_t)(cmd == 0x21);
        break;
    case 0x28:
    case 0x29:
        m->display_on = (uint8_t)(cmd == 0x29);
        break;
    case 0x2C:
        m->x = m->xs;
        m->y = m->ys;
        m->high = 0;
        m->window_full = 0;
        break;
    default:
        break;
    }
}

static void pixel_byte(zt_panel_model *m, uint8_t byte)
{
    uint16_t *c;
    if (m->colmod != 0x55) {
        if (m->nparams == 1u) /* once per RAMWR */
            fail(m, "pixel data while COLMOD is not 16 bits per pixel (COLMOD)", m->colmod, 0);
        return;
    }
    if (m->nparams % 2u == 1u) { /* first byte of a pixel: the high byte */
        m->high = byte;
        return;
    }
    if (m->window_full) {
        fail(m, "more pixels than the window holds (window width, height)", m->xe - m->xs + 1u,
             m->ye - m->ys + 1u);
        return;
    }
    c = cell(m, m->x, m->y);
    if (c != NULL)
        *c = (uint16_t)((m->high << 8) | byte);
    m->pixels++;
    if (m->x < m->xe) {
        m->x++;
    } else {
        m->x = m->xs;
        if (m->y < m->ye)
            m->y++;
        else
            m->window_full = 1;
    }
}

/* A data byte (D/C high): a parameter, or pixel data after RAMWR. */
static void data_byte(zt_panel_model *m, uint8_t byte)
{
    const command_info *info = m->cmd >= 0 ? lookup(m, m->cmd) : NULL;
    if (m->cmd < 0) {
        fail(m, "data byte before any command (byte)", byte, 0);
        return;
    }
    if (info == NULL)
        return; /* already reported as unknown */
    m->nparams++;
    m->finished = 0;
    if (m->cmd == 0x2C) {
        pixel_byte(m, byte);
        return;
    }
    if (m->nparams > info->max) {
        fail(m, "command got too many parameters (command, count)", (unsigned)m->cmd, m->nparams);
        return;
    }
    if (m->nparams <= sizeof m->params)
        m->params[m->nparams - 1u] = byte;
    if (m->nparams != info->max)
        return;
    switch (m->cmd) {
    case 0x2A:
        set_range(m, &m->xs, &m->xe, limit_x(m), "CASET out of range (start, end)");
        break;
    case 0x2B:
        set_range(m, &m->ys, &m->ye, limit_y(m), "RASET out of range (start, end)");
        break;
    case 0x36:
        m->madctl = byte;
        break;
    case 0x3A:
        m->colmod = byte;
        break;
    default:
        break;
    }
}

static void wire_byte(zt_panel_model *m, uint8_t byte)
{
    m->bytes++;
    if (!m->selected) {
        fail(m, "byte sent while the chip is not selected (byte)", byte, 0);
        return;
    }
    if (m->dc)
        data_byte(m, byte);
    else
        start_command(m, byte);
}

int zt_panel_model_check(zt_panel_model *m)
{
    finish_command(m);
    if (m->dma_busy)
        fail(m, "a DMA transfer was never waited for", 0, 0);
    return m->errors;
}

/* --- the wire -------------------------------------------------------------- */

void zt_panel_select(zt_panel_model *m, int selected)
{
    if (m->dma_busy)
        fail(m, "chip select changed during a DMA transfer", (unsigned)selected, 0);
    m->selected = (uint8_t)(selected != 0);
}

void zt_panel_set_dc(zt_panel_model *m, int data)
{
    if (m->dma_busy)
        fail(m, "D/C changed during a DMA transfer", (unsigned)data, 0);
    m->dc = (uint8_t)(data != 0);
}

void zt_panel_write(zt_panel_model *m, const uint8_t *bytes, size_t count)
{
    size_t i;
    if (m->dma_busy)
        fail(m, "blocking write during a DMA transfer", 0, 0);
    m->transfers++;
    for (i = 0; i < count; i++)
        wire_byte(m, bytes[i]);
}

void zt_panel_dma_start(zt_panel_model *m, const uint8_t *bytes, size_t count)
{
    if (m->dma_busy)
        fail(m, "DMA transfer started while one is in flight", 0, 0);
    m->dma_bytes = bytes;
    m->dma_count = count;
    m->dma_busy = 1;
}

/* The deferred transfer: the bytes are read now, as a slow DMA would read
 * them, so a buffer reused too early sends the wrong pixels. */
void zt_panel_dma_wait(zt_panel_model *m)
{
    size_t i;
    if (!m->dma_busy) {
        fail(m, "write_wait without a transfer", 0, 0);
        return;
    }
    m->dma_busy = 0;
    m->transfers++;
    for (i = 0; i < m->dma_count; i++)
        wire_byte(m, m->dma_bytes[i]);
}

void zt_panel_delay_ms(zt_panel_model *m, uint32_t ms)
{
    m->ms_since_cmd += ms;
    m->ms_since_reset += ms;
}
