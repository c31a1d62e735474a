/*
 * Fast exact division (zl_udiv64_32) against the plain 64-bit C division, on
 * edge cases and on many pseudo-random operands from a fixed-seed generator
 * (the same sequence on the host and on every Cortex-M).
 */
#include "unity.h"
#include "zline/zline.h"

void setUp(void) {}
void tearDown(void) {}

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;

/* splitmix64: small, deterministic, good enough to spread operands. */
static uint64_t rnd64(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

static uint32_t rnd32(void)
{
    return (uint32_t)(rnd64() >> 32);
}

/* A divisor of random bit length 1..32 (short divisors are the hard ones). */
static uint32_t rnd_divisor(void)
{
    unsigned len = 1u + (unsigned)(rnd64() % 32u);
    uint32_t d = rnd32() >> (32u - len);
    return d | ((uint32_t)1 << (len - 1u));
}

static int udiv_ok(uint64_t n, uint32_t d)
{
    uint32_t r = 0xDEADBEEFu;
    uint32_t q = zl_udiv64_32(n, d, &r);
    return (uint64_t)q == n / d && (uint64_t)r == n % d && zl_udiv64_32(n, d, NULL) == q;
}

static void check(uint64_t n, uint32_t d)
{
    if (!udiv_ok(n, d))
        TEST_FAIL_MESSAGE("zl_udiv64_32 differs from n / d");
}

static void test_udiv_edge_cases(void)
{
    static const uint32_t ds[] = {1u, 2u, 3u, 7u, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u,
                                  0x80000001u, 0xFFFF0000u, 0xFFFF8000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    unsigned i;
    for (i = 0; i < sizeof ds / sizeof ds[0]; i++) {
        uint32_t d = ds[i];
        uint64_t top = ((uint64_t)d << 32) - 1u; /* largest n with a 32-bit quotient */
        check(0, d);
        check(1, d);
        check(d, d);
        check((uint64_t)d - 1u, d);
        check(0xFFFFFFFFu, d);
        check(0x100000000ull, d < 2u ? 2u : d);
        check(top, d);
        check(top - d, d);
        check(top - d + 1u, d);
        check(((uint64_t)(d - 1u) << 32), d);
        check(((uint64_t)(d - 1u) << 32) | 0xFFFFu, d);
        check(((uint64_t)(d - 1u) << 32) | 0xFFFF0000u, d);
        check((uint64_t)0xFFFFFFFFu * d, d);
        check((uint64_t)0x10000u * d + d - 1u, d);
    }
}

/* n = q d + r for random q, r: every quotient, including ones near 2^32. */
static void test_udiv_random_quotients(void)
{
    unsigned k;
    for (k = 0; k < 60000u; k++) {
        uint32_t d = rnd_divisor();
        uint32_t q = rnd32() >> (rnd64() % 32u);
        uint32_t r = (uint32_t)(rnd64() % d);
        if (k & 1u)
            q = ~q; /* quotients near the top as well */
        check((uint64_t)q * d + r, d);
    }
}

/* Raw random numerators below d * 2^32, and the digit-correction corners:
 * divisor halves near 0x8000 and 0xFFFF, remainders near the divisor. */
static void test_udiv_random_numerators(void)
{
    unsigned k;
    for (k = 0; k < 60000u; k++) {
        uint32_t d = rnd_divisor();
        uint64_t n = rnd64() % ((uint64_t)d << 32);
        check(n, d);
        d = 0x80000000u | (rnd32() & 0xFFFFu) | ((rnd32() & 3u) << 16) | (k & 1u ? 0x7FFC0000u : 0u);
        n = ((uint64_t)(rnd32() % d) << 32) | rnd32();
        check(n, d);
        check(((uint64_t)d << 32) - 1u - (rnd32() & 0xFFFFu), d);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_udiv_edge_cases);
    RUN_TEST(test_udiv_random_quotients);
    RUN_TEST(test_udiv_random_numerators);
    return UNITY_END();
}
