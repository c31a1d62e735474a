/* SPDX-License-Identifier: MIT */
/*
 * How many random rounds a test runs. A slow emulated target divides them
 * (the ATmega2560 under qemu-system-avr runs some tens of millions of AVR
 * instructions a second, and 64-bit arithmetic is a library call there):
 * port/avr/run-avr-test.sh passes -DZT_ROUNDS_DIVISOR. Every other target
 * runs the full count. The loops count in uint32_t: 100000 rounds do not
 * fit an int of 16 bits.
 *
 * ZT_SMALL_RAM 1: the target has a few KB of RAM (the ATmega2560's 8 KB);
 * a test whose buffers would not fit takes smaller sizes that keep what it
 * checks (port/avr/run-avr-test.sh passes it).
 */
#ifndef ZT_ROUNDS_H
#define ZT_ROUNDS_H

#include <stdint.h>

#ifndef ZT_ROUNDS_DIVISOR
#define ZT_ROUNDS_DIVISOR 1
#endif

#ifndef ZT_SMALL_RAM
#define ZT_SMALL_RAM 0
#endif

/* zline wants its RGB565 colour and depth buffers 2-byte aligned (zline.h),
 * which a uint16_t array is not on every target: avr-gcc aligns it to 1.
 * A test's static buffers say so with ZT_ALIGNED(2). */
#if defined(__GNUC__)
#define ZT_ALIGNED(n) __attribute__((aligned(n)))
#else
#define ZT_ALIGNED(n)
#endif

#define ZT_ROUNDS(n) ((uint32_t)(n) / (uint32_t)(ZT_ROUNDS_DIVISOR))

#endif
