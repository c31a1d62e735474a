/* SPDX-License-Identifier: MIT */
/*
 * The self-test cases every bare-metal port runs under QEMU (port/cortex-m,
 * port/riscv): what the tests and benchmarks rely on. The C library pieces
 * the Unity runner uses (printf and snprintf with 64-bit numbers,
 * setjmp/longjmp), .data/.bss set-up with a big buffer, the heap, host files
 * and the stack high-water mark (zl_port.h). Each port's port_selftest.c
 * runs them next to its own cases and supplies selftest_write_file, its way
 * of writing a host file (semihosting call or the C library).
 */
#ifndef ZLINE_PORT_SELFTEST_COMMON_H
#define ZLINE_PORT_SELFTEST_COMMON_H

#include <stddef.h>

/* The port's: write n bytes to a host file; 0 on success. */
int selftest_write_file(const char *path, const char *data, size_t n);

void selftest_data_and_bss_are_set_up(void);
void selftest_printf_has_64_bit_formats(void);
void selftest_setjmp_longjmp(void);
void selftest_heap(void);
void selftest_host_files(void);
void selftest_stack_high_water_mark(void);

#endif
