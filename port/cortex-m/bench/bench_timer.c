/* SPDX-License-Identifier: MIT */
/* Exact instruction counting with TIMER0 under QEMU -icount (bench_timer.h). */
#include "bench_timer.h"

#include <stdio.h>

#define TIMER0_CTRL (*(volatile uint32_t *)0x40000000u)
#define TIMER0_VALUE (*(volatile uint32_t *)0x40000004u)
#define TIMER0_RELOAD (*(volatile uint32_t *)0x40000008u)

#define MAX_STAMPS 1024
static uint32_t stamps[MAX_STAMPS];
static unsigned stamp_count;
static uint32_t overhead; /* instructions of an empty interval */

__attribute__((noinline)) void mark(void)
{
    uint32_t v = TIMER0_VALUE;
    if (stamp_count < MAX_STAMPS)
        stamps[stamp_count] = v;
    stamp_count++;
}

unsigned bench_stamp_count(void)
{
    return stamp_count;
}

/* Instructions since the timer started at stamp i (shift 6: see the top). */
static uint32_t stamp_insns(unsigned i)
{
    uint64_t k = 0xFFFFFFFFu - stamps[i];
    return (uint32_t)((5u * k + 7u) / 8u);
}

uint32_t bench_between(unsigned i, unsigned j)
{
    return stamp_insns(j) - stamp_insns(i) - overhead;
}

int bench_timer_init(const char *who)
{
    unsigned a, c;
    uint32_t b;
    TIMER0_CTRL = 0;
    TIMER0_RELOAD = 0xFFFFFFFFu;
    TIMER0_VALUE = 0xFFFFFFFFu;
    TIMER0_CTRL = 1;
    a = stamp_count;
    mark();
    mark();
    overhead = 0;
    overhead = bench_between(a, a + 1);
    /* 1000 nops: the conversion must give exactly 1000 */
    c = stamp_count;
    mark();
    __asm__ volatile(".rept 1000\n nop\n .endr");
    mark();
    b = bench_between(c, c + 1);
    if (b != 1000) {
        printf("%s: 1000 nops counted as %lu (is QEMU running with -icount shift=6?)\n", who, (unsigned long)b);
        return 1;
    }
    printf("# timer: exact (1000 nops = 1000), measurement overhead %lu instructions subtracted\n",
           (unsigned long)overhead);
    return 0;
}
