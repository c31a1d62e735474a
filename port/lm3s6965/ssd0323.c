/* SPDX-License-Identifier: MIT */
/*
 * SSD0323 driver on the LM3S6965's SSI0: see ssd0323.h. Command numbers and
 * the initialisation values are from the SSD0323 data sheet (Solomon Systech)
 * for the OSRAM Pictiva 128x64 panel as the evaluation board wires it.
 *
 * OLED_FAULT (a build option of the CI test's negative controls only):
 *   1  nibbles swapped within each data byte
 *   2  D/C raised one byte early: the window's last address goes as data
 *   3  the window's column range one byte short
 * Each must make the QEMU display test fail.
 */
#include "ssd0323.h"

#include "lm3s6965.h"
#include "zl_grey4.h"

#ifndef OLED_FAULT
#define OLED_FAULT 0
#endif

#define PIN_SSI_CLK (1u << 2) /* PA2 */
#define PIN_SSI_FSS (1u << 3) /* PA3 */
#define PIN_SSI_TX (1u << 5)  /* PA5 */
#define PIN_DC (1u << 7)      /* PC7 */
#define PIN_SD_CS (1u << 0)   /* PD0 */

enum {
    CMD_SET_COLUMN = 0x15,
    CMD_SET_ROW = 0x75,
    CMD_CONTRAST = 0x81,
    CMD_HALF_CURRENT = 0x85,
    CMD_REMAP = 0xA0,
    CMD_START_LINE = 0xA1,
    CMD_OFFSET = 0xA2,
    CMD_NORMAL_DISPLAY = 0xA4,
    CMD_MULTIPLEX = 0xA8,
    CMD_PHASE_LENGTH = 0xB1,
    CMD_ROW_PERIOD = 0xB2,
    CMD_CLOCK = 0xB3,
    CMD_GREY_TABLE = 0xB8,
    CMD_PRECHARGE = 0xBC,
    CMD_VCOMH = 0xBE,
    CMD_VSL = 0xBF,
    CMD_DISPLAY_ON = 0xAF
};

/* --- SSI0 -------------------------------------------------------------- */

/* Every byte sent also clocks one into the receive FIFO: read them away,
 * or the SSI stops sending once that FIFO is full. */
static void ssi_drain_rx(void)
{
    while (SSI0_SR & SSI_SR_RNE)
        (void)SSI0_DR;
}

static void ssi_send(uint8_t byte)
{
    while (!(SSI0_SR & SSI_SR_TNF))
        ssi_drain_rx();
    SSI0_DR = byte;
    ssi_drain_rx();
}

/* Wait until the last bit is out: D/C must not change under a byte still
 * being shifted (the controller samples it with the byte's last bit). */
static void ssi_flush(void)
{
    while (SSI0_SR & SSI_SR_BSY)
        ssi_drain_rx();
    ssi_drain_rx();
}

static void dc_set(int data)
{
    ssi_flush();
    GPIO_DATA_MASKED(GPIO_PORTC, PIN_DC) = data ? PIN_DC : 0u;
}

static void send_command(const uint8_t *bytes, size_t count)
{
    size_t i;
    dc_set(0);
    for (i = 0; i < count; i++)
        ssi_send(bytes[i]);
}

/* --- set-up ------------------------------------------------------------ */

static void pins_init(void)
{
    SYSCTL_RCGC1 |= SYSCTL_RCGC1_SSI0;
    SYSCTL_RCGC2 |= SYSCTL_RCGC2_GPIOA | SYSCTL_RCGC2_GPIOC | SYSCTL_RCGC2_GPIOD;
    GPIO_AFSEL(GPIO_PORTA) |= PIN_SSI_CLK | PIN_SSI_FSS | PIN_SSI_TX;
    GPIO_DEN(GPIO_PORTA) |= PIN_SSI_CLK | PIN_SSI_FSS | PIN_SSI_TX;
    GPIO_DIR(GPIO_PORTC) |= PIN_DC;
    GPIO_DEN(GPIO_PORTC) |= PIN_DC;
    GPIO_DATA_MASKED(GPIO_PORTC, PIN_DC) = 0;
    GPIO_DIR(GPIO_PORTD) |= PIN_SD_CS;
    GPIO_DEN(GPIO_PORTD) |= PIN_SD_CS;
    GPIO_DATA_MASKED(GPIO_PORTD, PIN_SD_CS) = PIN_SD_CS;
}

