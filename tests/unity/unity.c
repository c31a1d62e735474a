/* SPDX-License-Identifier: MIT */
/* Implementation of the Unity-compatible subset declared in unity.h. */
#include "unity.h"

#include <setjmp.h>
#include <stdio.h>
#include <string.h>

static struct {
    const char *file;
    const char *test;
    int tests, failures, ignored;
    int current_failed, current_ignored;
    jmp_buf abort_frame;
} U;

/* 64-bit numbers as text without printf's %lld and %llX, which avr-libc's
 * printf does not have (the suite on the ATmega2560, port/avr). */
typedef struct {
    char text[24];
} number_text;

static number_text unsigned_text(uint64_t v, unsigned base)
{
    static const char digits[] = "0123456789ABCDEF";
    char reversed[24];
    number_text out;
    size_t n = 0, i;
    do {
        reversed[n++] = digits[v % base];
        v /= base;
    } while (v != 0);
    for (i = 0; i < n; i++)
        out.text[i] = reversed[n - 1 - i];
    out.text[n] = '\0';
    return out;
}

static number_text signed_text(int64_t v)
{
    number_text out;
    /* the magnitude in unsigned arithmetic: -INT64_MIN does not exist */
    uint64_t magnitude = v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
    number_text digits = unsigned_text(magnitude, 10u);
    out.text[0] = '-';
    memcpy(out.text + (v < 0), digits.text, strlen(digits.text) + 1u);
    return out;
}

static void print_location(int line)
{
    printf("%s:%d:%s:", U.file, line, U.test ? U.test : "");
}

void UnityBegin(const char *file)
{
    memset(&U, 0, sizeof U);
    U.file = file;
}

int UnityEnd(void)
{
    printf("\n-----------------------\n%d Tests %d Failures %d Ignored \n%s\n", U.tests, U.failures,
           U.ignored, U.failures == 0 ? "OK" : "FAIL");
    fflush(stdout);
    return U.failures;
}

void UnityDefaultTestRun(void (*fn)(void), const char *name, int line)
{
    U.test = name;
    U.tests++;
    U.current_failed = 0;
    U.current_ignored = 0;
    if (setjmp(U.abort_frame) == 0) {
        setUp();
        fn();
    }
    if (setjmp(U.abort_frame) == 0)
        tearDown();
    if (U.current_ignored) {
        U.ignored++;
    } else if (U.current_failed) {
        U.failures++;
    } else {
        printf("%s:%d:%s:PASS\n", U.file, line, name);
    }
    fflush(stdout);
    U.test = NULL;
}

static void fail_now(int line, const char *what, const char *msg)
{
    print_location(line);
    printf("FAIL: %s%s%s\n", what, msg ? " " : "", msg ? msg : "");
    fflush(stdout);
    U.current_failed = 1;
    longjmp(U.abort_frame, 1);
}

void UnityFail(const char *msg, int line)
{
    fail_now(line, msg ? msg : "", NULL);
}

void UnityIgnore(const char *msg, int line)
{
    print_location(line);
    printf("IGNORE: %s\n", msg ? msg : "");
    U.current_ignored = 1;
    longjmp(U.abort_frame, 1);
}

void UnityMessage(const char *msg, int line)
{
    print_location(line);
    printf("INFO: %s\n", msg ? msg : "");
}

void UnityAssertEqualInt(int64_t expected, int64_t actual, const char *msg, int line)
{
    char buf[96];
    if (expected == actual)
        return;
    snprintf(buf, sizeof buf, "Expected %s Was %s", signed_text(expected).text, signed_text(actual).text);
    fail_now(line, buf, msg);
}

void UnityAssertEqualUint(uint64_t expected, uint64_t actual, const char *msg, int line, int hex)
{
    char buf[96];
    if (expected == actual)
        return;
    snprintf(buf, sizeof buf, hex ? "Expected 0x%s Was 0x%s" : "Expected %s Was %s",
             unsigned_text(expected, hex ? 16u : 10u).text, unsigned_text(actual, hex ? 16u : 10u).text);
    fail_now(line, buf, msg);
}

void UnityAssertWithin(int64_t delta, int64_t expected, int64_t actual, const char *msg, int line)
{
    char buf[128];
    int64_t diff = actual > expected ? actual - expected : expected - actual;
    if (diff <= delta)
        return;
    snprintf(buf, sizeof buf, "Values Not Within Delta %s. Expected %s Was %s", signed_text(delta).text,
             signed_text(expected).text, signed_text(actual).text);
    fail_now(line, buf, msg);
}

void UnityAssertCompare(int64_t threshold, int64_t actual, int op, const char *msg, int line)
{
    static const char *names[] = {"", "greater than", "less than", "greater or equal to",
                                  "less or equal to"};
    char buf[128];
    int ok = (op == 1 && actual > threshold) || (op == 2 && actual < threshold) ||
             (op == 3 && actual >= threshold) || (op == 4 && actual <= threshold);
    if (ok)
        return;
    snprintf(buf, sizeof buf, "Expected %s %s Was %s", names[op], signed_text(threshold).text,
             signed_text(actual).text);
    fail_now(line, buf, msg);
}

void UnityAssertEqualMemory(const void *expected, const void *actual, uint32_t len, const char *msg,
                            int line)
{
    const unsigned char *e = expected, *a = actual;
    char buf[96];
    uint32_t i;
    if (!e || !a)
        fail_now(line, "Memory pointer is NULL", msg);
    for (i = 0; i < len; i++) {
        if (e[i] != a[i]) {
            snprintf(buf, sizeof buf, "Memory Mismatch at byte %lu: Expected 0x%02X Was 0x%02X",
                     (unsigned long)i, e[i], a[i]);
            fail_now(line, buf, msg);
        }
    }
}

void UnityAssertEqualString(const char *expected, const char *actual, const char *msg, int line)
{
    char buf[160];
    if (expected && actual && strcmp(expected, actual) == 0)
        return;
    snprintf(buf, sizeof buf, "Expected '%.60s' Was '%.60s'", expected ? expected : "(null)",
             actual ? actual : "(null)");
    fail_now(line, buf, msg);
}

void UnityAssertNull(const void *p, int want_null, const char *msg, int line)
{
    if ((p == NULL) == (want_null != 0))
        return;
    fail_now(line, want_null ? "Expected NULL" : "Expected Non-NULL", msg);
}
