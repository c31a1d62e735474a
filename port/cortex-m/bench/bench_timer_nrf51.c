/* SPDX-License-Identifier: MIT */
/*
 * Exact instruction counting on QEMU's microbit board (the Cortex-M0 build,
 * port/cortex-m/qemu.cmake), the same interface as bench_timer.c.
 *
 * The nRF51 TIMER0 at 0x40008000, 32-bit, prescaler 1: 8 MHz, 125 ns a tick.
 * QEMU runs with -icount shift=7: every instruction advances virtual time by
 * exactly 128 ns. QEMU's model derives the counter from virtual time as
 * floor(ns / 125), and with a prescaler of 1 its tick length is a whole
 * number of nanoseconds, so resynchronising it on every capture loses
 * nothing (with prescaler 0, 62.5 ns a tick, each resync would drop half a
 * nanosecond and the count would drift). n instructions after the start the
 * counter reads k = floor(1.024 n); 1.024 > 1 makes n unique: exactly
 * ceil(125 k / 128). The counter wraps after 2^32 ticks, about 4.2 G
 * instructions, far beyond a benchmark run.
 *
 * Reading the counter takes a task: writing 1 to TASKS_CAPTURE[0] copies it
 * to CC[0]. mark() does both; its cost (an empty interval) is calibrated and
 * subtracted as in bench_timer.c, and a call of 1000 nops must count as
 * 1002 (bl, the nops, bx lr). The nops sit in a function of their own: 2000
 * bytes inline would put the caller's literal pool out of Thumb-1's reach.
 */
#include "bench_timer.h"

#include <stdio.h>

#define TIMER0_BASE 0x40008000u
#define TIMER0_REG(off) (*(volatile uint32_t *)(TIMER0_BASE + (off)))
#define TIMER0_TASKS_START TIMER0_REG(0x000u)
#define TIMER0_TASKS_STOP TIMER0_REG(0x004u)
#define TIMER0_TASKS_CLEAR TIMER0_REG(0x00Cu)
#define TIMER0_TASKS_CAPTURE0 TIMER0_REG(0x040u)
#define TIMER0_MODE TIMER0_REG(0x504u)
#define TIMER0_BITMODE TIMER0_REG(0x508u)
#define TIMER0_PRESCALER TIMER0_REG(0x510u)
#define TIMER0_CC0 TIMER0_REG(0x540u)

#define MAX_STAMPS 1024
static uint32_t stamps[MAX_STAMPS];
static unsigned stamp_count;
static uint32_t overhead; /* instructions of an empty interval */

__attribute__((noinline)) void mark(void)
{
    uint32_t v;
    TIMER0_TASKS_CAPTURE0 = 1;
    v = TIMER0_CC0;
    if (stamp_count < MAX_STAMPS)
        stamps[stamp_count] = v;
    stamp_count++;
}

/* 1000 nops and the return: 1001 instructions, 1002 with the call. */
__attribute__((naked, noinline)) static void nops_1000(void)
{
    __asm__ volatile(".rept 1000\n nop\n .endr\n bx lr");
}

unsigned bench_stamp_count(void)
{
    return stamp_count;
}

/* Instructions since the timer started at stamp i (shift 7: see the top). */
static uint32_t stamp_insns(unsigned i)
{
    uint64_t k = stamps[i];
    return (uint32_t)((125u * k + 127u) / 128u);
}

uint32_t bench_between(unsigned i, unsigned j)
{
    return stamp_insns(j) - stamp_insns(i) - overhead;
}

int bench_timer_init(const char *who)
{
    unsigned a, c;
    uint32_t b;
    TIMER0_TASKS_STOP = 1;
    TIMER0_MODE = 0;      /* timer (not counter) */
    TIMER0_BITMODE = 3;   /* 32 bits */
    TIMER0_PRESCALER = 1; /* 16 MHz / 2: a whole 125 ns a tick */
    TIMER0_TASKS_CLEAR = 1;
    TIMER0_TASKS_START = 1;
    a = stamp_count;
    mark();
    mark();
    overhead = 0;
    overhead = bench_between(a, a + 1);
    /* bl, 1000 nops, bx lr: the conversion must give exactly 1002 */
    c = stamp_count;
    mark();
    nops_1000();
    mark();
    b = bench_between(c, c + 1);
    if (b != 1002) {
        printf("%s: a call of 1000 nops counted as %lu, not 1002 (is QEMU running microbit with -icount shift=7?)\n",
               who, (unsigned long)b);
        return 1;
    }
    printf("# timer: exact (a call of 1000 nops = 1002), measurement overhead %lu instructions subtracted\n",
           (unsigned long)overhead);
    return 0;
}
