/*
 * Division by an invariant divisor (zl_div_inv, the reciprocal triangle
 * setup uses for its plane equations) against the plain 64-bit C division:
 * every divisor length, quotients near 0 and near 2^32, remainders near 0
 * and near the divisor, from a fixed-seed generator (the same sequence on
 * the host and on every Cortex-M).
 */
#include "../core/src/zl_internal.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static uint64_t rng_state = 0x0123456789ABCDEFull;

/* splitmix64 */
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

static unsigned failures;

static void check(uint64_t n, uint32_t d)
{
    zl_div_inv di;
    zl_div_inv_init(&di, d);
    if ((uint64_t)zl_div_inv_q(&di, n) != n / d && failures++ < 5)
        TEST_FAIL_MESSAGE("zl_div_inv_q differs from n / d");
}

static void test_div_inv_corners(void)
{
    static const uint32_t ds[] = {1u, 2u, 3u, 5u, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u,
                                  0x80000001u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    unsigned i;
    for (i = 0; i < sizeof ds / sizeof ds[0]; i++) {
        uint32_t d = ds[i];
        uint64_t top = ((uint64_t)d << 32) - 1u; /* the largest numerator allowed */
        check(0, d);
        check(1, d);
        check(d, d);
        check((uint64_t)d - 1u, d);
        check(top, d);
        check(top - d, d);
        check(top - d + 1u, d);
        check((uint64_t)0xFFFFFFFFu * d, d);
        check((uint64_t)(d - 1u) << 32, d);
    }
    TEST_ASSERT_EQUAL_UINT(0, failures);
}

/* n = q d + r with random q and r, divisors of every bit length. */
static void test_div_inv_random(void)
{
    unsigned k;
    for (k = 0; k < 100000u; k++) {
        unsigned len = 1u + (unsigned)(rnd64() % 32u);
        uint32_t d = (rnd32() >> (32u - len)) | ((uint32_t)1 << (len - 1u));
        uint32_t q = rnd32() >> (rnd64() % 32u);
        uint32_t r = (uint32_t)(rnd64() % d);
        if (k & 1u)
            q = ~q;
        if (k & 2u)
            r = d - 1u - (r & 3u) % d;
        check((uint64_t)q * d + r, d);
    }
    TEST_ASSERT_EQUAL_UINT(0, failures);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_div_inv_corners);
    RUN_TEST(test_div_inv_random);
    return UNITY_END();
}
