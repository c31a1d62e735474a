/* SPDX-License-Identifier: MIT */
/*
 * Start-up for the LM3S6965 (lm3s6965.ld): the vector table, the reset
 * handler and fault handlers that stop at once.
 *
 * Reset copies .data from flash, zeroes .bss, paints the unused stack with a
 * pattern (so lm3s_stack_used() can tell the deepest stack use afterwards)
 * and calls main; main's return value ends the program through semihosting
 * (QEMU's exit code). A fault prints its exception number and stops with
 * exit code 240 + number, so a crash fails a test at once instead of
 * hanging it until a timeout.
 */
#include <stdint.h>

#include "lm3s_board.h"
#include "semihosting.h"

extern uint32_t __data_load[], __data_start[], __data_end[];
extern uint32_t __bss_start[], __bss_end[];
extern uint32_t __stack_bottom[], __stack_top[];

int main(void);
void Reset_Handler(void) __attribute__((noreturn));
void lm3s_fault(void) __attribute__((noreturn));
void SysTick_Handler(void);

#define STACK_PAINT 0x5A17C0DEu

/* 16 system vectors (word 0, the initial stack pointer, comes from the
 * linker script) and the LM3S6965's interrupts up to SSI0 (number 7): the
 * firmware enables none of them, so they all fault. */
typedef void (*lm3s_vector)(void);
__attribute__((section(".vectors"), used)) const lm3s_vector lm3s_vectors[15 + 8] = {
    Reset_Handler, lm3s_fault, lm3s_fault, lm3s_fault, lm3s_fault, lm3s_fault,
    0, 0, 0, 0,
    lm3s_fault, lm3s_fault, 0, lm3s_fault, SysTick_Handler,
    lm3s_fault, lm3s_fault, lm3s_fault, lm3s_fault, lm3s_fault, lm3s_fault, lm3s_fault, lm3s_fault,
};

/* Paint from the bottom of the stack up to a little below the live stack
 * pointer (this function's own frame stays intact). */
static void paint_stack(void)
{
    uint32_t *p = __stack_bottom;
    uint32_t *sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    while (p < sp - 16)
        *p++ = STACK_PAINT;
}

uint32_t lm3s_stack_used(void)
{
    const uint32_t *p = __stack_bottom;
    while (p < __stack_top && *p == STACK_PAINT)
        p++;
    return (uint32_t)((uintptr_t)__stack_top - (uintptr_t)p);
}

void Reset_Handler(void)
{
    uint32_t *src = __data_load, *dst = __data_start;
    while (dst < __data_end)
        *dst++ = *src++;
    for (dst = __bss_start; dst < __bss_end; dst++)
        *dst = 0;
    paint_stack();
    zl_semi_exit(main());
}

void lm3s_fault(void)
{
    uint32_t ipsr;
    char msg[] = "*** fault: exception   \n";
    __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
    ipsr &= 0x1ffu;
    msg[21] = (char)('0' + ipsr / 10u % 10u);
    msg[22] = (char)('0' + ipsr % 10u);
    zl_semi_puts(msg);
    zl_semi_exit((int)(240u + (ipsr < 15u ? ipsr : 15u)));
}
