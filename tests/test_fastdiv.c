/* SPDX-License-Identifier: MIT */
/*
 * Fast exact division (zl_udiv64_32, zl_div_inv for a divisor fixed per
 * triangle, and zl_div16 for one below 2^16: in the _mul32 build its
 * reciprocal form) against the plain C division, on
 * edge cases and on many pseudo-random operands from a fixed-seed generator
 * (the same sequence on the host and on every Cortex-M). Then the vertex
 * cache (zl_cache_vertex, zl_cache_vertices) and zl_project, whose fast
 * paths use it, against the straightforward 64-bit formulas written out here.
 */
#include <string.h>

#include "../core/src/1_base/zl_internal.h"
#include "../core/src/3_raster/zl_raster.h"
#include "../core/src/3_raster/zl_span_tex.h"
#include "unity.h"
#include "zt_target.h"

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

/* n = q d + r for a random divisor d (every bit length), quotient q (on
 * odd k its complement, so quotients near 2^32 as well) and remainder r;
 * on k & 2 with `high_r` the remainder is one of the top four below d. */
static void random_division(unsigned k, int high_r, uint64_t *n, uint32_t *d)
{
    uint32_t dv = rnd_divisor();
    uint32_t q = rnd32() >> (rnd64() % 32u);
    uint32_t r = (uint32_t)(rnd64() % dv);
    if (k & 1u)
        q = ~q;
    if (high_r && (k & 2u))
        r = dv - 1u - (r & 3u) % dv;
    *n = (uint64_t)q * dv + r;
    *d = dv;
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

/* The numerators both divisions are tried with for each edge-case divisor
 * d: 0, 1, d - 1, d, and at the top of the range (the largest numerator
 * with a 32-bit quotient, one d below it and one past that, (2^32 - 1) d,
 * (d - 1) 2^32). */
static void check_corners(uint32_t d, void (*check_one)(uint64_t, uint32_t))
{
    uint64_t top = ((uint64_t)d << 32) - 1u;
    check_one(0, d);
    check_one(1, d);
    check_one(d, d);
    check_one((uint64_t)d - 1u, d);
    check_one(top, d);
    check_one(top - d, d);
    check_one(top - d + 1u, d);
    check_one((uint64_t)0xFFFFFFFFu * d, d);
    check_one((uint64_t)(d - 1u) << 32, d);
}

static void test_udiv_edge_cases(void)
{
    static const uint32_t ds[] = {1u, 2u, 3u, 7u, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u,
                                  0x80000001u, 0xFFFF0000u, 0xFFFF8000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    unsigned i;
    for (i = 0; i < sizeof ds / sizeof ds[0]; i++) {
        uint32_t d = ds[i];
        check_corners(d, check);
        check(0xFFFFFFFFu, d);
        check(0x100000000ull, d < 2u ? 2u : d);
        check(((uint64_t)(d - 1u) << 32) | 0xFFFFu, d);
        check(((uint64_t)(d - 1u) << 32) | 0xFFFF0000u, d);
        check((uint64_t)0x10000u * d + d - 1u, d);
    }
}

/* n = q d + r for random q, r: every quotient, including ones near 2^32. */
static void test_udiv_random_quotients(void)
{
    uint32_t k;
    for (k = 0; k < ZT_ROUNDS(60000); k++) {
        uint64_t n;
        uint32_t d;
        random_division(k, 0, &n, &d);
        check(n, d);
    }
}

/* Raw random numerators below d * 2^32, and the digit-correction corners:
 * divisor halves near 0x8000 and 0xFFFF, remainders near the divisor. */
static void test_udiv_random_numerators(void)
{
    uint32_t k;
    for (k = 0; k < ZT_ROUNDS(60000); k++) {
        uint32_t d = rnd_divisor();
        uint64_t n = rnd64() % ((uint64_t)d << 32);
        check(n, d);
        d = 0x80000000u | (rnd32() & 0xFFFFu) | ((rnd32() & 3u) << 16) | (k & 1u ? 0x7FFC0000u : 0u);
        n = ((uint64_t)(rnd32() % d) << 32) | rnd32();
        check(n, d);
        check(((uint64_t)d << 32) - 1u - (rnd32() & 0xFFFFu), d);
    }
}


/* ------------------------------------- division by an invariant divisor */

/* zl_div_inv (the reciprocal triangle setup uses for its plane equations)
 * against the plain 64-bit C division. */
static unsigned inv_failures;

static void check_inv(uint64_t n, uint32_t d)
{
    zl_div_inv di;
    zl_div_inv_init(&di, d);
    if ((uint64_t)zl_div_inv_q(&di, n) != n / d && inv_failures++ < 5)
        TEST_FAIL_MESSAGE("zl_div_inv_q differs from n / d");
}

static void test_div_inv_corners(void)
{
    static const uint32_t ds[] = {1u, 2u, 3u, 5u, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u,
                                  0x80000001u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    unsigned i;
    for (i = 0; i < sizeof ds / sizeof ds[0]; i++)
        check_corners(ds[i], check_inv);
    TEST_ASSERT_EQUAL_UINT(0, inv_failures);
}

/* n = q d + r with random q and r, divisors of every bit length. */
static void test_div_inv_random(void)
{
    uint32_t k;
    for (k = 0; k < ZT_ROUNDS(100000); k++) {
        uint64_t n;
        uint32_t d;
        random_division(k, 1, &n, &d);
        check_inv(n, d);
    }
    TEST_ASSERT_EQUAL_UINT(0, inv_failures);
}

/* zl_div16_q (the planes' shared divisor below 2^16) for every divisor:
 * numerators 0, c - 1, c, the largest allowed (c 2^16 - 1), a quotient's
 * first and last numerator for random quotients below 2^16, and random
 * numerators, each against x / c. */
static void test_div16_every_divisor(void)
{
    uint32_t c, failures = 0;
    for (c = 1; c < 65536u; c++) {
        zl_div16 d;
        uint32_t top = c * 65536u - 1u, xs[12];
        unsigned k;
        zl_div16_init(&d, c);
        xs[0] = 0;
        xs[1] = c - 1u;
        xs[2] = c;
        xs[3] = top;
        for (k = 4; k < 12; k += 2) {
            uint32_t q = rnd32() >> 16;
            xs[k] = q * c;
            xs[k + 1] = k == 10 ? (uint32_t)(rnd64() % ((uint64_t)top + 1u)) : q * c + c - 1u;
        }
        for (k = 0; k < 12; k++)
            if (zl_div16_q(&d, xs[k]) != xs[k] / c && failures++ < 5)
                TEST_ASSERT_EQUAL_UINT32(xs[k] / c, zl_div16_q(&d, xs[k]));
    }
    TEST_ASSERT_EQUAL_UINT32(0, failures);
}

/* ------------------------------------------------ the vertex cache */

#define NV 24
#define LIM ((int64_t)1 << 30)

static int64_t floor_div(int64_t n, int64_t d) /* d > 0 */
{
    int64_t q = n / d;
    if (n % d < 0)
        q--;
    return q;
}

/* zl_round_div64's definition, floor((2n + d) / 2d); |n| below 2^62. */
static int64_t round_div(int64_t n, int64_t d)
{
    return floor_div(2 * n + d, 2 * d);
}

/* Transform, rounded; 0 when an operand or the result leaves its range. */
static int ref_transform(const zl_fixed *m, const zl_fixed *p, int32_t *c)
{
    int r, k;
    for (k = 0; k < 3; k++)
        if (p[k] < -LIM || p[k] > LIM)
            return 0;
    for (k = 0; k < 16; k++)
        if (m[k] < -LIM || m[k] > LIM)
            return 0;
    for (r = 0; r < 4; r++) {
        int64_t a = (int64_t)m[r * 4] * p[0] + (int64_t)m[r * 4 + 1] * p[1] + (int64_t)m[r * 4 + 2] * p[2] +
                    (int64_t)m[r * 4 + 3] * 65536;
        a = floor_div(a + 32768, 65536);
        if (a < INT32_MIN || a > INT32_MAX)
            return 0;
        c[r] = (int32_t)a;
    }
    return 1;
}

/* Inside the 7 clip planes, each written out as in the documentation. */
static int ref_inside(const int32_t *c, int64_t wd, int64_t ht)
{
    const int64_t g = ZL_GUARD_PX, x = c[0], y = c[1], z = c[2], w = c[3];
    return w - 1 >= 0 && z >= 0 && w - z >= 0 && wd * x + (wd + 2 * g) * w >= 0 &&
           -wd * x + (wd + 2 * g) * w >= 0 && -ht * y + (ht + 2 * g) * w >= 0 && ht * y + (ht + 2 * g) * w >= 0;
}

static zl_cached_vertex ref_cache(const zl_fixed *m, const zl_fixed *p, int64_t wd, int64_t ht)
{
    zl_cached_vertex r;
    int32_t c[4];
    int64_t x, y, q, rem;
    memset(&r, 0, sizeof r);
    r.x = ZL_CACHE_INVALID;
    if (!ref_transform(m, p, c))
        return r;
    r.x = ZL_CACHE_COMPLEX;
    if (!ref_inside(c, wd, ht))
        return r;
    x = round_div(((int64_t)c[0] + c[3]) * wd * (ZL_SUB_ONE / 2), c[3]);
    y = round_div(((int64_t)c[3] - c[1]) * ht * (ZL_SUB_ONE / 2), c[3]);
    if (x < INT16_MIN + 2 || x > INT16_MAX || y < INT16_MIN || y > INT16_MAX)
        return r;
    r.x = (int16_t)x;
    r.y = (int16_t)y;
    /* round(z / w * 65535 * 65536) by quotient and remainder */
    q = (int64_t)c[2] * 65535 / c[3];
    rem = (int64_t)c[2] * 65535 % c[3];
    r.z = (uint32_t)(q * 65536 + round_div(rem * 65536, c[3]));
    return r;
}

/* A value of random magnitude (and sign), now and then beyond the limit. */
static int32_t rnd_mag(void)
{
    uint32_t v = rnd32() >> (rnd64() % 32u);
    if ((rnd32() & 15u) != 0)
        v &= (uint32_t)LIM - 1u; /* mostly within the limit */
    return (rnd32() & 1u) ? (int32_t)(0u - (v & 0x7FFFFFFFu)) : (int32_t)(v & 0x7FFFFFFFu);
}

static int32_t clamp_lim(int64_t v)
{
    return (int32_t)(v < -LIM ? -LIM : (v > LIM ? LIM : v));
}

/* A coordinate near +-bound (the edge of a plane), or anywhere within it. */
static int32_t near_bound(int64_t bound)
{
    int64_t d = (int64_t)(rnd32() % 5u) - 2;
    int64_t v = (rnd32() & 3u) == 0 ? (int64_t)(rnd64() % (uint64_t)(2 * bound + 1)) - bound : bound + d;
    return clamp_lim((rnd32() & 1u) ? -v : v);
}

/*
 * Matrix and positions of one random draw: random entries (mostly out of
 * the planes or out of range), a perspective camera (mostly inside), or the
 * identity with w = position z and positions on the planes' edges.
 */
static void random_draw(zl_mat4 *m, zl_fixed *pos, uint16_t *wd, uint16_t *ht)
{
    unsigned kind = (unsigned)(rnd64() % 3u), v, k;
    *wd = (uint16_t)(1u + rnd32() % ((rnd32() & 7u) == 0 ? 65535u : 4096u));
    *ht = (uint16_t)(1u + rnd32() % ((rnd32() & 7u) == 0 ? 65535u : 4096u));
    if (kind == 0) {
        for (k = 0; k < 16; k++)
            m->m[k] = rnd_mag();
        for (k = 0; k < NV * 3u; k++)
            pos[k] = rnd_mag();
        return;
    }
    if (kind == 1) {
        zl_mat4 p, view;
        zl_vec3 eye = {rnd_mag() >> 12, rnd_mag() >> 12, rnd_mag() >> 12}, at = {0, 0, 0}, up = {0, ZL_FX_ONE, 0};
        zl_fixed near_z = (zl_fixed)(1u + rnd32() % 65536u);
        if (zl_mat4_perspective(&p, (zl_angle)(1000u + rnd32() % 30000u), (zl_fixed)(16384u + rnd32() % 200000u),
                                near_z, near_z + (zl_fixed)(1u + rnd32() % 0x1000000u)) != ZL_OK ||
            zl_mat4_look_at(&view, eye, at, up) != ZL_OK) {
            zl_mat4_identity(&p);
            zl_mat4_identity(&view);
        }
        zl_mat4_mul(m, &p, &view);
        for (k = 0; k < NV * 3u; k++)
            pos[k] = (zl_fixed)(rnd_mag() >> (rnd32() % 16u));
        return;
    }
    /* clip x = pos x, y = pos y, z = a pos z + b, w = pos z */
    zl_mat4_identity(m);
    m->m[10] = (rnd32() & 1u) ? ZL_FX_ONE : 0;
    m->m[11] = (zl_fixed)(rnd32() % 9u) - 4;
    m->m[14] = ZL_FX_ONE;
    m->m[15] = 0;
    for (v = 0; v < NV; v++) {
        int32_t w = (rnd32() & 3u) == 0 ? (int32_t)(rnd32() % 5u) - 2 : (int32_t)(rnd32() >> (rnd32() % 32u));
        if ((rnd32() & 3u) == 0) /* the x or y plane then passes through integers */
            w = (int32_t)(((rnd32() & 1u) ? *wd : *ht) * (int64_t)(rnd32() % 64u));
        w = clamp_lim(w);
        if (m->m[10] == 0)
            m->m[11] = (zl_fixed)(rnd32() % 9u) - 4 + ((rnd32() & 1u) ? w : 0);
        pos[v * 3u] = near_bound(((int64_t)*wd + 2 * ZL_GUARD_PX) * w / *wd);
        pos[v * 3u + 1] = near_bound(((int64_t)*ht + 2 * ZL_GUARD_PX) * w / *ht);
        pos[v * 3u + 2] = w;
    }
}

static void test_cache_matches_64bit_formulas(void)
{
    uint32_t draw, inside = 0, complex = 0, invalid = 0; /* 96000 vertices: beyond a 16-bit unsigned */
    unsigned v;
    for (draw = 0; draw < ZT_ROUNDS(4000); draw++) {
        zl_mat4 m;
        zl_fixed pos[NV * 3];
        zl_mesh mesh = {0};
        zl_source s;
        zl_cached_vertex cache[NV + 1];
        int any_bad = 0;
        zl_status st;
        random_draw(&m, pos, &s.width, &s.height);
        mesh.positions = pos;
        mesh.vertex_count = NV;
        s.mesh = &mesh;
        s.mvp = &m;
        s.state = NULL;
        s.cache = NULL;
        cache[NV].x = 1234; /* not written */
        st = zl_cache_vertices(&s, cache, 0, NV);
        for (v = 0; v < NV; v++) {
            zl_cached_vertex r = ref_cache(m.m, &pos[v * 3u], s.width, s.height);
            zl_cached_vertex one = zl_cache_vertex(&s, (uint16_t)v);
            TEST_ASSERT_EQUAL_INT(r.x, cache[v].x);
            TEST_ASSERT_EQUAL_INT(r.y, cache[v].y);
            TEST_ASSERT_EQUAL_UINT32(r.z, cache[v].z);
            TEST_ASSERT_EQUAL_INT(r.x, one.x);
            TEST_ASSERT_EQUAL_INT(r.y, one.y);
            TEST_ASSERT_EQUAL_UINT32(r.z, one.z);
            any_bad |= r.x == ZL_CACHE_INVALID;
            invalid += r.x == ZL_CACHE_INVALID;
            complex += r.x == ZL_CACHE_COMPLEX;
            inside += r.x != ZL_CACHE_INVALID && r.x != ZL_CACHE_COMPLEX;
        }
        TEST_ASSERT_EQUAL_INT(1234, cache[NV].x);
        TEST_ASSERT_EQUAL_INT(any_bad ? ZL_ERR_RANGE : ZL_OK, st);
        TEST_ASSERT_EQUAL_INT(zl_check_positions(pos, NV, &m), st);
        /* a part of the range writes just that part */
        cache[3].x = cache[9].x = 77;
        TEST_ASSERT_TRUE(zl_cache_vertices(&s, cache, 4, 5) <= ZL_OK);
        TEST_ASSERT_EQUAL_INT(77, cache[3].x);
        TEST_ASSERT_EQUAL_INT(77, cache[9].x);
        TEST_ASSERT_EQUAL_INT(ref_cache(m.m, &pos[8 * 3u], s.width, s.height).x, cache[8].x);
    }
    /* every outcome is exercised many times */
    TEST_ASSERT_TRUE(inside > ZT_ROUNDS(5000) && complex > ZT_ROUNDS(5000) && invalid > ZT_ROUNDS(5000));
    {
        /* no vertices: only the matrix decides */
        zl_mat4 m;
        zl_mesh mesh = {0};
        zl_source s = {0};
        zl_fixed pos[3] = {0, 0, 0};
        zl_cached_vertex c;
        zl_mat4_identity(&m);
        mesh.positions = pos;
        s.mesh = &mesh;
        s.mvp = &m;
        s.width = s.height = 8;
        TEST_ASSERT_EQUAL_INT(ZL_OK, zl_cache_vertices(&s, &c, 0, 0));
        m.m[7] = (zl_fixed)(LIM + 1);
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_cache_vertices(&s, &c, 0, 0));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_check_positions(pos, 0, &m));
        TEST_ASSERT_EQUAL_INT(ZL_ERR_RANGE, zl_cache_vertices(&s, &c, 0, 1));
        TEST_ASSERT_EQUAL_INT(ZL_CACHE_INVALID, c.x);
    }
}

/* One vertex through both cache functions against the formulas. */
static void check_one(const zl_mat4 *m, const zl_fixed *p, uint16_t wd, uint16_t ht)
{
    zl_mesh mesh = {0};
    zl_source s = {0};
    zl_cached_vertex c, r = ref_cache(m->m, p, wd, ht), one;
    mesh.positions = p;
    mesh.vertex_count = 1;
    s.mesh = &mesh;
    s.mvp = m;
    s.width = wd;
    s.height = ht;
    TEST_ASSERT_EQUAL_INT(r.x == ZL_CACHE_INVALID ? ZL_ERR_RANGE : ZL_OK, zl_cache_vertices(&s, &c, 0, 1));
    one = zl_cache_vertex(&s, 0);
    TEST_ASSERT_EQUAL_INT(r.x, c.x);
    TEST_ASSERT_EQUAL_INT(r.y, c.y);
    TEST_ASSERT_EQUAL_UINT32(r.z, c.z);
    TEST_ASSERT_EQUAL_INT(r.x, one.x);
    TEST_ASSERT_EQUAL_INT(r.y, one.y);
    TEST_ASSERT_EQUAL_UINT32(r.z, one.z);
}

/* Exact boundaries: transform results at INT32_MIN / INT32_MAX and one past,
 * coordinates at +-2^30 and one past, window x and y at the int16 limits and
 * the cache markers, planes met exactly. */
static void test_cache_edges(void)
{
    static const int32_t ws[] = {1, 2, 3, 16, 48, 1000, 65536};
    zl_mat4 m;
    zl_fixed p[3];
    int32_t off, t, x, side;
    unsigned row, k;
    for (row = 0; row < 4; row++) {
        for (k = 0; k < 18; k++) {
            off = (int32_t)(k % 3u) - 1;
            t = (int32_t)(k / 3u % 3u) - 1;
            side = k < 9 ? -1 : 1;
            zl_mat4_identity(&m);
            m.m[row * 4] = 2 * ZL_FX_ONE; /* 2 p.x + t */
            m.m[row * 4 + 1] = 0;
            m.m[row * 4 + 2] = 0;
            m.m[row * 4 + 3] = t;
            p[0] = (zl_fixed)(side * LIM + off);
            p[1] = p[0] / 4;
            p[2] = ZL_FX_ONE;
            check_one(&m, p, 64, 64);
        }
    }
    /* w = clip w, W = H = 1: window x = round((x + w) * 8 / w), window y =
     * round((w - y) * 8 / w); x and y swept across the int16 limits. */
    zl_mat4_identity(&m);
    m.m[10] = 0;
    m.m[14] = ZL_FX_ONE;
    m.m[15] = 0;
    for (k = 0; k < sizeof ws / sizeof ws[0]; k++) {
        int32_t w = ws[k];
        for (side = -1; side <= 1; side += 2) {
            int32_t c = (int32_t)((int64_t)side * 32768 * w / 8 - w);
            for (x = c - w / 4 - 3; x <= c + w / 4 + 3; x++) {
                p[0] = x;
                p[1] = 0; /* window y 8: x alone decides */
                p[2] = w;
                check_one(&m, p, 1, 1);
                p[0] = 0;
                p[1] = -x; /* y at the window value x had */
                check_one(&m, p, 1, 1);
            }
        }
    }
}

/* The fast path's bound on positions (the largest power of two P that keeps
 * every row of the transform inside Q16.16): rows whose worst case is near
 * 2^47, positions at and around every power of two and its negative. */
static void test_cache_position_bound(void)
{
    uint32_t draw;
    unsigned k, j;
    for (draw = 0; draw < ZT_ROUNDS(600); draw++) {
        zl_mat4 m;
        zl_fixed p[3];
        unsigned row = draw % 4u;
        /* |m0| + |m1| + |m2| near a power of two, translation near its limit */
        int32_t big = (int32_t)((UINT32_C(1) << (draw % 31u)) - 1u + rnd32() % 3u);
        zl_mat4_identity(&m);
        m.m[14] = ZL_FX_ONE;
        m.m[15] = ZL_FX_ONE / 2 + (zl_fixed)(rnd32() % 65536u);
        m.m[row * 4] = clamp_lim((rnd32() & 1u) ? big : -big);
        m.m[row * 4 + 1] = clamp_lim((int32_t)(rnd32() >> (1u + rnd32() % 31u)) * ((rnd32() & 1u) ? 1 : -1));
        m.m[row * 4 + 2] = clamp_lim((rnd32() & 1u) ? big / 3 : -(big / 2));
        m.m[row * 4 + 3] = (rnd32() & 1u) ? clamp_lim((int32_t)(rnd32() >> (1u + rnd32() % 31u)) - (int32_t)(rnd32() >> 1))
                                          : (zl_fixed)(rnd32() % 9u) - 4;
        for (k = 0; k <= 30u; k++) {
            for (j = 0; j < 8u; j++) {
                int32_t e = (int32_t)(UINT32_C(1) << k), v = (j & 1u) ? -e : e;
                v = (int32_t)((uint32_t)v + (uint32_t)((int32_t)(j >> 1) - 1)); /* -1, 0, +1, +2 around it */
                p[0] = clamp_lim(v);
                p[1] = (j & 4u) ? clamp_lim(-(int64_t)v) : p[0] / 3;
                p[2] = (rnd32() & 1u) ? p[0] : (zl_fixed)(rnd32() % 65536u);
                check_one(&m, p, (uint16_t)(1u + rnd32() % 640u), (uint16_t)(1u + rnd32() % 480u));
            }
        }
    }
}

/* The depth of zl_project (the vertex cache's division too) where its
 * long division changes: w around 2^20, z at 0, 1, w / 2, w - 1, w. */
static void test_depth_edges(void)
{
    static const int32_t ws[] = {1, 2, 3, 255, 256, 4095, 4096, 65535, 65536, 65537, 0xFFFFF - 1, 0xFFFFF,
                                 0x100000, 0x100001, 0x7FFFFFF, 0x3FFFFFFF, 0x40000000, INT32_MAX};
    unsigned k, j;
    for (k = 0; k < sizeof ws / sizeof ws[0]; k++) {
        int64_t w = ws[k];
        int64_t zs[7];
        zs[0] = 0;
        zs[1] = 1;
        zs[2] = w / 2;
        zs[3] = (w + 1) / 2;
        zs[4] = w - 1;
        zs[5] = w;
        zs[6] = (int64_t)(rnd32() % (uint32_t)w);
        for (j = 0; j < 7u; j++) {
            zl_mat4 m;
            zl_source s = {0};
            zl_cvert v = {0, 0, 0, 0, 0, 0, 0, ZL_ZD_NONE};
            zl_wvert out;
            int64_t z = zs[j] > w ? w : zs[j];
            zl_mat4_identity(&m);
            s.mvp = &m;
            s.width = 64;
            s.height = 48;
            v.w = (int32_t)w;
            v.z = (int32_t)z;
            zl_project(&s, &v, &out);
            TEST_ASSERT_EQUAL_UINT32((uint32_t)(z * 65535 / w * 65536 + round_div(z * 65535 % w * 65536, w)), out.z);
        }
    }
}

/* zl_project on any clip vertex (the clipping path's, slightly off the
 * planes too) against the 64-bit formulas. */
static void test_project_matches_64bit_formulas(void)
{
    uint32_t k;
    for (k = 0; k < ZT_ROUNDS(100000); k++) {
        zl_mat4 m;
        zl_source s = {0};
        zl_cvert v = {0, 0, 0, 0, 0, 0, 0, ZL_ZD_NONE};
        zl_wvert out;
        int64_t w, z;
        zl_mat4_identity(&m);
        s.mvp = &m;
        s.width = (uint16_t)(1u + rnd32() % 4096u);
        s.height = (uint16_t)(1u + rnd32() % 4096u);
        v.w = (k & 1u) ? (int32_t)(rnd32() % 100u) - 50 : rnd_mag();
        w = v.w < 1 ? 1 : v.w;
        v.x = (k & 2u) ? rnd_mag() : near_bound((((int64_t)s.width + 2 * ZL_GUARD_PX) * w) / s.width);
        v.y = (k & 4u) ? rnd_mag() : near_bound((((int64_t)s.height + 2 * ZL_GUARD_PX) * w) / s.height);
        v.z = (k & 8u) ? rnd_mag() : (int32_t)(w - (int64_t)(rnd32() % 3u) * (int64_t)(rnd32() & 1u ? 1 : w));
        zl_project(&s, &v, &out);
        TEST_ASSERT_EQUAL_INT((int32_t)round_div(((int64_t)v.x + w) * s.width * (ZL_SUB_ONE / 2), w), out.x);
        TEST_ASSERT_EQUAL_INT((int32_t)round_div((w - v.y) * s.height * (ZL_SUB_ONE / 2), w), out.y);
        z = v.z < 0 ? 0 : (v.z > w ? w : v.z);
        TEST_ASSERT_EQUAL_UINT32((uint32_t)(z * 65535 / w * 65536 + round_div(z * 65535 % w * 65536, w)), out.z);
    }
}

/* ------------------------------------------------------------ lighting */

static uint32_t ref_isqrt(uint64_t v)
{
    uint64_t r = 0, bit = (uint64_t)1 << 62;
    while (bit > v)
        bit >>= 2;
    for (; bit != 0; bit >>= 2) {
        if (v >= r + bit) {
            v -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
    }
    return (uint32_t)r;
}

static unsigned shift_to(int64_t big, unsigned bits)
{
    unsigned len = 0;
    while (big >= ((int64_t)1 << (bits + len)))
        len++;
    return len;
}

static int32_t ref_q14(zl_fixed c)
{
    int32_t v = c / 4;
    return v > (1 << 14) ? (1 << 14) : (v < -(1 << 14) ? -(1 << 14) : v);
}

/* The lighting definition: 64-bit normal, edges below 2^30, normal below 2^14. */
static unsigned ref_intensity(const zl_fixed *p0, const zl_fixed *p1, const zl_fixed *p2, const zl_state *st)
{
    int64_t e[6], n[3], big = 0;
    int32_t m[3], dot, len, cosv;
    unsigned k, sh;
    for (k = 0; k < 3; k++) {
        e[k] = (int64_t)p1[k] - p0[k];
        e[k + 3] = (int64_t)p2[k] - p0[k];
    }
    for (k = 0; k < 6; k++)
        big = (e[k] < 0 ? -e[k] : e[k]) > big ? (e[k] < 0 ? -e[k] : e[k]) : big;
    sh = shift_to(big, 30);
    for (k = 0; k < 6; k++)
        e[k] = floor_div(e[k], (int64_t)1 << sh);
    n[0] = e[1] * e[5] - e[2] * e[4];
    n[1] = e[2] * e[3] - e[0] * e[5];
    n[2] = e[0] * e[4] - e[1] * e[3];
    big = 0;
    for (k = 0; k < 3; k++)
        big = (n[k] < 0 ? -n[k] : n[k]) > big ? (n[k] < 0 ? -n[k] : n[k]) : big;
    sh = shift_to(big, 14);
    for (k = 0; k < 3; k++)
        m[k] = (int32_t)floor_div(n[k], (int64_t)1 << sh);
    len = (int32_t)ref_isqrt((uint64_t)((int64_t)m[0] * m[0] + (int64_t)m[1] * m[1] + (int64_t)m[2] * m[2]));
    if (len == 0)
        return st->ambient;
    dot = m[0] * ref_q14(st->light_dir.x) + m[1] * ref_q14(st->light_dir.y) + m[2] * ref_q14(st->light_dir.z);
    if (st->front_face == ZL_FRONT_CW)
        dot = -dot;
    if (dot <= 0)
        return st->ambient;
    cosv = dot / len;
    if (cosv > (1 << 14))
        cosv = 1 << 14;
    return st->ambient + (unsigned)(((255 - st->ambient) * cosv + (1 << 13)) >> 14);
}

/* A random vertex: anywhere, or near p within a random edge length. */
static void rnd_vertex(zl_fixed *v, const zl_fixed *near, unsigned edge_bits)
{
    unsigned k;
    for (k = 0; k < 3; k++) {
        uint32_t r = rnd32(); /* drawn either way, so the sequence does not depend on edge_bits */
        /* in [-2^(edge_bits-1), 2^(edge_bits-1)), the subtraction done unsigned */
        int32_t d = edge_bits ? (int32_t)((r >> (32u - edge_bits)) - (UINT32_C(1) << (edge_bits - 1u))) : 0;
        v[k] = near ? (zl_fixed)((uint32_t)near[k] + (uint32_t)d) : (zl_fixed)rnd32();
    }
}

static void test_lighting_matches_64bit_definition(void)
{
    uint32_t k, lit = 0, dark = 0;
#if !ZL_FEATURE_LIGHTING
    TEST_IGNORE_MESSAGE("ZL_FEATURE_LIGHTING=0: the light is compiled out (test_features: refused)");
#endif
    for (k = 0; k < ZT_ROUNDS(200000); k++) {
        zl_fixed pos[9];
        uint16_t idx[3] = {0, 1, 2};
        zl_mesh mesh = {0};
        zl_state st;
        zl_source s = {0};
        zl_poly poly;
        unsigned eb = 1u + (unsigned)(rnd64() % 32u), i, c;
        zl_state_default(&st);
        st.light_on = 1;
        st.ambient = (uint8_t)(rnd32() & 1u ? rnd32() : 0u);
        st.front_face = (uint8_t)(rnd32() & 1u ? ZL_FRONT_CW : ZL_FRONT_CCW);
        st.color.r = (uint8_t)rnd32();
        st.color.g = (uint8_t)rnd32();
        st.color.b = (uint8_t)rnd32();
        if (rnd32() & 1u) {
            st.light_dir.x = (zl_fixed)(rnd32() % 131073u) - 65536;
            st.light_dir.y = (zl_fixed)(rnd32() % 131073u) - 65536;
            st.light_dir.z = (zl_fixed)(rnd32() % 131073u) - 65536;
        } else {
            st.light_dir.x = (zl_fixed)rnd32();
            st.light_dir.y = (zl_fixed)rnd32();
            st.light_dir.z = (zl_fixed)rnd32();
        }
        /* first vertex anywhere (near the wrap too), the others near it */
        rnd_vertex(pos, NULL, 0);
        if ((k & 3u) == 0)
            for (i = 0; i < 3; i++)
                pos[i] = (zl_fixed)((rnd32() & 1u ? 0x80000000u : 0x7FFFFFFFu) + (rnd32() % 32768u) - 16384u);
        else if ((k & 3u) == 1)
            for (i = 0; i < 3; i++)
                pos[i] >>= rnd32() % 31u;
        rnd_vertex(&pos[3], pos, eb);
        rnd_vertex(&pos[6], (k & 4u) ? &pos[3] : pos, eb);
        if ((k & 31u) == 5)
            for (i = 0; i < 3; i++)
                pos[6 + i] = (zl_fixed)(pos[i] + ((int64_t)pos[3 + i] - pos[i]) / 2); /* flat: the midpoint */
        mesh.positions = pos;
        mesh.vertex_count = 3;
        mesh.triangle_count = 1;
        mesh.indices = idx;
        s.mesh = &mesh;
        s.state = &st;
        poly.n = 3;
        for (i = 0; i < 3; i++) {
            poly.v[i].r = (uint16_t)((k & 8u) ? 0u : rnd32() % (255u * 256u + 1u));
            poly.v[i].g = (uint16_t)((k & 8u) ? 0u : rnd32() % (255u * 256u + 1u));
            poly.v[i].b = (uint16_t)((k & 8u) ? 0u : rnd32() % (255u * 256u + 1u));
        }
        {
            zl_poly before = poly;
            unsigned want = ref_intensity(pos, &pos[3], &pos[6], &st);
            zl_tri_shade(&s, 0, &poly);
            TEST_ASSERT_EQUAL_UINT(want, poly.light);
            TEST_ASSERT_EQUAL_UINT((st.color.r * want + 127u) / 255u, poly.flat.r);
            TEST_ASSERT_EQUAL_UINT((st.color.b * want + 127u) / 255u, poly.flat.b);
            for (i = 0; i < 3; i++) {
                c = before.v[i].g;
                TEST_ASSERT_EQUAL_UINT((c * want + 127u) / 255u, poly.v[i].g);
            }
            lit += want > st.ambient;
            dark += want == st.ambient;
        }
    }
    TEST_ASSERT_TRUE(lit > ZT_ROUNDS(20000) && dark > ZT_ROUNDS(20000));
}

/* Lighting at the edges of its fast paths: first vertex at and around
 * +-2^30 (and beyond), edges at and around +-2^14, light components where
 * the Q14 clamp starts, polygons of 3 to ZL_MAX_POLY vertices with colour
 * on any one of them. */
static void test_lighting_edges(void)
{
    static const int32_t p0s[] = {0, 1, -1, 0x3FFFFFFF, 0x40000000, 0x40000001, -0x3FFFFFFF, -0x40000000,
                                  -0x40000001, INT32_MAX, INT32_MIN, INT32_MAX - 0x4000, INT32_MIN + 0x4000};
    static const int32_t es[] = {-0x4001, -0x4000, -0x3FFF, -1, 0, 1, 0x3FFF, 0x4000, 0x4001, -0x2000, 0x2345};
    static const int32_t ls[] = {0, 1, -1, 3, -3, 4, -4, 5, -5, 65535, 65536, 65539, 65540, 65543, -65535, -65536,
                                 -65539, -65540, -65543, 24576, -32768, 49152, INT32_MAX, INT32_MIN};
    uint32_t k;
    unsigned i;
#if !ZL_FEATURE_LIGHTING
    TEST_IGNORE_MESSAGE("ZL_FEATURE_LIGHTING=0: the light is compiled out (test_features: refused)");
#endif
    for (k = 0; k < ZT_ROUNDS(40000); k++) {
        zl_fixed pos[9];
        uint16_t idx[3] = {0, 1, 2};
        zl_mesh mesh = {0};
        zl_state st;
        zl_source s = {0};
        zl_poly poly, before;
        unsigned want, c;
        zl_state_default(&st);
        st.light_on = 1;
        st.ambient = (uint8_t)(rnd32() & 1u ? rnd32() : 0u);
        st.front_face = (uint8_t)(rnd32() & 1u ? ZL_FRONT_CW : ZL_FRONT_CCW);
        st.color.r = (uint8_t)rnd32();
        st.color.g = (uint8_t)rnd32();
        st.color.b = (uint8_t)rnd32();
        st.light_dir.x = ls[rnd32() % (sizeof ls / sizeof ls[0])];
        st.light_dir.y = ls[rnd32() % (sizeof ls / sizeof ls[0])];
        st.light_dir.z = ls[rnd32() % (sizeof ls / sizeof ls[0])];
        for (i = 0; i < 3; i++) {
            pos[i] = (rnd32() & 3u) ? p0s[rnd32() % (sizeof p0s / sizeof p0s[0])] : (zl_fixed)(rnd32() >> 2);
            pos[3 + i] = (zl_fixed)((uint32_t)pos[i] + (uint32_t)es[rnd32() % (sizeof es / sizeof es[0])]);
            pos[6 + i] = (zl_fixed)((uint32_t)pos[i] + (uint32_t)es[rnd32() % (sizeof es / sizeof es[0])]);
        }
        mesh.positions = pos;
        mesh.vertex_count = 3;
        mesh.triangle_count = 1;
        mesh.indices = idx;
        s.mesh = &mesh;
        s.state = &st;
        memset(&poly, 0, sizeof poly);
        poly.n = 3u + rnd32() % (ZL_MAX_POLY - 2u);
        if (rnd32() & 1u) {
            i = rnd32() % poly.n; /* one vertex with colour, the others black */
            poly.v[i].r = (uint16_t)(rnd32() % (255u * 256u + 1u));
            poly.v[i].g = (uint16_t)(rnd32() & 1u ? rnd32() % (255u * 256u + 1u) : 0u);
            poly.v[i].b = (uint16_t)(rnd32() & 1u ? rnd32() % (255u * 256u + 1u) : 0u);
        }
        before = poly;
        want = ref_intensity(pos, &pos[3], &pos[6], &st);
        zl_tri_shade(&s, 0, &poly);
        TEST_ASSERT_EQUAL_UINT(want, poly.light);
        TEST_ASSERT_EQUAL_UINT((st.color.r * want + 127u) / 255u, poly.flat.r);
        TEST_ASSERT_EQUAL_UINT((st.color.g * want + 127u) / 255u, poly.flat.g);
        TEST_ASSERT_EQUAL_UINT((st.color.b * want + 127u) / 255u, poly.flat.b);
        TEST_ASSERT_EQUAL_UINT(before.n, poly.n);
        for (i = 0; i < poly.n; i++) {
            c = before.v[i].r;
            TEST_ASSERT_EQUAL_UINT((c * want + 127u) / 255u, poly.v[i].r);
            c = before.v[i].g;
            TEST_ASSERT_EQUAL_UINT((c * want + 127u) / 255u, poly.v[i].g);
            c = before.v[i].b;
            TEST_ASSERT_EQUAL_UINT((c * want + 127u) / 255u, poly.v[i].b);
        }
    }
}

/* zl_isqrt32 around every square and power of two (the table's seams). */
static void test_isqrt32_squares(void)
{
    uint32_t k, d;
    for (k = 0; k <= 65535u; k++) {
        uint32_t sq = k * k;
        TEST_ASSERT_EQUAL_UINT(k, zl_isqrt32(sq));
        TEST_ASSERT_EQUAL_UINT(k, zl_isqrt32(sq + 2u * k)); /* (k + 1)^2 - 1 */
        if (k > 0)
            TEST_ASSERT_EQUAL_UINT(k - 1u, zl_isqrt32(sq - 1u));
    }
    for (k = 0; k < 32u; k++)
        for (d = 0; d < 64u; d++) {
            uint32_t v = ((uint32_t)1 << k) + d - 32u;
            TEST_ASSERT_EQUAL_UINT(ref_isqrt(v), zl_isqrt32(v));
            v = ((uint32_t)1 << k) * (1u + (d & 3u)) - 1u - (d >> 2);
            TEST_ASSERT_EQUAL_UINT(ref_isqrt(v), zl_isqrt32(v));
        }
    for (k = 0; k < ZT_ROUNDS(100000); k++) {
        uint32_t v = rnd32() >> (k % 32u);
        TEST_ASSERT_EQUAL_UINT(ref_isqrt(v), zl_isqrt32(v));
    }
}

/* zl_div255_small (colour scaling on cores without a 64-bit multiply):
 * every numerator colour scaling can make, 0 .. 255 * 255 + 127. */
static void test_div255_small_all(void)
{
    uint32_t x;
    for (x = 0; x <= 255u * 255u + 127u; x++)
        if (zl_div255_small(x) != x / 255u)
            TEST_ASSERT_EQUAL_UINT(x / 255u, zl_div255_small(x));
}

/* zl_div255_31 (smooth lighting's colour scaling without a divide): every
 * x below 2^16, the multiples of 255 and their neighbours up to 2^31 - 1
 * (stride 255 * 4099), the top values, and random ones, against x / 255. */
static void test_div255_31(void)
{
    uint32_t x, k, failures = 0;
    for (x = 0; x < 65536u; x++)
        failures += zl_div255_31(x) != x / 255u;
    for (x = 255u; x < 0x7FFFFFFFu - 255u * 4099u; x += 255u * 4099u)
        failures += (zl_div255_31(x - 1u) != (x - 1u) / 255u) + (zl_div255_31(x) != x / 255u) +
                    (zl_div255_31(x + 254u) != (x + 254u) / 255u);
    for (x = 0x7FFFFFFFu - 1000u; x < 0x7FFFFFFFu; x++)
        failures += zl_div255_31(x) != x / 255u;
    failures += zl_div255_31(0x7FFFFFFFu) != 0x7FFFFFFFu / 255u;
    for (k = 0; k < 200000u; k++) {
        x = rnd32() >> 1;
        failures += zl_div255_31(x) != x / 255u;
    }
    TEST_ASSERT_EQUAL_UINT32(0, failures);
}

/* zl_mul_s32_split (the plane set-up's products without a 64-bit
 * multiply) against the C product: the corners of int32 and random pairs
 * of every magnitude. */
static void test_mul_s32_split(void)
{
    static const int32_t edge[] = {0, 1, -1, 65535, 65536, -65536, -65537, 32767, -32768, INT32_MAX, INT32_MIN,
                                   INT32_MAX - 1, INT32_MIN + 1, 0x7FFF0000, -0x7FFF0000};
    unsigned i, j;
    uint32_t k;
    for (i = 0; i < sizeof edge / sizeof edge[0]; i++)
        for (j = 0; j < sizeof edge / sizeof edge[0]; j++)
            TEST_ASSERT_EQUAL_INT64((int64_t)edge[i] * edge[j], zl_mul_s32_split(edge[i], edge[j]));
    for (k = 0; k < 200000u; k++) {
        int32_t a = (int32_t)(rnd32() >> (k % 32u)), b = (int32_t)rnd32() >> ((k / 32u) % 32u);
        if (zl_mul_s32_split(a, b) != (int64_t)a * b)
            TEST_ASSERT_EQUAL_INT64((int64_t)a * b, zl_mul_s32_split(a, b));
    }
}

/* The perspective reciprocal stepped from a nearby one (zl_span_tex.h,
 * persp_recip_near) against 2^44 / q by a plain 64-bit division, q clamped
 * to 2^12 .. 2^29 as the rule says: neighbours at every distance (the
 * remainder 0 .. q, within 31 bits either sign, and beyond), and q outside
 * the clamp range. */
static void test_persp_recip_near(void)
{
    uint32_t k;
    for (k = 0; k < ZT_ROUNDS(200000); k++) {
        int64_t q0 = (int64_t)(rnd32() % (UINT32_C(1) << 30)), q, qc, dq;
        uint64_t want, r0;
        switch (k % 4) {
        case 0:
            dq = (int64_t)(rnd32() % 17u) - 8;
            break;
        case 1:
            dq = (int64_t)(rnd32() % 4097u) - 2048;
            break;
        case 2:
            dq = (int64_t)(rnd32() % (UINT32_C(1) << 20)) - (INT32_C(1) << 19);
            break;
        default:
            dq = (int64_t)(rnd32() % (UINT32_C(1) << 30)) - (INT32_C(1) << 29);
            break;
        }
        if (k % 97 == 0)
            q0 = (int64_t)(rnd32() % 5000u);
        q = q0 + dq;
        qc = q < 4096 ? 4096 : (q > (INT64_C(1) << 29) ? (INT64_C(1) << 29) : q);
        want = ((uint64_t)1 << 44) / (uint64_t)qc;
        r0 = persp_recip(q0);
        TEST_ASSERT_EQUAL_UINT64(want, persp_recip_near(r0, q));
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_udiv_edge_cases);
    RUN_TEST(test_udiv_random_quotients);
    RUN_TEST(test_udiv_random_numerators);
    RUN_TEST(test_div_inv_corners);
    RUN_TEST(test_div_inv_random);
    RUN_TEST(test_div16_every_divisor);
    RUN_TEST(test_cache_matches_64bit_formulas);
    RUN_TEST(test_cache_edges);
    RUN_TEST(test_cache_position_bound);
    RUN_TEST(test_depth_edges);
    RUN_TEST(test_project_matches_64bit_formulas);
    RUN_TEST(test_lighting_matches_64bit_definition);
    RUN_TEST(test_lighting_edges);
    RUN_TEST(test_isqrt32_squares);
    RUN_TEST(test_div255_small_all);
    RUN_TEST(test_div255_31);
    RUN_TEST(test_mul_s32_split);
    RUN_TEST(test_persp_recip_near);
    return UNITY_END();
}