static void ssi_init(void)
{
    SSI0_CR1 = 0; /* disabled while configured; master */
    /* SPI frame format, SPO = SPH = 1 (mode 3: the SSD0323 samples on the
     * rising edge), 8-bit frames; bit rate = 50 MHz / (CPSR * (1 + SCR))
     * = 50 MHz / (2 * 7) = 3.57 MHz. */
    SSI0_CPSR = 2;
    SSI0_CR0 = (6u << SSI_CR0_SCR_SHIFT) | (1u << 7) | (1u << 6) | SSI_CR0_DSS_8BIT;
    SSI0_CR1 = SSI_CR1_SSE;
}

/* The OSRAM 128x64 panel's settings. Remap 0x50: odd/even COM split and
 * COM scan remapped, as the panel is wired; column order and nibble order
 * as written (nibble remap off: the left pixel of a byte is its high
 * nibble, which is also the only layout QEMU's model shows). The grey
 * table has 8 entries: the data sheet's command takes 8 parameter bytes. */
static const uint8_t init_sequence[] = {
    CMD_SET_COLUMN, 0x00, 0x3F,
    CMD_SET_ROW, 0x00, 0x3F,
    CMD_CONTRAST, 0x33,
    CMD_HALF_CURRENT,
    CMD_REMAP, 0x50,
    CMD_START_LINE, 0x00,
    CMD_OFFSET, 0x4C,
    CMD_NORMAL_DISPLAY,
    CMD_MULTIPLEX, 0x3F,
    CMD_PHASE_LENGTH, 0x22,
    CMD_ROW_PERIOD, 0x46,
    CMD_CLOCK, 0x41,
    CMD_VSL, 0x0D,
    CMD_VCOMH, 0x02,
    CMD_PRECHARGE, 0x2B,
    CMD_GREY_TABLE, 0x01, 0x11, 0x22, 0x32, 0x43, 0x54, 0x65, 0x76,
    CMD_DISPLAY_ON,
};

void ssd0323_init(void)
{
    pins_init();
    ssi_init();
    send_command(init_sequence, sizeof init_sequence);
    ssi_flush();
}

/* --- drawing ----------------------------------------------------------- */

int ssd0323_window(uint16_t x0, uint16_t y0, uint16_t x1, uint16_t y1)
{
    uint8_t cmd[6];
    if (x0 > x1 || y0 > y1 || x1 >= SSD0323_WIDTH || y1 >= SSD0323_HEIGHT || (x0 & 1u) || !(x1 & 1u))
        return -1;
    cmd[0] = CMD_SET_COLUMN;
    cmd[1] = (uint8_t)(x0 / 2u);
    cmd[2] = (uint8_t)(x1 / 2u - (OLED_FAULT == 3 ? 1u : 0u));
    cmd[3] = CMD_SET_ROW;
    cmd[4] = (uint8_t)y0;
    cmd[5] = (uint8_t)y1;
#if OLED_FAULT == 2
    send_command(cmd, 5);
    ssd0323_data(&cmd[5], 1);
#else
    send_command(cmd, sizeof cmd);
#endif
    return 0;
}

void ssd0323_data(const uint8_t *bytes, size_t count)
{
    size_t i;
    dc_set(1);
    for (i = 0; i < count; i++)
        ssi_send(bytes[i]);
}

int ssd0323_send_band(void *user, const zl_band *band)
{
    uint8_t packed[SSD0323_WIDTH / 2];
    const uint8_t *row = band->color;
    uint16_t r;
    (void)user;
    if (band->format != ZL_FORMAT_RGB565 || band->width != SSD0323_WIDTH)
        return 1;
    for (r = 0; r < band->rows; r++) {
        zl_grey4_pack_row(packed, (const uint16_t *)(const void *)(row + (size_t)r * (size_t)band->color_stride),
                          band->width);
#if OLED_FAULT == 1
        {
            size_t i;
            for (i = 0; i < sizeof packed; i++)
                packed[i] = (uint8_t)((packed[i] >> 4) | (packed[i] << 4));
        }
#endif
        ssd0323_data(packed, sizeof packed);
    }
    return 0;
}
