/* SPDX-License-Identifier: MIT */
/*
 * Programs that must stop with a fault report instead of hanging: CTest
 * passes them when their output shows the expected report (see
 * zline_port_add_selftests in ../CMakeLists.txt). PORT_FAULT selects the bug.
 */
#include <stdint.h>
#include <stdio.h>

#ifndef PORT_FAULT
#error "define PORT_FAULT: 1 undefined instruction, 2 division by zero, 3 stack overflow, 4 64-bit division by zero"
#endif

volatile int32_t zero = 0;
volatile int64_t zero64 = 0;
volatile int limit = 1 << 30;

#if PORT_FAULT == 3
static int __attribute__((noinline)) recurse(int n)
{
    volatile uint8_t frame[256];
    frame[0] = (uint8_t)n;
    return n < limit ? recurse(n + 1) + frame[0] : 0;
}
#endif

int main(void)
{
    printf("port_fault %d: this program must stop with a fault report\n", PORT_FAULT);
#if PORT_FAULT == 1
    __asm__ volatile("udf #0");
#elif PORT_FAULT == 2
    return (int)(100 / zero);
#elif PORT_FAULT == 3
    return recurse(0);
#elif PORT_FAULT == 4
    return (int)(100 / zero64);
#endif
    return 0; /* reaching this fails the test: no report in the output */
}
