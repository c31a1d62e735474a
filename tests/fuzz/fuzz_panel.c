/* SPDX-License-Identifier: MIT */
/*
 * Fuzz target: the SPI panel driver (port/display/zl_spi_panel.c) fed
 * arbitrary configurations (either controller or an unknown one, any
 * MADCTL, visible areas and offsets in and beyond the controller's RAM),
 * blocking or DMA buses, and a sequence of windows, bands (in order or not,
 * of any width, row count, stride and format) and finishes. Its byte stream
 * goes to the controller model of tests/support/zt_panel_model.c (written
 * from the data sheets, independent of the driver). Checked:
 *   - every status against the rules of zl_spi_panel.h, computed here;
 *     a call that fails sends nothing (the model's byte and transfer counts
 *     do not move);
 *   - the model records no protocol error for the whole stream;
 *   - every pixel of the controller's RAM is the band pixel last sent to it,
 *     and no pixel outside the windows opened changed;
 *   - each band's pixels are allocated with exactly
 *     (rows - 1) * stride + width * 2 bytes and no guard, and kept until the
 *     end (a DMA transfer may still be reading them), so a read outside the
 *     band is an AddressSanitizer finding.
 */
#include "fz_common.h"
#include "zl_spi_panel.h"
#include "zt_panel_model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

#define MAX_OPS 12u
#define FILL 0x1234u

static zt_panel_model model;
static uint16_t expect[ZT_PANEL_RAM_H][ZT_PANEL_RAM_H]; /* orientation coordinates, up to 320 x 320 */

static void bus_select(void *user, int selected) { zt_panel_select(user, selected); }
static void bus_set_dc(void *user, int dc) { zt_panel_set_dc(user, dc); }
static void bus_write(void *user, const uint8_t *b, size_t n) { zt_panel_write(user, b, n); }
static void bus_start(void *user, const uint8_t *b, size_t n) { zt_panel_dma_start(user, b, n); }
static void bus_wait(void *user) { zt_panel_dma_wait(user); }
static void bus_delay(void *user, uint32_t ms) { zt_panel_delay_ms(user, ms); }

/* What the driver must be doing, kept here from the header's rules. */
typedef struct {
    zl_panel_config cfg;
    uint16_t x, y, w, h, next_row;
    int windowed;
} shadow;

static zl_status expect_init(const zl_panel_config *c)
{
    uint32_t rw = (c->madctl & ZL_PANEL_MADCTL_MV) ? 320u : 240u, rh = (c->madctl & ZL_PANEL_MADCTL_MV) ? 240u : 320u;
    if (c->controller > 1)
        return ZL_ERR_ARG;
    if (c->width == 0 || c->height == 0 || c->x_offset + c->width > rw || c->y_offset + c->height > rh)
        return ZL_ERR_RANGE;
    return ZL_OK;
}

static uint16_t read_u9(fz_in *in)
{
    return (uint16_t)(fz_u16(in) % 340u);
}

static void op_window(fz_in *in, zl_panel *p, shadow *s)
{
    uint16_t x = read_u9(in), y = read_u9(in), w = read_u9(in), h = read_u9(in);
    zl_status want = (w == 0 || h == 0 || x + w > s->cfg.width || y + h > s->cfg.height) ? ZL_ERR_RANGE : ZL_OK;
    uint32_t bytes = model.bytes;
    zl_status st;
    if (fz_u8(in) & 1u) { /* mostly a window that fits */
        x = (uint16_t)(x % s->cfg.width);
        y = (uint16_t)(y % s->cfg.height);
        w = (uint16_t)(1u + w % (s->cfg.width - x));
        h = (uint16_t)(1u + h % (s->cfg.height - y));
        want = ZL_OK;
    }
    st = zl_panel_window(p, x, y, w, h);
    FZ_REQUIRE(st == want, "window %u,%u %ux%u in %ux%u: %d, expected %d", x, y, w, h, s->cfg.width,
               s->cfg.height, (int)st, (int)want);
    if (st == ZL_OK) {
        s->x = x;
        s->y = y;
        s->w = w;
        s->h = h;
        s->next_row = 0;
        s->windowed = 1;
    } else {
        FZ_REQUIRE(model.bytes == bytes, "a refused window sent %u bytes", model.bytes - bytes);
    }
}

