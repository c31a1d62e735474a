/* SPDX-License-Identifier: MIT */
/*
 * Programs that must stop with a trap report instead of hanging: CTest
 * passes them when their output shows picolibc's "RISCV fault" register dump
 * with the expected mcause (see zline_port_add_selftests in ../CMakeLists.txt).
 * PORT_FAULT selects the bug. (Integer division by zero is not among them:
 * RISC-V defines its result, -1 for a quotient, and never traps.)
 */
#include <stdint.h>
#include <stdio.h>

#ifndef PORT_FAULT
#error "define PORT_FAULT: 1 illegal instruction, 2 load from unmapped memory, 3 store to unmapped memory, 4 stack overflow"
#endif

#if PORT_FAULT == 4
volatile int limit = 1 << 30;

static int __attribute__((noinline)) recurse(int n)
{
    volatile uint8_t frame[256];
    frame[0] = (uint8_t)n;
    return n < limit ? recurse(n + 1) + frame[0] : 0;
}
#endif

volatile uintptr_t unmapped_address = 16u;

int main(void)
{
    /* virt maps nothing at address 16: a load or store there is an access
     * fault (the address goes through a volatile so the compiler cannot see it) */
    volatile uint32_t *unmapped = (volatile uint32_t *)unmapped_address;
    printf("port_fault %d: this program must stop with a trap report\n", PORT_FAULT);
#if PORT_FAULT == 1
    __asm__ volatile(".word 0"); /* the all-zero word is defined as illegal */
#elif PORT_FAULT == 2
    return (int)*unmapped;
#elif PORT_FAULT == 3
    *unmapped = 1;
#elif PORT_FAULT == 4
    return recurse(0); /* runs into the stack guard (stack.c) */
#endif
    (void)unmapped;
    return 0; /* reaching this fails the test: no report in the output */
}
