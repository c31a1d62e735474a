/* SPDX-License-Identifier: MIT */
/*
 * The RISC-V test/benchmark port: what programs built with
 * zline_target_executable() can call besides the C library. printf, puts and
 * fopen/fwrite work through semihosting (picolibc's libsemihost); main's
 * return value is the exit code QEMU returns. Same interface as the
 * Cortex-M port's zl_port.h, so bench.c builds unchanged for both.
 */
#ifndef ZL_PORT_H
#define ZL_PORT_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Stack high-water mark by painting. The program stack is picolibc's: the
 * top __stack_size bytes of RAM (virt.ld), from __heap_end up to __stack,
 * less a 4 KiB no-access guard at its bottom (stack.c).
 *
 * zl_port_stack_paint() fills the unused part of the stack (below the
 * caller's frame) with a pattern and returns the bytes in use at the call.
 * zl_port_stack_used() returns the deepest use since then, in bytes from the
 * top of the stack. So the stack a call needs is
 *     size_t base = zl_port_stack_paint();
 *     f();
 *     size_t need = zl_port_stack_used() - base;
 * exact to a word. Traps run on the same stack (the port takes no
 * interrupts, and a trap ends the program).
 */
size_t zl_port_stack_paint(void);
size_t zl_port_stack_used(void);
/* Size of the program stack in bytes. */
size_t zl_port_stack_size(void);

#ifdef __cplusplus
}
#endif

#endif