static zl_status expect_band(const shadow *s, const zl_band *b)
{
    if (!s->windowed || b->format != ZL_FORMAT_RGB565_BE)
        return ZL_ERR_ARG;
    if (b->width != s->w || b->first_row != s->next_row || b->rows == 0 || b->first_row + b->rows > s->h ||
        b->color_stride < (int32_t)b->width * 2)
        return ZL_ERR_RANGE;
    return ZL_OK;
}

static void op_band(fz_in *in, zl_panel *p, shadow *s, uint8_t **keep, int in_order)
{
    zl_band b;
    size_t n, i;
    uint8_t *px;
    uint32_t bytes = model.bytes, transfers = model.transfers;
    zl_status want;
    int st;
    memset(&b, 0, sizeof b);
    b.format = ZL_FORMAT_RGB565_BE;
    if (in_order && s->windowed) {
        b.width = s->w;
        b.first_row = s->next_row;
        b.rows = (uint16_t)(s->h > s->next_row ? 1u + fz_u8(in) % (unsigned)(s->h - s->next_row) : 1u);
        b.color_stride = (int32_t)(b.width * 2u + (fz_u8(in) % 3u) * 2u);
    } else {
        b.width = (uint16_t)(1u + read_u9(in));
        b.first_row = read_u9(in);
        b.rows = (uint16_t)(fz_u8(in) % 8u);
        b.color_stride = (int32_t)(b.width * 2u) + (int32_t)(int8_t)fz_u8(in) % 5;
        b.format = (uint8_t)(fz_u8(in) % 3u);
    }
    n = b.rows == 0 || b.color_stride < (int32_t)b.width * 2
            ? 1u
            : (size_t)(b.rows - 1u) * (size_t)b.color_stride + b.width * 2u;
    px = (uint8_t *)malloc(n);
    if (px == NULL)
        abort();
    for (i = 0; i < n; i++)
        px[i] = (uint8_t)(fz_u8(in) ^ (i * 131u));
    *keep = px;
    b.color = px;
    want = expect_band(s, &b);
    st = zl_panel_send_band(p, &b);
    FZ_REQUIRE(st == (int)want, "band rows %u+%u width %u stride %ld format %u: %d, expected %d", b.first_row,
               b.rows, b.width, (long)b.color_stride, b.format, st, (int)want);
    if (st != 0) {
        FZ_REQUIRE(model.bytes == bytes && model.transfers == transfers, "a refused band sent bytes");
        return;
    }
    for (i = 0; i < (size_t)b.rows * b.width; i++) {
        size_t r = i / b.width, c = i % b.width;
        const uint8_t *q = px + r * (size_t)b.color_stride + c * 2u;
        expect[s->cfg.y_offset + s->y + b.first_row + r][s->cfg.x_offset + s->x + c] =
            (uint16_t)(q[0] << 8 | q[1]);
    }
    s->next_row = (uint16_t)(s->next_row + b.rows);
}

static void op_finish(zl_panel *p, shadow *s)
{
    zl_status want = s->windowed && s->next_row == s->h ? ZL_OK : ZL_ERR_ARG;
    zl_status st = zl_panel_finish(p);
    FZ_REQUIRE(st == want, "finish: %d, expected %d", (int)st, (int)want);
    s->windowed = 0;
}

