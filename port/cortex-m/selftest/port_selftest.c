/* SPDX-License-Identifier: MIT */
/*
 * Self-test of the Cortex-M port, run under QEMU by CTest: the cases every
 * bare-metal port runs (port/common/selftest_common.h: C library, memory
 * set-up, heap, host files, stack high-water mark), with host files written
 * through the port's semihosting call.
 */
#include <newlib.h>

#include "selftest_common.h"
#include "unity.h"
#include "zl_port.h"

int selftest_write_file(const char *path, const char *data, size_t n)
{
    return zl_semi_write_file(path, data, n);
}

static void test_printf_has_64_bit_formats(void)
{
#ifdef _NANO_FORMATTED_IO
    TEST_IGNORE_MESSAGE("ZLINE_NEWLIB_NANO: newlib-nano printf has no %lld (Unity messages are wrong)");
#endif
    /* newlib-nano would print "ld lX lu" here: by default the port links full newlib. */
    selftest_printf_has_64_bit_formats();
}

int main(void)
{
    UnityBegin(__FILE__);
    RUN_TEST(selftest_data_and_bss_are_set_up);
    RUN_TEST(test_printf_has_64_bit_formats);
    RUN_TEST(selftest_setjmp_longjmp);
    RUN_TEST(selftest_heap);
    RUN_TEST(selftest_host_files);
    RUN_TEST(selftest_stack_high_water_mark);
    return UNITY_END();
}
