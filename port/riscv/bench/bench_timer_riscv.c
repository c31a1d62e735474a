/* SPDX-License-Identifier: MIT */
/*
 * Exact instruction counting for the RISC-V benchmark firmware
 * (../../cortex-m/bench/bench_timer.h, the interface bench.c uses).
 *
 * QEMU 7.2's riscv32 reads minstret from the virtual clock when -icount is
 * on: with shift=0 one instruction is one nanosecond, so minstret is the
 * exact count of instructions executed (plus a constant; measured: 1000 nops
 * count 1000, and 8000 at shift=3). Without -icount it follows the host's
 * clock, so bench_timer_init checks the count on a run of exactly 1000 nops
 * and refuses to go on if it is not 1000.
 * The CLINT's mtime (10 MHz on virt) would count only every 100th
 * instruction at shift=0: minstret is both exact and simpler.
 */
#include "bench_timer.h"

#include <stdio.h>

#define MAX_STAMPS 1024
static uint32_t stamps[MAX_STAMPS];
static unsigned stamp_count;
static uint32_t overhead; /* instructions of an empty interval */

static inline uint32_t read_minstret(void)
{
    uint32_t v;
    __asm__ volatile("csrr %0, minstret" : "=r"(v));
    return v;
}

/* A real call: every interval then includes the same call and return. */
__attribute__((noinline)) void mark(void)
{
    uint32_t v = read_minstret();
    if (stamp_count < MAX_STAMPS)
        stamps[stamp_count] = v;
    stamp_count++;
}

unsigned bench_stamp_count(void)
{
    return stamp_count;
}

/* Unsigned differences: exact across a wrap of the low 32 bits. */
uint32_t bench_between(unsigned i, unsigned j)
{
    return stamps[j] - stamps[i] - overhead;
}

int bench_timer_init(const char *who)
{
    unsigned a, c;
    uint32_t b;
    a = stamp_count;
    mark();
    mark();
    overhead = 0;
    overhead = bench_between(a, a + 1);
    /* 1000 nops: the count must be exactly 1000 */
    c = stamp_count;
    mark();
    __asm__ volatile(".rept 1000\n nop\n .endr");
    mark();
    b = bench_between(c, c + 1);
    if (b != 1000) {
        printf("%s: 1000 nops counted as %lu (is QEMU running with -icount shift=0?)\n", who, (unsigned long)b);
        return 1;
    }
    printf("# timer: minstret exact (1000 nops = 1000), measurement overhead %lu instructions subtracted\n",
           (unsigned long)overhead);
    return 0;
}
