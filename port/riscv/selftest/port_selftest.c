/* SPDX-License-Identifier: MIT */
/*
 * Self-test of the RISC-V port, run under QEMU by CTest: the cases every
 * bare-metal port runs (port/common/selftest_common.h: C library, memory
 * set-up, heap, host files, stack high-water mark), with host files written
 * through picolibc's semihosting stdio, and minstret counting instructions
 * exactly (QEMU -icount shift=0).
 */
#include <stdint.h>
#include <stdio.h>

#include "selftest_common.h"
#include "unity.h"
#include "zl_port.h"

int selftest_write_file(const char *path, const char *data, size_t n)
{
    FILE *f = fopen(path, "wb");
    size_t written;
    if (f == NULL)
        return -1;
    written = fwrite(data, 1, n, f);
    return fclose(f) == 0 && written == n ? 0 : -1;
}

/* minstret around straight-line code: the difference of two reads around
 * N nops is N + 1 (the second csrr itself is not yet retired when it reads,
 * the first is), whatever N. */
static void test_minstret_counts_instructions(void)
{
    uint32_t a, b, c, d;
    __asm__ volatile("csrr %0, minstret" : "=r"(a));
    __asm__ volatile("csrr %0, minstret" : "=r"(b));
    __asm__ volatile("csrr %0, minstret\n .rept 500\n nop\n .endr\n csrr %1, minstret" : "=r"(c), "=r"(d));
    printf("minstret: back to back %lu, around 500 nops %lu\n", (unsigned long)(b - a), (unsigned long)(d - c));
    TEST_ASSERT_EQUAL_UINT32(500, (d - c) - (b - a));
}

int main(void)
{
    UnityBegin(__FILE__);
    RUN_TEST(selftest_data_and_bss_are_set_up);
    RUN_TEST(selftest_printf_has_64_bit_formats);
    RUN_TEST(selftest_setjmp_longjmp);
    RUN_TEST(selftest_heap);
    RUN_TEST(selftest_host_files);
    RUN_TEST(selftest_stack_high_water_mark);
    RUN_TEST(test_minstret_counts_instructions);
    return UNITY_END();
}
