/* SPDX-License-Identifier: MIT */
/*
 * How many random rounds a test runs. A slow emulated target divides them
 * (the ATmega2560 under qemu-system-avr runs some tens of millions of AVR
 * instructions a second, and 64-bit arithmetic is a library call there):
 * port/avr/run-avr-test.sh passes -DZT_ROUNDS_DIVISOR. Every other target
 * runs the full count. The loops count in uint32_t: 100000 rounds do not
 * fit an int of 16 bits.
 */
#ifndef ZT_ROUNDS_H
#define ZT_ROUNDS_H

#include <stdint.h>

#ifndef ZT_ROUNDS_DIVISOR
#define ZT_ROUNDS_DIVISOR 1
#endif

#define ZT_ROUNDS(n) ((uint32_t)(n) / (uint32_t)(ZT_ROUNDS_DIVISOR))

#endif
