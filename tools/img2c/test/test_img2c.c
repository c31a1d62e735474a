/* SPDX-License-Identifier: MIT */
/*
 * zline-img2c: the arrays it generated at build time (compiled in here)
 * against texels computed in this file, by the formulas of zl_image.h, from
 * the image's pixels as listed below (the table the test images
 * tools/img2c/test/rgba5x3.{ppm,png} and rgba5x3_alpha.pgm were written
 * from). Then one draw: the generated RGBA4444 texture blended over a
 * background, against the blend equation, through the library.
 */
#include <string.h>

#include "img4444_texture.h"
#include "img565_texture.h"
#ifdef HAVE_PNG_TEXTURE
#include "png4444_texture.h"
#endif
#include "unity.h"
#include "zl_image.h"

void setUp(void) {}
void tearDown(void) {}

/* r, g, b, a of the 5 x 3 test image, row by row */
static const uint8_t pixels[15][4] = {
    {0, 5, 255, 0},      {61, 28, 215, 51},  {122, 51, 175, 102}, {183, 74, 135, 153}, {244, 97, 95, 204},
    {17, 102, 225, 85},  {78, 125, 185, 136}, {139, 148, 145, 187}, {200, 171, 105, 238}, {5, 194, 65, 33},
    {34, 199, 195, 170}, {95, 222, 155, 221}, {156, 245, 115, 16},  {217, 12, 75, 67},   {22, 35, 35, 118}};

static unsigned to4(unsigned c)
{
    /* nearest of the 16 levels c4 * 17 (ties cannot occur: 17 is odd) */
    unsigned best = 0, k;
    for (k = 1; k < 16; k++)
        if ((c > k * 17 ? c - k * 17 : k * 17 - c) < (c > best * 17 ? c - best * 17 : best * 17 - c))
            best = k;
    return best;
}

static void test_rgb565(void)
{
    int i;
    TEST_ASSERT_EQUAL_UINT(5, IMG565_WIDTH);
    TEST_ASSERT_EQUAL_UINT(3, IMG565_HEIGHT);
    TEST_ASSERT_EQUAL_INT(0, IMG565_POW2);
    TEST_ASSERT_EQUAL_INT(ZL_TEXEL_RGB565, img565_texture.format);
    TEST_ASSERT_EQUAL_INT(ZL_WRAP_REPEAT, img565_texture.wrap_s);
    TEST_ASSERT_TRUE(img565_texture.texels == img565_texels);
    TEST_ASSERT_EQUAL_UINT(5, img565_texture.stride);
    for (i = 0; i < 15; i++) {
        unsigned e = ((unsigned)(pixels[i][0] / 8) << 11) | ((unsigned)(pixels[i][1] / 4) << 5) | (pixels[i][2] / 8u);
        TEST_ASSERT_EQUAL_HEX16(e, img565_texels[i]);
    }
}

static void check4444(const uint16_t *t)
{
    int i;
    for (i = 0; i < 15; i++) {
        unsigned e = (to4(pixels[i][0]) << 12) | (to4(pixels[i][1]) << 8) | (to4(pixels[i][2]) << 4) | to4(pixels[i][3]);
        TEST_ASSERT_EQUAL_HEX16(e, t[i]);
    }
}

static void test_rgba4444_with_alpha_mask(void)
{
    TEST_ASSERT_EQUAL_INT(ZL_TEXEL_RGBA4444, IMG4444_FORMAT);
    TEST_ASSERT_EQUAL_INT(ZL_WRAP_CLAMP, img4444_texture.wrap_t);
    check4444(img4444_texels);
}

static void test_rgba4444_from_png(void)
{
#ifdef HAVE_PNG_TEXTURE
    check4444(png4444_texels);
#else
    TEST_IGNORE_MESSAGE("built without libpng");
#endif
}

/* The generated texture in a draw: a 5 x 3 pixel quad, one pixel per texel,
 * blended (ZL_BLEND_ALPHA, constant alpha 255) over grey; every pixel must
 * be round((texel a + grey (255 - a)) / 255) of the widened channels, and
 * the alpha-0 texel leaves the grey (and the depth) alone. */
static void test_generated_texture_draws(void)
{
    static const zl_fixed quad[] = {0, 0, 0, ZL_FX_INT(5), 0, 0, ZL_FX_INT(5), ZL_FX_INT(3), 0, 0, ZL_FX_INT(3), 0};
    static const zl_fixed uv[] = {0, 0, ZL_FX_ONE, 0, ZL_FX_ONE, ZL_FX_ONE, 0, ZL_FX_ONE};
    static const uint16_t idx[] = {0, 1, 2, 0, 2, 3};
    static uint8_t color[8 * 4 * 3];
    static uint16_t depth[8 * 4];
    zl_mesh m = {quad, idx, NULL, NULL, 4, 2};
    zl_context c;
    zl_target t;
    zl_rgb grey = {100, 100, 100};
    int x, y, k;
    memset(&t, 0, sizeof t);
    t.color = color;
    t.color_stride = 8 * 3;
    t.depth = depth;
    t.depth_stride = 8 * 2;
    t.width = 8;
    t.height = 4;
    t.format = ZL_FORMAT_RGB888;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_init(&c, &t));
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_clear(&c, grey, 65535));
    c.style.texture = &img4444_texture;
    c.style.texcoords = uv;
    c.style.blend = ZL_BLEND_ALPHA;
    TEST_ASSERT_EQUAL_INT(ZL_OK, zl_draw_mesh(&c, &m, NULL));
    for (y = 0; y < 3; y++)
        for (x = 0; x < 5; x++) {
            uint16_t tx = img4444_texels[y * 5 + x];
            unsigned a = (tx & 15u) * 17u;
            for (k = 0; k < 3; k++) {
                unsigned s = ((unsigned)(tx >> (12 - 4 * k)) & 15u) * 17u;
                TEST_ASSERT_EQUAL_UINT8((s * a + 100u * (255u - a) + 127u) / 255u, color[(y * 8 + x) * 3 + k]);
            }
            TEST_ASSERT_EQUAL_UINT16(a == 0 ? 65535 : 0, depth[y * 8 + x]);
        }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_rgb565);
    RUN_TEST(test_rgba4444_with_alpha_mask);
    RUN_TEST(test_rgba4444_from_png);
    RUN_TEST(test_generated_texture_draws);
    return UNITY_END();
}
