/* SPDX-License-Identifier: MIT */
/*
 * zl_frame_bytes against a size written out here from docs/DESIGN.md's
 * table of the work buffer, not from the library's layout function:
 *
 *   colour band   width * band_rows * bpp (twice with two colour buffers)
 *   depth band    width * band_rows * 2
 *   vertex cache  ZL_VERTEX_CACHE_BYTES(max_vertices) = 12 per vertex (8 without
 *                 ZL_FEATURE_EXACT_DEPTH)
 *   row starts    2 * (height + 1)
 *   visible list  2 * max_triangles
 *   active pool   max_active * (record), plus a Gouraud record per active
 *                 triangle with cfg.gouraud
 *   mesh records  max_meshes * (record)
 *
 * each region rounded up to 8 bytes (the buffer is 8-byte aligned and every
 * region keeps that alignment). The private record sizes (zl_active,
 * zl_frame_mesh, the Gouraud record) are not public: they are found as the
 * growth of zl_frame_bytes over 8 more records, where rounding cannot hide
 * a byte, and then the whole formula must give zl_frame_bytes exactly, for
 * many configurations. The documented per-item costs (2 bytes a triangle, 8
 * a vertex, 2 a row, 2 + bpp a band pixel) are checked as such.
 */
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "zline/zl_visibility.h"
#include "zline/zline.h"
#include "zt_ref.h"

void setUp(void) {}
void tearDown(void) {}

/* Sizes in 32 bits: they exceed a 16-bit size_t (AVR), where zl_frame_bytes
 * must then return 0, never a wrapped size. */
static uint32_t align8(uint32_t n)
{
    return (n + 7u) & ~UINT32_C(7);
}

static void base_config(zl_frame_config *c)
{
    memset(c, 0, sizeof *c);
    c->width = 64;
    c->height = 48;
    c->band_rows = 1;
    c->format = ZL_FORMAT_RGB565;
    c->color_buffers = 1;
    c->max_meshes = 8;
    c->max_vertices = 64;
    c->max_triangles = 64;
    c->max_active = 64;
}

typedef struct {
    size_t mesh, active, gouraud;
} records;

/* Record sizes as the growth over 8 more records (8 records are a multiple
 * of 8 bytes whatever their size, so the rounding of the region is the same). */
static records record_sizes(void)
{
    zl_frame_config c;
    records r;
    size_t b0, b1;
    base_config(&c);
    b0 = zl_frame_bytes(&c);
    c.max_meshes += 8;
    r.mesh = (zl_frame_bytes(&c) - b0) / 8;
    base_config(&c);
    c.max_active += 8;
    r.active = (zl_frame_bytes(&c) - b0) / 8;
    base_config(&c);
    c.gouraud = 1;
    b0 = zl_frame_bytes(&c);
    c.max_active += 8;
    b1 = zl_frame_bytes(&c);
    r.gouraud = (b1 - b0) / 8 - r.active;
    return r;
}

/* The documented size (without styled or textured records). */
static uint32_t documented_bytes(const zl_frame_config *c, const records *r)
{
    uint32_t bpp = (uint32_t)zl_format_bytes((zl_format)c->format), band_px = (uint32_t)c->width * c->band_rows;
    uint32_t pool = align8(c->max_active * (uint32_t)r->active);
    uint32_t gouraud = c->gouraud ? c->max_active * (uint32_t)r->gouraud : 0;
    return align8(band_px * bpp) * c->color_buffers + align8(band_px * 2u) +
           align8((uint32_t)ZL_VERTEX_CACHE_BYTES(c->max_vertices)) + align8(2u * ((uint32_t)c->height + 1u)) +
           align8(2u * c->max_triangles) + pool + align8(gouraud) + align8((uint32_t)c->max_meshes * (uint32_t)r->mesh);
}

/* What zl_frame_bytes must return for a documented size: the size, or 0 when
 * no buffer can have it (beyond SIZE_MAX: 65535 where size_t has 16 bits). */
static uint32_t expected_bytes(uint32_t documented)
{
#if SIZE_MAX < UINT32_MAX
    return documented > SIZE_MAX ? 0 : documented;
#else
    return documented;
#endif
}

static void test_each_triangle_costs_two_bytes_and_each_vertex_twelve(void)
{
    zl_frame_config c;
    size_t b0;
    base_config(&c);
    b0 = zl_frame_bytes(&c);
    c.max_triangles += 4; /* 8 bytes: no rounding in between */
    TEST_ASSERT_EQUAL_UINT_MESSAGE(8, zl_frame_bytes(&c) - b0, "4 more triangles");
    base_config(&c);
    c.max_vertices += 2; /* 24 bytes, 16 without the exact depth plane's residuals: no rounding in between */
    TEST_ASSERT_EQUAL_UINT_MESSAGE(ZL_FEATURE_EXACT_DEPTH ? 24 : 16, zl_frame_bytes(&c) - b0, "2 more vertices");
    base_config(&c);
    c.height += 4; /* row starts: 8 bytes more; bands do not depend on height */
    TEST_ASSERT_EQUAL_UINT_MESSAGE(8, zl_frame_bytes(&c) - b0, "4 more rows");
    base_config(&c);
    c.width += 8; /* 8 band pixels of RGB565 colour and depth */
    TEST_ASSERT_EQUAL_UINT_MESSAGE(8 * (2 + 2), zl_frame_bytes(&c) - b0, "8 more band pixels");
}

