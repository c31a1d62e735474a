/* SPDX-License-Identifier: MIT */
/* The host PNM writer and reader: round trips, the streaming writer's checks,
 * and that a failed write leaves no file. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "zl_image.h"
#include "zl_pnm.h"

static char msg[512];
static char path[1024];
static zl_pnm_image img;

void setUp(void)
{
    msg[0] = '\0';
    memset(&img, 0, sizeof img);
}

void tearDown(void)
{
    zl_pnm_image_free(&img);
}

/* A file name in the build tree, removed first. */
static const char *out_path(const char *name)
{
    snprintf(path, sizeof path, "%s/test_pnm_%s", ZLINE_BINARY_DIR, name);
    remove(path);
    return path;
}

static int file_exists(const char *p)
{
    FILE *f = fopen(p, "rb");
    if (f == NULL)
        return 0;
    fclose(f);
    return 1;
}

/* The whole file, for byte comparisons. */
static size_t read_all(const char *p, unsigned char *buf, size_t cap)
{
    FILE *f = fopen(p, "rb");
    size_t n;
    TEST_ASSERT_TRUE_MESSAGE(f != NULL, p);
    n = fread(buf, 1, cap, f);
    fclose(f);
    return n;
}

static void test_ppm_rgb888_round_trip(void)
{
    enum { W = 5, H = 3, STRIDE = W * 3 + 7 };
    uint8_t pix[H * STRIDE];
    unsigned char file[256];
    size_t n;
    uint32_t x, y, c;
    for (y = 0; y < H; y++)
        for (x = 0; x < STRIDE; x++)
            pix[y * STRIDE + x] = (uint8_t)(y * 60 + x * 7 + 1);
    out_path("rgb888.ppm");
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        ZL_PNM_OK, zl_pnm_write_ppm(path, pix, STRIDE, ZL_FORMAT_RGB888, W, H, msg, sizeof msg),
        msg);
    /* The exact bytes: header, then the rows without their padding. */
    n = read_all(path, file, sizeof file);
    TEST_ASSERT_EQUAL_UINT(11 + W * H * 3, n);
    TEST_ASSERT_EQUAL_MEMORY("P6\n5 3\n255\n", file, 11);
    for (y = 0; y < H; y++)
        TEST_ASSERT_EQUAL_MEMORY(pix + y * STRIDE, file + 11 + y * W * 3, W * 3);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_read(&img, path, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(W, img.width);
    TEST_ASSERT_EQUAL_UINT(H, img.height);
    TEST_ASSERT_EQUAL_UINT(3, img.channels);
    TEST_ASSERT_EQUAL_UINT(255, img.maxval);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            for (c = 0; c < 3; c++)
                TEST_ASSERT_EQUAL_UINT(pix[y * STRIDE + x * 3 + c],
                                       img.samples[(y * W + x) * 3 + c]);
    remove(path);
}

static void test_ppm_from_rgb565(void)
{
    /* white, black, pure red/green/blue, and a mid value */
    static const uint16_t px[6] = {0xFFFF, 0x0000, 0xF800, 0x07E0, 0x001F, 0x8410};
    static const uint8_t want[18] = {255, 255, 255, 0, 0, 0,   255, 0,   0,
                                     0,   255, 0,   0, 0, 255, 132, 130, 132};
    uint8_t be[12];
    uint32_t i;
    out_path("rgb565.ppm");
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        ZL_PNM_OK, zl_pnm_write_ppm(path, px, 12, ZL_FORMAT_RGB565, 6, 1, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_read(&img, path, msg, sizeof msg), msg);
    for (i = 0; i < 18; i++)
        TEST_ASSERT_EQUAL_UINT(want[i], img.samples[i]);
    zl_pnm_image_free(&img);
    remove(path);
    /* The same pixels high byte first. */
    for (i = 0; i < 6; i++) {
        be[2 * i] = (uint8_t)(px[i] >> 8);
        be[2 * i + 1] = (uint8_t)(px[i] & 0xFF);
    }
    out_path("rgb565be.ppm");
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        ZL_PNM_OK, zl_pnm_write_ppm(path, be, 12, ZL_FORMAT_RGB565_BE, 6, 1, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_read(&img, path, msg, sizeof msg), msg);
    for (i = 0; i < 18; i++)
        TEST_ASSERT_EQUAL_UINT(want[i], img.samples[i]);
    remove(path);
}

