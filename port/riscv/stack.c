/* SPDX-License-Identifier: MIT */
/* The program stack: a guard at its bottom, and the high-water mark by
 * painting; see zl_port.h. */
#include <stdint.h>

#include "zl_port.h"

/* picolibc.ld: the stack is __heap_end .. __stack (the heap stops below it). */
extern uint32_t __heap_end[], __stack[];

#define ZL_PORT_STACK_PAINT 0xA5C3E1F0u

/*
 * Stack guard: PMP entry 0 makes the lowest ZL_PORT_STACK_GUARD bytes of the
 * stack inaccessible, so an overflow stops at once with a store access fault
 * (mcause 7) and picolibc's trap report, whose handler starts over at the top
 * of the stack. An M-mode access is checked against a PMP entry only when
 * the entry is locked, so it is locked (until reset, which ends the run
 * anyway). NAPOT: a naturally aligned power-of-two region, here 4 KiB at
 * __heap_end (__stack is the top of RAM and the stack size a multiple of
 * 4 KiB, so it is aligned). A constructor, so it is armed before main.
 */
#define ZL_PORT_STACK_GUARD 4096u
#define PMP_LOCKED_NAPOT_NO_ACCESS 0x98u /* L = 1, A = NAPOT, R = W = X = 0 */

__attribute__((constructor)) static void zl_port_stack_guard(void)
{
    uintptr_t base = (uintptr_t)__heap_end;
    uintptr_t napot = (base + ZL_PORT_STACK_GUARD / 2u - 1u) >> 2;
    if ((base & (ZL_PORT_STACK_GUARD - 1u)) != 0)
        return; /* not aligned: no guard rather than a wrong one */
    __asm__ volatile("csrw pmpaddr0, %0\n\t"
                     "csrw pmpcfg0, %1"
                     :
                     : "r"(napot), "r"(PMP_LOCKED_NAPOT_NO_ACCESS)
                     : "memory");
}

/* The usable stack starts above the guard. */
static volatile uint32_t *stack_bottom(void)
{
    return __heap_end + ZL_PORT_STACK_GUARD / sizeof(uint32_t);
}

static uintptr_t current_sp(void)
{
    uintptr_t sp;
    __asm__ volatile("mv %0, sp" : "=r"(sp));
    return sp;
}

/* noinline: the paint stops at this function's own stack pointer, which is
 * below the caller's frame. */
__attribute__((noinline)) size_t zl_port_stack_paint(void)
{
    uintptr_t sp = current_sp();
    volatile uint32_t *p = stack_bottom();
    while ((uintptr_t)p < sp)
        *p++ = ZL_PORT_STACK_PAINT;
    return (size_t)((uintptr_t)__stack - sp);
}

size_t zl_port_stack_used(void)
{
    const volatile uint32_t *p = stack_bottom();
    while (p < __stack && *p == ZL_PORT_STACK_PAINT)
        p++;
    return (size_t)((uintptr_t)__stack - (uintptr_t)p);
}

size_t zl_port_stack_size(void)
{
    return (size_t)((uintptr_t)__stack - (uintptr_t)stack_bottom());
}