static void test_frame_bytes_equals_the_documented_formula(void)
{
    records r = record_sizes();
    uint32_t rng = 0x5EEDu;
    unsigned n;
    /* The records hold 32-bit steppers: sizes a reviewer can sanity-check. */
    TEST_ASSERT_TRUE(r.active >= 40 && r.active <= 256);
    TEST_ASSERT_TRUE(r.mesh >= 64 && r.mesh <= 1024);
    TEST_ASSERT_TRUE(r.gouraud >= 24 && r.gouraud <= 256);
    for (n = 0; n < 2000; n++) {
        zl_frame_config c;
        uint32_t want, got;
        memset(&c, 0, sizeof c);
        c.width = (uint16_t)zt_rand_range(&rng, 1, 800);
        c.height = (uint16_t)zt_rand_range(&rng, 1, 600);
        c.band_rows = (uint16_t)zt_rand_range(&rng, 1, c.height < 16 ? c.height : 16);
        c.format = (uint8_t)zt_rand_range(&rng, 0, 2);
        c.color_buffers = (uint8_t)zt_rand_range(&rng, 1, 2);
        c.gouraud = (uint8_t)zt_rand_range(&rng, 0, 1);
        c.max_meshes = (uint16_t)zt_rand_range(&rng, 1, 255);
        c.max_vertices = (uint32_t)zt_rand_range(&rng, 0, 65535);
        c.max_triangles = (uint32_t)zt_rand_range(&rng, 0, 65535);
        /* the pool doubles as a 4-byte-per-row table while planning: keep it
         * the larger, as the formula above assumes */
        c.max_active = (uint32_t)zt_rand_range(&rng, (int32_t)(4u * (c.height + 1u) / r.active + 1u), 65534);
        want = expected_bytes(documented_bytes(&c, &r));
        got = (uint32_t)zl_frame_bytes(&c);
        if (want != got) {
            char msg[200];
            snprintf(msg, sizeof msg,
                     "%ux%u band %u format %u buffers %u gouraud %u meshes %u vertices %lu triangles %lu active %lu: "
                     "documented %lu bytes, zl_frame_bytes %lu",
                     c.width, c.height, c.band_rows, c.format, c.color_buffers, c.gouraud, c.max_meshes,
                     (unsigned long)c.max_vertices, (unsigned long)c.max_triangles, (unsigned long)c.max_active,
                     (unsigned long)want, (unsigned long)got);
            TEST_FAIL_MESSAGE(msg);
            return;
        }
    }
}

/* A work buffer larger than SIZE_MAX cannot exist: zl_frame_bytes and
 * zl_vis_bytes return 0 (and the begin calls, which use the same layout,
 * refuse the configuration), never the size wrapped to a small one that a
 * buffer could have. 65000 cached vertices take at least 8 bytes each
 * (520000 bytes): beyond a 16-bit size_t (AVR), within any wider one. */
static void test_sizes_beyond_size_max_are_refused(void)
{
    zl_frame_config c;
    zl_vis_config v;
    int too_large = (uint64_t)SIZE_MAX < UINT64_C(520000);
    base_config(&c);
    c.max_vertices = 65000;
    if (too_large)
        TEST_ASSERT_EQUAL_UINT_MESSAGE(0, zl_frame_bytes(&c), "zl_frame_bytes beyond SIZE_MAX");
    else
        TEST_ASSERT_GREATER_OR_EQUAL(520000, zl_frame_bytes(&c));
    memset(&v, 0, sizeof v);
    v.width = 64;
    v.height = 48;
    v.algorithm = ZL_VIS_PAINTER;
    v.format = ZL_FORMAT_RGB565;
    v.max_meshes = 1;
    v.max_vertices = 65000;
    v.max_triangles = 64;
    if (too_large)
        TEST_ASSERT_EQUAL_UINT_MESSAGE(0, zl_vis_bytes(&v), "zl_vis_bytes beyond SIZE_MAX");
    else
        TEST_ASSERT_GREATER_OR_EQUAL(520000, zl_vis_bytes(&v));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_each_triangle_costs_two_bytes_and_each_vertex_twelve);
    RUN_TEST(test_frame_bytes_equals_the_documented_formula);
    RUN_TEST(test_sizes_beyond_size_max_are_refused);
    return UNITY_END();
}
