/* SPDX-License-Identifier: MIT */
/* The self-test cases shared by the bare-metal ports (selftest_common.h). */
#include "selftest_common.h"

#include <setjmp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "zl_port.h"

static uint8_t big[512 * 1024]; /* .bss well beyond any small MCU's RAM */
static int initialised = 12345; /* .data, copied from flash or the image */

void setUp(void) {}
void tearDown(void) {}

void selftest_data_and_bss_are_set_up(void)
{
    size_t i, nonzero = 0;
    TEST_ASSERT_EQUAL_INT(12345, initialised);
    for (i = 0; i < sizeof big; i++)
        nonzero += big[i] != 0;
    TEST_ASSERT_EQUAL_UINT(0, nonzero);
    memset(big, 0x5a, sizeof big);
    TEST_ASSERT_EQUAL_UINT8(0x5a, big[sizeof big - 1]);
}

void selftest_printf_has_64_bit_formats(void)
{
    char buf[80];
    snprintf(buf, sizeof buf, "%lld %llX %llu %d", (long long)-1234567890123LL,
             (unsigned long long)0xABCDEF0123ULL, (unsigned long long)18446744073709551615ULL, -7);
    TEST_ASSERT_EQUAL_STRING("-1234567890123 ABCDEF0123 18446744073709551615 -7", buf);
}

static jmp_buf jb;
static void jump_back(int v)
{
    longjmp(jb, v);
}

void selftest_setjmp_longjmp(void)
{
    volatile int passes = 0;
    int v = setjmp(jb);
    passes++;
    if (v == 0)
        jump_back(42);
    TEST_ASSERT_EQUAL_INT(42, v);
    TEST_ASSERT_EQUAL_INT(2, passes);
}

void selftest_heap(void)
{
    uint8_t *p = malloc(256 * 1024);
    TEST_ASSERT_TRUE(p != NULL);
    memset(p, 1, 256 * 1024);
    free(p);
    /* More than the RAM: malloc fails instead of running into the stack. */
    TEST_ASSERT_TRUE(malloc(8u * 1024 * 1024) == NULL);
}

void selftest_host_files(void)
{
    static const char pgm[] = "P5\n2 1\n255\n\x10\x20";
    char back[32];
    FILE *f;
    size_t n;
    TEST_ASSERT_EQUAL_INT(0, selftest_write_file("port_selftest.pgm", pgm, sizeof pgm - 1));
    f = fopen("port_selftest.pgm", "rb");
    TEST_ASSERT_TRUE(f != NULL);
    n = fread(back, 1, sizeof back, f);
    TEST_ASSERT_EQUAL_UINT(sizeof pgm - 1, n);
    TEST_ASSERT_EQUAL_MEMORY(pgm, back, n);
    TEST_ASSERT_EQUAL_INT(0, fseek(f, 3, SEEK_SET));
    TEST_ASSERT_EQUAL_INT(3, ftell(f));
    TEST_ASSERT_EQUAL_INT('2', fgetc(f));
    TEST_ASSERT_EQUAL_INT(0, fclose(f));
    f = fopen("port_selftest.txt", "w");
    TEST_ASSERT_TRUE(f != NULL);
    TEST_ASSERT_EQUAL_INT(8, fprintf(f, "line %d\n", 42));
    TEST_ASSERT_EQUAL_INT(0, fclose(f));
    TEST_ASSERT_TRUE(fopen("no/such/dir/file", "rb") == NULL);
}

static int __attribute__((noinline)) use_stack(int depth)
{
    volatile uint8_t frame[1000];
    frame[0] = (uint8_t)depth;
    frame[999] = (uint8_t)depth;
    return depth > 0 ? use_stack(depth - 1) + frame[0] + frame[999] : 0;
}

void selftest_stack_high_water_mark(void)
{
    size_t base = zl_port_stack_paint();
    size_t need;
    /* Only this function's own calls have used stack since the paint. */
    TEST_ASSERT_LESS_OR_EQUAL(base + 64, zl_port_stack_used());
    use_stack(9); /* 10 frames of 1000 bytes and a little */
    need = zl_port_stack_used() - base;
    printf("stack: %u bytes in use before, %u for 10 x 1000-byte frames, of %u\n", (unsigned)base,
           (unsigned)need, (unsigned)zl_port_stack_size());
    TEST_ASSERT_GREATER_OR_EQUAL(10000, need);
    TEST_ASSERT_LESS_THAN(10000 + 10 * 64, need);
}
