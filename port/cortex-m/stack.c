/* SPDX-License-Identifier: MIT */
/* Stack high-water mark by painting; see zl_port.h. */
#include <stdint.h>

#include "zl_port.h"

extern uint32_t __stack_bottom[], __stack_top[];

#define ZL_PORT_STACK_PAINT 0xA5C3E1F0u

static uintptr_t current_sp(void)
{
    uintptr_t sp;
    __asm__ volatile("mov %0, sp" : "=r"(sp));
    return sp;
}

/* noinline: the paint stops at this function's own stack pointer, which is
 * below the caller's frame. */
__attribute__((noinline)) size_t zl_port_stack_paint(void)
{
    uintptr_t sp = current_sp();
    volatile uint32_t *p = __stack_bottom;
    /* Everything below sp is free (thread mode on PSP: no interrupt frames
     * are pushed here; they go to the handler stack). */
    while ((uintptr_t)p < sp)
        *p++ = ZL_PORT_STACK_PAINT;
    return (size_t)((uintptr_t)__stack_top - sp);
}

size_t zl_port_stack_used(void)
{
    const volatile uint32_t *p = __stack_bottom;
    while (p < __stack_top && *p == ZL_PORT_STACK_PAINT)
        p++;
    return (size_t)((uintptr_t)__stack_top - (uintptr_t)p);
}

size_t zl_port_stack_size(void)
{
    return (size_t)((uintptr_t)__stack_top - (uintptr_t)__stack_bottom);
}
