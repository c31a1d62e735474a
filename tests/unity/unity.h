/* SPDX-License-Identifier: MIT */
/*
 * A small Unity-compatible test runner: exactly the subset of Unity's API
 * (ThrowTheSwitch.org, MIT) that zline's tests use, with Unity's output
 * format ("file:line:test:PASS" / ":FAIL: message" and the closing
 * "N Tests N Failures N Ignored" / "OK" / "FAIL" lines). Built only when no
 * real Unity is given (see tests/CMakeLists.txt); tests compile unchanged
 * against either.
 *
 * Like Unity, a failed assertion ends the current test (longjmp back to
 * RUN_TEST); setUp and tearDown run around every test.
 */
#ifndef ZLINE_UNITY_SHIM_H
#define ZLINE_UNITY_SHIM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

void setUp(void);
void tearDown(void);

void UnityBegin(const char *file);
int UnityEnd(void);
void UnityDefaultTestRun(void (*fn)(void), const char *name, int line);
void UnityFail(const char *msg, int line);
void UnityIgnore(const char *msg, int line);
void UnityMessage(const char *msg, int line);
void UnityAssertEqualInt(int64_t expected, int64_t actual, const char *msg, int line);
void UnityAssertEqualUint(uint64_t expected, uint64_t actual, const char *msg, int line, int hex);
void UnityAssertWithin(int64_t delta, int64_t expected, int64_t actual, const char *msg, int line);
void UnityAssertCompare(int64_t threshold, int64_t actual, int op, const char *msg, int line);
void UnityAssertEqualMemory(const void *expected, const void *actual, uint32_t len, const char *msg,
                            int line);
void UnityAssertEqualString(const char *expected, const char *actual, const char *msg, int line);
void UnityAssertNull(const void *p, int want_null, const char *msg, int line);

#define UNITY_BEGIN() UnityBegin(__FILE__)
#define UNITY_END() UnityEnd()
#define RUN_TEST(fn) UnityDefaultTestRun(fn, #fn, __LINE__)

#define TEST_FAIL_MESSAGE(m) UnityFail((m), __LINE__)
#define TEST_FAIL() UnityFail(NULL, __LINE__)
#define TEST_IGNORE_MESSAGE(m) UnityIgnore((m), __LINE__)
#define TEST_IGNORE() UnityIgnore(NULL, __LINE__)
#define TEST_MESSAGE(m) UnityMessage((m), __LINE__)
#define TEST_PASS() ((void)0)

#define TEST_ASSERT_MESSAGE(c, m) do { if (!(c)) UnityFail((m), __LINE__); } while (0)
#define TEST_ASSERT(c) TEST_ASSERT_MESSAGE((c), "Expression Evaluated To FALSE")
#define TEST_ASSERT_TRUE(c) TEST_ASSERT_MESSAGE((c), "Expected TRUE Was FALSE")
#define TEST_ASSERT_FALSE(c) TEST_ASSERT_MESSAGE(!(c), "Expected FALSE Was TRUE")
#define TEST_ASSERT_TRUE_MESSAGE(c, m) TEST_ASSERT_MESSAGE((c), (m))
#define TEST_ASSERT_FALSE_MESSAGE(c, m) TEST_ASSERT_MESSAGE(!(c), (m))
#define TEST_ASSERT_NULL(p) UnityAssertNull((p), 1, NULL, __LINE__)
#define TEST_ASSERT_NOT_NULL(p) UnityAssertNull((p), 0, NULL, __LINE__)

