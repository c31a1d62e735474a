/* SPDX-License-Identifier: MIT */
/*
 * ATmega2560 firmware of the RotatingModel check: renders the example's
 * frames (port/arduino/examples/RotatingModel/rotating_scene.c, the code the
 * sketch runs) and prints over USART0 the lines the host reference
 * (scene_reference.c) prints, "frame N XXXXXXXX", then "done". Runs under
 * qemu-system-avr -M mega2560 (run-avr.sh), without the Arduino core: only
 * the USART registers, so the frames are zline's alone.
 */
#include "avr_board.h" /* port/avr: USART0, stack mark, QEMU work-arounds */
#include "rotating_scene.h"
#include "scene_checksum.h"

int main(void)
{
    static uint64_t work[ROTATING_SCENE_WORK_WORDS] ROTATING_SCENE_ALIGN8;
    uint16_t i;
    stack_paint();
    usart_init();
    {
        zl_frame_config cfg;
        rotating_scene_config(&cfg);
        usart_puts("# work buffer: ");
        usart_dec((uint16_t)zl_frame_bytes(&cfg));
        usart_puts(" bytes needed\n");
    }
    for (i = 0; i < SCENE_CHECK_FRAMES; i++) {
        uint32_t sum = SCENE_FNV_BASIS;
        int r = rotating_scene_render((uint16_t)(i * SCENE_CHECK_STEP), work, sizeof work, scene_checksum_row, &sum);
        if (r != 0) {
            usart_puts("render error ");
            usart_dec((uint16_t)-r);
            usart_puts("\n");
        }
        usart_puts("frame ");
        usart_dec(i);
        usart_put(' ');
        usart_hex32(sum);
        usart_put('\n');
    }
    usart_puts("# stack: ");
    usart_dec(stack_used());
    usart_puts(" bytes at most\n");
    usart_puts("done\n");
    board_halt();
    return 0;
}