static void test_rgb565_expansion_is_exact_at_the_ends(void)
{
    /* Every 5- and 6-bit level maps to round-trippable 8 bits, monotonic. */
    uint16_t row[64];
    uint8_t rgb[64 * 3];
    uint32_t i;
    for (i = 0; i < 64; i++)
        row[i] = (uint16_t)((i & 31u) << 11 | i << 5 | (i & 31u));
    zl_pnm_row_to_rgb888(rgb, row, ZL_FORMAT_RGB565, 64);
    for (i = 0; i < 64; i++) {
        TEST_ASSERT_EQUAL_UINT(i & 31u, rgb[3 * i] >> 3);
        TEST_ASSERT_EQUAL_UINT(i, rgb[3 * i + 1] >> 2);
        if (i > 0 && i < 32)
            TEST_ASSERT_TRUE(rgb[3 * i] > rgb[3 * (i - 1)]);
    }
    TEST_ASSERT_EQUAL_UINT(255, rgb[3 * 31]);
    TEST_ASSERT_EQUAL_UINT(255, rgb[3 * 63 + 1]);
}

static void test_pgm16_round_trip(void)
{
    enum { W = 4, H = 2 };
    static const uint16_t depth[H][W + 1] = {{0, 1, 255, 256, 0xAAAA},
                                             {0x1234, 0xFFFE, 0xFFFF, 0x8000, 7}};
    unsigned char file[128];
    uint32_t x, y;
    out_path("depth.pgm");
    TEST_ASSERT_EQUAL_INT_MESSAGE(
        ZL_PNM_OK, zl_pnm_write_pgm16(path, &depth[0][0], (W + 1) * 2, W, H, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(13 + W * H * 2, read_all(path, file, sizeof file));
    TEST_ASSERT_EQUAL_MEMORY("P5\n4 2\n65535\n", file, 13);
    /* big-endian samples */
    TEST_ASSERT_EQUAL_HEX8(0x12, file[13 + 8]);
    TEST_ASSERT_EQUAL_HEX8(0x34, file[13 + 9]);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_read(&img, path, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(1, img.channels);
    TEST_ASSERT_EQUAL_UINT(65535, img.maxval);
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++)
            TEST_ASSERT_EQUAL_UINT(depth[y][x], img.samples[y * W + x]);
    remove(path);
}

static void test_streaming_writer(void)
{
    zl_pnm_writer w;
    uint8_t row[3 * 7];
    uint32_t y, i;
    for (i = 0; i < sizeof row; i++)
        row[i] = (uint8_t)i;
    out_path("stream.ppm");
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK,
                                  zl_pnm_open(&w, path, ZL_PNM_PPM, 7, 4, msg, sizeof msg), msg);
    for (y = 0; y < 4; y++) {
        TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_write_row_rgb(&w, row, ZL_FORMAT_RGB888),
                                      msg);
        /* Nothing under the final name until the close. */
        TEST_ASSERT_FALSE(file_exists(path));
    }
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_close(&w), msg);
    TEST_ASSERT_TRUE(file_exists(path));
    zl_pnm_abort(&w); /* harmless after a close */
    TEST_ASSERT_TRUE(file_exists(path));
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_read(&img, path, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(7, img.width);
    TEST_ASSERT_EQUAL_UINT(4, img.height);
    TEST_ASSERT_EQUAL_UINT(row[20], img.samples[3 * 7 * 3 + 20]);
    remove(path);
}

static void test_too_few_rows_leaves_no_file(void)
{
    zl_pnm_writer w;
    uint16_t row[3] = {1, 2, 3};
    char tmp[1200];
    out_path("short.pgm");
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_open(&w, path, ZL_PNM_PGM16, 3, 5, msg, sizeof msg));
    /* the temporary file exists while writing, and goes with the failure */
    snprintf(tmp, sizeof tmp, "%s", w.out.tmp_path);
    TEST_ASSERT_TRUE(file_exists(tmp));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_write_row_gray16(&w, row));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_write_row_gray16(&w, row));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_ARG, zl_pnm_close(&w));
    TEST_ASSERT_NOT_NULL(strstr(msg, "2 of 5 rows"));
    TEST_ASSERT_FALSE(file_exists(path));
    TEST_ASSERT_FALSE(file_exists(tmp));
    /* The writer is released: another close reports, does not crash. */
    TEST_ASSERT_TRUE(zl_pnm_close(&w) != ZL_PNM_OK);
    zl_pnm_abort(&w);
}

static void test_too_many_rows_leaves_no_file(void)
{
    zl_pnm_writer w;
    uint8_t row[6] = {0};
    out_path("long.ppm");
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_open(&w, path, ZL_PNM_PPM, 2, 1, msg, sizeof msg));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_write_row_rgb(&w, row, ZL_FORMAT_RGB888));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_ARG, zl_pnm_write_row_rgb(&w, row, ZL_FORMAT_RGB888));
    TEST_ASSERT_NOT_NULL(strstr(msg, "row 2"));
    TEST_ASSERT_TRUE(zl_pnm_close(&w) != ZL_PNM_OK);
    TEST_ASSERT_FALSE(file_exists(path));
}

