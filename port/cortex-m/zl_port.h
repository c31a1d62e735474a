/* SPDX-License-Identifier: MIT */
/*
 * The Cortex-M test/benchmark port: what programs built with
 * zline_target_executable() can call besides the C library. printf, puts and
 * fopen/fwrite work through semihosting (syscalls.c); main's return value is
 * the exit code QEMU returns.
 */
#ifndef ZL_PORT_H
#define ZL_PORT_H

#include <stddef.h>

#include "semihosting.h"

#ifdef __cplusplus
extern "C" {
#endif

/*
 * Stack high-water mark by painting. The program runs on its own stack
 * (__stack_bottom .. __stack_top in the linker script, size __stack_size);
 * faults run on a separate small one.
 *
 * zl_port_stack_paint() fills the unused part of the stack (below the
 * caller's frame) with a pattern and returns the bytes in use at the call.
 * zl_port_stack_used() returns the deepest use since then, in bytes from the
 * top of the stack. So the stack a call needs is
 *     size_t base = zl_port_stack_paint();
 *     f();
 *     size_t need = zl_port_stack_used() - base;
 * exact to a word, give or take the few bytes of zl_port_stack_paint's own
 * frame. The count is only valid if nothing used the stack below the painted
 * area before the paint. Interrupt handlers run on the other stack and are
 * not counted.
 */
size_t zl_port_stack_paint(void);
size_t zl_port_stack_used(void);
/* Size of the program stack in bytes. */
size_t zl_port_stack_size(void);

/* Exit codes of the port itself (main's return value is passed through;
 * nonzero values that would read as 0 mod 256 become 255). */
#define ZL_PORT_EXIT_FAULT_BASE 240 /* + exception number: 243 HardFault .. 246 UsageFault */

#ifdef __cplusplus
}
#endif

#endif
