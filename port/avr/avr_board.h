/* SPDX-License-Identifier: MIT */
/*
 * What the ATmega2560 firmware of the tests share (port/avr/avr_model.c,
 * port/arduino/test/avr_scene.c), without the Arduino core: USART0 output
 * (QEMU's -serial), a stack high-water mark, and two work-arounds for QEMU
 * 7.2's AVR emulation (SCENE_QEMU_DATA_PRELOAD). Include it from one
 * translation unit of a firmware: its functions are static.
 */
#ifndef AVR_BOARD_H
#define AVR_BOARD_H

#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/pgmspace.h>
#include <avr/sleep.h>
#include <stdint.h>

/*
 * QEMU 7.2 (Debian 12) reads flash above 64 KB wrongly: its ELPM ignores
 * RAMPZ and reads the low 64 KB (checked with a 90 KB program: ELPM of
 * 0x16100 returns the bytes at 0x6100). avr-libc's start-up copies .data's
 * initial values from flash with ELPM, and with zline linked they lie above
 * 64 KB, so .data would start as garbage (on a real ATmega2560 it does
 * not). Here the start-up copy is left out (this empty __do_copy_data
 * replaces libgcc's) and run-avr.sh has QEMU load .data's image straight
 * into SRAM (-device loader). Nothing else in the program reads flash as
 * data above 64 KB (switch tables are placed low).
 */
#ifdef SCENE_QEMU_DATA_PRELOAD
__asm__(".section .init4,\"ax\",@progbits\n"
        ".global __do_copy_data\n"
        "__do_copy_data:\n"
        ".text\n");
#endif

/*
 * QEMU 7.2 also loops forever on libgcc's __clzsi2 and __clzdi2 (count
 * leading zeros of 32 and 64 bits, behind __builtin_clzl/clzll): each
 * returns from a call into "SBRS rN, b; RET", and QEMU never leaves that
 * skip when it is taken (a ten-line program calling __builtin_clzl(0x1234)
 * hangs on -M mega2560 and -M uno alike). These replacements, linked
 * before libgcc, count the same bits without that pattern.
 */
#ifdef SCENE_QEMU_DATA_PRELOAD
int __clzsi2(unsigned long v) __attribute__((used));
int __clzdi2(unsigned long long v) __attribute__((used));
int __clzsi2(unsigned long v)
{
    int n = 0;
    if (v == 0)
        return 32;
    while ((v & 0x80000000UL) == 0) {
        v <<= 1;
        n++;
    }
    return n;
}
int __clzdi2(unsigned long long v)
{
    unsigned long hi = (unsigned long)(v >> 32);
    int n = __clzsi2(hi != 0 ? hi : (unsigned long)v);
    return hi != 0 ? n : 32 + n;
}
#endif

static void usart_put(char c)
{
    while (!(UCSR0A & (1 << UDRE0)))
        ;
    UDR0 = (uint8_t)c;
}

static void usart_puts(const char *s)
{
    while (*s)
        usart_put(*s++);
}

/* A string kept in flash (PSTR("...")): string literals would take SRAM. */
static void usart_puts_P(const char *s)
{
    char c;
    while ((c = (char)pgm_read_byte(s++)) != 0)
        usart_put(c);
}

static void usart_hex32(uint32_t v)
{
    static const char digits[] = "0123456789abcdef";
    int8_t shift;
    for (shift = 28; shift >= 0; shift -= 4)
        usart_put(digits[(v >> shift) & 15u]);
}

static void usart_dec(uint16_t v)
{
    char buf[6];
    uint8_t n = 0;
    do {
        buf[n++] = (char)('0' + v % 10u);
        v /= 10u;
    } while (v != 0);
    while (n > 0)
        usart_put(buf[--n]);
}

/* Stack high-water mark: main paints the free RAM between the end of .bss
 * and its own stack frame; after the frames, the first byte from the bottom
 * that changed shows how deep the stack went. */
extern uint8_t __heap_start;
#define STACK_PAINT 0xa5u

static void stack_paint(void)
{
    uint8_t *p = &__heap_start;
    uint8_t *top = (uint8_t *)SP - 64; /* leave main's frame alone */
    while (p < top)
        *p++ = STACK_PAINT;
}

static uint16_t stack_used(void)
{
    const uint8_t *p = &__heap_start;
    while (p <= (const uint8_t *)RAMEND && *p == STACK_PAINT)
        p++;
    return (uint16_t)((const uint8_t *)RAMEND + 1 - p);
}

/* USART0 on, transmit only: 115200 baud at 16 MHz (QEMU ignores the rate). */
static void usart_init(void)
{
    UBRR0 = 8;
    UCSR0B = (uint8_t)(1 << TXEN0);
}

/* Stop for good: the test runner ends QEMU when it has read "done". */
static void board_halt(void)
{
    cli();
    for (;;)
        sleep_mode();
}

#endif