static void check_ram(const shadow *s)
{
    uint32_t rw = (s->cfg.madctl & ZL_PANEL_MADCTL_MV) ? 320u : 240u;
    uint32_t rh = (s->cfg.madctl & ZL_PANEL_MADCTL_MV) ? 240u : 320u, x, y;
    for (y = 0; y < rh; y++)
        for (x = 0; x < rw; x++)
            FZ_REQUIRE(zt_panel_pixel(&model, x, y) == expect[y][x], "RAM pixel %u,%u: %04x, expected %04x", x, y,
                       zt_panel_pixel(&model, x, y), expect[y][x]);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_in in = {data, size};
    zl_panel_config cfg;
    zl_panel_bus bus;
    zl_panel panel;
    shadow s;
    uint8_t *keep[MAX_OPS];
    unsigned ops, i, y, x;
    uint32_t f = fz_u8(&in);
    zl_status st, want;
    memset(&cfg, 0, sizeof cfg);
    memset(keep, 0, sizeof keep);
    cfg.controller = (uint8_t)(fz_u8(&in) % 3u);
    cfg.madctl = (uint8_t)fz_u8(&in);
    cfg.invert = (uint8_t)(fz_u8(&in) & 1u);
    cfg.width = read_u9(&in);
    cfg.height = read_u9(&in);
    cfg.x_offset = (uint16_t)(fz_u8(&in) % 90u);
    cfg.y_offset = (uint16_t)(fz_u8(&in) % 90u);
    if (f & 1u) { /* mostly a visible area that fits */
        uint16_t rw = (cfg.madctl & ZL_PANEL_MADCTL_MV) ? 320u : 240u, rh = (cfg.madctl & ZL_PANEL_MADCTL_MV) ? 240u : 320u;
        cfg.x_offset = (uint16_t)(cfg.x_offset % rw);
        cfg.y_offset = (uint16_t)(cfg.y_offset % rh);
        cfg.width = (uint16_t)(1u + cfg.width % (rw - cfg.x_offset));
        cfg.height = (uint16_t)(1u + cfg.height % (rh - cfg.y_offset));
    }
    memset(&bus, 0, sizeof bus);
    bus.user = &model;
    bus.select = bus_select;
    bus.set_dc = bus_set_dc;
    bus.write = bus_write;
    bus.delay_ms = bus_delay;
    if (f & 2u) {
        bus.write_start = bus_start;
        bus.write_wait = bus_wait;
    }
    zt_panel_model_reset(&model, cfg.controller == ZL_PANEL_ILI9341 ? ZT_PANEL_ILI9341 : ZT_PANEL_ST7789, FILL);
    for (y = 0; y < ZT_PANEL_RAM_H; y++)
        for (x = 0; x < ZT_PANEL_RAM_H; x++)
            expect[y][x] = FILL;
    want = expect_init(&cfg);
    st = zl_panel_init(&panel, &cfg, &bus);
    FZ_REQUIRE(st == want, "init %u madctl %02x %ux%u at %u,%u: %d, expected %d", cfg.controller, cfg.madctl,
               cfg.width, cfg.height, cfg.x_offset, cfg.y_offset, (int)st, (int)want);
    if (st != ZL_OK) {
        FZ_REQUIRE(model.bytes == 0, "a refused init sent %u bytes", model.bytes);
        return 0;
    }
    memset(&s, 0, sizeof s);
    s.cfg = cfg;
    ops = fz_u8(&in) % (MAX_OPS + 1u);
    for (i = 0; i < ops; i++) {
        switch (fz_u8(&in) % 5u) {
        case 0:
        case 1:
            op_window(&in, &panel, &s);
            break;
        case 2:
        case 3:
            op_band(&in, &panel, &s, &keep[i], (fz_u8(&in) % 4u) != 0);
            break;
        default:
            op_finish(&panel, &s);
            break;
        }
    }
    op_finish(&panel, &s); /* waits for the last transfer */
    FZ_REQUIRE(zt_panel_model_check(&model) == 0, "protocol error: %s", model.first_error);
    check_ram(&s);
    for (i = 0; i < MAX_OPS; i++)
        free(keep[i]);
    return 0;
}
