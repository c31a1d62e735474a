/* SPDX-License-Identifier: MIT */
/*
 * The ATmega2560 side of the portable unit suite (tests/test_*.c) under
 * qemu-system-avr (port/avr/run-avr-test.sh). A test is compiled with
 * -Dmain=avr_test_main; this file's main points stdout at USART0, paints
 * the free RAM, runs the test and prints, after Unity's own lines:
 *   "# exit N"            the test's return value, its failure count
 *   "# stack: N bytes"    the stack's high-water mark
 *   "# stack overflow"    when the stack reached the end of .bss
 *   "done"                the runner's cue to stop QEMU
 */
#include "avr_board.h"

#include <stdio.h>

int avr_test_main(void);

static int usart_stream_put(char c, FILE *stream)
{
    (void)stream;
    usart_put(c);
    return 0;
}

static FILE usart_stream = FDEV_SETUP_STREAM(usart_stream_put, NULL, _FDEV_SETUP_WRITE);

int main(void)
{
    int result;
    usart_init();
    stdout = &usart_stream;
    stack_paint();
    result = avr_test_main();
    usart_puts("\n# exit ");
    usart_dec((uint16_t)result);
    usart_puts("\n# stack: ");
    usart_dec(stack_used());
    usart_puts(" bytes\n");
    if (__heap_start != STACK_PAINT)
        usart_puts("# stack overflow: it reached the end of .bss\n");
    usart_puts("done\n");
    board_halt();
    return 0;
}
