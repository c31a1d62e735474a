/* SPDX-License-Identifier: MIT */
/*
 * Board support for the Stellaris LM3S6965 evaluation board (QEMU
 * lm3s6965evb): system clock, an instruction counter on SysTick for QEMU
 * -icount runs, the stack high-water mark, and waiting for the host.
 */
#ifndef ZL_LM3S_BOARD_H
#define ZL_LM3S_BOARD_H

#include <stdint.h>

#define LM3S_SYSCLK_HZ 50000000u

/* Run from the PLL at 50 MHz (8 MHz crystal, 200 MHz PLL / 4). Returns 0,
 * or -1 if the PLL did not lock (the clock is then left on the crystal). */
int lm3s_clock_init(void);

/* SysTick ticks at the processor clock since lm3s_ticks_start(), 64-bit
 * (SysTick itself is 24-bit: its interrupt counts the wraps). */
void lm3s_ticks_start(void);
uint64_t lm3s_ticks(void);

/* The deepest stack use since reset, bytes (the reset handler paints the
 * stack; see startup.c). */
uint32_t lm3s_stack_used(void);

/* Block until the host sends one character on the semihosting console
 * (SYS_READC): the CI test's "captured, go on". */
void lm3s_wait_host(void);

#endif
