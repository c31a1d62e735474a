/* Stack high-water mark by painting; see zl_port.h. */
#include <stdint.h>

#include "zl_port.h"

/* picolibc.ld: the stack is __heap_end .. __stack (the heap stops below it). */
extern uint32_t __heap_end[], __stack[];

#define ZL_PORT_STACK_PAINT 0xA5C3E1F0u

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
    volatile uint32_t *p = __heap_end;
    while ((uintptr_t)p < sp)
        *p++ = ZL_PORT_STACK_PAINT;
    return (size_t)((uintptr_t)__stack - sp);
}

size_t zl_port_stack_used(void)
{
    const volatile uint32_t *p = __heap_end;
    while (p < __stack && *p == ZL_PORT_STACK_PAINT)
        p++;
    return (size_t)((uintptr_t)__stack - (uintptr_t)p);
}

size_t zl_port_stack_size(void)
{
    return (size_t)((uintptr_t)__stack - (uintptr_t)__heap_end);
}