static void test_abort_and_wrong_row_kind(void)
{
    zl_pnm_writer w;
    uint16_t grey[2] = {0, 0};
    uint8_t rgb[6] = {0};
    char tmp[1200];
    out_path("abort.ppm");
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_open(&w, path, ZL_PNM_PPM, 2, 2, msg, sizeof msg));
    snprintf(tmp, sizeof tmp, "%s", w.out.tmp_path);
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_write_row_rgb(&w, rgb, ZL_FORMAT_RGB888));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_write_row_rgb(&w, rgb, ZL_FORMAT_RGB888));
    zl_pnm_abort(&w); /* complete, but abandoned */
    TEST_ASSERT_FALSE(file_exists(path));
    TEST_ASSERT_FALSE(file_exists(tmp));

    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_open(&w, path, ZL_PNM_PPM, 2, 1, msg, sizeof msg));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_ARG, zl_pnm_write_row_gray16(&w, grey));
    TEST_ASSERT_TRUE(zl_pnm_close(&w) != ZL_PNM_OK);
    TEST_ASSERT_FALSE(file_exists(path));

    /* Finished but not committed, then abandoned. */
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_open(&w, path, ZL_PNM_PPM, 2, 1, msg, sizeof msg));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_write_row_rgb(&w, rgb, ZL_FORMAT_RGB565));
    snprintf(tmp, sizeof tmp, "%s", w.out.tmp_path);
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_finish(&w));
    TEST_ASSERT_FALSE(file_exists(path));
    TEST_ASSERT_TRUE(file_exists(tmp));
    zl_pnm_abort(&w);
    TEST_ASSERT_FALSE(file_exists(path));
    TEST_ASSERT_FALSE(file_exists(tmp));
}

static void test_failed_write_keeps_existing_file(void)
{
    /* An existing file survives a failed write untouched. */
    zl_pnm_writer w;
    uint8_t rgb[3] = {9, 9, 9};
    unsigned char file[64];
    out_path("keep.ppm");
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK,
                          zl_pnm_write_ppm(path, rgb, 3, ZL_FORMAT_RGB888, 1, 1, msg, sizeof msg));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_open(&w, path, ZL_PNM_PPM, 1, 2, msg, sizeof msg));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_OK, zl_pnm_write_row_rgb(&w, rgb, ZL_FORMAT_RGB888));
    TEST_ASSERT_TRUE(zl_pnm_close(&w) != ZL_PNM_OK);
    TEST_ASSERT_EQUAL_UINT(14, read_all(path, file, sizeof file));
    TEST_ASSERT_EQUAL_MEMORY("P6\n1 1\n255\n\x09\x09\x09", file, 14);
    remove(path);
}

static void test_open_errors(void)
{
    zl_pnm_writer w;
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_IO, zl_pnm_open(&w, "/nonexistent/dir/x.ppm", ZL_PNM_PPM, 2, 2,
                                                     msg, sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "/nonexistent/dir/x.ppm"));
    zl_pnm_abort(&w);
    out_path("size.ppm");
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_ARG, zl_pnm_open(&w, path, ZL_PNM_PPM, 0, 2, msg, sizeof msg));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_ARG,
                          zl_pnm_open(&w, path, (zl_pnm_kind)4, 2, 2, msg, sizeof msg));
    TEST_ASSERT_FALSE(file_exists(path));
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_ARG,
                          zl_pnm_open(NULL, path, ZL_PNM_PPM, 2, 2, msg, sizeof msg));
}

static void write_raw(const char *p, const char *data, size_t n)
{
    FILE *f = fopen(p, "wb");
    TEST_ASSERT_TRUE(f != NULL);
    TEST_ASSERT_EQUAL_UINT(n, fwrite(data, 1, n, f));
    fclose(f);
}

