/* SPDX-License-Identifier: MIT */
/*
 * Helpers shared by the fuzz targets (tests/fuzz/fuzz_*.c).
 *
 * fz_in reads the fuzzer's bytes as numbers; past the end every read is 0,
 * so every input, even an empty one, is a complete test case. fz_fixed()
 * spends one selector byte to pick a kind of Q16.16 value: small integers,
 * fractions, powers of two and the documented limits (+-16384.0, the Q16.16
 * extremes) come up far more often than raw 32-bit noise would give them.
 *
 * fz_buf is a heap buffer between two guard zones holding a position-
 * dependent pattern; fz_buf_check() aborts (a libFuzzer finding) when a
 * guard byte changed. AddressSanitizer catches writes beyond the guards.
 * The buffer is allocated with the exact payload size the API is promised,
 * never more.
 */
#ifndef FZ_COMMON_H
#define FZ_COMMON_H

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "zline/zline.h"

typedef struct {
    const uint8_t *p;
    size_t n;
} fz_in;

static inline uint32_t fz_u8(fz_in *in)
{
    if (in->n == 0)
        return 0;
    in->n--;
    return *in->p++;
}

static inline uint32_t fz_u16(fz_in *in)
{
    uint32_t lo = fz_u8(in);
    return lo | (fz_u8(in) << 8);
}

static inline uint32_t fz_u32(fz_in *in)
{
    uint32_t lo = fz_u16(in);
    return lo | (fz_u16(in) << 16);
}

/* A Q16.16 value of a kind chosen by one selector byte. */
static inline zl_fixed fz_fixed(fz_in *in)
{
    static const int64_t edges[] = {0,          1,          -1,         65536,      -65536,
                                    32768,      1073741824, -1073741824, 1073741825, -1073741825,
                                    2147483647, -2147483647 - 1, 1 << 20, -(1 << 20), 8388608,
                                    -8388608};
    uint32_t sel = fz_u8(in);
    switch (sel % 8) {
    case 0: /* small integer -128..127 */
        return (zl_fixed)((int32_t)(int8_t)fz_u8(in) * 65536);
    case 1: /* fraction in -2..2, 1/16384 steps */
        return (zl_fixed)((int32_t)(int16_t)fz_u16(in) * 2);
    case 2: /* +-2^k plus a little */
    {
        uint32_t k = fz_u8(in) % 31;
        int32_t v = (int32_t)((uint32_t)1 << k) + (int32_t)(int8_t)fz_u8(in);
        return (sel & 8) ? -v : v;
    }
    case 3: /* a documented limit, possibly one off */
        return (zl_fixed)edges[fz_u8(in) % (sizeof edges / sizeof edges[0])];
    case 4: /* medium integer -32768..32767 */
        return (zl_fixed)((int32_t)(int16_t)fz_u16(in) * 65536);
    case 5: /* pixel-ish: 0..1023 pixels with a random fraction */
        return (zl_fixed)(fz_u32(in) & 0x3FFFFFFu);
    default: /* raw */
        return (zl_fixed)fz_u32(in);
    }
}

#define FZ_GUARD 64u

typedef struct {
    uint8_t *base;  /* guard + payload + guard */
    uint8_t *data;  /* the payload, 8-byte aligned (malloc alignment + 64) */
    size_t size;
} fz_buf;

static inline uint8_t fz_pattern(size_t i)
{
    return (uint8_t)(0xA5u ^ (i * 37u));
}

static inline void fz_buf_alloc(fz_buf *b, size_t size)
{
    size_t i;
    b->size = size;
    b->base = (uint8_t *)malloc(size + 2 * FZ_GUARD);
    if (b->base == NULL)
        abort();
    b->data = b->base + FZ_GUARD;
    for (i = 0; i < size + 2 * FZ_GUARD; i++)
        b->base[i] = fz_pattern(i);
}

static inline void fz_buf_check(const fz_buf *b, const char *what)
{
    size_t i;
    for (i = 0; i < FZ_GUARD; i++) {
        if (b->base[i] != fz_pattern(i)) {
            fprintf(stderr, "%s: guard byte %zu before the buffer changed\n", what, FZ_GUARD - i);
            abort();
        }
        if (b->base[FZ_GUARD + b->size + i] != fz_pattern(FZ_GUARD + b->size + i)) {
            fprintf(stderr, "%s: guard byte %zu after the buffer (of %zu) changed\n", what, i, b->size);
            abort();
        }
    }
}

static inline void fz_buf_free(fz_buf *b)
{
    free(b->base);
    b->base = b->data = NULL;
}

#define FZ_REQUIRE(cond, ...)                                                                      \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            fprintf(stderr, "%s:%d: %s: ", __FILE__, __LINE__, #cond);                             \
            fprintf(stderr, __VA_ARGS__);                                                          \
            fputc('\n', stderr);                                                                   \
            abort();                                                                               \
        }                                                                                          \
    } while (0)

#endif /* FZ_COMMON_H */
