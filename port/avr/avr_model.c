/* SPDX-License-Identifier: MIT */
/*
 * ATmega2560 firmware of the 8 KB demo (issue 23): renders the torus of
 * model_scene.c at 160x128 in scanline mode and streams every finished row
 * over USART0 as hex, the lines model_reference.c prints on the host:
 *   "# ..." lines (work buffer, replans, stack high-water mark), then per frame
 *   "frame N" and its 128 rows of 320 hex digits, then "done".
 * Each frame is rendered twice: once between two calls of mark() with rows
 * that go nowhere (the instructions of the frame alone, counted by the
 * QEMU plugin at mark's address: run-avr-model.sh), once to stream it.
 * All RAM is static or on the stack: data, bss, stack and zline's work
 * buffer together must stay within the chip's 8 KB (run-avr-model.sh
 * checks the map and the stack mark).
 */
#include "avr_board.h"
#include "model_scene.h"

/* The plugin records the instruction count each time this is entered. */
void mark(void) __attribute__((noinline, used));
void mark(void)
{
    __asm__ volatile("" ::: "memory");
}

static int row_nowhere(void *user, const zl_band *band)
{
    (void)user;
    (void)band;
    return 0;
}

static int row_to_usart(void *user, const zl_band *band)
{
    static const char digits[] PROGMEM = "0123456789abcdef";
    const uint8_t *bytes = (const uint8_t *)band->color;
    uint16_t i, count = (uint16_t)(band->width * 2u * band->rows);
    (void)user;
    for (i = 0; i < count; i++) {
        usart_put((char)pgm_read_byte(&digits[bytes[i] >> 4]));
        usart_put((char)pgm_read_byte(&digits[bytes[i] & 15u]));
    }
    usart_put('\n');
    return 0;
}

static void report_error(int r)
{
    usart_puts_P(PSTR("render error "));
    usart_dec((uint16_t)-r);
    usart_put('\n');
}

int main(void)
{
    static uint64_t work[MODEL_SCENE_WORK_WORDS] MODEL_SCENE_ALIGN8;
    uint16_t i, replans = 0;
    zl_frame_config cfg;
    stack_paint();
    usart_init();
    model_scene_config(&cfg);
    usart_puts_P(PSTR("# work buffer: "));
    usart_dec((uint16_t)zl_frame_bytes(&cfg));
    usart_puts_P(PSTR(" bytes needed of "));
    usart_dec((uint16_t)sizeof work);
    usart_put('\n');
    for (i = 0; i < MODEL_SCENE_CHECK_FRAMES; i++) {
        uint16_t index = (uint16_t)(i * MODEL_SCENE_CHECK_STEP);
        zl_frame_needs_t needs;
        int r;
        mark();
        r = model_scene_render(index, NULL, work, sizeof work, row_nowhere, NULL, &needs);
        mark();
        replans = (uint16_t)(replans + needs.replans); /* over capacity (model_scene.h) */
        if (r != 0)
            report_error(r);
        usart_puts_P(PSTR("frame "));
        usart_dec(index);
        usart_put('\n');
        r = model_scene_render(index, NULL, work, sizeof work, row_to_usart, NULL, NULL);
        if (r != 0)
            report_error(r);
    }
    usart_puts_P(PSTR("# replans: "));
    usart_dec(replans);
    usart_put('\n');
    usart_puts_P(PSTR("# stack: "));
    usart_dec(stack_used());
    usart_puts_P(PSTR(" bytes at most\n"));
    usart_puts_P(PSTR("done\n"));
    board_halt();
    return 0;
}
