/* SPDX-License-Identifier: MIT */
/*
 * Exact instruction counting for the Cortex-M benchmark firmware: QEMU with
 * -icount shift=6 advances TIMER0 (25 MHz) by 1.6 ticks per instruction, so
 * instructions = ceil(5 * ticks / 8) exactly. mark() stores the timer; the
 * cost of an empty interval is calibrated once and subtracted.
 */
#ifndef ZLINE_BENCH_TIMER_H
#define ZLINE_BENCH_TIMER_H

#include <stdint.h>

/* Record a time stamp. A real call (not inlined): measure.sh and the timing
 * plugin find it by its symbol name. */
void mark(void);
/* Number of mark() calls so far: the index the next mark() gets. */
unsigned bench_stamp_count(void);
/* Instructions executed between stamps i and j, measurement cost removed. */
uint32_t bench_between(unsigned i, unsigned j);
/* Start TIMER0, calibrate the empty interval and check that 1000 nops count
 * as 1000 (else QEMU is not running with -icount shift=6): 0 when exact. */
int bench_timer_init(const char *who);

#endif