#define TEST_ASSERT_EQUAL_INT_MESSAGE(e, a, m) UnityAssertEqualInt((int64_t)(e), (int64_t)(a), (m), __LINE__)
#define TEST_ASSERT_EQUAL_INT(e, a) TEST_ASSERT_EQUAL_INT_MESSAGE((e), (a), NULL)
#define TEST_ASSERT_EQUAL(e, a) TEST_ASSERT_EQUAL_INT((e), (a))
#define TEST_ASSERT_EQUAL_MESSAGE(e, a, m) TEST_ASSERT_EQUAL_INT_MESSAGE((e), (a), (m))
#define TEST_ASSERT_EQUAL_INT8(e, a) TEST_ASSERT_EQUAL_INT((e), (a))
#define TEST_ASSERT_EQUAL_INT16(e, a) TEST_ASSERT_EQUAL_INT((e), (a))
#define TEST_ASSERT_EQUAL_INT32(e, a) TEST_ASSERT_EQUAL_INT((e), (a))
#define TEST_ASSERT_EQUAL_INT64(e, a) TEST_ASSERT_EQUAL_INT((e), (a))
#define TEST_ASSERT_EQUAL_INT32_MESSAGE(e, a, m) TEST_ASSERT_EQUAL_INT_MESSAGE((e), (a), (m))
#define TEST_ASSERT_EQUAL_UINT_MESSAGE(e, a, m) UnityAssertEqualUint((uint64_t)(e), (uint64_t)(a), (m), __LINE__, 0)
#define TEST_ASSERT_EQUAL_UINT(e, a) TEST_ASSERT_EQUAL_UINT_MESSAGE((e), (a), NULL)
#define TEST_ASSERT_EQUAL_UINT8(e, a) TEST_ASSERT_EQUAL_UINT((e), (a))
#define TEST_ASSERT_EQUAL_UINT16(e, a) TEST_ASSERT_EQUAL_UINT((e), (a))
#define TEST_ASSERT_EQUAL_UINT32(e, a) TEST_ASSERT_EQUAL_UINT((e), (a))
#define TEST_ASSERT_EQUAL_UINT64(e, a) TEST_ASSERT_EQUAL_UINT((e), (a))
#define TEST_ASSERT_EQUAL_UINT16_MESSAGE(e, a, m) TEST_ASSERT_EQUAL_UINT_MESSAGE((e), (a), (m))
#define TEST_ASSERT_EQUAL_UINT32_MESSAGE(e, a, m) TEST_ASSERT_EQUAL_UINT_MESSAGE((e), (a), (m))
#define TEST_ASSERT_EQUAL_HEX8(e, a) UnityAssertEqualUint((uint64_t)(e), (uint64_t)(a), NULL, __LINE__, 1)
#define TEST_ASSERT_EQUAL_HEX16(e, a) UnityAssertEqualUint((uint64_t)(e), (uint64_t)(a), NULL, __LINE__, 1)
#define TEST_ASSERT_EQUAL_HEX32(e, a) UnityAssertEqualUint((uint64_t)(e), (uint64_t)(a), NULL, __LINE__, 1)
#define TEST_ASSERT_INT_WITHIN_MESSAGE(d, e, a, m) UnityAssertWithin((int64_t)(d), (int64_t)(e), (int64_t)(a), (m), __LINE__)
#define TEST_ASSERT_INT_WITHIN(d, e, a) TEST_ASSERT_INT_WITHIN_MESSAGE((d), (e), (a), NULL)
#define TEST_ASSERT_INT32_WITHIN(d, e, a) TEST_ASSERT_INT_WITHIN((d), (e), (a))
#define TEST_ASSERT_UINT_WITHIN(d, e, a) TEST_ASSERT_INT_WITHIN((d), (e), (a))
#define TEST_ASSERT_INT32_WITHIN_MESSAGE(d, e, a, m) TEST_ASSERT_INT_WITHIN_MESSAGE((d), (e), (a), (m))

/* op: 1 greater than, 2 less than, 3 greater or equal, 4 less or equal (actual vs threshold) */
#define TEST_ASSERT_GREATER_THAN(t, a) UnityAssertCompare((int64_t)(t), (int64_t)(a), 1, NULL, __LINE__)
#define TEST_ASSERT_LESS_THAN(t, a) UnityAssertCompare((int64_t)(t), (int64_t)(a), 2, NULL, __LINE__)
#define TEST_ASSERT_GREATER_OR_EQUAL(t, a) UnityAssertCompare((int64_t)(t), (int64_t)(a), 3, NULL, __LINE__)
#define TEST_ASSERT_LESS_OR_EQUAL(t, a) UnityAssertCompare((int64_t)(t), (int64_t)(a), 4, NULL, __LINE__)
#define TEST_ASSERT_GREATER_THAN_MESSAGE(t, a, m) UnityAssertCompare((int64_t)(t), (int64_t)(a), 1, (m), __LINE__)
#define TEST_ASSERT_LESS_THAN_MESSAGE(t, a, m) UnityAssertCompare((int64_t)(t), (int64_t)(a), 2, (m), __LINE__)
#define TEST_ASSERT_GREATER_OR_EQUAL_MESSAGE(t, a, m) UnityAssertCompare((int64_t)(t), (int64_t)(a), 3, (m), __LINE__)
#define TEST_ASSERT_LESS_OR_EQUAL_MESSAGE(t, a, m) UnityAssertCompare((int64_t)(t), (int64_t)(a), 4, (m), __LINE__)

#define TEST_ASSERT_EQUAL_MEMORY_MESSAGE(e, a, n, m) UnityAssertEqualMemory((e), (a), (uint32_t)(n), (m), __LINE__)
#define TEST_ASSERT_EQUAL_MEMORY(e, a, n) TEST_ASSERT_EQUAL_MEMORY_MESSAGE((e), (a), (n), NULL)
#define TEST_ASSERT_EQUAL_STRING_MESSAGE(e, a, m) UnityAssertEqualString((e), (a), (m), __LINE__)
#define TEST_ASSERT_EQUAL_STRING(e, a) TEST_ASSERT_EQUAL_STRING_MESSAGE((e), (a), NULL)

#ifdef __cplusplus
}
#endif

#endif