static void test_reader(void)
{
    /* Comments and odd white space in the header, 8-bit grey. */
    static const char pgm8[] = "P5 # grey\n# comment line\n 3\t1\n# max\n200\nabc";
    static const char truncated[] = "P6\n2 2\n255\nabcdef";
    static const char ascii[] = "P3\n1 1\n255\n1 2 3\n";
    static const char bad_max[] = "P5\n1 1\n70000\nab";
    out_path("reader.pgm");
    write_raw(path, pgm8, sizeof pgm8 - 1);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_read(&img, path, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(3, img.width);
    TEST_ASSERT_EQUAL_UINT(1, img.height);
    TEST_ASSERT_EQUAL_UINT(200, img.maxval);
    TEST_ASSERT_EQUAL_UINT('a', img.samples[0]);
    TEST_ASSERT_EQUAL_UINT('c', img.samples[2]);
    zl_pnm_image_free(&img);
    write_raw(path, truncated, sizeof truncated - 1);
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_FORMAT, zl_pnm_read(&img, path, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "truncated"));
    TEST_ASSERT_NULL(img.samples);
    write_raw(path, ascii, sizeof ascii - 1);
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_FORMAT, zl_pnm_read(&img, path, msg, sizeof msg));
    write_raw(path, bad_max, sizeof bad_max - 1);
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_FORMAT, zl_pnm_read(&img, path, msg, sizeof msg));
    write_raw(path, "", 0);
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_FORMAT, zl_pnm_read(&img, path, msg, sizeof msg));
    remove(path);
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_IO, zl_pnm_read(&img, path, msg, sizeof msg));
}

/* Netpbm: every sample is at most maxval (issue 26: P6 samples of 255
 * under maxval 100 were read as grey texels); two bytes a sample from a
 * maxval of 256 on. Independent expectations written out by hand. */
static void test_reader_maxval(void)
{
    static const char above8[] = "P6\n2 1\n100\n\x01\x02\x03\x04\x65\x06";
    static const char at8[] = "P5\n2 1\n100\n\x64\x00";
    static const char two_bytes_256[] = "P5\n2 1\n256\n\x01\x00\x00\xff";
    static const char above16[] = "P5\n2 1\n300\n\x00\x05\x01\x2d";
    out_path("maxval.pnm");
    write_raw(path, above8, sizeof above8 - 1);
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_FORMAT, zl_pnm_read(&img, path, msg, sizeof msg));
    TEST_ASSERT_TRUE_MESSAGE(strstr(msg, "sample 101 at pixel (1, 0) is above the maxval 100") != NULL, msg);
    TEST_ASSERT_NULL(img.samples);
    write_raw(path, at8, sizeof at8 - 1);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_read(&img, path, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(100, img.samples[0]);
    zl_pnm_image_free(&img);
    write_raw(path, two_bytes_256, sizeof two_bytes_256 - 1);
    TEST_ASSERT_EQUAL_INT_MESSAGE(ZL_PNM_OK, zl_pnm_read(&img, path, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_UINT(256, img.samples[0]);
    TEST_ASSERT_EQUAL_UINT(255, img.samples[1]);
    zl_pnm_image_free(&img);
    write_raw(path, above16, sizeof above16 - 1);
    TEST_ASSERT_EQUAL_INT(ZL_PNM_ERR_FORMAT, zl_pnm_read(&img, path, msg, sizeof msg));
    TEST_ASSERT_TRUE_MESSAGE(strstr(msg, "sample 301 at pixel (1, 0) is above the maxval 300") != NULL, msg);
    remove(path);
}

/* Samples under another maxval scale to 0..255 rounded to nearest, halves
 * up: round(s * 255 / 100) written out by hand (issue 26: truncation went
 * unnoticed). */
static void test_image_scales_rounding(void)
{
    static const char grey[] = "P5\n5 1\n100\n\x00\x01\x32\x63\x64";
    static const uint8_t want[5] = {0, 3, 128, 252, 255}; /* 0, 2.55, 127.5, 252.45, 255 */
    zl_image im;
    int k;
    out_path("scale.pgm");
    write_raw(path, grey, sizeof grey - 1);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, zl_image_load(&im, path, NULL, msg, sizeof msg), msg);
    for (k = 0; k < 5; k++) {
        TEST_ASSERT_EQUAL_UINT(want[k], im.rgba[4 * k]);
        TEST_ASSERT_EQUAL_UINT(want[k], im.rgba[4 * k + 2]);
        TEST_ASSERT_EQUAL_UINT(255, im.rgba[4 * k + 3]);
    }
    zl_image_free(&im);
    remove(path);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_ppm_rgb888_round_trip);
    RUN_TEST(test_ppm_from_rgb565);
    RUN_TEST(test_rgb565_expansion_is_exact_at_the_ends);
    RUN_TEST(test_pgm16_round_trip);
    RUN_TEST(test_streaming_writer);
    RUN_TEST(test_too_few_rows_leaves_no_file);
    RUN_TEST(test_too_many_rows_leaves_no_file);
    RUN_TEST(test_abort_and_wrong_row_kind);
    RUN_TEST(test_failed_write_keeps_existing_file);
    RUN_TEST(test_open_errors);
    RUN_TEST(test_reader);
    RUN_TEST(test_reader_maxval);
    RUN_TEST(test_image_scales_rounding);
    return UNITY_END();
}
